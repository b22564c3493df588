// demos/quad_distortion/vi1_quad_distortion_test.cpp — Figure VI.1 (quad distortion),
// rendered offscreen and checked the way conformance suites check pictures:
// probe pixels whose correct colour is known from the mathematics
// (demos/quad_distortion/quad_distortion_math.hpp) with a tolerance from the channel
// bits, never against a stored image.
//
// Geometry used throughout: in a panel (viewport in image pixels, top-left
// origin) pixel (x, y) has its centre at a = (x + 0.5 - vx) / w and
// b = 1 - (y + 0.5 - vy) / h, the square's coordinates with b up.  The
// checkerboard is 256 texels with 8 checks per side (32 texels a check).
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "common/core/image.hpp"
#include "common/core/probe.hpp"
#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "demos/quad_distortion/quad_distortion_math.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using quad::Corners;
using quad::Diagonal;

constexpr double kPi = 3.14159265358979323846;
constexpr int kTexels = 256, kChecks = 8;
const ts::Rgba kA{32, 32, 32, 255}, kB{224, 224, 224, 255};  // checkerboard()'s colours
const Corners kBook{glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0.75, 0.75), glm::dvec2(0, 1)};
// Pixels whose (s,t) is closer than this to a check edge are not probed.
constexpr double kMarginTexels = 1.5;

int tol() { return ts::probe::tolerance(8); }
double deg(double rad) { return rad * 180.0 / kPi; }

using Map = std::function<glm::dvec2(glm::dvec2)>;
Map affineMap(const Corners& st, Diagonal d) {
  quad::Split s = quad::split(st, d);
  return [s, d](glm::dvec2 p) { return s.at(p, d)(p); };
}
Map bilinearMap(const Corners& st) {
  return [st](glm::dvec2 p) { return quad::bilinear(st, p); };
}
Map projectiveMap(const Corners& st) {
  glm::dmat3 H = quad::homography(st);
  return [H](glm::dvec2 p) { return quad::projective(H, p); };
}

using ts::test::Demo;
using ts::test::value;

glm::dvec2 panelPoint(const ts::Rect& vp, int x, int y) {
  return {(x + 0.5 - vp.x) / vp.w, 1.0 - (y + 0.5 - vp.y) / vp.h};
}
// Distance, in texels, from (s,t) to the nearest check edge.
double edgeDistanceTexels(glm::dvec2 st) {
  const double check = double(kTexels) / kChecks;
  auto d = [&](double c) {
    double u = c * kTexels;
    return std::abs(u - check * std::round(u / check));
  };
  return std::min(d(st.x), d(st.y));
}

// Probes every pixel of the panel whose analytic (s,t) is at least
// kMarginTexels from a check edge against the checker colour there.
ts::probe::Result probePanel(const ts::Image& img, const ts::Rect& vp, const Map& map,
                             const std::function<bool(int, int)>& skip = nullptr) {
  ts::probe::Result r;
  for (int y = vp.y; y < vp.y + vp.h; ++y)
    for (int x = vp.x; x < vp.x + vp.w; ++x) {
      glm::dvec2 st = map(panelPoint(vp, x, y));
      if (edgeDistanceTexels(st) < kMarginTexels) continue;
      if (skip && skip(x, y)) continue;
      ts::Rgba want = ts::checkerAt(kTexels, kChecks, kA, kB, st.x, st.y), got = img.at(x, y);
      ++r.checked;
      if (!ts::probe::close(got, want, tol()) && r.failed++ == 0)
        r.firstX = x, r.firstY = y, r.firstGot = got, r.firstWant = want;
    }
  return r;
}

using ts::test::panelOf;

