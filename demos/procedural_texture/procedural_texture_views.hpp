// demos/procedural_texture/procedural_texture_views.hpp — the demo's geometry as Frames (a sphere and a cube carved
// from the solid texture, a sphere wearing the 2D image, the marble plane, the terrain), the measurements made on
// their renders (the seam across the sphere's u = 0 meridian, the marble's period by autocorrelation), and the row
// of pictures each view's figure shows.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "common/core/layout.hpp"
#include "procedural_texture_math.hpp"
#include "procedural_texture_textures.hpp"

namespace ts::proc {
inline const glm::vec4 kSeamMark{0.2f, 0.9f, 1.0f, 1.0f};  // ticks at the u = 0 = 1 meridian
// The terrain's height ramp: the lowest, the middle (60% of the way up), the highest, times Lambert's cosine.
inline const glm::vec4 kLow{0.3f, 0.62f, 0.26f, 1.0f}, kMid{0.55f, 0.42f, 0.28f, 1.0f},
    kHigh{0.95f, 0.95f, 0.95f, 1.0f};

// ---- geometry ---------------------------------------------------------------------------------------------------
// The unit sphere, `slices` x `stacks`, longitude lambda from the +z axis (which faces the camera) towards +x:
//   p = (sin lambda cos phi, sin phi, cos lambda cos phi).
// solid: (s, t, r) = (p + 1) / 2, the surface point itself in the 3D texture (affine in p, so interpolating it
// across a flat triangle gives every pixel its own point: exact, no seam anywhere).
// wrapped: (s, t) = (lambda / 2 pi, (phi + pi/2) / pi), the 2D image's sphere mapping; the meridian lambda = 0 is
// sent twice, as u = 0 and as u = 1: the seam.
inline Batch sphereBatch(int texture, bool solid, int slices = 64, int stacks = 32) {
  const double kPi = 3.14159265358979323846;
  Batch b;
  b.role = solid ? "solid_sphere" : "wrapped_sphere";
  b.texture = texture;
  auto vertex = [&](int i, int j) {
    const double u = double(i) / slices, v = double(j) / stacks;
    const double lam = 2 * kPi * u, phi = kPi * (v - 0.5);
    const glm::vec3 p(float(std::sin(lam) * std::cos(phi)), float(std::sin(phi)), float(std::cos(lam) * std::cos(phi)));
    const glm::vec4 tex = solid ? glm::vec4((p + 1.0f) * 0.5f, 1.0f) : glm::vec4(float(u), float(v), 0, 1);
    return Vertex{p, tex, {1, 1, 1, 1}};
  };
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i)
      for (auto [di, dj] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}})
        b.vertices.push_back(vertex(i + di, j + dj));
  return b;
}
// The cube [-1, 1]^3 (its faces two triangles each), (s, t, r) = (p + 1) / 2 as the sphere's: the sphere's texture
// coordinates are the cube's where they meet, so both are carved from the same block.
inline Batch cubeBatch(int texture) {
  Batch b;
  b.role = "solid_cube";
  b.texture = texture;
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f}) {
      auto corner = [&](int a, int c) {
        glm::vec3 p(0);
        p[axis] = side, p[(axis + 1) % 3] = a ? 1.0f : -1.0f, p[(axis + 2) % 3] = c ? 1.0f : -1.0f;
        return Vertex{p, glm::vec4((p + 1.0f) * 0.5f, 1.0f), {1, 1, 1, 1}};
      };
      for (auto [a, c] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}) b.vertices.push_back(corner(a, c));
    }
  return b;
}
// A panel looking down -z at an object of radius `radius` (orthographic, square pixels), depth tested.
inline Panel objectPanel(const std::string& id, const Rect& viewport, const glm::mat4& modelview, float radius) {
  Panel p;
  p.id = id;
  p.viewport = viewport;
  const float a = float(viewport.w) / float(std::max(1, viewport.h));
  p.projection = a >= 1 ? glm::ortho(-radius * a, radius * a, -radius, radius, -4.0f, 4.0f)
                        : glm::ortho(-radius, radius, -radius / a, radius / a, -4.0f, 4.0f);
  p.modelview = modelview;
  p.depthTest = true;
  p.clear = true;
  p.clearColor = {0.06f, 0.06f, 0.08f, 1.0f};
  return p;
}
constexpr float kObjectRadius = 1.18f;  // the panel's half height: the sphere and the seam's ticks
// Ticks above and below the sphere on the meridian lambda = 0 (x = 0 facing the camera): where the seam is.
inline Batch seamTicks() {
  return lineSegments({{0, 1.03f}, {0, 1.16f}, {0, -1.03f}, {0, -1.16f}}, kSeamMark, 2.0f, "seam_ticks");
}
inline glm::mat4 cubeTurn() {
  return glm::rotate(glm::rotate(glm::mat4(1.0f), glm::radians(28.0f), glm::vec3(1, 0, 0)), glm::radians(-38.0f),
                     glm::vec3(0, 1, 0)) *
         glm::scale(glm::mat4(1.0f), glm::vec3(0.62f));
}

