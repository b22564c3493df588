// demos/torus/torus_math.hpp — the mathematics of Exercise VI.2 (Buss,
// VI.1.2): where the texture's centre lands on the torus of Figure VI.6,
// and the demo's camera.  The torus itself (its points, normals, tangents
// and mesh) is common/core/torus.hpp.
//
// The torus p(θ, φ) = ((R + r cos φ) sin θ, r sin φ, (R + r cos φ) cos θ),
// θ, φ in [0°, 360°), R the major and r the minor radius, with the book's
// texture coordinates s = θ/360, t = φ/360.
//
// Exercise VI.2: the centre of the texture, (s, t) = (1/2, 1/2), lands at
// θ = 180°, φ = 180°: the point (0, 0, -(R - r)), on the inner wall of the
// hole at the back (its normal (0, 0, 1) faces the front, so it can be seen
// through the hole from above).  Adding 1/2 to both, s = θ/360 + 1/2 and
// t = φ/360 + 1/2, moves it to θ = φ = 0: the point (0, 0, R + r) at the
// front, on the positive z axis.  (GL_REPEAT makes s and t in [1/2, 3/2)
// show the same texture, shifted.)
//
// The mesh is ts::torusMesh with the mapping's offset added to every
// (s, t).  nu and nv are even, so a grid vertex sits exactly on the centre.
// Header-only so the demo and the tests share one copy.
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <functional>

#include "common/core/torus.hpp"

namespace torus {
enum class Mapping { Book, Front };

// The torus (ts::TorusShape's defaults: R = 1, r = 0.4, 48 x 24 cells) and
// how the texture is put on it.
struct Params : ts::TorusShape {
  Mapping mapping = Mapping::Book;
  // Exercise VI.2 as a student writes it (exercises/vi2_torus_front.cpp):
  // (s, t) at (θ, φ) in [0°, 360°).  When set, it gives grid vertex (i, j)
  // its (s, t), the last column and row (θ, φ = 360°) one turn on, in place
  // of `mapping`.
  std::function<glm::dvec2(double, double)> stOfAngles;
};

// What is added to (θ/360, φ/360): (0, 0) for the book, (1/2, 1/2) for the exercise.
inline glm::dvec2 offset(Mapping m) { return m == Mapping::Book ? glm::dvec2(0.0) : glm::dvec2(0.5); }

// (s, t) = (i/nu, j/nv) + offset at grid vertex (i, j).
inline ts::Mesh mesh(const Params& p) {
  if (!p.stOfAngles) return ts::torusMesh(p, offset(p.mapping));
  return ts::parametricGrid(
      p.nu, p.nv, /*periodicU=*/true, /*periodicV=*/true,
      [&](int i, int j) { return ts::torusPoint(p.R, p.r, p.nu, p.nv, i, j); },
      [&](int i, int j) {
        return p.stOfAngles(360.0 * (i % p.nu) / p.nu, 360.0 * (j % p.nv) / p.nv) + glm::dvec2(i / p.nu, j / p.nv);
      });
}

// (θ, φ) in degrees where (s, t) = (1/2, 1/2) lands: solve θ/360 + o = 1/2
// (mod 1) for θ in [0, 360).
inline glm::dvec2 centreAngles(Mapping m) {
  glm::dvec2 a = (glm::dvec2(0.5) - offset(m)) * 360.0;
  return {std::fmod(a.x + 360.0, 360.0), std::fmod(a.y + 360.0, 360.0)};
}
// The torus's frame there (its point Q, normal N, tangents T and B).
inline ts::TorusFrame centreFrame(const Params& p) {
  glm::dvec2 a = centreAngles(p.mapping);
  return ts::torusFrame(p.R, p.r, ts::degToRad(a.x), ts::degToRad(a.y));
}
// The exercise's answer: (0, 0, -(R - r)) for the book, (0, 0, R + r) in front.
inline glm::dvec3 centrePoint(const Params& p) { return centreFrame(p).Q; }
// The demo's camera: the eye on a sphere of this radius about the centre,
// `tilt` degrees above the torus's plane (5.2 for R + r = 1.4: the whole
// ring fits a 35° field of view at any tilt).
inline double eyeDistance(const Params& p) { return 5.2 * (p.R + p.r) / 1.4; }

// The book's centre (0, 0, -(R - r)) is seen through the hole once the line
// of sight to it clears the near side of the ring, the circle of radius r
// about (y, z) = (0, R) in the plane x = 0:
//   (2R - r) D sin(tilt) / |(D sin(tilt), D cos(tilt) + R - r)| > r.
// The smallest such tilt in degrees (16.1° for the defaults), by bisection.
inline double minTiltToSeeBookCentre(const Params& p) {
  const double D = eyeDistance(p);
  auto clear = [&](double deg) {
    double a = ts::degToRad(deg), y = D * std::sin(a), z = D * std::cos(a) + p.R - p.r;
    return (2 * p.R - p.r) * y / std::hypot(y, z) - p.r;
  };
  double lo = 0.0, hi = 90.0;
  for (int k = 0; k < 60; ++k) (clear((lo + hi) / 2) > 0 ? hi : lo) = (lo + hi) / 2;
  return hi;
}

// The grid vertex that carries (s, t) = (1/2, 1/2).
inline glm::ivec2 centreVertex(const Params& p) {
  glm::dvec2 a = centreAngles(p.mapping);
  return {int(std::lround(a.x / 360.0 * p.nu)), int(std::lround(a.y / 360.0 * p.nv))};
}
}  // namespace torus
