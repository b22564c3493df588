// bench_costs — the cost claims of the sources, timed on this renderer (OSMesa, llvmpipe): whole frames
// (clear, draw, glFinish; no readback), ms per frame, with counters for what each frame did.
//
// The claims, briefly quoted (translated), and the family that times each:
//   1. Buss VI.1.1: "the drawback of hyperbolic interpolation is that it requires extra computation and
//      therefore may be slower".  -> costs/interpolation/{smooth,noperspective}/{256,512,1024}: one receding
//      quad filling a square frame, its texture coordinate a `smooth` (hyperbolic) or `noperspective`
//      (screen-linear) varying; nothing else differs.  {smooth,noperspective}_8vec4/1024 add 8 vec4 varyings
//      of the same kind, to magnify the per-attribute part.
//   2. Buss VI.1: without texture maps surfaces "would need to be rendered with very small polygons"; texture
//      maps give "good results with a minimal computational load".  Seed 001 ¶1: a brick image on a polygon
//      instead of exact geometry "saves modelling work and memory, and speeds up drawing".  Seed 003's
//      opening: small surface objects "whose creation with polygons would be excessively resource-
//      intensive".  -> costs/detail/{parallax_quad,bump_quad,displaced_grid}: the same brick relief (one
//      256^2 height map) at the same view and the same diffuse lighting, as a 2-triangle quad whose fragment
//      shader reads the height map (bump: normal from 4 neighbours; parallax: a 16-step search along the view
//      ray, then the bump normal) against a grid with one vertex per texel displaced on the CPU, per-vertex
//      normals from the same differences; displaced_grid_vertices_only draws the grid with
//      GL_RASTERIZER_DISCARD, its vertex work alone.
//   3. Seed 001 ¶18-19 (texture caching): "group polygons that use the same texture ... avoid texture
//      switches".  -> costs/switches/{sorted,unsorted,sorted_batched}: 2,048 small quads, 32 textures;
//      sorted binds 32 times, unsorted once per quad (a neighbour never shares its texture), both with one
//      draw call per quad; sorted_batched also draws each texture's quads in one call (what grouping allows).
//   4. Buss VI.1.3: only the low-resolution mipmaps of distant textures need to be kept "in more accessible
//      memory locations (e.g. in cache or on the graphics chip)" — mipmapping is widely said to be faster when
//      minifying, besides removing aliasing.  -> costs/minify/{mipmapped,bilinear_mip,unmipmapped}/{2048,4096}:
//      a texture minified 16x onto a 1024^2 frame with GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_NEAREST
//      (the same 4 taps as GL_LINEAR, on the right level) and GL_LINEAR (4 taps 16 texels apart on level 0);
//      costs/minify/one_to_one/4096, GL_LINEAR at 1 texel a pixel, is the control for the memory access, and
//      costs/minify/clear_only the frame's fixed part (clear and glFinish, nothing drawn).
//
// The GL calls that carry each claim: glTexCoord arrays with a `smooth`/`noperspective` varying (1),
// glDrawElements of 2 triangles against 130,050 (2), glBindTexture per group or per quad (3),
// glTexParameteri(GL_TEXTURE_MIN_FILTER, ...) on a texture made with GL_GENERATE_MIPMAP (4).
//
// The frames themselves are common/gl/cost_workloads.cpp, which the texture_costs demo times live too.
// Vertices come from client arrays (the suite's loader has no buffer objects), so the displaced grid's
// 65,536 vertices and 390,150 indices are handed to GL each frame, as a GL 1.1 program's would be.
// Speed is measured, never asserted; compare variants as ratios within one run, and record the load.
// To see what is timed: TS_BENCH_COSTS_PNG=dir writes the first frame of each benchmark to dir/<name>.png.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "common/core/image.hpp"
#include "common/gl/context.hpp"
#include "common/gl/cost_workloads.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"

