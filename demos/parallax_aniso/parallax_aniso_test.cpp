// demos/parallax_aniso/parallax_aniso_test.cpp — seed 003: parallax mapping with
// anisotropic filtering that knows what the relief hides.
//
// What is asserted, never against a stored image or a stored number:
//   * Heckbert's ellipse coefficients and Gaussian weights, on the CPU and in
//     the shader (a float probe pass), against hand-computed cases: the sign
//     inside F (the seed's Ux Vy + Uy Vx would give 49 where Heckbert's gives
//     25), Q / F = the screen distance squared, and a magnified footprint,
//     which the unit reconstruction term keeps at least a texel wide;
//   * on a flat height map nothing is hidden: M4 and M5 give M3's image,
//     byte for byte, and exclude no texel;
//   * on the step map the shader's visibility trace (and its CPU mirror)
//     excludes exactly the floor texels behind a ridge — those closer to the
//     ridge's far edge than the parallax offset of the full depth, from known
//     view angles — and never a ridge texel; the max-height pyramid skip gives
//     the same answer;
//   * two references with different jitter seeds agree to at least 40 dB;
//   * M3 (the shader EWA) on the flat map agrees with the reference, which
//     uses the same kernel;
//   * the measured table, regenerated here at 160 x 120, is within bounds:
//     every PSNR/SSIM finite and sane, the masks non-empty, lookups ordered
//     as the algorithms imply; and the finding it gives on the bricks at 20
//     degrees (visibility-aware EWA closer to the reference than EWA over the
//     whole frame and the high-anisotropy pixels; the row walk within 0.5 dB
//     of the full trace) is checked as regenerated, not copied;
//   * the live view (the window's interactive view) draws the chosen mode at
//     the target's size, pixel for pixel what the measured passes draw, and
//     its split screen is the two modes' halves.
//   * the causes view's measurements of the seed's equations: Eq. 2's
//     forward differences of the shifted coordinate err by under a texel in
//     the median and at the steps by at least half the parallax of the full
//     depth (the flat map: no step); the footprint area ratio is about 1 over
//     the relief and above 2 at the steps (flat: 1); the hidden share rises
//     from the smallest footprint bin to the largest beyond the sampling
//     errors (flat: nothing hidden); M5's row walk counts no texel twice, the
//     walk without its stop index does (and a row by hand shows both); M3
//     with the seed's F changes pixels at 12 degrees of azimuth and none at
//     0, where Vx = 0 makes the two F equal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "demos/parallax_aniso/parallax_aniso_causes_gl.hpp"
#include "demos/parallax_aniso/parallax_aniso_measure.hpp"
#include "demos/parallax_aniso/parallax_aniso_gl.hpp"
#include "demos/parallax_aniso/parallax_aniso_math.hpp"
#include "demos/parallax_aniso/parallax_aniso_views.hpp"
#include "common/core/probe.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using namespace pax;

ReliefGL& gl() {
  static ReliefGL g(ts::test::renderer());
  return g;
}
const Relief& relief(const std::string& name) {
  static std::vector<std::unique_ptr<Relief>> cache;
  for (auto& r : cache)
    if (r->name == name) return *r;
  cache.push_back(std::make_unique<Relief>(makeRelief(name)));
  return *cache.back();
}
Camera smallCamera(double elevation = 20.0) {
  Camera c;
  c.width = 160;
  c.height = 120;
  c.elevationDeg = elevation;
  return c;
}
// Whole-frame GL checks: 160 x 120, or 80 x 60 on softpipe (which interprets
// the shader: M4 at 160 x 120 takes about 8 s a frame there).
Camera glCamera(double elevation = 20.0) {
  Camera c = smallCamera(elevation);
  if (ts::test::isSoftpipe()) {
    c.width = 80;
    c.height = 60;
  }
  return c;
}
// ------------------------------------------------------------- the ellipse
TEST(Ellipse, HandComputedAxisAligned) {
  // u stretched 2 texels per pixel along x, v 0.5 per pixel along y.
  Ellipse e = ellipse(2.0, 0.0, 0.0, 0.5, false);
  EXPECT_DOUBLE_EQ(e.A, 0.25);
  EXPECT_DOUBLE_EQ(e.B, 0.0);
  EXPECT_DOUBLE_EQ(e.C, 4.0);
  EXPECT_DOUBLE_EQ(e.F, 1.0);
  glm::dvec2 r = e.radii();
  EXPECT_NEAR(r.x, 2.0, 1e-12);
  EXPECT_NEAR(r.y, 0.5, 1e-12);
}

TEST(Ellipse, SignOfF) {
  // Ux = 1, Vx = 2, Uy = 3, Vy = 1.
  Ellipse e = ellipse(1.0, 2.0, 3.0, 1.0, false);
  EXPECT_DOUBLE_EQ(e.A, 5.0);    // Vx^2 + Vy^2
  EXPECT_DOUBLE_EQ(e.B, -10.0);  // -2 (Ux Vx + Uy Vy)
  EXPECT_DOUBLE_EQ(e.C, 10.0);   // Ux^2 + Uy^2
  EXPECT_DOUBLE_EQ(e.F, 25.0);   // (Ux Vy - Uy Vx)^2 = (1 - 6)^2; the seed's (1 + 6)^2 = 49 is wrong
  EXPECT_NE(e.F, 49.0);
  // F = A C - B^2 / 4 (Lagrange), the determinant of the quadratic form.
  EXPECT_DOUBLE_EQ(e.F, e.A * e.C - e.B * e.B / 4);
}

TEST(Ellipse, QOverFIsTheScreenDistanceSquared) {
  // A screen offset (x, y) pixels lands at (U, V) = J (x, y) in the texture;
  // Q(U, V) / F must be x^2 + y^2: the ellipse Q = F is the image of the unit
  // circle of the screen (which is what the seed's garbled F breaks).
  const double J[4] = {1.3, -0.4, 2.1, 0.7};  // Ux, Vx, Uy, Vy
  Ellipse e = ellipse(J[0], J[1], J[2], J[3], false);
  for (double a = 0; a < 6.28; a += 0.7) {
    double x = 0.8 * std::cos(a), y = 0.8 * std::sin(a);
    double U = J[0] * x + J[2] * y, V = J[1] * x + J[3] * y;
    EXPECT_NEAR(e.Q(U, V) / e.F, x * x + y * y, 1e-12);
  }
  // The seed's F: the same offsets would not give x^2 + y^2.
  double seedF = (J[0] * J[3] + J[2] * J[1]) * (J[0] * J[3] + J[2] * J[1]);
  EXPECT_GT(std::abs(e.Q(J[0], J[1]) / seedF - 1.0), 0.1);
}

