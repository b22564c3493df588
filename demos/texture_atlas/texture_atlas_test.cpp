// demos/texture_atlas/texture_atlas_test.cpp — the atlas demo's claims, from its own renders and measurement:
//   - the gutter each level needs is the equation's (texture_atlas_math.hpp gutterForLevel), recomputed here from
//     the generator's mip chains alone (the texels the bilinear filter reads at the tile's edge, in the atlas and in
//     the cell alone), and the demo measures the same from its renders; the rule of a tile aligned to the level's
//     boxes (2^k) does not fit (the control);
//   - with no gutter the floor bleeds, with the needed one it does not, with one level's less it does;
//   - the fixes stop the bleeding and each costs something; the atlas draws N objects with 1 bind and 1 glBegin;
//   - the in-place upload's texels are the tile's; with a wrong row length they are exactly what the unpack
//     equation reads (pixel skipRows rowLength + skipPixels + j rowLength + i of the picture), not the tile.
//
// Tolerance.  Floors are compared as the demo does, kTolerance = 3 levels (three 8-bit interpolation weights, each
// one step apart at most between two renders of the same texels).  Texels read back are compared exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "common/core/textures.hpp"
#include "demos/texture_atlas/texture_atlas_math.hpp"
#include "demos/texture_atlas/texture_atlas_textures.hpp"
#include "demos/texture_atlas/texture_atlas_views.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::Demo;
using ts::test::value;
namespace A = ts::atlas;

// The bilinear filter at level k reads, for samples from the tile's first texel x0 to its far edge x0 + kTile, the
// level-k texels floor(x0 / 2^k - 1/2) .. ceil((x0 + kTile) / 2^k - 1/2) (a texel whose weight is 0 at the edge is
// not read), or `reach` texels of level 0 more on each side, for the control.  True when every one of them, in both
// axes, is the texel the cell alone gives there (GL_CLAMP_TO_EDGE), the cell's origin falling on a texel of level k.
bool cleanAt(int gutter, int k, double reach) {
  const std::vector<ts::Image> atlas = ts::buildMipChain(A::atlasImage(gutter));
  const std::vector<ts::Image> cell = ts::buildMipChain(A::cellImage(A::kShownTile, gutter));
  if (size_t(k) >= cell.size()) return false;
  const int box = 1 << k;
  const int cx = A::tileX(A::kShownTile, gutter) - gutter, cy = A::tileY(A::kShownTile, gutter) - gutter;
  if (cx % box != 0 || cy % box != 0) return false;
  const ts::Image& a = atlas[size_t(k)];
  const ts::Image& c = cell[size_t(k)];
  auto range = [&](int x0) {
    return std::pair<int, int>{int(std::floor((x0 - reach) / box - 0.5)),
                               int(std::ceil((x0 + A::kTile + reach) / box - 0.5))};
  };
  const auto [i0, i1] = range(A::tileX(A::kShownTile, gutter));
  const auto [j0, j1] = range(A::tileY(A::kShownTile, gutter));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const int ci = std::clamp(i - cx / box, 0, c.width - 1), cj = std::clamp(j - cy / box, 0, c.height - 1);
      if (a.at(std::clamp(i, 0, a.width - 1), std::clamp(j, 0, a.height - 1)) != c.at(ci, cj)) return false;
    }
  return true;
}
// The smallest gutter of {0, 1, 2, ..., 32} from which on every wider one keeps levels 0..k clean.
int neededGutter(int k, double reach) {
  const std::vector<int> gutters = {0, 1, 2, 4, 8, 16, 32};
  size_t need = gutters.size();
  auto clean = [&](int g) {
    for (int j = 0; j <= k; ++j)
      if (!cleanAt(g, j, reach)) return false;
    return true;
  };
  while (need > 0 && clean(gutters[need - 1])) --need;
  return need < gutters.size() ? gutters[need] : -1;
}

