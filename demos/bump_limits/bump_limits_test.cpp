// demos/bump_limits/bump_limits_test.cpp — the bump-limits demo's claims, probed in the pictures its own
// measure() drew and its figures show (never against a stored image): every pixel of each shaded picture is the
// shading equation of bump_limits.cpp's header recomputed on the CPU from the same 8-bit texels; and the numbers
// the figures print follow: horizon mapping leaves far fewer lit shadowed pixels than plain bump mapping, the
// orthogonal-axes method's error grows with shear while Blinn's stays 0, baked shading is exact for its light
// only, and aliasing grows with distance while 4 x 4 supersampling stays near the reference.  Each probe has a
// control: the same check with a wrong parameter must fail.
//
// Tolerances.  A read-back level is the exact grey rounded to 8 bits (half a level); GL_LINEAR's weights are fixed
// point (llvmpipe: 1/256), which moves a bilinear height by at most 1/512 of the two texels' difference (a few
// hundredths of a level of z here) and the slopes by as little: 2 levels.  Pixels within 0.02 of n . L = 0 or
// within 0.5 degrees of their horizon (an 8-bit angle step is 0.35 degrees) are left out: there a rounding may
// flip lit and dark.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "demos/bump_limits/bump_limits_views.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using namespace bumplim;
using ts::test::Demo;
using ts::test::value;

struct Probe {
  Demo demo;
  const Pictures* pictures;
  explicit Probe(const std::vector<std::string>& flags) : demo("bump_limits", flags) {
    demo.measure();
    pictures = demo.measured.detailAs<Pictures>();
  }
  // Picture k as GL read it back (row 0 at the top; a texture holds row 0 at t = 0, the bottom).
  ts::Image picture(size_t k) const {
    ts::Image img = *pictures->shown.at(k).image;
    img.flipVertical();
    return img;
  }
};

// The figure shows measure()'s pictures: each panel's texture is one of them.
void expectFigureShowsPictures(Demo& d, const Pictures& p, int w, int h) {
  const ts::Frame f = d.frame(w, h);
  for (size_t k = 0; k < p.shown.size(); ++k) {
    const ts::Panel& panel = ts::test::panelOf(f, "picture_" + std::to_string(k));
    ASSERT_FALSE(panel.batches.empty());
    EXPECT_EQ(f.textures.at(size_t(panel.batches[0].texture)).image, p.shown[k].image) << "picture " << k;
  }
}

// The CPU's bilinear read of an 8-bit RGBA texture (GL_LINEAR, GL_REPEAT) at texel point (x, y), channel c, 0..1.
double bilinear(const ts::Image& img, double x, double y, int c) {
  const double u = x - 0.5, v = y - 0.5;
  const int i = int(std::floor(u)), j = int(std::floor(v));
  const double a = u - i, b = v - j;
  auto t = [&](int ii, int jj) {
    ii = ((ii % img.width) + img.width) % img.width, jj = ((jj % img.height) + img.height) % img.height;
    const ts::Rgba p = img.at(ii, jj);
    return (&p.r)[c] / 255.0;
  };
  return (1 - a) * (1 - b) * t(i, j) + a * (1 - b) * t(i + 1, j) + (1 - a) * b * t(i, j + 1) + a * b * t(i + 1, j + 1);
}
// The shader's normal for `method` at texel point (x, y), from the CPU's copies of its textures; `e` moves the
// filtered values the normal is made of (Blinn: the two height differences, z units; the maps: their channels,
// 0..1), to bound what the filtered texels' own 8 bits may change.
glm::dvec3 cpuNormal(const Field& f, Method method, double x, double y, glm::dvec3 e = glm::dvec3(0), double step = 1) {
  if (method == Method::kBlinn) {
    const double dx = f.at(x + step, y) - f.at(x - step, y) + e.x, dy = f.at(x, y + step) - f.at(x, y - step) + e.y;
    return glm::normalize(glm::dvec3(-dx / (2 * step), -dy / (2 * step), 1));
  }
  if (method == Method::kNormalMap) {
    static const ts::Image map = normalMapImage();
    const glm::dvec3 c(bilinear(map, x, y, 0), bilinear(map, x, y, 1), bilinear(map, x, y, 2));
    return glm::normalize((c + e) * 2.0 - 1.0);
  }
  static const ts::Image map = offsetMapImage();
  return glm::normalize(glm::dvec3((bilinear(map, x, y, 0) + e.x) * 2 - 1, (bilinear(map, x, y, 1) + e.y) * 2 - 1, 0) *
                            kOffsetRange +
                        glm::dvec3(0, 0, 1));
}
// The grey the shading equation gives, and how far the filtered values' 8 bits may move it: llvmpipe returns a
// GL_LINEAR sample of an 8-bit texture in 8 bits, so each filtered value may be a step off (a height difference
// two steps of kHeightMax / 255, a map channel one step of 1 / 255); the bound is the largest change over those
// corners, plus 2 levels (the read-back's rounding and the weights' fixed point, the header's tolerance).
struct Shade {
  double want, tolerance;
};
Shade shadeBound(const Field& f, Method method, double x, double y, const glm::dvec3& L, double lit, double step = 1) {
  auto grey = [&](glm::dvec3 e) {
    return 255.0 * (kAmbient + (1 - kAmbient) * std::max(glm::dot(cpuNormal(f, method, x, y, e, step), L), 0.0) * lit);
  };
  const double want = grey(glm::dvec3(0));
  const double step8 = method == Method::kBlinn ? 2 * kHeightMax / 255 : 1.0 / 255;
  double worst = 0;
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 e((c & 1 ? 1 : -1) * step8, (c & 2 ? 1 : -1) * step8,
                       method == Method::kNormalMap ? (c & 4 ? 1 : -1) * step8 : 0);
    worst = std::max(worst, std::fabs(grey(e) - want));
  }
  return {want, worst + 2};
}

