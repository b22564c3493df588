// demos/texture_compression/texture_compression_measure.hpp — the pictures the demo
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

#include "demos/texture_compression/texture_compression_textures.hpp"
#include "common/core/texture_memory.hpp"
#include "common/core/textures.hpp"
#include "texture_compression_math.hpp"

namespace dxt {
// The pictures (photo-like bricks, a checkerboard, a normal map), the
// 3-colour mode and RGB565 at half the size: demos/texture_compression/texture_compression_textures.hpp,
// where the sidecar's generator "dxt1_picture" remakes them too.

// ---- texture memory (seed 001 ¶21–24) -----------------------------------
// A clipmap keeps each mip level of a size x size texture at most clip x clip (common/core/texture_memory.hpp).
using ts::chainTexels;
using ts::clipmapTexels;
// The clipmap the demo measures: a 65536 x 65536 texture, levels of at most 512 x 512.
constexpr uint64_t kClipmapSide = 65536, kClipmapLevel = 512;

// A texture of 64 x 64 tiles (it repeats), a view 6 x 6 tiles wide moving a
// quarter tile right and an eighth down per frame for 1,024 frames; each
// frame asks for every tile the view touches.  An LRU cache of `capacity`
// tiles: a hit when the tile is held, else a load (evicting the least
// recently used).  Prefetching also loads, unasked, the column and row of
// tiles the view enters next.
// The camera path's view and step (lruRun), which the plot's title states.
constexpr int kCacheView = 6;
constexpr double kCacheStepX = 0.25, kCacheStepY = 0.125;
struct CacheRun {
  long requests = 0, hits = 0, loads = 0;
  double hitRate() const { return requests ? double(hits) / double(requests) : 0.0; }
};
inline CacheRun lruRun(int capacity, bool prefetch) {
  constexpr int kTiles = 64, kView = kCacheView, kFrames = 1024;
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
    const double x0 = f * kCacheStepX, y0 = f * kCacheStepY;
    const int tx0 = int(std::floor(x0)), ty0 = int(std::floor(y0)), tx1 = int(std::floor(x0 + kView)),
              ty1 = int(std::floor(y0 + kView));
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
