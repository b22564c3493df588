// demos/texture_compression/texture_compression_views.hpp — the Frame's panels: the picture,
// GL's decode of its DXT1 blocks, the error, and one block magnified with
// its palette (view "blocks"); the tile cache's hit rate against its size
// (view "memory").  Every picture is a texture of the image it shows
// (ts::renderedImageTexture), GL_NEAREST.
#pragma once
#include <string>
#include <vector>

#include "common/core/gl_call.hpp"
#include "common/core/layout.hpp"
#include "common/core/plot.hpp"
#include "common/core/textures.hpp"
#include "texture_compression_measure.hpp"

namespace dxt {
// What measure() found, for the views.
struct Result {
  int picture = kPhoto;
  bool threeColour = false, glDecode = false, fromFile = false;
  ts::Image original, decoded, error;  // decoded: GL's when it has S3TC, else the CPU's
  ts::Image rgb565;                    // the same memory at 16 bits: half the size, magnified back
  double rmsDxt1 = 0, rmsRgb565 = 0;   // each against the original
  std::string name;                    // the picture's name ("photo", or the file's)
  std::vector<Block> blocks;
  std::vector<CacheRun> plain, prefetched;
  ts::gl::CallList calls;  // the round trip's GL calls: the listing's first section
};

namespace views {
namespace L = ts::layout;

// Shown minified (512 texels in ~300 pixels) with GL_LINEAR: GL_NEAREST would
// pick between neighbouring texels at ties, where rasterizers round apart.
// A texture "dxt1_picture" the sidecar remakes (texture_compression_textures.hpp); a
// student's file, a picture of the demo's own.
inline int imageTexture(ts::Frame& f, const Result& m, Show show, Crop crop, const ts::Image& img,
                        const std::string& what, ts::gl::CallList calls = nullptr, GLenum filter = GL_LINEAR) {
  ts::TextureDesc t = m.fromFile ? ts::renderedImageTexture(img, "texture_compression", what, "texture_compression")
                                 : pictureTexture(m.picture, m.threeColour, show, crop, img);
  t.minFilter = t.magFilter = filter;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  t.renderedBy = std::move(calls);  // GL's own work behind the picture, listed first
  return f.addTexture(t);
}

// Picture | DXT1 | error x 8 | block (bx, by) and the 32 x 32 texels around it.
inline void buildBlocks(ts::Frame& f, const Result& m, const ts::Measurements& ms, int bx, int by,
                        const L::Text& numbers) {
  const L::Box area{8, 8, float(f.width - 8), float(f.height - 8)};
  const std::vector<L::Cell> cells = L::flow(area,
                                             {4, 1.0f, 1, 4, 10, 2,
                                              150});  // four lines under: the palette's rule, a normal map's angles
  const char* mode = m.threeColour ? "DXT1, every block in the 3-colour mode" : "DXT1, 4 bits per texel";
  const L::Text titles[4] = {std::string(kPictureNames[m.picture]) + ", " +
                                 L::given("the picture's width", m.original.width, "%.0f") + " x " +
                                 L::given("the picture's height", m.original.height, "%.0f") + ", " +
                                 L::given("bits a texel", 24, "%.0f") + " bits per texel",
                             std::string(mode) + (m.glDecode ? " (GL's decode)" : " (CPU decode: no S3TC here)"),
                             "|error| x " + L::given("the error's magnification", 8, "%.0f"),
                             "block (" + L::given("the block's column", bx, "%.0f") + ", " +
                                 L::given("the block's row", by, "%.0f") + ") and its palette"};
  const ts::Image* shown[3] = {&m.original, &m.decoded, &m.error};
  const Show what[3] = {Show::Original, m.glDecode ? Show::DecodedGl : Show::DecodedCpu, Show::Error};
  for (int k = 0; k < 3; ++k)
    f.panels.push_back(
        L::texturePanel("image_" + std::to_string(k), cells[size_t(k)].picture,
                        imageTexture(f, m, what[k], {}, *shown[k], titles[k].text, k == 1 ? m.calls : nullptr)));
  // The block, 8 x 8 blocks around it magnified, outlined; its palette below.
  // (A picture smaller than 32 texels a side is shown whole.)
  const int zw = std::min(32, m.decoded.width), zh = std::min(32, m.decoded.height);
  const int x0 = std::clamp(bx * 4 - 14, 0, m.decoded.width - zw),
            y0 = std::clamp(by * 4 - 14, 0, m.decoded.height - zh);
  ts::Image zoom(zw, zh);
  for (int y = 0; y < zh; ++y)
    for (int x = 0; x < zw; ++x) zoom.set(x, y, m.decoded.at(x0 + x, y0 + y));
  ts::Rect zr = cells[3].picture;
  const int sw = zr.h / 6, keyH = int(L::lineHeight(1)) + 2;  // the palette's strip, the outline's key
  zr.h = std::max(1, zr.h - (sw + 4 + keyH));  // a narrow window leaves the block a speck, never a negative viewport
  zr.w = zr.h, zr.x = cells[3].picture.x + (cells[3].picture.w - zr.w) / 2;
  ts::Panel z = L::texturePanel("block_zoom", zr,
                                imageTexture(f, m, what[1], {x0, y0, zw, zh}, zoom, "the block magnified", nullptr,
                                             GL_NEAREST));
  const float ux = float(bx * 4 - x0) / float(zw), uy = 1.0f - float(by * 4 - y0) / float(zh);
  const float bw = 4.0f / float(zw), bh = 4.0f / float(zh);
  z.batches.push_back(
      ts::lineLoop({{ux, uy}, {ux + bw, uy}, {ux + bw, uy - bh}, {ux, uy - bh}}, L::kAmber, 2.0f, "block_outline"));
  f.panels.push_back(z);
  const Block& b = m.blocks[size_t(by * blocksAcross(m.original.width) + bx)];
  const auto pal = palette(b.c0, b.c1);
  ts::Panel sp = L::unitPanel("palette", {zr.x, zr.y + zr.h + 4, zr.w, sw});
  ts::Batch quads;
  quads.role = "palette";
  for (int k = 0; k < 4; ++k) {
    const glm::vec4 c(pal[size_t(k)].r / 255.0f, pal[size_t(k)].g / 255.0f, pal[size_t(k)].b / 255.0f, 1.0f);
    const float a = k / 4.0f + 0.01f, e = (k + 1) / 4.0f - 0.01f;
    for (glm::vec2 p :
         {glm::vec2(a, 0), glm::vec2(e, 0), glm::vec2(e, 1), glm::vec2(a, 0), glm::vec2(e, 1), glm::vec2(a, 1)})
      quads.vertices.push_back({glm::vec3(p, 0.0f), glm::vec4(0, 0, 0, 1), c});
  }
  sp.batches.push_back(quads);
  f.panels.push_back(sp);
  for (int k = 0; k < 4; ++k) L::caption(f, cells[size_t(k)].above, titles[k], L::kWhite, cells[size_t(k)].scale);
  // The end points, then the rule they select, each formula whole on its line.
  char ends[80];
  std::snprintf(ends, sizeof ends, "c0 0x%04X %s c1 0x%04X:", b.c0, b.c0 > b.c1 ? ">" : "<=", b.c1);
  L::Column palette(f, cells[3].below);
  palette.add(ends, L::kWhite, cells[3].scale);
  if (b.c0 > b.c1) {
    palette.add("c2 = (2c0+c1)/3", L::kWhite, cells[3].scale);
    palette.add("c3 = (c0+2c1)/3", L::kWhite, cells[3].scale);
  } else {
    palette.add("c2 = (c0+c1)/2, c3 = black", L::kWhite, cells[3].scale);
  }
  // A normal map's block: how far its normals turn, where the reader looks.
  for (const ts::Measurement& x : ms)
    if (x.name == "normal_error_deg[shown_block]")
      palette.add(L::measuredText(ms, "its normals turn by up to {normal_error_deg[shown_block]|%.1f} deg"), L::kAmber,
                  cells[3].scale);
  // The outline's colour is the block's: named under the picture it marks.
  L::legend(f,
            {float(zr.x), float(zr.y + zr.h + 4 + sw + 2), float(cells[3].picture.x + cells[3].picture.w),
             cells[3].below.y0},
            {{L::kAmber, "the block"}}, 1);
  L::caption(f, {cells[0].below.x0, cells[0].below.y0, cells[2].below.x1, cells[0].below.y1}, numbers, L::kAmber,
             cells[0].scale);
}

// Equal memory, magnified: 64 x 64 texels around block (bx, by) of the
// original, of DXT1 at full size, and of RGB565 at half size magnified back
// (GL_NEAREST; each panel a multiple of 64 pixels, so no texel edge falls on
// a pixel centre).
inline void buildEqualMemory(ts::Frame& f, const Result& m, const ts::Measurements& ms, int bx, int by,
                             const L::Text& numbers) {
  const L::Box area{8, 8, float(f.width - 8), float(f.height - 8)};
  const std::vector<L::Cell> cells = L::flow(area, {3, 1.0f, 1, 2, 10, 2, 150});
  const int n = std::min({64, m.original.width, m.original.height});
  const int x0 = std::clamp(bx * 4 + 2 - n / 2, 0, m.original.width - n),
            y0 = std::clamp(by * 4 + 2 - n / 2, 0, m.original.height - n);
  const ts::Image* shown[3] = {&m.original, &m.decoded, &m.rgb565};
  const Show what[3] = {Show::Original, m.glDecode ? Show::DecodedGl : Show::DecodedCpu, Show::Rgb565};
  const std::string size = m.fromFile ? "file" : "512";
  const L::Text dims = L::given("the picture's width", m.original.width, "%.0f") + " x " +
                       L::given("the picture's height", m.original.height, "%.0f");
  const L::Text titles[3] = {m.name + ", " + dims + " at " + L::given("bits a texel", 24, "%.0f") + " bits",
                             "DXT1 at " + dims +
                                 L::measuredText(ms, ": RMS {rms_equal_memory[dxt1_" + size + "]|%.2f}"),
                             L::measuredText(ms, "RGB565 at half the size, magnified: RMS {rms_equal_memory[rgb565_" +
                                                     std::string(m.fromFile ? "half" : "256") + "]|%.2f}")};
  for (int k = 0; k < 3; ++k) {
    ts::Image crop(n, n);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) crop.set(x, y, shown[k]->at(x0 + x, y0 + y));
    const ts::Rect& c = cells[size_t(k)].picture;
    const int side = std::max(n, std::min(c.w, c.h) / n * n);
    f.panels.push_back(L::texturePanel("equal_" + std::to_string(k), L::centred(c, side, side),
                                       imageTexture(f, m, what[k], {x0, y0, n, n}, crop, titles[k].text,
                                                    k == 1 ? m.calls : nullptr, GL_NEAREST)));
    L::caption(f, cells[size_t(k)].above, titles[k], L::kWhite, cells[size_t(k)].scale);
  }
  L::caption(f, {cells[0].below.x0, cells[0].below.y0, cells[2].below.x1, cells[0].below.y1}, numbers, L::kAmber,
             cells[0].scale);
}

// The LRU tile cache: hit rate against its size, with and without prefetching.
// The title and the key are placed here, not by the plot, so that the
// title's numbers say what they are and the key goes into the frame's legend.
inline void buildMemory(ts::Frame& f, const Result& m, const L::Text& numbers) {
  const glm::vec4 kLru{0.4f, 0.7f, 1.0f, 1.0f};
  const float line = L::lineHeight(1);
  const L::Text view = L::given("the view's side, tiles", kCacheView, "%.0f");
  L::caption(f, {8, 8, float(f.width - 8), 8 + line},
             "an LRU tile cache along a camera path (a view " + view + " x " + view + " tiles wide, moving " +
                 L::given("the view's step across, tiles a frame", kCacheStepX, "%g") + " tile across and " +
                 L::given("the view's step down, tiles a frame", kCacheStepY, "%g") + " down a frame)",
             L::kWhite, 1);
  L::legend(f, {40, 8 + line, float(f.width - 8), 8 + 2 * line},
            {{kLru, "LRU"}, {L::kAmber, "LRU + prefetching the next column and row"}}, 1);
  ts::plot::Spec s;
  s.xLabel = "cache size, tiles", s.yLabel = "hit rate, %";
  // The axis runs past 100 % so that a curve at its plateau near 100 stays clear of the border.
  s.x0 = 24, s.x1 = 136, s.y0 = 0, s.y1 = 110;
  s.xTicks = ts::plot::ticks(32, 128, 16), s.yTicks = ts::plot::ticks(0, 100, 20);
  std::vector<glm::dvec2> a, b;
  for (size_t k = 0; k < cacheSizes().size(); ++k)
    a.push_back({double(cacheSizes()[k]), 100 * m.plain[k].hitRate()}),
        b.push_back({double(cacheSizes()[k]), 100 * m.prefetched[k].hitRate()});
  s.series.push_back({"lru", kLru, ts::plot::Mark::Line, a});
  s.series.push_back({"lru_prefetch", L::kAmber, ts::plot::Mark::Line, b});
  const int notes = int(line) * 3 + 8, top = 8 + int(2 * line);
  const size_t first = f.labels.size();
  ts::plot::draw(f, s, {8, top, f.width - 16, f.height - 8 - top - notes});
  // The ticks the plot placed are axis positions, not measurements.
  for (size_t k = first; k < f.labels.size(); ++k)
    for (const auto& [ticks, what] :
         {std::pair{&s.xTicks, "cache-size axis tick, tiles"}, std::pair{&s.yTicks, "hit-rate axis tick, %"}})
      for (const ts::plot::Tick& t : *ticks)
        if (f.labels[k].text == t.text) f.labels[k].given.push_back({what, t.at});
  L::caption(f, {8, float(f.height - notes), float(f.width - 8), float(f.height - 4)}, numbers, L::kAmber, 1);
}
}  // namespace views
}  // namespace dxt
