// common/core/env_maps.hpp — the world of the environment-mapping demo and
// the four ways of storing it (Buss VI.3; seed 001's lat-long, cube, sphere
// and paraboloid maps), shared by the demo (demos/environment_mapping), which
// draws its figures' texgen passes from these maps, and the CPU reference
// (reference/sidecar_reader.cpp's remakeTexture: the generator
// "environment_map"), which remakes them from a sidecar's parameters.
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
#include <utility>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "common/core/text.hpp"

namespace ts::envmaps {
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
    case kLatLong:
    case kParaboloid: {
      int h = int(std::lround(std::sqrt(total / 2)));
      return {2 * h, h};
    }
    case kCube: return {face, face};
    default: {
      int n = int(std::lround(std::sqrt(total)));
      return {n, n};
    }
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
    case kCube: {
      CubeST c = cubeST(d);
      if (face) *face = c.face;
      return {c.s, c.t};
    }
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
// The base colour alone (no lines, no boxes): what a key of the world's colours shows.
inline dvec3 directionColour(dvec3 d) { return 0.2 + 0.6 * (d + 1.0) / 2.0; }  // d unit
// The lines' colours over a base colour c: every 15 degrees dark, the equator and the meridian white.
inline dvec3 gridLineColour(dvec3 c) { return c * 0.3; }
inline const dvec3 kWhiteLine(0.97);
inline dvec3 worldColour(dvec3 d) {
  d = glm::normalize(d);
  dvec3 c = directionColour(d);
  const double lat = deg(std::asin(std::clamp(d.y, -1.0, 1.0))), lon = deg(std::atan2(-d.x, -d.z));
  auto off = [](double a) { return std::abs(a - 15.0 * std::round(a / 15.0)); };
  auto ramp = [](double insideDeg) { return std::clamp(insideDeg / 0.25 + 0.5, 0.0, 1.0); };
  const double lineDeg = 0.9;
  const double wLat = ramp(lineDeg - off(lat)),
               wLon = ramp(lineDeg - off(lon) * std::cos(rad(lat))) * ramp(82.5 - std::abs(lat));
  const dvec3 dark = gridLineColour(c), white = kWhiteLine;
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
    const double cov = glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), fx),
                                glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
    const double ink = std::clamp((cov - 0.5) * 4 + 0.5, 0.0, 1.0);
    c = glm::mix(c, glm::mix(dvec3(0.95), dvec3(0.05), ink), box);
  }
  return c;
}
inline ts::Rgba toRgba(dvec3 c) {
  auto b = [](double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  return {b(c.r), b(c.g), b(c.b), 255};
}

// ---- the maps as textures ----------------------------------------------------
// The map `p` at equal memory for `face` texels a cube face's side, each
// texel the world's colour at its centre's direction, 8 bits a channel,
// GL_LINEAR, no mipmaps; the lat-long map repeats in s, the others clamp to
// their edges; the cube map's six faces stacked (TextureDesc::cube).  The
// sphere map is made for the eye whose rotation (world -> eye) is
// `sphereView`.  Named "environment_map", its parameters recorded
// (param, face, sphere_view): remakeTexture makes it again from them.
TextureDesc environmentMap(Param p, int face, const glm::dmat3& sphereView = glm::dmat3(1.0));
// The background where a map holds no data (outside the sphere map's and the
// paraboloid's discs), and the demo's pictures' background.
inline const dvec3 kBackground{0.12, 0.12, 0.14};
// The same map laid out flat to be looked at (parameter layout=unwrapped):
// the cube's faces +X -X +Y over -Y +Z -Z, each with t down (as GL stores
// them); the 2D maps with t up, kBackground outside the discs; GL_NEAREST,
// clamped.  Texture coordinates (u, v) in [0,1]^2 cover the picture, v up.
TextureDesc unwrappedMap(Param p, int face, const glm::dmat3& sphereView = glm::dmat3(1.0));
// Its size in texels.
inline Size unwrappedSize(Param p, int face) {
  const Size sz = mapSize(p, face);
  return p == kCube ? Size{3 * sz.w, 2 * sz.h} : sz;
}
// The same from the sidecar's parameters (throws ts::Error on bad ones).
TextureDesc environmentMapFromParams(const std::vector<std::pair<std::string, std::string>>& params);
}  // namespace ts::envmaps
