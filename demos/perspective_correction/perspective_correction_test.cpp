// demos/perspective_correction/perspective_correction_test.cpp — Figure VI.2 (hyperbolic
// interpolation), rendered offscreen and probed against the mathematics of
// demos/perspective_correction/perspective_correction_math.hpp, never against a stored
// image:
//   * perspective panel: (s,t) of the ray through the pixel centre meeting
//     the plane (ray-plane intersection);
//   * affine panel: (s,t) interpolated with the screen-space barycentric
//     coordinates of the projected triangle.
// Geometry: in a panel (viewport in image pixels, top-left origin) pixel
// (x, y) has NDC x = 2 (x + 0.5 - vx)/w - 1, y = 1 - 2 (y + 0.5 - vy)/h.
// The checkerboard is 256 texels with 8 checks per side (32 texels a check).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/core/image.hpp"
#include "common/core/probe.hpp"
#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "demos/perspective_correction/perspective_correction_math.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/scene_test.hpp"

namespace {
constexpr int kTexels = persp::kTexels, kChecks = persp::kChecks;
const ts::Rgba kA{32, 32, 32, 255}, kB{224, 224, 224, 255};  // checkerboard()'s colours
// Pixels whose (s,t) is closer than this to a check edge (or to the square's
// edge) are not probed.
constexpr double kMarginTexels = 1.5;
constexpr int kW = 1024, kH = 380;  // the book figure's size

int tol() { return ts::probe::tolerance(8); }

using ts::test::Demo;
using ts::test::value;

using ts::test::panelOf;

glm::dvec2 ndcOf(const ts::Rect& vp, int x, int y) {
  return {2.0 * (x + 0.5 - vp.x) / vp.w - 1.0, 1.0 - 2.0 * (y + 0.5 - vp.y) / vp.h};
}

double edgeDistanceTexels(glm::dvec2 st) {
  const double check = double(kTexels) / kChecks;
  auto d = [&](double c) {
    double u = c * kTexels;
    return std::abs(u - check * std::round(u / check));  // includes s = 0 and s = 1
  };
  return std::min(d(st.x), d(st.y));
}

using Map = std::function<glm::dvec2(glm::dvec2)>;  // NDC -> (s, t)
Map perspectiveMap(const persp::View& v) {
  return [v](glm::dvec2 xy) { return persp::perspectiveST(v, xy); };
}
Map affineMap(const persp::View& v) {
  return [v](glm::dvec2 xy) { return persp::affineST(v, xy); };
}

// Probes every pixel of the panel whose analytic (s,t) lies inside the
// square, kMarginTexels from any check edge, against the checker colour.
ts::probe::Result probePanel(const ts::Image& img, const ts::Rect& vp, const Map& map) {
  ts::probe::Result r;
  for (int y = vp.y; y < vp.y + vp.h; ++y)
    for (int x = vp.x; x < vp.x + vp.w; ++x) {
      glm::dvec2 st = map(ndcOf(vp, x, y));
      if (st.x < 0 || st.y < 0 || st.x > 1 || st.y > 1 || edgeDistanceTexels(st) < kMarginTexels) continue;
      ts::Rgba want = ts::checkerAt(kTexels, kChecks, kA, kB, st.x, st.y), got = img.at(x, y);
      ++r.checked;
      if (!ts::probe::close(got, want, tol()) && r.failed++ == 0)
        r.firstX = x, r.firstY = y, r.firstGot = got, r.firstWant = want;
    }
  return r;
}

struct BookView {
  ts::Frame frame;
  ts::Image image;
  persp::Setup setup;
  const ts::Rect& vp(const char* id) const { return panelOf(frame, id).viewport; }
  persp::View view(const char* id) const {
    const ts::Rect& r = vp(id);
    return persp::makeView(setup, double(r.w) / r.h);
  }
};
BookView renderBook(double tilt, double distance) {
  char t[32], d[32];
  std::snprintf(t, sizeof t, "%g", tilt);
  std::snprintf(d, sizeof d, "%g", distance);
  Demo demo("perspective_correction", {"--view", "both", "--filter", "nearest", "--tilt", t, "--distance", d});
  BookView b;
  b.image = demo.render(kW, kH, &b.frame);
  b.setup = {tilt, distance};
  return b;
}

// Claim (precondition): the book view shows the 256-texel, 8-check
// checkerboard in two panels, left made from CPU-projected vertices with
// w = 1 and identity matrices, right through GL's projection of the plane
// (the matrices of perspective_correction_math.hpp) under GL_NICEST.
TEST(VI2, BookViewIsTheTwoVariantsOfOneSquare) {
  BookView b = renderBook(60, 1.5);
  const ts::Panel &a = panelOf(b.frame, "affine"), &p = panelOf(b.frame, "perspective");
  EXPECT_EQ(b.frame.perspectiveHint, GLenum(GL_NICEST));
  EXPECT_LT(a.viewport.x, p.viewport.x) << "without (affine) is on the left, as in the book";
  for (const ts::Panel* q : {&a, &p}) {
    ASSERT_FALSE(q->batches.empty());
    const ts::Batch& s = q->batches[0];
    ASSERT_EQ(s.vertices.size(), 6u) << "one quad, two triangles";
    EXPECT_EQ(b.frame.textures.at(size_t(s.texture)).key(), ts::checkerboard(kTexels, kChecks).key());
    EXPECT_EQ(b.frame.textures.at(size_t(s.texture)).magFilter, GLenum(GL_NEAREST));
  }
  EXPECT_EQ(a.projection, glm::mat4(1.0f));
  EXPECT_EQ(a.modelview, glm::mat4(1.0f));
  persp::View pv = b.view("perspective");
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(p.projection[c][r], pv.proj[c][r], 1e-5);
      EXPECT_NEAR(p.modelview[c][r], pv.mv[c][r], 1e-6);
    }
  // Vertex k of the affine batch is the perspective batch's vertex k, projected.
  for (size_t k = 0; k < 6; ++k) {
    glm::dvec4 c = pv.proj * pv.mv * glm::dvec4(glm::dvec3(p.batches[0].vertices[k].pos), 1.0);
    glm::dvec3 ndc = glm::dvec3(c) / c.w;
    EXPECT_NEAR(a.batches[0].vertices[k].pos.x, ndc.x, 1e-5);
    EXPECT_NEAR(a.batches[0].vertices[k].pos.y, ndc.y, 1e-5);
    EXPECT_EQ(a.batches[0].vertices[k].tex, p.batches[0].vertices[k].tex);
  }
  Demo affineOnly("perspective_correction", {"--view", "affine"});
  EXPECT_EQ(affineOnly.frame(800, 480).perspectiveHint, GLenum(GL_FASTEST)) << "the book's 'without' call";
}

