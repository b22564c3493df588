// demos/projectors/projectors_math.hpp — the projector functions of seed 002's lab
// sheet (lines 83-165) along X, Y and Z, as printed and corrected; box
// mapping; the slide projector's eye planes; the cube with 24 and with 8
// vertices.  Plain double arithmetic, no GL: tests/unit/projectors_test.cpp
// checks the closed forms, the demo renders them (per vertex, by glTexGen or
// per fragment in GLSL, where the same expressions are spelled again).
//
// Conventions: the object fits the cube [-1, 1]^3; scale s = 1/2 (seed 002:
// "s = 1/(the solid's largest size along the axis)"), centre offsets chosen
// so the corrected maps cover [0, 1].  The angles' raw values are kept as the
// seed prints them (ou = 0, so the printed cylindrical tu is in ±0.25 and the
// corrected one in ±0.5; GL_REPEAT wraps both); tv of the spherical wrap
// gets ov = -1/2 for both formulas, so the printed one covers [0.25, 0.75].
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace proj {
constexpr double kPi = 3.14159265358979323846;

enum class Axis { X, Y, Z };
enum class Projector { Planar, Cylindrical, Spherical, Box, Solid };
enum class Formula { Printed, Corrected };

// The planar scale and offset: tu = s*a - c maps a in [-1, 1] to [0, 1].
constexpr double kS = 0.5, kC = -0.5;

// The two coordinates of p "across" the axis, in the order the seed uses
// them (its tu, tv for the planar wrap, a and b of arctg(a/b) for the
// angles), and the coordinate along the axis.
struct Frame3 {
  double a, b, along;
};
inline Frame3 across(Axis ax, glm::dvec3 p) {
  switch (ax) {
    case Axis::X: return {p.z, p.y, p.x};  // seed: "x) tu = s·z − cz ; tv = s·y − cy", "arctg(z/y)"
    case Axis::Y: return {p.x, p.z, p.y};  // seed: "y) tu = s·x − cx ; tv = s·z − cz", "arctg(x/z)"
    case Axis::Z: return {p.x, p.y, p.z};  // seed: "z) tu = s·x − cx ; tv = s·x − cx"(!), "arctg(x/y)"
  }
  return {p.x, p.y, p.z};
}

// Planar wrap.  Seed 002, lines 84-86:
//   x) tu = s ⋅ z − cz ; tv = s ⋅ y − cy
//   y) tu = s ⋅ x − cx ; tv = s ⋅ z − cz
//   z) tu = s ⋅ x − cx ; tv = s ⋅ x − cx      <- tv written with x: tu ≡ tv
// Corrected z: tv = s ⋅ y − cy.
inline glm::dvec2 planar(Axis ax, Formula f, glm::dvec3 p) {
  Frame3 q = across(ax, p);
  double tu = kS * q.a - kC;
  double tv = kS * q.b - kC;
  if (ax == Axis::Z && f == Formula::Printed) tv = kS * p.x - kC;
  return {tu, tv};
}

// Cylindrical wrap.  Seed 002 (lines 92-110; the PDF lays each fraction out over several lines):
//   x) tu = su/(2π) · arctg(z/y) − ou ; tv = sv ⋅ x − ov
//   y) tu = su/(2π) · arctg(x/z) − ou ; tv = sv ⋅ y − ov
//   z) tu = su/(2π) · arctg(x/y) − ou ; tv = sv ⋅ z − ov
// arctg has period π: tu spans ±0.25, p and -p (across the axis) collide,
// b = 0 divides by zero.  Corrected: atan2(a, b), period 2π, tu in ±0.5 —
// along Y it is Buss's Eq. VI.1, s = θ/360 with p = (r sin θ, y, r cos θ).
inline double angleU(Axis ax, Formula f, glm::dvec3 p) {
  Frame3 q = across(ax, p);
  if (f == Formula::Printed) return std::atan(q.a / q.b) / (2 * kPi);  // b = 0: ±inf -> ±0.25 in IEEE
  return std::atan2(q.a, q.b) / (2 * kPi);
}
inline glm::dvec2 cylindrical(Axis ax, Formula f, glm::dvec3 p) {
  return {angleU(ax, f, p), kS * across(ax, p).along - kC};
}

// Spherical wrap.  Seed 002 (lines 112-162):
//   tu as the cylindrical one; tv = sv/π · arctg(x / √(x²+y²+z²)) − ov (along x; y, z alike)
// arctg of a value in [-1, 1] reaches only ±π/4: tv spans ±0.25 (pole 0.25,
// 45° latitude arctg(sin 45°)/π = 0.1959).  Corrected: arcsin (pole 0.5,
// 45° 0.25).  ov = -1/2 here for both.
inline double latitudeV(Axis ax, Formula f, glm::dvec3 p) {
  double r = glm::length(p), x = across(ax, p).along / r;
  return (f == Formula::Printed ? std::atan(x) : std::asin(std::clamp(x, -1.0, 1.0))) / kPi;
}
inline glm::dvec2 spherical(Axis ax, Formula f, glm::dvec3 p) { return {angleU(ax, f, p), latitudeV(ax, f, p) + 0.5}; }

// Box mapping (seed 001 ¶4): project along the axis of the normal's largest
// component, the planar map of that axis (corrected).  Its stretch (surface
// length per texture length, worst direction) is 1/|n_axis|, at most √3 at
// (1,1,1)/√3; one planar projection's is 1/|n·axis|: 5.76 at 80°.
inline Axis boxAxis(glm::dvec3 n) {
  glm::dvec3 a = glm::abs(n);
  if (a.x >= a.y && a.x >= a.z) return Axis::X;
  return a.y >= a.z ? Axis::Y : Axis::Z;
}
inline glm::dvec2 box(glm::dvec3 p, glm::dvec3 n) { return planar(boxAxis(n), Formula::Corrected, p); }
inline double boxStretch(glm::dvec3 n) {
  n = glm::normalize(n);
  glm::dvec3 a = glm::abs(n);
  return 1.0 / std::max({a.x, a.y, a.z});
}
inline double planarStretch(double angleDeg) { return 1.0 / std::cos(angleDeg * kPi / 180.0); }

inline glm::dvec2 project(Projector pr, Axis ax, Formula f, glm::dvec3 p, glm::dvec3 n) {
  switch (pr) {
    case Projector::Planar: return planar(ax, f, p);
    case Projector::Cylindrical: return cylindrical(ax, f, p);
    case Projector::Spherical: return spherical(ax, f, p);
    case Projector::Box: return box(p, n);
    case Projector::Solid: return planar(ax, Formula::Corrected, p);
  }
  return {0, 0};
}

// The planar projection as glTexGen planes (OBJECT_LINEAR, object
// coordinates): s = plane_s · (x, y, z, 1).  Only linear projectors have
// planes; as printed along Z both rows are the x row.
inline std::array<glm::dvec4, 2> planarPlanes(Axis ax, Formula f) {
  glm::dvec4 ex(kS, 0, 0, -kC), ey(0, kS, 0, -kC), ez(0, 0, kS, -kC);
  switch (ax) {
    case Axis::X: return {ez, ey};
    case Axis::Y: return {ex, ez};
    case Axis::Z: return {ex, f == Formula::Printed ? ex : ey};
  }
  return {ex, ey};
}

// The slide projector (Segal et al. 1992; the Red Book's projective
// texturing): a projector at V_L with projection P_L throws the slide on the
// scene; B = translate(½) · scale(½) takes its clip [-1, 1] to [0, 1].  The
// rows of B · P_L · V_L are the EYE_LINEAR planes S, T, R, Q when given with
// the modelview = identity-in-world (i.e. V_camera in force, so GL turns them
// into world planes).  q < 0 behind the projector: the back projection.
inline glm::dmat4 biasMatrix() {
  glm::dmat4 b(0.5);
  b[3] = glm::dvec4(0.5, 0.5, 0.5, 1.0);
  return b;
}
inline std::array<glm::dvec4, 4> slidePlanes(const glm::dmat4& projL, const glm::dmat4& viewL) {
  glm::dmat4 m = biasMatrix() * projL * viewL;
  std::array<glm::dvec4, 4> rows;
  for (int r = 0; r < 4; ++r) rows[size_t(r)] = glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]);  // glm is column-major
  return rows;
}
// (s, t, r, q) of a world point, as the planes give it.
inline glm::dvec4 slideCoords(const std::array<glm::dvec4, 4>& planes, glm::dvec3 world) {
  glm::dvec4 p(world, 1.0);
  return {glm::dot(planes[0], p), glm::dot(planes[1], p), glm::dot(planes[2], p), glm::dot(planes[3], p)};
}

