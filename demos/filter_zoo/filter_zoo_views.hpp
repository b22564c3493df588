// demos/filter_zoo/filter_zoo_views.hpp — how the filter zoo lays out what it
// measured: every method side by side at one azimuth; methods x azimuths;
// one pixel's footprint on the texture with every method's support over the
// exact preimage; memory against error; the mip kernels; the LOD bias.
// filter_zoo.cpp measures (filter_zoo_measure.hpp); this draws.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/layout.hpp"
#include "common/core/plot.hpp"
#include "common/core/text.hpp"
#include "filter_zoo_math.hpp"
#include "filter_zoo_measure.hpp"

namespace zoo::views {
using ts::layout::fmt;
using ts::layout::kAmber;
using ts::layout::kWhite;
namespace L = ts::layout;

enum ViewKind { kMethods, kAzimuthGrid, kSupports, kMemory, kKernels, kBias };
inline const char* const kViewKeys[] = {"methods", "azimuths", "supports", "memory", "kernels", "bias"};

const glm::vec4 kGrey{0.6f, 0.6f, 0.65f, 1.0f};
// The supports' colours (the inspector's for the preimage, the EWA ellipse
// and trilinear's 2^lambda square: common/app/inspect_view.cpp).
const glm::vec4 kPreimageColour{1.0f, 1.0f, 1.0f, 1.0f}, kEllipseColour{1.0f, 0.3f, 0.9f, 1.0f},
    kSquareColour{1.0f, 0.85f, 0.2f, 1.0f}, kRipmapColour{0.35f, 1.0f, 0.35f, 1.0f}, kSatColour{0.2f, 0.9f, 1.0f, 1.0f},
    kProbeColour{1.0f, 0.45f, 0.1f, 1.0f}, kTexelGridColour{0.42f, 0.42f, 0.47f, 1.0f};

// Bytes per texel of what each method keeps, over the texture's: the memory
// figure's x (SAT: satBits / 8 a channel).
inline double memoryRatio(int m) {
  switch (m) {
    case kNearest:
    case kLinear: return 1.0;
    case kRipmap: return ripmapMemoryRatio(kTexels, kTexels);
    case kSat: return satBits(kTexels, kTexels) / 8.0;
    case kExact: return 1.0;  // the texture, and per-row sums to go fast (ts::AreaIntegral) if wanted
    default: return mipMemoryRatio(kTexels, kTexels);
  }
}

// Whether `ms` holds every measurement a label template names ("{name}" or
// "{name|%.2f}"): a window draws before its first measurement, and the
// click test builds over stand-in pictures with none.
inline bool measuresAll(const ts::Measurements& ms, const std::string& templ) {
  for (size_t open = templ.find('{'); open != std::string::npos; open = templ.find('{', open + 1)) {
    const size_t close = templ.find('}', open);
    const std::string name = templ.substr(open + 1, std::min(templ.find('|', open), close) - open - 1);
    if (std::none_of(ms.begin(), ms.end(), [&](const ts::Measurement& x) { return x.name == name; })) return false;
  }
  return true;
}
// The template with its measurements printed, or `otherwise` when this
// state has not measured them: a number is printed only from `ms`.
inline L::Text printed(const ts::Measurements& ms, const std::string& templ, const L::Text& otherwise = L::Text()) {
  return measuresAll(ms, templ) ? L::measuredText(ms, templ) : otherwise;
}
// A method's name; GL's anisotropic filter's says its limit, a parameter.
inline L::Text methodText(int m) {
  if (m == kAniso16)
    return L::Text("GL anisotropic ") + L::given("GL_TEXTURE_MAX_ANISOTROPY_EXT", kMaxAniso, "%g") + "x";
  return L::Text(methodTitle(m));
}
// A number in a name (a kernel's width, a level's index): given, not measured.
inline L::Text num(const std::string& what, double v) { return L::given(what, v, "%g"); }
// A kernel's name, its parameters given.
inline L::Text kernelText(int k) {
  switch (k) {
    case kBox:
      return "box (Buss's " + num("the box's width, texels", 2) + "x" + num("the box's height, texels", 2) + ")";
    case kLanczos2: return "Lanczos-" + num("Lanczos lobes", 2);
    case kLanczos3: return "Lanczos-" + num("Lanczos lobes", 3);
    default: return L::Text(kernelTitle(k));
  }
}
// "1x1 level": the chain's last level, named by its size.
inline L::Text topLevelText() {
  return num("the last level's width", 1) + "x" + num("the last level's height", 1) + " level";
}
// A key of meaningful colours (layout::legend) whose meanings print numbers:
// the numbers attached to the labels that show them.
inline float legendOf(ts::Frame& f, L::Box band, const std::vector<std::pair<glm::vec4, L::Text>>& entries, int scale) {
  std::vector<ts::LegendEntry> plain;
  L::Text all;
  for (const auto& [colour, meaning] : entries) plain.push_back({colour, meaning.text}), all = all + meaning;
  const size_t first = f.labels.size();
  const float below = L::legend(f, band, plain, scale);
  L::attachNumbers(f, first, all);
  return below;
}
// A key line per entry (a swatch and its meaning in its colour), from the
// top of `band` down, the meanings' numbers attached; returns the y below
// the last line.  layout::legend's swatch is a boxed label, reaching 3 px a
// scale beyond its text on every side: the lines keep that room.
inline float keyPad(int scale) { return 3.0f * float(scale); }
inline float keyStep(int scale) { return L::lineHeight(scale) + 3.0f * float(scale); }
// The width a key line takes at `scale`: pad, swatch, gap and text (layout::legend's).
inline float keyWidth(const std::string& meaning, int scale) {
  return keyPad(scale) + ts::text::height(scale) + 4.0f * float(scale) + ts::text::width(meaning, scale);
}
inline float keyLines(ts::Frame& f, L::Box band, const std::vector<std::pair<glm::vec4, L::Text>>& entries, int scale) {
  float y = band.y0 + keyPad(scale);
  for (const auto& [colour, meaning] : entries) {
    if (y + ts::text::height(scale) + keyPad(scale) > band.y1 + 1) break;
    if (keyWidth(meaning.text, scale) <= band.w()) {
      legendOf(f, {band.x0 + keyPad(scale), y, band.x1, y + L::lineHeight(scale)}, {{colour, meaning}}, scale);
      y += keyStep(scale);
      continue;
    }
    // Too wide for its line (a small window): layout::legend's swatch, the
    // meaning wrapped beside it, and the entry in the frame's legend.
    L::addSwatch(f, band.x0 + keyPad(scale), y, scale, colour);
    f.legend.push_back({colour, meaning.text});
    const float x0 = band.x0 + keyPad(scale) + ts::text::height(scale) + 4.0f * float(scale);
    const float below = L::caption(f, {x0, y, band.x1, band.y1}, meaning, colour, scale, ts::Align::Left);
    y = std::max(y + keyStep(scale), below + keyPad(scale) + float(scale));
  }
  return y;
}
// The height `lines` key lines take at `scale`.
inline float keyHeight(int lines, int scale) { return float(lines) * keyStep(scale) + keyPad(scale); }

// The state a drawing needs.
struct Views {
  int scene = kSlant, method = kProbes, pattern = kChecker, kernel = kBox;
  double azimuth = 45, bias = 0;
  bool linearLight = false;
  int pickX = 250, pickY = 100;  // the supports view's pixel, in the 384 x 192 picture (0,0 top left)

