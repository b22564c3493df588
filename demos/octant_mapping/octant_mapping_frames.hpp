// demos/octant_mapping/octant_mapping_frames.hpp — the five views of
// demos/octant_mapping, each a ts::Frame of the state (octant_mapping_views.hpp has
// the pieces).  A view is a function of the options and of what measure()
// rendered with GL (GlRasters), nothing else.
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/orbit_camera.hpp"
#include "octant_mapping_math.hpp"
#include "octant_mapping_seed.hpp"
#include "octant_mapping_views.hpp"

namespace octant::frames {
using namespace views;

enum View { kOverview, kTable, kCatmull, kInverse, kMethods };
enum Method { kExact, kNearest, kCatmull4, kInverseMap, kTrilinear, kAnisotropic };
inline const char* methodLabel(int m) {
  const char* n[] = {"exact area integral", "point sampling (GL_NEAREST)", "Catmull, 4 levels", "inverse mapping",
                     "GL trilinear",        "GL anisotropic 16x"};
  return n[m];
}
inline const char* methodKey(int m) {
  const char* n[] = {"exact", "nearest", "catmull4", "inverse", "trilinear", "anisotropic"};
  return n[m];
}

// What measure() rendered with GL: intensity per pixel (pixelIndex).
struct GlRasters {
  std::vector<double> nearest, trilinear, anisotropic;
};

struct State {
  int view = kOverview, method = kExact, level = 4;
  float u = 0.25f;
  glm::ivec2 pixel{21, 15};
  ts::OrbitCamera camera;
  ts::TextureDesc pattern = patternTexture();  // the pattern shown: the grid, or --texture FILE's picture
};

// A method's values (empty: GL's, not measured yet).
inline std::vector<double> values(int method, const GlRasters* gl) {
  const Raster& r = raster();
  switch (method) {
    case kExact: return r.exact;
    case kCatmull4: return r.catmull;
    case kInverseMap: return r.inverse;
    case kNearest: return gl ? gl->nearest : std::vector<double>();
    case kTrilinear: return gl ? gl->trilinear : std::vector<double>();
    default: return gl ? gl->anisotropic : std::vector<double>();
  }
}
inline std::string pixelName(glm::ivec2 P) { return "(" + std::to_string(P.x) + "," + std::to_string(P.y) + ")"; }
inline std::string ratio(int a, int b) {
  return std::to_string(a) + "/" + std::to_string(b) + " = " + fmt("%.3f", b ? double(a) / b : 0.0);
}

// The octant in 3D, the pixel's preimage on it in red, the patch's edges.
inline void addOctant(ts::Frame& f, const L::Cell& c, int tex, const State& s, const std::vector<ts::Batch>& extra) {
  ts::Panel p = octantPanel(c.picture, tex, s.camera);
  p.batches.push_back(patchEdges());
  for (const auto& b : extra) p.batches.push_back(b);
  axisLabels(f, p, c.scale);
  f.panels.push_back(p);
}

// The pattern around the pixel's preimage: the curved preimage (blue), the
// quadrilateral of its corners (red), with `rounded` the one of the corners
// to 3 decimals (orange), and the texel centres counted.  The three lie
// within a fraction of a texel of each other, so each is drawn to show
// beside the others: the curve wide and under, the quadrilateral narrower on
// it, the rounded one dashed on top.  Returns the key of what it drew.
struct Preimage {
  std::vector<ts::LegendEntry> key;
};
inline Preimage addPreimage(ts::Frame& f, const ts::Rect& vp, int tex, glm::ivec2 P, bool rounded) {
  Preimage out;
  const auto curved = pixelPreimageUW(P);
  const auto corners = cornersUW(P.x, P.y);
  if (curved.empty() || !corners) {
    f.panels.push_back(patternPanel("pattern", vp, tex, {0, 0}, {kTexels, kTexels}));
    return out;
  }
  std::vector<glm::dvec2> texelPts;
  for (const auto& q : curved) texelPts.push_back(q * double(kTexels));
  const auto [lo, hi] = windowAround(texelPts, 10.0, 2.0);
  ts::Panel p = patternPanel("pattern", vp, tex, lo, hi);
  const auto quadExact = toTexels(*corners), quadRounded = toTexels(rounded3(*corners));
  const CentreCount ce = countCentres(quadExact), cr = countCentres(quadRounded);
  std::vector<glm::ivec2> both, onlyRounded, onlyExact;
  auto has = [](const CentreCount& c, glm::ivec2 t) {
    for (const auto& q : c.inside)
      if (q == t) return true;
    return false;
  };
  for (const auto& t : ce.inside) (rounded && !has(cr, t) ? onlyExact : both).push_back(t);
  if (rounded)
    for (const auto& t : cr.inside)
      if (!has(ce, t)) onlyRounded.push_back(t);
  // A dash of about 12 pixels, whatever the zoom.
  const double dash = 12.0 * (hi.x - lo.x) / std::max(1, vp.w);
  p.batches.push_back(loopInPattern(texelPts, kCurve, 9.0f, "preimage_curved"));
  p.batches.push_back(loopInPattern({quadExact.begin(), quadExact.end()}, kQuad, 4.0f, "preimage_quad"));
  out.key.push_back({kCurve, "wide blue: the true preimage"});
  out.key.push_back({kQuad, "red: the corners joined"});
  if (rounded) {
    p.batches.push_back(dashedLoopInPattern({quadRounded.begin(), quadRounded.end()}, kQuadRounded, 2.0f, dash,
                                            "preimage_quad_rounded"));
    out.key.push_back({kQuadRounded, "orange dashes: to 3 decimals"});
  }
  if (!both.empty()) {
    p.batches.push_back(centreMarks(both, kCounted, "centres_counted"));
    out.key.push_back({kCounted, rounded ? "centres counted by both" : "centres counted"});
  }
  if (!onlyRounded.empty()) {
    p.batches.push_back(centreMarks(onlyRounded, kMagenta, "centres_rounded_only"));
    out.key.push_back({kMagenta, "counted only to 3 decimals"});
  }
  if (!onlyExact.empty()) {
    p.batches.push_back(centreMarks(onlyExact, kQuad, "centres_unrounded_only"));
    out.key.push_back({kQuad, "counted only unrounded"});
  }
  f.panels.push_back(p);
  return out;
}

// --- overview: octant | raster | the pixel on the pattern ---------------------------
inline ts::Frame overviewView(const State& s, int width, int height, const GlRasters* gl) {
  ts::Frame f = L::blankFrame(width, height);
  const int tex = f.addTexture(s.pattern);
  L::FlowSpec spec;
  spec.n = 3;
  spec.linesAbove = 1;
  spec.linesBelow = 2;
  spec.gap = 14;
  spec.maxScale = 2;
  spec.minCellWidth = ts::text::width("pixel (21,15): exact 0.242", 1);
  const auto cells = L::flow({8, 8, float(width) - 8, float(height) - 8}, spec);
  const Raster& R = raster();
  const size_t k = size_t(pixelIndex(s.pixel.x, s.pixel.y));
  // The octant, the pixel's preimage on it.
  addOctant(f, cells[0], tex, s, {onSurface(pixelPreimageUW(s.pixel), kRed, 3.0f, true, "pixel_preimage")});
  L::caption(f, cells[0].above, "the octant (drag: orbit)", kWhite, cells[0].scale);
  {
    const auto [a, b] = L::halves(cells[0].below);
    L::caption(f, a, "theta = (pi/2) u, phi = pi/2 - (pi/4) w", kWhite, cells[0].scale);
    L::caption(f, b, "view Rx(35) Ry(-45), orthographic", kWhite, cells[0].scale);
  }
  // The raster.
  const std::vector<double> v = values(s.method, gl);
  f.panels.push_back(rasterPanel("raster", cells[1].picture, v, s.pixel));
  L::caption(f, cells[1].above, std::string("32x32 raster: ") + methodLabel(s.method), kWhite, cells[1].scale);
  {
    const auto [a, b] = L::halves(cells[1].below);
    L::caption(f, a, "pixel " + pixelName(s.pixel) + ": exact " + (R.interior[k] ? fmt("%.3f", R.exact[k]) : "-"),
               kAmber, cells[1].scale);
    std::string line = s.method == kExact ? std::to_string(interiorPixels(R)) + " px on the octant, " +
                                                std::to_string(linePixels(R)) + " on lines"
                       : v.empty()
                           ? std::string("measuring ...")
                           : std::string(methodKey(s.method)) + " " + (std::isfinite(v[k]) ? fmt("%.3f", v[k]) : "-") +
                                 ", rms " + fmt("%.3f", rmsAgainstExact(v, R)) + " over " +
                                 std::to_string(interiorPixels(R)) + " px";
    L::caption(f, b, line, kAmber, cells[1].scale);
  }
  // The pixel on the pattern.
  addPreimage(f, cells[2].picture, tex, s.pixel, false);
  L::caption(f, cells[2].above, "pixel " + pixelName(s.pixel) + " on the pattern", kWhite, cells[2].scale);
  {
    const auto [a, b] = L::halves(cells[2].below);
    const auto corners = cornersUW(s.pixel.x, s.pixel.y);
    if (corners && R.centreOnPatch[k]) {
      const CentreCount c = countCentres(toTexels(*corners));
      L::caption(f, a, "inverse: " + std::to_string(c.texels) + " centres, " + std::to_string(c.lines) + " on lines",
                 kAmber, cells[2].scale);
      const Average cat = fragmentAverage(fragmentAt(rasterGeometry()[k].centreUW, 4));
      L::caption(f, b, "Catmull-4: " + ratio(cat.line, cat.total), kAmber, cells[2].scale);
    } else {
      L::caption(f, a, "not on the octant", kAmber, cells[2].scale);
    }
  }
  return f;
}

// --- table: the forward table as the seed prints it ------------------------------
// An angle as the seed writes it (a multiple of pi), else its value.
inline L::Text angleText(double a) {
  const std::string p = piFraction(a);
  return p.empty() ? L::given("an angle of the line, radians", a, "%.3f") : L::Text(p);
}
inline L::Text tableTitle(double u, const ts::Measurements& measured) {
  return "the line u = " + fraction(u) + ": theta = (pi/2) u = " + angleText(anglesOf({u, 0}).x) + " (" +
         num(measured, names::tableThetaDeg(u), "%.2f") + " deg), phi = pi/2 - (pi/4) w";
}
// The table's columns: its rows, each followed by the seed's where it prints one.
inline std::vector<Row> tableRows(double u, const ts::Measurements& measured) {
  std::vector<Row> rows;
  const bool seeds = fraction(u) == fraction(0.25);
  const auto t = forwardTable(u);
  rows.push_back({{""}, {"u"}, {"w"}, {"theta"}, {"phi"}, {"x"}, {"y"}, {"z"}});
  for (size_t k = 0; k < t.size(); ++k) {
    Row r = {{""},
             {k == 0 ? fraction(u) : ""},
             {fraction(t[k].w)},
             {k == 0 ? angleText(t[k].theta) : L::Text()},
             {angleText(t[k].phi)}};
    for (int a = 0; a < 3; ++a) r.push_back({num(measured, names::tableXyz(u, t[k].w, a), "%.3f")});
    rows.push_back(r);
    if (!seeds) continue;
    const seed::PrintedRow& p = seed::table()[k];
    const bool thetaWrong = k == 0, phiWrong = k >= 1 && k <= 3;
    const double pr[3] = {p.x, p.y, p.z};
    Row q = {{"seed", kDim},
             {k == 0 ? fraction(u) : "", kDim},
             {p.w, kDim},
             {std::string(p.theta) + (thetaWrong ? " !" : ""), thetaWrong ? kRed : kDim},
             {std::string(p.phi) + (phiWrong ? " !" : ""), phiWrong ? kRed : kDim}};
    for (int a = 0; a < 3; ++a)
      q.push_back({L::given(std::string("the seed prints ") + "xyz"[a] + " at w = " + p.w, pr[a], "%.2f"),
                   std::fabs(pr[a] - t[k].xyz[a]) > 5e-3 + 1e-9 ? kRed : kDim});
    rows.push_back(q);
  }
  return rows;
}
// The lines under the table: the misprints, the checks, the mapping's constants.
inline std::vector<Row> tableNotes(double u, const ts::Measurements& measured) {
  std::vector<Row> rows;
  if (fraction(u) == fraction(0.25)) {
    for (const seed::Misprint& m : seed::misprints())
      if (m.id.rfind("table_", 0) == 0)
        rows.push_back(
            {{"! " + m.where.substr(m.where.find("row")) + " printed " + m.printedAs + " = " +
                  L::given("the seed's entry, read as printed", m.printedValue, "%.3f") + "; it is " + m.correctAs +
                  " = " + num(measured, "misprint[" + m.id + "]", "%.3f") + (m.note.empty() ? "" : " " + m.note),
              kRed}});
    rows.push_back(
        {{"x, y, z: the seed's 15 entries agree to 2 decimals (" + num(measured, "seed_table_xyz_wrong", "%.0f") +
              " wrong); p stands for pi, the transliteration's",
          kWhite}});
  } else {
    rows.push_back({{"the seed tabulates u = 1/4 only (] and [ step u by 1/16)", kDim}});
  }
  rows.push_back({{"closed form x = sin(pi u/2) cos(pi w/4), y = sin(pi w/4), z = cos(pi u/2) cos(pi w/4): off by " +
                       num(measured, names::tableMaxError(u), "%.1e"),
                   kAmber}});
  const Linear lm = linearMapping();
  rows.push_back({{"from the corners: A = " + angleText(lm.A) + ", B = " + angleText(lm.B) + ", C = -" +
                       angleText(-lm.C) + ", D = " + angleText(lm.D),
                   kWhite}});
  return rows;
}
// The height table() takes for rows of one cell each at `scale` in `width`.
inline float notesHeight(const std::vector<Row>& notes, int scale, float width) {
  float h = 0;
  for (const Row& r : notes)
    h += std::max(L::lineHeight(scale),
                  float(L::captionLines(r[0].text.text, scale, width)) * L::lineHeight(scale) + float(4 * scale));
  return h;
}

inline ts::Frame tableView(const State& s, int width, int height, const ts::Measurements& measured) {
  ts::Frame f = L::blankFrame(width, height);
  const int tex = f.addTexture(s.pattern);
  const float m = 8, W = float(width), H = float(height);
  const bool wide = width >= height;
  const L::Text title = tableTitle(s.u, measured);
  const std::vector<Row> rows = tableRows(s.u, measured), notes = tableNotes(s.u, measured);
  // The title across the top; the table under it, as large as leaves the
  // octant room, and the notes under the table (the misprints' key first):
  // the octant beside both when the figure is wide, under them when tall.
  const bool misprints = fraction(s.u) == fraction(0.25);
  const float textW = wide ? (W - 2 * m) * 0.62f : W - 2 * m;
  const float notesH = notesHeight(notes, 1, textW) + (misprints ? L::lineHeight(1) : 0);
  int ts_ = 1;
  for (int sc = 2; sc > 1; --sc) {
    const float tall = float(rows.size() + 1) * L::lineHeight(sc) + notesH + 8;
    const bool room = wide ? tall <= H - 2 * m : tall <= (H - 2 * m) * 0.6f;
    if (room && float(tableChars(rows)) * ts::text::width("0", sc) <= textW &&
        ts::text::width(title.text, sc) <= W - 2 * m) {
      ts_ = sc;
      break;
    }
  }
  const float lh = L::lineHeight(ts_);
  L::caption(f, {m, m, W - m, m + lh}, title, kWhite, ts_, ts::Align::Left);
  const Box tableBox{m, m + lh, m + textW, m + lh + float(rows.size()) * lh};
  table(f, tableBox, rows, ts_);
  // (A small window leaves out the notes that find no room.)
  const Box notesBox{m, tableBox.y1 + 8, m + textW, std::min(H - m, tableBox.y1 + 8 + notesH)};
  const size_t firstNote = f.labels.size();
  float y = notesBox.y0;
  if (misprints) y = L::legend(f, notesBox, {{kRed, "! a misprint of the seed, beside the right value"}}, 1);
  table(f, {notesBox.x0, y, notesBox.x1, notesBox.y1}, notes, 1);
  float textRight = m;  // the text's right edge: the table's columns, the notes' lines
  for (size_t k = 0; k < f.labels.size(); ++k)
    if (k >= firstNote || f.labels[k].y >= tableBox.y0) textRight = std::max(textRight, L::labelBox(f.labels[k]).x1);
  const Box pic = wide ? Box{textRight + 16, tableBox.y0, W - m, H - m} : Box{m, notesBox.y1 + 8, W - m, H - m};
  L::FlowSpec spec;
  spec.n = 1;
  spec.linesAbove = 1;
  spec.linesBelow = 2;
  spec.maxScale = 2;
  const auto cells = L::flow(pic, spec);
  std::vector<glm::dvec2> line;
  for (int k = 0; k <= 32; ++k) line.push_back({double(s.u), k / 32.0});
  addOctant(f, cells[0], tex, s, {onSurface(line, kMagenta, 3.0f, false, "table_line")});
  L::caption(f, cells[0].above, "the line u = " + fraction(s.u) + " on the octant", kWhite, cells[0].scale);
  const std::vector<ts::LegendEntry> key = {{kMagenta, "the line u = " + fraction(s.u)},
                                            {kAmber, "the octant's edges"},
                                            {kAxis[0], "x axis"},
                                            {kAxis[1], "y axis"},
                                            {kAxis[2], "z axis"}};
  L::legend(f, cells[0].below, key, keyScale(cells[0].below, key, cells[0].scale));
  return f;
}

// --- catmull: subdivision level by level ------------------------------------------------
inline std::vector<Row> catmullRows(glm::ivec2 P, int level, const ts::Measurements& measured) {
  std::vector<Row> rows;
  const Raster& R = raster();
  const size_t k = size_t(pixelIndex(P.x, P.y));
  if (!R.centreOnPatch[k]) return {{{"pixel " + pixelText(P) + ": its centre is not on the octant", kAmber}}};
  const int one = levelsToOneCentre(P.x, P.y);
  rows.push_back({{"level"}, {"texels"}, {"intensity"}, {"pixel centres"}, {"theta"}, {"phi"}});
  for (int l = 0; l <= level; ++l) {
    const Fragment fr = fragmentAt(rasterGeometry()[k].centreUW, l);
    const glm::dvec2 th = fr.thetaRange(), ph = fr.phiRange();
    const L::Text side = L::given("texels along a fragment's side, 64/2^level", fr.texelsPerSide(), "%.0f");
    rows.push_back({{std::to_string(l)},
                    {side + "x" + side},
                    {num(measured, names::catmull("line_texels", P, l), "%.0f") + "/" +
                         num(measured, names::catmull("texels", P, l), "%.0f") + " = " +
                         num(measured, names::catmull("fraction", P, l), "%.3f"),
                     kAmber},
                    {num(measured, names::catmull("centres", P, l), "%.0f") + (l == one ? " <- one" : ""),
                     l == one ? kGreen : kWhite},
                    {"[" + piFraction(th.x) + ", " + piFraction(th.y) + "]"},
                    {"[" + piFraction(ph.x) + ", " + piFraction(ph.y) + "]"}});
  }
  rows.push_back(
      {{"Catmull: subdivide until a fragment covers one pixel centre; the pixel takes the mean of its texels.",
        kWhite}});
  if (P == glm::ivec2(seed::kCatmullPx, seed::kCatmullPy)) {
    const L::Text line = L::given("the seed's line texels", seed::kCatmullLine, "%.0f"),
                  all = L::given("the seed's texels", seed::kCatmullTexels, "%.0f");
    rows.push_back({{"the seed's example: " + L::given("the seed's levels", seed::kCatmullLevels, "%.0f") +
                         " levels, " + line + " of " + all + " texels on lines = " + line + "/" + all +
                         "; ! it prints phi = " + piFraction(seed::kCatmullPhiPrinted) + " for " +
                         piFraction(fragmentAt({0, 0}, seed::kCatmullLevels).phiRange().x),
                     kRed}});
  }
  return rows;
}

inline ts::Frame catmullView(const State& s, int width, int height, const ts::Measurements& measured) {
  ts::Frame f = L::blankFrame(width, height);
  const int tex = f.addTexture(s.pattern);
  const Raster& R = raster();
  const size_t k = size_t(pixelIndex(s.pixel.x, s.pixel.y));
  const std::vector<Row> rows = catmullRows(s.pixel, s.level, measured);
  const bool misprint = s.pixel == glm::ivec2(seed::kCatmullPx, seed::kCatmullPy);
  const float m = 8;
  // The table and, for the seed's pixel, the key of its misprint under it.
  const float keyLines = misprint ? 1.0f : 0.0f;
  const int ts_ = tableScale(rows, float(width) - 2 * m, float(height) * 0.45f - keyLines * L::lineHeight(2), 2);
  const float textH = std::min(float(height) * 0.45f, float(rows.size() + keyLines) * L::lineHeight(ts_) + 8);
  L::FlowSpec spec;
  spec.n = 3;
  spec.linesAbove = 1;
  spec.linesBelow = 2;
  spec.gap = 14;
  spec.maxScale = 2;
  const auto cells = L::flow({m, m, float(width) - m, float(height) - m - textH}, spec);
  const Box text{m, float(height) - m - textH + 4, float(width) - m, float(height) - m};
  const float y = table(f, text, rows, 2);
  if (misprint)
    L::legend(f, {text.x0, y, text.x1, text.y1}, {{kRed, "! a misprint of the seed"}}, 1);  // as the notes above it
  // Each pixel the mean of the level's fragment holding its centre.
  std::vector<double> v(R.exact.size(), std::nan(""));
  const auto& geo = rasterGeometry();
  for (size_t q = 0; q < v.size(); ++q)
    if (geo[q].centreOnPatch) v[q] = fragmentAverage(fragmentAt(geo[q].centreUW, s.level)).value();
  ts::Panel rasterP = rasterPanel("raster", cells[0].picture, v, s.pixel);
  ts::Panel pat = patternPanel("pattern", cells[1].picture, tex, {0, 0}, {kTexels, kTexels});
  const int n = 1 << s.level;
  if (s.level <= 4) {  // the fragments' edges (finer, they hide the pixels)
    ts::Batch onRaster = ts::lineSegments({}, kFragmentEdge, 1.0f, "fragment_edges");
    std::vector<glm::vec2> onPattern;
    for (int e = 0; e <= n; ++e) {
      addPolyline(onRaster, curveOnRaster({double(e) / n, 0}, {double(e) / n, 1}, 16), kFragmentEdge, false);
      addPolyline(onRaster, curveOnRaster({0, double(e) / n}, {1, double(e) / n}, 16), kFragmentEdge, false);
      onPattern.insert(onPattern.end(),
                       {{float(e) / n, 0.0f}, {float(e) / n, 1.0f}, {0.0f, float(e) / n}, {1.0f, float(e) / n}});
    }
    rasterP.batches.insert(rasterP.batches.end() - 2, onRaster);  // under the outline and the pixel
    pat.batches.push_back(ts::lineSegments(onPattern, kFragmentEdge, 1.0f, "fragment_edges"));
  }
  L::Text under = "centre not on the octant";
  if (R.centreOnPatch[k]) {
    const Fragment fr = fragmentAt(rasterGeometry()[k].centreUW, s.level);
    const glm::dvec2 a = fr.uw0(), b = fr.uw1();
    ts::Batch img = ts::lineSegments({}, kGreen, 3.0f, "fragment");
    addPolyline(img, curveOnRaster(a, {b.x, a.y}, 8), kGreen, false);
    addPolyline(img, curveOnRaster({b.x, a.y}, b, 8), kGreen, false);
    addPolyline(img, curveOnRaster(b, {a.x, b.y}, 8), kGreen, false);
    addPolyline(img, curveOnRaster({a.x, b.y}, a, 8), kGreen, false);
    rasterP.batches.push_back(img);
    ts::Batch dots = flat("centres_covered");
    for (const auto& c : centresCovered(fr))
      quad(dots, {(c.x + 0.35f) / kRaster, (c.y + 0.35f) / kRaster}, {(c.x + 0.65f) / kRaster, (c.y + 0.65f) / kRaster},
           kGreen);
    rasterP.batches.push_back(dots);
    pat.batches.push_back(ts::lineLoop({glm::vec2(a), {float(b.x), float(a.y)}, glm::vec2(b), {float(a.x), float(b.y)}},
                                       kGreen, 3.0f, "fragment"));
    const double t = fr.texelsPerSide();
    const glm::dvec2 lo = a * double(kTexels), side(std::max(t, 4.0));
    ts::Panel zoom = patternPanel("fragment", cells[2].picture, tex, lo, lo + side);
    zoom.batches.push_back(loopInPattern({lo, lo + glm::dvec2(t, 0), lo + glm::dvec2(t), lo + glm::dvec2(0, t)}, kGreen,
                                         3.0f, "fragment"));
    f.panels.push_back(zoom);
    under = num(measured, names::catmull("line_texels", s.pixel, s.level), "%.0f") + " of " +
            num(measured, names::catmull("texels", s.pixel, s.level), "%.0f") +
            " on lines: " + num(measured, names::catmull("fraction", s.pixel, s.level), "%.4f");
  }
  f.panels.insert(f.panels.begin(), {rasterP, pat});
  const L::Text fragments = L::given("fragments along a side, 2^level", n, "%.0f");
  const L::Text texels = L::given("the pattern's texels along a side", kTexels, "%.0f");
  L::caption(f, cells[0].above, "level " + std::to_string(s.level) + ": each pixel its fragment's mean", kWhite,
             cells[0].scale);
  keyWithPixel(f, cells[0].below,
               {{kRed, "pixel " + pixelText(s.pixel).text},
                {kGreen, "its fragment"},
                {kAmber, "the octant's outline"},
                {kFragmentEdge, "fragments' edges"}},
               cells[0].scale, s.pixel);
  L::caption(f, cells[1].above, fragments + "x" + fragments + " fragments on the pattern", kWhite, cells[1].scale);
  L::caption(f, L::halves(cells[1].below).first, texels + "x" + texels + " texels, lines at " + gridLinesText(), kWhite,
             cells[1].scale);
  L::caption(f, cells[2].above, "the fragment's texels", kWhite, cells[2].scale);
  L::caption(f, L::halves(cells[2].below).first, under, kAmber, cells[2].scale);
  return f;
}

// --- inverse: the pixel's corners, both counts ---------------------------------------------
inline std::vector<Row> inverseRows(glm::ivec2 P, const ts::Measurements& measured) {
  std::vector<Row> rows;
  const auto corners = cornersUW(P.x, P.y);
  if (!corners) return {{{"pixel " + pixelText(P) + " is not wholly on the sphere", kAmber}}};
  const bool seeds = P == glm::ivec2(seed::kInversePx, seed::kInversePy);
  rows.push_back({{"Px"}, {"Py"}, {"x'"}, {"y'"}, {"z'"}, {"x"}, {"y"}, {"z"}, {"phi"}, {"theta"}, {"u"}, {"w"}});
  const char* what[10] = {"x'", "y'", "z'", "x", "y", "z", "phi_deg", "theta_deg", "u", "w"};
  const char* fmts[10] = {"%.4f", "%.4f", "%.3f", "%.3f", "%.3f", "%.3f", "%.2f", "%.2f", "%.3f", "%.3f"};
  const auto pc = pixelCorners(P.x, P.y);
  for (size_t c = 0; c < 4; ++c) {
    const Back b = *backOfPixelPoint(pc[c]);
    const double vals[10] = {b.viewPoint.x, b.viewPoint.y,     b.viewPoint.z,       b.point.x, b.point.y,
                             b.point.z,     b.phi * 180 / kPi, b.theta * 180 / kPi, b.uw.x,    b.uw.y};
    Row r = {{L::given("the corner's Px", pc[c].x, "%.0f")}, {L::given("the corner's Py", pc[c].y, "%.0f")}};
    for (int e = 0; e < 10; ++e) r.push_back({num(measured, names::corner(pc[c], what[e]), fmts[e])});
    rows.push_back(r);
    if (seeds) {
      const seed::PrintedCorner& s = seed::corners()[c];
      const double pr[10] = {s.xv, s.yv, s.zv, s.x, s.y, s.z, s.phiDeg, s.thetaDeg, s.u, s.w};
      const double unit[10] = {1e-4, 1e-4, 1e-3, 1e-3, 1e-3, 1e-3, 1e-2, 1e-2, 1e-3, 1e-3};
      Row q = {{"seed", kDim}, {""}};
      for (int e = 0; e < 10; ++e) {
        const bool wrong = std::fabs(pr[e] - vals[e]) > unit[e] + 1e-9;
        q.push_back({L::given(std::string("the seed prints ") + what[e] + " at this corner", pr[e], fmts[e]) +
                         (wrong ? "!" : ""),
                     wrong ? kRed : kDim});
      }
      rows.push_back(q);
    }
  }
  const auto count = [&](const std::string& variant, const char* fraction) {
    return num(measured, names::inverse("texels", P, variant), "%.0f") + " texels, " +
           num(measured, names::inverse("line_texels", P, variant), "%.0f") +
           " on lines = " + num(measured, names::inverse("fraction", P, variant), fraction);
  };
  rows.push_back({{"corners to 3 decimals as printed, centres at (i+1/2, j+1/2), lines at " + gridLinesText() +
                       ", inside or on: " + count("", "%.4f"),
                   kAmber}});
  rows.push_back(
      {{"unrounded corners: " + count("unrounded", "%.4f") + "; the curved preimage: " + count("curved", "%.4f"),
        kWhite}});
  const CentreCount ce = countCentres(toTexels(*corners)), cr = countCentres(toTexels(rounded3(*corners)));
  for (const auto& t : cr.inside) {
    bool inExact = false;
    for (const auto& q : ce.inside) inExact |= q == t;
    if (!inExact)
      rows.push_back(
          {{"texel (" + L::given("the texel's column i", t.x, "%.0f") + "," +
                L::given("the texel's row j", t.y, "%.0f") + ")" + (pattern(t.x, t.y) > 0 ? ", on a line" : "") +
                ": its centre is " + num(measured, names::centreDepth("outside", P, t), "%.3f") +
                " texels outside the unrounded quadrilateral, " +
                num(measured, names::centreDepth("inside_rounded", P, t), "%.3f") + " inside the rounded one",
            kMagenta}});
  }
  if (seeds) {
    const seed::PrintedCorner &c0 = seed::corners()[0], &c1 = seed::corners()[1];
    rows.push_back({{"! the seed prints z = " + L::given("the seed prints z at the first corner", c0.z, "%.3f") +
                         " at " + pixelText({c0.Px, c0.Py}) +
                         " and phi = " + L::given("the seed prints phi at the second corner", c1.phiDeg, "%.2f") +
                         " at " + pixelText({c1.Px, c1.Py}) +
                         "; it omits T, and gives the sphere as y = cos theta, z = cos theta sin theta",
                     kRed}});
  }
  return rows;
}

inline ts::Frame inverseView(const State& s, int width, int height, const ts::Measurements& measured) {
  ts::Frame f = L::blankFrame(width, height);
  const int tex = f.addTexture(s.pattern);
  const std::vector<Row> rows = inverseRows(s.pixel, measured);
  const float m = 8;
  const int ts_ = tableScale(rows, float(width) - 2 * m, float(height) * 0.5f, 2);
  const float textH = std::min(float(height) * 0.5f, float(rows.size() + 2) * L::lineHeight(ts_) + 4);
  L::FlowSpec spec;
  spec.n = 2;
  spec.linesAbove = 1;
  spec.linesBelow = 3;
  spec.gap = 16;
  spec.maxScale = 2;
  const auto cells = L::flow({m, m, float(width) - m, float(height) - m - textH}, spec);
  table(f, {m, float(height) - m - textH + 4, float(width) - m, float(height) - m}, rows, 2);
  f.panels.push_back(rasterPanel("raster", cells[0].picture, raster().inverse, s.pixel));
  const Preimage pre = addPreimage(f, cells[1].picture, tex, s.pixel, true);
  L::caption(f, cells[0].above, "inverse mapping over the raster (unrounded corners)", kWhite, cells[0].scale);
  std::vector<ts::LegendEntry> rasterKey = {{kRed, "pixel " + pixelText(s.pixel).text},
                                            {kAmber, "the octant's outline"},
                                            {kNoValue, "no value: partly off the octant"}};
  if (s.pixel == glm::ivec2(seed::kInversePx, seed::kInversePy))
    rasterKey.push_back({kRed, "! a misprint of the seed"});
  keyWithPixel(f, cells[0].below, rasterKey, cells[0].scale, s.pixel);
  L::caption(f, cells[1].above, "pixel " + pixelText(s.pixel) + " on the pattern", kWhite, cells[1].scale);
  L::legend(f, cells[1].below, pre.key, keyScale(cells[1].below, pre.key, cells[1].scale));
  return f;
}

// --- methods: the raster six ways ------------------------------------------------------------
inline ts::Frame methodsView(const State& s, int width, int height, const ts::Measurements& measured) {
  ts::Frame f = L::blankFrame(width, height);
  const GlRasters* gl = measured.detailAs<GlRasters>();
  L::FlowSpec spec;
  spec.n = 6;
  spec.aspect = float(kOctantWindow.z - kOctantWindow.x) / float(kOctantWindow.w - kOctantWindow.y);
  spec.linesAbove = 1;
  spec.linesBelow = 2;
  spec.gap = 12;
  const float keyH = L::lineHeight(1) + 4;
  const auto cells = L::flow({8, 8, float(width) - 8, float(height) - 8 - keyH}, spec);
  const std::string compared = "raster_pixels_compared", lines = "line_pixels";
  for (int mth = 0; mth < 6; ++mth) {
    const L::Cell& c = cells[size_t(mth)];
    const std::vector<double> v = values(mth, gl);
    f.panels.push_back(rasterPanel(std::string("raster_") + methodKey(mth), c.picture, v, s.pixel, kOctantWindow));
    L::caption(f, c.above, methodLabel(mth), kWhite, c.scale);
    const auto [a, b] = L::halves(c.below);
    const std::string key = methodKey(mth);
    if (v.empty() || !has(measured, compared) || (mth != kExact && !has(measured, "rms_exact[" + key + "]"))) {
      L::caption(f, a, "measuring ...", kAmber, c.scale);
    } else if (mth == kExact) {
      L::caption(f, a, L::measured(measured, compared, "%.0f") + " px wholly on the octant", kAmber, c.scale);
      L::caption(f, b, L::measured(measured, lines, "%.0f") + " over a line", kAmber, c.scale);
    } else {
      L::caption(f, a, "rms " + L::measured(measured, "rms_exact[" + key + "]", "%.3f"), kAmber, c.scale);
      L::caption(f, b,
                 "lost " + L::measured(measured, "lost_line_pixels[" + key + "]", "%.0f") + " of " +
                     L::measured(measured, lines, "%.0f"),
                 kAmber, c.scale);
    }
  }
  keyWithPixel(f, {8, float(height) - 8 - keyH + 4, float(width) - 8, float(height) - 4},
               {{kRed, "pixel " + pixelText(s.pixel).text},
                {kAmber, "the octant's outline"},
                {kNoValue, "no value: the pixel is partly off the octant"}},
               1, s.pixel);
  return f;
}

inline ts::Frame build(const State& s, int width, int height, const ts::Measurements& measured) {
  switch (s.view) {
    case kTable: return tableView(s, width, height, measured);
    case kCatmull: return catmullView(s, width, height, measured);
    case kInverse: return inverseView(s, width, height, measured);
    case kMethods: return methodsView(s, width, height, measured);
    default: return overviewView(s, width, height, measured.detailAs<GlRasters>());
  }
}
}  // namespace octant::frames
