// demos/quad_distortion/quad_distortion_math.hpp — the mathematics of Figure VI.1.
//
// A unit square, (a, b) in [0,1]^2 with a to the right and b up, gets texture
// coordinates st[0..3] at its corners (0,0), (1,0), (1,1), (0,1).  Three ways
// to fill in (s, t) inside:
//   * two triangles, each mapped linearly (what OpenGL does with a quad):
//     the map is affine on each triangle, and the two affine maps differ, so
//     the gradient of s and t jumps across the diagonal — the kink;
//   * bilinear interpolation over the quad (Buss VI.1.1): smooth everywhere;
//   * a projective map (the square's image under a homography, sent to GL as
//     (s q, t q, 0, q) per vertex): smooth everywhere and exactly what a
//     fixed-function pipeline can do with four texture coordinates.
// Header-only so the demo and the tests share one copy.
#pragma once
#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "common/core/error.hpp"

namespace quad {
using Corners = std::array<glm::dvec2, 4>;  // st at (0,0), (1,0), (1,1), (0,1)

// The diagonal that splits the square into two triangles.
enum class Diagonal { TopLeftBottomRight, BottomLeftTopRight };

// An affine map (a, b) -> M (a, b) + c.
struct Affine {
  glm::dmat2 m{1.0};
  glm::dvec2 c{0.0};
  glm::dvec2 operator()(glm::dvec2 p) const { return m * p + c; }
  // Gradient of s (row 0) or t (row 1) with respect to (a, b).
  glm::dvec2 gradient(int row) const { return {m[0][row], m[1][row]}; }
};

// The affine map taking three square corners p0, p1, p2 to st0, st1, st2.
inline Affine affineThrough(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, glm::dvec2 s0, glm::dvec2 s1, glm::dvec2 s2) {
  glm::dmat2 P(p1 - p0, p2 - p0), S(s1 - s0, s2 - s0);
  Affine A;
  A.m = S * glm::inverse(P);
  A.c = s0 - A.m * p0;
  return A;
}

// --corners: four "s,t" pairs (|s|, |t| <= 64) of a convex quadrilateral,
// else ts::Error saying what is wrong.
inline Corners parseCorners(const std::string& text) {
  Corners c{};
  std::istringstream in(text);
  for (int i = 0; i < 4; ++i) {
    double s = 0, t = 0;
    char comma = 0;
    if (!(in >> s >> comma >> t) || comma != ',' || !std::isfinite(s) || !std::isfinite(t) || std::abs(s) > 64 ||
        std::abs(t) > 64)
      throw ts::Error("--corners: '" + text + "' is not four \"s,t\" pairs with |s|,|t| <= 64");
    c[size_t(i)] = {s, t};
  }
  std::string rest;
  if (in >> rest) throw ts::Error("--corners: '" + text + "' has more than four pairs");
  // The projective fix needs a convex quadrilateral: only then is q of the
  // homography positive over the whole square.  All four turns must have one
  // sign (a zero turn is three corners in a line).
  double turn[4];
  for (int i = 0; i < 4; ++i) {
    glm::dvec2 u = c[size_t((i + 1) % 4)] - c[size_t(i)], w = c[size_t((i + 2) % 4)] - c[size_t((i + 1) % 4)];
    turn[i] = u.x * w.y - u.y * w.x;
    if (std::abs(turn[i]) < 1e-9) throw ts::Error("--corners: '" + text + "' has three corners in a line");
  }
  for (int i = 1; i < 4; ++i)
    if ((turn[i] > 0) != (turn[0] > 0)) throw ts::Error("--corners: '" + text + "' is not a convex quadrilateral");
  return c;
}

inline const std::array<glm::dvec2, 4>& squareCorners() {
  static const std::array<glm::dvec2, 4> k{glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)};
  return k;
}

// The two triangles' maps.  first = the triangle holding corner (1,0) for the
// top-left/bottom-right split (the lower-left half holds (0,0), so first is
// lower-left, second upper-right); for the other split first holds (1,0)
// (lower-right half) and second holds (0,1) (upper-left half).
struct Split {
  Affine first, second;
  bool inFirst(glm::dvec2 p, Diagonal d) const {
    return d == Diagonal::TopLeftBottomRight ? (p.x + p.y < 1.0) : (p.x > p.y);
  }
  const Affine& at(glm::dvec2 p, Diagonal d) const { return inFirst(p, d) ? first : second; }
};

inline Split split(const Corners& st, Diagonal d) {
  const auto& P = squareCorners();
  if (d == Diagonal::TopLeftBottomRight)  // triangles (00,10,01) and (10,11,01)
    return {affineThrough(P[0], P[1], P[3], st[0], st[1], st[3]), affineThrough(P[1], P[2], P[3], st[1], st[2], st[3])};
  // triangles (00,10,11) and (00,11,01)
  return {affineThrough(P[0], P[1], P[2], st[0], st[1], st[2]), affineThrough(P[0], P[2], P[3], st[0], st[2], st[3])};
}

