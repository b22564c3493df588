// demos/torus/torus_views.hpp — the torus demo's marks: the texture's centre
// (1/2, 1/2) in texture space, and the same point on the torus as a cross in
// its tangent plane with a label.
#pragma once
#include "common/core/frame.hpp"
#include "common/core/layout.hpp"
#include "common/core/torus.hpp"
#include "torus_math.hpp"

namespace torus::views {
inline const glm::vec4 kMarker{0.95f, 0.1f, 0.2f, 1.0f}, kMarkerBox{0.55f, 0.0f, 0.1f, 0.85f};

// The label at the largest scale that fits inside `vp` (left out if none does).
inline void label(ts::Frame& f, const ts::Rect& vp, glm::vec2 at, const char* text, int scale, glm::vec2 offset) {
  for (int sc = scale; sc >= 1; --sc)
    if (ts::layout::placeFree(f,
                              {at.x + offset.x * float(sc), at.y + offset.y * float(sc), text, ts::layout::kWhite, sc,
                               ts::Align::Left, kMarkerBox},
                              ts::layout::box(vp)))
      break;
}

// A cross at (1/2, 1/2) of the texture panel `p` (unit square), labelled.
inline void markTextureCentre(ts::Frame& f, ts::Panel& p, int scale) {
  const float a = 0.06f;
  p.batches.push_back(ts::lineSegments({{0.5f - a, 0.5f}, {0.5f + a, 0.5f}, {0.5f, 0.5f - a}, {0.5f, 0.5f + a}},
                                       kMarker, 3.0f, "centre_marker"));
  const ts::Rect& vp = p.viewport;
  label(f, vp, {float(vp.x + vp.w / 2), float(vp.y + vp.h / 2)}, "(1/2, 1/2)", scale, {8.0f, 4.0f});
}

// A cross in the tangent plane at the answer, its arms along the unit
// tangents T (along θ) and B (along φ), lifted 2% of r along the normal so
// the depth test keeps it above its own surface and hides it behind the
// rest of the ring; labelled, "hidden" when the render did not show it.
inline void markTorusCentre(ts::Frame& f, ts::Panel& p, const Params& tp, int scale, bool hidden) {
  const ts::TorusFrame fr = centreFrame(tp);
  const glm::dvec3 n = fr.N, c = fr.Q + 0.02 * tp.r * n, dTheta = fr.T, dPhi = fr.B;
  const double arm = 0.35 * tp.r;
  ts::Batch cross = ts::lineSegments({}, kMarker, 3.0f, "centre_marker");
  for (glm::dvec3 q : {c - arm * dTheta, c + arm * dTheta, c - arm * dPhi, c + arm * dPhi})
    cross.vertices.push_back({glm::vec3(q), {0, 0, 0, 1}, kMarker});
  p.batches.push_back(cross);
  const glm::vec2 q = ts::panelToPixels(p, p.projection * p.modelview * glm::vec4(glm::vec3(c), 1.0f));
  label(f, p.viewport, q, hidden ? "(1/2,1/2): hidden" : "(1/2,1/2)", scale, {10.0f, 6.0f});
}
}  // namespace torus::views
