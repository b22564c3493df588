// Section VI.1.3 — mipmapping, popping, and the over-blur anisotropic
// filtering removes.
//
// The claims (Buss VI.1.3): level k+1 of a mipmap is the 2x2 average of
// level k, and the whole chain costs about a third more memory.  Drawing
// each pixel from the one level nearest the screen resolution makes the
// picture "pop" when the distance changes and the chosen level jumps;
// blending the two nearest levels (trilinear) removes it.  Mipmaps over-blur
// surfaces seen at a slant, where the pixel's footprint is long in one
// texture direction and short in the other: anisotropic filtering addresses
// that.
//
// Views: single — a textured plane facing the eye at a distance (left half
// the texture, right half a texture whose mip levels are coloured, so the
// level GL chose is visible; the outlined square is the probe's size);
// filmstrip — frames 1/4 level apart, the current filter above, trilinear
// below; plot — the mean colour of the probe against distance (steps =
// popping, ramps = none); slant — a ground plane to the horizon: an 8x8
// supersampled reference and the seven filters.
//
// Keys (each is also a flag, see --help):
//   v  view: single | filmstrip | plot | slant      f  minification filter
//   d / D  farther / nearer (log2 distance +-1/8)    b / B  LOD bias +-1/4
//   a / A  max anisotropy +-2 (2..16)                c  levels: texture | colours | split
//   t  texture: labelled grid | checkerboard         g  gamma-correct (linear-light) mip averages
//   m  move: animate the distance (after a 30-frame pause; counted in frames)
//
// The distance: the camera's focal length is 256 pixels and the 256-texel
// texture repeats once per world unit, so at distance d a pixel covers d
// texels and --distance-log2 x is the LOD (mip_math.hpp derives it).
//
// Measured (printed, and on screen), every pass at a fixed size through
// Renderer::renderOffscreen (sweep.hpp): the chain's memory overhead (~1/3);
// the level GL used at the current distance, read back from the coloured
// levels, next to the analytic LOD; the popping measure of every filter —
// the largest jump of the probe's mean colour (coloured levels, 32 x 32
// pixels) between consecutive distances of a sweep in 1/16-level steps; and
// each filter's RMS error in the far field of the slanted plane against the
// supersampled reference (GL at 8x8 the resolution, GL_NEAREST on level 0,
// box-downsampled on the CPU).
//
// What Mesa does (record the renderer with every number): llvmpipe computes
// the LOD as log2(rho^2)/2 with a log2 that is linear between powers of
// two (up to 0.043 level low, so trilinear's blend is not quite linear in
// the LOD), one LOD per 2x2 quad; softpipe takes rho as the largest
// derivative component.  Both filter anisotropically with an EWA on one
// level, floor(LOD): on the coloured probe "anisotropic" switches level at
// integers as abruptly as GL_*_MIPMAP_NEAREST does at k + 1/2 (popping 210),
// though on a real texture the wide EWA kernel hides the switch.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "common/gl.hpp"
#include "common/render.hpp"
#include "common/layout.hpp"
#include "common/plot.hpp"
#include "common/scene.hpp"
#include "common/text.hpp"
#include "common/textures.hpp"
#include "mip_math.hpp"
#include "sweep.hpp"

namespace {
using namespace mipmath;

enum View { kSingle, kFilmstrip, kPlot, kSlant };
enum Levels { kTextureOnly, kColoursOnly, kSplit };

using ts::layout::fmt;

// The window's animation: after kHoldFrames frames at the chosen distance,
// log2 distance moves kStepPerFrame per frame, bouncing between the ends of
// the distance range.  Counted in frames, not seconds, so a given frame
// always shows the same picture (the window tests compare screenshots).
constexpr int kHoldFrames = 30;
constexpr double kStepPerFrame = 1.0 / 64;

class MipmapPopping final : public ts::Scene {
 public:
  std::string id() const override { return "mipmap_popping"; }
  std::string title() const override { return "Section VI.1.3 - mipmapping and popping"; }
  std::string about() const override {
    return "A textured plane facing the eye at a distance you choose (or moving), drawn with any of the\n"
           "minification filters: level k+1 of the mipmap is the book's 2x2 average of level k (optionally in\n"
           "linear light); coloured levels show which level GL chose.  Prints the chain's memory overhead (~1/3),\n"
           "the level observed against the analytic LOD, the popping measure of every filter (the largest jump of\n"
           "a probe's mean colour between consecutive distances, 1/16 level apart) and, for a plane seen at a\n"
           "slant, each filter's far-field error against an 8x8 supersampled reference.";
  }
  int defaultWidth() const override { return 1024; }
  int defaultHeight() const override { return 512; }

