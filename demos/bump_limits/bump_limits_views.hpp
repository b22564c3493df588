// demos/bump_limits/bump_limits_views.hpp — the three views' measurements (bump_limits_gl.hpp's passes read
// back, against bump_limits_math.hpp's CPU answers) and the row of pictures each figure shows.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bump_limits_gl.hpp"
#include "bump_limits_torus.hpp"
#include "common/core/layout.hpp"
#include "common/core/plot.hpp"
#include "common/core/scene.hpp"

namespace bumplim {
constexpr int kShadowPixels = 256, kShadowZoom = 4;  // the shadows view: the tile at 4 pixels a texel
constexpr int kMethodPixels = 256, kMethodZoom = 4;
constexpr int kDistancePixels = 128;            // the distance view's picture, pixels a side
constexpr int kSuper = 4, kReferenceSuper = 8;  // Blinn's 4 x 4 samples a pixel; the reference's 8 x 8
constexpr double kBakeMoveDeg = 30;             // the light moves this much in azimuth after baking
constexpr double kThetas[] = {90, 75, 60, 45};  // the sheared parameterisation's table, degrees
constexpr int kDistances[] = {1, 2, 4, 8};
constexpr double kStretch =
    2;  // the texture stretched: |dp/dt| = 2 |dp/ds|           // the distance view's distances (1x: 2 pixels a texel)

// Colours that mean something in the pictures (each has its legend entry).
const glm::vec4 kMissed{0.95f, 0.2f, 0.2f, 1}, kExtra{0.3f, 0.6f, 1.0f, 1};
const glm::vec4 kLitBoth{0.78f, 0.78f, 0.78f, 1}, kDarkBoth{0.3f, 0.3f, 0.3f, 1};
inline ts::Rgba rgba(glm::vec4 c) { return {u8(c.r), u8(c.g), u8(c.b), 255}; }

struct Pictures {
  int view = -1;                       // the view they are of (a window's key may have changed it since)
  std::vector<ts::TextureDesc> shown;  // the view's pictures, in order
  // View torus: each pixel's (s, t) as GL read it back (s < 0 off the torus), row 0 at the top, and what the
  // reference found there (bit k: light k+1 shadows it), for the test.
  std::vector<glm::dvec2> st;
  std::vector<uint8_t> rayShadow;
};

// The texel point at pixel (x, y) of a picture read back (row 0 at the top), `zoom` pixels a texel.
inline glm::dvec2 texelPoint(int x, int y, int size, double zoom) {
  return {(x + 0.5) / zoom, (size - 1 - y + 0.5) / zoom};
}
// The CPU's shadow picture: the displaced surface's ray-marched shadows, 1 = shadowed.
inline std::vector<uint8_t> rayShadows(const Field& f, double az, double elev, int size, double zoom) {
  std::vector<uint8_t> out(size_t(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec2 p = texelPoint(x, y, size, zoom);
      out[size_t(y) * size + size_t(x)] = rayShadowed(f, p.x, p.y, az * kPi / 180, elev * kPi / 180);
    }
  return out;
}

// ---- view shadows ------------------------------------------------------------------------------------------------
inline void measureShadows(ts::Renderer& r, double az, double elev, ts::Measurements& ms, Pictures& pic) {
  auto put = [&](const std::string& n, double v, const std::string& m) { ms.push_back({n, v, m}); };
  const Field field;
  Inputs in;
  in.horizons = horizonMaps(field);
  Pass p;
  p.azDeg = az, p.elevDeg = elev, p.size = kShadowPixels, p.zoom = kShadowZoom;
  p.output = Output::kMasks, p.horizon = true;
  const ts::Image masks = shaderPass(r, in, p);
  Pass wrong = p;  // a control: the horizon looked up a quarter turn away from the light
  wrong.azDeg = az + 90;
  const ts::Image wrongMasks = shaderPass(r, in, wrong);
  ts::measureProgress(0.3);
  const std::vector<uint8_t> ray = rayShadows(field, az, elev, kShadowPixels, kShadowZoom);
  ts::measureProgress(0.7);
  long none = 0, missed = 0, extra = 0, shadowed = 0, wrongMissed = 0;
  ts::Image diff(kShadowPixels, kShadowPixels);
  for (int y = 0; y < kShadowPixels; ++y)
    for (int x = 0; x < kShadowPixels; ++x) {
      const ts::Rgba m = masks.at(x, y), w = wrongMasks.at(x, y);
      const bool facing = m.r > 127, horizonLit = m.g > 127, s = ray[size_t(y) * kShadowPixels + size_t(x)];
      shadowed += s;
      none += s && facing;
      missed += s && facing && horizonLit;
      extra += !s && facing && !horizonLit;
      wrongMissed += s && facing && w.g > 127;
      diff.set(x, y,
               s && facing && horizonLit     ? rgba(kMissed)
               : !s && facing && !horizonLit ? rgba(kExtra)
               : !s && facing                ? rgba(kLitBoth)
                                             : rgba(kDarkBoth));
    }
  put("bump_self_shadow_px[none]", double(none),
      "pixels the displaced surface's ray-marched shadow covers that plain bump mapping lights (n . L > 0)");
  put("bump_self_shadow_px[horizon]", double(missed),
      "the same with horizon mapping (8 directions): shadowed pixels it still lights");
  put("bump_self_shadow_px[horizon_extra]", double(extra),
      "pixels horizon mapping darkens that the ray march lights (and n . L > 0)");
  put("bump_self_shadow_px[horizon_wrong_azimuth]", double(wrongMissed),
      "shadowed pixels lit when the horizon is looked up a quarter turn from the light (a control that must miss "
      "many)");
  put("bump_shadowed_px", double(shadowed),
      "pixels the ray march shadows, of " + std::to_string(kShadowPixels * kShadowPixels));
  ts::gl::CallList noneCalls, horizonCalls;
  ts::Image shadeNone, shadeHorizon;
  Pass shade = p;
  shade.output = Output::kShade, shade.horizon = false;
  noneCalls = recorded(r, [&] { shadeNone = shaderPass(r, in, shade); });
  shade.horizon = true;
  horizonCalls = recorded(r, [&] { shadeHorizon = shaderPass(r, in, shade); });
  ts::Image rayPic = shadeNone;
  for (int y = 0; y < kShadowPixels; ++y)
    for (int x = 0; x < kShadowPixels; ++x)
      if (ray[size_t(y) * kShadowPixels + size_t(x)]) {
        const uint8_t a = u8(kAmbient);
        rayPic.set(x, y, {a, a, a, 255});
      }
  pic.shown = {glPicture(shadeNone, "plain bump mapping", noneCalls),
               glPicture(shadeHorizon, "horizon mapping", horizonCalls),
               shownPicture(rayPic, "bump shading darkened where the ray march shadows"),
               shownPicture(diff, "horizon mapping against the ray march")};
}

// ---- view torus ---------------------------------------------------------------------------------------------------
inline void measureTorus(ts::Renderer& r, ts::Measurements& ms, Pictures& pic) {
  auto put = [&](const std::string& n, double v, const std::string& m) { ms.push_back({n, v, m}); };
  const TorusField field;
  const HorizonAngles angles = torusHorizonAngles(field);
  const std::vector<ts::Image> maps = torusHorizonMaps(angles), smoothMaps = torusHorizonMaps(field, 0);
  const Ptm ptm = fitPtm(field, angles);
  ts::measureProgress(0.3);
  TorusPass p;
  p.maps = &maps;
  p.output = TorusOutput::kS;
  const ts::Image sImg = torusPass(r, p);
  p.output = TorusOutput::kT;
  const ts::Image tImg = torusPass(r, p);
  p.output = TorusOutput::kDiffuse;
  const ts::Image diffuse = torusPass(r, p);
  TorusPass wrong = p;  // controls: the horizon looked up a quarter turn from the light; the smooth torus's horizon
  wrong.azShiftDeg = 90;
  const ts::Image wrongImg = torusPass(r, wrong);
  TorusPass smooth = p;
  smooth.maps = &smoothMaps;
  const ts::Image smoothImg = torusPass(r, smooth);
  const int n = kTorusPixels;
  pic.st.assign(size_t(n) * n, glm::dvec2(-1));
  pic.rayShadow.assign(size_t(n) * n, 0);
  const glm::dvec3 L[2] = {torusLight(0), torusLight(1)};
  long none = 0, missed = 0, extra = 0, shadowed = 0, wrongMissed = 0, smoothMissed = 0, covered = 0;
  ts::Image diff(n, n), refPic(n, n);
  auto litBit = [](uint8_t b, int k) { return k == 0 ? b >= 96 : (b % 128) >= 32; };  // b = 128 lit1 + 64 lit2
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const ts::Rgba cs = sImg.at(x, y), ct = tImg.at(x, y), d = diffuse.at(x, y);
      if (cs.b < 128) {
        diff.set(x, y, {0, 0, 0, 255}), refPic.set(x, y, {0, 0, 0, 255});
        continue;
      }
      ++covered;
      const glm::dvec2 st((cs.r * 256 + cs.g) / 65535.0, (ct.r * 256 + ct.g) / 65535.0);
      const size_t at = size_t(y) * n + size_t(x);
      pic.st[at] = st;
      bool anyNone = false, anyMissed = false, anyExtra = false, anyLitBoth = false, anyWrong = false,
           anySmooth = false, anyShadow = false;
      double grey = kAmbient;
      for (int k = 0; k < 2; ++k) {
        const uint8_t dk = k == 0 ? d.r : d.g;
        const bool facing = dk > 0, hLit = litBit(d.b, k);
        const bool traced = torusShadowed(field, st.x, st.y, L[k]), s = facing && traced;
        pic.rayShadow[at] |= uint8_t(traced << k);
        anyShadow |= traced;
        anyNone |= s;
        anyMissed |= s && hLit;
        anyExtra |= facing && !s && !hLit;
        anyLitBoth |= facing && !s && hLit;
        anyWrong |= s && litBit(wrongImg.at(x, y).b, k);
        anySmooth |= s && litBit(smoothImg.at(x, y).b, k);
        if (!s) grey += kTorusIntensity[k] * dk / 255.0;
      }
      shadowed += anyShadow, none += anyNone, missed += anyMissed, extra += anyExtra;
      wrongMissed += anyWrong, smoothMissed += anySmooth;
      diff.set(x, y,
               anyMissed    ? rgba(kMissed)
               : anyExtra   ? rgba(kExtra)
               : anyLitBoth ? rgba(kLitBoth)
                            : rgba(kDarkBoth));
      const uint8_t g = u8(std::min(grey, 1.0));
      refPic.set(x, y, {g, g, g, 255});
    }
    if (y % 32 == 31) ts::measureProgress(0.3 + 0.6 * (y + 1) / n);
  }
  put("bump_self_shadow_torus_px[none]", double(none),
      "pixels of the bumped torus that plain bump mapping lights (n' . L > 0) from a light whose ray from the "
      "displaced surface's point at the same (s, t) hits the displaced torus (traced on the CPU)");
  put("bump_self_shadow_torus_px[horizon]", double(missed),
      "the same with horizon mapping (8 azimuths a texel, both lights): shadowed pixels it still lights");
  put("bump_self_shadow_torus_px[horizon_extra]", double(extra),
      "pixels horizon mapping darkens for a light that the trace finds unshadowed (and n' . L > 0)");
  put("bump_self_shadow_torus_px[horizon_wrong_azimuth]", double(wrongMissed),
      "shadowed pixels lit when the horizon is looked up a quarter turn from the light (a control)");
  put("bump_self_shadow_torus_px[horizon_smooth]", double(smoothMissed),
      "shadowed pixels lit by a horizon map of the smooth torus, the bumps left out (a control)");
  put("bump_torus_shadowed_px", double(shadowed),
      "torus pixels the trace shadows from either light (whichever way their bumped normal faces)");
  put("bump_torus_covered_px", double(covered), "pixels the torus covers, of " + std::to_string(n * n));
  ts::gl::CallList noneCalls, horizonCalls;
  ts::Image shadeNone, shadeHorizon;
  TorusPass shade;
  shade.maps = &maps;
  noneCalls = recorded(r, [&] { shadeNone = torusPass(r, shade); });
  shade.horizon = 1;
  horizonCalls = recorded(r, [&] { shadeHorizon = torusPass(r, shade); });
  ts::Image shadePtm;
  shade.horizon = 2, shade.ptm = &ptm;
  const ts::gl::CallList ptmCalls = recorded(r, [&] { shadePtm = torusPass(r, shade); });
  // Each picture against the traced one, over the torus's pixels.
  auto rms = [&](const ts::Image& img) {
    double se = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        if (pic.st[size_t(y) * n + size_t(x)].x >= 0) {
          const double d = double(img.at(x, y).r) - double(refPic.at(x, y).r);
          se += d * d;
        }
    return std::sqrt(se / double(std::max(covered, 1L)));
  };
  put("bump_shadow_torus_rms_levels[none]", rms(shadeNone),
      "RMS (8-bit levels) of plain bump mapping's picture against the traced shadows' over the torus's pixels");
  put("bump_shadow_torus_rms_levels[horizon]", rms(shadeHorizon), "the same for horizon mapping");
  put("bump_shadow_torus_rms_levels[ptm]", rms(shadePtm),
      "the same for the polynomial texture map (6 coefficients a texel, fitted to the horizon-shadowed shading)");
  put("bump_ptm_fit_rms_levels", 255 * ptm.fitRms,
      "RMS (8-bit levels) of the PTM's biquadratic against the self-shadowed diffuse term it was fitted to, over "
      "every texel's light directions");
  put("bump_ptm_fit_rms_levels[unshadowed]", 255 * fitPtm(field, angles, false).fitRms,
      "the same for a PTM fitted to the diffuse term without its shadows: the biquadratic's own error");
  pic.shown = {glPicture(shadeNone, "plain bump mapping on the torus", noneCalls),
               glPicture(shadeHorizon, "horizon mapping on the torus", horizonCalls),
               shownPicture(refPic, "the displaced torus's traced shadows"),
               shownPicture(diff, "horizon mapping against the traced shadows"),
               glPicture(shadePtm, "a polynomial texture map on the torus", ptmCalls)};
}

