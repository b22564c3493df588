// Figure VI.7 — jittered supersampling, on a checkerboard receding to the
// horizon.
//
// The claim (Buss, VI.1.4): supersampling renders n x n samples per pixel
// (the book: 3 x 3 subpixels) and averages them.  Regular samples at the
// subpixel centres only push aliasing further off; jittering puts one random
// sample inside each subpixel and turns the aliasing (interference, moire:
// coherent patterns) into noise (grain) — but only if the jitter is chosen
// independently for every pixel, "otherwise interference patterns can still
// form".  More samples reduce the noise.
//
// Five images of one scene (an infinite procedural checkerboard under a
// perspective camera), each 288 x 192 whatever the window's size:
//   one            1 sample per pixel, at its centre
//   regular        n x n at the subpixel centres      } the Red Book's method:
//   jitter-global  n x n jittered, the same jitter     } n*n passes with the
//                  for every pixel                     } projection shifted,
//                                                      } glAccum (or FBO averaging)
//   jitter-pixel   n x n jittered independently per pixel (a fragment shader
//                  hashes (seed, pixel, sample))
//   reference      16 x 16 stratified samples per pixel, on the CPU in double
//                  precision (the checkerboard is analytic)
//
// Keys (each is also a flag, see --help):
//   m  mode: one | regular | jitter-global | jitter-pixel | reference
//   + / -  samples per side n (1..4)      s / S  seed up / down
//   v  view: mode (one image large) | compare (the figure) | plot (error vs n)
//   e  show the image's error against the reference instead of the image
// Flag only: --average auto|accum|fbo (how the passes are averaged).
//
// Measured, per mode, against the reference: the RMS error, split into
// "aliasing" — the part of each pixel's error that one linear rule predicts
// from its 24 neighbours' errors: interference patterns repeat, so they are
// predictable — and "noise", the unpredictable rest: grain
// (jitter::analyse; rms^2 = aliasing^2 + noise^2).  The plot view adds the
// RMS and aliasing at n = 1..4 for the three patterns.  Which path averaged
// the multi-pass images — glAccum, or FBO averaging where there is no usable
// accumulation buffer (EGL; Mesa's sRGB GLX visuals) — is printed on stderr
// ("jitter: multi-pass images averaged with glAccum ...") and recorded in the
// sidecar's texture params; the two agree to one 8-bit step, so a window and
// --png show the same picture and numbers whichever each used.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "common/context.hpp"
#include "common/error.hpp"
#include "common/render.hpp"
#include "common/layout.hpp"
#include "common/plot.hpp"
#include "common/scene.hpp"
#include "common/text.hpp"
#include "common/textures.hpp"
#include "jitter_gl.hpp"
#include "jitter_math.hpp"

