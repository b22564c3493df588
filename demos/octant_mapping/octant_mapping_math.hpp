// demos/octant_mapping/octant_mapping_math.hpp — Rogers' worked examples of texture
// mapping (seed 004, after Procedural Elements for Computer Graphics): a
// 64 x 64 grid pattern on the octant of the unit sphere, seen on a 32 x 32
// raster.  No GL: the demo, its views and its tests share this.
//
// The surface (the seed's parametric octant):
//   x = sin θ sin φ,  y = cos φ,  z = cos θ sin φ,   0 <= θ <= π/2, π/4 <= φ <= π/2.
// The mapping: θ = A u + B, φ = C w + D, fixed by sending the pattern's
// corners to the octant's (u = 0 -> θ = 0, u = 1 -> θ = π/2, w = 0 -> φ = π/2,
// w = 1 -> φ = π/4): A = π/2, B = 0, C = -π/4, D = π/2 (linearMapping()).
// Its inverse: u = θ/(π/2), w = (π/2 - φ)/(π/4).
// The view: turned -45° about y, then 35° about x (p' = Rx(35°) Ry(-45°) p,
// column vectors), projected orthographically along z' onto the window
// -1 <= x', y' <= 1, which is a 32 x 32 raster: x' = Px/16 - 1, y' = Py/16 - 1.
//
// Conventions (the seed's, stated where it leaves them open):
//  - Pixel (Px, Py) is named by its lower-left corner and covers
//    [Px, Px+1] x [Py, Py+1]; Py counts UP from the bottom row (row 0 of an
//    image, the top, is Py = 31).  Its centre is (Px + ½, Py + ½).
//  - The pattern: texel (i, j) covers u in [i, i+1]/64, w in [j, j+1]/64, its
//    centre is ((i + ½)/64, (j + ½)/64).  Grid lines are one texel wide, at
//    columns and rows ⌊63 k/4⌋ = 0, 15, 31, 47, 63 (k = 0..4): inferred, it
//    is the grid that gives Catmull's 7/16.  Pattern value 1 on a line
//    ("black"), 0 elsewhere; a pixel's intensity is the mean value, 0..1.
//  - The visible side: the hemisphere z' >= 0 (the whole octant faces the
//    eye: its normal is its position, and z' > 0.57 on it).
//  - Inverse pixel mapping: the pixel's corners mapped back, joined by
//    straight lines (the seed's Fig. 29.4 "approximated by a quadrilateral");
//    a texel counts when its centre is inside or on that quadrilateral.
//    The seed counts with its corners as it prints them, rounded to 3
//    decimals; seedCorners() rounds the same way.
//  - The exact value of a pixel: the area-weighted mean of the pattern over
//    the pixel's true (curved) preimage, a polygon of kEdgeSteps points per
//    side, clipped texel by texel (common/core/area_filter.hpp, shared with
//    the filter zoo's reference).
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "common/core/area_filter.hpp"

namespace octant {
constexpr double kPi = 3.14159265358979323846;
constexpr int kTexels = 64;    // the pattern, per side
constexpr int kCells = 4;      // grid cells per side: lines at ⌊63 k/4⌋
constexpr int kRaster = 32;    // the raster, per side
constexpr int kEdgeSteps = 8;  // points per side of a pixel's curved preimage
constexpr double kViewYDeg = -45.0, kViewXDeg = 35.0;

// --- the mapping -----------------------------------------------------------
struct Linear {
  double A = 0, B = 0, C = 0, D = 0;
};
// θ = A u + B, φ = C w + D through two matched corners each: (u, θ) = (0, 0),
// (1, π/2) and (w, φ) = (0, π/2), (1, π/4).
inline Linear linearMapping() {
  const double u0 = 0, th0 = 0, u1 = 1, th1 = kPi / 2;
  const double w0 = 0, ph0 = kPi / 2, w1 = 1, ph1 = kPi / 4;
  Linear m;
  m.A = (th1 - th0) / (u1 - u0);
  m.B = th0 - m.A * u0;
  m.C = (ph1 - ph0) / (w1 - w0);
  m.D = ph0 - m.C * w0;
  return m;
}
// (u, w) -> (θ, φ) and back.
inline glm::dvec2 anglesOf(glm::dvec2 uw) {
  const Linear m = linearMapping();
  return {m.A * uw.x + m.B, m.C * uw.y + m.D};
}
inline glm::dvec2 uwOf(double theta, double phi) { return {theta / (kPi / 2), (kPi / 2 - phi) / (kPi / 4)}; }

// The sphere's point at (θ, φ), and at (u, w).
inline glm::dvec3 surface(double theta, double phi) {
  return {std::sin(theta) * std::sin(phi), std::cos(phi), std::cos(theta) * std::sin(phi)};
}
inline glm::dvec3 surfaceUW(glm::dvec2 uw) {
  const glm::dvec2 a = anglesOf(uw);
  return surface(a.x, a.y);
}

// --- the view --------------------------------------------------------------
inline glm::dmat3 rotX(double deg) {
  const double a = deg * kPi / 180, c = std::cos(a), s = std::sin(a);
  return glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, c, s), glm::dvec3(0, -s, c));  // columns
}
inline glm::dmat3 rotY(double deg) {
  const double a = deg * kPi / 180, c = std::cos(a), s = std::sin(a);
  return glm::dmat3(glm::dvec3(c, 0, -s), glm::dvec3(0, 1, 0), glm::dvec3(s, 0, c));
}
// p' = V p: Ry(-45°) first, then Rx(35°).  V is a rotation: V^-1 = V^T.
inline glm::dmat3 view() { return rotX(kViewXDeg) * rotY(kViewYDeg); }

