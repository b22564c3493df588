// demos/cylinder_seam/cylinder_seam_test.cpp — Figures VI.3, VI.4 and Exercise
// VI.1 (demos/cylinder_seam): the label on the cylinder and the patch across
// the seam, checked from renders against the mathematics in
// demos/cylinder_seam/cylinder_seam_math.hpp, never against a stored image.
//
// Tolerances.  The demo's measurement reads s from a texel-index texture of
// N = 2048 texels (GL_NEAREST): each pixel's s is the centre of the texel it
// took, within 1/2 texel of the interpolated value (the demo reports the
// largest distance, texel_error_max; we require <= 1).  The span is the
// slope of a least-squares line through 256 x 32 such values across the
// patch, so it is good to a small fraction of a texel; we allow 2 texels,
// 2/2048 ≈ 0.001, against 0.8 vs 0.2 — a difference of 1229 texels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/image.hpp"
#include "common/core/mesh.hpp"
#include "common/core/probe.hpp"
#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "demos/cylinder_seam/cylinder_seam_math.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/scene_test.hpp"

namespace {
constexpr int kN = 2048;               // texels of the texel-index texture
constexpr double kSpanTol = 2.0 / kN;  // see the header comment

using ts::test::Demo;
using ts::test::value;

using ts::test::panelOf;

// The frame as the figure shows it, but every textured triangle batch reads
// the texel-index texture (GL_NEAREST, GL_REPEAT, replace) and lines,
// blended overlays and labels are left out: each pixel of the picture then
// says which texel the figure shows there.  Clear alpha 0 marks "nothing".
ts::Image renderTexelIndex(ts::Frame f) {
  int tex = f.addTexture(ts::texelIndexTexture(kN));
  f.clearColor = glm::vec4(0.0f);
  for (auto& p : f.panels) {
    std::vector<ts::Batch> keep;
    for (auto& b : p.batches)
      if (b.prim == ts::Prim::Triangles && b.texture >= 0 && !b.blend) {
        b.texture = tex;
        b.texEnv = GL_REPLACE;
        keep.push_back(b);
      }
    p.batches = keep;
  }
  return ts::test::renderer().render(f, false);
}
double sAt(const ts::Image& img, glm::vec2 q) {
  ts::Rgba c = img.at(int(q.x), int(q.y));
  EXPECT_EQ(c.a, 255) << "no surface at (" << q.x << ", " << q.y << ")";
  int i = 0, j = 0;
  ts::decodeTexelIndex(c, &i, &j);
  return (i + 0.5) / kN;
}
// Distance between two s values modulo 1 (GL_REPEAT).
double wrapDist(double a, double b) {
  double d = a - b;
  return std::abs(d - std::round(d));
}

// Claim (Figure VI.4): with each vertex's s reduced to [0,1) the patch across
// the front seam shows 0.8 of the texture, backwards (ds/dx < 0), measured
// from a render; it is the only reversed patch.
TEST(CylinderSeam, WrongSeamPatchShowsEightTenthsBackwards) {
  Demo demo("cylinder_seam", {"--coords", "wrong", "--slices", "5", "--seam", "front"});
  ts::Measurements m = demo.measure();
  EXPECT_EQ(value(m, "seam_patch"), 0.0);
  EXPECT_NEAR(value(m, "seam_patch_span_s[wrong]"), 0.8, kSpanTol);
  EXPECT_EQ(value(m, "seam_patch_direction[wrong]"), -1.0);
  EXPECT_EQ(value(m, "reversed_patches[wrong]"), 1.0);
  EXPECT_LE(value(m, "texel_error_max[wrong]"), 1.0);
}

// Claim (the fix): s = 0.9 -> 1.1 with GL_REPEAT shows the intended 0.2,
// forwards, and no patch is reversed.
TEST(CylinderSeam, RightSeamPatchShowsTwoTenthsForwards) {
  Demo demo("cylinder_seam", {"--coords", "right", "--slices", "5", "--seam", "front"});
  ts::Measurements m = demo.measure();
  EXPECT_NEAR(value(m, "seam_patch_span_s[right]"), 0.2, kSpanTol);
  EXPECT_EQ(value(m, "seam_patch_direction[right]"), 1.0);
  EXPECT_EQ(value(m, "reversed_patches[right]"), 0.0);
  EXPECT_LE(value(m, "texel_error_max[right]"), 1.0);
}

// Negative control: the check separates the two: the wrong patch's measured
// span is nowhere near the right one's (a measurement that always said 0.2,
// or that unwrapped s into forwards order, would fail the two tests above).
TEST(CylinderSeam, NegativeControlTheTwoMeasurementsDiffer) {
  Demo demo("cylinder_seam", {"--view", "compare"});
  ts::Measurements m = demo.measure();
  double wrong = value(m, "seam_patch_span_s[wrong]"), right = value(m, "seam_patch_span_s[right]");
  EXPECT_GT(std::abs(wrong - 0.2), 100 * kSpanTol) << "the wrong patch measured like the right one";
  EXPECT_GT(std::abs(right - 0.8), 100 * kSpanTol);
  EXPECT_NE(value(m, "seam_patch_direction[wrong]"), value(m, "seam_patch_direction[right]"));
}

// Claim (Exercise VI.1): with s = θ/360 + 1/2 the edges meet at the back: the
// front patch shows 0.2 forwards in both coordinate modes; the seam patch is
// the one at the back (slices/2), and reducing s there still reverses it.
TEST(CylinderSeam, BackSeamLeavesTheFrontPatchForwards) {
  Demo demo("cylinder_seam", {"--seam", "back", "--view", "compare", "--slices", "5"});
  ts::Measurements m = demo.measure();
  EXPECT_EQ(value(m, "seam_patch"), 2.0);
  for (const char* c : {"wrong", "right"}) {
    SCOPED_TRACE(c);
    EXPECT_NEAR(value(m, std::string("front_patch_span_s[") + c + "]"), 0.2, kSpanTol);
    EXPECT_EQ(value(m, std::string("front_patch_direction[") + c + "]"), 1.0);
  }
  EXPECT_NEAR(value(m, "seam_patch_span_s[wrong]"), 0.8, kSpanTol);
  EXPECT_EQ(value(m, "seam_patch_direction[wrong]"), -1.0);
  EXPECT_EQ(value(m, "reversed_patches[right]"), 0.0);
  // The same with an even count (the seam then crosses the middle of a patch).
  Demo even("cylinder_seam", {"--seam", "back", "--coords", "wrong", "--slices", "8"});
  ts::Measurements e = even.measure();
  EXPECT_EQ(value(e, "seam_patch"), 4.0);
  EXPECT_EQ(value(e, "front_patch_direction[wrong]"), 1.0);
  EXPECT_NEAR(value(e, "front_patch_span_s[wrong]"), 1.0 / 8, kSpanTol);
  EXPECT_NEAR(value(e, "seam_patch_span_s[wrong]"), 1.0 - 1.0 / 8, kSpanTol);
}

// Claim (the book's numbers, exactly): θ = -36° at x, w and +36° at y, z
// give s = 0.9 and 0.1 reduced, 0.9 and 1.1 with the winding tracked; the
// seam column i = slices repeats column 0 as 0.9 (wrong) or 1.9 (right).
TEST(CylinderSeam, BookTextureCoordinates) {
  cylinder::Params p;
  EXPECT_DOUBLE_EQ(cylinder::thetaDeg(5, 0), -36.0);
  EXPECT_DOUBLE_EQ(cylinder::thetaDeg(5, 1), 36.0);
  p.coords = cylinder::Coords::Wrong;
  EXPECT_DOUBLE_EQ(cylinder::sOf(p, 0), 0.9);
  EXPECT_DOUBLE_EQ(cylinder::sOf(p, 1), 0.1);
  EXPECT_DOUBLE_EQ(cylinder::sOf(p, 5), 0.9);
  EXPECT_DOUBLE_EQ(cylinder::patchSpan(p, 0), 0.1 - 0.9);
  p.coords = cylinder::Coords::Right;
  EXPECT_DOUBLE_EQ(cylinder::sOf(p, 0), 0.9);
  EXPECT_DOUBLE_EQ(cylinder::sOf(p, 1), 1.1);
  EXPECT_DOUBLE_EQ(cylinder::sOf(p, 5), 1.9);
  EXPECT_DOUBLE_EQ(cylinder::tOf(p, 0), 0.0);
  EXPECT_DOUBLE_EQ(cylinder::tOf(p, 1), 1.0);
  // Exercise VI.1: s = θ/360 + 1/2: column 0 at 0.4, the front patch 0.4..0.6.
  p.seam = cylinder::Seam::Back;
  EXPECT_DOUBLE_EQ(cylinder::sOf(p, 0), 0.4);
  EXPECT_DOUBLE_EQ(cylinder::sOf(p, 1), 0.6);
}

// Claim (Buss III.3.2): vertices shared by neighbouring patches have
// bit-identical positions, including the seam column (i = 0 and i = slices),
// because ts::parametricGrid evaluates the wrapped column.
TEST(CylinderSeam, SharedVerticesAreBitIdentical) {
  for (int slices : {3, 5, 8, 24, 36})
    for (int stacks : {1, 4}) {
      SCOPED_TRACE("slices " + std::to_string(slices) + " stacks " + std::to_string(stacks));
      cylinder::Params p;
      p.slices = slices;
      p.stacks = stacks;
      p.coords = cylinder::Coords::Right;
      ts::Mesh m = cylinder::mesh(p);
      ASSERT_EQ(m.nu, slices);
      for (int j = 0; j <= stacks; ++j) {
        const auto& a = m.points[size_t(m.at(0, j))].pos;
        const auto& b = m.points[size_t(m.at(slices, j))].pos;
        EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "seam column differs at row " << j;
      }
      // In the drawn batch, every occurrence of one position is the same
      // bits: no two vertices are within round-off of each other but unequal.
      ts::Batch b = ts::meshBatch(m, 0);
      for (size_t u = 0; u < b.vertices.size(); ++u)
        for (size_t v = u + 1; v < b.vertices.size(); ++v) {
          const glm::vec3 &x = b.vertices[u].pos, &y = b.vertices[v].pos;
          if (glm::length(x - y) < 1e-4f) ASSERT_EQ(std::memcmp(&x, &y, sizeof x), 0) << u << " vs " << v;
        }
      // And the seam column still carries its own s: 1 + s_0 (right).
      EXPECT_DOUBLE_EQ(m.st[size_t(m.at(slices, 0))].x, m.st[size_t(m.at(0, 0))].x + 1.0);
    }
}

// Negative control: computing the seam column from θ = θ0 + 360° (the
// unwrapped index) instead gives a point within round-off of column 0 but
// not the same bits: sin(-36°) and sin(324°) differ in the last place.  (So
// the memcmp above is a real check.)
TEST(CylinderSeam, NegativeControlSeamColumnFrom360DegreesIsNotBitIdentical) {
  cylinder::Params p;  // the book's 5 slices, θ0 = -36°
  int differ = 0;
  for (int j = 0; j <= p.stacks; ++j) {
    ts::SurfacePoint a = ts::cylinderPoint(p.r, p.h, p.slices, p.stacks, 0, j, cylinder::theta0Deg(p.slices));
    ts::SurfacePoint b = ts::cylinderPoint(p.r, p.h, p.slices, p.stacks, p.slices, j, cylinder::theta0Deg(p.slices));
    EXPECT_LT(glm::length(a.pos - b.pos), 1e-12) << "the same point up to round-off";
    differ += std::memcmp(&a.pos, &b.pos, sizeof a.pos) != 0;
  }
  EXPECT_EQ(differ, p.stacks + 1) << "θ = 324° computed as -36° + 360° should not round to sin(-36°)'s bits";
}

// Claim, read off the displayed figure itself: in the cylinder panel the
// middle of the front patch's chord (θ = 0, mid-height) shows s = 0.5 — the
// middle of the texture, not its edge — with s reduced per vertex, and s = 1
// (the seam, column J meets A) with the winding tracked.  A quarter of the
// way from x to y it shows 0.9 - 0.8/4 = 0.7 and 0.9 + 0.2/4 = 0.95.
// Perspective-correct interpolation gives these exactly at the projected
// chord points; one pixel moves s by about 0.005 here, so 0.01 is allowed.
TEST(CylinderSeam, DisplayedFrontPatchShowsTheAssignedRegion) {
  for (const char* c : {"wrong", "right"}) {
    SCOPED_TRACE(c);
    const bool wrong = std::string(c) == "wrong";
    Demo demo("cylinder_seam", {"--coords", c});
    ts::Frame f = demo.frame(1024, 512);
    const ts::Panel& p = panelOf(f, std::string("cylinder_") + c);
    ts::Image img = renderTexelIndex(f);
    cylinder::Params cp;
    auto screenOf = [&](double along) {
      // The point of the chord from θ = -36° to θ = 36° at fraction `along`.
      glm::dvec3 a = cylinder::point(cp.r, -36.0, 0.0), b = cylinder::point(cp.r, 36.0, 0.0);
      glm::dvec3 q = a + along * (b - a);
      return ts::panelToPixels(p, p.projection * p.modelview * glm::vec4(glm::vec3(q), 1.0f));
    };
    double mid = sAt(img, screenOf(0.5)), quarter = sAt(img, screenOf(0.25));
    if (wrong) {
      EXPECT_NEAR(mid, 0.5, 0.01);
      EXPECT_NEAR(quarter, 0.7, 0.01);
    } else {
      EXPECT_LT(wrapDist(mid, 1.0), 0.01);
      EXPECT_NEAR(quarter, 0.95, 0.01);
    }
    // Left of the middle shows larger s than right of it when reversed.
    glm::vec2 l = screenOf(0.4), r = screenOf(0.6);
    double sl = sAt(img, l), sr = sAt(img, r);
    if (wrong) EXPECT_GT(sl, sr);
    else EXPECT_GT(sr + (sr < 0.5 ? 1.0 : 0.0), sl);  // 0.98 -> 1.02 read as 0.98 -> 0.02
  }
}

// Claim: the texture-space panel shades the intended region — s in
// [0.9, 1] and [0, 0.1], drawn wrapping — and nothing in between: compared
// with the panel drawn without the overlays, pixels in the two strips turn
// closer to the overlay's green and pixels in the middle (away from the red outline, hatching and
// arrow) are unchanged.
TEST(CylinderSeam, TextureSpaceShowsTheIntendedRegionWrapping) {
  // The panel without the overlays: the same frame with only the texture's
  // batch kept (--patch=off also drops the colours' key, and with it the
  // room the layout kept for it, so its panel would sit elsewhere).
  Demo on("cylinder_seam", {"--coords", "wrong"});
  ts::Frame fa = on.frame(1024, 512), fb = fa;
  for (ts::Panel& p : fb.panels)
    if (p.id == "texture_space")
      p.batches.erase(std::remove_if(p.batches.begin(), p.batches.end(),
                                     [](const ts::Batch& b) { return b.role != "texture"; }),
                      p.batches.end());
  ts::Image a = ts::test::renderer().render(fa, false), b = ts::test::renderer().render(fb, false);
  const ts::Rect vp = panelOf(fa, "texture_space").viewport;
  ASSERT_EQ(vp.w, vp.h);
  long greener = 0, strip = 0, changedInside = 0, inside = 0;
  auto toGreen = [](ts::Rgba c) {  // distance to the overlay's green (0.2, 0.85, 0.3)
    return std::hypot(c.r - 51.0, c.g - 216.75, c.b - 76.5);
  };
  for (int y = vp.y + 8; y < vp.y + vp.h - 8; ++y)
    for (int x = vp.x; x < vp.x + vp.w; ++x) {
      double s = (x + 0.5 - vp.x) / vp.w, t = 1.0 - (y + 0.5 - vp.y) / vp.h;
      if (std::abs(t - 0.5) < 0.05) continue;  // the arrow
      ts::Rgba pa = a.at(x, y), pb = b.at(x, y);
      if ((s > 0.91 && s < 0.99) || (s > 0.01 && s < 0.09)) {
        ++strip;
        greener += toGreen(pa) < 0.7 * toGreen(pb);  // a 45% blend leaves 55% of the distance
      }
      // Inside the red region, away from its outline and the hatch lines
      // (which lean across each tenth), nothing is drawn over the texture.
      double u = (s - 0.15) / 0.1 - std::floor((s - 0.15) / 0.1);
      if (s > 0.13 && s < 0.87 && std::abs(u - (t * 0.5)) > 0.12 && std::abs(u - (t * 0.5) - 1) > 0.12 &&
          std::abs(u - (t * 0.5) + 1) > 0.12) {
        ++inside;
        changedInside += !ts::probe::close(pa, pb, ts::probe::tolerance(8));
      }
    }
  EXPECT_GT(strip, 1000);
  EXPECT_EQ(greener, strip) << "every pixel of the two strips should be shaded green";
  EXPECT_GT(inside, 10000);
  EXPECT_EQ(changedInside, 0);
}

// Claim: bad values of the demo's own flags are one clear error each.
TEST(CylinderSeam, BadFlagsAreErrors) {
  for (std::vector<std::string> bad : {std::vector<std::string>{"--slices", "2"},
                                       {"--slices", "37"},
                                       {"--coords", "fixed"},
                                       {"--seam", "side"},
                                       {"--turn", "400"}}) {
    SCOPED_TRACE(bad[0] + " " + bad[1]);
    std::unique_ptr<ts::Scene> s = ts::makeScene("cylinder_seam");
    ts::Options o;
    s->addOptions(o);
    EXPECT_THROW(o.parse(bad), ts::Error);
  }
}
}  // namespace
