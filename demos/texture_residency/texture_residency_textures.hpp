// demos/texture_residency/texture_residency_textures.hpp — the size view's texture: the same picture at any
// power-of-two size (a checkerboard of 8 x 8 squares and a red marker square over s in [40/64, 42/64),
// t in [20/64, 22/64)), so that only the texel count changes between 64^2, 256^2 and 1024^2.  GL-free: the
// sidecar's generator "texture_residency_marker" remakes it.
#pragma once
#include "common/core/frame.hpp"

namespace ts::residency {
// A size x size marker texture (GL_NEAREST both ways, GL_CLAMP_TO_EDGE).
TextureDesc markerTexture(int size);
}  // namespace ts::residency
