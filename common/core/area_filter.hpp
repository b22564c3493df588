// common/core/area_filter.hpp — the ideal minification filter, exactly.
//
// Buss VI.1.3: the ideal colour of a pixel averages "the texels under the
// pixel's preimage, weighted by area".  Rogers (seed 004) does the same by
// hand.  Here it is computed, not sampled: the preimage of the pixel square
// (a convex quadrilateral in texel units, the pixel's corners mapped back
// through the plane's homography) is clipped against each texel square it
// touches, and each texel's weight is
//
//     w(i,j) = area(preimage ∩ [i, i+1] × [j, j+1]) / area(preimage).
//
// The weights sum to 1.  The cost grows with the number of texels the
// preimage touches (its bounding box), never with the texture's size.
// Texel (i, j) covers u ∈ [i, i+1], v ∈ [j, j+1]: its centre is (i+½, j+½),
// as in the GL specification's sampling equations.  No GL here.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <vector>

#include "common/core/image.hpp"

namespace ts {
using Polygon2 = std::vector<glm::dvec2>;

// Signed area (shoelace formula): positive for a counter-clockwise polygon.
double signedArea(const Polygon2& poly);

// Sutherland–Hodgman: the part of a convex polygon inside the box
// [x0, x1] × [y0, y1] (empty when they do not meet).
Polygon2 clipToBox(const Polygon2& poly, double x0, double y0, double x1, double y1);

struct TexelWeight {
  int i = 0, j = 0;    // texel index before wrapping (may be < 0 or ≥ size)
  double weight = 0;   // overlap area / preimage area
};

// Each texel the convex polygon overlaps, with its share of the polygon's
// area, row by row.  A degenerate polygon (area < 1e-12 texels²) gives the
// one texel that holds its first corner, with weight 1 (point sampling is the
// limit of a vanishing footprint).
std::vector<TexelWeight> exactAreaWeights(const Polygon2& preimage);

// The area-weighted average of `texture` over the polygon (texel units of
// this image, v = 0 at the image's first row), wrapping with GL_REPEAT.
// Channels in 0..255, not rounded.
glm::dvec4 exactAreaAverage(const Image& texture, const Polygon2& preimage);

// The same average, exactly, at the cost of the preimage's outline instead of
// its area: for a whole picture of large footprints (the filter zoo's
// reference at 800 x 600 reaches footprints of thousands of texels near the
// horizon, where clipping every texel takes minutes).  By Green's theorem,
//
//     integral over P of f du dv  =  contour integral over the edges of P of G(u, v) dv,
//
// with G(u, v) = integral from 0 to u of f(s, v) ds, the running sum along the
// texel row through v: G = (texels left of floor(u) in the row, whole
// periods included) + f(floor(u), row) (u - floor(u)).  G is linear in u
// within a texel, so along each piece of an edge between two texel-grid
// crossings the integral is the piece's dv times G at its midpoint: exact.
// Each edge costs |du| + |dv| + 1 pieces (texels crossed), so a pixel costs
// its footprint's perimeter in texels, never the texture's size; the row
// sums are made once per texture.  Agrees with exactAreaAverage to about
// 1e-8 (8-bit units; tests/unit/area_filter_test.cpp).  GL_REPEAT; (u, v) as
// there.  Not thread-safe to build, safe to use from several threads.
class AreaIntegral {
 public:
  explicit AreaIntegral(const Image& texture);
  // Texels given as numbers, w x h, row by row (e.g. linear-light values).
  AreaIntegral(int w, int h, std::vector<glm::dvec4> texels);
  // The area-weighted average over the polygon (any orientation; a
  // degenerate polygon, area < 1e-12 texels^2, gives the texel under its
  // first corner).  `pieces`, when given, gets the number of edge pieces
  // summed: the cost.
  glm::dvec4 average(const Polygon2& preimage, long* pieces = nullptr) const;
  int width() const { return w_; }
  int height() const { return h_; }

 private:
  int w_ = 0, h_ = 0;
  std::vector<glm::dvec4> texel_;   // w x h
  std::vector<glm::dvec4> prefix_;  // (w + 1) per row: sums of the texels left of i
};
}  // namespace ts
