// demos/texture_atlas/texture_atlas_views.hpp — the atlas demo's measurement (texture_atlas_math.hpp's floors
// rendered and read back, texture_atlas_gl.hpp's passes) and the rows of pictures its figures show.
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "common/gl/render.hpp"
#include "demos/texture_atlas/texture_atlas_gl.hpp"
#include "demos/texture_atlas/texture_atlas_math.hpp"

namespace ts::atlas {
inline const glm::vec4 kBleed{1.0f, 0.15f, 0.1f, 1.0f};   // red: a pixel more than kTolerance off the reference
inline const glm::vec4 kOutline{1.0f, 0.9f, 0.0f, 1.0f};  // yellow: the tile the sub-image upload reads
inline Rgba rgba(const glm::vec4& c) { return {uint8_t(c.r * 255), uint8_t(c.g * 255), uint8_t(c.b * 255), 255}; }
inline glm::vec4 colour(Rgba c) { return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f}; }

// What measure() rendered, for build(): the floors read back (row 0 the top) and the passes' pictures and calls.
struct Pictures {
  int deepest = 0;                 // the deepest level the floor reads (the level picture)
  std::vector<int> gutters;        // the gutters measured: 0, 1, 2, 4, ... 32
  size_t enoughIndex = 0;          // the one the deepest level needs (measured)
  std::vector<Image> atlasFloors;  // the atlas floor of each gutter
  std::vector<Image> cellFloors;   // its cell alone, the reference
  Image levels;                    // the level picture
  // The fixes (view fixes): clamped coordinates and limited levels, each with its reference.
  float inset = 0;
  int limitGutter = 1, limitLevel = 0;  // the limited-levels fix: its gutter and GL_TEXTURE_MAX_LEVEL
  Image clampAtlas, clampCell, limitAtlas, limitCell;
  // N objects, N textures or one atlas.
  Image objectsSeparate, objectsAtlas;
  gl::CallList objectsSeparateCalls, objectsAtlasCalls;
  // The sub-image upload.
  int rowLength = 0, skipPixels = 0, skipRows = 0, wrongRowLength = 0;
  Image subTexels, copiedTexels, wrongTexels;
  gl::CallList subCalls, copiedCalls, wrongCalls;
};

// The reference dimmed, the pixels `differing` counts red (row 0 the top, as both are).
inline Image bleedMap(const Image& got, const Image& want) {
  Image out = want;
  for (int y = 0; y < got.height; ++y)
    for (int x = 0; x < got.width; ++x) {
      const Rgba w = want.at(x, y);
      out.set(x, y,
              channelDiff(got.at(x, y), w) > kTolerance
                  ? rgba(kBleed)
                  : Rgba{uint8_t(w.r / 3), uint8_t(w.g / 3), uint8_t(w.b / 3), 255});
    }
  return out;
}
// Texels (not rows of the picture) where two kTile x kTile textures read back differ.
inline int texelMismatches(const Image& a, const Image& b) {
  int n = 0;
  for (int j = 0; j < a.height; ++j)
    for (int i = 0; i < a.width; ++i) n += a.at(i, j) != b.at(i, j);
  return n;
}
// Tile k of `source` copied out on the CPU (the upload the in-place one must equal).
inline Image copyTile(const Image& source, int x0, int y0) {
  Image out(kTile, kTile);
  for (int j = 0; j < kTile; ++j)
    for (int i = 0; i < kTile; ++i) out.set(i, j, source.at(x0 + i, y0 + j));
  return out;
}
constexpr int kSubTile = 6;  // the tile the sub-image view uploads: column 2, row 1 (its skips differ)

