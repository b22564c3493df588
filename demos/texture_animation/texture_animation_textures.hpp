// demos/texture_animation/texture_animation_textures.hpp — the waterfall's texture: streaks of
// water, a different shade in every texel (an integer hash), so that the picture moved by any
// amount but the right one differs somewhere.  GL-free: the sidecar's generator remakes it.
#pragma once
#include "common/core/frame.hpp"

namespace ts::texanim {
// A size x size texture of water (GL_NEAREST, GL_REPEAT: the texture matrix scrolls it without end).
TextureDesc waterTexture(int size);
}  // namespace ts::texanim
