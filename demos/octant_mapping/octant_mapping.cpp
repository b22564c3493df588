// Seed 004 (Rogers) — a grid pattern mapped onto the octant of a sphere: the
// worked examples, reproduced and measured.
//
// The claims (seed 004, after Rogers' Procedural Elements for Computer
// Graphics): the linear mapping θ = (π/2) u, φ = π/2 - (π/4) w puts the 64 x 64
// grid on the octant (the table of the line u = 1/4); Catmull's subdivision
// needs 4 levels for a fragment to cover one pixel centre, and that
// fragment's 4 x 4 texels hold 7 on the grid's lines: intensity 7/16; inverse
// pixel mapping sends pixel (21, 15)'s corners back to the pattern, and 5 of
// the 18 texel centres inside are on lines: 5/18.  Point sampling "can lose
// much or all of the pattern".
//
// Found: 5/18 is reproduced only with the corners rounded to 3 decimals as
// the seed prints them: texel (47, 46), on the line u = 47, has its centre
// 0.005 texels outside the exact quadrilateral and 0.003 inside the rounded
// one; unrounded (and over the true curved preimage) the count is 4/17.
// The seed's misprints are flagged beside the corrected values
// (octant_mapping_seed.hpp) and listed as measurements misprint[...].
//
// Views (v): overview (the octant in 3D with the mouse orbit, the 32 x 32
// raster enlarged with the chosen pixel, the pixel's preimage on the
// pattern) | table (the forward table for any u as the seed prints it, the
// misprints flagged) | catmull (subdivision level by level on the chosen
// pixel) | inverse (the pixel's corners, both counts) | methods (the raster
// by each method against the exact area integral).
//
// Keys (each is also a flag, see --help):
//   v  view            m  the raster's method in the overview
//   + / -  Catmull level shown     a  animate the levels (window)
//   ] / [  the table's u, by 1/16  left drag, wheel: orbit and zoom the octant
//   click a raster pixel, or --pixel X,Y (Rogers' Px, Py: Py counts up from
//   the bottom row, 0..31)
//   --texture FILE  a picture (hand-drawn or scanned: PNG, JPEG, BMP) shown on
//   the octant and as the pattern instead of the grid; the numbers stay the
//   grid's (they count its line texels), and the figure says so under it
//
// What the GL does: the octant is one glBegin(GL_TRIANGLES) of
// glTexCoord4f(u, w, 0, 1) + glVertex3f per vertex (octant_mapping_gl.hpp), the
// raster's pixels flat-coloured quads holding the values computed here (so
// the sidecar has every value), the pattern ts::lineGrid(64, 4) on a unit
// square.  measure() renders the 32 x 32 raster with GL_NEAREST, trilinear and
// anisotropic 16x and reads the intensities back.
// Listings: book_figures/octant_tables.gl.txt, octant_catmull.gl.txt,
// octant_inverse_pixel.gl.txt, octant_methods.gl.txt.
//
// Measured: the worked answers from octant_mapping_math.hpp (catmull_fraction,
// inverse_fraction, table_xyz[u=1/4,w=1/2].x/.y/.z), and over the raster's
// 212 pixels whose preimage lies on the octant, the RMS error of each method
// against the exact area integral (common/core/area_filter.hpp): rms_exact[...],
// and the pixels over a line that point sampling shows none of:
// lost_line_pixels[nearest].
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "common/core/error.hpp"
#include "common/core/layout.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/core/scene.hpp"
#include "common/gl/render.hpp"
#include "common/core/user_texture.hpp"
#include "octant_mapping_frames.hpp"  // the five views
#include "octant_mapping_gl.hpp"      // the mesh and the GL renders of the raster
#include "octant_mapping_math.hpp"
#include "octant_mapping_seed.hpp"  // what the seed prints, and its misprints

