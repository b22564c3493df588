// demos/octant_mapping/octant_mapping_views.hpp — the pieces of demos/octant_mapping's
// pictures: the octant in 3D, the 32 x 32 raster enlarged (pixels as flat
// quads of their intensity, so the sidecar holds every value), the pattern
// around a pixel's preimage, and text tables laid out in columns.  Pure
// description: no GL, no state but what the caller hands in.
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/mesh.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/core/text.hpp"
#include "octant_mapping_gl.hpp"
#include "octant_mapping_math.hpp"

namespace octant::views {
namespace L = ts::layout;
using L::Box;
const glm::vec4 kWhite = L::kWhite, kAmber = L::kAmber;
const glm::vec4 kRed{1.0f, 0.3f, 0.25f, 1.0f}, kCyan{0.3f, 0.85f, 1.0f, 1.0f}, kGreen{0.35f, 0.9f, 0.4f, 1.0f},
    kMagenta{1.0f, 0.35f, 0.95f, 1.0f}, kDim{0.62f, 0.62f, 0.68f, 1.0f};
// On the pattern (black lines on white): the pixel's quadrilateral, the
// rounded one, the curved preimage, the counted centres.
const glm::vec4 kQuad{0.95f, 0.1f, 0.1f, 1.0f}, kQuadRounded{1.0f, 0.55f, 0.0f, 1.0f}, kCurve{0.15f, 0.4f, 1.0f, 1.0f},
    kCounted{0.1f, 0.75f, 0.25f, 1.0f}, kFragmentEdge{0.25f, 0.55f, 0.75f, 1.0f};
// The axes of the octant's view: x, y, z.
const glm::vec4 kAxis[3] = {{1.0f, 0.35f, 0.35f, 1.0f}, {0.4f, 0.95f, 0.4f, 1.0f}, {0.45f, 0.6f, 1.0f, 1.0f}};
const glm::vec4 kNoValue{0.3f, 0.3f, 0.36f, 1.0f};  // a pixel on the octant without a value (its edge)
const glm::vec4 kPixelGrid{0.42f, 0.42f, 0.5f, 1.0f};

inline std::string fmt(const char* f, double v) { return L::fmt(f, v); }

// k·π/d reduced, as the seed writes angles: "pi/8", "7pi/16", "0"; "" when
// `x` is no multiple of π/1024.
inline std::string piFraction(double x) {
  const double k = x / kPi * 1024;
  if (std::fabs(k - std::round(k)) > 1e-7) return "";
  long n = std::lround(k), d = 1024;
  if (n == 0) return "0";
  const long g = std::gcd(std::labs(n), d);
  n /= g, d /= g;
  std::string s = (n == 1 ? "" : n == -1 ? "-" : std::to_string(n)) + "pi";
  return d == 1 ? s : s + "/" + std::to_string(d);
}
// 0.25 -> "1/4"; decimals when no sixty-fourth.
inline std::string fraction(double x) {
  const double k = x * 64;
  if (std::fabs(k - std::round(k)) > 1e-9) return fmt("%.3f", x);
  long n = std::lround(k), d = 64;
  if (n == 0) return "0";
  const long g = std::gcd(std::labs(n), d);
  n /= g, d /= g;
  return d == 1 ? std::to_string(n) : std::to_string(n) + "/" + std::to_string(d);
}

// --- the measurements the views print ----------------------------------------------
// measure() adds them for the state shown, named by that state (the table's
// u, the pixel, the level), so a view never prints another state's numbers.
namespace names {
inline std::string pixel(glm::ivec2 P) { return std::to_string(P.x) + "," + std::to_string(P.y); }
// "table_xyz[u=1/4,w=1/2].x": the point of the line u at w.
inline std::string tableXyz(double u, double w, int axis) {
  return "table_xyz[u=" + fraction(u) + ",w=" + fraction(w) + "]." + std::string(1, "xyz"[axis]);
}
inline std::string tableThetaDeg(double u) { return "table_theta_deg[u=" + fraction(u) + "]"; }
inline std::string tableMaxError(double u) { return "table_max_error[u=" + fraction(u) + "]"; }
// "catmull_line_texels[5,9,4]": of the fragment of level 4 holding pixel (5,9)'s centre.
inline std::string catmull(const std::string& what, glm::ivec2 P, int level) {
  return "catmull_" + what + "[" + pixel(P) + "," + std::to_string(level) + "]";
}
// "inverse_texels[21,15]", "inverse_texels[21,15,unrounded]".
inline std::string inverse(const std::string& what, glm::ivec2 P, const std::string& variant = "") {
  return "inverse_" + what + "[" + pixel(P) + (variant.empty() ? "" : "," + variant) + "]";
}
// "corner[22,15].x'": a value of the inverse example's table at a pixel corner.
inline std::string corner(glm::dvec2 c, const std::string& what) {
  return "corner[" + std::to_string(int(c.x)) + "," + std::to_string(int(c.y)) + "]." + what;
}
// The texel counted only with the rounded corners: how far its centre lies
// outside the unrounded quadrilateral and inside the rounded one.
inline std::string centreDepth(const std::string& which, glm::ivec2 P, glm::ivec2 t) {
  return "inverse_centre_" + which + "[" + pixel(P) + ";" + std::to_string(t.x) + "," + std::to_string(t.y) + "]";
}
}  // namespace names
// A measurement as printed, or "-" while the state shown is not measured
// yet (the window before its numbers arrive, the frame a click reads).
inline L::Text num(const ts::Measurements& m, const std::string& name, const char* format) {
  for (const ts::Measurement& x : m)
    if (x.name == name) return L::measured(m, name, format);
  return L::Text("-");
}
inline bool has(const ts::Measurements& m, const std::string& name) {
  for (const ts::Measurement& x : m)
    if (x.name == name) return true;
  return false;
}
// A pixel's coordinates as the inputs they are: "(21,15)".
inline L::Text pixelText(glm::ivec2 P) {
  return "(" + L::given("pixel Px", P.x, "%.0f") + "," + L::given("pixel Py (up from the bottom row)", P.y, "%.0f") +
         ")";
}
// The largest scale, at most `scale`, at which layout::legend() places
// every entry in `band` (its swatch, gap and wrapping reckoned the same way).
inline int keyScale(Box band, const std::vector<ts::LegendEntry>& entries, int scale) {
  for (int s = std::max(1, scale); s > 1; --s) {
    float x = band.x0, y = band.y0;
    bool fits = true;
    for (const ts::LegendEntry& e : entries) {
      const float w = ts::text::height(s) + 4.0f * float(s) + ts::text::width(e.meaning, s);
      if (x > band.x0 && x + w > band.x1) x = band.x0, y += L::lineHeight(s);
      if (w > band.w() || y + ts::text::height(s) > band.y1 + 0.5f) fits = false;
      x += w + 8.0f * float(s);
    }
    if (fits) return s;
  }
  return 1;
}
// A key whose entries name the pixel: its coordinates go in as the inputs they are.
inline void keyWithPixel(ts::Frame& f, Box band, const std::vector<ts::LegendEntry>& entries, int scale, glm::ivec2 P) {
  const size_t first = f.labels.size();
  L::legend(f, band, entries, keyScale(band, entries, scale));
  L::attachNumbers(f, first, pixelText(P));
}
// The pattern's grid lines, as the texel columns they are: "0 15 31 47 63".
inline L::Text gridLinesText() {
  L::Text t;
  for (int k : lineTexels()) t = t + (t.empty() ? "" : " ") + L::given("a grid line's texel column and row", k, "%.0f");
  return t;
}

// --- text tables -------------------------------------------------------------
struct Cell {
  L::Text text;  // its numbers say where they come from
  glm::vec4 colour = kWhite;
};
using Row = std::vector<Cell>;
// `rows` as columns (each as wide as its widest cell and two spaces) at the
// largest scale up to maxScale at which they fit `box`; at scale 1 the
// columns that do not fit are left out from the right, the rows from the
// bottom.  A row of one cell is a line of its own (cut with "..." when too
// long).  Returns the y below the last row placed.
inline size_t tableChars(const std::vector<Row>& rows, std::vector<size_t>* widthsOut = nullptr) {
  std::vector<size_t> widths;
  for (const Row& r : rows)
    if (r.size() > 1)
      for (size_t c = 0; c < r.size(); ++c) {
        if (widths.size() <= c) widths.push_back(0);
        widths[c] = std::max(widths[c], r[c].text.text.size() + 2);
      }
  size_t longest = 0;  // the widest multi-cell row, in characters
  for (const Row& r : rows)
    if (r.size() > 1) {
      size_t w = 0;
      for (size_t c = 0; c < r.size(); ++c) w += widths[c];
      longest = std::max(longest, w);
    }
  if (widthsOut) *widthsOut = widths;
  return longest;
}
// The scale table() takes in a box of this size.
inline int tableScale(const std::vector<Row>& rows, float width, float height, int maxScale) {
  const size_t longest = tableChars(rows);
  int s = std::max(1, maxScale);
  for (; s > 1; --s)
    if (float(longest) * ts::text::width("0", s) <= width && float(rows.size()) * L::lineHeight(s) <= height) break;
  return s;
}
inline float table(ts::Frame& f, Box box, const std::vector<Row>& rows, int maxScale) {
  if (rows.empty() || box.empty()) return box.y0;
  std::vector<size_t> widths;
  tableChars(rows, &widths);
  const int s = tableScale(rows, box.w(), box.h(), maxScale);
  const float cw = ts::text::width("0", s), lh = L::lineHeight(s);
  float y = box.y0;
  for (const Row& r : rows) {
    if (y + ts::text::height(s) > box.y1) break;
    if (r.size() == 1) {
      const float below = L::caption(f, {box.x0, y, box.x1, box.y1}, r[0].text, r[0].colour, s, ts::Align::Left);
      y = std::max(y + lh, below + float(4 * s));
      continue;
    } else {
      float x = box.x0;
      for (size_t c = 0; c < r.size(); ++c) {
        if (x + ts::text::width(r[c].text.text, s) > box.x1) break;
        if (!r[c].text.empty()) f.labels.push_back(L::textLabel(x, y, r[c].text, r[c].colour, s, ts::Align::Left));
        x += float(widths[c]) * cw;
      }
    }
    y += lh;
  }
  return y;
}

// --- shapes in a panel -----------------------------------------------------------
inline void quad(ts::Batch& b, glm::vec2 a, glm::vec2 c, glm::vec4 colour) {
  const glm::vec2 p[4] = {a, {c.x, a.y}, c, {a.x, c.y}};
  for (int k : {0, 1, 2, 0, 2, 3}) b.vertices.push_back({glm::vec3(p[k], 0.0f), {0, 0, 0, 1}, colour});
}
inline ts::Batch flat(const std::string& role) {
  ts::Batch b;
  b.role = role;
  b.prim = ts::Prim::Triangles;
  return b;
}
// The patch's boundary on the raster, in the raster panel's unit square.
inline std::vector<glm::vec2> outlineOnRaster(int steps = 24) {
  std::vector<glm::vec2> pts;
  const glm::dvec2 c[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < 4; ++k)
    for (int s = 0; s < steps; ++s) {
      const glm::dvec2 uw = c[k] + (c[(k + 1) % 4] - c[k]) * (double(s) / steps);
      pts.push_back(glm::vec2(glm::dvec2(projectUW(uw)) / double(kRaster)));
    }
  return pts;
}
// The line of the pattern from uw0 to uw1, projected onto the raster.
inline std::vector<glm::vec2> curveOnRaster(glm::dvec2 uw0, glm::dvec2 uw1, int steps) {
  std::vector<glm::vec2> pts;
  for (int s = 0; s <= steps; ++s)
    pts.push_back(glm::vec2(glm::dvec2(projectUW(uw0 + (uw1 - uw0) * (double(s) / steps))) / double(kRaster)));
  return pts;
}
// A polyline as GL_LINES segments.
inline void addPolyline(ts::Batch& b, const std::vector<glm::vec2>& pts, glm::vec4 colour, bool closed) {
  for (size_t k = 0; k + 1 < pts.size() + (closed ? 1 : 0); ++k) {
    b.vertices.push_back({glm::vec3(pts[k], 0.0f), {0, 0, 0, 1}, colour});
    b.vertices.push_back({glm::vec3(pts[(k + 1) % pts.size()], 0.0f), {0, 0, 0, 1}, colour});
  }
}

// The 32 x 32 raster: each pixel with a value drawn as a flat quad of grey
// 1 - value (a line is black, as in the seed's figures), the pixels on the
// octant without one dim, the pixel grid, the patch's outline, and `pick`
// outlined in red (none when pick.x < 0).
// The part of the raster the octant covers (Px 4.7..27.3, Py 6.8..20.7), 3:2.
const glm::ivec4 kOctantWindow{4, 6, 28, 22};
inline ts::Panel rasterPanel(const std::string& id, const ts::Rect& vp, const std::vector<double>& values,
                             glm::ivec2 pick, glm::ivec4 window = {0, 0, kRaster, kRaster}) {
  ts::Panel p = L::unitPanel(id, vp);
  p.projection = glm::ortho(float(window.x) / kRaster, float(window.z) / kRaster, float(window.y) / kRaster,
                            float(window.w) / kRaster, -1.0f, 1.0f);
  ts::Batch px = flat("pixels");
  const Raster& r = raster();
  const float n = float(kRaster);
  for (int Py = 0; Py < kRaster; ++Py)
    for (int Px = 0; Px < kRaster; ++Px) {
      const size_t k = size_t(pixelIndex(Px, Py));
      const double v = values.empty() ? std::nan("") : values[k];
      glm::vec4 c;
      if (std::isfinite(v)) {
        const float g = float(1.0 - std::clamp(v, 0.0, 1.0));
        c = {g, g, g, 1.0f};
      } else if (r.centreOnPatch[k]) {
        c = kNoValue;
      } else {
        continue;
      }
      quad(px, {Px / n, Py / n}, {(Px + 1) / n, (Py + 1) / n}, c);
    }
  if (!px.vertices.empty()) p.batches.push_back(px);
  std::vector<glm::vec2> grid;
  for (int k = 0; k <= kRaster; ++k) {
    grid.push_back({k / n, 0.0f}), grid.push_back({k / n, 1.0f});
    grid.push_back({0.0f, k / n}), grid.push_back({1.0f, k / n});
  }
  p.batches.push_back(ts::lineSegments(grid, kPixelGrid, 1.0f, "pixel_grid"));
  ts::Batch outline = ts::lineSegments({}, kAmber, 2.0f, "octant_outline");
  addPolyline(outline, outlineOnRaster(), kAmber, true);
  p.batches.push_back(outline);
  if (pick.x >= 0)
    p.batches.push_back(ts::lineLoop({{pick.x / n, pick.y / n},
                                      {(pick.x + 1) / n, pick.y / n},
                                      {(pick.x + 1) / n, (pick.y + 1) / n},
                                      {pick.x / n, (pick.y + 1) / n}},
                                     kRed, 3.0f, "pixel"));
  return p;
}
// The raster pixel under frame point (x, y) of a raster panel, or (-1, -1).
inline glm::ivec2 pixelAt(const ts::Panel& p, int x, int y) {
  const ts::Rect& v = p.viewport;
  if (!v.contains(x, y) || v.w <= 0 || v.h <= 0) return {-1, -1};
  const glm::vec4 ndc(2.0f * (float(x) + 0.5f - float(v.x)) / float(v.w) - 1.0f,
                      1.0f - 2.0f * (float(y) + 0.5f - float(v.y)) / float(v.h), 0.0f, 1.0f);
  const glm::vec4 unit = glm::inverse(p.projection) * ndc;  // the raster's unit square
  const int Px = int(std::floor(unit.x * kRaster)), Py = int(std::floor(unit.y * kRaster));
  if (Px < 0 || Py < 0 || Px >= kRaster || Py >= kRaster) return {-1, -1};
  return {Px, Py};
}

// The pattern (texture `tex`) seen through the window [lo, hi] (texel units,
// square), with the texel grid when there is room to see it.
inline ts::Panel patternPanel(const std::string& id, const ts::Rect& vp, int tex, glm::dvec2 lo, glm::dvec2 hi) {
  ts::Panel p = L::unitPanel(id, vp);
  const glm::dvec2 a = lo / double(kTexels), b = hi / double(kTexels);
  p.projection = glm::ortho(float(a.x), float(b.x), float(a.y), float(b.y), -1.0f, 1.0f);
  p.batches.push_back(L::unitSquare(tex, "pattern"));
  if (hi.x - lo.x <= 24 && vp.w >= 3 * (hi.x - lo.x)) {
    std::vector<glm::vec2> grid;
    for (int k = int(std::floor(lo.x)); k <= int(std::ceil(hi.x)); ++k)
      grid.push_back({k / float(kTexels), float(a.y)}), grid.push_back({k / float(kTexels), float(b.y)});
    for (int k = int(std::floor(lo.y)); k <= int(std::ceil(hi.y)); ++k)
      grid.push_back({float(a.x), k / float(kTexels)}), grid.push_back({float(b.x), k / float(kTexels)});
    p.batches.push_back(ts::lineSegments(grid, {0.6f, 0.6f, 0.68f, 1.0f}, 1.0f, "texel_grid"));
  }
  return p;
}
// A square window round texel-unit points, at least `minSide` texels, kept
// inside the pattern where it can be.
inline std::pair<glm::dvec2, glm::dvec2> windowAround(const std::vector<glm::dvec2>& pts, double minSide,
                                                      double margin) {
  glm::dvec2 lo(1e9), hi(-1e9);
  for (const auto& q : pts) lo = glm::min(lo, q), hi = glm::max(hi, q);
  const glm::dvec2 c = (lo + hi) * 0.5;
  const double side = std::min(double(kTexels), std::max(minSide, std::max(hi.x - lo.x, hi.y - lo.y) + 2 * margin));
  glm::dvec2 a = c - side / 2;
  a = glm::clamp(a, glm::dvec2(0.0), glm::dvec2(kTexels - side));
  a = glm::floor(a * 2.0) / 2.0;  // on half texels: the grid lines stay put
  return {a, a + side};
}
// Texel-unit points as a closed line in a pattern panel (unit square = the pattern).
inline ts::Batch loopInPattern(const std::vector<glm::dvec2>& texelPts, glm::vec4 colour, float width,
                               const std::string& role) {
  std::vector<glm::vec2> pts;
  for (const auto& q : texelPts) pts.push_back(glm::vec2(q / double(kTexels)));
  return ts::lineLoop(pts, colour, width, role);
}
// The same loop dashed: `dash` texels drawn, `dash` left out, along each
// edge, so a line lying on another shows both.
inline ts::Batch dashedLoopInPattern(const std::vector<glm::dvec2>& texelPts, glm::vec4 colour, float width,
                                     double dash, const std::string& role) {
  std::vector<glm::vec2> pts;
  for (size_t k = 0; k < texelPts.size(); ++k) {
    const glm::dvec2 a = texelPts[k], b = texelPts[(k + 1) % texelPts.size()];
    const double len = glm::length(b - a);
    for (double t = 0; t < len; t += 2 * dash) {
      const double e = std::min(len, t + dash);
      pts.push_back(glm::vec2((a + (b - a) * (t / len)) / double(kTexels)));
      pts.push_back(glm::vec2((a + (b - a) * (e / len)) / double(kTexels)));
    }
  }
  return ts::lineSegments(pts, colour, width, role);
}
// Texel centres marked by small squares (0.36 texel a side).
inline ts::Batch centreMarks(const std::vector<glm::ivec2>& texels, glm::vec4 colour, const std::string& role) {
  ts::Batch b = flat(role);
  const float h = 0.18f / kTexels;
  for (const auto& t : texels) {
    const glm::vec2 c((t.x + 0.5f) / kTexels, (t.y + 0.5f) / kTexels);
    quad(b, c - h, c + h, colour);
  }
  return b;
}

// --- the octant in 3D ----------------------------------------------------------------
// Orthographic, the seed's view (Rx(35°) Ry(-45°)) turned by the orbit about
// the patch's centre, the pattern mapped (lit from the eye), the axes, the
// patch's edges; the caller adds curves on the surface (onSurface()).
inline ts::Panel octantPanel(const ts::Rect& vp, int tex, const ts::OrbitCamera& camera) {
  ts::Panel p;
  p.id = "octant";
  p.viewport = vp;
  const float a = float(vp.w) / float(std::max(1, vp.h)), e = 1.05f;
  p.projection = a >= 1 ? glm::ortho(-e * a, e * a, -e, e, -10.0f, 10.0f)
                        : glm::ortho(-e, e, -e / a, e / a, -10.0f, 10.0f);
  p.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.24f, 0.0f)) * viewMatrix();
  camera.apply(p, glm::vec3(surfaceUW({0.5, 0.5})));
  p.depthTest = true;
  const glm::dvec3 toLight = glm::dvec3(glm::inverse(glm::mat3(p.modelview)) * glm::vec3(-0.3f, 0.4f, 1.0f));
  p.batches.push_back(ts::litMeshBatch(mesh(kPictureMesh), tex, toLight, 0.55, 0.45, "octant"));
  const glm::vec4* axis = kAxis;
  for (int k = 0; k < 3; ++k) {
    ts::Batch b = ts::lineSegments({}, axis[k], 2.0f, std::string("axis_") + "xyz"[k]);
    glm::vec3 tip(0.0f);
    tip[k] = 1.2f;
    b.vertices.push_back({glm::vec3(0.0f), {0, 0, 0, 1}, axis[k]});
    b.vertices.push_back({tip, {0, 0, 0, 1}, axis[k]});
    p.batches.push_back(b);
  }
  return p;
}
// Points of the pattern (u, w) on the surface, lifted 0.4% off it so the
// depth test keeps them above their own triangles.
inline ts::Batch onSurface(const std::vector<glm::dvec2>& uws, glm::vec4 colour, float width, bool closed,
                           const std::string& role) {
  ts::Batch b = ts::lineSegments({}, colour, width, role);
  for (size_t k = 0; k + 1 < uws.size() + (closed ? 1 : 0); ++k)
    for (size_t e : {k, (k + 1) % uws.size()})
      b.vertices.push_back({glm::vec3(surfaceUW(uws[e]) * 1.004), {0, 0, 0, 1}, colour});
  return b;
}
// The axes' names at their tips, inside the panel where they fit.
inline void axisLabels(ts::Frame& f, const ts::Panel& p, int scale) {
  for (int k = 0; k < 3; ++k) {
    glm::vec4 tip(0.0f, 0.0f, 0.0f, 1.0f);
    tip[k] = 1.28f;
    const glm::vec2 q = ts::panelToPixels(p, p.projection * p.modelview * tip);
    L::placeFree(f, {q.x, q.y - 6.0f * scale, std::string(1, "xyz"[k]), kWhite, scale, ts::Align::Center},
                 L::box(p.viewport));
  }
}
// The patch's four edges on the surface.
inline ts::Batch patchEdges() {
  std::vector<glm::dvec2> pts;
  const glm::dvec2 c[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < 4; ++k)
    for (int s = 0; s < 24; ++s) pts.push_back(c[k] + (c[(k + 1) % 4] - c[k]) * (s / 24.0));
  return onSurface(pts, kAmber, 2.0f, true, "patch_edges");
}
// A pixel's curved preimage, on the surface (empty when off the sphere).
inline std::vector<glm::dvec2> pixelPreimageUW(glm::ivec2 P, int stepsPerSide = 8) {
  std::vector<glm::dvec2> out;
  const auto c = pixelCorners(P.x, P.y);
  for (int k = 0; k < 4; ++k)
    for (int s = 0; s < stepsPerSide; ++s) {
      auto b = backOfPixelPoint(c[size_t(k)] + (c[size_t((k + 1) % 4)] - c[size_t(k)]) * (double(s) / stepsPerSide));
      if (!b) return {};
      out.push_back(b->uw);
    }
  return out;
}
}  // namespace octant::views
