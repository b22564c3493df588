// common/core/layout.hpp — the demos' one layout kit: where a figure's panels,
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
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/scene.hpp"
#include "common/core/text.hpp"

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

// The pixels a label covers as common/gl/render.cpp draws it (its text at its
// scale, placed by its alignment, plus the background box when it has one).
Box labelBox(const Label& l);

// The demos' shared text colours: captions, and measured values / the current state.
inline const glm::vec4 kWhite{0.95f, 0.95f, 0.95f, 1.0f}, kAmber{1.0f, 0.75f, 0.3f, 1.0f};

// An empty frame of this size on the demos' shared background.
Frame blankFrame(int width, int height);

// A texture on the unit square (s, t from 0 to 1 across and up; s from s0 to
// s1 when a panel shows a part): the batch, and a panel `id` at `viewport`
// showing only it (a texture-space view, a rendered image).
Batch unitSquare(int texture, const std::string& role, float s0 = 0.0f, float s1 = 1.0f);
Panel texturePanel(const std::string& id, const Rect& viewport, int texture, const std::string& role = "image",
                   float s0 = 0.0f, float s1 = 1.0f);
// The texturePanel of `t`, added to `f`.  A nested frame's picture
// (TextureDesc::renderedFrom) is its readback, row 0 at the top: t runs down
// it, so the picture stands upright.
Panel picturePanel(Frame& f, const std::string& id, const Rect& viewport, const TextureDesc& t);
// An empty panel `id` at `viewport` that shows the unit square (x, y from 0
// to 1 across and up): what texturePanel starts from, and the flat figures'
// panels (a quad in screen space, a lit plane).
Panel unitPanel(const std::string& id, const Rect& viewport);

// A w x h picture centred in `r` (whole pixels, as the demos place a square
// texture view inside a cell sized for a wider picture).
inline Rect centred(const Rect& r, int w, int h) { return {r.x + (r.w - w) / 2, r.y + (r.h - h) / 2, w, h}; }
// A two-line caption band cut into its upper and lower line (a title above a
// formula, an equation above its text).
inline std::pair<Box, Box> halves(const Box& b) {
  const float mid = b.y0 + b.h() / 2;
  return {{b.x0, b.y0, b.x1, mid}, {b.x0, mid, b.x1, b.y1}};
}

// printf of one number ("%.2f") into a std::string.
std::string fmt(const char* format, double v);

// The text scale for captions of a picture this size: grows with the
// picture, never with the window (1 below ~220 x 140 pixels).
int scaleFor(const Rect& picture, int maxScale = 3);
// One line of text's height at a scale, with its leading.
inline float lineHeight(int scale) { return text::height(scale) + float(4 * scale); }
// The text scale of a layout whose picture depends on the room its text
// takes: the largest s (maxScale down to 1) for which the picture laid out
// with text at s, pictureAt(s), asks for at least s (scaleFor).  For views
// that place their pictures themselves (whole zooms, fixed grids) and
// still want their text to grow with the pictures, as flow() does.
int fitScale(const std::function<Rect(int scale)>& pictureAt, int maxScale = 3);

// n pictures of one aspect (width / height) in `area`: in a row when the
// area is wide, in a column when it is tall (or a grid, whichever gives the
// largest pictures), centred, `gap` apart, each with bands for `above` and
// `below` lines of captions at the cell's scale (which is scaleFor(picture),
// at most maxScale).
struct Cell {
  Rect picture;
  Box above, below;  // the caption bands, as wide as the cell
  int scale = 1;
};
struct FlowSpec {
  int n = 1;
  float aspect = 1.0f;
  int linesAbove = 1, linesBelow = 1;
  int gap = 12;
  int maxScale = 3;
  // The width a cell's captions need at scale 1: an arrangement whose cells
  // are narrower is taken only when no other is wide enough.
  float minCellWidth = 0;
};
std::vector<Cell> flow(Box area, const FlowSpec& spec);
// flow() whose caption bands take as many lines as the cells' captions need
// at the cells' width (up to maxLines), so that in a narrow window a caption
// wraps rather than being cut with "...".  above[k] and below[k] are cell
// k's texts stacked in its band (a title over a formula; phrases), their
// lines summed; `keyLines` more lines above hold a key.  Where every text
// fits spec's lines, it is flow(area, spec) itself.  Each row's bands are as
// deep as its own cells need when that gives larger pictures than an even
// grid (one long note costs its row the lines, not every row).
using Stack = std::vector<std::string>;
std::vector<Cell> flowFitting(Box area, FlowSpec spec, const std::vector<Stack>& above, const std::vector<Stack>& below,
                              int keyLines = 0, int maxLines = 8);