// The terrain as triangles, two a cell, each flat-shaded on the CPU (a height ramp times Lambert's cosine for a
// light from the upper left): the cells' edges, and so the depth, stay visible.  x, z in [-1, 1].
inline Batch terrainBatch(const HeightField& f, double H) {
  Batch b;
  b.role = "terrain";
  const int n = f.n;
  const double top = std::pow(double(1 << kTerrainMaxDepth), H);  // the corners' displacement's scale
  auto P = [&](int x, int y) { return glm::dvec3(2.0 * x / n - 1, 0.5 * f.at(x, y) / top, 2.0 * y / n - 1); };
  double lo = 1e30, hi = -1e30;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) lo = std::min(lo, P(x, y).y), hi = std::max(hi, P(x, y).y);
  const glm::dvec3 light = glm::normalize(glm::dvec3(-0.5, 0.8, 0.4));
  auto colour = [&](const glm::dvec3& a, const glm::dvec3& c, const glm::dvec3& d) {
    glm::dvec3 nrm = glm::normalize(glm::cross(d - a, c - a));
    if (nrm.y < 0) nrm = -nrm;
    const double hgt = hi > lo ? std::clamp(((a.y + c.y + d.y) / 3 - lo) / (hi - lo), 0.0, 1.0) : 0.5;
    const glm::dvec3 low{glm::vec3(kLow)}, mid{glm::vec3(kMid)}, high{glm::vec3(kHigh)};
    const glm::dvec3 ramp = hgt < 0.6 ? glm::mix(low, mid, hgt / 0.6) : glm::mix(mid, high, (hgt - 0.6) / 0.4);
    const double lit = 0.3 + 0.7 * std::max(0.0, glm::dot(nrm, light));
    return glm::vec4(glm::vec3(ramp * lit), 1.0f);
  };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const glm::dvec3 p00 = P(x, y), p10 = P(x + 1, y), p11 = P(x + 1, y + 1), p01 = P(x, y + 1);
      for (const auto& tri : {std::array<glm::dvec3, 3>{p00, p10, p11}, std::array<glm::dvec3, 3>{p00, p11, p01}}) {
        const glm::vec4 c = colour(tri[0], tri[1], tri[2]);
        for (const auto& q : tri) b.vertices.push_back({glm::vec3(q), {0, 0, 0, 1}, c});
      }
    }
  return b;
}
// The terrain seen from 2.8 x `distance` terrain half-widths away, 30 degrees from above.
inline Panel terrainPanel(const std::string& id, const Rect& viewport, double distance) {
  Panel p;
  p.id = id;
  p.viewport = viewport;
  p.projection = glm::perspective(glm::radians(30.0f), float(viewport.w) / float(std::max(1, viewport.h)), 0.1f,
                                  400.0f);
  const float d = float(2.8 * distance);
  p.modelview = glm::lookAt(glm::vec3(0, d * 0.5f, d * 0.866f), glm::vec3(0, -0.1f, 0), glm::vec3(0, 1, 0));
  p.depthTest = true;
  p.clear = true;
  p.clearColor = {0.35f, 0.5f, 0.7f, 1.0f};
  return p;
}
inline int triangles(const Panel& p) {
  int n = 0;
  for (const Batch& b : p.batches)
    if (b.role == "terrain") n += int(b.vertices.size()) / 3;
  return n;
}