  std::vector<std::string> claim() const override { return {"popping_ratio", "mip_overhead"}; }

  void addOptions(ts::Options& o) override {
    o.addEnum("view", &view_, {"single", "filmstrip", "plot", "slant"},
              "single plane | frames at several distances | probe colour vs distance | slanted plane", 'v');
    std::vector<std::string> names;
    for (int f = 0; f < kFilterCount; ++f) names.push_back(filterName(f));
    o.addEnum("filter", &filter_, names, "minification filter (anisotropic = trilinear + max anisotropy)", 'f');
    o.addFloat("distance-log2", &distLog2_, float(kMinLog2), float(kMaxLog2),
               "log2 of the plane's distance; the distance is the texels per pixel, so this is the LOD", 'd', 'D',
               0.125f);
    o.addFloat("lod-bias", &bias_, -4.0f, 4.0f, "GL_TEXTURE_LOD_BIAS added to the LOD", 'b', 'B', 0.25f);
    o.addInt("anisotropy", &aniso_, 2, 16, "GL_TEXTURE_MAX_ANISOTROPY of the anisotropic filter (2..16)", 'a', 'A', 2);
    o.addEnum("levels", &levels_, {"texture", "colours", "split"},
              "the texture | each mip level one colour | left texture, right colours", 'c');
    o.addEnum("pattern", &texture_, {"grid", "checker"}, "labelled grid or checkerboard (256 x 256)", 't');
    picture_.addOption(o, "the pattern (mip chain built from it)");
    camera_.addOptions(o);  // the slanted plane's view
    o.addBool("linear-light", &linearLight_, "average the mip levels in linear light (gamma-correct) instead of sRGB",
              'g');
    o.addBool("animate", &animate_, "window: move the plane to and fro (starts after 30 frames)", 'm');
  }

  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"mip_popping_filmstrip", "Section VI.1.3",
         "A plane facing the eye at eight distances, 1/4 level apart (left half: the texture; right half: a texture "
         "whose mip levels are coloured). Top: GL_NEAREST_MIPMAP_NEAREST uses one level and jumps to the next at "
         "LOD k + 1/2 (popping). Bottom: GL_LINEAR_MIPMAP_LINEAR blends the two nearest levels: the colour, and the "
         "blur, change smoothly.",
         {"--view", "filmstrip", "--filter", "nearest-mipmap-nearest", "--distance-log2", "2.875", "--levels", "split"},
         1024, 400},
        {"mip_popping_plot", "Section VI.1.3",
         "Mean colour of a probe region (coloured mip levels) against log2 distance, in steps of 1/16 level. "
         "GL_NEAREST_MIPMAP_NEAREST (top) steps from one level's colour to the next: popping. "
         "GL_LINEAR_MIPMAP_LINEAR (bottom) ramps between them. The popping measure is the largest jump between "
         "neighbouring distances.",
         {"--view", "plot", "--filter", "nearest-mipmap-nearest", "--distance-log2", "2.875"}, 1024, 640},
        {"mip_anisotropic", "Section VI.1.3",
         "A ground plane seen at a slant: the supersampled reference (8x8 samples of level 0 per pixel) and the "
         "seven filters. GL_NEAREST and GL_LINEAR alias; the mipmap filters choose their level from the long side "
         "of the pixel's footprint and over-blur the distance, most visibly trilinear "
         "(GL_LINEAR_MIPMAP_LINEAR); anisotropic filtering (16) keeps the detail across the view. Numbers: RMS "
         "error against the reference in the far field (LOD 1.5 to 5, between the white lines).",
         {"--view", "slant", "--filter", "linear-mipmap-linear", "--anisotropy", "16", "--levels", "texture"}, 1280,
         640},
    };
  }

  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;
  void update(double) override {
    if (animate_) ++animFrames_;
    else animFrames_ = 0;
  }

 private:
  // The plane's log2 distance as drawn (the option, or the animation).
  double shownLog2() const {
    if (!animate_ || animFrames_ <= kHoldFrames) return distLog2_;
    double span = kMaxLog2 - kMinLog2, x = distLog2_ - kMinLog2 + kStepPerFrame * (animFrames_ - kHoldFrames);
    double p = std::fmod(x, 2 * span);
    return kMinLog2 + (p <= span ? p : 2 * span - p);
  }
  sweep::Look look() const { return {filter_, aniso_, bias_, texture_, linearLight_, &picture_, camera_}; }

  struct Result;  // what measure() found (null: not measured yet)
  void buildSingle(ts::Frame& f, const Result* m) const;
  void buildFilmstrip(ts::Frame& f, const Result* m) const;
  void buildPlot(ts::Frame& f, const Result* m) const;
  void buildSlant(ts::Frame& f, const Result* m) const;

  int view_ = kSingle, filter_ = kNearestMipNearest, aniso_ = 16, levels_ = kSplit, texture_ = 0;
  ts::UserTexture picture_;  // --texture FILE
  ts::OrbitCamera camera_;   // --yaw --pitch --zoom: the mouse, on the slanted plane
  float distLog2_ = 2.375f, bias_ = 0.0f;
  bool linearLight_ = false, animate_ = false;
  long animFrames_ = 0;

};

