#include "raster.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ref {
namespace {
// Coverage is decided exactly, on vertex positions snapped to 1/256 pixel
// (llvmpipe's sub-pixel precision): an edge's x at a scanline centre is the
// rational N / (256 DY) with N stepped by an integer increment per scanline
// (the seed's x11 += dx12, done without round-off).  So ties — a centre on
// an edge or on a vertex — go by the fill rule alone, never by accumulated
// floating-point error.  Attributes are stepped in double precision along
// the same edges (seed: xd1 += tx12, yd1 += ty12) from the unsnapped
// positions.
constexpr int64_t kSub = 256;  // sub-pixel steps per pixel

int64_t floorDiv(int64_t a, int64_t b) {  // b > 0
  int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}
int64_t ceilDiv(int64_t a, int64_t b) { return -floorDiv(-a, b); }

struct Snapped {
  int64_t X, Y;
};
Snapped snap(const ScreenVertex& v) { return {int64_t(std::llround(v.x * kSub)), int64_t(std::llround(v.y * kSub))}; }

// First scanline (image rows, y down) whose centre is at or below
// (ImageTopLeft) / strictly below (GLTopLeft) the height Y (sub-pixels):
// which centres on a horizontal boundary belong to the triangle.  With
// GLTopLeft a span runs over centres y0 < yc <= y2: the image-bottom edge is
// GL's top edge.
int64_t firstRow(int64_t Y, FillRule rule) {
  return rule == FillRule::ImageTopLeft ? ceilDiv(Y - kSub / 2, kSub) : floorDiv(Y - kSub / 2, kSub) + 1;
}

// One edge, stepped scanline by scanline from its upper vertex.
struct Edge {
  int64_t N = 0, dN = 0, DY = 1;  // x at the scanline centre: N / DY sub-pixels; dN per scanline
  double x = 0, dx = 0;           // the same line unsnapped, for the attributes
  std::array<double, kMaxAttributes> a{}, da{};
  int64_t row = 0, rowEnd = 0;  // scanlines [row, rowEnd) whose centres it spans
  // First pixel whose centre is at or right of the edge: centre (c + 1/2)
  // >= x  <=>  (kSub c + kSub/2) DY >= N.
  int64_t firstColumn() const { return ceilDiv(N - (kSub / 2) * DY, kSub * DY); }
  // The same at scanline r without stepping there: N grows by dN a scanline,
  // in integers, so this is exactly the value the stepping reaches.
  int64_t firstColumnAt(int64_t r) const {
    Edge e = *this;
    e.N += (r - row) * dN;
    return e.firstColumn();
  }
};

Edge makeEdge(const ScreenVertex& u, const ScreenVertex& l, Snapped su, Snapped sl, int n, FillRule rule) {
  Edge e;
  e.row = firstRow(su.Y, rule);
  e.rowEnd = firstRow(sl.Y, rule);
  e.DY = sl.Y - su.Y;
  if (e.DY <= 0) {
    e.rowEnd = e.row;
    e.DY = 1;
    return e;
  }
  int64_t DX = sl.X - su.X;
  int64_t YC = e.row * kSub + kSub / 2;  // the first centre, sub-pixels
  e.N = su.X * e.DY + (YC - su.Y) * DX;
  e.dN = kSub * DX;
  double dy = l.y - u.y;
  if (dy > 0) {
    e.dx = (l.x - u.x) / dy;
    double off = (double(e.row) + 0.5) - u.y;  // from the vertex to the first centre
    e.x = u.x + off * e.dx;
    for (int k = 0; k < n; ++k) {
      e.da[size_t(k)] = (l.a[size_t(k)] - u.a[size_t(k)]) / dy;
      e.a[size_t(k)] = u.a[size_t(k)] + off * e.da[size_t(k)];
    }
  } else {
    e.x = u.x;
    for (int k = 0; k < n; ++k) e.a[size_t(k)] = u.a[size_t(k)];
  }
  return e;
}

// A triangle's vertices sorted by y (snapped, so ties are exact) and the
// sign of its area on the snapped grid (0: degenerate).
struct Sorted {
  const ScreenVertex *a, *b, *c;
  Snapped sa, sb, sc;
  int64_t cross;
};
Sorted sortByY(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2) {
  const ScreenVertex* p[3] = {&v0, &v1, &v2};
  Snapped sp[3] = {snap(v0), snap(v1), snap(v2)};
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return sp[i].Y < sp[j].Y; });
  Sorted o{p[order[0]], p[order[1]], p[order[2]], sp[order[0]], sp[order[1]], sp[order[2]], 0};
  o.cross = (o.sb.X - o.sa.X) * (o.sc.Y - o.sa.Y) - (o.sb.Y - o.sa.Y) * (o.sc.X - o.sa.X);
  return o;
}

