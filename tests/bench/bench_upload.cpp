// bench_upload — the upload rate of an animated texture (demos/texture_animation's flipbook): one texture made
// once, each frame of the flame's loop sent by glTexSubImage2D, whole or only the rectangle where it differs
// from the frame before, at 64^2, 256^2 and 1024^2 texels (OSMesa, llvmpipe).  Reported: time per upload (glFinish
// included), uploads a second and bytes a second.  Speed is measured, never asserted.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "bench_gl.hpp"
#include "common/gl/context.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"
#include "demos/texture_animation/texture_animation_gl.hpp"

namespace {
namespace ta = ts::texanim;

ts::bench::GLRig& rig() {
  static ts::bench::GLRig r(64, 64);
  return r;
}

// The loop's frames at `size` and, per frame, what its upload sends: all of it, or the changed rectangle.
struct Loop {
  std::vector<ts::Image> frames;
  std::vector<ta::TexRect> rects;
};
Loop loop(int size, bool partial) {
  Loop l;
  for (int k = 0; k < ta::kFlipFrames; ++k) l.frames.push_back(ta::flameFrame(size, k, ta::kFlipFrames));
  for (int k = 0; k < ta::kFlipFrames; ++k) {
    const ts::Image& before = l.frames[size_t((k + ta::kFlipFrames - 1) % ta::kFlipFrames)];
    l.rects.push_back(partial ? ta::changedRect(before, l.frames[size_t(k)]) : ta::TexRect{0, 0, size, size});
  }
  return l;
}

void benchUpload(benchmark::State& st, int size, bool partial) {
  try {
    rig();
    const Loop l = loop(size, partial);
    std::vector<ts::Image> parts;  // packed before the clock runs: the benchmark times the upload alone
    for (int k = 0; k < ta::kFlipFrames; ++k) parts.push_back(ta::subImage(l.frames[size_t(k)], l.rects[size_t(k)]));
    const GLuint tex = ts::texture2D(size, size, &l.frames[0], GL_NEAREST, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    size_t k = 0;
    int64_t bytes = 0;
    for (auto _ : st) {
      const ta::TexRect& r = l.rects[k];
      glTexSubImage2D(GL_TEXTURE_2D, 0, r.x, r.y, r.w, r.h, GL_RGBA, GL_UNSIGNED_BYTE, parts[k].pixels.data());
      glFinish();
      bytes += int64_t(r.texels()) * 4;
      k = (k + 1) % parts.size();
    }
    glDeleteTextures(1, &tex);
    st.SetBytesProcessed(bytes);
    st.counters["uploads_per_s"] = benchmark::Counter(double(st.iterations()), benchmark::Counter::kIsRate);
    st.counters["bytes_per_upload"] = double(bytes) / double(std::max<int64_t>(1, st.iterations()));
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}
}  // namespace

int main(int argc, char** argv) {
  for (int size : {64, 256, 1024})
    for (bool partial : {false, true})
      benchmark::RegisterBenchmark(
          ("upload/" + std::string(partial ? "partial/" : "whole/") + std::to_string(size)).c_str(), benchUpload, size,
          partial)
          ->Unit(benchmark::kMicrosecond)
          ->UseRealTime();
  return ts::bench::run(argc, argv);
}