// The horizon the shader interpolates at the light's azimuth, radians.
double cpuHorizon(const std::vector<ts::Image>& maps, double x, double y, double azDeg) {
  const double k = std::fmod(azDeg + 360, 360) / 45;
  const int k0 = int(std::floor(k));
  const double a = k - k0;
  auto pick = [&](int d) { return bilinear(maps[size_t((d % 8) / 4)], x, y, (d % 8) % 4) * kPi / 2; };
  return (1 - a) * pick(k0) + a * pick(k0 + 1);
}

// Pixels of `img` (zoom pixels a texel) further than 2 levels from the equation, of those not near a threshold.
struct Fit {
  long off = 0, probed = 0;
};
Fit fitShading(const ts::Image& img, double zoom, Method method, double az, double elev, bool horizon,
               const std::vector<ts::Image>& maps) {
  const Field field;
  const glm::dvec3 L = lightVector(az, elev);
  Fit fit;
  for (int y = 0; y < img.height; y += 3)
    for (int x = 0; x < img.width; x += 3) {
      const glm::dvec2 q = texelPoint(x, y, img.height, zoom);
      const double nl = glm::dot(cpuNormal(field, method, q.x, q.y), L);
      double lit = 1;
      if (horizon) {
        const double h = cpuHorizon(maps, q.x, q.y, az), e = elev * kPi / 180;
        if (std::fabs(e - h) < 0.5 * kPi / 180) continue;
        lit = e > h;
      }
      if (std::fabs(nl) < 0.02) continue;
      const Shade sh = shadeBound(field, method, q.x, q.y, L, lit);
      ++fit.probed;
      fit.off += std::fabs(img.at(x, y).r - sh.want) > sh.tolerance;
    }
  return fit;
}

