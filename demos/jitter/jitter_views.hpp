// demos/jitter/jitter_views.hpp — how the jitter demo (Figure VI.7) lays
// out what it measured: the mode view (one image large, its sample pattern
// and numbers), the compare view (the book's figure: every mode, its error,
// the reference and the sample patterns) and the plot view (error against
// samples per pixel, and the table).  jitter.cpp measures; this draws.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/layout.hpp"
#include "common/core/plot.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "common/core/scene.hpp"
#include "jitter_math.hpp"
#include "jitter_zone.hpp"

namespace jitter::views {
using jitter::Pattern;
using ts::layout::fmt;

// random: n x n points anywhere in the pixel, drawn anew per pixel (it clusters: no strata).
enum Mode { kOne, kRegular, kJitterGlobal, kJitterPixel, kReference, kRandom, kModes };
const char* const kModeNames[] = {"one", "regular", "jitter-global", "jitter-pixel", "reference", "random"};
constexpr int kMaxSide = 4;

// The three n x n patterns the sweep covers (jitter.cpp's kKinds), in this order.
// (and a fourth, pure random, measured at the current n only)
const char* const kKindKeys[4] = {"regular", "jitter_global", "jitter_pixel", "random"};
const char* const kKindTitles[3] = {"regular", "jittered, one pattern", "jittered per pixel"};
// The key of a mode's measurements (rms[one], aliasing[jitter_pixel], ...); the reference has none.
inline const char* modeKey(int mode) {
  const char* const keys[] = {"one", "regular", "jitter_global", "jitter_pixel", "reference", "random"};
  return keys[mode];
}

using ts::layout::kWhite, ts::layout::kAmber;
const glm::vec4 kGrey{0.6f, 0.6f, 0.65f, 1.0f};
const glm::vec4 kSeriesColour[3] = {{0.35f, 0.65f, 1.0f, 1.0f}, {1.0f, 0.55f, 0.2f, 1.0f}, {0.4f, 0.9f, 0.45f, 1.0f}};

// The demo's figures (jitter.cpp's figures()).
inline std::vector<ts::FigureSpec> figureSpecs() {
  return {
      {"vi7_jitter",
       "Figure VI.7",
       "A checkerboard receding to the horizon, 288x192 pixels each: one sample per pixel; 3x3 samples at the "
       "subpixel centres; 3x3 jittered with one pattern for every pixel (the accumulation buffer); 3x3 jittered "
       "independently per pixel; below, each one's error against a 256-sample reference (x3). Regular samples "
       "and one jitter pattern for all pixels keep interference patterns; jitter chosen per pixel turns them into "
       "grain. Bottom: the reference, and the sample patterns of Figure VI.7: regular; jittered, one pattern for "
       "every pixel; jittered anew in each pixel (2x2 pixels shown).",
       {"--view", "compare", "--samples", "3", "--seed", "1"},
       1320,
       830,
       "Aliasing (the error the neighbours' errors predict) at 3x3 samples: regular {aliasing[regular]}, one "
       "jitter pattern {aliasing[jitter_global]}, jittered per pixel {aliasing[jitter_pixel]}."},
      {"vi7_error_vs_samples",
       "Figure VI.7 (error vs samples)",
       "RMS error against the reference, and its aliasing (the part of each pixel's error its neighbours' errors "
       "predict), for 1, 4, 9 and 16 samples per pixel: "
       "the error falls as samples rise; jitter per pixel leaves almost no aliasing; one jitter pattern for all "
       "pixels keeps much of it (with seed 1 about as much as regular sampling; how much depends on the pattern).",
       {"--view", "plot", "--seed", "1"},
       1024,
       600,
       "Jittered per pixel, the RMS error falls from {rms[jitter_pixel_1x1]} (1 sample) to {rms[jitter_pixel_4x4]} "
       "(16) with aliasing {aliasing[jitter_pixel_4x4]}; regular 4x4 keeps {aliasing[regular_4x4]}."},
      {"jitter_zone_plate",
       "Figure VI.7 (where aliasing sets in)",
       "A zone plate, its frequency rising upwards from 0.02 to 3 cycles per pixel (bands of 2 rows, 64 pixels "
       "wide, shown 2x), rendered by GL with 1 sample per pixel, 3x3 samples at the subpixel centres and 3x3 "
       "jittered per pixel; right, the alias of each band, its error against the exact box filter of the pixel "
       "as a fraction of the box-filtered signal, with the onsets (the alias reaching half the signal) marked: "
       "at the sample grid's Nyquist, 0.5 and 1.5 cycles per pixel. Jitter's error starts lower and stays noise.",
       {"--view", "zone", "--samples", "3", "--seed", "1"},
       1100,
       740,
       "Aliasing sets in at {alias_onset_gl[1x1]} cycles per pixel with 1 sample and at {alias_onset_gl[3x3]} with "
       "3x3 regular samples (GL; the CPU model: {alias_onset_cpp[1x1]}, {alias_onset_cpp[3x3]})."},
  };
}

// One image measure() made, and its error against the reference.
struct Result {
  ts::Image image;
  jitter::ErrorStats stats;
  std::vector<double> error;
  ts::TextureDesc texture;
  ts::TextureDesc errorTexture;  // the error x3, as a picture
  bool valid = false;
};
// The images measure() has made for the current seed and averaging (one
// per pattern kind and side, and the reference): its detail, which
// build() draws.
struct Found {
  std::array<std::array<Result, kMaxSide>, 3> results;
  std::array<Result, kMaxSide> random;  // pure random per pixel, n = 1..4 (made when shown or measured)
  zone::Plate zone;                     // the zone plate's GL renders and alias curves (jitter_gl.hpp, zoneMeasure)
  Result reference;
  // A window's first stage (Jitter::measure): the reference is a coarse
  // stand-in, so it and every error picture are tagged refining.
  bool coarse = false;
  const Result& at(int kind, int side) const { return results[size_t(kind)][size_t(side - 1)]; }
  Result& at(int kind, int side) { return results[size_t(kind)][size_t(side - 1)]; }
};

inline ts::TextureDesc imageTexture(const ts::Image& img, const std::string& what,
                                    std::vector<std::pair<std::string, std::string>> params) {
  return ts::renderedImageTexture(img, "jitter_render", what, "jitter", std::move(params));
}

// Signed error, 3x: orange where the image is brighter than the reference,
// blue where darker, grey where equal.
inline ts::Image errorPicture(const std::vector<double>& e, int w, int h) {
  ts::Image out(w, h);
  const glm::dvec3 mid(96, 96, 100), pos(255, 150, 40), neg(60, 140, 255);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double v = std::clamp(3.0 * e[size_t(y) * size_t(w) + size_t(x)], -1.0, 1.0);
      glm::dvec3 c = v >= 0 ? glm::mix(mid, pos, v) : glm::mix(mid, neg, -v);
      out.set(x, y, {uint8_t(std::lround(c.r)), uint8_t(std::lround(c.g)), uint8_t(std::lround(c.b)), 255});
    }
  return out;
}