// ---- view methods --------------------------------------------------------------------------------------------------
inline const char* const kMethodKeys[] = {"blinn", "normalmap", "offset"};
inline void measureMethods(ts::Renderer& r, double thetaDeg, ts::Measurements& ms, Pictures& pic) {
  auto put = [&](const std::string& n, double v, const std::string& m) { ms.push_back({n, v, m}); };
  Inputs in;
  double floorDeg = 0;
  for (int y = 0; y < kMethodPixels; ++y)
    for (int x = 0; x < kMethodPixels; ++x) {
      const glm::dvec2 q = texelPoint(x, y, kMethodPixels, kMethodZoom);
      const glm::dvec3 n = exactNormal(q.x, q.y);
      const ts::Rgba c{u8(0.5 + 0.5 * n.x), u8(0.5 + 0.5 * n.y), u8(0.5 + 0.5 * n.z), 255};
      floorDeg += angleDeg(decodeNormal(c), n);
    }
  floorDeg /= double(kMethodPixels) * kMethodPixels;
  put("bump_normal_error_deg[readback]", floorDeg,
      "mean angle (degrees) of the exact normals written as 8-bit colours: the floor of any method's read-back error");
  for (int m = 0; m < 3; ++m) {
    Pass p;
    p.method = Method(m), p.output = Output::kNormal, p.size = kMethodPixels, p.zoom = kMethodZoom;
    const ts::Image normals = shaderPass(r, in, p);
    double sum = 0;
    for (int y = 0; y < kMethodPixels; ++y)
      for (int x = 0; x < kMethodPixels; ++x) {
        const glm::dvec2 q = texelPoint(x, y, kMethodPixels, kMethodZoom);
        sum += angleDeg(decodeNormal(normals.at(x, y)), exactNormal(q.x, q.y));
      }
    put(std::string("bump_normal_error_deg[") + kMethodKeys[m] + "]", sum / (double(kMethodPixels) * kMethodPixels),
        std::string("mean angle (degrees) between the ") + kMethodKeys[m] +
            " method's normal (GL, read back) and the displaced surface's exact normal");
    p.output = Output::kShade, p.azDeg = 30, p.elevDeg = 45;
    ts::Image shaded;
    const ts::gl::CallList calls = recorded(r, [&] { shaded = shaderPass(r, in, p); });
    pic.shown.push_back(glPicture(shaded, std::string("shaded, ") + kMethodKeys[m], calls));
  }
  ts::measureProgress(0.4);
  // The sheared parameterisation: the orthogonal-axes method's error against theta, and Blinn's.
  char key[64];
  for (double th : kThetas) {
    std::snprintf(key, sizeof key, "bump_shear_error_deg[%.0f]", th);
    put(key, shearError(th, shearedOrthogonalNormal),
        "mean angle (degrees) between the normal of a method that assumes dp/ds and dp/dt orthogonal and the true "
        "normal, the two at this angle");
  }
  put("bump_shear_error_deg[shown]", shearError(thetaDeg, shearedOrthogonalNormal),
      "the same at --shear, the angle the keys set");
  put("bump_shear_error_deg[blinn_shown]", shearError(thetaDeg, shearedBlinnNormal),
      "Blinn's n' = N + z_s (N x Pt)/|N| + z_t (Ps x N)/|N| at --shear (it carries the shear)");
  // Not square: dp/dt twice dp/ds's length, at right angles.
  put("bump_stretch_error_deg[orthogonal]", shearError(90, shearedOrthogonalNormal, kStretch),
      "mean angle (degrees) between the orthogonal-unit-axes method's normal and the true one, dp/dt twice as "
      "long as dp/ds (at right angles)");
  put("bump_stretch_error_deg[blinn]", shearError(90, shearedBlinnNormal, kStretch), "the same for Blinn's formula");
  put("bump_stretch_aspect", kStretch, "|dp/dt| / |dp/ds| of the stretched parameterisation");
  ts::measureProgress(0.7);
  // Baking: the shading for the light at azimuth 30, elevation 45, one pixel a texel, read back as the texture.
  Pass bake;
  bake.size = kTexels, bake.zoom = 1, bake.azDeg = 30, bake.elevDeg = 45;
  ts::Image baked = shaderPass(r, in, bake);
  baked.flipVertical();  // read back row 0 at the top; a texture's row 0 is t = 0
  const ts::Image shownBaked = bakedPass(r, baked, kTexels, 1);
  Pass moved = bake;
  moved.azDeg += kBakeMoveDeg;
  const ts::Image live = shaderPass(r, in, bake), liveMoved = shaderPass(r, in, moved);
  put("bump_baked_error_levels[same_light]", maxDiffGrey(shownBaked, live),
      "largest difference (8-bit levels) between the baked texture drawn without shaders and per-pixel shading, "
      "the light it was baked for");
  put("bump_baked_rms_levels[moved]", rmsGrey(shownBaked, liveMoved),
      "RMS (8-bit levels) between the baked shading and per-pixel shading once the light moved in azimuth");
  put("bump_baked_light_moved_deg", kBakeMoveDeg, "degrees of azimuth the light moved after baking");
  ts::Image bakedBig, liveBig;
  const ts::gl::CallList bc = recorded(r, [&] { bakedBig = bakedPass(r, baked, kMethodPixels, kMethodZoom); });
  Pass movedBig = moved;
  movedBig.size = kMethodPixels, movedBig.zoom = kMethodZoom;
  const ts::gl::CallList lc = recorded(r, [&] { liveBig = shaderPass(r, in, movedBig); });
  pic.shown.push_back(glPicture(bakedBig, "baked shading", bc));
  pic.shown.push_back(glPicture(liveBig, "per-pixel shading, the light moved", lc));
}

