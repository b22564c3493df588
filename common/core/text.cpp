#include "common/core/text.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace ts::text {
namespace {
// The font file's bytes (common/cmake/embed_bytes.cmake): no path to find at
// run time.
const unsigned char kFontFile[] = {
#include "label_font.inc"
};

struct FontAtlas {
  ImFontAtlas atlas;
  ImFont* fonts[kMaxScale] = {};
  float lineHeight[kMaxScale] = {};
  Image image;
  FontAtlas() {
    for (int s = 1; s <= kMaxScale; ++s) {
      ImFontConfig cfg;
      cfg.OversampleH = cfg.OversampleV = 1;  // one texel a pixel: no filtering when drawn
      cfg.PixelSnapH = true;                  // whole-pixel advances
      cfg.FontDataOwnedByAtlas = false;       // the bytes are static
      fonts[s - 1] = atlas.AddFontFromMemoryTTF(const_cast<unsigned char*>(kFontFile), int(sizeof kFontFile),
                                                float(kPixels[s - 1]), &cfg);
    }
    unsigned char* px = nullptr;
    int w = 0, h = 0;
    atlas.GetTexDataAsRGBA32(&px, &w, &h);
    image = Image(w, h, {255, 255, 255, 0});
    std::copy(px, px + size_t(w) * h * 4, image.pixels.begin());
    // The line: from the top to the lowest glyph's bottom (ImGui's font size
    // is the ascent less the descent, which a rounded descender may pass).
    for (int s = 0; s < kMaxScale; ++s)
      for (const ImFontGlyph& g : fonts[s]->Glyphs) lineHeight[s] = std::max(lineHeight[s], std::ceil(g.Y1));
  }
};
FontAtlas& instance() {
  static FontAtlas a;
  return a;
}
}  // namespace

const Image& atlas() { return instance().image; }

bool glyph(char c, int scale, Glyph* out) {
  scale = std::clamp(scale, 1, kMaxScale);
  const ImFontGlyph* g = instance().fonts[scale - 1]->FindGlyphNoFallback(ImWchar(static_cast<unsigned char>(c)));
  if (!g) g = instance().fonts[scale - 1]->FindGlyph(ImWchar('?'));
  if (!g) return false;
  *out = {g->X0, g->Y0, g->X1, g->Y1, g->U0, g->V0, g->U1, g->V1, g->AdvanceX};
  return true;
}

float height(int scale) { return instance().lineHeight[std::clamp(scale, 1, kMaxScale) - 1]; }

int inkHeight(char c, int scale) {
  const Image& a = atlas();
  Glyph g;
  if (!glyph(c, scale, &g)) return 0;
  const int x0 = int(std::lround(g.u0 * a.width)), x1 = int(std::lround(g.u1 * a.width));
  const int y0 = int(std::lround(g.v0 * a.height)), y1 = int(std::lround(g.v1 * a.height));
  int top = -1, bottom = -1;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (a.at(x, y).a >= 128) {
        if (top < 0) top = y;
        bottom = y;
        break;
      }
  return top < 0 ? 0 : bottom - top + 1;
}

float width(const std::string& s, int scale) {
  float w = 0;
  Glyph g;
  for (char c : s)
    if (glyph(c, scale, &g)) w += g.advance;
  return w;
}

void draw(Image& img, float x, float y, const std::string& s, Rgba color, int scale) {
  const Image& a = atlas();
  Glyph g;
  float pen = std::floor(x);
  y = std::floor(y);
  for (char c : s) {
    if (!glyph(c, scale, &g)) continue;
    int gx0 = int(pen + g.x0), gy0 = int(y + g.y0);
    int gw = int(std::lround((g.u1 - g.u0) * a.width)), gh = int(std::lround((g.v1 - g.v0) * a.height));
    int ax = int(std::lround(g.u0 * a.width)), ay = int(std::lround(g.v0 * a.height));
    for (int j = 0; j < gh; ++j)
      for (int i = 0; i < gw; ++i) {
        int px = gx0 + i, py = gy0 + j;
        if (px < 0 || py < 0 || px >= img.width || py >= img.height) continue;
        unsigned cov = a.at(ax + i, ay + j).a * unsigned(color.a) / 255u;
        Rgba d = img.at(px, py);
        auto mix = [cov](uint8_t dst, uint8_t src) { return uint8_t((src * cov + dst * (255u - cov) + 127u) / 255u); };
        img.set(px, py, {mix(d.r, color.r), mix(d.g, color.g), mix(d.b, color.b), d.a});
      }
    pen += g.advance;
  }
}
}  // namespace ts::text