inline glm::dvec2 bilinear(const Corners& st, glm::dvec2 p) {
  return (1 - p.x) * (1 - p.y) * st[0] + p.x * (1 - p.y) * st[1] + p.x * p.y * st[2] + (1 - p.x) * p.y * st[3];
}

// The homography H (column vectors) with H (a, b, 1) ~ (s, t, 1) at the four
// corners (Heckbert's square-to-quadrilateral construction).
inline glm::dmat3 homography(const Corners& st) {
  const glm::dvec2 &x0 = st[0], &x1 = st[1], &x2 = st[2], &x3 = st[3];
  glm::dvec2 sum = x0 - x1 + x2 - x3;
  double a, b, c = x0.x, d, e, f = x0.y, g = 0, h = 0;
  if (std::abs(sum.x) < 1e-12 && std::abs(sum.y) < 1e-12) {  // a parallelogram: affine
    a = x1.x - x0.x, b = x3.x - x0.x, d = x1.y - x0.y, e = x3.y - x0.y;
  } else {
    glm::dvec2 d1 = x1 - x2, d2 = x3 - x2;
    double det = d1.x * d2.y - d2.x * d1.y;
    g = (sum.x * d2.y - d2.x * sum.y) / det;
    h = (d1.x * sum.y - sum.x * d1.y) / det;
    a = x1.x - x0.x + g * x1.x, b = x3.x - x0.x + h * x3.x;
    d = x1.y - x0.y + g * x1.y, e = x3.y - x0.y + h * x3.y;
  }
  // glm is column-major: columns are the images of a, b and 1.
  return glm::dmat3(glm::dvec3(a, d, g), glm::dvec3(b, e, h), glm::dvec3(c, f, 1));
}
inline glm::dvec4 projectiveTexCoord(const glm::dmat3& H, glm::dvec2 p) {
  glm::dvec3 v = H * glm::dvec3(p, 1.0);
  return {v.x, v.y, 0.0, v.z};  // (s q, t q, r, q): GL divides by q per pixel
}
inline glm::dvec2 projective(const glm::dmat3& H, glm::dvec2 p) {
  glm::dvec3 v = H * glm::dvec3(p, 1.0);
  return {v.x / v.z, v.y / v.z};
}

// Angle in degrees between the lines of constant s (or t) on the two sides
// of the diagonal: the kink the figure is about.  Iso-lines are perpendicular
// to the gradients, so the angle between gradients is the bend.
inline double angleDeg(glm::dvec2 g1, glm::dvec2 g2) {
  double c = glm::dot(g1, g2) / (glm::length(g1) * glm::length(g2));
  return std::acos(std::fmax(-1.0, std::fmin(1.0, c))) * 180.0 / 3.14159265358979323846;
}
inline double predictedKinkDeg(const Corners& st, Diagonal d) {
  Split s = split(st, d);
  return std::fmax(angleDeg(s.first.gradient(0), s.second.gradient(0)),
                   angleDeg(s.first.gradient(1), s.second.gradient(1)));
}
// The same angle for any map of the square (s,t) = map(x,y), found the way
// the render is measured: the gradients of s and of t just either side of
// the diagonal, by one-sided differences, at points along it; the largest
// angle between the two sides.  For the affine split it is predictedKinkDeg;
// for a map smooth across the diagonal (bilinear, projective) it is 0 up to
// the differences' error (about 1e-4 degrees).
template <typename Map>
double kinkAcrossDiagonalDeg(const Map& map, Diagonal d) {
  const glm::dvec2 a = d == Diagonal::TopLeftBottomRight ? glm::dvec2(0, 1) : glm::dvec2(0, 0);
  const glm::dvec2 b = d == Diagonal::TopLeftBottomRight ? glm::dvec2(1, 0) : glm::dvec2(1, 1);
  const glm::dvec2 along = glm::normalize(b - a), across(-along.y, along.x);
  const double h = 1e-6, off = 1e-6;
  double worst = 0;
  for (int k = 1; k < 8; ++k) {
    glm::dvec2 p = a + (b - a) * (k / 8.0);
    glm::dvec2 g[2][2];  // [side][s or t]
    for (int side = 0; side < 2; ++side) {
      glm::dvec2 q = p + across * (side ? off : -off);
      glm::dvec2 f0 = map(q), fa = map(q + along * h), fc = map(q + across * (side ? h : -h));
      glm::dvec2 dAlong = (fa - f0) / h, dAcross = (fc - f0) / (side ? h : -h);
      for (int c = 0; c < 2; ++c) g[side][c] = along * dAlong[c] + across * dAcross[c];  // back to (x, y)
    }
    worst = std::fmax(worst, std::fmax(angleDeg(g[0][0], g[1][0]), angleDeg(g[0][1], g[1][1])));
  }
  return worst;
}
// Largest distance, over the square, between where the two triangles' maps
// put the same point, in texture units: how far apart the two halves would
// drift if each were extended across the diagonal.
inline double splitDisagreement(const Corners& st, Diagonal d) {
  Split s = split(st, d);
  double worst = 0;
  for (const auto& p : squareCorners()) worst = std::fmax(worst, glm::length(s.first(p) - s.second(p)));
  return worst;
}
}  // namespace quad