// ---- measuring --------------------------------------------------------------------------------------------------
inline Pictures measureAtlas(Renderer& r, Measurements& ms) {
  Pictures pic;
  auto put = [&](const std::string& n, double v, const std::string& meaning) { ms.push_back({n, v, meaning}); };
  auto valueOf = [&](const std::string& n) {
    for (const Measurement& m : ms)
      if (m.name == n) return m.value;
    return -1.0;
  };
  // Which levels the floor reads: the level picture's red is kLevelRed x the LOD wherever GL_LINEAR_MIPMAP_LINEAR
  // blends two flat levels (and the tile's own size, so the same LOD as the tile's).
  pic.levels = r.renderOffscreen(levelFloor());
  const double lod = maxLod(pic.levels);
  pic.deepest = deepestLevel(lod);
  const int enough = gutterForLevel(pic.deepest);  // the equation's; the measured one follows
  put("atlas_lod_max", lod,
      "the largest LOD (lambda) on the floor, from the level picture's red / " + std::to_string(kLevelRed));
  put("atlas_deepest_level", pic.deepest, "the deepest mip level GL_LINEAR_MIPMAP_LINEAR reads on the floor");
  int floorPx = 0;
  for (int y = 0; y < pic.levels.height; ++y)
    for (int x = 0; x < pic.levels.width; ++x) floorPx += onFloor(pic.levels.at(x, y));
  put("atlas_floor_px", floorPx, "pixels of the floor (the rest is sky)");
  measureProgress(0.1);
  // The floor with the atlas of each gutter against its cell alone, and where the LOD is at most k (the levels
  // read are k and below), for each level k the floor reads.
  pic.gutters = {0};
  for (int g = 1; g <= std::max(32, enough); g *= 2) pic.gutters.push_back(g);
  std::vector<std::vector<int>> within;  // [gutter][k]: bleeding pixels where the LOD is at most k
  for (int g : pic.gutters) {
    pic.atlasFloors.push_back(r.renderOffscreen(atlasFloor(g)));
    pic.cellFloors.push_back(r.renderOffscreen(cellFloor(g)));
    put("atlas_bleed_px[gutter=" + std::to_string(g) + "]", differing(pic.atlasFloors.back(), pic.cellFloors.back()),
        "floor pixels more than " + std::to_string(kTolerance) + " levels off the tile's cell alone, atlas gutter " +
            std::to_string(g));
    within.emplace_back();
    // LOD <= k - 1/kLevelRed: level k + 1's weight is under one red step of the level picture (LOD 0: red 0).
    for (int k = 0; k <= pic.deepest; ++k)
      within.back().push_back(differingWhereLod(pic.atlasFloors.back(), pic.cellFloors.back(), pic.levels,
                                                std::max(0.0, k - 1.0 / kLevelRed)));
    measureProgress(0.1 + 0.5 * double(pic.atlasFloors.size()) / double(pic.gutters.size() + 1));
  }
  // The gutter each level needs, measured: the smallest whose floor (and every wider one's) shows no bleeding
  // where the LOD is at most k.
  for (int k = 0; k <= pic.deepest; ++k) {
    size_t need = pic.gutters.size();
    while (need > 0 && within[need - 1][size_t(k)] == 0) --need;
    const double g = need < pic.gutters.size() ? pic.gutters[need] : -1;
    put("atlas_gutter_needed[level=" + std::to_string(k) + "]", g,
        "the smallest gutter (texels) with no bleeding where the LOD is at most " + std::to_string(k) + " (-1: none)");
  }
  const double needed = valueOf("atlas_gutter_needed[level=" + std::to_string(pic.deepest) + "]");
  put("atlas_gutter_needed", needed, "texels of gutter the deepest level read needs (measured)");
  size_t e = 0;
  while (e + 1 < pic.gutters.size() && pic.gutters[e] != int(needed)) ++e;
  pic.enoughIndex = e;
  put("atlas_bleed_px[gutter=enough]", valueOf("atlas_bleed_px[gutter=" + std::to_string(pic.gutters[e]) + "]"),
      "the same with the gutter the deepest level needs");
  put("atlas_bleed_px[gutter=short]",
      e > 0 ? valueOf("atlas_bleed_px[gutter=" + std::to_string(pic.gutters[e - 1]) + "]") : -1,
      "the same with the next narrower gutter measured (the control; -1: none)");
  put("atlas_gutter_short", e > 0 ? pic.gutters[e - 1] : -1, "that narrower gutter, texels");
  put("atlas_tile_share[gutter=0]", tileShare(0), "share of the atlas's texels the tiles fill, no gutter");
  put("atlas_tile_share[gutter=enough]", tileShare(pic.gutters[e]), "the same with the gutter the deepest level needs");

  // The fixes.  Clamped coordinates: no gutter, the coordinates half a level-`deepest` texel in from the tile's
  // edge, so the filter at that level stops at the tile's last texel centre; against the cell drawn the same way.
  pic.inset = 0.5f * float(1 << pic.deepest);
  pic.clampAtlas = r.renderOffscreen(atlasFloor(0, pic.inset));
  pic.clampCell = r.renderOffscreen(cellFloor(0, pic.inset));
  put("fix_bleed_px[clamp]", differing(pic.clampAtlas, pic.clampCell),
      "floor pixels off the tile alone (drawn the same way): no gutter, (s, t) clamped half a level-" +
          std::to_string(pic.deepest) + " texel in");
  put("fix_cost_px[clamp]", differing(pic.clampCell, pic.cellFloors[0]),
      "its cost: floor pixels that differ from the whole tile drawn (the tile's border texels never shown)");
  put("fix_inset_texels[clamp]", pic.inset, "texels of level 0 the coordinates stop short of the edge, each side");
  // Limited levels: a gutter of 1 texel, and GL_TEXTURE_MAX_LEVEL the deepest level that gutter was measured to keep
  // clean (atlas_gutter_needed[level=k] <= 1).
  pic.limitLevel = 0;
  for (int k = 0; k <= pic.deepest; ++k)
    if (valueOf("atlas_gutter_needed[level=" + std::to_string(k) + "]") <= pic.limitGutter) pic.limitLevel = k;
  put("fix_max_level", pic.limitLevel,
      "GL_TEXTURE_MAX_LEVEL of the limited-levels fix: the deepest level its gutter covers");
  put("fix_gutter[max_level]", pic.limitGutter, "the limited-levels fix's gutter, texels");
  pic.limitAtlas = r.renderOffscreen(atlasFloor(pic.limitGutter, 0, pic.limitLevel));
  pic.limitCell = r.renderOffscreen(cellFloor(pic.limitGutter, 0, pic.limitLevel));
  const size_t g1 = 1;  // pic.gutters[1] is 1
  put("fix_bleed_px[max_level]", differing(pic.limitAtlas, pic.limitCell),
      "floor pixels off the tile alone (drawn the same way): gutter 1, levels 0..fix_max_level only");
  put("fix_bleed_px[max_level_full_chain]", differing(pic.atlasFloors[g1], pic.cellFloors[g1]),
      "the same gutter with every level: the bleed the limit removes");
  put("fix_cost_px[max_level]", differing(pic.limitCell, pic.cellFloors[g1]),
      "its cost: floor pixels that differ from the fully mipmapped tile (the far floor under-filtered: aliasing)");
  measureProgress(0.75);

  // N objects: N textures (N binds, N glBegin) against one atlas (1, 1); the pictures must be the same.
  const ObjectsRun separate = objectsPass(r, false), together = objectsPass(r, true);
  pic.objectsSeparate = separate.picture, pic.objectsAtlas = together.picture;
  pic.objectsSeparateCalls = separate.calls, pic.objectsAtlasCalls = together.calls;
  put("atlas_binds[separate]", separate.binds, "glBindTexture calls drawing the N objects, each its own texture");
  put("atlas_binds[atlas]", together.binds, "the same, every object from the atlas");
  put("atlas_draws[separate]", separate.draws, "glBegin calls drawing the N objects, each its own texture");
  put("atlas_draws[atlas]", together.draws, "the same from the atlas: one batch");
  put("atlas_objects", kTiles, "N: the objects, each with its own tile");
  put("atlas_objects_mismatches", differing(separate.picture, together.picture, 0),
      "pixels where the two scenes' pictures differ (GL_NEAREST, a pixel a texel)");
  measureProgress(0.85);

  // One tile of the atlas picture uploaded in place, against the tile copied out first; a wrong row length.
  const Image source = atlasImage(0);
  pic.rowLength = source.width, pic.skipPixels = tileX(kSubTile, 0), pic.skipRows = tileY(kSubTile, 0);
  pic.wrongRowLength = source.width - 1;
  const Image tile = copyTile(source, pic.skipPixels, pic.skipRows);
  const SubImageRun sub = subImagePass(r, source, pic.rowLength, pic.skipPixels, pic.skipRows);
  const SubImageRun copied = copiedTilePass(r, tile);
  const SubImageRun wrong = subImagePass(r, source, pic.wrongRowLength, pic.skipPixels, pic.skipRows);
  pic.subTexels = sub.texels, pic.copiedTexels = copied.texels, pic.wrongTexels = wrong.texels;
  pic.subCalls = sub.calls, pic.copiedCalls = copied.calls, pic.wrongCalls = wrong.calls;
  put("subimage_mismatches", texelMismatches(sub.texels, copied.texels),
      "texels (glGetTexImage) where the in-place upload differs from the tile copied out and uploaded whole");
  put("subimage_mismatches[cpu]", texelMismatches(sub.texels, tile), "the same against the CPU's copy itself");
  put("subimage_mismatches[wrong_row_length]", texelMismatches(wrong.texels, copied.texels),
      "the same with GL_UNPACK_ROW_LENGTH one pixel short (the control: the rows shear)");
  put("subimage_row_length", pic.rowLength, "GL_UNPACK_ROW_LENGTH: the source picture's width, pixels");
  put("subimage_skip_pixels", pic.skipPixels, "GL_UNPACK_SKIP_PIXELS: the tile's first column in the picture");
  put("subimage_skip_rows", pic.skipRows, "GL_UNPACK_SKIP_ROWS: the tile's first row in the picture");
  double bytes = 0;
  for (const gl::Call& c : *sub.calls)
    if (std::string(c.name) == "glTexSubImage2D" && c.args.size() > 8 && c.args[8].bytes)
      bytes += double(c.args[8].bytes->size());
  put("subimage_bytes", bytes, "bytes the glTexSubImage2D read from the picture (counted from the recorded call)");
  return pic;
}

