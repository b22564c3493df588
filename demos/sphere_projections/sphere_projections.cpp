// Figure VI.5 — two ways to put a checkerboard on a sphere.
//
// The claim (Buss, VI.1.2): the sphere p(θ, φ) = (r sin θ cos φ, r sin φ,
// r cos θ cos φ) takes s = θ/360 and either t = φ/180 + 1/2 (Eq. VI.2, left)
// or t = (sin φ + 1)/2 (Eq. VI.3, right: the sphere projected out onto a
// cylinder and the cylinder unrolled).  VI.3 preserves area, VI.2 does not:
// its checks shrink toward the poles.  Both pinch at the poles, where the
// whole top (bottom) edge of the texture meets in one point.
//
// Keys (each is also a flag, see --help):
//   m  mapping: both side by side | VI.2 | VI.3
//   v  view: the spheres | the plot of area ratio against latitude
//   r / R  turn the spheres about their axis (15° steps)
//   t / T  tilt toward / away from the viewer (10° steps)
//   + / -  mesh resolution: cells per 20° band (cells of 20/N degrees)
//
// What the GL does: each sphere is one glBegin(GL_TRIANGLES) sent by
// common/gl/render.cpp: Renderer::draw, glTexCoord4f(s, t, 0, 1) + glVertex3f
// per vertex, (s, t) from sphere_projections_math.hpp's texCoord (Eq. VI.2 or VI.3) at the
// grid's corners, interpolated by GL inside each cell; the two spheres differ
// only in those t (book_figures/vi5_sphere_projections.gl.txt: the first
// vertices' t = 0.0278 against 0.0019).  Renderer::texture uploads the
// mipmapped checkerboard (GL_LINEAR_MIPMAP_LINEAR) and makes
// glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE).
// vi5_area_ratio.gl.txt draws only the plot; its numbers come from
// sphere_projections_measure.hpp's texel-index renders (Renderer::renderOffscreen).
//
// Measured, per 20° band of latitude and per mapping: texture area / surface
// area, normalised to a whole-sphere mean of 1 — analytic (sphere_projections_math.hpp),
// exact from the mesh's triangles, and from a render that shows which texel
// every pixel took; plus the pinch (how much of the texture's width meets
// within 3 px of a pole) and the texture the pole triangles draw nowhere.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "common/gl/render.hpp"
#include "common/core/layout.hpp"
#include "common/core/plot.hpp"
#include "common/core/scene.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/core/user_texture.hpp"
#include "sphere_projections_math.hpp"
#include "sphere_projections_measure.hpp"  // the band ratios and the pinch, from a texel-index render

namespace {
using sphere::Mapping;
using sphere::kBands;

enum Shown { kBoth, kVI2, kVI3 };
const char* const kKey[] = {"vi2", "vi3"};  // measurement names
const char* const kEq[] = {"Eq. VI.2", "Eq. VI.3"};
const char* const kFormula[] = {"s = theta/360,  t = phi/180 + 1/2", "s = theta/360,  t = (sin phi + 1)/2"};
const glm::vec4 kColour[] = {{1.0f, 0.55f, 0.1f, 1.0f}, {0.35f, 0.7f, 1.0f, 1.0f}};
using ts::layout::kWhite;

using ts::layout::fmt;
std::string bandName(int b) {
  return "[" + fmt("%.0f", sphere::bandLo(b)) + ":" + fmt("%.0f", sphere::bandHi(b)) + "]";
}

class SphereProjections final : public ts::Scene {
 public:
  std::string id() const override { return "sphere_projections"; }
  std::string title() const override { return "Figure VI.5 - two sphere projections"; }
  std::string about() const override {
    return "A checkerboard on a sphere with s = theta/360 and t = phi/180 + 1/2 (Eq. VI.2) or t = (sin phi + 1)/2\n"
           "(Eq. VI.3, the cylinder projection unrolled). Prints texture area / surface area per 20 deg band of\n"
           "latitude (whole-sphere mean 1): analytic, from the mesh, and measured from a texel-index render.\n"
           "VI.3 is 1 in every band (area-preserving); VI.2 grows like 1/cos(phi) toward the poles. Both pinch.";
  }
  std::vector<std::string> claim() const override { return {"vi2[-10:10]_render", "vi2[70:90]_render", "vi3_spread"}; }

