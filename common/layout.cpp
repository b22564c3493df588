#include "layout.hpp"

#include <cmath>
#include <cstdio>

#include "text.hpp"

namespace ts::layout {
Box labelBox(const Label& l) {
  // As Renderer::drawLabels places it: left edge and top truncated to whole pixels.
  float w = text::width(l.text, l.scale), h = text::height(l.scale);
  float x = l.align == Align::Left ? l.x : l.align == Align::Center ? l.x - w / 2 : l.x - w;
  x = float(int(x));
  float y = float(int(l.y));
  float pad = l.background.a > 0 ? 3.0f * float(l.scale) : 0.0f;
  return {x - pad, y - pad, x + w + pad, y + h + pad};
}

std::string fmt(const char* format, double v) {
  char b[128];
  std::snprintf(b, sizeof b, format, v);
  return b;
}
}  // namespace ts::layout