// ---- view distance -------------------------------------------------------------------------------------------------
// The plane at distance d: kDistancePixels pixels showing d/2 texels a pixel (1x: 2 pixels a texel).
inline double zoomAt(int d) { return 2.0 / d; }
inline void measureDistance(ts::Renderer& r, int shownDistance, ts::Measurements& ms, Pictures& pic) {
  auto put = [&](const std::string& n, double v, const std::string& m) { ms.push_back({n, v, m}); };
  Inputs in;
  char key[96];
  int done = 0;
  for (int d : kDistances) {
    Pass p;
    p.size = kDistancePixels, p.zoom = zoomAt(d), p.azDeg = 30, p.elevDeg = 45;
    auto render = [&](int super, bool mip, Output out) {
      Pass q = p;
      q.size = p.size * super, q.zoom = p.zoom * super, q.mipmapped = mip, q.output = out;
      // Mipmapped heights are differenced a pixel's footprint apart (at least a texel): the level GL reads.
      if (mip) q.step = std::max(1.0, 1.0 / q.zoom);
      return shaderPass(r, in, q);
    };
    const ts::Image refFine = render(kReferenceSuper, false, Output::kShade);
    const ts::Image ref = boxDown(refFine, kReferenceSuper);
    const ts::Image plain = render(1, false, Output::kShade), mip = render(1, true, Output::kShade);
    const ts::Image super = boxDown(render(kSuper, false, Output::kShade), kSuper);
    const double refTilt = meanTiltDeg(render(kReferenceSuper, false, Output::kNormal));
    const double mipTilt = meanTiltDeg(render(1, true, Output::kNormal));
    const double superTilt = meanTiltDeg(render(kSuper, false, Output::kNormal));
    auto name = [&](const char* what) {
      std::snprintf(key, sizeof key, "%s[%dx]", what, d);
      return std::string(key);
    };
    put(name("bump_distance_rms_levels[unfiltered]"), rmsGrey(plain, ref),
        "RMS (8-bit levels) of the bumped plane shaded once a pixel against the 8 x 8 supersampled reference");
    put(name("bump_distance_rms_levels[mipmapped]"), rmsGrey(mip, ref),
        "the same with the heights mipmapped (trilinear) and differenced a pixel's footprint apart");
    put(name("bump_distance_rms_levels[super4x4]"), rmsGrey(super, ref),
        "the same rendered at 4 x 4 the resolution and box-filtered down (Blinn's answer)");
    put(name("bump_tilt_lost_deg[mipmapped]"), refTilt - mipTilt,
        "the reference's mean normal tilt (degrees from the plane's normal, over its 8 x 8 samples) minus the "
        "mipmapped heights' mean tilt (below 0 where the pixel centres fall on texel centres, where central "
        "differences of bilinear heights are steepest)");
    put(name("bump_tilt_lost_deg[super4x4]"), refTilt - superTilt, "the same for the 4 x 4 samples of Blinn's answer");
    put(name("bump_tilt_deg[reference]"), refTilt, "the reference's mean normal tilt, degrees");
    if (d == shownDistance) {
      auto show = [&](const char* what, int super, bool mip) {
        ts::Image img;
        const ts::gl::CallList c = recorded(r, [&] {
          img = render(super, mip, Output::kShade);
          if (super > 1) img = boxDown(img, super);
        });
        pic.shown.push_back(glPicture(img, what, c));
      };
      show("unfiltered", 1, false);
      show("mipmapped heights", 1, true);
      show("4 x 4 supersampled, box filter", kSuper, false);
      pic.shown.push_back(shownPicture(ref, "the 8 x 8 supersampled reference"));
    }
    ts::measureProgress(double(++done) / 4.0);
  }
}

