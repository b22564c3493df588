// common/plot.hpp — a small x-y plot as Frame data, part of the layout kit
// (common/layout.hpp): one panel whose projection is the data's own
// coordinates, axes, grid and series as line batches, tick and axis labels
// as ts::Label.  Titles and axis names are fitted to their bands (shrunk,
// wrapped, cut); ticks, tags, notes and the legend that would overlap
// another label or leave the plot are left out.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/frame.hpp"
#include "common/layout.hpp"
#include "common/text.hpp"

namespace ts::plot {
struct Point {
  double x = 0, y = 0;
  double tag = 0;  // shown beside measured points (here: the tilt)
};
struct Data {
  std::string title, xLabel, yLabel, tagFormat = "%g";
  std::vector<Point> curve;     // analytic, drawn as a line
  std::vector<Point> measured;  // drawn as crosses, each with its tag
  Point current;                // the current state, a ring
  double xMarker = 1.0;         // a dashed vertical line (the rule of thumb)
  std::string xMarkerLabel = "d2 - d1 = d1";
  struct Note {
    Point at;
    std::string text;
  };
  std::vector<Note> notes;  // text beside a data point
};

// A tick: where on its axis (data units) and what it says.
struct Tick {
  double at = 0;
  std::string text;
};
// The tick labels of a plot panel `vp` whose data range is [x0, x1] x [y0, y1]:
// the x ticks under it, the y ticks left of it (right-aligned, centred on
// their value), all inside `area`; a tick that would overlap another label
// is left out.  The demos' plots share it (perspective_correction,
// sphere_projections, mipmap_popping, jitter).
inline void tickLabels(ts::Frame& f, const ts::Rect& vp, const ts::Rect& area, double x0, double x1, double y0, double y1,
                       const std::vector<Tick>& xs, const std::vector<Tick>& ys, glm::vec4 color, int scale = 1) {
  namespace L = ts::layout;
  const float h = ts::text::height(scale), gap = 4.0f * float(scale);
  const L::Box under{float(area.x), float(vp.y + vp.h + 1), float(area.x + area.w), float(vp.y + vp.h) + gap + h + 2},
      leftOf{float(area.x), float(vp.y) - h, float(vp.x - 1), float(vp.y + vp.h) + h / 2 + 1};
  for (const Tick& t : xs)
    L::placeFree(f, {float(vp.x + (t.at - x0) / (x1 - x0) * vp.w), float(vp.y + vp.h) + gap, t.text, color, scale,
                     ts::Align::Center},
                 under);
  for (const Tick& t : ys)
    L::placeFree(f, {float(vp.x) - gap - 2, float(vp.y + (1 - (t.at - y0) / (y1 - y0)) * vp.h) - h / 2, t.text, color, scale,
                     ts::Align::Right},
                 leftOf);
}

// 1, 2 or 5 times a power of ten, about range/6.
inline double niceStep(double range) {
  double raw = range / 6, p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (raw <= m * p) return m * p;
  return 10 * p;
}
inline std::string num(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// Lays the plot out in `area` (frame pixels) and appends its panel and labels.
inline void draw(ts::Frame& f, const Data& d, ts::Rect area) {
  const glm::vec4 axis{0.85f, 0.85f, 0.85f, 1.0f}, grid{0.32f, 0.32f, 0.36f, 1.0f}, curveC{0.35f, 0.7f, 1.0f, 1.0f},
      measuredC{1.0f, 0.75f, 0.3f, 1.0f}, currentC{1.0f, 0.3f, 0.3f, 1.0f}, white{0.95f, 0.95f, 0.95f, 1.0f},
      background{0.17f, 0.17f, 0.2f, 1.0f};
  const int line = int(ts::text::height(1)) + 6;
  double xmax = std::max(1.2, d.current.x), ymax = std::max(1.0, d.current.y);
  for (const auto* s : {&d.curve, &d.measured})
    for (const Point& p : *s) xmax = std::max(xmax, p.x), ymax = std::max(ymax, p.y);
  const double xs = niceStep(xmax * 1.05), ys = niceStep(ymax * 1.1);
  xmax = xs * std::ceil(xmax * 1.05 / xs), ymax = ys * std::ceil(ymax * 1.1 / ys);

  ts::Panel p;
  p.id = "plot";
  p.viewport = {area.x + 70, area.y + 3 * line, std::max(1, area.w - 100), std::max(1, area.h - 6 * line)};
  p.projection = glm::ortho(0.0f, float(xmax), 0.0f, float(ymax), -1.0f, 1.0f);
  const ts::Rect& vp = p.viewport;
  auto px = [&](double x, double y) {
    return glm::vec2(float(vp.x + x / xmax * vp.w), float(vp.y + (1 - y / ymax) * vp.h));
  };
  // Data units per pixel, for marks of a fixed size in pixels.
  const double ux = xmax / vp.w, uy = ymax / vp.h;

  // The plot's background as two triangles rather than Panel::clear, which
  // the sidecar JSON does not record (so the reference could not redraw it).
  ts::Batch bg;
  bg.role = "background";
  for (auto [x, y] : {std::pair{0.0, 0.0}, {xmax, 0.0}, {xmax, ymax}, {0.0, 0.0}, {xmax, ymax}, {0.0, ymax}})
    bg.vertices.push_back({{float(x), float(y), 0.0f}, {0, 0, 0, 1}, background});
  p.batches.push_back(bg);
  std::vector<glm::vec2> g;
  for (double x = xs; x < xmax - 1e-9; x += xs) g.insert(g.end(), {{float(x), 0.0f}, {float(x), float(ymax)}});
  for (double y = ys; y < ymax - 1e-9; y += ys) g.insert(g.end(), {{0.0f, float(y)}, {float(xmax), float(y)}});
  p.batches.push_back(ts::lineSegments(g, grid, 1.0f, "grid"));
  // The rule of thumb, dashed every 8 px.
  std::vector<glm::vec2> dash;
  for (double y = 0; y < ymax; y += 16 * uy)
    dash.insert(dash.end(), {{float(d.xMarker), float(y)}, {float(d.xMarker), float(std::min(ymax, y + 8 * uy))}});
  p.batches.push_back(ts::lineSegments(dash, axis, 1.0f, "rule_of_thumb"));
  std::vector<glm::vec2> c;
  for (const Point& q : d.curve) c.push_back({float(q.x), float(q.y)});
  ts::Batch cb = ts::lineSegments(c, curveC, 2.0f, "analytic");
  cb.prim = ts::Prim::LineStrip;
  p.batches.push_back(cb);
  std::vector<glm::vec2> m;
  for (const Point& q : d.measured) {
    const float a = float(5 * ux), b = float(5 * uy), x = float(q.x), y = float(q.y);
    m.insert(m.end(), {{x - a, y - b}, {x + a, y + b}, {x - a, y + b}, {x + a, y - b}});
  }
  if (!m.empty()) p.batches.push_back(ts::lineSegments(m, measuredC, 2.0f, "measured"));
  std::vector<glm::vec2> ring;
  for (int k = 0; k < 16; ++k) {
    double a = 2 * 3.14159265358979 * k / 16;
    ring.push_back({float(d.current.x + 8 * ux * std::cos(a)), float(d.current.y + 8 * uy * std::sin(a))});
  }
  p.batches.push_back(ts::lineLoop(ring, currentC, 2.0f, "current"));
  p.batches.push_back(ts::lineLoop({{0, 0}, {float(xmax), 0}, {float(xmax), float(ymax)}, {0, float(ymax)}}, axis,
                                   1.0f, "axes"));
  f.panels.push_back(p);

  // Labels, the essential first: title, axis names, ticks, legend; then the
  // tags and notes where they fit.
  namespace L = ts::layout;
  const L::Box all{float(area.x), float(area.y), float(area.x + area.w), float(area.y + area.h)}, inPlot = L::box(vp);
  L::caption(f, {all.x0 + 4, all.y0 + 4, all.x1 - 4, float(vp.y - line - 6)}, d.title, white, 1);
  L::caption(f, {all.x0 + 4, float(vp.y - line - 4), all.x1 - 4, float(vp.y - 1)}, d.yLabel, axis, 1,
             ts::Align::Left);
  L::caption(f, {all.x0 + 4, float(vp.y + vp.h + line + 4), all.x1 - 4, all.y1 - 1}, d.xLabel, axis, 1);
  std::vector<Tick> xt, yt;
  for (double x = 0; x <= xmax + 1e-9; x += xs) xt.push_back({x, num("%g", x)});
  for (double y = 0; y <= ymax + 1e-9; y += ys) yt.push_back({y, num("%g", y)});
  tickLabels(f, vp, area, 0, xmax, 0, ymax, xt, yt, axis);
  const float lx = float(vp.x + vp.w - 12), ly = float(vp.y + vp.h - 4 * line);
  L::placeFree(f, {lx, ly, "x  measured (texel-index render), tagged by tilt", measuredC, 1, ts::Align::Right}, inPlot);
  L::placeFree(f, {lx, ly + line, "-  analytic (ray-plane vs screen barycentrics)", curveC, 1, ts::Align::Right}, inPlot);
  L::placeFree(f, {lx, ly + 2 * line, "o  current state (" + num(d.tagFormat.c_str(), d.current.tag) + ")", currentC, 1,
                   ts::Align::Right},
               inPlot);
  L::placeFree(f, {px(d.xMarker, ymax).x + 6, float(vp.y + 6), d.xMarkerLabel, axis, 1, ts::Align::Left}, inPlot);
  for (const Point& q : d.measured)
    L::placeFree(f, {px(q.x, q.y).x + 8, px(q.x, q.y).y + 4, num(d.tagFormat.c_str(), q.tag), measuredC, 1,
                     ts::Align::Left},
                 inPlot);
  for (const auto& n : d.notes)  // boxed: it crosses the dashed line
    L::placeFree(f, {px(n.at.x, n.at.y).x + 40, px(n.at.x, n.at.y).y - 20, n.text, axis, 1, ts::Align::Left, background},
                 inPlot);
}
}  // namespace ts::plot