// A result's error as a texture: its image's parameters (not its digest,
// size or maker), and which image it is the error of.
inline ts::TextureDesc errorTexture(const Result& res) {
  const jitter::Camera cam;
  auto params = res.texture.params;
  params.erase(std::remove_if(params.begin(), params.end(),
                              [](const auto& p) {
                                return p.first == "digest" || p.first == "size" || p.first == "image" ||
                                       p.first == "made_by";
                              }),
               params.end());
  params.push_back({"of", res.texture.params.front().second});
  return imageTexture(errorPicture(res.error, cam.width, cam.height), "error_x3", params);
}

// The demo's state as the views see it (its flags), and how it draws them.
struct Views {
  int mode_ = kJitterPixel, side_ = 3, seed_ = 1;
  bool showError_ = false;
  const ts::Measurements* measured = nullptr;  // what build() was given: the numbers the labels print
  bool coarse() const {                        // a first stage's pictures (Found::coarse)
    const Found* f = measured ? measured->detailAs<Found>() : nullptr;
    return f && f->coarse;
  }
  // One measurement printed as `format` (measure() made every one a drawn result shows).
  ts::layout::Text num(const std::string& name, const char* format = "%.4f") const {
    return ts::layout::measured(*measured, name, format);
  }

  const Result* current(const Found& fd) const;
  void addImage(ts::Frame& f, const std::string& id, ts::Rect rect, const ts::TextureDesc& tex) const;
  void addPattern(ts::Frame& f, ts::Panel& canvas, ts::Rect box, int mode, int side, bool labels, float labelW = 0,
                  int scale = 1) const;
  void buildMode(ts::Frame& f, ts::Panel& canvas, const Found& fd) const;
  void buildCompare(ts::Frame& f, ts::Panel& canvas, const Found& fd) const;
  void buildPlot(ts::Frame& f, const Found& fd) const;
  void buildZone(ts::Frame& f, ts::Panel& canvas, const Found& fd) const;
  // Draws one plot of the sweep in `area`; returns its data area.
  ts::Rect addPlot(ts::Frame& f, ts::Rect area, const std::string& title, bool aliasing, const Found& fd,
                   int scale) const;
};

inline const Result* Views::current(const Found& fd) const {
  const Result* res = &fd.reference;
  switch (mode_) {
    case kOne: res = &fd.at(0, 1); break;
    case kRegular: res = &fd.at(0, side_); break;
    case kJitterGlobal: res = &fd.at(1, side_); break;
    case kJitterPixel: res = &fd.at(2, side_); break;
    case kRandom: res = &fd.random[size_t(side_ - 1)]; break;
    default: break;
  }
  return res->valid ? res : nullptr;
}

