// exercises/scanline.cpp — seed 002's scanline texturer.
//
// The statement (seed 002, "Poniżej przedstawiono algorytm realizujący
// teksturowanie"): a textured triangle is drawn like Gouraud shading —
// sort the vertices by y, compute per-scanline increments of x and of the
// texture coordinates along the edges 1-2, 1-3 and 2-3, draw horizontal
// spans interpolating the texture coordinates along each, step the edge
// values, and switch at the middle vertex.  Below it is in C++ exactly as the
// seed prints it, steps 1 to 22, bugs and all.  Run it first: the checker
// counts the pixels each bug costs.  Then fix it.
//
// Write: plot(x, y, s, t) once for every pixel (x, y) whose centre
// (x + 1/2, y + 1/2) lies inside the triangle, with (s, t) interpolated
// linearly in screen space at that centre.  Positions are pixels, x right,
// y down.  A centre exactly on an edge belongs to one triangle only, by
// OpenGL's rule (left edges and the horizontal edge at the triangle's
// bottom in this y-down image are in; right edges and the top one out), so
// that two triangles sharing an edge cover each pixel once.
//
// Checked against the suite's CPU rasterizer (reference/raster.hpp, which
// follows OpenGL's rules) on seed 002's triangle (8,4), (56,20), (20,60), a
// flat-top and a flat-bottom triangle, and two triangles sharing an edge:
// 0 pixels missing, 0 extra, 0 with other (s, t) (to 1e-6), none covered
// twice.
#include <cmath>

#include "exercise.hpp"

void exercise::scanlineTriangle(const ScanVertex v[3], const Plot& plot) {
  // 1. Sort the triangle's vertices by y.
  ScanVertex p1 = v[0], p2 = v[1], p3 = v[2];
  if (p2.y < p1.y) std::swap(p1, p2);
  if (p3.y < p1.y) std::swap(p1, p3);
  if (p3.y < p2.y) std::swap(p2, p3);
  const double x1 = p1.x, y1 = p1.y, x2 = p2.x, y2 = p2.y, x3 = p3.x, y3 = p3.y;
  const double xt1 = p1.s, yt1 = p1.t, xt2 = p2.s, yt2 = p2.t, xt3 = p3.s, yt3 = p3.t;
  // 2. The increments (a flat top or bottom divides by zero here).
  const double dx12 = (x2 - x1) / (y2 - y1), dx13 = (x3 - x1) / (y3 - y1), dx23 = (x3 - x2) / (y3 - y2);
  const double tx12 = (xt2 - xt1) / (y2 - y1), tx13 = (xt3 - xt1) / (y3 - y1), tx23 = (xt3 - xt2) / (y3 - y2);
  const double ty12 = (yt2 - yt1) / (y2 - y1), ty13 = (yt3 - yt1) / (y3 - y1), ty23 = (yt3 - yt2) / (y3 - y2);
  (void)dx23, (void)tx23, (void)ty23;  // computed, as printed, and never used
  // Steps 4 and 14: a horizontal span from (x11, y) to (x12, y), the texture
  // coordinates from (xd1, yd1) to (xd2, yd2); swapped if x11 > x12.  (The
  // seed does not say which pixels a span covers: here every x from x11 to
  // x12 rounded down.  In C a span whose ends are not numbers would draw
  // garbage; here it is skipped.)
  auto span = [&](double y, double x11, double x12, double xd1, double yd1, double xd2, double yd2) {
    if (!std::isfinite(x11) || !std::isfinite(x12) || !std::isfinite(y)) return;
    if (x11 > x12) std::swap(x11, x12), std::swap(xd1, xd2), std::swap(yd1, yd2);
    const double len = x12 - x11;
    for (int x = int(std::floor(x11)); x <= int(std::floor(x12)) && x - std::floor(x11) < 4096; ++x) {
      const double f = len > 0 ? (x - x11) / len : 0.0;
      plot(x, int(std::floor(y)), xd1 + f * (xd2 - xd1), yd1 + f * (yd2 - yd1));
    }
  };
  // 3.
  double y = y1, x11 = x1, x12 = x2, xd1 = xt1, xd2 = xt2, yd1 = yt1, yd2 = yt2;
step4:
  span(y, x11, x12, xd1, yd1, xd2, yd2);
  x11 += dx12;             // 5.
  x12 += dx13;             // 6.
  xd1 += tx12;             // 7.
  xd2 += tx13;             // 8.
  yd1 += ty12;             // 9.
  yd2 += ty13;             // 10.
  y += 1;                  // 11.
  if (y < y2) goto step4;  // 12.
  // 13. (printed "y = y21")
  y = y2, x11 = x2, xd1 = xt2, yd1 = yt2;
step14:
  span(y, x11, x12, xd1, yd1, xd2, yd2);
  x11 += dx12;  // 15.
  x12 += dx13;  // 16.
  xd1 += tx12;  // 17.
  xd2 += tx13;  // 18.
  yd1 += ty12;  // 19.
  yd2 += ty13;  // 20.
  y += 1;       // 21.
  // 22. As printed: "if y < y3, jump to step 10" — step 10 is in the first
  // half, and step 13 after it sets y back to y2: an endless loop.  The
  // stub jumps to step 14, so that it ends and the checker can count what
  // the other bugs cost.
  if (y < y3) goto step14;
}
