// demos/filter_zoo/filter_zoo_test.cpp — the filter zoo, rendered
// offscreen: the numbers measure() prints against their closed
// forms (computed here again), GL's filters against the exact area integral
// with margins, and the GL pictures against the homography they must show.
// The GL-free half (the CPU methods, the closed forms themselves) is
// tests/unit/zoo_test.cpp.  Every filtering number is printed with the
// renderer string: llvmpipe and softpipe differ in their LOD form and their
// anisotropic filter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/gl/render.hpp"
#include "demos/filter_zoo/filter_zoo_math.hpp"
#include "demos/filter_zoo/filter_zoo_measure.hpp"
#include "demos/filter_zoo/filter_zoo_views.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::Demo;
using ts::test::value;
using namespace zoo;

const ts::Measurements& defaults() {
  static ts::Measurements m = Demo("filter_zoo", {}).measure();
  return m;
}
double rms(const char* method, const char* az) {
  return value(defaults(), std::string("rms_exact[") + method + "@" + az + "]");
}

// Claim: read from texel-index renders (GL_NEAREST), 256 texels over 300
// pixels show 44 texels twice and 212 once; over 512 all 256 twice; over 200,
// 56 never.  (256 - 200 and 300 - 256: each pixel takes one texel, and no
// texel gets three pixels below 512.)
TEST(FilterZoo, MagnificationCountsReadFromGL) {
  const ts::Measurements& m = defaults();
  EXPECT_EQ(value(m, "mag_texels_twice[300]"), 300 - 256);
  EXPECT_EQ(value(m, "mag_texels_once[300]"), 256 - (300 - 256));
  EXPECT_EQ(value(m, "mag_texels_twice[512]"), 256);
  EXPECT_EQ(value(m, "min_texels_unseen[200]"), 256 - 200);
  // The render itself: the texel each pixel shows is floor((x + 1/2) 256 / W),
  // but where (x + 1/2) 256 / W is a whole number (a texel's edge exactly at
  // the pixel's centre: x = 12, 37, 62, ... over 200 pixels) GL's
  // interpolated s may land on either side; the counts hold either way.
  for (int w : {300, 512, 200}) {
    const std::vector<int> t = texelsShown(ts::test::renderer(), w);
    int bad = 0, ties = 0;
    for (int x = 0; x < w; ++x) {
      const bool tie = (2 * x + 1) * 128 % w == 0;
      ties += tie;
      const int want = int(std::floor((x + 0.5) * 256 / w));
      bad += tie ? t[size_t(x)] != want && t[size_t(x)] != want - 1 : t[size_t(x)] != want;
    }
    EXPECT_EQ(bad, 0) << w << " pixels (" << ties << " on a texel's edge)";
  }
}

// Claim: the memory and the seeds' numbers, printed as the closed forms give them.
TEST(FilterZoo, MemoryLevelsAndBits) {
  const ts::Measurements& m = defaults();
  EXPECT_NEAR(value(m, "ripmap_memory_ratio"), std::pow(2 - 1.0 / 256, 2), 1e-12);
  EXPECT_NEAR(value(m, "ripmap_memory_ratio"), 3.98439, 5e-6);
  EXPECT_NEAR(value(m, "mip_memory_ratio"), 4.0 / 3, 1e-4);
  EXPECT_EQ(value(m, "sat_bits[256]"), 24);
  EXPECT_EQ(value(m, "sat_bits[512]"), 26);
  EXPECT_EQ(value(m, "sat_bits[1024]"), 28);
  EXPECT_EQ(value(m, "sat_float_inexact[256]"), 0);
  EXPECT_GT(value(m, "sat_float_inexact[512]"), 0);
  EXPECT_EQ(value(m, "levels[32x64]"), 7);
  EXPECT_EQ(value(m, "levels_seed[32x64]"), 6);
  EXPECT_NEAR(value(m, "sat_box_ratio[8to1_45deg]"), 5.0625, 1e-12);
  EXPECT_NEAR(value(m, "sat_box_ratio[8to1_0deg]"), 1.0, 1e-12);
}

