// Environment mapping: one world in four parameterizations, and where each
// one is wrong (Buss VI.3; seeds 001, 002).
//
// The claim: a mirror-like object shows the world in the direction of the
// reflected ray, r = v - 2 (v.n) n (Buss VI.3; v from the eye to the surface,
// n the unit normal), and an environment map is a table of the world by
// direction.  How the table is laid out decides where the picture is wrong:
//   lat-long (Blinn–Newell)  s = λ/2π + 1/2, t = φ/π + 1/2: a seam where λ
//       wraps and whole rows of texels at the poles
//   cube map (GL_TEXTURE_CUBE_MAP)  face = the largest |r_i|, (s, t) from the
//       other two over it (environment_mapping_math.hpp has the spec's table); texels 3√3
//       times larger in solid angle at a face's centre than at its corners
//   sphere map (GL_SPHERE_MAP)  m = 2 sqrt(r_x^2 + r_y^2 + (r_z + 1)^2),
//       s = r_x/m + 1/2: made for one eye; the whole back is squeezed into its rim
//   dual paraboloid  s = r_x / (2 (1 + |r_z|)) + 1/2 on two discs: no seam
//       inside a disc, a ring where they meet
// and whether r is computed per vertex, (s,t,r) then interpolated, or per pixel.  The
// world (environment_mapping_math.hpp) is made so any direction can be read: colour = direction, lines
// every 15°, the six cube faces named.  Measured against the exact r per pixel: the
// direction error in degrees of every parameterization x per vertex/pixel for the object
// shown, and where it is largest (environment_mapping_measure.hpp); texels per steradian, largest /
// smallest, at equal memory; a sphere map reused as the eye turns; seed 001's cube example
// read back; seed 002's u = N_x/2 + 1/2 against GL_SPHERE_MAP and its R = 2 N_z N - I
// against r off the view axis; the flat mirror that cannot show a nearby ball; lat-long's seam
// per vertex as computed and with the sources' +1 rule (a triangle whose s differ by more than 1/2
// adds 1 to the smaller: 0.97, 0.02 -> 0.97, 1.02, GL_REPEAT), within 30° of the seam and at the poles.
//
// What the GL does (environment_mapping_gl.hpp: EnvGL::draw, into a float FBO read back for the measurements; the
// figures' pictures are the same passes as ts::Frames nested in the figure, environment_mapping_views.hpp): the mesh as
// glNormal3f + glVertex3f, no glTexCoord.  Cube and sphere maps per vertex are fixed
// function: glTexGeni(GL_S/T/R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP or GL_SPHERE_MAP)
// and glEnable(GL_TEXTURE_GEN_S/T/R) make r from the normal and the modelview; the rest
// is a GLSL program, r = reflect(...) per vertex or per pixel, then texture(mapCube, r)
// or texture(map2d, st).  Listings: book_figures/env_cube_sphere.gl.txt (and the other
// env_*.gl.txt: each picture's pass, then the frame).
//
// Keys (each is also a flag, see --help):
//   p  parameterization        o  object: sphere | torus | mirror
//   e  evaluate r per pixel | per vertex      v  view: object | map | compare
//   ] / [  turn the object     . / ,  tilt it (also the arrows)
//   left drag, wheel: the eye orbits, zooms   s  sphere map made for: this eye | the first eye
//   + / -  memory (texels a cube face side; the others as many texels)
//   u  lat-long per vertex: s as computed | the +1 rule across the seam (then (s, t) are computed per
//      triangle corner and sent by glTexCoord2f: a vertex shader sees one vertex, the rule needs three)
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <thread>

#include "common/gl/gl_listing.hpp"
#include "common/core/layout.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "environment_mapping_gl.hpp"
#include "environment_mapping_measure.hpp"
#include "environment_mapping_studies.hpp"
#include "environment_mapping_math.hpp"
#include "environment_mapping_views.hpp"

