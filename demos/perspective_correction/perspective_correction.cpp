// Figure VI.2 — a checkerboard plane seen at a slant, without and with
// hyperbolic (perspective-correct) interpolation of (s, t).
//
// The claim (Buss, VI.1.1 and V.5): interpolating texture coordinates
// linearly in screen space does not shorten distant squares correctly;
// hyperbolic interpolation does.  It matters most for large polygons seen at
// a slant — roughly when d2 - d1 (farthest minus nearest distance from the
// eye to the polygon) is comparable to d1 or larger.
//
// What the GL does (common/gl/render.cpp: Renderer::draw): the book's
// glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST), then the square as one
// glBegin(GL_TRIANGLES) of six glTexCoord4f(s, t, 0, 1) + glVertex3f — one
// quad, two triangles, as in the book: subdividing it would hide the error.
// Right: model coordinates under glMatrixMode(GL_PROJECTION); glLoadMatrixf:
// w is the depth and GL interpolates (s/w, t/w, 1/w).  Does the driver honour
// the hint?  measure() renders that square under GL_FASTEST and GL_NICEST and
// compares.  Mesa (llvmpipe, softpipe) ignores it and always interpolates
// hyperbolically, so the left image is made the same on every driver: the
// vertices projected on the CPU and sent as glVertex3f(x/w, y/w, z/w) under
// an identity projection; dividing by w = 1 at every vertex is exactly
// linear interpolation in screen space.  Listings:
// book_figures/vi2_perspective_correction.gl.txt (both squares) and
// vi2_error_vs_depth_ratio.gl.txt (only the plot of the measured sweep).
//
// Keys (each is also a flag, see --help):
//   v  view: both (the book's figure) | affine | perspective | plot (the sweep)
//   t / T  tilt up / down (0 = facing the eye)   d / D  distance up / down
//   f  filter: nearest | linear | mipmap         e  the two triangles' edges
//
// Measured: the square drawn again with texelIndexTexture (each pixel says
// which texel it took) against the perspective-correct (s, t) of the ray
// through the pixel: the affine image's largest error in texels, at the
// current state and over a sweep of tilts, against the book's (d2 - d1)/d1.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "common/core/error.hpp"
#include "common/gl/gl.hpp"
#include "common/core/layout.hpp"
#include "common/core/plot.hpp"
#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/core/user_texture.hpp"
#include "perspective_correction_math.hpp"
#include "perspective_correction_measure.hpp"  // the texel-index comparison, the results and the plot

namespace {
enum View { kBoth, kAffine, kPerspective, kPlot };
enum Variant { kAffineVariant, kPerspectiveVariant };

// The measurement's sizes and sweep (perspective_correction_measure.hpp).
using persp::kMeasureSize, persp::kIndexTexels, persp::kSweepStepDeg, persp::kSweepMaxDeg;

using ts::layout::fmt;
namespace plot = ts::plot;

class PerspectiveCorrection final : public ts::Scene {
 public:
  std::string id() const override { return "perspective_correction"; }
  std::string title() const override { return "Figure VI.2 - hyperbolic (perspective-correct) interpolation"; }
  std::string about() const override {
    return "A checkerboard square seen at a slant, drawn as two triangles with (s,t) interpolated linearly in screen\n"
           "space (left) and hyperbolically (right).  Tests whether the driver honours "
           "GL_PERSPECTIVE_CORRECTION_HINT,\n"
           "measures the affine image's largest (s,t) error in texels from a texel-index render, and sweeps the tilt\n"
           "to set that error against the book's rule of thumb (d2 - d1)/d1.";
  }
  int defaultWidth() const override { return 1024; }
  int defaultHeight() const override { return 400; }