// Claim: log2(rho_edge / rho_max) = 0.5 at 45 degrees and 0 along the axes
// (the reference model); GL's trilinear filter reads a level that either
// stays put when the footprint turns (the edge form, llvmpipe) or drops by
// that 0.5 (the largest-component form, softpipe).
TEST(FilterZoo, TheTwoLodForms) {
  const ts::Measurements& m = defaults();
  EXPECT_NEAR(value(m, "lod_form_gap_45deg"), 0.5, 1e-12);
  EXPECT_NEAR(value(m, "lod_form_gap_0deg"), 0.0, 1e-12);
  const double drop = value(m, "lod_gl_drop_45deg");
  std::printf("[ lod form ] %s: level read at 0 deg %.3f, at 45 deg %.3f: %s form\n",
              ts::test::rendererString().c_str(), value(m, "lod_gl[0deg]"), value(m, "lod_gl[45deg]"),
              std::abs(drop) < 0.25 ? "edge" : "largest-component");
  // Either form, within llvmpipe's LOD arithmetic (0.043 level) and 8-bit quantisation.
  EXPECT_NEAR(value(m, "lod_gl[0deg]"), 2.5, 0.07);
  EXPECT_TRUE(std::abs(drop) < 0.07 || std::abs(drop - 0.5) < 0.07) << drop;
  if (ts::test::rendererString().find("llvmpipe") != std::string::npos) EXPECT_LT(std::abs(drop), 0.07);
}

// Claim: the GL pictures show the scene's homography exactly: a texel-index
// texture drawn with GL_NEAREST through viewFrame's projective coordinates
// takes, at every pixel whose (u, v) is not within 0.05 texel of a texel's
// edge, the texel floor(u, v) of the CPU's homography (the slanted plane,
// turned 22.5 degrees, up to LOD 8: the far field ends at LOD 5).
TEST(FilterZoo, GLDrawsTheHomography) {
  const View v = slantView(kImageW, kImageH, 22.5);
  ts::TextureDesc t = ts::texelIndexTexture(kTexels);
  t.minFilter = t.magFilter = GL_NEAREST;
  const ts::Image img = ts::test::renderer().renderOffscreen(viewFrame(v, t, backgroundColour()));
  long checked = 0, bad = 0;
  for (int row = 0; row < kImageH; ++row)
    for (int col = 0; col < kImageW; ++col) {
      if (!v.coversPixel(col, row)) continue;
      const glm::dvec2 uv = v.uv(col + 0.5, kImageH - 1 - row + 0.5);
      const double fu = uv.x - std::floor(uv.x), fv = uv.y - std::floor(uv.y);
      if (fu < 0.05 || fu > 0.95 || fv < 0.05 || fv > 0.95) continue;
      int i = 0, j = 0;
      ts::decodeTexelIndex(img.at(col, row), &i, &j);
      const int wi = ((int(std::floor(uv.x)) % kTexels) + kTexels) % kTexels,
                wj = ((int(std::floor(uv.y)) % kTexels) + kTexels) % kTexels;
      // Near the horizon (LOD 14, (u, v) ~ 30000 texels) GL's 32-bit floats
      // no longer hold a texel's position to 0.05: only the LOD <= 8 part counts.
      const double lod = std::log2(ts::lod::rhoExact(v.jacobian(col + 0.5, kImageH - 1 - row + 0.5)));
      if (lod > 8) continue;
      ++checked, bad += i != wi || j != wj;
    }
  EXPECT_GT(checked, 20000);
  EXPECT_EQ(bad, 0) << "of " << checked;
}

