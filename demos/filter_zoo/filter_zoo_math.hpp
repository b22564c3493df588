// demos/filter_zoo/filter_zoo_math.hpp — the filter zoo's mathematics, without
// OpenGL, shared by the demo and its tests (tests/unit/zoo_test.cpp asserts
// every closed form here against a computation of its own).
//
// 1. Magnification (Buss VI.1.3, seed 002).  GL_NEAREST with 256 texels over
//    W pixels takes texel floor((x + 1/2) 256 / W) at pixel x.  Over 300
//    pixels 300 - 256 = 44 texels get two pixels and 212 get one ("texels get
//    unequal pixel counts"); over 512 every texel gets 2; over 200 pixels
//    256 - 200 = 56 texels are never shown ("minification skips texels").
// 2. Memory.  A mipmap adds sum 4^-k < 1/3; a ripmap (levels W/2^i x H/2^j,
//    every i and j) holds sum_i 2^-i times sum_j 2^-j = (2 - 2^-k)^2 times
//    the texture: 3.98439 at 256^2 (seed 001's "3x" is the overhead,
//    2.98439).  A summed-area table's largest sum is 255 W H, so it needs
//    ceil(log2(255 W H + 1)) bits a channel: 24 at 256^2 (3x an 8-bit
//    texture; seed 001: ">= 16 bits"), 26 at 512^2, 28 at 1024^2.  A 32-bit
//    float holds integers exactly up to 2^24: 255 W H passes it at 512^2.
// 3. Levels.  GL halves each side down to 1 (a side already 1 stays 1) and
//    ends at 1 x 1: 32 x 64 has 7 levels; seed 001's "until either
//    dimension is one texel" stops at 1 x 2: 6.
// 4. The two LOD forms.  rho_edge = max(|(u_x, v_x)|, |(u_y, v_y)|) (GL's
//    formula) is the same for a footprint turned any way; rho_max =
//    max(|u_x|, |v_x|, |u_y|, |v_y|) (the largest partial derivative) is
//    1/sqrt 2 of it at 45 degrees: log2(rho_edge / rho_max) = 0.5 there, 0
//    along the axes.
// 5. SAT's box.  The bounding box of the derivative parallelogram over its
//    area, (|u_x| + |u_y|)(|v_x| + |v_y|) / |u_x v_y - u_y v_x|: 1 for an
//    axis-aligned footprint, (9/sqrt 2)^2 / 8 = 5.0625 for an 8:1 one at 45.
// 6. The methods on the CPU (each counts the texels it reads):
//    nearest, bilinear, GL_NEAREST_MIPMAP_NEAREST and trilinear by GL's rules
//    (4.6 §8.14, common/core/mip_lod.hpp) on the book's 2x2 chain; the
//    ripmap (level i from log2 max(|u_x|, |u_y|), j from log2 max(|v_x|,
//    |v_y|), both fractional: 4 levels x 4 texels); the SAT (the average
//    over the footprint's bounding box, [S(x1,y1) - S(x0,y1) - S(x1,y0) +
//    S(x0,y0)] / area, each S bilinear between table entries, which is
//    exact for texels constant over their squares: 16 reads); the probe
//    line (seed 001 ¶17-18: P_x = |(u_x, v_x)|, P_y = |(u_y, v_y)|,
//    N = min(ceil(P_max / P_min), 16), lambda = log2(P_max / N), N
//    trilinear probes spaced along the major axis: 8N texels); EWA
//    (common/core/ewa.hpp, shared with the parallax demo, the corrected F);
//    and the exact reference: the area average over the pixel's preimage
//    (common/core/area_filter.hpp: ts::AreaIntegral, the same numbers as
//    clipping the preimage against every texel square).
// 7. The scenes, each a homography from window pixels to texels: the
//    mipmap demo's slanted ground plane (common/core/slant_plane.hpp) with
//    the texture turned by an azimuth; a zone plate seen flat; a
//    magnification (256 texels over 300 pixels).
// 8. Mip kernels: each level made from the one before by a separable 2:1
//    decimation with a box (Buss's 2x2), tent (Crow's pyramid), Gaussian,
//    Lanczos-2/3 or Kaiser-windowed sinc, in sRGB values or linear light.
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "common/core/area_filter.hpp"
#include "common/core/ewa.hpp"
#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "common/core/mip_lod.hpp"
#include "common/core/slant_plane.hpp"
#include "common/core/textures.hpp"

