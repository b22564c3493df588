// demos/bump_mapping/bump_mapping_test.cpp — demos/bump_mapping: each bump
// method's normal against the truly displaced surface, from renders, never
// against stored numbers.  What is asserted are relations the mathematics
// fixes: Blinn's form (seed 004) and a normal map are near the displaced
// surface's normal, the flat torus and seed 002's shortcut are not; seed
// 002's x perturbation runs against the truth on the near side of the ring
// and with it on the far side (it is added in eye space, not along the
// surface); doubling the height scale doubles Blinn's tilt (small angles)
// and leaves seed 002's alone; doubling the object halves Blinn's and the
// true tilt (seed 004's claim) and leaves the normal map's.
//
// Tolerances.  Normals are read back through 8 bits a channel: one step is
// 1/127.5 of a unit vector's component, about 0.45 degrees, so angles are
// compared with margins of a few degrees, ratios within 0.1 of 1/2 or 2
// (the tilt is an angle, tan is not linear: at 10 degrees tan 2a / tan a
// differs from 2 by 3 %, and the 8-bit normals add their own).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "common/core/image.hpp"
#include "demos/bump_mapping/bump_mapping_gl.hpp"
#include "demos/bump_mapping/bump_mapping_math.hpp"
#include "demos/bump_mapping/bump_mapping_measure.hpp"
#include "common/core/layout.hpp"
#include "common/core/probe.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::Demo;
using ts::test::value;

// The default state's measurement, made once (about 10 s on softpipe).
const ts::Measurements& defaults() {
  static const ts::Measurements m = Demo("bump_mapping", {}).measure();
  return m;
}

// The figures' pictures and captions: R's normals are shown on the
// figure's background like every other panel (the measurements' renders
// keep black, which tells the surface from the rest); the captions print
// the measurements whole, every number as a measurement or a named value,
// never cut with "...".
TEST(BumpMapping, FiguresShowTheirNumbersWhole) {
  const bump::Found* found = defaults().detailAs<bump::Found>();
  ASSERT_NE(found, nullptr);
  const ts::Frame blank = ts::layout::blankFrame(1, 1);
  const ts::Rgba corner = found->refNormals->at(0, 0);
  EXPECT_NEAR(corner.r, blank.clearColor.r * 255, 1);
  EXPECT_NEAR(corner.g, blank.clearColor.g * 255, 1);
  EXPECT_NEAR(corner.b, blank.clearColor.b * 255, 1);
  // Each view's numbers: six cells of PSNR, |diff| and (GLSL) the normal's error, emboss's two contrasts; two
  // cells of normal errors; seed 002 beside its x tilt (B2's four, the near and far agreement, R's PSNR);
  // emboss beside its term (B4's two, the four bands' contrasts, R's PSNR).
  for (const auto& [view, method, w, h, numbers] :
       {std::tuple{"all", "normalmap", 1280, 720, 16u}, std::tuple{"normals", "normalmap", 1024, 560, 3u},
        std::tuple{"compare", "seed002", 1024, 560, 7u}, std::tuple{"compare", "emboss", 1024, 560, 7u}}) {
    Demo d("bump_mapping", {"--view", view, "--method", method});
    d.measured = defaults();
    const ts::Frame f = d.frame(w, h);
    size_t printed = 0;
    for (const ts::Label& l : f.labels) {
      EXPECT_EQ(l.text.find("..."), std::string::npos) << view << ": " << l.text;
      for (const ts::Label::Printed& p : l.printed) {
        EXPECT_EQ(ts::layout::measured(d.measured, p.name, p.format.c_str()).text, p.text) << p.name;
        ++printed;
      }
    }
    EXPECT_EQ(printed, numbers) << view << " " << method;
  }
}