// Window <-> raster: x' = Px/16 - 1, y' = Py/16 - 1.
inline glm::dvec2 pixelOfView(glm::dvec2 v) { return (v + 1.0) * (kRaster / 2.0); }
inline glm::dvec2 viewOfPixel(glm::dvec2 P) { return P / (kRaster / 2.0) - 1.0; }
// Where a point of the pattern lands on the raster (Px, Py), and its depth z'.
inline glm::dvec3 projectUW(glm::dvec2 uw) {
  const glm::dvec3 p = view() * surfaceUW(uw);
  return {pixelOfView({p.x, p.y}), p.z};
}

// The inverse: a raster point (Px, Py) -> (x', y', z') on the visible
// hemisphere -> (x, y, z) = V^T p' -> φ = acos y, θ = atan2(x, z) (the seed's
// asin(x / sin φ) where z >= 0) -> (u, w).  Empty off the sphere's disc.
struct Back {
  glm::dvec3 viewPoint{0.0}, point{0.0};
  double theta = 0, phi = 0;
  glm::dvec2 uw{0.0};
};
inline std::optional<Back> backOfPixelPoint(glm::dvec2 P) {
  const glm::dvec2 v = viewOfPixel(P);
  const double r2 = v.x * v.x + v.y * v.y;
  if (r2 > 1.0) return std::nullopt;
  Back b;
  b.viewPoint = {v.x, v.y, std::sqrt(1.0 - r2)};
  b.point = glm::transpose(view()) * b.viewPoint;
  b.phi = std::acos(std::clamp(b.point.y, -1.0, 1.0));
  b.theta = std::atan2(b.point.x, b.point.z);
  b.uw = uwOf(b.theta, b.phi);
  return b;
}
inline bool inPatch(glm::dvec2 uw, double eps = 0) {
  return uw.x >= -eps && uw.x <= 1 + eps && uw.y >= -eps && uw.y <= 1 + eps;
}

// --- the forward table (the seed's first example) ----------------------------
struct TableRow {
  double u = 0, w = 0, theta = 0, phi = 0;
  glm::dvec3 xyz{0.0};
};
// The line u = const at w = 0, 1/4, 1/2, 3/4, 1, through the mapping.
inline std::vector<TableRow> forwardTable(double u) {
  std::vector<TableRow> rows;
  for (int k = 0; k <= 4; ++k) {
    TableRow r;
    r.u = u, r.w = k / 4.0;
    const glm::dvec2 a = anglesOf({r.u, r.w});
    r.theta = a.x, r.phi = a.y;
    r.xyz = surface(r.theta, r.phi);
    rows.push_back(r);
  }
  return rows;
}
// The same point in closed form, without θ and φ: sin(π/2 - πw/4) = cos(πw/4).
inline glm::dvec3 closedForm(double u, double w) {
  const double su = std::sin(kPi * u / 2), cu = std::cos(kPi * u / 2), c = std::cos(kPi * w / 4);
  return {su * c, std::sin(kPi * w / 4), cu * c};
}