inline void Views::addImage(ts::Frame& f, const std::string& id, ts::Rect rect, const ts::TextureDesc& tex) const {
  ts::TextureDesc t = tex;
  // Pixel-exact at 1:1; scaled down (a small window) it is filtered.
  if (rect.w < t.image->width || rect.h < t.image->height) t.minFilter = GL_LINEAR;
  int index = -1;
  for (size_t i = 0; i < f.textures.size(); ++i)
    if (f.textures[i].key() == t.key() && f.textures[i].minFilter == t.minFilter) index = int(i);
  if (index < 0) index = f.addTexture(t);
  f.panels.push_back(ts::layout::texturePanel(id, rect, index));
  // A first stage (Jitter::measure): the reference and the errors are coarse.
  if (coarse() && (id.rfind("error", 0) == 0 || id == "image_reference")) ts::layout::refiningTag(f, rect);
}

// A pixel square of `box` (canvas pixels, y down) with its subpixel grid and
// the sample points of `mode` (jitter-pixel: a 2 x 2 block of pixels, each
// with its own jitter).
inline void Views::addPattern(ts::Frame& f, ts::Panel& canvas, ts::Rect box, int mode, int side, bool labels,
                              float labelW, int scale) const {
  const int n = mode == kOne ? 1 : mode == kReference ? jitter::kReferenceSide : side;
  const int cells = mode == kJitterPixel || mode == kRandom ? 2 : 1;
  const float cell = float(box.w) / float(cells);
  std::vector<glm::vec2> grid, border, dots;
  for (int cy = 0; cy < cells; ++cy)
    for (int cx = 0; cx < cells; ++cx) {
      float x0 = float(box.x) + cx * cell, y0 = float(box.y) + cy * cell;
      border.insert(border.end(), {{x0, y0},
                                   {x0 + cell, y0},
                                   {x0 + cell, y0},
                                   {x0 + cell, y0 + cell},
                                   {x0 + cell, y0 + cell},
                                   {x0, y0 + cell},
                                   {x0, y0 + cell},
                                   {x0, y0}});
      if (mode != kOne && mode != kRandom && n <= 8)  // random has no strata
        for (int k = 1; k < n; ++k) {
          float t = float(k) / float(n) * cell;
          grid.insert(grid.end(), {{x0 + t, y0}, {x0 + t, y0 + cell}, {x0, y0 + t}, {x0 + cell, y0 + t}});
        }
      // The pixel shown: for jitter-pixel, (100 + cx, 100 + 1 - cy) of the image (GL rows from the bottom).
      const int pi = 100 + cx, pj = 100 + (cells - 1 - cy);
      Pattern p = mode == kJitterGlobal  ? Pattern::JitterGlobal
                  : mode == kJitterPixel ? Pattern::JitterPixel
                  : mode == kReference   ? Pattern::Reference
                  : mode == kRandom      ? Pattern::Random
                                         : Pattern::Regular;
      for (int k = 0; k < n * n; ++k) {
        glm::dvec2 s = jitter::samplePos(p, n, uint32_t(seed_), pi, pj, k);
        dots.push_back({x0 + float(s.x) * cell, y0 + float(1.0 - s.y) * cell});
      }
    }
  canvas.batches.push_back(ts::lineSegments(grid, kGrey, 1.0f, "subpixel_grid"));
  canvas.batches.push_back(ts::lineSegments(border, kWhite, 2.0f, "pixel_border"));
  ts::Batch d = ts::lineSegments(dots, kAmber, 1.0f, "sample_points");
  d.prim = ts::Prim::Points;
  d.pointSize = n > 8 ? 3.0f : std::clamp(std::round(cell / float(4 * n)), 3.0f, 8.0f);
  canvas.batches.push_back(d);
  if (labels) {
    std::string nn = std::to_string(n) + "x" + std::to_string(n);
    std::string l1 = mode == kOne         ? "1 sample"
                     : mode == kReference ? "16x16 stratified"
                     : mode == kRegular   ? nn + " regular"
                     : mode == kRandom    ? nn + " random"
                                          : nn + " jittered";
    std::string l2 = mode == kOne            ? "the pixel centre"
                     : mode == kRegular      ? "subpixel centres"
                     : mode == kJitterGlobal ? "same in every pixel"
                     : mode == kJitterPixel  ? "new in every pixel"
                     : mode == kRandom       ? "anywhere, new per pixel"
                                             : "jittered (the reference)";
    // Under the box, in a band as wide as the box and its margins, two lines at `scale`.
    const float half = (labelW > 0 ? labelW : std::max(float(box.w), 120.0f * float(scale))) / 2,
                cx = float(box.x + box.w / 2), y = float(box.y + box.h + 5), line = ts::layout::lineHeight(scale);
    const ts::layout::Box band{std::max(0.0f, cx - half), y, std::min(float(f.width), cx + half), y + line};
    ts::layout::caption(f, band, l1, kWhite, scale);
    ts::layout::caption(f, {band.x0, y + line, band.x1, y + 2 * line}, l2, kGrey, scale);
  }
}

