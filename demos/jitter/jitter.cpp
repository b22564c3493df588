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
//   m  mode: one | regular | jitter-global | jitter-pixel | reference | random
//      (random: n x n points anywhere in the pixel, one shader pass like jitter-pixel; they cluster)
//   + / -  samples per side n (1..4)      s / S  seed up / down
//   v  view: mode (one image large) | compare (the figure) | plot (error vs n) | zone (a
//      zone plate rendered with 1, n x n regular and n x n jittered samples; where its alias sets in)
//   e  show the image's error against the reference instead of the image
// Flag only: --average auto|accum|fbo (how the passes are averaged).
//
// What the GL does (jitter_gl.hpp): regular and jitter-global are n*n passes
// of groundPass, each drawn by common/gl/render.cpp: Renderer::draw with the
// projection shifted by its sample's offset (glMatrixMode(GL_PROJECTION);
// glLoadMatrixf(pixelShift · P), the Red Book's accPerspective), summed by
// accumulateWithAccumBuffer: glAccum(GL_LOAD, 1/n²) for the first pass,
// glAccum(GL_ACCUM, 1/n²) for the others, glAccum(GL_RETURN, 1) (or by
// accumulateWithFbo on the CPU).  jitter-pixel is one full-viewport pass of
// a fragment shader that hashes (seed, pixel, sample) and averages its n x n
// colourAt() calls.  Both shade the analytic checkerboard in GLSL, no
// texture lookups: no filtering enters.  The passes run in measure() and
// are not in the listings: book_figures/vi7_jitter.gl.txt shows the finished
// 288 x 192 images drawn as GL_NEAREST textures, vi7_error_vs_samples.gl.txt
// only the plot.
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

#include "common/gl/context.hpp"
#include "common/core/error.hpp"
#include "common/gl/render.hpp"
#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "jitter_gl.hpp"
#include "jitter_math.hpp"
#include "jitter_views.hpp"
#include "jitter_zone.hpp"

namespace {
using jitter::Pattern;

using namespace jitter::views;  // the modes, the results and their drawing
enum View { kViewMode, kViewCompare, kViewPlot, kViewZone };
enum Average { kAuto, kAccum, kFbo };
constexpr Pattern kKinds[4] = {Pattern::Regular, Pattern::JitterGlobal, Pattern::JitterPixel,
                               Pattern::Random};  // kKindKeys

using ts::layout::fmt;

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
    o.addEnum("mode", &mode_,
              {kModeNames[0], kModeNames[1], kModeNames[2], kModeNames[3], kModeNames[4], kModeNames[5]},
              "one sample | regular n x n | jittered, one pattern for all pixels | jittered per pixel | reference | "
              "pure random n x n per pixel",
              'm');
    o.addInt("samples", &side_, 1, kMaxSide, "samples per side of a pixel, n (n x n per pixel; the book: 3)", '+', '-');
    o.addInt("seed", &seed_, 0, 1000000, "seed of the jitter (the hash of seed, pixel and sample)", 's', 'S');
    o.addEnum("view", &view_, {"mode", "compare", "plot", "zone"},
              "mode: the current mode large; compare: every mode and the sample patterns; plot: error vs n; "
              "zone: where aliasing sets in on a zone plate",
              'v');
    o.addBool("error", &showError_, "show the error against the reference (orange brighter, blue darker, x3)", 'e');
    o.addEnum("average", &average_, {"auto", "accum", "fbo"},
              "how the passes are averaged: glAccum when the context has an accumulation buffer (auto), or FBO "
              "averaging");
  }

  std::vector<ts::FigureSpec> figures() const override { return figureSpecs(); }  // jitter_views.hpp

  ts::Measurements measure(ts::Renderer& r) override;
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;

 private:
  using Result = jitter::views::Result;
  using Found = jitter::views::Found;
  void prepare(ts::Renderer& r);
  void ensure(ts::Renderer& r, int kind, int side);
  Result& result(int kind, int side) { return kind == 3 ? found_.random[size_t(side - 1)] : found_.at(kind, side); }
  // The drawing (jitter_views.hpp) for the current flags.
  // (their numbers printed from `m`, so each label names the measurement it shows).
  Views views(const ts::Measurements& m) const {
    Views v{mode_, side_, seed_, showError_};
    v.measured = &m;
    return v;
  }

  int mode_ = kJitterPixel, side_ = 3, seed_ = 1, view_ = kViewMode, average_ = kAuto;
  bool showError_ = false;

  // What measure() computed, for which seed and averaging.
  bool accum_ = false;
  bool coarse_ = false;  // prepare() makes the first stage's coarse reference
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
    // coarse_: a window's first stage (measure()) stands in 4 x 4 jittered
    // samples a pixel for the reference's 16 x 16, a sixteenth of the work.
    reference_ = coarse_ ? jitter::renderCpu(cam, Pattern::JitterPixel, 4, jitter::kReferenceSeed)
                         : jitter::renderCpu(cam, Pattern::Reference, jitter::kReferenceSide, 0);
    ts::Image ref(cam.width, cam.height);
    for (size_t p = 0; p < size_t(cam.width) * size_t(cam.height); ++p)
      for (int ch = 0; ch < 3; ++ch)
        ref.pixels[p * 4 + size_t(ch)] = uint8_t(std::lround(reference_.rgb[p * 3 + size_t(ch)]));
    Result& res = found_.reference;
    res.image = ref;
    res.error = jitter::errorImage(ref.pixels.data(), reference_);
    res.stats = jitter::analyse(res.error, cam.width, cam.height);
    res.texture = imageTexture(ref, "reference", {{"samples", "16x16 stratified"}});
    res.errorTexture = errorTexture(res);
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
  for (Result& res : found_.random) res = Result();
  preparedSeed_ = seed_;
  preparedAverage_ = average_;
}