TEST(BumpLimits, ShadowsPicturesAreTheEquationAndHorizonMappingLeavesFewShadowsLit) {
  Probe p({"--view", "shadows"});
  ASSERT_NE(p.pictures, nullptr);
  ASSERT_EQ(p.pictures->shown.size(), 4u);
  expectFigureShowsPictures(p.demo, *p.pictures, 1000, 460);
  const std::vector<ts::Image> maps = horizonMaps(Field());
  const Fit plain = fitShading(p.picture(0), kShadowZoom, Method::kBlinn, 30, 20, false, maps);
  const Fit hor = fitShading(p.picture(1), kShadowZoom, Method::kBlinn, 30, 20, true, maps);
  EXPECT_GT(plain.probed, 5000);
  EXPECT_GT(hor.probed, 5000);
  EXPECT_EQ(plain.off, 0);
  EXPECT_EQ(hor.off, 0);
  // Controls: the horizon picture is not plain bump mapping, nor horizon mapping for a light 45 degrees round.
  EXPECT_GT(fitShading(p.picture(1), kShadowZoom, Method::kBlinn, 30, 20, false, maps).off, hor.probed / 10);
  EXPECT_GT(fitShading(p.picture(1), kShadowZoom, Method::kBlinn, 75, 20, true, maps).off, hor.probed / 10);

  // The claim: horizon mapping leaves under a quarter of the shadowed pixels plain bump mapping lights, and the
  // control (the horizon looked up a quarter turn away) leaves more than twice its own.
  const ts::Measurements& m = p.demo.measured;
  EXPECT_GT(value(m, "bump_self_shadow_px[none]"), 0.1 * value(m, "bump_shadowed_px"));
  EXPECT_LT(value(m, "bump_self_shadow_px[horizon]"), 0.25 * value(m, "bump_self_shadow_px[none]"));
  EXPECT_GT(value(m, "bump_self_shadow_px[horizon_wrong_azimuth]"), 2 * value(m, "bump_self_shadow_px[horizon]"));
  // The ray march itself: a light straight above casts no shadow, a grazing one shadows most of the plane.
  const Field f;
  EXPECT_FALSE(rayShadowed(f, 10.5, 20.5, 0, kPi / 2));
  long grazing = 0;
  for (int j = 0; j < kTexels; j += 4)
    for (int i = 0; i < kTexels; i += 4) grazing += rayShadowed(f, i + 0.5, j + 0.5, 0, 2 * kPi / 180);
  EXPECT_GT(grazing, (kTexels / 4) * (kTexels / 4) / 2);
}