// What measure() found, for the labels and the plot: measure()'s detail.
struct MipmapPopping::Result {
  double overhead = 0, topLevel = 0;
  double levelObserved = 0, residual = 0;
  std::vector<double> sweepLods;
  std::vector<std::vector<Mean>> sweepMeans;  // [filter][distance]
  double popping[kFilterCount] = {};
    double farError[kFilterCount] = {};
    long farPixels = 0;
    bool anisotropy = false;
    float maxAnisotropy = 0;
    std::string renderer;
};

ts::Frame MipmapPopping::build(int width, int height, const ts::Measurements& measured) const {
  const Result* m = measured.detailAs<Result>();
  ts::Frame f;
  f.width = width;
  f.height = height;
  f.clearColor = {0.12f, 0.12f, 0.14f, 1.0f};
  switch (view_) {
    case kSingle: buildSingle(f, m); break;
    case kFilmstrip: buildFilmstrip(f, m); break;
    case kPlot: buildPlot(f, m); break;
    default: buildSlant(f, m); break;
  }
  return f;
}

using ts::layout::kWhite, ts::layout::kAmber;
const glm::vec4 kGrey{0.75f, 0.75f, 0.78f, 1.0f},
    kBox{0.0f, 0.0f, 0.0f, 0.65f};

// A facing-plane panel: the plane (split or not) at log2 distance x.
void addFacing(ts::Frame& f, ts::Panel& p, double x, const sweep::Look& look, int levels) {
  Camera cam = facingCamera(p.viewport.w, p.viewport.h, facingDistance(x));
  p.projection = cam.projection(p.viewport.w, p.viewport.h);
  p.modelview = cam.modelview();
  if (levels == kTextureOnly || levels == kColoursOnly) {
    int t = f.addTexture(levels == kColoursOnly ? sweep::colouredTexture(look) : sweep::texture(look));
    p.batches.push_back(sweep::facingBatch(facingDistance(x), t, -kPlaneHalf, kPlaneHalf));
  } else {
    int t = f.addTexture(sweep::texture(look)), c = f.addTexture(sweep::colouredTexture(look));
    p.batches.push_back(sweep::facingBatch(facingDistance(x), t, -kPlaneHalf, 0));
    p.batches.push_back(sweep::facingBatch(facingDistance(x), c, 0, kPlaneHalf));
  }
}

std::string levelText(int filter, double lambda) {
  if (!usesMipmaps(filter)) return "level 0 (no mipmaps)";
  if (lambda <= 0) return "level 0 (magnified)";
  if (blendsLevels(filter)) {
    LevelBlend b = linearLevels(lambda);
    if (b.lo == b.hi) return "level " + std::to_string(b.lo);
    return "levels " + std::to_string(b.lo) + "+" + std::to_string(b.hi) + " (" + fmt("%.0f", 100 * b.weight) + "% of " +
           std::to_string(b.hi) + ")";
  }
  return "level " + std::to_string(nearestLevel(lambda));
}