// The same with a key (legend(), at scale 1) under cell k's title, keys[k]
// (empty: none): the band takes the lines the key needs at the cell's width,
// so that a narrow window wraps the key rather than leave entries out.
std::vector<Cell> flowFitting(Box area, FlowSpec spec, const std::vector<Stack>& above, const std::vector<Stack>& below,
                              const std::vector<std::vector<LegendEntry>>& keys, int maxLines = 8);
// The band's lines but its last (a title over a key's line), and its last
// line, at `scale`.  For a two-line band, halves().
inline std::pair<Box, Box> lastLineApart(const Box& b, int scale) {
  const float lines = std::max(1.0f, std::round(b.h() / lineHeight(scale)));
  const float mid = b.y0 + b.h() * (lines - 1) / lines;
  return {{b.x0, b.y0, b.x1, mid}, {b.x0, mid, b.x1, b.y1}};
}
// The band's lines but its last `lower` lines of scale 1 (a key under a
// title, flowFitting with keys), and those lines; one line: lastLineApart.
inline std::pair<Box, Box> keyApart(const Box& b, int scale, int lower) {
  if (lower <= 1) return lastLineApart(b, scale);
  const float mid = std::max(b.y0, b.y1 - float(lower) * lineHeight(1));
  return {{b.x0, b.y0, b.x1, mid}, {b.x0, mid, b.x1, b.y1}};
}

// Text whose numbers say where they come from (Label::printed, Label::given):
// a caption made of it hands each line the numbers that line shows, so the
// sidecar holds, beside every measured number a figure prints, the
// measurement's name.  A plain string converts to it (no numbers recorded).
struct Text {
  std::string text;
  std::vector<Label::Printed> printed;
  struct Given {
    std::string name;
    double value;
    std::string text;
  };
  std::vector<Given> given;
  Text() = default;
  Text(std::string s) : text(std::move(s)) {}  // NOLINT: plain text is text
  Text(const char* s) : text(s) {}             // NOLINT
  bool empty() const { return text.empty(); }
};
Text operator+(const Text& a, const Text& b);
// One measurement of `m`, printed with `format` ("%.1f"); throws ts::Error
// when `m` has no measurement of that name (a figure would print a number
// nobody measured).  While `m` is empty (nothing measured yet, as in a
// window's first frames) it prints "(measuring)".
Text measured(const Measurements& m, const std::string& name, const char* format);
// A template whose "{name}" or "{name|%.2f}" stand for measurements of `m`
// ("%g" when no format is given): "red: the ball, {mirror_ball_pixels|%.0f} px".
Text measuredText(const Measurements& m, const std::string& templ);
// A measurement's value that a view holds in measure()'s detail rather than
// in the list: printed and named all the same, so the proofreader holds it
// to the sidecar's value of `name`.
Text measuredValue(const std::string& name, double value, const char* format);
// A number that is not measured, with what it is: an axis tick, a parameter.
Text given(const std::string& name, double value, const char* format);
// One label of `t`, whole (no fitting): a tag, a note, a key placed by hand.
Label textLabel(float x, float y, const Text& t, glm::vec4 color, int scale, Align align = Align::Left,
                glm::vec4 background = glm::vec4(0.0f));
// A small "refining" tag in the top-left corner of `picture`: the picture
// is a coarse stage of a CPU computation still running (Measurements::
// refining, ts::measureStage), to be replaced in place.  Only in a window.
void refiningTag(Frame& f, const Rect& picture);
// Hands `t`'s numbers to the labels f.labels[first..] that show them.
void attachNumbers(Frame& f, size_t first, const Text& t);