TEST(BumpLimits, MethodsPicturesAreTheirEquationsAndShearAndBakingBehave) {
  Probe p({"--view", "methods", "--shear", "60"});
  ASSERT_NE(p.pictures, nullptr);
  ASSERT_EQ(p.pictures->shown.size(), 5u);
  expectFigureShowsPictures(p.demo, *p.pictures, 1000, 640);
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE(kMethodKeys[k]);
    const Fit fit = fitShading(p.picture(size_t(k)), kMethodZoom, Method(k), 30, 45, false, {});
    EXPECT_GT(fit.probed, 5000);
    EXPECT_EQ(fit.off, 0);
  }
  // Control: Blinn's picture is not the normal map's equation, nor the light at another azimuth.
  EXPECT_GT(fitShading(p.picture(0), kMethodZoom, Method::kNormalMap, 30, 45, false, {}).off, 500);
  EXPECT_GT(fitShading(p.picture(0), kMethodZoom, Method::kBlinn, 45, 45, false, {}).off, 500);

  // Each method's measured error is its equation's: the CPU's normals against the exact ones, within the 8-bit
  // read-back (the demo's bump_normal_error_deg[readback], an average, doubled for the worst of rounding).
  const ts::Measurements& m = p.demo.measured;
  const Field field;
  for (int k = 0; k < 3; ++k) {
    double sum = 0;
    int n = 0;
    for (int y = 0; y < kMethodPixels; y += 2)
      for (int x = 0; x < kMethodPixels; x += 2, ++n) {
        const glm::dvec2 q = texelPoint(x, y, kMethodPixels, kMethodZoom);
        sum += angleDeg(cpuNormal(field, Method(k), q.x, q.y), exactNormal(q.x, q.y));
      }
    EXPECT_NEAR(value(m, std::string("bump_normal_error_deg[") + kMethodKeys[k] + "]"), sum / n,
                2 * value(m, "bump_normal_error_deg[readback]"))
        << kMethodKeys[k];
  }
  // Shear: 0 at 90 degrees, growing as theta falls; Blinn's formula keeps it 0 (to double precision).
  EXPECT_LT(value(m, "bump_shear_error_deg[90]"), 1e-6);
  EXPECT_GT(value(m, "bump_shear_error_deg[75]"), 1.0);
  EXPECT_GT(value(m, "bump_shear_error_deg[60]"), value(m, "bump_shear_error_deg[75]"));
  EXPECT_GT(value(m, "bump_shear_error_deg[45]"), value(m, "bump_shear_error_deg[60]"));
  EXPECT_LT(value(m, "bump_shear_error_deg[blinn_shown]"), 1e-6);
  EXPECT_DOUBLE_EQ(value(m, "bump_shear_error_deg[shown]"), value(m, "bump_shear_error_deg[60]"));
  // Not square: the orthogonal unit axes are off, Blinn's formula is not.
  EXPECT_GT(value(m, "bump_stretch_error_deg[orthogonal]"), 1.0);
  EXPECT_LT(value(m, "bump_stretch_error_deg[blinn]"), 1e-6);
  // The true sheared normal is the cross product of the displaced surface's partials (checked at one point by a
  // finite difference of p(s, t) = s Ps + t Pt + z n).
  const double th = 50 * kPi / 180, e = 1e-5, s0 = 11.3, t0 = 27.8;
  auto P = [&](double s, double t) {
    return glm::dvec3(s + t * std::cos(th), t * std::sin(th), kHeightMax * heightAt(s, t));
  };
  const glm::dvec3 fd = glm::normalize(glm::cross(P(s0 + e, t0) - P(s0 - e, t0), P(s0, t0 + e) - P(s0, t0 - e)));
  EXPECT_LT(angleDeg(fd, shearedTrueNormal(s0, t0, th)), 1e-3);
  EXPECT_GT(angleDeg(fd, shearedOrthogonalNormal(s0, t0, th)), 1e-2);  // control
  // Baking: exact for its light, off once the light moved.
  EXPECT_EQ(value(m, "bump_baked_error_levels[same_light]"), 0);
  EXPECT_GT(value(m, "bump_baked_rms_levels[moved]"), 2);
  // The baked picture (one texel a block of kMethodZoom pixels) is the shading at texel centres for its light.
  const Fit baked = [&] {
    Fit fit;
    const ts::Image img = p.picture(3);
    for (int j = 0; j < kTexels; ++j)
      for (int i = 0; i < kTexels; ++i) {
        const int x = int((i + 0.5) * kMethodZoom), y = img.height - 1 - int((j + 0.5) * kMethodZoom);
        const double nl = glm::dot(cpuNormal(field, Method::kBlinn, i + 0.5, j + 0.5), lightVector(30, 45));
        if (std::fabs(nl) < 0.02) continue;
        const Shade sh = shadeBound(field, Method::kBlinn, i + 0.5, j + 0.5, lightVector(30, 45), 1);
        ++fit.probed;
        fit.off += std::fabs(img.at(x, y).r - sh.want) > sh.tolerance;
      }
    return fit;
  }();
  EXPECT_GT(baked.probed, 2000);
  EXPECT_EQ(baked.off, 0);
}

