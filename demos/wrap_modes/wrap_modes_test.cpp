// demos/wrap_modes/wrap_modes_test.cpp — demos/wrap_modes: the wrap modes,
// the texture matrix and the texture environment, checked from renders
// against the formulas of demos/wrap_modes/wrap_modes_math.hpp, never against a
// stored image.
//
// Tolerances.  Texel-index renders are exact (GL_NEAREST, pixel centres a
// quarter texel inside or exactly on integer s, where GL's floor(u) is
// exact for these sizes): 0 mismatches.  Colours are 8-bit: a value read
// back is within 1/2 of its channel's step of the exact result, and a
// GL_LINEAR weight is quantised by the rasterizer (llvmpipe: 1/256), so a
// percentage of the border colour is within 100 (1.5/255) of the formula.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/core/image.hpp"
#include "common/core/textures.hpp"
#include "demos/wrap_modes/wrap_modes_math.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::Demo;
using ts::test::value;

const GLenum kModes[] = {GL_REPEAT, GL_MIRRORED_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER};
const char* const kNames[] = {"repeat", "mirrored", "clamp", "edge", "border"};
constexpr double kPctTol = 100.0 * 1.5 / 255.0;

TEST(WrapModes, EveryPixelsTexelIsTheSpecsFormula) {
  for (const char* range : {"1", "0.5", "2"}) {
    SCOPED_TRACE(range);
    Demo d("wrap_modes", {"--range", range});
    ts::Measurements m = d.measure();
    EXPECT_EQ(value(m, "wrap_texel_mismatches"), 0);
    for (const char* n : kNames) {
      EXPECT_EQ(value(m, std::string("texel_mismatches[") + n + "]"), 0) << n;
      EXPECT_EQ(value(m, std::string("npot_texel_mismatches[") + n + "]"), 0) << n;
    }
  }
}

// Seed 002's MIRROR against GL_MIRRORED_REPEAT: the demo counts GL's texel
// at every integer s in the range against the seed's; on the CPU the two
// formulas differ at exactly the integers (and agree between them), so the
// count must be the number of integers.
TEST(WrapModes, SeedMirrorDiffersAtIntegersOnly) {
  Demo d("wrap_modes", {"--range", "1"});
  ts::Measurements m = d.measure();
  int integers = 0, differ = 0;
  for (int k = -1; k <= 2; ++k) {
    ++integers;
    differ += wrap::seedMirrorTexel(k, 8) != wrap::nearestTexel(GL_MIRRORED_REPEAT, k, 8);
  }
  EXPECT_EQ(differ, integers);  // the opposite edge at every integer
  EXPECT_EQ(value(m, "seed_mirror_integers"), integers);
  EXPECT_EQ(value(m, "seed_mirror_differs"), differ);
  // Away from integers they agree (a fine sweep of u, not at texel edges).
  for (double s = -2.0; s < 3.0; s += 1.0 / 128 + 1e-4)
    if (std::abs(s - std::round(s)) > 1e-3)
      ASSERT_EQ(wrap::seedMirrorTexel(s, 8), wrap::nearestTexel(GL_MIRRORED_REPEAT, s, 8)) << s;
}

// The border colour's share with GL_LINEAR at s = -1/4, 0, 1, 5/4: from the
// render, against the formula; and the relations the figure is about.
TEST(WrapModes, BorderShareAtTheEdges) {
  Demo d("wrap_modes", {});
  ts::Measurements m = d.measure();
  const double probes[] = {-0.25, 0.0, 1.0, 1.25};
  const char* const probeNames[] = {"-0.25", "0", "1", "1.25"};
  for (int mode = 2; mode < 5; ++mode)
    for (int k = 0; k < 4; ++k) {
      std::string n = std::string("border_pct[") + kNames[mode] + "@" + probeNames[k] + "]";
      EXPECT_NEAR(value(m, n), 100.0 * wrap::borderShare(kModes[mode], probes[k], 8), kPctTol) << n;
    }
  // GL_CLAMP: half the border at the edges and outside; CLAMP_TO_EDGE none;
  // CLAMP_TO_BORDER all of it outside.
  EXPECT_GT(value(m, "border_pct[clamp@0]"), 40);
  EXPECT_LT(value(m, "border_pct[edge@0]"), 1);
  EXPECT_GT(value(m, "border_pct[border@1.25]"), 99);
}

