// common/core/dxt1.hpp — S3TC/DXT1 by hand: the encoder and decoder the
// texture-compression demo measures GL against (seed 001 ¶19–24), and the
// bump-mapping demo's compressed normal map.  CPU only.
//
// A DXT1 texture is 4x4 blocks of 64 bits each: two colours c0, c1 in RGB565
// (16 bits each) and 16 indices of 2 bits (32 bits), one per texel, row by
// row from the block's top left, texel k in bits 2k..2k+1.  The palette:
//     c0 > c1 (as 16-bit numbers):  c2 = (2 c0 + c1) / 3,  c3 = (c0 + 2 c1) / 3
//     c0 <= c1 (the 3-colour mode, which seed 001 leaves out):
//                                   c2 = (c0 + c1) / 2,    c3 = black
// so 4 bits per texel: 4:1 against 16-bit RGB565, 6:1 against 24-bit RGB888,
// and a 512x512 texture in the 131,072 bytes of a 256x256 one at 16 bits.
//
// The encoder here: per block, the colours' principal axis (power iteration
// on their covariance), the extreme projections as endpoints, quantised to
// RGB565 and put in c0 > c1 order, each texel given the nearest of the four
// palette colours; then one least-squares refit of the endpoints from those
// indices, kept if it lowers the block's error.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/core/image.hpp"