// Claim: the right panel is perspective-correct: every probed pixel has the
// colour of the (s,t) where its ray meets the plane.  The left panel is
// screen-linear: every probed pixel has the colour of the projected
// triangle's barycentric (s,t).  Checked at the book's state and at a mild
// and a steep one.
TEST(VI2, PanelsMatchTheirAnalyticMaps) {
  for (auto [tilt, dist] : {std::pair{60.0, 1.5}, {30.0, 3.0}, {80.0, 1.25}}) {
    SCOPED_TRACE("tilt " + std::to_string(tilt) + " distance " + std::to_string(dist));
    BookView b = renderBook(tilt, dist);
    for (const char* id : {"perspective", "affine"}) {
      SCOPED_TRACE(id);
      persp::View v = b.view(id);
      ts::probe::Result r = probePanel(b.image, b.vp(id), id[0] == 'p' ? perspectiveMap(v) : affineMap(v));
      EXPECT_TRUE(r.ok()) << r.describe();
      EXPECT_GT(r.checked, 5000) << "too few pixels probed";
    }
  }
}

// Negative control: each panel checked against the other's map fails many
// probes at the book's state — the probes can tell the two apart.
TEST(VI2, EachPanelFailsTheOtherMapNegativeControl) {
  BookView b = renderBook(60, 1.5);
  ts::probe::Result ra = probePanel(b.image, b.vp("affine"), perspectiveMap(b.view("affine")));
  ts::probe::Result rp = probePanel(b.image, b.vp("perspective"), affineMap(b.view("perspective")));
  EXPECT_GT(ra.failed, ra.checked / 5) << ra.describe();
  EXPECT_GT(rp.failed, rp.checked / 5) << rp.describe();
}

// Fraction of the projected square's pixels whose colour differs between the
// affine and the perspective panel (same size, same framing).
double differingFraction(const BookView& b) {
  const ts::Rect &a = b.vp("affine"), &p = b.vp("perspective");
  EXPECT_EQ(a.w, p.w);
  EXPECT_EQ(a.h, p.h);
  persp::View v = b.view("perspective");
  long inside = 0, differ = 0;
  for (int y = 0; y < p.h; ++y)
    for (int x = 0; x < p.w; ++x) {
      if (!persp::insideProjected(v, ndcOf(p, p.x + x, p.y + y))) continue;
      ++inside;
      differ += !ts::probe::close(b.image.at(a.x + x, a.y + y), b.image.at(p.x + x, p.y + y), tol());
    }
  EXPECT_GT(inside, 10000);
  return double(differ) / double(std::max(1L, inside));
}