// A window's first stage (ts::measureStage, only on the window's worker):
// the pictures at once, the numbers to come.  Its R is the displaced grid
// drawn coarse, tagged refining and replaced (it is not the result's R), and
// the frame built from it prints no number: every note says "(measuring)".
// The control: the result's frame of the same view prints its numbers.
TEST(BumpMapping, AWindowsFirstStageShowsThePicturesNotTheNumbers) {
  Demo d("bump_mapping", {});
  // Superseded as soon as the stage is handed over: the rest (some 40 renders) is not needed here.
  const std::vector<ts::Measurements> stages = ts::test::measureInStages(d, 1);
  ASSERT_EQ(stages.size(), 1u);
  const ts::Measurements& stage = stages[0];
  EXPECT_TRUE(stage.refining);
  EXPECT_TRUE(stage.empty());  // no number measured yet
  const bump::Found* first = stage.detailAs<bump::Found>();
  const bump::Found* result = defaults().detailAs<bump::Found>();
  ASSERT_NE(first, nullptr);
  ASSERT_NE(result, nullptr);
  ASSERT_TRUE(first->pictures.count(bump::kReference));
  const ts::Image &coarse = *first->pictures.at(bump::kReference), &fine = *result->pictures.at(bump::kReference);
  ASSERT_EQ(coarse.width, fine.width);
  ASSERT_EQ(coarse.height, fine.height);
  EXPECT_GT(ts::probe::countDiffering(coarse, fine, 0), 0) << "the stage's R is the coarse grid's, not R";
  d.measured = stage;
  const ts::Frame f = d.frame(1024, 512);
  bool tagged = false;
  size_t measuring = 0;
  for (const ts::Label& l : f.labels) {
    EXPECT_TRUE(l.printed.empty()) << l.text;
    tagged = tagged || l.text == "refining";
    for (size_t at = l.text.find("(measuring)"); at != std::string::npos; at = l.text.find("(measuring)", at + 1))
      ++measuring;
  }
  EXPECT_TRUE(tagged);
  EXPECT_GT(measuring, 0u);
  EXPECT_NE(f.panel("picture_reference"), nullptr);
  // The control: the result's frame of the same view prints its numbers, says "(measuring)" nowhere, tags nothing.
  d.measured = defaults();
  size_t printed = 0;
  for (const ts::Label& l : d.frame(1024, 512).labels) {
    printed += l.printed.size();
    EXPECT_EQ(l.text.find("(measuring)"), std::string::npos) << l.text;
    EXPECT_NE(l.text, "refining");
  }
  EXPECT_GT(printed, 0u);
}

// A window's later stages.  The second: R's picture whole (the full grid,
// the result's picture), not tagged refining, its numbers still to come
// (the method's renders not made yet).  The third: the default view (B1
// beside R) complete before the rest of the measurement, R's normals not
// drawn yet (the grid drawn once: its coverage, from the shaded render's
// depth, stands in), its numbers the result's own (the same pixels compared,
// the same values), so the frame built from it is the result's frame: the
// window's picture stops changing there.  The controls: the first and second
// stages' frames are not the result's.
TEST(BumpMapping, AWindowsLaterStagesBringRWholeThenTheDefaultViewComplete) {
  Demo d("bump_mapping", {});
  const std::vector<ts::Measurements> stages = ts::test::measureInStages(d, 3);  // the rest is not needed here
  ASSERT_EQ(stages.size(), 3u);
  const bump::Found* result = defaults().detailAs<bump::Found>();
  ASSERT_NE(result, nullptr);
  auto texts = [&](const ts::Measurements& m) {
    d.measured = m;
    std::vector<std::string> out;
    for (const ts::Label& l : d.frame(1024, 512).labels) out.push_back(l.text);
    return out;
  };
  const std::vector<std::string> final = texts(defaults());
  // The second stage: R whole, no numbers.
  const bump::Found* whole = stages[1].detailAs<bump::Found>();
  ASSERT_NE(whole, nullptr);
  EXPECT_TRUE(stages[1].empty());
  EXPECT_FALSE(whole->coarseReference);
  ASSERT_TRUE(whole->pictures.count(bump::kReference));
  EXPECT_EQ(ts::probe::countDiffering(*whole->pictures.at(bump::kReference), *result->pictures.at(bump::kReference), 0),
            0);
  const std::vector<std::string> second = texts(stages[1]);
  EXPECT_NE(second, final);
  EXPECT_EQ(std::count(second.begin(), second.end(), "refining"), 0);
  EXPECT_TRUE(std::any_of(second.begin(), second.end(),
                          [](const std::string& t) { return t.find("(measuring)") != std::string::npos; }));
  // The third stage: the view complete.
  const ts::Measurements& third = stages[2];
  ASSERT_FALSE(third.empty());
  for (const ts::Measurement& m : third) EXPECT_EQ(m.value, value(defaults(), m.name)) << m.name;
  const bump::Found* found = third.detailAs<bump::Found>();
  ASSERT_NE(found, nullptr);
  EXPECT_FALSE(found->coarseReference);
  EXPECT_EQ(found->refNormals, nullptr) << "R's normals drawn before the view was complete";
  for (int m : {bump::kBlinn, bump::kReference}) {  // R's coverage from its depth: the pixels its normals cover
    ASSERT_TRUE(found->cmp.count(m) && result->cmp.count(m)) << m;
    EXPECT_GT(found->cmp.at(m).pixels, 10000) << m;
    EXPECT_EQ(found->cmp.at(m).pixels, result->cmp.at(m).pixels) << m;
  }
  EXPECT_EQ(ts::probe::countDiffering(*found->pictures.at(bump::kReference), *result->pictures.at(bump::kReference), 0),
            0);
  EXPECT_EQ(texts(third), final);
  EXPECT_NE(texts(stages[0]), final);  // the control: the first stage says "(measuring)"
}

