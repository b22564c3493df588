// demos/perspective_correction/perspective_correction_math.hpp — the mathematics of Figure VI.2.
//
// A square of side 2, model coordinates (u, v, 0) with u, v in [-1, 1] and
// texture coordinates (s, t) = ((u + 1)/2, (v + 1)/2), is tilted back by
// `tilt` degrees about its horizontal axis (0 = facing the eye, 90 = edge-on;
// its top edge recedes) and its centre put `distance` in front of the eye,
// which looks at the centre down -z.  The eye coordinates of a point are
//     P(u, v) = C + u e1 + v e2,  C = (0, 0, -D),  e1 = (1, 0, 0),
//     e2 = (0, cos tilt, -sin tilt),  normal n = e1 x e2.
// The picture is framed by an off-centre frustum fitted around the square
// (framing is a 2D affine map of the screen, so it changes neither of the two
// interpolations below, only how big the square looks).
//
// Two ways to fill (s, t) into the projected square, drawn as two triangles
// (corners 0 1 2 and 0 2 3; corner 0 = (u, v) = (-1, -1), then
// counter-clockwise):
//   * hyperbolic (perspective-correct, Buss V.5): (s, t) of the point of the
//     plane seen through the pixel — a ray-plane intersection;
//   * affine: (s, t) interpolated linearly in screen space with the projected
//     triangle's barycentric coordinates.
// They agree at the vertices and differ inside by an amount that grows with
// how much the depth w varies over the polygon; the book's rule of thumb
// reads it from distances: it matters once d2 - d1 (farthest minus nearest
// distance from the eye to the polygon) is comparable to d1.
// Header-only so the demo and the tests share one copy.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace persp {
constexpr double kPi = 3.14159265358979323846;
// The checkerboard the figure maps: texels per side (errors are reported in
// these texels) and checks per side.
constexpr int kTexels = 256, kChecks = 8;

struct Setup {
  double tiltDeg = 60.0;
  double distance = 1.5;
};

inline const std::array<glm::dvec2, 4>& corners() {  // (u, v), counter-clockwise
  static const std::array<glm::dvec2, 4> k{glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)};
  return k;
}
inline glm::dvec2 texCoord(glm::dvec2 uv) { return (uv + 1.0) * 0.5; }

struct Frame3 {
  glm::dvec3 c, e1, e2, n;
};
inline Frame3 placement(const Setup& s) {
  double a = s.tiltDeg * kPi / 180.0;
  Frame3 f;
  f.c = {0, 0, -s.distance};
  f.e1 = {1, 0, 0};
  f.e2 = {0, std::cos(a), -std::sin(a)};
  f.n = glm::cross(f.e1, f.e2);
  return f;
}
inline glm::dvec3 eyePoint(const Setup& s, glm::dvec2 uv) {
  Frame3 f = placement(s);
  return f.c + uv.x * f.e1 + uv.y * f.e2;
}
// The modelview matrix: model (u, v, w) -> eye C + u e1 + v e2 + w n.
inline glm::dmat4 modelview(const Setup& s) {
  Frame3 f = placement(s);
  return glm::dmat4(glm::dvec4(f.e1, 0), glm::dvec4(f.e2, 0), glm::dvec4(f.n, 0), glm::dvec4(f.c, 1));
}

// d1, d2: nearest and farthest distance from the eye to the polygon.  The
// nearest point of a rectangle is the foot of the perpendicular from the eye
// clamped into the rectangle (in its own coordinates); the farthest is a
// corner.  w1, w2: smallest and largest depth (-z, GL's clip w) of a corner.
struct Distances {
  double d1 = 0, d2 = 0, w1 = 0, w2 = 0;
  double ratio() const { return (d2 - d1) / d1; }       // the book's (d2 - d1)/d1
  double depthRatio() const { return (w2 - w1) / w1; }  // what the interpolation sees
};
inline Distances distances(const Setup& s) {
  Frame3 f = placement(s);
  glm::dvec2 foot(std::clamp(-glm::dot(f.c, f.e1), -1.0, 1.0), std::clamp(-glm::dot(f.c, f.e2), -1.0, 1.0));
  Distances d;
  d.d1 = glm::length(eyePoint(s, foot));
  d.w1 = 1e300;
  for (const auto& uv : corners()) {
    glm::dvec3 p = eyePoint(s, uv);
    d.d2 = std::max(d.d2, glm::length(p));
    d.w1 = std::min(d.w1, -p.z);
    d.w2 = std::max(d.w2, -p.z);
  }
  return d;
}

