// Bump mapping on the torus, two lights, measured against the truly
// displaced surface (Buss VI.2, "bump mapping"; seeds 001, 002, 004).
//
// The claim: a bump map changes the normal the lighting sees, not the
// surface.  With a height field P(s, t) (procedural dimples and ridges, or
// bricks) the true surface is Q' = Q + P n; its normal is Q'_s x Q'_t.
// Each method approximates that normal per pixel on the smooth torus of
// Figure VI.6 (common/core/torus.hpp), lit by two lights (Phong, GLSL):
//   B1  seed 004, Blinn:   n' = n + P_u (n x Q_w)/|n| + P_w (Q_u x n)/|n|
//       (it drops P (n/|n|)_u: exact for small P and flat Q);
//   B2  seed 002, literally: g_x = j(x+1,y) - j(x-1,y), g_y = j(x,y+1) - j(x,y-1),
//       added / 255 to the x and y of the interpolated normal;
//   B3  a tangent-space normal map baked from the same heights;
//   B4  emboss (seed 001), fixed function, three passes: the heights, minus
//       the heights shifted toward the light, times the diffuse light;
//   B5  DOT3: GL_COMBINE with GL_DOT3_RGB, the normal map dotted with the
//       light in tangent space sent as each vertex's colour;
//   R   the reference: the heights displacing a 1024 x 512 grid.
// Measured (measure()): each method's shading against R (PSNR, mean absolute
// difference over the pixels both cover), the normal error in degrees (a
// render that writes the normal as its colour), which way each method tilts
// the normals against R along the eye's x and y (+1 with it, -1 against),
// how the tilt answers doubling the height scale and doubling the object
// (seed 004: the normal grows 4x, its perturbation 2x: bumps look half as
// deep), emboss's contrast against the light's angle to the normal (0 with
// the light along it), DOT3 against the shader's diffuse sum, the outline
// (seed 001: no bumps on the silhouette) and the normal map's seam where
// the texture repeats (slopes baked one-sided at its edge, and the fix),
// minification (the mean tilt at 2, 4, 8 times the distance, mipmapped
// heights against a mipmapped normal map).
//
// Keys (each is also a flag, see --help):
//   m  method: flat | B1 blinn | B2 seed002 | B3 normalmap | R reference | B4 emboss | B5 dot3
//   v  view: single | compare (the method beside R) | normals (both as colours) | all (B1-B5 and R)
//   t  heights: procedural | bricks (--texture FILE: a picture's luminance)
//   + / -  height scale   s / S  object scale (seed 004's claim)
//     w  the normal map's edge slopes wrap (the seam's fix)
//   a / A, e / E  light 1 azimuth, elevation (or a right drag)   b / B, d / D  light 2   . / ,  tilt
// What the GL does: one GLSL 1.20 program (bump_mapping_gl.hpp: kFS) for B1-B3, the
// method a uniform (its number from bump_mapping_methods.hpp: kMethods, the one table
// of the methods): common/gl/render.cpp: Renderer::draw sends the torus as
// glTexCoord4f(s, t, 0, 1) + glVertex3f after glUseProgram and glUniform4f,
// and the shader reads the heights (or the normal map) in texture unit 0 with
// textureLod (B2: texelFetch of the 8-bit texels).  R, B4 and B5 are passes
// of their own, drawn by measure() and shown as pictures: R is
// bump_mapping_gl.hpp: renderReference, the grid's (s, t) by glVertexPointer +
// glDrawElements, displaced in the vertex shader; B4 and B5 are bump_mapping_ff.hpp:
// renderFixedFunction, immediate mode, emboss's glBlendFunc(GL_ONE, GL_ONE)
// and (GL_DST_COLOR, GL_SRC_COLOR) passes, DOT3's glTexEnvi(GL_TEXTURE_ENV,
// GL_COMBINE_RGB, GL_DOT3_RGB).  The numbers: bump_mapping_measure.hpp.  Listings (the
// pictures' passes first, then the frame): book_figures/bump_two_lights.gl.txt,
// bump_seed002.gl.txt, bump_normals.gl.txt, bump_methods.gl.txt and
// bump_emboss_overhead.gl.txt.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "bump_mapping_ff.hpp"
#include "bump_mapping_gl.hpp"
#include "bump_mapping_math.hpp"
#include "bump_mapping_measure.hpp"
#include "bump_mapping_methods.hpp"
#include "common/gl/gl_listing.hpp"
#include "common/core/layout.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/core/torus.hpp"
#include "common/core/user_texture.hpp"