  void buildMethods(ts::Frame& f, const Result* m) const;
  void buildAzimuths(ts::Frame& f, const Result* m, const ts::Measurements& ms) const;
  void buildSupports(ts::Frame& f, const Result* m, const ts::Measurements& ms) const;
  void buildMemory(ts::Frame& f, const Result* m, const ts::Measurements& ms) const;
  void buildKernels(ts::Frame& f, const Result* m, const ts::Measurements& ms) const;
  void buildBias(ts::Frame& f, const Result* m) const;

  L::Text sceneText() const {
    const L::Text turn = L::given("azimuth, degrees", azimuth, "%g");
    return scene == kSlant ? "slanted plane, texture turned " + turn + " deg"
           : scene == kZonePlate
               ? "zone plate, turned " + turn + " deg, " + L::given("texels a pixel", kZoneTexelsPerPixel, "%g") +
                     " texels a pixel"
               : "magnified: " + L::given("texels across", kTexels, "%g") + " texels over " +
                     L::given("pixels across", kMagnifyPixels, "%g") + " pixels, turned " + turn + " deg";
  }
  L::Text maskText() const {
    const L::Text rms = "RMS (" + L::given("bits a channel", 8, "%g") +
                        "-bit R,G,B) against the exact area integral over ";
    return scene == kSlant ? rms + "the far field, LOD " + L::given("the far field's lowest LOD", kFarLo, "%g") + ".." +
                                 L::given("the far field's highest LOD", kFarHi, "%g")
                           : rms + "the picture";
  }
};

// The scale of lines of notes: the largest (up to maxScale) at which every
// line fits `width` (at 1 they may wrap).
inline int notesScale(const std::vector<L::Text>& lines, float width, int maxScale) {
  int s = std::max(1, maxScale);
  while (s > 1 &&
         std::any_of(lines.begin(), lines.end(), [&](const L::Text& l) { return ts::text::width(l.text, s) > width; }))
    --s;
  return s;
}
// Lines of notes at notesScale's scale, from the box's top down.
inline void notes(ts::Frame& f, L::Box box, const std::vector<L::Text>& lines, glm::vec4 colour, int maxScale,
                  ts::Align align = ts::Align::Left) {
  const int s = notesScale(lines, box.w(), maxScale);
  L::Column c(f, box);
  for (const L::Text& l : lines) c.add(l, colour, s, align);
}
// The height `lines` lines of notes take at `scale` (one line each).
inline int notesHeight(int lines, int scale) { return int(std::ceil(lines * L::lineHeight(scale))) + 4; }

// A picture measure() made, in a cell (or "measuring..." before it).
inline void picturePanel(ts::Frame& f, const std::string& id, const ts::Rect& r, const ts::TextureDesc* t, int scale) {
  if (t && t->image) {
    f.panels.push_back(L::texturePanel(id, r, f.addTexture(*t)));
    for (const auto& p : t->params)  // a coarse first stage (coarseRow): marked as such
      if (p.first == "stage" && p.second == "coarse") L::refiningTag(f, r);
  } else L::caption(f, L::box(r), "measuring...", kWhite, scale);
}
inline const Row* rowAt(const Result* m, double az) {
  if (!m) return nullptr;
  for (const Row& r : m->rows)
    if (std::abs(r.azimuth - az) < 1e-9) return &r;
  return nullptr;
}
inline std::string readsText(double r) { return r < 0 ? "reads: GL's own" : fmt("%.1f texels", r); }

// Every method side by side at the current azimuth.  A narrow window
// wraps the notes and the cells' captions rather than cut them: the notes
// take the lines they need at the frame's width (at least two), the cells'
// bands the lines their captions need at the cells' width (flowFitting; at
// the figures' sizes every caption fits one line, and the layout is
// flow()'s).
inline void Views::buildMethods(ts::Frame& f, const Result* m) const {
  const int w = f.width, h = f.height;
  const int sc = L::scaleFor({0, 0, w, h}, 2), line = int(L::lineHeight(sc));
  const std::vector<L::Text> footNotes = {
      sceneText().text + (bias != 0 ? ", LOD bias " + fmt("%g", bias) : std::string()) + ".  " + maskText().text,
      "GL_* and anisotropic: GL renders" + (m ? " (" + m->renderer + ")" : std::string()) +
          "; ripmap, SAT, probe line, EWA, exact: on the CPU, in double precision"};
  const int fs = notesScale(footNotes, float(w - 8), sc);  // as notes() picks it; at 1 a line may wrap
  const int footH = std::max(2 * line, int(std::ceil(L::columnHeight(footNotes, fs, float(w - 8)))));
  const Row* row = m && m->scene == scene ? rowAt(m, azimuth) : nullptr;
  auto noteOf = [&](int k) -> std::string {
    if (!row) return "";
    return std::isnan(row->rms[size_t(k)]) ? std::string("RMS, reads: measuring...")
           : k == kExact                   ? "the reference (" + readsText(row->reads[size_t(k)]) + ")"
                         : "RMS " + fmt("%.2f", row->rms[size_t(k)]) + ", " + readsText(row->reads[size_t(k)]);
  };
  L::FlowSpec spec;
  spec.n = kMethodCount, spec.aspect = float(kImageW) / kImageH, spec.linesAbove = 1, spec.linesBelow = 1, spec.gap = 8;
  spec.minCellWidth = 150;
  std::vector<L::Stack> above, below;
  for (int k = 0; k < kMethodCount; ++k) above.push_back({methodTitle(k)}), below.push_back({noteOf(k)});
  const std::vector<L::Cell> cells = L::flowFitting({4, 4, float(w - 4), float(h - footH - 4)}, spec, above, below);
  for (int k = 0; k < kMethodCount && k < int(cells.size()); ++k) {
    const L::Cell& c = cells[size_t(k)];
    const glm::vec4 colour = k == method ? kAmber : kWhite;
    L::caption(f, c.above, methodTitle(k), colour, c.scale, ts::Align::Left);
    picturePanel(f, std::string("method_") + methodKey(k), c.picture, row ? &row->pictures[size_t(k)] : nullptr,
                 c.scale);
    if (row) L::caption(f, c.below, noteOf(k), colour, c.scale, ts::Align::Left);
  }
  notes(f, {4, float(h - footH - 2), float(w - 4), float(h)}, footNotes, kGrey, sc, ts::Align::Center);
}

// Methods x azimuths (the slanted plane): a band per azimuth, each
// method's RMS after its name; at the foot, the key of the highlight and
// what the numbers are.
inline void Views::buildAzimuths(ts::Frame& f, const Result* m, const ts::Measurements& ms) const {
  const int w = f.width, h = f.height;
  const int sc = L::scaleFor({0, 0, w, h / 3}, 2), line = int(L::lineHeight(sc));
  // The foot: the highlight's key and two lines of notes, at one scale.
  const L::Text same = measuresAll(ms, "{last_level_like_level0}{nmn_nearest_differ_far}{nmn_nearest_differ_lod_min}")
                           ? "GL_NEAREST_MIPMAP_NEAREST's error is GL_NEAREST's: levels " +
                                 num("the first level above level 0", 1) + ".." +
                                 L::measured(ms, "last_level_like_level0", "%.0f") +
                                 " of the checkerboard are the same board, so a nearest sample takes level " +
                                 num("level", 0) + "'s colour; the pictures differ in " +
                                 L::measured(ms, "nmn_nearest_differ_far", "%.0f") +
                                 " far-field pixels, beyond it from LOD " +
                                 L::measured(ms, "nmn_nearest_differ_lod_min", "%.2f")
                           : L::Text();
  const std::vector<L::Text> footNotes = {"after each name: " + maskText() +
                                              (bias != 0 ? "; LOD bias " + L::given("LOD bias", bias, "%g")
                                                         : L::Text()),
                                          same};
  const int fs = notesScale(footNotes, float(w - 8), sc);
  int noteLines = 0;  // a note too long for one line wraps: its lines are reserved
  for (const L::Text& t : footNotes) noteLines += L::captionLines(t.text, fs, float(w - 8));
  const float footH = keyHeight(1, fs) + float(noteLines) * L::lineHeight(fs) + 4;
  const float bandH = (float(h) - footH - 4) / 3;
  for (int b = 0; b < 3; ++b) {
    const double az = kAzimuths[size_t(b)];
    const float y0 = 2 + b * bandH;
    L::caption(f, {4, y0, float(w - 4), y0 + float(line)},
               "texture turned " + L::given("azimuth, degrees", az, "%g") + " deg", kWhite, sc, ts::Align::Left);
    L::FlowSpec spec;
    spec.n = kMethodCount, spec.aspect = float(kImageW) / kImageH, spec.linesAbove = 1, spec.linesBelow = 0,
    spec.gap = 6;
    const std::vector<L::Cell> cells = L::flow({4, y0 + float(line), float(w - 4), y0 + bandH - 2}, spec);
    const Row* row = m && m->scene == kSlant ? rowAt(m, az) : nullptr;
    for (int k = 0; k < kMethodCount && k < int(cells.size()); ++k) {
      const L::Cell& c = cells[size_t(k)];
      L::Text t = methodText(k);
      if (k != kExact) t = t + printed(ms, "  {rms_exact[" + std::string(methodKey(k)) + "@" + azKey(az) + "]|%.1f}");
      L::caption(f, c.above, t, k == method ? kAmber : kWhite, c.scale, ts::Align::Left);
      picturePanel(f, std::string("az") + azKey(az) + "_" + methodKey(k), c.picture,
                   row ? &row->pictures[size_t(k)] : nullptr, c.scale);
    }
  }
  // The key of the highlight, then why GL_NEAREST_MIPMAP_NEAREST's number is GL_NEAREST's, measured.
  const float foot = float(h) - footH;
  const float below = keyLines(f, {4, foot, float(w - 4), foot + keyHeight(1, fs)},
                               {{kAmber, "the method highlighted (--method): " + std::string(methodTitle(method))}},
                               fs);
  notes(f, {4, below, float(w - 4), float(h)}, footNotes, kGrey, fs);
}

// One pixel's footprint on level 0 with every method's support: left (or
// above, in a tall window) the picture with the pixel ringed, the claim's
// number (SAT's box over an 8:1 footprint at 45 degrees) and the key;
// right (or below) level 0 of the texture around the footprint.
inline void Views::buildSupports(ts::Frame& f, const Result* m, const ts::Measurements& ms) const {
  const int w = f.width, h = f.height;
  const bool wide = w >= h;
  const int sc = L::scaleFor({0, 0, wide ? w / 2 : w, wide ? h : h / 2}, 2), line = int(L::lineHeight(sc));
  const View v = sceneView(scene, azimuth);
  const int col = std::clamp(pickX, 0, kImageW - 1), row = std::clamp(pickY, 0, kImageH - 1);
  const double x = col + 0.5, y = kImageH - 1 - row + 0.5;
  const bool on = v.covers(x, y);
  const glm::dvec2 c = on ? v.uv(x, y) : glm::dvec2(0.0);
  const Jacobian j = on ? v.jacobian(x, y) : Jacobian{};
  const ts::Polygon2 pre = on ? v.preimage(col, row) : ts::Polygon2{};
  const double lambda = on ? glLambda(j, bias) : 0;
  const ProbeLine probe = on ? probeLine(j, bias) : ProbeLine{};
  // The key: each support's colour and what it is (this pixel's numbers, measured).
  const std::vector<std::pair<glm::vec4, L::Text>> key = {
      {kPreimageColour, "the exact preimage" + printed(ms, " ({pick_preimage_texels|%.1f} texels)")},
      {kSquareColour, "trilinear's " + num("the levels' ratio", 2) + "^lambda square"},
      {kRipmapColour,
       "the ripmap's " + num("the levels' ratio", 2) + "^i x " + num("the levels' ratio", 2) + "^j rectangle"},
      {kSatColour, "the SAT's box" + printed(ms, ", {pick_sat_box_ratio|%.2f}x this pixel's footprint")},
      {kProbeColour,
       printed(ms, "{pick_probes|%.0f} probes, lambda {pick_probe_lambda|%.2f}", "the probe line's probes")},
      {kEllipseColour, "EWA's ellipse"},
      {kAmber, "the pixel, ringed in the picture"},
      {kTexelGridColour, "level " + num("level", 0) + "'s texel grid"}};
  const L::Text where = sceneText();
  // The claim's number, where the reader looks for the SAT's box.
  const bool claimed = measuresAll(ms, "{sat_box_ratio[8to1_45deg]}{sat_box_ratio[8to1_0deg]}");
  const L::Text eight = L::given("the footprint's long side over its short", 8, "%g") + ":" +
                        L::given("the footprint's short side", 1, "%g");
  const std::vector<std::pair<L::Text, int>> claim =
      claimed ? std::vector<std::pair<L::Text, int>>{{"The SAT's box: " +
                                                          L::measured(ms, "sat_box_ratio[8to1_45deg]", "%.2f") +
                                                          "x the area",
                                                      sc},
                                                     {"of an " + eight + " footprint at " +
                                                          L::given("the footprint's turn, degrees", 45, "%g") + " deg",
                                                      sc},
                                                     {"(along the axes: " +
                                                          L::measured(ms, "sat_box_ratio[8to1_0deg]", "%.2f") + "x)",
                                                      1}}
              : std::vector<std::pair<L::Text, int>>{};
  auto placeClaim = [&](L::Box band) {
    L::Column lines(f, band);
    for (const auto& [text, scale] : claim) lines.add(text, scale == 1 ? kGrey : kWhite, scale, ts::Align::Left);
  };
  int claimH = 0;
  for (const auto& c : claim) claimH += int(std::ceil(L::lineHeight(c.second)));
  if (claimH) claimH += 6;
  // The key's scale: the largest (up to sc) at which its widest line fits `width`.
  auto keyScale = [&](float width) {
    int s2 = sc;
    auto fits = [&](int s3) {
      if (ts::text::width(where.text, s3) > width) return false;
      for (const auto& kl : key)
        if (keyWidth(kl.second.text, s3) > width) return false;
      return true;
    };
    while (s2 > 1 && !fits(s2)) --s2;
    return s2;
  };
  // Wide: the picture, the claim and the key in a column left of the
  // texture view.  Tall: the picture and the key side by side above it,
  // the claim under both.
  float keyW = ts::text::width(where.text, 1) + 8;
  for (const auto& kl : key) keyW = std::max(keyW, keyWidth(kl.second.text, 1) + 8);
  const int leftW = wide ? w * 2 / 5 : std::max(40, w - 8 - int(keyW) - 8);
  const int ks = keyScale(wide ? float(leftW - 4) : keyW);
  const int keyH = int(std::ceil(keyHeight(int(key.size()), ks) + L::lineHeight(ks))) + 4;
  const int pictureRoom = wide ? h - 2 * line - keyH - claimH : std::max(20, (h - 3 * line - claimH) / 3);
  const double k = std::max(0.05, std::min(double(leftW - 8) / kImageW, double(pictureRoom) / kImageH));
  const ts::Rect pic{4, line + 2, std::max(8, int(kImageW * k)), std::max(4, int(kImageH * k))};
  const Row* r = m && m->scene == scene ? rowAt(m, azimuth) : nullptr;
  L::caption(f, {4, 2, float(wide ? leftW : w - 4), float(line)},
             L::Text(methodTitle(method)) + ", pixel " + L::given("the pixel's column", col, "%g") + "," +
                 L::given("the pixel's row", row, "%g"),
             kAmber, sc, ts::Align::Left);
  picturePanel(f, "picture", pic, r ? &r->pictures[size_t(method)] : nullptr, sc);
  {
    ts::Panel ring = L::unitPanel("pick", pic);
    const float px = float(x / kImageW), py = float(y / kImageH), rx = 5.0f / float(pic.w), ry = 5.0f / float(pic.h);
    ring.batches.push_back(
        ts::lineLoop({{px - rx, py - ry}, {px + rx, py - ry}, {px + rx, py + ry}, {px - rx, py + ry}}, kAmber, 2.0f,
                     "pick"));
    f.panels.push_back(ring);
  }
  float below = float(pic.y + pic.h + 6);
  if (wide && claimH) {
    placeClaim({4, below, float(leftW), below + float(claimH)});
    below += float(claimH);
  }
  const L::Box keyBox = wide ? L::Box{4, below, float(leftW), float(h)}
                             : L::Box{float(pic.x + pic.w + 8), float(pic.y), float(w - 4),
                                      float(pic.y + std::max(pic.h, keyH))};
  {
    const float after = keyLines(f, keyBox, key, ks);
    L::Column tail(f, {keyBox.x0, after, keyBox.x1, keyBox.y1});
    tail.add(where, kGrey, ks, ts::Align::Left);
  }
  int areaY = wide ? line + 2 : pic.y + std::max(pic.h, keyH) + line + 4;
  if (!wide && claimH) {
    placeClaim({4, float(areaY - line), float(w - 4), float(areaY - line + claimH)});
    areaY += claimH;
  }
  // The texture around the footprint.
  const int areaX = wide ? leftW + 12 : 4;
  const ts::Rect view{areaX, areaY, std::max(8, w - areaX - 4), std::max(8, h - areaY - 4)};
  L::caption(f, {float(areaX), float(areaY - line), float(w - 4), float(areaY - 2)},
             on ? "level " + num("level", 0) + " around its footprint" +
                      printed(ms, ": lambda {pick_lambda|%.2f}, {pick_texels_per_pixel|%.1f} texels a pixel")
                : L::Text("the pixel is off the surface: pick another (--pick X,Y)"),
             kWhite, sc, ts::Align::Left);
  if (!on) return;
  const double side = std::exp2(std::max(0.0, lambda));
  const glm::dvec2 rip = ripmapLevels(j, bias);
  const glm::dvec2 ripSize(std::exp2(std::clamp(rip.x, 0.0, double(kLevels - 1))),
                           std::exp2(std::clamp(rip.y, 0.0, double(kLevels - 1))));
  const glm::dvec2 box = satHalfBox(j, bias);
  double u0 = c.x - box.x, u1 = c.x + box.x, v0 = c.y - box.y, v1 = c.y + box.y;
  auto grow = [&](glm::dvec2 p) {
    u0 = std::min(u0, p.x), u1 = std::max(u1, p.x), v0 = std::min(v0, p.y), v1 = std::max(v1, p.y);
  };
  for (const glm::dvec2& p : pre) grow(p);
  grow(c - side / 2), grow(c + side / 2), grow(c - ripSize / 2.0), grow(c + ripSize / 2.0);
  const double eu = std::hypot(j.dudx, j.dudy), ev = std::hypot(j.dvdx, j.dvdy);
  grow({c.x - eu, c.y - ev}), grow({c.x + eu, c.y + ev});
  const double extent = std::max({u1 - u0, v1 - v0, 4.0}) * 1.1, cu = (u0 + u1) / 2, cv = (v0 + v1) / 2;
  const double aspect = double(view.w) / double(view.h);
  const double halfU = extent / 2 * std::max(1.0, aspect), halfV = extent / 2 * std::max(1.0, 1.0 / aspect);
  ts::Panel p;
  p.id = "supports";
  p.viewport = view;
  p.projection = glm::ortho(float(cu - halfU), float(cu + halfU), float(cv - halfV), float(cv + halfV), -1.0f, 1.0f);
  ts::TextureDesc tex = sceneTexture(scene, pattern);
  tex.minFilter = tex.magFilter = GL_NEAREST;
  tex.mipmaps = false;
  ts::Batch quad;
  quad.role = "texture";
  quad.texture = f.addTexture(tex);
  const float x0 = float(cu - halfU), x1 = float(cu + halfU), y0 = float(cv - halfV), y1 = float(cv + halfV);
  for (glm::vec2 q : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y0), glm::vec2(x1, y1),
                      glm::vec2(x0, y1)})
    quad.vertices.push_back({glm::vec3(q, 0.0f), glm::vec4(q.x / kTexels, q.y / kTexels, 0.0f, 1.0f), glm::vec4(1.0f)});
  p.batches.push_back(quad);
  if (halfU <= 40 && halfV <= 40) {  // level 0's texel grid, faint
    std::vector<glm::vec2> grid;
    for (double u = std::ceil(cu - halfU); u <= cu + halfU; ++u)
      grid.push_back({float(u), y0}), grid.push_back({float(u), y1});
    for (double t = std::ceil(cv - halfV); t <= cv + halfV; ++t)
      grid.push_back({x0, float(t)}), grid.push_back({x1, float(t)});
    p.batches.push_back(ts::lineSegments(grid, kTexelGridColour, 1.0f, "texel_grid"));
  }
  auto rect = [&](glm::dvec2 half, glm::vec4 colour, float width, const char* role) {
    p.batches.push_back(ts::lineLoop({{float(c.x - half.x), float(c.y - half.y)},
                                      {float(c.x + half.x), float(c.y - half.y)},
                                      {float(c.x + half.x), float(c.y + half.y)},
                                      {float(c.x - half.x), float(c.y + half.y)}},
                                     colour, width, role));
  };
  rect(box, kSatColour, 1.0f, "sat_box");
  rect(ripSize / 2.0, kRipmapColour, 1.0f, "ripmap_rectangle");
  rect(glm::dvec2(side / 2), kSquareColour, 1.0f, "trilinear_square");
  std::vector<glm::vec2> pts;
  for (int q = 0; q < 64; ++q) {
    const double a = 2 * kPi * q / 64, ca = std::cos(a), sa = std::sin(a);
    pts.push_back({float(c.x + j.dudx * ca + j.dudy * sa), float(c.y + j.dvdx * ca + j.dvdy * sa)});
  }
  p.batches.push_back(ts::lineLoop(pts, kEllipseColour, 1.0f, "ewa_ellipse"));
  // The probes: a square at each, its side the texels of its level (2^lambda).
  const double ps = std::exp2(std::max(0.0, probe.lambda)) / 2;
  for (int q = 0; q < probe.n; ++q) {
    const glm::dvec2 at = probe.at(c, q);
    const float a = float(at.x), b = float(at.y), s = float(std::max(ps, extent / 150));
    p.batches.push_back(
        ts::lineLoop({{a - s, b - s}, {a + s, b - s}, {a + s, b + s}, {a - s, b + s}}, kProbeColour, 2.0f, "probe"));
  }
  pts.clear();
  for (const glm::dvec2& q : pre) pts.push_back(glm::vec2(q));
  p.batches.push_back(ts::lineLoop(pts, kPreimageColour, 2.0f, "exact_preimage"));
  f.panels.push_back(p);
}

