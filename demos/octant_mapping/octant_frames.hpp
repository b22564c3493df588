// demos/octant_mapping/octant_frames.hpp — the five views of
// demos/octant_mapping, each a ts::Frame of the state (octant_views.hpp has
// the pieces).  A view is a function of the options and of what measure()
// rendered with GL (GlRasters), nothing else.
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/orbit_camera.hpp"
#include "octant_math.hpp"
#include "octant_seed.hpp"
#include "octant_views.hpp"

namespace octant::frames {
using namespace views;

enum View { kOverview, kTable, kCatmull, kInverse, kMethods };
enum Method { kExact, kNearest, kCatmull4, kInverseMap, kTrilinear, kAnisotropic };
inline const char* methodLabel(int m) {
  const char* n[] = {"exact area integral", "point sampling (GL_NEAREST)", "Catmull, 4 levels",
                     "inverse mapping", "GL trilinear", "GL anisotropic 16x"};
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

// The pattern around the pixel's preimage: the curved preimage (cyan), the
// quadrilateral of its corners (white), with `rounded` the one of the corners
// to 3 decimals (amber), and the texel centres counted.
inline void addPreimage(ts::Frame& f, const ts::Rect& vp, int tex, glm::ivec2 P, bool rounded) {
  const auto curved = pixelPreimageUW(P);
  const auto corners = cornersUW(P.x, P.y);
  if (curved.empty() || !corners) {
    f.panels.push_back(patternPanel("pattern", vp, tex, {0, 0}, {kTexels, kTexels}));
    return;
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
  p.batches.push_back(loopInPattern(texelPts, kCurve, 5.0f, "preimage_curved"));
  p.batches.push_back(loopInPattern({quadExact.begin(), quadExact.end()}, kQuad, 3.0f, "preimage_quad"));
  if (rounded) p.batches.push_back(loopInPattern({quadRounded.begin(), quadRounded.end()}, kQuadRounded, 1.0f, "preimage_quad_rounded"));
  if (!both.empty()) p.batches.push_back(centreMarks(both, kCounted, "centres_counted"));
  if (!onlyRounded.empty()) p.batches.push_back(centreMarks(onlyRounded, kMagenta, "centres_rounded_only"));
  if (!onlyExact.empty()) p.batches.push_back(centreMarks(onlyExact, kQuad, "centres_unrounded_only"));
  f.panels.push_back(p);
}

// --- overview: octant | raster | the pixel on the pattern ---------------------------
inline ts::Frame overviewView(const State& s, int width, int height, const GlRasters* gl) {
  ts::Frame f = L::blankFrame(width, height);
  const int tex = f.addTexture(patternTexture());
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
                       : v.empty() ? std::string("measuring ...")
                                 : std::string(methodKey(s.method)) + " " +
                                       (std::isfinite(v[k]) ? fmt("%.3f", v[k]) : "-") + ", rms " +
                                       fmt("%.3f", rmsAgainstExact(v, R)) + " over " +
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
inline std::vector<Row> tableRows(double u) {
  std::vector<Row> rows;
  const bool seeds = std::fabs(u - 0.25) < 1e-9;
  const auto t = forwardTable(u);
  auto angle = [](double a) {
    const std::string p = piFraction(a);
    return p.empty() ? fmt("%.3f", a) : p;
  };
  rows.push_back({{"the line u = " + fraction(u) + ": theta = (pi/2) u = " + angle(t[0].theta) + " (" +
                       fmt("%.2f", t[0].theta * 180 / kPi) + " deg), phi = pi/2 - (pi/4) w",
                   kWhite}});
  rows.push_back({{""}, {"u"}, {"w"}, {"theta"}, {"phi"}, {"x"}, {"y"}, {"z"}});
  for (size_t k = 0; k < t.size(); ++k) {
    rows.push_back({{""}, {k == 0 ? fraction(u) : ""}, {fraction(t[k].w)}, {k == 0 ? angle(t[k].theta) : ""},
                    {angle(t[k].phi)}, {fmt("%.3f", t[k].xyz.x)}, {fmt("%.3f", t[k].xyz.y)}, {fmt("%.3f", t[k].xyz.z)}});
    if (!seeds) continue;
    const seed::PrintedRow& p = seed::table()[k];
    const bool thetaWrong = k == 0, phiWrong = k >= 1 && k <= 3;
    const double pr[3] = {p.x, p.y, p.z};
    Row r = {{"seed", kDim}, {k == 0 ? "1/4" : "", kDim}, {p.w, kDim},
             {std::string(p.theta) + (thetaWrong ? " !" : ""), thetaWrong ? kRed : kDim},
             {std::string(p.phi) + (phiWrong ? " !" : ""), phiWrong ? kRed : kDim}};
    for (int a = 0; a < 3; ++a)
      r.push_back({fmt("%.2f", pr[a]), std::fabs(pr[a] - t[k].xyz[a]) > 5e-3 + 1e-9 ? kRed : kDim});
    rows.push_back(r);
  }
  if (seeds) {
    for (const seed::Misprint& m : seed::misprints())
      if (m.id.rfind("table_", 0) == 0)
        rows.push_back({{"! " + m.where.substr(m.where.find("row")) + " printed " + m.printed + "; it is " + m.correct, kRed}});
    rows.push_back({{"x, y, z: the seed's 15 entries agree to 2 decimals (" + std::to_string(seed::tableXyzWrong()) +
                         " wrong); p stands for pi, the transliteration's",
                     kWhite}});
  } else {
    rows.push_back({{"the seed tabulates u = 1/4 only (] and [ step u by 1/16)", kDim}});
  }
  double err = 0;
  for (const auto& row : t) err = std::max(err, glm::length(row.xyz - closedForm(row.u, row.w)));
  rows.push_back({{"closed form x = sin(pi u/2) cos(pi w/4), y = sin(pi w/4), z = cos(pi u/2) cos(pi w/4): off by " +
                       fmt("%.1e", err),
                   kAmber}});
  const Linear m = linearMapping();
  rows.push_back({{"from the corners: A = " + angle(m.A) + ", B = " + angle(m.B) + ", C = -" + angle(-m.C) +
                       ", D = " + angle(m.D),
                   kWhite}});
  return rows;
}

inline ts::Frame tableView(const State& s, int width, int height) {
  ts::Frame f = L::blankFrame(width, height);
  const int tex = f.addTexture(patternTexture());
  const float m = 8;
  const bool wide = width >= height;
  Box text{m, m, wide ? float(width) * 0.6f : float(width) - m, wide ? float(height) - m : float(height) * 0.55f};
  Box pic{wide ? text.x1 + 12 : m, wide ? m : text.y1 + 8, float(width) - m, float(height) - m};
  table(f, text, tableRows(s.u), 2);
  L::FlowSpec spec;
  spec.n = 1;
  spec.linesAbove = 1;
  spec.linesBelow = 0;
  const auto cells = L::flow(pic, spec);
  std::vector<glm::dvec2> line;
  for (int k = 0; k <= 32; ++k) line.push_back({double(s.u), k / 32.0});
  addOctant(f, cells[0], tex, s, {onSurface(line, kRed, 3.0f, false, "table_line")});
  L::caption(f, cells[0].above, "the line u = " + fraction(s.u) + " on the octant", kWhite, cells[0].scale);
  return f;
}

// --- catmull: subdivision level by level ------------------------------------------------
inline std::vector<Row> catmullRows(glm::ivec2 P, int level) {
  std::vector<Row> rows;
  const Raster& R = raster();
  const size_t k = size_t(pixelIndex(P.x, P.y));
  if (!R.centreOnPatch[k]) return {{{"pixel " + pixelName(P) + ": its centre is not on the octant", kAmber}}};
  const int one = levelsToOneCentre(P.x, P.y);
  rows.push_back({{"level"}, {"texels"}, {"intensity"}, {"pixel centres"}, {"theta"}, {"phi"}});
  for (int l = 0; l <= level; ++l) {
    const Fragment fr = fragmentAt(rasterGeometry()[k].centreUW, l);
    const Average a = fragmentAverage(fr);
    const glm::dvec2 th = fr.thetaRange(), ph = fr.phiRange();
    const size_t n = centresCovered(fr).size();
    rows.push_back({{std::to_string(l)},
                    {std::to_string(fr.texelsPerSide()) + "x" + std::to_string(fr.texelsPerSide())},
                    {ratio(a.line, a.total), kAmber},
                    {std::to_string(n) + (l == one ? " <- one" : ""), l == one ? kGreen : kWhite},
                    {"[" + piFraction(th.x) + ", " + piFraction(th.y) + "]"},
                    {"[" + piFraction(ph.x) + ", " + piFraction(ph.y) + "]"}});
  }
  rows.push_back({{"Catmull: subdivide until a fragment covers one pixel centre; the pixel takes the mean of its texels.",
                   kWhite}});
  if (P == glm::ivec2(seed::kCatmullPx, seed::kCatmullPy))
    rows.push_back({{"the seed's example: 4 levels, 7 of 16 texels on lines = 7/16; it prints phi = 59pi/64 for 31pi/64 (!)",
                     kRed}});
  return rows;
}

inline ts::Frame catmullView(const State& s, int width, int height) {
  ts::Frame f = L::blankFrame(width, height);
  const int tex = f.addTexture(patternTexture());
  const Raster& R = raster();
  const size_t k = size_t(pixelIndex(s.pixel.x, s.pixel.y));
  const std::vector<Row> rows = catmullRows(s.pixel, s.level);
  const float m = 8;
  const int ts_ = tableScale(rows, float(width) - 2 * m, float(height) * 0.42f, 2);
  const float textH = std::min(float(height) * 0.42f, float(rows.size() + 1) * L::lineHeight(ts_) + 4);
  L::FlowSpec spec;
  spec.n = 3;
  spec.linesAbove = 1;
  spec.linesBelow = 1;
  spec.gap = 14;
  spec.maxScale = 2;
  const auto cells = L::flow({m, m, float(width) - m, float(height) - m - textH}, spec);
  table(f, {m, float(height) - m - textH + 4, float(width) - m, float(height) - m}, rows, 2);
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
      onPattern.insert(onPattern.end(), {{float(e) / n, 0.0f}, {float(e) / n, 1.0f}, {0.0f, float(e) / n}, {1.0f, float(e) / n}});
    }
    rasterP.batches.insert(rasterP.batches.end() - 2, onRaster);  // under the outline and the pixel
    pat.batches.push_back(ts::lineSegments(onPattern, kFragmentEdge, 1.0f, "fragment_edges"));
  }
  std::string under = "centre not on the octant";
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
      quad(dots, {(c.x + 0.35f) / kRaster, (c.y + 0.35f) / kRaster}, {(c.x + 0.65f) / kRaster, (c.y + 0.65f) / kRaster}, kGreen);
    rasterP.batches.push_back(dots);
    pat.batches.push_back(ts::lineLoop({glm::vec2(a), {float(b.x), float(a.y)}, glm::vec2(b), {float(a.x), float(b.y)}},
                                       kCounted, 3.0f, "fragment"));
    const double t = fr.texelsPerSide();
    const glm::dvec2 lo = a * double(kTexels), side(std::max(t, 4.0));
    ts::Panel zoom = patternPanel("fragment", cells[2].picture, tex, lo, lo + side);
    zoom.batches.push_back(loopInPattern({lo, lo + glm::dvec2(t, 0), lo + glm::dvec2(t), lo + glm::dvec2(0, t)}, kCounted,
                                         3.0f, "fragment"));
    f.panels.push_back(zoom);
    const Average av = fragmentAverage(fr);
    under = std::to_string(av.line) + " of " + std::to_string(av.total) + " on lines: " + fmt("%.4f", av.value());
  }
  f.panels.insert(f.panels.begin(), {rasterP, pat});
  L::caption(f, cells[0].above, "level " + std::to_string(s.level) + ": each pixel its fragment's mean", kWhite, cells[0].scale);
  L::caption(f, cells[0].below, "pixel " + pixelName(s.pixel) + ", its fragment in green", kAmber, cells[0].scale);
  L::caption(f, cells[1].above, std::to_string(n) + "x" + std::to_string(n) + " fragments on the pattern", kWhite, cells[1].scale);
  L::caption(f, cells[1].below, "64x64 texels, lines at 0 15 31 47 63", kWhite, cells[1].scale);
  L::caption(f, cells[2].above, "the fragment's texels", kWhite, cells[2].scale);
  L::caption(f, cells[2].below, under, kAmber, cells[2].scale);
  return f;
}

// --- inverse: the pixel's corners, both counts ---------------------------------------------
inline std::vector<Row> inverseRows(glm::ivec2 P) {
  std::vector<Row> rows;
  const auto corners = cornersUW(P.x, P.y);
  if (!corners) return {{{"pixel " + pixelName(P) + " is not wholly on the sphere", kAmber}}};
  const bool seeds = P == glm::ivec2(seed::kInversePx, seed::kInversePy);
  rows.push_back({{"Px"}, {"Py"}, {"x'"}, {"y'"}, {"z'"}, {"x"}, {"y"}, {"z"}, {"phi"}, {"theta"}, {"u"}, {"w"}});
  const auto pc = pixelCorners(P.x, P.y);
  for (size_t c = 0; c < 4; ++c) {
    const Back b = *backOfPixelPoint(pc[c]);
    const double vals[10] = {b.viewPoint.x, b.viewPoint.y, b.viewPoint.z, b.point.x, b.point.y, b.point.z,
                             b.phi * 180 / kPi, b.theta * 180 / kPi, b.uw.x, b.uw.y};
    const char* fmts[10] = {"%.4f", "%.4f", "%.3f", "%.3f", "%.3f", "%.3f", "%.2f", "%.2f", "%.3f", "%.3f"};
    Row r = {{std::to_string(int(pc[c].x))}, {std::to_string(int(pc[c].y))}};
    for (int e = 0; e < 10; ++e) r.push_back({fmt(fmts[e], vals[e])});
    rows.push_back(r);
    if (seeds) {
      const seed::PrintedCorner& s = seed::corners()[c];
      const double pr[10] = {s.xv, s.yv, s.zv, s.x, s.y, s.z, s.phiDeg, s.thetaDeg, s.u, s.w};
      const double unit[10] = {1e-4, 1e-4, 1e-3, 1e-3, 1e-3, 1e-3, 1e-2, 1e-2, 1e-3, 1e-3};
      Row q = {{"seed", kDim}, {""}};
      for (int e = 0; e < 10; ++e) {
        const bool wrong = std::fabs(pr[e] - vals[e]) > unit[e] + 1e-9;
        q.push_back({fmt(fmts[e], pr[e]) + (wrong ? "!" : ""), wrong ? kRed : kDim});
      }
      rows.push_back(q);
    }
  }
  const CentreCount ce = countCentres(toTexels(*corners)), cr = countCentres(toTexels(rounded3(*corners))),
                    cc = countCentresCurved(P.x, P.y);
  rows.push_back({{"corners to 3 decimals as printed, centres at (i+1/2, j+1/2), lines at 0 15 31 47 63, inside or on: " +
                       std::to_string(cr.texels) + " texels, " + std::to_string(cr.lines) + " on lines = " +
                       fmt("%.4f", cr.fraction()),
                   kAmber}});
  rows.push_back({{"unrounded corners: " + std::to_string(ce.texels) + ", " + std::to_string(ce.lines) + " = " +
                       fmt("%.4f", ce.fraction()) + "; the curved preimage: " + std::to_string(cc.texels) + ", " +
                       std::to_string(cc.lines) + " = " + fmt("%.4f", cc.fraction()),
                   kWhite}});
  const auto qe = toTexels(*corners), qr = toTexels(rounded3(*corners));
  for (const auto& t : cr.inside) {
    bool inExact = false;
    for (const auto& q : ce.inside) inExact |= q == t;
    if (!inExact)
      rows.push_back({{"texel (" + std::to_string(t.x) + "," + std::to_string(t.y) + ")" +
                           (pattern(t.x, t.y) > 0 ? ", on a line" : "") + ": its centre is " +
                           fmt("%.3f", -centreDepth(qe, t)) + " texels outside the unrounded quadrilateral, " +
                           fmt("%.3f", centreDepth(qr, t)) + " inside the rounded one",
                       kMagenta}});
  }
  if (seeds)
    rows.push_back({{"! the seed prints z = 0.341 at (21,15) and phi = 61.34 at (22,15); it omits T, and gives the sphere as y = cos theta, z = cos theta sin theta",
                     kRed}});
  return rows;
}

inline ts::Frame inverseView(const State& s, int width, int height) {
  ts::Frame f = L::blankFrame(width, height);
  const int tex = f.addTexture(patternTexture());
  const std::vector<Row> rows = inverseRows(s.pixel);
  const float m = 8;
  const int ts_ = tableScale(rows, float(width) - 2 * m, float(height) * 0.5f, 2);
  const float textH = std::min(float(height) * 0.5f, float(rows.size() + 2) * L::lineHeight(ts_) + 4);
  L::FlowSpec spec;
  spec.n = 2;
  spec.linesAbove = 1;
  spec.linesBelow = 1;
  spec.gap = 16;
  spec.maxScale = 2;
  const auto cells = L::flow({m, m, float(width) - m, float(height) - m - textH}, spec);
  table(f, {m, float(height) - m - textH + 4, float(width) - m, float(height) - m}, rows, 2);
  f.panels.push_back(rasterPanel("raster", cells[0].picture, raster().inverse, s.pixel));
  addPreimage(f, cells[1].picture, tex, s.pixel, true);
  L::caption(f, cells[0].above, "inverse mapping over the raster (unrounded corners)", kWhite, cells[0].scale);
  L::caption(f, cells[0].below, "pixel " + pixelName(s.pixel) + " in red", kAmber, cells[0].scale);
  L::caption(f, cells[1].above, "pixel " + pixelName(s.pixel) + " on the pattern", kWhite, cells[1].scale);
  L::caption(f, cells[1].below, "blue: true preimage; red: corners; orange: to 3 decimals", kWhite,
             cells[1].scale);
  return f;
}

// --- methods: the raster six ways ------------------------------------------------------------
inline ts::Frame methodsView(const State& s, int width, int height, const GlRasters* gl) {
  ts::Frame f = L::blankFrame(width, height);
  L::FlowSpec spec;
  spec.n = 6;
  spec.aspect = float(kOctantWindow.z - kOctantWindow.x) / float(kOctantWindow.w - kOctantWindow.y);
  spec.linesAbove = 1;
  spec.linesBelow = 2;
  spec.gap = 12;
  const auto cells = L::flow({8, 8, float(width) - 8, float(height) - 8}, spec);
  const Raster& R = raster();
  for (int mth = 0; mth < 6; ++mth) {
    const L::Cell& c = cells[size_t(mth)];
    const std::vector<double> v = values(mth, gl);
    f.panels.push_back(rasterPanel(std::string("raster_") + methodKey(mth), c.picture, v, s.pixel, kOctantWindow));
    L::caption(f, c.above, methodLabel(mth), kWhite, c.scale);
    const auto [a, b] = L::halves(c.below);
    if (v.empty()) {
      L::caption(f, a, "measuring ...", kAmber, c.scale);
    } else if (mth == kExact) {
      L::caption(f, a, std::to_string(interiorPixels(R)) + " px wholly on the octant", kAmber, c.scale);
      L::caption(f, b, std::to_string(linePixels(R)) + " over a line", kAmber, c.scale);
    } else {
      L::caption(f, a, "rms " + fmt("%.3f", rmsAgainstExact(v, R)), kAmber, c.scale);
      L::caption(f, b, "lost " + std::to_string(lostLinePixels(v, R)) + " of " + std::to_string(linePixels(R)), kAmber,
                 c.scale);
    }
  }
  return f;
}

inline ts::Frame build(const State& s, int width, int height, const GlRasters* gl) {
  switch (s.view) {
    case kTable: return tableView(s, width, height);
    case kCatmull: return catmullView(s, width, height);
    case kInverse: return inverseView(s, width, height);
    case kMethods: return methodsView(s, width, height, gl);
    default: return overviewView(s, width, height, gl);
  }
}
}  // namespace octant::frames