namespace {
using namespace octant;

// "X,Y", two whole numbers 0..31.
glm::ivec2 parsePixelOption(const std::string& text) {
  const size_t comma = text.find(',');
  auto number = [&](const std::string& v) {
    if (v.empty() || v.size() > 2 || v.find_first_not_of("0123456789") != std::string::npos || std::stoi(v) >= kRaster)
      throw ts::Error("--pixel: '" + text + "' is not a raster pixel X,Y with 0 <= X, Y <= 31 (Rogers' Px, Py)");
    return std::stoi(v);
  };
  if (comma == std::string::npos) number("");
  return {number(text.substr(0, comma)), number(text.substr(comma + 1))};
}

class OctantMapping final : public ts::Scene {
 public:
  std::string id() const override { return "octant_mapping"; }
  std::string title() const override { return "Seed 004 - Rogers' sphere octant: tables, Catmull, inverse mapping"; }
  std::string about() const override {
    return "Rogers' worked examples (seed 004): a 64x64 grid on the octant of the unit sphere by theta = (pi/2) u,\n"
           "phi = pi/2 - (pi/4) w, seen as Rx(35) Ry(-45) on a 32x32 raster.  The forward table of u = 1/4, Catmull's\n"
           "subdivision (4 levels, 7/16) and inverse pixel mapping of pixel (21,15) (the seed's 5/18 with its corners\n"
           "rounded as printed; 4/17 unrounded), the seed's misprints flagged; and over the raster, point sampling,\n"
           "Catmull-4, inverse mapping, GL trilinear and anisotropic against the exact area integral.\n"
           "Click a pixel of the raster (or --pixel X,Y, Py up from the bottom row).";
  }
  int defaultWidth() const override { return 1024; }
  int defaultHeight() const override { return 540; }
  std::vector<std::string> claim() const override {
    return {"catmull_fraction", "inverse_fraction", "lost_line_pixels[nearest]"};
  }

