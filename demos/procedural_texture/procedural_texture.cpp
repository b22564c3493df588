// Procedural textures: a solid (3D) texture made with noise, marble made from it, and a fractal terrain.
//
// The solid texture's claim (view solid; seed 001 ¶7): a texture defined at every point of space, not on a
// surface, is carved out of by the object: the texture coordinate is the surface point itself, so a sphere or a
// cube shows no seam, no stretching at the poles, whatever its shape.  A 2D image of the same noise wrapped round a
// sphere (u = longitude) meets itself at u = 0 = 1 along a meridian, where its colour jumps.  Measured on the
// renders, across the meridian facing the camera: the step over three pixels less the same step beside it
// (solid_seam_levels[solid] ~ 0, [wrapped_2d] > 0).  The lattice's values are computed once (one lattice of 16^3,
// reused by every octave) and interpolated; a lattice for each octave would grow eightfold an octave.
//
// Marble's claim (view marble): noise bends regular stripes into veins without changing their spacing:
// M = 1/2 + 1/2 sin(2 pi (stripes x + a T(p))) keeps the period 1 / stripes, measured by the autocorrelation of
// the render.
//
// The terrain's claim (view terrain; Rogers, seed 004): recursive random midpoint displacement (diamond-square)
// makes a fractal surface whose detail is chosen by the distance: depth d gives 4^d cells (2 4^d triangles,
// counted), one level less each time the distance doubles, and its roughness scales as a power of the distance
// between two points, sqrt(E[(h(x + r) - h(x))^2]) ~ r^H (H fitted from the generated field).  Its cost grows
// with the cells, faster than linearly in the edge's resolution: tests/bench/bench_procedural.cpp.
//
// Keys (each is also a flag, see --help):
//   v      view: solid | marble | terrain
//   o / O  octaves summed, 1..6                   s / S  marble's stripes across the block
//   t / T  marble's turbulence weight (percent)  d / D  the terrain's distance (depth follows it)
//   r / R  the terrain's roughness exponent H     (h, q and l are the window's: overlay, quit, GL calls)
//
// The equations (procedural_texture_math.hpp):
//   n(p) = trilinear interpolation of the lattice values L[i mod 16, j mod 16, k mod 16] round p (in cells)
//   S(p) = sum_{i<k} 2^-i n(2 2^i p + o_i) / sum_{i<k} 2^-i      (k octaves, o_i an offset of each octave's own)
//   lattice bytes: 16^3 x 4 however many octaves; one lattice an octave: sum_{i<k} (2 2^i + 1)^3 x 4
//   solid: (s, t, r) = (p + 1) / 2 for the surface point p;  wrapped: (s, t) = (lambda / 2 pi, phi / pi + 1/2)
//   marble period (pixels) = picture width / stripes
//   terrain: cells 4^d, triangles 2 4^d, d = clamp(6 - round(log2 distance), 1, 6); displacement s^H r at side s
//
// What the GL does, all in common/gl/render.cpp (Renderer::texture and Renderer::draw of the frame's batches):
//   glBindTexture(GL_TEXTURE_3D, tex);
//   glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 64, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, slices);
//   glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER / MAG_FILTER, GL_LINEAR);   the trilinear filter
//   glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S / _T / _R, GL_CLAMP_TO_EDGE);
//   glEnable(GL_TEXTURE_3D);
//   glBegin(GL_TRIANGLES); glTexCoord4f(s, t, r, 1); glVertex3f(x, y, z); ... glEnd();
// The solid texture is a GL_TEXTURE_3D (TextureDesc::depth) rather than noise computed per pixel: the fixed
// function has no per-pixel program, and 64^3 texels computed once make every later frame one lookup a pixel;
// the coordinate is per vertex, and exact, since (s, t, r) is affine in the position across a flat triangle.
// Listings: book_figures/procedural_texture_solid.gl.txt, procedural_texture_marble.gl.txt,
// procedural_texture_terrain.gl.txt.
//
// Measured (measure()): the sphere alone rendered offscreen (256 x 256) with each texture, the seam's step read
// back; the marble plane rendered at a pixel a texel, its period by autocorrelation; the lattices' and the 3D
// texture's bytes counted from what was allocated; the terrain's triangles counted from its batch at every depth,
// and H fitted from the variogram of a 513 x 513 field.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/gl/render.hpp"
#include "demos/procedural_texture/procedural_texture_textures.hpp"
#include "procedural_texture_math.hpp"
#include "procedural_texture_views.hpp"