namespace {
using ts::layout::kAmber;
using ts::layout::kWhite;
using bump::Found;
using bump::kMethods;
constexpr int kMeasureSize = 480;
constexpr float kIntensity[2] = {0.75f, 0.5f};  // the two lights'

class BumpMapping final : public ts::Scene {
 public:
  std::string id() const override { return "bump_mapping"; }
  std::string title() const override { return "Bump mapping on the torus (Buss VI.2; seeds 001, 002, 004)"; }
  std::string about() const override {
    return "A torus with dimples and ridges (or bricks), lit by two "
           "lights, bump mapped per pixel by Blinn's perturbed\n"
           "normal (seed 004), seed 002's height differences, a "
           "normal map, emboss and DOT3; each measured against the\n"
           "same heights displacing a finely tessellated torus: PSNR, mean difference, normal error in degrees.";
  }
  std::vector<std::string> claim() const override { return {"normal_err_deg[blinn]", "normal_err_deg[seed002]"}; }
  void addOptions(ts::Options& o) override {
    std::vector<std::string> keys;
    for (const bump::MethodInfo& m : kMethods) keys.push_back(m.key);
    o.addEnum(
        "method", &method_, keys,
        "flat | B1 Blinn (seed 004) | B2 seed 002 | B3 normal map | R the displaced reference | B4 emboss | B5 DOT3",
        'm');
    o.addEnum("view", &view_, {"single", "compare", "normals", "all"},
              "single | compare: the method beside R | normals as colours | all: B1-B5 and R side by side", 'v');
    o.addEnum("heights", &heights_, {"procedural", "bricks"}, "the height field: dimples and ridges | bricks", 't');
    o.addFloat("height-scale", &heightScale_, 0.0f, 0.12f,
               "P = scale h: the bumps' height in the torus's units (r = 0.4)", '+', '-', 0.01f);
    o.addFloat("object-scale", &objectScale_, 1.0f, 4.0f,
               "the torus scaled (R, r and the eye's distance), the bumps not", 's', 'S', 1.0f);
    o.addFloat("light1-az", &light_[0].x, -180.0f, 180.0f, "light 1 azimuth, degrees, 0 = from the eye", 'a', 'A',
               15.0f);
    o.addFloat("light1-el", &light_[0].y, -90.0f, 90.0f, "light 1 elevation, degrees", 'e', 'E', 15.0f);
    o.addFloat("light2-az", &light_[1].x, -180.0f, 180.0f, "light 2 azimuth, degrees", 'b', 'B', 15.0f);
    o.addFloat("light2-el", &light_[1].y, -90.0f, 90.0f, "light 2 elevation, degrees", 'd', 'D', 15.0f);
    o.addBool("wrap-slopes", &wrapSlopes_,
              "the normal map's slopes wrap across the texture's edge (off: one-sided there, the seam)", 'w');
    o.addFloat("tilt", &tilt_, -90.0f, 90.0f, "the eye's height above the torus's plane, degrees", '.', ',', 5.0f);
    camera_.addOptions(o);
    file_.addOption(o, "the built-in heights (its luminance is the height)");
  }
  std::vector<ts::FigureSpec> figures() const override;
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  // What is measured depends on the heights, the lights, the scales, the
  // tilt and the orbit, not on the method or the view shown: three of the
  // five figures (bricks, the default lights) measure the same state, some 40
  // renders each.  The last few states' results are kept and reused: the
  // same numbers and pictures.  Their GL calls (the listings) hold the
  // viewport current when they were recorded (a pass restores it): R's, two
  // renders of the displaced grid, are kept and fitted to the viewport of now
  // (retargetViewports); those of the fixed-function pictures the view shows
  // (some 100,000 immediate-mode calls each) are recorded again, cheap renders.
  ts::Measurements measure(ts::Renderer& r) override {
    const std::string key = measuredState();
    const bump::RenderFn draw = [&](const bump::RenderSpec& s) { return render(r, s); };
    // The fixed-function pictures this view shows (build(): a cell per method of the view, the compare view's
    // middle cell for emboss's term).
    const bump::ShownFn shown = [&](int p) {
      return p == bump::kEmbossTermPicture ? view_ == 1 && method_ == bump::kEmboss : view_ == 3 || method_ == p;
    };
    glm::ivec4 viewport(0);
    glGetIntegerv(GL_VIEWPORT, &viewport.x);
    for (const Kept& k : measuredCache_)
      if (k.key == key) {
        ts::Measurements again = k.m;
        bump::Found found = *k.m.detailAs<bump::Found>();
        const bool fitted = bump::retargetViewports(found, k.viewport, viewport, {0, 0, kMeasureSize, kMeasureSize});
        bump::recordPicturesAgain(draw, found, !fitted, shown);
        again.detail = found;
        return again;
      }
    const ts::Image &wrapped = *normalTexture(heightScale_, false, true, false).image,
                    &unwrapped = *normalTexture(heightScale_, false, false, false).image;
    struct StageRenders {  // a staged measurement's renders, kept for its end only
      const BumpMapping& scene;
      explicit StageRenders(const BumpMapping& s) : scene(s) {
        if (ts::measureStaged()) scene.stageRenders_ = std::make_shared<StageMap>();
      }
      ~StageRenders() { scene.stageRenders_ = nullptr; }
    } stageRenders(*this);
    if (ts::measureStaged()) {
      referenceStage(draw, true);
      // R's picture whole, the view's other pictures as they are, before what
      // needs R drawn a second time (its normals, for the numbers): refined in
      // place, the numbers still coming.  measureAll takes this render again.
      if (view_ != 0 || method_ == bump::kReference) referenceStage(draw, false);
      // The second stage: the view's own numbers and R's pictures, complete,
      // when its cells need nothing but the methods' comparison with R (not
      // seed 002's tilt cell, not the fixed-function methods' extra notes, not
      // the view of all).  R's normals only where they are shown (the normals
      // view): elsewhere its coverage serves these numbers, and the grid's
      // second draw comes after the picture is complete.  Its renders serve
      // the whole measurement after it.
      const bool plain = view_ != 3 && !kMethods[method_].fixedFunction && !(view_ == 1 && method_ == bump::kSeed002);
      if (plain) {
        const std::vector<int> only = {method_, bump::kReference};
        ts::measureStage(bump::measureAll(draw, toLight(0), wrapped, unwrapped, shown, &only, view_ == 2));
      }
    }
    ts::Measurements m = bump::measureAll(draw, toLight(0), wrapped, unwrapped, shown);
    ts::Measurements kept = m;
    bump::Found bare = *m.detailAs<bump::Found>();
    for (int k = 0; k < bump::kMethodCount; ++k)
      if (kMethods[k].fixedFunction) bare.picturesGL.erase(k);
    bare.embossTermGL = nullptr;
    kept.detail = bare;
    if (measuredCache_.size() >= 4) measuredCache_.erase(measuredCache_.begin());
    measuredCache_.push_back({key, std::move(kept), viewport});
    return m;
  }
  // A window's stage (ts::measureStage), before the 40-odd renders the
  // numbers need: the pictures this view shows that measure() draws.  R from
  // the coarse grid at once (`coarse`: tagged refining, replaced in place),
  // or whole (recorded, as measureAll records it); the fixed-function methods
  // as they are; every picture's note is there, its numbers "(measuring)"
  // (the stage's list is empty).  The other pictures are GL's own, drawn by
  // the window.  Elsewhere (--png, make_figures, the tests) there is no stage.
  void referenceStage(const bump::RenderFn& draw, bool coarse) const {
    bump::Found first;
    const bool all = view_ == 3, normals = view_ == 2;
    if (view_ != 0 || method_ == bump::kReference) {
      bump::RenderSpec s = normals ? bump::shownNormalsSpec() : bump::referenceSpec();
      s.coarseGrid = coarse;
      if (!coarse) s.recordTo = normals ? &first.refNormalsGL : &first.picturesGL[bump::kReference];
      (normals ? first.refNormals : first.pictures[bump::kReference]) = std::make_shared<const ts::Image>(
          normals ? draw(s) : bump::partCoverage(draw(s)).first);
    }
    for (int m = 0; m < bump::kMethodCount; ++m) {
      if (kMethods[m].fixedFunction && (all || m == method_))
        first.pictures[m] = std::make_shared<const ts::Image>(draw({m}));
      first.cmp[m] = bump::Compare{};
    }
    first.coarseReference = coarse;
    ts::Measurements stage;
    stage.detail = first;
    ts::measureStage(std::move(stage));
  }