TEST(Ellipse, MagnifiedFootprintKeepsATexel) {
  // 0.1 texel per pixel: without reconstruction the ellipse is a tenth of a
  // texel wide (it would fall between texel centres); with the unit term it
  // is a texel: A = C = 1.01, F = A C = 1.0201, radius sqrt(1.01).
  Ellipse plain = ellipse(0.1, 0.0, 0.0, 0.1, false);
  EXPECT_NEAR(plain.radii().x, 0.1, 1e-12);
  Ellipse e = ellipse(0.1, 0.0, 0.0, 0.1, true);
  EXPECT_DOUBLE_EQ(e.A, 1.01);
  EXPECT_DOUBLE_EQ(e.C, 1.01);
  EXPECT_NEAR(e.F, 1.0201, 1e-12);
  EXPECT_NEAR(e.radii().x, std::sqrt(1.01), 1e-12);
  EXPECT_NEAR(e.radii().y, std::sqrt(1.01), 1e-12);
  EXPECT_DOUBLE_EQ(ewaLod(plain), 0.0);
}

TEST(Ellipse, GaussianWeights) {
  Ellipse e = ellipse(2.0, 0.0, 0.0, 0.5, false);  // semi-axes 2 (U) and 0.5 (V)
  EXPECT_DOUBLE_EQ(ewaWeight(e, 0, 0), 1.0);
  EXPECT_NEAR(ewaWeight(e, 1.0, 0.0), std::exp(-kAlpha * 0.25), 1e-12);   // q = A U^2 / F = 0.25
  EXPECT_NEAR(ewaWeight(e, 0.0, 0.25), std::exp(-kAlpha * 0.25), 1e-12);  // q = C V^2 / F = 0.25
  EXPECT_NEAR(ewaWeight(e, 2.0, 0.0), std::exp(-kAlpha), 1e-12);          // on the ellipse
  EXPECT_EQ(ewaWeight(e, 2.01, 0.0), 0.0);                                // outside
  EXPECT_EQ(ewaWeight(e, 0.0, 0.51), 0.0);
  // Level: the short axis 0.5 texel -> level 0; a 16 x 4 ellipse -> log2(4) = 2;
  // 64 x 1 is thinner than 16:1 -> log2(64 / 16) = 2.
  EXPECT_DOUBLE_EQ(ewaLod(e), 0.0);
  EXPECT_NEAR(ewaLod(ellipse(16, 0, 0, 4, false)), 2.0, 1e-12);
  EXPECT_NEAR(ewaLod(ellipse(64, 0, 0, 1, false)), 2.0, 1e-12);
}

TEST(Ellipse, ShaderComputesTheSameCoefficients) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  const double cases[][4] = {{2, 0, 0, 0.5}, {1, 2, 3, 1}, {0.1, 0, 0, 0.1}, {1.3, -0.4, 2.1, 0.7}};
  for (const auto& c : cases)
    for (bool recon : {false, true}) {
      Ellipse e = ellipse(c[0], c[1], c[2], c[3], recon);
      glm::dvec4 g = gl().probeEllipse(glm::dvec4(c[0], c[1], c[2], c[3]), recon);
      const double tol = 1e-5 * (1 + std::abs(e.F) + std::abs(e.A) + std::abs(e.C));
      EXPECT_NEAR(g.x, e.A, tol) << "A, case " << c[0] << " " << c[1] << " " << c[2] << " " << c[3];
      EXPECT_NEAR(g.y, e.B, tol) << "B";
      EXPECT_NEAR(g.z, e.C, tol) << "C";
      EXPECT_NEAR(g.w, e.F, tol) << "F";
    }
}

// ------------------------------------------------------------- visibility
// Floor texels of the step map behind a ridge (v = 32 + k, k = 0..31; the
// ridge is v = 0..31 and the eye looks along +v) for the view's parallax |Vt|
// texels per unit depth: texel k's surface point at depth 1 sees the eye
// over the ridge's far edge at v = 32 only if (k + 0.5) >= |Vt|.  The trace
// steps half a texel and tolerates kHiddenEps, so texels within one texel of
// the continuous shadow boundary may go either way; every other must be
// exactly as predicted.
struct StepExpect {
  int hidden = 0, visible = 0, either = 0;
};
StepExpect checkStep(const std::vector<int>& got, int w, int h, glm::ivec2 first, int period, double vt,
                     std::string* why) {
  StepExpect e;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int v = first.y + y, k = ((v % period) + period) % period;
      int flag = got[size_t(y) * size_t(w) + size_t(x)];
      bool ridge = k < period / 2;
      double dc = k - period / 2 + 0.5;  // texel centre to the ridge's far edge
      int want = ridge ? 0 : dc < vt * (1.0 - kHiddenEps) - 1.0 ? 1 : dc > vt ? 0 : -1;
      if (want == -1) {
        ++e.either;
        continue;
      }
      (want ? e.hidden : e.visible)++;
      if (flag != want && why->empty())
        *why = "texel (" + std::to_string(first.x + x) + ", " + std::to_string(v) + ") " +
               (ridge ? "on the ridge" : "on the floor, " + std::to_string(dc) + " texels behind the edge") +
               (flag ? " is hidden" : " is visible") + ", |Vt| = " + std::to_string(vt);
    }
  return e;
}

TEST(Visibility, StepMapExcludesExactlyTheTexelsBehindTheStep) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  const Relief& step = relief("step");
  for (double elevation : {25.0, 35.0, 50.0, 70.0})
    for (int L : {0, 1}) {
      Camera cam = smallCamera(elevation);
      cam.azimuthDeg = 0;
      // The parallax of the full depth along +v, in texels of level L.
      glm::dvec2 Vt = glm::dvec2(0, 1) / std::tan(glm::radians(elevation)) * (cam.heightScale / cam.tile) *
                      double(kTexSize >> L);
      const int w = 8, h = 64 >> L, period = 64 >> L;
      const glm::ivec2 first(3, 2 * period);
      for (bool accel : {false, true}) {
        std::vector<int> got = gl().probeHidden(step, first, w, h, L, Vt, accel);
        std::string why;
        StepExpect e = checkStep(got, w, h, first, period, Vt.y, &why);
        EXPECT_TRUE(why.empty()) << "elevation " << elevation << ", level " << L << ", accel " << accel << ": " << why;
        EXPECT_GT(e.hidden, 0) << "elevation " << elevation;
        EXPECT_LE(e.either, 2 * w) << "at most one texel per column is left open";
        // The CPU mirror agrees texel for texel.
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x)
            ASSERT_EQ(got[size_t(y) * size_t(w) + size_t(x)],
                      int(hiddenTexel(step.height, L, first.x + x, first.y + y, Vt)))
                << "texel " << first.x + x << ", " << first.y + y << " level " << L << " elevation " << elevation;
      }
    }
}