TEST(BumpLimits, DistanceAliasesUnfilteredAndSupersamplingAnswersIt) {
  Probe p({"--view", "distance", "--distance", "4"});
  ASSERT_NE(p.pictures, nullptr);
  ASSERT_EQ(p.pictures->shown.size(), 4u);
  expectFigureShowsPictures(p.demo, *p.pictures, 1000, 480);
  // The unfiltered picture at 4x is the equation at each pixel centre (0.5 pixels a texel); not at 2x (control).
  const Fit at4 = fitShading(p.picture(0), zoomAt(4), Method::kBlinn, 30, 45, false, {});
  EXPECT_GT(at4.probed, 1000);
  EXPECT_EQ(at4.off, 0);
  EXPECT_GT(fitShading(p.picture(0), zoomAt(2), Method::kBlinn, 30, 45, false, {}).off, at4.probed / 4);
  // The 4 x 4 picture is the unfiltered one's equation averaged over 4 x 4 sample centres a pixel, within a level
  // of rounding each (the box filter of 8-bit samples, rounded again).
  const Field field;
  const glm::dvec3 L = lightVector(30, 45);
  long superOff = 0;
  const ts::Image sup = p.picture(2);
  for (int y = 0; y < sup.height; y += 5)
    for (int x = 0; x < sup.width; x += 5) {
      double sum = 0, tol = 0;
      for (int b = 0; b < kSuper; ++b)
        for (int a = 0; a < kSuper; ++a) {
          const glm::dvec2 q = texelPoint(x * kSuper + a, y * kSuper + b, sup.height * kSuper, zoomAt(4) * kSuper);
          const Shade sh = shadeBound(field, Method::kBlinn, q.x, q.y, L, 1);
          sum += sh.want, tol += sh.tolerance;
        }
      // The box filter rounds the mean of the samples once more: half a level.
      superOff += std::fabs(sup.at(x, y).r - sum / (kSuper * kSuper)) > tol / (kSuper * kSuper) + 0.5;
    }
  EXPECT_EQ(superOff, 0);

  const ts::Measurements& m = p.demo.measured;
  auto v = [&](const char* what, int d) { return value(m, std::string(what) + "[" + std::to_string(d) + "x]"); };
  // Aliasing grows with distance; 4 x 4 supersampling stays near the reference (under a quarter of the
  // unfiltered error at 4x and 8x); mipmapped heights lose the bumps' tilt far away and 4 x 4 does not.
  EXPECT_LT(v("bump_distance_rms_levels[unfiltered]", 1), v("bump_distance_rms_levels[unfiltered]", 2));
  EXPECT_LT(v("bump_distance_rms_levels[unfiltered]", 2), v("bump_distance_rms_levels[unfiltered]", 4));
  EXPECT_LT(v("bump_distance_rms_levels[unfiltered]", 4), v("bump_distance_rms_levels[unfiltered]", 8));
  for (int d : {4, 8})
    EXPECT_LT(v("bump_distance_rms_levels[super4x4]", d), 0.25 * v("bump_distance_rms_levels[unfiltered]", d)) << d;
  EXPECT_GT(v("bump_tilt_lost_deg[mipmapped]", 8), 0.25 * v("bump_tilt_deg[reference]", 8));
  EXPECT_LT(std::fabs(v("bump_tilt_lost_deg[super4x4]", 8)), 0.25 * v("bump_tilt_lost_deg[mipmapped]", 8));
}

