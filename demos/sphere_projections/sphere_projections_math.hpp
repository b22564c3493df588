// demos/sphere_projections/sphere_projections_math.hpp — the mathematics of Figure VI.5.
//
// The sphere p(θ, φ) = (r sin θ cos φ, r sin φ, r cos θ cos φ), θ in
// [0°, 360°), φ in [-90°, 90°], gets texture coordinates two ways (Buss VI.1.2):
//   Eq. VI.2 (latitude):  s = θ/360,  t = φ/180 + 1/2
//   Eq. VI.3 (cylinder):  s = θ/360,  t = (sin φ + 1)/2
// VI.3 projects the sphere straight out onto the cylinder around it and
// unrolls the cylinder (Archimedes' hat-box theorem): it preserves area.
//
// The claim is measured as the ratio  texture area / surface area,  the
// Jacobian |∂(s,t)/∂(surface)|, normalised so that its mean over the whole
// sphere is 1 (the texture's area 1 spread over the sphere's 4πr²).  With
// dA = r² cos φ dθ dφ (radians):
//   VI.2: ds dt = dθ dφ / (2π²)        ->  ratio(φ) = 4πr² / (2π² r² cos φ) = 2 / (π cos φ)
//   VI.3: ds dt = cos φ dθ dφ / (4π)   ->  ratio(φ) = 1
// and over a latitude band [φ0, φ1] (all θ; texture area over surface area):
//   VI.2: (φ1 - φ0)/π  over  2πr² (sin φ1 - sin φ0)/(4πr²)  =  2 (φ1 - φ0) / (π (sin φ1 - sin φ0))
//   VI.3: (sin φ1 - sin φ0)/2  over the same  =  1.
// VI.2 gives the equator 2/π ≈ 0.64 of the mean and grows like 1/cos φ
// toward the poles (3.69 in the band 70°..90°); VI.3 is 1 everywhere.
// Both pinch: at φ = ±90° every s meets one point, the whole edge t = 1
// (t = 0) of the texture.
//
// Header-only so the demo and the tests share one copy.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "common/core/mesh.hpp"