TEST(Visibility, PyramidSkipKeepsTheAnswer) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  const Relief& bricks = relief("bricks");
  for (glm::dvec2 Vt : {glm::dvec2(9.0, 40.0), glm::dvec2(-3.0, 12.0)}) {
    std::vector<int> off = gl().probeHidden(bricks, {100, 200}, 64, 64, 0, Vt, false);
    std::vector<int> on = gl().probeHidden(bricks, {100, 200}, 64, 64, 0, Vt, true);
    EXPECT_EQ(off, on);
    EXPECT_GT(std::count(off.begin(), off.end(), 1), 0);
  }
}

// ------------------------------------------------------------- whole frames
TEST(Frames, FlatMapHidesNothing) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  const Relief& flat = relief("flat");
  Camera cam = glCamera();
  ts::Image m3 = gl().render(cam, flat, kEwa);
  for (int mode : {kEwaVis, kEwaRows}) {
    ts::Image img = gl().render(cam, flat, mode);
    EXPECT_EQ(img.pixels, m3.pixels) << kModeLabels[mode] << " differs from M3 on a flat map";
    PassOptions count;
    count.count = true;
    ts::Image c = gl().render(cam, flat, mode, count);
    long excluded = 0;
    for (size_t p = 0; p < size_t(cam.width) * size_t(cam.height); ++p)
      excluded += c.pixels[p * 4 + 2] + 256 * c.pixels[p * 4 + 3];
    EXPECT_EQ(excluded, 0) << kModeLabels[mode];
  }
}

TEST(Frames, AccelerationKeepsTheImage) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  const Relief& bricks = relief("bricks");
  Camera cam = glCamera();
  PassOptions off, on;
  off.accel = false;
  for (int mode : {kEwaVis, kEwaRows}) {
    EXPECT_EQ(gl().render(cam, bricks, mode, off).pixels, gl().render(cam, bricks, mode, on).pixels)
        << kModeLabels[mode];
    // And it saves lookups over the frame (long traces over the mortar floor).
    auto lookups = [&](PassOptions o) {
      o.count = true;
      ts::Image c = gl().render(cam, bricks, mode, o);
      long n = 0;
      for (size_t p = 0; p < size_t(cam.width) * size_t(cam.height); ++p)
        n += c.pixels[p * 4] + 256 * c.pixels[p * 4 + 1];
      return n;
    };
    long a = lookups(off), b = lookups(on);
    std::printf("%s, bricks %dx%d: %ld lookups without the max-height pyramid, %ld with\n", kModeLabels[mode],
                cam.width, cam.height, a, b);
    EXPECT_LT(b, a) << kModeLabels[mode];
  }
}

// The visibility trace reads a texel once per run of samples over it
// instead of once per sample (PLAIN_TRACE): the same images and the same
// texels excluded, byte for byte, on both maps, two view angles, with and
// without the max-height bound; and fewer lookups.
TEST(Frames, TraceReadingEachTexelOnceKeepsTheImage) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  // softpipe interprets the shader (M4 about 2 s a frame at 80 x 60): one case there.
  const bool few = ts::test::isSoftpipe();
  for (const char* map : {"bricks", "step"})
    for (double elevation : {20.0, 35.0})
      for (bool accel : {true, false}) {
        if (few && (std::string(map) != "bricks" || elevation != 20.0 || !accel)) continue;
        Camera cam = glCamera(elevation);
        PassOptions once, plain;
        once.accel = plain.accel = accel;
        plain.plainTrace = true;
        for (int mode : {kEwaVis, kEwaRows}) {
          std::string what = std::string(kModeLabels[mode]) + ", " + map + ", " + std::to_string(int(elevation)) +
                             " degrees, bound " + (accel ? "on" : "off");
          EXPECT_EQ(gl().render(cam, relief(map), mode, once).pixels, gl().render(cam, relief(map), mode, plain).pixels)
              << what;
          long excluded[2] = {0, 0};
          auto lookups = [&](PassOptions o, long& excl) {
            o.count = true;
            ts::Image c = gl().render(cam, relief(map), mode, o);
            long n = 0;
            for (size_t p = 0; p < size_t(cam.width) * size_t(cam.height); ++p) {
              n += c.pixels[p * 4] + 256 * c.pixels[p * 4 + 1];
              excl += c.pixels[p * 4 + 2] + 256 * c.pixels[p * 4 + 3];
            }
            return n;
          };
          long a = lookups(plain, excluded[0]), b = lookups(once, excluded[1]);
          EXPECT_EQ(excluded[1], excluded[0]) << what << ": the same texels excluded";
          std::printf("%s: %ld lookups reading every sample, %ld reading each texel once\n", what.c_str(), a, b);
          EXPECT_LT(b, a) << what;
        }
      }
}

TEST(Frames, CentreLookupsEqualTexelFetch) {
  // The softpipe workaround reads the same texels: on llvmpipe both paths
  // give the same image (on softpipe texelFetch is what is broken).
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  if (ts::test::isSoftpipe()) GTEST_SKIP() << "softpipe's texelFetch is the broken path this compares against";
  const Relief& bricks = relief("bricks");
  Camera cam = glCamera();
  PassOptions fetch, centre;
  fetch.centreLookups = 0;
  centre.centreLookups = 1;
  for (int mode : {kEwa, kEwaVis, kEwaRows})
    EXPECT_EQ(gl().render(cam, bricks, mode, fetch).pixels, gl().render(cam, bricks, mode, centre).pixels)
        << kModeLabels[mode];
}