  std::vector<std::string> claim() const override { return {"affine_error_texels", "d_ratio", "hint_honoured"}; }
  void addOptions(ts::Options& o) override {
    o.addEnum("view", &view_, {"both", "affine", "perspective", "plot"},
              "both: the book's figure; one variant large; plot: error vs (d2-d1)/d1 over tilts", 'v');
    o.addFloat("tilt", &tilt_, 0.0f, 85.0f, "degrees the square is tilted back (0 = facing the eye)", 't', 'T', 5.0f);
    o.addFloat("distance", &distance_, 1.25f, 32.0f,
               "eye to the square's centre, in half-sides (the square's side is 2)", 'd', 'D', 0.25f);
    o.addEnum("filter", &filter_, {"nearest", "linear", "mipmap"},
              "checkerboard filter (mipmap = trilinear over the book's 2x2 mip chain)", 'f');
    o.addBool("edges", &edges_, "draw the two triangles' edges (the affine error kinks along the diagonal)", 'e');
    picture_.addOption(o, "the checkerboard");
    camera_.addOptions(o);
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"vi2_perspective_correction",
         "Figure VI.2",
         "A checkerboard square tilted 60 degrees, its centre 1.5 half-sides from the eye ((d2 - d1)/d1 = 2.24), as "
         "two triangles: without hyperbolic interpolation (left: (s,t) linear in screen space, the far squares are "
         "not shortened) and with it (right). The note says whether the driver honours "
         "GL_PERSPECTIVE_CORRECTION_HINT and how the left image was made.",
         {"--view", "both", "--tilt", "60", "--distance", "1.5", "--filter", "mipmap"},
         1024,
         300,
         "Interpolated linearly in screen space, (s,t) is off by up to {affine_error_texels} texels (of 256) at (d2 "
         "- d1)/d1 = {d_ratio}."},
        {"vi2_error_vs_depth_ratio",
         "Figure VI.2 (measured)",
         "The screen-linear image's largest (s,t) error, measured from texel-index renders (crosses), against the "
         "book's (d2 - d1)/d1 over tilts 0..80 degrees at distance 1.5; the line is the analytic error. Facing the "
         "eye (tilt 0) the error is zero although (d2 - d1)/d1 = 0.37: what the interpolation feels is how much the "
         "depth w varies over the polygon, which the distances only approximate.",
         {"--view", "plot", "--tilt", "60", "--distance", "1.5"},
         1024,
         560,
         "The screen-linear error grows with the tilt, from {sweep_t00_error_texels} texels facing the eye, where "
         "(d2 - d1)/d1 is already {sweep_t00_d_ratio}, to {sweep_t80_error_texels} at 80 deg."},
        {"inspect_vi2_footprints",
         "Figure VI.2 (inside six pixels)",
         "The plane at 80 degrees, six pixels picked from near to far (--inspect X,Y --footprints), ringed in the "
         "plane's panel drawn again pixel for pixel; below: each one's footprint on level 0 of the texture: the "
         "preimage of the pixel square (white), the derivatives' parallelogram, the EWA ellipse, the 2^lambda "
         "square of its mip level and the texels trilinear reads.",
         {"--view", "perspective", "--tilt", "80", "--distance", "1.5", "--footprints", "--inspect", "515,185",
          "--inspect", "515,160", "--inspect", "515,145", "--inspect", "515,133", "--inspect", "515,126", "--inspect",
          "515,121"},
         1024,
         400,
         "lambda rises from {inspect_lambda[1]} near to {inspect_lambda[6]} far, rho from {inspect_rho[1]} to "
         "{inspect_rho[6]} texels per pixel."},
    };
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;

 private:
  persp::Setup setup() const { return {double(tilt_), double(distance_)}; }
  void addSquare(ts::Panel& p, const persp::Setup& s, Variant v, int texture, bool edges) const;
  ts::TextureDesc checker() const;
  // The texel-index render of one variant at kMeasureSize, and the largest
  // error of the texels it took against the perspective-correct (s, t).
  using Pass = persp::Pass;
  Pass measurePass(ts::Renderer& r, const persp::Setup& s, Variant v, GLenum hint, ts::Image* out = nullptr) const;
  using Result = persp::Result;  // what measure() found: the labels and the plot
  int view_ = kBoth, filter_ = 2;
  float tilt_ = 60.0f, distance_ = 1.5f;
  ts::UserTexture picture_;  // --texture FILE
  ts::OrbitCamera camera_;   // --yaw --pitch --zoom: the mouse (the picture; the measurement keeps the setup's view)
  bool edges_ = false;
};

ts::TextureDesc PerspectiveCorrection::checker() const {
  ts::TextureDesc t = ts::checkerboard(persp::kTexels, persp::kChecks);
  t.magFilter = filter_ == 0 ? GL_NEAREST : GL_LINEAR;
  t.minFilter = filter_ == 0 ? GL_NEAREST : filter_ == 1 ? GL_LINEAR : GL_LINEAR_MIPMAP_LINEAR;
  t.mipmaps = filter_ == 2;
  return picture_.orDefault(t);
}