// Renders the book view (1024x512, the demo's default size) in one state and
// probes its screen-space panel against `map`.
ts::probe::Result checkScreenSpace(const std::vector<std::string>& flags, const Map& map) {
  Demo demo("quad_distortion", flags);
  ts::Frame f;
  ts::Image img = demo.render(1024, 512, &f);
  const ts::Rect vp = panelOf(f, "screen_space").viewport;
  ts::probe::Result r = probePanel(img, vp, map);
  // Most of the square is check interior: a probe that checks little is no test.
  EXPECT_GT(r.checked, long(0.6 * vp.w * vp.h)) << "only " << r.checked << " pixels probed";
  return r;
}

// Claim (precondition of every probe below): the demo maps the 256-texel,
// 8-check checkerboard on both panels, and --filter sets its filters.
TEST(VI1, MapsThe256TexelCheckerboard) {
  Demo demo("quad_distortion", {"--filter", "nearest"});
  ts::Frame f;
  demo.render(1024, 512, &f);
  for (const char* id : {"texture_space", "screen_space"}) {
    const ts::Panel& p = panelOf(f, id);
    ASSERT_FALSE(p.batches.empty()) << id;
    ASSERT_GE(p.batches[0].texture, 0) << id;
    const ts::TextureDesc& t = f.textures.at(size_t(p.batches[0].texture));
    EXPECT_EQ(t.name, "checkerboard");
    EXPECT_EQ(t.key(), ts::checkerboard(kTexels, kChecks).key());
    EXPECT_EQ(t.magFilter, GLenum(GL_NEAREST));
    // Square panels (the probes assume a and b scale alike).
    EXPECT_EQ(p.viewport.w, p.viewport.h);
    EXPECT_GT(p.viewport.w, 300);
  }
  Demo linear("quad_distortion", {"--filter", "linear"});
  ts::Frame g = linear.frame(1024, 512);
  EXPECT_EQ(g.textures.at(0).magFilter, GLenum(GL_LINEAR));
}

// Claim: split along the book's diagonal (tl-br), each triangle shows the
// texture through its own affine map: every probed pixel has the colour the
// triangle's map predicts.
TEST(VI1, AffineTlBrMatchesTheTrianglesMaps) {
  ts::probe::Result r = checkScreenSpace({"--diagonal", "tl-br", "--interp", "affine", "--filter", "nearest"},
                                         affineMap(kBook, Diagonal::TopLeftBottomRight));
  EXPECT_TRUE(r.ok()) << r.describe();
}

// Claim: the same for the other diagonal (bl-tr) with its own two maps.
TEST(VI1, AffineBlTrMatchesTheTrianglesMaps) {
  ts::probe::Result r = checkScreenSpace({"--diagonal", "bl-tr", "--interp", "affine", "--filter", "nearest"},
                                         affineMap(kBook, Diagonal::BottomLeftTopRight));
  EXPECT_TRUE(r.ok()) << r.describe();
}

// Claim: with linear filtering the check interiors are unchanged (a 2x2
// texel footprint inside one check has one colour).
TEST(VI1, AffineWithLinearFilterMatchesInCheckInteriors) {
  ts::probe::Result r = checkScreenSpace({"--diagonal", "tl-br", "--interp", "affine", "--filter", "linear"},
                                         affineMap(kBook, Diagonal::TopLeftBottomRight));
  EXPECT_TRUE(r.ok()) << r.describe();
}

// Claim: the bilinear variant (GLSL) shows (s,t) interpolated bilinearly over
// the quad, whichever diagonal the triangles use.
TEST(VI1, BilinearMatchesBilinearInterpolation) {
  for (const char* d : {"tl-br", "bl-tr"}) {
    SCOPED_TRACE(d);
    ts::probe::Result r = checkScreenSpace({"--diagonal", d, "--interp", "bilinear", "--filter", "nearest"},
                                           bilinearMap(kBook));
    EXPECT_TRUE(r.ok()) << r.describe();
  }
}

