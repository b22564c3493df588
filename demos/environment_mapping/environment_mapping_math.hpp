// demos/environment_mapping/environment_mapping_math.hpp — the world around the object and
// the four ways of storing it (Buss VI.3; seed 001's lat-long, cube, sphere
// and paraboloid maps; seed 002's sphere and cube formulas).  Pure CPU, no
// GL: the tests check it, and the measurement decodes GL's read-backs with it.
//
// The maps themselves (lat-long, cube, sphere, dual paraboloid: each
// direction's (s, t) and back), their sizes at equal memory and the world's
// colours live in common/core/env_maps.hpp, which the CPU reference shares
// to remake the figures' maps from their sidecars; this file adds the seeds'
// variants and the solid angle of a texel.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/env_maps.hpp"
#include "common/core/image.hpp"

namespace envmap {
using glm::dvec2;
using glm::dvec3;
using namespace ts::envmaps;  // the maps and the world: common/core/env_maps.hpp (the reference remakes them)

inline const char* const kParamLabels[] = {"lat-long", "cube map", "sphere map", "dual paraboloid"};

// Seed 001's rule as its worked example applies it: the two other components
// in (x, y, z) order, divided by |ma|, mapped to [0,1], no signs (the seed's
// example: (-3.2, 5.1, -8.4) -> ((-3.2/8.4 + 1)/2, (5.1/8.4 + 1)/2)).
inline CubeST seedCubeST(dvec3 r) {
  CubeST gl = cubeST(r);
  const int axis = gl.face / 2;
  const double ma = std::abs(r[axis]);
  const int i = axis == 0 ? 1 : 0, j = axis == 2 ? 1 : 2;
  return {gl.face, (r[i] / ma + 1) / 2, (r[j] / ma + 1) / 2};
}
// Seed 002: u = N_x/2 + 1/2, v = N_y/2 + 1/2 from the surface normal (eye
// space).  It is GL_SPHERE_MAP's (s, t) when the eye looks along -z at the
// point (I = (0,0,-1)), and not elsewhere.
inline dvec2 seedSphereST(dvec3 nEye) { return {nEye.x / 2 + 0.5, nEye.y / 2 + 0.5}; }

// ---- solid angle ---------------------------------------------------------
// Texels per steradian varies over a map: its largest / smallest value (=
// the largest / smallest texel's solid angle) measures how evenly the map
// spends its memory.  Analytic per texel where a closed form exists:
//   lat-long: a row's texels span Δλ (sin φ1 - sin φ0)
//   cube: a face texel [x0,x1] x [y0,y1] (face at distance 1) spans
//         F(x1,y1) - F(x0,y1) - F(x1,y0) + F(x0,y0), F = atan2(xy, sqrt(1 + x^2 + y^2))
//   sphere: dΩ/dA = 4 on the disc (ρ = sin(θ/2) gives ρ dρ = sin θ dθ / 4):
//         every texel inside the disc spans the same 4 (2/n)^2
//   paraboloid: dΩ/dA = 4 / (1 + ρ^2)^2, 4 at the centre, 1 at the rim
//         (here at the texel's centre, times its area: exact to O(texel^2))
// and numerically for all four by splitting each texel into k x k cells and
// summing the spherical triangles between their corners' directions.
inline double triangleSolidAngle(dvec3 a, dvec3 b, dvec3 c) {  // Van Oosterom & Strackee
  a = glm::normalize(a), b = glm::normalize(b), c = glm::normalize(c);
  return 2 * std::atan2(std::abs(glm::dot(a, glm::cross(b, c))), 1 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a));
}
struct Uniformity {
  double analyticMax = 0, analyticMin = 1e300, numericMax = 0, numericMin = 1e300;
  double largestRelDiff = 0;  // max over texels of |numeric - analytic| / analytic
  double analyticRatio() const { return analyticMax / analyticMin; }
  double numericRatio() const { return numericMax / numericMin; }
};
// Texels counted: all of lat-long and cube; of the sphere and paraboloid
// maps those wholly inside their discs (the others are partly unused).
inline Uniformity uniformity(Param p, int faceTexels, int k = 6) {
  const Size sz = mapSize(p, faceTexels);
  const glm::dmat3 I(1.0);
  Uniformity u;
  auto F = [](double x, double y) { return std::atan2(x * y, std::sqrt(1 + x * x + y * y)); };
  for (int j = 0; j < sz.h; ++j)
    for (int i = 0; i < sz.w; ++i) {
      const double s0 = double(i) / sz.w, s1 = double(i + 1) / sz.w, t0 = double(j) / sz.h, t1 = double(j + 1) / sz.h;
      double analytic;
      if (p == kLatLong) {
        analytic = 2 * kPi / sz.w * (std::sin((t1 - 0.5) * kPi) - std::sin((t0 - 0.5) * kPi));
      } else if (p == kCube) {
        const double x0 = 2 * s0 - 1, x1 = 2 * s1 - 1, y0 = 2 * t0 - 1, y1 = 2 * t1 - 1;
        analytic = F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0);
      } else {
        const double back = p == kParaboloid && i >= sz.w / 2 ? 1.0 : 0.0, k2 = p == kParaboloid ? 2.0 : 1.0;
        const double ls0 = k2 * s0 - back, ls1 = k2 * s1 - back;  // s across the texel's disc
        const double xs[] = {2 * ls0 - 1, 2 * ls1 - 1}, ys[] = {2 * t0 - 1, 2 * t1 - 1};
        bool inside = true;
        for (double x : xs)
          for (double y : ys) inside = inside && x * x + y * y <= 1;
        if (!inside) continue;
        const double area = (xs[1] - xs[0]) * (ys[1] - ys[0]);
        const double xc = (xs[0] + xs[1]) / 2, yc = (ys[0] + ys[1]) / 2, rho2 = xc * xc + yc * yc;
        analytic = p == kSphere ? 4 * area : 4 * area / ((1 + rho2) * (1 + rho2));
      }
      double numeric = 0;
      for (int b = 0; b < k; ++b)
        for (int a = 0; a < k; ++a) {
          auto dir = [&](int da, int db) {
            return texelDir(p, 0, s0 + (s1 - s0) * (a + da) / k, t0 + (t1 - t0) * (b + db) / k, I);
          };
          const dvec3 c00 = dir(0, 0), c10 = dir(1, 0), c11 = dir(1, 1), c01 = dir(0, 1);
          numeric += triangleSolidAngle(c00, c10, c11) + triangleSolidAngle(c00, c11, c01);
        }
      u.analyticMax = std::max(u.analyticMax, analytic), u.analyticMin = std::min(u.analyticMin, analytic);
      u.numericMax = std::max(u.numericMax, numeric), u.numericMin = std::min(u.numericMin, numeric);
      u.largestRelDiff = std::max(u.largestRelDiff, std::abs(numeric - analytic) / analytic);
    }
  return u;
}

// Lat-long's seam across a triangle (seed 001): s jumps from 1 back to 0 where the longitude wraps, so a
// triangle with corners on both sides, its s interpolated per vertex, runs the long way round the map.  The
// sources' fix, per triangle: when two corners' s differ by more than 1/2, add 1 to the smaller one (0.97 and
// 0.02 become 0.97 and 1.02), and draw with GL_REPEAT, which wraps s in [1, 1.5] back onto the map.  Near a
// pole the longitude itself means nothing (every s meets there), so no shift of s mends it.
inline void plusOneRule(glm::vec2 corner[3]) {
  const float largest = std::max({corner[0].x, corner[1].x, corner[2].x});
  for (int k = 0; k < 3; ++k)
    if (largest - corner[k].x > 0.5f) corner[k].x += 1.0f;
}
}  // namespace envmap