namespace zoo {
using ts::lod::Jacobian;

constexpr double kPi = 3.14159265358979323846;
constexpr int kTexels = 256;  // every texture of the zoo is 256 x 256: levels 0..8
constexpr int kLevels = 9;
constexpr double kMaxAniso = 16;   // GL's anisotropic 16x, the probe line's and EWA's limit
constexpr double kEwaAlpha = 2.0;  // EWA's Gaussian falloff, exp(-alpha Q/F) (the parallax demo's)

// ---------------------------------------------------------------- 1. magnification
// The texel GL_NEAREST takes at pixel x when `texels` texels span `pixels`
// pixels (s from 0 to 1 across them).
inline int nearestTexel(int x, int pixels, int texels = kTexels) {
  return int(std::floor((x + 0.5) * texels / pixels));
}
// How many texels got no pixel, one, two, more.
struct TexelCounts {
  int unseen = 0, once = 0, twice = 0, more = 0;
};
inline TexelCounts countTexels(const std::vector<int>& texelOfPixel, int texels = kTexels) {
  std::vector<int> n(size_t(texels), 0);
  for (int t : texelOfPixel)
    if (t >= 0 && t < texels) ++n[size_t(t)];
  TexelCounts c;
  for (int k : n) (k == 0 ? c.unseen : k == 1 ? c.once : k == 2 ? c.twice : c.more)++;
  return c;
}

// ---------------------------------------------------------------- 2, 3. memory and levels
// GL's chain: each side halved (never below 1) until 1 x 1.
inline int glLevelCount(int w, int h) {
  int n = 1;
  while (w > 1 || h > 1) w = std::max(1, w / 2), h = std::max(1, h / 2), ++n;
  return n;
}
// Seed 001: "downsample until either dimension is one texel".
inline int seedLevelCount(int w, int h) {
  int n = 1;
  while (w > 1 && h > 1) w /= 2, h /= 2, ++n;
  return n;
}
// Texels of every GL level over the texels of level 0.
inline double mipMemoryRatio(int w, int h) {
  double sum = 0;
  for (int k = 0, a = w, b = h; k < glLevelCount(w, h); ++k, a = std::max(1, a / 2), b = std::max(1, b / 2))
    sum += double(a) * b;
  return sum / (double(w) * h);
}
// Texels of every ripmap level (W/2^i x H/2^j, i and j from 0 to the last
// level of each side) over the texels of level 0.
inline double ripmapMemoryRatio(int w, int h) {
  double su = 0, sv = 0;
  for (int a = w;; a /= 2) {
    su += a;
    if (a == 1) break;
  }
  for (int b = h;; b /= 2) {
    sv += b;
    if (b == 1) break;
  }
  return su * sv / (double(w) * h);
}
// The largest entry of a w x h summed-area table of `maxValue`-valued texels.
inline long long satLargestSum(long long w, long long h, long long maxValue = 255) { return maxValue * w * h; }
// Bits a channel needs to hold every SAT entry: ceil(log2(largest + 1)).
inline int satBits(long long w, long long h, long long maxValue = 255) {
  const long long largest = satLargestSum(w, h, maxValue);
  int b = 0;
  while ((1LL << b) <= largest) ++b;
  return b;
}
// Whether every SAT entry is an integer a 32-bit float holds exactly (all
// integers up to 2^24 are; beyond, only some).
inline bool floatHoldsSat(long long w, long long h, long long maxValue = 255) {
  return satLargestSum(w, h, maxValue) <= (1LL << 24);
}
// The table summed in 32-bit floats as a GPU builds it, a prefix sum along
// each row, then down each column (so no partial sum exceeds the entry it
// makes), over the red channel of `img` tiled to side x side texels: how
// many entries differ from the exact integer sum.  0 while 255 side^2 <= 2^24.
inline long floatSatMismatches(const ts::Image& img, int side) {
  std::vector<float> column(size_t(side), 0.0f);
  std::vector<long long> exactColumn(size_t(side), 0);
  long bad = 0;
  for (int y = 0; y < side; ++y) {
    float row = 0.0f;
    long long exactRow = 0;
    for (int x = 0; x < side; ++x) {
      const int v = img.at(x % img.width, y % img.height).r;
      row += float(v), exactRow += v;
      column[size_t(x)] += row, exactColumn[size_t(x)] += exactRow;
      bad += double(column[size_t(x)]) != double(exactColumn[size_t(x)]);
    }
  }
  return bad;
}

// ---------------------------------------------------------------- 4, 5. footprints
// A footprint `major` texels long and `minor` wide, its long side at
// `angleDeg` to the u axis: d(u,v)/dx along it, d(u,v)/dy across.
inline Jacobian footprint(double major, double minor, double angleDeg) {
  const double a = glm::radians(angleDeg), c = std::cos(a), s = std::sin(a);
  Jacobian j;
  j.dudx = major * c, j.dvdx = major * s;
  j.dudy = -minor * s, j.dvdy = minor * c;
  return j;
}
// log2(rho_edge / rho_max): how much lower the largest-partial-derivative
// form puts the LOD.
inline double lodFormGap(const Jacobian& j) { return std::log2(ts::lod::rhoExact(j) / ts::lod::rhoMax(j)); }
// The SAT's bounding box over the derivative parallelogram's area.
inline double satBoxRatio(const Jacobian& j) {
  return (std::abs(j.dudx) + std::abs(j.dudy)) * (std::abs(j.dvdx) + std::abs(j.dvdy)) /
         std::abs(j.dudx * j.dvdy - j.dudy * j.dvdx);
}

// ---------------------------------------------------------------- textures and pyramids
// One level as doubles (8-bit units), GL_REPEAT.
struct Level {
  int w = 0, h = 0;
  std::vector<glm::dvec4> t;
  Level() = default;
  explicit Level(const ts::Image& img) : w(img.width), h(img.height), t(size_t(img.width) * size_t(img.height)) {
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const ts::Rgba c = img.at(i, j);
        t[size_t(j) * size_t(w) + size_t(i)] = glm::dvec4(c.r, c.g, c.b, c.a);
      }
  }
  const glm::dvec4& at(long i, long j) const {
    i %= w, j %= h;
    if (i < 0) i += w;
    if (j < 0) j += h;
    return t[size_t(j) * size_t(w) + size_t(i)];
  }
};

// 2:1 in u (axis 0) or v (axis 1), 8-bit, rounding half up (the ripmap's step).
inline ts::Image halve(const ts::Image& src, int axis) {
  const int w = axis == 0 ? std::max(1, src.width / 2) : src.width,
            h = axis == 1 ? std::max(1, src.height / 2) : src.height;
  ts::Image dst(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const ts::Rgba a = axis == 0 ? src.at(std::min(2 * i, src.width - 1), j)
                                   : src.at(i, std::min(2 * j, src.height - 1));
      const ts::Rgba b = axis == 0 ? src.at(std::min(2 * i + 1, src.width - 1), j)
                                   : src.at(i, std::min(2 * j + 1, src.height - 1));
      dst.set(i, j,
              {uint8_t((a.r + b.r + 1) / 2), uint8_t((a.g + b.g + 1) / 2), uint8_t((a.b + b.b + 1) / 2),
               uint8_t((a.a + b.a + 1) / 2)});
    }
  return dst;
}

// A ripmap: level (i, j) is W/2^i x H/2^j, made from (i - 1, j) by halving u
// (from (0, j - 1) by halving v in the first column).
struct Ripmap {
  int nu = 0, nv = 0;         // levels along u and v
  std::vector<Level> levels;  // (i, j) at j * nu + i
  std::vector<ts::Image> images;
  explicit Ripmap(const ts::Image& base) {
    nu = glLevelCount(base.width, 1), nv = glLevelCount(1, base.height);
    images.resize(size_t(nu) * size_t(nv));
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i)
        images[size_t(j * nu + i)] = i > 0   ? halve(images[size_t(j * nu + i - 1)], 0)
                                     : j > 0 ? halve(images[size_t((j - 1) * nu)], 1)
                                             : base;
    for (const ts::Image& im : images) levels.emplace_back(im);
  }
  const Level& at(int i, int j) const { return levels[size_t(j * nu + i)]; }
  long texels() const {
    long n = 0;
    for (const Level& l : levels) n += long(l.w) * l.h;
    return n;
  }
};