// Claim: against the exact integral, in the far field of the slanted plane,
// at every azimuth: GL_NEAREST and GL_LINEAR alias, trilinear over-blurs,
// GL's anisotropic filter does better, and the anisotropic methods of the
// CPU (ripmap, SAT, probe line) better than trilinear; the probe line best.
TEST(FilterZoo, MethodsAgainstTheExactIntegral) {
  std::printf("[ zoo      ] %s\n", ts::test::rendererString().c_str());
  for (const char* az : {"0", "22.5", "45"}) {
    SCOPED_TRACE(az);
    std::printf("[ zoo      ] %4s deg:", az);
    for (int m = kNearest; m < kMethodCount; ++m) std::printf(" %s %.2f", methodKey(m), rms(methodKey(m), az));
    std::printf("\n");
    EXPECT_GT(rms("nearest", az), 1.05 * rms("linear", az));
    EXPECT_GT(rms("linear", az), 1.5 * rms("trilinear", az));
    EXPECT_GT(rms("trilinear", az), 1.2 * rms("aniso16", az));
    EXPECT_GT(rms("trilinear", az), 1.3 * rms("ripmap", az));
    EXPECT_GT(rms("trilinear", az),
              1.1 * rms("sat", az));  // softpipe's largest-component LOD sharpens trilinear at 45: 1.17
    EXPECT_GT(rms("aniso16", az), 2.0 * rms("probes", az));
  }
}

// Claim (the shape box filters predict): ripmap and SAT lose as the texture
// turns from 0 to 45 degrees, the probe line and EWA stay nearly flat.
TEST(FilterZoo, AzimuthShape) {
  EXPECT_GT(rms("sat", "45"), 1.2 * rms("sat", "0"));
  EXPECT_GT(rms("ripmap", "45"), 1.12 * rms("ripmap", "0"));
  EXPECT_LT(rms("probes", "45"), 1.1 * rms("probes", "0"));
  EXPECT_LT(rms("ewa", "45"), 1.1 * rms("ewa", "0"));
  // GL's trilinear agrees with the CPU model of GL's rule (on llvmpipe within
  // 3 %: its LOD per 2x2 quad and its log2's approximation; 20 % allowed for
  // any rasterizer): the GL and CPU columns measure the same thing.
  const Pyramids& p = pyramids(kSlant, kChecker);
  const View v = slantView(kImageW, kImageH, 0);
  const std::vector<char> mask = farField(v, kFarLo, kFarHi);
  const double cpu = rmsAgainst(cpuPicture(kTrilinear, p, v, 0, mask).image,
                                exactPicture(kSlant, kChecker, 0, p)->exact, mask);
  EXPECT_NEAR(rms("trilinear", "0"), cpu, 0.2 * cpu);
}

// Claim: texels read per pixel, counted: nearest 1, bilinear 4, trilinear 8,
// ripmap and SAT 16, the probe line 8N, EWA about the ellipse's area; the
// exact integral weighs the texels under the preimage.
TEST(FilterZoo, TexelsReadPerPixel) {
  const ts::Measurements& m = defaults();
  EXPECT_EQ(value(m, "texels_per_pixel[nearest]"), 1);
  EXPECT_EQ(value(m, "texels_per_pixel[linear]"), 4);
  EXPECT_NEAR(value(m, "texels_per_pixel[trilinear]"), 8, 0.1);
  EXPECT_NEAR(value(m, "texels_per_pixel[ripmap]"), 16, 0.5);
  EXPECT_EQ(value(m, "texels_per_pixel[sat]"), 16);
  EXPECT_GT(value(m, "texels_per_pixel[probes]"), 16);
  EXPECT_GT(value(m, "texels_per_pixel[ewa]"), value(m, "texels_per_pixel[ripmap]"));
  EXPECT_GT(value(m, "texels_per_pixel[exact]"), 8);
  for (const auto& x : m) EXPECT_NE(x.name, "texels_per_pixel[aniso16]") << "GL's anisotropic filter cannot be counted";
}

