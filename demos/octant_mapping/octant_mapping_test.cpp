// demos/octant_mapping/octant_mapping_test.cpp — Rogers' worked examples (seed
// 004, demos/octant_mapping): the demo's measurements against the answers
// tests/unit/octant_test.cpp recomputes from first principles without the
// demo's code (7/16; the table to 3 decimals; 18 texel centres, 5 on lines,
// with the corners rounded as the seed prints them, 17 and 4 unrounded and
// over the curved preimage), its misprints, the raster's methods against the
// exact area integral, the pictures' values, the click and bad --pixel input.
//
// Tolerances.  The worked answers are counts and ratios of counts: exact.
// The table: 5e-4, half a unit of the third decimal.  The raster's RMS
// values are asserted by their order and by wide bands around the measured
// (nearest 0.298, Catmull-4 0.115, inverse 0.026, trilinear 0.107,
// anisotropic 0.068 on llvmpipe): another rasterizer filters a little
// differently (softpipe, EGL), the order of the methods is the claim.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/image.hpp"
#include "common/core/scene.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::Demo;
using ts::test::panelOf;
using ts::test::value;

// Where the centre of raster pixel (Px, Py) is drawn in a raster panel (frame pixels).
glm::ivec2 centreOf(const ts::Panel& p, double Px, double Py) {
  const glm::vec2 q = ts::panelToPixels(p,
                                        p.projection * glm::vec4(float((Px + 0.5) / 32), float((Py + 0.5) / 32), 0, 1));
  return {int(std::floor(q.x)), int(std::floor(q.y))};
}

const ts::Measurements& measured() {
  static Demo d("octant_mapping", {});
  static const ts::Measurements m = d.measure();
  return m;
}

TEST(OctantMapping, TheForwardTable) {
  const auto& m = measured();
  EXPECT_NEAR(value(m, "table_xyz[u=1/4,w=1/2].x"), 0.354, 5e-4);
  EXPECT_NEAR(value(m, "table_xyz[u=1/4,w=1/2].y"), 0.383, 5e-4);
  EXPECT_NEAR(value(m, "table_xyz[u=1/4,w=1/2].z"), 0.854, 5e-4);
  EXPECT_LT(value(m, "table_max_error[u=1/4]"), 1e-12);
  EXPECT_EQ(value(m, "seed_table_xyz_wrong"), 0.0);
}

TEST(OctantMapping, CatmullSevenSixteenths) {
  const auto& m = measured();
  EXPECT_EQ(value(m, "catmull_fraction"), 0.4375);
  EXPECT_EQ(value(m, "catmull_line_texels"), 7.0);
  EXPECT_EQ(value(m, "catmull_texels"), 16.0);
  EXPECT_EQ(value(m, "catmull_levels[5,9]"), 4.0);
}

// The seed's 5/18 under the stated conventions (corners to 3 decimals), and
// 4/17 without the rounding, as the oracle finds.
TEST(OctantMapping, InversePixelMappingCount) {
  const auto& m = measured();
  EXPECT_EQ(value(m, "inverse_texels"), 18.0);
  EXPECT_EQ(value(m, "inverse_line_texels"), 5.0);
  EXPECT_DOUBLE_EQ(value(m, "inverse_fraction"), 5.0 / 18);
  EXPECT_EQ(value(m, "inverse_texels[unrounded]"), 17.0);
  EXPECT_EQ(value(m, "inverse_line_texels[unrounded]"), 4.0);
  EXPECT_DOUBLE_EQ(value(m, "inverse_fraction[unrounded]"), 4.0 / 17);
  EXPECT_EQ(value(m, "inverse_texels[curved]"), 17.0);
  EXPECT_EQ(value(m, "inverse_line_texels[curved]"), 4.0);
}