// Memory against error: each method's bytes per texel over the texture's,
// and its far-field RMS at 0 and 45 degrees.  Several methods share a
// memory (the mip chain's), so each is named by a tag beside its pair of
// marks, tags stacked apart with a leader to their marks.
inline void Views::buildMemory(ts::Frame& f, const Result* m, const ts::Measurements& ms) const {
  const int w = f.width, h = f.height;
  const int sc = L::scaleFor({0, 0, w, h}, 2), line = int(L::lineHeight(sc));
  const Row* a = m && m->scene == kSlant ? rowAt(m, 0.0) : nullptr;
  const Row* b = m && m->scene == kSlant ? rowAt(m, 45.0) : nullptr;
  if (!a || !b) {
    L::caption(f, {4, float(h / 2), float(w - 4), float(h)},
               m && m->scene != kSlant ? "the memory view measures the slanted plane (--scene slant)" : "measuring...",
               kWhite, 1);
    return;
  }
  const glm::vec4 kBlue{0.35f, 0.65f, 1.0f, 1.0f};
  float y = L::caption(f, {4, 2, float(w - 4), 2.0f + float(line)}, "memory against error", kWhite, sc);
  y = keyLines(f, {8, y, float(w - 4), y + keyHeight(2, sc)},
               {{kBlue, "squares: texture turned " + L::given("azimuth, degrees", 0, "%g") + " deg"},
                {kAmber, "crosses: texture turned " + L::given("azimuth, degrees", 45, "%g") + " deg"}},
               sc);
  ts::plot::Spec s;
  s.id = "memory_plot";
  s.xLabel = "memory, over the 8-bit texture's";
  s.yLabel = "far-field RMS vs exact";
  s.scale = sc;
  double ymax = 0;
  for (int k = kNearest; k < kMethodCount; ++k) ymax = std::max({ymax, a->rms[size_t(k)], b->rms[size_t(k)]});
  // Room left of memory 1 for the tags of the methods there.
  s.x0 = 0.3, s.x1 = 4.3, s.y0 = 0, s.y1 = std::ceil(ymax / 5 + 0.5) * 5;
  s.xTicks = ts::plot::ticks(1, 4, 0.5);
  s.yTicks = ts::plot::ticks(0, s.y1, ts::plot::niceStep(s.y1));
  ts::plot::Series at0("rms_0deg", kBlue, ts::plot::Mark::Squares), at45("rms_45deg", kAmber, ts::plot::Mark::Crosses);
  for (int k = kNearest; k < kMethodCount; ++k) {
    at0.points.push_back({memoryRatio(k), a->rms[size_t(k)]});
    at45.points.push_back({memoryRatio(k), b->rms[size_t(k)]});
  }
  s.series = {at0, at45};
  const size_t firstPlotLabel = f.labels.size();
  const ts::Rect vp = ts::plot::draw(f, s, {0, int(y), w, h - 2 * line - int(y)});
  L::attachNumbers(f, firstPlotLabel, L::given("bits a channel of the texture", 8, "%g"));

  // The tags: a method at memory 1 or at the ripmap's (the plot's edges) to
  // the left of its marks, the others to the right; in each column from
  // the top down, each at its marks' height or a line below the one above;
  // at the largest scale (up to the text's) at which they fit.  A tag that
  // would still overlap another label tries the other side, else is left
  // out (small windows only).
  auto at = [&](double mx, double my) {
    return glm::vec2(float(vp.x + (mx - s.x0) / (s.x1 - s.x0) * vp.w),
                     float(vp.y + (1 - (my - s.y0) / (s.y1 - s.y0)) * vp.h));
  };
  struct Tag {
    int method;
    glm::vec2 mark;
    bool left;
    L::Text name;
    float top = 0;
  };
  std::vector<Tag> tags;
  for (int k = kNearest; k < kMethodCount; ++k) {
    const double mx = memoryRatio(k);
    tags.push_back({k, at(mx, (a->rms[size_t(k)] + b->rms[size_t(k)]) / 2), mx < 1.2 || mx > 3.5,
                    k == kAniso16 ? "aniso " + L::given("GL_TEXTURE_MAX_ANISOTROPY_EXT", kMaxAniso, "%g") + "x"
                                  : L::Text(methodKey(k))});
  }
  std::stable_sort(tags.begin(), tags.end(), [](const Tag& p, const Tag& q) {
    return p.mark.x != q.mark.x ? p.mark.x < q.mark.x : p.left != q.left ? p.left : p.mark.y < q.mark.y;
  });
  const float gap = 10.0f + 2.0f * float(sc);
  auto fits = [&](int scale) {
    int column = 0;
    for (size_t k = 0; k < tags.size(); ++k) {
      const float tw = ts::text::width(tags[k].name.text, scale);
      if (tags[k].left ? tags[k].mark.x - gap - tw < float(vp.x) + 2
                       : tags[k].mark.x + gap + tw > float(vp.x + vp.w) - 2)
        return false;
      column = k > 0 && tags[k].mark.x == tags[k - 1].mark.x && tags[k].left == tags[k - 1].left ? column + 1 : 1;
      if (float(column) * L::lineHeight(scale) > float(vp.h) - 4) return false;
    }
    return true;
  };
  int tagScale = sc;
  while (tagScale > 1 && !fits(tagScale)) --tagScale;
  const float th = ts::text::height(tagScale), lh = L::lineHeight(tagScale);
  for (size_t k = 0; k < tags.size();) {
    size_t e = k;
    while (e < tags.size() && tags[e].mark.x == tags[k].mark.x && tags[e].left == tags[k].left) ++e;
    for (size_t i = k; i < e; ++i)
      tags[i].top = std::max(tags[i].mark.y - th / 2, i > k ? tags[i - 1].top + lh : float(vp.y) + 2);
    // A column that runs out of the plot's bottom moves up, not above its top.
    const float over = std::min(tags[e - 1].top + th - float(vp.y + vp.h - 2), tags[k].top - float(vp.y) - 2);
    for (size_t i = k; over > 0 && i < e; ++i) tags[i].top -= over;
    k = e;
  }
  ts::Panel leaders;
  leaders.id = "memory_tags";
  leaders.viewport = vp;
  leaders.projection = glm::ortho(float(vp.x), float(vp.x + vp.w), float(vp.y + vp.h), float(vp.y), -1.0f,
                                  1.0f);  // frame pixels, y down
  std::vector<glm::vec2> segs;
  for (const Tag& t : tags) {
    for (bool left : {t.left, !t.left}) {
      ts::Label l;
      l.x = left ? t.mark.x - gap : t.mark.x + gap, l.y = std::round(t.top);
      l.text = t.name.text, l.color = s.textColor, l.scale = tagScale,
      l.align = left ? ts::Align::Right : ts::Align::Left;
      for (const L::Text::Given& g : t.name.given) l.given.push_back({g.name, g.value});
      if (!L::placeFree(f, l, L::box(vp))) continue;
      const L::Box placed = L::labelBox(f.labels.back());
      segs.push_back({t.mark.x + (left ? -7.0f : 7.0f), t.mark.y});
      segs.push_back({left ? placed.x1 + 2 : placed.x0 - 2, (placed.y0 + placed.y1) / 2});
      break;
    }
  }
  leaders.batches.push_back(ts::lineSegments(segs, kGrey, 1.0f, "tag_leaders"));
  f.panels.push_back(leaders);

  notes(f, {4, float(h - 2 * line), float(w - 4), float(h)},
        {printed(ms, "mip chain {mip_memory_ratio|%.4f}x (nmn, trilinear, aniso, probes, EWA); ripmap "
                     "{ripmap_memory_ratio|%.5f}x; "
                     "SAT {sat_bits[256]|%.0f} bits a channel = {sat_memory_ratio|%g}x"),
         L::given("texture side, texels", kTexels, "%g") + "x" + L::given("texture side, texels", kTexels, "%g") +
             " texture; RMS over the slanted plane's far field (LOD " +
             L::given("the far field's lowest LOD", kFarLo, "%g") + ".." +
             L::given("the far field's highest LOD", kFarHi, "%g") + ")"},
        kGrey, sc);
}