// Vertices this far out are not rasterized (the caller clips to the viewport).
bool inRange(const ScreenVertex& v) { return std::abs(v.x) < 1e6 && std::abs(v.y) < 1e6; }

void step(Edge& e, int n) {
  e.N += e.dN;
  e.x += e.dx;
  for (int k = 0; k < n; ++k) e.a[size_t(k)] += e.da[size_t(k)];
}
}  // namespace

Plane planeThrough(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int k, bool* ok) {
  double x1 = v1.x - v0.x, y1 = v1.y - v0.y, x2 = v2.x - v0.x, y2 = v2.y - v0.y;
  double det = x1 * y2 - x2 * y1;
  Plane p;
  if (det == 0) {
    if (ok) *ok = false;
    return p;
  }
  double f1 = v1.a[size_t(k)] - v0.a[size_t(k)], f2 = v2.a[size_t(k)] - v0.a[size_t(k)];
  p.a = (f1 * y2 - f2 * y1) / det;
  p.b = (x1 * f2 - x2 * f1) / det;
  p.c = v0.a[size_t(k)] - p.a * v0.x - p.b * v0.y;
  if (ok) *ok = true;
  return p;
}

long scanTriangle(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int n, PixelRect clip,
                  FillRule rule, const Emit& emit) {
  n = std::clamp(n, 0, kMaxAttributes);
  if (!inRange(v0) || !inRange(v1) || !inRange(v2)) return 0;
  // 1. Sort the vertices by y (snapped, so ties are exact).
  const Sorted o = sortByY(v0, v1, v2);
  const ScreenVertex &a = *o.a, &b = *o.b, &c = *o.c;
  const Snapped sa = o.sa, sb = o.sb, sc = o.sc;
  const int64_t cross = o.cross;
  if (cross == 0) return 0;
  // Per-pixel increments along a span: the attribute planes' x gradients.
  std::array<double, kMaxAttributes> dadx{};
  for (int k = 0; k < n; ++k) dadx[size_t(k)] = planeThrough(v0, v1, v2, k, nullptr).a;
  // 2. Increments along the three edges.
  Edge longEdge = makeEdge(a, c, sa, sc, n, rule), upper = makeEdge(a, b, sa, sb, n, rule),
       lower = makeEdge(b, c, sb, sc, n, rule);
  // The middle vertex left of the long edge: the short edges are on the left.
  bool shortLeft = cross < 0;
  long emitted = 0;
  std::array<double, kMaxAttributes> attr{};
  // 3.-22. Spans from the top scanline to the bottom one.
  for (int64_t row = longEdge.row; row < longEdge.rowEnd; ++row) {
    Edge& shortEdge = row < upper.rowEnd ? upper : lower;
    const Edge& left = shortLeft ? shortEdge : longEdge;
    const Edge& right = shortLeft ? longEdge : shortEdge;
    if (row >= clip.y0 && row < clip.y1) {
      // Centres with left.x <= x + 1/2 < right.x: left edges in, right edges out.
      int64_t x0 = left.firstColumn(), x1 = right.firstColumn();
      int64_t cx0 = std::max<int64_t>(x0, clip.x0), cx1 = std::min<int64_t>(x1, clip.x1);
      if (cx0 < cx1) {
        double off = (double(cx0) + 0.5) - left.x;
        for (int k = 0; k < n; ++k) attr[size_t(k)] = left.a[size_t(k)] + off * dadx[size_t(k)];
        for (int64_t x = cx0; x < cx1; ++x) {
          emit(int(x), int(row), attr.data());
          ++emitted;
          for (int k = 0; k < n; ++k) attr[size_t(k)] += dadx[size_t(k)];
        }
      }
    }
    step(longEdge, n);
    step(shortEdge, n);
  }
  return emitted;
}
bool coversCentre(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int x, int y, FillRule rule) {
  if (!inRange(v0) || !inRange(v1) || !inRange(v2)) return false;
  const Sorted o = sortByY(v0, v1, v2);
  if (o.cross == 0) return false;
  // The scanline loop of scanTriangle, at the one row y: the same three
  // edges, the same choice of the short edge and of left and right.
  Edge longEdge = makeEdge(*o.a, *o.c, o.sa, o.sc, 0, rule), upper = makeEdge(*o.a, *o.b, o.sa, o.sb, 0, rule),
       lower = makeEdge(*o.b, *o.c, o.sb, o.sc, 0, rule);
  if (y < longEdge.row || y >= longEdge.rowEnd) return false;
  const Edge& shortEdge = y < upper.rowEnd ? upper : lower;
  const bool shortLeft = o.cross < 0;
  const Edge& left = shortLeft ? shortEdge : longEdge;
  const Edge& right = shortLeft ? longEdge : shortEdge;
  // Left edges in, right edges out.
  return x >= left.firstColumnAt(y) && x < right.firstColumnAt(y);
}
}  // namespace ref