// Claim (the book's rule of thumb): the two images differ in many pixels
// when (d2 - d1)/d1 >= 1 and in few when it is <= 0.05.  Measured (llvmpipe,
// 1024x380): 44% of the square's pixels at ratios 1.03..2.24; at <= 0.05,
// 0% (tilt 0: equal depths), 1.9% (tilt 10, distance 32) and 8.1% (tilt 20,
// distance 16: the error is 3.9 texels, 1.5% of the square, and the framing
// makes the square fill the panel, so check edges move by up to ~7 px).
// "Almost none" is therefore asserted as: under a tenth of the square, and
// under a quarter of the smallest fraction seen at ratio >= 1.
TEST(VI2, ImagesDifferWhenTheDistanceRatioIsLarge) {
  struct Case {
    double tilt, dist;
    bool large;
  } cases[] = {{60, 1.5, true}, {40, 1.5, true}, {80, 3.0, true}, {20, 16, false}, {10, 32, false}, {0, 8, false}};
  double smallestLarge = 1, largestSmall = 0;
  for (const Case& c : cases) {
    BookView b = renderBook(c.tilt, c.dist);
    double ratio = persp::distances(b.setup).ratio(), frac = differingFraction(b);
    std::printf("[ info ] tilt %g distance %g: (d2-d1)/d1 = %.3f, %.2f%% of the square's pixels differ\n", c.tilt,
                c.dist, ratio, 100 * frac);
    if (c.large) {
      EXPECT_GE(ratio, 1.0);
      EXPECT_GT(frac, 0.3) << "tilt " << c.tilt << " distance " << c.dist;
      smallestLarge = std::min(smallestLarge, frac);
    } else {
      EXPECT_LE(ratio, 0.05);
      EXPECT_LT(frac, 0.1) << "tilt " << c.tilt << " distance " << c.dist;
      largestSmall = std::max(largestSmall, frac);
    }
  }
  EXPECT_LT(largestSmall, smallestLarge / 4);
}

// Claim (the measurement): from the texel-index render the affine image's
// largest (s,t) error matches the analytic value at the same pixels (within
// the index texture's 1/8 texel), the hyperbolic render took the analytic
// texel (within one texel of 2048), and (d1, d2) are the square's nearest
// and farthest distances (checked here by brute force over the square).
TEST(VI2, MeasuredErrorMatchesTheAnalyticError) {
  Demo demo("perspective_correction", {"--tilt", "60", "--distance", "1.5"});
  ts::Measurements m = demo.measure();
  persp::Setup s{60, 1.5};
  double d1 = 1e9, d2 = 0;
  for (int j = 0; j <= 400; ++j)
    for (int i = 0; i <= 400; ++i) {
      double r = glm::length(persp::eyePoint(s, {-1 + i / 200.0, -1 + j / 200.0}));
      d1 = std::min(d1, r), d2 = std::max(d2, r);
    }
  EXPECT_NEAR(value(m, "d1"), d1, 1e-4);
  EXPECT_NEAR(value(m, "d2"), d2, 1e-9);
  EXPECT_NEAR(value(m, "d_ratio"), (d2 - d1) / d1, 1e-3);
  EXPECT_NEAR(value(m, "affine_error_texels"), value(m, "affine_error_predicted"), 0.5);
  EXPECT_GT(value(m, "affine_error_texels"), 3.0 * kTexels / kChecks) << "over three checks at the book's state";
  EXPECT_LE(value(m, "perspective_error_index"), 1.0);
  EXPECT_NEAR(value(m, "sweep_t60_error_texels"), value(m, "affine_error_texels"), 1e-9);
}

// Claim (the rule of thumb, measured): over the sweep of tilts the measured
// error follows the analytic one, is zero at tilt 0 (the square faces the
// eye: every depth is equal, so screen-linear is exact although
// (d2 - d1)/d1 = 0.37), and grows with tilt and with (d2 - d1)/d1; from
// (d2 - d1)/d1 >= 1 it exceeds two checks.
TEST(VI2, SweepFollowsTheRuleOfThumb) {
  Demo demo("perspective_correction", {"--distance", "1.5"});
  ts::Measurements m = demo.measure();
  double lastRatio = -1, lastError = -1;
  for (int tilt = 0; tilt <= 80; tilt += 10) {
    char key[32];
    std::snprintf(key, sizeof key, "sweep_t%02d", tilt);
    std::string k = key;
    double ratio = value(m, k + "_d_ratio"), err = value(m, k + "_error_texels");
    EXPECT_NEAR(ratio, persp::distances({double(tilt), 1.5}).ratio(), 1e-9);
    EXPECT_NEAR(err, value(m, k + "_predicted"), 0.5) << k;
    EXPECT_GT(ratio, lastRatio) << k;
    EXPECT_GT(err, lastError) << k;
    if (ratio >= 1) EXPECT_GT(err, 2.0 * kTexels / kChecks) << k;
    lastRatio = ratio, lastError = err;
  }
  EXPECT_LT(value(m, "sweep_t00_error_texels"), 0.25) << "tilt 0: equal depths, no error but quantisation";
  EXPECT_NEAR(value(m, "sweep_t00_d_ratio"), (std::sqrt(1.5 * 1.5 + 2) - 1.5) / 1.5, 1e-9);
}