// The reference traces with traceBatch: the steps Skip proves are above the
// relief are not looked up, and the rays' halvings run side by side; the
// rest is traceFine's.  Every hit depth must be the same double, over the
// rays of a whole figure's camera on both maps, one ray at a time
// (traceFast) and a row's rays at once (traceBatch); the control: a Skip
// that claims every cell is deeper than it is must change some hit, so the
// comparison can fail.
TEST(Reference, FastTraceIsTraceFineBitForBit) {
  for (const char* map : {"bricks", "step"}) {
    const Relief& rel = relief(map);
    const Skip skip(rel);
    Camera cam;  // the figures' camera, 320 x 240
    size_t rays = 0, differing = 0, batchDiffering = 0, controlDiffering = 0;
    Skip wrong = skip;
    for (double& v : wrong.leastOf) v += 0.05;  // claims every cell is deeper than it is
    for (int y = 0; y < cam.height; y += 3) {
      std::vector<glm::dvec2> uv0s, Vps;
      std::vector<double> fines;
      for (int x = 0; x < cam.width; x += 3) {
        glm::dvec3 d = cam.ray(glm::dvec2(x + 0.25, y + 0.75));
        glm::dvec2 uv0 = cam.topUV(d), Vp = cam.parallax(d);
        double fine = traceFine(rel, uv0, Vp);
        differing += traceFast(rel, skip, uv0, Vp) != fine;
        controlDiffering += traceFast(rel, wrong, uv0, Vp) != fine;
        uv0s.push_back(uv0), Vps.push_back(Vp), fines.push_back(fine);
        ++rays;
      }
      std::vector<double> batch(fines.size(), -1.0);
      traceBatch(rel, skip, uv0s.data(), Vps.data(), int(fines.size()), batch.data());
      for (size_t q = 0; q < fines.size(); ++q) batchDiffering += batch[q] != fines[q];
    }
    EXPECT_EQ(differing, 0u) << map << ": " << differing << " of " << rays << " rays";
    EXPECT_EQ(batchDiffering, 0u) << map << ": " << batchDiffering << " of " << rays << " rays traced in rows";
    EXPECT_GT(controlDiffering, 0u) << map << ": a wrong skip changed nothing";
  }
}

TEST(Reference, TwoSeedsAgree) {
  const Relief& bricks = relief("bricks");
  Camera cam = smallCamera();
  Reference a = renderReference(cam, bricks, 8, 1), b = renderReference(cam, bricks, 8, 2);
  double p = psnr(a.image(), b.image(), nullptr);
  std::printf("two 8x8-ray references, seeds 1 and 2: %.2f dB\n", p);
  EXPECT_GE(p, 40.0);
}

TEST(Frames, ShaderEwaMatchesTheReferenceOnAFlatMap) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  const Relief& flat = relief("flat");
  Camera cam = smallCamera(30.0);
  Reference ref = renderReference(cam, flat, 8, 1);
  ts::Image m3 = gl().render(cam, flat, kEwa);
  double p = psnr(m3, ref.image(), nullptr);
  std::printf("flat map, 30 degrees: M3 vs reference %.2f dB\n", p);
  EXPECT_GE(p, 30.0) << "the shader EWA should reproduce the reference's kernel where nothing is hidden";
}

// Does the hardware filter use the gradients textureGrad gives it?  The
// table answers by rendering M1 and M2 with the gradients x4.  Trilinear
// filtering must answer yes (a coarser level: GL's lambda is log2 of the
// gradients' length), so the switch demonstrably reaches the lookup; for M2
// whatever the driver does is the answer, but it must be consistent: a
// filter that ignores the gradients at x4 ignores them at x1/4 too, and one
// that uses them changes at both.  (llvmpipe in Mesa 22.3 ignores them: its
// anisotropic footprint and level come from the coordinate's own quad
// differences.)
TEST(Frames, GradientTestSeesWhetherTheFilterUsesTheGradients) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  if (!ts::gl::hasAnisotropicFiltering()) GTEST_SKIP() << "no anisotropic filtering";
  const Relief& bricks = relief("bricks");
  Camera cam = glCamera();
  MeasureOptions o;
  o.refRays = 2;
  o.timingRuns = 0;
  Table t = measureAll(gl(), cam, bricks, o, {kTrilinear, kAniso16});
  std::printf("%s\n", gradientFinding(t).c_str());
  const long pixels = long(cam.width) * cam.height;
  EXPECT_GT(t.gradChangeM1, pixels / 2) << "trilinear filtering must see 4x longer gradients";
  ASSERT_GE(t.gradChangeM2, 0);
  PassOptions quarter;
  quarter.gradScale = 0.25f;
  long m2Quarter = ts::probe::countDiffering(t.rows[1].image, gl().render(cam, bricks, kAniso16, quarter), 0);
  std::printf("M2 with the gradients x1/4: %ld px change\n", m2Quarter);
  if (t.gradChangeM2 == 0) EXPECT_EQ(m2Quarter, 0) << "the filter ignored 4x gradients but not 1/4x ones";
  else EXPECT_GT(m2Quarter, 0) << "the filter used 4x gradients but not 1/4x ones";
  EXPECT_NE(gradientFinding(t).find(std::to_string(t.gradChangeM2) + " px of M2"), std::string::npos);
}

// ------------------------------------------------------------- the table
TEST(Table, RegeneratedWithinBounds) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  if (ts::test::isSoftpipe())
    GTEST_SKIP() << "softpipe interprets the shader: the twelve full-frame passes of the table at 160x120 (M4 and "
                    "M5 about 8 s a frame there) would take minutes; the probes and the whole-frame tests above run "
                    "on softpipe at 80x60";
  const Relief& bricks = relief("bricks");
  MeasureOptions o;
  o.refRays = 8;
  o.timingRuns = 0;
  Table t = measureAll(gl(), smallCamera(), bricks, o);
  std::printf("%s", textTable(t).c_str());
  ASSERT_EQ(t.rows.size(), size_t(kShaderModes));
  EXPECT_GT(t.bandPixels, 300u);
  EXPECT_GT(t.anisoPixels, 2000u);
  for (const Row& r : t.rows) {
    for (double v : {r.psnrAll, r.psnrAniso, r.psnrBand}) {
      EXPECT_TRUE(std::isfinite(v)) << kModeLabels[r.mode];
      EXPECT_GT(v, 10.0) << kModeLabels[r.mode];
      EXPECT_LT(v, 60.0) << kModeLabels[r.mode];
    }
    for (double v : {r.ssimAll, r.ssimAniso, r.ssimBand}) {
      EXPECT_GT(v, 0.0) << kModeLabels[r.mode];
      EXPECT_LE(v, 1.0) << kModeLabels[r.mode];
    }
  }
  const Row &m1 = t.rows[kTrilinear], &m2 = t.rows[kAniso16], &m3 = t.rows[kEwa], &m4 = t.rows[kEwaVis],
            &m5 = t.rows[kEwaRows];
  // Lookups: one albedo call for M1/M2, the ellipse for M3, plus traces for M4; M5 traces no more than M4.
  EXPECT_EQ(m1.lookupsPerPixel, m2.lookupsPerPixel);
  EXPECT_GT(m3.lookupsPerPixel, m1.lookupsPerPixel);
  EXPECT_GT(m4.lookupsPerPixel, m3.lookupsPerPixel);
  EXPECT_LE(m5.lookupsPerPixel, m4.lookupsPerPixel);
  EXPECT_EQ(m3.excludedPerPixel, 0.0);
  EXPECT_GT(m4.excludedPerPixel, 0.0);
  EXPECT_GE(m5.excludedPerPixel, m4.excludedPerPixel);  // the untraced middle of a row is dropped too
  // The finding, as regenerated: on the bricks at 20 degrees, visibility-aware
  // EWA is closer to the reference than EWA over the frame and the
  // high-anisotropy pixels, and the row walk costs it almost nothing.
  EXPECT_GT(m4.psnrAll, m3.psnrAll + 1.0);
  EXPECT_GT(m4.psnrAniso, m3.psnrAniso + 1.0);
  EXPECT_NEAR(m5.psnrAll, m4.psnrAll, 0.5);
  // The gradient test ran (its consistency is checked above).
  EXPECT_GT(t.gradChangeM1, 0);
  EXPECT_GE(t.gradChangeM2, 0);
  // The CSV carries every row and the renderer.
  std::string c = csv(t);
  EXPECT_NE(c.find(t.renderer), std::string::npos);
  EXPECT_EQ(std::count(c.begin(), c.end(), '\n'), kShaderModes + 1);
}