// Claim: every kernel's 1x1 level of the checkerboard is its mean
// (taps summing to 1 keep it) but for the 8-bit rounding of each level: the
// mean of the board's two colours in sRGB values, and of their linear-light
// values encoded back (computed here from the colours), each chain's top
// within one 8-bit step of it.  Against the exact (box) integral the box
// chain is the closest under trilinear filtering, and Lanczos and Kaiser
// (sharper) are closer than the tent and the Gaussian (blurrier).
TEST(FilterZoo, MipKernels) {
  Demo d("filter_zoo", {"--view", "kernels", "--azimuth", "45"});
  const ts::Measurements m = d.measure();
  const ts::TextureDesc texture = sceneTexture(kSlant, kChecker);
  const ts::Image& board = *texture.image;
  const ts::Rgba a = board.at(0, 0), b = board.at(board.width - 1, 0);  // 8 checks: the two ends differ
  ASSERT_FALSE(a == b);
  auto decode = [](double v) {
    const double c = v / 255;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  auto encode = [](double l) { return 255 * (l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1 / 2.4) - 0.055); };
  const double srgbMean = (a.r + b.r) / 2.0, linearMean = encode((decode(a.r) + decode(b.r)) / 2);
  EXPECT_NEAR(value(m, "mip_mean[srgb]"), srgbMean, 1e-9);
  EXPECT_NEAR(value(m, "mip_mean[linear]"), linearMean, 1e-9);
  for (const char* domain : {"srgb", "linear"}) {
    const double mean = value(m, std::string("mip_mean[") + domain + "]");
    double worst = 0;
    for (int k = 0; k < kKernelCount; ++k) {
      const double top = value(m, std::string("mip_top[") + kernelKey(k) + "_" + domain + "]");
      EXPECT_NEAR(top, mean, 1.0) << kernelKey(k) << " " << domain;
      worst = std::max(worst, std::abs(top - mean));
    }
    EXPECT_NEAR(value(m, std::string("mip_top_max_error[") + domain + "]"), worst, 1e-12) << domain;
  }
  for (int k = 0; k < kKernelCount; ++k) {
    SCOPED_TRACE(kernelKey(k));
    if (k != kBox)
      EXPECT_GT(value(m, std::string("rms_kernel[") + kernelKey(k) + "_srgb]"), 1.2 * value(m, "rms_kernel[box_srgb]"));
  }
  for (const char* sharp : {"lanczos2", "lanczos3", "kaiser"})
    for (const char* soft : {"tent", "gaussian"})
      EXPECT_LT(1.2 * value(m, std::string("rms_kernel[") + sharp + "_srgb]"),
                value(m, std::string("rms_kernel[") + soft + "_srgb]"))
          << sharp << " vs " << soft;
}

// Claim (seed 001 ¶13): a positive LOD bias blurs (the far field's
// error grows) and flickers less on a moving plane; a negative one sharpens
// and flickers more.
TEST(FilterZoo, LodBias) {
  Demo d("filter_zoo", {"--view", "bias"});
  const ts::Measurements m = d.measure();
  EXPECT_GT(value(m, "rms_bias[1]"), 1.5 * value(m, "rms_bias[0]"));
  EXPECT_GT(value(m, "flicker[-1]"), 1.2 * value(m, "flicker[0]"));
  EXPECT_GT(value(m, "flicker[0]"), 1.2 * value(m, "flicker[1]"));
  for (const char* b : {"-1", "-0.5", "0", "0.5"}) {
    const double next = std::stod(b) + 0.5;
    EXPECT_GT(value(m, std::string("flicker[") + b + "]"), value(m, "flicker[" + ts::layout::fmt("%g", next) + "]"))
        << b;
  }
}

