// demos/parallax_aniso/parallax_aniso_views.hpp — how the parallax_aniso demo
// (seed 003) lays out what it measured: the single view (one mode large, or
// the split screen), the modes view (all seven with their numbers and the
// occlusion band's table), the error view (the band's error for M2, M3, M4)
// and the live view's bars.  Text scales with the pictures (common/layout's
// fitScale / scaleFor) and sits in bands beside them, never over a picture
// of a figure.  parallax_aniso.cpp measures; this draws.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/layout.hpp"
#include "common/gl/render.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "parallax_aniso_measure.hpp"
#include "parallax_aniso_gl.hpp"

namespace pax::views {
enum View { kSingle, kModes, kError, kLive, kRanking, kCauses, kSeedF };
inline const char* const kMaps[] = {"bricks", "step", "flat"};
using ts::layout::kWhite, ts::layout::kAmber;
inline const glm::vec4 kGrey{0.62f, 0.62f, 0.66f, 1.0f};

inline ts::TextureDesc imageTexture(const ts::Image& img, const std::string& what) {
  return ts::renderedImageTexture(img, "parallax_render", what, "parallax_aniso");
}

// |error| against the reference inside the occlusion band, x4, on a heat
// scale (black 0 .. yellow 64 levels); outside the band the reference, dimmed.
inline ts::Image bandError(const ts::Image& img, const Table& t) {
  ts::Image out(img.width, img.height);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      size_t p = size_t(y) * size_t(img.width) + size_t(x);
      const uint8_t* a = &img.pixels[p * 4];
      const uint8_t* r = &t.referenceImage.pixels[p * 4];
      if (!t.bandMask[p]) {
        double l = (0.299 * r[0] + 0.587 * r[1] + 0.114 * r[2]) * 0.25;
        out.set(x, y, {u8(l), u8(l), u8(l + 8), 255});
        continue;
      }
      double e = 0;
      for (int c = 0; c < 3; ++c) e += std::abs(double(a[c]) - double(r[c]));
      double v = std::clamp(e / 3.0 / 64.0, 0.0, 1.0);
      glm::dvec3 col = v < 0.5 ? glm::mix(glm::dvec3(30, 20, 60), glm::dvec3(220, 40, 40), v * 2)
                               : glm::mix(glm::dvec3(220, 40, 40), glm::dvec3(255, 240, 80), v * 2 - 1);
      out.set(x, y, {u8(col.r), u8(col.g), u8(col.b), 255});
    }
  return out;
}

// The occlusion band itself: yellow inside, the reference halved outside.
inline ts::Image bandPicture(const Table& t) {
  ts::Image band(t.cam.width, t.cam.height);
  for (size_t p = 0; p < t.bandMask.size(); ++p) {
    const uint8_t* c = &t.referenceImage.pixels[p * 4];
    bool in = t.bandMask[p];
    for (int k = 0; k < 3; ++k)
      band.pixels[p * 4 + size_t(k)] = in ? uint8_t(k == 0 ? 255 : k == 1 ? 200 : 40) : uint8_t(c[k] / 2);
  }
  return band;
}

// What measure() found, for the pictures (its detail): the table and its
// images as textures; or, in the live view, the texture it drew.
struct Shown {
  std::shared_ptr<const Table> table;
  std::vector<ts::TextureDesc> textures, errorTextures;
  const ts::TextureDesc& of(int mode) const { return textures[size_t(mode == kReference ? 6 : mode)]; }
};
// A table's pictures as textures: each mode's image and the reference; the
// band's error for M2, M3 and M4, and the band itself.
inline Shown shownOf(std::shared_ptr<const Table> table) {
  Shown s;
  for (const Row& row : table->rows) {
    s.textures.push_back(imageTexture(row.image, kModeKeys[row.mode]));
    s.textures.back().renderedBy = row.calls;
  }
  s.textures.push_back(imageTexture(table->referenceImage, "reference"));
  for (int m : {kAniso16, kEwa, kEwaVis})
    s.errorTextures.push_back(
        imageTexture(bandError(table->rows[size_t(m)].image, *table), std::string("band_error_") + kModeKeys[m]));
  s.errorTextures.push_back(imageTexture(bandPicture(*table), "occlusion_band"));
  s.table = std::move(table);
  return s;
}
struct Live {
  ts::TextureDesc texture;
  glm::ivec2 size{0}, modes{-1};
  double scale = 1, fps = 0;  // drawn smaller while the view moves (window only): shown in the picture
};

