// common/core/area_filter.cpp — see area_filter.hpp.
#include "common/core/area_filter.hpp"

#include <algorithm>
#include <cmath>

namespace ts {
double signedArea(const Polygon2& poly) {
  double twice = 0;
  for (size_t k = 0; k < poly.size(); ++k) {
    const glm::dvec2& a = poly[k];
    const glm::dvec2& b = poly[(k + 1) % poly.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

namespace {
// One Sutherland–Hodgman step: keep the side of the line where
// inside(p) holds; `cross` gives the point where the edge a→b crosses it.
template <class Inside, class Cross>
Polygon2 clipEdge(const Polygon2& in, Inside inside, Cross cross) {
  Polygon2 out;
  for (size_t k = 0; k < in.size(); ++k) {
    const glm::dvec2& a = in[k];
    const glm::dvec2& b = in[(k + 1) % in.size()];
    const bool ia = inside(a), ib = inside(b);
    if (ia) out.push_back(a);
    if (ia != ib) out.push_back(cross(a, b));
  }
  return out;
}
// Where a→b meets x = c (ax != bx is guaranteed: a and b lie on opposite sides).
glm::dvec2 atX(glm::dvec2 a, glm::dvec2 b, double c) { return {c, a.y + (b.y - a.y) * (c - a.x) / (b.x - a.x)}; }
glm::dvec2 atY(glm::dvec2 a, glm::dvec2 b, double c) { return {a.x + (b.x - a.x) * (c - a.y) / (b.y - a.y), c}; }
}  // namespace

Polygon2 clipToBox(const Polygon2& poly, double x0, double y0, double x1, double y1) {
  Polygon2 p = poly;
  p = clipEdge(p, [&](glm::dvec2 q) { return q.x >= x0; }, [&](glm::dvec2 a, glm::dvec2 b) { return atX(a, b, x0); });
  p = clipEdge(p, [&](glm::dvec2 q) { return q.x <= x1; }, [&](glm::dvec2 a, glm::dvec2 b) { return atX(a, b, x1); });
  p = clipEdge(p, [&](glm::dvec2 q) { return q.y >= y0; }, [&](glm::dvec2 a, glm::dvec2 b) { return atY(a, b, y0); });
  p = clipEdge(p, [&](glm::dvec2 q) { return q.y <= y1; }, [&](glm::dvec2 a, glm::dvec2 b) { return atY(a, b, y1); });
  return p;
}

std::vector<TexelWeight> exactAreaWeights(const Polygon2& preimage) {
  std::vector<TexelWeight> out;
  if (preimage.empty()) return out;
  const double total = std::fabs(signedArea(preimage));
  if (!(total >= 1e-12)) {
    out.push_back({int(std::floor(preimage[0].x)), int(std::floor(preimage[0].y)), 1.0});
    return out;
  }
  double u0 = preimage[0].x, u1 = u0, v0 = preimage[0].y, v1 = v0;
  for (const glm::dvec2& p : preimage) {
    u0 = std::min(u0, p.x), u1 = std::max(u1, p.x);
    v0 = std::min(v0, p.y), v1 = std::max(v1, p.y);
  }
  // The texels the bounding box touches: the only ones that can overlap.
  const int i0 = int(std::floor(u0)), i1 = int(std::ceil(u1)) - 1;
  const int j0 = int(std::floor(v0)), j1 = int(std::ceil(v1)) - 1;
  for (int j = j0; j <= std::max(j0, j1); ++j) {
    // Clip to the row first, then each texel of the row: a row's strip is
    // small, so the per-texel clip works on few vertices.
    const Polygon2 row = clipToBox(preimage, u0, j, u1, j + 1.0);
    if (row.size() < 3) continue;
    for (int i = i0; i <= std::max(i0, i1); ++i) {
      const double a = std::fabs(signedArea(clipToBox(row, i, j, i + 1.0, j + 1.0)));
      if (a > 0) out.push_back({i, j, a / total});
    }
  }
  return out;
}

glm::dvec4 exactAreaAverage(const Image& texture, const Polygon2& preimage) {
  glm::dvec4 sum(0.0);
  if (texture.empty()) return sum;
  for (const TexelWeight& t : exactAreaWeights(preimage)) {
    const int i = ((t.i % texture.width) + texture.width) % texture.width;    // GL_REPEAT
    const int j = ((t.j % texture.height) + texture.height) % texture.height;
    const Rgba c = texture.at(i, j);
    sum += t.weight * glm::dvec4(c.r, c.g, c.b, c.a);
  }
  return sum;
}
}  // namespace ts