// --- the pattern -------------------------------------------------------------
inline bool isLine(int k) {
  for (int c = 0; c <= kCells; ++c)
    if (k == (kTexels - 1) * c / kCells) return true;
  return false;
}
inline std::vector<int> lineTexels() {
  std::vector<int> out;
  for (int k = 0; k < kTexels; ++k)
    if (isLine(k)) out.push_back(k);
  return out;
}
// 1 on a grid line (black), 0 elsewhere; 0 outside the pattern.
inline double pattern(int i, int j) {
  if (i < 0 || j < 0 || i >= kTexels || j >= kTexels) return 0.0;
  return isLine(i) || isLine(j) ? 1.0 : 0.0;
}
// The texel holding (u, w) (u = 1 in the last one).
inline glm::ivec2 texelOf(glm::dvec2 uw) {
  return {std::clamp(int(std::floor(uw.x * kTexels)), 0, kTexels - 1),
          std::clamp(int(std::floor(uw.y * kTexels)), 0, kTexels - 1)};
}

// --- Catmull's subdivision -----------------------------------------------------
// A fragment of level k: the patch cut into 2^k x 2^k, index (a, b) along
// (u, w).  At level k <= 6 it covers 64/2^k x 64/2^k whole texels.
constexpr int kMaxLevel = 6;
struct Fragment {
  int level = 0, a = 0, b = 0;
  int n() const { return 1 << level; }
  glm::dvec2 uw0() const { return {double(a) / n(), double(b) / n()}; }
  glm::dvec2 uw1() const { return {double(a + 1) / n(), double(b + 1) / n()}; }
  int texelsPerSide() const { return kTexels / n(); }
  // θ from A u0 to A u1; φ from C w1 + D to C w0 + D (φ falls as w grows).
  glm::dvec2 thetaRange() const { return {anglesOf(uw0()).x, anglesOf(uw1()).x}; }
  glm::dvec2 phiRange() const { return {anglesOf(uw1()).y, anglesOf(uw0()).y}; }
  bool contains(glm::dvec2 uw) const {
    auto in = [&](double x, int k) {
      const double lo = double(k) / n(), hi = double(k + 1) / n();
      return x >= lo && (x < hi || (k + 1 == n() && x <= hi));
    };
    return in(uw.x, a) && in(uw.y, b);
  }
};
inline Fragment fragmentAt(glm::dvec2 uw, int level) {
  Fragment f;
  f.level = level;
  f.a = std::clamp(int(std::floor(uw.x * f.n())), 0, f.n() - 1);
  f.b = std::clamp(int(std::floor(uw.y * f.n())), 0, f.n() - 1);
  return f;
}
// Its averaged intensity: line texels over all texels of its block.
struct Average {
  int line = 0, total = 0;
  double value() const { return total ? double(line) / total : 0.0; }
};
inline Average fragmentAverage(const Fragment& f) {
  Average avg;
  const int t = f.texelsPerSide();
  for (int j = f.b * t; j < (f.b + 1) * t; ++j)
    for (int i = f.a * t; i < (f.a + 1) * t; ++i) avg.line += int(pattern(i, j)), ++avg.total;
  return avg;
}

// --- the raster's geometry -----------------------------------------------------
inline int pixelIndex(int Px, int Py) { return Py * kRaster + Px; }
// A pixel's corners in the seed's order: (Px, Py), (Px+1, Py), (Px+1, Py+1), (Px, Py+1).
inline std::array<glm::dvec2, 4> pixelCorners(int Px, int Py) {
  return {glm::dvec2(Px, Py), glm::dvec2(Px + 1, Py), glm::dvec2(Px + 1, Py + 1), glm::dvec2(Px, Py + 1)};
}
struct PixelGeometry {
  bool centreOnPatch = false;  // the centre's preimage is on the octant
  bool interior = false;       // the whole pixel's preimage is (the pixels compared)
  glm::dvec2 centreUW{0.0};
  std::array<glm::dvec2, 4> cornerUW{};  // valid when interior
  ts::Polygon2 preimage;                 // the curved preimage in texel units, kEdgeSteps points a side (interior only)
};
inline PixelGeometry pixelGeometry(int Px, int Py) {
  PixelGeometry g;
  if (auto c = backOfPixelPoint({Px + 0.5, Py + 0.5})) {
    g.centreUW = c->uw;
    g.centreOnPatch = inPatch(c->uw);
  }
  const auto P = pixelCorners(Px, Py);
  g.interior = true;
  for (int k = 0; k < 4 && g.interior; ++k)
    for (int s = 0; s < kEdgeSteps; ++s) {
      const glm::dvec2 q = P[size_t(k)] + (P[size_t((k + 1) % 4)] - P[size_t(k)]) * (double(s) / kEdgeSteps);
      auto b = backOfPixelPoint(q);
      if (!b || !inPatch(b->uw)) {
        g.interior = false;
        break;
      }
      if (s == 0) g.cornerUW[size_t(k)] = b->uw;
      g.preimage.push_back(b->uw * double(kTexels));
    }
  if (!g.interior) g.preimage.clear();
  return g;
}
// Every pixel's, computed once (Py-major: pixelIndex).
inline const std::vector<PixelGeometry>& rasterGeometry() {
  static const std::vector<PixelGeometry> all = [] {
    std::vector<PixelGeometry> v;
    for (int Py = 0; Py < kRaster; ++Py)
      for (int Px = 0; Px < kRaster; ++Px) v.push_back(pixelGeometry(Px, Py));
    return v;
  }();
  return all;
}

