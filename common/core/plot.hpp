// common/core/plot.hpp — the demos' one x-y plot, part of the layout kit
// (common/core/layout.hpp).  A demo describes its plot as data (a Spec: ranges,
// ticks, series, marker lines, legend, titles) and draw() lays it out in a
// rectangle: one panel whose projection is the data's own coordinates, with
// the background, grid, series and axes as batches, and the title, axis
// names, ticks, legend, tags and notes as labels.  Titles and axis names are
// fitted to their bands (shrunk, wrapped, cut); ticks, tags, notes and a
// legend that would overlap another label or leave the plot are left out.
// Used by perspective_correction, sphere_projections, mipmap_popping and
// jitter.
#pragma once
#include <glm/glm.hpp>

#include <string>
#include <utility>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/layout.hpp"

namespace ts::plot {
// A tick: where on its axis (data units) and what it says.  The grid's
// lines are drawn at the ticks.
struct Tick {
  double at = 0;
  std::string text;
};
// Ticks every `step` from lo to hi (inclusive), printed with `format`.
std::vector<Tick> ticks(double lo, double hi, double step, const char* format = "%g");
// 1, 2 or 5 times a power of ten, about range/6.
double niceStep(double range);

// How a series is drawn.  Marks have a size in pixels, whatever the scale
// of the data; none is a GL point (the sidecar must be able to redraw it).
enum class Mark {
  Line,     // a line strip through the points
  Crosses,  // an x of half-size `size` px on each point (two segments)
  Squares,  // a filled square of half-size `size` px (two triangles)
  Bars,     // a horizontal bar from x - halfWidth to x + halfWidth
  Rings,    // a 16-sided ring of radius `size` px
};
struct Series {
  Series() = default;
  Series(std::string r, glm::vec4 c, Mark m = Mark::Line, std::vector<glm::dvec2> pts = {}, float w = 2.0f,
         float sz = 5.0f)
      : role(std::move(r)), color(c), mark(m), points(std::move(pts)), width(w), size(sz) {}
  std::string role;  // the batch's role in the sidecar
  glm::vec4 color{1.0f};
  Mark mark = Mark::Line;
  std::vector<glm::dvec2> points;
  float width = 2.0f;              // line width (Line, Crosses, Bars, Rings)
  float size = 5.0f;               // half-size of a mark in pixels
  double halfWidth = 0;            // Bars, in data units
  std::vector<layout::Text> tags;  // text beside each point, where it fits
};
// A vertical line across the plot at x (dashed every 8 px, or solid), with
// an optional label at its top.
struct Marker {
  double x = 0;
  glm::vec4 color{0.85f, 0.85f, 0.85f, 1.0f};
  std::string role{};
  layout::Text label{};
  bool dashed = true;
  float width = 1.0f;
};
struct Legend {
  layout::Text text;
  glm::vec4 color{1.0f};
};
// Text beside a data point, boxed (it may cross a line), offset in pixels.
struct Note {
  glm::dvec2 at{0.0};
  layout::Text text;
  glm::vec2 offset{40.0f, -20.0f};
};

struct Spec {
  std::string id = "plot";
  layout::Text title, xLabel, yLabel;
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;  // the data range shown
  std::vector<Tick> xTicks, yTicks;
  std::vector<Series> series;
  std::vector<Marker> markers;
  std::vector<Legend> legend;  // one line each, above the plot
  bool legendInside = false;   // ... or right-aligned in its lower right
  std::vector<Note> notes;
  int scale = 1;  // of the text
  glm::vec4 titleColor{0.95f, 0.95f, 0.95f, 1.0f}, textColor{0.85f, 0.85f, 0.85f, 1.0f};
};

// Lays the plot out in `area` (frame pixels), appends its panel and labels,
// and returns the panel's viewport.
Rect draw(Frame& f, const Spec& s, Rect area);

// The tick labels of a plot panel `vp` whose data range is [x0, x1] x [y0, y1]:
// the x ticks under it, the y ticks left of it (right-aligned, centred on
// their value), all inside `area`; a tick that would overlap another label
// is left out.  (draw() places its ticks with it.)
void tickLabels(Frame& f, const Rect& vp, const Rect& area, double x0, double x1, double y0, double y1,
                const std::vector<Tick>& xs, const std::vector<Tick>& ys, glm::vec4 color, int scale = 1);
}  // namespace ts::plot