inline void Views::buildMode(ts::Frame& f, ts::Panel& canvas, const Found& fd) const {
  namespace L = ts::layout;
  const int W = jitter::kImageW, H = jitter::kImageH;
  std::string n = std::to_string(side_) + "x" + std::to_string(side_);
  std::string what = mode_ == kOne            ? "1 sample per pixel"
                     : mode_ == kRegular      ? n + " regular samples per pixel"
                     : mode_ == kJitterGlobal ? n + " jittered, one pattern for all pixels"
                     : mode_ == kJitterPixel  ? n + " jittered independently per pixel"
                     : mode_ == kRandom       ? n + " pure random points per pixel (they cluster)"
                                              : "reference: 16x16 stratified samples per pixel";
  // The image as large as the window allows (whole zooms are pixel-exact;
  // a zoom is rounded down to a whole one when that loses little), the
  // sample pattern and the numbers beside it (a wide window) or under it,
  // all text at the scale the image asks for (fitScale).
  struct Place {
    int line, top, sideW, under;
    bool column;
    ts::Rect rect;
  };
  // The pattern's two lines of labels under its box (addPattern), with a margin.
  auto labelsUnder = [](int sc) { return 5 + int(2 * L::lineHeight(sc)) + 4 * sc; };
  auto placeAt = [&](int sc) {
    Place p;
    p.line = int(L::lineHeight(sc)) + 2 * sc, p.top = 2 * p.line;
    p.sideW = std::min(220 * sc, std::max(130 * sc, f.width / 4)), p.under = 156 + labelsUnder(sc);
    auto fit = [&](int availW, int availH) {
      double k = std::max(0.05, std::min(double(std::max(1, availW)) / W, double(std::max(1, availH)) / H));
      if (k >= 1 && std::floor(k) >= 0.92 * k) k = std::floor(k);
      return k;
    };
    double beside = fit(f.width - p.sideW - 48, f.height - p.top - 16),
           below = fit(f.width - 32, f.height - p.top - p.under - 16);
    p.column = below > beside;
    const double k = p.column ? below : beside;
    p.rect = {16, p.top, std::max(1, int(W * k)), std::max(1, int(H * k))};
    // The pattern's labels and the numbers must fit beside each other (a
    // column layout) or in the side column at this scale, else it is too large.
    const float numbersW = ts::text::width("RMS error 0.0000", sc) + 8;
    if (p.column ? float(160 * sc + 24) + numbersW > float(f.width - 32) : numbersW > float(p.sideW)) p.rect.w = 0;
    return p;
  };
  const int sc = L::fitScale([&](int s) { return placeAt(s).rect; });
  const Place p = placeAt(sc);
  const ts::Rect rect = p.rect;
  std::string title = "Figure VI.7: " + what + (showError_ ? "  (error x3)" : "");
  if (ts::text::width(title, sc) > float(f.width - 25))
    title = title.substr(7);  // "Figure " goes before the scale does
  L::caption(f, {12, 8, float(f.width) - 12, float(p.top - 2)}, title, kWhite, sc, ts::Align::Left);
  const Result* res = current(fd);
  if (res) addImage(f, "image", rect, showError_ ? res->errorTexture : res->texture);
  if (res && coarse() && (showError_ || mode_ == kReference))  // coarse, as in addImage
    L::refiningTag(f, rect);
  int sideX = rect.x + rect.w + 24;  // where the numbers start
  int x = p.column ? 16 : sideX, y0 = p.column ? rect.y + rect.h + 12 : p.top + 4;
  int room = p.column ? p.under - 12 : f.height - y0 - 3 * p.line - labelsUnder(sc);
  int box = std::max(16, std::min({p.sideW - 20, room - labelsUnder(sc), f.height / 3}));
  int labelW = 160 * sc;
  const int numbersW = 150 * sc;
  if (p.column) {
    // The pattern (centred over its labels), then the numbers beside it.
    x = std::max(16, (f.width - (std::max(box, labelW) + 24 + numbersW)) / 2);
    sideX = x + std::max(box, labelW) + 24;
    x += (std::max(box, labelW) - box) / 2;
  } else {
    // Beside the image: the pattern centred in the column right of it, its labels as wide as the column.
    labelW = std::max(box, f.width - 4 - x);
    x += (labelW - box) / 2;  // (the numbers stay at the column's left, sideX)
  }
  addPattern(f, canvas, {x, y0, box, box}, mode_, side_, true, float(labelW), sc);
  if (res && mode_ != kReference) {
    // The numbers: right of the pattern in a column layout, under it beside the image.
    float nx = float(sideX), ny = p.column ? float(y0) : float(y0 + box + labelsUnder(sc));
    L::Column numbers(f, {nx, ny, float(f.width) - 4, float(f.height) - 2});
    const std::string k = std::string("[") + modeKey(mode_) + "]";
    numbers.add("RMS error " + num("rms" + k), kAmber, sc, ts::Align::Left);
    numbers.add("aliasing  " + num("aliasing" + k), kAmber, sc, ts::Align::Left);
    numbers.add("noise     " + num("noise" + k), kAmber, sc, ts::Align::Left);
  }
}