// The pictures that show seed 002's and emboss's claims show what was
// measured: seed 002's x tilt picture, counted in the near and the far rows,
// gives the measured agreements exactly; emboss's term, as shown (magnified),
// is flatter where the light is within 10 degrees of the normal than where
// it is beyond 60, and the edge of that region is drawn.
TEST(BumpMapping, ClaimPicturesShowTheMeasurements) {
  const bump::Found* found = defaults().detailAs<bump::Found>();
  ASSERT_NE(found, nullptr);
  ASSERT_TRUE(found->seedTiltX && found->embossTerm);
  auto same = [](ts::Rgba a, ts::Rgba b) { return a.r == b.r && a.g == b.g && a.b == b.b; };
  for (const auto& [rows, name] : {std::pair{found->nearRows, "tilt_agreement_x_near[seed002]"},
                                   std::pair{found->farRows, "tilt_agreement_x_far[seed002]"}}) {
    double with = 0, against = 0;
    for (int y = rows.x; y < rows.y; ++y)
      for (int x = 0; x < found->seedTiltX->width; ++x) {
        with += same(found->seedTiltX->at(x, y), bump::kTiltWith);
        against += same(found->seedTiltX->at(x, y), bump::kTiltAgainst);
      }
    ASSERT_GT(with + against, 100) << name;
    EXPECT_NEAR((with - against) / (with + against), value(defaults(), name), 1e-9) << name;
  }
  const ts::Image& term = *found->embossTerm;
  ASSERT_EQ(found->embossBand.size(), size_t(term.width) * size_t(term.height));
  double dev[4] = {0, 0, 0, 0}, n[4] = {0, 0, 0, 0};
  long edge = 0;
  for (int y = 0; y < term.height; ++y)
    for (int x = 0; x < term.width; ++x) {
      const int b = found->embossBand[size_t(y) * size_t(term.width) + size_t(x)];
      if (b < 0) continue;
      if (same(term.at(x, y), bump::kEmbossEdge)) {
        ++edge;
        continue;
      }
      dev[b] += std::fabs(term.at(x, y).r - 127.5), n[b] += 1;
    }
  EXPECT_GT(edge, 20);
  ASSERT_GT(n[0], 0);
  ASSERT_GT(n[3], 0);
  EXPECT_LT(dev[0] / n[0], 0.3 * dev[3] / n[3]);
}

TEST(BumpMapping, BlinnAndNormalMapFollowTheDisplacedSurface) {
  for (const char* heights : {"procedural", "bricks"}) {
    SCOPED_TRACE(heights);
    const ts::Measurements m = std::string(heights) == "procedural"
                                   ? defaults()
                                   : Demo("bump_mapping", {"--heights", heights}).measure();
    const double flat = value(m, "normal_err_deg[flat]");
    // The bumps tilt the normal by several degrees: the flat torus is that far off.
    EXPECT_GT(flat, 5.0);
    EXPECT_NEAR(flat, value(m, "tilt_deg[reference]"), 1.0);
    // Blinn's form drops P (n/|n|)_u: small against the slopes here.
    EXPECT_LT(value(m, "normal_err_deg[blinn]"), flat / 4);
    // The normal map is baked for one texel size (the ring's mean circle).
    EXPECT_LT(value(m, "normal_err_deg[normalmap]"), flat / 3);
    // Seed 001: DXT1 is "bad for normal maps": compressed (4 bits a texel,
    // two endpoint colours a block) the same map is measurably further off,
    // by at least 0.2 deg (0.51 deg measured on the procedural heights),
    // yet still a bump map, well under the flat torus.
    EXPECT_GT(value(m, "normal_err_deg[normalmap_dxt1]"), value(m, "normal_err_deg[normalmap]") + 0.2);
    EXPECT_LT(value(m, "normal_err_deg[normalmap_dxt1]"), flat / 2);
    // In the picture (the same pixel, not the same surface point) the
    // displacement moves the bumps by ~4 pixels: on the broad dimples the
    // methods are still closer than flat; on bricks the mortar lines (~5
    // pixels wide) move off themselves, and every bump map, R's own normals
    // included, is further from R's picture than the flat torus (measured).
    if (std::string(heights) == "procedural") {
      EXPECT_LT(value(m, "mad[blinn]"), value(m, "mad[flat]"));
      EXPECT_LT(value(m, "mad[normalmap]"), value(m, "mad[flat]"));
    } else {
      EXPECT_GT(value(m, "mad[ideal]"), value(m, "mad[flat]"));
    }
    // No bump map beats R's own normals on the smooth torus.
    EXPECT_LE(value(m, "mad[ideal]"), value(m, "mad[blinn]") + 0.5);
  }
}