void MipmapPopping::buildSingle(ts::Frame& f, const Result* m) const {
  const int w = f.width, h = f.height;
  const int scale = std::max(1, std::min(2, std::min(w / 560, h / 300)));
  const int line = int(ts::text::height(scale)) + 6 * scale;
  const double x = shownLog2();
  ts::Panel p;
  p.id = "plane";
  p.viewport = {0, 0, w, h};
  addFacing(f, p, x, look(), levels_);
  // The probe region of the popping measure, 32 x 32 pixels (in the
  // coloured half when split): the LOD is the same all over the plane, so
  // the measurement pass draws just that region.
  ts::Panel probe;
  probe.id = "probe_outline";
  probe.viewport = {0, 0, w, h};
  probe.projection = glm::ortho(0.0f, float(w), float(h), 0.0f, -1.0f, 1.0f);
  float cx = float(levels_ == kSplit ? 3 * w / 4 : w / 2), cy = float(h / 2), r = float(sweep::kCell / 2) + 1.5f;
  // Black under white: visible on every level colour.
  for (float k : {1.0f, 0.0f}) {
    float q = r + k;
    probe.batches.push_back(ts::lineLoop({{cx - q, cy - q}, {cx + q, cy - q}, {cx + q, cy + q}, {cx - q, cy + q}},
                                         k > 0 ? glm::vec4(0, 0, 0, 1) : kWhite, k > 0 ? 3.0f : 1.0f, "probe"));
  }
  f.panels = {p, probe};

  const double lambda = x + bias_;
  // The state top left, the measurements top right; under it when the
  // window is too narrow for both side by side.
  namespace L = ts::layout;
  std::vector<std::pair<std::string, glm::vec4>> left = {
      {std::string(filterGLName(filter_)) + (filter_ == kAnisotropic ? " x" + std::to_string(aniso_) : ""), kWhite},
      {"distance 2^" + fmt("%.3f", x) + " = " + fmt("%.3g", facingDistance(x)) + " texels per pixel", kWhite},
      {"LOD = " + (bias_ != 0 ? fmt("%.3f", x) + " + bias " + fmt("%g", bias_) + " = " : std::string()) +
           fmt("%.3f", lambda) + " -> " + levelText(filter_, lambda),
       kAmber}};
  std::vector<std::pair<std::string, glm::vec4>> right;
  if (m) {
    right.push_back({"mip chain +" + fmt("%.2f", 100 * m->overhead) + "% memory", kWhite});
    right.push_back({"popping " + fmt("%.1f", m->popping[filter_]) + " (trilinear " +
                         fmt("%.1f", m->popping[kLinearMipLinear]) + ")",
                     kWhite});
    if (!animate_) right.push_back({"level read from the colours " + fmt("%.2f", m->levelObserved), kAmber});
  }
  auto widest = [&](const std::vector<std::pair<std::string, glm::vec4>>& v) {
    float wd = 0;
    for (const auto& t : v) wd = std::max(wd, ts::text::width(t.first, scale) + 6.0f * float(scale) + 2);
    return wd;
  };
  const float pad = float(8 * scale), top = float(6 * scale), bottom = float(h - 2 * line);
  const bool besides = widest(left) + widest(right) + 3 * pad <= float(w);
  L::Column lc(f, {pad, top, besides ? float(w) - widest(right) - 2 * pad : float(w) - pad, bottom});
  for (const auto& t : left) lc.add(t.first, t.second, scale, ts::Align::Left, kBox);
  L::Column rc(f, besides ? L::Box{float(w) - widest(right) - pad, top, float(w) - pad, bottom}
                          : L::Box{pad, lc.y(), float(w) - pad, bottom});
  for (const auto& t : right) rc.add(t.first, t.second, scale, besides ? ts::Align::Right : ts::Align::Left, kBox);
  if (levels_ == kSplit) {
    L::caption(f, {0, float(h - 2 * line), float(w / 2), float(h - line)}, "the texture", kWhite, scale,
               ts::Align::Center, kBox);
    L::caption(f, {float(w / 2), float(h - 2 * line), float(w), float(h - line)}, "levels coloured", kWhite, scale,
               ts::Align::Center, kBox);
  }
}

