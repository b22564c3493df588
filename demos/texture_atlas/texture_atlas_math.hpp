// demos/texture_atlas/texture_atlas_math.hpp — the atlas demo's Frames and counts, GL-free: the receding floor that
// repeats one tile (as plain data the renderer draws and the sidecar records), the (s, t) range a tile takes in
// the atlas or in its own texture, and the pixel comparisons the measurement makes of the renders read back.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "demos/texture_atlas/texture_atlas_textures.hpp"

namespace ts::atlas {
constexpr int kFloorW = 256, kFloorH = 160;     // the floor's picture, pixels (measured and shown at this size)
constexpr int kFloorCols = 8, kFloorRows = 16;  // the floor: kFloorCols x kFloorRows squares, one tile each
// Levels by which two renders of the same texels may differ: llvmpipe's three interpolation weights (s, t and
// the level blend) are 8-bit fixed point, and the two renders reach the same texels through coordinates that
// differ in their last float bits, so each weight may be one step (1/256) apart: a level each, 3 at most.
constexpr int kTolerance = 3;
const glm::vec4 kSky{0.10f, 0.11f, 0.14f, 1.0f};  // the background above the floor

// The (s, t) square a tile's texels fill in its texture, and how far in from its edge the floor's coordinates
// stop (texels of level 0, on every side: the clamped-coordinates fix).
struct TileRange {
  float s0 = 0, t0 = 0, s1 = 1, t1 = 1;
};
// Tile k in the atlas of gutter g, its coordinates `inset` texels in from its edge.
inline TileRange atlasRange(int k, int gutter, float inset = 0) {
  const float n = float(atlasSize(gutter));
  const float x = float(tileX(k, gutter)), y = float(tileY(k, gutter));
  return {(x + inset) / n, (y + inset) / n, (x + kTile - inset) / n, (y + kTile - inset) / n};
}
// The tile in its own cell texture (the gutter around it), `inset` texels in.
inline TileRange cellRange(int gutter, float inset = 0) {
  const float p = float(pitch(gutter)), g = float(gutter);
  return {(g + inset) / p, (g + inset) / p, (g + kTile - inset) / p, (g + kTile - inset) / p};
}

// The camera: at height 0.55 above the floor, looking down the -z axis tilted 12 degrees down, 50 degree fov.
inline glm::mat4 floorProjection() {
  return glm::perspective(glm::radians(50.0f), float(kFloorW) / float(kFloorH), 0.1f, 40.0f);
}
inline glm::mat4 floorView() {
  return glm::rotate(glm::mat4(1.0f), glm::radians(12.0f), glm::vec3(1, 0, 0)) *
         glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.55f, 0.0f));
}
// The floor: squares of side 1 from z = -0.3 to z = -0.3 - kFloorRows, x from -kFloorCols/2 to kFloorCols/2, each
// showing the tile once: its corners carry the tile's (s, t) range, so a square repeats the tile without GL_REPEAT
// (which would wrap the whole atlas, not the tile).
inline Batch floorBatch(int texture, const TileRange& r) {
  Batch b;
  b.role = "floor";
  b.texture = texture;
  for (int row = 0; row < kFloorRows; ++row)
    for (int col = 0; col < kFloorCols; ++col) {
      const float x0 = float(col - kFloorCols / 2), z0 = -0.3f - float(row);
      for (int c : {0, 1, 2, 0, 2, 3}) {
        const float u = float(c == 1 || c == 2), v = float(c >= 2);
        const glm::vec3 pos(x0 + u, 0.0f, z0 - v);
        const glm::vec4 tex(r.s0 + u * (r.s1 - r.s0), r.t0 + v * (r.t1 - r.t0), 0.0f, 1.0f);
        b.vertices.push_back({pos, tex, {1, 1, 1, 1}});
      }
    }
  return b;
}
// The floor's picture as a Frame of its own, kFloorW x kFloorH: what measure() renders, and what the figure
// shows as a nested frame (TextureDesc::renderedFrom), so the reference recomputes it from the sidecar.
inline Frame floorFrame(const TextureDesc& tex, const TileRange& r) {
  Frame f;
  f.width = kFloorW, f.height = kFloorH;
  f.clearColor = kSky;
  Panel p;
  p.id = "floor";
  p.viewport = {0, 0, kFloorW, kFloorH};
  p.projection = floorProjection();
  p.modelview = floorView();
  p.clear = true, p.clearColor = kSky;
  p.batches.push_back(floorBatch(f.addTexture(tex), r));
  f.panels.push_back(p);
  return f;
}
// The floors the demo draws: the atlas of gutter g (tile kShownTile), its cell alone, and the level picture; each
// texture's levels 0..maxLevel only (kMaxLevel: the tile's own).
inline Frame atlasFloor(int gutter, float inset = 0, int maxLevel = kMaxLevel) {
  return floorFrame(atlasTexture(gutter, maxLevel), atlasRange(kShownTile, gutter, inset));
}
inline Frame cellFloor(int gutter, float inset = 0, int maxLevel = kMaxLevel) {
  return floorFrame(cellTexture(kShownTile, gutter, maxLevel), cellRange(gutter, inset));
}
// The level picture: a kTile x kTile texture (the tile's own size, so the same lambda at every pixel) whose level
// k is red = kLevelRed k, on the same floor with coordinates 0..1 a square.
inline Frame levelFloor() { return floorFrame(levelTexture(kTile), {0, 0, 1, 1}); }