// Claim: the supports figure's pixel lies in the far field of the plane, its
// footprint long and thin (so the supports differ), and the frame draws every
// support.
TEST(FilterZoo, SupportsFigure) {
  Demo d("filter_zoo", {"--view", "supports", "--azimuth", "45", "--pick", "250,100"});
  const View v = slantView(kImageW, kImageH, 45);
  const Jacobian j = v.jacobian(250.5, kImageH - 1 - 100 + 0.5);
  const double lambda = std::log2(ts::lod::rhoExact(j));
  EXPECT_GT(lambda, kFarLo);
  EXPECT_LT(lambda, kFarHi);
  EXPECT_GT(satBoxRatio(j), 2.0);
  d.measure();
  const ts::Frame f = d.frame(1200, 640);
  const ts::Panel& p = ts::test::panelOf(f, "supports");
  std::vector<std::string> roles;
  for (const ts::Batch& b : p.batches) roles.push_back(b.role);
  for (const char* r : {"exact_preimage", "trilinear_square", "ripmap_rectangle", "sat_box", "probe", "ewa_ellipse"})
    EXPECT_NE(std::find(roles.begin(), roles.end(), r), roles.end()) << r;
}
// Claim: each figure's number is its measurement.  Two methods whose
// pictures differ over the far field (the pixels the RMS is taken over)
// cannot share an RMS to 1e-6: an equal pair would be the same picture
// measured twice, or a mask that misses where they differ.  (Pictures that
// differ only outside the far field may share it: see the next test.)
TEST(FilterZoo, DifferentPicturesHaveDifferentErrors) {
  const Result* res = defaults().detailAs<Result>();
  ASSERT_NE(res, nullptr);
  int checked = 0;
  for (const char* az : {"0", "22.5", "45"}) {
    const Row* row = nullptr;
    for (const Row& r : res->rows)
      if (azKey(r.azimuth) == az) row = &r;
    ASSERT_NE(row, nullptr) << az;
    const View v = slantView(kImageW, kImageH, row->azimuth);
    const std::vector<char> mask = farField(v, kFarLo, kFarHi);
    // The pictures are textures, row 0 at the bottom: image row y is the view's row H - 1 - y.
    auto differ = [&](int a, int b) {
      const ts::Image &p = *row->pictures[size_t(a)].image, &q = *row->pictures[size_t(b)].image;
      for (int y = 0; y < kImageH; ++y)
        for (int x = 0; x < kImageW; ++x)
          if (mask[size_t(kImageH - 1 - y) * kImageW + size_t(x)] && !(p.at(x, y) == q.at(x, y))) return true;
      return false;
    };
    for (int a = kNearest; a < kMethodCount; ++a)
      for (int b = a + 1; b < kMethodCount; ++b) {
        if (!differ(a, b)) continue;
        ++checked;
        EXPECT_GT(std::abs(rms(methodKey(a), az) - rms(methodKey(b), az)), 1e-6)
            << methodKey(a) << " vs " << methodKey(b) << " at " << az;
      }
  }
  EXPECT_GT(checked, 0);
}

// Claim: GL_NEAREST_MIPMAP_NEAREST's far-field error is GL_NEAREST's, by the
// texture, not by the measurement.  The checkerboard's checks are 256 / 8 =
// 32 texels, so box levels 1..5 (checks 16 .. 1 texel) are the same board:
// a nearest sample in level k <= 5 takes level 0's colour.  The filter reads
// level round(lambda), so the two pictures can differ only where lambda >
// 5.5 (GL's LOD within 0.07 of the exact one, TheTwoLodForms), beyond the
// far field's LOD 5: there they do differ, in the far field they cannot.
TEST(FilterZoo, NearestMipNearestIsNearestOverTheFarField) {
  const ts::Measurements& m = defaults();
  const ts::TextureDesc texture = sceneTexture(kSlant, kChecker);
  const ts::Image& board = *texture.image;
  int check = 1;
  while (check < board.width && board.at(check, 0) == board.at(0, 0)) ++check;
  const int last = int(std::round(std::log2(check)));
  EXPECT_EQ(1 << last, check);
  EXPECT_EQ(value(m, "last_level_like_level0"), last);
  EXPECT_GT(last + 0.5, kFarHi) << "the far field reaches levels that are no longer the board";
  EXPECT_EQ(value(m, "nmn_nearest_differ_far"), 0);
  const double from = value(m, "nmn_nearest_differ_lod_min");
  EXPECT_TRUE(std::isfinite(from)) << "the pictures must differ somewhere (beyond the far field)";
  EXPECT_GT(from, last + 0.5 - 0.07);
  for (const char* az : {"0", "22.5", "45"}) EXPECT_NEAR(rms("nmn", az), rms("nearest", az), 1e-9) << az;
}

