// common/core/texture_memory.hpp — texture memory in texels, as plain math: a whole mip chain and a
// clipmap (Tanner's: every level of a size x size texture held at most clip x clip).  Shared by the
// texture-memory demos (texture_compression's size table, texture_residency's working clipmap).  No GL.
#pragma once
#include <algorithm>
#include <cstdint>

namespace ts {
// A clipmap keeps each mip level of a size x size texture at most clip x clip.
inline uint64_t clipmapTexels(uint64_t size, uint64_t clip) {
  uint64_t n = 0;
  for (uint64_t s = size;; s /= 2) {
    n += std::min(s, clip) * std::min(s, clip);
    if (s <= 1) return n;
  }
}
// The whole chain, levels 0 .. the 1 x 1: about 4/3 of level 0.
inline uint64_t chainTexels(uint64_t size) { return clipmapTexels(size, size); }
}  // namespace ts