 private:
  const bump::Heights& heights() const {
    const std::string want = file_.active() ? file_.path() : heights_ ? "bricks" : "procedural";
    if (!cache_ || cacheKey_ != want) {
      cache_ = std::make_shared<bump::Heights>(file_.active() ? bump::fromImage(file_.image())
                                               : heights_     ? bump::bricks()
                                                              : bump::procedural());
      cacheKey_ = want;
    }
    return *cache_;
  }
  // Every option measure() reads (all but --method and --view), floats in hex: exact.
  std::string measuredState() const {
    char b[128];
    std::snprintf(b, sizeof b, "%a %a %a %a|", light_[0].x, light_[0].y, light_[1].x, light_[1].y);
    return b + shapeState();
  }
  // The same but the lights: all a normal render (colour 0.5 + 0.5 n) depends on.
  std::string shapeState() const {
    char b[512];
    std::snprintf(b, sizeof b, "%a %a %a %a %d %a %a %a|", heightScale_, objectScale_, tilt_, distance_,
                  wrapSlopes_ ? 1 : 0, camera_.yaw, camera_.pitch, camera_.zoom);
    return b + std::string(file_.active() ? file_.path() : heights_ ? "bricks" : "procedural");
  }
  // The textures the renders bind, each baked on the CPU once per source and
  // parameters (the heights as grey, the normal map, its DXT1 round trip) and
  // shared by every render of a measurement and every copy of the scene.
  ts::TextureDesc heightTexture(bool inverted, bool mip) const {
    const bump::Heights& H = heights();
    return memo('h' + std::to_string(inverted) + std::to_string(mip),
                [&] { return bump::heightTexture(H, cacheKey_, inverted, mip); });
  }
  ts::TextureDesc normalTexture(float scale, bool mip, bool wrap, bool dxt1) const {
    const bump::Heights& H = heights();
    char k[64];
    std::snprintf(k, sizeof k, "n%a %d%d%d", double(scale), mip, wrap, dxt1);
    return memo(k, [&] { return bump::normalTexture(H, cacheKey_, scale, mip, wrap, dxt1); });
  }
  template <class Make>
  ts::TextureDesc memo(const std::string& what, Make make) const {
    auto& m = *textures_;
    const std::string key = cacheKey_ + '|' + what;
    auto it = m.find(key);
    if (it != m.end()) return it->second;
    if (m.size() >= 32) m.clear();  // a window's many height scales: the cache stays small
    return m.emplace(key, make()).first->second;
  }
  glm::vec3 toLight(int k) const {
    float az = glm::radians(light_[k].x), el = glm::radians(light_[k].y);
    return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
  }
  ts::TorusShape torus() const {
    ts::TorusShape tp;
    tp.R = objectScale_, tp.r = 0.4 * objectScale_, tp.nu = 64, tp.nv = 32;
    return tp;
  }
  // The torus panel of a GLSL method at `vp` (its matrices serve every
  // method); the demo's own torus (R = 1, r = 0.4) times the object scale.
  ts::Panel torusPanel(ts::Frame& f, const ts::Rect& vp, const bump::RenderSpec& s) const;
  // One method's picture alone at the measurement size (no labels): from
  // the normal renders kept (normalRenders_) or renderNow.
  ts::Image render(ts::Renderer& r, const bump::RenderSpec& s) const;
  ts::Image renderNow(ts::Renderer& r, const bump::RenderSpec& s) const;