// Claim: the projective variant, (sq, tq, 0, q) per vertex, shows the
// homography that sends the square onto the quad.
TEST(VI1, ProjectiveMatchesTheHomography) {
  for (const char* d : {"tl-br", "bl-tr"}) {
    SCOPED_TRACE(d);
    ts::probe::Result r = checkScreenSpace({"--diagonal", d, "--interp", "projective", "--filter", "nearest"},
                                           projectiveMap(kBook));
    EXPECT_TRUE(r.ok()) << r.describe();
  }
}

// Claim: the compare view (the vi1_quad_variants figure's layout: panels not
// centred vertically, so a flipped viewport would show) draws the four
// variants left to right: tl-br triangles, bl-tr triangles, bilinear,
// projective, each matching its own analytic map.
TEST(VI1, CompareViewShowsTheFourMaps) {
  Demo demo("quad_distortion", {"--view", "compare", "--filter", "nearest"});
  ts::Frame f;
  ts::Image img = demo.render(1280, 420, &f);
  const Map maps[4] = {affineMap(kBook, Diagonal::TopLeftBottomRight), affineMap(kBook, Diagonal::BottomLeftTopRight),
                       bilinearMap(kBook), projectiveMap(kBook)};
  for (int k = 0; k < 4; ++k) {
    SCOPED_TRACE("variant_" + std::to_string(k));
    const ts::Rect vp = panelOf(f, "variant_" + std::to_string(k)).viewport;
    ASSERT_EQ(vp.w, vp.h);
    ts::probe::Result r = probePanel(img, vp, maps[k]);
    EXPECT_TRUE(r.ok()) << r.describe();
    EXPECT_GT(r.checked, long(0.5 * vp.w * vp.h));
    // And not the next variant's map (each differs from its neighbour).
    EXPECT_GT(probePanel(img, vp, maps[(k + 1) % 4]).failed, 200);
  }
}

// Claim: the choice of diagonal matters, and the probes can tell: the tl-br
// render checked against the bl-tr maps (and vice versa) fails many probes,
// the bilinear map fails against the affine render, and the two renders
// differ in about as many pixels as their analytic maps' colours do.
TEST(VI1, DiagonalChoiceChangesThePictureNegativeControl) {
  Demo tlbr("quad_distortion", {"--diagonal", "tl-br", "--filter", "nearest"});
  Demo bltr("quad_distortion", {"--diagonal", "bl-tr", "--filter", "nearest"});
  ts::Frame f;
  ts::Image a = tlbr.render(1024, 512, &f), b = bltr.render(1024, 512);
  const ts::Rect vp = panelOf(f, "screen_space").viewport;
  Map mapA = affineMap(kBook, Diagonal::TopLeftBottomRight), mapB = affineMap(kBook, Diagonal::BottomLeftTopRight);
  for (auto [img, wrong, name] :
       {std::tuple{&a, &mapB, "tl-br render vs bl-tr map"}, std::tuple{&b, &mapA, "bl-tr render vs tl-br map"}}) {
    ts::probe::Result r = probePanel(*img, vp, *wrong);
    EXPECT_GT(r.failed, r.checked / 20) << name << ": " << r.describe();
  }
  EXPECT_GT(probePanel(a, vp, bilinearMap(kBook)).failed, 1000);

  // Pixels that differ between the renders vs pixels where the two analytic
  // maps give different check colours.
  long differ = 0, predicted = 0, pixels = long(vp.w) * vp.h;
  for (int y = vp.y; y < vp.y + vp.h; ++y)
    for (int x = vp.x; x < vp.x + vp.w; ++x) {
      differ += !ts::probe::close(a.at(x, y), b.at(x, y), tol());
      glm::dvec2 p = panelPoint(vp, x, y), sa = mapA(p), sb = mapB(p);
      predicted += ts::checkerAt(kTexels, kChecks, kA, kB, sa.x, sa.y) !=
                   ts::checkerAt(kTexels, kChecks, kA, kB, sb.x, sb.y);
    }
  EXPECT_GT(differ, pixels / 10) << "the diagonals should give visibly different pictures";
  EXPECT_NEAR(double(differ), double(predicted), 0.02 * pixels) << differ << " differ, " << predicted << " predicted";
  // Outside the screen-space panel (the texture view aside) nothing else moves.
  const ts::Rect tv = panelOf(f, "texture_space").viewport;
  long elsewhere = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (!vp.contains(x, y) && !tv.contains(x, y)) elsewhere += a.at(x, y) != b.at(x, y);
  EXPECT_EQ(elsewhere, 0);
}

