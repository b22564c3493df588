// common/core/text.hpp — the suite's one font: Dear ImGui's built-in ProggyClean,
// rasterised at integer multiples of 13 px so every glyph stays pixel-exact
// and figures are byte-identical everywhere.  Used for figure labels (GL
// quads), for text baked into textures (CPU), and by the window overlay.
#pragma once
#include <string>

#include "common/core/image.hpp"

namespace ts::text {
constexpr int kBasePixels = 13;
constexpr int kMaxScale = 4;
struct Glyph {
  float x0, y0, x1, y1;  // quad relative to the pen, pixels, y down
  float u0, v0, u1, v1;  // atlas coordinates
  float advance;
};
// The alpha-only atlas, built once.
const Image& atlas();  // RGBA with the coverage in alpha, white RGB
bool glyph(char c, int scale, Glyph* out);
float width(const std::string& s, int scale);
inline float height(int scale) { return float(kBasePixels * scale); }
// Draws text into an image on the CPU (alpha-blended), top-left at (x, y).
void draw(Image& img, float x, float y, const std::string& s, Rgba color, int scale);
}  // namespace ts::text