  int method_ = 1, view_ = 1, heights_ = 0;
  bool wrapSlopes_ = true;
  float heightScale_ = 0.04f, objectScale_ = 1.0f, tilt_ = 30.0f;
  float distance_ = 1.0f;  // measurements only: the eye this many times as far
  glm::vec2 light_[2] = {{-45.0f, 40.0f}, {60.0f, -10.0f}};
  ts::OrbitCamera camera_;
  ts::UserTexture file_;
  mutable std::shared_ptr<const bump::Heights> cache_;
  mutable std::string cacheKey_;
  std::shared_ptr<std::map<std::string, ts::TextureDesc>> textures_ =
      std::make_shared<std::map<std::string, ts::TextureDesc>>();  // heightTexture, normalTexture: cacheKey_|what
  struct Kept {
    std::string key;  // measuredState()
    ts::Measurements m;
    glm::ivec4 viewport;  // current when it was measured (the pictures' passes restore it)
  };
  std::vector<Kept> measuredCache_;
  using StageMap = std::map<std::string, std::pair<ts::Image, ts::gl::CallList>>;
  mutable std::shared_ptr<StageMap> stageRenders_;  // render(): set during a window's staged measure() only
  // render()'s normal renders: "spec|shapeState()" -> picture (packed), for the shapes listed (newest last).
  std::shared_ptr<std::map<std::string, bump::PackedNormals>> normalRenders_ =
      std::make_shared<std::map<std::string, bump::PackedNormals>>();
  std::shared_ptr<std::vector<std::string>> normalRenderShapes_ =
      std::make_shared<std::vector<std::string>>();  // oldest first
};

ts::Panel BumpMapping::torusPanel(ts::Frame& f, const ts::Rect& vp, const bump::RenderSpec& s) const {
  const ts::TorusShape tp = torus();
  ts::Panel p;
  p.id = std::string("torus_") + kMethods[s.method].key;
  p.viewport = vp;
  p.depthTest = true;
  p.projection = glm::perspective(glm::radians(35.0f), float(vp.w) / float(vp.h), 0.5f * objectScale_,
                                  20.0f * objectScale_ * distance_);
  p.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -4.8f * objectScale_ * distance_));
  p.modelview = glm::rotate(p.modelview, glm::radians(tilt_), glm::vec3(1, 0, 0));
  camera_.apply(p);
  const bump::Heights& H = heights();
  ts::TextureDesc tex = s.method == bump::kNormalMap ? normalTexture(heightScale_, s.mipmaps, wrapSlopes_, s.dxt1)
                                                     : heightTexture(false, s.mipmaps);
  // The mesh's (s, t) become glTexCoord4f(s, t, 0, 1) in Renderer::draw: the shader's gl_MultiTexCoord0.
  ts::Batch b = ts::meshBatch(ts::torusMesh(tp), f.addTexture(tex));
  b.role = "torus";
  b.program = "bump";
  b.uniforms = {{"torus", {float(tp.R), float(tp.r), heightScale_, float(kMethods[s.method].shaderId)}},
                {"rep", {H.rep.x, H.rep.y, float(H.w), float(H.h)}},
                {"l0", glm::vec4(toLight(0), kIntensity[0])},
                {"l1", glm::vec4(toLight(1), kIntensity[1])},
                {"opts", {s.normals ? 1.0f : 0.0f, s.noSpecular ? 1.0f : 0.0f, s.mipmaps ? 1.0f : 0.0f, 0.0f}}};
  if (f.programs.empty()) f.programs.push_back({"bump", bump::meshProgram()});
  p.batches.push_back(b);
  return p;
}