inline void Views::buildCompare(ts::Frame& f, ts::Panel& canvas, const Found& fd) const {
  namespace L = ts::layout;
  const int W = jitter::kImageW, H = jitter::kImageH, line = int(L::lineHeight(1)), gap = 24;
  // At 1:1 the figure needs four images and three gaps across, three images
  // and ten lines of text down; a smaller frame (a window) scales the images.
  // A tall window puts two columns across, each row of four in two rows.
  auto scaleFor = [&](int cols, int numberLines) {
    const int R = 4 / cols;
    const int textH = 2 * line + 2 + R * ((numberLines + 1) * line + 10) + 2 * line + R * (2 * line) + 8;
    return std::min(
        {1.0, double(f.width - 16 - (cols - 1) * gap) / (cols * W), double(f.height - textH) / (3 * R * H)});
  };
  int cols = scaleFor(2, 3) > scaleFor(4, 2) * 1.05 ? 2 : 4;
  double s = scaleFor(cols, 2);
  const bool narrow = W * s < 220;  // the numbers take three lines instead of two
  if (narrow) s = scaleFor(cols, 3);
  const int R = 4 / cols;
  const int w = std::max(1, int(W * s)), h = std::max(1, int(H * s)), g = std::max(6, int(gap * s));
  const int left = std::max(0, (f.width - (cols * w + (cols - 1) * g)) / 2);
  const std::string n = std::to_string(side_) + "x" + std::to_string(side_);
  // The key of the sample patterns' points at the title line's right end, the title centred in the rest.
  const std::string pointsMeaning = "sample positions";
  const float keyW = ts::text::height(1) + 4 + ts::text::width(pointsMeaning, 1);
  L::caption(f, {4, 4, float(f.width) - 12 - keyW, float(line + 4)},
             "Figure VI.7  jittered supersampling: " + n + " samples per pixel, seed " + L::given("seed", seed_, "%g"),
             kWhite, 1);
  L::legend(f, {float(f.width) - 4 - keyW, 4, float(f.width) - 4, float(line + 4)}, {{kAmber, pointsMeaning}}, 1);
  if (!fd.at(0, 1).valid || !fd.at(0, side_).valid || !fd.at(1, side_).valid || !fd.at(2, side_).valid)
    return;  // measure() makes them
  const int modes[4] = {kOne, kRegular, kJitterGlobal, kJitterPixel};
  const std::string titles[4] = {narrow ? "1 sample" : "1 sample per pixel", n + " regular",
                                 n + (narrow ? " jitter, global" : " jittered, one pattern"),
                                 n + (narrow ? " jitter, per pixel" : " jittered per pixel")};
  const int numberLines = narrow ? 3 : 2;
  const int blockA = line + h + numberLines * line + 10;  // title, image, numbers
  const int rowA = 2 * line + 2;
  const int rowB = rowA + R * blockA + line;
  const int rowC = rowB + R * (h + g) + line / 2;
  // A caption band: the column's width and half a gap each side, in the frame.
  auto band = [&](int x, float y, float h2) {
    return L::Box{std::max(0.0f, float(x - g / 2)), y, std::min(float(f.width), float(x + w + g / 2)), y + h2};
  };
  for (int k = 0; k < 4; ++k) {
    const Result& res = modes[k] == kOne ? fd.at(0, 1)
                                         : fd.at(modes[k] == kRegular        ? 0
                                                 : modes[k] == kJitterGlobal ? 1
                                                                             : 2,
                                                 side_);
    int x = left + (k % cols) * (w + g), r = k / cols;
    int ya = rowA + r * blockA + line, yb = rowB + r * (h + g);
    addImage(f, std::string("image_") + kModeNames[modes[k]], {x, ya, w, h}, res.texture);
    addImage(f, std::string("error_") + kModeNames[modes[k]], {x, yb, w, h}, res.errorTexture);
    L::caption(f, band(x, float(ya - line), float(line)), titles[k], kWhite, 1);
    L::Column numbers(f, band(x, float(ya + h + 4), float(numberLines * line + 6)));
    const std::string key = std::string("[") + modeKey(modes[k]) + "]";
    numbers.add("RMS error " + num("rms" + key), kAmber, 1);
    if (narrow) {
      numbers.add("aliasing " + num("aliasing" + key), kAmber, 1);
      numbers.add("noise " + num("noise" + key), kAmber, 1);
    } else {
      numbers.add("aliasing " + num("aliasing" + key) + "  noise " + num("noise" + key), kAmber, 1);
    }
  }
  L::caption(f, {4, float(rowB - line - 2), float(f.width) - 4, float(rowB - 1)},
             "error against the reference, x3 (orange: too bright, blue: too dark)", kGrey, 1);
  // Bottom rows: the reference, then the sample patterns of Figure VI.7.
  const int box = std::max(16, h - line);
  const int patterns[3] = {kRegular, kJitterGlobal, kJitterPixel};
  for (int k = 0; k < 4; ++k) {
    int x = left + (k % cols) * (w + g), y = rowC + (k / cols) * (h + 2 * line + 8);
    if (k == 0) {
      addImage(f, "image_reference", {x, y, w, h}, fd.reference.texture);
      L::caption(f, band(x, float(y + h + 4), float(line)), "reference: 16x16 stratified", kWhite, 1);
    } else {
      addPattern(f, canvas, {x + (w - box) / 2, y, box, box}, patterns[k - 1], side_, true, float(w + g));
    }
  }
}