// View torus.  The plain picture is Blinn's perturbed normal on the torus lit by the two lights, recomputed on the
// CPU at each pixel's (s, t) as GL read it back (the same 8-bit heights, bilinear); the reference's trace and the
// horizon map are checked against closed forms on the smooth torus; the claim's numbers against their controls.
double torusGrey(const TorusField& f, double s, double t, const glm::dvec3 L[2], glm::dvec2 e = glm::dvec2(0),
                 const double lit[2] = nullptr) {
  const ts::TorusFrame fr = ts::torusFrameAt(kTorusR, kTorusr, {s, t});
  const double x = s * kRepS * kTexels, y = t * kRepT * kTexels, k = kHeightWorld / kHeightMax;
  // dP/ds, dP/dt: central differences a texel apart (the shader's), e moving each difference
  const double ps = (k * (f.tile.at(x + 1, y) - f.tile.at(x - 1, y)) + e.x) * kRepS * kTexels / 2;
  const double pt = (k * (f.tile.at(x, y + 1) - f.tile.at(x, y - 1)) + e.y) * kRepT * kTexels / 2;
  const glm::dvec3 n = glm::normalize(fr.N - ps / glm::length(fr.Qs) * fr.T - pt / glm::length(fr.Qt) * fr.B);
  double g = kAmbient;
  for (int i = 0; i < 2; ++i) g += kTorusIntensity[i] * std::max(glm::dot(n, L[i]), 0.0) * (lit ? lit[i] : 1.0);
  return 255 * g;
}
// The horizon map's lookup as the shader makes it: the light's azimuth and elevation in the smooth frame (T, B, N),
// the two nearest azimuths' angles interpolated; returns elevation - horizon, radians (lit when > 0).
double torusAboveHorizon(const std::vector<ts::Image>& maps, double s, double t, const glm::dvec3& L,
                         double shiftDeg = 0) {
  const ts::TorusFrame fr = ts::torusFrameAt(kTorusR, kTorusr, {s, t});
  const double az = std::fmod(std::atan2(glm::dot(L, fr.B), glm::dot(L, fr.T)) + shiftDeg * kPi / 180 + 4 * kPi,
                              2 * kPi);
  const double el = std::asin(std::clamp(glm::dot(L, fr.N), -1.0, 1.0));
  const double k = az / (kPi / 4), x = s * kRepS * kTexels, y = t * kRepT * kTexels;
  const int k0 = int(std::floor(k)) % 8, k1 = (k0 + 1) % 8;
  auto pick = [&](int d) { return (bilinear(maps[size_t(d / 4)], x, y, d % 4) - 0.5) * kPi; };
  return el - ((1 - (k - std::floor(k))) * pick(k0) + (k - std::floor(k)) * pick(k1));
}
// The horizon picture against the equation with the horizon map's lookup, pixels within half a degree of their
// horizon left out (an 8-bit angle step is 0.7 degrees; GL_LINEAR's weights move it a little more).
Fit fitTorusHorizon(const Pictures& p, const ts::Image& img, const glm::dvec3 L[2], const std::vector<ts::Image>& maps,
                    double shiftDeg) {
  const TorusField f;
  Fit fit;
  const int n = kTorusPixels;
  for (int y = 1; y < n - 1; y += 2)
    for (int x = 1; x < n - 1; x += 2) {
      auto st = [&](int xx, int yy) { return p.st[size_t(yy) * n + size_t(xx)]; };
      if (st(x, y).x < 0 || st(x - 1, y).x < 0 || st(x + 1, y).x < 0 || st(x, y - 1).x < 0 || st(x, y + 1).x < 0)
        continue;
      const glm::dvec2 q = st(x, y);
      double lit[2];
      bool near = false;
      for (int k = 0; k < 2; ++k) {
        const double a = torusAboveHorizon(maps, q.x, q.y, L[k], shiftDeg);
        near |= std::fabs(a) < 0.5 * kPi / 180;
        lit[k] = a > 0;
      }
      if (near) continue;
      const double want = torusGrey(f, q.x, q.y, L, glm::dvec2(0), lit);
      const double e = 2 * kHeightWorld / 255;
      double worst = 0;
      for (int c = 0; c < 4; ++c)
        worst = std::max(worst, std::fabs(torusGrey(f, q.x, q.y, L, {c & 1 ? e : -e, c & 2 ? e : -e}, lit) - want));
      ++fit.probed;
      fit.off += std::fabs(img.at(x, y).r - want) > worst + 2;
    }
  return fit;
}
Fit fitTorus(const Pictures& p, const ts::Image& img, const glm::dvec3 L[2]) {
  const TorusField f;
  Fit fit;
  const int n = kTorusPixels;
  for (int y = 1; y < n - 1; y += 2)
    for (int x = 1; x < n - 1; x += 2) {
      auto st = [&](int xx, int yy) { return p.st[size_t(yy) * n + size_t(xx)]; };
      if (st(x, y).x < 0 || st(x - 1, y).x < 0 || st(x + 1, y).x < 0 || st(x, y - 1).x < 0 || st(x, y + 1).x < 0)
        continue;  // the silhouette's pixels: a neighbour off the torus
      const glm::dvec2 q = st(x, y);
      const double want = torusGrey(f, q.x, q.y, L);
      // The filtered heights' 8 bits: each difference may be 2 steps of kHeightWorld / 255 off; plus 2 levels.
      const double e = 2 * kHeightWorld / 255;
      double worst = 0;
      for (int c = 0; c < 4; ++c)
        worst = std::max(worst, std::fabs(torusGrey(f, q.x, q.y, L, {c & 1 ? e : -e, c & 2 ? e : -e}) - want));
      ++fit.probed;
      fit.off += std::fabs(img.at(x, y).r - want) > worst + 2;
    }
  return fit;
}

