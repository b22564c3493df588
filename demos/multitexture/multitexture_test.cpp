// demos/multitexture/multitexture_test.cpp — seed 001's multitexturing claims
// (demos/multitexture), each against a value computed here: the alpha test
// hides no sky and blending's fringe is gone with it; a cross tree's least
// width is cos 45°; light maps converge on per-pixel lighting; the gloss map's
// highlights are in the ratio of its values, 5; AB + CD within a level of the
// CPU with two units or a stored copy, (AB + C) D without; the pear in one
// GL_MODULATE_ADD_ATI stage as in two passes; and the passes each takes.
#include <gtest/gtest.h>

#include <cmath>

#include "demos/multitexture/multitexture_math.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::value;

class MultitextureFigure : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    demo = new ts::test::Demo("multitexture", {});
    ms = demo->measure();
  }
  static void TearDownTestSuite() { delete demo; }
  static ts::test::Demo* demo;
  static ts::Measurements ms;
};
ts::test::Demo* MultitextureFigure::demo = nullptr;
ts::Measurements MultitextureFigure::ms;

// Claim: drawn first, without the alpha test every transparent texel writes
// depth and hides the sky behind it: 64 x 64 texels over 128 x 128 pixels
// (GL_NEAREST), so 4 pixels a transparent texel, counted here from the
// texture; with glAlphaFunc(GL_GREATER, 0.5) none.  Blending alone hides as
// many (it still writes depth).
TEST_F(MultitextureFigure, AlphaTestHidesNoSky) {
  const ts::Image tree = mt::treeTexture();
  int transparent = 0;
  for (int j = 0; j < tree.height; ++j)
    for (int i = 0; i < tree.width; ++i) transparent += tree.at(i, j).a == 0;
  ASSERT_GT(transparent, 0);
  EXPECT_EQ(value(ms, "cutout_hidden_px[alpha_test]"), 0.0);
  EXPECT_EQ(value(ms, "cutout_hidden_px[no_alpha_test]"), 4.0 * transparent);
  EXPECT_EQ(value(ms, "cutout_hidden_px[blend]"), 4.0 * transparent);
}

// Claim: magnified, blending mixes sky and tree along the edge; the alpha
// test leaves every pixel sky or tree (0 mixed pixels).
TEST_F(MultitextureFigure, AlphaTestEdgeHasNoFringe) {
  EXPECT_EQ(value(ms, "edge_fringe_px[alpha_test]"), 0.0);
  EXPECT_GT(value(ms, "edge_fringe_px[blend]"), 100.0);
}

// Claim: over a full turn (5-degree steps, orthographic) one quad's width is
// |cos θ| (0 edge-on, 1 face-on) and the cross tree's max(|cos θ|, |sin θ|),
// least at 45°: cos 45° = 0.7071.  A width is counted in pixel centres, 128
// to the unit: within 1.5 pixels.
TEST_F(MultitextureFigure, CrossTreeWidth) {
  const double px = 1.5 / 128.0;
  EXPECT_NEAR(value(ms, "cross_tree_min_width"), std::cos(M_PI / 4), px);
  EXPECT_NEAR(value(ms, "cross_tree_max_width"), 1.0, px);
  EXPECT_NEAR(value(ms, "single_quad_min_width"), 0.0, px);
  EXPECT_NEAR(value(ms, "single_quad_max_width"), 1.0, px);
}

// Claim: c = base ⊗ L approaches per-pixel lighting as L grows (8² .. 64²),
// at L's memory: n² bytes (GL_LUMINANCE8).
TEST_F(MultitextureFigure, LightMapConverges) {
  EXPECT_GT(value(ms, "light_map_rms[8]"), value(ms, "light_map_rms[16]"));
  EXPECT_GT(value(ms, "light_map_rms[16]"), value(ms, "light_map_rms[32]"));
  EXPECT_GT(value(ms, "light_map_rms[32]"), value(ms, "light_map_rms[64]"));
  EXPECT_GT(value(ms, "light_map_rms[8]"), 2.0 * value(ms, "light_map_rms[64]"));
  EXPECT_LT(value(ms, "light_map_rms[64]"), 2.0) << "within 2 levels at 64^2";
  for (int n : {8, 16, 32, 64}) EXPECT_EQ(value(ms, "light_map_bytes[" + std::to_string(n) + "]"), double(n * n));
}