// ---- measuring on renders ---------------------------------------------------------------------------------------
// The colour step across a vertical line of a picture: the mean, over the rows y0..y1, of the largest channel
// difference between the pixels at columns x - 2 and x + 1 (three apart, the line between x - 1 and x in the middle).
inline double stepAcross(const Image& img, int x, int y0, int y1) {
  double sum = 0;
  for (int y = y0; y <= y1; ++y) {
    const Rgba a = img.at(x - 2, y), b = img.at(x + 1, y);
    sum += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
  }
  return sum / (y1 - y0 + 1);
}
// The seam at the sphere's centre column (x = 0 between columns w/2 - 1 and w/2 of a panel of even width w), against
// the same step at columns `offsets` pixels either side (the noise's own change over three pixels): rows within
// 0.6 of the radius of the centre, where the meridian is nearly vertical.
struct Seam {
  double across = 0, control = 0;
  double excess() const { return across - control; }
};
constexpr int kSeamOffsets[] = {-24, -16, -8, 8, 16, 24};
inline Seam seamOf(const Image& img, const Rect& panel, float radius) {
  const int cx = panel.x + panel.w / 2, cy = panel.y + panel.h / 2;
  const int half = int(0.6 * panel.h / 2 / radius);
  Seam s;
  s.across = stepAcross(img, cx, cy - half, cy + half);
  for (int o : kSeamOffsets) s.control += stepAcross(img, cx + o, cy - half, cy + half);
  s.control /= double(std::size(kSeamOffsets));
  return s;
}
// The stripes' period along x (pixels): the autocorrelation of the red channel (a straight line of the marble
// value), A(l) = sum over rows and x of (R(x) - m)(R(x + l) - m), at its first maximum after its first negative
// lag, refined by a parabola through the maximum and its neighbours.  `r` is the picture's rectangle.
inline double stripePeriod(const Image& img, const Rect& r) {
  const int maxLag = r.w / 2;
  double mean = 0;
  for (int y = r.y; y < r.y + r.h; ++y)
    for (int x = r.x; x < r.x + r.w; ++x) mean += img.at(x, y).r;
  mean /= double(r.w) * r.h;
  std::vector<double> A(size_t(maxLag + 2), 0.0);
  for (int l = 0; l <= maxLag + 1; ++l) {
    double s = 0;
    for (int y = r.y; y < r.y + r.h; ++y)
      for (int x = r.x; x + l < r.x + r.w; ++x) s += (img.at(x, y).r - mean) * (img.at(x + l, y).r - mean);
    A[size_t(l)] = s / (double(r.w - l) * r.h);
  }
  int l = 1;
  while (l <= maxLag && A[size_t(l)] >= 0) ++l;
  while (l <= maxLag && !(A[size_t(l)] >= A[size_t(l - 1)] && A[size_t(l)] >= A[size_t(l + 1)] && A[size_t(l)] > 0))
    ++l;
  if (l > maxLag) return -1;
  const double a = A[size_t(l - 1)], b = A[size_t(l)], c = A[size_t(l + 1)];
  const double den = a - 2 * b + c;
  return l + (den != 0 ? 0.5 * (a - c) / den : 0.0);
}

// ---- the figures' row of pictures -----------------------------------------------------------------------------
namespace L = ts::layout;
struct Picture {
  std::function<void(Frame&, const Rect&)> draw;  // adds the picture's panel(s) at its rectangle
  L::Text title, note;
};
// The pictures side by side (or in a grid) above a legend and the numbers (layout::pictureFigure).
inline void pictureRow(Frame& f, const std::vector<Picture>& ps, const std::vector<LegendEntry>& legend,
                       const L::Text& numbers) {
  std::vector<L::Captioned> captions;
  for (const Picture& p : ps) captions.push_back({p.title, p.note});
  L::pictureFigure(
      f, captions,
      [&](size_t k, const Rect& cell) {
        Rect r = cell;
        r.w -= r.w % 2;  // even: the sphere's centre meridian lies between two columns
        ps[k].draw(f, r);
      },
      legend, {numbers}, {0, 1.0f, 1, 1, 10, 2, 150}, 2);
}
}  // namespace ts::proc
