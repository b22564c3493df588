// demos/texture_residency/texture_residency_test.cpp — the three claims, probed in the demo's own renders against
// the equations of texture_residency_math.hpp (never against a stored image), each with a control that a wrong
// parameter fails.
//
// Tolerances.  sizes: GL_NEAREST, so the marker's pixels are its texels' exactly and their centroid is exact to
// the pixel grid; the claim allows a 64^2 texel (the panel's width / 64).  residency: the level is decoded from an
// 8-bit blend of two level colours at least 100 levels apart in some channel (1/100 of a level each rounding),
// and llvmpipe computes lambda with an approximate log2 (measured 0.02 level below log2 d here): 1/16 of a level.
// clipmap: GL_NEAREST from RGBA8 textures with no pixel centre on a texel edge: 0; in perspective, 0 outside
// the pixels within 1/64 pixel of a texel's or window's edge (texture_residency_math.hpp, referenceFlight).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/core/image.hpp"
#include "common/core/mip_lod.hpp"
#include "demos/texture_residency/texture_residency_math.hpp"
#include "demos/texture_residency/texture_residency_views.hpp"
#include "tests/support/scene_test.hpp"

namespace {
namespace R = ts::residency;
using ts::test::Demo;
using ts::test::value;

// ---- sizes ------------------------------------------------------------------------------------------------------
// The marker's centroid in each size's panel of the figure, as a fraction of the panel (s, t).
TEST(TextureResidency, TheSameStLandsOnTheSamePlaceAtEverySize) {
  Demo d("texture_residency", {"--view", "sizes"});
  const ts::Measurements m = d.measure();
  ts::Frame f;
  const ts::Image img = d.render(1024, 520, &f);
  for (int size : R::kSizes) {
    SCOPED_TRACE(size);
    const ts::Rect p = ts::test::panelOf(f, "size_" + std::to_string(size)).viewport;
    const R::Centroid c = R::markerCentroid(img, p);
    ASSERT_GT(c.n, 0);
    const double texel64 = double(p.w) / 64;  // the claim: within a texel of the smallest texture
    EXPECT_LE(std::abs(c.x - R::kMarkerS * p.w), texel64 / 2);
    EXPECT_LE(std::abs(c.y - R::kMarkerT * p.h), texel64 / 2);
    // The control: had the vertices carried texel coordinates (u, v) fixed at the 64^2 texture's, the 1024^2
    // texture would put the marker at u / 1024 of the panel, far off.
    if (size == 1024) EXPECT_GT(std::abs(c.x - R::kMarkerS * 64 / size * p.w), 10 * texel64);
    // The demo's own measurement (a 256 px panel) says the same.
    EXPECT_LE(value(m, "marker_offset_px[" + std::to_string(size) + "]"), R::kSizePanelPx / 64.0 / 2);
  }
}

// The proxy: a size that fits reads its width back, twice the maximum reads 0, and the halving settles on a
// size that fits, at most the maximum (llvmpipe: the maximum; softpipe refuses max^2 RGBA8 for its memory and
// settles on half: both are right, GL_MAX_TEXTURE_SIZE bounds a side and promises no memory).
TEST(TextureResidency, AProxyTextureSaysWhetherASizeFits) {
  Demo d("texture_residency", {"--view", "sizes"});
  const ts::Measurements m = d.measure();
  EXPECT_EQ(value(m, "proxy_width[1024]"), 1024);
  EXPECT_EQ(value(m, "proxy_width[2max]"), 0);
  const double max = value(m, "max_texture_size"), settled = value(m, "proxy_settled_size");
  EXPECT_GE(max, 1024);  // GL 2.1 requires 64; every backend here has more
  EXPECT_GE(value(m, "proxy_halvings"), 1);
  EXPECT_EQ(settled, 2 * max / std::pow(2.0, value(m, "proxy_halvings")));
  EXPECT_LE(settled, max);
  EXPECT_EQ(value(m, "proxy_width[settled]"), settled);
}

// ---- residency --------------------------------------------------------------------------------------------------
// The level each quad of the figure reads, decoded from its colour, against lambda = log2 rho; the finest level
// and the resident fraction follow.
TEST(TextureResidency, DistantQuadsReadOnlyCoarseLevels) {
  Demo d("texture_residency", {"--view", "residency"});
  const ts::Measurements m = d.measure();
  ts::Frame f;
  const ts::Image img = d.render(1100, 460, &f);
  const double tolerance = 1.0 / 16;
  int previous = -1;
  for (size_t k = 0; k < R::kDistances.size(); ++k) {
    const double dist = R::kDistances[k];
    SCOPED_TRACE(dist);
    const ts::Rect p = ts::test::panelOf(f, "distance_" + std::to_string(k)).viewport;
    // The quad spans p.h / (2 d tan(fov / 2)) pixels of the 256-texel texture: rho = 256 / that.
    const double quad = p.h / (2 * dist * R::kTanHalfFov), lambda = std::log2(R::kLevelTexels / quad);
    const int q = std::max(1, int(quad / 2)), cx = p.x + p.w / 2, cy = p.y + p.h / 2;
    double residual = 0;
    const double level = ts::lod::levelOfColour(ts::lod::meanOf(img, {cx - q / 2, cy - q / 2, q, q}), R::kLevels,
                                                &residual);
    EXPECT_NEAR(level, lambda, tolerance);
    EXPECT_LE(residual, 3.0) << "the colour is a blend of two neighbouring levels";
    // The control: the equation at twice the distance is a whole level off.
    EXPECT_GT(std::abs(level - std::log2(R::kLevelTexels / (quad / 2))), 1 - tolerance);
    const int finest = int(std::floor(level));
    EXPECT_EQ(finest, int(std::floor(lambda)));
    EXPECT_GT(finest, previous) << "each doubling of the distance drops a level";
    previous = finest;
    // The measurement (192 px panels, the figure's here) agrees, and the resident fraction is the levels'.
    const std::string n = "[" + R::distanceKey(dist) + "]";
    EXPECT_EQ(value(m, "finest_level_read" + n), finest);
    double held = 0, all = 0;
    for (int l = 0; l < R::kLevels; ++l) {
      const double texels = std::pow(4.0, R::kLevels - 1 - l);
      all += texels, held += l >= finest ? texels : 0;
    }
    EXPECT_NEAR(value(m, "resident_fraction" + n), held / all, 1e-12);
  }
  // Buss VI.1.3: the distant quad needs under 1 % of the chain.
  EXPECT_LT(value(m, "resident_fraction[24]"), 0.01);
}

// ---- clipmap ----------------------------------------------------------------------------------------------------
// GL's view through the stack equals the procedural texture sampled at the stack's level, pixel for pixel; the
// same view against the eye one move back (a wrong offset) does not.
TEST(TextureResidency, TheClipmapShowsTheVirtualTextureExactly) {
  for (int moves : {1, R::kMoves, 40}) {  // the key . moves the eye on: the claim holds wherever it is
    SCOPED_TRACE(moves);
    Demo d("texture_residency", {"--view", "clipmap", "--moves", std::to_string(moves)});
    const ts::Measurements m = d.measure();
    const R::Detail* detail = m.detailAs<R::Detail>();
    ASSERT_NE(detail, nullptr);
    const R::Eye end = R::eyeAfter(moves);
    EXPECT_EQ(R::differingPixels(detail->clipViewRaw, R::referenceView(end)), 0);
    EXPECT_GT(R::differingPixels(detail->clipViewRaw, R::referenceView(R::eyeAfter(moves - 1))), 0);
    EXPECT_EQ(value(m, "clipmap_mismatch_px"), 0);
    EXPECT_GT(value(m, "clipmap_mismatch_px[stale]"), 0);
    // Each level's storage holds its window toroidally: texel i of level l at i mod 512.
    for (int l = 0; l < R::kClipLevels; ++l) {
      SCOPED_TRACE(l);
      const R::Eye w = R::windowOrigin(end, l);
      int wrong = 0, wrongShifted = 0;
      for (int j = w.y; j < w.y + R::kClip; j += 7)
        for (int i = w.x; i < w.x + R::kClip; i += 7) {
          const ts::Rgba held = detail->clipStorage[l].at(R::mod(i, R::kClip), R::mod(j, R::kClip));
          wrong += held != R::virtualTexel(l, i, j);
          wrongShifted += held != R::virtualTexel(l, i + 1, j);  // the control: an offset one texel off
        }
      EXPECT_EQ(wrong, 0);
      EXPECT_GT(wrongShifted, 0);
    }
  }
}

// The same stack in perspective: every pixel not within 1/64 pixel of an edge is the texel the CPU's ray to the
// ground finds at the level whose window holds the ground point; against the eye one move back, many are not.
TEST(TextureResidency, TheClipmapInPerspectiveShowsTheVirtualTexture) {
  Demo d("texture_residency", {"--view", "clipmap"});
  const ts::Measurements m = d.measure();
  const R::Detail* detail = m.detailAs<R::Detail>();
  ASSERT_NE(detail, nullptr);
  std::vector<char> ambiguous, ambiguousBefore;
  const ts::Image want = R::referenceFlight(R::eyeAfter(R::kMoves), &ambiguous);
  const ts::Image before = R::referenceFlight(R::eyeAfter(R::kMoves - 1), &ambiguousBefore);
  long long held = 0;
  for (char a : ambiguous) held += !a;
  EXPECT_GT(held, (long long)R::kFlightW * R::kFlightH / 2) << "most pixels are held to one texel";
  EXPECT_EQ(R::differingPixels(detail->flightRaw, want, ambiguous), 0);
  EXPECT_GT(R::differingPixels(detail->flightRaw, before, ambiguous), held / 10);
  EXPECT_EQ(value(m, "clipmap_flight_mismatch_px"), 0);
}

// The texels uploaded a move are the strips that entered the windows (the equation), far fewer than a reload.
TEST(TextureResidency, AMoveUploadsOnlyTheExposedStrips) {
  Demo d("texture_residency", {"--view", "clipmap"});
  const ts::Measurements m = d.measure();
  long long predicted = 0;
  for (int k = 1; k <= R::kMoves; ++k) predicted += R::exposedTexels(R::eyeAfter(k - 1), R::eyeAfter(k));
  EXPECT_EQ(value(m, "clipmap_texels_uploaded[move]"), double(predicted) / R::kMoves);
  EXPECT_EQ(value(m, "clipmap_texels_uploaded[reload]"), double(R::kClipLevels) * R::kClip * R::kClip);
  // One move of (37, 21) at level 0: 37 columns of 512, then 21 rows of the other 475.
  EXPECT_EQ(R::exposed({1024, 1024}, {1024 + R::kStepX, 1024 + R::kStepY}, 0)[0].texels(), 37LL * 512);
  EXPECT_EQ(R::exposed({1024, 1024}, {1024 + R::kStepX, 1024 + R::kStepY}, 0)[1].texels(), 21LL * (512 - 37));
  EXPECT_LT(value(m, "clipmap_texels_uploaded[move]") * 10, value(m, "clipmap_texels_uploaded[reload]"));
  // The memory: the closed form of common/core/texture_memory.hpp, six 512^2 levels and the 256^2 .. 1x1 tail.
  EXPECT_EQ(value(m, "clipmap_stack_texels"), 6 * 512.0 * 512.0 + (256.0 * 256.0 * 4 - 1) / 3);
  EXPECT_NEAR(value(m, "clipmap_saving[65536/512]"), 2621.44, 0.01);
}
}  // namespace
