// demos/texture_compression/dxt_measure.hpp — the pictures the demo
// compresses, what it measures of them, and texture memory on the CPU:
// an LRU tile cache along a camera path and the clipmap's texel count.
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <list>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/core/relief_maps.hpp"
#include "common/core/textures.hpp"
#include "dxt_math.hpp"

namespace dxt {
enum Picture : int { kPhoto, kChecker, kNormals, kPictureCount };
inline const char* const kPictureNames[] = {"photo", "checker", "normals"};

// 512 x 512: the parallax demo's bricks (a photograph's variety of colour),
// a checkerboard, and a normal map made from the bricks' heights
// (n = normalize(-4 dh/dx, -4 dh/dy, 1), stored as 127.5 (n + 1)).
inline ts::Image picture(int which) {
  if (which == kChecker) return *ts::checkerboard(512, 16).image;
  const ts::relief::Relief rel = ts::relief::makeRelief("bricks");
  if (which == kPhoto) return rel.albedo[0];
  const ts::Image& h = rel.height[0];
  ts::Image out(h.width, h.height);
  auto at = [&](int x, int y) { return h.at((x + h.width) % h.width, (y + h.height) % h.height).r / 255.0; };
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) {
      const glm::dvec3 n = glm::normalize(glm::dvec3(-4 * (at(x + 1, y) - at(x - 1, y)), -4 * (at(x, y + 1) - at(x, y - 1)), 1.0));
      auto u8 = [](double v) { return uint8_t(std::lround(std::clamp(127.5 * (v + 1.0), 0.0, 255.0))); };
      out.set(x, y, {u8(n.x), u8(n.y), u8(n.z), 255});
    }
  return out;
}

// Every block turned to the 3-colour mode (c0 <= c1: the palette's third
// colour the midpoint, the fourth black), its indices chosen again.
inline std::vector<Block> threeColour(const std::vector<Block>& blocks, const ts::Image& img) {
  std::vector<Block> out = blocks;
  for (size_t k = 0; k < out.size(); ++k) {
    Block& b = out[k];
    if (b.c0 > b.c1) std::swap(b.c0, b.c1);
    assign(&b, blockTexels(img, int(k) % blocksAcross(img.width), int(k) / blocksAcross(img.width)));
  }
  return out;
}

// 256 x 256 at 16 bits, the memory of 512 x 512 in DXT1: each 2x2 averaged,
// quantised to RGB565, then magnified back to 512 x 512 (bilinear).
inline ts::Image rgb565Half(const ts::Image& img) {
  ts::Image half(std::max(1, img.width / 2), std::max(1, img.height / 2));
  for (int y = 0; y < half.height; ++y)
    for (int x = 0; x < half.width; ++x) {
      glm::dvec3 s(0.0);
      for (int k = 0; k < 4; ++k) {
        const ts::Rgba c = img.at(std::min(2 * x + k % 2, img.width - 1), std::min(2 * y + k / 2, img.height - 1));
        s += glm::dvec3(c.r, c.g, c.b) / 4.0;
      }
      const glm::ivec3 q = unpack565(pack565(s));
      half.set(x, y, {uint8_t(q.r), uint8_t(q.g), uint8_t(q.b), 255});
    }
  return ts::resizeBilinear(half, img.width, img.height);
}

// ---- texture memory (seed 001 ¶21–24) -----------------------------------
// A clipmap keeps each mip level of a size x size texture at most clip x clip.
inline uint64_t clipmapTexels(uint64_t size, uint64_t clip) {
  uint64_t n = 0;
  for (uint64_t s = size;; s /= 2) {
    n += std::min(s, clip) * std::min(s, clip);
    if (s == 1) return n;
  }
}
inline uint64_t chainTexels(uint64_t size) { return clipmapTexels(size, size); }

// A texture of 64 x 64 tiles (it repeats), a view 6 x 6 tiles wide moving a
// quarter tile right and an eighth down per frame for 1,024 frames; each
// frame asks for every tile the view touches.  An LRU cache of `capacity`
// tiles: a hit when the tile is held, else a load (evicting the least
// recently used).  Prefetching also loads, unasked, the column and row of
// tiles the view enters next.
struct CacheRun {
  long requests = 0, hits = 0, loads = 0;
  double hitRate() const { return requests ? double(hits) / double(requests) : 0.0; }
};
inline CacheRun lruRun(int capacity, bool prefetch) {
  constexpr int kTiles = 64, kView = 6, kFrames = 1024;
  std::list<int> order;  // most recent first
  std::unordered_map<int, std::list<int>::iterator> held;
  CacheRun run;
  auto touch = [&](int tx, int ty, bool asked) {
    const int id = ((ty % kTiles + kTiles) % kTiles) * kTiles + (tx % kTiles + kTiles) % kTiles;
    auto it = held.find(id);
    if (asked) ++run.requests;
    if (it != held.end()) {
      if (asked) ++run.hits;
      order.splice(order.begin(), order, it->second);
      return;
    }
    ++run.loads;
    order.push_front(id);
    held[id] = order.begin();
    if (int(held.size()) > capacity) held.erase(order.back()), order.pop_back();
  };
  for (int f = 0; f < kFrames; ++f) {
    const double x0 = f * 0.25, y0 = f * 0.125;
    const int tx0 = int(std::floor(x0)), ty0 = int(std::floor(y0)), tx1 = int(std::floor(x0 + kView)), ty1 = int(std::floor(y0 + kView));
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) touch(tx, ty, true);
    if (prefetch) {  // the column and the row the view moves into next
      for (int ty = ty0; ty <= ty1 + 1; ++ty) touch(tx1 + 1, ty, false);
      for (int tx = tx0; tx <= tx1 + 1; ++tx) touch(tx, ty1 + 1, false);
    }
  }
  return run;
}
inline const std::vector<int>& cacheSizes() {
  static const std::vector<int> s = {32, 40, 48, 56, 64, 80, 96, 128};
  return s;
}
}  // namespace dxt
