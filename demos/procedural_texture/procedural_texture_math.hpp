// demos/procedural_texture/procedural_texture_math.hpp — the demo's mathematics, GL-free: lattice noise (seed
// 001 ¶7: "a 3D texture made with noise, the lattice values precomputed and interpolated"), marble from it, and
// Rogers' fractal terrain by recursive random midpoint displacement (seed 004), with the measurements made on the
// numbers themselves (lattice bytes, the terrain's triangles, its variogram's slope).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ts::proc {
// ---- lattice noise ----------------------------------------------------------------------------------------------
// A value in [0, 1) from three integers: 32-bit unsigned arithmetic only, so the same on every platform and
// compiler (no rand(), no floating point in the hash).
inline double hash3(uint32_t i, uint32_t j, uint32_t k) {
  uint32_t h = i * 73856093u ^ j * 19349663u ^ k * 83492791u;
  h ^= h >> 16, h *= 0x7feb352du, h ^= h >> 15, h *= 0x846ca68bu, h ^= h >> 16;
  return double(h & 0xffffffu) / 16777216.0;
}

// The precomputed lattice: period^3 random values, lattice point (i, j, k) at values[i + p (j + p k)], read
// modulo the period (the noise tiles every `period` cells).  One lattice serves every octave.
constexpr int kLatticePeriod = 16;
constexpr int kBaseCells = 2;  // octave 0: 2 lattice cells across the unit cube; octave i: 2 x 2^i
constexpr int kMaxOctaves = 6;
struct Lattice {
  int period = kLatticePeriod;
  std::vector<float> values;
  size_t bytes() const { return values.size() * sizeof(float); }
};
inline Lattice makeLattice(int period = kLatticePeriod) {
  Lattice l;
  l.period = period;
  l.values.resize(size_t(period) * size_t(period) * size_t(period));
  for (int k = 0; k < period; ++k)
    for (int j = 0; j < period; ++j)
      for (int i = 0; i < period; ++i)
        l.values[size_t(i + period * (j + period * k))] = float(hash3(uint32_t(i), uint32_t(j), uint32_t(k)));
  return l;
}
inline const Lattice& lattice() {
  static const Lattice l = makeLattice();
  return l;
}

// Value noise at (x, y, z) in lattice cells: the eight lattice values round the point, trilinearly interpolated
//   n = sum over the corners c of w_c L[c],  w = (1 - fx or fx)(1 - fy or fy)(1 - fz or fz),  f = frac(x, y, z)
inline double noise(const Lattice& l, double x, double y, double z) {
  const double fx0 = std::floor(x), fy0 = std::floor(y), fz0 = std::floor(z);
  const double fx = x - fx0, fy = y - fy0, fz = z - fz0;
  const int p = l.period;
  auto wrap = [p](double v) { return int(((long long)v % p + p) % p); };
  const int i0 = wrap(fx0), j0 = wrap(fy0), k0 = wrap(fz0);
  const int i1 = (i0 + 1) % p, j1 = (j0 + 1) % p, k1 = (k0 + 1) % p;
  auto L = [&](int i, int j, int k) { return double(l.values[size_t(i + p * (j + p * k))]); };
  const double x00 = L(i0, j0, k0) * (1 - fx) + L(i1, j0, k0) * fx, x10 = L(i0, j1, k0) * (1 - fx) + L(i1, j1, k0) * fx;
  const double x01 = L(i0, j0, k1) * (1 - fx) + L(i1, j0, k1) * fx, x11 = L(i0, j1, k1) * (1 - fx) + L(i1, j1, k1) * fx;
  const double y0 = x00 * (1 - fy) + x10 * fy, y1 = x01 * (1 - fy) + x11 * fy;
  return y0 * (1 - fz) + y1 * fz;
}

// The octaves summed at a point of the unit cube: octave i at kBaseCells 2^i cells across, amplitude 2^-i, read
// from the one lattice at an offset of its own (so the octaves do not line up), normalised to [0, 1]:
//   S(p) = sum_{i<k} 2^-i n(2^i c p + o_i) / sum_{i<k} 2^-i
inline double octaves(const Lattice& l, double x, double y, double z, int k) {
  double sum = 0, amp = 1, norm = 0;
  for (int i = 0; i < k; ++i) {
    const double f = kBaseCells * double(1 << i), o = 5.3 * i;
    sum += amp * noise(l, f * x + o, f * y + o, f * z + o), norm += amp, amp *= 0.5;
  }
  return norm > 0 ? sum / norm : 0;
}

// Bytes of lattice values the octaves need: one lattice reused at every octave (what the demo does), against a
// lattice of its own for each octave, covering the unit cube without repeating ((kBaseCells 2^i + 1)^3 values).
inline size_t latticeBytesReused(int /*octaves*/) { return lattice().bytes(); }
inline size_t latticeBytesPerLevel(int k) {
  size_t n = 0;
  for (int i = 0; i < k; ++i) {
    const size_t side = size_t(kBaseCells) * (size_t(1) << i) + 1;
    n += side * side * side;
  }
  return n * sizeof(float);
}

