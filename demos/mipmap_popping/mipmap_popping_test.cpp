// demos/mipmap_popping/mipmap_popping_test.cpp — Section VI.1.3 (mipmapping and
// popping), rendered offscreen and checked against the mathematics of
// demos/mipmap_popping/mipmap_popping_math.hpp, never against a stored image:
//   * the mip chain GL samples is the book's 2x2 average and costs ~1/3;
//   * with coloured levels, the level GL used at every probe is the level the
//     analytic derivatives give (GL 4.6 §8.14), allowing the neighbouring
//     level only within kBoundaryMargin of a level boundary — the way
//     conformance tests allow for an implementation's LOD arithmetic;
//   * the popping measure of GL_NEAREST_MIPMAP_NEAREST is several times that
//     of GL_LINEAR_MIPMAP_LINEAR, and it is the level switch that makes it;
//   * against a supersampled reference the far field's error falls from
//     GL_NEAREST to trilinear to anisotropic.
// Every filtering number is printed with the renderer string (docs/platform.md:
// llvmpipe's anisotropic filter is EWA on one level; softpipe's LOD and
// llvmpipe's differ).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/gl/gl.hpp"
#include "common/core/image.hpp"
#include "common/core/probe.hpp"
#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "demos/mipmap_popping/mipmap_popping_math.hpp"
#include "demos/mipmap_popping/mipmap_popping_sweep.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using namespace mipmap;

// Within this many levels of a level boundary (k + 1/2 for the
// MIPMAP_NEAREST filters) either neighbouring level is legal.  It covers
// llvmpipe's LOD arithmetic: lambda = log2(rho^2)/2 with a log2 that is
// linear between powers of two, at most 0.043 levels below the exact value
// (measured: the blend weight at LOD 0.375 reads 0.341).
constexpr double kBoundaryMargin = 1.0 / 16;
// The blend weight of *_MIPMAP_LINEAR read back from the colours may differ
// from frac(lambda) by the same LOD error plus 8-bit quantisation.
constexpr double kBlendTolerance = 0.06;

std::string renderer() { return ts::test::rendererString(); }

using ts::test::Demo;
using ts::test::value;

// The default state's measurement, shared by the tests that read it (on
// softpipe one measure() takes seconds).
const ts::Measurements& defaultMeasurement() {
  static ts::Measurements m = Demo("mipmap_popping", {}).measure();
  return m;
}

// Which coloured level a pixel shows: the level whose colour is within the
// channel tolerance, or -1 (a blend or something else).
int levelOfPixel(ts::Rgba c) {
  for (int k = 0; k < kLevels; ++k)
    if (ts::probe::close(c, ts::mipLevelColour(k), ts::probe::tolerance(8))) return k;
  return -1;
}

// Levels a MIPMAP_NEAREST filter may legally use for lambda in [lo, hi],
// widened by the boundary margin.
std::vector<int> legalLevels(double lo, double hi) {
  std::vector<int> out;
  for (int k = nearestLevel(lo - kBoundaryMargin); k <= nearestLevel(hi + kBoundaryMargin); ++k) out.push_back(k);
  return out;
}
bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

