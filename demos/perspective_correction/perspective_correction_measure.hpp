// demos/perspective_correction/perspective_correction_measure.hpp — the measurement of
// demos/perspective_correction and its plot: what a texel-index render of
// the square says about each pixel's (s, t) against the perspective-correct
// value (perspective_correction_math.hpp), the results measure() keeps, and the plot of
// the screen-linear error against the book's (d2 - d1)/d1.  Kept out of
// perspective_correction.cpp so that file shows the figure first.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/core/image.hpp"
#include "common/core/layout.hpp"
#include "common/core/plot.hpp"
#include "common/core/textures.hpp"
#include "perspective_correction_math.hpp"

namespace persp {
// Measurement passes: a square N x N render (aspect 1, so the sweep's numbers
// do not depend on the window) of a 2048-texel index texture: one texel of it
// is 1/8 texel of the 256-texel checkerboard, so each pixel's (s, t) is known
// to well under the errors measured.
constexpr int kMeasureSize = 256, kIndexTexels = 2048;
// The sweep: tilts 0, 10, ... 80 degrees at the current distance (85 would
// be nearly edge-on and the square a sliver a few pixels high).
constexpr int kSweepStepDeg = 10, kSweepMaxDeg = 80;

// One variant's texel-index render, against the perspective-correct (s, t).
struct Pass {
  double maxErrorTexels = 0;   // |(s,t) taken - correct|, texels of 256
  double predictedTexels = 0;  // the analytic error at the same pixels
  int maxIndexError = 0;       // largest index difference, texels of 2048
};

// What measure() found, for the labels and the plot (measure()'s detail;
// the labels use it when its setup is the current one).
struct Result {
  persp::Setup setup;
  Pass affine, perspective;
  long hintDiffering = 0;
  double hintFastestError = 0;
  std::string driver;
  std::vector<glm::dvec3> sweep;  // ((d2 - d1)/d1, error in texels, tilt) per tilt
  std::vector<glm::dvec3> curve;  // the analytic error, every 2.5 degrees of tilt at this distance
};

// Every pixel `img` covers (alpha > 0; a kMeasureSize render of setup `s`)
// against the perspective-correct (s, t) of the ray through it; `affine`:
// also the analytic error of the screen-linear image at the same pixels.
inline Pass compare(const ts::Image& img, const persp::Setup& s, bool affine) {
  const int N = kMeasureSize;
  const double T = kIndexTexels;
  persp::View view = persp::makeView(s, 1.0);
  Pass pass;
  for (int y = 0; y < N; ++y)
    for (int x = 0; x < N; ++x) {
      ts::Rgba c = img.at(x, y);
      if (c.a == 0) continue;
      glm::dvec2 xy(2 * (x + 0.5) / N - 1, 1 - 2 * (y + 0.5) / N);
      glm::dvec2 want = glm::clamp(persp::perspectiveST(view, xy), 0.0, 1.0);
      int i = 0, j = 0;
      ts::decodeTexelIndex(c, &i, &j);
      glm::dvec2 took((i + 0.5) / T, (j + 0.5) / T);
      pass.maxErrorTexels = std::max(pass.maxErrorTexels, glm::length(took - want) * persp::kTexels);
      int wi = std::min(int(T) - 1, int(want.x * T)), wj = std::min(int(T) - 1, int(want.y * T));
      pass.maxIndexError = std::max({pass.maxIndexError, std::abs(i - wi), std::abs(j - wj)});
      if (affine) pass.predictedTexels = std::max(pass.predictedTexels, persp::affineErrorTexels(view, xy));
    }
  return pass;
}

// The notes under the pictures: the hint test and the measured error (with
// `last`, measure()'s result for setup `s`, else null), and the book's rule
// of thumb for `s`.
inline const glm::vec4 kGrey{0.75f, 0.75f, 0.78f, 1.0f};
// Every number in them is a measurement of `m` (measure()'s, for this
// setup) or a parameter of the state, named as such.
inline std::vector<std::pair<ts::layout::Text, glm::vec4>> notes(const persp::Setup& s, const Result* last,
                                                                 const ts::Measurements& m) {
  namespace L = ts::layout;
  const glm::vec4 &white = L::kWhite, &amber = L::kAmber;
  const persp::Distances d = persp::distances(s);
  std::vector<std::pair<L::Text, glm::vec4>> notes;
  if (last) {
    notes.push_back(
        {last->hintDiffering == 0
             ? L::Text(last->driver +
                       " ignores GL_PERSPECTIVE_CORRECTION_HINT: its GL_FASTEST and GL_NICEST renders are identical")
             : last->driver + L::measuredText(m, " honours GL_PERSPECTIVE_CORRECTION_HINT: GL_FASTEST changes "
                                                 "{hint_pixels_differing|%.0f} px (error up to "
                                                 "{hint_fastest_error_texels|%.1f} texels)"),
         amber});
    notes.push_back(
        {L::measuredText(m, "screen-linear image: largest (s,t) error {affine_error_texels|%.1f} texels of ") +
             L::given("texels across the checkerboard", persp::kTexels, "%g") +
             L::measuredText(m, " ({affine_error_checks|%.2f} checks), measured from a texel-index render"),
         white});
  }
  notes.push_back({"tilt " + L::given("tilt, deg", s.tiltDeg, "%g") + " deg, distance " +
                       L::given("distance from the eye", s.distance, "%g") +
                       ": d1 = " + (last ? L::measured(m, "d1", "%.2f") : L::Text(L::fmt("%.2f", d.d1))) + ", d2 = " +
                       (last ? L::measured(m, "d2", "%.2f") : L::Text(L::fmt("%.2f", d.d2))) + ", (d2 - d1)/d1 = " +
                       (last ? L::measured(m, "d_ratio", "%.2f") : L::Text(L::fmt("%.2f", d.ratio()))) +
                       " (book: it matters from about " + L::given("the book's rule of thumb", 1, "%g") + ")",
                   kGrey});
  return notes;
}

// The plot view: the screen-linear image's largest error against (d2 -
// d1)/d1 over the sweep's tilts (measured crosses, the analytic line) and
// the current state (a ring), for setup `s` and what measure() found.
inline ts::plot::Spec plotSpec(const persp::Setup& s, const Result* last) {
  namespace plot = ts::plot;
  namespace L = ts::layout;
  using ts::layout::fmt;
  const glm::vec4 curveC{0.35f, 0.7f, 1.0f, 1.0f}, measuredC = ts::layout::kAmber, currentC{1.0f, 0.3f, 0.3f, 1.0f};
  plot::Spec p;
  p.title = "largest (s,t) error of the screen-linear image vs (d2 - d1)/d1: tilts 0.." + std::to_string(kSweepMaxDeg) +
            " deg at distance " + fmt("%g", s.distance);
  p.xLabel = "(d2 - d1)/d1   (d1, d2: nearest and farthest distance from the eye to the square)";
  p.yLabel = "error, texels of " + L::given("texels across the checkerboard", persp::kTexels, "%g") +
             " (one check = " + L::given("texels a check", persp::kTexels / persp::kChecks, "%g") + ")";
  glm::dvec3 now{persp::distances(s).ratio(), persp::maxAffineErrorTexels(s, kMeasureSize), s.tiltDeg};
  plot::Series curve{"analytic", curveC}, sweep{"measured", measuredC, plot::Mark::Crosses};
  if (last && last->setup.distance == s.distance) {  // the curve and sweep come with a measurement
    for (const glm::dvec3& q : last->curve) curve.points.push_back(glm::dvec2(q));
    for (const glm::dvec3& q : last->sweep)
      sweep.points.push_back(glm::dvec2(q)), sweep.tags.push_back("t=" + L::given("tilt, deg", q.z, "%g"));
    if (!last->curve.empty() && last->curve.front().x >= 0.05)  // the rule of thumb's blind spot, when it shows
      p.notes.push_back({glm::dvec2(last->curve.front()),
                         "<- tilt 0: facing the eye, all depths equal, no error although (d2 - d1)/d1 = " +
                             fmt("%.2f", last->curve.front().x)});
    if (last->setup.tiltDeg == s.tiltDeg) now.y = last->affine.maxErrorTexels;
  }
  p.series = {curve, sweep, {"current", currentC, plot::Mark::Rings, {glm::dvec2(now)}, 2.0f, 8.0f}};
  p.markers = {{1.0, p.textColor, "rule_of_thumb", "d2 - d1 = d1"}};
  p.legend = {{"x  measured (texel-index render), tagged by tilt", measuredC},
              {"-  analytic (ray-plane vs screen barycentrics)", curveC},
              {"o  current state (t=" + L::given("tilt, deg", now.z, "%g") + ")", currentC}};
  p.legendInside = true;
  // Ranges: from 0 to a round number past the largest value.
  double xmax = std::max(1.2, now.x), ymax = std::max(1.0, now.y);
  for (const auto* se : {&curve.points, &sweep.points})
    for (const glm::dvec2& q : *se) xmax = std::max(xmax, q.x), ymax = std::max(ymax, q.y);
  const double xs = plot::niceStep(xmax * 1.05), ys = plot::niceStep(ymax * 1.1);
  p.x1 = xs * std::ceil(xmax * 1.05 / xs), p.y1 = ys * std::ceil(ymax * 1.1 / ys);
  p.xTicks = plot::ticks(0, p.x1, xs), p.yTicks = plot::ticks(0, p.y1, ys);
  return p;
}
}  // namespace persp