inline ts::Rect Views::addPlot(ts::Frame& f, ts::Rect area, const std::string& title, bool aliasing, const Found& fd,
                               int scale) const {
  namespace plot = ts::plot;
  plot::Spec p;
  p.id = aliasing ? "plot_aliasing" : "plot_rms";
  p.title = title;
  p.xLabel = "samples per pixel";
  p.titleColor = kWhite, p.textColor = kGrey;
  p.scale = scale;
  p.y1 = 0;  // the largest value, then rounded up
  for (int kind = 0; kind < 3; ++kind) {
    plot::Series curve(std::string("series_") + kKindKeys[kind], kSeriesColour[kind]),
        marks(std::string("points_") + kKindKeys[kind], kSeriesColour[kind], plot::Mark::Squares, {}, 1.0f, 3.5f);
    for (int side = 1; side <= kMaxSide; ++side) {
      const jitter::ErrorStats& s = fd.at(kind, side).stats;
      curve.points.push_back({side * side, aliasing ? s.aliasing : s.rms});
      p.y1 = std::max(p.y1, curve.points.back().y);
    }
    marks.points = curve.points;
    p.series.insert(p.series.end(), {curve, marks});
  }
  // A round step giving at most six intervals, the top a little over the largest value.
  double step = 0.01;
  for (double c : {0.005, 0.01, 0.02, 0.025, 0.05, 0.1})
    if (p.y1 / c <= 6) {
      step = c;
      break;
    }
  p.x1 = 17, p.y1 = std::max(step, step * std::ceil(p.y1 * 1.08 / step));
  for (int side = 1; side <= kMaxSide; ++side) p.xTicks.push_back({double(side * side), std::to_string(side * side)});
  p.yTicks = plot::ticks(0, p.y1, step, step < 0.01 ? "%.3f" : "%.2f");
  return plot::draw(f, p, area);
}