// The flat map has no occluding edge, so no occlusion band: its PSNR/SSIM do
// not exist and the CSV leaves the cells empty (not "nan", which spreadsheet
// and CSV readers take differently).
TEST(Table, AnEmptyBandLeavesItsCellsEmpty) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  MeasureOptions o;
  o.refRays = 2;
  o.timingRuns = 0;
  Camera cam = glCamera();
  cam.width /= 2;
  cam.height /= 2;
  Table t = measureAll(gl(), cam, relief("flat"), o, {kTrilinear});
  EXPECT_EQ(t.bandPixels, 0u);
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_TRUE(std::isnan(t.rows[0].psnrBand));
  std::string c = csv(t);
  EXPECT_EQ(c.find("nan"), std::string::npos) << c;
  // Columns 6 and 7 of the data row (psnr_band, ssim_band) are empty; the header names them.
  auto cells = [](const std::string& line) {
    std::vector<std::string> v(1);
    for (char ch : line) {
      if (ch == ',') v.emplace_back();
      else v.back().push_back(ch);
    }
    return v;
  };
  size_t nl = c.find('\n');
  std::vector<std::string> head = cells(c.substr(0, nl)), row = cells(c.substr(nl + 1, c.find('\n', nl + 1) - nl - 1));
  ASSERT_GT(row.size(), 7u);
  EXPECT_EQ(head[6], "psnr_band");
  EXPECT_EQ(head[7], "ssim_band");
  EXPECT_EQ(row[6], "");
  EXPECT_EQ(row[7], "");
  EXPECT_NE(row[2], "") << "the whole-frame PSNR exists";
}

// ------------------------------------------------------------- the live view
// Rows of `a` and `b` in [y0, y1) equal, columns [x0, x1) (both row 0 = top).
::testing::AssertionResult sameRows(const ts::Image& a, const ts::Image& b, int y0, int y1, int x0, int x1) {
  long differ = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c)
        differ += a.pixels[(size_t(y) * size_t(a.width) + size_t(x)) * 4 + size_t(c)] !=
                  b.pixels[(size_t(y) * size_t(b.width) + size_t(x)) * 4 + size_t(c)];
  if (differ == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << differ << " channel values differ in rows " << y0 << ".." << y1
                                       << ", columns " << x0 << ".." << x1;
}

// A window's first stage (ts::measureStage, only on the window's worker).
// The single view's is its whole picture: the shown mode as GL draws it and
// its numbers against the reference traced with all its rays, so the
// result's table changes nothing the view draws (every label the same, the
// picture the same pixels).  The modes view's is coarse: its pictures at
// once, the reference with fewer rays, no numbers ("(measuring)"), which
// the control shows differs from its result's frame.
std::vector<ts::Measurements> firstStages(const std::vector<std::string>& flags) {
  ts::test::Demo staged("parallax_aniso", flags);
  return ts::test::measureInStages(staged, 1);  // superseded: the table is not needed here
}
std::vector<std::string> labelTexts(ts::test::Demo& d) {
  std::vector<std::string> texts;
  for (const ts::Label& l : d.frame(1024, 560).labels) texts.push_back(l.text);
  return texts;
}
bool says(ts::test::Demo& d, const std::string& what) {
  for (const std::string& t : labelTexts(d))
    if (t.find(what) != std::string::npos) return true;
  return false;
}

TEST(Stage, TheSingleViewsFirstStageIsItsWholePicture) {
  const std::vector<std::string> flags = {"--res", "80", "--rays", "2"};
  ts::test::Demo plain("parallax_aniso", flags);
  plain.measure();
  const std::vector<ts::Measurements> stages = firstStages(flags);
  ASSERT_EQ(stages.size(), 1u);
  const pax::views::Shown* first = stages[0].detailAs<pax::views::Shown>();
  const pax::views::Shown* result = plain.measured.detailAs<pax::views::Shown>();
  ASSERT_NE(first, nullptr);
  ASSERT_NE(result, nullptr);
  EXPECT_FALSE(first->table->stage);
  ASSERT_NE(first->of(pax::kEwa).image, nullptr);
  ASSERT_NE(result->of(pax::kEwa).image, nullptr);
  EXPECT_EQ(ts::probe::countDiffering(*first->of(pax::kEwa).image, *result->of(pax::kEwa).image, 0), 0);
  ts::test::Demo staged("parallax_aniso", flags);
  staged.measured = stages[0];
  EXPECT_EQ(labelTexts(staged), labelTexts(plain));
  EXPECT_TRUE(says(staged, " dB"));
  EXPECT_FALSE(says(staged, "(measuring)"));
}

// A key that shows a mode the single view's first stage did not measure
// (c: the split screen's other half) before the table is in: the view waits
// for it ("rendering the modes ..."), never draws a picture it lacks.  The
// control: the same stage without the key draws its picture.
TEST(Stage, AKeyThatShowsAModeTheStageLacksWaits) {
  const std::vector<std::string> flags = {"--res", "80", "--rays", "2"};
  const std::vector<ts::Measurements> stages = firstStages(flags);
  ASSERT_EQ(stages.size(), 1u);
  std::vector<std::string> compared = flags;
  compared.push_back("--compare");
  ts::test::Demo keyed("parallax_aniso", compared), plain("parallax_aniso", flags);
  keyed.measured = plain.measured = stages[0];
  EXPECT_TRUE(says(keyed, "rendering the modes"));
  EXPECT_EQ(keyed.frame(1024, 560).panels.size(), plain.frame(1024, 560).panels.size() - 1);
  EXPECT_FALSE(says(plain, "rendering the modes"));
}

