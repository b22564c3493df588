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

#include <cstddef>
#include <memory>
#include <vector>

#include "common/core/image.hpp"

namespace ts {
namespace detail {
// Allocates large arrays on 2 MB boundaries and asks Linux for huge pages
// there (madvise; transparent huge pages): a walk across a large table then
// misses the TLB once per 2 MB instead of once per 4 KB page.
void* allocateLarge(std::size_t bytes);
void freeLarge(void* p);
template <class T>
struct LargeAllocator {
  using value_type = T;
  LargeAllocator() = default;
  template <class U>
  LargeAllocator(const LargeAllocator<U>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(allocateLarge(n * sizeof(T))); }
  void deallocate(T* p, std::size_t) { freeLarge(p); }
  friend bool operator==(const LargeAllocator&, const LargeAllocator&) { return true; }
  friend bool operator!=(const LargeAllocator&, const LargeAllocator&) { return false; }
};
}  // namespace detail

using Polygon2 = std::vector<glm::dvec2>;

// Signed area (shoelace formula): positive for a counter-clockwise polygon.
double signedArea(const Polygon2& poly);

// Sutherland–Hodgman: the part of a convex polygon inside the box
// [x0, x1] × [y0, y1] (empty when they do not meet).
Polygon2 clipToBox(const Polygon2& poly, double x0, double y0, double x1, double y1);

struct TexelWeight {
  int i = 0, j = 0;   // texel index before wrapping (may be < 0 or ≥ size)
  double weight = 0;  // overlap area / preimage area
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
//
// The tables are laid out for the outline's walk, so that its time follows the
// footprint's texels and not the texture's size.  They hold running sums:
// P(i, j) = the sum of the texels left of i in row j, for i = 0 .. W (P(W, j)
// is the row's total).  For an 8-bit texture they are integers, 32 bits a
// channel (16 bytes a texel, exact): the sum in the low 24 bits and the texel
// itself in the top 8 (exact up to 65,793 texels a row; an Image has at most
// 16,384); for texels
// given as numbers they are 4 doubles (32 bytes) and a texel is
// P(i+1, j) - P(i, j).  The sums are stored in tiles of 4 KB (one page),
// column by column inside a tile (16 x 16 for 16-byte sums): an outline edge
// that steps from row to row, as the long edges of a far footprint do, reads
// four rows per 64-byte cache line and 16 rows per page, instead of a line and
// a page a row.  The table is in memory on 2 MB boundaries (huge pages where
// Linux gives them), and a table larger than the caches is walked with
// prefetching.  bench_zoo's zoo/exact_texture times the same 800 x 600 view
// and footprints on textures of 256^2 .. 4096^2 (README: "Benchmarks").
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
  // The same average for polygons that share edges, as the preimages of a
  // picture's pixels do (each pixel's right edge is its neighbour's left):
  // each edge walked once, not twice.  edge(a, b) is the outline integral
  // of G dv along a -> b, as average() walks it, at the edge's own shift of
  // whole periods (with the integral of the row totals T(v) dv that moves it
  // to another shift); averageOfEdges(poly, edges, signs) adds the polygon's
  // edges (edges[k] from poly[k] to poly[k+1], or, with signs[k] = -1, the
  // edge walked the other way) at the polygon's shift and divides by its
  // area.  Not average()'s doubles bit for bit (a reversed edge's pieces and
  // the shifts round differently; tests/unit/area_filter_test.cpp: within
  // 1e-9 of it), the same on degenerate polygons.
  struct Edge {
    glm::dvec4 g{0.0}, rows{0.0};  // integral of G(u - shift.x, v) dv, and of T(v) dv
    glm::dvec2 shift{0.0};         // whole periods subtracted from a and b
    long pieces = 0;
  };
  Edge edge(glm::dvec2 a, glm::dvec2 b) const;
  glm::dvec4 averageOfEdges(const Polygon2& poly, const Edge* const* edges, const int* signs) const;
  int width() const { return w_; }
  int height() const { return h_; }
  size_t tableBytes() const;  // the running sums' memory

 private:
  struct Tables;  // area_filter.cpp
  int w_ = 0, h_ = 0;
  std::shared_ptr<const Tables> tables_;  // immutable once made: copies share it
};
}  // namespace ts