inline void Views::buildPlot(ts::Frame& f, const Found& fd) const {
  namespace L = ts::layout;
  // The two plots side by side (a wide window) or one over the other, the
  // table under them; the text at the scale a plot's area asks for, the
  // table's at the largest scale at most that whose columns hold its rows
  // on one line each.
  struct Place {
    int line, tableScale, tableLine;
    float nameW, colW;
    bool twoLines;
    int plotsH;
  };
  auto placeAt = [&](int sc) {
    Place p;
    p.line = int(L::lineHeight(sc));
    // The table: one row per pattern, RMS / aliasing at 1, 4, 9, 16 (on two
    // lines, RMS then aliasing, when the columns are too narrow for both).
    for (p.tableScale = sc; p.tableScale >= 1; --p.tableScale) {
      const int t = p.tableScale;
      // (the names are keys: a swatch as tall as the text before each)
      p.nameW = std::min(ts::text::height(t) + 4.0f * float(t) + ts::text::width(kKindTitles[1], t) + 12,
                         float(f.width) / 3);
      p.colW = std::min(150.0f * float(t), (float(f.width) - 16 - p.nameW) / 4.0f);
      p.twoLines = p.colW < ts::text::width("0.0000 / 0.0000", t) + 8;
      // Above scale 1 only on one line a row: the plots, the figure's claim, keep the height.
      if (t == 1 ||
          (!p.twoLines && ts::text::height(t) + 4.0f * float(t) + ts::text::width(kKindTitles[1], t) <= p.nameW - 4))
        break;
    }
    p.tableLine = int(L::lineHeight(p.tableScale));
    const int tableH = (p.twoLines ? 7 : 4) * p.tableLine + 8;
    p.plotsH = std::max(60, f.height - 2 * p.line - tableH);
    return p;
  };
  auto plotArea = [&](const Place& p) {
    return f.width >= f.height ? ts::Rect{0, 2 * p.line, f.width / 2, p.plotsH}
                               : ts::Rect{0, 2 * p.line, f.width, p.plotsH / 2};
  };
  // The scale the plots' data areas ask for, each laid out on a scratch frame (the wider title).
  const int sc = L::fitScale([&](int s) {
    ts::Frame scratch = L::blankFrame(f.width, f.height);
    return addPlot(scratch, plotArea(placeAt(s)), "aliasing (the predictable part)", true, fd, s);
  });
  const Place pl = placeAt(sc);
  const int line = pl.line, plotsH = pl.plotsH;
  const float nameW = pl.nameW, colW = pl.colW;
  const bool twoLines = pl.twoLines;
  L::caption(f, {4, 6, float(f.width) - 4, float(6 + line)},
             "Figure VI.7  error against a " +
                 L::given("reference samples per pixel", double(jitter::kReferenceSide * jitter::kReferenceSide),
                          "%g") +
                 "-sample reference, seed " + L::given("seed", seed_, "%g"),
             kWhite, sc);
  for (const auto& row : fd.results)
    for (const Result& res : row)
      if (!res.valid) return;  // measure() makes them (view=plot)
  if (f.width >= f.height) {
    addPlot(f, {0, 2 * line, f.width / 2, plotsH}, "RMS error (1 = full scale)", false, fd, sc);
    addPlot(f, {f.width / 2, 2 * line, f.width - f.width / 2, plotsH}, "aliasing (the predictable part)", true, fd, sc);
  } else {
    addPlot(f, {0, 2 * line, f.width, plotsH / 2}, "RMS error (1 = full scale)", false, fd, sc);
    addPlot(f, {0, 2 * line + plotsH / 2, f.width, plotsH - plotsH / 2}, "aliasing (the predictable part)", true, fd,
            sc);
  }
  float y = float(2 * line + plotsH + 4);
  const float x0 = std::max(8.0f, (float(f.width) - nameW - 4 * colW) / 2.0f);
  auto cell = [&](float x, float w2, const L::Text& text, glm::vec4 c) {
    L::caption(f, {x, y, x + w2 - 4, y + float(pl.tableLine)}, text, c, pl.tableScale, ts::Align::Left);
  };
  cell(x0, nameW, twoLines ? "RMS, aliasing" : "RMS error / aliasing", kGrey);
  for (int side = 1; side <= kMaxSide; ++side)
    cell(x0 + nameW + colW * float(side - 1), colW, std::to_string(side * side) + (side == 1 ? " sample" : " samples"),
         kGrey);
  for (int kind = 0; kind < 3; ++kind) {
    y += float(pl.tableLine);
    // The row's name is the key of its colour in both plots: a swatch and the name.
    L::legend(f, {x0, y, x0 + nameW, y + float(pl.tableLine)}, {{kSeriesColour[kind], kKindTitles[kind]}},
              pl.tableScale);
    for (int side = 1; side <= kMaxSide; ++side) {
      const std::string key = std::string("[") + kKindKeys[kind] + "_" + std::to_string(side) + "x" +
                              std::to_string(side) + "]";
      cell(x0 + nameW + colW * float(side - 1), colW,
           twoLines ? num("rms" + key) : num("rms" + key) + " / " + num("aliasing" + key), kSeriesColour[kind]);
    }
    if (twoLines) {
      y += float(pl.tableLine);
      for (int side = 1; side <= kMaxSide; ++side)
        cell(x0 + nameW + colW * float(side - 1), colW,
             num(std::string("aliasing[") + kKindKeys[kind] + "_" + std::to_string(side) + "x" + std::to_string(side) +
                 "]"),
             kSeriesColour[kind]);
    }
  }
}