  void addOptions(ts::Options& o) override {
    o.addEnum("view", &s_.view, {"overview", "table", "catmull", "inverse", "methods"},
              "overview | the forward table | Catmull subdivision | inverse pixel mapping | the raster by each method",
              'v');
    o.addEnum("method", &s_.method, {"exact", "nearest", "catmull4", "inverse", "trilinear", "anisotropic"},
              "the overview raster: exact area integral, GL_NEAREST, Catmull at 4 levels, inverse mapping, GL "
              "trilinear, GL anisotropic 16x",
              'm');
    o.addText("pixel", &pixelText_, "the raster pixel X,Y (Rogers' Px, Py: 0..31, Py up from the bottom row)",
              [](const std::string& v) { parsePixelOption(v); });
    o.addInt("level", &s_.level, 0, kMaxLevel, "Catmull subdivision level shown", '+', '-');
    o.addBool("animate", &animate_, "window: step the Catmull level once a second", 'a');
    o.addFloat("u", &s_.u, 0.0f, 1.0f, "the forward table's line u (the seed's: 0.25)", ']', '[', 1.0f / 16);
    s_.camera.addOptions(o);
    picture_.addOption(o, "Rogers' 64 x 64 grid (the numbers stay the grid's)");
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"octant_tables",
         "Seed 004: the forward table",
         "The line u = 1/4 of Rogers' grid mapped onto the sphere octant (theta = (pi/2) u, phi = pi/2 - (pi/4) w), "
         "tabulated as the seed prints it, the seed's misprints flagged in red beside the corrected values; right: "
         "the line on the octant.",
         {"--view", "table", "--u", "0.25"},
         1280,
         600,
         "u = 1/4, w = 1/2 lands at ({table_xyz[u=1/4,w=1/2].x}, {table_xyz[u=1/4,w=1/2].y}, "
         "{table_xyz[u=1/4,w=1/2].z}); the seed's x, y, z agree ({seed_table_xyz_wrong} wrong), its theta and phi "
         "carry 4 misprints."},
        {"octant_catmull",
         "Seed 004: Catmull subdivision",
         "Catmull's subdivision on pixel (5,9): left, the raster with each pixel the mean of the fragment of level 4 "
         "holding its centre, the fragments' images and the chosen one's; middle, the fragments on the pattern; "
         "right, the chosen fragment's texels; below, level by level.",
         {"--view", "catmull", "--pixel", "5,9", "--level", "4"},
         1280,
         720,
         "After {catmull_levels[5,9]} subdivisions the fragment covers one pixel centre and 4x4 texels, "
         "{catmull_line_texels} on lines: {catmull_fraction} = 7/16."},
        {"octant_inverse_pixel",
         "Seed 004: inverse pixel mapping",
         "Pixel (21,15) mapped back onto the pattern: its corners joined unrounded (red) and as the seed prints them "
         "(orange dashes, 3 decimals), the true curved preimage (wide, blue), and the texel centres each counts; the "
         "corner table with the seed's printed values, misprints in red.",
         {"--view", "inverse", "--pixel", "21,15"},
         1280,
         720,
         "With the corners rounded as printed, {inverse_texels} texel centres, {inverse_line_texels} on lines: "
         "{inverse_fraction} (the seed's 5/18); unrounded {inverse_texels[unrounded]}, "
         "{inverse_line_texels[unrounded]}: {inverse_fraction[unrounded]}."},
        {"octant_methods",
         "Seed 004: four methods",
         "The 32x32 raster by the exact area integral of the pattern under each pixel's preimage, point sampling "
         "(GL_NEAREST), Catmull at 4 levels, inverse mapping (texel centres in the preimage), GL trilinear and GL "
         "anisotropic 16x; under each, its RMS error against the exact values over the pixels wholly on the octant.",
         {"--view", "methods"},
         1280,
         560,
         "RMS error against the exact area integral: GL_NEAREST {rms_exact[nearest]}, Catmull-4 "
         "{rms_exact[catmull4]}, inverse mapping {rms_exact[inverse]}, trilinear {rms_exact[trilinear]}, "
         "anisotropic {rms_exact[anisotropic]}; point sampling shows nothing of {lost_line_pixels[nearest]} of "
         "{line_pixels} pixels over a line."},
    };
  }
  // The animation steps the `level` option itself, once a second, so F12 saves
  // what is shown; the frame the key is taken on is left still.
  void update(double seconds) override {
    if (!animate_) {
      animFrames_ = 0, animClock_ = 0;
      return;
    }
    if (++animFrames_ <= 1) return;
    animClock_ += seconds;
    if (animClock_ >= 1.0) animClock_ = 0, s_.level = (s_.level + 1) % (kMaxLevel + 1);
  }
  bool animating() const override { return animate_; }
  // A click on a raster picks its pixel.
  std::vector<std::pair<std::string, std::string>> click(int x, int y, int width, int height) const override {
    const ts::Frame f = build(width, height, ts::Measurements());
    for (const ts::Panel& p : f.panels)
      if (p.id.rfind("raster", 0) == 0) {
        const glm::ivec2 P = views::pixelAt(p, x, y);
        if (P.x >= 0) return {{"pixel", std::to_string(P.x) + "," + std::to_string(P.y)}};
      }
    return {};
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override {
    frames::State s = s_;
    s.pixel = parsePixelOption(pixelText_);
    if (!picture_.active()) return frames::build(s, width, height, measured);
    // A picture instead of the grid (Rogers: a pattern may be mathematical, hand-drawn or scanned).  Every number
    // counts the grid's line texels or is the mapping's geometry, so measure() keeps the grid; a line under the
    // figure says so.
    namespace L = ts::layout;
    s.pattern = picture_.orDefault(patternTexture());
    const float band = 2 * L::lineHeight(1) + 8;
    ts::Frame f = frames::build(s, width, std::max(1, int(float(height) - band)), measured);
    f.height = height;
    L::caption(f, {8, float(height) - band, float(width) - 8, float(height) - 4},
               "Pattern: " + picture_.path() +
                   " (the octant and the pattern panels).  The fractions, counts and "
                   "rasters are of Rogers' grid, which measure() keeps: they count its line texels.",
               L::kAmber, 1);
    return f;
  }
  ts::Measurements measure(ts::Renderer& r) override;

 private:
  using Add = std::function<void(const std::string&, double, const std::string&)>;
  void addShownExamples(glm::ivec2 P, const Add& add) const;
  frames::State s_;
  std::string pixelText_ = "21,15";
  ts::UserTexture picture_;  // --texture FILE: the picture shown instead of the grid
  bool animate_ = false;
  long animFrames_ = 0;
  double animClock_ = 0;
};