void MipmapPopping::buildFilmstrip(ts::Frame& f, const Result* m) const {
  const int w = f.width, h = f.height;
  const int line = int(ts::text::height(1)) + 6;
  constexpr int kCols = 8;
  const int gap = 6;
  int cell = std::min((w - 2 * gap) / kCols - gap, (h - 6 * line - gap) / 2);
  cell = std::max(8, cell);
  int x0 = (w - (kCols * (cell + gap) - gap)) / 2;
  int rowsTop = std::max(2 * line, (h - (2 * cell + 3 * line + gap)) / 2);
  const int rows[2] = {filter_, kLinearMipLinear};
  const double x = shownLog2();
  namespace L = ts::layout;
  L::caption(f, {4, 4, float(w - 4), float(4 + line)},
             "the plane at 8 distances, 1/4 level apart (LOD bias " + fmt("%g", bias_) + ")", kWhite, 1);
  const bool narrow = float(cell + gap) < ts::text::width("top: level 1 ", 1);
  for (int r = 0; r < 2; ++r) {
    int y = rowsTop + r * (cell + line + gap) + line;
    sweep::Look lk = look();
    lk.filter = rows[r];
    std::string name = std::string(filterGLName(rows[r])) + (rows[r] == kAnisotropic ? " x" + std::to_string(aniso_) : "");
    if (m) name += "   popping " + fmt("%.1f", m->popping[rows[r]]);
    L::caption(f, {float(x0), float(y - line), float(w - 2), float(y - 2)}, name, r == 0 ? kAmber : kWhite, 1,
               ts::Align::Left);
    for (int c = 0; c < kCols; ++c) {
      double xc = x + 0.25 * (c - kCols / 2);
      ts::Panel p;
      p.id = "frame_" + std::to_string(r) + "_" + std::to_string(c);
      p.viewport = {x0 + c * (cell + gap), y, cell, cell};
      addFacing(f, p, xc, lk, levels_);
      f.panels.push_back(p);
      if (r == 1) {
        double lambda = xc + bias_;
        float lx = float(p.viewport.x + cell / 2);
        // Under each frame, in its column: the LOD, and the level the top row shows.
        const L::Box col{lx - float(cell + gap) / 2, float(y + cell + 4), lx + float(cell + gap) / 2,
                         float(y + cell + 4 + line)};
        L::caption(f, col, (narrow ? "" : "LOD ") + fmt("%.3f", lambda), kWhite, 1);
        std::string top = usesMipmaps(rows[0]) && !blendsLevels(rows[0])
                              ? std::to_string(nearestLevel(lambda))
                              : fmt("%.2f", effectiveLevel(rows[0], lambda));
        L::caption(f, {col.x0, col.y1, col.x1, col.y1 + float(line)}, (narrow ? "L " : "top: level ") + top, kGrey, 1);
      }
    }
  }
}

// A plot of the probe's mean R, G, B against log2 distance.
void plotSweep(ts::Frame& f, ts::Rect area, const std::string& title, const std::vector<double>& xs,
               const std::vector<Mean>& ys, double current, const std::vector<double>& switches) {
  namespace plot = ts::plot;
  plot::Spec p;
  p.id = "plot_" + std::to_string(f.panels.size());
  p.title = title;
  p.x0 = xs.front(), p.x1 = xs.back(), p.y1 = 255;
  p.xTicks = plot::ticks(std::ceil(p.x0), std::floor(p.x1), 1), p.yTicks = plot::ticks(0, 255, 64);
  const char* roles[3] = {"mean_red", "mean_green", "mean_blue"};
  const glm::vec4 colours[3] = {{1.0f, 0.3f, 0.3f, 1.0f}, {0.3f, 0.95f, 0.3f, 1.0f}, {0.4f, 0.55f, 1.0f, 1.0f}};
  for (int c = 0; c < 3; ++c) {
    plot::Series se(roles[c], colours[c]);
    for (size_t k = 0; k < xs.size() && k < ys.size(); ++k) se.points.push_back({xs[k], c == 0 ? ys[k].r : c == 1 ? ys[k].g : ys[k].b});
    p.series.push_back(se);
  }
  for (double sw : switches) p.markers.push_back({sw, {0.55f, 0.55f, 0.6f, 1.0f}, "level_switches"});  // where the level changes
  p.markers.push_back({current, kAmber, "current", "", false, 2.0f});
  plot::draw(f, p, area);
}