// The largest channel difference of two pixels (colour only).
inline int channelDiff(Rgba a, Rgba b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}
// Pixels where `a` and `b` differ by more than `tol` in some channel.
inline int differing(const Image& a, const Image& b, int tol = kTolerance) {
  int n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) n += channelDiff(a.at(x, y), b.at(x, y)) > tol;
  return n;
}
// The same, only at pixels whose LOD (the level picture `levels`: lambda = red / kLevelRed) is at most `lambda`.
inline int differingWhereLod(const Image& a, const Image& b, const Image& levels, double lambda, int tol = kTolerance) {
  int n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      n += channelDiff(a.at(x, y), b.at(x, y)) > tol && levels.at(x, y).r <= lambda * kLevelRed;
  return n;
}
// The floor's pixels (those the level picture draws: not the sky).
inline bool onFloor(Rgba levelPixel) { return levelPixel.g == 40; }
// The deepest LOD the floor reads, from the level picture: the largest red / kLevelRed over the floor.
inline double maxLod(const Image& levels) {
  int red = 0;
  for (int y = 0; y < levels.height; ++y)
    for (int x = 0; x < levels.width; ++x)
      if (onFloor(levels.at(x, y))) red = std::max(red, int(levels.at(x, y).r));
  return double(red) / kLevelRed;
}
// The deepest mip level GL_LINEAR_MIPMAP_LINEAR reads at LOD lambda: floor(lambda) + 1 when the blend gives that
// level any weight (a red step of the level picture is 1/kLevelRed of a level: less is rounding), else floor(lambda).
inline int deepestLevel(double lambda) {
  const int k = int(std::floor(lambda));
  return lambda - k >= 1.0 / kLevelRed ? k + 1 : k;
}
// The gutter level k needs, for a tile packed right after its gutter (x0 = c pitch + g, pitch = kTile + 2g).  A
// level-k texel is the mean of a 2^k x 2^k box of level 0, the boxes starting at multiples of 2^k.  At the tile's
// edge the bilinear filter reaches back half a level-k texel, to x0 - 2^(k-1), and reads the whole box holding
// that texel.  The atlas shows the cell alone's texels there only if (a) the cells start on box boundaries
// (pitch a multiple of 2^k) and (b) that box starts inside the cell: 2^k floor((x0 - 2^(k-1)) / 2^k) >= x0 - g,
// which for x0 = c pitch + g is g >= 2^(k-1).  Level 0 reads half a texel past the edge: one texel of gutter.
//      gutter(k) = 1 (k = 0),  2^(k-1) (k >= 1)
// (A tile aligned to 2^k boxes, x0 a multiple of 2^k, has its edge on a box boundary: the filter then reads the
// whole box left of it, and needs 2^k.)  The smallest gutter that keeps level k clean also keeps every level below.
inline bool gutterCovers(int gutter, int k) {
  if (k == 0) return gutter >= 1;
  return pitch(gutter) % (1 << k) == 0 && gutter >= (1 << (k - 1));
}
inline int gutterForLevel(int k) { return k == 0 ? 1 : 1 << (k - 1); }
// Of the atlas's texels, the share the tiles themselves fill (the gutters' cost).
inline double tileShare(int gutter) {
  const double n = atlasSize(gutter);
  return double(kTiles) * kTile * kTile / (n * n);
}
}  // namespace ts::atlas
