// common/core/mip_lod.hpp — OpenGL's level of detail (4.6 §8.14), as plain
// math: the scale factor rho from the four screen derivatives of the texel
// coordinates, the level(s) a mipmap filter reads at lambda, and reading a
// level back from a render of the mip-level-colours texture.  Moved here from
// the mipmap demo (demos/mipmap_popping/mipmap_popping_math.hpp derives them) so the
// filter zoo (demos/filter_zoo) uses the same rules.  No GL.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "common/core/textures.hpp"

namespace ts::lod {
// The texel-space Jacobian of a pixel: du/dx, du/dy, dv/dx, dv/dy (texels of
// level 0 per pixel).
struct Jacobian {
  double dudx = 0, dudy = 0, dvdx = 0, dvdy = 0;  // texels per pixel
};
// GL's formula (the "edge" form): the longer of the two derivative vectors,
// rho = max(|(du/dx, dv/dx)|, |(du/dy, dv/dy)|).
inline double rhoExact(const Jacobian& j) { return std::max(std::hypot(j.dudx, j.dvdx), std::hypot(j.dudy, j.dvdy)); }
// The cheaper bound GL also allows (seed 001: "the largest partial
// derivative"): rho = max(|du/dx|, |dv/dx|, |du/dy|, |dv/dy|).
inline double rhoMax(const Jacobian& j) {
  return std::max({std::abs(j.dudx), std::abs(j.dvdx), std::abs(j.dudy), std::abs(j.dvdy)});
}
// GL allows any rho in [max(mu, mv), mu + mv].  Mesa's two rasterisers stay
// inside the lower part: softpipe takes the largest component max(mu, mv)
// (the interval's low end), llvmpipe the exact lengths; the tests allow
// that range [lo, hi].  (For the facing plane lo = hi.)
inline void rhoBounded(const Jacobian& j, double* lo, double* hi) {
  double mu = std::max(std::abs(j.dudx), std::abs(j.dudy)), mv = std::max(std::abs(j.dvdx), std::abs(j.dvdy));
  *lo = std::max(mu, mv);
  *hi = rhoExact(j);
}

// The level a *_MIPMAP_NEAREST filter uses at lambda (bias included), of
// `levels` levels: round to nearest, .5 rounding down, clamped.
inline int nearestLevel(double lambda, int levels) {
  if (lambda <= 0.5) return 0;
  return std::min(levels - 1, int(std::ceil(lambda + 0.5)) - 1);
}
// The two levels and the weight of the second for *_MIPMAP_LINEAR.
struct LevelBlend {
  int lo = 0, hi = 0;
  double weight = 0;  // of `hi`
};
inline LevelBlend linearLevels(double lambda, int levels) {
  if (lambda <= 0) return {0, 0, 0};
  if (lambda >= levels - 1) return {levels - 1, levels - 1, 0};
  int k = int(std::floor(lambda));
  return {k, k + 1, lambda - k};
}

// The mean colour of a region of an image (8-bit units).
struct Mean {
  double r = 0, g = 0, b = 0;
};
inline Mean meanOf(const ts::Image& img, ts::Rect r) {
  Mean m;
  long n = 0;
  for (int y = std::max(0, r.y); y < std::min(img.height, r.y + r.h); ++y)
    for (int x = std::max(0, r.x); x < std::min(img.width, r.x + r.w); ++x) {
      ts::Rgba c = img.at(x, y);
      m.r += c.r, m.g += c.g, m.b += c.b, ++n;
    }
  if (n) m.r /= double(n), m.g /= double(n), m.b /= double(n);
  return m;
}

// Reads a colour of the mip-level-colours texture (ts::mipLevelColours) back
// as a level: the k (and blend weight f towards k + 1) whose
// (1 - f) C_k + f C_{k+1} is nearest to `c`.  Returns k + f; *residual is the
// distance left (8-bit).
inline double levelOfColour(const Mean& c, int levels, double* residual = nullptr) {
  auto col = [](int k) {
    ts::Rgba q = ts::mipLevelColour(k);
    return glm::dvec3(q.r, q.g, q.b);
  };
  glm::dvec3 x(c.r, c.g, c.b);
  double best = 1e300, at = 0;
  for (int k = 0; k < levels; ++k) {
    glm::dvec3 a = col(k);
    double d0 = glm::length(x - a);
    if (d0 < best) best = d0, at = k;
    if (k + 1 < levels) {
      glm::dvec3 b = col(k + 1), ab = b - a;
      double f = std::clamp(glm::dot(x - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
      double d = glm::length(x - (a + f * ab));
      if (d < best - 1e-9) best = d, at = k + f;
    }
  }
  if (residual) *residual = best;
  return at;
}

// RMS difference (8-bit units, over R, G, B) between two images where
// mask[y * w + x] is set.
inline double rmsError(const ts::Image& a, const ts::Image& b, const std::vector<char>& mask, long* count = nullptr) {
  double sum = 0;
  long n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (!mask[size_t(y) * size_t(a.width) + size_t(x)]) continue;
      ts::Rgba p = a.at(x, y), q = b.at(x, y);
      double dr = p.r - q.r, dg = p.g - q.g, db = p.b - q.b;
      sum += dr * dr + dg * dg + db * db;
      n += 3;
    }
  if (count) *count = n / 3;
  return n ? std::sqrt(sum / double(n)) : 0.0;
}
}  // namespace ts::lod