// The worked examples as the catmull and inverse views print them, for the
// chosen pixel (and level): each row's numbers.
void OctantMapping::addShownExamples(glm::ivec2 P, const Add& add) const {
  namespace N = views::names;
  const std::string at = "pixel (" + N::pixel(P) + ")";
  const PixelGeometry& g = rasterGeometry()[size_t(pixelIndex(P.x, P.y))];
  if (g.centreOnPatch)
    for (int l = 0; l <= s_.level; ++l) {
      const Fragment fr = fragmentAt(g.centreUW, l);
      const Average a = fragmentAverage(fr);
      const std::string which = "the fragment of level " + std::to_string(l) + " holding " + at + "'s centre";
      add(N::catmull("line_texels", P, l), a.line, which + ": its texels on grid lines");
      add(N::catmull("texels", P, l), a.total, which + ": its texels");
      add(N::catmull("fraction", P, l), a.value(), which + ": line texels / texels, the pixel's intensity");
      add(N::catmull("centres", P, l), double(centresCovered(fr).size()), which + ": the pixel centres it covers");
    }
  const auto corners = cornersUW(P.x, P.y);
  if (!corners) return;
  const char* what[10] = {"x'", "y'", "z'", "x", "y", "z", "phi_deg", "theta_deg", "u", "w"};
  const char* meaning[10] = {"x' = Px/16 - 1",
                             "y' = Py/16 - 1",
                             "z' = sqrt(1 - x'^2 - y'^2), on the visible hemisphere",
                             "x of (x,y,z) = V^T (x',y',z')",
                             "y of V^T (x',y',z')",
                             "z of V^T (x',y',z')",
                             "phi = acos y, degrees",
                             "theta = atan2(x, z), degrees",
                             "u = theta/(pi/2)",
                             "w = (pi/2 - phi)/(pi/4)"};
  for (const glm::dvec2& c : pixelCorners(P.x, P.y)) {
    const Back b = *backOfPixelPoint(c);
    const double v[10] = {b.viewPoint.x, b.viewPoint.y,     b.viewPoint.z,       b.point.x, b.point.y,
                          b.point.z,     b.phi * 180 / kPi, b.theta * 180 / kPi, b.uw.x,    b.uw.y};
    for (int e = 0; e < 10; ++e)
      add(N::corner(c, what[e]), v[e],
          std::string("corner (") + std::to_string(int(c.x)) + "," + std::to_string(int(c.y)) + ") of " + at + ": " +
              meaning[e]);
  }
  const auto qe = toTexels(*corners), qr = toTexels(rounded3(*corners));
  const CentreCount ce = countCentres(qe), cr = countCentres(qr), cc = countCentresCurved(P.x, P.y);
  const std::pair<const char*, const CentreCount*> counts[] = {{"", &cr}, {"unrounded", &ce}, {"curved", &cc}};
  const char* how[] = {"the quadrilateral of its corners to 3 decimals", "the quadrilateral of its corners unrounded",
                       "its curved preimage"};
  for (int k = 0; k < 3; ++k) {
    const CentreCount& c = *counts[k].second;
    add(N::inverse("texels", P, counts[k].first), c.texels, at + ": texel centres in " + how[k]);
    add(N::inverse("line_texels", P, counts[k].first), c.lines, at + ": of them on grid lines, in " + how[k]);
    add(N::inverse("fraction", P, counts[k].first), c.fraction(), at + ": line texels / texels, in " + how[k]);
  }
  for (const glm::ivec2& t : cr.inside)
    if (std::find(ce.inside.begin(), ce.inside.end(), t) == ce.inside.end()) {
      const std::string texel = "texel (" + std::to_string(t.x) + "," + std::to_string(t.y) + ")";
      add(N::centreDepth("outside", P, t), -centreDepth(qe, t),
          at + ": " + texel +
              "'s centre, counted only with the corners rounded: texels outside the unrounded quadrilateral");
      add(N::centreDepth("inside_rounded", P, t), centreDepth(qr, t),
          at + ": the same centre, texels inside the rounded one");
    }
}

