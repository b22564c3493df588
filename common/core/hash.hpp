// common/core/hash.hpp — the one integer hash the suite's random numbers come from
// (jitter offsets, reference rays).  A hash of (seed, pixel, sample) instead of
// a sequential generator: any pixel's samples can be recomputed alone, and a
// GLSL copy gives the GPU the very same numbers (demos/jitter/jitter_gl.hpp).
#pragma once
#include <cstdint>

namespace ts {
// Chris Wellons' "lowbias32".
inline uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}
}  // namespace ts
