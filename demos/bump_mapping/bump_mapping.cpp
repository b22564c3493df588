// Bump mapping on the torus, two lights, measured against the truly
// displaced surface (Buss VI.2, "bump mapping"; seeds 001, 002, 004).
//
// The claim: a bump map changes the normal the lighting sees, not the
// surface.  With a height field P(s, t) (procedural dimples and ridges, or
// bricks) the true surface is Q' = Q + P n; its normal is Q'_s x Q'_t.
// Each method approximates that normal per pixel on the smooth torus of
// Figure VI.6 (demos/torus/torus_map.hpp), lit by two lights (Phong, GLSL):
//   B1  seed 004, Blinn:   n' = n + P_u (n x Q_w)/|n| + P_w (Q_u x n)/|n|
//       (it drops P (n/|n|)_u: exact for small P and flat Q);
//   B2  seed 002, literally: g_x = j(x+1,y) - j(x-1,y), g_y = j(x,y+1) - j(x,y-1),
//       added / 255 to the x and y of the interpolated normal;
//   B3  a tangent-space normal map baked from the same heights;
//   R   the reference: the heights displacing a 1024 x 512 grid.
// Measured (measure()): each method's shading against R (PSNR, mean absolute
// difference over the pixels both cover), the normal error in degrees (a
// render that writes the normal as its colour), which way each method tilts
// the normals against R along the eye's x and y (+1 with it, -1 against),
// and how the tilt answers doubling the height scale and doubling the object
// (seed 004: the normal grows 4x, its perturbation 2x: bumps look half as deep).
//
// Keys (each is also a flag, see --help):
//   m  method: flat | B1 blinn | B2 seed002 | B3 normalmap | R reference
//   v  view: single | compare (the method beside R) | normals (both as colours)
//   t  heights: procedural | bricks (--texture FILE: a picture's luminance)
//   + / -  height scale   s / S  object scale (seed 004's claim)
//   a / A, e / E  light 1 azimuth, elevation   b / B, d / D  light 2   . / ,  tilt
// What the GL does: one GLSL 1.30 program (bump_gl.hpp) for every method,
// the method a uniform; the heights (or the normal map) in texture unit 0.
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <map>
#include <memory>

#include "bump_gl.hpp"
#include "bump_math.hpp"
#include "common/layout.hpp"
#include "common/orbit_camera.hpp"
#include "common/render.hpp"
#include "common/scene.hpp"
#include "common/textures.hpp"
#include "common/user_texture.hpp"
#include "demos/torus/torus_map.hpp"

namespace {
using ts::layout::fmt;
using ts::layout::kAmber;
using ts::layout::kWhite;
const char* const kMethods[] = {"flat", "blinn", "seed002", "normalmap", "reference"};
const char* const kMethodTitles[] = {"flat (no bumps)", "B1 Blinn (seed 004)", "B2 seed 002 literally",
                                     "B3 normal map", "R displaced"};
const int kMethodIds[] = {bump::kFlat, bump::kBlinn, bump::kSeed002, bump::kNormalMap, bump::kReference};
constexpr int kMeasureSize = 480;

// What measure() found: per method its comparison with R, and R's renders.
struct Found {
  std::map<int, bump::Compare> cmp;  // method index -> against R
  std::shared_ptr<const ts::Image> refShaded, refNormals;
};

class BumpMapping final : public ts::Scene {
 public:
  std::string id() const override { return "bump_mapping"; }
  std::string title() const override { return "Bump mapping on the torus (Buss VI.2; seeds 002, 004)"; }
  std::string about() const override {
    return "A torus with dimples and ridges (or bricks), lit by two lights, bump mapped per pixel by Blinn's perturbed\n"
           "normal (seed 004), seed 002's height differences, and a normal map; each measured against the same heights\n"
           "displacing a finely tessellated torus: PSNR, mean difference, normal error in degrees, tilt direction.";
  }
  std::vector<std::string> claim() const override { return {"normal_err_deg*"}; }
  void addOptions(ts::Options& o) override {
    o.addEnum("method", &method_, std::vector<std::string>(kMethods, kMethods + 5),
              "flat | B1 Blinn (seed 004) | B2 seed 002 | B3 normal map | R the displaced reference", 'm');
    o.addEnum("view", &view_, {"single", "compare", "normals"}, "single | compare: the method beside R | normals as colours", 'v');
    o.addEnum("heights", &heights_, {"procedural", "bricks"}, "the height field: dimples and ridges | bricks", 't');
    o.addFloat("height-scale", &heightScale_, 0.0f, 0.12f, "P = scale h: the bumps' height in the torus's units (r = 0.4)", '+', '-', 0.01f);
    o.addFloat("object-scale", &objectScale_, 1.0f, 4.0f, "the torus scaled (R, r and the eye's distance), the bumps not", 's', 'S', 1.0f);
    o.addFloat("light1-az", &light_[0].x, -180.0f, 180.0f, "light 1 azimuth, degrees, 0 = from the eye", 'a', 'A', 15.0f);
    o.addFloat("light1-el", &light_[0].y, -90.0f, 90.0f, "light 1 elevation, degrees", 'e', 'E', 15.0f);
    o.addFloat("light2-az", &light_[1].x, -180.0f, 180.0f, "light 2 azimuth, degrees", 'b', 'B', 15.0f);
    o.addFloat("light2-el", &light_[1].y, -90.0f, 90.0f, "light 2 elevation, degrees", 'd', 'D', 15.0f);
    o.addFloat("tilt", &tilt_, -90.0f, 90.0f, "the eye's height above the torus's plane, degrees", '.', ',', 5.0f);
    camera_.addOptions(o);
    file_.addOption(o, "the built-in heights (its luminance is the height)");
  }
  std::vector<ts::FigureSpec> figures() const override;
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;