// The four book figures print their numbers from the measurements (each
// printed label formats its measurement's value again to the text it
// shows), name every colour that carries meaning in a legend, and print
// no renderer string (the sidecar records it).
TEST(FilterZoo, FiguresPrintTheirMeasurements) {
  for (const ts::FigureSpec& spec : zoo::views::figureSpecs()) {
    SCOPED_TRACE(spec.id);
    Demo d("filter_zoo", spec.flags);
    const ts::Measurements m = d.measure();
    const ts::Frame f = d.frame(spec.width, spec.height);
    std::vector<std::string> shown;
    for (const ts::Label& l : f.labels) {
      // A label that shows a number says where it comes from: a measurement or a given value.
      if (std::any_of(l.text.begin(), l.text.end(), [](char c) { return c >= '0' && c <= '9'; }))
        EXPECT_TRUE(!l.printed.empty() || !l.given.empty()) << "\"" << l.text << "\" prints a number of unknown origin";
      EXPECT_EQ(l.text.find("llvmpipe"), std::string::npos) << l.text;
      EXPECT_EQ(l.text.find("LLVM"), std::string::npos) << l.text;
      for (const ts::Label::Printed& p : l.printed) {
        char b[64];
        std::snprintf(b, sizeof b, p.format.c_str(), value(m, p.name));
        EXPECT_EQ(p.text, b) << p.name;
        EXPECT_NE(l.text.find(p.text), std::string::npos) << l.text << " should show " << p.name;
        shown.push_back(p.name);
      }
    }
    auto printedAll = [&](const std::vector<std::string>& names) {
      for (const std::string& n : names)
        EXPECT_NE(std::find(shown.begin(), shown.end(), n), shown.end()) << n << " is not printed";
    };
    EXPECT_FALSE(f.legend.empty()) << "colours that carry meaning are named";
    if (spec.id == "filter_zoo_azimuth") {
      for (const char* az : {"0", "22.5", "45"})
        for (int k = kNearest; k < kMethodCount; ++k)
          printedAll({std::string("rms_exact[") + methodKey(k) + "@" + az + "]"});
      printedAll({"last_level_like_level0", "nmn_nearest_differ_far", "nmn_nearest_differ_lod_min"});
    } else if (spec.id == "filter_zoo_supports") {
      printedAll({"sat_box_ratio[8to1_45deg]", "pick_sat_box_ratio", "pick_preimage_texels", "pick_probes"});
      EXPECT_EQ(f.legend.size(), 8u) << "six supports, the ring and the texel grid";
    } else if (spec.id == "filter_zoo_memory") {
      printedAll({"mip_memory_ratio", "ripmap_memory_ratio", "sat_bits[256]", "sat_memory_ratio"});
      // Every plotted method is named by a tag.
      for (int k = kNearest; k < kMethodCount; ++k) {
        const std::string tag = k == kAniso16 ? "aniso 16x" : methodKey(k);
        EXPECT_TRUE(std::any_of(f.labels.begin(), f.labels.end(), [&](const ts::Label& l) { return l.text == tag; }))
            << tag;
      }
      EXPECT_EQ(f.legend.size(), 2u) << "0 and 45 degrees";
    } else if (spec.id == "mip_kernels") {
      for (int k = 0; k < kKernelCount; ++k)
        for (const char* domain : {"_srgb", "_linear"})
          printedAll({std::string("mip_top[") + kernelKey(k) + domain + "]",
                      std::string("rms_kernel[") + kernelKey(k) + domain + "]"});
      printedAll({"mip_mean[srgb]", "mip_mean[linear]", "mip_top_max_error[srgb]", "mip_top_max_error[linear]"});
    }
  }
}

