// demos/mipmap_popping/mipmap_popping_views.hpp — how the mipmap_popping demo
// (Section VI.1.3) lays out what it measured: the single plane with its level
// read-out, the filmstrip of distances, the plot of the probe's colour
// against distance, and the slanted plane with its far-field errors.
// mipmap_popping.cpp measures; this draws.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/layout.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/core/plot.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "mipmap_popping_math.hpp"
#include "mipmap_popping_sweep.hpp"

namespace mipmap::views {
using namespace mipmap;
using ts::layout::fmt;

enum View { kFilmstrip, kSingle, kPlot, kSlant };  // the filmstrip first: it shows the popping
enum Levels { kTextureOnly, kColoursOnly, kSplit };

// What measure() found, for the labels and the plot: measure()'s detail.
struct Result {
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

// The demo's state as the views see it (its flags), and how it draws them.
struct Views {
  mipmap::Look look_;    // filter, anisotropy, bias, texture, camera
  int levels_ = kSplit;  // how the level colours show
  bool animate_ = false;
  double shown_ = 0;  // the plane's log2 distance as drawn

  void buildSingle(ts::Frame& f, const Result* m) const;
  void buildFilmstrip(ts::Frame& f, const Result* m) const;
  void buildPlot(ts::Frame& f, const Result* m) const;
  void buildSlant(ts::Frame& f, const Result* m) const;
};

using ts::layout::kWhite, ts::layout::kAmber;
const glm::vec4 kGrey{0.75f, 0.75f, 0.78f, 1.0f}, kBox{0.0f, 0.0f, 0.0f, 0.65f};

// A facing-plane panel: the plane (split or not) at log2 distance x.
inline void addFacing(ts::Frame& f, ts::Panel& p, double x, const mipmap::Look& look, int levels) {
  Camera cam = facingCamera(p.viewport.w, p.viewport.h, facingDistance(x));
  p.projection = cam.projection(p.viewport.w, p.viewport.h);
  p.modelview = cam.modelview();
  if (levels == kTextureOnly || levels == kColoursOnly) {
    int t = f.addTexture(levels == kColoursOnly ? mipmap::colouredTexture(look) : mipmap::texture(look));
    p.batches.push_back(mipmap::facingBatch(facingDistance(x), t, -kPlaneHalf, kPlaneHalf));
  } else {
    int t = f.addTexture(mipmap::texture(look)), c = f.addTexture(mipmap::colouredTexture(look));
    p.batches.push_back(mipmap::facingBatch(facingDistance(x), t, -kPlaneHalf, 0));
    p.batches.push_back(mipmap::facingBatch(facingDistance(x), c, 0, kPlaneHalf));
  }
}

// "1.5 to 5": the far field's LODs, parameters of the measurement.
inline ts::layout::Text farLods(const char* between) {
  namespace L = ts::layout;
  return L::given("the far field's lowest LOD", mipmap::kFarLodLo, "%g") + between +
         L::given("the far field's highest LOD", mipmap::kFarLodHi, "%g");
}
inline std::string levelText(int filter, double lambda) {
  if (!usesMipmaps(filter)) return "level 0 (no mipmaps)";
  if (lambda <= 0) return "level 0 (magnified)";
  if (blendsLevels(filter)) {
    LevelBlend b = linearLevels(lambda);
    if (b.lo == b.hi) return "level " + std::to_string(b.lo);
    return "levels " + std::to_string(b.lo) + "+" + std::to_string(b.hi) + " (" + fmt("%.0f", 100 * b.weight) +
           "% of " + std::to_string(b.hi) + ")";
  }
  return "level " + std::to_string(nearestLevel(lambda));
}

inline void Views::buildSingle(ts::Frame& f, const Result* m) const {
  const int w = f.width, h = f.height;
  const int scale = std::max(1, std::min(2, std::min(w / 560, h / 300)));
  const int line = int(ts::text::height(scale)) + 6 * scale;
  const double x = shown_;
  ts::Panel p;
  p.id = "plane";
  p.viewport = {0, 0, w, h};
  addFacing(f, p, x, look_, levels_);
  // The probe region of the popping measure, 32 x 32 pixels (in the
  // coloured half when split): the LOD is the same all over the plane, so
  // the measurement pass draws just that region.
  ts::Panel probe;
  probe.id = "probe_outline";
  probe.viewport = {0, 0, w, h};
  probe.projection = glm::ortho(0.0f, float(w), float(h), 0.0f, -1.0f, 1.0f);
  float cx = float(levels_ == kSplit ? 3 * w / 4 : w / 2), cy = float(h / 2), r = float(mipmap::kCell / 2) + 1.5f;
  // Black under white: visible on every level colour.
  for (float k : {1.0f, 0.0f}) {
    float q = r + k;
    probe.batches.push_back(ts::lineLoop({{cx - q, cy - q}, {cx + q, cy - q}, {cx + q, cy + q}, {cx - q, cy + q}},
                                         k > 0 ? glm::vec4(0, 0, 0, 1) : kWhite, k > 0 ? 3.0f : 1.0f, "probe"));
  }
  f.panels = {p, probe};

  const double lambda = x + look_.lodBias;
  // The state top left, the measurements top right; under it when the
  // window is too narrow for both side by side.
  namespace L = ts::layout;
  std::vector<std::pair<std::string, glm::vec4>> left = {
      {std::string(filterGLName(look_.filter)) +
           (look_.filter == kAnisotropic ? " x" + std::to_string(look_.anisotropy) : ""),
       kWhite},
      {"distance 2^" + fmt("%.3f", x) + " = " + fmt("%.3g", facingDistance(x)) + " texels per pixel", kWhite},
      {"LOD = " +
           (look_.lodBias != 0 ? fmt("%.3f", x) + " + bias " + fmt("%g", look_.lodBias) + " = " : std::string()) +
           fmt("%.3f", lambda) + " -> " + levelText(look_.filter, lambda),
       kAmber}};
  std::vector<std::pair<std::string, glm::vec4>> right;
  if (m) {
    right.push_back({"mip chain +" + fmt("%.2f", 100 * m->overhead) + "% memory", kWhite});
    right.push_back({"popping " + fmt("%.1f", m->popping[look_.filter]) + " (trilinear " +
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

inline void Views::buildFilmstrip(ts::Frame& f, const Result* m) const {
  const int w = f.width, h = f.height;
  constexpr int kFrames = 8;
  const int gap = 6;
  namespace L = ts::layout;
  // Square frames as large as fit, in one band of 8 (a wide window) or two
  // bands of 4 (a tall one); a band is the current filter's row over
  // trilinear's, each with its title, and two lines under the frames; the
  // text at the scale the frames ask for.
  auto lineAt = [](int s) { return int(ts::text::height(s)) + 6 * s; };
  auto cellAt = [&](int s, int bands) {
    int c = std::min((w - 2 * gap) / (kFrames / bands) - gap,
                     (h - 2 * lineAt(s) - bands * (4 * lineAt(s) + 3 * gap) + 2 * gap) / (2 * bands));
    return ts::Rect{0, 0, std::max(8, c), std::max(8, c)};
  };
  auto scaleOf = [&](int bands) { return L::fitScale([&](int s) { return cellAt(s, bands); }); };
  const int bands = cellAt(scaleOf(2), 2).w > cellAt(scaleOf(1), 1).w ? 2 : 1, cols = kFrames / bands;
  const int sc = scaleOf(bands), line = lineAt(sc), cell = cellAt(sc, bands).w;
  const int bandH = 2 * cell + 4 * line + gap + 2 * gap;  // (and the gap to the next band)
  const int x0 = (w - (cols * (cell + gap) - gap)) / 2;
  const int rowsTop = std::max(2 * line, (h - (bands * bandH - 2 * gap - line)) / 2);
  const int rows[2] = {look_.filter, kLinearMipLinear};
  const double x = shown_;
  L::caption(f, {4, 4, float(w - 4), float(4 + line)},
             "the plane at 8 distances, 1/4 level apart (LOD bias " + fmt("%g", look_.lodBias) + ")", kWhite, sc);
  const bool narrow = float(cell + gap) < ts::text::width("top: level 1 ", sc);
  for (int b = 0; b < bands; ++b)
    for (int r = 0; r < 2; ++r) {
      int y = rowsTop + b * bandH + r * (cell + line + gap) + line;
      mipmap::Look lk = look_;
      lk.filter = rows[r];
      std::string name = std::string(filterGLName(rows[r])) +
                         (rows[r] == kAnisotropic ? " x" + std::to_string(look_.anisotropy) : "");
      if (m) name += "   popping " + fmt("%.1f", m->popping[rows[r]]);
      L::caption(f, {float(x0), float(y - line), float(w - 2), float(y - 2)}, name, r == 0 ? kAmber : kWhite, sc,
                 ts::Align::Left);
      for (int c = b * cols; c < (b + 1) * cols; ++c) {
        double xc = x + 0.25 * (c - kFrames / 2);
        ts::Panel p;
        p.id = "frame_" + std::to_string(r) + "_" + std::to_string(c);
        p.viewport = {x0 + (c % cols) * (cell + gap), y, cell, cell};
        addFacing(f, p, xc, lk, levels_);
        f.panels.push_back(p);
        if (r == 1) {
          double lambda = xc + look_.lodBias;
          float lx = float(p.viewport.x + cell / 2);
          // Under each frame, in its column: the LOD, and the level the top row shows.
          const L::Box col{lx - float(cell + gap) / 2, float(y + cell + 4), lx + float(cell + gap) / 2,
                           float(y + cell + 4 + line)};
          L::caption(f, col, (narrow ? "" : "LOD ") + L::given("the frame's LOD", lambda, "%.3f"), kWhite, sc);
          std::string top = usesMipmaps(rows[0]) && !blendsLevels(rows[0])
                                ? std::to_string(nearestLevel(lambda))
                                : fmt("%.2f", effectiveLevel(rows[0], lambda));
          L::caption(f, {col.x0, col.y1, col.x1, col.y1 + float(line)}, (narrow ? "L " : "top: level ") + top, kGrey,
                     sc);
        }
      }
    }
}

// The probe's mean R, G, B as the plot draws and its key names them.
inline const glm::vec4 kMeanColours[3] = {{1.0f, 0.3f, 0.3f, 1.0f},
                                          {0.3f, 0.95f, 0.3f, 1.0f},
                                          {0.4f, 0.55f, 1.0f, 1.0f}};
inline const glm::vec4 kSwitchColour{0.55f, 0.55f, 0.6f, 1.0f};

// A plot of the probe's mean R, G, B against log2 distance; returns its data area.
inline ts::Rect plotSweep(ts::Frame& f, ts::Rect area, const std::string& title, const std::vector<double>& xs,
                          const std::vector<Mean>& ys, double current, const std::vector<double>& switches, int scale) {
  namespace plot = ts::plot;
  plot::Spec p;
  p.id = "plot_" + std::to_string(f.panels.size());
  p.title = title;
  p.scale = scale;
  p.x0 = xs.front(), p.x1 = xs.back(), p.y1 = 255;
  p.xTicks = plot::ticks(std::ceil(p.x0), std::floor(p.x1), 1), p.yTicks = plot::ticks(0, 255, 64);
  const char* roles[3] = {"mean_red", "mean_green", "mean_blue"};
  for (int c = 0; c < 3; ++c) {
    plot::Series se(roles[c], kMeanColours[c]);
    for (size_t k = 0; k < xs.size() && k < ys.size(); ++k)
      se.points.push_back({xs[k], c == 0 ? ys[k].r : c == 1 ? ys[k].g : ys[k].b});
    p.series.push_back(se);
  }
  for (double sw : switches) p.markers.push_back({sw, kSwitchColour, "level_switches"});  // where the level changes
  p.markers.push_back({current, kAmber, "current", "", false, 2.0f});
  return plot::draw(f, p, area);
}

inline void Views::buildPlot(ts::Frame& f, const Result* m) const {
  const int w = f.width, h = f.height;
  namespace L = ts::layout;
  // Two plots one over the other, two lines of key under them, the text at
  // the scale a plot's data area asks for (laid out on a scratch frame).
  auto lineAt = [](int s) { return int(ts::text::height(s)) + 6 * s; };
  if (!m || m->sweepLods.empty()) {
    L::caption(f, {4, float(h / 2), float(w - 4), float(h)}, "(measuring...)", kWhite, 1);
    return;
  }
  auto title = [&](int fl) {
    return (fl == kAnisotropic ? "anisotropic x" + std::to_string(look_.anisotropy) : std::string(filterGLName(fl))) +
           ":  popping (largest jump) " + fmt("%.1f", m->popping[fl]);
  };
  auto plotAt = [&](int s) {
    ts::Frame scratch = L::blankFrame(w, h);
    return plotSweep(scratch, {0, 0, w, (h - 4 * lineAt(s)) / 2}, title(look_.filter), m->sweepLods,
                     m->sweepMeans[size_t(look_.filter)], shown_, {}, s);
  };
  const int sc = L::fitScale(plotAt), line = lineAt(sc), plotH = (h - 4 * line) / 2;
  const int rows[2] = {look_.filter, kLinearMipLinear};
  for (int r = 0; r < 2; ++r) {
    int fl = rows[r];
    std::vector<double> switches;
    if (usesMipmaps(fl))
      for (int k = 0; k < kLevels - 1; ++k) {
        double s = (blendsLevels(fl) ? k + 1.0 : k + 0.5) - look_.lodBias;  // log2 distance where the level changes
        if (s > m->sweepLods.front() && s < m->sweepLods.back()) switches.push_back(s);
      }
    plotSweep(f, {0, r * plotH + line / 2, w, plotH}, title(fl), m->sweepLods, m->sweepMeans[size_t(fl)], shown_,
              switches, sc);
  }
  L::Column notes(f, {4, float(h - 3 * line), float(w - 4), float(h - line - 1)});
  notes.add("the probe's mean R, G, B against x = log2 distance = LOD - bias (" + fmt("%g", look_.lodBias) + ")", kGrey,
            sc);
  // The key of the curves and lines, centred on its line.
  const std::vector<ts::LegendEntry> key = {{kMeanColours[0], "mean R"},
                                            {kMeanColours[1], "mean G"},
                                            {kMeanColours[2], "mean B"},
                                            {kAmber, "the current distance"},
                                            {kSwitchColour, "dashed: GL's rule changes level"}};
  float keyW = 0;
  for (const auto& e : key)
    keyW += ts::text::height(sc) + 4.0f * float(sc) + ts::text::width(e.meaning, sc) + 8.0f * float(sc);
  const float keyX = std::max(4.0f, (float(w) - keyW) / 2);
  L::legend(f, {keyX, notes.y(), float(w - 4), float(h - line - 1)}, key, sc);
  // The level colours the probe sees, as a key (its lead shortened when narrow).
  std::string lead = "the probe's texture, level by level:";
  const float step = 34.0f * float(sc);  // a level's box
  if (ts::text::width(lead, sc) + 10 + kLevels * step > float(w - 8)) lead = "levels:";
  float x = std::max(4.0f, float(w / 2) - (ts::text::width(lead, sc) + 10 + kLevels * step) / 2);
  const L::Box keyRow{0, float(h - line - 3), float(w), float(h)};
  const float y = float(h - line + 3 * (sc - 1));  // the row's 3 px margin, the box's 3 px a scale
  L::placeFree(f, {x, y, lead, kGrey, sc, ts::Align::Left}, keyRow);
  x += ts::text::width(lead, sc) + 10;
  for (int k = 0; k < kLevels; ++k) {
    ts::Rgba c = ts::mipLevelColour(k);
    glm::vec4 bg(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f);
    bool dark = c.r * 0.3 + c.g * 0.59 + c.b * 0.11 < 140;
    L::placeFree(f,
                 {x + float(k) * step, y, " " + std::to_string(k) + " ", dark ? kWhite : glm::vec4(0, 0, 0, 1), sc,
                  ts::Align::Left, bg},
                 keyRow);
  }
}

// The far field's bounds in a slant panel: the curves where the analytic
// LOD is kFarLodLo and kFarLodHi (it grows towards the horizon).
inline ts::Panel farFieldOutline(const ts::Rect& vp, const ts::OrbitCamera& orbit) {
  ts::Panel o;
  o.id = "far_field_outline";
  o.viewport = vp;
  o.projection = glm::ortho(0.0f, float(vp.w), float(vp.h), 0.0f, -1.0f, 1.0f);
  Camera cam = mipmap::slantCamera(vp.w, vp.h, orbit);
  Plane ground = groundPlane();
  for (double lod : {mipmap::kFarLodLo, mipmap::kFarLodHi}) {
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
    ts::Batch b = ts::lineSegments(pts, kWhite, 2.0f,
                                   lod == mipmap::kFarLodLo ? "far_field_near_edge" : "far_field_far_edge");
    b.prim = ts::Prim::LineStrip;
    if (pts.size() > 1) o.batches.push_back(b);
  }
  return o;
}

// The slanted plane: the supersampled reference and the seven filters, four
// panels a row (the current filter's title in amber), each with its title
// above and its far-field error below, the text at the scale the panels ask
// for (fitScale); the notes under them.
inline void Views::buildSlant(ts::Frame& f, const Result* m) const {
  const int w = f.width, h = f.height;
  const int gap = 8;
  namespace L = ts::layout;
  // Four panels a row, or two in a tall window (four rows).
  const int kCols = w >= h ? 4 : 2, kRows = (kFilterCount + 1 + kCols - 1) / kCols;
  auto lineAt = [](int s) { return int(ts::text::height(s)) + 6 * s; };
  auto panelAt = [&](int s) {
    const int line = lineAt(s);
    return ts::Rect{0, 0, std::max(8, (w - (kCols + 1) * gap) / kCols),
                    std::max(8, (h - line / 2 - kRows * (2 * line + gap) - 2 * line) / kRows)};
  };
  const int sc = L::fitScale(panelAt), line = lineAt(sc), pw = panelAt(sc).w, ph = panelAt(sc).h;
  for (int k = 0; k <= kFilterCount; ++k) {
    const int fl = k - 1;  // -1: the reference
    int cx = gap + (k % kCols) * (pw + gap), cy = line / 2 + (k / kCols) * (ph + 2 * line + gap) + line;
    ts::Panel p;
    p.id = fl < 0 ? std::string("slant_reference") : "slant_" + filterKey(fl);
    p.viewport = {cx, cy, pw, ph};
    mipmap::Look lk = look_;
    if (fl >= 0) lk.filter = fl;
    mipmap::addSlant(f, p, lk,
                     fl < 0                    ? mipmap::kReferenceProgram
                     : levels_ == kColoursOnly ? mipmap::kColoured
                                               : mipmap::kTextured,
                     h);
    f.panels.push_back(p);
    const L::Box above{float(cx), float(cy - line + 2), float(cx + pw), float(cy - 1)},
        below{float(cx), float(cy + ph + 2), float(cx + pw), float(cy + ph + line)};
    std::string t;
    if (fl < 0) {
      t = "reference: 8x8 samples/pixel (GLSL)";
      f.panels.push_back(farFieldOutline(p.viewport, look_.orbit));  // the far field's two edges
      L::caption(f, below, "far field: LOD " + farLods(" to "), kWhite, sc, ts::Align::Left);
    } else {
      t = fl == kAnisotropic ? "anisotropic x" + std::to_string(look_.anisotropy) : std::string(filterGLName(fl));
      if (m)
        L::caption(f, below,
                   "error " + L::measuredValue("far_error[" + filterKey(fl) + "]", m->farError[fl], "%.1f") +
                       (fl == kAnisotropic && !m->anisotropy ? " (no anisotropy here)" : ""),
                   fl == look_.filter ? kAmber : kWhite, sc, ts::Align::Left);
    }
    // Titles: "GL_" goes, then the reference's detail, when the panel is narrow.
    if (ts::text::width(t, sc) > float(pw) && t.rfind("GL_", 0) == 0) t = t.substr(3);
    if (ts::text::width(t, sc) > float(pw) && fl < 0) t = "reference (8x8 samples)";
    L::caption(f, above, t, fl == look_.filter ? kAmber : kWhite, sc, ts::Align::Left);
  }
  const L::Text note1 = "error: RMS (R,G,B, 8-bit) against the reference in the far field, LOD " + farLods("..") +
                        " (between the white lines)";
  const L::Text note2 = "measured at " + L::given("the measured render's width", mipmap::kSlantW, "%.0f") + "x" +
                        L::given("the measured render's height", mipmap::kSlantH, "%.0f") +
                        "; amber: the filter chosen (key f, --filter)";
  L::Column notes(f,
                  {4, float(std::min(h - 2 * line, line / 2 + kRows * (ph + 2 * line + gap))), float(w - 4), float(h)});
  notes.add(note1, kGrey, sc);
  notes.add(note2, kGrey, sc);
}
}  // namespace mipmap::views
