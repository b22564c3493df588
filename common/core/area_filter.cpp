// common/core/area_filter.cpp — see area_filter.hpp.
#include "common/core/area_filter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <cstdlib>
#include <new>
#ifdef _WIN32
#include <malloc.h>
#endif
#include <utility>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace ts {
namespace detail {
void* allocateLarge(std::size_t bytes) {
  const std::size_t huge = std::size_t(1) << 21, align = bytes >= huge ? huge : 64;
#ifdef _WIN32
  // Windows' C runtime has no aligned_alloc (its free() cannot free such a
  // block); _aligned_malloc pairs with _aligned_free below.
  void* p = _aligned_malloc(std::max<std::size_t>(align, (bytes + align - 1) / align * align), align);
#else
  void* p = std::aligned_alloc(align, std::max<std::size_t>(align, (bytes + align - 1) / align * align));
#endif
  if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (align == huge) madvise(p, (bytes + align - 1) / align * align, MADV_HUGEPAGE);  // a hint: ignored if unavailable
#endif
  return p;
}
void freeLarge(void* p) {
#ifdef _WIN32
  _aligned_free(p);
#else
  std::free(p);
#endif
}
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
  p = clipEdge(
      p, [&](glm::dvec2 q) { return q.x >= x0; }, [&](glm::dvec2 a, glm::dvec2 b) { return atX(a, b, x0); });
  p = clipEdge(
      p, [&](glm::dvec2 q) { return q.x <= x1; }, [&](glm::dvec2 a, glm::dvec2 b) { return atX(a, b, x1); });
  p = clipEdge(
      p, [&](glm::dvec2 q) { return q.y >= y0; }, [&](glm::dvec2 a, glm::dvec2 b) { return atY(a, b, y0); });
  p = clipEdge(
      p, [&](glm::dvec2 q) { return q.y <= y1; }, [&](glm::dvec2 a, glm::dvec2 b) { return atY(a, b, y1); });
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
    const int i = ((t.i % texture.width) + texture.width) % texture.width;  // GL_REPEAT
    const int j = ((t.j % texture.height) + texture.height) % texture.height;
    const Rgba c = texture.at(i, j);
    sum += t.weight * glm::dvec4(c.r, c.g, c.b, c.a);
  }
  return sum;
}