  void addOptions(ts::Options& o) override {
    o.addEnum("mapping", &shown_, {"both", "vi2", "vi3"}, "both spheres, or Eq. VI.2 or Eq. VI.3 alone", 'm');
    o.addEnum("view", &view_, {"spheres", "plot"}, "the spheres, or area ratio against latitude", 'v');
    o.addInt("rotation", &rotation_, -180, 180, "turn about the sphere's axis, degrees", 'r', 'R', 15);
    o.addInt("tilt", &tilt_, -90, 90, "tilt of the north pole toward the viewer, degrees", 't', 'T', 10);
    o.addInt("resolution", &resolution_, 1, 16,
             "mesh cells per 20 deg band (stacks 9N, slices 18N; the book-like default 4 = 5 deg cells)", '+', '-');
    picture_.addOption(o, "the checkerboard");
    camera_.addOptions(o);
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"vi5_sphere_projections",
         "Figure VI.5",
         "A checkerboard on two spheres, drawn with a tilt and a small rotation. Left: t = phi/180 + 1/2 "
         "(Eq. VI.2), the checks shrink toward the poles. Right: t = (sin phi + 1)/2 (Eq. VI.3), the cylinder "
         "projection: every check has the same area. Both pinch at the poles.",
         {"--view", "spheres", "--mapping", "both"},
         1024,
         512,
         "Texture area per surface area varies {vi2_spread}x between latitude bands with Eq. VI.2, {vi3_spread}x "
         "with Eq. VI.3 (area-preserving)."},
        {"vi5_area_ratio",
         "Figure VI.5 (measured)",
         "Texture area / surface area by 20 deg band of latitude, measured from texel-index renders (bars and "
         "dots) against the analytic ratio (lines): 2/(pi cos phi) for Eq. VI.2, 1 for Eq. VI.3 (whole-sphere "
         "mean 1).",
         {"--view", "plot", "--mapping", "both"},
         1024,
         512,
         "Eq. VI.2 gives the bands near the poles {vi2[70:90]_render}x the mean texture area per surface area "
         "(analytic {vi2[70:90]_analytic}), the equator {vi2[-10:10]_render}x; Eq. VI.3 varies {vi3_spread}x."},
    };
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;

 private:
  using Result = sphere::Result;
  std::vector<Mapping> mappings() const {
    if (shown_ == kVI2) return {Mapping::Latitude};
    if (shown_ == kVI3) return {Mapping::Cylinder};
    return {Mapping::Latitude, Mapping::Cylinder};
  }
  using Results = std::map<std::pair<int, int>, Result>;  // (mapping, resolution) -> numbers
  // What measure() found for this mapping at this resolution (null before it has).
  const Result* found(const ts::Measurements& measured, Mapping m) const {
    const Results* all = measured.detailAs<Results>();
    if (!all) return nullptr;
    auto it = all->find({int(m), resolution_});
    return it == all->end() ? nullptr : &it->second;
  }
  void addSphere(ts::Frame& f, const ts::layout::Cell& cell, Mapping m, int texture, const Result* res,
                 const ts::Measurements& measured) const;
  void addPlot(ts::Frame& f, int width, int height, const ts::Measurements& measured) const;

  int shown_ = kBoth, view_ = 0, rotation_ = 20, tilt_ = 20, resolution_ = 4;
  ts::UserTexture picture_;  // --texture FILE
  ts::OrbitCamera camera_;   // --yaw --pitch --zoom: the mouse
  Results cache_;            // measure()'s: rotation and tilt do not change the numbers
};

// ---------------------------------------------------------------------------
// The picture.