TEST(Stage, TheModesViewsFirstStageIsCoarseAndSaysSo) {
  const std::vector<std::string> flags = {"--res", "80", "--rays", "4", "--view", "modes"};
  ts::test::Demo plain("parallax_aniso", flags);
  plain.measure();
  const std::vector<ts::Measurements> stages = firstStages(flags);
  ASSERT_EQ(stages.size(), 1u);
  EXPECT_TRUE(stages[0].refining);
  const pax::views::Shown* first = stages[0].detailAs<pax::views::Shown>();
  ASSERT_NE(first, nullptr);
  EXPECT_TRUE(first->table->stage);
  ts::test::Demo staged("parallax_aniso", flags);
  staged.measured = stages[0];
  EXPECT_NE(labelTexts(staged), labelTexts(plain));
  EXPECT_TRUE(says(staged, "(measuring)"));
  EXPECT_FALSE(says(plain, "(measuring)"));
}

TEST(Live, DrawsTheModeAtTheTargetSize) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  const int W = ts::test::isSoftpipe() ? 96 : 240, H = W * 3 / 4, bar = views::liveBarHeight(W, H);
  ts::test::Demo d("parallax_aniso", {"--view", "live", "--mode", "aniso16"});
  ASSERT_TRUE(d.scene->live());
  ts::test::context().resize(W, H);  // the live view draws at the target's size
  ts::Measurements m = d.measure();
  EXPECT_GT(ts::test::value(m, "live_ms_per_frame"), 0.0);
  ts::Frame f;
  ts::Image live = d.render(W, H, &f);
  ASSERT_NE(f.panel("live"), nullptr);
  Camera c;  // the demo's defaults: bricks, 20 degrees, azimuth 12, height 0.06
  c.width = W;
  c.height = H;
  ts::Image m2 = gl().render(c, relief("bricks"), kAniso16);
  // Between the two text bars, the window shows exactly the M2 pass.
  EXPECT_TRUE(sameRows(live, m2, bar, H - bar, 0, W));
  // Not a picture of nothing: the relief has both bricks and mortar in it.
  EXPECT_FALSE(sameRows(live, gl().render(c, relief("bricks"), kNaive), bar, H - bar, 0, W))
      << "M2 and M0 drew the same picture";
}

TEST(Live, SplitScreenIsTheTwoModesHalves) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  const int W = ts::test::isSoftpipe() ? 96 : 240, H = W * 3 / 4, bar = views::liveBarHeight(W, H);
  ts::test::Demo d("parallax_aniso", {"--view", "live", "--mode", "trilinear", "--compare", "--against", "ewa"});
  ts::test::context().resize(W, H);
  d.measure();
  ts::Image live = d.render(W, H);
  Camera c;
  c.width = W;
  c.height = H;
  ts::Image left = gl().render(c, relief("bricks"), kTrilinear), right = gl().render(c, relief("bricks"), kEwa);
  // The divider (2 px at W/2) is left out.
  EXPECT_TRUE(sameRows(live, left, bar, H - bar, 0, W / 2 - 2));
  EXPECT_TRUE(sameRows(live, right, bar, H - bar, W / 2 + 2, W));
}

// The g key (--gradients x4) reaches the passes the window shows: in the
// live split screen M1 | M2 the left half is the M1 pass with its gradients
// x4 (and so differs from x1), the right half the M2 pass with them x4 --
// whatever the driver makes of them; the header says the gradients are off.
TEST(Live, GradientsKeyReachesTheLivePasses) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  const int W = ts::test::isSoftpipe() ? 96 : 240, H = W * 3 / 4, bar = views::liveBarHeight(W, H);
  ts::test::Demo d("parallax_aniso",
                   {"--view", "live", "--mode", "trilinear", "--compare", "--against", "aniso16", "--gradients", "x4"});
  ts::test::context().resize(W, H);
  d.measure();
  ts::Frame f;
  ts::Image live = d.render(W, H, &f);
  Camera c;  // the demo's defaults
  c.width = W;
  c.height = H;
  PassOptions x4;
  x4.gradScale = 4;
  ts::Image m1x4 = gl().render(c, relief("bricks"), kTrilinear, x4),
            m2x4 = gl().render(c, relief("bricks"), kAniso16, x4);
  // (The divider, 2 px at W/2, is left out.)
  EXPECT_TRUE(sameRows(live, m1x4, bar, H - bar, 0, W / 2 - 2));
  EXPECT_TRUE(sameRows(live, m2x4, bar, H - bar, W / 2 + 2, W));
  EXPECT_FALSE(sameRows(live, gl().render(c, relief("bricks"), kTrilinear), bar, H - bar, 0, W / 2 - 2))
      << "M1 with its gradients x4 should be blurrier than with x1";
  // The header says so wherever it has room (at softpipe's 96 px the layout
  // shortens it with "..."): the same state laid out at 800 x 600.
  bool said = false;
  for (const auto& l : d.scene->build(800, 600, d.measured).labels)
    said = said || l.text.find("gradients x4") != std::string::npos;
  EXPECT_TRUE(said) << "the picture must say its M1/M2 gradients are not the true ones";
}

TEST(Live, TheReferenceIsNotDrawnLive) {
  ts::test::context();
  ts::test::Demo d("parallax_aniso", {"--view", "live", "--mode", "reference"});
  ts::test::context().resize(64, 48);
  EXPECT_TRUE(d.measure().empty());  // no pass, no timing
  EXPECT_EQ(d.frame(64, 48).panel("live"), nullptr);
}

// ------------------------------------------------------------- the causes view
// Seed 003's equations measured one by one (parallax_aniso_causes.hpp), each
// against what the geometry implies, each with a control that fails.
const causes::Cpu& causesOf(const std::string& map) {
  static std::vector<std::pair<std::string, std::unique_ptr<causes::Cpu>>> cache;
  for (auto& c : cache)
    if (c.first == map) return *c.second;
  cache.emplace_back(map, std::make_unique<causes::Cpu>(causes::measureCpu(smallCamera(), relief(map))));
  return *cache.back().second;
}
// The smallest parallax of the full depth over the frame, level-0 texels: a
// step (neighbours' depths more than half the relief apart) moves the shifted
// coordinate by at least half of it.
double smallestParallaxTexels(const Camera& cam) {
  double m = 1e30;
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x)
      m = std::min(m, glm::length(cam.parallax(cam.ray({x + 0.5, y + 0.5}))) * kTexSize);
  return m;
}

