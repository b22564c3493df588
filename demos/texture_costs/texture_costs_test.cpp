// demos/texture_costs/texture_costs_test.cpp — what the cost claims' frames show, from the demo's own renders:
//   - each interpolation mode draws its own equation (computed here on the CPU, texel by texel), and the two
//     equations differ over much of the floor (the control: each picture against the other equation);
//   - the binds and draws are what the recorded calls say, and the order does not change a pixel;
//   - the grid has one vertex per height texel;
//   - mipmapped minification is flat at the texture's average, GL_LINEAR's aliases;
//   - a window times every variant and each claim's ratio is the ratio of its medians (no time is asserted).
// Tolerance: a channel more than 16 levels off (K::kOff): the CPU's bilinear lookup at the equation's (s, t) and
// GL's at its own interpolated (s, t) may sit a fraction of a texel apart, across a texel step of up to 31 levels
// (the checker's per-texel variation); a wrong equation is off by the checker's 190 levels over whole cells.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "demos/texture_costs/texture_costs_measure.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::Demo;
using ts::test::value;
namespace K = ts::costs_demo;
namespace C = ts::costs;

const K::Pictures& pictures(const Demo& d) {
  const auto* p = d.measured.detailAs<std::shared_ptr<K::Pictures>>();
  if (!p || !*p) throw std::runtime_error("texture_costs measured no pictures");
  return **p;
}

TEST(TextureCosts, EachInterpolationDrawsItsOwnEquation) {
  Demo d("texture_costs", {});
  const ts::Measurements m = d.measure();
  const K::Pictures& p = pictures(d);
  const ts::Image hyperbolic = K::predictedQuad(true), linear = K::predictedQuad(false);
  const double all = double(K::kPicture) * K::kPicture;
  const double smoothOwn = K::offPixels(p.runs[K::kSmooth].image, hyperbolic, K::kOff) / all;
  const double linearOwn = K::offPixels(p.runs[K::kNoPerspective].image, linear, K::kOff) / all;
  EXPECT_LE(smoothOwn, 0.01);
  EXPECT_LE(linearOwn, 0.01);
  // The controls: each picture against the other mode's equation.
  EXPECT_GE(K::offPixels(p.runs[K::kSmooth].image, linear, K::kOff) / all, 0.3);
  EXPECT_GE(K::offPixels(p.runs[K::kNoPerspective].image, hyperbolic, K::kOff) / all, 0.3);
  EXPECT_DOUBLE_EQ(value(m, "costs_interp_off_share[smooth_vs_hyperbolic]"), smoothOwn);
  EXPECT_DOUBLE_EQ(value(m, "costs_interp_off_share[noperspective_vs_linear]"), linearOwn);
  // Where the two agree: the bottom edge (w = 1 at both of its vertices) and the diagonal's ends.
  const glm::dvec2 a = K::quadST(0.3, -1, true), b = K::quadST(0.3, -1, false);
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
}

TEST(TextureCosts, BindsAndDrawsAreTheRecordedCallsAndOrderChangesNoPixel) {
  const ts::Measurements m = Demo("texture_costs", {}).measure();
  EXPECT_EQ(value(m, "costs_binds[sorted]"), C::kTextures);
  EXPECT_EQ(value(m, "costs_binds[unsorted]"), C::kQuads);
  EXPECT_EQ(value(m, "costs_draws[sorted]"), C::kQuads);
  EXPECT_EQ(value(m, "costs_draws[unsorted]"), C::kQuads);
  EXPECT_EQ(value(m, "costs_binds[sorted_batched]"), C::kTextures);
  EXPECT_EQ(value(m, "costs_draws[sorted_batched]"), C::kTextures);
  EXPECT_EQ(value(m, "costs_switch_off_px[unsorted_vs_sorted]"), 0);
  EXPECT_EQ(value(m, "costs_switch_off_px[batched_vs_sorted]"), 0);
}

TEST(TextureCosts, TheGridHasAVertexPerHeightTexel) {
  const ts::Measurements m = Demo("texture_costs", {}).measure();
  EXPECT_EQ(value(m, "costs_detail_triangles[bump_quad]"), 2);
  EXPECT_EQ(value(m, "costs_detail_triangles[displaced_grid]"), 2.0 * (C::kReliefTexels - 1) * (C::kReliefTexels - 1));
  EXPECT_EQ(value(m, "costs_interp_triangles"), 2);
}

TEST(TextureCosts, MipmapsGiveTheAverageWithoutThemItAliases) {
  const ts::Measurements m = Demo("texture_costs", {}).measure();
  // Level 4 of a 5-texel checker holds 16 x 16 boxes straddling cells: an 8-bit mix within a few levels of the
  // mean; trilinear blends two such levels.  GL_LINEAR picks 4 texels of 256 a pixel: the cells' own colours.
  EXPECT_LE(value(m, "costs_minify_rms[mipmapped]"), 8);
  EXPECT_LE(value(m, "costs_minify_mean_error[mipmapped]"), 4);
  EXPECT_GE(value(m, "costs_minify_rms[unmipmapped]"), 4 * value(m, "costs_minify_rms[mipmapped]"));
}

// As a window does: each measure() times one frame of the next variant, until all have their samples.  What the
// times are is the machine's; what is checked is that every variant is timed and each ratio is its medians'.
TEST(TextureCosts, AWindowTimesEveryVariantAndReportsEachClaimsRatio) {
  Demo d("texture_costs", {});
  d.scene->update(0);
  ts::Measurements m;
  size_t calls = 0;
  do {
    m = d.measure();
    ++calls;
  } while (d.scene->live() && calls < 1000);
  EXPECT_FALSE(d.scene->live()) << "timing never finished";
  EXPECT_EQ(calls, K::timedVariants().size() * K::Timer::kSamples);
  for (const K::Timed& t : K::timedVariants()) EXPECT_GT(value(m, std::string("cost_ms_per_frame[") + t.key + "]"), 0);
  for (const K::Claim& c : K::kClaims)
    EXPECT_DOUBLE_EQ(value(m, std::string("cost_timed_ratio[") + c.key + "]"),
                     value(m, std::string("cost_ms_per_frame[") + c.slow + "]") /
                         value(m, std::string("cost_ms_per_frame[") + c.fast + "]"));
  // The figure's measurements are there too, unchanged by the timing.
  EXPECT_EQ(value(m, "costs_binds[unsorted]"), C::kQuads);
}
}  // namespace
