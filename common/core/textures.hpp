// common/core/textures.hpp — the procedural textures every demo draws with.
// Each returns a TextureDesc whose name and params say exactly how it was
// made, so the sidecar JSON is enough to remake the texels.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"

namespace ts {
// size x size texels, checks x checks squares; texel (0,0) (s≈0, t≈0, the
// bottom-left in GL) has colour `a`.  Square (i, j) is `a` when i+j is even.
TextureDesc checkerboard(int size, int checks, Rgba a = {32, 32, 32, 255}, Rgba b = {224, 224, 224, 255});
// size x size texels, white, with grid lines one texel wide in columns and
// rows floor((size - 1) k / cells), k = 0..cells: Rogers' grid pattern
// (seed 004: 64 texels, 4 cells, lines at 0, 15, 31, 47, 63).  Texel (i, j)
// is row j from t = 0, like every procedural texture here.
TextureDesc lineGrid(int size, int cells, Rgba line = {0, 0, 0, 255}, Rgba background = {255, 255, 255, 255});
// A texture whose texel (i, j) holds its own indices, i and j in 12 bits:
// R = i & 255, G = j & 255, B = (i >> 8) | (j >> 8) << 4 (size <= 4096).
// Drawn with GL_NEAREST it turns a render into a map of which texel each
// pixel took; decodeTexelIndex reads it back.
TextureDesc texelIndexTexture(int size = 2048);
void decodeTexelIndex(Rgba c, int* i, int* j);
// width x height texels whose colour runs with the texel index, R with i
// and G with j, B alternating like a checkerboard: a repeat, a mirror or a
// clamp is visible at a glance, even at a few texels.  With alphaRamp the
// alpha runs down with i (255 at i = 0 to 64 at the last column), so an
// RGBA texture's alpha shows in GL_DECAL/GL_BLEND; else it is 255.
// Texel (i, j): (40 + 200 i/(w-1), 40 + 200 j/(h-1), 150 - 100 [i+j odd], 255 - 191 i/(w-1) or 255).
TextureDesc gradientTexture(int width, int height, bool alphaRamp = false);
// A grid of size/cells cells labelled "A1".."H8" (column letter, row number
// from the bottom): shows orientation and left/right in any mapping.
TextureDesc labelledGrid(int size = 512, int cells = 8);
// Level k filled with a distinct saturated colour (red, green, blue, ...) so
// the mip level a pixel uses is visible (the Red Book's mipmap.c idea).
TextureDesc mipLevelColours(int size = 256);
Rgba mipLevelColour(int level);

// A picture a demo rendered with GL in its measure() pass (Figure VI.7's
// sampling modes, the parallax filtering modes), shown in a panel as a
// GL_NEAREST texture.  The sidecar cannot remake it: its params name the
// image, its size, an FNV-1a digest of the pixels (also the upload cache's
// key) and the demo that made it, so the sidecar's command reproduces it.
// `img` has row 0 at the top, as every ts::Image.
TextureDesc renderedImageTexture(const Image& img, const std::string& generator, const std::string& what,
                                 const std::string& demo,
                                 std::vector<std::pair<std::string, std::string>> extraParams = {});

// A picture GL drew in a demo's measure() (`img`, row 0 at the top) together with
// the Frame that describes it (TextureDesc::renderedFrom): the sidecar writes
// that frame, and the CPU reference recomputes it and holds GL's picture to
// it.  Its params name the pass and an FNV-1a digest of the pixels (the upload
// cache's key); GL_LINEAR, clamped.
TextureDesc nestedPictureTexture(const Image& img, const Frame& frame, const std::string& generator,
                                 const std::string& what);

// A PNG, JPEG or 24/32-bit BMP file as a texture (row 0 of the picture = the top =
// t = 1).  Throws ts::Error "<path>: <what is wrong>" for a missing,
// unreadable or malformed file, and refuses sizes over the limits in
// image.hpp before allocating.  Any size is kept as it is (no resampling):
// non-power-of-two sizes are uploaded directly where the context has
// ARB_texture_non_power_of_two (GL >= 2.0, every backend here), otherwise
// resized to the next powers of two with resizeBilinear (render.cpp says so
// on stderr).
TextureDesc fileTexture(const std::string& path);
// Resamples with a bilinear filter, sample centres aligned ((x + 0.5) *
// src/dst - 0.5), edges clamped.
Image resizeBilinear(const Image& src, int width, int height);

// The book's mip chain: level k+1 texel (i, j) is the average of level k's
// texels (2i..2i+1, 2j..2j+1).  Odd sizes clamp the second row/column.
// linearLight: average in linear light (sRGB decode, mean, encode).
std::vector<Image> buildMipChain(const Image& level0, bool linearLight = false);
// Bytes of all levels above level 0 divided by level 0's bytes (≈ 1/3).
double mipChainOverhead(const std::vector<Image>& chain);

// Texel centre value of the checkerboard at (s, t): which colour GL_NEAREST
// returns (texture coordinates wrap with GL_REPEAT).
Rgba checkerAt(int size, int checks, Rgba a, Rgba b, double s, double t);
}  // namespace ts
