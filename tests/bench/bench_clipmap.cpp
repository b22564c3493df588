// bench_clipmap — what keeping demos/texture_residency's clipmap up to date costs: one move of the eye (each of
// the six 512^2 levels gets only the strips that entered its window, glTexSubImage2D into their toroidal places)
// against reloading every window whole (OSMesa, llvmpipe).  Both times include computing the procedural texels,
// as the demo does: the virtual texture is never stored.  Reported: time per update (glFinish included) and the
// texels each sends.  Speed is measured, never asserted.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "bench_common.hpp"
#include "bench_gl.hpp"
#include "common/gl/context.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"
#include "demos/texture_residency/texture_residency_gl.hpp"

namespace {
namespace R = ts::residency;

ts::bench::GLRig& rig() {
  static ts::bench::GLRig r(64, 64);
  return r;
}

void benchClipmap(benchmark::State& st, bool reload) {
  try {
    rig();
    R::ClipStack stack;
    stack.load(R::kEyeStart);
    glFinish();
    int k = 0;
    long long texels = 0;
    for (auto _ : st) {
      const R::Eye from = R::eyeAfter(k), to = R::eyeAfter(k + 1);
      if (reload) stack.load(to), texels += R::kClipLevels * (long long)R::kClip * R::kClip;
      else stack.move(from, to), texels += R::exposedTexels(from, to);
      glFinish();
      ++k;
    }
    st.SetBytesProcessed(texels * 4);
    st.counters["texels_per_update"] = double(texels) / double(std::max<int64_t>(1, st.iterations()));
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}
}  // namespace

int main(int argc, char** argv) {
  for (bool reload : {false, true})
    benchmark::RegisterBenchmark(reload ? "clipmap/reload" : "clipmap/move", benchClipmap, reload)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  return ts::bench::run(argc, argv);
}