TEST(BumpMapping, Seed002TiltsInEyeSpace) {
  const ts::Measurements& m = defaults();
  // Its fixed 1/255 per texel pair is far from the true slope: barely better than flat.
  EXPECT_GT(value(m, "normal_err_deg[seed002]"), 0.8 * value(m, "normal_err_deg[flat]"));
  // Blinn tilts the way the surface does everywhere.
  for (const char* side : {"near", "far"}) {
    EXPECT_GT(value(m, std::string("tilt_agreement_x_") + side + "[blinn]"), 0.9) << side;
    EXPECT_GT(value(m, std::string("tilt_agreement_y_") + side + "[blinn]"), 0.9) << side;
  }
  // Seed 002 adds g_x to the eye's x: against the surface's slope on the near
  // side, where s runs along +x (Blinn: n' = n - P_s x), and the sign turns
  // on the far side, where s runs along -x.
  EXPECT_LT(value(m, "tilt_agreement_x_near[seed002]"), -0.3);
  EXPECT_GT(value(m, "tilt_agreement_x_far[seed002]"), value(m, "tilt_agreement_x_near[seed002]") + 0.5);
  // Its formula has no height scale in it.
  EXPECT_NEAR(value(m, "tilt_ratio_height_x2[seed002]"), 1.0, 0.02);
  EXPECT_NEAR(value(m, "tilt_ratio_height_x2[blinn]"), 2.0, 0.25);
  EXPECT_NEAR(value(m, "tilt_ratio_height_x2[reference]"), 2.0, 0.25);
}

// Seed 004: "if the object is enlarged twice, the normal grows four times,
// its perturbation only twice": the bumps look half as deep.  So do the true
// displaced surface's (the heights stay); a normal map, baked once, does not.
TEST(BumpMapping, Seed004ScaleClaim) {
  const ts::Measurements& m = defaults();
  EXPECT_NEAR(value(m, "tilt_ratio_object_x2[blinn]"), 0.5, 0.06);
  EXPECT_NEAR(value(m, "tilt_ratio_object_x2[reference]"), 0.5, 0.06);
  EXPECT_NEAR(value(m, "tilt_ratio_object_x2[normalmap]"), 1.0, 0.02);
}

// Emboss (seed 001) shifts the heights by the light's part along the
// surface: with the light along the normal the shift, and so the bump, is 0.
// Its contrast grows with the angle between light and normal (as its sine).
TEST(BumpMapping, EmbossFadesWithTheLightOverhead) {
  const ts::Measurements& m = defaults();
  const double overhead = value(m, "emboss_contrast[0-10deg]"), grazing = value(m, "emboss_contrast[60-90deg]");
  ASSERT_GT(grazing, 0.01);  // there are bumps to see
  EXPECT_LT(overhead, 0.3 * grazing);
  EXPECT_LT(value(m, "emboss_contrast[10-30deg]"), value(m, "emboss_contrast[30-60deg]"));
  EXPECT_LT(value(m, "emboss_contrast[30-60deg]"), grazing);
}

// GL_DOT3_RGB computes 4 (t - 1/2).(c - 1/2): with the normal map as t and
// the tangent-space light as the colour c it is the shader's diffuse sum,
// within the rounding of 8-bit colours (2 levels of 255) and of the light
// vector interpolated per vertex rather than per pixel.
TEST(BumpMapping, Dot3IsTheShadersDiffuseSum) { EXPECT_LT(value(defaults(), "dot3_vs_shader_mad"), 2.0); }