// The frame's window on the image plane z = -1 (x/-z, y/-z): the projected
// square's bounding box, grown to the viewport's aspect (width / height) and
// by `margin` of its size on every side.
struct Window {
  double xmin, xmax, ymin, ymax;
};
inline Window bounds(const Setup& s) {  // the projected square's bounding box
  Window w{1e300, -1e300, 1e300, -1e300};
  for (const auto& uv : corners()) {
    glm::dvec3 p = eyePoint(s, uv);
    w.xmin = std::min(w.xmin, p.x / -p.z), w.xmax = std::max(w.xmax, p.x / -p.z);
    w.ymin = std::min(w.ymin, p.y / -p.z), w.ymax = std::max(w.ymax, p.y / -p.z);
  }
  return w;
}
inline double boundsAspect(const Setup& s) {
  Window w = bounds(s);
  return (w.xmax - w.xmin) / (w.ymax - w.ymin);
}
inline Window framing(const Setup& s, double aspect, double margin = 0.05) {
  Window w = bounds(s);
  double cx = (w.xmin + w.xmax) / 2, cy = (w.ymin + w.ymax) / 2;
  double hw = (w.xmax - w.xmin) / 2, hh = (w.ymax - w.ymin) / 2;
  if (hw < hh * aspect) hw = hh * aspect;
  else hh = hw / aspect;
  hw *= 1 + 2 * margin, hh *= 1 + 2 * margin;
  return {cx - hw, cx + hw, cy - hh, cy + hh};
}
// glFrustum of that window.  Near and far only bound the depth range (no
// depth test is used): half the nearest corner's depth, twice the farthest.
inline glm::dmat4 projection(const Setup& s, double aspect) {
  Window w = framing(s, aspect);
  Distances d = distances(s);
  double n = 0.5 * d.w1, f = 2.0 * d.w2;
  glm::dmat4 m(0.0);
  m[0][0] = 2 / (w.xmax - w.xmin);
  m[1][1] = 2 / (w.ymax - w.ymin);
  m[2][0] = (w.xmax + w.xmin) / (w.xmax - w.xmin);  // column 2: the x/z, y/z offsets
  m[2][1] = (w.ymax + w.ymin) / (w.ymax - w.ymin);
  m[2][2] = -(f + n) / (f - n);
  m[2][3] = -1;
  m[3][2] = -2 * f * n / (f - n);
  return m;  // = glFrustum(n xmin, n xmax, n ymin, n ymax, n, f)
}
// Everything a pixel's (s, t) needs, computed once per setup and viewport
// aspect (width / height).
struct View {
  Setup setup;
  double aspect = 1.0;
  Window window{};
  Frame3 frame{};
  glm::dmat4 proj{1.0}, mv{1.0};
  std::array<glm::dvec2, 4> screen{};  // the corners in NDC (x/w, y/w)
};
// A projection whose depth range runs from 0.01 to 1000: an orbited view
// can bring a corner nearer than the framing's near plane (half the nearest
// corner's depth); nothing here is depth-tested.
inline void widenDepthRange(glm::dmat4* proj) {
  const double n = 0.01, far = 1000;
  (*proj)[2][2] = -(far + n) / (far - n);
  (*proj)[3][2] = -2 * far * n / (far - n);
}