TEST(TextureAtlas, GutterEachLevelNeedsIsTheEquations) {
  Demo d("texture_atlas", {});
  const ts::Measurements m = d.measure();
  const int deepest = int(value(m, "atlas_deepest_level"));
  EXPECT_EQ(deepest, A::deepestLevel(value(m, "atlas_lod_max")));
  EXPECT_GE(deepest, 2) << "the floor must read several levels for the claim to say anything";
  for (int k = 0; k <= deepest; ++k) {
    SCOPED_TRACE("level " + std::to_string(k));
    const int fromChains = neededGutter(k, 0);
    EXPECT_EQ(fromChains, A::gutterForLevel(k)) << "the mip chains against the equation";
    EXPECT_EQ(value(m, "atlas_gutter_needed[level=" + std::to_string(k) + "]"), fromChains) << "GL's renders";
    // The control: a filter that reached a whole level-k texel further (the aligned tile's rule, 2^k) would need
    // wider gutters than GL's renders show from level 1 on.
    if (k >= 1) EXPECT_NE(neededGutter(k, 1 << (k - 1)), fromChains);
  }
  EXPECT_EQ(value(m, "atlas_gutter_needed"), A::gutterForLevel(deepest));
}

// No gutter bleeds; the needed gutter does not, pixel for pixel against the cell alone; one level's less does.
TEST(TextureAtlas, BleedStopsAtTheNeededGutter) {
  Demo d("texture_atlas", {});
  const ts::Measurements m = d.measure();
  const A::Pictures* p = d.measured.detailAs<A::Pictures>();
  ASSERT_TRUE(p);
  EXPECT_GT(value(m, "atlas_bleed_px[gutter=0]"), 0);
  EXPECT_EQ(value(m, "atlas_bleed_px[gutter=enough]"), 0);
  EXPECT_GT(value(m, "atlas_bleed_px[gutter=short]"), 0) << "a gutter one level short must bleed";
  EXPECT_EQ(value(m, "atlas_gutter_short"), A::gutterForLevel(int(value(m, "atlas_deepest_level"))) / 2);
  // The floors themselves: the needed gutter's within the tolerance everywhere, no gutter's not.
  const size_t e = p->enoughIndex;
  EXPECT_EQ(p->gutters[e], int(value(m, "atlas_gutter_needed")));
  int worst = 0;
  for (int y = 0; y < A::kFloorH; ++y)
    for (int x = 0; x < A::kFloorW; ++x)
      worst = std::max(worst, A::channelDiff(p->atlasFloors[e].at(x, y), p->cellFloors[e].at(x, y)));
  EXPECT_LE(worst, A::kTolerance);
  EXPECT_EQ(A::differing(p->atlasFloors[0], p->cellFloors[0]), value(m, "atlas_bleed_px[gutter=0]"));
  // The reference is a fair one: the gutter-0 cell is the lone tile, and every floor covers the same pixels.
  EXPECT_EQ(A::cellImage(A::kShownTile, 0).pixels, A::tileImage(A::kShownTile).pixels);
  EXPECT_GT(value(m, "atlas_floor_px"), A::kFloorW * A::kFloorH / 2);
}

TEST(TextureAtlas, FixesStopTheBleedAndCostSomething) {
  const ts::Measurements m = Demo("texture_atlas", {"--view", "fixes"}).measure();
  EXPECT_EQ(value(m, "fix_bleed_px[clamp]"), 0);
  EXPECT_EQ(value(m, "fix_bleed_px[max_level]"), 0);
  EXPECT_GT(value(m, "fix_bleed_px[max_level_full_chain]"), 0) << "a 1-texel gutter with every level bleeds";
  EXPECT_GT(value(m, "fix_cost_px[clamp]"), 0);
  EXPECT_GT(value(m, "fix_cost_px[max_level]"), 0);
  // The limit is the deepest level a 1-texel gutter keeps clean, by the equation.
  int limit = 0;
  while (limit + 1 <= A::kMaxLevel && A::gutterForLevel(limit + 1) <= 1) ++limit;
  EXPECT_EQ(value(m, "fix_max_level"), limit);
  EXPECT_EQ(value(m, "fix_gutter[max_level]"), 1);
  EXPECT_EQ(value(m, "fix_inset_texels[clamp]"), 0.5 * (1 << int(value(m, "atlas_deepest_level"))));
  // The gutter's cost: the tiles' share of the atlas, N tiles of kTile^2 in a power-of-two square.
  const int g = int(value(m, "atlas_gutter_needed"));
  const double side = A::atlasSize(g);
  EXPECT_DOUBLE_EQ(value(m, "atlas_tile_share[gutter=enough]"), A::kTiles * A::kTile * A::kTile / (side * side));
  EXPECT_LT(value(m, "atlas_tile_share[gutter=enough]"), value(m, "atlas_tile_share[gutter=0]"));
}