// Seed 002's Task 2 / Buss VI.1.2: a cube's corner belongs to three faces,
// so a textured cube needs 4 vertices per face, 24, each face's corners
// reading (0,0), (1,0), (1,1), (0,1) counter-clockwise seen from outside.
struct CubeVertex {
  glm::dvec3 pos, normal;
  glm::dvec2 st;
};
// Face k: normal ±axis; corners counter-clockwise seen from outside.
inline std::vector<CubeVertex> cube24() {
  std::vector<CubeVertex> v;
  for (int k = 0; k < 6; ++k) {
    int axis = k / 2;
    double sign = k % 2 ? -1.0 : 1.0;
    glm::dvec3 n(0.0);
    n[axis] = sign;
    // Two tangents u, w with u × w = n: counter-clockwise from outside.
    glm::dvec3 u(0.0), w(0.0);
    u[(axis + 1) % 3] = 1.0;
    w[(axis + 2) % 3] = 1.0;
    if (sign < 0) u = -u;
    const glm::dvec2 st[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const glm::dvec2& c : st) v.push_back({n + (2 * c.x - 1) * u + (2 * c.y - 1) * w, n, c});
  }
  return v;
}
// The 8-vertex cube: one (s, t) per corner, which three faces must share.
// The natural guess (s, t) = ((x+1)/2, (y+1)/2) — a planar map along Z —
// is right on ±Z only: ±X faces get s constant (a smear), ±Y t constant,
// and -Z is mirrored.
inline glm::dvec2 cube8St(glm::dvec3 corner) { return {(corner.x + 1) / 2, (corner.y + 1) / 2}; }
inline std::vector<CubeVertex> cube8() {
  std::vector<CubeVertex> v = cube24();
  for (CubeVertex& c : v) c.st = cube8St(c.pos);
  return v;
}
// Signed area of a face's (s, t) corners against its outward orientation:
// +1 for a unit square read counter-clockwise, 0 for a smear, < 0 mirrored.
inline double faceStArea(const std::vector<CubeVertex>& v, int face) {
  double a = 0;
  for (int k = 0; k < 4; ++k) {
    glm::dvec2 p = v[size_t(4 * face + k)].st, q = v[size_t(4 * face + (k + 1) % 4)].st;
    a += p.x * q.y - q.x * p.y;
  }
  return a / 2;
}
// Distinct positions among the vertices (8 for both cubes).
inline int distinctPositions(const std::vector<CubeVertex>& v) {
  std::vector<glm::dvec3> seen;
  for (const CubeVertex& c : v)
    if (std::none_of(seen.begin(), seen.end(), [&](glm::dvec3 s) { return s == c.pos; })) seen.push_back(c.pos);
  return int(seen.size());
}
// Distinct (position, st) pairs: the vertices GL must be sent.
inline int distinctVertices(const std::vector<CubeVertex>& v) {
  std::vector<const CubeVertex*> seen;
  for (const CubeVertex& c : v)
    if (std::none_of(seen.begin(), seen.end(), [&](const CubeVertex* s) { return s->pos == c.pos && s->st == c.st; }))
      seen.push_back(&c);
  return int(seen.size());
}
}  // namespace proj