// Claim (the figure's measurement): the kink measured from a texel-index
// render is, for the book's corners, atan(1/3) = 18.43 deg with the tl-br
// split and atan(1/4) = 14.04 deg with bl-tr, each within 0.2 deg of the
// prediction; bilinear and projective have no kink (< 0.5 deg); every
// variant took the texel the analytic map says, within one texel of 2048.
TEST(VI1, MeasuredKinkMatchesThePrediction) {
  Demo demo("quad_distortion", {"--view", "compare"});
  ts::Measurements m = demo.measure();
  const double tlbr = deg(std::atan(1.0 / 3.0)), bltr = deg(std::atan(0.25));
  EXPECT_NEAR(value(m, "kink_predicted_deg[affine_tl_br]"), tlbr, 1e-9);
  EXPECT_NEAR(value(m, "kink_predicted_deg[affine_bl_tr]"), bltr, 1e-9);
  EXPECT_NEAR(value(m, "kink_deg[affine_tl_br]"), value(m, "kink_predicted_deg[affine_tl_br]"), 0.2);
  EXPECT_NEAR(value(m, "kink_deg[affine_tl_br]"), tlbr, 0.2);
  EXPECT_NEAR(value(m, "kink_deg[affine_bl_tr]"), value(m, "kink_predicted_deg[affine_bl_tr]"), 0.2);
  EXPECT_LT(value(m, "kink_deg[bilinear]"), 0.5);
  EXPECT_LT(value(m, "kink_deg[projective]"), 0.5);
  // Predicted from the analytic maps (not a literal): smooth across the
  // diagonal, so no bend beyond the one-sided differences' error.
  EXPECT_LT(value(m, "kink_predicted_deg[bilinear]"), 1e-2);
  EXPECT_LT(value(m, "kink_predicted_deg[projective]"), 1e-2);
  for (const char* v : {"affine_tl_br", "affine_bl_tr", "bilinear", "projective"})
    EXPECT_LE(value(m, std::string("texel_error_max[") + v + "]"), 1.0) << v;
  // Far apart the two triangles' maps put the square's corner (0,0):
  // |(0.25, 0.25)| of the texture = 90.5 texels of 256.
  EXPECT_NEAR(value(m, "split_disagreement_texels"), 256.0 * std::sqrt(0.125), 1e-6);
}

// Claim: the book view measures only the variant it shows, with the same
// numbers as the compare view.
TEST(VI1, BookViewMeasuresItsOwnVariant) {
  Demo demo("quad_distortion", {"--diagonal", "bl-tr"});
  ts::Measurements m = demo.measure();
  EXPECT_NEAR(value(m, "kink_deg[affine_bl_tr]"), deg(std::atan(0.25)), 0.2);
  for (const auto& x : m) EXPECT_EQ(x.name.find("tl_br"), std::string::npos) << x.name;
}