// A key of the colours that carry meaning: a swatch and its meaning per
// entry, left to right, wrapping to the next line (an entry wider than the
// band: its meaning wrapped at words beside the swatch); each entry also
// goes into f.legend.  What the band has no room for is left out, never
// cut.  Returns the y below the last line.
float legend(Frame& f, Box band, const std::vector<LegendEntry>& entries, int scale);
// A legend's swatch: a square panel of the colour, as tall as a line of text
// at `scale`, its top-left at (x, y).  The caller records the legend entry.
void addSwatch(Frame& f, float x, float y, int scale, glm::vec4 colour);

// Text fitted to a box: at `scale` if it fits, else smaller, else wrapped at
// spaces (a word too wide for a line, a GL name, after an underscore) onto
// the lines the box has room for, else cut with "...".  Adds
// the labels and returns the y below the last line (band.y0 when nothing
// fits).  Never places text outside `band`.
float caption(Frame& f, Box band, const Text& text, glm::vec4 color, int scale, Align align = Align::Center,
              glm::vec4 background = glm::vec4(0.0f));
// A caption made of phrases (its clauses, each with its punctuation): on
// one line when all fit, else on as few lines as the phrases need, breaking
// only between phrases, each line at the largest scale (at most `scale`) at
// which every phrase fits the band's width and the lines its height; when
// none does, caption() of the whole.  Returns the y below the last line.
float phrases(Frame& f, Box band, const std::vector<Text>& parts, glm::vec4 color, int scale,
              Align align = Align::Center);
// The lines caption() would use at most: wrapped text at the scale that
// fits `width` (for reserving a band's height before placing it).
int captionLines(const std::string& text, int scale, float width);
// A band cut for two captions stacked: the lower gets the lines `lower`
// needs at the band's width (all but one at most), the upper the rest.  For
// a two-line band whose texts take a line each, halves().
std::pair<Box, Box> stackApart(const Box& b, int scale, const std::string& lower);

// A figure of pictures: cells flowed over the frame (flowFitting, `spec` but
// its n) above a legend and lines of notes at scale 1, each band as many lines
// as its text takes at the frame's width (the notes at least `minNoteLines`):
// a narrow window wraps the text rather than cutting it.  `draw(k, rect)` adds
// picture k's panel(s) in its cell's picture rectangle; its title and note are
// captioned above and below it.  `extraCells` more cells after the pictures
// are the caller's (a plot).  Returns the cells.
struct Captioned {
  Text title, note;
};
std::vector<Cell> pictureFigure(Frame& f, const std::vector<Captioned>& pictures,
                                const std::function<void(size_t, const Rect&)>& draw,
                                const std::vector<LegendEntry>& legend, const std::vector<Text>& notes, FlowSpec spec,
                                int minNoteLines = 1, Align notesAlign = Align::Center, int extraCells = 0);

// The lines legend() takes for `entries` at `scale` across `width` (0: none),
// and the height a Column takes for `texts` at `scale` across `width`: for
// reserving a figure's bands before laying out its pictures in the rest.
int legendLines(const std::vector<LegendEntry>& entries, int scale, float width);
float columnHeight(const std::vector<Text>& texts, int scale, float width);

// Lines of text stacked downwards in a box (a figure's notes): each add()
// takes the room its caption needs; what no longer fits is left out.
class Column {
 public:
  Column(Frame& f, Box area) : f_(f), area_(area), y_(area.y0) {}
  bool add(const Text& text, glm::vec4 color, int scale, Align align = Align::Center,
           glm::vec4 background = glm::vec4(0.0f));
  float y() const { return y_; }

 private:
  Frame& f_;
  Box area_;
  float y_;
};

// Adds `l` where asked, moved the least it takes to lie inside `within`,
// unless it is larger than `within` or would overlap a label already in the
// frame: tags, ticks and notes that do not fit are left out, never drawn
// over each other.  Returns whether it was placed.
bool placeFree(Frame& f, Label l, Box within);
}  // namespace ts::layout