// Every misprint the demo flags, with its corrected value.
TEST(OctantMapping, MisprintsFlagged) {
  const auto& m = measured();
  const double pi = std::acos(-1.0);
  EXPECT_EQ(value(m, "misprints_flagged"), 9.0);
  EXPECT_NEAR(value(m, "misprint[table_theta_w0]"), pi / 8, 1e-12);
  EXPECT_NEAR(value(m, "misprint[table_phi_w1/4]"), 7 * pi / 16, 1e-12);
  EXPECT_NEAR(value(m, "misprint[table_phi_w1/2]"), 3 * pi / 8, 1e-12);
  EXPECT_NEAR(value(m, "misprint[table_phi_w3/4]"), 5 * pi / 16, 1e-12);
  EXPECT_NEAR(value(m, "misprint[catmull_phi]"), 31 * pi / 64, 1e-12);
  EXPECT_NEAR(value(m, "misprint[corner_z_21_15]"), 0.353, 5e-4);
  EXPECT_NEAR(value(m, "misprint[corner_phi_22_15]"), 61.36, 5e-3);
  EXPECT_NEAR(value(m, "misprint[sphere_formula]"), 0.492, 5e-4);
  EXPECT_NEAR(value(m, "misprint[view_matrix]"), 1.0, 1e-12);
  // Of the 40 entries of the corner tables only z = 0.341 and phi = 61.34 are off by more than a unit.
  EXPECT_EQ(value(m, "seed_corner_entries_wrong"), 2.0);
}

// Over the pixels wholly on the octant: inverse mapping is closest to the
// exact area integral, then anisotropic, Catmull-4 and trilinear, and point
// sampling is worst and shows nothing of most pixels over a line.
TEST(OctantMapping, MethodsAgainstTheExactIntegral) {
  const auto& m = measured();
  EXPECT_EQ(value(m, "raster_pixels_compared"), 212.0);
  EXPECT_EQ(value(m, "line_pixels"), 122.0);
  const double nearest = value(m, "rms_exact[nearest]"), catmull = value(m, "rms_exact[catmull4]"),
               inverse = value(m, "rms_exact[inverse]"), trilinear = value(m, "rms_exact[trilinear]"),
               aniso = value(m, "rms_exact[anisotropic]");
  EXPECT_LT(inverse, aniso);
  EXPECT_LT(aniso, trilinear);
  EXPECT_LT(trilinear, nearest);
  EXPECT_LT(catmull, nearest);
  EXPECT_NEAR(nearest, 0.298, 0.03);
  EXPECT_NEAR(catmull, 0.115, 1e-3);  // CPU
  EXPECT_NEAR(inverse, 0.026, 1e-3);  // CPU
  EXPECT_NEAR(trilinear, 0.107, 0.03);
  EXPECT_NEAR(aniso, 0.068, 0.03);
  EXPECT_GT(value(m, "lost_line_pixels[nearest]"), 0.5 * value(m, "line_pixels"));
  EXPECT_EQ(value(m, "lost_line_pixels[trilinear]"), 0.0);
  EXPECT_EQ(value(m, "lost_line_pixels[anisotropic]"), 0.0);
  // GL_NEAREST at the pixel centres takes the texel the CPU's inverse finds.
  EXPECT_EQ(value(m, "point_gl_vs_cpu_mismatches"), 0.0);
}

// The pictures hold the values: in the methods figure each raster pixel is a
// flat quad of grey 1 - value, drawn so by GL.
TEST(OctantMapping, MethodsFigureShowsTheValues) {
  Demo d("octant_mapping", {"--view", "methods"});
  d.measure();
  ts::Frame f;
  const ts::Image img = d.render(1280, 560, &f);
  const ts::Panel& p = panelOf(f, "raster_exact");
  const double exact = value(d.measured, "pixel_exact");  // pixel (21,15), the default
  const glm::ivec2 at = centreOf(p, 21, 15);
  const ts::Rgba c = img.at(at.x, at.y);
  EXPECT_NEAR(c.r, 255 * (1 - exact), 1.01);
  // Point sampling's panel: that pixel took a white texel (its preimage's centre is off the lines).
  const ts::Panel& q = panelOf(f, "raster_nearest");
  const glm::ivec2 atq = centreOf(q, 21, 15);
  EXPECT_EQ(img.at(atq.x, atq.y).r, 255);
}