// Claim: when the (s,t) corners form a parallelogram (the identity here, and
// a sheared one) the two triangles share one affine map: no kink with
// either diagonal, and both diagonals draw the same picture.
TEST(VI1, ParallelogramCornersHaveNoKink) {
  const std::pair<const char*, Corners> cases[] = {
      {"0,0 1,0 1,1 0,1", {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)}},
      {"0,0 0.75,0.25 1,1 0.25,0.75",
       {glm::dvec2(0, 0), glm::dvec2(0.75, 0.25), glm::dvec2(1, 1), glm::dvec2(0.25, 0.75)}}};
  for (const auto& [text, st] : cases) {
    SCOPED_TRACE(text);
    Demo demo("quad_distortion", {"--view", "compare", "--corners", text});
    ts::Measurements m = demo.measure();
    for (const char* v : {"affine_tl_br", "affine_bl_tr", "bilinear", "projective"}) {
      EXPECT_LT(value(m, std::string("kink_deg[") + v + "]"), 0.2) << v;
      EXPECT_NEAR(value(m, std::string("kink_predicted_deg[") + v + "]"), 0.0, 1e-5) << v;
      EXPECT_LE(value(m, std::string("texel_error_max[") + v + "]"), 1.0) << v;
    }
    EXPECT_NEAR(value(m, "split_disagreement_texels"), 0.0, 1e-6);

    Demo a("quad_distortion", {"--corners", text, "--diagonal", "tl-br", "--filter", "nearest"});
    Demo b("quad_distortion", {"--corners", text, "--diagonal", "bl-tr", "--filter", "nearest"});
    ts::Frame f;
    ts::Image ia = a.render(1024, 512, &f), ib = b.render(1024, 512);
    const ts::Rect vp = panelOf(f, "screen_space").viewport;
    // Both are the one affine map of the parallelogram...
    Map one = affineMap(st, Diagonal::TopLeftBottomRight);
    ts::probe::Result ra = probePanel(ia, vp, one), rb = probePanel(ib, vp, one);
    EXPECT_TRUE(ra.ok()) << ra.describe();
    EXPECT_TRUE(rb.ok()) << rb.describe();
    // ... so the pictures agree, but for pixel centres lying on a check edge.
    long differ = 0;
    for (int y = vp.y; y < vp.y + vp.h; ++y)
      for (int x = vp.x; x < vp.x + vp.w; ++x) differ += !ts::probe::close(ia.at(x, y), ib.at(x, y), tol());
    EXPECT_LT(differ, long(vp.w) * vp.h / 100) << differ << " pixels differ";
  }
}

