// demos/cylinder_seam/cylinder_seam_views.hpp — the texture-space view of
// demos/cylinder_seam: where the seam patch's corners x, y, z, w fall in the
// label.  The green region is what the patch should show (s = 0.9 -> 1.1,
// drawn wrapping), the red hatched one what s reduced per vertex selects
// (0.1..0.9), and the orange arrow the way s runs from x to y on screen.
// Secondary to the demo's idea, so kept out of cylinder_seam.cpp.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/layout.hpp"
#include "common/core/text.hpp"
#include "cylinder_seam_math.hpp"

namespace cylinder::views {
// The figure's colours: the intended region, the region actually shown, the
// seam patch (its outline on the cylinder, the arrow, the vertex names).
inline const glm::vec4 kIntended{0.2f, 0.85f, 0.3f, 1.0f}, kActual{0.95f, 0.15f, 0.15f, 1.0f},
    kPatch{1.0f, 0.55f, 0.0f, 1.0f};

// Adds to `p` (a texturePanel of the label at p.viewport) the seam patch's
// regions: intended from the winding-tracked coordinates `right`, actual and
// the arrow from `shown`; the vertex names go into `f` at `scale`.
inline void markSeamPatch(ts::Frame& f, ts::Panel& p, const cylinder::Params& right, const cylinder::Params& shown,
                          int scale) {
  const ts::Rect& vp = p.viewport;
  const int k = cylinder::seamPatch(right);
  // Intended: [s_k, s_k+1] of the right coordinates, cut where it wraps.
  double a = cylinder::sOf(right, k), b = cylinder::sOf(right, k + 1);
  double fa = a - std::floor(a);
  std::vector<std::pair<double, double>> pieces;
  if (fa + (b - a) <= 1.0 + 1e-12) pieces = {{fa, fa + (b - a)}};
  else pieces = {{fa, 1.0}, {0.0, fa + (b - a) - 1.0}};
  for (auto [lo, hi] : pieces) {
    ts::Batch shade;
    shade.role = "intended_region";
    shade.blend = true;
    for (int i : {0, 1, 2, 0, 2, 3}) {
      glm::vec2 c(float(i == 1 || i == 2 ? hi : lo), float(i >= 2));
      shade.vertices.push_back({{c, 0}, {0, 0, 0, 1}, {kIntended.r, kIntended.g, kIntended.b, 0.45f}});
    }
    p.batches.push_back(shade);
    p.batches.push_back(
        ts::lineLoop({{float(lo), 0.003f}, {float(hi), 0.003f}, {float(hi), 0.997f}, {float(lo), 0.997f}}, kIntended,
                     3.0f, "intended_outline"));
  }
  // Actual: from column k's s to column k+1's s, walked left to right on
  // screen; an arrow at mid-height shows the way.
  double sa = cylinder::sOf(shown, k), sb = cylinder::sOf(shown, k + 1);
  if (shown.coords == cylinder::Coords::Wrong) {
    float lo = float(std::min(sa, sb)), hi = float(std::max(sa, sb));
    p.batches.push_back(
        ts::lineLoop({{lo, 0.01f}, {hi, 0.01f}, {hi, 0.99f}, {lo, 0.99f}}, kActual, 3.0f, "actual_region"));
    std::vector<glm::vec2> hatch;  // the book's cross-hatching
    for (float u = lo + 0.05f; u < hi; u += 0.1f)
      hatch.insert(hatch.end(), {{u, 0.01f}, {std::min(u + 0.05f, hi), 0.99f}});
    p.batches.push_back(ts::lineSegments(hatch, {kActual.r, kActual.g, kActual.b, 1.0f}, 1.0f, "actual_hatch"));
  }
  // The arrow: s from x (left edge) to y (right edge), as GL_REPEAT reads
  // it: right = from + 0.2, continued from the left edge if it passes 1.
  const float from = float(sa - std::floor(sa));
  const float to = shown.coords == cylinder::Coords::Right ? from + float(sb - sa) : float(sb);
  const float y0 = 0.5f, ah = 0.03f, dir = to > from ? 1.0f : -1.0f;
  const float tip = to > 1.0f ? to - 1.0f : to;
  std::vector<glm::vec2> arrow;
  if (to > 1.0f) arrow = {{from, y0}, {1.0f, y0}, {0.0f, y0}, {tip, y0}};
  else arrow = {{from, y0}, {to, y0}};
  arrow.insert(arrow.end(), {{tip, y0}, {tip - dir * ah, y0 + ah}, {tip, y0}, {tip - dir * ah, y0 - ah}});
  p.batches.push_back(ts::lineSegments(arrow, kPatch, 3.0f, "direction"));
  // Vertex names at the corners of the region actually shown.
  auto at = [&](double s, double t) {
    return glm::vec2(float(vp.x) + float(s) * float(vp.w), float(vp.y) + float(1.0 - t) * float(vp.h));
  };
  float line = ts::text::height(scale);
  struct {
    const char* n;
    double s, t;
  } names[] = {{"x", from, 0}, {"y", tip, 0}, {"z", tip, 1}, {"w", from, 1}};
  for (auto& v : names) {
    glm::vec2 q = at(v.s, v.t);
    ts::layout::placeFree(f,
                          {q.x, v.t > 0.5 ? q.y - line - 4.0f * float(scale) : q.y + 4.0f * float(scale), v.n, kPatch,
                           scale, ts::Align::Center},
                          {0, 0, float(f.width), float(f.height)});
  }
}
}  // namespace cylinder::views