TEST(TextureAtlas, AtlasDrawsNObjectsWithOneBindAndOneBatch) {
  const ts::Measurements m = Demo("texture_atlas", {}).measure();
  EXPECT_EQ(value(m, "atlas_objects"), A::kTiles);
  EXPECT_EQ(value(m, "atlas_binds[separate]"), A::kTiles);
  EXPECT_EQ(value(m, "atlas_draws[separate]"), A::kTiles);
  EXPECT_EQ(value(m, "atlas_binds[atlas]"), 1);
  EXPECT_EQ(value(m, "atlas_draws[atlas]"), 1);
  EXPECT_EQ(value(m, "atlas_objects_mismatches"), 0) << "the same picture either way";
}

// The texel (i, j) glTexSubImage2D stores, by the unpack equation: the picture's pixel at index
// (skipRows + j) rowLength + skipPixels + i, rows of the picture packed (GL_UNPACK_ALIGNMENT 1, RGBA8).
ts::Rgba unpacked(const ts::Image& picture, int rowLength, int skipPixels, int skipRows, int i, int j) {
  const size_t at = size_t((skipRows + j) * rowLength + skipPixels + i) * 4;
  const auto& px = picture.pixels;
  return {px[at], px[at + 1], px[at + 2], px[at + 3]};
}
TEST(TextureAtlas, SubImageUploadReadsTheTileInPlace) {
  Demo d("texture_atlas", {"--view", "subimage"});
  const ts::Measurements m = d.measure();
  const A::Pictures* p = d.measured.detailAs<A::Pictures>();
  ASSERT_TRUE(p);
  const ts::Image picture = A::atlasImage(0);
  EXPECT_EQ(value(m, "subimage_row_length"), picture.width);
  EXPECT_EQ(value(m, "subimage_skip_pixels"), A::tileX(A::kSubTile, 0));
  EXPECT_EQ(value(m, "subimage_skip_rows"), A::tileY(A::kSubTile, 0));
  EXPECT_EQ(value(m, "subimage_bytes"), 4.0 * A::kTile * A::kTile);
  EXPECT_EQ(value(m, "subimage_mismatches"), 0);
  EXPECT_EQ(value(m, "subimage_mismatches[cpu]"), 0);
  EXPECT_GT(value(m, "subimage_mismatches[wrong_row_length]"), 0);
  const ts::Image tile = A::tileImage(A::kSubTile);
  int offRight = 0, offWrong = 0, wrongIsTile = 0;
  for (int j = 0; j < A::kTile; ++j)
    for (int i = 0; i < A::kTile; ++i) {
      offRight += p->subTexels.at(i, j) != unpacked(picture, p->rowLength, p->skipPixels, p->skipRows, i, j);
      offRight += p->subTexels.at(i, j) != tile.at(i, j);
      offWrong += p->wrongTexels.at(i, j) != unpacked(picture, p->wrongRowLength, p->skipPixels, p->skipRows, i, j);
      wrongIsTile += p->wrongTexels.at(i, j) == tile.at(i, j);
    }
  EXPECT_EQ(offRight, 0);
  EXPECT_EQ(offWrong, 0) << "the sheared texels are the unpack equation's with the wrong row length";
  EXPECT_LT(wrongIsTile, A::kTile * A::kTile) << "and not the tile";
}

// The figures print the measurement's numbers (Label::printed), never their own.
TEST(TextureAtlas, FiguresPrintTheMeasurement) {
  const std::vector<std::pair<std::vector<std::string>, std::vector<const char*>>> views = {
      {{"--view", "atlas"},
       {"atlas_bleed_px[gutter=0]", "atlas_lod_max", "atlas_gutter_needed[level=3]", "atlas_binds[separate]",
        "atlas_draws[atlas]"}},
      {{"--view", "fixes"},
       {"fix_bleed_px[clamp]", "fix_bleed_px[max_level]", "fix_cost_px[max_level]", "atlas_tile_share[gutter=enough]"}},
      {{"--view", "subimage"},
       {"subimage_mismatches", "subimage_mismatches[wrong_row_length]", "subimage_row_length", "subimage_skip_rows"}}};
  for (const auto& [flags, names] : views) {
    SCOPED_TRACE(flags[1]);
    Demo d("texture_atlas", flags);
    d.measure();
    const ts::Frame f = d.frame(1100, 720);
    std::set<std::string> printed;
    for (const ts::Label& l : f.labels)
      for (const ts::Label::Printed& pr : l.printed) printed.insert(pr.name);
    for (const char* name : names) EXPECT_TRUE(printed.count(name)) << name;
  }
}
}  // namespace
