// demos/procedural_texture/procedural_texture_textures.hpp — the demo's textures, GL-free, each remade by the
// sidecar's generator from its parameters (procedural_texture_textures.cpp): the solid (3D) noise and marble, the
// same noise as a 2D image for the sphere's (u, v) mapping, marble on a plane.
#pragma once
#include "common/core/frame.hpp"

namespace ts::proc {
constexpr int kSolidTexels = 64;                         // the 3D texture is 64^3 texels (RGBA8: 1 MiB)
constexpr int kNoise2DWidth = 128, kNoise2DHeight = 64;  // the 2D image wrapped round the sphere
constexpr int kMarblePixels = 256;                       // the marble plane's texels (and its pixels, measured)
// The solid texture, kSolidTexels^3, GL_LINEAR, clamped in s, t, r: texel (i, j, k) holds, at its centre
// p = ((i, j, k) + 1/2) / kSolidTexels, the octaves' sum S(p) (kind 0) or marble M(p) (kind 1), through
// the demo's colour ramps (stoneColour, marbleColour).
TextureDesc solidTexture(int kind, int octaves, int stripes, int turbulencePercent);
// The same noise on the plane z = 1/2 as a 2D image for a sphere's (u, v): texel (i, j) holds S(3u, 3v/2, 1/2), u =
// (i + 1/2) / width: as u runs round the sphere the noise does not come back to where it began (a seam at u = 0 = 1).
TextureDesc noise2DTexture(int octaves);
// Marble on the plane z = 1/2: kMarblePixels^2, texel (i, j) = M((i + 1/2) / n, (j + 1/2) / n, 1/2), GL_NEAREST.
TextureDesc marblePlaneTexture(int stripes, int turbulencePercent, int octaves);
// The ramps: a value in [0, 1] to a colour (stone: v spread about 1/2 by 2.2 and clamped; RGB each a straight line
// of v, so a difference of values is a difference of levels in every channel).
Rgba stoneColour(double v);
Rgba marbleColour(double v);
}  // namespace ts::proc