// The pixel centres a fragment covers (their preimages lie in it).
inline std::vector<glm::ivec2> centresCovered(const Fragment& f) {
  std::vector<glm::ivec2> out;
  const auto& geo = rasterGeometry();
  for (int Py = 0; Py < kRaster; ++Py)
    for (int Px = 0; Px < kRaster; ++Px) {
      const PixelGeometry& g = geo[size_t(pixelIndex(Px, Py))];
      if (g.centreOnPatch && f.contains(g.centreUW)) out.push_back({Px, Py});
    }
  return out;
}
// Catmull's stopping rule for the pixel: the first level at which the
// fragment holding its centre covers no other pixel centre (-1: none up to
// kMaxLevel, or the centre is off the patch).
inline int levelsToOneCentre(int Px, int Py) {
  const PixelGeometry& g = rasterGeometry()[size_t(pixelIndex(Px, Py))];
  if (!g.centreOnPatch) return -1;
  for (int k = 0; k <= kMaxLevel; ++k)
    if (centresCovered(fragmentAt(g.centreUW, k)).size() == 1) return k;
  return -1;
}

// --- inverse pixel mapping: texel centres in the quadrilateral -----------------
struct CentreCount {
  int texels = 0, lines = 0;
  std::vector<glm::ivec2> inside;  // the texels counted
  double fraction() const { return texels ? double(lines) / texels : 0.0; }
};
// Texel centres (i + ½, j + ½) inside or on the convex quadrilateral `q`
// (texel units, either orientation).
inline CentreCount countCentres(const std::array<glm::dvec2, 4>& q) {
  CentreCount c;
  double x0 = q[0].x, x1 = x0, y0 = q[0].y, y1 = y0;
  for (const auto& p : q)
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  for (int j = int(std::floor(y0 - 0.5)); j <= int(std::ceil(y1)); ++j)
    for (int i = int(std::floor(x0 - 0.5)); i <= int(std::ceil(x1)); ++i) {
      const glm::dvec2 t(i + 0.5, j + 0.5);
      bool pos = true, neg = true;
      for (size_t k = 0; k < 4; ++k) {
        const glm::dvec2 a = q[k], b = q[(k + 1) % 4];
        const double cr = (b.x - a.x) * (t.y - a.y) - (b.y - a.y) * (t.x - a.x);
        pos = pos && cr >= 0, neg = neg && cr <= 0;
      }
      if (!(pos || neg)) continue;
      ++c.texels;
      c.lines += int(pattern(i, j));
      c.inside.push_back({i, j});
    }
  return c;
}
inline std::array<glm::dvec2, 4> toTexels(std::array<glm::dvec2, 4> uw) {
  for (auto& p : uw) p *= double(kTexels);
  return uw;
}
// A pixel's corners mapped back (u, w), unrounded; empty off the sphere.
inline std::optional<std::array<glm::dvec2, 4>> cornersUW(int Px, int Py) {
  std::array<glm::dvec2, 4> out{};
  const auto P = pixelCorners(Px, Py);
  for (size_t k = 0; k < 4; ++k) {
    auto b = backOfPixelPoint(P[k]);
    if (!b) return std::nullopt;
    out[k] = b->uw;
  }
  return out;
}
// The same as the seed prints them: to 3 decimals.
inline double round3(double v) { return std::round(v * 1000.0) / 1000.0; }
inline std::array<glm::dvec2, 4> rounded3(std::array<glm::dvec2, 4> uw) {
  for (auto& p : uw) p = {round3(p.x), round3(p.y)};
  return uw;
}