namespace {
using jitter::Pattern;

enum Mode { kOne, kRegular, kJitterGlobal, kJitterPixel, kReference, kModes };
const char* const kModeNames[] = {"one", "regular", "jitter-global", "jitter-pixel", "reference"};
enum View { kViewMode, kViewCompare, kViewPlot };
enum Average { kAuto, kAccum, kFbo };
constexpr int kMaxSide = 4;

// The three n x n patterns the sweep covers, in the order of the arrays below.
constexpr Pattern kKinds[3] = {Pattern::Regular, Pattern::JitterGlobal, Pattern::JitterPixel};
const char* const kKindKeys[3] = {"regular", "jitter_global", "jitter_pixel"};
const char* const kKindTitles[3] = {"regular", "jittered, one pattern", "jittered per pixel"};

using ts::layout::kWhite, ts::layout::kAmber;
const glm::vec4 kGrey{0.6f, 0.6f, 0.65f, 1.0f};
const glm::vec4 kSeriesColour[3] = {{0.35f, 0.65f, 1.0f, 1.0f}, {1.0f, 0.55f, 0.2f, 1.0f}, {0.4f, 0.9f, 0.45f, 1.0f}};

using ts::layout::fmt;

ts::TextureDesc imageTexture(const ts::Image& img, const std::string& what,
                             std::vector<std::pair<std::string, std::string>> params) {
  return ts::renderedImageTexture(img, "jitter_render", what, "jitter", std::move(params));
}

// Signed error, 3x: orange where the image is brighter than the reference,
// blue where darker, grey where equal.
ts::Image errorPicture(const std::vector<double>& e, int w, int h) {
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

class Jitter final : public ts::Scene {
 public:
  std::string id() const override { return "jitter"; }
  std::string title() const override { return "Figure VI.7 - jittered supersampling"; }
  std::string about() const override {
    return "A checkerboard receding to the horizon, sampled 1 per pixel, n x n at the subpixel centres, n x n\n"
           "jittered with one pattern for all pixels (the Red Book's accumulation buffer), and n x n jittered\n"
           "independently per pixel (the book).  Prints, per mode, the RMS error against a 256-sample reference,\n"
           "split into aliasing (the part of a pixel's error its neighbours' errors predict: interference) and\n"
           "noise (the unpredictable rest: grain).";
  }
  int defaultWidth() const override { return 1024; }
  int defaultHeight() const override { return 560; }
  bool wantsAccumBuffer() const override { return true; }

  std::vector<std::string> claim() const override { return {"aliasing[*"}; }

  void addOptions(ts::Options& o) override {
    o.addEnum("mode", &mode_, {kModeNames[0], kModeNames[1], kModeNames[2], kModeNames[3], kModeNames[4]},
              "one sample | regular n x n | jittered, one pattern for all pixels | jittered per pixel | reference",
              'm');
    o.addInt("samples", &side_, 1, kMaxSide, "samples per side of a pixel, n (n x n per pixel; the book: 3)", '+', '-');
    o.addInt("seed", &seed_, 0, 1000000, "seed of the jitter (the hash of seed, pixel and sample)", 's', 'S');
    o.addEnum("view", &view_, {"mode", "compare", "plot"},
              "mode: the current mode large; compare: every mode and the sample patterns; plot: error vs n", 'v');
    o.addBool("error", &showError_, "show the error against the reference (orange brighter, blue darker, x3)", 'e');
    o.addEnum("average", &average_, {"auto", "accum", "fbo"},
              "how the passes are averaged: glAccum when the context has an accumulation buffer (auto), or FBO "
              "averaging");
  }

  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"vi7_jitter", "Figure VI.7",
         "A checkerboard receding to the horizon, 288x192 pixels each: one sample per pixel; 3x3 samples at the "
         "subpixel centres; 3x3 jittered with one pattern for every pixel (the accumulation buffer); 3x3 jittered "
         "independently per pixel; below, each one's error against a 256-sample reference (x3). Regular samples "
         "and one jitter pattern for all pixels keep interference patterns; jitter chosen per pixel turns them into "
         "grain. Bottom: the reference, and the sample patterns of Figure VI.7: regular; jittered, one pattern for "
         "every pixel; jittered anew in each pixel (2x2 pixels shown).",
         {"--view", "compare", "--samples", "3", "--seed", "1"}, 1320, 760},
        {"vi7_error_vs_samples", "Figure VI.7 (error vs samples)",
         "RMS error against the reference, and its aliasing (the part of each pixel's error its neighbours' errors "
         "predict), for 1, 4, 9 and 16 samples per pixel: "
         "the error falls as samples rise; jitter per pixel leaves almost no aliasing; one jitter pattern for all "
         "pixels keeps much of it (with seed 1 about as much as regular sampling; how much depends on the pattern).",
         {"--view", "plot", "--seed", "1"}, 1024, 600},
    };
  }

  ts::Measurements measure(ts::Renderer& r) override;
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;

 private:
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
    Result reference;
    const Result& at(int kind, int side) const { return results[size_t(kind)][size_t(side - 1)]; }
    Result& at(int kind, int side) { return results[size_t(kind)][size_t(side - 1)]; }
  };
  void prepare(ts::Renderer& r);
  void ensure(ts::Renderer& r, int kind, int side);
  Result& result(int kind, int side) { return found_.at(kind, side); }
  const Result* current(const Found& fd) const;
  static ts::TextureDesc errorTextureOf(const Result& res);

  void addImage(ts::Frame& f, const std::string& id, ts::Rect rect, const ts::TextureDesc& tex) const;
  void addPattern(ts::Frame& f, ts::Panel& canvas, ts::Rect box, int mode, int side, bool labels, float labelW = 0) const;
  void buildMode(ts::Frame& f, ts::Panel& canvas, const Found& fd) const;
  void buildCompare(ts::Frame& f, ts::Panel& canvas, const Found& fd) const;
  void buildPlot(ts::Frame& f, const Found& fd) const;
  void addPlot(ts::Frame& f, ts::Rect area, const std::string& title, bool aliasing, const Found& fd) const;

  int mode_ = kJitterPixel, side_ = 3, seed_ = 1, view_ = kViewMode, average_ = kAuto;
  bool showError_ = false;

  // What measure() computed, for which seed and averaging.
  bool accum_ = false;
  std::string path_, printedPath_;
  int preparedSeed_ = -1, preparedAverage_ = -1;
  jitter::FloatImage reference_;
  Found found_;
};