void MipmapPopping::buildPlot(ts::Frame& f, const Result* m) const {
  const int w = f.width, h = f.height;
  const int line = int(ts::text::height(1)) + 6;
  if (!m || m->sweepLods.empty()) {
    f.labels.push_back({float(w / 2), float(h / 2), "(measuring...)", kWhite, 1, ts::Align::Center});
    return;
  }
  const int rows[2] = {filter_, kLinearMipLinear};
  const int plotH = (h - 4 * line) / 2;
  for (int r = 0; r < 2; ++r) {
    int fl = rows[r];
    std::vector<double> switches;
    if (usesMipmaps(fl))
      for (int k = 0; k < kLevels - 1; ++k) {
        double s = (blendsLevels(fl) ? k + 1.0 : k + 0.5) - bias_;  // log2 distance where the level changes
        if (s > m->sweepLods.front() && s < m->sweepLods.back()) switches.push_back(s);
      }
    std::string title = (fl == kAnisotropic ? "anisotropic x" + std::to_string(aniso_) : std::string(filterGLName(fl))) +
                        ": probe mean R, G, B vs log2 distance;  popping (largest jump) " + fmt("%.1f", m->popping[fl]);
    plotSweep(f, {0, r * plotH + line / 2, w, plotH}, title, m->sweepLods, m->sweepMeans[size_t(fl)], shownLog2(),
              switches);
  }
  namespace L = ts::layout;
  L::caption(f, {4, float(h - 2 * line - 2), float(w - 4), float(h - line - 1)},
             "x: log2 distance = LOD - bias (" + fmt("%g", bias_) +
                 ");  dashed: where GL's rule changes level;  amber: the current distance",
             kGrey, 1);
  // The level colours the probe sees, as a key (its lead shortened when narrow).
  std::string lead = "the probe's texture, level by level:";
  if (ts::text::width(lead, 1) + 10 + kLevels * 34.0f > float(w - 8)) lead = "levels:";
  float x = std::max(4.0f, float(w / 2) - (ts::text::width(lead, 1) + 10 + kLevels * 34.0f) / 2);
  const L::Box keyRow{0, float(h - line - 3), float(w), float(h)};
  L::placeFree(f, {x, float(h - line), lead, kGrey, 1, ts::Align::Left}, keyRow);
  x += ts::text::width(lead, 1) + 10;
  for (int k = 0; k < kLevels; ++k) {
    ts::Rgba c = ts::mipLevelColour(k);
    glm::vec4 bg(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f);
    bool dark = c.r * 0.3 + c.g * 0.59 + c.b * 0.11 < 140;
    L::placeFree(f, {x + k * 34.0f, float(h - line), " " + std::to_string(k) + " ", dark ? kWhite : glm::vec4(0, 0, 0, 1),
                     1, ts::Align::Left, bg},
                 keyRow);
  }
}

// The far field's bounds in a slant panel: the curves where the analytic
// LOD is kFarLodLo and kFarLodHi (it grows towards the horizon).
ts::Panel farFieldOutline(const ts::Rect& vp, const ts::OrbitCamera& orbit) {
  ts::Panel o;
  o.id = "far_field_outline";
  o.viewport = vp;
  o.projection = glm::ortho(0.0f, float(vp.w), float(vp.h), 0.0f, -1.0f, 1.0f);
  Camera cam = sweep::slantCamera(vp.w, vp.h, orbit);
  Plane ground = groundPlane();
  for (double lod : {sweep::kFarLodLo, sweep::kFarLodHi}) {
    std::vector<glm::vec2> pts;
    for (int x = 0; x <= vp.w; x += 4) {
      for (int y = vp.h - 1; y >= 0; --y) {
        Jacobian j;
        if (!planeAt(cam, ground, x, vp.h - y - 0.5, nullptr, &j)) break;
        if (std::log2(rhoExact(j)) >= lod) {
          pts.push_back({float(x), float(y) + 0.5f});
          break;
        }
      }
    }
    ts::Batch b = ts::lineSegments(pts, kWhite, 2.0f, lod == sweep::kFarLodLo ? "far_field_near_edge" : "far_field_far_edge");
    b.prim = ts::Prim::LineStrip;
    if (pts.size() > 1) o.batches.push_back(b);
  }
  return o;
}