ts::Image BumpMapping::render(ts::Renderer& r, const bump::RenderSpec& s) const {
  if (stageRenders_) {  // a window's staged measurement: each render once for all its stages
    char b[256];
    std::snprintf(b, sizeof b, "%d %d %d %d %d %a %a %a %d %d %d %d %d %d", s.method, s.normals, s.smoothGeometry,
                  s.embossTermOnly, s.noSpecular, s.heightFactor, s.objectFactor, s.distanceFactor, s.mipmaps, s.dxt1,
                  s.onBackdrop, s.coarseGrid, s.coverageAlpha, s.recordTo != nullptr);
    auto keep = std::move(stageRenders_);  // the render itself goes on below
    const auto it = keep->find(b);
    ts::Image img;
    ts::gl::CallList gl;
    if (it != keep->end()) {
      img = it->second.first, gl = it->second.second;
    } else {
      img = render(r, s);
      if (s.recordTo) gl = *s.recordTo;
      keep->emplace(b, std::make_pair(img, gl));
    }
    if (s.recordTo) *s.recordTo = gl;
    stageRenders_ = std::move(keep);
    return img;
  }
  if (s.recordTo) {  // a picture shown: the same render, its calls kept for the listing
    bump::RenderSpec plain = s;
    plain.recordTo = nullptr;
    ts::Image img;
    *s.recordTo = ts::recordRender(r, [&] { img = renderNow(r, plain); });  // its calls: never from a kept render
    return img;
  }
  // A GLSL normal render on black does not depend on the lights: one made for
  // another state of the same shape (emboss's figure: light 1 moved) serves.
  std::string normalsKey;
  if (s.normals && !s.onBackdrop && !kMethods[s.method].fixedFunction) {
    char b[256];
    std::snprintf(b, sizeof b, "%d %d %d %d %a %a %a %d %d|", s.method, s.smoothGeometry, s.noSpecular, s.coarseGrid,
                  s.heightFactor, s.objectFactor, s.distanceFactor, s.mipmaps, s.dxt1);
    normalsKey = b + shapeState();
    const auto it = normalRenders_->find(normalsKey);
    if (it != normalRenders_->end()) return it->second.image();
  }
  ts::Image img = renderNow(r, s);
  if (!normalsKey.empty()) {
    // Two shapes' worth (some 30 renders each, packed: 10 MB a shape), the oldest shape dropped first.
    auto& order = normalRenderShapes_;
    if (std::find(order->begin(), order->end(), shapeState()) == order->end()) {
      order->push_back(shapeState());
      if (order->size() > 2) {
        const std::string old = order->front();
        order->erase(order->begin());
        for (auto it = normalRenders_->begin(); it != normalRenders_->end();)
          it = it->first.size() >= old.size() && it->first.compare(it->first.size() - old.size(), old.size(), old) == 0
                   ? normalRenders_->erase(it)
                   : std::next(it);
      }
    }
    normalRenders_->emplace(normalsKey, bump::PackedNormals(img));
  }
  return img;
}

ts::Image BumpMapping::renderNow(ts::Renderer& r, const bump::RenderSpec& s) const {
  BumpMapping v = *this;
  v.heightScale_ *= s.heightFactor, v.objectScale_ *= s.objectFactor, v.distance_ = s.distanceFactor;
  ts::Frame f = ts::layout::blankFrame(kMeasureSize, kMeasureSize);
  if ((s.normals || s.embossTermOnly) && !s.onBackdrop)
    f.clearColor = {0.0f, 0.0f, 0.0f, 1.0f};  // "covered" = not black
  f.panels.push_back(v.torusPanel(f, {0, 0, kMeasureSize, kMeasureSize}, s));
  if (s.method == bump::kReference && !s.smoothGeometry)
    return s.coarseGrid ? bump::renderReference<bump::CoarseReferencePass>(r, f, s.coverageAlpha)
                        : bump::renderReference(r, f, s.coverageAlpha);
  if (!kMethods[s.method].fixedFunction) return r.renderOffscreen(f);
  const bump::Heights& H = v.heights();
  bump::FixedInputs in{v.torus(),
                       H.rep,
                       glm::vec2(float(H.w), float(H.h)),
                       {v.toLight(0), v.toLight(1)},
                       {kIntensity[0], kIntensity[1]},
                       v.heightTexture(false, false),
                       v.heightTexture(true, false),
                       v.normalTexture(v.heightScale_, false, wrapSlopes_, false),
                       s.embossTermOnly};
  return bump::renderFixedFunction(r, f, s.method, in);
}