// A window's measurement (ts::measureStage): a first stage with GL's
// pictures and the CPU methods' coarse, no numbers; a second with the
// current azimuth's row whole, the result's.  That row's CPU work runs on a
// thread of its own beside the first stage, keeping to one thread until the
// stage is handed over (RowShare): its pictures, RMS and reads are those
// computed here again, one call at a time without the kept copies.  At
// azimuth 30, which nothing else in this program measures, the staged
// measurement computes the row itself.
TEST(Stage, TheSecondStageIsTheCurrentRowAsTheSerialWorkMakesIt) {
  Demo staged("filter_zoo", {"--azimuth", "30"});
  const std::vector<ts::Measurements> stages = ts::test::measureInStages(staged);
  ASSERT_EQ(stages.size(), 2u);
  const Result *result = staged.measured.detailAs<Result>(), *first = stages[0].detailAs<Result>(),
               *second = stages[1].detailAs<Result>();
  ASSERT_TRUE(result && first && second);
  const Row &row = result->rows[size_t(result->current)], &one = first->rows[size_t(first->current)],
            &two = second->rows[size_t(second->current)];
  ASSERT_EQ(row.azimuth, 30.0);
  const Pyramids& p = pyramids(kSlant, kChecker);
  const View v = sceneView(kSlant, 30);
  const std::vector<char> mask = sceneMask(kSlant, v);
  const Picture exact = cpuPicture(kExact, p, v, 0, mask, kBackground);
  for (int m = 0; m < kMethodCount; ++m) {
    SCOPED_TRACE(methodKey(m));
    const size_t k = size_t(m);
    EXPECT_EQ(two.rms[k], row.rms[k]);
    EXPECT_EQ(two.reads[k], row.reads[k]);
    EXPECT_EQ(two.pictures[k].image->pixels, row.pictures[k].image->pixels);
    EXPECT_TRUE(std::isnan(one.rms[k]) && std::isnan(one.reads[k])) << "the first stage has no numbers";
    if (byGL(m)) {
      EXPECT_EQ(one.pictures[k].image->pixels, row.pictures[k].image->pixels) << "GL's pictures come whole at once";
      EXPECT_EQ(row.reads[k], texelsPerPixel(m, p, v, 0, mask));
      continue;
    }
    const Picture alone = m == kExact ? exact : cpuPicture(m, p, v, 0, mask, kBackground);
    EXPECT_EQ(row.pictures[k].image->pixels, pictureTexture(alone.image, methodKey(m), kSlant, 30).image->pixels);
    EXPECT_NE(one.pictures[k].image->width, alone.image.width) << "the first stage's CPU pictures are coarse";
    EXPECT_EQ(row.reads[k], m == kExact ? exactTexels(v, mask) : alone.meanReads);
    if (m != kExact) EXPECT_EQ(row.rms[k], rmsAgainst(alone.image, exact.exact, mask));
  }
  EXPECT_TRUE(RowShare::get().isOpen());
}

// Superseded after its first stage, while the row's CPU work runs beside it:
// the measurement ends (the work is waited for, not left running) and
// parallelRows has both threads again.
TEST(Stage, SupersededAfterTheFirstStageItEndsAndSharesTheRowsAgain) {
  Demo d("filter_zoo", {"--azimuth", "60"});
  const std::vector<ts::Measurements> stages = ts::test::measureInStages(d, 1);
  EXPECT_EQ(stages.size(), 1u);
  EXPECT_TRUE(RowShare::get().isOpen());
}
}  // namespace