// The summed-area table of a texture, in doubles (exact: 255 W H < 2^53):
// S(I, J) = the sum of texels i < I, j < J, any integers I, J (GL_REPEAT:
// whole periods added), and between integers bilinear, which is exact for
// texels constant over their squares.
struct Sat {
  int w = 0, h = 0;
  std::vector<glm::dvec4> s;  // (w + 1) x (h + 1)
  explicit Sat(const ts::Image& img)
      : w(img.width), h(img.height), s(size_t(img.width + 1) * size_t(img.height + 1), glm::dvec4(0.0)) {
    for (int j = 1; j <= h; ++j)
      for (int i = 1; i <= w; ++i) {
        const ts::Rgba c = img.at(i - 1, j - 1);
        s[idx(i, j)] = glm::dvec4(c.r, c.g, c.b, c.a) + s[idx(i - 1, j)] + s[idx(i, j - 1)] - s[idx(i - 1, j - 1)];
      }
  }
  size_t idx(int i, int j) const { return size_t(j) * size_t(w + 1) + size_t(i); }
  static long floorDiv(long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
  glm::dvec4 entry(long I, long J) const {  // one table read
    const long q = floorDiv(I, w), r = floorDiv(J, h);
    const int m = int(I - q * w), n = int(J - r * h);
    return double(q) * double(r) * s[idx(w, h)] + double(q) * s[idx(w, n)] + double(r) * s[idx(m, h)] + s[idx(m, n)];
  }
  glm::dvec4 at(double x, double y, long* reads) const {  // bilinear: 4 reads
    const double fx = std::floor(x), fy = std::floor(y), ax = x - fx, ay = y - fy;
    const long I = long(fx), J = long(fy);
    if (reads) *reads += 4;
    return glm::mix(glm::mix(entry(I, J), entry(I + 1, J), ax), glm::mix(entry(I, J + 1), entry(I + 1, J + 1), ax), ay);
  }
  // The average over [u0, u1] x [v0, v1] (texels): 4 corners, 16 reads.
  glm::dvec4 boxAverage(double u0, double v0, double u1, double v1, long* reads) const {
    // Whole periods off first, so the sums stay small.
    const double su = w * std::floor(u0 / w), sv = h * std::floor(v0 / h);
    u0 -= su, u1 -= su, v0 -= sv, v1 -= sv;
    const glm::dvec4 sum = at(u1, v1, reads) - at(u0, v1, reads) - at(u1, v0, reads) + at(u0, v0, reads);
    return sum / ((u1 - u0) * (v1 - v0));
  }
};

// sRGB values (0..255) to linear light (0..1) and back.
inline double srgbToLinear(double v8) {
  const double c = v8 / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
inline double linearToSrgb(double l) {
  l = std::clamp(l, 0.0, 1.0);
  return 255.0 * (l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1 / 2.4) - 0.055);
}
// Everything the CPU methods read, made once per texture.
struct Pyramids {
  ts::Image base;
  std::vector<ts::Image> mip8;  // the book's 2x2 chain, bytes as GL holds them
  std::vector<Level> chain;
  Ripmap rip;
  Sat sat;
  ts::AreaIntegral exact;
  explicit Pyramids(const ts::Image& img) : base(img), mip8(ts::buildMipChain(img)), rip(img), sat(img), exact(img) {
    for (const ts::Image& l : mip8) chain.emplace_back(l);
  }
  // The exact integral of the linear-light values (0..1; alpha / 255): only
  // the kernels view asks for it, so it is made when first asked (a window's
  // first picture does not wait for its 8 ms).
  const ts::AreaIntegral& exactLinear() const {
    std::call_once(linearOnce_,
                   [&] { linear_ = std::make_unique<ts::AreaIntegral>(base.width, base.height, linearTexels(base)); });
    return *linear_;
  }
  static std::vector<glm::dvec4> linearTexels(const ts::Image& img) {
    std::vector<glm::dvec4> t;
    for (int j = 0; j < img.height; ++j)
      for (int i = 0; i < img.width; ++i) {
        const ts::Rgba c = img.at(i, j);
        t.push_back({srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b), c.a / 255.0});
      }
    return t;
  }
  int levels() const { return int(chain.size()); }

 private:
  mutable std::once_flag linearOnce_;
  mutable std::unique_ptr<ts::AreaIntegral> linear_;
};

// ---------------------------------------------------------------- 6. the lookups
// (u, v) in texels of level 0 (texel (i, j) covers [i, i+1] x [j, j+1]); the
// Jacobian in texels of level 0 per pixel.  `reads` (optional) counts the
// texels (or table entries) read.
inline glm::dvec4 nearest(const Level& l, double u, double v, long* reads) {
  if (reads) ++*reads;
  return l.at(long(std::floor(u)), long(std::floor(v)));
}
// GL_LINEAR: the four texels around (u - 1/2, v - 1/2).
inline glm::dvec4 bilinear(const Level& l, double u, double v, long* reads) {
  const double x = u - 0.5, y = v - 0.5, fx = std::floor(x), fy = std::floor(y), ax = x - fx, ay = y - fy;
  const long i = long(fx), j = long(fy);
  if (reads) *reads += 4;
  return glm::mix(glm::mix(l.at(i, j), l.at(i + 1, j), ax), glm::mix(l.at(i, j + 1), l.at(i + 1, j + 1), ax), ay);
}
// (u, v) on level L: level-0 texels scaled by 2^-L.
inline glm::dvec4 bilinearAt(const std::vector<Level>& chain, int L, double u, double v, long* reads) {
  const double s = std::ldexp(1.0, -L);
  return bilinear(chain[size_t(L)], u * s, v * s, reads);
}
inline double glLambda(const Jacobian& j, double bias) { return std::log2(ts::lod::rhoExact(j)) + bias; }

// GL_NEAREST_MIPMAP_NEAREST (magnifying with GL_NEAREST: c = 0).
inline glm::dvec4 nearestMipNearest(const std::vector<Level>& chain, double u, double v, const Jacobian& j, double bias,
                                    long* reads) {
  const double lambda = glLambda(j, bias);
  const int L = lambda <= 0 ? 0 : ts::lod::nearestLevel(lambda, int(chain.size()));
  const double s = std::ldexp(1.0, -L);
  return nearest(chain[size_t(L)], u * s, v * s, reads);
}
// Trilinear at a given lambda: GL_LINEAR on level 0 when magnifying, else the
// two levels around lambda blended (one level at the last).
inline glm::dvec4 trilinearAt(const std::vector<Level>& chain, double u, double v, double lambda, long* reads) {
  const ts::lod::LevelBlend b = ts::lod::linearLevels(lambda, int(chain.size()));
  const glm::dvec4 a = bilinearAt(chain, b.lo, u, v, reads);
  if (b.weight <= 0 || b.hi == b.lo) return a;
  return glm::mix(a, bilinearAt(chain, b.hi, u, v, reads), b.weight);
}
inline glm::dvec4 trilinear(const std::vector<Level>& chain, double u, double v, const Jacobian& j, double bias,
                            long* reads) {
  return trilinearAt(chain, u, v, glLambda(j, bias), reads);
}

// The ripmap levels (fractional) a footprint asks for.
inline glm::dvec2 ripmapLevels(const Jacobian& j, double bias) {
  return {std::log2(std::max({std::abs(j.dudx), std::abs(j.dudy), 1e-300})) + bias,
          std::log2(std::max({std::abs(j.dvdx), std::abs(j.dvdy), 1e-300})) + bias};
}
// 4 levels x 4 texels: the levels around (i, j), bilinear on each, blended by
// the fractions.
inline glm::dvec4 ripmap(const Ripmap& r, double u, double v, const Jacobian& j, double bias, long* reads) {
  const glm::dvec2 lv = ripmapLevels(j, bias);
  const double li = std::clamp(lv.x, 0.0, double(r.nu - 1)), lj = std::clamp(lv.y, 0.0, double(r.nv - 1));
  const int i0 = std::min(int(std::floor(li)), r.nu - 1), j0 = std::min(int(std::floor(lj)), r.nv - 1);
  const double fi = li - i0, fj = lj - j0;
  glm::dvec4 sum(0.0);
  for (int dj = 0; dj <= 1; ++dj)
    for (int di = 0; di <= 1; ++di) {
      const double w = (di ? fi : 1 - fi) * (dj ? fj : 1 - fj);
      if (w <= 0) continue;
      const int i = std::min(i0 + di, r.nu - 1), jj = std::min(j0 + dj, r.nv - 1);
      sum += w * bilinear(r.at(i, jj), std::ldexp(u, -i), std::ldexp(v, -jj), reads);
    }
  return sum;
}