// The demo's state as the views see it (its flags), and how it draws them.
struct Views {
  int map_ = 0, mode_ = kEwa, against_ = kEwaVis, gradients_ = 0;
  bool compare_ = false;
  float heightScale_ = 0.06f;
  Camera cam_;  // the mouse's orbit included

  // Said in the picture whenever M1/M2 are not given the true gradients.
  std::string gradientsNote() const { return gradients_ ? ", M1/M2 gradients x4" : ""; }
  // The state, not the renderer: its version string belongs to the report, and
  // a figure's title should read the same on every Mesa.
  std::string header() const {
    return std::string("Seed 003  ") + kMaps[map_] + ", view angle " + fmtNum("%.0f", cam_.elevationDeg) +
           " deg, height " + fmtNum("%.2f", heightScale_) + gradientsNote();
  }
  static std::string numbers(const Table& table, int mode) {
    if (mode == kReference) return std::to_string(table.refRays) + "x" + std::to_string(table.refRays) + " rays, CPU";
    // A window's first stage: the reference is coarse, so its PSNRs would mislead; they come with the table.
    if (table.stage) return "(measuring)";
    const Row& r = table.rows[size_t(mode)];
    // A map with no occluding edge (flat) has an empty band: no number to show.
    std::string band = table.bandPixels ? "band " + fmtNum("%.1f", r.psnrBand) + " dB" : std::string("no band");
    return fmtNum("%.1f", r.psnrAll) + " dB  " + band + "  " + fmtNum("%.0f", r.lookupsPerPixel) + " lk/px";
  }
  static void addImage(ts::Frame& f, const std::string& id, ts::Rect rect, const ts::TextureDesc& tex, float s0 = 0,
                       float s1 = 1) {
    f.panels.push_back(ts::layout::texturePanel(id, rect, f.addTexture(tex), "image", s0, s1));
  }
  // A picture made from the reference in a window's first stage (Table::stage):
  // the reference itself, the band and the errors, coarse until the table replaces them.
  static void tagCoarse(ts::Frame& f, const Table& table, ts::Rect rect) {
    if (table.stage) ts::layout::refiningTag(f, rect);
  }
  static void addDivider(ts::Frame& f, float x, float y0, float y1) {
    ts::Panel canvas;
    canvas.id = "divider";
    canvas.viewport = {0, 0, f.width, f.height};
    canvas.projection = glm::ortho(0.0f, float(f.width), float(f.height), 0.0f, -1.0f, 1.0f);
    canvas.batches.push_back(ts::lineSegments({{x, y0}, {x, y1}}, kWhite, 2.0f, "divider"));
    f.panels.push_back(canvas);
  }
  // The panels of the modes and error views: shrunk to fit, or enlarged by a
  // whole factor when two or more fit (each rendered pixel stays a block of
  // equal pixels: small --res renders stay readable and comparable).
  static double panelScale(double fit) { return fit >= 2.0 ? std::floor(fit) : std::min(1.0, fit); }
  // The cells of those views: `cells` pictures of the camera's size in two
  // or four columns (two in a tall window), centred under the header line,
  // each row a picture, its title line above and `below` pixels under it
  // (`belowLines` text lines + `belowPixels`), at the text scale that fits.
  struct Grid {
    int gap = 12, s = 1, line = 0, cols = 4, w = 0, h = 0, left = 0, width = 0;
    // The box of column x's captions, from y0 to y1, reaching into the gaps.
    ts::layout::Box column(int x, float y0, float y1) const {
      return {std::max(0.0f, float(x - gap / 2)), y0, std::min(float(width), float(x + w + gap / 2)), y1};
    }
  };
  static Grid grid(const ts::Frame& f, const Table& table, int cells, int belowLines, int belowPixels) {
    namespace L = ts::layout;
    Grid g;
    g.width = f.width;
    const int W = table.cam.width, H = table.cam.height;
    auto fit = [&](int cols, int line) {
      int rows = cells / cols;
      return std::min(double(f.width - (cols + 1) * g.gap) / (cols * W),
                      double(f.height - 2 * line - rows * ((belowLines + 1) * line + belowPixels)) / (rows * H));
    };
    auto colsAt = [&](int line) { return fit(2, line) > fit(4, line) * 1.05 ? 2 : 4; };
    auto pictureAt = [&](int s) {
      const int line = int(L::lineHeight(s));
      double k = panelScale(fit(colsAt(line), line));
      return ts::Rect{0, 0, std::max(1, int(W * k)), std::max(1, int(H * k))};
    };
    g.s = L::fitScale(pictureAt), g.line = int(L::lineHeight(g.s)), g.cols = colsAt(g.line);
    g.w = pictureAt(g.s).w, g.h = pictureAt(g.s).h;
    g.left = std::max(0, (f.width - g.cols * g.w - (g.cols - 1) * g.gap) / 2);
    return g;
  }

