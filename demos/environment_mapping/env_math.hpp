// demos/environment_mapping/env_math.hpp — the world around the object and
// the four ways of storing it (Buss VI.3; seed 001's lat-long, cube, sphere
// and paraboloid maps; seed 002's sphere and cube formulas).  Pure CPU, no
// GL: the demo bakes its textures from here, the tests check it, and the
// measurement decodes GL's read-backs with it.
//
// Every map takes a direction d (unit, world coordinates) to a texture
// coordinate (s, t) in [0,1]^2 and back:
//   lat-long (Blinn–Newell)  λ = atan2(-d_x, -d_z), φ = asin d_y,
//                            s = λ/2π + 1/2, t = φ/π + 1/2
//                            (the seam λ = ±180° is the direction +Z, the
//                            poles ±Y: a whole row of texels each)
//   cube (GL spec, table "selection of cube map images"): the face is the
//        component of largest magnitude (ma), then
//          +X: sc = -r_z, tc = -r_y   -X: sc = +r_z, tc = -r_y
//          +Y: sc = +r_x, tc = +r_z   -Y: sc = +r_x, tc = -r_z
//          +Z: sc = +r_x, tc = -r_y   -Z: sc = -r_x, tc = -r_y
//        s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2
//   sphere (GL_SPHERE_MAP, r in the eye space of the view the map was made
//        for): m = 2 sqrt(r_x^2 + r_y^2 + (r_z + 1)^2), s = r_x/m + 1/2,
//        t = r_y/m + 1/2; the map is a mirror ball seen along -z: its point
//        (x, y) = (2s - 1, 2t - 1) has normal N = (x, y, sqrt(1 - x^2 - y^2))
//        and reflects r = 2 N_z N - (0, 0, 1)
//   dual paraboloid (Heidrich–Seidel): front (d_z >= 0) s = d_x/(2(1 + d_z))
//        + 1/2, back with 1 - d_z; both discs side by side in one texture
//        (front left half, back right half)
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/image.hpp"
#include "common/core/text.hpp"

