// bench_figures — where the time of a book figure goes, offscreen, for every
// registered figure at its own size (both backends are llvmpipe):
//
//   <figure>/context/<backend>   create + destroy an offscreen context (GL pointers loaded)
//   <figure>/measure/osmesa      scene->measure(renderer) of a new scene: the figure's numbers
//   <figure>/build               scene->build(w, h): the Frame, no GL
//   <figure>/render/<backend>    renderer.draw(frame) + glFinish (textures, shaders cached)
//   <figure>/render_after_recording/osmesa  the same after a gl::Recording came and went (the
//                                cost of the recorder when off: the pointers are the driver's again)
//   <figure>/render_recording/osmesa        the same while recording (what the GL pane pays)
//   <figure>/readback/<backend>  Context::readPixels (glReadPixels + row flip)
//   <figure>/encode              ts::encodePng of the rendered image
//   <figure>/warm/osmesa         new scene + renderScene + encodePng on a live context (make_figures' per figure)
//   <figure>/cold/<backend>      context + scene + renderScene + encodePng + teardown (one `demo --png` minus exec)
//
// <backend> is osmesa and egl (EGL is what remains on Mesa >= 25.1); the
// CPU-bound measure and the warm figure run on OSMesa only.  Times are wall
// clock (llvmpipe renders on its own threads), medians of 5 repetitions by
// default; any benchmark flag overrides, e.g.
//   bench_figures --benchmark_filter=render --benchmark_repetitions=9
// After the usual output it prints the medians as markdown tables.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "common/gl/context.hpp"
#include "common/core/error.hpp"
#include "common/gl/figure.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/gl_record.hpp"
#include "common/core/image.hpp"
#include "common/gl/render.hpp"

namespace {
using ts::bench::Figure;

const ts::Backend kBackends[] = {ts::Backend::OSMesa, ts::Backend::EGL};

std::unique_ptr<ts::Context> makeContext(ts::Backend b, int w, int h) {
  ts::ContextOptions o;
  o.width = w;
  o.height = h;
  return ts::createOffscreenContext(b, o);
}

// A context at the figure's size with a renderer and the scene in the
// figure's state, measured and drawn once (textures uploaded, shaders
// compiled): where make_figures is when it renders a figure.
struct Rig {
  Rig(const Figure& f, ts::Backend b)
      : w(f.spec.width), h(f.spec.height), ctx(makeContext(b, w, h)), renderer(*ctx), state(f) {
    measured = state.scene->measure(renderer);
    if (ctx->width() != w || ctx->height() != h) ctx->resize(w, h);
    frame = state.scene->build(w, h, measured);
    renderer.draw(frame);
    glFinish();
    ts::gl::check("the benchmark's first draw");
  }
  ~Rig() { renderer.release(); }
  ts::Scene& scene() { return *state.scene; }