// Starts over for the current seed and averaging: the reference (once), the
// averaging path; the images themselves are made on demand (ensure).
void Jitter::prepare(ts::Renderer& r) {
  const jitter::Camera cam;
  if (reference_.rgb.empty()) {
    reference_ = jitter::renderCpu(cam, Pattern::Reference, jitter::kReferenceSide, 0);
    ts::Image ref(cam.width, cam.height);
    for (size_t p = 0; p < size_t(cam.width) * size_t(cam.height); ++p)
      for (int ch = 0; ch < 3; ++ch)
        ref.pixels[p * 4 + size_t(ch)] = uint8_t(std::lround(reference_.rgb[p * 3 + size_t(ch)]));
    Result& res = found_.reference;
    res.image = ref;
    res.error = jitter::errorImage(ref.pixels.data(), reference_);
    res.stats = jitter::analyse(res.error, cam.width, cam.height);
    res.texture = imageTexture(ref, "reference", {{"samples", "16x16 stratified"}});
    res.errorTexture = errorTextureOf(res);
    res.valid = true;
  }
  accum_ = false;
  if (average_ != kFbo) {
    jitter::AccumStatus status = jitter::accumStatus(r, cam.width, cam.height);
    if (average_ == kAccum && status != jitter::AccumStatus::Usable)
      throw ts::Error("--average accum: " + jitter::reason(status) + "; use --average auto or fbo");
    accum_ = status == jitter::AccumStatus::Usable;
    path_ = jitter::describe(status);
  } else {
    path_ = "averaged in FBOs (--average fbo)";
  }
  // Which path: a note on stderr (like the backend fallback), once per
  // change; not a measurement, because a window and --png may differ here and
  // still show the same picture (FBO and glAccum agree to one 8-bit step).
  if (path_ != printedPath_) {
    ts::note("jitter: multi-pass images " + path_);
    printedPath_ = path_;
  }
  for (auto& row : found_.results)
    for (Result& res : row) res = Result();
  preparedSeed_ = seed_;
  preparedAverage_ = average_;
}

void Jitter::ensure(ts::Renderer& r, int kind, int side) {
  Result& res = result(kind, side);
  if (res.valid) return;
  const jitter::Camera cam;
  const uint32_t seed = uint32_t(seed_);
  if (kKinds[kind] == Pattern::JitterPixel) {
    res.image = r.renderOffscreen(jitter::pixelJitterPass(cam, side, seed));
  } else {
    std::vector<ts::Frame> passes;
    for (glm::dvec2 o : jitter::passOffsets(kKinds[kind], side, seed)) passes.push_back(jitter::groundPass(cam, o));
    res.image = accum_ ? jitter::accumulateWithAccumBuffer(r, passes) : jitter::accumulateWithFbo(r, passes);
  }
  res.error = jitter::errorImage(res.image.pixels.data(), reference_);
  res.stats = jitter::analyse(res.error, cam.width, cam.height);
  std::string n = std::to_string(side) + "x" + std::to_string(side);
  res.texture = imageTexture(res.image, kKindKeys[kind],
                             {{"samples", n},
                              {"seed", kKinds[kind] == Pattern::Regular ? "-" : std::to_string(seed_)},
                              {"averaging", kKinds[kind] == Pattern::JitterPixel ? "shader"
                                            : accum_                             ? "glAccum"
                                                                                 : "fbo"}});
  res.errorTexture = errorTextureOf(res);
  res.valid = true;
}