// ---- marble -----------------------------------------------------------------------------------------------------
// Turbulence: the octaves' absolute deviations, |2 n - 1|, summed at amplitudes 2^-i (in [0, ~2)).
inline double turbulence(const Lattice& l, double x, double y, double z, int k) {
  double sum = 0, amp = 1;
  for (int i = 0; i < k; ++i) {
    const double f = kBaseCells * double(1 << i), o = 11.7 * i;
    sum += amp * std::abs(2 * noise(l, f * x + o, f * y + o, f * z + o) - 1), amp *= 0.5;
  }
  return sum;
}
// Marble: M(p) = 1/2 + 1/2 sin(2 pi (stripes x + a T(p))), stripes across the unit cube, a the turbulence's weight.
// With a = 0 the stripes' period is exactly 1 / stripes; turbulence bends them, and keeps the mean period.
inline double marble(const Lattice& l, double x, double y, double z, int stripes, double a, int k) {
  const double kPi = 3.14159265358979323846;
  return 0.5 + 0.5 * std::sin(2 * kPi * (stripes * x + a * turbulence(l, x, y, z, k)));
}

// ---- fractal terrain ----------------------------------------------------------------------------------------------
// A (2^d + 1)^2 height field by diamond-square (Fournier, Fussell and Carpenter's recursive random midpoint
// displacement, as Rogers gives it): the corners random; then, for squares of side s = 2^d, 2^(d-1), .., 2:
//   diamond: each square's centre = the mean of its 4 corners + s^H r
//   square:  each edge's midpoint = the mean of its 2..4 diamond neighbours + s^H r
// r uniform in [-1/2, 1/2) from the point's place on the finest grid (hash3), s in units of the finest grid's
// step at depth kTerrainMaxDepth, so a shallower field is the deeper one's coarse points exactly.
// The roughness then scales as a power of the distance: E[(h(x + r) - h(x))^2]^(1/2) ~ r^H.
constexpr int kTerrainMaxDepth = 9;
struct HeightField {
  int depth = 0, n = 1;  // n = 2^depth cells a side, (n + 1)^2 heights
  std::vector<double> h;
  double at(int x, int y) const { return h[size_t(y) * size_t(n + 1) + size_t(x)]; }
};
inline HeightField diamondSquare(int depth, double H, uint32_t seed) {
  HeightField f;
  f.depth = depth, f.n = 1 << depth;
  const int n = f.n, w = n + 1;
  f.h.assign(size_t(w) * size_t(w), 0.0);
  const int scale = 1 << (kTerrainMaxDepth - std::min(depth, kTerrainMaxDepth));  // finest-grid steps a cell
  auto r = [&](int x, int y) { return hash3(uint32_t(x * scale), uint32_t(y * scale), seed) - 0.5; };
  auto H_ = [&](int x, int y) -> double& { return f.h[size_t(y) * size_t(w) + size_t(x)]; };
  const double top = std::pow(double(n * scale), H);
  for (int y : {0, n})
    for (int x : {0, n}) H_(x, y) = top * r(x, y);
  for (int s = n; s >= 2; s /= 2) {
    const int half = s / 2;
    const double amp = std::pow(double(s * scale) / std::sqrt(2.0), H), amp2 = std::pow(double(half * scale), H);
    for (int y = half; y < n; y += s)
      for (int x = half; x < n; x += s)
        H_(x, y) = (H_(x - half, y - half) + H_(x + half, y - half) + H_(x - half, y + half) + H_(x + half, y + half)) /
                       4 +
                   amp * r(x, y);
    for (int y = 0; y <= n; y += half)
      for (int x = (y / half) % 2 == 0 ? half : 0; x <= n; x += s) {
        double sum = 0;
        int c = 0;
        if (x >= half) sum += H_(x - half, y), ++c;
        if (x + half <= n) sum += H_(x + half, y), ++c;
        if (y >= half) sum += H_(x, y - half), ++c;
        if (y + half <= n) sum += H_(x, y + half), ++c;
        H_(x, y) = sum / c + amp2 * r(x, y);
      }
  }
  return f;
}

// The variogram at lag r (grid steps): the mean of (h(x + r) - h(x))^2 over every pair r apart along a row or a
// column.  Its log against log r is a line of slope 2H where the field is self-affine of exponent H.
inline double variogram(const HeightField& f, int r) {
  double sum = 0;
  size_t count = 0;
  for (int y = 0; y <= f.n; ++y)
    for (int x = 0; x + r <= f.n; ++x) {
      const double a = f.at(x + r, y) - f.at(x, y), b = f.at(y, x + r) - f.at(y, x);
      sum += a * a + b * b, count += 2;
    }
  return count ? sum / double(count) : 0;
}
// H fitted from the field: least squares of (1/2) log variogram(r) against log r, r = 1, 2, 4, .., maxLag.
inline double fittedH(const HeightField& f, int maxLag) {
  std::vector<double> xs, ys;
  for (int r = 1; r <= maxLag; r *= 2) xs.push_back(std::log(double(r))), ys.push_back(0.5 * std::log(variogram(f, r)));
  const double n = double(xs.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < xs.size(); ++i) sx += xs[i], sy += ys[i], sxx += xs[i] * xs[i], sxy += xs[i] * ys[i];
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// The depth the distance chooses: one level less each time the distance doubles, so that a cell's projected size
// (its edge 2^-d over the distance) stays about the same: d = clamp(maxDepth - round(log2 distance), 1, maxDepth).
constexpr int kTerrainShownMaxDepth = 6;  // the deepest level drawn (2 4^6 = 8192 triangles)
inline int depthForDistance(double distance) {
  const int d = kTerrainShownMaxDepth - int(std::lround(std::log2(std::max(distance, 1e-6))));
  return std::clamp(d, 1, kTerrainShownMaxDepth);
}
}  // namespace ts::proc
