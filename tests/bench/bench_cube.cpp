// bench_cube — the dynamic cube map's pass (demos/dynamic_reflection): the scene rendered from the mirror
// sphere's centre and copied into the faces of a GL_TEXTURE_CUBE_MAP by glCopyTexSubImage2D, all six faces
// against only the faces a reflector reads (the lab sheet §2.1: render only the faces that are seen).  The
// faces read are found as the demo's faces_read[...] is, before the clock runs: the reflector drawn with the
// face-ID cube map and its colours counted (the flat mirror 1, the sphere 6, the torus between).  Reported: ms
// per cube pass (glFinish included) at 128 texels a face, the demo's default (OSMesa, llvmpipe).  Speed is
// measured, never asserted.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "bench_common.hpp"
#include "bench_gl.hpp"
#include "common/gl/context.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"
#include "demos/dynamic_reflection/dynamic_reflection_gl.hpp"
#include "demos/dynamic_reflection/dynamic_reflection_views.hpp"

namespace {
namespace dr = dynref;
constexpr int kFace = 128;     // texels a face's side
constexpr double kTime = 1.5;  // the ball's time, the demo's default
constexpr int kEyeSize = 256;  // the face-ID render that finds the faces read

ts::bench::GLRig& rig() {
  static ts::bench::GLRig r(64, 64);
  return r;
}

// The faces `reflector` reads, a bit a face: its render with the face-ID cube map, the face colours in it.
unsigned facesRead(ts::Renderer& r, int reflector) {
  const ts::Image img = r.renderOffscreen(
      dr::eyeFrame(kEyeSize, dr::faceIdCube(), reflector, false, dr::ballCentre(kTime)));
  unsigned mask = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int f = 0; f < 6; ++f) {
        const ts::Rgba p = img.at(x, y), c = dr::kFaceIds[f];
        if (p.r == c.r && p.g == c.g && p.b == c.b) mask |= 1u << f;
      }
  return mask;
}

// reflector < 0: all six faces, whatever reads them.
void benchCube(benchmark::State& st, int reflector) {
  try {
    ts::Renderer& r = *rig().renderer;
    const unsigned faces = reflector < 0 ? 0x3fu : facesRead(r, reflector);
    const ts::Frame pass = dr::cubeFrame(kFace, dr::ballCentre(kTime), dr::kRight, dr::kColours, dr::kBallRadius, true,
                                         faces);
    const GLuint cube = dr::makeCubeMap(kFace);
    dr::renderIntoCube(r, pass, cube);  // the environment map uploaded before the clock runs
    glFinish();
    for (auto _ : st) {
      dr::renderIntoCube(r, pass, cube);
      glFinish();
    }
    glDeleteTextures(1, &cube);
    int n = 0;
    for (int f = 0; f < 6; ++f) n += faces >> f & 1u;
    st.counters["faces_rendered"] = n;
    st.counters["frames_per_s"] = benchmark::Counter(double(st.iterations()), benchmark::Counter::kIsRate);
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}
}  // namespace

int main(int argc, char** argv) {
  for (int k = -1; k < dr::kReflectors; ++k)
    benchmark::RegisterBenchmark((k < 0 ? std::string("cube_pass/all_6_faces")
                                        : "cube_pass/faces_read/" + std::string(dr::kReflectorKeys[k]))
                                     .c_str(),
                                 benchCube, k)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  return ts::bench::run(argc, argv);
}