// Claim: i = t_d ⊗ i_diff + g · i_spec: the highlight under g = 1 (255) is
// 255 / 51 = 5 times the one under g = 0.2 (51), each peak within a level
// (the tolerance of the ratio follows), the diffuse untouched by the gloss
// pass; two passes.
TEST_F(MultitextureFigure, GlossPeakRatio) {
  const double hi = value(ms, "gloss_peak[g=1]"), lo = value(ms, "gloss_peak[g=0.2]");
  EXPECT_EQ(255.0 / (mt::kGlossLow * 255.0), 5.0);
  EXPECT_LE(hi, mt::kSpecular * 255 + 1);
  EXPECT_GE(hi, 0.9 * mt::kSpecular * 255) << "the highlight's peak, Gouraud-interpolated between vertices";
  EXPECT_NEAR(value(ms, "gloss_peak_ratio"), 5.0, 5.0 * (1.0 / hi + 1.0 / lo));
  // Away from the highlights pass 2 adds less than 0.1/255: llvmpipe keeps
  // every pixel, softpipe rounds the blend's sum up by a level at a few
  // hundred of them (measured 490 of 32,768).
  EXPECT_LE(value(ms, "gloss_diffuse_change"), 1.0);
  EXPECT_GT(value(ms, "gloss_diffuse_px"), 256 * 128 / 4) << "checked over a good part of the plane";
  EXPECT_EQ(value(ms, "gloss_passes"), 2.0);
}

// Claim: AB + CD with two units (GL_COMBINE) takes 2 passes, with one unit 5
// and a copy to a texture, both within 1 level of the CPU; the framebuffer
// alone (4 passes, no copy) makes (AB + C) D: within 1 level of that, far
// from AB + CD.
TEST_F(MultitextureFigure, AbPlusCd) {
  EXPECT_LE(value(ms, "abcd_max_diff[multitexture]"), 1.0);
  EXPECT_LE(value(ms, "abcd_max_diff[stored]"), 1.0);
  EXPECT_EQ(value(ms, "abcd_passes[multitexture]"), 2.0);
  EXPECT_EQ(value(ms, "abcd_copies[multitexture]"), 0.0);
  EXPECT_EQ(value(ms, "abcd_passes[stored]"), 5.0);
  EXPECT_EQ(value(ms, "abcd_copies[stored]"), 1.0);
  EXPECT_EQ(value(ms, "abcd_passes[framebuffer_only]"), 4.0);
  EXPECT_EQ(value(ms, "abcd_copies[framebuffer_only]"), 0.0);
  EXPECT_LE(value(ms, "abcd_max_diff[framebuffer_only_vs_cpu_model]"), 1.0);
  EXPECT_GT(value(ms, "abcd_max_diff[framebuffer_only]"), 20.0);
  EXPECT_GT(value(ms, "abcd_rms[framebuffer_only]"), 5.0);
}

// Claim: this Mesa has GL_ATI_texture_env_combine3 (docs/platform.md);
// the pear t_d i_diff + t_g t_r takes one pass with GL_MODULATE_ADD_ATI and
// two without, the same within the two passes' extra rounding.
TEST_F(MultitextureFigure, PearCombine3) {
  ASSERT_EQ(value(ms, "combine3_supported"), 1.0);
  EXPECT_EQ(value(ms, "pear_passes[combine3]"), 1.0);
  EXPECT_EQ(value(ms, "pear_passes[two_passes]"), 2.0);
  EXPECT_LE(value(ms, "pear_combine3_vs_two_passes_max_diff"), 2.0);
}

// The CPU's models: AB + CD and (AB + C) D differ; the light map samples the
// lighting at its texel centres.
TEST(MultitextureMath, Models) {
  const auto t = mt::abcdTextures();
  const ts::Image a = mt::abcdCpu(t, 64, false), b = mt::abcdCpu(t, 64, true);
  EXPECT_GT(mt::maxDiff(a, b), 20);
  const ts::Image l = mt::lightMap(8);
  EXPECT_EQ(l.at(3, 5).r, mt::u8(mt::lightAt(3.5 / 8, 5.5 / 8)));
  EXPECT_NEAR(mt::lightAt(0.5, 0.5), 1.0, 1e-12);
}
}  // namespace