ts::Measurements OctantMapping::measure(ts::Renderer& r) {
  ts::Measurements out;
  auto add = [&](const std::string& n, double v, const std::string& m) { out.push_back({n, v, m}); };
  // Example 1: the line u = 1/4 (and the table view's line, when another).
  auto addTable = [&](double u) {
    const auto rows = forwardTable(u);
    const char* axis[3] = {"x = sin theta sin phi", "y = cos phi", "z = cos theta sin phi"};
    for (const TableRow& row : rows)
      for (int a = 0; a < 3; ++a)
        add(views::names::tableXyz(u, row.w, a), row.xyz[a],
            std::string(axis[a]) + " of the line u = " + views::fraction(u) + " at w = " + views::fraction(row.w) +
                (u == 0.25 && row.w == 0.5
                     ? " (theta = pi/8, phi = 3pi/8: x = sqrt(2)/4, y = cos(3pi/8), z = (2 + sqrt(2))/4)"
                     : ""));
    add(views::names::tableThetaDeg(u), rows[0].theta * 180 / kPi, "theta = (pi/2) u of the line, in degrees");
    double err = 0;
    for (const TableRow& row : rows) err = std::max(err, glm::length(row.xyz - closedForm(row.u, row.w)));
    add(views::names::tableMaxError(u), err,
        "largest distance of the table's points from the closed form (sin, cos of u, w)");
  };
  addTable(0.25);
  if (views::fraction(s_.u) != views::fraction(0.25)) addTable(s_.u);
  add("seed_table_xyz_wrong", seed::tableXyzWrong(),
      "of the 15 x, y, z the seed prints (2 decimals), how many are wrong");
  // Example 2: Catmull's fragment.
  const Fragment sf = fragmentAt({0.0, 0.0}, 4);
  const Average a = fragmentAverage(sf);
  add("catmull_fraction", a.value(),
      "the seed's fragment (theta in [0, pi/32], phi in [31pi/64, pi/2]): line texels / texels");
  add("catmull_line_texels", a.line, "its texels on grid lines (the seed: 7)");
  add("catmull_texels", a.total, "its texels (the seed: 16, 4x4)");
  add("catmull_levels[5,9]", levelsToOneCentre(seed::kCatmullPx, seed::kCatmullPy),
      "subdivisions until the fragment holding pixel (5,9)'s centre covers no other pixel centre (the seed: 4)");
  // Example 3: pixel (21, 15).
  const auto corners = *cornersUW(seed::kInversePx, seed::kInversePy);
  const CentreCount rounded = countCentres(toTexels(rounded3(corners))), exact = countCentres(toTexels(corners)),
                    curved = countCentresCurved(seed::kInversePx, seed::kInversePy);
  add("inverse_fraction", rounded.fraction(),
      "pixel (21,15): line texels / texel centres in the quadrilateral of its corners rounded to 3 decimals as "
      "printed (centres at i + 1/2, lines 0 15 31 47 63, inside or on)");
  add("inverse_texels", rounded.texels, "texel centres in it (the seed: 18)");
  add("inverse_line_texels", rounded.lines, "of them on lines (the seed: 5)");
  add("inverse_fraction[unrounded]", exact.fraction(), "the same with the corners unrounded");
  add("inverse_texels[unrounded]", exact.texels, "texel centres in the unrounded quadrilateral");
  add("inverse_line_texels[unrounded]", exact.lines, "of them on lines");
  add("inverse_texels[curved]", curved.texels,
      "texel centres whose sphere point lands in the pixel (the true preimage)");
  add("inverse_line_texels[curved]", curved.lines, "of them on lines");
  // The seed's misprints, each checked (octant_mapping_seed.hpp).
  const auto mp = seed::misprints();
  for (const seed::Misprint& m : mp)
    add("misprint[" + m.id + "]", m.value, m.where + ": printed " + m.printed + "; it is " + m.correct);
  add("misprints_flagged", double(mp.size()), "misprints of the seed the demo flags");
  const seed::CornerCheck cc = seed::checkCorners();
  add("seed_corner_entries_wrong", cc.wrong,
      "of the 40 entries of the inverse example's corner tables, off by more than a unit of their last digit");
  // The chosen pixel.
  const glm::ivec2 P = parsePixelOption(pixelText_);
  addShownExamples(P, add);
  const size_t k = size_t(pixelIndex(P.x, P.y));
  const Raster& R = raster();
  const double none = -1;
  add("pixel_exact", R.interior[k] ? R.exact[k] : none,
      "the chosen pixel's exact area integral (-1: not wholly on the octant)");
  add("pixel_catmull4", R.centreOnPatch[k] ? R.catmull[k] : none, "its Catmull value at 4 levels");
  add("pixel_inverse", R.interior[k] ? R.inverse[k] : none, "its inverse-mapping value (unrounded corners)");
  add("pixel_catmull_levels", levelsToOneCentre(P.x, P.y), "subdivisions until its fragment covers one pixel centre");
  // The raster by each method (GL: three passes of 32 x 32).
  frames::GlRasters gl;
  ts::measureProgress(0.1);
  gl.nearest = renderRaster(r, GlFilter::Nearest);
  ts::measureProgress(0.4);
  gl.trilinear = renderRaster(r, GlFilter::Trilinear);
  ts::measureProgress(0.7);
  gl.anisotropic = renderRaster(r, GlFilter::Anisotropic);
  add("raster_pixels_compared", interiorPixels(R),
      "pixels whose whole preimage lies on the octant (the comparisons' pixels)");
  add("line_pixels", linePixels(R), "of them with some grid line under the preimage (exact > 0)");
  const std::pair<const char*, const std::vector<double>*> methods[] = {{"nearest", &gl.nearest},
                                                                        {"catmull4", &R.catmull},
                                                                        {"inverse", &R.inverse},
                                                                        {"trilinear", &gl.trilinear},
                                                                        {"anisotropic", &gl.anisotropic}};
  const char* meaning[] = {"GL_NEAREST, one sample at the pixel centre",
                           "Catmull: the mean of the level-4 fragment holding the centre",
                           "inverse mapping: texel centres in the corners' quadrilateral", "GL_LINEAR_MIPMAP_LINEAR",
                           "GL_LINEAR_MIPMAP_LINEAR with anisotropy 16"};
  for (size_t m = 0; m < 5; ++m)
    add(std::string("rms_exact[") + methods[m].first + "]", rmsAgainstExact(*methods[m].second, R),
        std::string("RMS of (value - exact) over those pixels, intensity 0..1: ") + meaning[m]);
  for (size_t m = 0; m < 5; ++m)
    add(std::string("lost_line_pixels[") + methods[m].first + "]", lostLinePixels(*methods[m].second, R),
        "pixels over a line that show none of it (value 0)");
  int mismatches = 0;
  for (size_t q = 0; q < R.point.size(); ++q) mismatches += R.interior[q] && R.point[q] != gl.nearest[q];
  add("point_gl_vs_cpu_mismatches", mismatches,
      "pixels where GL_NEAREST's texel differs from the CPU's (the mesh is 64x64)");
  out.detail = gl;
  return out;
}
}  // namespace

TS_REGISTER_SCENE(OctantMapping);
