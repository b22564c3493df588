// common/core/area_filter.cpp — see area_filter.hpp.
#include "common/core/area_filter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <new>
#include <utility>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace ts {
namespace detail {
void* allocateLarge(std::size_t bytes) {
  const std::size_t huge = std::size_t(1) << 21, align = bytes >= huge ? huge : 64;
  void* p = std::aligned_alloc(align, std::max<std::size_t>(align, (bytes + align - 1) / align * align));
  if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (align == huge) madvise(p, (bytes + align - 1) / align * align, MADV_HUGEPAGE);  // a hint: ignored if unavailable
#endif
  return p;
}
void freeLarge(void* p) { std::free(p); }
}  // namespace detail

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

AreaIntegral::AreaIntegral(const Image& texture) : w_(texture.width), h_(texture.height) {
  std::vector<glm::dvec4> texels(size_t(w_) * size_t(h_));
  for (int j = 0; j < h_; ++j)
    for (int i = 0; i < w_; ++i) {
      const Rgba c = texture.at(i, j);
      texels[size_t(j) * size_t(w_) + size_t(i)] = glm::dvec4(c.r, c.g, c.b, c.a);
    }
  build(texels);
}

AreaIntegral::AreaIntegral(int w, int h, std::vector<glm::dvec4> texels) : w_(w), h_(h) {
  texels.resize(size_t(w_) * size_t(h_), glm::dvec4(0.0));
  build(texels);
}

void AreaIntegral::build(const std::vector<glm::dvec4>& texels) {
  tilesAcross_ = (w_ + kTile - 1) / kTile;
  const int tilesDown = (h_ + kTile - 1) / kTile;
  cells_.assign(size_t(tilesAcross_) * size_t(tilesDown) * kTile * kTile, Cell{glm::dvec4(0.0), glm::dvec4(0.0)});
  rowTotal_.assign(size_t(h_), glm::dvec4(0.0));
  for (int j = 0; j < h_; ++j) {
    glm::dvec4 run(0.0);  // the same additions, in the same order, as a plain running sum
    const size_t base = rowBase(j);
    for (int i = 0; i < w_; ++i) {
      Cell& c = cells_[base + cellOffset(i)];
      c.prefix = run;
      c.texel = texels[size_t(j) * size_t(w_) + size_t(i)];
      run = run + c.texel;
    }
    rowTotal_[size_t(j)] = run;
  }
}

namespace {
// One piece of an edge between two texel-grid crossings: its dv, and G at
// its midpoint = periods * (row total) + prefix + texel * du.
struct Piece {
  const glm::dvec4 *prefix, *texel, *total;
  double dv, periods, du;
};
}  // namespace

glm::dvec4 AreaIntegral::average(const Polygon2& in, long* pieces) const {
  if (pieces) *pieces = 0;
  if (in.empty() || w_ <= 0 || h_ <= 0) return glm::dvec4(0.0);
  // Work near the origin: shift by whole periods (the texture is the same
  // there), so G's running sums and the area's products stay small, and the
  // rounding with them.
  double u0 = in[0].x, v0 = in[0].y;
  for (const glm::dvec2& p : in) u0 = std::min(u0, p.x), v0 = std::min(v0, p.y);
  const glm::dvec2 shift(w_ * std::floor(u0 / w_), h_ * std::floor(v0 / h_));
  double twice = 0;
  for (size_t k = 0; k < in.size(); ++k) {
    const glm::dvec2 a = in[k] - shift, b = in[(k + 1) % in.size()] - shift;
    twice += a.x * b.y - b.x * a.y;
  }
  const double total = 0.5 * twice;
  if (!(std::fabs(total) >= 1e-12)) {
    const long i = long(std::floor(in[0].x)), j = long(std::floor(in[0].y));
    return cells_[rowBase(((j % h_) + h_) % h_) + cellOffset(((i % w_) + w_) % w_)].texel;
  }
  glm::dvec4 sum(0.0);
  long count = 0;
  thread_local std::vector<Piece> pieceBuffer;  // one edge's pieces
  const bool prefetch = cells_.size() * sizeof(Cell) > kPrefetchBytes;
  const size_t n = in.size();
  for (size_t k = 0; k < n; ++k) {
    const glm::dvec2 a = in[k] - shift, b = in[(k + 1) % n] - shift;
    if (a.y == b.y) continue;  // dv = 0: nothing to add
    const glm::dvec2 d = b - a;
    const int si = d.x > 0 ? 1 : -1, sj = d.y > 0 ? 1 : -1;
    // t (0..1 along the edge) of the next crossing of a vertical (tu) and a
    // horizontal (tv) grid line, and the step to the one after.
    double tu = 2, dtu = 0;
    if (d.x != 0) {
      const double c = d.x > 0 ? std::floor(a.x) + 1 : std::ceil(a.x) - 1;
      tu = (c - a.x) / d.x, dtu = si / d.x;
    }
    const double cv = d.y > 0 ? std::floor(a.y) + 1 : std::ceil(a.y) - 1;
    double tv = (cv - a.y) / d.y;
    const double dtv = sj / d.y;
    // The first texel: under the first piece's midpoint; then one step per crossing.
    double t0 = 0, t1 = std::min(std::min(tu, tv), 1.0);
    const glm::dvec2 m0 = a + 0.5 * t1 * d;
    const long i = long(std::floor(m0.x)), j = long(std::floor(m0.y));
    long q = i >= 0 ? i / w_ : -((-i + w_ - 1) / w_);  // whole periods left of texel i
    long mi = i - q * w_;                             // its column in the texture
    long row = ((j % h_) + h_) % h_;
    const Cell* cells = &cells_[rowBase(row)];  // row's cells: cells[cellOffset(i)]
    const glm::dvec4* total = &rowTotal_[size_t(row)];
    // A table larger than the caches is walked in two passes over the edge:
    // the first finds its pieces and asks for their cells (prefetch: a long
    // edge crosses texels far apart in memory, and waiting for each in turn
    // is what made large textures slow), the second sums them — the same
    // numbers in the same order as the one pass a small table takes.
    pieceBuffer.clear();
    for (;;) {
      if (t1 > t0) {
        const double um = a.x + 0.5 * (t0 + t1) * d.x;  // G is linear in u within the texel: its midpoint value
        const Cell* c = &cells[cellOffset(mi)];
        const Piece pc{&c->prefix, &c->texel, total, d.y * (t1 - t0), double(q), um - double(q * w_ + mi)};
        if (prefetch) {
          __builtin_prefetch(c);
          pieceBuffer.push_back(pc);
        } else {
          sum += pc.dv * (pc.periods * *pc.total + *pc.prefix + *pc.texel * pc.du);
          ++count;
        }
      }
      if (t1 >= 1) break;
      if (t1 == tu) {
        tu += dtu, mi += si;
        if (mi == w_) mi = 0, ++q;
        else if (mi < 0) mi = w_ - 1, --q;
      }
      if (t1 == tv) {
        tv += dtv, row += sj;
        if (row == h_) row = 0;
        else if (row < 0) row = h_ - 1;
        cells = &cells_[rowBase(row)];
        total = &rowTotal_[size_t(row)];
      }
      t0 = t1;
      t1 = std::min(std::min(tu, tv), 1.0);
    }
    for (const Piece& pc : pieceBuffer)
      sum += pc.dv * (pc.periods * *pc.total + *pc.prefix + *pc.texel * pc.du);
    count += long(pieceBuffer.size());
  }
  if (pieces) *pieces = count;
  return sum / total;  // a clockwise polygon gives both signs negative
}
}  // namespace ts