const Jitter::Result* Jitter::current(const Found& fd) const {
  const Result* res = &fd.reference;
  switch (mode_) {
    case kOne: res = &fd.at(0, 1); break;
    case kRegular: res = &fd.at(0, side_); break;
    case kJitterGlobal: res = &fd.at(1, side_); break;
    case kJitterPixel: res = &fd.at(2, side_); break;
    default: break;
  }
  return res->valid ? res : nullptr;
}

ts::TextureDesc Jitter::errorTextureOf(const Result& res) {
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

ts::Measurements Jitter::measure(ts::Renderer& r) {
  if (preparedSeed_ != seed_ || preparedAverage_ != average_) prepare(r);
  // The images this state shows and prints: the four modes at n, and in the
  // plot view every pattern at n = 1..4.
  ensure(r, 0, 1);
  for (int kind = 0; kind < 3; ++kind) ensure(r, kind, side_);
  if (view_ == kViewPlot)
    for (int kind = 0; kind < 3; ++kind)
      for (int side = 1; side <= kMaxSide; ++side) ensure(r, kind, side);
  ts::Measurements out;
  const std::string n = std::to_string(side_) + "x" + std::to_string(side_);
  struct Row {
    const char* key;
    const Result* res;
    std::string what;
  } rows[] = {{"one", &result(0, 1), "1 sample at the pixel centre"},
              {"regular", &result(0, side_), n + " at the subpixel centres"},
              {"jitter_global", &result(1, side_), n + " jittered, one pattern for every pixel"},
              {"jitter_pixel", &result(2, side_), n + " jittered independently per pixel"}};
  for (const Row& row : rows) {
    std::string k = std::string("[") + row.key + "]";
    out.push_back({"rms" + k, row.res->stats.rms, "RMS error vs the 256-sample reference (1 = full scale); " + row.what});
    out.push_back({"aliasing" + k, row.res->stats.aliasing,
                   "RMS of the error its 24 neighbours' errors predict: interference, moire"});
    out.push_back({"noise" + k, row.res->stats.noise, "RMS of the unpredictable rest: grain"});
  }
  if (view_ == kViewPlot)
    for (int kind = 0; kind < 3; ++kind)
      for (int side = 1; side <= kMaxSide; ++side) {
        std::string k = std::string("[") + kKindKeys[kind] + "_" + std::to_string(side) + "x" + std::to_string(side) + "]";
        out.push_back({"rms" + k, result(kind, side).stats.rms, "RMS error, " + std::to_string(side * side) + " samples"});
        out.push_back({"aliasing" + k, result(kind, side).stats.aliasing, "its predictable part"});
      }
  out.detail = found_;
  return out;
}

// ---------------------------------------------------------------- drawing
void Jitter::addImage(ts::Frame& f, const std::string& id, ts::Rect rect, const ts::TextureDesc& tex) const {
  ts::TextureDesc t = tex;
  // Pixel-exact at 1:1; scaled down (a small window) it is filtered.
  if (rect.w < t.image->width || rect.h < t.image->height) t.minFilter = GL_LINEAR;
  int index = -1;
  for (size_t i = 0; i < f.textures.size(); ++i)
    if (f.textures[i].key() == t.key() && f.textures[i].minFilter == t.minFilter) index = int(i);
  if (index < 0) index = f.addTexture(t);
  f.panels.push_back(ts::layout::texturePanel(id, rect, index));
}

// A pixel square of `box` (canvas pixels, y down) with its subpixel grid and
// the sample points of `mode` (jitter-pixel: a 2 x 2 block of pixels, each
// with its own jitter).
void Jitter::addPattern(ts::Frame& f, ts::Panel& canvas, ts::Rect box, int mode, int side, bool labels,
                        float labelW) const {
  const int n = mode == kOne ? 1 : mode == kReference ? jitter::kReferenceSide : side;
  const int cells = mode == kJitterPixel ? 2 : 1;
  const float cell = float(box.w) / float(cells);
  std::vector<glm::vec2> grid, border, dots;
  for (int cy = 0; cy < cells; ++cy)
    for (int cx = 0; cx < cells; ++cx) {
      float x0 = float(box.x) + cx * cell, y0 = float(box.y) + cy * cell;
      border.insert(border.end(), {{x0, y0}, {x0 + cell, y0}, {x0 + cell, y0}, {x0 + cell, y0 + cell},
                                   {x0 + cell, y0 + cell}, {x0, y0 + cell}, {x0, y0 + cell}, {x0, y0}});
      if (mode != kOne && n <= 8)
        for (int k = 1; k < n; ++k) {
          float t = float(k) / float(n) * cell;
          grid.insert(grid.end(), {{x0 + t, y0}, {x0 + t, y0 + cell}, {x0, y0 + t}, {x0 + cell, y0 + t}});
        }
      // The pixel shown: for jitter-pixel, (100 + cx, 100 + 1 - cy) of the image (GL rows from the bottom).
      const int pi = 100 + cx, pj = 100 + (cells - 1 - cy);
      Pattern p = mode == kJitterGlobal ? Pattern::JitterGlobal : mode == kJitterPixel ? Pattern::JitterPixel
                  : mode == kReference ? Pattern::Reference : Pattern::Regular;
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
    std::string l1 = mode == kOne ? "1 sample" : mode == kReference ? "16x16 stratified" : mode == kRegular ? nn + " regular"
                                                                                                     : nn + " jittered";
    std::string l2 = mode == kOne ? "the pixel centre"
                     : mode == kRegular ? "subpixel centres"
                     : mode == kJitterGlobal ? "same in every pixel"
                     : mode == kJitterPixel ? "new in every pixel"
                                            : "jittered (the reference)";
    // Under the box, in a band as wide as the box and its margins.
    const float half = (labelW > 0 ? labelW : std::max(float(box.w), 120.0f)) / 2, cx = float(box.x + box.w / 2), y = float(box.y + box.h + 5);
    const ts::layout::Box band{std::max(0.0f, cx - half), y, std::min(float(f.width), cx + half), y + 16};
    ts::layout::caption(f, band, l1, kWhite, 1);
    ts::layout::caption(f, {band.x0, y + 16, band.x1, y + 32}, l2, kGrey, 1);
  }
}

ts::Frame Jitter::build(int width, int height, const ts::Measurements& measured) const {
  const Found none, *found = measured.detailAs<Found>();
  const Found& fd = found ? *found : none;
  ts::Frame f;
  f.width = width;
  f.height = height;
  f.clearColor = {0.12f, 0.12f, 0.14f, 1.0f};
  ts::Panel canvas;
  canvas.id = "canvas";
  canvas.viewport = {0, 0, width, height};
  canvas.projection = glm::ortho(0.0f, float(width), float(height), 0.0f, -1.0f, 1.0f);
  if (view_ == kViewCompare) buildCompare(f, canvas, fd);
  else if (view_ == kViewPlot) buildPlot(f, fd);
  else buildMode(f, canvas, fd);
  f.panels.push_back(canvas);
  return f;
}

void Jitter::buildMode(ts::Frame& f, ts::Panel& canvas, const Found& fd) const {
  namespace L = ts::layout;
  const int W = jitter::kImageW, H = jitter::kImageH, line = 19, top = 2 * line;
  std::string n = std::to_string(side_) + "x" + std::to_string(side_);
  std::string what = mode_ == kOne ? "1 sample per pixel"
                     : mode_ == kRegular ? n + " regular samples per pixel"
                     : mode_ == kJitterGlobal ? n + " jittered, one pattern for all pixels"
                     : mode_ == kJitterPixel ? n + " jittered independently per pixel"
                                             : "reference: 16x16 stratified samples per pixel";
  L::caption(f, {12, 8, float(f.width) - 12, float(top - 2)}, "Figure VI.7: " + what + (showError_ ? "  (error x3)" : ""),
             kWhite, 1, ts::Align::Left);
  // The image as large as the window allows (whole zooms are pixel-exact;
  // a zoom is rounded down to a whole one when that loses little), the
  // sample pattern and the numbers beside it (a wide window) or under it.
  const int sideW = std::min(220, std::max(130, f.width / 4)), under = 200;
  auto fit = [&](int availW, int availH) {
    double s = std::max(0.05, std::min(double(std::max(1, availW)) / W, double(std::max(1, availH)) / H));
    if (s >= 1 && std::floor(s) >= 0.92 * s) s = std::floor(s);
    return s;
  };
  double beside = fit(f.width - sideW - 48, f.height - top - 16), below = fit(f.width - 32, f.height - top - under - 16);
  const bool column = below > beside;
  const double s = column ? below : beside;
  ts::Rect rect{16, top, std::max(1, int(W * s)), std::max(1, int(H * s))};
  const Result* res = current(fd);
  if (res) addImage(f, "image", rect, showError_ ? res->errorTexture : res->texture);
  int x = column ? 16 : rect.x + rect.w + 24, y0 = column ? rect.y + rect.h + 12 : top + 4;
  int room = column ? under - 12 : f.height - y0 - 3 * line - 44;
  int box = std::max(16, std::min({sideW - 20, room - 44, f.height / 3}));
  if (column) x = std::max(16, (f.width - (std::max(box, 160) + 24 + 150)) / 2);  // the pattern, then the numbers beside it
  addPattern(f, canvas, {x, y0, box, box}, mode_, side_, true, 160.0f);
  if (res && mode_ != kReference) {
    // The numbers: right of the pattern in a column layout, under it beside the image.
    float nx = column ? float(x + std::max(box, 160) + 24) : float(x), ny = column ? float(y0) : float(y0 + box + 44);
    L::Column numbers(f, {nx, ny, float(f.width) - 4, float(f.height) - 2});
    numbers.add("RMS error " + fmt("%.4f", res->stats.rms), kAmber, 1, ts::Align::Left);
    numbers.add("aliasing  " + fmt("%.4f", res->stats.aliasing), kAmber, 1, ts::Align::Left);
    numbers.add("noise     " + fmt("%.4f", res->stats.noise), kAmber, 1, ts::Align::Left);
  }
}

void Jitter::buildCompare(ts::Frame& f, ts::Panel& canvas, const Found& fd) const {
  namespace L = ts::layout;
  const int W = jitter::kImageW, H = jitter::kImageH, line = 17, gap = 24;
  // At 1:1 the figure needs four images and three gaps across, three images
  // and ten lines of text down; a smaller frame (a window) scales the images.
  // A tall window puts two columns across, each row of four in two rows.
  auto scaleFor = [&](int cols, int numberLines) {
    const int R = 4 / cols;
    const int textH = 2 * line + 2 + R * ((numberLines + 1) * line + 10) + 2 * line + R * (2 * line) + 8;
    return std::min({1.0, double(f.width - 16 - (cols - 1) * gap) / (cols * W), double(f.height - textH) / (3 * R * H)});
  };
  int cols = scaleFor(2, 3) > scaleFor(4, 2) * 1.05 ? 2 : 4;
  double s = scaleFor(cols, 2);
  const bool narrow = W * s < 220;  // the numbers take three lines instead of two
  if (narrow) s = scaleFor(cols, 3);
  const int R = 4 / cols;
  const int w = std::max(1, int(W * s)), h = std::max(1, int(H * s)), g = std::max(6, int(gap * s));
  const int left = std::max(0, (f.width - (cols * w + (cols - 1) * g)) / 2);
  const std::string n = std::to_string(side_) + "x" + std::to_string(side_);
  L::caption(f, {4, 4, float(f.width) - 4, float(line + 4)},
             "Figure VI.7  jittered supersampling: " + n + " samples per pixel, seed " + std::to_string(seed_), kWhite, 1);
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
                                         : fd.at(modes[k] == kRegular ? 0 : modes[k] == kJitterGlobal ? 1 : 2, side_);
    int x = left + (k % cols) * (w + g), r = k / cols;
    int ya = rowA + r * blockA + line, yb = rowB + r * (h + g);
    addImage(f, std::string("image_") + kModeNames[modes[k]], {x, ya, w, h}, res.texture);
    addImage(f, std::string("error_") + kModeNames[modes[k]], {x, yb, w, h}, res.errorTexture);
    L::caption(f, band(x, float(ya - line), float(line)), titles[k], kWhite, 1);
    L::Column numbers(f, band(x, float(ya + h + 4), float(numberLines * line + 6)));
    numbers.add("RMS error " + fmt("%.4f", res.stats.rms), kAmber, 1);
    if (narrow) {
      numbers.add("aliasing " + fmt("%.4f", res.stats.aliasing), kAmber, 1);
      numbers.add("noise " + fmt("%.4f", res.stats.noise), kAmber, 1);
    } else {
      numbers.add("aliasing " + fmt("%.4f", res.stats.aliasing) + "  noise " + fmt("%.4f", res.stats.noise), kAmber, 1);
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

void Jitter::addPlot(ts::Frame& f, ts::Rect area, const std::string& title, bool aliasing, const Found& fd) const {
  namespace plot = ts::plot;
  plot::Spec p;
  p.id = aliasing ? "plot_aliasing" : "plot_rms";
  p.title = title;
  p.xLabel = "samples per pixel";
  p.titleColor = kWhite, p.textColor = kGrey;
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
  plot::draw(f, p, area);
}

void Jitter::buildPlot(ts::Frame& f, const Found& fd) const {
  namespace L = ts::layout;
  const int line = 17;
  L::caption(f, {4, 6, float(f.width) - 4, float(6 + line)},
             "Figure VI.7  error against a 256-sample reference, seed " + std::to_string(seed_), kWhite, 1);
  for (const auto& row : fd.results)
    for (const Result& res : row)
      if (!res.valid) return;  // measure() makes them (view=plot)
  // The table: one row per pattern, RMS / aliasing at 1, 4, 9, 16 (on two
  // lines, RMS then aliasing, when the columns are too narrow for both).
  const float nameW = std::min(170.0f, float(f.width) / 4), colW = std::min(150.0f, (float(f.width) - 16 - nameW) / 4.0f);
  const bool twoLines = colW < ts::text::width("0.0000 / 0.0000", 1) + 8;
  const int tableH = (twoLines ? 7 : 4) * line + 8;
  const int plotsH = std::max(60, f.height - 2 * line - tableH);
  if (f.width >= f.height) {
    addPlot(f, {0, 2 * line, f.width / 2, plotsH}, "RMS error (1 = full scale)", false, fd);
    addPlot(f, {f.width / 2, 2 * line, f.width - f.width / 2, plotsH},
            "aliasing: the predictable part of the error", true, fd);
  } else {
    addPlot(f, {0, 2 * line, f.width, plotsH / 2}, "RMS error (1 = full scale)", false, fd);
    addPlot(f, {0, 2 * line + plotsH / 2, f.width, plotsH - plotsH / 2},
            "aliasing: the predictable part of the error", true, fd);
  }
  float y = float(2 * line + plotsH + 4);
  const float x0 = std::max(8.0f, (float(f.width) - nameW - 4 * colW) / 2.0f);
  auto cell = [&](float x, float w2, const std::string& text, glm::vec4 c) {
    L::caption(f, {x, y, x + w2 - 4, y + float(line)}, text, c, 1, ts::Align::Left);
  };
  cell(x0, nameW, twoLines ? "RMS, aliasing" : "RMS error / aliasing", kGrey);
  for (int side = 1; side <= kMaxSide; ++side)
    cell(x0 + nameW + colW * float(side - 1), colW, std::to_string(side * side) + (side == 1 ? " sample" : " samples"),
         kGrey);
  for (int kind = 0; kind < 3; ++kind) {
    y += float(line);
    cell(x0, nameW, kKindTitles[kind], kSeriesColour[kind]);
    for (int side = 1; side <= kMaxSide; ++side) {
      const jitter::ErrorStats& st = fd.at(kind, side).stats;
      cell(x0 + nameW + colW * float(side - 1), colW,
           twoLines ? fmt("%.4f", st.rms) : fmt("%.4f", st.rms) + " / " + fmt("%.4f", st.aliasing), kSeriesColour[kind]);
    }
    if (twoLines) {
      y += float(line);
      for (int side = 1; side <= kMaxSide; ++side)
        cell(x0 + nameW + colW * float(side - 1), colW, fmt("%.4f", fd.at(kind, side).stats.aliasing), kSeriesColour[kind]);
    }
  }
}
}  // namespace

TM_REGISTER_SCENE(Jitter);