void PerspectiveCorrection::addSquare(ts::Panel& p, const persp::Setup& s, Variant v, int texture, bool edges) const {
  double aspect = double(p.viewport.w) / p.viewport.h;
  persp::View view = persp::makeView(s, aspect);
  view.mv = camera_.view(view.mv);  // both variants: the affine one projects with these on the CPU
  view.proj = camera_.lens(view.proj);
  if (camera_.yaw != 0 || camera_.pitch != 0) persp::widenDepthRange(&view.proj);  // orbited: corners come nearer
  // Perspective: model coordinates through GL's projection (w = depth).
  // Affine: the same vertices projected here, sent with w = 1.
  auto position = [&](glm::dvec2 uv) {
    return v == kPerspectiveVariant ? glm::vec3(glm::vec2(uv), 0.0f) : glm::vec3(persp::ndc(view, uv));
  };
  if (v == kPerspectiveVariant) {
    p.projection = glm::mat4(view.proj);
    p.modelview = glm::mat4(view.mv);
  }
  ts::Batch b;
  b.role = v == kPerspectiveVariant ? "surface_hyperbolic" : "surface_screen_linear";
  b.texture = texture;
  for (size_t k : {0, 1, 2, 0, 2, 3}) {
    glm::dvec2 uv = persp::corners()[k];
    // becomes glTexCoord4f(s, t, 0, 1) + glVertex3f(position) in Renderer::draw
    b.vertices.push_back({position(uv), glm::vec4(glm::vec2(persp::texCoord(uv)), 0, 1), glm::vec4(1.0f)});
  }
  p.batches.push_back(b);
  if (edges) {
    ts::Batch e;
    e.role = "triangle_edges";
    e.prim = ts::Prim::Lines;
    e.lineWidth = 2.0f;
    for (auto [a, c] : {std::pair{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}})
      for (int k : {a, c})
        e.vertices.push_back({position(persp::corners()[size_t(k)]), {0, 0, 0, 1}, {1.0f, 0.55f, 0.0f, 1.0f}});
    p.batches.push_back(e);
  }
}

ts::Frame PerspectiveCorrection::build(int width, int height, const ts::Measurements& measured) const {
  ts::Frame f = ts::layout::blankFrame(width, height);
  // The book's call.  The right (and single perspective) image is drawn under GL_NICEST; the affine-only
  // view asks for GL_FASTEST, which Mesa ignores — and which cannot matter to it anyway, since w = 1 everywhere.
  f.perspectiveHint = view_ == kAffine ? GL_FASTEST : GL_NICEST;
  const glm::vec4 &white = ts::layout::kWhite, &grey = persp::kGrey;
  const persp::Setup s = setup();
  const Result* last = measured.detailAs<Result>();
  const bool have = last && last->setup.tiltDeg == s.tiltDeg && last->setup.distance == s.distance;
  if (view_ == kPlot) {
    plot::draw(f, persp::plotSpec(s, last), {0, 0, width, height});
    return f;
  }
  int tex = f.addTexture(checker());
  // The notes: the hint test, and the measured error against the rule of thumb (perspective_correction_measure.hpp).
  const auto notes = persp::notes(s, have ? last : nullptr, measured);
  // Room for the notes under the pictures (at most a third of the height).
  const float margin = 8, noteW = float(width) - 2 * margin;
  float notesH = 0;
  for (const auto& n : notes)
    notesH += float(ts::layout::captionLines(n.first.text, 1, noteW)) * ts::layout::lineHeight(1) + 4;
  notesH = std::min(notesH, float(height) / 3);
  const std::string how[2] = {"CPU-projected vertices, w = 1: screen-linear", "glHint(..., GL_NICEST): hyperbolic"};
  const char* titles[2] = {"without hyperbolic interpolation", "with hyperbolic interpolation"};
  const Variant shown[2] = {view_ == kPerspective ? kPerspectiveVariant : kAffineVariant, kPerspectiveVariant};
  ts::layout::FlowSpec spec;
  spec.n = view_ == kBoth ? 2 : 1;
  spec.aspect = float(persp::boundsAspect(s));  // panels as tall as the projected square needs
  spec.gap = 16;
  spec.maxScale = 2;
  std::vector<ts::layout::Cell> cells = ts::layout::flow({margin, margin, float(width) - margin,
                                                          float(height) - margin - notesH},
                                                         spec);
  float bottom = margin;
  for (int k = 0; k < spec.n; ++k) {
    const ts::layout::Cell& c = cells[size_t(k)];
    ts::Panel p;
    p.id = shown[k] == kAffineVariant ? "affine" : "perspective";
    p.viewport = c.picture;
    addSquare(p, s, shown[k], tex, edges_);
    f.panels.push_back(p);
    ts::layout::caption(f, c.above, titles[shown[k]], white, c.scale);
    ts::layout::caption(f, c.below, how[shown[k]], grey, std::max(1, c.scale - 1));
    bottom = std::max(bottom, c.below.y1);
  }
  ts::layout::Column column(f, {margin, bottom + 4, float(width) - margin, float(height) - 2});
  for (const auto& n : notes) column.add(n.first, n.second, 1);
  return f;
}

