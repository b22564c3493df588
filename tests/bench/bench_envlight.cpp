// bench_envlight — ms per frame of lighting from an environment map
// (demos/env_lighting) against per-pixel Phong, at 1, 4 and 16 lights: the
// sphere filling a 768x768 frame offscreen on OSMesa (llvmpipe), drawn by the
// demo's own Frame and GLSL programs (env_lighting_views.hpp), glFinish and
// readback included.  The map method reads one texel block a pixel whatever
// the number of lights, so its time should stay flat; Phong's loop grows
// with the lights.  The map is made once per light count (uploaded on the
// first frame and cached by the renderer), as a static scene's would be.
// Speed is measured, never asserted.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "bench_common.hpp"
#include "bench_gl.hpp"
#include "common/gl/context.hpp"
#include "common/gl/render.hpp"
#include "demos/env_lighting/env_lighting_views.hpp"

namespace {
constexpr int kSize = 768, kFace = 64;

ts::bench::GLRig& rig() {
  static ts::bench::GLRig r(kSize, kSize);
  return r;
}

void benchMethod(benchmark::State& st, envlight::Method m, int lights) {
  try {
    ts::bench::GLRig& r = rig();
    const ts::Frame f = envlight::sphereFrame(m, lights, kFace, kSize, kSize);
    r.renderer->render(f, false);  // warm: the program compiled, the map uploaded
    for (auto _ : st) benchmark::DoNotOptimize(r.renderer->render(f, false).pixels.data());
    st.counters["fps"] = benchmark::Counter(double(st.iterations()), benchmark::Counter::kIsRate);
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}
}  // namespace

int main(int argc, char** argv) {
  for (envlight::Method m : {envlight::kMap, envlight::kPhong})
    for (int n : envlight::kLightCounts)
      benchmark::RegisterBenchmark(
          (std::string("envlight/") + envlight::kMethodKeys[m] + "/lights:" + std::to_string(n)).c_str(), benchMethod,
          m, n)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
  return ts::bench::run(argc, argv);
}