// Where the notes under the slant panels start.
int cy0Notes(int h, int line, int rows, int ph, int gap) {
  return std::min(h - 2 * line, 2 * line + rows * (ph + gap + line));
}

// The slanted plane: the supersampled reference and the seven filters, four
// panels a row (the current filter's title in amber).
void MipmapPopping::buildSlant(ts::Frame& f, const Result* m) const {
  const int w = f.width, h = f.height;
  const int line = int(ts::text::height(1)) + 6;
  const int gap = 8;
  namespace L = ts::layout;
  // Four panels a row, or two in a tall window (four rows).
  const int kCols = w >= h ? 4 : 2, kRows = (kFilterCount + 1 + kCols - 1) / kCols;
  const int pw = std::max(8, (w - (kCols + 1) * gap) / kCols),
            ph = std::max(8, (h - kRows * gap - (2 + 2 * kRows) * line) / kRows);
  for (int k = 0; k <= kFilterCount; ++k) {
    const int fl = k - 1;  // -1: the reference
    int cx = gap + (k % kCols) * (pw + gap), cy = line + (k / kCols) * (ph + gap + line) + line;
    const L::Box inPanel{float(cx), float(cy), float(cx + pw), float(cy + ph)};
    ts::Panel p;
    p.id = fl < 0 ? std::string("slant_reference") : "slant_" + filterKey(fl);
    p.viewport = {cx, cy, pw, ph};
    sweep::Look lk = look();
    if (fl >= 0) lk.filter = fl;
    sweep::addSlant(f, p, lk, fl < 0 ? sweep::kReferenceProgram : levels_ == kColoursOnly ? sweep::kColoured : sweep::kTextured,
                    h);
    f.panels.push_back(p);
    std::string t;
    if (fl < 0) {
      t = "reference: 8x8 samples/pixel (GLSL)";
      // The far field's two edges, labelled at the left.
      ts::Panel o = farFieldOutline(p.viewport, camera_);
      for (const auto& b : o.batches)
        L::placeFree(f, {float(cx + 4), float(cy) + b.vertices.front().pos.y - 16.0f,
                         b.role == "far_field_near_edge" ? "LOD " + fmt("%g", sweep::kFarLodLo)
                                                         : "LOD " + fmt("%g", sweep::kFarLodHi),
                         kWhite, 1, ts::Align::Left, kBox},
                     inPanel);
      f.panels.push_back(o);
    } else {
      t = fl == kAnisotropic ? "anisotropic x" + std::to_string(aniso_) : std::string(filterGLName(fl));
      if (m)
        L::caption(f, {inPanel.x0 + 1, inPanel.y0 + 1, inPanel.x1 - 1, std::min(inPanel.y1, inPanel.y0 + 2 * float(line))},
                   "error " + fmt("%.1f", m->farError[fl]) +
                       (fl == kAnisotropic && !m->anisotropy ? " (no anisotropy here)" : ""),
                   fl == filter_ ? kAmber : kWhite, 1, ts::Align::Left, kBox);
    }
    // Titles: "GL_" goes, then the reference's detail, when the panel is narrow.
    if (ts::text::width(t, 1) > float(pw) && t.rfind("GL_", 0) == 0) t = t.substr(3);
    if (ts::text::width(t, 1) > float(pw) && fl < 0) t = "reference (8x8 samples)";
    L::caption(f, {float(cx), float(cy - line + 2), float(cx + pw), float(cy - 1)}, t, fl == filter_ ? kAmber : kWhite, 1,
               ts::Align::Left);
  }
  const std::string note1 = "error: RMS (R,G,B, 8-bit) against the reference in the far field, LOD " +
                            fmt("%g", sweep::kFarLodLo) + ".." + fmt("%g", sweep::kFarLodHi) + " (between the white lines)";
  std::string note2 = "measured at " + std::to_string(sweep::kSlantW) + "x" + std::to_string(sweep::kSlantH);
  if (m) note2 += " on " + m->renderer;
  L::Column notes(f, {4, float(cy0Notes(h, line, kRows, ph, gap)), float(w - 4), float(h)});
  notes.add(note1, kGrey, 1);
  notes.add(note2, kGrey, 1);
}