 private:
  const bump::Heights& heights() const {
    const std::string want = file_.active() ? file_.path() : heights_ ? "bricks" : "procedural";
    if (!cache_ || cacheKey_ != want) {
      cache_ = std::make_shared<bump::Heights>(file_.active() ? bump::fromImage(file_.image())
                                               : heights_      ? bump::bricks()
                                                               : bump::procedural());
      cacheKey_ = want;
    }
    return *cache_;
  }
  ts::TextureDesc heightTexture() const {
    const bump::Heights& H = heights();
    ts::TextureDesc t;
    t.name = "bump_heights";
    t.params = {{"source", cacheKey_}};
    t.image = std::make_shared<const ts::Image>(bump::heightImage(H));
    t.minFilter = t.magFilter = GL_LINEAR;
    return t;
  }
  ts::TextureDesc normalTexture() const {
    const bump::Heights& H = heights();
    ts::TextureDesc t;
    t.name = "bump_normal_map";
    t.params = {{"source", cacheKey_}, {"height_scale", fmt("%.4f", heightScale_)}, {"baked_for_R", "1"}, {"r", "0.4"}};
    t.image = std::make_shared<const ts::Image>(bump::normalMap(H, 1.0, 0.4, heightScale_));
    t.minFilter = t.magFilter = GL_LINEAR;
    return t;
  }
  glm::vec3 toLight(int k) const {
    float az = glm::radians(light_[k].x), el = glm::radians(light_[k].y);
    return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
  }
  // The torus panel of a method at `vp`; `normals`: the normal render.
  // The torus is the demo's own torus (R = 1, r = 0.4) times the object scale.
  ts::Panel torusPanel(ts::Frame& f, const ts::Rect& vp, int method, bool normals) const;
  // One method's picture alone at the measurement size (no labels).
  ts::Frame single(int method, bool normals) const {
    ts::Frame f = ts::layout::blankFrame(kMeasureSize, kMeasureSize);
    if (normals) f.clearColor = {0.0f, 0.0f, 0.0f, 1.0f};  // "covered" = not black
    f.panels.push_back(torusPanel(f, {0, 0, kMeasureSize, kMeasureSize}, method, normals));
    return f;
  }
  // Method 4 is R, the displaced grid; with `smoothGeometry` it is R's
  // normal on the smooth torus: the best any bump map can do.
  ts::Image renderMethod(ts::Renderer& r, int method, bool normals, bool smoothGeometry = false) const {
    ts::Frame f = single(method, normals);
    return method == 4 && !smoothGeometry ? bump::renderReference(r, f) : r.renderOffscreen(f);
  }

