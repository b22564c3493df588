#include "common/core/layout.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>

#include "common/core/error.hpp"
#include "common/core/text.hpp"

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

Frame blankFrame(int width, int height) {
  Frame f;
  f.width = width;
  f.height = height;
  f.clearColor = {0.12f, 0.12f, 0.14f, 1.0f};
  return f;
}

Batch unitSquare(int texture, const std::string& role, float s0, float s1) {
  Batch b;
  b.role = role;
  b.texture = texture;
  const glm::vec2 c[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i : {0, 1, 2, 0, 2, 3})
    b.vertices.push_back({{c[i], 0.0f}, {s0 + c[i].x * (s1 - s0), c[i].y, 0.0f, 1.0f}, {1, 1, 1, 1}});
  return b;
}

Panel unitPanel(const std::string& id, const Rect& viewport) {
  Panel p;
  p.id = id;
  p.viewport = viewport;
  p.projection = glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f);
  return p;
}

Panel texturePanel(const std::string& id, const Rect& viewport, int texture, const std::string& role, float s0,
                   float s1) {
  Panel p = unitPanel(id, viewport);
  p.batches.push_back(unitSquare(texture, role, s0, s1));
  return p;
}

Panel picturePanel(Frame& f, const std::string& id, const Rect& viewport, const TextureDesc& t) {
  Panel p = texturePanel(id, viewport, f.addTexture(t));
  if (t.renderedFrom)
    for (Vertex& v : p.batches.back().vertices) v.tex.y = 1.0f - v.tex.y;
  return p;
}