  void buildWaiting(ts::Frame& f) const;
  void buildSingle(ts::Frame& f, const Shown& shown) const;
  void buildModes(ts::Frame& f, const Shown& shown) const;
  void buildError(ts::Frame& f, const Shown& shown) const;
  void buildLive(ts::Frame& f, const Live* live) const;
};

// A window before the first measurement: what is coming.
inline void Views::buildWaiting(ts::Frame& f) const {
  namespace L = ts::layout;
  const int s = L::scaleFor({0, 0, f.width, f.height}, 2);
  L::caption(f, {16, 6, float(f.width - 4), 6 + 2 * L::lineHeight(s)}, header(), kWhite, s, ts::Align::Left);
  L::caption(f, {4, float(f.height) / 2, float(f.width - 4), float(f.height - 2)},
             "rendering the modes and tracing the reference...", kAmber, s);
}

inline void Views::buildSingle(ts::Frame& f, const Shown& shown) const {
  namespace L = ts::layout;
  // A window's first stage holds only the modes it was asked for: a key that
  // shows another (c, b, m) before the table is in waits for it.
  for (int m : {mode_, compare_ ? against_ : mode_})
    if (!shown.of(m).image) return buildWaiting(f);
  const Table& table = *shown.table;
  // The render as large as fits between the header (two lines) and the numbers (two lines).
  auto pictureAt = [&](int s) {
    const int line = int(L::lineHeight(s));
    double k = std::min(double(f.width - 32) / table.cam.width, double(f.height - 4 * line) / table.cam.height);
    int w = std::max(1, int(table.cam.width * k)), h = std::max(1, int(table.cam.height * k));
    return ts::Rect{(f.width - w) / 2, 2 * line, w, h};
  };
  // The split screen's captions sit under its halves: their scale is a half's.
  const int s = L::fitScale([&](int sc) {
    ts::Rect r = pictureAt(sc);
    if (compare_) r.w /= 2;
    return r;
  });
  const ts::Rect rect = pictureAt(s);
  const float line = L::lineHeight(s);
  // The header on one line, smaller where the window is narrow.
  int hs = s;
  while (hs > 1 && ts::text::width(header(), hs) > float(f.width - 21)) --hs;
  L::caption(f, {16, 6, float(f.width - 4), 2 * line - 2}, header(), kWhite, hs, ts::Align::Left);
  const L::Box under{4, float(rect.y + rect.h + 6), float(f.width - 4), float(f.height - 2)};
  if (!compare_) {
    addImage(f, "image", rect, shown.of(mode_));
    if (mode_ == kReference) tagCoarse(f, table, rect);
    L::caption(f, under, std::string(kModeLabels[mode_]) + ":  " + numbers(table, mode_), kAmber, s);
    return;
  }
  ts::Rect left{rect.x, rect.y, rect.w / 2, rect.h}, right{rect.x + rect.w / 2, rect.y, rect.w - rect.w / 2, rect.h};
  addImage(f, "left", left, shown.of(mode_), 0.0f, 0.5f);
  addImage(f, "right", right, shown.of(against_), 0.5f, 1.0f);
  if (mode_ == kReference) tagCoarse(f, table, left);
  if (against_ == kReference) tagCoarse(f, table, right);
  addDivider(f, float(right.x), float(rect.y), float(rect.y + rect.h));
  const float mid = float(right.x);
  L::caption(f, {under.x0, under.y0, mid - 4, under.y1}, std::string(kModeLabels[mode_]) + ": " + numbers(table, mode_),
             kAmber, s);
  L::caption(f, {mid + 4, under.y0, under.x1, under.y1},
             std::string(kModeLabels[against_]) + ": " + numbers(table, against_), kAmber, s);
}