namespace {
// One running sum of four channels.  An 8-bit texture's are integers in
// 32 bits a channel (16 bytes): the sum in the low 24 bits (exact while
// 255 W < 2^24) and the texel itself in the top 8, so one read gives both.
// Texels given as numbers get doubles (32 bytes), and the texel is the
// difference of two sums.
struct IntegerSum {
  static constexpr bool kHoldsTexel = true;
  static constexpr uint32_t kSumMask = 0xFFFFFFu;
  uint32_t c[4];
};
// (Both fit a signed 32-bit integer, which converts to double two at a time.)
static_assert(255 * kMaxImageDimension <= int64_t(IntegerSum::kSumMask), "an image's row sums must fit 24 bits");
inline glm::dvec4 valueOf(const IntegerSum& s) {
  return {double(int32_t(s.c[0] & IntegerSum::kSumMask)), double(int32_t(s.c[1] & IntegerSum::kSumMask)),
          double(int32_t(s.c[2] & IntegerSum::kSumMask)), double(int32_t(s.c[3] & IntegerSum::kSumMask))};
}
inline glm::dvec4 texelOf(const IntegerSum& a, const IntegerSum&) {
  return {double(int32_t(a.c[0] >> 24)), double(int32_t(a.c[1] >> 24)), double(int32_t(a.c[2] >> 24)),
          double(int32_t(a.c[3] >> 24))};
}
struct RealSum {
  static constexpr bool kHoldsTexel = false;
  glm::dvec4 v;
};
inline const glm::dvec4& valueOf(const RealSum& s) { return s.v; }
// The texel between two running sums: P(i+1) - P(i).
inline glm::dvec4 texelOf(const RealSum& a, const RealSum& b) { return b.v - a.v; }

// P(i, j) for i = 0 .. W, j = 0 .. H-1, in tiles of 4 KB (kTileW columns of
// kTileH sums, column by column): see area_filter.hpp.
template <class Sum>
struct SumTable {
  static constexpr int kTileW = 16, kTileH = int(4096 / (kTileW * sizeof(Sum)));  // 16 x 16 integers, 16 x 8 doubles
  int cols = 0, rows = 0, tilesAcross = 0;
  std::vector<Sum, detail::LargeAllocator<Sum>> sums;
  SumTable(int w, int h)
      : cols(w + 1),
        rows(h),
        tilesAcross((w + 1 + kTileW - 1) / kTileW),
        sums(size_t(tilesAcross) * size_t((h + kTileH - 1) / kTileH) * kTileW * kTileH) {}
  // Where row j's sums start (add column(i)).
  size_t rowBase(long j) const {
    return size_t(j / kTileH) * size_t(tilesAcross) * kTileW * kTileH + size_t(j % kTileH);
  }
  static size_t column(long i) { return size_t(i / kTileW) * kTileW * kTileH + size_t(i % kTileW) * kTileH; }
  size_t bytes() const { return sums.size() * sizeof(Sum); }
};

// One piece of an edge between two texel-grid crossings: its dv, and G at
// its midpoint = periods * (row total) + P(i) + texel(i) * du.
template <class Sum>
struct Piece {
  const Sum *left, *right, *total;  // P(i), P(i+1), and P(W) of the piece's row or a zero sum
  double dv, periods, du;
  glm::dvec4 g() const { return periods * valueOf(*total) + valueOf(*left) + texelOf(*left, *right) * du; }
};
#if defined(__SSE2__)
// The same sum for an 8-bit texture's table, two channels at a time (SSE2,
// the x86-64 baseline): unpacking and converting the integers channel by
// channel cost a third more time than the walk itself.  Same operations in
// the same order: the same doubles.
template <>
inline glm::dvec4 Piece<IntegerSum>::g() const {
  const __m128i mask = _mm_set1_epi32(int(IntegerSum::kSumMask));
  const __m128i l = _mm_loadu_si128(reinterpret_cast<const __m128i*>(left->c));
  const __m128i t = _mm_loadu_si128(reinterpret_cast<const __m128i*>(total->c));
  const __m128i sumL = _mm_and_si128(l, mask), texel = _mm_srli_epi32(l, 24), sumT = _mm_and_si128(t, mask);
  const __m128d p = _mm_set1_pd(periods), d = _mm_set1_pd(du);
  const auto half = [&](__m128i tot, __m128i sum, __m128i tex) {  // lanes 0 and 1 of each
    return _mm_add_pd(_mm_add_pd(_mm_mul_pd(p, _mm_cvtepi32_pd(tot)), _mm_cvtepi32_pd(sum)),
                      _mm_mul_pd(_mm_cvtepi32_pd(tex), d));
  };
  const auto upper = [](__m128i v) { return _mm_unpackhi_epi64(v, v); };
  glm::dvec4 out;
  _mm_storeu_pd(&out.x, half(sumT, sumL, texel));
  _mm_storeu_pd(&out.z, half(upper(sumT), upper(sumL), upper(texel)));
  return out;
}
#endif

// Tables larger than this (bytes) are walked with prefetching.
constexpr size_t kPrefetchBytes = size_t(8) << 20;

// One edge a -> b (already shifted near the origin) of the outline: adds
// dv * G at each piece's midpoint to `sum`, in the order of the walk, and
// counts the pieces.  With `rows`, also adds dv * (the piece's row total)
// there: the integral of T(v) dv, which moves the edge's integral from one
// shift of whole periods to another (G(u - w, v) = G(u, v) - T(v)).
template <class Sum>
void walkEdge(const SumTable<Sum>& table, int w_, int h_, glm::dvec2 a, glm::dvec2 b, glm::dvec4& sum, glm::dvec4* rows,
              long& count) {
  using Table = SumTable<Sum>;
  if (a.y == b.y) return;                            // dv = 0: nothing to add
  thread_local std::vector<Piece<Sum>> pieceBuffer;  // one edge's pieces
  const bool prefetch = table.bytes() > kPrefetchBytes;
  const size_t totalColumn = Table::column(w_);
  static const Sum zero{};
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
  long mi = i - q * w_;                              // its column in the texture
  long row = ((j % h_) + h_) % h_;
  const Sum* sums = &table.sums[table.rowBase(row)];  // row's sums: sums[Table::column(i)]
  // A table larger than the caches is walked in two passes over the edge:
  // the first finds its pieces and asks for their sums (prefetch: a long
  // edge crosses texels far apart in memory, and waiting for each in turn
  // is what made large textures slow), the second adds them — the same
  // numbers in the same order as the one pass a small table takes.
  pieceBuffer.clear();
  for (;;) {
    if (t1 > t0) {
      const double um = a.x + 0.5 * (t0 + t1) * d.x;  // G is linear in u within the texel: its midpoint value
      // No whole periods to add (q = 0): the row total is not read, a zero
      // stands in (a select, not a branch: q changes often on a tiled plane).
      const Piece<Sum> pc{&sums[Table::column(mi)],
                          &sums[Table::column(mi + 1)],
                          q != 0 ? &sums[totalColumn] : &zero,
                          d.y * (t1 - t0),
                          double(q),
                          um - double(q * w_ + mi)};
      if (rows) *rows += pc.dv * valueOf(sums[totalColumn]);
      if (prefetch) {
        __builtin_prefetch(pc.left);
        if (!Sum::kHoldsTexel) __builtin_prefetch(pc.right);
        if (q != 0) __builtin_prefetch(pc.total);  // the branch only steers the hint
        pieceBuffer.push_back(pc);
      } else {
        sum += pc.dv * pc.g();
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
      sums = &table.sums[table.rowBase(row)];
    }
    t0 = t1;
    t1 = std::min(std::min(tu, tv), 1.0);
  }
  for (const Piece<Sum>& pc : pieceBuffer) sum += pc.dv * pc.g();
  count += long(pieceBuffer.size());
}

// Whole periods near a polygon's lowest u and v: subtracting them leaves the
// texture the same and keeps G's sums and the area's products small.
glm::dvec2 periodShift(int w_, int h_, double u0, double v0) {
  return {w_ * std::floor(u0 / w_), h_ * std::floor(v0 / h_)};
}

// A polygon's place and area as outlineAverage and averageFromEdges take
// them.  Work near the origin: shift by whole periods (the texture is the
// same there), so G's running sums and the area's products stay small, and
// the rounding with them.  A polygon of no area (degenerate) reads the texel
// under its first corner instead.
struct Placed {
  glm::dvec2 shift;
  double total = 0;
  bool degenerate = false;
};
Placed place(int w_, int h_, const Polygon2& in) {
  double u0 = in[0].x, v0 = in[0].y;
  for (const glm::dvec2& p : in) u0 = std::min(u0, p.x), v0 = std::min(v0, p.y);
  Placed pl;
  pl.shift = periodShift(w_, h_, u0, v0);
  double twice = 0;
  for (size_t k = 0; k < in.size(); ++k) {
    const glm::dvec2 a = in[k] - pl.shift, b = in[(k + 1) % in.size()] - pl.shift;
    twice += a.x * b.y - b.x * a.y;
  }
  pl.total = 0.5 * twice;
  pl.degenerate = !(std::fabs(pl.total) >= 1e-12);
  return pl;
}
template <class Sum>
glm::dvec4 firstCornerTexel(const SumTable<Sum>& table, int w_, int h_, const Polygon2& in) {
  using Table = SumTable<Sum>;
  const long i = ((long(std::floor(in[0].x)) % w_) + w_) % w_, j = ((long(std::floor(in[0].y)) % h_) + h_) % h_;
  const Sum* row = &table.sums[table.rowBase(j)];
  return texelOf(row[Table::column(i)], row[Table::column(i + 1)]);
}

template <class Sum>
glm::dvec4 outlineAverage(const SumTable<Sum>& table, int w_, int h_, const Polygon2& in, long* pieces) {
  if (pieces) *pieces = 0;
  if (in.empty() || w_ <= 0 || h_ <= 0) return glm::dvec4(0.0);
  const Placed pl = place(w_, h_, in);
  if (pl.degenerate) return firstCornerTexel(table, w_, h_, in);
  const glm::dvec2 shift = pl.shift;
  const double total = pl.total;
  glm::dvec4 sum(0.0);
  long count = 0;
  const size_t n = in.size();
  for (size_t k = 0; k < n; ++k) walkEdge(table, w_, h_, in[k] - shift, in[(k + 1) % n] - shift, sum, nullptr, count);
  if (pieces) *pieces = count;
  return sum / total;  // a clockwise polygon gives both signs negative
}

template <class Sum>
AreaIntegral::Edge outlineEdge(const SumTable<Sum>& table, int w_, int h_, glm::dvec2 a, glm::dvec2 b) {
  AreaIntegral::Edge e;
  if (w_ <= 0 || h_ <= 0) return e;
  e.shift = periodShift(w_, h_, std::min(a.x, b.x), std::min(a.y, b.y));
  walkEdge(table, w_, h_, a - e.shift, b - e.shift, e.g, &e.rows, e.pieces);
  return e;
}

template <class Sum>
glm::dvec4 averageFromEdges(const SumTable<Sum>& table, int w_, int h_, const Polygon2& in,
                            const AreaIntegral::Edge* const* edges, const int* signs) {
  if (in.empty() || w_ <= 0 || h_ <= 0) return glm::dvec4(0.0);
  // The polygon's shift, area and degenerate case exactly as outlineAverage's.
  const Placed pl = place(w_, h_, in);
  if (pl.degenerate) return firstCornerTexel(table, w_, h_, in);
  const glm::dvec2 shift = pl.shift;
  const double total = pl.total;
  // Each edge's integral moved from its own shift to the polygon's: G at
  // u - s_e is G at u - s minus (s_e - s) / W row totals (the v shift does
  // not change G: the rows repeat).
  glm::dvec4 sum(0.0);
  for (size_t k = 0; k < in.size(); ++k) {
    const AreaIntegral::Edge& e = *edges[k];
    sum += double(signs[k]) * (e.g + ((e.shift.x - shift.x) / w_) * e.rows);
  }
  return sum / total;
}
}  // namespace

struct AreaIntegral::Tables {
  std::unique_ptr<SumTable<IntegerSum>> integer;  // an 8-bit texture's
  std::unique_ptr<SumTable<RealSum>> real;        // texels given as numbers
};

AreaIntegral::AreaIntegral(const Image& texture) : w_(texture.width), h_(texture.height) {
  auto t = std::make_shared<Tables>();
  t->integer = std::make_unique<SumTable<IntegerSum>>(w_, h_);
  SumTable<IntegerSum>& s = *t->integer;
  for (int j = 0; j < h_; ++j) {
    IntegerSum run{{0, 0, 0, 0}};
    const size_t base = s.rowBase(j);
    for (int i = 0; i <= w_; ++i) {
      const Rgba c = i < w_ ? texture.at(i, j) : Rgba{0, 0, 0, 0};
      s.sums[base + s.column(i)] = IntegerSum{{run.c[0] | uint32_t(c.r) << 24, run.c[1] | uint32_t(c.g) << 24,
                                               run.c[2] | uint32_t(c.b) << 24, run.c[3] | uint32_t(c.a) << 24}};
      run.c[0] += c.r, run.c[1] += c.g, run.c[2] += c.b, run.c[3] += c.a;
    }
  }
  tables_ = std::move(t);
}

AreaIntegral::AreaIntegral(int w, int h, std::vector<glm::dvec4> texels) : w_(w), h_(h) {
  texels.resize(size_t(w_) * size_t(h_), glm::dvec4(0.0));
  auto t = std::make_shared<Tables>();
  t->real = std::make_unique<SumTable<RealSum>>(w_, h_);
  SumTable<RealSum>& s = *t->real;
  for (int j = 0; j < h_; ++j) {
    glm::dvec4 run(0.0);
    const size_t base = s.rowBase(j);
    for (int i = 0; i <= w_; ++i) {
      s.sums[base + s.column(i)] = RealSum{run};
      if (i < w_) run = run + texels[size_t(j) * size_t(w_) + size_t(i)];
    }
  }
  tables_ = std::move(t);
}

glm::dvec4 AreaIntegral::average(const Polygon2& in, long* pieces) const {
  if (tables_ && tables_->integer) return outlineAverage(*tables_->integer, w_, h_, in, pieces);
  if (tables_ && tables_->real) return outlineAverage(*tables_->real, w_, h_, in, pieces);
  if (pieces) *pieces = 0;
  return glm::dvec4(0.0);
}

AreaIntegral::Edge AreaIntegral::edge(glm::dvec2 a, glm::dvec2 b) const {
  if (tables_ && tables_->integer) return outlineEdge(*tables_->integer, w_, h_, a, b);
  if (tables_ && tables_->real) return outlineEdge(*tables_->real, w_, h_, a, b);
  return Edge();
}

glm::dvec4 AreaIntegral::averageOfEdges(const Polygon2& in, const Edge* const* edges, const int* signs) const {
  if (tables_ && tables_->integer) return averageFromEdges(*tables_->integer, w_, h_, in, edges, signs);
  if (tables_ && tables_->real) return averageFromEdges(*tables_->real, w_, h_, in, edges, signs);
  return glm::dvec4(0.0);
}

size_t AreaIntegral::tableBytes() const {
  if (!tables_) return 0;
  return tables_->integer ? tables_->integer->bytes() : tables_->real ? tables_->real->bytes() : 0;
}
}  // namespace ts