void Jitter::ensure(ts::Renderer& r, int kind, int side) {
  Result& res = result(kind, side);
  if (res.valid) return;
  const jitter::Camera cam;
  const uint32_t seed = uint32_t(seed_);
  const bool shader = kKinds[kind] == Pattern::JitterPixel || kKinds[kind] == Pattern::Random;
  if (shader) {  // one pass: jittered (or pure random) points per pixel, hashed in the fragment shader
    res.image = r.renderOffscreen(jitter::pixelJitterPass(cam, side, seed, -1, kKinds[kind] == Pattern::Random));
  } else {
    std::vector<ts::Frame> passes;
    // Each offset o becomes the projection's shift: glLoadMatrixf(pixelShift(o) P) in Renderer::draw.
    for (glm::dvec2 o : jitter::passOffsets(kKinds[kind], side, seed)) passes.push_back(jitter::groundPass(cam, o));
    res.image = accum_ ? jitter::accumulateWithAccumBuffer(r, passes) : jitter::accumulateWithFbo(r, passes);
  }
  res.error = jitter::errorImage(res.image.pixels.data(), reference_);
  res.stats = jitter::analyse(res.error, cam.width, cam.height);
  std::string n = std::to_string(side) + "x" + std::to_string(side);
  res.texture = imageTexture(res.image, kKindKeys[kind],
                             {{"samples", n},
                              {"seed", kKinds[kind] == Pattern::Regular ? "-" : std::to_string(seed_)},
                              {"averaging", shader   ? "shader"
                                            : accum_ ? "glAccum"
                                                     : "fbo"}});
  res.errorTexture = errorTexture(res);
  res.valid = true;
}