namespace sphere {
constexpr double kPi = 3.14159265358979323846;
inline double rad(double deg) { return deg * kPi / 180.0; }
inline double deg(double r) { return r * 180.0 / kPi; }

enum class Mapping { Latitude, Cylinder };  // Eq. VI.2, Eq. VI.3

inline glm::dvec2 texCoord(Mapping m, double thetaDeg, double phiDeg) {
  double s = thetaDeg / 360.0;
  double t = m == Mapping::Latitude ? phiDeg / 180.0 + 0.5 : (std::sin(rad(phiDeg)) + 1.0) / 2.0;
  return {s, t};
}
// The inverse in t: the latitude (degrees) that texture row t lands on.
inline double phiFromT(Mapping m, double t) {
  if (m == Mapping::Latitude) return (t - 0.5) * 180.0;
  return deg(std::asin(std::clamp(2.0 * t - 1.0, -1.0, 1.0)));
}

// Texture area / surface area at latitude phi, whole-sphere mean 1.
inline double ratioAt(Mapping m, double phiDeg) {
  return m == Mapping::Latitude ? 2.0 / (kPi * std::cos(rad(phiDeg))) : 1.0;
}
// The same over the band [phi0, phi1] (degrees): band texture area over band
// surface area.
inline double bandRatio(Mapping m, double phi0, double phi1) {
  if (m == Mapping::Cylinder) return 1.0;
  return 2.0 * rad(phi1 - phi0) / (kPi * (std::sin(rad(phi1)) - std::sin(rad(phi0))));
}

// The measurement's bands: 9 bands of 20° of latitude, -90..-70 first.
constexpr int kBands = 9;
constexpr double kBandDeg = 180.0 / kBands;
inline double bandLo(int b) { return -90.0 + kBandDeg * b; }
inline double bandHi(int b) { return bandLo(b + 1); }
inline double bandMid(int b) { return bandLo(b) + kBandDeg / 2; }

// The mesh: `resolution` cells per 20° band, so every band edge is a row of
// grid vertices (stacks = 9 N) and cells are square at the equator
// (slices = 2 stacks).  The shared grid (common/core/mesh.hpp) computes positions
// from the wrapped column and (s, t) from the unwrapped one: the seam column
// carries s = 1.
inline int stacksFor(int resolution) { return kBands * resolution; }
inline int slicesFor(int resolution) { return 2 * stacksFor(resolution); }
inline ts::Mesh sphereMesh(Mapping m, int resolution, double r = 1.0) {
  const int stacks = stacksFor(resolution), slices = slicesFor(resolution);
  return ts::parametricGrid(
      slices, stacks, true, false, [&](int i, int j) { return ts::spherePoint(r, slices, stacks, i, j); },
      [&](int i, int j) { return texCoord(m, 360.0 * i / slices, -90.0 + 180.0 * j / stacks); });
}

// The ratio per band computed from the mesh itself: the sum over the band's
// triangles of their (s,t) areas over the sum of their 3D areas, times the
// whole mesh's 3D area over its (s,t) area (so the whole-mesh mean is 1).
// The triangles at the poles with two vertices on the pole have no area but
// still carry (s,t) area: half of each pole cell's texture is drawn nowhere.
// That texture area (a fraction of the whole texture) is `pinchLost`.
struct MeshRatios {
  std::array<double, kBands> ratio{};
  std::array<double, kBands> texArea{}, area{};  // raw sums per band
  double totalTexArea = 0, totalArea = 0;
  double pinchLost = 0;
};
inline MeshRatios meshRatios(const ts::Mesh& m) {
  MeshRatios out;
  std::vector<unsigned> tri = m.triangles();
  for (size_t k = 0; k + 2 < tri.size(); k += 3) {
    const unsigned a = tri[k], b = tri[k + 1], c = tri[k + 2];
    glm::dvec2 u = m.st[b] - m.st[a], v = m.st[c] - m.st[a];
    double st = std::abs(u.x * v.y - u.y * v.x) / 2.0;
    double area = glm::length(glm::cross(m.points[b].pos - m.points[a].pos, m.points[c].pos - m.points[a].pos)) / 2.0;
    int row = std::min({m.index[a].y, m.index[b].y, m.index[c].y});
    int band = row * kBands / m.nv;
    out.texArea[size_t(band)] += st;
    out.area[size_t(band)] += area;
    out.totalTexArea += st;
    out.totalArea += area;
    // Zero area up to round-off (two vertices on the pole, bit-identical).
    if (area < 1e-12) out.pinchLost += st;
  }
  double norm = out.totalArea / out.totalTexArea;
  for (int b = 0; b < kBands; ++b) out.ratio[size_t(b)] = out.texArea[size_t(b)] / out.area[size_t(b)] * norm;
  return out;
}
// pinchLost in closed form: per pole, half of the pole row of cells (all s,
// one row of t) -> in total the t-height of one pole row.
inline double pinchLostExact(Mapping m, int resolution) {
  double poleRowDeg = 180.0 / stacksFor(resolution);
  glm::dvec2 top = texCoord(m, 0, 90), below = texCoord(m, 0, 90 - poleRowDeg);
  return top.y - below.y;  // (1/2 per pole) x 2 poles, mappings symmetric in φ
}

// The measuring view of band b looks at its centre (θ = 0, φ = mid) face-on
// (the sphere turned by rotateX(mid)), and measures the part of the band
// with |θ| <= thetaHalfWidth(b): the widest multiple of 20° (a multiple of
// the mesh's column width at every resolution, so the region is whole cells)
// whose every point faces the camera with n·v >= kMinFacing.  The polar
// bands are measured whole (180°).
constexpr double kMinFacing = 0.45;
inline double facing(double thetaDeg, double phiDeg, double elevationDeg) {
  // n = (sin θ cos φ, sin φ, cos θ cos φ), v = (0, sin e, cos e).
  return std::cos(rad(thetaDeg)) * std::cos(rad(phiDeg)) * std::cos(rad(elevationDeg)) +
         std::sin(rad(phiDeg)) * std::sin(rad(elevationDeg));
}
inline double thetaHalfWidth(int b) {
  for (double w = 180.0; w > 20.0; w -= 20.0) {
    bool ok = true;
    for (int k = 0; k <= 40 && ok; ++k) {
      double phi = bandLo(b) + kBandDeg * k / 40.0;
      for (int q = 0; q <= 40 && ok; ++q) ok = facing(w * q / 40.0, phi, bandMid(b)) >= kMinFacing;
    }
    if (ok) return w;
  }
  return 20.0;
}

// The measured region of band b seen in its view (orthographic along z after
// rotateX(band centre)): its bounding box (xmin, xmax, ymin, ymax) with a 3%
// margin.  The measuring panel shows just this box, so the band is hundreds
// of pixels tall: a pixel row more or less at its edges is < 0.3%.
inline glm::dvec4 regionBox(int b) {
  const double w = thetaHalfWidth(b), e = rad(bandMid(b));
  glm::dvec4 box(1e9, -1e9, 1e9, -1e9);
  for (int k = 0; k <= 72; ++k)
    for (int q = -72; q <= 72; ++q) {
      double th = rad(w * q / 72.0), ph = rad(bandLo(b) + kBandDeg * k / 72.0);
      double x = std::sin(th) * std::cos(ph), y = std::sin(ph), z = std::cos(th) * std::cos(ph);
      double yv = y * std::cos(e) - z * std::sin(e);  // rotateX(e)
      box = {std::min(box.x, x), std::max(box.y, x), std::min(box.z, yv), std::max(box.w, yv)};
    }
  glm::dvec2 margin = 0.03 * glm::dvec2(box.y - box.x, box.w - box.z);
  return {box.x - margin.x, box.y + margin.x, box.z - margin.y, box.w + margin.y};
}

// Fraction of the circle [0, 1) covered by a set of s values: 1 minus the
// largest gap between neighbours (cyclically).  All of [0,1) around a pole,
// a sliver at the equator.
inline double circularSpan(std::vector<double> s) {
  if (s.empty()) return 0.0;
  for (double& x : s) x -= std::floor(x);
  std::sort(s.begin(), s.end());
  double gap = s.front() + 1.0 - s.back();
  for (size_t k = 1; k < s.size(); ++k) gap = std::max(gap, s[k] - s[k - 1]);
  return 1.0 - gap;
}
}  // namespace sphere