namespace envmap {
using glm::dvec2;
using glm::dvec3;
constexpr double kPi = 3.14159265358979323846;
inline double deg(double r) { return r * 180.0 / kPi; }
inline double rad(double d) { return d * kPi / 180.0; }
inline double angleDeg(dvec3 a, dvec3 b) {  // atan2 form: exact for tiny angles too
  return deg(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

enum Param { kLatLong, kCube, kSphere, kParaboloid, kParams };
inline const char* const kParamKeys[] = {"latlong", "cube", "sphere", "paraboloid"};
inline const char* const kParamLabels[] = {"lat-long", "cube map", "sphere map", "dual paraboloid"};

// ---- lat-long -----------------------------------------------------------
inline dvec2 latlongST(dvec3 d) {
  d = glm::normalize(d);
  return {std::atan2(-d.x, -d.z) / (2 * kPi) + 0.5, std::asin(std::clamp(d.y, -1.0, 1.0)) / kPi + 0.5};
}
inline dvec3 latlongDir(double s, double t) {
  double lam = (s - 0.5) * 2 * kPi, phi = (t - 0.5) * kPi;
  return {-std::sin(lam) * std::cos(phi), std::sin(phi), -std::cos(lam) * std::cos(phi)};
}

// ---- cube ---------------------------------------------------------------
// face 0..5 = +X, -X, +Y, -Y, +Z, -Z (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face).
inline const char* const kFaceNames[] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
struct CubeST {
  int face = 0;
  double s = 0, t = 0;
};
inline CubeST cubeST(dvec3 r) {
  const dvec3 a = glm::abs(r);
  double sc, tc, ma;
  int face;
  if (a.x >= a.y && a.x >= a.z) face = r.x >= 0 ? 0 : 1, ma = a.x, sc = r.x >= 0 ? -r.z : r.z, tc = -r.y;
  else if (a.y >= a.z) face = r.y >= 0 ? 2 : 3, ma = a.y, sc = r.x, tc = r.y >= 0 ? r.z : -r.z;
  else face = r.z >= 0 ? 4 : 5, ma = a.z, sc = r.z >= 0 ? r.x : -r.x, tc = -r.y;
  return {face, (sc / ma + 1) / 2, (tc / ma + 1) / 2};
}
inline dvec3 cubeDir(int face, double s, double t) {  // the inverse of cubeST (unit length)
  const double a = 2 * s - 1, b = 2 * t - 1;
  const dvec3 d[] = {{1, -b, -a}, {-1, -b, a}, {a, 1, b}, {a, -1, -b}, {a, -b, 1}, {-a, -b, -1}};
  return glm::normalize(d[face]);
}
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

// ---- sphere map ---------------------------------------------------------
inline dvec2 sphereST(dvec3 rEye) {
  const double m = 2 * std::sqrt(rEye.x * rEye.x + rEye.y * rEye.y + (rEye.z + 1) * (rEye.z + 1));
  return {rEye.x / m + 0.5, rEye.y / m + 0.5};
}
// (s, t) outside the disc are taken to its rim (all of which is -z).
inline dvec3 sphereDir(double s, double t) {
  dvec2 p(2 * s - 1, 2 * t - 1);
  double rho2 = glm::dot(p, p);
  if (rho2 > 1) p /= std::sqrt(rho2), rho2 = 1;
  const dvec3 n(p.x, p.y, std::sqrt(1 - rho2));
  return glm::normalize(2 * n.z * n - dvec3(0, 0, 1));
}
// Seed 002: u = N_x/2 + 1/2, v = N_y/2 + 1/2 from the surface normal (eye
// space).  It is GL_SPHERE_MAP's (s, t) when the eye looks along -z at the
// point (I = (0,0,-1)), and not elsewhere.
inline dvec2 seedSphereST(dvec3 nEye) { return {nEye.x / 2 + 0.5, nEye.y / 2 + 0.5}; }

// ---- dual paraboloid (packed: front s in [0, 1/2), back in [1/2, 1]) -----
inline dvec2 paraboloidST(dvec3 d) {
  d = glm::normalize(d);
  const bool front = d.z >= 0;
  const double k = 2 * (1 + std::abs(d.z));
  const dvec2 p(d.x / k + 0.5, d.y / k + 0.5);
  return {(p.x + (front ? 0.0 : 1.0)) / 2, p.y};
}
inline dvec3 paraboloidDir(double s, double t) {
  const bool front = s < 0.5;
  const double x = 2 * (2 * s - (front ? 0.0 : 1.0)) - 1, y = 2 * t - 1, rho2 = x * x + y * y;
  // Outside the disc the formula continues into the other hemisphere: the
  // texels there keep bilinear filtering at the rim sensible.
  return glm::normalize(dvec3(2 * x, 2 * y, (front ? 1 : -1) * (1 - rho2)));
}

// ---- one map as texels ----------------------------------------------------
// A 2D map (lat-long, sphere, paraboloid) or one cube face: w x h texel
// centres' directions in GL's upload order (row 0 is t = 0).  The sphere
// map's directions are in the eye space of its view; `toWorld` (the
// transpose of that view's rotation) turns them into the world's.
struct Size {
  int w = 0, h = 0;
};
// Sizes at equal memory: `face` texels a cube face side, 6 face^2 texels in
// all; the others as close to that count as their shapes allow.
inline Size mapSize(Param p, int face) {
  const double total = 6.0 * face * face;
  switch (p) {
    case kLatLong: case kParaboloid: { int h = int(std::lround(std::sqrt(total / 2))); return {2 * h, h}; }
    case kCube: return {face, face};
    default: { int n = int(std::lround(std::sqrt(total))); return {n, n}; }
  }
}
inline int mapTexels(Param p, int face) {
  const Size s = mapSize(p, face);
  return s.w * s.h * (p == kCube ? 6 : 1);
}
inline dvec3 texelDir(Param p, int face, double s, double t, const glm::dmat3& toWorld) {
  switch (p) {
    case kLatLong: return latlongDir(s, t);
    case kCube: return cubeDir(face, s, t);
    case kSphere: return toWorld * sphereDir(s, t);
    default: return paraboloidDir(s, t);
  }
}
// The map coordinate of a world direction (`toEye` = the sphere map's view).
inline dvec2 mapST(Param p, dvec3 d, const glm::dmat3& toEye, int* face = nullptr) {
  switch (p) {
    case kLatLong: return latlongST(d);
    case kCube: { CubeST c = cubeST(d); if (face) *face = c.face; return {c.s, c.t}; }
    case kSphere: return sphereST(toEye * d);
    default: return paraboloidST(d);
  }
}

// ---- the world -------------------------------------------------------------
// A label bitmap per face ("+X" ...), white on nothing, drawn once.
inline const ts::Image& faceLabel(int face) {
  static const std::array<ts::Image, 6> labels = [] {
    std::array<ts::Image, 6> out;
    for (int f = 0; f < 6; ++f) {
      ts::Image img(int(ts::text::width(kFaceNames[f], 1)) + 2, int(ts::text::height(1)));
      for (auto& b : img.pixels) b = 0;
      ts::text::draw(img, 1, 0, kFaceNames[f], {255, 255, 255, 255}, 1);  // coverage in red
      out[size_t(f)] = img;
    }
    return out;
  }();
  return labels[size_t(face)];
}
// The colour of direction d (unit), RGB in [0,1]:
//   - the base colour encodes the direction, 0.2 + 0.6 (d + 1)/2 per channel
//     (red grows to +X, green to +Y, blue to +Z);
//   - dark lines every 15 degrees of latitude and longitude (of the lat-long
//     map's λ, φ), the equator and the meridian λ = 0 (through -Z) white;
//   - each cube face's name in a white box at its centre, written in the
//     face's GL (s, t) with t downwards, the way the face images are stored:
//     it reads the right way round in the map views and in a mirror.
//   Every edge (lines, boxes, letters) is a ramp about a quarter of a degree
//   wide instead of a step, so a direction that moves by a rounding error
//   changes its colour by as little: two rasterizers' pictures then agree to
//   a level or two instead of flipping whole pixels along every line.
inline dvec3 worldColour(dvec3 d) {
  d = glm::normalize(d);
  dvec3 c = 0.2 + 0.6 * (d + 1.0) / 2.0;
  const double lat = deg(std::asin(std::clamp(d.y, -1.0, 1.0))), lon = deg(std::atan2(-d.x, -d.z));
  auto off = [](double a) { return std::abs(a - 15.0 * std::round(a / 15.0)); };
  auto ramp = [](double insideDeg) { return std::clamp(insideDeg / 0.25 + 0.5, 0.0, 1.0); };
  const double lineDeg = 0.9;
  const double wLat = ramp(lineDeg - off(lat)),
               wLon = ramp(lineDeg - off(lon) * std::cos(rad(lat))) * ramp(82.5 - std::abs(lat));
  const dvec3 dark = c * 0.3, white(0.97);
  c = glm::mix(c, std::abs(lat) < 7.5 ? white : dark, wLat);  // the equator white
  c = glm::mix(c, std::abs(lon) < 7.5 ? white : dark, wLon);  // the meridian through -Z white
  const CubeST f = cubeST(d);
  const ts::Image& label = faceLabel(f.face);
  // The text spans s in 0.5 -/+ 0.15 (t in proportion); the box 1.2 times
  // that.  A unit of a is about 17 degrees at a face's centre.
  const double a = (f.s - 0.5) / 0.15, b = (f.t - 0.5) / 0.15 * label.width / label.height;
  const double box = std::clamp((1.2 - std::max(std::abs(a), std::abs(b))) / 0.015 + 0.5, 0.0, 1.0);
  if (box > 0) {
    // The letters' coverage, bilinear between the bitmap's pixels, then sharpened.
    const double u = (a + 1) / 2 * label.width - 0.5, v = (b + 1) / 2 * label.height - 0.5;
    const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
    auto at = [&](int x, int y) {
      return x >= 0 && y >= 0 && x < label.width && y < label.height ? label.at(x, y).r / 255.0 : 0.0;
    };
    const double fx = u - x0, fy = v - y0;
    const double cov = glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), fx), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
    const double ink = std::clamp((cov - 0.5) * 4 + 0.5, 0.0, 1.0);
    c = glm::mix(c, glm::mix(dvec3(0.95), dvec3(0.05), ink), box);
  }
  return c;
}
inline ts::Rgba toRgba(dvec3 c) {
  auto b = [](double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  return {b(c.r), b(c.g), b(c.b), 255};
}

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
}  // namespace envmap