TEST(Causes, Eq2ForwardDifferencesJumpAtSteps) {
  const causes::Cpu& c = causesOf("bricks");
  ASSERT_GT(c.stepPixels, 0);
  // Where the shifted coordinate is smooth, a forward difference is off the
  // analytic derivative by its second-order term and the relief's slope:
  // under a texel in the median.
  EXPECT_LT(c.eq2Frame, 1.0);
  // At a step it jumps by the parallax of at least half the relief.
  const double jump = 0.5 * smallestParallaxTexels(smallCamera());
  EXPECT_GT(jump, 4.0);
  EXPECT_GT(c.eq2Steps, jump - 1.0);
  // The seed's printed dv = v - u: wrong by about the distance between u and v, everywhere.
  EXPECT_GT(c.eq2TypoFrame, 100.0);
  // Control: the flat map has no step, and its shifted coordinate is the plain one shifted smoothly.
  const causes::Cpu& flat = causesOf("flat");
  EXPECT_EQ(flat.stepPixels, 0);
  EXPECT_LT(flat.eq2Frame, 0.1);
}

TEST(Causes, FootprintAreaGrowsAtSteps) {
  const causes::Cpu& c = causesOf("bricks");
  // Over the relief the footprint from the shifted differences is the plain
  // one, give or take the slopes; at the steps it is stretched by the jump.
  EXPECT_GT(c.areaRatioMedian, 0.8);
  EXPECT_LT(c.areaRatioMedian, 1.25);
  EXPECT_GT(c.areaRatioStepsMedian, 2.0);
  // Control: on the flat map the parallax is a smooth shift: the ratio is 1.
  EXPECT_NEAR(causesOf("flat").areaRatioMedian, 1.0, 0.02);
}

TEST(Causes, HiddenShareRisesWithTheFootprint) {
  for (const char* map : {"bricks", "step"}) {
    SCOPED_TRACE(map);
    const causes::Cpu& c = causesOf(map);
    std::vector<const causes::Bin*> populated;
    for (const causes::Bin& b : c.bins)
      if (b.pixels >= 20) populated.push_back(&b);
    ASSERT_GE(populated.size(), 2u);
    const causes::Bin *lo = populated.front(), *hi = populated.back();
    // The smallest populated bin below the largest by more than both sampling errors.
    EXPECT_LT(lo->share + 2 * lo->sampleError, hi->share - 2 * hi->sampleError) << lo->name << " vs " << hi->name;
  }
  // Control: nothing is hidden on the flat map, in any bin.
  for (const causes::Bin& b : causesOf("flat").bins)
    if (b.pixels > 0) EXPECT_EQ(b.hidden, 0) << b.name;
}

TEST(Causes, RowWalkBufferKeepsTexelsFromBeingCountedTwice) {
  // A row by hand: no hidden texel -- without the stop index the walk from
  // the right counts all four again; M5's walk does not start it.
  auto none = [](long) { return false; };
  long counted = 0;
  EXPECT_EQ(causes::rowWalkDoubles(0, 3, none, causes::Walk::kBuffer, &counted), 0);
  EXPECT_EQ(counted, 4);
  EXPECT_EQ(causes::rowWalkDoubles(0, 3, none, causes::Walk::kNoBuffer, nullptr), 4);
  EXPECT_EQ(causes::rowWalkDoubles(0, 3, none, causes::Walk::kSeedNoBound, nullptr), 0);
  // A hidden texel at 2: the walks meet it from both sides, nothing twice.
  auto at2 = [](long i) { return i == 2; };
  EXPECT_EQ(causes::rowWalkDoubles(0, 4, at2, causes::Walk::kNoBuffer, nullptr), 0);
  // Over a frame: M5 never counts a texel twice, the walk without its index does.
  const causes::Cpu& c = causesOf("bricks");
  EXPECT_GT(c.walkedTexels, 0);
  EXPECT_EQ(c.doubleBuffer, 0);
  EXPECT_EQ(c.doubleSeedNoBound, 0);
  EXPECT_GT(c.doubleNoBuffer, 0);
  EXPECT_LE(c.doubleNoBuffer, c.walkedTexels);
}

TEST(Causes, SeedFChangesTheEwaOnlyWhereTheFootprintIsSheared) {
  // At 12 degrees of azimuth Uy and Vx are both non-zero: the seed's F
  // (Ux Vy + Uy Vx)^2 differs from det^2 and M3 changes.
  Camera cam = glCamera();
  const Relief& rel = relief("bricks");
  PassOptions po;
  const ts::Image corrected = gl().render(cam, rel, kEwa, po);
  const ts::Image seed = causes::renderSeedF(gl(), cam, rel, po.accel);
  EXPECT_GT(ts::probe::countDiffering(seed, corrected, 0), cam.width * cam.height / 20);
  // Control: looking along +v (azimuth 0) Vx = 0 exactly, the two F are
  // equal and so are the renders, byte for byte.
  cam.azimuthDeg = 0;
  const ts::Image straight = gl().render(cam, rel, kEwa, po);
  EXPECT_EQ(ts::probe::countDiffering(causes::renderSeedF(gl(), cam, rel, po.accel), straight, 0), 0);
}
}  // namespace