// Texel centres whose point on the sphere lands in the pixel's square
// (inside or on it): the count over the true, curved preimage.
inline CentreCount countCentresCurved(int Px, int Py) {
  CentreCount c;
  const auto q = cornersUW(Px, Py);
  if (!q) return c;
  glm::dvec2 lo(1e9), hi(-1e9);
  for (const auto& p : toTexels(*q)) lo = glm::min(lo, p), hi = glm::max(hi, p);
  for (int j = int(std::floor(lo.y)) - 2; j <= int(std::ceil(hi.y)) + 2; ++j)
    for (int i = int(std::floor(lo.x)) - 2; i <= int(std::ceil(hi.x)) + 2; ++i) {
      const glm::dvec3 p = projectUW({(i + 0.5) / kTexels, (j + 0.5) / kTexels});
      if (p.z < 0 || p.x < Px || p.x > Px + 1 || p.y < Py || p.y > Py + 1) continue;
      ++c.texels;
      c.lines += int(pattern(i, j));
      c.inside.push_back({i, j});
    }
  return c;
}
// Signed distance (texel units) from a texel's centre to the nearest edge of
// the quadrilateral: > 0 inside, < 0 outside.
inline double centreDepth(const std::array<glm::dvec2, 4>& q, glm::ivec2 t) {
  const glm::dvec2 c(t.x + 0.5, t.y + 0.5);
  double area2 = 0;
  for (size_t k = 0; k < 4; ++k) area2 += q[k].x * q[(k + 1) % 4].y - q[(k + 1) % 4].x * q[k].y;
  const double orient = area2 >= 0 ? 1.0 : -1.0;
  double best = 1e9;
  for (size_t k = 0; k < 4; ++k) {
    const glm::dvec2 a = q[k], b = q[(k + 1) % 4];
    const double cr = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    best = std::min(best, orient * cr / glm::length(b - a));
  }
  return best;
}

// --- the raster by each method ----------------------------------------------------
// Per pixel (pixelIndex), intensity 0..1; NaN where a method has no value
// (off the patch).  Compared only where `interior`.
struct Raster {
  std::vector<double> exact, point, catmull, inverse;
  std::vector<bool> interior, centreOnPatch;
};
inline double exactValue(const PixelGeometry& g) {
  double v = 0;
  for (const ts::TexelWeight& t : ts::exactAreaWeights(g.preimage)) v += t.weight * pattern(t.i, t.j);
  return v;
}
inline double pointValue(const PixelGeometry& g) {
  const glm::ivec2 t = texelOf(g.centreUW);
  return pattern(t.x, t.y);
}
inline double catmullValue(const PixelGeometry& g, int level = 4) {
  return fragmentAverage(fragmentAt(g.centreUW, level)).value();
}
inline double inverseValue(const PixelGeometry& g) {
  const CentreCount c = countCentres(toTexels(g.cornerUW));
  return c.texels ? c.fraction() : pointValue(g);  // no centre inside: the nearest texel
}
inline Raster computeRaster() {
  Raster r;
  const size_t n = size_t(kRaster * kRaster);
  const double none = std::nan("");
  r.exact.assign(n, none), r.point.assign(n, none), r.catmull.assign(n, none), r.inverse.assign(n, none);
  r.interior.assign(n, false), r.centreOnPatch.assign(n, false);
  const auto& geo = rasterGeometry();
  for (size_t k = 0; k < n; ++k) {
    const PixelGeometry& g = geo[k];
    r.centreOnPatch[k] = g.centreOnPatch;
    r.interior[k] = g.interior;
    if (g.centreOnPatch) r.point[k] = pointValue(g), r.catmull[k] = catmullValue(g);
    if (g.interior) r.exact[k] = exactValue(g), r.inverse[k] = inverseValue(g);
  }
  return r;
}
inline const Raster& raster() {
  static const Raster r = computeRaster();
  return r;
}

// RMS of (method - exact) over the interior pixels.
inline double rmsAgainstExact(const std::vector<double>& method, const Raster& r) {
  double sum = 0;
  int n = 0;
  for (size_t k = 0; k < method.size(); ++k)
    if (r.interior[k]) sum += (method[k] - r.exact[k]) * (method[k] - r.exact[k]), ++n;
  return n ? std::sqrt(sum / n) : 0.0;
}
// Interior pixels whose preimage holds some line (exact > 0) ...
inline int linePixels(const Raster& r) {
  int n = 0;
  for (size_t k = 0; k < r.exact.size(); ++k) n += r.interior[k] && r.exact[k] > 0;
  return n;
}
// ... of which a method shows none at all (value 0: the line is lost).
inline int lostLinePixels(const std::vector<double>& method, const Raster& r) {
  int n = 0;
  for (size_t k = 0; k < method.size(); ++k) n += r.interior[k] && r.exact[k] > 0 && !(method[k] > 0);
  return n;
}
inline int interiorPixels(const Raster& r) { return int(std::count(r.interior.begin(), r.interior.end(), true)); }
}  // namespace octant
