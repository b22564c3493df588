// bench_atlas — a frame of N textured objects (demos/texture_atlas): each object with its own texture (N
// glBindTexture and N glBegin ... glEnd) against all of them from one atlas (one bind, one batch), for N = 16 and
// N = 256 squares of 32 x 32 pixels, GL_NEAREST, at 512 x 512 (OSMesa, llvmpipe).  The demo counts the calls; this
// times them: ms per frame, glFinish included.  Speed is measured, never asserted.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "bench_gl.hpp"
#include "common/gl/context.hpp"
#include "common/gl/gl.hpp"
#include "demos/texture_atlas/texture_atlas_gl.hpp"

namespace {
namespace A = ts::atlas;
constexpr int kSide = 512;  // the frame; objects are A::kTile pixels a side, kSide / A::kTile to a row

ts::bench::GLRig& rig() {
  static ts::bench::GLRig r(kSide, kSide);
  return r;
}

// Object k's square in the frame, showing (s0, t0)..(s1, t1).
void square(int k, float s0, float t0, float s1, float t1) {
  const int perRow = kSide / A::kTile;
  const float x = float((k % perRow) * A::kTile), y = float((k / perRow) * A::kTile);
  glTexCoord2f(s0, t0), glVertex2f(x, y);
  glTexCoord2f(s1, t0), glVertex2f(x + A::kTile, y);
  glTexCoord2f(s1, t1), glVertex2f(x + A::kTile, y + A::kTile);
  glTexCoord2f(s0, t1), glVertex2f(x, y + A::kTile);
}

void benchObjects(benchmark::State& st, int n, bool atlas) {
  try {
    rig();
    glViewport(0, 0, kSide, kSide);
    glMatrixMode(GL_PROJECTION), glLoadIdentity(), glOrtho(0, kSide, 0, kSide, -1, 1);
    glMatrixMode(GL_MODELVIEW), glLoadIdentity();
    glDisable(GL_DEPTH_TEST), glDisable(GL_BLEND);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    // Object k shows tile k mod N: N separate textures (one per object, as a scene of N materials has), or the atlas.
    std::vector<GLuint> textures;
    if (atlas) textures.push_back(ts::imageTexture(A::atlasImage(0)));
    else
      for (int k = 0; k < n; ++k) textures.push_back(ts::imageTexture(A::tileImage(k % A::kTiles)));
    const float side = float(A::atlasSize(0));
    for (auto _ : st) {
      glClear(GL_COLOR_BUFFER_BIT);
      if (atlas) {
        glBindTexture(GL_TEXTURE_2D, textures[0]);
        glBegin(GL_QUADS);
        for (int k = 0; k < n; ++k) {
          const int t = k % A::kTiles;
          square(k, float(A::tileX(t, 0)) / side, float(A::tileY(t, 0)) / side, float(A::tileX(t, 0) + A::kTile) / side,
                 float(A::tileY(t, 0) + A::kTile) / side);
        }
        glEnd();
      } else {
        for (int k = 0; k < n; ++k) {
          glBindTexture(GL_TEXTURE_2D, textures[size_t(k)]);
          glBegin(GL_QUADS);
          square(k, 0, 0, 1, 1);
          glEnd();
        }
      }
      glFinish();
    }
    glDeleteTextures(GLsizei(textures.size()), textures.data());
    st.counters["binds_per_frame"] = atlas ? 1 : n;
    st.counters["frames_per_s"] = benchmark::Counter(double(st.iterations()), benchmark::Counter::kIsRate);
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}
}  // namespace

int main(int argc, char** argv) {
  for (int n : {16, 256})
    for (bool atlas : {false, true})
      benchmark::RegisterBenchmark(
          ("objects/" + std::string(atlas ? "atlas/" : "separate/") + std::to_string(n)).c_str(), benchObjects, n,
          atlas)
          ->Unit(benchmark::kMicrosecond)
          ->UseRealTime();
  return ts::bench::run(argc, argv);
}