// ------------------------------------------------------------- the ranking view
// Bump, normal, parallax, parallax occlusion and displacement mapping lit by one light, held against the
// traced, lit reference (parallax_aniso_ranking.hpp).  What the geometry implies at 20 degrees over bricks
// with deep mortar, asserted from the measured PSNRs: the parallax occlusion march finds the brick faces where
// the unshifted methods (bump, normal) show the mortar behind them, so it is closer than both; a displaced
// grid 2 texels fine is the geometry itself, so it is closest.  The controls: a grid 32 texels coarse loses
// the mortar and drops below the march, and a reference traced with the relief flattened (height scale 0) turns
// the order of bump and the march around: the checks can fail.
#include "demos/parallax_aniso/parallax_aniso_ranking.hpp"
namespace {
using namespace pax;

// The figure's setup (240 x 180, 3 x 3 rays: fewer leave the reference's own noise as large as the
// differences between methods), the grid 2 texels fine: five vertices across each 10-texel joint.
rank::Setup rankSetup(int grid = 2) {
  rank::Setup s;
  s.cam = smallCamera();
  s.cam.width = 240;
  s.cam.height = 180;
  s.rays = 3;
  s.gridTexels = grid;
  return s;
}
#define SKIP_RANKING_ON_SOFTPIPE()                                                                           \
  if (ts::test::isSoftpipe())                                                                                \
  GTEST_SKIP() << "softpipe interprets the shaders and rasterises the displaced grid's 870000 triangles in " \
                  "software: minutes a ranking; llvmpipe and EGL run it"
void printRanking(const char* what, const rank::Ranking& k) {
  std::printf("%s:", what);
  for (int m = 0; m < rank::kMethods; ++m)
    std::printf("  %s %.2f dB (%.3f) #%d", rank::kMethodKeys[m], k.psnr[m], k.ssim[m], k.rank[m]);
  std::printf("\n");
}

TEST(Ranking, TheGeometryImpliesTheOrder) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  SKIP_RANKING_ON_SOFTPIPE();
  const rank::Ranking k = rank::measureRanking(ts::test::renderer(), relief("bricks"), rankSetup());
  printRanking("bricks, 20 degrees, grid 2", k);
  for (int m = 0; m < rank::kMethods; ++m) {
    EXPECT_TRUE(std::isfinite(k.psnr[m])) << rank::kMethodKeys[m];
    EXPECT_GT(k.ssim[m], 0.0) << rank::kMethodKeys[m];
    EXPECT_LE(k.ssim[m], 1.0) << rank::kMethodKeys[m];
  }
  EXPECT_GT(k.psnr[rank::kPom], k.psnr[rank::kBump]);
  EXPECT_GT(k.psnr[rank::kPom], k.psnr[rank::kNormalMap]);
  EXPECT_EQ(k.rank[rank::kDisplacement], 1);
  EXPECT_EQ(k.best(), int(rank::kDisplacement));
  // The ranks are the PSNRs' order.
  for (int a = 0; a < rank::kMethods; ++a)
    for (int b = 0; b < rank::kMethods; ++b)
      if (k.psnr[a] > k.psnr[b]) EXPECT_LT(k.rank[a], k.rank[b]) << rank::kMethodKeys[a] << " " << rank::kMethodKeys[b];
}

// Vertices 32 texels apart, three joints' width: most joints fall between two vertices and vanish.
TEST(Ranking, ACoarseGridDropsBelowTheMarch) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  SKIP_RANKING_ON_SOFTPIPE();
  const rank::Ranking fine = rank::measureRanking(ts::test::renderer(), relief("bricks"), rankSetup(2));
  const rank::Ranking coarse = rank::measureRanking(ts::test::renderer(), relief("bricks"), rankSetup(32));
  printRanking("grid 32", coarse);
  EXPECT_LT(coarse.psnr[rank::kDisplacement], fine.psnr[rank::kDisplacement]);
  EXPECT_LT(coarse.psnr[rank::kDisplacement], coarse.psnr[rank::kPom]);
  EXPECT_GT(coarse.rank[rank::kDisplacement], 1);
  EXPECT_LT(coarse.gridCells * 200, fine.gridCells);  // (32 / 2)^2 = 256 times fewer cells
}

TEST(Ranking, AFlattenedReferenceTurnsTheOrder) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  SKIP_RANKING_ON_SOFTPIPE();
  rank::Setup s = rankSetup();
  s.refHeightScale = 0;  // the wrong reference: no relief to trace, no slopes to light
  const rank::Ranking k = rank::measureRanking(ts::test::renderer(), relief("bricks"), s);
  printRanking("reference flattened", k);
  EXPECT_LT(k.psnr[rank::kPom], k.psnr[rank::kBump]) << "the check of the true order must be able to fail";
  EXPECT_GT(k.rank[rank::kDisplacement], 1);
}

// On the flat map (the bricks' albedo, every height 1) there is no relief: the four per-pixel methods read
// the same coordinate with the normal (0, 0, 1), so they draw one image, c = albedo (ka + (1 - ka) L.z) --
// up to the normal map's quantisation (n.xy within 1/255: (1 - ka) |L.xy| / 255 of the albedo, under a
// level) and a level of rounding.  Each is closer to the reference lit by L than to one lit from below
// (-L: the ambient term alone), the control that shows the Lambert factor is what is compared.
TEST(Ranking, OnAFlatMapEveryMethodIsLambertOfTheAlbedo) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  SKIP_RANKING_ON_SOFTPIPE();
  const rank::Setup s = rankSetup(8);
  const rank::Ranking k = rank::measureRanking(ts::test::renderer(), relief("flat"), s);
  printRanking("flat map", k);
  const ts::Image& a = k.images[rank::kNormalMap];
  for (int m : {rank::kBump, rank::kParallax, rank::kPom}) {
    int worst = 0;
    for (size_t p = 0; p < a.pixels.size(); ++p)
      worst = std::max(worst, std::abs(int(a.pixels[p]) - int(k.images[m].pixels[p])));
    EXPECT_LE(worst, 2) << rank::kMethodKeys[m] << " differs from normal mapping on a flat map";
  }
  rank::Setup below = s;
  below.light.dir = -s.light.dir;
  const ts::Image wrong = rank::traceShaded(below, relief("flat"));
  for (int m = 0; m < rank::kMethods; ++m)
    EXPECT_GT(k.psnr[m], psnr(k.images[m], wrong, nullptr) + 6.0) << rank::kMethodKeys[m];
}

TEST(Ranking, TheFigureSaysWhatTheRanksSay) {
  ts::test::context();
  TS_REQUIRE_GL_VERSION(30);
  SKIP_RANKING_ON_SOFTPIPE();
  ts::test::Demo d("parallax_aniso", {"--view", "ranking", "--res", "80", "--rays", "2", "--grid", "4"});
  const ts::Measurements m = d.measure();
  const auto* shown = m.detailAs<rank::RankShown>();
  ASSERT_NE(shown, nullptr);
  const rank::Ranking& k = *shown->ranking;
  std::string text;
  for (const auto& l : d.scene->build(1360, 640, m).labels) text += l.text + " ";  // wrapped lines joined
  const std::string holds = "claim holds as measured", fails = "claim does not hold as measured";
  EXPECT_EQ(text.find(k.claimHolds() ? holds : fails) != std::string::npos, true) << text;
  EXPECT_EQ(text.find(k.claimHolds() ? fails : holds), std::string::npos) << text;
  // The closest method is named first in the ranking line.
  EXPECT_NE(text.find(std::string("Ranked by PSNR: ") + rank::kMethodKeys[k.best()] + " "), std::string::npos) << text;
}
}  // namespace
