// common/core/text.hpp — the suite's one font: DejaVu Sans Condensed, compiled
// into the program and rasterised by Dear ImGui's font atlas at four sizes,
// its scales 1 to 4.  At scale 1 (18 px) its capitals are 11 px tall: readable
// when a 1280-1500 px figure is printed at a page's width.  The larger scales
// grow by less than whole multiples, as titles need.  Glyphs sit on whole
// pixels and are drawn texel for pixel, so figures are byte-identical
// everywhere.  Used for figure labels (GL quads), for text baked into
// textures (CPU), and by the window overlay.
#pragma once
#include <string>

#include "common/core/image.hpp"

namespace ts::text {
constexpr int kMaxScale = 4;
// The font's size at each scale, in ImGui's terms (ascent to descent).
constexpr int kPixels[kMaxScale] = {18, 26, 36, 46};
struct Glyph {
  float x0, y0, x1, y1;  // quad relative to the pen, pixels, y down
  float u0, v0, u1, v1;  // atlas coordinates
  float advance;
};
// The alpha-only atlas, built once.
const Image& atlas();  // RGBA with the coverage in alpha, white RGB
bool glyph(char c, int scale, Glyph* out);
float width(const std::string& s, int scale);
// A line's height at a scale: every glyph lies within it, descenders included.
float height(int scale);
// The height in pixels of a glyph's ink (rows with half coverage or more):
// capitalHeight(scale) is the 'H's, what "text N px tall" means in print.
int inkHeight(char c, int scale);
inline int capitalHeight(int scale) { return inkHeight('H', scale); }
// Draws text into an image on the CPU (alpha-blended), top-left at (x, y).
void draw(Image& img, float x, float y, const std::string& s, Rgba color, int scale);
}  // namespace ts::text