// ---- the shear plot --------------------------------------------------------------------------------------------
// The measured mean normal error against the angle between dp/ds and dp/dt: the orthogonal-axes method at the
// table's angles, Blinn's formula at the keys' angle, and a marker there.
inline double valueOf(const ts::Measurements& m, const std::string& name) {
  for (const ts::Measurement& x : m)
    if (x.name == name) return x.value;
  return 0;
}
inline ts::plot::Spec shearPlot(const ts::Measurements& m, int shownDeg) {
  namespace P = ts::plot;
  P::Spec s;
  s.id = "shear_plot";
  s.title = "normal error, sheared";
  s.xLabel = "dp/ds to dp/dt, deg";
  s.yLabel = "mean error, deg";
  double ymax = 1;
  P::Series ortho("orthogonal_axes", kMissed, P::Mark::Squares), line("orthogonal_axes_line", kMissed);
  char key[64];
  for (double th : kThetas) {
    std::snprintf(key, sizeof key, "bump_shear_error_deg[%.0f]", th);
    const double v = valueOf(m, key);
    ortho.points.push_back({th, v}), line.points.push_back({th, v});
    ymax = std::max(ymax, v);
  }
  P::Series blinn("blinn", kExtra, P::Mark::Rings);
  blinn.points.push_back({double(shownDeg), valueOf(m, "bump_shear_error_deg[blinn_shown]")});
  s.x0 = std::min(40.0, shownDeg - 5.0), s.x1 = 95, s.y0 = 0, s.y1 = std::ceil(ymax / 5 + 0.2) * 5;
  s.xTicks = P::ticks(45, 90, 15, "%g");
  s.yTicks = P::ticks(0, s.y1, P::niceStep(s.y1));
  s.series = {line, ortho, blinn};
  P::Marker mk;
  mk.x = shownDeg;
  s.markers = {mk};
  s.legend = {{"orthogonal axes", kMissed}, {"Blinn's formula", kExtra}};
  return s;
}