  int method_ = 1, view_ = 1, heights_ = 0;
  float heightScale_ = 0.04f, objectScale_ = 1.0f, tilt_ = 30.0f;
  glm::vec2 light_[2] = {{-45.0f, 40.0f}, {60.0f, -10.0f}};
  ts::OrbitCamera camera_;
  ts::UserTexture file_;
  mutable std::shared_ptr<const bump::Heights> cache_;
  mutable std::string cacheKey_;
};

ts::Panel BumpMapping::torusPanel(ts::Frame& f, const ts::Rect& vp, int method, bool normals) const {
  torusmap::Params tp;
  tp.R = objectScale_, tp.r = 0.4 * objectScale_, tp.nu = 64, tp.nv = 32;
  ts::Panel p;
  p.id = std::string("torus_") + kMethods[method];
  p.viewport = vp;
  p.depthTest = true;
  p.projection = glm::perspective(glm::radians(35.0f), float(vp.w) / float(vp.h), 0.5f * objectScale_, 20.0f * objectScale_);
  p.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -4.8f * objectScale_));
  p.modelview = glm::rotate(p.modelview, glm::radians(tilt_), glm::vec3(1, 0, 0));
  camera_.apply(p);
  const bump::Heights& H = heights();
  ts::Batch b = ts::meshBatch(torusmap::mesh(tp), f.addTexture(method == 3 ? normalTexture() : heightTexture()));
  b.role = "torus";
  b.program = "bump";
  b.uniforms = {{"torus", {float(tp.R), float(tp.r), heightScale_, float(kMethodIds[method])}},
                {"rep", {H.rep.x, H.rep.y, float(H.w), float(H.h)}},
                {"l0", glm::vec4(toLight(0), 0.75f)},
                {"l1", glm::vec4(toLight(1), 0.5f)},
                {"opts", {normals ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f}}};
  if (f.programs.empty()) f.programs.push_back({"bump", bump::meshProgram()});
  p.batches.push_back(b);
  return p;
}

ts::Frame BumpMapping::build(int width, int height, const ts::Measurements& measured) const {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(width, height);
  const Found* found = measured.detailAs<Found>();
  L::FlowSpec spec;
  spec.n = view_ == 0 ? 1 : 2, spec.linesAbove = 1, spec.linesBelow = 2;
  std::vector<L::Cell> cells = L::flow({6, 6, float(width) - 6, float(height) - 6}, spec);
  const bool normals = view_ == 2;
  for (size_t k = 0; k < cells.size(); ++k) {
    const L::Cell& c = cells[k];
    const int m = k == 0 ? method_ : 4;
    const std::string what = std::string(kMethodTitles[m]) + (normals ? ", normals" : "");
    if (m != 4) {
      f.panels.push_back(torusPanel(f, c.picture, m, normals));
    } else if (found && found->refShaded) {
      f.panels.push_back(L::texturePanel("reference", c.picture,
                                         f.addTexture(ts::renderedImageTexture(normals ? *found->refNormals : *found->refShaded,
                                                                               "bump_reference", normals ? "R normals" : "R shaded",
                                                                               "bump_mapping"))));
    } else {
      L::caption(f, L::box(c.picture), "R: measuring...", kWhite, c.scale);
    }
    L::caption(f, c.above, what, kWhite, c.scale);
    auto it = found ? found->cmp.find(m) : std::map<int, bump::Compare>::const_iterator();
    if (found && it != found->cmp.end() && m == 4)
      L::caption(f, c.below,
                 normals ? fmt("R's normals on the smooth torus: %.1f deg off in the same pixel (the geometry's share)",
                               it->second.screenNormalDeg)
                         : fmt("R's own normals on the smooth torus reach %.1f dB against it: the rest is geometry", it->second.psnr),
                 kAmber, c.scale);
    else if (found && it != found->cmp.end() && normals)
      L::caption(f, c.below,
                 fmt("normal off by %.1f deg at the same (s,t)", it->second.normalDeg) +
                     fmt(", %.1f deg in the same pixel", it->second.screenNormalDeg),
                 kAmber, c.scale);
    else if (found && it != found->cmp.end())
      L::caption(f, c.below,
                 fmt("against R: PSNR %.1f dB", it->second.psnr) + fmt(", mean |diff| %.1f", it->second.mad) +
                     fmt(", normal off by %.1f deg", it->second.normalDeg),
                 kAmber, c.scale);

  }
  return f;
}