void SphereProjections::addSphere(ts::Frame& f, const ts::layout::Cell& cell, Mapping m, int texture, const Result* res,
                                  const ts::Measurements& measured) const {
  const ts::Rect& vp = cell.picture;
  ts::Panel p;
  p.id = std::string("sphere_") + kKey[int(m)];
  p.viewport = vp;
  p.depthTest = true;
  // A narrow perspective (30°, eye 4.6 radii away): the sphere fills ~83% of
  // the panel and looks round, not fish-eyed.
  p.projection = camera_.lens(glm::perspective(float(sphere::rad(30.0)), float(vp.w) / float(vp.h), 1.0f, 10.0f));
  // The orbit turns the sphere about its centre, after its own turn.
  glm::mat4 turn = camera_.view(glm::rotate(glm::rotate(glm::mat4(1.0f), float(sphere::rad(tilt_)), {1, 0, 0}),
                                            float(sphere::rad(rotation_)), {0, 1, 0}));
  p.modelview = glm::translate(glm::mat4(1.0f), {0, 0, -4.6f}) * turn;
  // Light from the upper left, in front, fixed to the viewer: into model
  // coordinates with the inverse (transpose) of the rotation.
  glm::dvec3 toLight = glm::transpose(glm::dmat3(glm::mat3(turn))) * glm::dvec3(-0.45, 0.55, 0.7);
  // The mesh's (s, t) (sphere::texCoord) become glTexCoord4f(s, t, 0, 1) in Renderer::draw.
  p.batches.push_back(ts::litMeshBatch(sphere::sphereMesh(m, resolution_), texture, toLight));
  f.panels.push_back(p);

  // The equation and its formula above, the measured ratios below.
  namespace L = ts::layout;
  const auto [equation, formula] = L::halves(cell.above);
  // The equation's name is the key of its colour (the area-ratio plot draws
  // each mapping in it): a swatch and the name, centred over the formula.
  const float keyW = ts::text::height(cell.scale) + 4.0f * float(cell.scale) + ts::text::width(kEq[int(m)], cell.scale);
  const float keyX = std::max(equation.x0, (equation.x0 + equation.x1 - keyW) / 2);
  L::legend(f, {keyX, equation.y0, equation.x1, equation.y1}, {{kColour[int(m)], kEq[int(m)]}}, cell.scale);
  L::caption(f, formula, kFormula[int(m)], kWhite, cell.scale);
  if (res)
    L::caption(f, cell.below,
               "texture/surface area: equator band " +
                   L::measured(measured, kKey[int(m)] + bandName(kBands / 2) + "_render", "%.2f") + ", pole bands " +
                   L::measured(measured, kKey[int(m)] + bandName(kBands - 1) + "_render", "%.2f"),
               kWhite, cell.scale);
}

void SphereProjections::addPlot(ts::Frame& f, int width, int height, const ts::Measurements& measured) const {
  namespace plot = ts::plot;
  // Latitude -90..90 across, ratio 0..4.5 up.  The VI.2 curve leaves the top
  // near the poles (it is 1/cos φ); the viewport clips it.
  plot::Spec p;
  p.x0 = -90, p.x1 = 90, p.y1 = 4.5;
  p.xLabel = "latitude phi (degrees)";
  p.yLabel = "texture area / surface area (whole sphere = 1)";
  p.xTicks = plot::ticks(sphere::bandLo(0), sphere::bandHi(kBands - 1), sphere::kBandDeg, "%.0f");
  p.yTicks = plot::ticks(0, 4, 1, "%.0f");
  p.scale = ts::layout::scaleFor({0, 0, width * 2 / 5, height * 2 / 5});
  p.titleColor = p.textColor = kWhite;
  for (Mapping m : mappings()) {
    const glm::vec4 c = kColour[int(m)];
    // Analytic ratio, every degree (±89.5°: 2/(π cos φ) = 73, far off the top).
    plot::Series analytic(std::string("analytic_") + kKey[int(m)], c, plot::Mark::Line, {}, 1.0f);
    for (double phi = -89.5; phi <= 89.5; phi += 1.0) analytic.points.push_back({phi, sphere::ratioAt(m, phi)});
    p.series.push_back(analytic);
    ts::layout::Text legend = std::string(kEq[int(m)]) + "  " + kFormula[int(m)] + ":  analytic (line)";
    if (const Result* res = found(measured, m)) {
      // Bars across each band and a 7-px square at its centre.
      plot::Series bars(std::string("measured_") + kKey[int(m)], c, plot::Mark::Bars, {}, 3.0f),
          dots(std::string("measured_points_") + kKey[int(m)], c, plot::Mark::Squares, {}, 1.0f, 3.5f);
      for (int b = 0; b < kBands; ++b) bars.points.push_back({sphere::bandMid(b), res->render[size_t(b)]});
      bars.halfWidth = sphere::kBandDeg / 2 - 1;
      dots.points = bars.points;
      p.series.insert(p.series.end(), {bars, dots});
      legend = legend + ", measured (bars): max/min " +
               ts::layout::measured(measured, std::string(kKey[int(m)]) + "_spread", "%.2f");
    }
    p.legend.push_back({legend, c});
  }
  plot::draw(f, p, {0, 0, width, height});
}