PerspectiveCorrection::Pass PerspectiveCorrection::measurePass(ts::Renderer& r, const persp::Setup& s, Variant v,
                                                               GLenum hint, ts::Image* out) const {
  const int N = kMeasureSize;
  ts::Frame mf;
  mf.width = mf.height = N;
  mf.clearColor = glm::vec4(0.0f);  // alpha 0 marks pixels the square does not cover
  mf.perspectiveHint = hint;
  ts::TextureDesc t = ts::texelIndexTexture(kIndexTexels);
  // Clamp, not repeat: a pixel centre just outside the square reads the edge
  // texel instead of wrapping to the far side of the texture.
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  int tex = mf.addTexture(t);
  ts::Panel p;
  p.id = "texel_index";
  p.viewport = {0, 0, N, N};
  addSquare(p, s, v, tex, false);
  mf.panels.push_back(p);
  ts::Image img = r.renderOffscreen(mf);
  // Every covered pixel's texel against the ray through it (perspective_correction_measure.hpp).
  Pass pass = persp::compare(img, s, v == kAffineVariant);
  if (out) *out = std::move(img);
  return pass;
}

ts::Measurements PerspectiveCorrection::measure(ts::Renderer& r) {
  const persp::Setup s = setup();
  const persp::Distances d = persp::distances(s);
  Result m;
  m.setup = s;
  m.affine = measurePass(r, s, kAffineVariant, GL_FASTEST);
  // The hint test: GL's own projection under both hints, pixel by pixel.
  ts::Image nicest, fastest;
  m.perspective = measurePass(r, s, kPerspectiveVariant, GL_NICEST, &nicest);
  Pass fast = measurePass(r, s, kPerspectiveVariant, GL_FASTEST, &fastest);
  for (size_t k = 0; k < nicest.pixels.size(); k += 4)
    m.hintDiffering += std::memcmp(&nicest.pixels[k], &fastest.pixels[k], 4) != 0;
  m.hintFastestError = fast.maxErrorTexels;
  std::string renderer = ts::gl::rendererString();
  m.driver = renderer.substr(0, renderer.find(' '));
  ts::Measurements out{
      {"d1", d.d1, "nearest distance from the eye to the square"},
      {"d2", d.d2, "farthest distance from the eye to the square"},
      {"d_ratio", d.ratio(), "(d2 - d1)/d1, the book's rule of thumb"},
      {"depth_ratio", d.depthRatio(), "(w2 - w1)/w1 over the corners' depths"},
      {"affine_error_texels", m.affine.maxErrorTexels,
       "largest |(s,t) - correct| of the screen-linear image, texels of 256"},
      {"affine_error_checks", m.affine.maxErrorTexels / (persp::kTexels / persp::kChecks),
       "the same in checks of the checkerboard"},
      {"affine_error_predicted", m.affine.predictedTexels, "the same from the analytic maps at the same pixels"},
      {"perspective_error_index", double(m.perspective.maxIndexError),
       "hyperbolic image: largest texel-index error (of 2048)"},
      {"hint_pixels_differing", double(m.hintDiffering), "GL_FASTEST vs GL_NICEST render of the GL-projected square"},
      {"hint_honoured", m.hintDiffering > 0 ? 1.0 : 0.0, "1 if the driver changes anything for GL_FASTEST"},
      {"hint_fastest_error_texels", m.hintFastestError, "largest (s,t) error of the GL_FASTEST render, texels of 256"},
  };
  // The sweep: the rule of thumb measured.
  for (int tilt = 0; tilt <= kSweepMaxDeg; tilt += kSweepStepDeg) {
    persp::Setup st{double(tilt), s.distance};
    Pass p = measurePass(r, st, kAffineVariant, GL_FASTEST);
    double ratio = persp::distances(st).ratio();
    m.sweep.push_back({ratio, p.maxErrorTexels, double(tilt)});
    std::string key = "sweep_t" + fmt("%02.0f", tilt);
    out.push_back({key + "_d_ratio", ratio, "(d2 - d1)/d1 at tilt " + std::to_string(tilt)});
    out.push_back({key + "_error_texels", p.maxErrorTexels, "measured largest error of the screen-linear image"});
    out.push_back({key + "_predicted", p.predictedTexels, "analytic largest error at the same pixels"});
  }
  // The analytic curve, densely (2.5 degree steps), at the measurement's size.
  for (double tilt = 0; tilt <= kSweepMaxDeg + 1e-9; tilt += 2.5) {
    persp::Setup st{tilt, s.distance};
    m.curve.push_back({persp::distances(st).ratio(), persp::maxAffineErrorTexels(st, kMeasureSize), tilt});
  }
  out.detail = m;
  return out;
}

}  // namespace

TS_REGISTER_SCENE(PerspectiveCorrection);
