// demos/texture_atlas/texture_atlas_textures.hpp — the atlas demo's textures, GL-free so that a figure's sidecar
// remakes them (texture_atlas_textures.cpp registers the generator):
//   tileImage(k)           tile k of kTiles, kTile x kTile texels: a check pattern in a colour of its own;
//   atlasImage(g)          the kGrid x kGrid tiles packed in one texture, each with a gutter of g texels (its
//                          own edge texels replicated), cell pitch kTile + 2g, the texture the next power of two;
//   cellImage(k, g)        tile k with its gutter, alone: the atlas's cell as a texture of its own (the reference);
//   levelImages(size)      a mip chain whose level k is one flat colour, red = kLevelRed x k, for reading the level
//                          GL_LINEAR_MIPMAP_LINEAR reads at a pixel (red / kLevelRed = the LOD lambda).
#pragma once
#include <vector>

#include "common/core/frame.hpp"

namespace ts::atlas {
constexpr int kTile = 32;              // a tile is kTile x kTile texels (levels 0..5)
constexpr int kGrid = 4;               // the atlas holds kGrid x kGrid tiles
constexpr int kTiles = kGrid * kGrid;  // N = 16 textures
constexpr int kShownTile = 5;          // the floor repeats tile 5 (column 1, row 1: it has four neighbours)
constexpr int kLevelRed = 32;          // the level picture's red per level
// The atlas's last level: the tile's own last one (log2 kTile, where the tile is one texel).  Past it a tile is
// less than a texel, and no gutter keeps the tiles apart: the atlas's GL_TEXTURE_MAX_LEVEL stops there.
constexpr int kMaxLevel = 5;
static_assert(1 << kMaxLevel == kTile, "the tile's last level");

int pitch(int gutter);      // kTile + 2 gutter: one cell of the atlas
int atlasSize(int gutter);  // the atlas texture's side: kGrid pitch, up to a power of two
// Where tile k's first texel (its lower-left, t = 0 at row 0) lies in the atlas of gutter g.
int tileX(int k, int gutter);
int tileY(int k, int gutter);

Image tileImage(int k);
Image atlasImage(int gutter);
Image cellImage(int k, int gutter);
std::vector<Image> levelImages(int size);

// The textures as the Frames use them: mipmapped (the book's 2x2 box average, built on the CPU), trilinear
// (GL_LINEAR_MIPMAP_LINEAR), clamped to the edge.  maxLevel >= 0: only levels 0..maxLevel (GL_TEXTURE_MAX_LEVEL).
TextureDesc atlasTexture(int gutter, int maxLevel = -1);
TextureDesc cellTexture(int k, int gutter, int maxLevel = -1);
TextureDesc levelTexture(int size);
// The atlas of gutter 0 as a picture: GL_LINEAR, no mipmaps (the sub-image view's source).
TextureDesc sourceTexture();
// Tile k alone, GL_NEAREST, no mipmaps: one of the N separate textures of the draw-call count.
TextureDesc tileTexture(int k);
}  // namespace ts::atlas
