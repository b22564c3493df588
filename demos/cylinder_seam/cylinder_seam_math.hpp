// demos/cylinder_seam/cylinder_seam_math.hpp — the mathematics of Figures VI.3 and
// VI.4 and Exercise VI.1 (Buss, VI.1.2).
//
// The side of a cylinder, p(θ, y) = (r sin θ, y, r cos θ), -h/2 <= y <= h/2,
// cut into `slices` patches by columns i = 0..slices at
//     θ_i = θ0 + 360 i / slices,   θ0 = -180 / slices,
// so patch 0 (columns 0 and 1) is centred on the front (θ = 0, the +z axis):
// with 5 slices its columns are at θ = -36° (vertices x, w) and +36° (y, z),
// the book's Figure VI.4 patch.  Eq. VI.1: s = θ/360, t = (y + h/2)/h;
// Exercise VI.1 moves the seam to the back with s = θ/360 + 1/2.
//
// Two ways to give column i its s:
//   * Wrong: s_i = (θ_i/360 + shift) reduced to [0, 1) for each vertex on its
//     own.  The patch across the seam gets s = 0.9 at x, w and 0.1 at y, z and
//     shows the long region 0.1..0.9 of the texture, backwards.
//   * Right: track the winding number: s_i = s_0 + i / slices, so the seam
//     patch gets 0.9 -> 1.1 and GL_REPEAT shows 0.9..1 then 0..0.1.
// θ_i / 360 = (2i - 1) / (2 slices) exactly, so both are computed from that
// integer fraction: no round-off decides which side of the seam a column at
// exactly θ = 180° falls on (it happens for odd slice counts, seam at back).
//
// Positions come from ts::parametricGrid + ts::cylinderPoint, which evaluates
// the *wrapped* column (i mod slices): column `slices` is bit-identical to
// column 0 (Buss III.3.2: shared vertices computed the same way every time).
// Header-only so the demo and the tests share one copy.
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <functional>

#include "common/core/mesh.hpp"

namespace cylinder {
enum class Coords { Wrong, Right };
enum class Seam { Front, Back };

struct Params {
  double r = 1.0;
  double h = 2.5;  // a label a little taller than the radius: rows stay readable
  int slices = 5;  // the book's patch: 72° wide
  int stacks = 1;  // s does not depend on y: one patch per column, as x,y,z,w
  Coords coords = Coords::Wrong;
  Seam seam = Seam::Front;
  // Exercise VI.1 as a student writes it (exercises/vi1_back_seam.cpp): s
  // at θ in [0°, 360°).  When set, it gives column i its s, the turns past
  // 0° added (GL_REPEAT: s + 1 shows what s shows), in place of `coords`.
  std::function<double(double)> sOfTheta;
};

// The same expression ts::cylinderPoint uses for column i.
inline double theta0Deg(int slices) { return -180.0 / slices; }
inline double thetaDeg(int slices, int i) { return theta0Deg(slices) + 360.0 * i / slices; }

// (θ_i / 360 + shift) * 2 slices as an integer: 2i - 1, plus `slices` for
// the back seam (shift 1/2).
inline long halfSteps(const Params& p, int i) { return 2L * i - 1 + (p.seam == Seam::Back ? p.slices : 0); }
inline long mod(long a, long m) { return ((a % m) + m) % m; }

// s of column i.
inline double sOf(const Params& p, int i) {
  if (p.sOfTheta) {
    const double th = thetaDeg(p.slices, i), turns = std::floor(th / 360.0);
    return p.sOfTheta(th - 360.0 * turns) + turns;
  }
  const long n2 = 2L * p.slices;
  if (p.coords == Coords::Wrong) return double(mod(halfSteps(p, i), n2)) / double(n2);  // reduced per vertex
  return double(mod(halfSteps(p, 0), n2) + 2L * i) / double(n2);                        // winding tracked
}
// t of row j: (y + h/2)/h with y = -h/2 + h j / stacks.
inline double tOf(const Params& p, int j) { return double(j) / p.stacks; }

// The patch the texture's left and right edges meet in: the k whose
// correctly assigned interval (s_k, s_k+1] holds an integer.  Front seam:
// patch 0; back seam: slices / 2.
inline int seamPatch(const Params& p) {
  if (p.sOfTheta) {  // a student's s: the patch whose ends lie in different turns
    for (int k = 0; k < p.slices; ++k)
      if (std::floor(sOf(p, k)) != std::floor(sOf(p, k + 1))) return k;
    return 0;
  }
  const long n2 = 2L * p.slices, a0 = mod(halfSteps(p, 0), n2);
  for (int k = 0; k < p.slices; ++k) {
    long lo = a0 + 2L * k, hi = lo + 2;  // s_k and s_k+1 in units of 1/n2
    if (lo / n2 != hi / n2) return k;
  }
  return 0;
}

// The s a patch shows from its left edge (column k) to its right edge
// (column k+1) as seen from outside: right - left, signed.  Right: 1/slices;
// wrong across the seam: -(1 - 1/slices).
inline double patchSpan(const Params& p, int k) { return sOf(p, k + 1) - sOf(p, k); }

inline ts::Mesh mesh(const Params& p) {
  return ts::parametricGrid(
      p.slices, p.stacks, /*periodicU=*/true, /*periodicV=*/false,
      [&](int i, int j) { return ts::cylinderPoint(p.r, p.h, p.slices, p.stacks, i, j, theta0Deg(p.slices)); },
      [&](int i, int j) { return glm::dvec2(sOf(p, i), tOf(p, j)); });
}

// A point of the cylinder at angle θ (degrees) and height y.
inline glm::dvec3 point(double r, double thetaDegrees, double y) {
  double th = ts::degToRad(thetaDegrees);
  return {r * std::sin(th), y, r * std::cos(th)};
}
}  // namespace cylinder