ts::Frame BumpMapping::build(int width, int height, const ts::Measurements& measured) const {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(width, height);
  const Found* found = measured.detailAs<Found>();
  L::FlowSpec spec;
  const int kAll[] = {bump::kBlinn, bump::kSeed002, bump::kNormalMap, bump::kEmboss, bump::kDot3, bump::kReference};
  const bool normals = view_ == 2;
  // What a cell shows besides the methods: seed 002's x tilt against R's, and emboss's term alone (each
  // between the method and R in the compare view: where its claim is seen).
  constexpr int kTiltCell = -1, kTermCell = -2;
  std::vector<int> shown;
  if (view_ == 0) shown = {method_};
  else if (view_ == 3) shown.assign(std::begin(kAll), std::end(kAll));
  else if (view_ == 1 && method_ == bump::kSeed002) shown = {method_, kTiltCell, bump::kReference};
  else if (view_ == 1 && method_ == bump::kEmboss) shown = {method_, kTermCell, bump::kReference};
  else shown = {method_, bump::kReference};
  const bool keyed = normals || shown.size() == 3;  // a second line above: the key of a picture's colours
  // A number of measure() by name: R's own comparison is its [ideal] (its normal on the smooth torus).
  auto num = [&](const std::string& name, int m, const char* format) {
    return L::measured(measured, name + "[" + (m == bump::kReference ? "ideal" : kMethods[m].key) + "]", format);
  };
  auto band = [&](int b) {  // emboss's contrast in band b of the light's angle to the normal (kEmbossBands)
    return L::measured(measured,
                       "emboss_contrast[" + std::to_string(int(bump::kEmbossBands[b])) + "-" +
                           std::to_string(int(bump::kEmbossBands[b + 1])) + "deg]",
                       "%.3f");
  };
  auto bandDeg = [&](int b) { return L::given("emboss band: light to normal, degrees", bump::kEmbossBands[b], "%g"); };
  // Cell k's title, and its note as phrases (a line breaks between them, never inside one): empty while
  // what it speaks of is still being measured.
  auto titleOf = [&](int m) -> L::Text {
    if (m == kTiltCell) return "B2's tilt along x against R's";
    if (m == kTermCell)
      return "B4's term (1+H-H')/2 alone, shown x" + L::given("emboss term's magnification", bump::kEmbossGain, "%g");
    const bool noNormals = normals && kMethods[m].fixedFunction;
    return std::string(kMethods[m].title) + (normals && !noNormals ? ", normals" : "");
  };
  auto noteOf = [&](int m) -> std::vector<L::Text> {
    if (m == kTiltCell) {
      if (!found || !found->seedTiltX) return {};
      // Seed 002's claim, where its colours are: the near side (the lower third) mostly against R.
      return {"x tilt with R (+1) or against it (-1):",
              "near side (lower third) " + L::measured(measured, "tilt_agreement_x_near[seed002]", "%+.2f") + ",",
              "far side (upper third) " + L::measured(measured, "tilt_agreement_x_far[seed002]", "%+.2f")};
    }
    if (m == kTermCell) {
      if (!found || !found->embossTerm) return {};
      // The contrast per band: where the light is along the normal the bricks are gone.
      return {"mean contrast |H-H'|:", band(0) + " inside the line,",
              band(1) + " at " + bandDeg(1) + "-" + bandDeg(2) + " deg,",
              band(2) + " at " + bandDeg(2) + "-" + bandDeg(3) + ",", band(3) + " beyond " + bandDeg(3) + " deg"};
    }
    if (!found || !found->cmp.count(m)) return {};
    const bool noNormals = normals && kMethods[m].fixedFunction;
    std::vector<L::Text> note;
    if (m == bump::kReference)
      note = normals ? std::vector<L::Text>{"R's normals on the smooth torus:",
                                            num("screen_normal_err_deg", m, "%.1f") + " deg off", "in the same pixel",
                                            "(the geometry's share)"}
                     : std::vector<L::Text>{"R's own normals on the smooth torus",
                                            "reach " + num("psnr_db", m, "%.1f") + " dB against it:",
                                            "the rest is geometry"};
    else if (noNormals)
      note = {"fixed function: no normal to show", "(the shaded picture),",
              num("psnr_db", m, "%.1f") + " dB against R"};
    else if (normals)
      note = {"normal off by " + num("normal_err_deg", m, "%.1f") + " deg at the same (s,t),",
              num("screen_normal_err_deg", m, "%.1f") + " deg in the same pixel"};
    else
      note = {"against R: PSNR " + num("psnr_db", m, "%.1f") + " dB,",
              "mean |diff| " + num("mad", m, "%.1f") + (!kMethods[m].fixedFunction ? L::Text(",") : L::Text())};
    if (!normals && !kMethods[m].fixedFunction && m != bump::kReference)
      note.push_back("normal off by " + num("normal_err_deg", m, "%.1f") + " deg" +
                     (m == bump::kSeed002 && shown.size() == 3 && !measured.empty() ? ";" : ""));
    // The second half of seed 002's claim: its tilt has no scale in it (a first stage leaves it out: four
    // "(measuring)" would not fit the note's three lines).
    if (m == bump::kSeed002 && shown.size() == 3 && !measured.empty())
      note.push_back("twice the heights: tilt ratio " + L::measured(measured, "tilt_ratio_height_x2[seed002]", "%.2f"));
    if (m == bump::kEmboss && !normals && shown.size() != 3 && found->embossContrast[3] >= 0) {
      note.back() = note.back() + ";";
      note.insert(note.end(), {"contrast " + band(0) + " with the light within " + bandDeg(1) + " deg of the normal,",
                               band(3) + " beyond " + bandDeg(3) + " deg"});
    }
    return note;
  };
  // Six narrow cells (view all) need a third line for emboss's contrasts, as do the compare view's three; a
  // narrow window wraps the titles and the notes rather than cut them (flowFitting: at the figures' sizes
  // every caption fits these lines, and the layout is flow()'s).
  spec.n = int(shown.size()), spec.linesAbove = keyed ? 2 : 1, spec.linesBelow = shown.size() >= 3 ? 3 : 2;
  // The keys of the pictures' colours, under their titles: seed 002's tilt, emboss's term, and one key for
  // both normal pictures (each channel is 0.5 + 0.5 of an eye-space component).
  auto rgba = [](ts::Rgba q) { return glm::vec4(q.r, q.g, q.b, 255) / 255.0f; };
  auto keyOf = [&](size_t k) -> std::vector<ts::LegendEntry> {
    if (shown[k] == kTiltCell)
      return {{rgba(bump::kTiltWith), "with R"},
              {rgba(bump::kTiltAgainst), "against R"},
              {rgba(bump::kTiltUncounted), "not counted"}};
    if (shown[k] == kTermCell)
      return {
          {rgba(bump::kEmbossEdge), "light 1 within " + L::fmt("%g", bump::kEmbossBands[1]) + " deg of the normal"}};
    if (normals && k == 0)
      return {{{1.0f, 0.5f, 0.5f, 1.0f}, "n to the right (+x)"},
              {{0.5f, 1.0f, 0.5f, 1.0f}, "n up (+y)"},
              {{0.5f, 0.5f, 1.0f, 1.0f}, "n to the eye (+z)"}};
    return {};
  };
  std::vector<L::Stack> above, below;
  std::vector<std::vector<ts::LegendEntry>> keys;
  for (size_t k = 0; k < shown.size(); ++k) {
    above.push_back({titleOf(shown[k]).text});
    std::string note;
    for (const L::Text& t : noteOf(shown[k])) note += (note.empty() ? "" : " ") + t.text;
    below.push_back({note});
    keys.push_back(keyOf(k));
  }
  std::vector<L::Cell> cells = L::flowFitting({6, 6, float(width) - 6, float(height) - 6}, spec, above, below, keys,
                                              20);
  // Every title on the same line: the key bands as deep as the deepest key.
  int keyLines = keyed ? 1 : 0;
  for (size_t k = 0; k < cells.size(); ++k)
    keyLines = std::max(keyLines, L::legendLines(keys[k], 1, cells[k].above.w()));
  auto picture = [&](const L::Cell& c, const std::string& id, const std::shared_ptr<const ts::Image>& img,
                     const std::string& what, const ts::gl::CallList& gl) {
    ts::TextureDesc t = ts::renderedImageTexture(*img, "bump_render", what, "bump_mapping");
    t.renderedBy = gl;
    f.panels.push_back(L::texturePanel(id, c.picture, f.addTexture(t)));
  };
  for (size_t k = 0; k < cells.size(); ++k) {
    const L::Cell& c = cells[k];
    const int m = shown[k];
    const auto [title, key] = keyLines ? L::keyApart(c.above, c.scale, keyLines)
                                       : std::pair<L::Box, L::Box>{c.above, {}};
    L::caption(f, title, titleOf(m), kWhite, c.scale);
    if (!keys[k].empty()) L::legend(f, key, keys[k], 1);
    const std::vector<L::Text> note = noteOf(m);
    if (m == kTiltCell) {
      if (!found || !found->seedTiltX) {  // a window's first stage: a CPU picture of the numbers' renders
        L::caption(f, L::box(c.picture), "measuring...", kWhite, c.scale);
        continue;
      }
      picture(c, "picture_seed002_tilt_x", found->seedTiltX, "seed002 x tilt against R", nullptr);
      L::phrases(f, c.below, note, kAmber, c.scale);
      continue;
    }
    if (m == kTermCell) {
      if (!found || !found->embossTerm) {
        L::caption(f, L::box(c.picture), "measuring...", kWhite, c.scale);
        continue;
      }
      picture(c, "picture_emboss_term", found->embossTerm, "emboss term", found->embossTermGL);
      L::phrases(f, c.below, note, kAmber, c.scale);
      continue;
    }
    const bool isPicture = m == bump::kReference || kMethods[m].fixedFunction;  // drawn by measure()
    if (!isPicture) {
      f.panels.push_back(torusPanel(f, c.picture, {m, normals}));
    } else if (found && (normals && m == bump::kReference ? found->refNormals != nullptr : found->pictures.count(m))) {
      const bool n = normals && m == bump::kReference;
      const auto gl = found->picturesGL.find(m);
      picture(c, std::string("picture_") + kMethods[m].key, n ? found->refNormals : found->pictures.at(m),
              std::string(kMethods[m].key) + (n ? " normals" : ""),
              n                               ? found->refNormalsGL
              : gl != found->picturesGL.end() ? gl->second
                                              : nullptr);
      if (m == bump::kReference && found->coarseReference)
        L::refiningTag(f, c.picture);  // the coarse grid (referenceStage)
    } else {
      L::caption(f, L::box(c.picture), "measuring...", kWhite, c.scale);
    }
    if (note.empty()) continue;
    L::phrases(f, c.below, note, kAmber, c.scale);
  }
  return f;
}