// A click on the raster sets --pixel to the pixel under it (Py up).
TEST(OctantMapping, ClickPicksTheRasterPixel) {
  Demo d("octant_mapping", {});
  const ts::Frame f = d.frame(1024, 540);
  const ts::Panel& p = panelOf(f, "raster");
  const glm::ivec2 at = centreOf(p, 5, 9);
  const auto set = d.scene->click(at.x, at.y, 1024, 540);
  ASSERT_EQ(set.size(), 1u);
  EXPECT_EQ(set[0].first, "pixel");
  EXPECT_EQ(set[0].second, "5,9");
  EXPECT_TRUE(d.scene->click(2, 2, 1024, 540).empty());  // the margin: nothing
  // In the methods view the rasters show the octant's part (Px 4..28, Py 6..22): the click follows.
  Demo m("octant_mapping", {"--view", "methods"});
  const ts::Frame fm = m.frame(1280, 560);
  for (const char* id : {"raster_exact", "raster_anisotropic"}) {
    const glm::ivec2 q = centreOf(panelOf(fm, id), 21, 15);
    const auto picked = m.scene->click(q.x, q.y, 1280, 560);
    ASSERT_EQ(picked.size(), 1u) << id;
    EXPECT_EQ(picked[0].second, "21,15") << id;
  }
}

// --pixel outside 0..31 or malformed: one line on stderr, exit 2, no file.
TEST(OctantMapping, BadPixelIsOneLineExit2AndNoFile) {
  const std::string png = ::testing::TempDir() + "ts_octant_bad.png";
  for (const char* bad : {"32,1", "1,32", "-1,3", "5", "5,9,1", "a,b", "", " 5,9", "5,"}) {
    std::remove(png.c_str());
    std::vector<std::string> args = {"octant_mapping", "--png", png, "--pixel", bad};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    testing::internal::CaptureStderr();
    const int status = ts::runDemo("octant_mapping", int(argv.size()), argv.data());
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(status, 2) << bad;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << bad << ": " << err;
    EXPECT_NE(err.find("--pixel"), std::string::npos) << err;
    EXPECT_FALSE(std::ifstream(png).good()) << bad;
  }
}
}  // namespace

// Claim: --texture FILE shows a picture (hand-drawn or scanned, Rogers' other kinds of pattern) on the pattern
// panel instead of the grid, and every number stays what it was: measure() counts the grid's line texels and the
// mapping's geometry, none of which reads the shown picture.  Control: without the file the panel holds the grid.
TEST(OctantMapping, TextureFileIsShownAndTheNumbersStayTheGrids) {
  const std::string file = "textures/labelled_grid_512_8.png";  // tests run in the source tree
  Demo withFile("octant_mapping", {"--view", "overview", "--texture", file});
  const ts::Measurements& m = withFile.measure();
  const ts::Measurements& base = measured();
  ASSERT_EQ(m.size(), base.size());
  for (size_t k = 0; k < m.size(); ++k) {
    EXPECT_EQ(m[k].name, base[k].name);
    EXPECT_EQ(m[k].value, base[k].value) << m[k].name;
  }
  ts::Image picture = ts::readPng(file);  // row 0 = the top; a texture's row 0 = t = 0
  picture.flipVertical();
  auto shownPattern = [](Demo& d) {
    const ts::Frame f = d.frame(1024, 540);
    const ts::Panel& p = panelOf(f, "pattern");
    return *f.textures.at(size_t(p.batches.at(0).texture)).image;
  };
  const ts::Image shown = shownPattern(withFile);
  ASSERT_EQ(shown.width, picture.width);
  ASSERT_EQ(shown.height, picture.height);
  EXPECT_TRUE(shown.pixels == picture.pixels);
  Demo plain("octant_mapping", {"--view", "overview"});
  plain.measure();
  const ts::Image grid = shownPattern(plain);
  EXPECT_FALSE(grid.width == picture.width && grid.pixels == picture.pixels);
}
