// demos/texture_animation/texture_animation_textures.hpp — the demo's textures, GL-free, each remade by the
// sidecar's generator: the waterfall's water (streaks, a different shade in every texel, an integer hash, so that
// the picture moved by any amount but the right one differs somewhere), the flipbook's flame frames, the light
// map for the light at a time, and the CPU's pictures the figures show beside GL's.
#pragma once
#include "common/core/frame.hpp"

namespace ts::texanim {
// A size x size texture of water (GL_NEAREST, GL_REPEAT: the texture matrix scrolls it without end).
TextureDesc waterTexture(int size);
// Frame k of n of a flame flipbook, size x size RGBA, row 0 the bottom (t = 0): a tongue of fire that sways
// and flickers with k, alpha its opacity, every texel outside it transparent and the same in every frame
// (so a frame differs from the next only inside a rectangle: what a partial upload sends).
Image flameFrame(int size, int k, int n);
// Frame k of the n-frame flame as a texture (GL_NEAREST, GL_CLAMP_TO_EDGE); `opaque`: alpha 1 everywhere, as the
// flipbook view's GL_RGB8 texture holds it (it shows colour only; the torch's flames keep their alpha).
TextureDesc flameTexture(int size, int k, int n, bool opaque);
// The light map for the light at `seconds` (GL_LINEAR, GL_CLAMP_TO_EDGE): texels x texels, grey.
TextureDesc lightMapTexture(int texels, double seconds);
// The CPU's pictures beside GL's (GL_LINEAR, clamped; row 0 at t = 0): per-pixel lighting at `seconds`; the
// light map at `seconds` magnified with the light's places marked; what changed from flipbook frame k to k + 1.
TextureDesc litTexture(double seconds);
TextureDesc lightMapPictureTexture(double seconds);
TextureDesc changesTexture(int k);
// The torch at flipbook frame k composited layer by layer on the CPU (the wall, the handle, the flames back to
// front), row 0 at t = 0.
TextureDesc torchTexture(int k);
}  // namespace ts::texanim