inline void Views::buildModes(ts::Frame& f, const Shown& shown) const {
  namespace L = ts::layout;
  const Table& table = *shown.table;
  // Four cells a row (two rows), or two (four rows) in a tall window; under
  // each picture two lines of numbers, at the text's scale.
  const Grid g = grid(f, table, 8, 2, 6);
  const int gap = g.gap, s = g.s, line = g.line, cols = g.cols, w = g.w, h = g.h, left = g.left;
  L::caption(f, {4, 4, float(f.width - 4), float(2 * line - 2)}, header(), kWhite, s);
  auto column = [&](int x, float y0, float y1) { return g.column(x, y0, y1); };
  const int order[7] = {kNaive, kTrilinear, kAniso16, kReference, kEwa, kEwaVis, kEwaRows};
  for (int k = 0; k < 7; ++k) {
    int col = k % cols, row = k / cols;
    int x = left + col * (w + gap), y = 2 * line + row * (h + 3 * line + 6) + line;
    addImage(f, std::string("image_") + kModeKeys[order[k]], {x, y, w, h}, shown.of(order[k]));
    if (order[k] == kReference) tagCoarse(f, table, {x, y, w, h});
    L::caption(f, column(x, float(y - line), float(y - 1)), kModeLabels[order[k]], kWhite, s);
    L::caption(f, column(x, float(y + h + 3), float(y + h + 2 * line + 3)), numbers(table, order[k]), kAmber, s);
  }
  // The eighth cell: the band in numbers.
  int x = left + (7 % cols) * (w + gap), y = 2 * line + (7 / cols) * (h + 3 * line + 6) + line;
  const float cellW = std::min(float(f.width - 2), float(x + std::max(w, 240 * s))) - float(x);
  // A narrow cell gets the short form of each line (never a row wrapped in two).
  const bool brief = ts::text::width("M0     17.17  0.6129", s) > cellW - 1;
  L::Column c(f, {float(x), float(y), float(x) + cellW, float(f.height - 2)});
  c.add((brief ? "band: " : "occlusion band: ") +
            (table.stage ? std::string("(measuring)") : std::to_string(table.bandPixels) + " px"),
        kGrey, s, ts::Align::Left);
  c.add(brief ? "   PSNR  SSIM" : "mode     PSNR    SSIM", kGrey, s, ts::Align::Left);
  for (int m = 0; m < kShaderModes; ++m) {
    const Row& r = table.rows[size_t(m)];
    std::string values = brief ? fmtNum("%.2f", r.psnrBand) + " " + fmtNum("%.3f", r.ssimBand)
                               : fmtNum("%6.2f", r.psnrBand) + "  " + fmtNum("%6.4f", r.ssimBand);
    if (table.stage) values = "(measuring)";
    c.add(std::string("M") + std::to_string(m) + (brief ? " " : "    ") +
              (table.bandPixels ? values : std::string(brief ? "  -     -" : "     -       -")),
          m >= kEwa ? kAmber : kWhite, s, ts::Align::Left);
  }
  // (Milliseconds are in the CSV, not here: the figure must regenerate byte-identically.)
  c.add(brief ? "PSNR: dB vs R" : "PSNR in dB against R;", kGrey, s, ts::Align::Left);
  c.add(brief ? "lk/px: lookups" : "lk/px: texture lookups per pixel", kGrey, s, ts::Align::Left);
  L::legend(f, {float(x), c.y(), float(x) + cellW, float(f.height - 2)},
            {{kAmber, brief ? "EWA" : "the EWA modes (seed 003)"}}, s);
}

