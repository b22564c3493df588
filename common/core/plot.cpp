#include "common/core/plot.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

#include "common/core/layout.hpp"
#include "common/core/text.hpp"

namespace ts::plot {
namespace {
const glm::vec4 kBackground{0.17f, 0.17f, 0.2f, 1.0f}, kGrid{0.32f, 0.32f, 0.36f, 1.0f};

// One series as a batch in data units; (ux, uy) = data units per pixel.
Batch seriesBatch(const Series& s, double ux, double uy) {
  std::vector<glm::vec2> v;
  const float a = float(s.size * ux), b = float(s.size * uy);
  for (const glm::dvec2& q : s.points) {
    const float x = float(q.x), y = float(q.y);
    switch (s.mark) {
      case Mark::Line: v.push_back({x, y}); break;
      case Mark::Crosses: v.insert(v.end(), {{x - a, y - b}, {x + a, y + b}, {x - a, y + b}, {x + a, y - b}}); break;
      case Mark::Squares:
        v.insert(v.end(),
                 {{x - a, y - b}, {x + a, y - b}, {x + a, y + b}, {x - a, y - b}, {x + a, y + b}, {x - a, y + b}});
        break;
      case Mark::Bars: v.insert(v.end(), {{float(q.x - s.halfWidth), y}, {float(q.x + s.halfWidth), y}}); break;
      case Mark::Rings:
        for (int k = 0; k < 16; ++k)
          for (int e : {k, k + 1}) {
            const double t = 2 * 3.14159265358979 * e / 16;
            v.push_back({float(x + a * std::cos(t)), float(y + b * std::sin(t))});
          }
        break;
    }
  }
  Batch out = lineSegments(v, s.color, s.width, s.role);
  if (s.mark == Mark::Line) out.prim = Prim::LineStrip;
  if (s.mark == Mark::Squares) {
    out.prim = Prim::Triangles;
    out.lineWidth = 1.0f;
  }
  return out;
}
}  // namespace

std::vector<Tick> ticks(double lo, double hi, double step, const char* format) {
  std::vector<Tick> out;
  for (double v = lo; v <= hi + 1e-9 * std::max(1.0, std::abs(hi)); v += step)
    out.push_back({v, layout::fmt(format, v)});
  return out;
}

double niceStep(double range) {
  double raw = range / 6, p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (raw <= m * p) return m * p;
  return 10 * p;
}

void tickLabels(Frame& f, const Rect& vp, const Rect& area, double x0, double x1, double y0, double y1,
                const std::vector<Tick>& xs, const std::vector<Tick>& ys, glm::vec4 color, int scale) {
  namespace L = layout;
  const float h = text::height(scale), gap = 4.0f * float(scale);
  const L::Box under{float(area.x), float(vp.y + vp.h + 1), float(area.x + area.w), float(vp.y + vp.h) + gap + h + 2},
      leftOf{float(area.x), float(vp.y) - h, float(vp.x - 1), float(vp.y + vp.h) + h / 2 + 1};
  // A tick's number is the axis's, not a measurement: the label names it so.
  auto tick = [&](const Tick& t, const char* axis, float x, float y, Align a, const L::Box& within) {
    Label l{x, y, t.text, color, scale, a};
    l.given.push_back({std::string(axis) + " axis tick", t.at});
    L::placeFree(f, l, within);
  };
  for (const Tick& t : xs)
    tick(t, "x", float(vp.x + (t.at - x0) / (x1 - x0) * vp.w), float(vp.y + vp.h) + gap, Align::Center, under);
  for (const Tick& t : ys)
    tick(t, "y", float(vp.x) - gap - 2, float(vp.y + (1 - (t.at - y0) / (y1 - y0)) * vp.h) - h / 2, Align::Right,
         leftOf);
}

Rect draw(Frame& f, const Spec& s, Rect area) {
  namespace L = layout;
  const int sc = s.scale;
  const float line = L::lineHeight(sc), th = text::height(sc), gap = 4.0f * float(sc);
  const float x0 = float(area.x), x1 = float(area.x + area.w), y0 = float(area.y), y1 = float(area.y + area.h);

  // The bands around the plot: title, legend and the y axis's name above,
  // tick numbers left and below, the x axis's name at the bottom.
  const float titleH = s.title.empty() ? 0.0f
                                       : float(std::min(2, L::captionLines(s.title.text, sc, x1 - x0 - 8))) * line;
  float tickW = 0, lastX = 0;
  for (const Tick& t : s.yTicks) tickW = std::max(tickW, text::width(t.text, sc));
  if (!s.xTicks.empty()) lastX = text::width(s.xTicks.back().text, sc) / 2;
  // A legend line above the plot may wrap once when the plot is narrow.
  std::vector<float> legendLines;
  for (const Legend& l : s.legendInside ? std::vector<Legend>{} : s.legend)
    legendLines.push_back(float(std::min(2, L::captionLines(l.text.text, sc, x1 - 4 - (x0 + 4 + tickW + gap + 4)))) *
                          line);
  float legendH = 0;
  for (float h : legendLines) legendH += h;
  const int top = int(4 + titleH + legendH + (s.yLabel.empty() ? 0.0f : line) + th / 2 + 2);
  const int left = int(4 + tickW + gap + 4), right = int(std::max(line, lastX + 4));
  const int bottom = int(gap + th + 4 + (s.xLabel.empty() ? 0.0f : line + 2) + 2);
  Panel p;
  p.id = s.id;
  p.viewport = {area.x + left, area.y + top, std::max(1, area.w - left - right), std::max(1, area.h - top - bottom)};
  p.projection = glm::ortho(float(s.x0), float(s.x1), float(s.y0), float(s.y1), -1.0f, 1.0f);
  const Rect vp = p.viewport;
  const double ux = (s.x1 - s.x0) / vp.w, uy = (s.y1 - s.y0) / vp.h;
  auto px = [&](glm::dvec2 q) {
    return glm::vec2(float(vp.x + (q.x - s.x0) / (s.x1 - s.x0) * vp.w),
                     float(vp.y + (1 - (q.y - s.y0) / (s.y1 - s.y0)) * vp.h));
  };
  const float fx0 = float(s.x0), fx1 = float(s.x1), fy0 = float(s.y0), fy1 = float(s.y1);

  // The background as two triangles rather than Panel::clear, which the
  // sidecar JSON does not record (so the reference could not redraw it).
  Batch bg;
  bg.role = "background";
  for (glm::vec2 q : {glm::vec2(fx0, fy0), {fx1, fy0}, {fx1, fy1}, {fx0, fy0}, {fx1, fy1}, {fx0, fy1}})
    bg.vertices.push_back({{q, 0.0f}, {0, 0, 0, 1}, kBackground});
  p.batches.push_back(bg);
  std::vector<glm::vec2> g;
  const double ex = 1e-9 * (s.x1 - s.x0), ey = 1e-9 * (s.y1 - s.y0);
  for (const Tick& t : s.xTicks)
    if (t.at > s.x0 + ex && t.at < s.x1 - ex) g.insert(g.end(), {{float(t.at), fy0}, {float(t.at), fy1}});
  for (const Tick& t : s.yTicks)
    if (t.at > s.y0 + ey && t.at < s.y1 - ey) g.insert(g.end(), {{fx0, float(t.at)}, {fx1, float(t.at)}});
  p.batches.push_back(lineSegments(g, kGrid, 1.0f, "grid"));
  auto marker = [&](const Marker& m) {
    std::vector<glm::vec2> v;
    if (!m.dashed) v = {{float(m.x), fy0}, {float(m.x), fy1}};
    for (double y = s.y0; m.dashed && y < s.y1; y += 16 * uy)
      v.insert(v.end(), {{float(m.x), float(y)}, {float(m.x), float(std::min(s.y1, y + 8 * uy))}});
    p.batches.push_back(lineSegments(v, m.color, m.width, m.role));
  };
  for (const Marker& m : s.markers)
    if (m.dashed) marker(m);
  for (const Series& se : s.series)
    if (!se.points.empty()) p.batches.push_back(seriesBatch(se, ux, uy));
  for (const Marker& m : s.markers)
    if (!m.dashed) marker(m);
  p.batches.push_back(lineLoop({{fx0, fy0}, {fx1, fy0}, {fx1, fy1}, {fx0, fy1}}, s.textColor, 1.0f, "axes"));
  f.panels.push_back(p);

  // Labels, the essential first: title, legend, axis names, ticks; then the
  // marker labels, tags and notes where they fit.
  const L::Box inPlot = L::box(vp);
  float y = y0 + 4;
  if (!s.title.empty()) L::caption(f, {x0 + 4, y, x1 - 4, y + titleH}, s.title, s.titleColor, sc);
  y += titleH;
  for (size_t k = 0; k < legendLines.size(); ++k) {
    L::caption(f, {float(vp.x), y, x1 - 4, y + legendLines[k]}, s.legend[k].text, s.legend[k].color, sc, Align::Left);
    y += legendLines[k];
  }
  // The legend's lines are written in their series' colours: each is the key of its colour.
  for (const Legend& l : s.legend) f.legend.push_back({l.color, l.text.text});
  if (!s.yLabel.empty())
    L::caption(f, {float(vp.x), float(vp.y) - th / 2 - 2 - line, x1 - 4, float(vp.y) - th / 2 - 2}, s.yLabel,
               s.textColor, sc, Align::Left);
  if (!s.xLabel.empty())
    L::caption(f, {x0 + 4, float(vp.y + vp.h) + gap + th + 4, x1 - 4, y1 - 1}, s.xLabel, s.textColor, sc);
  tickLabels(f, vp, area, s.x0, s.x1, s.y0, s.y1, s.xTicks, s.yTicks, s.textColor, sc);
  if (s.legendInside) {
    float ly = float(vp.y + vp.h) - float(s.legend.size() + 1) * line;
    for (const Legend& l : s.legend) {
      L::placeFree(f, L::textLabel(float(vp.x + vp.w - 12), ly, l.text, l.color, sc, Align::Right), inPlot);
      ly += line;
    }
  }
  for (const Marker& m : s.markers)  // a marker's label, in its colour, is its key
    if (!m.label.empty() &&
        L::placeFree(f, L::textLabel(px({m.x, s.y1}).x + 6, float(vp.y + 6), m.label, m.color, sc), inPlot))
      f.legend.push_back({m.color, m.label.text});
  for (const Series& se : s.series)
    for (size_t k = 0; k < se.tags.size() && k < se.points.size(); ++k) {
      glm::vec2 q = px(se.points[k]);
      L::placeFree(f, L::textLabel(q.x + se.size + 3, q.y + 4, se.tags[k], se.color, sc), inPlot);
    }
  for (const Note& n : s.notes) {
    glm::vec2 q = px(n.at) + n.offset;
    L::placeFree(f, L::textLabel(q.x, q.y, n.text, s.textColor, sc, Align::Left, kBackground), inPlot);
  }
  return vp;
}
}  // namespace ts::plot