// ---------------------------------------------------------------------------
// Claim: level k+1 is the 2x2 average of level k (in sRGB values, or in
// linear light with --linear-light), and it is that chain GL samples: each
// level read back from GL equals ts::buildMipChain's, which is the book's
// average texel by texel.
TEST(MipmapPopping, GLSamplesTheBooks2x2AverageChain) {
  for (bool linear : {false, true}) {
    SCOPED_TRACE(linear ? "linear light" : "sRGB values");
    mipmap::Look l;
    l.linearLight = linear;
    ts::TextureDesc t = mipmap::texture(l);
    ASSERT_TRUE(t.mipmaps);
    ASSERT_FALSE(t.mipLevels) << "the chain must be the 2x2 average, not explicit levels";
    EXPECT_EQ(t.linearLightMips, linear);
    std::vector<ts::Image> chain = ts::buildMipChain(*t.image, linear);
    ASSERT_EQ(int(chain.size()), kLevels);
    // The book's average, recomputed here for a few hundred texels.
    auto dec = [](int v) {
      double c = v / 255.0;
      return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    auto enc = [](double c) {
      double v = c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
      return int(std::lround(std::clamp(v, 0.0, 1.0) * 255));
    };
    long checked = 0, bad = 0;
    for (int k = 0; k + 1 < kLevels; ++k)
      for (int j = 0; j < chain[size_t(k) + 1].height; j += 3)
        for (int i = 0; i < chain[size_t(k) + 1].width; i += 5) {
          const ts::Image& a = chain[size_t(k)];
          ts::Rgba q[4] = {a.at(2 * i, 2 * j), a.at(2 * i + 1, 2 * j), a.at(2 * i, 2 * j + 1),
                           a.at(2 * i + 1, 2 * j + 1)};
          ts::Rgba got = chain[size_t(k) + 1].at(i, j);
          for (int c = 0; c < 3; ++c) {
            auto ch = [c](ts::Rgba p) { return c == 0 ? p.r : c == 1 ? p.g : p.b; };
            int want = linear ? enc((dec(ch(q[0])) + dec(ch(q[1])) + dec(ch(q[2])) + dec(ch(q[3]))) / 4)
                              : (ch(q[0]) + ch(q[1]) + ch(q[2]) + ch(q[3]) + 2) / 4;
            ++checked;
            bad += std::abs(int(ch(got)) - want) > (linear ? 1 : 0);
          }
        }
    EXPECT_GT(checked, 3000);
    EXPECT_EQ(bad, 0) << bad << " of " << checked << " channels are not the 2x2 average";

    // What GL holds is that chain.
    ts::test::context();
    GLuint id = ts::test::renderer().texture(t);
    ASSERT_NE(id, 0u);
    for (int k = 0; k < kLevels; ++k) {
      ts::Image gl(chain[size_t(k)].width, chain[size_t(k)].height);
      glPixelStorei(GL_PACK_ALIGNMENT, 1);
      glGetTexImage(GL_TEXTURE_2D, k, GL_RGBA, GL_UNSIGNED_BYTE, gl.pixels.data());
      EXPECT_TRUE(gl.pixels == chain[size_t(k)].pixels) << "level " << k << " in GL differs from the CPU chain";
    }
  }
}

// Claim: the chain costs about one third more memory: exactly
// (1 - 4^-8)/3 for 256 x 256, and the demo prints it.
TEST(MipmapPopping, ChainCostsAboutAThird) {
  const ts::Measurements& m = defaultMeasurement();
  double want = (1.0 - std::pow(4.0, -8)) / 3.0;
  EXPECT_NEAR(value(m, "mip_overhead"), want, 1e-9);
  EXPECT_LT(value(m, "mip_overhead"), 1.0 / 3.0);
  EXPECT_EQ(value(m, "mip_levels"), 9.0);
  // Negative control: the sum it is measured from changes with the chain
  // (a chain cut after level 1 costs 1/4).
  std::vector<ts::Image> two = ts::buildMipChain(ts::Image(256, 256));
  two.resize(2);
  EXPECT_NEAR(ts::mipChainOverhead(two), 0.25, 1e-12);
}

// Claim: averaging in linear light (gamma-correct) makes the distant
// average brighter than averaging sRGB values: the checkerboard's 1x1 level
// is (32 + 224)/2 = 128 in sRGB values and encode((dec 32 + dec 224)/2) =
// 166 in linear light, and the demo prints the level it built.
TEST(MipmapPopping, LinearLightAveragesAreBrighter) {
  auto dec = [](double v) {
    double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  double lin = (dec(32) + dec(224)) / 2;
  double want = 255 * (1.055 * std::pow(lin, 1 / 2.4) - 0.055);
  Demo srgb("mipmap_popping", {"--pattern", "checker"});
  Demo linear("mipmap_popping", {"--pattern", "checker", "--linear-light"});
  std::vector<ts::Image> a = ts::buildMipChain(*mipmap::texture({kNearestMipNearest, 16, 0, 1, false}).image, false);
  std::vector<ts::Image> b = ts::buildMipChain(*mipmap::texture({kNearestMipNearest, 16, 0, 1, true}).image, true);
  EXPECT_EQ(a.back().at(0, 0).r, 128);
  EXPECT_NEAR(b.back().at(0, 0).r, want, 2.0);
  EXPECT_GT(want, 150.0);
  // The demo's frames carry the flag to the renderer.
  ts::Frame fs = srgb.frame(256, 128), fl = linear.frame(256, 128);
  ASSERT_FALSE(fs.textures.empty());
  EXPECT_FALSE(fs.textures[0].linearLightMips);
  EXPECT_TRUE(fl.textures[0].linearLightMips);
  EXPECT_NE(fs.textures[0].key(), fl.textures[0].key()) << "the two chains must not share a GL texture";
}

// ---------------------------------------------------------------------------
// The facing plane at many distances (1/32 level apart, LOD -1 .. 7.5) and
// three LOD biases: the LOD from the analytic derivatives (mipmap_popping_math.hpp:
// planeAt, the ray-plane Jacobian, not the closed form) against the level
// whose colour every pixel of the 32 x 32 probe shows.
struct SweepCheck {
  long cells = 0, pixels = 0, bad = 0, allowance = 0;
  std::string first;
};
SweepCheck checkFacingSweep(int filter, float bias, double shift = 0) {
  mipmap::Look l;
  l.filter = filter;
  l.lodBias = bias;
  std::vector<double> lods = mipmap::sweepLods(kMinLog2, kMaxLog2, 1.0 / 32);
  ts::Frame f = mipmap::sweepFrame(l, lods);
  ts::Image img = ts::test::renderer().renderOffscreen(f);
  SweepCheck r;
  for (size_t k = 0; k < lods.size(); ++k) {
    const ts::Rect& vp = f.panels[k].viewport;
    double d = facingDistance(lods[k]);
    Jacobian j;
    if (!planeAt(facingCamera(vp.w, vp.h, d), facingPlane(d), vp.w / 2.0, vp.h / 2.0, nullptr, &j)) {
      ADD_FAILURE() << "the ray misses the facing plane";
      return r;
    }
    double lo = 0, hi = 0;
    rhoBounded(j, &lo, &hi);
    double lambda = std::log2(rhoExact(j)) + bias + shift;
    std::vector<int> legal = legalLevels(std::log2(lo) + bias + shift, std::log2(hi) + bias + shift);
    ++r.cells;
    bool allowance = false;
    for (int y = vp.y; y < vp.y + vp.h; ++y)
      for (int x = vp.x; x < vp.x + vp.w; ++x) {
        int got = levelOfPixel(img.at(x, y));
        ++r.pixels;
        if (!contains(legal, got)) {
          if (r.bad++ == 0) {
            char b[200];
            std::snprintf(b, sizeof b, "LOD %.4f: pixel shows level %d, the analytic LOD gives level %d", lambda, got,
                          nearestLevel(lambda));
            r.first = b;
          }
        } else if (got != nearestLevel(lambda)) {
          allowance = true;
        }
      }
    r.allowance += allowance;
  }
  return r;
}

// Claim: with coloured levels a MIPMAP_NEAREST filter shows, at every
// distance, the level GL's rule gives for the LOD of the analytic
// derivatives (log2 of texels per pixel, plus the bias): the neighbouring
// level appears only within kBoundaryMargin of a boundary k + 1/2.
TEST(MipmapPopping, FacingPlaneShowsTheAnalyticLevel) {
  std::printf("[ info ] renderer: %s\n", renderer().c_str());
  for (int filter : {kNearestMipNearest, kLinearMipNearest})
    for (float bias : {0.0f, 1.0f, -0.5f}) {
      SCOPED_TRACE(std::string(filterName(filter)) + " bias " + std::to_string(bias));
      SweepCheck r = checkFacingSweep(filter, bias);
      // Every 1/32 of a level from kMinLog2 to kMaxLog2, both ends included.
      EXPECT_EQ(r.cells, long(std::lround((kMaxLog2 - kMinLog2) * 32)) + 1);
      EXPECT_EQ(r.bad, 0) << r.bad << " of " << r.pixels << " pixels: " << r.first;
      // The allowance is used only near boundaries: at most the cells within
      // the margin (2 per boundary at 1/32 steps, 8 boundaries).
      EXPECT_LE(r.allowance, 16) << "cells that needed the neighbouring level";
      std::printf("[ info ] %s bias %+.1f: %ld cells, %ld pixels, all at the analytic level; %ld cells used the "
                  "neighbour within %.4f of a boundary\n",
                  filterName(filter), bias, r.cells, r.pixels, r.allowance, kBoundaryMargin);
    }
}

// Negative control: the same renders checked against an LOD one level off
// (or half a level) fail almost everywhere, so the check above can fail.
TEST(MipmapPopping, FacingPlaneCheckFailsForAWrongLod) {
  for (double shift : {1.0, -1.0, 0.5}) {
    SCOPED_TRACE("LOD shifted by " + std::to_string(shift));
    SweepCheck r = checkFacingSweep(kNearestMipNearest, 0, shift);
    EXPECT_GT(r.bad, r.pixels / 3) << r.bad << " of " << r.pixels;
  }
}

// Claim: a MIPMAP_LINEAR filter blends levels floor(lambda) and
// floor(lambda) + 1 with weight frac(lambda): the colour read back as
// k + weight follows the analytic LOD (within kBlendTolerance), and is
// level 0 when magnified (lambda <= 0) and the last level past it.
TEST(MipmapPopping, TrilinearBlendWeightIsTheFractionOfTheLod) {
  for (int filter : {kLinearMipLinear, kNearestMipLinear}) {
    SCOPED_TRACE(filterName(filter));
    mipmap::Look l;
    l.filter = filter;
    std::vector<double> lods = mipmap::sweepLods(kMinLog2, kMaxLog2, 1.0 / 32);
    std::vector<Mean> means = mipmap::probeSweep(ts::test::renderer(), l, lods);
    double worst = 0, worstAt = 0, worstResidual = 0;
    for (size_t k = 0; k < lods.size(); ++k) {
      double residual = 0;
      double got = levelFromColour(means[k], kLevels, &residual);
      double want = effectiveLevel(filter, lods[k]);
      if (std::abs(got - want) > worst) worst = std::abs(got - want), worstAt = lods[k];
      worstResidual = std::max(worstResidual, residual);
    }
    EXPECT_LE(worst, kBlendTolerance) << "at LOD " << worstAt;
    // The colours are blends of two neighbouring level colours (nothing else).
    EXPECT_LE(worstResidual, 3.0);
    std::printf("[ info ] %s: blend weight within %.4f of frac(LOD) (worst at LOD %.4f) on %s\n", filterName(filter),
                worst, worstAt, renderer().c_str());
  }
}

// ---------------------------------------------------------------------------
// Claim: on a plane seen at a slant the LOD changes from pixel to pixel, and
// each pixel shows the level of its own analytic derivatives.  Allowed per
// pixel: rho from max(mu, mv) (softpipe: the largest component) to the exact
// length (llvmpipe), over the pixel's 2x2 quad (llvmpipe computes one LOD per
// quad), then kBoundaryMargin.  (GL would allow up to mu + mv; the check
// keeps to what the two Mesa rasterisers do, so it stays a sharp one.)
struct SlantCheck {
  long checked = 0, bad = 0, allowance = 0, levelsSeen = 0;
  std::string first;
};
SlantCheck checkSlant(int filter, double shift) {
  const int w = mipmap::kSlantW, h = mipmap::kSlantH;
  mipmap::Look l;
  l.filter = filter;
  ts::Image img = ts::test::renderer().renderOffscreen(mipmap::slantFrame(l, mipmap::kColoured, w, h));
  Camera cam = slantCamera(w, h);
  Plane ground = groundPlane();
  // LOD interval at GL pixel (x, y) (y up).
  auto interval = [&](int x, int y, double* lo, double* hi, double* exact) {
    Jacobian j;
    glm::dvec2 ab;
    if (!planeAt(cam, ground, x + 0.5, y + 0.5, &ab, &j)) return false;
    if (std::abs(ab.x) > 0.9 * kGroundHalfWidth || ab.y > 0.5 * kGroundDepth) return false;
    double a = 0, b = 0;
    rhoBounded(j, &a, &b);
    *lo = std::log2(a), *hi = std::log2(b), *exact = std::log2(rhoExact(j));
    return true;
  };
  SlantCheck r;
  std::vector<bool> seen(kLevels, false);
  for (int gy = 0; gy < h; ++gy)
    for (int gx = 0; gx < w; ++gx) {
      double lo = 1e9, hi = -1e9, exact = 0;
      bool ok = true;
      // The pixel's aligned 2x2 quad.
      for (int qy = gy & ~1; qy <= (gy | 1) && ok; ++qy)
        for (int qx = gx & ~1; qx <= (gx | 1) && ok; ++qx) {
          double a, b, e;
          if (!interval(qx, qy, &a, &b, &e)) ok = false;
          lo = std::min(lo, a), hi = std::max(hi, b);
          if (qx == gx && qy == gy) exact = e;
        }
      if (!ok) continue;
      int got = levelOfPixel(img.at(gx, h - 1 - gy));
      std::vector<int> legal = legalLevels(lo + shift, hi + shift);
      ++r.checked;
      if (got >= 0) seen[size_t(got)] = true;
      if (!contains(legal, got)) {
        if (r.bad++ == 0) {
          char b[200];
          std::snprintf(b, sizeof b, "GL pixel (%d, %d): level %d, LOD %.3f (allowed %.3f .. %.3f)", gx, gy, got,
                        exact + shift, lo + shift, hi + shift);
          r.first = b;
        }
      } else if (got != nearestLevel(exact + shift)) {
        ++r.allowance;
      }
    }
  r.levelsSeen = std::count(seen.begin(), seen.end(), true);
  return r;
}

TEST(MipmapPopping, SlantedPlaneShowsEachPixelsAnalyticLevel) {
  for (int filter : {kNearestMipNearest, kLinearMipNearest}) {
    SCOPED_TRACE(filterName(filter));
    SlantCheck r = checkSlant(filter, 0);
    EXPECT_GT(r.checked, 30000);
    EXPECT_EQ(r.bad, 0) << r.bad << " of " << r.checked << ": " << r.first;
    EXPECT_GE(r.levelsSeen, 5) << "the slant should span several levels";
    // The allowance is the exception: pixels near a boundary or where the
    // quad's LOD differs from the pixel's.
    EXPECT_LT(r.allowance, r.checked / 10);
    std::printf("[ info ] slant, %s: %ld pixels, %ld levels, all legal; %ld (%.1f%%) show the neighbouring level "
                "allowed near a boundary (%s)\n",
                filterName(filter), r.checked, r.levelsSeen, r.allowance, 100.0 * r.allowance / std::max(1L, r.checked),
                renderer().c_str());
  }
}

// Negative control: against an LOD shifted by one level the same check
// fails on most pixels.
TEST(MipmapPopping, SlantedPlaneCheckFailsForAWrongLod) {
  SlantCheck r = checkSlant(kNearestMipNearest, 1.0);
  EXPECT_GT(r.bad, r.checked / 2) << r.bad << " of " << r.checked;
}

// ---------------------------------------------------------------------------
// Claim (the popping measure): the largest jump of the probe's mean colour
// between distances 1/16 level apart is several times larger with one level
// per pixel than with two blended: NEAREST_MIPMAP_NEAREST >= 4 x
// LINEAR_MIPMAP_LINEAR, and LINEAR_MIPMAP_NEAREST >= 4 x
// NEAREST_MIPMAP_LINEAR.  Quantitatively: a MIPMAP_NEAREST jump is (at
// least half of: at a tie k + 1/2 llvmpipe splits the probe between the two
// levels) a whole level change of the coloured levels; a MIPMAP_LINEAR jump
// is at most the largest level change times 1/16 times the blend's slope
// (1, or up to 2 ln 2 = 1.39 with llvmpipe's piecewise-linear log2).
TEST(MipmapPopping, PoppingOfNearestMipIsSeveralTimesTrilinear) {
  const ts::Measurements& m = defaultMeasurement();
  double nmn = value(m, "popping[nearest_mipmap_nearest]"), lml = value(m, "popping[linear_mipmap_linear]");
  double lmn = value(m, "popping[linear_mipmap_nearest]"), nml = value(m, "popping[nearest_mipmap_linear]");
  std::printf("[ info ] popping: NMN %.1f LMN %.1f NML %.1f LML %.1f (ratio %.1f); anisotropic %.1f (EWA on one "
              "level) on %s\n",
              nmn, lmn, nml, lml, nmn / lml, value(m, "popping[anisotropic]"), renderer().c_str());
  EXPECT_GE(nmn, 4 * lml);
  EXPECT_GE(lmn, 4 * nml);
  EXPECT_NEAR(value(m, "popping_ratio"), nmn / lml, 1e-6);
  double largest = 0;
  for (int k = 0; k + 1 < kLevels; ++k) {
    ts::Rgba a = ts::mipLevelColour(k), b = ts::mipLevelColour(k + 1);
    largest = std::max({largest, std::abs(a.r - b.r + 0.0), std::abs(a.g - b.g + 0.0), std::abs(a.b - b.b + 0.0)});
  }
  EXPECT_GE(nmn, largest / 2);
  EXPECT_LE(nmn, largest + 1);
  EXPECT_LE(lml, largest * 1.4 / 16 + 1);
  EXPECT_GT(lml, 0.0) << "trilinear must still change with the distance";
}

// Negative controls: the measure responds to level switches, not to the
// distance as such.  (a) A sweep inside one level (LOD 2.55 .. 3.45) does not
// pop with NEAREST_MIPMAP_NEAREST.  (b) Without mipmaps (GL_NEAREST) the
// coloured texture is level 0 at every distance: no jump.  (c) Halving the
// step halves trilinear's largest jump (a smooth curve) but not
// NEAREST_MIPMAP_NEAREST's (a step).
TEST(MipmapPopping, PoppingMeasureSeesLevelSwitchesOnly) {
  ts::Renderer& r = ts::test::renderer();
  mipmap::Look nmn;
  nmn.filter = kNearestMipNearest;
  EXPECT_LT(poppingMeasure(mipmap::probeSweep(r, nmn, mipmap::sweepLods(2.55, 3.45, 1.0 / 16))), 0.5);
  mipmap::Look nearest;
  nearest.filter = kNearest;
  EXPECT_EQ(poppingMeasure(mipmap::probeSweep(r, nearest, mipmap::sweepLods(-1, 7.5, 1.0 / 16))), 0.0);
  mipmap::Look lml;
  lml.filter = kLinearMipLinear;
  double big = poppingMeasure(mipmap::probeSweep(r, lml, mipmap::sweepLods(0.5, 6.5, 1.0 / 8)));
  double small = poppingMeasure(mipmap::probeSweep(r, lml, mipmap::sweepLods(0.5, 6.5, 1.0 / 32)));
  double stepBig = poppingMeasure(mipmap::probeSweep(r, nmn, mipmap::sweepLods(0.55, 6.55, 1.0 / 8)));
  double stepSmall = poppingMeasure(mipmap::probeSweep(r, nmn, mipmap::sweepLods(0.55, 6.55, 1.0 / 32)));
  std::printf("[ info ] step 1/8 -> 1/32: trilinear %.1f -> %.1f, nearest-mip %.1f -> %.1f\n", big, small, stepBig,
              stepSmall);
  EXPECT_NEAR(big / small, 4.0, 1.5);
  EXPECT_NEAR(stepBig, stepSmall, 1.0);
}

// ---------------------------------------------------------------------------
// Claim: on the slanted plane, against the supersampled reference (GL at
// 8 x 8 the resolution, GL_NEAREST on level 0, box-downsampled), the far
// field's RMS error falls from GL_NEAREST (aliasing) to trilinear
// (over-blur) to anisotropic: each by at least a quarter.
TEST(MipmapPopping, FarFieldErrorFallsFromNearestToTrilinear) {
  const ts::Measurements& m = defaultMeasurement();
  double n = value(m, "far_error[nearest]"), t = value(m, "far_error[linear_mipmap_linear]");
  std::printf("[ info ] far-field error: nearest %.2f, trilinear %.2f over %g pixels (%s)\n", n, t,
              value(m, "far_pixels"), renderer().c_str());
  EXPECT_GT(value(m, "far_pixels"), 10000);
  EXPECT_GE(n, 1.25 * t);
  EXPECT_GT(t, 2.0) << "trilinear should over-blur the far field measurably";
}

TEST(MipmapPopping, FarFieldErrorFallsFromTrilinearToAnisotropic) {
  ts::test::context();
  if (!ts::gl::hasExtension("GL_EXT_texture_filter_anisotropic") &&
      !ts::gl::hasExtension("GL_ARB_texture_filter_anisotropic") && ts::gl::version() < 46)
    GTEST_SKIP() << "no anisotropic filtering on " << renderer()
                 << " (neither EXT/ARB_texture_filter_anisotropic nor GL 4.6)";
  const ts::Measurements& m = defaultMeasurement();
  double t = value(m, "far_error[linear_mipmap_linear]"), a = value(m, "far_error[anisotropic]");
  std::printf("[ info ] far-field error: trilinear %.2f, anisotropic x16 %.2f (%s)\n", t, a, renderer().c_str());
  EXPECT_EQ(value(m, "anisotropy_supported"), 1.0);
  EXPECT_GE(t, 1.25 * a);
  // Control: anisotropic filtering limited to 1 is trilinear (same error),
  // so the gain is the anisotropy's.
  mipmap::Look one;
  one.filter = kAnisotropic;
  one.anisotropy = 1;
  mipmap::Look tri;
  tri.filter = kLinearMipLinear;
  ts::Renderer& r = ts::test::renderer();
  ts::Image a1 = r.renderOffscreen(mipmap::slantFrame(one, mipmap::kTextured, mipmap::kSlantW, mipmap::kSlantH));
  ts::Image t1 = r.renderOffscreen(mipmap::slantFrame(tri, mipmap::kTextured, mipmap::kSlantW, mipmap::kSlantH));
  EXPECT_EQ(ts::probe::countDiffering(a1, t1, 0), 0);
}

// Claim (over-blur, not just error): in the far field trilinear keeps less
// of the reference's detail across the view (horizontal contrast between
// neighbouring pixels) than anisotropic filtering does.
double horizontalDetail(const ts::Image& img, const std::vector<char>& mask) {
  double sum = 0;
  long n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x + 1 < img.width; ++x) {
      if (!mask[size_t(y) * size_t(img.width) + size_t(x)] || !mask[size_t(y) * size_t(img.width) + size_t(x) + 1])
        continue;
      ts::Rgba a = img.at(x, y), b = img.at(x + 1, y);
      sum += std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
      ++n;
    }
  return n ? sum / n : 0;
}
TEST(MipmapPopping, TrilinearOverBlursTheFarField) {
  ts::Renderer& r = ts::test::renderer();
  mipmap::Look l;
  ts::Image ref = mipmap::slantReference(r, l);
  std::vector<char> mask = mipmap::farField(mipmap::kSlantW, mipmap::kSlantH);
  l.filter = kLinearMipLinear;
  ts::Image tri = r.renderOffscreen(mipmap::slantFrame(l, mipmap::kTextured, mipmap::kSlantW, mipmap::kSlantH));
  double dr = horizontalDetail(ref, mask), dt = horizontalDetail(tri, mask);
  std::printf("[ info ] far-field horizontal detail: reference %.2f, trilinear %.2f (%s)\n", dr, dt,
              renderer().c_str());
  EXPECT_LT(dt, 0.7 * dr);
  // Negative control: the reference against itself has no error.
  EXPECT_EQ(rmsError(ref, ref, mask), 0.0);
}

// The reference drawn in the figure (a GLSL program: 8 x 8 exact samples of
// level 0 per pixel, mapped by the plane's homography) and the measurement's
// reference (GL at 8 x 8 the size, rasterised and interpolated, then
// box-downsampled on the CPU) are the same picture wherever 8 x 8 samples
// can follow the texture, i.e. up to LOD 8 (measured on llvmpipe and
// softpipe: RMS 0.14, no pixel of 59,000 differs by more than 8).  Nearer
// the horizon a sample 1/8 pixel away is a different texel and the two
// sample sets stop agreeing.
TEST(MipmapPopping, GLSLReferenceAgreesWithTheDownsampledRender) {
  ts::Renderer& r = ts::test::renderer();
  mipmap::Look l;
  ts::Image down = mipmap::slantReference(r, l);
  ts::Image glsl = r.renderOffscreen(
      mipmap::slantFrame(l, mipmap::kReferenceProgram, mipmap::kSlantW, mipmap::kSlantH));
  std::vector<char> all = mipmap::farField(mipmap::kSlantW, mipmap::kSlantH, -10, 8);
  long n = 0, differ = 0;
  double rms = rmsError(glsl, down, all, &n);
  for (int y = 0; y < glsl.height; ++y)
    for (int x = 0; x < glsl.width; ++x)
      differ += all[size_t(y) * size_t(glsl.width) + size_t(x)] && !ts::probe::close(glsl.at(x, y), down.at(x, y), 8);
  std::printf("[ info ] GLSL vs downsampled reference, LOD <= 8: RMS %.3f, %ld of %ld pixels differ by > 8 (%s)\n", rms,
              differ, n, renderer().c_str());
  EXPECT_GT(n, 40000);
  EXPECT_LT(rms, 1.0);
  EXPECT_LE(differ, n / 1000);
  // Negative control: a trilinear render is not the reference.
  l.filter = kLinearMipLinear;
  ts::Image tri = r.renderOffscreen(mipmap::slantFrame(l, mipmap::kTextured, mipmap::kSlantW, mipmap::kSlantH));
  EXPECT_GT(rmsError(tri, down, all), 3 * rms);
}

// ---------------------------------------------------------------------------
// Claim (the filmstrip figure): in the top row (NEAREST_MIPMAP_NEAREST) the
// coloured half of every frame is one level's colour — the level of that
// frame's LOD; in the bottom row (trilinear) it is the blend frac(LOD).
TEST(MipmapPopping, FilmstripFramesShowTheirLevels) {
  Demo demo("mipmap_popping", {"--view", "filmstrip", "--filter", "nearest-mipmap-nearest", "--distance-log2", "2.625",
                               "--levels", "split"});
  ts::Frame f;
  ts::Image img = demo.render(1024, 400, &f);
  int frames = 0;
  for (int c = 0; c < 8; ++c) {
    double lod = 2.625 + 0.25 * (c - 4);
    for (int row = 0; row < 2; ++row) {
      const ts::Panel* p = f.panel("frame_" + std::to_string(row) + "_" + std::to_string(c));
      ASSERT_NE(p, nullptr);
      const ts::Rect& vp = p->viewport;
      ts::Rect right{vp.x + vp.w / 2 + 2, vp.y + 2, vp.w / 2 - 4, vp.h - 4};
      Mean mean = meanOf(img, right);
      if (row == 0) {
        ts::probe::Result pr = ts::probe::rect(img, right, ts::mipLevelColour(nearestLevel(lod)),
                                               ts::probe::tolerance(8));
        EXPECT_TRUE(pr.ok()) << "frame " << c << " (LOD " << lod << "): " << pr.describe();
      } else {
        EXPECT_NEAR(levelFromColour(mean), effectiveLevel(kLinearMipLinear, lod), kBlendTolerance) << "frame " << c;
      }
      ++frames;
    }
  }
  EXPECT_EQ(frames, 16);
}

// Claim (the plot figure): the curves are the measured sweep, one point per
// distance for R, G and B, for the current filter (top) and trilinear.
TEST(MipmapPopping, PlotDrawsTheMeasuredSweep) {
  Demo demo("mipmap_popping", {"--view", "plot"});
  demo.measure();
  ts::Frame f = demo.frame(1024, 640);
  int series = 0;
  const size_t n = mipmap::sweepLods().size();
  for (const auto& p : f.panels)
    for (const auto& b : p.batches)
      if (b.role == "mean_red" || b.role == "mean_green" || b.role == "mean_blue") {
        ++series;
        EXPECT_EQ(b.vertices.size(), n);
      }
  EXPECT_EQ(series, 6);
}

// ---------------------------------------------------------------------------
// Claim: the three figures are registered under Section VI.1.3 and their
// flags parse.
TEST(MipmapPopping, FiguresAreRegistered) {
  Demo demo("mipmap_popping", {});
  std::map<std::string, ts::FigureSpec> byId;
  for (const auto& s : demo.scene->figures()) byId[s.id] = s;
  for (const char* id : {"mip_popping_filmstrip", "mip_popping_plot", "mip_anisotropic"}) {
    ASSERT_TRUE(byId.count(id)) << id;
    EXPECT_EQ(byId[id].bookNumber, "Section VI.1.3");
    Demo d("mipmap_popping", ts::sceneFlags(byId[id].flags));  // throws on a bad flag
  }
}

// Bad flag values are one clear line (ts::Error, exit status 2).
TEST(MipmapPopping, BadFlagValuesAreOneLineErrors) {
  const std::vector<std::vector<std::string>> bad = {{"--distance-log2", "99"}, {"--distance-log2", "far"},
                                                     {"--anisotropy", "1"},     {"--anisotropy", "32"},
                                                     {"--lod-bias", "5"},       {"--filter", "trilinear"},
                                                     {"--levels", "rainbow"},   {"--view", "side"}};
  for (const auto& flags : bad) {
    try {
      Demo d("mipmap_popping", flags);
      ADD_FAILURE() << flags[0] << " " << flags[1] << " was accepted";
    } catch (const ts::Error& e) {
      EXPECT_EQ(e.exit_code, ts::kExitUsage);
      std::string w = e.what();
      EXPECT_EQ(w.find('\n'), std::string::npos) << w;
      EXPECT_NE(w.find(flags[0]), std::string::npos) << w;
    }
  }
}

// Claim: the animation is counted in frames and pauses first, so the first
// frames of an animated window equal the --png of the same state, and the
// same frame count always gives the same picture.
TEST(MipmapPopping, AnimationIsFrameCountedAfterAPause) {
  auto planeProjection = [](ts::Scene& s) {
    ts::Frame f = s.build(320, 200, {});
    return f.panel("plane")->projection;
  };
  Demo still("mipmap_popping", {"--view", "single"}), moving("mipmap_popping", {"--view", "single", "--animate"});
  glm::mat4 p0 = planeProjection(*still.scene);
  for (int k = 0; k < 30; ++k) moving.scene->update(1.0);  // a second per frame: wall time does not matter
  EXPECT_EQ(planeProjection(*moving.scene), p0);
  for (int k = 0; k < 10; ++k) moving.scene->update(0.001);
  glm::mat4 p40 = planeProjection(*moving.scene);
  EXPECT_NE(p40, p0);
  Demo again("mipmap_popping", {"--view", "single", "--animate"});
  for (int k = 0; k < 40; ++k) again.scene->update(0.5);
  EXPECT_EQ(planeProjection(*again.scene), p40);
  // Turning it off returns to the chosen distance.
  moving.opts.set("animate", "off");
  moving.scene->update(0.0);
  EXPECT_EQ(planeProjection(*moving.scene), p0);
}
}  // namespace