inline void Views::buildError(ts::Frame& f, const Shown& shown) const {
  namespace L = ts::layout;
  const Table& table = *shown.table;
  // Four in a row, or 2 x 2 in a tall window; two lines under each.
  const Grid g = grid(f, table, 4, 2, 0);
  const int gap = g.gap, s = g.s, line = g.line, cols = g.cols, w = g.w, h = g.h, left = g.left;
  L::caption(f, {4, 4, float(f.width - 4), float(2 * line - 2)}, header(), kWhite, s);
  auto column = [&](int x, float y0, float y1) { return g.column(x, y0, y1); };
  const char* titles[4] = {"occlusion band", "M2 aniso 16x |error|", "M3 EWA |error|", "M4 EWA visible |error|"};
  const int modes[4] = {-1, kAniso16, kEwa, kEwaVis};
  for (int k = 0; k < 4; ++k) {
    int x = left + (k % cols) * (w + gap), y = 2 * line + line / 2 + (k / cols) * (h + 3 * line);
    addImage(f, std::string("error_") + std::to_string(k), {x, y, w, h},
             shown.errorTextures[size_t(k == 0 ? 3 : k - 1)]);
    tagCoarse(f, table, {x, y, w, h});
    L::caption(f, column(x, float(y - line), float(y - 1)), titles[k], kWhite, s);
    std::string n = k == 0 ? std::to_string(table.bandPixels) + " px"
                           : "band PSNR " + fmtNum("%.2f", table.rows[size_t(modes[k])].psnrBand) + " dB, SSIM " +
                                 fmtNum("%.3f", table.rows[size_t(modes[k])].ssimBand);
    if (table.stage) n = "(measuring)";
    L::caption(f, column(x, float(y + h + 4), float(y + h + 2 * line)), n, kAmber, s);
  }
}

// The live view: the picture fills the window; its two lines of text sit on
// dark bars across the top and bottom, a line of text tall and a margin,
// their scale the window's (at most 2).
inline int liveTextScale(int width, int height) { return ts::layout::scaleFor({0, 0, width, height}, 2); }
inline int liveBarHeight(int width, int height) {
  const int s = liveTextScale(width, height);
  return int(ts::layout::lineHeight(s)) + 5 * s;
}
inline void Views::buildLive(ts::Frame& f, const Live* live) const {
  namespace L = ts::layout;
  const int s = liveTextScale(f.width, f.height), bar = liveBarHeight(f.width, f.height);
  std::string head = std::string("Seed 003  ") + kMaps[map_] + ", view angle " + fmtNum("%.0f", cam_.elevationDeg) +
                     " deg, azimuth " + fmtNum("%.0f", cam_.azimuthDeg) + " deg, height " +
                     fmtNum("%.2f", heightScale_) + gradientsNote() + ", live";
  if (!live || !live->texture.glTexture) {
    L::Column c(f, {16, 6, float(f.width - 4), float(f.height - 2)});
    c.add(head, kWhite, s, ts::Align::Left);
    c.add("R (the reference) is traced on the CPU and is not drawn live: m picks a mode", kAmber, s, ts::Align::Left);
    return;
  }
  addImage(f, "live", {0, 0, f.width, f.height}, live->texture);
  auto addBar = [&](const char* id, int y) {
    ts::Panel p;
    p.id = id;
    p.viewport = {0, y, f.width, bar};
    p.clear = true;
    p.clearColor = f.clearColor;
    f.panels.push_back(p);
  };
  addBar("top_bar", 0);
  addBar("bottom_bar", f.height - bar);
  // A narrow window gets a smaller header, then a shorter one, never one cut before its gradients note.
  int hs = s;
  while (hs > 1 && ts::text::width(head, hs) > float(f.width - 21)) --hs;
  for (const std::string& h :
       {std::string(kMaps[map_]) + gradientsNote() + ", live", std::string(kMaps[map_]) + gradientsNote()})
    if (ts::text::width(head, hs) > float(f.width - 21)) head = h;
  const float top = float(2 * s), bottom = float(f.height - bar + 2 * s);
  L::caption(f, {16, top, float(f.width - 4), float(bar)}, head, kWhite, hs, ts::Align::Left);
  std::string sizeText = std::to_string(live->size.x) + "x" + std::to_string(live->size.y);
  if (live->scale < 1.0)
    sizeText += " (scale " + fmtNum("%.2f", live->scale) + " while moving, draw " + fmtNum("%.0f", live->fps) + " fps)";
  if (live->modes.y < 0) {
    L::caption(f, {4, bottom, float(f.width - 4), float(f.height)},
               std::string(kModeLabels[live->modes.x]) + ", " + sizeText, kAmber, s);
    return;
  }
  L::caption(f, {4, bottom, float(f.width / 2 - 4), float(f.height)}, kModeLabels[live->modes.x], kAmber, s);
  L::caption(f, {float(f.width / 2 + 4), bottom, float(f.width - 4), float(f.height)}, kModeLabels[live->modes.y],
             kAmber, s);
  addDivider(f, float(f.width / 2), 0.0f, float(f.height));
}
}  // namespace pax::views