namespace {
using ts::layout::fmt, ts::layout::kAmber, ts::layout::kWhite;
enum View { kObjectView, kMapView, kCompareView, kSeamView };
const char* const kEval[] = {"pixel", "vertex"};
const char* const kSeamRules[] = {"none", "plus_one"};
using envmap::Found;  // what measure() found (environment_mapping_studies.hpp)
class EnvironmentMapping final : public ts::Scene {
 public:
  std::string id() const override { return "environment_mapping"; }
  std::string title() const override { return "Environment mapping: four parameterizations (Buss VI.3)"; }
  std::string about() const override {
    return "A mirror sphere, torus or flat mirror reflecting one legible world (colour = direction, 15-degree grid,\n"
           "cube faces named) stored as a lat-long map, a cube map (GL_REFLECTION_MAP texgen), a sphere map\n"
           "(GL_SPHERE_MAP texgen) and a dual paraboloid (GLSL), at equal memory, r per vertex or per pixel.\n"
           "Measured against the exact reflection per pixel: direction error in degrees and where it concentrates;\n"
           "texels per steradian; a sphere map reused as the eye "
           "turns; seed 001's cube example; seed 002's sphere and\n"
           "cube formulas off the view axis; a ball near the flat mirror that no environment map can show.";
  }
  int defaultWidth() const override { return 1080; }
  int defaultHeight() const override { return 440; }
  std::vector<std::string> claim() const override { return {"error_mean_deg[shown]", "error_max_deg[shown]"}; }
  void addOptions(ts::Options& o) override {
    std::vector<std::string> params(envmap::kParamKeys, envmap::kParamKeys + 4);
    o.addEnum("param", &param_, params, "how the world is stored: latlong | cube | sphere | paraboloid", 'p');
    o.addEnum("object", &object_, {"sphere", "torus", "mirror"}, "the mirror object", 'o');
    o.addEnum("eval", &eval_, {"pixel", "vertex"},
              "r per pixel (GLSL) or per vertex (texgen / vertex shader), interpolated", 'e');
    o.addEnum("view", &view_, {"object", "map", "compare", "seam"},
              "object: picture | reference | error; map: the unwrapped map, "
              "the texels the object reads lit; compare: the four maps; seam: lat-long per vertex "
              "without and with the +1 rule",
              'v');
    o.addEnum("seam", &seam_, {"none", "plus_one"},
              "lat-long per vertex: s as computed, or the +1 rule (a triangle whose s differ by more than 1/2 "
              "adds 1 to the smaller, GL_REPEAT)",
              'u');
    o.addFloat("turn", &turn_, -180.0f, 180.0f, "turn the object about the vertical, degrees", ']', '[', 15.0f);
    o.addFloat("tilt", &tilt_, -90.0f, 90.0f, "tilt the object about the horizontal, degrees", '.', ',', 15.0f);
    o.addEnum("sphere-eye", &sphereEye_, {"this", "first"},
              "the sphere map is made for this eye, or for the first one (yaw 0, pitch 0) and reused", 's');
    o.addInt("face", &face_, 16, 256, "memory: texels along a cube face's side (6 face^2 texels; the others as many)",
             '+', '-', 16);
    o.addInt("render", &render_, 64, 1024, "side of the rendered pictures in pixels");
    orbit_.addOptions(o);
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {{"env_cube_sphere",
             "Buss VI.3 (seeds 001, 002)",
             "A mirror sphere reflecting the world stored as a cube map, r per vertex by GL_REFLECTION_MAP texgen: "
             "the picture, the exact reflection per pixel, and the direction error "
             "in degrees (black 0, red at half the scale, white at 4 or more).",
             {"--eval", "vertex"},
             1080,
             440,
             "r per vertex, interpolated, through the cube map: {error_mean_deg[shown]} deg mean and "
             "{error_max_deg[shown]} deg largest direction error (r per pixel: {error_mean_deg[cube/sphere/pixel]})."},
            {"env_compare_torus",
             "Buss VI.3 (seed 001)",
             "A torus in the four parameterizations at equal memory (24,576 texels), r per vertex: lat-long tears at "
             "its seam, the sphere map smears toward its rim; the reference is the exact reflection per pixel.",
             {"--view", "compare", "--object", "torus", "--eval", "vertex", "--tilt", "30"},
             1280,
             360,
             "Mean direction error, r per vertex: lat-long {error_mean_deg[latlong/torus/vertex]} deg "
             "({error_region_deg[latlong/torus/vertex@seam]} at its seam), sphere map "
             "{error_mean_deg[sphere/torus/vertex]}, cube {error_mean_deg[cube/torus/vertex]}, paraboloid "
             "{error_mean_deg[paraboloid/torus/vertex]}."},
            {"env_latlong_map",
             "Buss VI.3 (seed 001)",
             "The lat-long map unwrapped, the texels the flat mirror reads lit: a region at the +Y pole, spread along "
             "whole rows and cut in two by the seam at the map's left and right edges.",
             {"--view", "map", "--param", "latlong", "--object", "mirror"},
             1080,
             440,
             "The mirror reads lat-long texels {texel_aspect[latlong@pole]} times longer than wide at the pole "
             "({texel_aspect[latlong@body]} elsewhere); the map's texel solid angles differ "
             "{texel_solid_angle_ratio[latlong]}x."},
            {"env_cube_map",
             "Buss VI.3 (seed 001)",
             "The cube map's six faces as GL stores them (s right, t down), the texels the flat mirror reads lit: one "
             "small patch of +Y, magnified across the whole mirror, texels visible.",
             {"--view", "map", "--param", "cube", "--object", "mirror"},
             1080,
             440,
             "Cube-map texels stay near square ({texel_aspect[cube@face]} on a face) and differ in solid angle at "
             "most {texel_solid_angle_ratio[cube]}x (lat-long: {texel_solid_angle_ratio[latlong]}x)."},
            {"env_flat_mirror",
             "Buss VI.3 (seed 001)",
             "A flat mirror leaning back 35 degrees, lat-long with r per vertex: the seam runs across it, and a ball "
             "near the mirror (red in the reference) is in no environment map; one made at the mirror's centre would "
             "show it many times too large.",
             {"--object", "mirror", "--param", "latlong", "--eval", "vertex"},
             1080,
             440,
             "Lat-long, r per vertex, across the seam: {error_mean_deg[shown]} deg mean, {error_max_deg[shown]} deg "
             "largest error; a map made at the centre shows the near ball at {mirror_ball_pixels_centre_map[shown]} "
             "pixels of the picture, not {mirror_ball_pixels[shown]}."},
            {"env_latlong_seam_fix",
             "Buss VI.3 (seed 001)",
             "The torus in lat-long with r per vertex, before and after the +1 rule: a triangle whose corners' s "
             "differ by more than 1/2 adds 1 to the smaller (0.97 and 0.02 become 0.97 and 1.02; GL_REPEAT wraps "
             "it). The tear along the seam is gone; at the poles, where longitude means nothing, the error stays.",
             {"--view", "seam", "--object", "torus", "--param", "latlong", "--eval", "vertex", "--tilt", "30"},
             1280,
             440,
             "Within 30 deg of the seam, r per vertex: {latlong_seam_error_deg[none]} deg mean error as computed, "
             "{latlong_seam_error_deg[plus_one]} with the +1 rule; at the poles {latlong_pole_error_deg[none]} and "
             "{latlong_pole_error_deg[plus_one]}: the rule does not mend them."}};
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;

 private:
  envmap::Pass pass(int param, int object, bool perVertex, bool directions, int size) const {
    envmap::Pass p;
    p.param = param, p.object = object, p.perVertex = perVertex, p.directions = directions;
    p.view = envmap::viewMatrix(orbit_.yaw, orbit_.pitch);
    p.projection = envmap::projectionMatrix(orbit_.zoom * envmap::objectLens(object));
    // No texture coordinates: view * model becomes glLoadMatrixf(GL_MODELVIEW) in EnvGL::draw, r comes from it.
    p.model = glm::rotate(glm::mat4(1.0f), glm::radians(tilt_), glm::vec3(1, 0, 0)) *
              glm::rotate(glm::mat4(1.0f), glm::radians(turn_), glm::vec3(0, 1, 0));
    p.sphereView = glm::dmat3(glm::mat3(sphereEye_ ? envmap::viewMatrix(0, 0) : p.view));
    p.faceTexels = face_, p.w = p.h = size;
    p.seamRule = seam_ == 1 && param == envmap::kLatLong && perVertex ? 1 : -1;
    return p;
  }
  // The mirror's is the exact world; the others read a fine cube map (environment_mapping_views.hpp).
  ts::layout::Text refCaption() const {
    if (object_ == envmap::kMirror) return "reference: exact r per pixel";
    return "reference: exact r, cube map " +
           ts::layout::given("reference cube map: texels along a face's side", envmap::kReferenceFace, "%.0f");
  }
  // The measurement table's key of `param` for the shown object and evaluation ("latlong/torus/vertex").
  std::string tableKey(int param) const {
    return std::string(envmap::kParamKeys[param]) + "/" + envmap::kObjectKeys[object_] + "/" + kEval[eval_];
  }
  std::string stateName(int param) const {
    return std::string(envmap::kParamLabels[param]) + ", r per " + kEval[eval_] +
           (eval_ == 1 && param == envmap::kCube     ? " (GL_REFLECTION_MAP)"
            : eval_ == 1 && param == envmap::kSphere ? " (GL_SPHERE_MAP)"
                                                     : "");
  }
  int param_ = envmap::kCube, object_ = envmap::kSphereObject, eval_ = 0, view_ = kObjectView, sphereEye_ = 0;
  int face_ = 64, render_ = 320, seam_ = 0;
  ts::Measurements studies_;  // addStudies' numbers for the map size studiesFace_ (0: none yet)
  int studiesFace_ = 0;
  float turn_ = 0, tilt_ = 0;
  ts::OrbitCamera orbit_;
};

ts::TextureDesc image(const ts::Image& img, const std::string& what, ts::gl::CallList gl = nullptr) {
  ts::TextureDesc t = ts::renderedImageTexture(img, "environment_mapping_render", what, "environment_mapping");
  t.minFilter = t.magFilter = GL_LINEAR;
  t.renderedBy = std::move(gl);
  return t;
}
// The shown state's error, as measured (measure() names it [shown]).
std::vector<ts::layout::Text> statsLine(const ts::Measurements& m, const envmap::ErrorStats& s) {
  namespace L = ts::layout;
  return {L::measuredText(m, "error mean {error_mean_deg[shown]|%.2f},"),
          L::given("percentile", 95, "%g") + L::measuredText(m, "% {error_p95_deg[shown]|%.2f},"),
          L::measuredText(m, "max {error_max_deg[shown]|%.1f} deg") + " (" + s.maxRegion + ")"};
}
// The error picture's key: the heat scale's colours at 0, half and the whole of the scale.
std::vector<ts::LegendEntry> heatKey(double scaleDeg) {
  auto c = [&](double e) { return glm::vec4(glm::vec3(envmap::heat(e, scaleDeg)), 1.0f); };
  return {{c(0), "no error"}, {c(0.5 * scaleDeg), "half the scale"}, {c(scaleDeg), "the scale or more"}};
}
// A key in a cell's band: at the largest scale (at most `scale`) at which its widest entry fits; at scale 1
// legend() wraps what a line cannot hold (a narrow window's cell: the band has the lines, keyLinesAt).
void cellKey(ts::Frame& f, ts::layout::Box band, const std::vector<ts::LegendEntry>& entries, int scale) {
  auto entryWidth = [](const ts::LegendEntry& e, int s) {
    return ts::text::height(s) + 4.0f * float(s) + ts::text::width(e.meaning, s);
  };
  float widest = 0;
  for (const ts::LegendEntry& e : entries) widest = std::max(widest, entryWidth(e, 1));
  int s = std::max(1, scale);
  while (s > 1 && widest * float(s) > band.w()) --s;
  ts::layout::legend(f, band, entries, s);
}
const glm::vec4 kNearBall{230 / 255.0f, 40 / 255.0f, 40 / 255.0f, 1.0f};  // painted on the flat mirror's reference
// The key of the world's colours (ts::envmaps::worldColour): its base colour toward +X, +Y and +Z (the
// colours mix between them), and the white of the equator and of the meridian through -Z.
std::vector<ts::LegendEntry> worldKey() {
  auto c = [](glm::dvec3 d) { return glm::vec4(glm::vec3(envmap::directionColour(d)), 1.0f); };
  return {{c({1, 0, 0}), "toward +X"},
          {c({0, 1, 0}), "toward +Y"},
          {c({0, 0, 1}), "toward +Z"},
          {glm::vec4(glm::vec3(envmap::kWhiteLine), 1.0f), "equator, meridian through -Z"}};
}
// Whether `m` has a measurement of this name.
bool has(const ts::Measurements& m, const std::string& name) {
  return std::any_of(m.begin(), m.end(), [&](const ts::Measurement& x) { return x.name == name; });
}

ts::Frame EnvironmentMapping::build(int width, int height, const ts::Measurements& measured) const {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(width, height);
  const Found* found = measured.detailAs<Found>();
  const L::Box area{6, 6, float(width) - 6, float(height) - 6};
  // The object pictures are resampled to the panel with GL_LINEAR: with GL_NEAREST the panel's middle row and
  // column sample exactly between two pixels, where backends round apart.  The map keeps its texels sharp.
  // A cell's title takes the upper line of its band; a key of the picture's colours, when it has one, the lower.
  // The note below is set as phrases: a line breaks between them, never inside one.
  auto show = [&](const L::Cell& c, const std::string& id, const ts::TextureDesc* t, const L::Text& above,
                  const std::vector<L::Text>& below, const std::vector<ts::LegendEntry>& key = {}, int keyLines = 0) {
    if (t && t->image) f.panels.push_back(L::picturePanel(f, id, c.picture, *t));  // a nested frame's picture upright
    // keyLines: the lower lines hold a key (this cell's, or one drawn across cells by the caller).
    const int lower = std::max(keyLines, key.empty() ? 0 : 1);
    const auto [title, keyBand] = lower ? L::keyApart(c.above, c.scale, lower) : std::pair<L::Box, L::Box>{c.above, {}};
    L::caption(f, title, above, kWhite, c.scale);
    if (!key.empty()) cellKey(f, keyBand, key, c.scale);
    if (!below.empty()) L::phrases(f, c.below, below, kAmber, c.scale);
  };
  if (view_ == kCompareView) {
    L::FlowSpec spec;
    spec.n = 5, spec.linesAbove = 1, spec.linesBelow = 2, spec.gap = 8;
    std::vector<L::Cell> cells = L::flow(area, spec);
    for (int k = 0; k < 4; ++k)
      show(cells[size_t(k)], envmap::kParamKeys[k], found ? &found->pictures[size_t(k)] : nullptr,
           std::string(envmap::kParamLabels[k]) +
               (eval_ == 1 && (k == envmap::kCube || k == envmap::kSphere) ? " (texgen)" : ""),
           found ? std::vector<L::Text>{L::measuredText(measured, "mean {error_mean_deg[" + tableKey(k) + "]|%.2f},"),
                                        L::measuredText(measured, "max {error_max_deg[" + tableKey(k) + "]|%.1f} deg")}
                 : std::vector<L::Text>{});
    show(cells[4], "reference", found ? &found->reference : nullptr, refCaption(),
         {std::string("the maps: r per ") + kEval[eval_]});
    return f;
  }
  if (view_ == kSeamView) {
    // Lat-long per vertex without and with the +1 rule: the two pictures, then their errors on one scale.
    L::FlowSpec spec;
    spec.n = 4, spec.linesAbove = 2, spec.linesBelow = 2, spec.gap = 8;
    const double scale = found ? found->seamScale : envmap::errorScale(true, 0);
    const L::Text seamDeg = L::given("the seam's region: degrees of longitude from the seam", 30, "%g"),
                  poleDeg = L::given("the poles' region: degrees of latitude from the equator", 75, "%g");
    const char* const titles[] = {"lat-long per vertex, s as computed", "the +1 rule: s + 1 where s differ > 1/2"};
    std::vector<L::Text> errorTitles;
    std::vector<std::vector<L::Text>> numbers;
    for (int rule = 0; rule < 2; ++rule) {
      const std::string k = kSeamRules[rule];
      errorTitles.push_back(std::string(rule ? "+1 rule" : "as computed") + ": error, white " +
                            L::given("error shown white, degrees (the heat scale's top)", scale, "%g") +
                            " deg or more");
      numbers.push_back(
          found ? std::vector<L::Text>{"within " + seamDeg + " deg of the seam " +
                                           L::measured(measured, "latlong_seam_error_deg[" + k + "]", "%.2f") + " deg,",
                                       "|latitude| > " + poleDeg + " deg " +
                                           L::measured(measured, "latlong_pole_error_deg[" + k + "]", "%.2f") + " deg"}
                : std::vector<L::Text>{});
    }
    // Each title over a key's line; a narrow window wraps the titles and the numbers rather than cut them.
    std::vector<L::Stack> above = {{titles[0]}, {titles[1]}, {errorTitles[0].text}, {errorTitles[1].text}}, below(4);
    for (int rule = 0; rule < 2; ++rule)
      for (const L::Text& t : numbers[size_t(rule)]) below[size_t(2 + rule)].push_back(t.text);
    std::vector<L::Cell> cells = L::flowFitting(area, spec, above, below, 1);
    for (int rule = 0; rule < 2; ++rule) {
      const std::string k = kSeamRules[rule];
      show(cells[size_t(rule)], "seam_" + k, found ? &found->seamPictures[size_t(rule)] : nullptr, titles[rule], {}, {},
           1);
      const ts::TextureDesc errorTex = found ? image(found->seamErrors[size_t(rule)], "seam error " + k)
                                             : ts::TextureDesc{};
      show(cells[size_t(2 + rule)], "seam_error_" + k, found ? &errorTex : nullptr, errorTitles[size_t(rule)],
           numbers[size_t(rule)], {}, 1);
    }
    // One key across the two pictures (the world's colours), one across the two errors (the heat scale).
    auto acrossTwo = [&](size_t first) {
      const L::Cell &a = cells[first], &b = cells[first + 1];
      const float x1 = b.above.y0 == a.above.y0 ? b.above.x1 : a.above.x1;  // side by side, or a's band alone
      return L::Box{a.above.x0, L::lastLineApart(a.above, a.scale).second.y0, x1, a.above.y1};
    };
    cellKey(f, acrossTwo(0), worldKey(), cells[0].scale);
    cellKey(f, acrossTwo(2), heatKey(scale), cells[2].scale);
    return f;
  }
  if (view_ == kMapView) {
    // The same layout for every map (the lat-long and the cube map figures are siblings): the map left with
    // its title and what is lit above it, the texels' shape and solid angles (the figures' claims) below;
    // the picture right; every text at one scale, the smaller of the two cells'.
    const float mid = area.x0 + (area.x1 - area.x0) * 0.62f;
    const envmap::Size sz = envmap::mapSize(envmap::Param(param_), face_);
    // The map's cell is laid out for the widest map (lat-long, 2:1) whichever is shown, and each map is as
    // tall as that one: titles, maps and captions at the same places in every map figure.
    constexpr float kWidestMap = 2.0f;
    L::FlowSpec spec;
    spec.linesAbove = 2, spec.linesBelow = 2, spec.aspect = 1.0f;
    spec.maxScale = L::flow({mid + 6, area.y0, area.x1, area.y1}, spec)[0].scale;
    spec.aspect = kWidestMap;
    L::Cell m = L::flow({area.x0, area.y0, mid - 6, area.y1}, spec)[0];
    const float aspect = std::min(kWidestMap, param_ == envmap::kCube ? 1.5f : float(sz.w) / float(sz.h));
    m.picture = L::centred(m.picture, int(std::lround(float(m.picture.h) * aspect)), m.picture.h);
    spec.aspect = 1.0f;  // the picture: in the rows the map's cell takes, its title beside the map's
    L::Cell p = L::flow({mid + 6, m.above.y0, area.x1, m.below.y1}, spec)[0];
    m.scale = p.scale = std::min(m.scale, p.scale);
    const L::Text texels = found
                               ? L::measured(measured, "texels", "%.0f")
                               : L::given("texels of the map", envmap::mapTexels(envmap::Param(param_), face_), "%.0f");
    if (found) f.panels.push_back(L::picturePanel(f, "map", m.picture, found->map));
    L::caption(f, L::halves(m.above).first,
               std::string(envmap::kParamLabels[param_]) + ", " + texels + " texels" +
                   (param_ == envmap::kCube ? ", faces as GL stores them (t down)" : ""),
               kWhite, m.scale);
    L::caption(f, L::halves(m.above).second,
               std::string("lit: the texels the ") + envmap::kObjectKeys[object_] + " reads; the rest dimmed", kWhite,
               m.scale);
    if (found) {
      envmap::lightTheReadTexels(f.panels.back(), found->lit);
      // The texels the object reads: how much longer than wide, per region of the map it reads them in.
      const std::string key = envmap::kParamKeys[param_];
      std::vector<L::Text> shape;
      for (const ts::Measurement& x : measured)
        if (x.name.rfind("texel_aspect[" + key + "@", 0) == 0) {
          if (!shape.empty()) shape.back() = shape.back() + ",";
          const size_t at = x.name.find('@');
          shape.push_back(x.name.substr(at + 1, x.name.size() - at - 2) + " " + L::measured(measured, x.name, "%.2f"));
        }
      if (!shape.empty()) {
        shape.back() = shape.back() + ";";
        shape.insert(shape.begin(), "texels read, longer / shorter side:");
      }
      shape.push_back("texel solid angles differ " +
                      L::measured(measured, "texel_solid_angle_ratio[" + key + "]", "%.1f") + "x across the map" +
                      (param_ != envmap::kLatLong && has(measured, "texel_solid_angle_ratio[latlong]")
                           ? " (lat-long " + L::measured(measured, "texel_solid_angle_ratio[latlong]", "%.1f") + "x)"
                           : L::Text()));
      L::phrases(f, m.below, shape, kAmber, m.scale);
    }
    show(p, "picture", found ? &found->picture : nullptr, stateName(param_),
         found ? statsLine(measured, found->current) : std::vector<L::Text>{});
    return f;
  }
  // Two lines above each picture: its title, and the key of the colours the reference and the error carry.
  // The near ball's pixels are those painted red on this very picture (measure(): [shown]).
  std::vector<L::Text> refNote;
  if (found && object_ == envmap::kMirror)
    refNote = {L::measuredText(measured, "red: a near ball, {mirror_ball_pixels[shown]|%.0f} px;"),
               L::measuredText(measured, "a map made at the centre: {mirror_ball_pixels_centre_map[shown]|%.0f} px, "
                                         "{mirror_ball_pixels_both[shown]|%.0f} right")};
  // Where the error is worst, and the other evaluation's mean beside it (the figures' claims compare them).
  auto errorNote = [&]() -> std::vector<L::Text> {
    const std::string other = std::string(envmap::kParamKeys[param_]) + "/" + envmap::kObjectKeys[object_] + "/" +
                              kEval[1 - eval_];
    if (!has(measured, "error_mean_deg[" + other + "]")) return {"worst in: " + found->current.maxRegion};
    return {"worst in: " + found->current.maxRegion + ";",
            std::string("r per ") + kEval[1 - eval_] + ": " +
                L::measured(measured, "error_mean_deg[" + other + "]", "%.2f") + " deg mean"};
  };
  const double scale = found ? found->errorScale : envmap::errorScale(eval_ == 1, 0);
  const L::Text errorTitle = "direction error (black " + L::given("error shown black, degrees", 0, "%g") + ", white " +
                             L::given("error shown white, degrees (the heat scale's top)", scale, "%g") +
                             " deg or more)";
  const std::vector<L::Text> notes[3] = {found ? statsLine(measured, found->current) : std::vector<L::Text>{}, refNote,
                                         found ? errorNote() : std::vector<L::Text>{}};
  // Each title over a key's line; a narrow window wraps the titles and the notes rather than cut them.
  std::vector<L::Stack> above = {{stateName(param_)}, {refCaption().text}, {errorTitle.text}}, below(3);
  for (int k = 0; k < 3; ++k) {
    std::string note;
    for (const L::Text& t : notes[k]) note += (note.empty() ? "" : " ") + t.text;
    below[size_t(k)].push_back(note);
  }
  L::FlowSpec spec;
  spec.n = 3, spec.linesAbove = 2, spec.linesBelow = 2, spec.gap = 8;
  // One key for the picture and the reference, under their titles: the world's colours, and the flat
  // mirror's near ball painted on the reference; the error's heat scale under its own.
  std::vector<ts::LegendEntry> key = worldKey();
  if (object_ == envmap::kMirror) key.push_back({kNearBall, "the near ball"});
  const std::vector<ts::LegendEntry> heat = heatKey(scale);
  // The keys' lines at the cells' widths (the world's across the first two cells): one at the figures' sizes;
  // a narrow window lays the cells out again with the lines its keys wrap to, every entry kept.
  auto keyLinesAt = [&](const std::vector<L::Cell>& c) {
    return std::max(L::legendLines(key, 1, c[1].above.x1 - c[0].above.x0), L::legendLines(heat, 1, c[2].above.w()));
  };
  std::vector<L::Cell> cells = L::flowFitting(area, spec, above, below, 1);
  for (int lines = 1, want = keyLinesAt(cells); want > lines && want <= 4; lines = want, want = keyLinesAt(cells))
    cells = L::flowFitting(area, spec, above, below, want);
  const int keyLines = keyLinesAt(cells);
  const L::Box keyBand = L::keyApart(cells[0].above, cells[0].scale, keyLines).second;
  show(cells[0], "picture", found ? &found->picture : nullptr, stateName(param_), notes[0], {}, keyLines);
  show(cells[1], "reference", found ? &found->reference : nullptr, refCaption(), notes[1], {}, keyLines);
  cellKey(f, {cells[0].above.x0, keyBand.y0, cells[1].above.x1, keyBand.y1}, key, cells[0].scale);
  const ts::TextureDesc errorTex = found ? image(found->error, "error") : ts::TextureDesc{};
  show(cells[2], "error", found ? &errorTex : nullptr, errorTitle, notes[2], heat, keyLines);
  return f;
}

ts::Measurements EnvironmentMapping::measure(ts::Renderer& r) {
  envmap::EnvGL& g = r.attachment<envmap::EnvGL>();
  const int kMeasureSize = 256;  // the table: every parameterization x evaluation for this object at 256 x 256
  // The shown state's pictures and their own numbers ([shown]); in a window also first, alone, as a
  // first stage (ts::measureStage): the pictures at once, the table's numbers after them.
  auto shownPictures = [&](Found& found, ts::Measurements& out) {
    // The shown state's pictures: nested frames drawn by GL (their calls recorded for the listings), which the
    // reference recomputes (environment_mapping_views.hpp); the measurements read the float passes.
    const int n = render_;
    envmap::Pixels ref;  // its calls recorded for the mirror's reference picture (the target made again: they show how)
    g.forget(pass(-1, object_, false, true, n));
    const ts::gl::CallList refGL = ts::recordRender(r, [&] { ref = g.draw(pass(-1, object_, false, true, n)); });
    const envmap::Pass shown = pass(param_, object_, eval_ == 1, true, n);
    const envmap::Pixels looked = g.draw(shown);
    std::vector<float> perPixel;
    found.current = envmap::errorStats(param_, looked, ref, shown.eyeRotation(), &perPixel);
    out.insert(out.begin(), {"error_p95_deg[shown]", found.current.p95,
                             "the picture shown: 95th percentile of the direction error, degrees"});
    out.insert(out.begin(),
               {"error_max_deg[shown]", found.current.max, "the picture shown: largest direction error, degrees"});
    out.insert(out.begin(),
               {"error_mean_deg[shown]", found.current.mean, "the picture shown: mean direction error, degrees"});
    auto picture = [&](int p) {
      return envmap::nestedTexture(r, envmap::passFrame(pass(p, object_, eval_ == 1, false, n)), stateName(p));
    };
    found.picture = picture(param_);
    found.errorScale = envmap::errorScale(eval_ == 1, found.current.p95);
    found.error = envmap::errorImage(perPixel, n, n, found.errorScale);
    found.map = ts::envmaps::unwrappedMap(envmap::Param(param_), face_, shown.sphereView);
    found.lit = envmap::litTexels(param_, face_, shown.sphereView, looked);
    if (view_ == kCompareView)
      for (int p = 0; p < 4; ++p) found.pictures[size_t(p)] = picture(p);
    if (view_ == kSeamView)
      for (int rule = 0; rule < 2; ++rule) {
        envmap::Pass ps = pass(envmap::kLatLong, object_, true, true, n);
        ps.seamRule = rule;
        std::vector<float> e;
        const envmap::ErrorStats s = envmap::errorStats(envmap::kLatLong, g.draw(ps), ref, ps.eyeRotation(), &e);
        if (rule == 0) found.seamScale = envmap::errorScale(true, s.p95);
        found.seamErrors[size_t(rule)] = envmap::errorImage(e, n, n, found.seamScale);
        ps.directions = false;
        found.seamPictures[size_t(rule)] = envmap::nestedTexture(r, envmap::passFrame(ps),
                                                                 std::string("lat-long per vertex, ") +
                                                                     kSeamRules[rule]);
      }
    if (object_ == envmap::kMirror) {  // the flat mirror: where a nearby ball should appear (red in the reference)
      const envmap::Pass ps = pass(-1, object_, false, true, n);
      found.mirror = envmap::mirrorNear(ref, ps.projection, ps.view, ps.model);
      ts::Image painted = envmap::referenceImage(ref);
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          if (found.mirror.trueMask[size_t(y) * size_t(n) + size_t(x)])
            painted.set(x, n - 1 - y, envmap::toRgba(glm::dvec3(kNearBall)));
      found.reference = image(painted, "reference", refGL);
      // The picture's own counts (render_ x render_ pixels), which its caption prints: the table's
      // mirror_ball_pixels* come from addStudies' pass at the measuring size.
      out.push_back({"mirror_ball_pixels[shown]", double(found.mirror.truePixels),
                     "pixels of the shown reference picture painted red: the near ball in a true mirror"});
      out.push_back({"mirror_ball_pixels_centre_map[shown]", double(found.mirror.mapPixels),
                     "pixels of the shown picture where a map made at the mirror's centre, ball included, shows it"});
      out.push_back({"mirror_ball_pixels_both[shown]", double(found.mirror.both),
                     "pixels of the shown picture where both show it"});
    } else {
      found.reference = envmap::nestedTexture(r, envmap::referenceFrame(pass(-1, object_, false, false, n)),
                                              "reference");
    }
  };
  // In a window: the solid-angle studies (arithmetic only, a third of a
  // measurement's CPU) on another thread while this one has GL draw; joined
  // before addStudies reads them (kept: envmap::keptUniformity), or on a cancel.
  std::thread studies;
  struct Join {
    std::thread& t;
    ~Join() {
      if (t.joinable()) t.join();
    }
  } joinStudies{studies};
  // The first stage's pictures and [shown] numbers are the result's too: kept, not drawn again.
  std::unique_ptr<Found> first;
  ts::Measurements shownNumbers;
  if (ts::measureStaged()) {
    const int face = face_;
    if (studiesFace_ != face)  // not yet measured at this size
      studies = std::thread([face] {
        for (int p = 0; p < envmap::kParams; ++p) envmap::keptUniformity(envmap::Param(p), face);
      });
    first = std::make_unique<Found>();
    shownPictures(*first, shownNumbers);  // not shown before the table's: the stage's labels say "(measuring)"
    ts::Measurements stage;
    stage.detail = *first;
    ts::measureStage(std::move(stage));
  }
  ts::Measurements out;
  Found found;
  if (first) found = *first;  // the table below fills found.compare, which shownPictures leaves alone
  for (int o = object_; o == object_; ++o) {
    const envmap::Pixels ref = g.draw(pass(-1, o, false, true, kMeasureSize));
    for (int p = 0; p < envmap::kParams; ++p)
      for (int e = 0; e < 2; ++e) {
        const envmap::Pass ps = pass(p, o, e == 1, true, kMeasureSize);
        const envmap::ErrorStats s = envmap::errorStats(p, g.draw(ps), ref, ps.eyeRotation());
        const std::string key = std::string(envmap::kParamKeys[p]) + "/" + envmap::kObjectKeys[o] + "/" + kEval[e];
        out.push_back({"error_mean_deg[" + key + "]", s.mean, "mean direction error against the exact r, degrees"});
        out.push_back({"error_p95_deg[" + key + "]", s.p95, "95th percentile of the direction error, degrees"});
        out.push_back(
            {"error_max_deg[" + key + "]", s.max, "largest direction error, degrees, in region " + s.maxRegion});
        for (const auto& [region, mean] : s.regionMean)
          out.push_back(
              {"error_region_deg[" + key + "@" + region + "]", mean,
               fmt("mean error in this region of the map, degrees (%.0f pixels)", s.regionPixels.at(region))});
        if (o == object_ && e == eval_) found.compare[size_t(p)] = s;
      }
    for (int p = 0; p < envmap::kParams; ++p) {
      const envmap::Pass ps = pass(p, o, false, true, kMeasureSize);
      for (const auto& [region, t] : envmap::texelShape(p, face_, ref, ps.sphereView, ps.eyeRotation())) {
        const std::string k = std::string(envmap::kParamKeys[p]) + "@" + region;
        out.push_back({"texel_extent_deg[" + k + "]", t.extentDeg,
                       "mean size of the texel read here, degrees along its longer side"});
        out.push_back({"texel_aspect[" + k + "]", t.aspect, "mean longer / shorter side of the texel read here"});
      }
    }
    // Lat-long per vertex as computed and with the +1 rule, in the table's regions and against its reference:
    // measured when the rule or its view is asked for (each state measures what it shows).
    if (seam_ == 1 || view_ == kSeamView)
      for (int rule = 0; rule < 2; ++rule) {
        envmap::Pass ps = pass(envmap::kLatLong, o, true, true, kMeasureSize);
        ps.seamRule = rule;
        const envmap::ErrorStats s = envmap::errorStats(envmap::kLatLong, g.draw(ps), ref, ps.eyeRotation());
        for (const char* region : {"seam", "pole"})
          if (s.regionMean.count(region))
            out.push_back({std::string("latlong_") + region + "_error_deg[" + kSeamRules[rule] + "]",
                           s.regionMean.at(region),
                           std::string("lat-long, r per vertex, (s, t) per triangle corner ") +
                               (rule ? "with the +1 rule" : "as computed") + ": mean direction error in the " + region +
                               " region (seam: within 30 deg of it; pole: |latitude| > 75 deg), degrees"});
      }
    ts::measureProgress(0.4);
  }
  if (first) {  // what shownPictures(found, out) does to `out`: its three numbers first, the mirror's last
    out.insert(out.begin(), shownNumbers.begin(), shownNumbers.begin() + 3);
    out.insert(out.end(), shownNumbers.begin() + 3, shownNumbers.end());
  } else {
    shownPictures(found, out);
  }
  ts::measureProgress(0.6);
  // In a window, every view but the map's is whole now (the studies below
  // print only in the map view's notes and the panel): a second stage.
  if (ts::measureStaged() && view_ != kMapView && studiesFace_ != face_) {
    ts::Measurements shown = out;
    shown.detail = found;
    ts::measureStage(std::move(shown));
  }
  // The seeds' examples, solid angle, the stale sphere map, the near ball:
  // they depend on the map's size alone, so they are measured once per size
  // (a third of the work of each figure, and of each key in a window).
  if (studies.joinable()) studies.join();
  if (studiesFace_ != face_) {
    ts::Measurements kept;
    envmap::addStudies(g, face_, kept);
    studies_ = std::move(kept), studiesFace_ = face_;
  }
  out.insert(out.end(), studies_.begin(), studies_.end());
  out.push_back({"texels", double(envmap::mapTexels(envmap::Param(param_), face_)), "texels of the shown map"});
  out.detail = found;
  return out;
}
}  // namespace

TS_REGISTER_SCENE(EnvironmentMapping);