// The SAT's box: the bounding box of the derivative parallelogram centred at
// (u, v), each side at least one texel, scaled by 2^bias.
inline glm::dvec2 satHalfBox(const Jacobian& j, double bias) {
  const double k = 0.5 * std::exp2(bias);
  return {std::max(0.5, k * (std::abs(j.dudx) + std::abs(j.dudy))),
          std::max(0.5, k * (std::abs(j.dvdx) + std::abs(j.dvdy)))};
}
inline glm::dvec4 sat(const Sat& s, double u, double v, const Jacobian& j, double bias, long* reads) {
  const glm::dvec2 hb = satHalfBox(j, bias);
  return s.boxAverage(u - hb.x, v - hb.y, u + hb.x, v + hb.y, reads);
}

// The probe line (seed 001 ¶17-18): N trilinear probes along the major axis.
struct ProbeLine {
  int n = 1;
  double lambda = 0;
  glm::dvec2 axis{0.0};  // the major axis vector (texels)
  glm::dvec2 at(glm::dvec2 centre, int k) const { return centre + axis * ((k + 0.5) / n - 0.5); }
};
inline ProbeLine probeLine(const Jacobian& j, double bias, double maxAniso = kMaxAniso) {
  const double px = std::hypot(j.dudx, j.dvdx), py = std::hypot(j.dudy, j.dvdy);
  const double pmax = std::max(px, py), pmin = std::min(px, py);
  ProbeLine p;
  p.n = pmin > 0 ? int(std::min(std::ceil(pmax / pmin), maxAniso)) : int(maxAniso);
  p.n = std::max(1, p.n);
  p.lambda = std::log2(std::max(pmax, 1e-300) / p.n) + bias;
  p.axis = px >= py ? glm::dvec2(j.dudx, j.dvdx) : glm::dvec2(j.dudy, j.dvdy);
  return p;
}
inline glm::dvec4 probes(const std::vector<Level>& chain, double u, double v, const Jacobian& j, double bias,
                         long* reads) {
  const ProbeLine p = probeLine(j, bias);
  glm::dvec4 sum(0.0);
  for (int k = 0; k < p.n; ++k) {
    const glm::dvec2 q = p.at({u, v}, k);
    sum += trilinearAt(chain, q.x, q.y, p.lambda, reads);
  }
  return sum / double(p.n);
}

// EWA (common/core/ewa.hpp): the ellipse of the derivatives, Gaussian weights.
inline glm::dvec4 ewa(const std::vector<Level>& chain, double u, double v, const Jacobian& j, double bias,
                      long* reads) {
  return ts::ewa::ewaFilter([&](int L, long i, long jj) { return chain[size_t(L)].at(i, jj); }, int(chain.size()), u, v,
                            j.dudx, j.dvdx, j.dudy, j.dvdy, kEwaAlpha, kMaxAniso, bias, reads);
}