ts::Measurements Jitter::measure(ts::Renderer& r) {
  // A window's first measurement comes in two stages (ts::measureStage):
  // the pictures GL draws at once, their errors against the coarse stand-in
  // for the reference (prepare); then all again against the reference.
  if (ts::measureStaged() && reference_.rgb.empty()) {
    coarse_ = true;
    prepare(r);
    ensure(r, 0, 1);
    for (int kind = 0; kind < 4; ++kind) ensure(r, kind, side_);
    ts::Measurements first;
    found_.coarse = true;
    first.detail = found_;
    found_.coarse = false;
    coarse_ = false;
    reference_ = jitter::FloatImage();
    preparedSeed_ = -1;
    ts::measureStage(std::move(first));
  }
  if (preparedSeed_ != seed_ || preparedAverage_ != average_) prepare(r);
  // The images this state shows and prints: the four modes at n, and in the
  // plot view every pattern at n = 1..4.
  // (A window shows the progress; a newer key stops the passes here.)
  const double passes = view_ == kViewPlot ? 5 + 3 * kMaxSide : 5;
  ensure(r, 0, 1);
  for (int kind = 0; kind < 4; ++kind) ts::measureProgress((1 + kind) / passes), ensure(r, kind, side_);
  if (view_ == kViewPlot)
    for (int kind = 0; kind < 3; ++kind)
      for (int side = 1; side <= kMaxSide; ++side)
        ts::measureProgress((5 + kind * kMaxSide + side - 1) / passes), ensure(r, kind, side);
  ts::Measurements out;
  const std::string n = std::to_string(side_) + "x" + std::to_string(side_);
  struct Row {
    const char* key;
    const Result* res;
    std::string what;
  } rows[] = {{"one", &result(0, 1), "1 sample at the pixel centre"},
              {"regular", &result(0, side_), n + " at the subpixel centres"},
              {"jitter_global", &result(1, side_), n + " jittered, one pattern for every pixel"},
              {"jitter_pixel", &result(2, side_), n + " jittered independently per pixel"},
              {"random", &result(3, side_), n + " pure random points per pixel (GL, as jitter_pixel)"}};
  for (const Row& row : rows) {
    std::string k = std::string("[") + row.key + "]";
    out.push_back(
        {"rms" + k, row.res->stats.rms, "RMS error vs the 256-sample reference (1 = full scale); " + row.what});
    out.push_back({"aliasing" + k, row.res->stats.aliasing,
                   "RMS of the error its 24 neighbours' errors predict: interference, moire"});
    out.push_back({"noise" + k, row.res->stats.noise, "RMS of the unpredictable rest: grain"});
  }
  // The mode and compare views draw nothing below this line: in a window,
  // their whole picture goes out now, as a second stage (not coarse), and
  // the CPU model's and the zone plate's numbers follow in the panel.
  if (ts::measureStaged() && (view_ == kViewMode || view_ == kViewCompare)) {
    ts::Measurements shown = out;
    shown.detail = found_;
    ts::measureStage(std::move(shown));
  }
  // Pure random sampling against jittered (jitter_math.hpp, the CPU model).
  for (Pattern p : {Pattern::Random, Pattern::JitterPixel})
    out.push_back({std::string("rms_cpu[") + (p == Pattern::Random ? "random" : "jitter_pixel") + "_" + n + "]",
                   jitter::cpuRms(p, side_, uint32_t(seed_), reference_),
                   p == Pattern::Random
                       ? "RMS error, n x n points anywhere in the pixel (pure random: they cluster), CPU"
                       : "RMS error, n x n jittered per pixel, the same CPU model"});
  jitter::zoneMeasure(r, out, side_, uint32_t(seed_), &found_.zone);  // the zone plate's aliasing onset
  if (view_ == kViewPlot)
    for (int kind = 0; kind < 3; ++kind)
      for (int side = 1; side <= kMaxSide; ++side) {
        std::string k = std::string("[") + kKindKeys[kind] + "_" + std::to_string(side) + "x" + std::to_string(side) +
                        "]";
        out.push_back(
            {"rms" + k, result(kind, side).stats.rms, "RMS error, " + std::to_string(side * side) + " samples"});
        out.push_back({"aliasing" + k, result(kind, side).stats.aliasing, "its predictable part"});
      }
  out.detail = found_;
  return out;
}

ts::Frame Jitter::build(int width, int height, const ts::Measurements& measured) const {
  const Found none, *found = measured.detailAs<Found>();
  const Found& fd = found ? *found : none;
  ts::Frame f = ts::layout::blankFrame(width, height);
  ts::Panel canvas;
  canvas.id = "canvas";
  canvas.viewport = {0, 0, width, height};
  canvas.projection = glm::ortho(0.0f, float(width), float(height), 0.0f, -1.0f, 1.0f);
  if (view_ == kViewCompare) views(measured).buildCompare(f, canvas, fd);
  else if (view_ == kViewPlot) views(measured).buildPlot(f, fd);
  else if (view_ == kViewZone) views(measured).buildZone(f, canvas, fd);
  else views(measured).buildMode(f, canvas, fd);
  f.panels.push_back(canvas);
  return f;
}

}  // namespace

TS_REGISTER_SCENE(Jitter);
