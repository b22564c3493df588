// demos/texture_animation/texture_animation_textures.hpp — the waterfall's texture: streaks of
// water, a different shade in every texel (an integer hash), so that the picture moved by any
// amount but the right one differs somewhere.  GL-free: the sidecar's generator remakes it.
#pragma once
#include "common/core/frame.hpp"

namespace ts::texanim {
// A size x size texture of water (GL_NEAREST, GL_REPEAT: the texture matrix scrolls it without end).
TextureDesc waterTexture(int size);
// Frame k of n of a flame flipbook, size x size RGBA, row 0 the bottom (t = 0): a tongue of fire that sways
// and flickers with k, alpha its opacity, every texel outside it transparent and the same in every frame
// (so a frame differs from the next only inside a rectangle: what a partial upload sends).
Image flameFrame(int size, int k, int n);
}  // namespace ts::texanim