// ---------------------------------------------------------------- 7. scenes as homographies
// A picture w x h whose window pixel (x, y) (GL: y up, centres at +1/2)
// shows texel (u, v) = (H (x, y, 1)).xy / (H (x, y, 1)).z of level 0, where
// every a.(x, y, 1) >= 0 for a in `inside` (the surface's extent).
struct View {
  int w = 0, h = 0;
  glm::dmat3 H{1.0};  // glm: H[col][row]
  std::vector<glm::dvec3> inside;
  bool covers(double x, double y) const {
    const glm::dvec3 p(x, y, 1);
    for (const glm::dvec3& a : inside)
      if (glm::dot(a, p) < 0) return false;
    return true;
  }
  glm::dvec2 uv(double x, double y) const {
    const glm::dvec3 q = H * glm::dvec3(x, y, 1);
    return {q.x / q.z, q.y / q.z};
  }
  // d(u, v)/dx and d(u, v)/dy of the homography, exactly.
  Jacobian jacobian(double x, double y) const {
    const glm::dvec3 q = H * glm::dvec3(x, y, 1);
    const glm::dvec3 qx = H * glm::dvec3(1, 0, 0), qy = H * glm::dvec3(0, 1, 0);
    Jacobian j;
    j.dudx = (qx.x * q.z - q.x * qx.z) / (q.z * q.z);
    j.dvdx = (qx.y * q.z - q.y * qx.z) / (q.z * q.z);
    j.dudy = (qy.x * q.z - q.x * qy.z) / (q.z * q.z);
    j.dvdy = (qy.y * q.z - q.y * qy.z) / (q.z * q.z);
    return j;
  }
  // The preimage of the pixel in image row `row` (0 = top), column `col`:
  // its four corners mapped to texels.
  ts::Polygon2 preimage(int col, int row) const {
    const double y = h - 1 - row;
    return {uv(col, y), uv(col + 1, y), uv(col + 1, y + 1), uv(col, y + 1)};
  }
  // Whether the whole pixel square lies on the surface.
  bool coversPixel(int col, int row) const {
    const double y = h - 1 - row;
    return covers(col, y) && covers(col + 1, y) && covers(col + 1, y + 1) && covers(col, y + 1);
  }
  // The picture rectangle cut by `inside`: the polygon GL draws (counter-clockwise).
  std::vector<glm::dvec2> outline() const {
    std::vector<glm::dvec2> poly{{0, 0}, {double(w), 0}, {double(w), double(h)}, {0, double(h)}};
    for (const glm::dvec3& a : inside) {
      std::vector<glm::dvec2> out;
      for (size_t k = 0; k < poly.size(); ++k) {
        const glm::dvec2 p = poly[k], q = poly[(k + 1) % poly.size()];
        const double dp = a.x * p.x + a.y * p.y + a.z, dq = a.x * q.x + a.y * q.y + a.z;
        if (dp >= 0) out.push_back(p);
        if ((dp >= 0) != (dq >= 0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
      }
      poly = out;
    }
    return poly;
  }
};

// The turn of the texture by `azimuthDeg` and the scale to texels:
// (s q, t q, q) -> (u q, v q, q), u = 256 (s cos a - t sin a), v = 256 (s sin a + t cos a).
inline glm::dmat3 turnAndScale(double azimuthDeg, double texels = kTexels) {
  const double a = glm::radians(azimuthDeg), c = std::cos(a) * texels, s = std::sin(a) * texels;
  glm::dmat3 m(1.0);
  m[0][0] = c, m[1][0] = -s;  // row 0: (c, -s, 0)
  m[0][1] = s, m[1][1] = c;   // row 1: (s, c, 0)
  return m;
}
// The mipmap demo's slanted ground plane (common/core/slant_plane.hpp) at w x h,
// the texture turned by `azimuthDeg` about the plane's normal.
inline View slantView(int w, int h, double azimuthDeg) {
  const glm::dmat3 G = ts::slant::groundHomography(ts::slant::slantCamera(w, h));  // (s q, t q, q)
  View v;
  v.w = w, v.h = h;
  v.H = turnAndScale(azimuthDeg) * G;
  auto row = [&](int r) { return glm::dvec3(G[0][r], G[1][r], G[2][r]); };
  const glm::dvec3 s = row(0), t = row(1), q = row(2);
  v.inside = {q - 1e-9 * glm::dvec3(0, 0, 1),                                            // in front of the eye
              ts::slant::kGroundHalfWidth * q - s, ts::slant::kGroundHalfWidth * q + s,  // |s| <= half width
              t, ts::slant::kGroundDepth * q - t};                                       // 0 <= t <= depth
  return v;
}
// A flat view: u = centre + texelsPerPixel R(azimuth) (x - w/2, y - h/2).
inline View flatView(int w, int h, double azimuthDeg, double texelsPerPixel, glm::dvec2 centre) {
  View v;
  v.w = w, v.h = h;
  glm::dmat3 shift(1.0);
  shift[2][0] = -w / 2.0, shift[2][1] = -h / 2.0;
  glm::dmat3 back(1.0);
  back[2][0] = centre.x, back[2][1] = centre.y;
  v.H = back * turnAndScale(azimuthDeg, texelsPerPixel) * shift;
  return v;
}
// The zone plate scene: 2.5 texels a pixel (lambda 1.32).
constexpr double kZoneTexelsPerPixel = 2.5;
inline View zonePlateView(int w, int h, double azimuthDeg) {
  return flatView(w, h, azimuthDeg, kZoneTexelsPerPixel, {kTexels / 2.0, kTexels / 2.0});
}
// The magnification scene: 256 texels over 300 pixels.
constexpr double kMagnifyPixels = 300;
inline View magnifyView(int w, int h, double azimuthDeg) {
  return flatView(w, h, azimuthDeg, kTexels / kMagnifyPixels, {kTexels / 2.0, kTexels / 2.0});
}

// A zone plate: grey 127.5 + 127.5 cos(pi r^2 / 256), r the distance from the
// centre in texels, so the local frequency r / 256 cycles a texel reaches the
// texture's Nyquist limit (1/2) at the edge, r = 128.
inline ts::TextureDesc zonePlate(int size = kTexels) {
  auto img = std::make_shared<ts::Image>(size, size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const double x = i + 0.5 - size / 2.0, y = j + 0.5 - size / 2.0;
      const uint8_t g = uint8_t(std::lround(127.5 + 127.5 * std::cos(kPi * (x * x + y * y) / size)));
      img->set(i, j, {g, g, g, 255});
    }
  ts::TextureDesc t;
  t.name = "zone_plate";
  t.params = {{"size", std::to_string(size)},
              {"grey", "127.5 + 127.5 cos(pi r^2 / size), r from the centre in texels"}};
  t.image = img;
  return t;
}

// Far field: the pixels whose (GL-form) LOD is in [lo, hi] and whose square
// lies on the surface.  lo = -inf takes every covered pixel.
inline std::vector<char> farField(const View& v, double lo, double hi) {
  std::vector<char> m(size_t(v.w) * size_t(v.h), 0);
  for (int row = 0; row < v.h; ++row)
    for (int col = 0; col < v.w; ++col) {
      if (!v.coversPixel(col, row)) continue;
      const double lod = std::log2(ts::lod::rhoExact(v.jacobian(col + 0.5, v.h - 1 - row + 0.5)));
      m[size_t(row) * size_t(v.w) + size_t(col)] = lod >= lo && lod <= hi;
    }
  return m;
}

// ---------------------------------------------------------------- the methods by name
enum Method {
  kExact,
  kNearest,
  kLinear,
  kNearestMipNearest,
  kTrilinear,
  kAniso16,
  kRipmap,
  kSat,
  kProbes,
  kEwa,
  kMethodCount
};
inline const char* methodKey(int m) {
  static const char* const k[] = {"exact",   "nearest", "linear", "nmn",    "trilinear",
                                  "aniso16", "ripmap",  "sat",    "probes", "ewa"};
  return k[m];
}
inline const char* methodTitle(int m) {
  static const char* const k[] = {"exact area integral",
                                  "GL_NEAREST",
                                  "GL_LINEAR",
                                  "GL_NEAREST_MIPMAP_NEAREST",
                                  "trilinear",
                                  "GL anisotropic 16x",
                                  "ripmap",
                                  "summed-area table",
                                  "probe line",
                                  "EWA"};
  return k[m];
}
// Drawn by the GL's own filters (fixed function) or computed here on the CPU.
inline bool byGL(int m) { return m >= kNearest && m <= kAniso16; }

// One CPU method at one pixel (window coordinates, centre), with its reads.
inline glm::dvec4 lookup(int method, const Pyramids& p, const View& v, double x, double y, double bias, long* reads) {
  const glm::dvec2 uv = v.uv(x, y);
  const Jacobian j = v.jacobian(x, y);
  switch (method) {
    case kNearest: return nearest(p.chain[0], uv.x, uv.y, reads);
    case kLinear: return bilinear(p.chain[0], uv.x, uv.y, reads);
    case kNearestMipNearest: return nearestMipNearest(p.chain, uv.x, uv.y, j, bias, reads);
    case kTrilinear:
    case kAniso16: return trilinear(p.chain, uv.x, uv.y, j, bias, reads);  // (no CPU anisotropic model of the GL's)
    case kRipmap: return ripmap(p.rip, uv.x, uv.y, j, bias, reads);
    case kSat: return sat(p.sat, uv.x, uv.y, j, bias, reads);
    case kProbes: return probes(p.chain, uv.x, uv.y, j, bias, reads);
    case kEwa: return ewa(p.chain, uv.x, uv.y, j, bias, reads);
    default: return glm::dvec4(0.0);
  }
}

inline ts::Rgba toRgba(const glm::dvec4& c) {
  auto b = [](double x) { return uint8_t(std::lround(std::clamp(x, 0.0, 255.0))); };
  return {b(c.r), b(c.g), b(c.b), 255};
}

// A method's picture of a view (rows top-down, off-surface pixels
// `background`) and the mean texels it read over `mask` (all covered pixels
// when empty).  The exact reference has no "reads" here (its cost is the
// outline, ts::AreaIntegral); exactTexels counts the texels it weighs.
struct Picture {
  ts::Image image;
  std::vector<glm::dvec4> exact;  // kExact only: the unrounded averages
  double meanReads = 0;
};
// Whether parallelRows may use its second thread.  A window's measurement
// closes it while its first stage is drawn beside CPU work it started on a
// thread of its own (FilterZoo::measure): that work keeps to one thread
// until the stage is handed over, so that the stage is not delayed much.
// The pictures are the same either way (parallelRows computes each row as
// one thread would).
class RowShare {
 public:
  static RowShare& get() {
    static RowShare s;
    return s;
  }
  void set(bool open) {
    std::lock_guard<std::mutex> g(m_);
    open_ = open;
    cv_.notify_all();
  }
  // Waits until the share is open or `done()`.
  template <class Done>
  void wait(Done done) {
    std::unique_lock<std::mutex> g(m_);
    cv_.wait(g, [&] { return open_ || done(); });
  }
  void wake() {
    std::lock_guard<std::mutex> g(m_);
    cv_.notify_all();
  }
  bool isOpen() {
    std::lock_guard<std::mutex> g(m_);
    return open_;
  }

 private:
  std::mutex m_;
  std::condition_variable cv_;
  bool open_ = true;
};
// Rows 0 .. h-1 shared by two threads (the machine's two cores), each taking
// the next row not yet taken: a picture's rows differ in cost (the horizon's
// footprints are the long ones).  Every pixel is computed as one thread would
// compute it, so the picture is the same; `row(r)` must write only row r's
// pixels and its own counters.
template <class RowFn>
inline void parallelRows(int h, RowFn row) {
  std::atomic<int> next{0};
  auto work = [&] {
    for (int r; (r = next.fetch_add(1)) < h;) row(r);
  };
  std::thread other([&] {
    RowShare::get().wait([&] { return next.load() >= h; });
    work();
  });
  work();
  RowShare::get().wake();  // a second thread still waiting: the rows are done
  other.join();
}

// The exact average over every wanted pixel's preimage (wanted(col, row):
// the pixel square lies on the surface), each preimage edge walked once
// (ts::AreaIntegral::edge): a pixel's edges are its neighbours' too, so a
// picture costs half the walks of one average() a pixel.  The horizontal
// edges first (two rows of pixels share each), then each row's vertical
// edges and its pixels; rows in parallel.  store(col, row, average).
template <class Wanted, class Store>
inline void exactAverages(const ts::AreaIntegral& ai, const View& v, Wanted wanted, Store store) {
  using Edge = ts::AreaIntegral::Edge;
  const int w = v.w, h = v.h;
  // Corner (i, y) (window coordinates, y up) in texels: as View::preimage computes it.
  auto corner = [&](int i, int y) { return v.uv(double(i), double(y)); };
  std::vector<char> want(size_t(w) * size_t(h));
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col) want[size_t(row) * size_t(w) + size_t(col)] = wanted(col, row) ? 1 : 0;
  auto wants = [&](int col, int y) {  // the pixel whose bottom edge is at window y
    return y >= 0 && y < h && want[size_t(h - 1 - y) * size_t(w) + size_t(col)];
  };
  // horizontal[y * w + i]: corner (i, y) -> (i + 1, y), for y = 0 .. h.
  std::vector<Edge> horizontal(size_t(h + 1) * size_t(w));
  parallelRows(h + 1, [&](int y) {
    glm::dvec2 a = corner(0, y);
    for (int i = 0; i < w; ++i) {
      const glm::dvec2 b = corner(i + 1, y);
      if (wants(i, y) || wants(i, y - 1)) horizontal[size_t(y) * size_t(w) + size_t(i)] = ai.edge(a, b);
      a = b;
    }
  });
  parallelRows(h, [&](int row) {
    const int y = h - 1 - row;
    std::vector<Edge> vertical(size_t(w) + 1);  // corner (i, y) -> (i, y + 1)
    for (int i = 0; i <= w; ++i)
      if ((i < w && wants(i, y)) || (i > 0 && wants(i - 1, y)))
        vertical[size_t(i)] = ai.edge(corner(i, y), corner(i, y + 1));
    for (int col = 0; col < w; ++col) {
      if (!wants(col, y)) continue;
      const ts::Polygon2 poly = v.preimage(col, row);
      const Edge* edges[4] = {&horizontal[size_t(y) * size_t(w) + size_t(col)], &vertical[size_t(col) + 1],
                              &horizontal[size_t(y + 1) * size_t(w) + size_t(col)], &vertical[size_t(col)]};
      const int signs[4] = {1, 1, -1, -1};  // the top and left edges walked the other way
      store(col, row, ai.averageOfEdges(poly, edges, signs));
    }
  });
}

// One pixel's exact average exactly as exactAverages computes it (its four
// edges walked in the same directions, added the same way): for a picture
// of single pixels (a window's coarse first stage).
inline glm::dvec4 exactPixel(const ts::AreaIntegral& ai, const View& v, int col, int row) {
  const int y = v.h - 1 - row;
  auto corner = [&](int i, int yy) { return v.uv(double(i), double(yy)); };
  const ts::AreaIntegral::Edge bottom = ai.edge(corner(col, y), corner(col + 1, y)),
                               right = ai.edge(corner(col + 1, y), corner(col + 1, y + 1)),
                               top = ai.edge(corner(col, y + 1), corner(col + 1, y + 1)),
                               left = ai.edge(corner(col, y), corner(col, y + 1));
  const ts::AreaIntegral::Edge* edges[4] = {&bottom, &right, &top, &left};
  const int signs[4] = {1, 1, -1, -1};
  return ai.averageOfEdges(v.preimage(col, row), edges, signs);
}

// With onlyMask, the pixels outside the mask are left as background.
inline Picture cpuPicture(int method, const Pyramids& p, const View& v, double bias, const std::vector<char>& mask,
                          ts::Rgba background = {77, 92, 115, 255}, bool onlyMask = false) {
  Picture out;
  out.image = ts::Image(v.w, v.h, background);
  if (method == kExact) {
    out.exact.assign(size_t(v.w) * size_t(v.h), glm::dvec4(background.r, background.g, background.b, 255));
    exactAverages(
        p.exact, v,
        [&](int col, int row) {
          return v.coversPixel(col, row) && (!onlyMask || mask[size_t(row) * size_t(v.w) + size_t(col)]);
        },
        [&](int col, int row, const glm::dvec4& c) {
          out.exact[size_t(row) * size_t(v.w) + size_t(col)] = c;
          out.image.set(col, row, toRgba(c));
        });
    return out;  // no reads: its cost is the outline's (exactTexels counts the texels it weighs)
  }
  std::atomic<long> reads{0}, counted{0};  // integers: the same totals in any order
  parallelRows(v.h, [&](int row) {
    long rowReads = 0, rowCounted = 0;
    for (int col = 0; col < v.w; ++col) {
      const size_t k = size_t(row) * size_t(v.w) + size_t(col);
      if (!v.coversPixel(col, row) || (onlyMask && !mask[k])) continue;
      long r = 0;
      out.image.set(col, row, toRgba(lookup(method, p, v, col + 0.5, v.h - 1 - row + 0.5, bias, &r)));
      if (mask.empty() || mask[k]) rowReads += r, ++rowCounted;
    }
    reads += rowReads, counted += rowCounted;
  });
  out.meanReads = counted ? double(reads) / double(counted) : 0;
  return out;
}
// A CPU method's picture at 1/k of the resolution, for a window's first
// stage: each k x k block of pixels takes the method's value at its pixel
// (k/2, k/2) exactly as cpuPicture computes that pixel (its own footprint),
// in 1/k^2 of the work; a block whose pixel is off the surface is background.
inline ts::Image coarsePicture(int method, const Pyramids& p, const View& v, double bias, int k,
                               ts::Rgba background = {77, 92, 115, 255}) {
  ts::Image img(v.w / k, v.h / k, background);
  for (int row = 0; row < img.height; ++row)
    for (int col = 0; col < img.width; ++col) {
      const int x = col * k + k / 2, y = row * k + k / 2;
      if (!v.coversPixel(x, y)) continue;
      long reads = 0;
      img.set(col, row,
              toRgba(method == kExact ? exactPixel(p.exact, v, x, y)
                                      : lookup(method, p, v, x + 0.5, v.h - 1 - y + 0.5, bias, &reads)));
    }
  return img;
}
// Mean number of texels the exact integral weighs over the mask: per texel
// row, the texels between the ends of the preimage's strip in that row
// (every one of them overlaps it with a positive area, but for a corner
// exactly on a grid line).
//
// The strip is ts::clipToBox(preimage, u0, j, u1, j + 1) with [u0, u1] the
// preimage's own u extent, computed here as clipToBox computes it (the same
// Sutherland-Hodgman steps, the same arithmetic in the same order, so the
// same vertices and the same count) without its four vectors a row: the two
// u clips keep every vertex (none lies outside the polygon's own extent), and
// the two v clips work in arrays on the stack.  A quadrilateral clipped twice
// has at most 16 vertices (each step at most doubles them; convex: 6).
struct StripPoly {
  glm::dvec2 p[16];
  int n = 0;
};
// One clipToBox step against v >= c (below = false) or v <= c (below = true).
inline void clipStripV(const StripPoly& in, StripPoly& out, double c, bool below) {
  out.n = 0;
  for (int k = 0; k < in.n; ++k) {
    const glm::dvec2& a = in.p[k];
    const glm::dvec2& b = in.p[(k + 1) % in.n];
    const bool ia = below ? a.y <= c : a.y >= c, ib = below ? b.y <= c : b.y >= c;
    if (ia) out.p[out.n++] = a;
    if (ia != ib) out.p[out.n++] = {a.x + (b.x - a.x) * (c - a.y) / (b.y - a.y), c};  // area_filter.cpp's atY
  }
}
inline double exactTexels(const View& v, const std::vector<char>& mask) {
  std::atomic<long> total{0}, pixels{0};  // integers: the same totals in any order
  parallelRows(v.h, [&](int row) {
    long n = 0, px = 0;
    for (int col = 0; col < v.w; ++col) {
      if (!mask[size_t(row) * size_t(v.w) + size_t(col)]) continue;
      const ts::Polygon2 poly = v.preimage(col, row);
      double v0 = poly[0].y, v1 = v0;
      for (const glm::dvec2& q : poly) v0 = std::min(v0, q.y), v1 = std::max(v1, q.y);
      StripPoly quad, half, strip;
      quad.n = int(poly.size());
      for (int k = 0; k < quad.n; ++k) quad.p[k] = poly[size_t(k)];
      for (long j = long(std::floor(v0)); j < long(std::ceil(v1)); ++j) {
        clipStripV(quad, half, double(j), false);
        clipStripV(half, strip, double(j + 1), true);
        if (strip.n < 3) continue;
        double twice = 0;  // ts::signedArea, term by term
        for (int k = 0; k < strip.n; ++k) {
          const glm::dvec2& a = strip.p[k];
          const glm::dvec2& b = strip.p[(k + 1) % strip.n];
          twice += a.x * b.y - b.x * a.y;
        }
        if (std::fabs(0.5 * twice) <= 0) continue;
        double a = strip.p[0].x, b = a;
        for (int k = 0; k < strip.n; ++k) a = std::min(a, strip.p[k].x), b = std::max(b, strip.p[k].x);
        n += long(std::ceil(b)) - long(std::floor(a));
      }
      ++px;
    }
    total += n, pixels += px;
  });
  return pixels ? double(total) / double(pixels) : 0;
}

// RMS (8-bit units over R, G, B) of an image against the exact averages, where mask is set.
inline double rmsAgainst(const ts::Image& img, const std::vector<glm::dvec4>& exact, const std::vector<char>& mask) {
  double sum = 0;
  long n = 0;
  for (int row = 0; row < img.height; ++row)
    for (int col = 0; col < img.width; ++col) {
      const size_t k = size_t(row) * size_t(img.width) + size_t(col);
      if (!mask[k]) continue;
      const ts::Rgba a = img.at(col, row);
      const glm::dvec4& e = exact[k];
      sum += (a.r - e.r) * (a.r - e.r) + (a.g - e.g) * (a.g - e.g) + (a.b - e.b) * (a.b - e.b);
      n += 3;
    }
  return n ? std::sqrt(sum / double(n)) : 0.0;
}

// The GL picture of a view: one panel the size of the view, pixel
// coordinates (y up), the outline as a triangle fan with projective texture
// coordinates (u q, v q, 0, q) / 256 at its corners, so GL's
// perspective-correct interpolation (w = 1) makes (s/q, t/q) the homography
// exactly at every pixel.  `texture` carries the filter.
inline ts::Frame viewFrame(const View& v, const ts::TextureDesc& texture, glm::vec4 background) {
  ts::Frame f;
  f.width = v.w, f.height = v.h;
  f.clearColor = background;
  ts::Panel p;
  p.id = "view";
  p.viewport = {0, 0, v.w, v.h};
  p.projection = glm::ortho(0.0f, float(v.w), 0.0f, float(v.h), -1.0f, 1.0f);
  p.clear = true;
  p.clearColor = background;
  ts::Batch b;
  b.role = "surface";
  b.texture = f.addTexture(texture);
  const std::vector<glm::dvec2> o = v.outline();
  auto vertex = [&](glm::dvec2 x) {
    const glm::dvec3 q = v.H * glm::dvec3(x, 1.0);
    // (s q, t q, 0, q): glTexCoord4f in Renderer::draw (common/gl/render.cpp)
    return ts::Vertex{{float(x.x), float(x.y), 0.0f},
                      {float(q.x / kTexels), float(q.y / kTexels), 0.0f, float(q.z)},
                      glm::vec4(1.0f)};
  };
  for (size_t k = 1; k + 1 < o.size(); ++k)
    for (size_t i : {size_t(0), k, k + 1}) b.vertices.push_back(vertex(o[i]));
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}

// ---------------------------------------------------------------- 8. mip kernels
enum Kernel { kBox, kTent, kGaussian, kLanczos2, kLanczos3, kKaiser, kKernelCount };
inline const char* kernelKey(int k) {
  static const char* const n[] = {"box", "tent", "gaussian", "lanczos2", "lanczos3", "kaiser"};
  return n[k];
}
inline const char* kernelTitle(int k) {
  static const char* const n[] = {"box (Buss's 2x2)", "tent (Crow's pyramid)",
                                  "Gaussian",         "Lanczos-2",
                                  "Lanczos-3",        "Kaiser"};
  return n[k];
}
inline double sinc(double x) { return x == 0 ? 1.0 : std::sin(kPi * x) / (kPi * x); }
// I0, the modified Bessel function of the first kind (series).
inline double besselI0(double x) {
  double sum = 1, term = 1;
  for (int k = 1; k < 50; ++k) {
    term *= (x / (2 * k)) * (x / (2 * k));
    sum += term;
  }
  return sum;
}
constexpr double kKaiserBeta = 4.0, kKaiserRadius = 3.0, kGaussianSigma = 0.5;
// The kernel at x output texels from an output texel's centre.
inline double kernelAt(int k, double x) {
  const double a = std::abs(x);
  switch (k) {
    case kBox: return a < 0.5 ? 1.0 : 0.0;
    case kTent: return std::max(0.0, 1.0 - a);
    case kGaussian: return std::exp(-0.5 * a * a / (kGaussianSigma * kGaussianSigma));
    case kLanczos2: return a < 2 ? sinc(a) * sinc(a / 2) : 0.0;
    case kLanczos3: return a < 3 ? sinc(a) * sinc(a / 3) : 0.0;
    default: {
      if (a >= kKaiserRadius) return 0.0;
      const double r = a / kKaiserRadius;
      return sinc(a) * besselI0(kKaiserBeta * std::sqrt(1 - r * r)) / besselI0(kKaiserBeta);
    }
  }
}
// The taps of the 2:1 decimation: input texels at offsets +-1/2, +-3/2, ...
// (input texels) from the output texel's centre, i.e. +-1/4, +-3/4, ...
// output texels; weights normalised to sum 1.  taps[n] is the weight of the
// two texels at +-(n + 1/2).
inline std::vector<double> kernelTaps(int k) {
  std::vector<double> t;
  for (int n = 0; n < 8; ++n) t.push_back(kernelAt(k, (n + 0.5) / 2.0));
  while (!t.empty() && t.back() == 0) t.pop_back();
  double s = 0;
  for (double x : t) s += 2 * x;
  for (double& x : t) x /= s;
  return t;
}
// One level from the one before, separable, GL_REPEAT, 8-bit (rounded and
// clamped: negative lobes can overshoot), in sRGB values or in linear light.
inline ts::Image decimate(const ts::Image& src, int kernel, bool linearLight) {
  const std::vector<double> taps = kernelTaps(kernel);
  const int w = std::max(1, src.width / 2), h = std::max(1, src.height / 2);
  // srgbToLinear of each of the 256 byte values, once: the taps read every
  // texel several times, and pow was most of a linear-light chain's time.
  std::array<double, 256> toLinear{};
  for (int b = 0; b < 256; ++b) toLinear[size_t(b)] = srgbToLinear(double(b));
  auto val = [&](int i, int j, int c) {
    const ts::Rgba p = src.at(((i % src.width) + src.width) % src.width, ((j % src.height) + src.height) % src.height);
    const uint8_t v = c == 0 ? p.r : c == 1 ? p.g : c == 2 ? p.b : p.a;
    return linearLight && c < 3 ? toLinear[v] : double(v);
  };
  // Along u first (src.height rows of w), then v.
  std::vector<double> mid(size_t(w) * size_t(src.height) * 4);
  for (int j = 0; j < src.height; ++j)
    for (int i = 0; i < w; ++i)
      for (int c = 0; c < 4; ++c) {
        double s = 0;
        if (src.width == 1) s = val(0, j, c);
        else
          for (size_t n = 0; n < taps.size(); ++n)
            s += taps[n] * (val(2 * i - int(n), j, c) + val(2 * i + 1 + int(n), j, c));
        mid[(size_t(j) * size_t(w) + size_t(i)) * 4 + size_t(c)] = s;
      }
  ts::Image dst(w, h);
  auto m = [&](int i, int j, int c) {
    j = ((j % src.height) + src.height) % src.height;
    return mid[(size_t(j) * size_t(w) + size_t(i)) * 4 + size_t(c)];
  };
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      double out[4];
      for (int c = 0; c < 4; ++c) {
        double s = 0;
        if (src.height == 1) s = m(i, 0, c);
        else
          for (size_t n = 0; n < taps.size(); ++n)
            s += taps[n] * (m(i, 2 * j - int(n), c) + m(i, 2 * j + 1 + int(n), c));
        out[c] = linearLight && c < 3 ? linearToSrgb(s) : s;
      }
      dst.set(i, j, toRgba({out[0], out[1], out[2], out[3]}));
    }
  return dst;
}
inline std::vector<ts::Image> kernelChain(const ts::Image& base, int kernel, bool linearLight) {
  std::vector<ts::Image> chain{base};
  while (chain.back().width > 1 || chain.back().height > 1)
    chain.push_back(decimate(chain.back(), kernel, linearLight));
  return chain;
}
// The 1 x 1 level's grey (mean of R, G, B).
inline double topValue(const std::vector<ts::Image>& chain) {
  const ts::Rgba c = chain.back().at(0, 0);
  return (c.r + c.g + c.b) / 3.0;
}
// The last level k of a chain in which a nearest sample takes level 0's
// colour wherever it lands: every level-0 texel (i, j) has the colour of
// level k's texel (i >> k, j >> k).  A checkerboard of 32-texel checks
// keeps its board through level 5 (1-texel checks), so up to there
// GL_NEAREST_MIPMAP_NEAREST, which reads level round(lambda), draws exactly
// what GL_NEAREST draws: the two differ only where lambda > 5.5.
inline int lastLevelLikeLevel0(const std::vector<ts::Image>& chain) {
  int last = 0;
  for (size_t k = 1; k < chain.size(); ++k) {
    const ts::Image& base = chain[0];
    for (int j = 0; j < base.height; ++j)
      for (int i = 0; i < base.width; ++i)
        if (!(chain[k].at(std::min(i >> k, chain[k].width - 1), std::min(j >> k, chain[k].height - 1)) ==
              base.at(i, j)))
          return last;
    last = int(k);
  }
  return last;
}
// What a 1 x 1 level stands for: the image's mean grey in double precision,
// of the sRGB values or of the linear-light values encoded back to sRGB.  A
// kernel whose taps sum to 1 (GL_REPEAT) keeps the mean exactly; a chain's
// 1 x 1 level departs from it only by the 8-bit rounding of each level.
inline double meanGrey(const ts::Image& img, bool linearLight) {
  double sum = 0;
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) {
      const ts::Rgba c = img.at(i, j);
      for (double v : {double(c.r), double(c.g), double(c.b)}) sum += linearLight ? srgbToLinear(v) : v;
    }
  const double mean = sum / (3.0 * img.width * img.height);
  return linearLight ? linearToSrgb(mean) : mean;
}
}  // namespace zoo