// The mip kernels: trilinear with each kernel's chain, sRGB values and
// linear light; under each, its far-field RMS and its 1 x 1 level.
inline void Views::buildKernels(ts::Frame& f, const Result* m, const ts::Measurements& ms) const {
  const int w = f.width, h = f.height;
  const int sc = L::scaleFor({0, 0, w, h}, 2), line = int(L::lineHeight(sc));
  L::FlowSpec spec;
  spec.n = 2 * kKernelCount, spec.aspect = float(kImageW) / kImageH, spec.linesAbove = 1, spec.linesBelow = 1,
  spec.gap = 8;
  spec.minCellWidth = 150;
  const std::vector<L::Cell> cells = L::flow({4, 4, float(w - 4), float(h - 2 * line - 4)}, spec);
  for (int k = 0; k < 2 * kKernelCount && k < int(cells.size()); ++k) {
    const L::Cell& c = cells[size_t(k)];
    const int kern = k / 2;
    const bool lin = k % 2;
    const KernelRow* row = nullptr;
    if (m)
      for (const KernelRow& r : m->kernels)
        if (r.kernel == kern && r.linear == lin) row = &r;
    const glm::vec4 colour = kern == kernel && lin == linearLight ? kAmber : kWhite;
    const std::string key = std::string(kernelKey(kern)) + (lin ? "_linear" : "_srgb");
    L::caption(f, c.above, kernelText(kern) + (lin ? ", linear light" : ", sRGB"), colour, c.scale, ts::Align::Left);
    picturePanel(f, "kernel_" + key, c.picture, row ? &row->picture : nullptr, c.scale);
    if (row)
      L::caption(f, c.below,
                 printed(ms, "RMS {rms_kernel[" + key + "]|%.2f}, ") + topLevelText() +
                     printed(ms, " {mip_top[" + key + "]|%.0f}"),
                 colour, c.scale, ts::Align::Left);
  }
  const std::string tops =
      ": the checkerboard's mean in double precision, {mip_mean[srgb]|%.1f} in sRGB values, {mip_mean[linear]|%.1f} "
      "in linear light; each chain's is off it by at most {mip_top_max_error[srgb]|%.1f} and "
      "{mip_top_max_error[linear]|%.1f}: "
      "every level is rounded to ";
  // The foot: the highlight's key with a note beside it, then two notes.
  const float foot = float(h - 2 * line - 2);
  const int fs = std::max(1, sc - 1);
  const L::Text highlighted = "the chain highlighted (--kernel, --linear-light): " + kernelText(kernel) +
                              (linearLight ? ", linear light" : ", sRGB values");
  const float below = keyLines(f, {4, foot, float(w - 4), foot + keyHeight(1, fs)}, {{kAmber, highlighted}}, fs);
  const float right = 4 + keyWidth(highlighted.text, fs) + 16;
  if (right < float(w - 4))
    L::caption(f, {right, foot + keyPad(fs), float(w - 4), foot + keyPad(fs) + L::lineHeight(fs)},
               "linear light: against the exact integral of the linear-light values", kGrey, fs, ts::Align::Right);
  notes(f, {4, below, float(w - 4), float(h)},
        {"trilinear (GL) with each kernel's mip chain; " + maskText() + ", texture turned " +
             L::given("azimuth, degrees", azimuth, "%g") + " deg",
         measuresAll(ms, tops)
             ? topLevelText() + L::measuredText(ms, tops) + L::given("bits a channel", 8, "%g") + " bits"
             : topLevelText() + ": the checkerboard's mean"},
        kGrey, fs, ts::Align::Center);
}