// ---- the figures' row of pictures -------------------------------------------------------------------------------
namespace L = ts::layout;
struct Picture {
  TextureDesc texture;
  L::Text title, note;
  std::vector<Batch> over;  // drawn over the picture in its panel (an outline), in the panel's unit square
};
// A picture GL drew in measure() (row 0 the top), shown as it is.
inline TextureDesc drawnPicture(const Image& img, const std::string& what, const gl::CallList& calls) {
  TextureDesc t = renderedImageTexture(img, "texture_atlas", what, "texture_atlas");
  // A panel's pixel centre may fall on a texel edge, where GL_NEAREST's tie goes either way.
  t.minFilter = t.magFilter = GL_LINEAR;
  t.renderedBy = calls;
  return t;
}
// A floor measure() rendered, as the nested frame it is the render of: the reference recomputes it.
inline TextureDesc floorPicture(const Image& img, const Frame& frame, const std::string& what) {
  TextureDesc t = drawnPicture(img, what, nullptr);
  t.image = std::make_shared<const Image>(img);  // row 0 the top, as rendered: picturePanel turns t round
  t.renderedFrom = std::make_shared<const Frame>(frame);
  return t;
}
// The pictures in a grid above a legend and the lines of numbers (layout::pictureFigure).
inline void pictureGrid(Frame& f, const std::vector<Picture>& ps, float aspect, const std::vector<LegendEntry>& legend,
                        const std::vector<L::Text>& lines) {
  std::vector<L::Captioned> captions;
  for (const Picture& p : ps) captions.push_back({p.title, p.note});
  L::pictureFigure(
      f, captions,
      [&](size_t k, const Rect& r) {
        f.panels.push_back(L::picturePanel(f, "picture_" + std::to_string(k), r, ps[k].texture));
        for (const Batch& b : ps[k].over) f.panels.back().batches.push_back(b);
      },
      legend, lines, {0, aspect, 1, 1, 10, 2, 150}, 1, Align::Left);
}
}  // namespace ts::atlas