namespace ts::dxt1 {
// RGB565: 5 bits red, 6 green, 5 blue; unpacked by bit replication (the
// high bits repeated into the low ones), so 0 -> 0 and 31 -> 255.
inline uint16_t pack565(glm::dvec3 c) {
  auto q = [](double v, int bits) { return int(std::lround(std::clamp(v, 0.0, 255.0) / 255.0 * ((1 << bits) - 1))); };
  return uint16_t((q(c.r, 5) << 11) | (q(c.g, 6) << 5) | q(c.b, 5));
}
inline glm::ivec3 unpack565(uint16_t v) {
  const int r = v >> 11, g = (v >> 5) & 63, b = v & 31;
  return {(r << 3) | (r >> 2), (g << 2) | (g >> 4), (b << 3) | (b >> 2)};
}

struct Block {
  uint16_t c0 = 0, c1 = 0;
  uint32_t indices = 0;  // texel k (row-major from the top left) in bits 2k, 2k+1
  int index(int k) const { return int((indices >> (2 * k)) & 3u); }
};

// The four colours a block's indices choose from (integer arithmetic, as
// the S3TC specification writes it; alpha 0 marks the 3-colour mode's black).
inline std::array<glm::ivec4, 4> palette(uint16_t c0, uint16_t c1) {
  const glm::ivec3 a = unpack565(c0), b = unpack565(c1);
  if (c0 > c1)
    return {glm::ivec4(a, 255), glm::ivec4(b, 255), glm::ivec4((2 * a + b) / 3, 255), glm::ivec4((a + 2 * b) / 3, 255)};
  return {glm::ivec4(a, 255), glm::ivec4(b, 255), glm::ivec4((a + b) / 2, 255), glm::ivec4(0, 0, 0, 0)};
}

inline double dist2(glm::dvec3 a, glm::dvec3 b) { return glm::dot(a - b, a - b); }

// The indices nearest each texel's colour, and the block's squared error.
inline double assign(Block* b, const std::array<glm::dvec3, 16>& px) {
  const auto pal = palette(b->c0, b->c1);
  double err = 0;
  b->indices = 0;
  for (int k = 0; k < 16; ++k) {
    int best = 0;
    double bd = 1e30;
    for (int i = 0; i < 4; ++i) {
      const double d = dist2(px[size_t(k)], glm::dvec3(pal[size_t(i)]));
      if (d < bd) bd = d, best = i;
    }
    b->indices |= uint32_t(best) << (2 * k);
    err += bd;
  }
  return err;
}

// c0 > c1 (the 4-colour mode) unless they are equal.
inline Block fromEndpoints(glm::dvec3 e0, glm::dvec3 e1, const std::array<glm::dvec3, 16>& px, double* err) {
  Block b;
  b.c0 = pack565(e0), b.c1 = pack565(e1);
  if (b.c0 < b.c1) std::swap(b.c0, b.c1);
  *err = assign(&b, px);
  return b;
}

inline Block encodeBlock(const std::array<glm::dvec3, 16>& px) {
  glm::dvec3 mean(0.0);
  for (const auto& p : px) mean += p / 16.0;
  glm::dmat3 cov(0.0);
  for (const auto& p : px) cov += glm::outerProduct(p - mean, p - mean);
  // Power iteration for the principal axis, from the texel farthest from
  // the mean (a fixed start could be orthogonal to the axis).
  glm::dvec3 axis(0.0);
  for (const auto& p : px)
    if (dist2(p, mean) > glm::dot(axis, axis)) axis = p - mean;
  if (glm::dot(axis, axis) < 1e-12) axis = glm::dvec3(1.0);  // one colour: any axis
  axis = glm::normalize(axis);
  for (int it = 0; it < 8; ++it) {
    const glm::dvec3 next = cov * axis;
    if (glm::length(next) < 1e-9) break;
    axis = glm::normalize(next);
  }
  double lo = 1e30, hi = -1e30;
  for (const auto& p : px) lo = std::min(lo, glm::dot(p - mean, axis)), hi = std::max(hi, glm::dot(p - mean, axis));
  double err = 0;
  Block best = fromEndpoints(mean + hi * axis, mean + lo * axis, px, &err);
  // Refit: with the indices fixed, each texel is w e0 + (1 - w) e1 (w = 1, 0,
  // 2/3, 1/3 for indices 0..3): the least-squares endpoints.
  const double w[4] = {1.0, 0.0, 2.0 / 3.0, 1.0 / 3.0};
  double aa = 0, ab = 0, bb = 0;
  glm::dvec3 ax(0.0), bx(0.0);
  for (int k = 0; k < 16; ++k) {
    const double a = w[best.index(k)], b = 1.0 - a;
    aa += a * a, ab += a * b, bb += b * b, ax += a * px[size_t(k)], bx += b * px[size_t(k)];
  }
  const double det = aa * bb - ab * ab;
  if (best.c0 != best.c1 && std::abs(det) > 1e-9) {
    double err2 = 0;
    const Block refit = fromEndpoints((ax * bb - bx * ab) / det, (bx * aa - ax * ab) / det, px, &err2);
    if (err2 < err) best = refit;
  }
  return best;
}

// The format's blocks cover ceil(W/4) x ceil(H/4) blocks: a picture whose
// sides are not multiples of 4 is padded, its last column and row repeated
// into the texels no one sees (GL decodes only the W x H texels; the S3TC
// specification leaves the padding's values to the encoder).
inline int blocksAcross(int w) { return (w + 3) / 4; }
inline std::array<glm::dvec3, 16> blockTexels(const ts::Image& img, int bx, int by) {
  std::array<glm::dvec3, 16> px;
  for (int k = 0; k < 16; ++k) {
    const ts::Rgba c = img.at(std::min(bx * 4 + k % 4, img.width - 1), std::min(by * 4 + k / 4, img.height - 1));
    px[size_t(k)] = {c.r, c.g, c.b};
  }
  return px;
}
// The whole image: blocks row by row, from the top of the image (its row 0).
inline std::vector<Block> encode(const ts::Image& img) {
  std::vector<Block> out;
  for (int by = 0; by < blocksAcross(img.height); ++by)
    for (int bx = 0; bx < blocksAcross(img.width); ++bx) out.push_back(encodeBlock(blockTexels(img, bx, by)));
  return out;
}
inline ts::Image decode(const std::vector<Block>& blocks, int w, int h) {
  ts::Image out(w, h);
  for (int by = 0; by < blocksAcross(h); ++by)
    for (int bx = 0; bx < blocksAcross(w); ++bx) {
      const Block& b = blocks[size_t(by * blocksAcross(w) + bx)];
      const auto pal = palette(b.c0, b.c1);
      for (int k = 0; k < 16; ++k) {
        const glm::ivec4 c = pal[size_t(b.index(k))];
        const int x = bx * 4 + k % 4, y = by * 4 + k / 4;
        if (x < w && y < h) out.set(x, y, {uint8_t(c.r), uint8_t(c.g), uint8_t(c.b), uint8_t(c.a)});
      }
    }
  return out;
}
// The bytes GL takes (glCompressedTexImage2D): per block c0, c1, the indices, little-endian.
inline std::vector<uint8_t> bytes(const std::vector<Block>& blocks) {
  std::vector<uint8_t> out;
  for (const Block& b : blocks)
    for (uint32_t v : {uint32_t(b.c0) | (uint32_t(b.c1) << 16), b.indices})
      for (int k = 0; k < 4; ++k) out.push_back(uint8_t(v >> (8 * k)));
  return out;
}

}  // namespace ts::dxt1