namespace {
namespace pr = ts::proc;
constexpr int kMeasurePixels = 256;  // the seam's and the marble's offscreen renders, square
constexpr uint32_t kTerrainSeed = 7;
constexpr int kFitMaxLag = 16;  // the variogram's lags: 1, 2, 4, 8, 16 cells of the 512-cell field

class ProceduralTexture final : public ts::Scene {
 public:
  std::string id() const override { return "procedural_texture"; }
  std::string title() const override { return "Procedural textures: solid noise, marble, fractal terrain"; }
  std::string about() const override {
    return "A 3D texture of lattice noise (an integer hash, trilinear interpolation, octaves summed) carved by a\n"
           "sphere and a cube: no seam, where the same noise as a 2D image wrapped round a sphere jumps at u = 0 = 1\n"
           "(measured across the meridian).  Views: marble (sin of x plus turbulence; the stripes' period by\n"
           "autocorrelation), a fractal terrain by diamond-square, its depth chosen by the distance (triangles\n"
           "counted; roughness exponent H fitted from the field's variogram).";
  }
  std::vector<std::string> claim() const override {
    if (view_ == 1) return {"marble_period_px*"};
    if (view_ == 2) return {"terrain_triangles*", "terrain_H_fit"};
    return {"solid_seam_levels*", "lattice_bytes*"};
  }
  void addOptions(ts::Options& o) override {
    o.addEnum("view", &view_, {"solid", "marble", "terrain"},
              "a sphere and a cube of solid noise | marble | a fractal terrain by midpoint displacement", 'v');
    o.addInt("octaves", &octaves_, 1, pr::kMaxOctaves, "octaves of noise summed", 'o', 'O');
    o.addInt("stripes", &stripes_, 1, 32, "marble's stripes across the block", 's', 'S');
    o.addInt("turbulence", &turbulence_, 0, 300, "marble's turbulence weight, percent of a period", 't', 'T', 10);
    o.addFloat("distance", &distance_, 1.0f, 32.0f, "the terrain's distance; its depth follows", 'd', 'D', 1.0f);
    o.addFloat("roughness", &roughness_, 0.1f, 0.9f, "the terrain's exponent H (displacement s^H)", 'r', 'R', 0.1f);
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {{"procedural_texture_solid",
             "Solid noise (seed 001)",
             "A 64^3 GL_TEXTURE_3D of lattice noise, five octaves, carved by a sphere and a cube (the texture "
             "coordinate is the surface point), and the same noise as a 2D image wrapped round a sphere, its seam "
             "(u = 0 = 1) facing the camera.",
             {"--view", "solid", "--octaves", "5"},
             960,
             440,
             "Across the meridian the solid sphere steps {solid_seam_levels[solid]} levels more than beside it, the "
             "wrapped image {solid_seam_levels[wrapped_2d]}."},
            {"procedural_texture_marble",
             "Marble from noise (seed 001)",
             "Marble, 1/2 + 1/2 sin(2 pi (stripes x + a turbulence)): stripes bent by turbulence, the plain stripes, "
             "and the same function as a 3D texture carved by a sphere.",
             {"--view", "marble"},
             960,
             440,
             "The marble's period by autocorrelation: {marble_period_px[measured]} pixels, the formula's "
             "{marble_period_px[formula]}."},
            {"procedural_texture_terrain",
             "Fractal terrain (Rogers, seed 004)",
             "A terrain by recursive random midpoint displacement (diamond-square), its depth chosen by the distance: "
             "one level less each time the distance doubles.",
             {"--view", "terrain", "--distance", "2"},
             960,
             440,
             "Triangles counted: {terrain_triangles[shown]}; roughness exponent fitted {terrain_H_fit} for H "
             "{terrain_H}."}};
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;

 private:
  void measureSolid(ts::Renderer& r, ts::Measurements& out) const;
  void measureMarble(ts::Renderer& r, ts::Measurements& out) const;
  void measureTerrain(ts::Measurements& out) const;
  int view_ = 0, octaves_ = 4, stripes_ = 6, turbulence_ = 60;
  float distance_ = 2.0f, roughness_ = 0.5f;
};

ts::Frame ProceduralTexture::build(int width, int height, const ts::Measurements& last) const {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(width, height);
  // The window draws with the last measurement until the next one ends: after the view key it is another view's,
  // whose numbers this view does not print ("(measuring)" until its own arrive).
  static const char* const kViewsOwn[] = {"solid_texture_bytes", "marble_plane_px", "terrain_H"};
  const bool ours = std::any_of(last.begin(), last.end(),
                                [&](const ts::Measurement& m) { return m.name == kViewsOwn[view_]; });
  const ts::Measurements none;
  const ts::Measurements& measured = ours ? last : none;
  auto M = [&](const std::string& templ) { return L::measuredText(measured, templ); };
  const L::Text oct = L::given("octaves", octaves_, "%.0f");
  if (view_ == 0) {
    const int solid = f.addTexture(pr::solidTexture(0, octaves_, stripes_, turbulence_));
    const int flat = f.addTexture(pr::noise2DTexture(octaves_));
    auto sphere = [&](const std::string& id, int tex, bool isSolid) {
      return [=](ts::Frame& fr, const ts::Rect& r) {
        ts::Panel p = pr::objectPanel(id, r, glm::mat4(1.0f), pr::kObjectRadius);
        p.batches.push_back(pr::sphereBatch(tex, isSolid));
        p.batches.push_back(pr::seamTicks());
        fr.panels.push_back(p);
      };
    };
    auto cube = [=](ts::Frame& fr, const ts::Rect& r) {
      ts::Panel p = pr::objectPanel("solid_cube", r, pr::cubeTurn(), pr::kObjectRadius);
      p.batches.push_back(pr::cubeBatch(solid));
      fr.panels.push_back(p);
    };
    pr::pictureRow(
        f,
        {{sphere("solid_sphere", solid, true), "solid: (s,t,r) = the point",
          M("seam {solid_seam_levels[solid]|%.1f} levels")},
         {cube, "the cube, the same block",
          oct + " octaves, " + L::given("3D texture's texels a side", pr::kSolidTexels, "%.0f") + "^3 texels"},
         {sphere("wrapped_sphere", flat, false), "2D image: (u,v) = longitude, latitude",
          M("seam {solid_seam_levels[wrapped_2d]|%.1f} levels")}},
        {{pr::kSeamMark, "the meridian u = 0 = 1, where the 2D image meets itself"}},
        M("Step across the meridian less the step beside it: solid {solid_seam_levels[solid]|%.1f}, wrapped 2D "
          "{solid_seam_levels[wrapped_2d]|%.1f} levels (8-bit).  ") +
            "Lattice for " + oct +
            M(" octaves: {lattice_bytes[octaves=" + std::to_string(octaves_) +
              "]|%.0f} bytes reused, {lattice_bytes_per_level[octaves=" + std::to_string(octaves_) +
              "]|%.0f} with one an octave; the 3D texture {solid_texture_bytes|%.0f} bytes."));
  } else if (view_ == 1) {
    const int bent = f.addTexture(pr::marblePlaneTexture(stripes_, turbulence_, octaves_));
    const int plain = f.addTexture(pr::marblePlaneTexture(stripes_, 0, octaves_));
    const int solid = f.addTexture(pr::solidTexture(1, octaves_, stripes_, turbulence_));
    auto plane = [](const std::string& id, int tex) {
      return [=](ts::Frame& fr, const ts::Rect& r) { fr.panels.push_back(L::texturePanel(id, r, tex, "marble")); };
    };
    auto sphere = [=](ts::Frame& fr, const ts::Rect& r) {
      ts::Panel p = pr::objectPanel("marble_sphere", r, glm::mat4(1.0f), pr::kObjectRadius);
      p.batches.push_back(pr::sphereBatch(solid, true));
      fr.panels.push_back(p);
    };
    pr::pictureRow(
        f,
        {{plane("marble_bent", bent), "turbulence " + L::given("turbulence, percent", turbulence_, "%.0f") + "%",
          M("period {marble_period_px[measured]|%.1f} px")},
         {plane("marble_plain", plain), "no turbulence", M("period {marble_period_px[plain]|%.1f} px")},
         {sphere, "the same marble, solid", "carved by a sphere"}},
        {},
        "M = 1/2 + 1/2 sin(2 pi (" + L::given("stripes", stripes_, "%.0f") +
            M(" x + a T(p))): the formula's period {marble_period_px[formula]|%.1f} pixels of the "
              "{marble_plane_px|%.0f}-pixel plane; by autocorrelation of the render {marble_period_px[measured]|%.1f} "
              "with turbulence, {marble_period_px[plain]|%.1f} without."));
  } else {
    std::vector<pr::Picture> ps;
    for (int k = 0; k < 3; ++k) {
      const double dist = double(distance_) * (1 << k);
      const int depth = pr::depthForDistance(dist);
      const std::string id = "terrain_" + std::to_string(k);
      const double H = roughness_;
      ps.push_back({[=](ts::Frame& fr, const ts::Rect& r) {
                      ts::Panel p = pr::terrainPanel(id, r, dist);
                      p.batches.push_back(pr::terrainBatch(pr::diamondSquare(depth, H, kTerrainSeed), H));
                      fr.panels.push_back(p);
                    },
                    "distance " + L::given("distance", dist, "%.0f") + ": depth " + L::given("depth", depth, "%.0f"),
                    M("{terrain_triangles[depth=" + std::to_string(depth) + "]|%.0f} triangles")});
    }
    pr::pictureRow(
        f, ps,
        {{pr::kLow, "the lowest ground"},
         {pr::kMid, "the middle heights"},
         {pr::kHigh, "the highest (each triangle shaded by the light's cosine)"}},
        M("Triangles counted 2 x 4^d: depth 1 {terrain_triangles[depth=1]|%.0f}, 2 {terrain_triangles[depth=2]|%.0f}, "
          "3 {terrain_triangles[depth=3]|%.0f}, 4 {terrain_triangles[depth=4]|%.0f}, 5 "
          "{terrain_triangles[depth=5]|%.0f}, 6 {terrain_triangles[depth=6]|%.0f}.  ") +
            M("Roughness sqrt(E[(h(x+r) - h(x))^2]) ~ r^H: fitted {terrain_H_fit|%.2f} for H {terrain_H|%.2f} "
              "(lags 1 to {terrain_fit_max_lag|%.0f} of a {terrain_fit_cells|%.0f}-cell field)."));
  }
  return f;
}

ts::Measurements ProceduralTexture::measure(ts::Renderer& r) {
  ts::Measurements out;
  if (view_ == 0) measureSolid(r, out);
  else if (view_ == 1) measureMarble(r, out);
  else measureTerrain(out);
  return out;
}

// The sphere alone, solid and wrapped, its seam's step read back; the bytes counted from what was allocated.
void ProceduralTexture::measureSolid(ts::Renderer& r, ts::Measurements& out) const {
  const int n = kMeasurePixels;
  for (bool solid : {true, false}) {
    ts::Frame f;
    f.width = f.height = n;
    const int tex = f.addTexture(solid ? pr::solidTexture(0, octaves_, stripes_, turbulence_)
                                       : pr::noise2DTexture(octaves_));
    ts::Panel p = pr::objectPanel("sphere", {0, 0, n, n}, glm::mat4(1.0f), pr::kObjectRadius);
    p.batches.push_back(pr::sphereBatch(tex, solid));
    f.panels.push_back(p);
    const pr::Seam s = pr::seamOf(r.renderOffscreen(f), {0, 0, n, n}, pr::kObjectRadius);
    const std::string key = solid ? "solid" : "wrapped_2d";
    out.push_back({"solid_seam_levels[" + key + "]", s.excess(),
                   "8-bit levels: the mean step across the meridian facing the camera (pixels 3 apart) less the same "
                   "step beside it"});
    out.push_back({"solid_seam_across_levels[" + key + "]", s.across, "the mean step across the meridian alone"});
    out.push_back({"solid_seam_control_levels[" + key + "]", s.control,
                   "the mean step at columns 8, 16 and 24 pixels either side (the noise's own change)"});
  }
  for (int k = 1; k <= pr::kMaxOctaves; ++k) {
    out.push_back({"lattice_bytes[octaves=" + std::to_string(k) + "]", double(pr::latticeBytesReused(k)),
                   "bytes of lattice values: one 16^3 lattice of floats reused by every octave"});
    out.push_back({"lattice_bytes_per_level[octaves=" + std::to_string(k) + "]", double(pr::latticeBytesPerLevel(k)),
                   "the same with a lattice of its own for each octave, covering the block without repeating"});
  }
  const ts::TextureDesc t = pr::solidTexture(0, octaves_, stripes_, turbulence_);
  out.push_back({"solid_texture_bytes", double(t.image->pixels.size()), "bytes of the 64^3 RGBA8 3D texture's texels"});
}

// The two marble planes at a pixel a texel, their stripes' period by autocorrelation of the render.
void ProceduralTexture::measureMarble(ts::Renderer& r, ts::Measurements& out) const {
  const int n = kMeasurePixels;
  for (bool plain : {false, true}) {
    const int a = plain ? 0 : turbulence_;
    ts::Frame f;
    f.width = f.height = n;
    const int tex = f.addTexture(pr::marblePlaneTexture(stripes_, a, octaves_));
    f.panels.push_back(ts::layout::texturePanel("marble", {0, 0, n, n}, tex));
    out.push_back({plain ? "marble_period_px[plain]" : "marble_period_px[measured]",
                   pr::stripePeriod(r.renderOffscreen(f), {0, 0, n, n}),
                   plain ? "pixels: the plain stripes' (no turbulence) period, autocorrelation of the render"
                         : "pixels: the marble's period, the first peak of the render's autocorrelation along x"});
  }
  out.push_back({"marble_period_px[formula]", double(n) / stripes_, "pixels: the plane's width / stripes"});
  out.push_back({"marble_plane_px", double(n), "pixels across the measured plane (a texel a pixel)"});
}

// Triangles counted from the batch at every depth; H fitted from the deepest field's variogram.
void ProceduralTexture::measureTerrain(ts::Measurements& out) const {
  for (int d = 1; d <= pr::kTerrainShownMaxDepth; ++d) {
    ts::Panel p;
    p.batches.push_back(pr::terrainBatch(pr::diamondSquare(d, roughness_, kTerrainSeed), roughness_));
    out.push_back({"terrain_triangles[depth=" + std::to_string(d) + "]", double(pr::triangles(p)),
                   "triangles in the terrain's batch at this depth (vertices / 3)"});
  }
  const int shown = pr::depthForDistance(distance_);
  out.push_back({"terrain_depth", double(shown), "the depth the distance chose"});
  out.push_back({"terrain_triangles[shown]", out[size_t(shown - 1)].value, "triangles at the chosen depth"});
  const pr::HeightField field = pr::diamondSquare(pr::kTerrainMaxDepth, roughness_, kTerrainSeed);
  out.push_back({"terrain_H_fit", pr::fittedH(field, kFitMaxLag),
                 "the slope of (1/2) log variogram against log lag, lags 1..16, from the generated field"});
  out.push_back({"terrain_H", double(roughness_), "the displacement's exponent H (--roughness)"});
  out.push_back({"terrain_fit_max_lag", double(kFitMaxLag), "the largest lag fitted, cells"});
  out.push_back({"terrain_fit_cells", double(field.n), "cells a side of the fitted field"});
}
}  // namespace

TS_REGISTER_SCENE(ProceduralTexture);