// The zone view: the three GL renders of the zone plate (frequency rising
// upwards, 2x), the onset marked on each, and the alias curves with the
// threshold and the onsets.
inline void Views::buildZone(ts::Frame& f, ts::Panel& canvas, const Found& fd) const {
  namespace L = ts::layout;
  namespace plot = ts::plot;
  const int line = int(L::lineHeight(1));
  L::caption(f, {4, 4, float(f.width) - 4, float(line + 4)},
             "Figure VI.7  where aliasing sets in: a zone plate, " +
                 L::given("lowest frequency (the sweep's step)", zone::kStep, "%g") + " to " +
                 L::given("highest frequency", zone::kMaxF, "%g") + " cycles per pixel upwards",
             kWhite, 1);
  const zone::Plate& z = fd.zone;
  if (!z.valid) return;  // measure() makes it
  const std::string nn = std::to_string(z.n) + "x" + std::to_string(z.n);
  const std::string titles[3] = {"1 sample", nn + " regular", nn + " jittered"};
  const std::string onsetNames[3] = {"alias_onset_gl[1x1]", "alias_onset_gl[" + nn + "]",
                                     "alias_onset_gl[jitter_pixel_" + nn + "]"};
  const glm::vec4 colours[3] = {kSeriesColour[0], kSeriesColour[1], kSeriesColour[2]};
  // The images: as large as the height allows in whole zooms (at most 2x),
  // or scaled down (filtered) in a window too low for 1:1.
  const int imgH = z.images[0].height, imgW = z.images[0].width;
  const double room = double(f.height - 5 * line) / std::max(1, imgH);
  const double zoom = room >= 1 ? std::min(2.0, std::floor(room)) : std::max(0.1, room);
  const int w = std::max(1, int(imgW * zoom)), h = std::max(1, int(imgH * zoom)), top = 3 * line, gap = 28, left = 56;
  std::vector<glm::vec2> onsetLines[3];
  for (int k = 0; k < 3; ++k) {
    const int x = left + k * (w + gap);
    ts::TextureDesc t = renderedImageTexture(z.images[size_t(k)], "jitter_render", "zone_plate", "jitter",
                                             {{"samples", titles[k]}});
    if (zoom < 1) t.minFilter = GL_LINEAR;
    f.panels.push_back(ts::layout::texturePanel("zone_" + std::to_string(k), {x, top, w, h}, f.addTexture(t)));
    // (not over the frequency scale left of the first image)
    L::caption(f, {float(std::max(left, x - gap / 2)), float(top - line - 2), float(x + w + gap / 2), float(top - 2)},
               titles[k], colours[k], 1);
    const double onset = z.sweeps[size_t(k)].onset;
    if (onset > 0) {  // the bottom edge of the onset's band
      const float y = float(top + h) - float((onset / zone::kStep - 1) * zone::kGlBandRows * (double(h) / imgH));
      onsetLines[k] = {{float(x - 6), y}, {float(x + w + 6), y}};
      L::caption(f, {float(x - gap / 2), float(top + h + 4), float(x + w + gap / 2), float(top + h + 4 + line)},
                 "onset " + num(onsetNames[k], "%.2f"), colours[k], 1);
    }
  }
  // The frequency scale left of the images.
  for (double fr : {0.5, 1.0, 1.5, 2.0, 2.5, 3.0}) {
    const float y = float(top + h) - float((fr / zone::kStep) * zone::kGlBandRows * (double(h) / imgH));
    L::caption(f, {4, y - line / 2.0f, float(left - 6), y + line / 2.0f},
               L::given("frequency, cycles per pixel", fr, "%.1f"), kGrey, 1, ts::Align::Right);
  }
  for (int k = 0; k < 3; ++k)
    if (!onsetLines[k].empty()) canvas.batches.push_back(ts::lineSegments(onsetLines[k], colours[k], 2.0f, "onset"));
  // The alias curves.
  plot::Spec p;
  p.id = "plot_alias";
  p.title = "alias / box-filtered signal (RMS)";
  p.xLabel = "cycles per pixel";
  p.titleColor = kWhite, p.textColor = kGrey;
  p.x0 = 0, p.x1 = zone::kMaxF, p.y0 = 0, p.y1 = 2;
  p.xTicks = plot::ticks(0, zone::kMaxF, 0.5, "%.1f");
  p.yTicks = plot::ticks(0, 2, 0.5, "%.1f");
  for (int k = 0; k < 3; ++k) {
    plot::Series curve(std::string("alias_") + (k == 0 ? "one" : k == 1 ? "regular" : "jitter_pixel"), colours[k]);
    const zone::Sweep& sw = z.sweeps[size_t(k)];
    for (size_t q = 0; q < sw.f.size(); ++q) {
      if (q > 0 && sw.f[q] - sw.f[q - 1] > 1.5 * zone::kStep) {  // a gap (skipped bands): a new strip
        p.series.push_back(curve);
        curve.points.clear();
      }
      curve.points.push_back({sw.f[q], std::min(sw.rho[q], p.y1)});
    }
    p.series.push_back(curve);
    p.legend.push_back({titles[k], colours[k]});
    if (sw.onset > 0) p.markers.push_back({sw.onset, colours[k], "onset", num(onsetNames[k], "%.2f")});
  }
  p.series.push_back(plot::Series("threshold", kGrey, plot::Mark::Line,
                                  {{0, zone::kThreshold}, {zone::kMaxF, zone::kThreshold}}, 1.0f));
  const int px = left + 3 * (w + gap) + 8;
  plot::draw(f, p, {px, 2 * line, f.width - px - 4, f.height - 2 * line - 4});
}
}  // namespace jitter::views