namespace {
namespace C = ts::costs;
constexpr int kDetailFrame = 768, kMinifyFrame = 1024;

// One OSMesa context, resized to each benchmark's square frame.
struct Rig {
  Rig() {
    ts::ContextOptions o;
    o.width = o.height = 512;
    ctx = ts::createOffscreenContext(ts::Backend::OSMesa, o);
    renderer = std::make_unique<ts::Renderer>(*ctx);
    glDisable(GL_DEBUG_OUTPUT);  // a shipped program runs without the suite's error reports
  }
  ~Rig() { renderer->release(); }
  void frame(int n) {
    if (ctx->width() != n || ctx->height() != n) ctx->resize(n, n);
    glViewport(0, 0, n, n);
  }
  std::unique_ptr<ts::Context> ctx;
  std::unique_ptr<ts::Renderer> renderer;
};
Rig& rig() {
  static Rig r;
  return r;
}

// The running benchmark's name, for the pictures below.
std::string g_running;

// The workload's frames, timed: clear, draw, glFinish (llvmpipe renders on its own threads: real time is the
// cost).  With TS_BENCH_COSTS_PNG=dir the first frame of each benchmark is written to dir/<name>.png, to see
// that the variants compared draw the same thing.  Its counters, and frames per second, go beside the time.
void timeFrames(benchmark::State& st, int n, const std::function<std::unique_ptr<C::Workload>()>& make) {
  try {
    Rig& r = rig();
    r.frame(n);
    std::unique_ptr<C::Workload> w = make();
    w->begin();
    w->frame();
    glFinish();  // warm: programs linked, textures made resident
    ts::gl::check("the first frame");
    if (const char* dir = std::getenv("TS_BENCH_COSTS_PNG")) {
      std::string file = g_running;
      std::replace(file.begin(), file.end(), '/', '_');
      ts::writePng(std::string(dir) + "/" + file + ".png", r.ctx->readPixels());
    }
    for (auto _ : st) {
      w->frame();
      glFinish();
    }
    w->end();
    for (const auto& [k, v] : w->counters) st.counters[k] = v;
    st.counters["pixels"] = double(n) * n;
    st.counters["fps"] = benchmark::Counter(double(st.iterations()), benchmark::Counter::kIsRate);
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}

// The part of every minify frame that is not texturing.
void clearOnly(benchmark::State& st) {
  rig().frame(kMinifyFrame);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  for (auto _ : st) {
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
  }
  st.counters["pixels"] = double(kMinifyFrame) * kMinifyFrame;
}

struct MinFilter {
  const char* key;
  GLint filter;
};
const MinFilter kMinFilters[] = {{"mipmapped", GL_LINEAR_MIPMAP_LINEAR},
                                 {"bilinear_mip", GL_LINEAR_MIPMAP_NEAREST},
                                 {"unmipmapped", GL_LINEAR}};

// The medians as markdown tables, each variant beside the one its claim compares it with.
void summary(const ts::bench::SummaryReporter& rep) {
  using ts::bench::fmt;
  using ts::bench::ratio;
  auto ms = [&](const std::string& n) { return rep.ms("costs/" + n); };
  auto count = [&](const std::string& n, const char* key) {
    const double v = rep.counter("costs/" + n, key);
    return std::isfinite(v) ? std::to_string(std::llround(v)) : std::string("–");
  };
  std::printf("\n%s, ms per frame (OSMesa, llvmpipe).\n", rep.statistic().c_str());
  if (rep.ran("costs/interpolation/")) {
    std::printf("\n| frame | smooth (hyperbolic) | noperspective (screen-linear) | smooth / noperspective |\n"
                "|---|---|---|---|\n");
    for (const char* n : {"256", "512", "1024", "8vec4/1024"}) {
      const std::string k = n[0] == '8' ? "_" + std::string(n) : "/" + std::string(n);
      const double a = ms("interpolation/smooth" + k), b = ms("interpolation/noperspective" + k);
      const std::string label = n[0] == '8' ? "1024^2, 8 more vec4 varyings" : std::string(n) + "^2";
      std::printf("| %s | %s | %s | %s |\n", label.c_str(), fmt(a).c_str(), fmt(b).c_str(), ratio(a, b).c_str());
    }
  }
  if (rep.ran("costs/detail/")) {
    std::printf("\n| relief, %d^2 frame | triangles | ms | / bump_quad |\n|---|---|---|---|\n", kDetailFrame);
    for (const char* k : C::kDetailKeys) {
      const std::string n = std::string("detail/") + k;
      std::printf("| %s | %s | %s | %s |\n", k, count(n, "triangles").c_str(), fmt(ms(n)).c_str(),
                  ratio(ms(n), ms("detail/bump_quad")).c_str());
    }
  }
  if (rep.ran("costs/switches/")) {
    std::printf("\n| %d quads, %d textures | binds | draw calls | ms | / sorted |\n|---|---|---|---|---|\n", C::kQuads,
                C::kTextures);
    for (const char* k : C::kOrderKeys) {
      const std::string n = std::string("switches/") + k;
      std::printf("| %s | %s | %s | %s | %s |\n", k, count(n, "binds").c_str(), count(n, "draws").c_str(),
                  fmt(ms(n)).c_str(), ratio(ms(n), ms("switches/sorted")).c_str());
    }
  }
  if (rep.ran("costs/minify/")) {
    std::printf(
        "\n| texture, 16x minified onto %d^2 | mipmapped (trilinear) | bilinear_mip | unmipmapped (GL_LINEAR) | "
        "mipmapped / unmipmapped | bilinear_mip / unmipmapped |\n|---|---|---|---|---|---|\n",
        kMinifyFrame);
    for (int size : {2048, 4096}) {
      const std::string z = "/" + std::to_string(size);
      const double tri = ms("minify/mipmapped" + z), bi = ms("minify/bilinear_mip" + z),
                   lin = ms("minify/unmipmapped" + z);
      std::printf("| %d^2 | %s | %s | %s | %s | %s |\n", size, fmt(tri).c_str(), fmt(bi).c_str(), fmt(lin).c_str(),
                  ratio(tri, lin).c_str(), ratio(bi, lin).c_str());
    }
    std::printf("\nControls: GL_LINEAR at 1 texel a pixel on the 4096^2 texture, %s ms; the clear alone, %s ms.\n",
                fmt(ms("minify/one_to_one/4096")).c_str(), fmt(ms("minify/clear_only")).c_str());
  }
  std::printf("\n");
}
}  // namespace

int main(int argc, char** argv) {
  auto add = [](const std::string& name, int n, std::function<std::unique_ptr<C::Workload>()> make) {
    benchmark::RegisterBenchmark(name.c_str(),
                                 [=](benchmark::State& st) {
                                   g_running = name;
                                   timeFrames(st, n, make);
                                 })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->ComputeStatistics("min", ts::bench::minimum);  // on a shared machine, the least disturbed repetition
  };
  auto& r = *rig().renderer;
  for (int n : {256, 512, 1024})
    for (bool persp : {true, false})
      add("costs/interpolation/" + std::string(persp ? "smooth/" : "noperspective/") + std::to_string(n), n,
          [&r, persp] { return C::interpolation(r, persp); });
  for (bool persp : {true, false})
    add("costs/interpolation/" + std::string(persp ? "smooth" : "noperspective") + "_8vec4/1024", 1024,
        [&r, persp] { return C::interpolation(r, persp, 8); });
  for (C::Detail d : {C::Detail::Parallax, C::Detail::Bump, C::Detail::Grid, C::Detail::GridVerticesOnly})
    add(std::string("costs/detail/") + C::kDetailKeys[int(d)], kDetailFrame, [&r, d] { return C::detail(r, d); });
  for (C::Order o : {C::Order::Sorted, C::Order::Unsorted, C::Order::SortedBatched})
    add(std::string("costs/switches/") + C::kOrderKeys[int(o)], 512, [&r, o] { return C::switches(r, o); });
  for (int size : {2048, 4096})
    for (const MinFilter& f : kMinFilters)
      add(std::string("costs/minify/") + f.key + "/" + std::to_string(size), kMinifyFrame,
          [&r, f, size] { return C::minify(r, f.filter, size, 16, kMinifyFrame); });
  // The control: level 0 read at one texel a pixel, where neighbouring pixels share cache lines.
  add("costs/minify/one_to_one/4096", kMinifyFrame, [&r] { return C::minify(r, GL_LINEAR, 4096, 1, kMinifyFrame); });
  benchmark::RegisterBenchmark("costs/minify/clear_only", clearOnly)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->ComputeStatistics("min", ts::bench::minimum);
  return ts::bench::run(argc, argv, summary);
}