// Claim: the left panel is the texture itself (s, t = a, b) with the region
// outlined in red and the screen diagonal's image in orange: check interiors
// away from the lines are the checker colours, the region edge from (1,0) to
// (0.75,0.75) is red, and the orange line passes through the image of the
// screen diagonal's midpoint under the first triangle's map (tl-br: (0.5,
// 0.5); bl-tr: (0.375, 0.375)).
TEST(VI1, TextureSpacePanelShowsTheTextureAndTheRegion) {
  for (Diagonal d : {Diagonal::TopLeftBottomRight, Diagonal::BottomLeftTopRight}) {
    const bool tlbr = d == Diagonal::TopLeftBottomRight;
    SCOPED_TRACE(tlbr ? "tl-br" : "bl-tr");
    Demo demo("quad_distortion", {"--diagonal", tlbr ? "tl-br" : "bl-tr", "--filter", "nearest"});
    ts::Frame f;
    ts::Image img = demo.render(1024, 512, &f);
    const ts::Panel& p = panelOf(f, "texture_space");
    const ts::Rect vp = p.viewport;
    // Line vertices (panel units) in pixels, to keep probes 4 px away.
    std::vector<std::vector<glm::dvec2>> lines;
    for (const ts::Batch& b : p.batches) {
      if (b.role != "region" && b.role != "diagonal_image") continue;
      std::vector<glm::dvec2> pts;
      for (const auto& v : b.vertices) pts.push_back({vp.x + v.pos.x * vp.w, vp.y + (1.0 - v.pos.y) * vp.h});
      if (b.prim == ts::Prim::LineLoop) pts.push_back(pts.front());
      lines.push_back(pts);
    }
    ASSERT_EQ(lines.size(), 2u) << "expected the region outline and the diagonal's image";
    auto nearLine = [&](int x, int y) {
      glm::dvec2 q(x + 0.5, y + 0.5);
      for (const auto& pts : lines)
        for (size_t k = 0; k + 1 < pts.size(); ++k) {
          glm::dvec2 u = pts[k + 1] - pts[k];
          double h = std::clamp(glm::dot(q - pts[k], u) / std::max(1e-12, glm::dot(u, u)), 0.0, 1.0);
          if (glm::length(q - pts[k] - h * u) < 4.0) return true;
        }
      return false;
    };
    ts::probe::Result r = probePanel(
        img, vp, [](glm::dvec2 ab) { return ab; }, nearLine);
    EXPECT_TRUE(r.ok()) << r.describe();
    EXPECT_GT(r.checked, long(0.5 * vp.w * vp.h));

    auto pixelAt = [&](glm::dvec2 ab) { return img.at(vp.x + int(ab.x * vp.w), vp.y + int((1.0 - ab.y) * vp.h)); };
    const ts::Rgba red{230, 26, 26, 255}, orange{255, 140, 0, 255};
    EXPECT_TRUE(ts::probe::close(pixelAt({0.875, 0.375}), red, tol()));
    glm::dvec2 mid = quad::split(kBook, d).first({0.5, 0.5});
    EXPECT_NEAR(mid.x, tlbr ? 0.5 : 0.375, 1e-12);
    EXPECT_TRUE(ts::probe::close(pixelAt(mid), orange, tol()));
    // A point on the other diagonal's image, away from where the two images
    // cross, is not orange (tl-br render: (0.25,0.25) on the bl-tr image;
    // bl-tr render: (0.25,0.75) on the tl-br image).
    glm::dvec2 other = tlbr ? quad::split(kBook, Diagonal::BottomLeftTopRight).first({1.0 / 3, 1.0 / 3})
                            : quad::split(kBook, Diagonal::TopLeftBottomRight).first({0.25, 0.75});
    EXPECT_NEAR(other.x, 0.25, 1e-12);
    EXPECT_FALSE(ts::probe::close(pixelAt(other), orange, tol()));
  }
}

// Claim: --texture FILE maps a picture upright: with the identity corners
// the square shows the PNG as it looks (its top row at t = 1, the top of
// the square; its left column at s = 0).
TEST(VI1, TextureFileIsMappedUpright) {
  const ts::Rgba red{255, 0, 0, 255}, green{0, 255, 0, 255}, blue{0, 0, 255, 255}, white{255, 255, 255, 255};
  ts::Image pic(2, 2);
  pic.set(0, 0, red);    // top-left of the picture
  pic.set(1, 0, green);  // top-right
  pic.set(0, 1, blue);   // bottom-left
  pic.set(1, 1, white);  // bottom-right
  const char* tmp = std::getenv("TMPDIR");
  std::string path = std::string(tmp && *tmp ? tmp : "/tmp") + "/vi1_texture_test_" + std::to_string(::getpid()) +
                     ".png";
  ts::writePng(path, pic);
  Demo demo("quad_distortion", {"--texture", path, "--corners", "0,0 1,0 1,1 0,1", "--filter", "nearest"});
  std::remove(path.c_str());
  ts::Frame f;
  ts::Image img = demo.render(1024, 512, &f);
  const ts::Rect vp = panelOf(f, "screen_space").viewport;
  const int h = vp.w / 2, m = 3;  // quadrant side, margin away from the centre lines
  struct {
    ts::Rect r;
    ts::Rgba want;
  } quads[] = {{{vp.x + m, vp.y + m, h - 2 * m, h - 2 * m}, red},
               {{vp.x + h + m, vp.y + m, h - 2 * m, h - 2 * m}, green},
               {{vp.x + m, vp.y + h + m, h - 2 * m, h - 2 * m}, blue},
               {{vp.x + h + m, vp.y + h + m, h - 2 * m, h - 2 * m}, white}};
  for (const auto& q : quads) {
    ts::probe::Result r = ts::probe::rect(img, q.r, q.want, tol());
    EXPECT_TRUE(r.ok()) << r.describe();
  }
}

