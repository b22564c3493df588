// demos/bump_mapping/bump_mapping_measure.hpp — what the bump-mapping demo measures,
// from renders the scene makes on request (RenderSpec): every method
// against R, the tilt each gives and how it answers the height and the
// object's size, emboss's contrast against the light's angle to the
// normal, and DOT3 against the shader doing the same diffuse sum.
#pragma once
#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "bump_mapping_math.hpp"
#include "bump_mapping_methods.hpp"
#include "common/core/gl_call.hpp"
#include "common/core/scene.hpp"

namespace bump {
struct RenderSpec {
  int method = kFlat;           // a row of kMethods
  bool normals = false;         // the normal as colour (GLSL methods)
  bool smoothGeometry = false;  // R's normal on the smooth torus (kReference)
  bool embossTermOnly = false;  // B4's 0.5 + 0.5 (H - H') alone
  bool noSpecular = false;      // the shader's diffuse sum only (to compare with DOT3)
  float heightFactor = 1.0f, objectFactor = 1.0f;
  float distanceFactor = 1.0f;           // the eye this many times as far
  bool mipmaps = false;                  // mipmapped heights (B1) or normal map (B3), trilinear
  bool dxt1 = false;                     // B3's normal map compressed to DXT1 (seed 001: "bad for normal maps")
  ts::gl::CallList* recordTo = nullptr;  // a picture shown: its GL calls recorded here (ts::recordRender)
  // Normals shown in a figure: drawn on the figure's background.  The
  // measurements' normal renders stay on black, which is how covered() tells
  // the surface from the rest.
  bool onBackdrop = false;
  bool coarseGrid = false;     // R from CoarseReferencePass (a window's first stage)
  bool coverageAlpha = false;  // R's grid: alpha 255 where it covers the pixel, else 0 (renderReference)
};
using RenderFn = std::function<ts::Image(const RenderSpec&)>;
// Which fixed-function pictures the view shows (a method of kMethods, or
// kEmbossTermPicture): only theirs have their GL calls recorded for the
// listing (a quarter of a million immediate-mode calls each); the others are
// rendered for the numbers only.  R's two pictures are always recorded.
constexpr int kEmbossTermPicture = -1;
using ShownFn = std::function<bool(int picture)>;

// Emboss's contrast per band of the angle between the smooth normal and light 1.
inline const double kEmbossBands[] = {0, 10, 30, 60, 90};

// Seed 002's x tilt as a picture (agreementPicture): the pixels counted
// with the displaced surface, against it, and the rest of the surface.
inline const ts::Rgba kTiltWith{80, 200, 110, 255}, kTiltAgainst{225, 70, 200, 255}, kTiltUncounted{95, 95, 100, 255};
// Emboss's term shown magnified about 1/2 (0.5 + kEmbossGain (E - 0.5)),
// the edge of the region where light 1 is within kEmbossBands[1] degrees of
// the normal drawn in kEmbossEdge.
constexpr double kEmbossGain = 4.0;
inline const ts::Rgba kEmbossEdge{60, 210, 255, 255};

// A normal render (colour 0.5 + 0.5 n) drawn on `background`, as drawn on
// black: only the clear colour differs, so the pixels of that colour become
// black.  No unit normal has the background's colour (a grey near 0.12 is n
// near -0.76 in every component, |n| = 1.3), so no surface pixel is taken.
inline ts::Image onBlack(const ts::Image& normals, ts::Rgba background) {
  ts::Image out = normals;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const ts::Rgba c = out.at(x, y);
      if (c.r == background.r && c.g == background.g && c.b == background.b) out.set(x, y, {0, 0, 0, 255});
    }
  return out;
}

// What measure() found, for the pictures.
struct Found {
  bool coarseReference = false;  // R drawn from the coarse grid (a window's first stage): tagged refining
  std::map<int, Compare> cmp;    // method -> against R (normalDeg: at the same (s,t); screenNormalDeg: same pixel)
  std::map<int, std::shared_ptr<const ts::Image>> pictures;  // R and the fixed-function methods, shaded
  std::shared_ptr<const ts::Image> refNormals;               // R's normals as shown (on the figure's background)
  std::map<int, ts::gl::CallList> picturesGL;                // the calls that rendered each picture (the GL listing)
  ts::gl::CallList refNormalsGL;
  double embossContrast[4] = {-1, -1, -1, -1};  // per band of kEmbossBands
  // Seed 002's x tilt against R's per pixel (agreementPicture) and the rows of
  // its near and far side, as tilt_agreement_x_near/far[seed002] count them.
  std::shared_ptr<const ts::Image> seedTiltX;
  glm::ivec2 nearRows{0}, farRows{0};
  // Emboss's term 0.5 + 0.5 (H - H') alone, magnified by kEmbossGain, the
  // overhead band's edge drawn on it; each pixel's band of the light's
  // angle to the normal (-1: not on the torus), and the GL that drew it.
  std::shared_ptr<const ts::Image> embossTerm;
  std::vector<signed char> embossBand;
  ts::gl::CallList embossTermGL;
};

