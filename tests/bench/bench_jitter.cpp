// bench_jitter — time per frame of each Figure VI.7 sampling mode at
// 1024x768, offscreen on OSMesa (llvmpipe), the way the demo makes each image:
//   one            one pass, samples at the pixel centres
//   regular        n*n passes with the projection shifted to the subpixel
//                  centres, averaged in the accumulation buffer (Red Book)
//   jitter_global  the same with one jittered offset per subpixel for all pixels
//   jitter_pixel   one pass of the fragment shader that jitters per pixel
//   *_fbo          the multi-pass modes averaged in FBOs (the EGL path)
// n = 3 (the book's 3x3).  Reported: median ms per finished frame (glFinish
// and readback included).  Speed is measured, never asserted.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "common/gl/context.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"
#include "demos/jitter/jitter_gl.hpp"

namespace {
constexpr int kW = 1024, kH = 768, kN = 3;
constexpr uint32_t kSeed = 1;

enum class Mode { One, Regular, JitterGlobal, JitterPixel };
enum class Average { Accum, Fbo };

struct Rig {
  Rig() {
    ts::ContextOptions o;
    o.width = kW;
    o.height = kH;
    o.accumBuffer = true;
    ctx = ts::createOffscreenContext(ts::Backend::OSMesa, o);
    renderer = std::make_unique<ts::Renderer>(*ctx);
    cam.width = kW;
    cam.height = kH;
  }
  ~Rig() { renderer->release(); }
  std::unique_ptr<ts::Context> ctx;
  std::unique_ptr<ts::Renderer> renderer;
  jitter::Camera cam;
};

Rig& rig() {
  static Rig r;
  return r;
}

ts::Image frame(Rig& r, Mode m, Average a) {
  switch (m) {
    case Mode::One: return r.renderer->render(jitter::groundPass(r.cam, {0.5, 0.5}), false);
    case Mode::JitterPixel: return r.renderer->render(jitter::pixelJitterPass(r.cam, kN, kSeed), false);
    default: {
      auto p = m == Mode::Regular ? jitter::Pattern::Regular : jitter::Pattern::JitterGlobal;
      std::vector<ts::Frame> passes;
      for (glm::dvec2 off : jitter::passOffsets(p, kN, kSeed)) passes.push_back(jitter::groundPass(r.cam, off));
      return a == Average::Accum ? jitter::accumulateWithAccumBuffer(*r.renderer, passes)
                                 : jitter::accumulateWithFbo(*r.renderer, passes);
    }
  }
}

void benchMode(benchmark::State& st, Mode m, Average a) {
  try {
    Rig& r = rig();
    if (a == Average::Accum && m != Mode::One && m != Mode::JitterPixel &&
        jitter::accumStatus(*r.renderer, kW, kH) != jitter::AccumStatus::Usable) {
      st.SkipWithError("no usable accumulation buffer in this context");
      return;
    }
    frame(r, m, a);  // warm: shaders compiled, buffers allocated
    for (auto _ : st) benchmark::DoNotOptimize(frame(r, m, a).pixels.data());
    st.counters["fps"] = benchmark::Counter(double(st.iterations()), benchmark::Counter::kIsRate);
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}
}  // namespace

int main(int argc, char** argv) {
  struct Case {
    const char* name;
    Mode m;
    Average a;
  };
  const Case cases[] = {{"jitter/one", Mode::One, Average::Accum},
                        {"jitter/regular_accum", Mode::Regular, Average::Accum},
                        {"jitter/jitter_global_accum", Mode::JitterGlobal, Average::Accum},
                        {"jitter/regular_fbo", Mode::Regular, Average::Fbo},
                        {"jitter/jitter_global_fbo", Mode::JitterGlobal, Average::Fbo},
                        {"jitter/jitter_pixel", Mode::JitterPixel, Average::Accum}};
  for (const Case& c : cases)
    benchmark::RegisterBenchmark(c.name, benchMode, c.m, c.a)->Unit(benchmark::kMillisecond)->UseRealTime();
  ts::bench::Args args(argc, argv, {TS_BENCH_DEFAULT_FLAGS});
  benchmark::Initialize(args.argc(), args.argv());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