ts::Measurements MipmapPopping::measure(ts::Renderer& r) {
  Result out;
  out.renderer = ts::gl::rendererString();
  out.anisotropy = ts::gl::hasExtension("GL_EXT_texture_filter_anisotropic") ||
                   ts::gl::hasExtension("GL_ARB_texture_filter_anisotropic") || ts::gl::version() >= 46;
  if (out.anisotropy) glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &out.maxAnisotropy);

  // 1. The chain's memory.
  ts::TextureDesc tex = sweep::texture(look());
  std::vector<ts::Image> chain = ts::buildMipChain(*tex.image, linearLight_);
  out.overhead = ts::mipChainOverhead(chain);
  ts::Rgba top = chain.back().at(0, 0);
  out.topLevel = (top.r + top.g + top.b) / 3.0;

  // 2. The level observed at the current distance.
  Mean now = sweep::probeAt(r, look(), distLog2_);
  out.levelObserved = levelFromColour(now, kLevels, &out.residual);

  // 3. Popping: every filter over the sweep.
  out.sweepLods = sweep::sweepLods();
  for (int fl = 0; fl < kFilterCount; ++fl) {
    sweep::Look lk = look();
    lk.filter = fl;
    out.sweepMeans.push_back(sweep::probeSweep(r, lk, out.sweepLods));
    out.popping[fl] = poppingMeasure(out.sweepMeans.back());
  }

  // 4. Far-field error on the slanted plane against the supersampled reference.
  sweep::SlantErrors se = sweep::slantErrors(r, look());
  for (int fl = 0; fl < kFilterCount; ++fl) out.farError[fl] = se.error[fl];
  out.farPixels = se.pixels;

  const double lambda = distLog2_ + bias_;
  ts::Measurements ms;
  ms.push_back({"mip_overhead", out.overhead, "bytes of levels 1.. over level 0's bytes (the book: about 1/3)"});
  ms.push_back({"mip_levels", double(chain.size()), "levels of the 256 x 256 chain (256 .. 1)"});
  ms.push_back({"mip_top_level_value", out.topLevel,
                std::string("the 1x1 level: mean of the texture, averaged in ") + (linearLight_ ? "linear light" : "sRGB values")});
  ms.push_back({"lod_analytic", lambda, "log2(texels per pixel) + bias at the current distance"});
  ms.push_back({"level_expected", effectiveLevel(filter_, lambda), "level (k + blend weight) GL's rules give at that LOD"});
  ms.push_back({"level_observed", out.levelObserved, "level read back from the coloured levels at that distance"});
  for (int fl = 0; fl < kFilterCount; ++fl)
    ms.push_back({"popping[" + filterKey(fl) + "]", out.popping[fl],
                  "largest probe mean jump (8-bit) between distances 1/16 level apart"});
  double tri = out.popping[kLinearMipLinear];
  ms.push_back({"popping_ratio", tri > 0 ? out.popping[kNearestMipNearest] / tri : 0.0,
                "popping of NEAREST_MIPMAP_NEAREST / LINEAR_MIPMAP_LINEAR"});
  for (int fl = 0; fl < kFilterCount; ++fl)
    ms.push_back({"far_error[" + filterKey(fl) + "]", out.farError[fl],
                  fl == kAnisotropic ? "RMS vs 8x8 supersampled reference, slanted plane far field (renderer: " +
                                           out.renderer + ", max anisotropy " + std::to_string(aniso_) + ")"
                                     : "RMS vs 8x8 supersampled reference, slanted plane far field"});
  ms.push_back({"far_pixels", double(out.farPixels), "pixels in the far field"});
  ms.push_back({"anisotropy_supported", out.anisotropy ? 1.0 : 0.0,
                "EXT/ARB_texture_filter_anisotropic (max " + fmt("%g", out.maxAnisotropy) + ")"});
  ms.detail = out;
  return ms;
}
}  // namespace

TM_REGISTER_SCENE(MipmapPopping);