// The picture: every pixel of the nearest row of the modes figure whose
// centre is not near a texel edge shows the texel the formula picks.
TEST(WrapModes, ModesFigureShowsTheFormulasTexels) {
  Demo d("wrap_modes", {"--view", "modes"});
  ts::Frame f;
  ts::Image img = d.render(1280, 640, &f);
  const ts::TextureDesc tex = ts::gradientTexture(8, 8);
  int checked = 0;
  for (int m = 0; m < 5; ++m) {
    const ts::Panel* p = f.panel(std::string(kNames[m]) + "_nearest");
    ASSERT_NE(p, nullptr);
    const double lo = -1, hi = 2;
    int bad = 0;
    for (int y = p->viewport.y + 2; y < p->viewport.y + p->viewport.h - 2; y += 3)
      for (int x = p->viewport.x + 2; x < p->viewport.x + p->viewport.w - 2; x += 3) {
        double s = lo + (hi - lo) * (x + 0.5 - p->viewport.x) / p->viewport.w;
        double t = lo + (hi - lo) * (p->viewport.y + p->viewport.h - y - 0.5) / p->viewport.h;
        double us = s * 8, ut = t * 8;
        // Skip texel edges and the lines of the integer grid and the square.
        if (std::abs(us - std::round(us)) < 0.2 || std::abs(ut - std::round(ut)) < 0.2) continue;
        int i = wrap::nearestTexel(kModes[m], s, 8), j = wrap::nearestTexel(kModes[m], t, 8);
        ts::Rgba want = i == wrap::kBorder || j == wrap::kBorder ? ts::Rgba{217, 26, 191, 255}
                                                                 // the border colour (0.85, 0.1, 0.75) in 8 bits
                                                                 : tex.image->at(i, j);
        ts::Rgba got = img.at(x, y);
        ++checked;
        bad += std::abs(got.r - want.r) > 1 || std::abs(got.g - want.g) > 1 || std::abs(got.b - want.b) > 1;
      }
    EXPECT_EQ(bad, 0) << kNames[m];
  }
  EXPECT_GT(checked, 5000);
}

// The texture matrix: the texel under probe points against M applied on the
// CPU, for several matrices; and the matrix must matter (the identity's
// texels differ from the rotated one's).
TEST(WrapModes, TextureMatrixAtProbes) {
  const std::vector<std::vector<std::string>> states = {
      {"--rotate", "30", "--scale", "1.5", "--shear", "0.25"},
      {"--shift", "0.375", "--shift-t", "-0.625", "--rotate", "-75"},
      {"--scale", "0.5", "--shear", "-1"},
  };
  for (const auto& s : states) {
    std::vector<std::string> flags = s;
    flags.insert(flags.begin(), {"--view", "matrix"});
    Demo d("wrap_modes", flags);
    ts::Measurements m = d.measure();
    EXPECT_EQ(value(m, "texture_matrix_mismatches"), 0) << s[1];
    EXPECT_GT(value(m, "texture_matrix_probes"), 40) << s[1];
  }
  // The figure's state: the right title (the matrix's parameters, named) is whole, the count printed is the
  // measurement, and the left picture's lines have a key.
  Demo fig("wrap_modes",
           {"--view", "matrix", "--rotate", "30", "--scale", "1.5", "--shear", "0.25", "--wrap-s", "mirrored"});
  fig.measure();
  const ts::Frame f = fig.frame(1024, 512);
  size_t given = 0, printed = 0;
  for (const ts::Label& l : f.labels) {
    EXPECT_EQ(l.text.find("..."), std::string::npos) << l.text;
    given += l.given.size(), printed += l.printed.size();
  }
  EXPECT_EQ(given, 5u) << "rotation, scale, shear and the two shifts";
  EXPECT_EQ(printed, 2u) << "mismatches and probes";
  EXPECT_EQ(f.legend.size(), 2u);
  wrap::TexTransform x;
  x.angleDeg = 30;
  glm::mat4 m = wrap::textureMatrix(x);
  glm::dvec2 c = wrap::transformST(m, 0.5, 0.5), e = wrap::transformST(m, 1.0, 0.5);
  EXPECT_NEAR(c.x, 0.5, 1e-6);  // about the centre
  EXPECT_NEAR(c.y, 0.5, 1e-6);
  EXPECT_NEAR(std::atan2(e.y - 0.5, e.x - 0.5) * 180 / M_PI, 30.0, 1e-4);
}
}  // namespace

namespace {
// The texture environments: each mode's result on the grid of fragment
// colours x texels x alphas against the table (0 beyond 8-bit rounding),
// and the highlight: GL_MODULATE can never be brighter than the brightest
// texel (Cf Ct <= Ct), GL_SEPARATE_SPECULAR_COLOR reaches white at the
// highlight's centre (specular 1 added after texturing, clamped).
TEST(WrapModes, TextureEnvironmentTableAndHighlight) {
  Demo d("wrap_modes", {"--view", "env"});
  ts::Measurements m = d.measure();
  EXPECT_EQ(value(m, "env_table_mismatches"), 0);
  for (const char* n : {"replace", "modulate", "decal", "blend", "add"})
    EXPECT_EQ(value(m, std::string("env_mismatches[") + n + "]"), 0) << n;
  const ts::TextureDesc tex = ts::gradientTexture(8, 8);
  double brightest = 0;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      ts::Rgba c = tex.image->at(i, j);
      brightest = std::max(brightest, (c.r + c.g + c.b) / (3.0 * 255.0));
    }
  EXPECT_LE(value(m, "highlight_peak[modulate]"), brightest + 2.0 / 255);
  EXPECT_GE(value(m, "highlight_peak[separate_specular]"), 0.98);
  EXPECT_GT(value(m, "highlight_peak[separate_specular]") - value(m, "highlight_peak[modulate]"), 0.2);
}
}  // namespace