ts::Measurements BumpMapping::measure(ts::Renderer& r) {
  ts::Measurements out;
  Found found;
  auto refShaded = std::make_shared<ts::Image>(renderMethod(r, 4, false));
  auto refNormals = std::make_shared<ts::Image>(renderMethod(r, 4, true));
  const ts::Image exactNormals = renderMethod(r, 4, true, true), smooth = renderMethod(r, 0, true);
  ts::measureProgress(0.2);
  std::map<int, ts::Image> normals;
  for (int m = 0; m < 5; ++m) {
    const bool ideal = m == 4;
    ts::Image shaded = renderMethod(r, m, false, true);
    normals[m] = m == 0 ? smooth : ideal ? exactNormals : renderMethod(r, m, true);
    bump::Compare c = bump::compare(shaded, normals[m], *refShaded, *refNormals);
    bump::Compare atPoint = bump::compare(shaded, normals[m], shaded, exactNormals);
    found.cmp[m] = c;
    found.cmp[m].screenNormalDeg = c.normalDeg;
    found.cmp[m].normalDeg = atPoint.normalDeg;
    const std::string k = std::string("[") + (ideal ? "ideal" : kMethods[m]) + "]";
    if (!ideal)
      out.push_back({"normal_err_deg" + k, atPoint.normalDeg,
                     "mean angle between the method's normal and the displaced surface's at the same (s,t), degrees"});
    out.push_back({"psnr_db" + k, c.psnr, "shading against R's picture over the pixels both cover, dB"});
    out.push_back({"mad" + k, c.mad, "mean absolute difference from R's picture, 8-bit units"});
    out.push_back({"screen_normal_err_deg" + k, c.normalDeg, "mean angle between the normal and R's in the same pixel, degrees"});
    ts::measureProgress(0.2 + 0.1 * m);
  }
  // Seed 002 adds to the eye's x and y, not along the surface: on the near
  // side of the ring s runs along +x, on the far side along -x.
  const glm::ivec2 rows = bump::coveredRows(smooth);
  const int third = (rows.y - rows.x) / 3;
  for (int m = 1; m < 4; ++m)
    for (int side = 0; side < 2; ++side) {
      glm::ivec2 band = side == 0 ? glm::ivec2(rows.y - third, rows.y) : glm::ivec2(rows.x, rows.x + third);
      glm::dvec2 a = bump::perturbationAgreement(normals[m], exactNormals, smooth, band);
      const std::string where = side == 0 ? "near" : "far";
      out.push_back({"tilt_agreement_x_" + where + "[" + kMethods[m] + "]", a.x,
                     "+1: tilts the normal along eye x as the true surface does, -1: the opposite way (" + where + " side)"});
      out.push_back({"tilt_agreement_y_" + where + "[" + kMethods[m] + "]", a.y, "the same along eye y (" + where + " side)"});
    }
  out.push_back({"tilt_deg[reference]", bump::meanTiltDeg(exactNormals, smooth), "mean angle of R's normal from the smooth torus's"});
  for (int m = 1; m < 4; ++m)
    out.push_back({std::string("tilt_deg[") + kMethods[m] + "]", bump::meanTiltDeg(normals[m], smooth), "mean angle from the smooth normal"});
  // Doubling the height scale: B1 and R tilt about twice as far, seed 002's
  // formula has no scale in it.
  {
    BumpMapping twice = *this;
    twice.heightScale_ = 2 * heightScale_;
    for (int m : {1, 2, 4}) {
      double t1 = bump::meanTiltDeg(normals[m], smooth);
      double t2 = bump::meanTiltDeg(twice.renderMethod(r, m, true, true), smooth);
      out.push_back({std::string("tilt_ratio_height_x2[") + kMethods[m] + "]", t1 > 0 ? t2 / t1 : 0,
                     "mean tilt with twice the height scale / with it"});
    }
  }
  ts::measureProgress(0.85);
  // Seed 004's scale claim: the object twice as large (and the eye twice as
  // far, so the picture is the same size), the bumps as high as before.
  {
    BumpMapping big = *this;
    big.objectScale_ = 2 * objectScale_;
    const ts::Image bigSmooth = big.renderMethod(r, 0, true);
    for (int m : {1, 3, 4}) {
      double t1 = bump::meanTiltDeg(normals[m], smooth);
      double t2 = bump::meanTiltDeg(big.renderMethod(r, m, true, true), bigSmooth);
      out.push_back({std::string("tilt_ratio_object_x2[") + kMethods[m] + "]", t1 > 0 ? t2 / t1 : 0,
                     "mean tilt of the object twice as large / as it is (seed 004 predicts 1/2 for Blinn's form)"});
    }
  }
  found.refShaded = refShaded, found.refNormals = refNormals;
  out.detail = found;
  return out;
}

std::vector<ts::FigureSpec> BumpMapping::figures() const {
  return {{"bump_two_lights", "Buss VI.2 (seed 002, Fig. 1)",
           "Seed 002's figure: a torus under Phong shading and two lights, bump mapped per pixel (Blinn's perturbed normal, "
           "seed 004), beside the same heights displacing a 1024x512 grid (R). Captions: the shading and normal error against R.",
           {"--view", "compare", "--method", "blinn", "--heights", "bricks"}, 1024, 560},
          {"bump_seed002", "Buss VI.2 (seed 002)",
           "Seed 002's shortcut taken literally: the 8-bit height differences added to the eye-space normal's x and y. "
           "Its tilt along x runs against the true surface's and does not grow with the height scale: measured.",
           {"--view", "compare", "--method", "seed002"}, 1024, 560},
          {"bump_normals", "Buss VI.2 (normal map)",
           "Normals as colours (0.5 + 0.5 n, eye space): the normal map baked from the same heights (B3) beside R's.",
           {"--view", "normals", "--method", "normalmap", "--heights", "bricks"}, 1024, 560}};
}
}  // namespace

TM_REGISTER_SCENE(BumpMapping);