std::vector<ts::FigureSpec> BumpMapping::figures() const {
  return {
      {"bump_two_lights",
       "Buss VI.2 (seed 002, Fig. 1)",
       "Seed 002's figure: a torus under Phong shading and two "
       "lights, bump mapped per pixel (Blinn's perturbed normal, "
       "seed 004), beside the same heights displacing a 1024x512 "
       "grid (R). Captions: the shading and normal error against R.",
       {"--view", "compare", "--method", "blinn", "--heights", "bricks"},
       1024,
       560,
       "Blinn's perturbed normal is {normal_err_deg[blinn]} deg from the displaced surface's and tilts "
       "{tilt_deg[blinn]} deg from the smooth torus's (the surface: {tilt_deg[reference]})."},
      {"bump_seed002",
       "Buss VI.2 (seed 002)",
       "Seed 002's shortcut taken literally: the 8-bit height differences added to the eye-space normal's x and y. "
       "Its tilt along x runs against the true surface's on the near side of the ring and with it on the far side, and "
       "does not grow with the height scale: measured. The middle "
       "picture shows, in the near and the far third of the ring, "
       "each pixel where B2 tilts the normal along x as R does (green) or against it (magenta).",
       {"--view", "compare", "--method", "seed002"},
       1024,
       560,
       "Seed 002's shortcut tilts the normal along x against the surface on the near side "
       "({tilt_agreement_x_near[seed002]}; +1 agrees), and no more with twice the heights (ratio "
       "{tilt_ratio_height_x2[seed002]})."},
      {"bump_normals",
       "Buss VI.2 (normal map)",
       "Normals as colours (0.5 + 0.5 n, eye space): the normal map baked from the same heights (B3) beside R's.",
       {"--view", "normals", "--method", "normalmap", "--heights", "bricks"},
       1024,
       632,
       "The normal map baked from the heights is {normal_err_deg[normalmap]} deg from the displaced surface's "
       "normal on average (Blinn's per pixel: {normal_err_deg[blinn]})."},
      {"bump_methods",
       "Buss VI.2 (seeds 001, 002, 004)",
       "Every method side by side on bricks under two lights: B1 "
       "Blinn (seed 004), B2 seed 002's shortcut, B3 a normal map "
       "(GLSL), B4 emboss and B5 DOT3 (fixed function), and R, the heights displacing a 1024x512 grid.",
       {"--view", "all", "--heights", "bricks"},
       1280,
       720,
       "Mean normal error against the displaced surface: B1 Blinn {normal_err_deg[blinn]} deg, B3 normal map "
       "{normal_err_deg[normalmap]}, B2 seed 002 {normal_err_deg[seed002]}, no bumps {normal_err_deg[flat]}."},
      {"bump_emboss_overhead",
       "Buss VI.2 (seed 001, emboss)",
       "Emboss (seed 001), three fixed-function passes, with light "
       "1 at the eye: where the light falls along the normal "
       "(the middle of the ring) the shift toward it is 0 and the "
       "bricks vanish; R keeps them. The middle picture is emboss's "
       "term alone, magnified, the region where the light is nearly "
       "along the normal outlined: the bricks are gone inside "
       "it. The contrast is measured per band of the light-normal angle.",
       {"--view", "compare", "--method", "emboss", "--heights", "bricks", "--light1-az", "0", "--light1-el", "0"},
       1024,
       560,
       "With light 1 at the eye, emboss contrast is {emboss_contrast[0-10deg]} where the light is within 10 deg "
       "of the normal, {emboss_contrast[60-90deg]} at 60-90 deg."}};
}
}  // namespace

TS_REGISTER_SCENE(BumpMapping);