// The pictures measureAll shows and records: R shaded, with its coverage
// in alpha (partCoverage parts them); R's normals on the figure's
// background; and emboss's term alone.
inline RenderSpec referenceSpec() {
  RenderSpec s{kReference};
  s.coverageAlpha = true;
  return s;
}
// R's picture as shown (opaque: its clear colour's alpha and its
// fragments' are 1), and the pixels it covers as covered() reads a normal
// render: white where covered, black elsewhere.
inline std::pair<ts::Image, ts::Image> partCoverage(const ts::Image& withCoverage) {
  ts::Image shaded = withCoverage, coverage(withCoverage.width, withCoverage.height, ts::Rgba{0, 0, 0, 255});
  for (int y = 0; y < shaded.height; ++y)
    for (int x = 0; x < shaded.width; ++x) {
      ts::Rgba c = shaded.at(x, y);
      if (c.a == 255) coverage.set(x, y, {255, 255, 255, 255});
      c.a = 255;
      shaded.set(x, y, c);
    }
  return {std::move(shaded), std::move(coverage)};
}
inline RenderSpec shownNormalsSpec() {
  RenderSpec s{kReference, true};
  s.onBackdrop = true;
  return s;
}
inline RenderSpec embossTermSpec() {
  RenderSpec s{kEmboss};
  s.embossTermOnly = true;
  return s;
}

// The GL calls of the pictures measureAll records, recorded again (the
// pictures themselves are the same): a measurement reused for another figure
// of the same state takes them anew, since a recording holds the viewport it
// found (that figure's size).  `reference`: R's two pictures too, else only
// the fixed-function ones the view shows (R's fitted by retargetViewports).
inline void recordPicturesAgain(const RenderFn& render, Found& found, bool reference, const ShownFn& shown) {
  auto recorded = [&](RenderSpec s, ts::gl::CallList* calls) {
    s.recordTo = calls;
    render(s);
  };
  if (reference) {
    recorded({kReference}, &found.picturesGL[kReference]);
    recorded(shownNormalsSpec(), &found.refNormalsGL);
  }
  for (int m = 0; m < kMethodCount; ++m)
    if (kMethods[m].fixedFunction && shown(m)) recorded({m}, &found.picturesGL[m]);
  if (shown(kEmbossTermPicture)) recorded(embossTermSpec(), &found.embossTermGL);
}

// R's GL calls (its shaded picture and its normals) as they would be
// recorded with the viewport `now` current instead of `was`: a pass
// (RenderTarget::Bind) ends by restoring the viewport it found, the one call
// of a recording that depends on it; every other viewport a pass sets is its
// own, `own`.  A restore equal to `own` is left out as a no-op, so a
// recording made or wanted there cannot be fitted: false, nothing changed.
inline bool retargetViewports(Found& found, glm::ivec4 was, glm::ivec4 now, glm::ivec4 own) {
  if (!found.picturesGL.count(kReference) || !found.refNormalsGL) return false;
  if (was == now) return true;
  if (was == own || now == own) return false;
  auto fit = [&](ts::gl::CallList& list) {
    auto calls = std::make_shared<std::vector<ts::gl::Call>>(*list);
    for (ts::gl::Call& c : *calls)
      if (std::string(c.name) == "glViewport" && c.args.size() == 4 && c.args[0].i == was.x && c.args[1].i == was.y &&
          c.args[2].i == was.z && c.args[3].i == was.w)
        c.args[0].i = now.x, c.args[1].i = now.y, c.args[2].i = now.z, c.args[3].i = now.w;
    list = std::move(calls);
  };
  fit(found.picturesGL[kReference]);
  fit(found.refNormalsGL);
  return true;
}

