// common/layout.hpp — the demos' one layout kit: where a figure's panels,
// captions and plots go in a rectangle of any size and aspect.
//
//   - panels flow in a row when the rectangle is wide and in a column when
//     it is tall (flow), each keeping its aspect;
//   - text scales with its panel, not the window (scaleFor);
//   - a caption shrinks, then wraps, then is cut with "..." rather than run
//     outside its box (fitText / caption);
//   - nothing is placed outside the rectangle it was given.
// The layout tests (tests/layout) read back the same boxes (labelBox) and
// check that no label leaves its panel or the window and no two overlap.
#pragma once
#include <string>
#include <vector>

#include "frame.hpp"

namespace ts::layout {
// A box in frame pixels, top-left origin, as floats (labels sit on halves).
struct Box {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  float w() const { return x1 - x0; }
  float h() const { return y1 - y0; }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  bool inside(const Box& o, float slack = 0) const {
    return x0 >= o.x0 - slack && y0 >= o.y0 - slack && x1 <= o.x1 + slack && y1 <= o.y1 + slack;
  }
};
inline Box box(const Rect& r) { return {float(r.x), float(r.y), float(r.x + r.w), float(r.y + r.h)}; }

// The pixels a label covers as common/render.cpp draws it (its text at its
// scale, placed by its alignment, plus the background box when it has one).
Box labelBox(const Label& l);

// printf of one number ("%.2f") into a std::string.
std::string fmt(const char* format, double v);
}  // namespace ts::layout
