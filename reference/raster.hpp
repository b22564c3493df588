// reference/raster.hpp — triangle rasterization on the CPU: the scanline
// algorithm of the lab sheet (seed 002), made to follow OpenGL's rules.
//
// Seed 002's algorithm: sort the vertices by y; compute the increments of x
// and of the texture coordinates per scanline along the edges 1-2, 1-3, 2-3;
// draw horizontal spans from the left edge to the right edge, interpolating
// the coordinates along the span; step every edge value by its increment;
// switch from edge 1-2 to edge 2-3 at the middle vertex.  Here:
//   * positions are window coordinates in the image's orientation (x right,
//     y down, pixel (i, j) covers [i, i+1) x [j, j+1), its centre is
//     (i + 1/2, j + 1/2)) — GL samples coverage and attributes at centres;
//   * a centre on an edge belongs to one triangle only: the top-left rule
//     (left edges and top horizontal edges in, right and bottom out).  "Top"
//     is GL's: window coordinates have y up, so FillRule::GLTopLeft takes
//     centres on a horizontal edge at the triangle's bottom in the image
//     (what llvmpipe does, tests/oracle/test_gl_sampling.cpp checks it);
//     FillRule::ImageTopLeft is the same rule with y down (Direct3D's);
//   * coverage is exact: positions are snapped to 1/256 pixel (llvmpipe's
//     sub-pixel grid) and each edge's x is stepped per scanline as an integer
//     numerator over the edge's height, from the edge's own upper vertex —
//     so triangles sharing edges or vertices cover each pixel exactly once,
//     also where centres lie exactly on edges or vertices;
//   * every attribute given is interpolated linearly in screen space (the
//     caller passes a/w and 1/w for hyperbolic interpolation and divides).
#pragma once
#include <array>
#include <functional>

namespace ref {
constexpr int kMaxAttributes = 16;

struct ScreenVertex {
  double x = 0, y = 0;  // pixels, image orientation
  std::array<double, kMaxAttributes> a{};
};

enum class FillRule { GLTopLeft, ImageTopLeft };

// Pixels whose centres are emitted: x in [x0, x1), y in [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Calls emit(x, y, attributes) for every pixel centre inside the triangle
// (in rows top to bottom, each row left to right).  Returns the number of
// pixels emitted.  Degenerate (zero-area) triangles emit nothing.
using Emit = std::function<void(int x, int y, const double* attributes)>;
long scanTriangle(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int attributes,
                  PixelRect clip, FillRule rule, const Emit& emit);

// Whether scanTriangle would emit pixel (x, y): the same exact test of the
// centre (x + 1/2, y + 1/2) with the same fill rule, for one pixel, without
// walking the triangle.
bool coversCentre(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int x, int y, FillRule rule);

// An attribute that is linear in screen space: value = a x + b y + c.
struct Plane {
  double a = 0, b = 0, c = 0;
  double at(double x, double y) const { return a * x + b * y + c; }
};
// The plane through three (x, y, value) points.  `ok` false if degenerate.
Plane planeThrough(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, int attribute, bool* ok);
}  // namespace ref
