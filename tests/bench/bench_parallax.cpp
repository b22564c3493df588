// bench_parallax — milliseconds per frame of each filtering mode of the
// parallax demo (seed 003) at 800 x 600 on llvmpipe (OSMesa), bricks at 20
// degrees, the demo's default view:
//
//   parallax/<mode>              M0..M5, one full frame + glFinish
//   parallax/<mode>/no-accel     M4, M5 without the max-height bound (same image)
//   parallax/<mode>/plain-trace  M4, M5 with the visibility trace reading every
//                                sample's texel (same image, more lookups)
//   parallax/<mode>/no-parallax  M1, M2 without the march (depth 0): what the rest
//                                of the mode costs; for M2 llvmpipe's anisotropic filter
//   parallax/<mode>/unshifted-lookup  M1, M2 with the march, the albedo read at
//                                the unshifted coordinate: the mode minus this is
//                                what the shifted coordinate's jumps at occluding
//                                edges cost the filter
//
// Speed is measured here, never asserted.  Medians of 5 repetitions by
// default (any benchmark flag overrides); a frame of M4 takes seconds, so
// each repetition is one or a few frames.  Afterwards it prints a markdown
// table: ms per frame, frames per second, and how far each mode is from the
// 20 frames per second (50 ms) a window needs to feel interactive.  The
// renderer string is printed with it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "common/gl/context.hpp"
#include "common/gl/render.hpp"
#include "demos/parallax_aniso/parallax_aniso_gl.hpp"
#include "demos/parallax_aniso/parallax_aniso_math.hpp"

namespace {
struct Rig {
  Rig() {
    ts::ContextOptions o;
    o.width = 800;
    o.height = 600;
    ctx = ts::createOffscreenContext(ts::Backend::OSMesa, o);
    renderer = std::make_unique<ts::Renderer>(*ctx);
    gl = std::make_unique<pax::ReliefGL>(*renderer);
    relief = pax::makeRelief("bricks");
    cam.width = 800;
    cam.height = 600;
  }
  std::unique_ptr<ts::Context> ctx;
  std::unique_ptr<ts::Renderer> renderer;
  std::unique_ptr<pax::ReliefGL> gl;
  pax::Relief relief;
  pax::Camera cam;
};
Rig& rig() {
  static Rig r;
  return r;
}

void benchMode(benchmark::State& st, int mode, pax::PassOptions o) {  // default o: the demo's own pass
  try {
    Rig& r = rig();
    r.gl->draw(r.cam, r.relief, mode, o);  // compile, upload, JIT
    glFinish();
    for (auto _ : st) {
      r.gl->draw(r.cam, r.relief, mode, o);
      glFinish();
    }
    st.counters["fps"] = benchmark::Counter(double(st.iterations()), benchmark::Counter::kIsRate);
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}
}  // namespace

int main(int argc, char** argv) {
  ts::bench::Args args(argc, argv,
                       {"--benchmark_repetitions=5", "--benchmark_report_aggregates_only=true",
                        "--benchmark_min_time=0.05"});
  // Every benchmark is parallax/<mode><suffix>: a mode's pass with options o.
  struct Variant {
    const char* suffix;
    const char* label;  // after the mode's name in the table
    pax::PassOptions o;
    bool (*appliesTo)(int mode);
  };
  auto every = [](int) { return true; };
  auto traced = [](int m) { return m >= pax::kEwaVis; };  // M4, M5
  auto hardware = [](int m) { return m == pax::kTrilinear || m == pax::kAniso16; };
  std::vector<Variant> variants(5);
  variants[0] = {"", "", {}, every};
  variants[1] = {"/no-accel", " (no max-height bound)", {}, traced};
  variants[1].o.accel = false;
  variants[2] = {"/plain-trace", " (trace reading every sample)", {}, traced};
  variants[2].o.plainTrace = true;
  // What the modes cost without the parallax march (the flat top, depth 0):
  // the floor the march adds to; for M2 that is llvmpipe's anisotropic filter.
  variants[3] = {"/no-parallax", " without the parallax march (flat top)", {}, hardware};
  variants[3].o.parallax = false;
  // With the march but the albedo read at the unshifted coordinate: the
  // difference to the mode is what the shifted coordinate's jumps at
  // occluding edges cost (llvmpipe's anisotropic filter takes its footprint
  // from the coordinate's quad differences, whatever textureGrad is given).
  variants[4] = {"/unshifted-lookup", " with the march, albedo read at the unshifted coordinate", {}, hardware};
  variants[4].o.unshiftedLookup = true;
  auto name = [](int m, const Variant& v) { return std::string("parallax/") + pax::kModeKeys[m] + v.suffix; };
  for (int m = 0; m < pax::kShaderModes; ++m)
    for (const Variant& v : variants)
      if (v.appliesTo(m))
        benchmark::RegisterBenchmark(name(m, v).c_str(), [m, o = v.o](benchmark::State& st) { benchMode(st, m, o); })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
  benchmark::Initialize(args.argc(), args.argv());
  ts::bench::SummaryReporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  std::printf("\nparallax_aniso at 800x600, bricks, 20 degrees, %s\n\n", ts::gl::rendererString().c_str());
  std::printf("| mode | ms/frame (median) | frames/s | x the 50 ms of 20 fps |\n|---|---|---|---|\n");
  for (int m = 0; m < pax::kShaderModes; ++m)
    for (const Variant& v : variants) {
      double ms = v.appliesTo(m) ? rep.ms(name(m, v)) : std::nan("");
      if (!std::isnan(ms))
        std::printf("| %s%s | %.1f | %.2f | %.2f |\n", pax::kModeLabels[m], v.label, ms, 1000.0 / ms, ms / 50.0);
    }
  rig().renderer->release();
  return 0;
}