ts::Frame SphereProjections::build(int width, int height, const ts::Measurements& measured) const {
  ts::Frame f = ts::layout::blankFrame(width, height);
  if (view_ == 1) {
    addPlot(f, width, height, measured);
    return f;
  }
  // 16 x 16 checks: 22.5° of θ per check around, 11.25° of φ (VI.2) per
  // check up, so the checks' shapes show both maps.  Mipmapped: VI.2 squeezes
  // a whole texture row into a point at the poles.  t does not wrap.
  ts::TextureDesc checker = ts::checkerboard(512, 16);
  checker.mipmaps = true;
  checker.minFilter = GL_LINEAR_MIPMAP_LINEAR;
  checker.wrapT = GL_CLAMP_TO_EDGE;
  int tex = f.addTexture(picture_.orDefault(checker));
  std::vector<Mapping> ms = mappings();
  int n = int(ms.size());
  ts::layout::FlowSpec spec;
  spec.n = n;
  spec.linesAbove = 2;  // the equation, its formula
  spec.linesBelow = 2;  // the measured ratios (wrapped when narrow)
  spec.gap = 16;
  std::vector<ts::layout::Cell> cells = ts::layout::flow({8, 8, float(width) - 8, float(height) - 8}, spec);
  for (int k = 0; k < n; ++k)
    addSphere(f, cells[size_t(k)], ms[size_t(k)], tex, found(measured, ms[size_t(k)]), measured);
  return f;
}

// ---------------------------------------------------------------------------
// The measurement: each band's region drawn face-on with a texel-index
// texture, its surface area summed from the pixels that took its texels
// (sphere_projections_measure.hpp), against its texture area.

ts::Measurements SphereProjections::measure(ts::Renderer& r) {
  ts::Measurements out;
  for (Mapping m : mappings()) {
    auto key = std::make_pair(int(m), resolution_);
    if (!cache_.count(key)) cache_[key] = sphere::measureMapping(r, m, resolution_);  // rotation and tilt do not matter
    const Result& res = cache_[key];
    const std::string k = kKey[int(m)];
    for (int b = 0; b < kBands; ++b) {
      std::string band = bandName(b), deg = fmt("%.0f", sphere::bandLo(b)) + ".." + fmt("%.0f", sphere::bandHi(b));
      out.push_back({k + band + "_analytic", res.analytic[size_t(b)],
                     "texture/surface area, latitudes " + deg + ", whole sphere = 1: exact for the sphere"});
      out.push_back(
          {k + band + "_mesh", res.mesh[size_t(b)], "the same from the mesh's triangles ((s,t) area / 3D area)"});
      out.push_back({k + band + "_render", res.render[size_t(b)], "the same measured from a texel-index render"});
    }
    out.push_back({k + "_spread", res.spread, "largest / smallest measured band ratio (1 = area-preserving)"});
    out.push_back({k + "_pinch_lost", res.pinchLost,
                   "fraction of the texture on the pole triangles that have no area (drawn nowhere)"});
    out.push_back({k + "_pole_s_span", res.poleSpan, "fraction of the texture's width (s) seen within 3 px of a pole"});
    out.push_back({k + "_front_s_span", res.frontSpan, "the same within 3 px of the front point (theta 0, phi 0)"});
  }
  out.detail = cache_;
  return out;
}
}  // namespace

TS_REGISTER_SCENE(SphereProjections);
