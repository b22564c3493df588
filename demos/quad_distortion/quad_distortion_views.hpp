// demos/quad_distortion/quad_distortion_views.hpp — the secondary parts of
// demos/quad_distortion's picture: the texture-space view (the whole
// checkerboard, the region the (s,t) corners select, the image of the screen
// diagonal) and the corner labels beside a square.  Kept out of
// quad_distortion.cpp so that file shows the square and its GL first.
#pragma once
#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/gl/render.hpp"
#include "common/core/text.hpp"
#include "quad_distortion_math.hpp"

namespace quad::views {
// The marks' colours: the region the corners select, the diagonal (and its image).
inline const glm::vec4 kRegion{0.9f, 0.1f, 0.1f, 1.0f}, kDiagonal{1.0f, 0.55f, 0.0f, 1.0f};

// Adds to `p` (a unit-square panel) the whole texture on the unit square (s,
// t = a, b), the region the corners `st` select (red) and the image under
// `map` ((a, b) -> (s, t)) of the screen diagonal `d` (orange).
template <typename Map>
void addTextureView(ts::Panel& p, const quad::Corners& st, quad::Diagonal d, int texture, Map map) {
  p.batches.push_back(ts::layout::unitSquare(texture, "texture"));
  std::vector<glm::vec2> region;
  for (const auto& c : st) region.push_back(glm::vec2(c));
  p.batches.push_back(ts::lineLoop(region, kRegion, 3.0f, "region"));
  glm::dvec2 a = d == quad::Diagonal::TopLeftBottomRight ? glm::dvec2(0, 1) : glm::dvec2(0, 0);
  glm::dvec2 b = d == quad::Diagonal::TopLeftBottomRight ? glm::dvec2(1, 0) : glm::dvec2(1, 1);
  std::vector<glm::vec2> diag;
  for (int k = 0; k <= 32; ++k) diag.push_back(glm::vec2(map(glm::mix(a, b, k / 32.0))));
  ts::Batch line = ts::lineLoop(diag, kDiagonal, 2.0f, "diagonal_image");
  line.prim = ts::Prim::LineStrip;
  p.batches.push_back(line);
}

// Corner labels "<a,b>" (or, withValues, the corner's "<s,t>") beside each
// corner of cell c's picture, in the cell's caption bands: the top corners
// on the last line above, the bottom ones on the first line below (left out
// where two would not fit side by side).
inline void cornerLabels(ts::Frame& f, const ts::layout::Cell& c, const quad::Corners& st, bool withValues) {
  namespace L = ts::layout;
  const auto& P = quad::squareCorners();
  const ts::Rect& r = c.picture;
  int scale = c.scale;
  while (scale > 1 && 2 * ts::text::width("<0.75,0.75>", scale) + 8 > r.w) --scale;
  for (int i = 0; i < 4; ++i) {
    glm::dvec2 q = P[size_t(i)];
    const L::Text text = withValues ? "<" + L::given("s of the corner", st[size_t(i)].x, "%g") + "," +
                                          L::given("t of the corner", st[size_t(i)].y, "%g") + ">"
                                    : "<" + L::given("a of the corner", q.x, "%g") + "," +
                                          L::given("b of the corner", q.y, "%g") + ">";
    float x = float(r.x) + float(q.x) * float(r.w);
    bool top = q.y > 0.5;
    L::Box band = top ? L::Box{c.above.x0, c.above.y1 - L::lineHeight(scale), c.above.x1, c.above.y1}
                      : L::Box{c.below.x0, c.below.y0, c.below.x1, c.below.y0 + L::lineHeight(scale)};
    L::placeFree(f,
                 L::textLabel(x, band.y0 + float(2 * scale), text, L::kWhite, scale,
                              q.x > 0.5 ? ts::Align::Right : ts::Align::Left),
                 band);
  }
}
}  // namespace quad::views