// Seed 001's limit: no bumps on the silhouette.  B1 draws the smooth torus,
// so its outline is the smooth one to the pixel; R's moves by the heights
// (about P / distance * focal length: 0.5 to 0.9 of the scale, several pixels).
TEST(BumpMapping, OnlyTheDisplacedSurfaceChangesTheOutline) {
  const ts::Measurements& m = defaults();
  EXPECT_EQ(value(m, "outline_deviation_px[blinn]"), 0.0);
  EXPECT_GT(value(m, "outline_deviation_px[reference]"), 2.0);
}

// The seam where the texture repeats (and s wraps): baked with one-sided
// slopes at the edge the normal map creases there; with slopes that wrap
// the step across the edge is like any other column's.
TEST(BumpMapping, NormalMapSeamAndItsFix) {
  const ts::Measurements& m = defaults();
  const double other = value(m, "neighbour_jump_deg");
  EXPECT_GT(value(m, "seam_jump_deg[unwrapped]"), 1.5 * other);
  EXPECT_LT(value(m, "seam_jump_deg[wrapped]"), 1.3 * other);
}

// Minification flattens bumps: with the torus 2, 4, 8 times as far the
// texels shrink below the pixels and trilinear mipmapping averages them.
// Averaged heights lose their slopes faster than averaged normals (a
// normal map's mip level keeps the mean direction of its texels; the
// heights' level keeps their mean height, whose differences shrink).
TEST(BumpMapping, MinificationFlattensTheBumps) {
  const ts::Measurements& m = defaults();
  for (const char* method : {"blinn", "normalmap"}) {
    const std::string k = std::string("mip_tilt_ratio[") + method + "@";
    EXPECT_LT(value(m, k + "8x]"), value(m, k + "4x]")) << method;
    EXPECT_LT(value(m, k + "4x]"), value(m, k + "2x]")) << method;
    EXPECT_LT(value(m, k + "8x]"), 0.85) << method;
  }
  EXPECT_LT(value(m, "mip_tilt_ratio[blinn@8x]"), value(m, "mip_tilt_ratio[normalmap@8x]"));
}

// The CPU side: the baked normal map of a flat field is straight up, and a
// slope of the heights tilts it against the slope (n = (-dP/dx, -dP/dy, 1)).
TEST(BumpMapping, NormalMapBakesTheSlope) {
  bump::Heights H{"ramp", 64, 64, std::vector<float>(64 * 64), {1.0f, 1.0f}};
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) H.v[size_t(y * 64 + x)] = 0.25f + 0.5f * float(x) / 64.0f;  // rises along u
  ts::Image n = bump::normalMap(H, 1.0, 0.4, 0.1);
  ts::Rgba c = n.at(32, 32);
  const double texelS = 2 * bump::kPi / 64, slope = 0.1 * 0.5 / 64 / texelS;  // dP/dx in world units
  glm::dvec3 want = glm::normalize(glm::dvec3(-slope, 0, 1));
  EXPECT_NEAR(c.r / 255.0, 0.5 + 0.5 * want.x, 1.0 / 255);
  EXPECT_NEAR(c.g / 255.0, 0.5, 1.0 / 255);
  EXPECT_NEAR(c.b / 255.0, 0.5 + 0.5 * want.z, 1.0 / 255);
}

// The shader's numbers come from the method table (bump_mapping_methods.hpp) and the
// material (bump_mapping_gl.hpp): the text GL compiles holds the numbers, no name is
// left over, and each method's branch tests its own shader id.
TEST(BumpMapping, ShaderTextTakesItsNumbersFromTheTable) {
  const ts::Program p = bump::meshProgram();
  for (const std::string& text : {p.vertex, p.fragment}) {
    EXPECT_EQ(text.find("METHOD_"), std::string::npos);
    EXPECT_EQ(text.find("ALBEDO"), std::string::npos);
    EXPECT_EQ(text.find("AMBIENT"), std::string::npos);
  }
  for (int m : {bump::kBlinn, bump::kSeed002, bump::kNormalMap, bump::kReference})
    EXPECT_NE(p.fragment.find("(method == " + std::to_string(bump::kMethods[m].shaderId) + ")"), std::string::npos)
        << bump::kMethods[m].key;
  EXPECT_EQ(bump::glslNumber(1.0f), "1.0");
  EXPECT_EQ(bump::glslNumber(0.74f), "0.74");
}
}  // namespace
