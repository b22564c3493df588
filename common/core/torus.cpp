#include "common/core/torus.hpp"

#include <cmath>

namespace ts {
Mesh torusMesh(const TorusShape& t, glm::dvec2 stOffset) {
  return parametricGrid(
      t.nu, t.nv, /*periodicU=*/true, /*periodicV=*/true,
      [&](int i, int j) { return torusPoint(t.R, t.r, t.nu, t.nv, i, j); },
      [&](int i, int j) { return glm::dvec2(double(i) / t.nu, double(j) / t.nv) + stOffset; });
}

TorusFrame torusFrame(double R, double r, double thetaRad, double phiRad) {
  // The names torus_frame.inl is written with: GLSL's vec3, sin and cos are
  // glm's dvec3 and the standard library's here, in double precision.
  using vec3 = glm::dvec3;
  using std::cos;
  using std::sin;
  const double TAU = kTau, th = thetaRad, ph = phiRad;
  TorusFrame f;
  vec3 &Q = f.Q, &N = f.N, &Qs = f.Qs, &Qt = f.Qt, &Ns = f.Ns, &Nt = f.Nt;
#include "common/core/torus_frame.inl"
  f.T = dTh, f.B = dPh;
  return f;
}

const char* const kTorusFrameGLSL =
#include "torus_frame_glsl.inc"  // torus_frame.inl as a string (common/CMakeLists.txt)
    ;
}  // namespace ts