std::string fmt(const char* format, double v) {
  char b[128];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

int scaleFor(const Rect& picture, int maxScale) {
  return std::clamp(std::min(picture.w / 220, picture.h / 140), 1, std::max(1, maxScale));
}

int fitScale(const std::function<Rect(int)>& pictureAt, int maxScale) {
  for (int s = std::max(1, maxScale); s > 1; --s)
    if (scaleFor(pictureAt(s), maxScale) >= s) return s;
  return 1;
}

namespace {
// A word that is an operator alone ("=", "+", "-", "/", "<=", "..", ...): a
// formula's, which must not be broken beside it.
bool operatorWord(const std::string& w) { return !w.empty() && w.find_first_not_of("=+-*/<>~^.") == std::string::npos; }

// Words of `text` on lines no wider than `width` at `scale`; a word wider
// than the line stays alone on its line (the caller cuts it).  A formula
// stays on one line: the words either side of an operator word are glued
// to it ("c3 = (c0+2c1)/3" breaks before "c3" or after "/3", never inside).
std::vector<std::string> wrap(const std::string& text, int scale, float width) {
  std::vector<std::string> words, units;
  std::string word;
  for (char c : text) {
    if (c != ' ') word += c;
    else if (!word.empty()) words.push_back(word), word.clear();
  }
  if (!word.empty()) words.push_back(word);
  for (size_t k = 0; k < words.size(); ++k) {
    const bool glue = k > 0 && !units.empty() && (operatorWord(words[k]) || operatorWord(words[k - 1]));
    if (glue) units.back() += " " + words[k];
    else units.push_back(words[k]);
  }
  std::vector<std::string> lines;
  std::string line;
  for (const std::string& u : units) {
    // A word wider than the line with underscores in it (a GL name,
    // GL_NEAREST_MIPMAP_NEAREST) breaks after an underscore: on lines of
    // its own, as many parts to a line as fit, the last part going on with
    // the words after it.
    if (u.find(' ') == std::string::npos && u.find('_') + 1 < u.size() && text::width(u, scale) > width) {
      if (!line.empty()) lines.push_back(line), line.clear();
      for (size_t from = 0; from < u.size();) {
        const size_t end = std::min(u.find('_', from), u.size() - 1) + 1;  // a part, with its underscore
        const std::string part = u.substr(from, end - from);
        if (!line.empty() && text::width(line + part, scale) > width) lines.push_back(line), line.clear();
        line += part;
        from = end;
      }
      continue;
    }
    std::string joined = line.empty() ? u : line + " " + u;
    if (!line.empty() && text::width(joined, scale) > width) {
      lines.push_back(line);
      line = u;
    } else {
      line = joined;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string cut(std::string s, int scale, float width) {
  if (text::width(s, scale) <= width) return s;
  while (!s.empty() && text::width(s + "...", scale) > width) s.pop_back();
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s.empty() ? std::string() : s + "...";
}
// A key entry's meaning as legend() sets it in a band `width` wide at
// `scale`: one line when the entry fits, else wrapped at words onto lines
// beside its swatch (a narrow window's cell); none when a word does not
// fit even so (the entry is left out, never cut).
std::vector<std::string> entryLines(const LegendEntry& e, int scale, float width) {
  const float indent = text::height(scale) + 4.0f * float(scale);
  if (indent + text::width(e.meaning, scale) <= width) return {e.meaning};
  std::vector<std::string> lines = wrap(e.meaning, scale, width - indent);
  for (const std::string& l : lines)
    if (indent + text::width(l, scale) > width) return {};
  return lines;
}
}  // namespace

int captionLines(const std::string& text, int scale, float width) {
  // caption()'s test: a line is at most the band's width less one pixel.
  for (int s = std::max(1, scale); s >= 1; --s)
    if (text::width(text, s) <= width - 1) return 1;
  return int(wrap(text, 1, width - 1).size());
}

std::pair<Box, Box> stackApart(const Box& b, int scale, const std::string& lower) {
  const float lines = std::max(1.0f, std::round(b.h() / lineHeight(scale)));
  const float need = std::clamp(float(captionLines(lower, scale, b.w())), 1.0f, std::max(1.0f, lines - 1));
  const float mid = b.y0 + b.h() * (lines - need) / lines;
  return {{b.x0, b.y0, b.x1, mid}, {b.x0, mid, b.x1, b.y1}};
}

Text operator+(const Text& a, const Text& b) {
  Text out = a;
  out.text += b.text;
  out.printed.insert(out.printed.end(), b.printed.begin(), b.printed.end());
  out.given.insert(out.given.end(), b.given.begin(), b.given.end());
  return out;
}

namespace {
// A number is printed from a double, so its format must take one: "%d" given
// a double prints whatever the register holds, and the label would disagree
// with its sidecar.  Refused at render time rather than printed wrong.
std::string formatted(const char* format, double v) {
  const char* c = std::strchr(format, '%');
  while (c && c[1] == '%') c = std::strchr(c + 2, '%');
  if (c) {
    c = c + 1 + std::strspn(c + 1, "-+ #0123456789.");
    if (!*c || !std::strchr("fFeEgGaA", *c))
      throw Error(std::string("a label's number format '") + format + "' does not print a double (use %.0f, not %d)");
  }
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}
}  // namespace

Text measured(const Measurements& m, const std::string& name, const char* format) {
  for (const Measurement& x : m)
    if (x.name == name) {
      Text t(formatted(format, x.value));
      t.printed.push_back({name, format, t.text});
      return t;
    }
  // Before the first measurement ends (a window's first frames) every number
  // is still coming; once measured, a name the state lacks is a mistake.
  if (m.empty()) return Text("(measuring)");
  throw Error("a label prints the measurement '" + name + "', which this state does not measure");
}

Text measuredText(const Measurements& m, const std::string& templ) {
  Text out;
  size_t at = 0;
  while (at < templ.size()) {
    const size_t open = templ.find('{', at);
    if (open == std::string::npos) {
      out = out + Text(templ.substr(at));
      break;
    }
    const size_t close = templ.find('}', open);
    if (close == std::string::npos) throw Error("unbalanced braces in the label template \"" + templ + "\"");
    std::string name = templ.substr(open + 1, close - open - 1), format = "%g";
    const size_t bar = name.find('|');
    if (bar != std::string::npos) format = name.substr(bar + 1), name = name.substr(0, bar);
    out = out + Text(templ.substr(at, open - at)) + measured(m, name, format.c_str());
    at = close + 1;
  }
  return out;
}

Text measuredValue(const std::string& name, double value, const char* format) {
  Text t(formatted(format, value));
  t.printed.push_back({name, format, t.text});
  return t;
}

Text given(const std::string& name, double value, const char* format) {
  Text t(formatted(format, value));
  t.given.push_back({name, value, t.text});
  return t;
}

Label textLabel(float x, float y, const Text& t, glm::vec4 color, int scale, Align align, glm::vec4 background) {
  Label l{x, y, t.text, color, scale, align, background};
  l.printed = t.printed;
  for (const Text::Given& g : t.given) l.given.push_back({g.name, g.value});
  return l;
}

void refiningTag(Frame& f, const Rect& picture) {
  const std::string tag = "refining";
  if (text::width(tag, 1) + 6 > float(picture.w) || text::height(1) + 6 > float(picture.h)) return;
  f.labels.push_back(textLabel(float(picture.x + 3), float(picture.y + 3), tag, kAmber, 1, Align::Left,
                               glm::vec4(0.0f, 0.0f, 0.0f, 0.7f)));
}

void attachNumbers(Frame& f, size_t first, const Text& t) {
  // In order: a number goes to the first line at or after the previous
  // one's that shows it (wrapping breaks at spaces, never inside a number).
  std::vector<size_t> from(f.labels.size(), 0);  // where the next search starts in each line
  size_t line = first;
  auto place = [&](const std::string& text, const std::function<void(Label&)>& add) {
    for (size_t k = line; k < f.labels.size(); ++k) {
      const size_t at = f.labels[k].text.find(text, from[k]);
      if (at == std::string::npos) continue;
      add(f.labels[k]);
      from[k] = at + text.size();
      line = k;
      return;
    }
  };
  for (const Label::Printed& p : t.printed) place(p.text, [&](Label& l) { l.printed.push_back(p); });
  line = first;
  std::fill(from.begin(), from.end(), 0);
  for (const Text::Given& g : t.given) place(g.text, [&](Label& l) { l.given.push_back({g.name, g.value}); });
}

void addSwatch(Frame& f, float x, float y, int scale, glm::vec4 colour) {
  const int side = int(text::height(scale));
  Panel key = unitPanel("legend_swatch", {int(x), int(y), side, side});
  Batch fill;
  fill.role = "swatch";
  for (glm::vec2 q : {glm::vec2(0, 0), {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}})
    fill.vertices.push_back({{q, 0.0f}, {0, 0, 0, 1}, colour});
  key.batches.push_back(fill);
  f.panels.push_back(key);
}

float legend(Frame& f, Box band, const std::vector<LegendEntry>& entries, int scale) {
  // A swatch is a square panel of the colour, as tall as the text beside it.
  const float swatch = text::height(scale), gap = 8.0f * float(scale), row = lineHeight(scale);
  float x = band.x0, y = band.y0;
  for (const LegendEntry& e : entries) {
    // An entry wider than the band has its meaning wrapped beside its swatch, on lines of its own.
    const std::vector<std::string> lines = entryLines(e, scale, band.w());
    const float w = lines.size() == 1 ? swatch + 4.0f * float(scale) + text::width(e.meaning, scale) : band.w();
    if (x > band.x0 && x + w > band.x1) x = band.x0, y += row;
    const float last = y + row * float(int(lines.size()) - 1);
    if (lines.empty() || last + swatch > band.y1 + 0.5f) break;  // no room: left out, never cut
    addSwatch(f, x, y, scale, e.color);
    // The meaning in its colour, unless that colour is too dark to read on the figure's background.
    const float luma = 0.3f * e.color.r + 0.59f * e.color.g + 0.11f * e.color.b;
    for (size_t k = 0; k < lines.size(); ++k)
      f.labels.push_back({float(int(x)) + swatch + 4.0f * float(scale), y + row * float(k), lines[k],
                          luma < 0.35f ? kWhite : e.color, scale, Align::Left, glm::vec4(0.0f)});
    f.legend.push_back(e);
    y = last;
    x += w + gap;
  }
  return y + row;
}

namespace {
float plainCaption(Frame& f, Box band, const std::string& text, glm::vec4 color, int scale, Align align,
                   glm::vec4 background) {
  if (text.empty()) return band.y0;
  float pad = background.a > 0 ? 3.0f : 0.0f;  // the background box grows 3 px per scale each side
  auto place = [&](const std::vector<std::string>& lines, int s) {
    float p = pad * float(s), y = band.y0 + p;
    for (const std::string& l : lines) {
      float x = align == Align::Left ? band.x0 + p : align == Align::Right ? band.x1 - p : (band.x0 + band.x1) / 2;
      if (align == Align::Center) {
        // Whole pixels as the renderer places it, kept inside the band.
        float w = text::width(l, s);
        x = std::max(x, band.x0 + p + w / 2);
        x = std::min(x, band.x1 - p - w / 2);
      }
      f.labels.push_back({x, std::ceil(y), l, color, s, align, background});
      y += lineHeight(s) + 2 * p;  // boxed lines: their boxes must not overlap
    }
    return std::ceil(y) - float(4 * s) + p;
  };
  // One line, as large as fits (at most `scale`).
  for (int s = std::max(1, scale); s >= 1; --s) {
    float p = pad * float(s);
    if (text::width(text, s) + 2 * p <= band.w() - 1 && text::height(s) + 2 * p <= band.h()) return place({text}, s);
  }
  // Wrapped at scale 1 onto the lines the band has room for; the last cut.
  float p = pad;
  float width = band.w() - 1 - 2 * p;
  int room = int((band.h() + 4) / (lineHeight(1) + 2 * p));
  if (room < 1 || width < text::width("...", 1)) return band.y0;
  std::vector<std::string> lines = wrap(text, 1, width);
  if (int(lines.size()) > room) {
    std::string rest;
    for (size_t k = size_t(room) - 1; k < lines.size(); ++k) rest += (rest.empty() ? "" : " ") + lines[k];
    lines.resize(size_t(room));
    lines.back() = rest;  // cut below
  }
  for (auto& l : lines) l = cut(l, 1, width);
  return place(lines, 1);
}

}  // namespace

float caption(Frame& f, Box band, const Text& t, glm::vec4 color, int scale, Align align, glm::vec4 background) {
  const size_t first = f.labels.size();
  const float below = plainCaption(f, band, t.text, color, scale, align, background);
  attachNumbers(f, first, t);
  return below;
}

bool placeFree(Frame& f, Label l, Box within) {
  Box b = labelBox(l);
  if (l.text.empty() || b.w() > within.w() || b.h() > within.h()) return false;
  float dx = 0, dy = 0;
  if (b.x0 < within.x0) dx = std::ceil(within.x0 - b.x0);
  else if (b.x1 > within.x1) dx = -std::ceil(b.x1 - within.x1);
  if (b.y0 < within.y0) dy = std::ceil(within.y0 - b.y0);
  else if (b.y1 > within.y1) dy = -std::ceil(b.y1 - within.y1);
  l.x += dx;
  l.y += dy;
  b = labelBox(l);
  if (!b.inside(within)) return false;
  for (const Label& o : f.labels)
    if (!o.text.empty() && labelBox(o).overlaps(b)) return false;
  f.labels.push_back(l);
  return true;
}

float phrases(Frame& f, Box band, const std::vector<Text>& parts, glm::vec4 color, int scale, Align align) {
  Text all;
  for (const Text& p : parts) all = all.empty() ? p : all + " " + p;
  if (all.empty()) return band.y0;
  // As caption() does, largest scale first; a line breaks only between phrases.
  for (int s = std::max(1, scale); s >= 1; --s) {
    const float width = band.w() - 1;
    std::vector<Text> lines;
    bool fits = true;
    for (const Text& p : parts) {
      if (p.empty()) continue;
      fits = fits && text::width(p.text, s) <= width;
      if (!lines.empty() && text::width(lines.back().text + " " + p.text, s) <= width)
        lines.back() = lines.back() + " " + p;
      else lines.push_back(p);
    }
    if (!fits || float(lines.size()) * lineHeight(s) - float(4 * s) > band.h()) continue;
    float y = band.y0;
    for (const Text& l : lines)
      y = caption(f, {band.x0, y, band.x1, y + lineHeight(s)}, l, color, s, align) + float(4 * s);
    return y - float(4 * s);
  }
  return caption(f, band, all, color, scale, align);  // a phrase wider than the band: wrapped at its words
}

int legendLines(const std::vector<LegendEntry>& entries, int scale, float width) {
  if (entries.empty()) return 0;
  // As legend() places them: left to right, a new line when the next would not fit.
  const float swatch = text::height(scale), gap = 8.0f * float(scale);
  int lines = 1;
  float x = 0;
  for (const LegendEntry& e : entries) {
    const size_t n = std::max<size_t>(1, entryLines(e, scale, width).size());
    const float w = n == 1 ? swatch + 4.0f * float(scale) + text::width(e.meaning, scale) : width;
    if (x > 0 && x + w > width) x = 0, ++lines;
    lines += int(n) - 1;
    x += w + gap;
  }
  return lines;
}

float columnHeight(const std::vector<Text>& texts, int scale, float width) {
  float h = 0;
  // Each caption's lines, and the leading Column::add() puts after it: a line height a line.
  for (const Text& t : texts) h += float(captionLines(t.text, scale, width)) * lineHeight(scale);
  return h;
}

std::vector<Cell> pictureFigure(Frame& f, const std::vector<Captioned>& pictures,
                                const std::function<void(size_t, const Rect&)>& draw,
                                const std::vector<LegendEntry>& legend, const std::vector<Text>& notes, FlowSpec spec,
                                int minNoteLines, Align notesAlign, int extraCells) {
  const float width = float(f.width - 16);
  int lines = 0;
  for (const Text& n : notes) lines += captionLines(n.text, 1, width);
  const float band = lineHeight(1) * float(std::max(minNoteLines, lines)) + 8;
  const float key = legend.empty() ? 0 : lineHeight(1) * float(legendLines(legend, 1, width)) + 4;
  std::vector<Stack> above, below;
  for (const Captioned& p : pictures) above.push_back({p.title.text}), below.push_back({p.note.text});
  for (int k = 0; k < extraCells; ++k) above.push_back({""}), below.push_back({""});
  spec.n = int(above.size());
  const std::vector<Cell> cells = flowFitting({8, 8, float(f.width - 8), float(f.height) - 8 - band - key}, spec, above,
                                              below);
  for (size_t k = 0; k < pictures.size() && k < cells.size(); ++k) {
    draw(k, cells[k].picture);
    caption(f, cells[k].above, pictures[k].title, kWhite, cells[k].scale);
    caption(f, cells[k].below, pictures[k].note, kAmber, cells[k].scale);
  }
  if (!legend.empty())  // within the window: notes that fill a tiny window leave the key no room (left out)
    layout::legend(f, {8, std::max(8.0f, float(f.height) - band - key), float(f.width - 8), float(f.height) - band},
                   legend, 1);
  float y = float(f.height) - band;
  for (const Text& n : notes) {
    const float h = lineHeight(1) * float(captionLines(n.text, 1, width));
    caption(f, {8, y, float(f.width - 8), y + h}, n, kAmber, 1, notesAlign);
    y += h;
  }
  return cells;
}

bool Column::add(const Text& text, glm::vec4 color, int scale, Align align, glm::vec4 background) {
  if (y_ >= area_.y1) return false;
  Box band{area_.x0, y_, area_.x1, area_.y1};
  float y = caption(f_, band, text, color, scale, align, background);
  if (y <= y_) return false;
  y_ = y + 4.0f;
  return true;
}

namespace {
// The caption lines a cell's bands take (above, below) in an arrangement.
using Lines = std::pair<int, int>;
// flow() with each arrangement's caption lines from `lines(cell width, scale)`:
// cell k's (above, below).  Every row's bands are as tall as the tallest of
// all cells' (flow()'s even grid), or with `perRow` as its own cells' tallest.
std::vector<Cell> flowWith(Box area, const FlowSpec& spec,
                           const std::function<std::vector<Lines>(float width, int scale)>& lines,
                           bool perRow = false) {
  std::vector<Cell> best;
  double bestArea = -1;
  bool bestFits = false;
  const int n = std::max(1, spec.n);
  for (int rows = 1; rows <= n; ++rows) {
    int cols = (n + rows - 1) / rows;
    if ((rows - 1) * cols >= n) continue;  // an empty row
    // The scale is found with the picture: try large first, keep the first
    // whose picture asks for at least that scale.
    for (int s = std::max(1, spec.maxScale); s >= 1; --s) {
      float cw = (area.w() - float(cols - 1) * spec.gap) / float(cols);
      const std::vector<Lines> need = lines(cw, s);
      // Each row's band heights: its own cells' lines, or every cell's.
      std::vector<float> bandA(size_t(rows), 0), bandB(size_t(rows), 0);
      for (int k = 0; k < int(need.size()); ++k)  // (a cell k >= n is in no row: counted only without perRow)
        for (int r = 0; r < rows; ++r)
          if (!perRow || r == k / cols) {
            bandA[size_t(r)] = std::max(bandA[size_t(r)], float(need[size_t(k)].first) * lineHeight(s));
            bandB[size_t(r)] = std::max(bandB[size_t(r)], float(need[size_t(k)].second) * lineHeight(s));
          }
      float bands = 0;
      for (int r = 0; r < rows; ++r) bands += bandA[size_t(r)] + bandB[size_t(r)];
      float ch = (area.h() - float(rows - 1) * spec.gap) / float(rows);
      float ph = perRow ? (area.h() - float(rows - 1) * spec.gap - bands) / float(rows) : ch - bandA[0] - bandB[0];
      float pw = cw;
      if (pw < 1 || ph < 1) continue;
      if (pw / ph > spec.aspect) pw = ph * spec.aspect;
      else ph = pw / spec.aspect;
      Rect pic{0, 0, std::max(1, int(pw)), std::max(1, int(ph))};
      if (s > 1 && scaleFor(pic, spec.maxScale) < s) continue;
      double a = double(pic.w) * pic.h;
      bool fits = cw >= spec.minCellWidth;
      if (bestFits && !fits) break;
      if (fits == bestFits && a <= bestArea) break;
      bestArea = a;
      bestFits = fits;
      best.clear();
      // Centre the grid: the used width and height.
      float usedW = float(cols) * cw + float(cols - 1) * spec.gap;
      float cellH = bandA[0] + float(pic.h) + bandB[0];
      float usedH = perRow ? bands + float(rows) * float(pic.h) + float(rows - 1) * spec.gap
                           : float(rows) * cellH + float(rows - 1) * spec.gap;
      float y0 = area.y0 + (area.h() - usedH) / 2;
      std::vector<float> rowY(size_t(rows), y0);  // each row's top (perRow)
      for (int r = 1; r < rows; ++r)
        rowY[size_t(r)] = rowY[size_t(r - 1)] + bandA[size_t(r - 1)] + float(pic.h) + bandB[size_t(r - 1)] + spec.gap;
      for (int k = 0; k < n; ++k) {
        int r = k / cols, c = k % cols;
        int inRow = std::min(cols, n - r * cols);  // a short last row is centred too
        float x0 = area.x0 + (area.w() - usedW) / 2 + (float(cols - inRow) * (cw + spec.gap)) / 2 +
                   float(c) * (cw + spec.gap);
        float cy = perRow ? rowY[size_t(r)] : y0 + float(r) * (cellH + spec.gap);
        const float a0 = bandA[size_t(r)], b0 = bandB[size_t(r)];
        Cell cell;
        cell.scale = s;
        cell.picture = {int(std::lround(x0 + (cw - float(pic.w)) / 2)), int(std::lround(cy + a0)), pic.w, pic.h};
        cell.above = {x0, cy, x0 + cw, float(cell.picture.y)};
        cell.below = {x0, float(cell.picture.y + pic.h), x0 + cw, float(cell.picture.y + pic.h) + b0};
        best.push_back(cell);
      }
      break;
    }
  }
  if (best.empty())
    for (int k = 0; k < n; ++k) best.push_back({{int(area.x0), int(area.y0), 1, 1}, {}, {}, 1});
  return best;
}
}  // namespace

std::vector<Cell> flow(Box area, const FlowSpec& spec) {
  return flowWith(area, spec, [&](float, int) {
    return std::vector<Lines>(size_t(std::max(1, spec.n)), Lines{spec.linesAbove, spec.linesBelow});
  });
}

namespace {
// flowFitting's arrangements; keyLines(k, width): the lines cell k's key takes above its title.
std::vector<Cell> fitting(Box area, const FlowSpec& spec, const std::vector<Stack>& above,
                          const std::vector<Stack>& below, const std::function<int(size_t, float)>& keyLines,
                          int maxLines) {
  // Each arrangement with the lines its cells' width needs: a grid of wider cells may then give larger
  // pictures than a row of narrow ones whose captions wrap.  Cells too narrow for a caption's longest
  // word, or a formula's glued words (cut however many lines they had), are not an arrangement.
  constexpr int kNoRoom = 100000;
  auto unbreakable = [](const std::string& t, float width) {  // a word, or a formula's glued words, too wide
    for (const std::string& line : wrap(t, 1, width - 1))     // caption()'s width
      if (text::width(line, 1) > width - 1) return true;
    return false;
  };
  std::map<std::pair<float, int>, std::vector<Lines>> known;  // both flows try the same widths and scales
  auto lines = [&](float width, int scale) {
    const auto seen = known.find({width, scale});
    if (seen != known.end()) return seen->second;
    std::vector<Lines> out(std::max(above.size(), below.size()), Lines{spec.linesAbove, spec.linesBelow});
    auto need = [&](const std::string& t) { return unbreakable(t, width) ? kNoRoom : captionLines(t, scale, width); };
    for (size_t k = 0; k < out.size(); ++k) {
      int a = k < above.size() ? keyLines(k, width) : 0, b = 0;
      if (k < above.size())
        for (const std::string& t : above[k]) a = std::min(kNoRoom, a + need(t));
      if (k < below.size())
        for (const std::string& t : below[k]) b = std::min(kNoRoom, b + need(t));
      out[k].first = std::max(out[k].first, a >= kNoRoom ? kNoRoom : std::min(maxLines, a));
      out[k].second = std::max(out[k].second, b >= kNoRoom ? kNoRoom : std::min(maxLines, b));
    }
    known.emplace(std::pair{width, scale}, out);
    return out;
  };
  auto none = [](const std::vector<Cell>& c) {
    return c.empty() || (c.front().picture.w <= 1 && c.front().picture.h <= 1);
  };
  auto wide = [&](const std::vector<Cell>& c) { return !none(c) && c.front().above.w() >= spec.minCellWidth; };
  auto size = [](const std::vector<Cell>& c) {
    return c.empty() ? 0.0 : double(c.front().picture.w) * c.front().picture.h;
  };
  // An even grid: every row's bands as deep as the deepest cell's.  Rows of their own, each as deep as
  // its own cells need, when that gives larger pictures in cells wide enough (one cell's long note then
  // costs its row the lines, not every row; in a narrow window that can be most of the height), or
  // when the even grid has no room for the words at all; failing both, flow()'s, its captions cut
  // with "...".
  std::vector<Cell> cells = flowWith(area, spec, lines);
  std::vector<Cell> rows = flowWith(area, spec, lines, true);
  if ((wide(rows) && (!wide(cells) || size(rows) > size(cells))) || none(cells)) cells = std::move(rows);
  if (none(cells)) return flow(area, spec);
  return cells;
}
}  // namespace

std::vector<Cell> flowFitting(Box area, FlowSpec spec, const std::vector<Stack>& above, const std::vector<Stack>& below,
                              int keyLines, int maxLines) {
  return fitting(
      area, spec, above, below, [&](size_t, float) { return keyLines; }, maxLines);
}

std::vector<Cell> flowFitting(Box area, FlowSpec spec, const std::vector<Stack>& above, const std::vector<Stack>& below,
                              const std::vector<std::vector<LegendEntry>>& keys, int maxLines) {
  return fitting(
      area, spec, above, below,
      [&](size_t k, float width) { return k < keys.size() ? legendLines(keys[k], 1, width) : 0; }, maxLines);
}
}  // namespace ts::layout