// The LOD bias: far-field RMS and flicker against the bias, one plot each.
inline void Views::buildBias(ts::Frame& f, const Result* m) const {
  const int w = f.width, h = f.height;
  const int sc = L::scaleFor({0, 0, w, h / 2}, 2), line = int(L::lineHeight(sc));
  if (!m || m->bias.empty()) {
    L::caption(f, {4, float(h / 2), float(w - 4), float(h)}, "measuring...", kWhite, 1);
    return;
  }
  const int plotH = (h - 2 * line) / 2;
  for (int k = 0; k < 2; ++k) {
    ts::plot::Spec s;
    s.id = k == 0 ? "bias_rms_plot" : "bias_flicker_plot";
    s.title = k == 0 ? "trilinear with LOD bias: far-field RMS against the exact integral (turned " +
                           fmt("%g", azimuth) + " deg)"
                     : "flicker: RMS of a frame's change, the plane moving 1/8 texel a frame";
    s.xLabel = k == 1 ? "LOD bias" : "";
    s.scale = sc;
    double ymax = k == 1 ? m->flickerExact : 0;
    ts::plot::Series line(k == 0 ? "rms" : "flicker", k == 0 ? glm::vec4(0.35f, 0.65f, 1.0f, 1.0f) : kAmber,
                          ts::plot::Mark::Line);
    ts::plot::Series marks(k == 0 ? "rms_points" : "flicker_points", line.color, ts::plot::Mark::Squares);
    for (const BiasRow& r : m->bias) {
      const double y = k == 0 ? r.rms : r.flicker;
      line.points.push_back({r.bias, y});
      marks.points.push_back({r.bias, y});
      marks.tags.push_back(fmt(k == 0 ? "%.1f" : "%.2f", y));
      ymax = std::max(ymax, y);
    }
    const double step = ts::plot::niceStep(ymax * 1.2);
    s.x0 = -1.15, s.x1 = 1.15, s.y0 = 0, s.y1 = std::ceil(ymax * 1.2 / step) * step;
    s.xTicks = ts::plot::ticks(-1, 1, 0.5);
    s.yTicks = ts::plot::ticks(0, s.y1, step);
    s.series = {line, marks};
    ts::plot::Marker cur;
    cur.x = bias, cur.color = kWhite, cur.role = "current_bias", cur.dashed = false;
    s.markers.push_back(cur);
    if (k == 1) {
      s.legend = {{"the exact picture's own change: " + fmt("%.2f", m->flickerExact) + " a frame", kGrey}};
    }
    ts::plot::draw(f, s, {0, k * plotH, w, plotH});
  }
  notes(f, {4, float(h - 2 * line), float(w - 4), float(h)},
        {"seed 001: a positive bias blurs, a negative one sharpens and aliases (and flickers when the surface moves)"},
        kGrey, sc, ts::Align::Center);
}
// The four book figures (the gallery's captions and their {measurements}).
inline std::vector<ts::FigureSpec> figureSpecs() {
  return {
      {"filter_zoo_azimuth",
       "Section VI.1.3 (seeds 001, 003)",
       "The mipmap demo's slanted plane with a checkerboard turned 0, 22.5 and 45 degrees, drawn by every minification "
       "filter: GL's (nearest, linear, nearest-mipmap-nearest, trilinear, anisotropic 16x), a ripmap, a summed-area "
       "table, the probe line and EWA, beside the exact area integral over each pixel's preimage. After each name: its "
       "RMS against the exact integral in the far field (LOD 1.5 "
       "to 5). The ripmap and the SAT fit footprints along the "
       "texture's axes and lose as the texture turns; the probe line and EWA follow the footprint. "
       "GL_NEAREST_MIPMAP_NEAREST's error is GL_NEAREST's: the "
       "checkerboard's levels up to those the far field reads are "
       "the same board, so a nearest sample in them takes level "
       "0's colour (the note under the figure measures where the "
       "two pictures part).",
       {"--view", "azimuths", "--method", "sat"},
       1500,
       1100,
       "SAT's error grows from {rms_exact[sat@0]} at 0 deg to {rms_exact[sat@45]} at 45 deg and the ripmap's from "
       "{rms_exact[ripmap@0]} to {rms_exact[ripmap@45]}; the probe line stays at {rms_exact[probes@0]} .. "
       "{rms_exact[probes@45]}, EWA at {rms_exact[ewa@0]} .. {rms_exact[ewa@45]}."},
      {"filter_zoo_supports",
       "Section VI.1.3 (inside a pixel)",
       "One far pixel of the slanted plane with the texture turned 45 degrees: on level 0 of the texture, its exact "
       "preimage (white) and what each method reads instead: trilinear's 2^lambda square (yellow), the ripmap's "
       "2^i x 2^j rectangle (green), the SAT's bounding box (cyan), the probe line's probes (orange), the EWA ellipse "
       "(magenta).",
       {"--view", "supports", "--azimuth", "45", "--method", "probes", "--pick", "250,100"},
       1200,
       640,
       "At 45 deg the SAT's box is {sat_box_ratio[8to1_45deg]} times an 8:1 footprint; log2(rho_edge/rho_max) = "
       "{lod_form_gap_45deg}."},
      {"filter_zoo_memory",
       "Section VI.1.3 (seed 001)",
       "Memory against error: each method's storage over the 8-bit texture's (mip chain 4/3, ripmap (2 - 2^-8)^2, SAT "
       "24 bits a channel) against its far-field RMS on the slanted plane, the texture turned 0 (squares) and 45 "
       "degrees (crosses).",
       {"--view", "memory"},
       1024,
       640,
       "A ripmap costs {ripmap_memory_ratio} times the texture (seed 001: 3x), a SAT {sat_bits[256]} bits a channel "
       "(seed 001: >= 16); the probe line reads the mip chain alone ({mip_memory_ratio})."},
      {"mip_kernels",
       "Section VI.1.3 (seed 001)",
       "Trilinear filtering of the slanted plane (texture turned "
       "45 degrees) with mip chains made by six kernels (Buss's "
       "2x2 box, Crow's tent, a Gaussian, Lanczos-2 and -3, a "
       "Kaiser-windowed sinc), each averaged in sRGB values and in "
       "linear light: far-field RMS against the exact integral, and the 1x1 level.",
       {"--view", "kernels", "--azimuth", "45"},
       1400,
       760,
       "The checkerboard's mean is {mip_mean[srgb]} in sRGB values "
       "and {mip_mean[linear]} in linear light; every kernel's "
       "1x1 level is within {mip_top_max_error[srgb]} and "
       "{mip_top_max_error[linear]} of it (8-bit rounding at each level: "
       "the box chain ends at {mip_top[box_linear]}, the tent's at {mip_top[tent_linear]})."},
  };
}
}  // namespace zoo::views