// ---- the figures' row of pictures ----------------------------------------------------------------------------------
namespace L = ts::layout;
struct Picture {
  const ts::TextureDesc* texture;
  L::Text title, note;
};
// The pictures side by side above a legend and the notes (layout::pictureFigure).  `plot`, when given, takes one
// more cell after the pictures (its title band, picture and note band together), drawn when that cell is at least
// 200 x 200 pixels.
inline void pictureRow(ts::Frame& f, const std::vector<Picture>& ps, const std::vector<ts::LegendEntry>& legend,
                       const std::vector<L::Text>& notes, const ts::plot::Spec* plot = nullptr) {
  std::vector<L::Captioned> captions;
  for (const Picture& p : ps) captions.push_back({p.title, p.note});
  const std::vector<L::Cell> cells = L::pictureFigure(
      f, captions,
      [&](size_t k, const ts::Rect& r) {
        f.panels.push_back(L::picturePanel(f, "picture_" + std::to_string(k), r, *ps[k].texture));
      },
      legend, notes, {0, 1.0f, 1, 1, 10, 2, 120}, 1, ts::Align::Center, plot ? 1 : 0);
  // A plot needs room for its legend, axes and ticks; in a small window its numbers stay in the notes alone.
  if (plot && cells.size() > ps.size() && cells[ps.size()].above.w() >= 200 &&
      cells[ps.size()].below.y1 - cells[ps.size()].above.y0 >= 200) {
    const L::Cell& c = cells[ps.size()];
    ts::plot::draw(f, *plot, {int(c.above.x0), int(c.above.y0), int(c.above.w()), int(c.below.y1 - c.above.y0)});
  }
}
}  // namespace bumplim