// Claim: one orientation everywhere.  textures/ holds its files
// with the top row at t = 1, so `--texture textures/labelled_grid_512_8.png`
// shows A1 at the bottom left, reading the right way: the square (identity
// corners) matches the built-in grid cell by cell (texel row 0 = t = 0), and
// the file's own bottom-left cell is A1's colour.  A file written upside
// down (row 0 at t = 0, as textures/ was) shows A8 there and fails.
TEST(VI1, CommittedGridShowsA1AtTheBottomLeft) {
  const std::string file = "textures/labelled_grid_512_8.png";  // tests run in the source tree
  Demo demo("quad_distortion", {"--texture", file, "--corners", "0,0 1,0 1,1 0,1", "--filter", "nearest"});
  ts::Frame f;
  ts::Image img = demo.render(1024, 512, &f);
  const ts::Rect vp = panelOf(f, "screen_space").viewport;
  const ts::Image grid = *ts::labelledGrid(512, 8).image;  // row 0 = t = 0
  const ts::Image picture = ts::readPng(file);             // row 0 = the top
  int wrong = 0;
  for (int row = 0; row < 8; ++row)      // row 0 = the bottom (A1's row)
    for (int col = 0; col < 8; ++col) {  // col 0 = A
      // A point in the cell clear of its label, border and the t = 0 bar.
      double s = (col + 0.2) / 8, t = (row + 0.25) / 8;
      ts::Rgba want = grid.at(int(s * 512), int(t * 512));
      ts::Rgba got = img.at(vp.x + int(s * vp.w), vp.y + vp.h - 1 - int(t * vp.h));
      if (!ts::probe::close(got, want, tol()) && wrong++ < 3)
        ADD_FAILURE() << "cell " << char('A' + col) << row + 1 << " (s=" << s << ", t=" << t << ") is " << int(got.r)
                      << "," << int(got.g) << "," << int(got.b) << ", the grid's is " << int(want.r) << ","
                      << int(want.g) << "," << int(want.b);
    }
  EXPECT_EQ(wrong, 0);
  // A1 is the blue-ish, dark cell (column A: most blue; row 1: least green);
  // in the file it is at the bottom left, in the square too.
  ts::Rgba a1 = grid.at(int(0.2 / 8 * 512), int(0.25 / 8 * 512)), a8 = grid.at(int(0.2 / 8 * 512), int(7.25 / 8 * 512));
  EXPECT_GT(a8.g, a1.g + 50) << "A1 and A8 must differ for this test to see a flip";
  EXPECT_TRUE(ts::probe::close(picture.at(int(0.2 / 8 * 512), 511 - int(0.25 / 8 * 512)), a1, 0))
      << file << ": its bottom-left cell is not A1 (run make_textures textures)";
  EXPECT_TRUE(ts::probe::close(img.at(vp.x + vp.w / 40, vp.y + vp.h - 1 - vp.h / 32), a1, tol()))
      << "the square's bottom-left cell is not A1";
}

// Claim: rendering is deterministic: the same frame drawn twice, and the
// frame rebuilt from the same state, give identical pixels and identical
// PNG bytes.
TEST(VI1, RenderingIsDeterministic) {
  Demo demo("quad_distortion", {"--view", "compare", "--edges"});
  ts::Frame f;
  ts::Image a = demo.render(1280, 420, &f);
  ts::Image b = ts::test::renderer().render(f, true);
  ts::Image c = ts::test::renderer().render(f, true);
  ts::Image d = demo.render(1280, 420);  // rebuilt, no labels
  EXPECT_TRUE(b.pixels == c.pixels);
  EXPECT_TRUE(ts::encodePng(b) == ts::encodePng(c));
  EXPECT_TRUE(a.pixels == d.pixels);
  // Labels are drawn on top (b) and not in a: the check sees a difference.
  EXPECT_GT(ts::probe::countDiffering(a, b, 0), 100);
}