  int w, h;
  std::unique_ptr<ts::Context> ctx;
  ts::Renderer renderer;
  ts::bench::SceneState state;
  ts::Measurements measured;
  ts::Frame frame;
};

// Runs `body` and turns any exception into a skipped benchmark (e.g. no EGL).
template <class Body>
void guarded(benchmark::State& st, Body body) {
  try {
    body();
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}

void benchContext(benchmark::State& st, const Figure& f, ts::Backend b) {
  guarded(st, [&] {
    for (auto _ : st) {
      auto c = makeContext(b, f.spec.width, f.spec.height);
      benchmark::DoNotOptimize(c.get());
      c.reset();
    }
  });
}

// A fresh scene each time (constructed outside the timing): a scene may keep
// its numbers, and make_figures measures each figure once, in a new scene.
void benchMeasure(benchmark::State& st, const Figure& f, ts::Backend b) {
  guarded(st, [&] {
    Rig rig(f, b);
    for (auto _ : st) {
      st.PauseTiming();
      auto s = std::make_unique<ts::bench::SceneState>(f);
      st.ResumeTiming();
      ts::Measurements m = s->scene->measure(rig.renderer);
      benchmark::DoNotOptimize(m.data());
      st.PauseTiming();
      s.reset();
      st.ResumeTiming();
    }
  });
}

void benchBuild(benchmark::State& st, const Figure& f) {
  guarded(st, [&] {
    Rig rig(f, ts::Backend::Auto);  // measured first: labels show the measured numbers
    for (auto _ : st) {
      ts::Frame fr = rig.scene().build(rig.w, rig.h, rig.measured);
      benchmark::DoNotOptimize(fr.panels.data());
    }
  });
}

void benchRender(benchmark::State& st, const Figure& f, ts::Backend b) {
  guarded(st, [&] {
    Rig rig(f, b);
    for (auto _ : st) {
      rig.renderer.draw(rig.frame);
      glFinish();
    }
  });
}

// The recorder's cost: off (after a Recording ended) and on.
void benchRenderRecorder(benchmark::State& st, const Figure& f, bool recording) {
  guarded(st, [&] {
    Rig rig(f, ts::Backend::OSMesa);
    { ts::gl::Recording warmup; }
    for (auto _ : st) {
      if (recording) {
        ts::gl::Recording rec;
        rig.renderer.draw(rig.frame);
        glFinish();
        benchmark::DoNotOptimize(rec.calls().size());
      } else {
        rig.renderer.draw(rig.frame);
        glFinish();
      }
    }
  });
}

void benchReadback(benchmark::State& st, const Figure& f, ts::Backend b) {
  guarded(st, [&] {
    Rig rig(f, b);
    for (auto _ : st) {
      ts::Image img = rig.ctx->readPixels();
      benchmark::DoNotOptimize(img.pixels.data());
    }
  });
}

void benchEncode(benchmark::State& st, const Figure& f) {
  guarded(st, [&] {
    ts::Image img;
    {
      Rig rig(f, ts::Backend::Auto);
      img = rig.renderer.render(rig.frame);
    }
    size_t bytes = 0;
    for (auto _ : st) {
      std::vector<uint8_t> png = ts::encodePng(img);
      bytes = png.size();
      benchmark::DoNotOptimize(png.data());
    }
    st.counters["png_KiB"] = double(bytes) / 1024.0;
  });
}

// make_figures' loop body: a new scene in the figure's state, rendered on the
// shared context (textures and shaders already cached), then encoded.
void benchWarm(benchmark::State& st, const Figure& f, ts::Backend b) {
  guarded(st, [&] {
    Rig rig(f, b);
    for (auto _ : st) {
      ts::bench::SceneState s(f);
      ts::Rendered got = ts::renderScene(*s.scene, rig.renderer, rig.w, rig.h);
      std::vector<uint8_t> png = ts::encodePng(got.image);
      benchmark::DoNotOptimize(png.data());
    }
  });
}

void benchCold(benchmark::State& st, const Figure& f, ts::Backend b) {
  guarded(st, [&] {
    for (auto _ : st) {
      auto ctx = makeContext(b, f.spec.width, f.spec.height);
      ts::Renderer r(*ctx);
      ts::bench::SceneState s(f);
      ts::Rendered got = ts::renderScene(*s.scene, r, f.spec.width, f.spec.height);
      std::vector<uint8_t> png = ts::encodePng(got.image);
      benchmark::DoNotOptimize(png.data());
      r.release();
    }
  });
}

std::string name(const Figure& f, const std::string& stage, ts::Backend b = ts::Backend::Auto) {
  std::string n = f.spec.id + "/" + stage;
  if (b != ts::Backend::Auto) n += std::string("/") + ts::backendName(b);
  return n;
}

benchmark::internal::Benchmark* timed(benchmark::internal::Benchmark* bm) {
  return bm->Unit(benchmark::kMillisecond)->UseRealTime()->ComputeStatistics("min", ts::bench::minimum);
}

// Each backend's "backend | GL version | renderer", or why it is missing.
std::string describe(ts::Backend b) {
  try {
    return makeContext(b, 16, 16)->describe();
  } catch (const std::exception& e) {
    return std::string(ts::backendName(b)) + " unavailable: " + e.what();
  }
}

void summary(const ts::bench::SummaryReporter& rep, const std::vector<Figure>& figs,
             const std::vector<std::string>& renderers) {
  using ts::bench::fmt;
  using ts::bench::ratio;
  const ts::Backend O = ts::Backend::OSMesa, E = ts::Backend::EGL;
  auto ms = [&](const Figure& f, const char* stage, ts::Backend b = ts::Backend::Auto) {
    return rep.ms(name(f, stage, b));
  };
  auto both = [&](const Figure& f, const char* stage) { return fmt(ms(f, stage, O)) + " / " + fmt(ms(f, stage, E)); };

  std::printf("\n## Offscreen stages per figure (ms, wall clock, %s)\n\n", rep.statistic().c_str());
  for (const auto& r : renderers) std::printf("- `%s`\n", r.c_str());
  std::printf(
      "\n| figure | size | context create+destroy (OSMesa / EGL) | measure | build | render: draw+glFinish (OSMesa / "
      "EGL) | readback (OSMesa / EGL) | PNG encode | warm figure | cold figure (OSMesa / EGL) |\n"
      "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  for (const Figure& f : figs)
    if (rep.ran(f.spec.id + "/"))
      std::printf("| `%s` | %dx%d | %s | %s | %s | %s | %s | %s | %s | %s |\n", f.spec.id.c_str(), f.spec.width,
                  f.spec.height, both(f, "context").c_str(), fmt(ms(f, "measure", O)).c_str(),
                  fmt(ms(f, "build")).c_str(), both(f, "render").c_str(), both(f, "readback").c_str(),
                  fmt(ms(f, "encode")).c_str(), fmt(ms(f, "warm", O)).c_str(), both(f, "cold").c_str());
  std::printf(
      "\nmeasure, build, encode and warm on OSMesa; measure and warm use a new scene each time. warm figure = "
      "measure + build +\nrender + readback + PNG encode on a live context (what make_figures pays per figure); cold "
      "figure = the same\nplus context creation, first texture uploads and shader compiles (one `demo --png`, minus "
      "exec and dynamic loading).\n");

  std::printf(
      "\n### Ratios\n\n| figure | measure ÷ warm | readback ÷ render | encode ÷ render | stage sum ÷ warm | cold ÷ "
      "warm | EGL ÷ OSMesa: context | render | readback | cold |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  for (const Figure& f : figs) {
    if (!rep.ran(f.spec.id + "/")) continue;
    double sum = ms(f, "measure", O) + ms(f, "build") + ms(f, "render", O) + ms(f, "readback", O) + ms(f, "encode");
    double warm = ms(f, "warm", O);
    std::printf("| `%s` | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", f.spec.id.c_str(),
                ratio(ms(f, "measure", O), warm).c_str(), ratio(ms(f, "readback", O), ms(f, "render", O)).c_str(),
                ratio(ms(f, "encode"), ms(f, "render", O)).c_str(), ratio(sum, warm).c_str(),
                ratio(ms(f, "cold", O), warm).c_str(), ratio(ms(f, "context", E), ms(f, "context", O)).c_str(),
                ratio(ms(f, "render", E), ms(f, "render", O)).c_str(),
                ratio(ms(f, "readback", E), ms(f, "readback", O)).c_str(),
                ratio(ms(f, "cold", E), ms(f, "cold", O)).c_str());
  }
  std::printf("\nOSMesa unless marked; stage sum = measure + build + render + readback + encode (≈ 1 when the "
              "stages account for the figure).\n\n");
}
}  // namespace

int main(int argc, char** argv) {
  std::vector<Figure> figs = ts::bench::registeredFigures();
  std::vector<std::string> renderers;
  for (ts::Backend b : kBackends) {
    renderers.push_back(describe(b));
    benchmark::AddCustomContext(std::string("gl_") + ts::backendName(b), renderers.back());
  }
  const ts::Backend O = ts::Backend::OSMesa;
  for (const Figure& f : figs) {
    for (ts::Backend b : kBackends)
      timed(benchmark::RegisterBenchmark(name(f, "context", b).c_str(), benchContext, f, b));
    timed(benchmark::RegisterBenchmark(name(f, "measure", O).c_str(), benchMeasure, f, O));
    timed(benchmark::RegisterBenchmark(name(f, "build").c_str(), benchBuild, f));
    for (ts::Backend b : kBackends)
      timed(benchmark::RegisterBenchmark(name(f, "render", b).c_str(), benchRender, f, b));
    for (ts::Backend b : kBackends)
      timed(benchmark::RegisterBenchmark(name(f, "readback", b).c_str(), benchReadback, f, b));
    timed(benchmark::RegisterBenchmark(name(f, "render_after_recording", O).c_str(), benchRenderRecorder, f, false));
    timed(benchmark::RegisterBenchmark(name(f, "render_recording", O).c_str(), benchRenderRecorder, f, true));
    timed(benchmark::RegisterBenchmark(name(f, "encode").c_str(), benchEncode, f));
    timed(benchmark::RegisterBenchmark(name(f, "warm", O).c_str(), benchWarm, f, O));
    for (ts::Backend b : kBackends) timed(benchmark::RegisterBenchmark(name(f, "cold", b).c_str(), benchCold, f, b));
  }
  return ts::bench::run(argc, argv, [&](const ts::bench::SummaryReporter& rep) { summary(rep, figs, renderers); });
}