// `seam`: the normal map baked with and without wrapping differences.
// `only` (may be null): just R's pictures and the comparison of these
// methods with R (a window's view, shown first: the same numbers, the rest
// left out); without `refNormals`, not even R's normals (the view shows
// neither them nor a number of theirs): the comparisons take the pixels R
// covers from its shaded render instead, the same pixels (the same grid
// rasterized alike), and so the same numbers, one draw of the grid sooner.
inline ts::Measurements measureAll(const RenderFn& render, glm::dvec3 light1Eye, const ts::Image& wrapped,
                                   const ts::Image& unwrapped, const ShownFn& shown,
                                   const std::vector<int>* only = nullptr, bool refNormals = true) {
  ts::Measurements out;
  Found found;
  // The pictures shown (R, its normals, B4, B5) are rendered with their GL
  // calls recorded, for the listing.
  auto recorded = [&](RenderSpec s, ts::gl::CallList* calls) {
    s.recordTo = calls;
    return render(s);
  };
  auto [shadedR, coverageR] = partCoverage(recorded(referenceSpec(), &found.picturesGL[kReference]));
  auto refShaded = std::make_shared<const ts::Image>(std::move(shadedR));
  // R's normals are drawn once, on the figure's background (shown); the
  // measurements' copy on black is the same picture with that colour zeroed
  // (onBlack): the displaced grid is the costliest render here.  Left out,
  // the coverage stands in for them (covered() alone reads it).
  const bool withNormals = !only || refNormals;
  if (withNormals)
    found.refNormals = std::make_shared<const ts::Image>(recorded(shownNormalsSpec(), &found.refNormalsGL));
  const auto onBlackR = std::make_shared<const ts::Image>(
      withNormals ? onBlack(*found.refNormals, found.refNormals->at(0, 0)) : std::move(coverageR));
  const ts::Image exact = render({kReference, true, true}), smooth = render({kFlat, true});
  found.pictures[kReference] = refShaded;
  ts::measureProgress(0.15);
  std::map<int, ts::Image> normals;
  for (int m = 0; m < kMethodCount; ++m) {
    if (only && std::find(only->begin(), only->end(), m) == only->end()) continue;
    const bool ideal = m == kReference, fixed = kMethods[m].fixedFunction;
    ts::Image shaded = fixed && shown(m) ? recorded({m}, &found.picturesGL[m]) : render({m, false, ideal});
    normals[m] = m == kFlat ? smooth : ideal ? exact : fixed ? smooth : render({m, true});
    Compare c = compare(shaded, normals[m], *refShaded, *onBlackR);
    const std::string k = std::string("[") + (ideal ? "ideal" : kMethods[m].key) + "]";
    if (!fixed) {
      c.screenNormalDeg = withNormals ? c.normalDeg : NAN;  // (from the coverage: no normals)
      c.normalDeg = compare(shaded, normals[m], shaded, exact).normalDeg;
      if (!ideal)
        out.push_back(
            {"normal_err_deg" + k, c.normalDeg,
             "mean angle between the method's normal and the displaced surface's at the same (s,t), degrees"});
      if (withNormals)
        out.push_back({"screen_normal_err_deg" + k, c.screenNormalDeg,
                       "mean angle between the normal and R's in the same pixel, degrees"});
    } else {
      found.pictures[m] = std::make_shared<const ts::Image>(shaded);
    }
    out.push_back({"psnr_db" + k, c.psnr, "shading against R's picture over the pixels both cover, dB"});
    out.push_back({"mad" + k, c.mad, "mean absolute difference from R's picture, 8-bit units"});
    found.cmp[m] = c;
    ts::measureProgress(0.15 + 0.06 * m);
  }
  if (only) {
    out.detail = found;
    return out;
  }
  // Seed 001: DXT1 is "bad for normal maps".  B3 with its map compressed,
  // against the displaced surface at the same (s,t), as B3 itself above.
  {
    RenderSpec s{kNormalMap};
    s.dxt1 = true;
    const ts::Image shaded = render(s);
    s.normals = true;
    out.push_back({"normal_err_deg[normalmap_dxt1]", compare(shaded, render(s), shaded, exact).normalDeg,
                   "the same for B3 with its normal map compressed to DXT1 (4 bits a texel), degrees"});
  }
  // Seed 002 adds to the eye's x and y, not along the surface: on the near
  // side of the ring s runs along +x, on the far side along -x.
  const glm::ivec2 rows = coveredRows(smooth);
  const int third = (rows.y - rows.x) / 3;
  found.nearRows = {rows.y - third, rows.y}, found.farRows = {rows.x, rows.x + third};
  found.seedTiltX = std::make_shared<const ts::Image>(
      agreementPicture(normals[kSeed002], exact, smooth, {found.nearRows, found.farRows}, kTiltWith, kTiltAgainst,
                       kTiltUncounted,
                       found.refNormals->at(0, 0)));  // the figure's background, as R's normals are shown on it
  for (int m = kBlinn; m <= kNormalMap; ++m)
    for (int side = 0; side < 2; ++side) {
      glm::ivec2 band = side == 0 ? found.nearRows : found.farRows;
      glm::dvec2 a = perturbationAgreement(normals[m], exact, smooth, band);
      const std::string where = side == 0 ? "near" : "far";
      out.push_back(
          {"tilt_agreement_x_" + where + "[" + kMethods[m].key + "]", a.x,
           "+1: tilts the normal along eye x as the true surface does, -1: the opposite way (" + where + " side)"});
      out.push_back({"tilt_agreement_y_" + where + "[" + kMethods[m].key + "]", a.y,
                     "the same along eye y (" + where + " side)"});
    }
  out.push_back({"tilt_deg[reference]", meanTiltDeg(exact, smooth),
                 "mean angle of the displaced surface's normal from the smooth torus's"});
  for (int m = kBlinn; m <= kNormalMap; ++m)
    out.push_back({std::string("tilt_deg[") + kMethods[m].key + "]", meanTiltDeg(normals[m], smooth),
                   "mean angle from the smooth normal"});
  // Twice the height scale: B1 and R tilt about twice as far (small angles);
  // seed 002's formula has no scale in it.
  for (int m : {kBlinn, kSeed002, kReference}) {
    RenderSpec s{m, true, true};
    s.heightFactor = 2;
    double t1 = meanTiltDeg(normals[m], smooth), t2 = meanTiltDeg(render(s), smooth);
    out.push_back({std::string("tilt_ratio_height_x2[") + kMethods[m].key + "]", t1 > 0 ? t2 / t1 : 0,
                   "mean tilt with twice the height scale / with it"});
  }
  ts::measureProgress(0.65);
  // Seed 004's scale claim: the object twice as large (the eye twice as far,
  // so the picture is the same), the bumps as high as before.
  {
    RenderSpec s{kFlat, true};
    s.objectFactor = 2;
    const ts::Image bigSmooth = render(s);
    for (int m : {kBlinn, kNormalMap, kReference}) {
      s.method = m, s.smoothGeometry = true;
      double t1 = meanTiltDeg(normals[m], smooth), t2 = meanTiltDeg(render(s), bigSmooth);
      out.push_back({std::string("tilt_ratio_object_x2[") + kMethods[m].key + "]", t1 > 0 ? t2 / t1 : 0,
                     "mean tilt of the object twice as large / as it is (seed 004: 1/2 for Blinn's form)"});
    }
  }
  ts::measureProgress(0.8);
  // Emboss: its term 0.5 + 0.5 (H - H') alone; the contrast |E - 1/2| / (1/2)
  // per band of the angle between the smooth normal and light 1.  The shift
  // is the light's part along the surface: 0 with the light along the normal.
  {
    const ts::Image term = shown(kEmbossTermPicture) ? recorded(embossTermSpec(), &found.embossTermGL)
                                                     : render(embossTermSpec());
    double sum[4] = {0, 0, 0, 0}, cnt[4] = {0, 0, 0, 0};
    const glm::dvec3 L = glm::normalize(light1Eye);
    found.embossBand.assign(size_t(term.width) * size_t(term.height), -1);
    for (int y = 0; y < term.height; ++y)
      for (int x = 0; x < term.width; ++x) {
        if (!covered(smooth, x, y)) continue;
        double a = angleDeg(normalAt(smooth, x, y), L);
        for (int b = 0; b < 4; ++b)
          if (a >= kEmbossBands[b] && a < kEmbossBands[b + 1]) {
            sum[b] += std::fabs(term.at(x, y).r - 127.5) / 127.5, cnt[b] += 1;
            found.embossBand[size_t(y) * size_t(term.width) + size_t(x)] = static_cast<signed char>(b);
          }
      }
    for (int b = 0; b < 4; ++b) found.embossContrast[b] = cnt[b] ? sum[b] / cnt[b] : -1.0;
    // The term as the figure shows it: magnified about 1/2 (the contrasts are
    // a few hundredths), on the figure's background, the edge of band 0 (the
    // light within kEmbossBands[1] degrees of the normal) two pixels wide.
    ts::Image shown(term.width, term.height, found.refNormals->at(0, 0));
    auto band = [&](int x, int y) {
      return x < 0 || y < 0 || x >= term.width || y >= term.height
                 ? -1
                 : int(found.embossBand[size_t(y) * size_t(term.width) + size_t(x)]);
    };
    for (int y = 0; y < term.height; ++y)
      for (int x = 0; x < term.width; ++x) {
        if (band(x, y) < 0) continue;
        const ts::Rgba t = term.at(x, y);
        auto magnified = [](uint8_t v) {
          return uint8_t(std::lround(std::clamp(127.5 + kEmbossGain * (v - 127.5), 0.0, 255.0)));
        };
        shown.set(x, y, {magnified(t.r), magnified(t.g), magnified(t.b), 255});
        bool edge = false;
        for (int dy = -1; dy <= 1 && !edge; ++dy)
          for (int dx = -1; dx <= 1 && !edge; ++dx) edge = (band(x + dx, y + dy) == 0) != (band(x, y) == 0);
        if (edge) shown.set(x, y, kEmbossEdge);
      }
    found.embossTerm = std::make_shared<const ts::Image>(std::move(shown));
    for (int b = 0; b < 4; ++b)
      out.push_back({"emboss_contrast[" + std::to_string(int(kEmbossBands[b])) + "-" +
                         std::to_string(int(kEmbossBands[b + 1])) + "deg]",
                     found.embossContrast[b],
                     "mean |H - H'| where the light is this far from the normal (-1: no pixels)"});
  }
  // The outline: the bump methods keep the smooth torus's, R does not.
  out.push_back({"outline_deviation_px[blinn]", outlineDeviationPx(normals[kBlinn], smooth),
                 "mean distance of B1's outline from the smooth torus's, pixels"});
  out.push_back({"outline_deviation_px[reference]", outlineDeviationPx(*onBlackR, smooth),
                 "mean distance of R's outline from the smooth torus's, pixels"});
  // DOT3 against the shader's own diffuse sum with the same normal map.
  {
    RenderSpec s{kNormalMap};
    s.noSpecular = true;
    Compare c = compare(render(s), smooth, *found.pictures[kDot3], smooth);
    out.push_back({"dot3_vs_shader_mad", c.mad,
                   "GL_DOT3_RGB's picture against the GLSL diffuse sum of the same normal map, 8-bit units"});
  }
  // Minification: the torus further away, its texels smaller than pixels.
  // Mipmapped heights (B1: slopes from the averaged heights) and a
  // mipmapped normal map (B3: averaged normals) both flatten the bumps; the
  // mean tilt relative to the nearest view, per distance.
  std::map<int, double> nearTilt;  // the nearest view's tilt, the same for every distance: rendered once
  for (float dist : {2.0f, 4.0f, 8.0f}) {
    RenderSpec s{kFlat, true};
    s.distanceFactor = dist, s.mipmaps = true;
    const ts::Image far = render(s);
    for (int m : {kBlinn, kNormalMap}) {
      RenderSpec near = s;
      near.method = m, near.distanceFactor = 1.0f;
      s.method = m;
      if (!nearTilt.count(m)) nearTilt[m] = meanTiltDeg(render(near), smooth);
      double t1 = nearTilt[m], t2 = meanTiltDeg(render(s), far);
      out.push_back({std::string("mip_tilt_ratio[") + kMethods[m].key + "@" + std::to_string(int(dist)) + "x]",
                     t1 > 0 ? t2 / t1 : 0,
                     std::string("mean tilt at this distance / at the nearest, mipmapped ") +
                         (m == kBlinn ? "heights" : "normal map")});
      s.method = kFlat;
    }
    ts::measureProgress(0.85 + 0.03 * dist / 2);
  }
  // The seam of the normal map where the texture repeats (s wraps at the
  // front of the ring): one-sided differences at the edge make a crease.
  const glm::dvec2 seamBad = seamJumpDeg(unwrapped), seamFixed = seamJumpDeg(wrapped);
  out.push_back({"seam_jump_deg[unwrapped]", seamBad.x,
                 "mean normal-map angle across the texture's edge, slopes baked one-sided there, degrees"});
  out.push_back({"seam_jump_deg[wrapped]", seamFixed.x, "the same baked with differences that wrap (the fix)"});
  out.push_back({"neighbour_jump_deg", seamFixed.y, "mean angle between any other two neighbouring columns, degrees"});
  out.detail = found;
  return out;
}
}  // namespace bump