// Claim: "the checker lines bend by the amount the math predicts", read off
// the checkerboard picture itself.  Follow the check edge s = 1/2 on each
// side of the diagonal: in every pixel row crossing it, find the single
// dark/light transition within 10 px of where the triangle's map puts it,
// fit a line a = alpha + beta b through the crossings, and compare the
// slope with the map's (da/db = -(ds/db)/(ds/da)) and the angle between the
// two sides' lines with the angle between the s gradients (tl-br: atan 1/3,
// bl-tr: atan 1/4).
TEST(VI1, CheckerLinesBendByThePredictedAngle) {
  for (Diagonal d : {Diagonal::TopLeftBottomRight, Diagonal::BottomLeftTopRight}) {
    const bool tlbr = d == Diagonal::TopLeftBottomRight;
    SCOPED_TRACE(tlbr ? "tl-br" : "bl-tr");
    Demo demo("quad_distortion", {"--diagonal", tlbr ? "tl-br" : "bl-tr", "--filter", "nearest"});
    ts::Frame f;
    ts::Image img = demo.render(1024, 512, &f);
    const ts::Rect vp = panelOf(f, "screen_space").viewport;
    quad::Split sp = quad::split(kBook, d);
    double slope[2];
    for (int side = 0; side < 2; ++side) {
      const quad::Affine& A = side == 0 ? sp.first : sp.second;
      glm::dvec2 g = A.gradient(0);  // (ds/da, ds/db)
      const double s0 = 0.5, window = 10.0;
      double n = 0, sb = 0, sa = 0, sbb = 0, sab = 0;
      for (int y = vp.y + 8; y < vp.y + vp.h - 8; ++y) {
        const double b = panelPoint(vp, vp.x, y).y;
        double aPred = (s0 - A.c.x - g.y * b) / g.x;
        glm::dvec2 p(aPred, b);
        double distDiag = (tlbr ? std::abs(p.x + p.y - 1.0) : std::abs(p.y - p.x)) * vp.w / std::sqrt(2.0);
        if (sp.inFirst(p, d) != (side == 0) || distDiag < 16 || aPred < 0.05 || aPred > 0.95) continue;
        int xc = vp.x + int(std::floor(aPred * vp.w));
        int transitions = 0;
        double where = 0;
        for (int x = xc - int(window); x < xc + int(window); ++x) {
          bool l0 = img.at(x, y).r > 128, l1 = img.at(x + 1, y).r > 128;
          if (l0 != l1) ++transitions, where = x + 1.0;  // the boundary between pixels x and x+1
        }
        if (transitions != 1) continue;
        double a = (where - vp.x) / vp.w;
        n += 1, sb += b, sa += a, sbb += b * b, sab += a * b;
      }
      ASSERT_GE(n, 60) << "side " << side << ": too few rows crossed the edge cleanly";
      slope[side] = (n * sab - sa * sb) / (n * sbb - sb * sb);
      EXPECT_NEAR(slope[side], -g.y / g.x, 0.01) << "side " << side;
    }
    double measured = deg(std::abs(std::atan(slope[0]) - std::atan(slope[1])));
    double predicted = quad::angleDeg(sp.first.gradient(0), sp.second.gradient(0));
    EXPECT_NEAR(predicted, deg(std::atan(tlbr ? 1.0 / 3.0 : 0.25)), 1e-9);
    EXPECT_NEAR(measured, predicted, 0.5);
    std::printf("[ info ] %s: s = 1/2 edge bends by %.3f deg in the image, %.3f predicted\n", tlbr ? "tl-br" : "bl-tr",
                measured, predicted);
  }
}
}  // namespace