// Claim: the measurement can fail — at a far distance and a small tilt
// ((d2 - d1)/d1 <= 0.05) the same measurement reports an error under a
// tenth of the book state's, and the hyperbolic render measured the same
// way (hint_fastest_error_texels: GL's own projection) is within the index
// texture's quantisation of zero.
TEST(VI2, SmallRatioGivesSmallErrorNegativeControl) {
  Demo book("perspective_correction", {"--tilt", "60", "--distance", "1.5"});
  Demo far("perspective_correction", {"--tilt", "20", "--distance", "16"});
  ts::Measurements mb = book.measure(), mf = far.measure();
  EXPECT_LE(value(mf, "d_ratio"), 0.05);
  EXPECT_LT(value(mf, "affine_error_texels"), 0.1 * value(mb, "affine_error_texels"));
  EXPECT_NEAR(value(mf, "affine_error_texels"), value(mf, "affine_error_predicted"), 0.5);
  EXPECT_LT(value(mb, "hint_fastest_error_texels"), 0.25);
}

// Claim: the demo detects whether the driver honours the hint by rendering
// both and comparing, and says so in the figure.  Mesa (llvmpipe and
// softpipe) ignores it (docs/platform.md): 0 pixels differ.
TEST(VI2, HintDetectionIsReportedOnScreen) {
  Demo demo("perspective_correction", {"--tilt", "60", "--distance", "1.5"});
  ts::Measurements m = demo.measure();
  const double differ = value(m, "hint_pixels_differing");
  EXPECT_EQ(value(m, "hint_honoured"), differ > 0 ? 1.0 : 0.0);
  std::string renderer = ts::test::rendererString();
  if (renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos)
    EXPECT_EQ(differ, 0.0) << renderer << " was measured to ignore the hint";
  ts::Frame f = demo.frame(kW, kH);
  std::string driver = renderer.substr(0, renderer.find(' '));
  bool said = false;
  for (const auto& l : f.labels)
    said |= l.text.find(driver + (differ > 0 ? " honours" : " ignores") + " GL_PERSPECTIVE_CORRECTION_HINT") == 0;
  EXPECT_TRUE(said) << "no label says whether " << driver << " honours the hint";
}

// Claim: the plot figure draws the measured sweep where the measurement put
// it: one cross per tilt, centred on ((d2 - d1)/d1, error), in the cross
// colour, on the analytic curve, with the rule-of-thumb line at 1.
TEST(VI2, PlotShowsTheMeasuredSweep) {
  Demo demo("perspective_correction", {"--view", "plot", "--distance", "1.5", "--tilt", "60"});
  ts::Measurements m = demo.measure();
  ts::Frame f;
  ts::Image img = demo.render(1024, 560, &f);
  const ts::Panel& p = panelOf(f, "plot");
  const ts::Batch* crosses = nullptr;
  for (const auto& b : p.batches)
    if (b.role == "measured") crosses = &b;
  ASSERT_NE(crosses, nullptr);
  ASSERT_EQ(crosses->vertices.size(), 9u * 4u) << "nine tilts, two segments each";
  for (int k = 0; k < 9; ++k) {
    char key[32];
    std::snprintf(key, sizeof key, "sweep_t%02d", 10 * k);
    glm::vec2 c = (glm::vec2(crosses->vertices[size_t(4 * k)].pos) +
                   glm::vec2(crosses->vertices[size_t(4 * k + 1)].pos)) /
                  2.0f;
    EXPECT_NEAR(c.x, value(m, std::string(key) + "_d_ratio"), 1e-4) << key;
    EXPECT_NEAR(c.y, value(m, std::string(key) + "_error_texels"), 1e-3) << key;
    // The cross colour is at its centre, or within a pixel of it: the
    // analytic curve passes through the centre too, and which line wins the
    // centre pixel is the rasterizer's choice (softpipe gives it the curve).
    glm::vec2 at = ts::panelToPixels(p, p.projection * glm::vec4(c, 0, 1));
    bool crossColour = false;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        crossColour |= ts::probe::close(img.at(int(at.x) + dx, int(at.y) + dy), {255, 191, 77, 255}, 8);
    EXPECT_TRUE(crossColour) << key << " at " << at.x << "," << at.y;
  }
}
}  // namespace