inline View makeView(const Setup& s, double aspect) {
  View v;
  v.setup = s;
  v.aspect = aspect;
  v.window = framing(s, aspect);
  v.frame = placement(s);
  v.proj = projection(s, aspect);
  v.mv = modelview(s);
  for (size_t k = 0; k < 4; ++k) {
    glm::dvec4 c = v.proj * v.mv * glm::dvec4(corners()[k], 0, 1);
    v.screen[k] = glm::dvec2(c) / c.w;
  }
  return v;
}
// Clip coordinates of a corner, and its normalised device coordinates
// (x/w, y/w, z/w): what the affine variant sends to GL with w = 1.
inline glm::dvec4 clip(const View& v, glm::dvec2 uv) { return v.proj * v.mv * glm::dvec4(uv, 0, 1); }
inline glm::dvec3 ndc(const View& v, glm::dvec2 uv) {
  glm::dvec4 c = clip(v, uv);
  return glm::dvec3(c) / c.w;
}

// Hyperbolic: the (s, t) of the plane point seen at NDC (x, y): the ray
// through the image-plane point q = (X, Y, -1) meets the plane at l q with
// l = (C . n) / (q . n).  The plane is unbounded: outside the square this
// is still the plane's (s, t).
inline glm::dvec2 perspectiveST(const View& v, glm::dvec2 xy) {
  const Window& w = v.window;
  const Frame3& f = v.frame;
  glm::dvec3 q(w.xmin + (xy.x + 1) / 2 * (w.xmax - w.xmin), w.ymin + (xy.y + 1) / 2 * (w.ymax - w.ymin), -1.0);
  glm::dvec3 p = glm::dot(f.c, f.n) / glm::dot(q, f.n) * q - f.c;
  return texCoord({glm::dot(p, f.e1), glm::dot(p, f.e2)});
}

inline double cross2(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }
// Affine: the projected triangle that holds (x, y) — corner 1's side of the
// diagonal 0-2 is triangle 0 1 2, the other side 0 2 3 — and (s, t)
// interpolated with its screen-space barycentric coordinates (extended
// linearly beyond the triangle).
inline glm::dvec2 affineST(const View& v, glm::dvec2 xy) {
  const auto& p = v.screen;
  bool first = (cross2(p[2] - p[0], xy - p[0]) > 0) == (cross2(p[2] - p[0], p[1] - p[0]) > 0);
  size_t a = 0, b = first ? 1 : 2, c = first ? 2 : 3;
  double area = cross2(p[b] - p[a], p[c] - p[a]);
  double lb = cross2(xy - p[a], p[c] - p[a]) / area, lc = cross2(p[b] - p[a], xy - p[a]) / area;
  glm::dvec2 ta = texCoord(corners()[a]), tb = texCoord(corners()[b]), tc = texCoord(corners()[c]);
  return ta + lb * (tb - ta) + lc * (tc - ta);
}

// Whether NDC (x, y) lies inside the projected square (convex,
// counter-clockwise on screen while the square faces the eye).
inline bool insideProjected(const View& v, glm::dvec2 xy) {
  for (size_t k = 0; k < 4; ++k)
    if (cross2(v.screen[(k + 1) % 4] - v.screen[k], xy - v.screen[k]) < 0) return false;
  return true;
}

// The affine image's error at a point, in texels of the checkerboard: how far
// the (s, t) it shows is from the perspective-correct one.
inline double affineErrorTexels(const View& v, glm::dvec2 xy) {
  return glm::length(affineST(v, xy) - perspectiveST(v, xy)) * kTexels;
}
// Its largest value over the pixel centres of an n x n render (aspect 1)
// that fall inside the projected square.
inline double maxAffineErrorTexels(const Setup& s, int n) {
  View v = makeView(s, 1.0);
  double worst = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      glm::dvec2 xy(2 * (x + 0.5) / n - 1, 1 - 2 * (y + 0.5) / n);
      if (insideProjected(v, xy)) worst = std::max(worst, affineErrorTexels(v, xy));
    }
  return worst;
}
}  // namespace persp