TEST(BumpLimits, TorusPicturesAreTheEquationAndHorizonMappingLeavesFewShadowsLit) {
  Probe p({"--view", "torus"});
  ASSERT_NE(p.pictures, nullptr);
  ASSERT_EQ(p.pictures->shown.size(), 5u);
  expectFigureShowsPictures(p.demo, *p.pictures, 1000, 480);
  const ts::Image plain = p.picture(0), hor = p.picture(1);  // row 0 at the top, as pictures->st
  const glm::dvec3 L[2] = {torusLight(0), torusLight(1)};
  const Fit fit = fitTorus(*p.pictures, plain, L);
  EXPECT_GT(fit.probed, 3000);
  EXPECT_EQ(fit.off, 0);
  // Control: light 1 moved 30 degrees round (in the eye's frame) does not fit.
  const double az = (kTorusLights[0][0] + 30) * kPi / 180, el = kTorusLights[0][1] * kPi / 180;
  const glm::dvec3 moved[2] = {eyeToWorld({std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)}),
                               L[1]};
  EXPECT_GT(fitTorus(*p.pictures, plain, moved).off, fit.probed / 10);
  // The horizon picture is the same shading with each light's horizon test (the map recomputed here from the
  // CPU's equations); control: the lookup a quarter turn off does not fit it.
  const std::vector<ts::Image> maps = torusHorizonMaps(TorusField());
  const Fit hfit = fitTorusHorizon(*p.pictures, hor, L, maps, 0);
  EXPECT_GT(hfit.probed, 3000);
  EXPECT_EQ(hfit.off, 0);
  EXPECT_GT(fitTorusHorizon(*p.pictures, hor, L, maps, 90).off, hfit.probed / 50);
  // Horizon mapping only darkens: each of its pixels is plain bump mapping's or darker (a level of rounding).
  long brighter = 0, darker = 0;
  for (int y = 0; y < kTorusPixels; ++y)
    for (int x = 0; x < kTorusPixels; ++x) {
      brighter += hor.at(x, y).r > plain.at(x, y).r + 1;
      darker += hor.at(x, y).r + 1 < plain.at(x, y).r;
    }
  EXPECT_EQ(brighter, 0);
  EXPECT_GT(darker, 0);

  // The claim, with its controls: plain bump mapping lights shadowed pixels; horizon mapping leaves under a
  // quarter of them; looked up a quarter turn off, or made of the smooth torus, it leaves more than twice its own.
  const ts::Measurements& m = p.demo.measured;
  EXPECT_GT(value(m, "bump_self_shadow_torus_px[none]"), 0);
  EXPECT_LT(value(m, "bump_self_shadow_torus_px[horizon]"), 0.25 * value(m, "bump_self_shadow_torus_px[none]"));
  EXPECT_GT(value(m, "bump_self_shadow_torus_px[horizon_wrong_azimuth]"),
            2 * value(m, "bump_self_shadow_torus_px[horizon]"));
  EXPECT_GT(value(m, "bump_self_shadow_torus_px[horizon_smooth]"), 2 * value(m, "bump_self_shadow_torus_px[horizon]"));
  // Against the traced picture horizon mapping is closer than plain bump mapping, and so is the PTM; the PTM's
  // biquadratic fits its shadowed samples worse than the same fit without the shadows (they are not smooth).
  EXPECT_LT(value(m, "bump_shadow_torus_rms_levels[horizon]"), value(m, "bump_shadow_torus_rms_levels[none]"));
  EXPECT_LT(value(m, "bump_shadow_torus_rms_levels[ptm]"), value(m, "bump_shadow_torus_rms_levels[none]"));
  EXPECT_GT(value(m, "bump_ptm_fit_rms_levels"), value(m, "bump_ptm_fit_rms_levels[unshadowed]"));

  // The trace: the outer equator lit along its normal is not shadowed; the inner equator lit along its normal,
  // across the hole, is (the far side of the ring is in the way); the far side's outer equator, lit by that same
  // light along its own normal, is not (a control).
  const TorusField f;
  EXPECT_FALSE(torusShadowed(f, 0, 0, {0, 0, 1}));
  EXPECT_TRUE(torusShadowed(f, 0, 0.5, {0, 0, -1}));
  EXPECT_FALSE(torusShadowed(f, 0.5, 0, {0, 0, -1}));
  // The horizon of the smooth torus: along the ring at the inner equator the surface is the circle of radius
  // R - r curving towards the normal, so a point an arc sigma away is sigma / (2 (R - r)) above the tangent
  // plane; around the tube it curves away (below 0).
  double last = 0;
  for (double sg = kHorizonFirst; sg <= kHorizonReachWorld; sg += std::max(kHorizonFirst, kHorizonGrowth * sg))
    last = sg;
  EXPECT_NEAR(torusHorizonAngle(f, 0, 0.5, 0, 0), last / (2 * (kTorusR - kTorusr)), 1e-9);
  EXPECT_LT(torusHorizonAngle(f, 0, 0, kPi / 2, 0), 0);
  EXPECT_GT(torusHorizonAngle(f, 0, 0.5, 0, 0), 0.1);  // control: the same direction seen from the inner side
}
}  // namespace
