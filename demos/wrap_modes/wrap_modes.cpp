// Wrap modes and the texture matrix, measured (Buss VI.4; seeds 001, 002).
//
// The claim: outside the unit square, what a texture shows is one
// glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S/T, mode) call, and each
// mode is a formula on the texel index (wrap_math.hpp, from the spec's table
// 8.20): GL_REPEAT i mod N; GL_MIRRORED_REPEAT (N-1) - mirror((i mod 2N) - N);
// GL_CLAMP_TO_EDGE clamp(i, 0, N-1); GL_CLAMP_TO_BORDER clamp(i, -1, N) with
// the border colour outside; GL_CLAMP clamps s to [0,1], and GL_LINEAR then
// blends the border in: half of it at s = 0 and s = 1 (the dark seam),
// where GL_CLAMP_TO_EDGE blends none and GL_CLAMP_TO_BORDER all of it
// outside.  Seed 002's MIRROR program agrees with GL_MIRRORED_REPEAT except
// at integer s, where it returns the opposite edge.  The texture matrix
// (glMatrixMode(GL_TEXTURE); glLoadMatrixf) moves (s,t) before all of it:
// (s', t', r', q') = M (s, t, r, q), here T(shift) R(angle) Sh(shear) S(scale)
// about the texture's centre.
//
// Keys (each is also a flag, see --help):
//   v  view: modes (5 modes x nearest/linear) | single | matrix
//   s / t  wrap mode of s / of t (single and matrix views)   f  nearest | linear
//   + / -  range: (s,t) run from -range to 1 + range          n  a 7x5 texture (NPOT)
//   ] / [  shift s of the texture matrix   r / R  rotate   > / <  scale   k / K  shear
//   a  animate the rotation
//
// Measured (measure()): the quad drawn again with a texture whose texels hold
// their indices (common/textures.hpp), every pixel's texel against the
// formula, with pixel centres a quarter texel inside and, in a second pass,
// exactly at every integer s (0 mismatches each, for 8x8 and 37x23 texels);
// the texels seed 002's MIRROR picks at the integers (all differ); the share
// of the border colour GL_LINEAR reads at s = -1/4, 0, 1, 5/4 against the
// formula; the texel under probe points with the texture matrix on.
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <map>

#include "common/error.hpp"
#include "common/layout.hpp"
#include "common/render.hpp"
#include "common/scene.hpp"
#include "common/textures.hpp"
#include "wrap_math.hpp"

namespace {
const GLenum kModes[] = {GL_REPEAT, GL_MIRRORED_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER};
const char* const kModeNames[] = {"repeat", "mirrored", "clamp", "edge", "border"};
const GLenum kEnvs[] = {GL_REPLACE, GL_MODULATE, GL_DECAL, GL_BLEND, GL_ADD};
const char* const kEnvNames[] = {"replace", "modulate", "decal", "blend", "add"};
const char* const kEnvGL[] = {"GL_REPLACE", "GL_MODULATE", "GL_DECAL", "GL_BLEND", "GL_ADD"};
const glm::vec4 kEnvColour{0.2f, 0.6f, 1.0f, 1.0f};  // GL_TEXTURE_ENV_COLOR for GL_BLEND
const char* const kModeGL[] = {"GL_REPEAT", "GL_MIRRORED_REPEAT", "GL_CLAMP", "GL_CLAMP_TO_EDGE", "GL_CLAMP_TO_BORDER"};
const glm::vec4 kWhite{0.95f, 0.95f, 0.95f, 1.0f}, kSquare{1.0f, 0.85f, 0.1f, 1.0f}, kGrid{0.55f, 0.55f, 0.6f, 1.0f},
    kMeasured{1.0f, 0.75f, 0.3f, 1.0f}, kBorderColour{0.85f, 0.1f, 0.75f, 1.0f};
using ts::layout::fmt;

// What measure() found, for the captions.
struct Found {
  std::map<int, int> mismatches;      // mode index -> texel mismatches (both passes, both sizes)
  std::map<int, double> borderAt0;    // mode index -> % border at s = 0 (linear)
  int seedDiffers = 0, integers = 0;  // seed 002's MIRROR vs GL at integer s
  int matrixMismatches = -1;
  int envMismatches = -1;
  double peak[2] = {-1, -1};  // the highlight's peak (mean of R, G, B): specular in the primary colour | separate
};

// A texel-index texture of any size (a crop of the square one): the NPOT
// case.  Border (1,1,1,1) decodes to index 4095, which no texel has.
ts::TextureDesc indexTexture(int w, int h, GLenum mode) {
  ts::TextureDesc t = ts::texelIndexTexture(std::max(w, h));
  auto img = std::make_shared<ts::Image>(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) img->set(i, j, t.image->at(i, j));
  t.image = img;
  t.params = {{"width", std::to_string(w)}, {"height", std::to_string(h)}};
  t.wrapS = t.wrapT = mode;
  t.border = glm::vec4(1.0f);
  return t;
}

// A quad over `vp` (ortho 0..1) whose corners carry (s,t) from lo to hi.
ts::Batch stQuad(glm::vec2 p0, glm::vec2 p1, glm::dvec2 lo, glm::dvec2 hi, int tex) {
  ts::Batch b;
  b.role = "surface";
  b.texture = tex;
  for (int i : {0, 1, 2, 0, 2, 3}) {
    glm::vec2 c(i == 1 || i == 2, i >= 2);
    b.vertices.push_back({{glm::mix(p0, p1, c), 0}, {glm::mix(lo.x, hi.x, double(c.x)), glm::mix(lo.y, hi.y, double(c.y)), 0, 1}, {1, 1, 1, 1}});
  }
  return b;
}

class WrapModes final : public ts::Scene {
 public:
  std::string id() const override { return "wrap_modes"; }
  std::string title() const override { return "Wrap modes and the texture matrix (Buss VI.4)"; }
  std::string about() const override {
    return "A quad whose (s,t) run past the unit square, drawn with each wrap mode (GL_REPEAT, GL_MIRRORED_REPEAT,\n"
           "GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER) and filter, and with a texture matrix.  Measured from\n"
           "renders whose pixels name their texels: every pixel against the spec's wrap formula (also at integer s),\n"
           "seed 002's MIRROR program against GL_MIRRORED_REPEAT, the border share of GL_LINEAR at the edges.";
  }
  std::vector<std::string> claim() const override { return {"wrap_texel_mismatches", "seed_mirror_differs"}; }
  void addOptions(ts::Options& o) override {
    o.addEnum("view", &view_, {"modes", "single", "matrix", "env"},
              "modes: 5 modes x 2 filters; single: one state; matrix: the texture matrix; env: the texture environments", 'v');
    o.addEnum("env", &env_, std::vector<std::string>(kEnvNames, kEnvNames + 5),
              "texture environment of the single view's quad (on vertex colours)", 'e');
    o.addBool("separate-specular", &separate_, "env view, last panel: GL_SEPARATE_SPECULAR_COLOR (specular added after texturing)", 'p');
    o.addEnum("wrap-s", &wrapS_, std::vector<std::string>(kModeNames, kModeNames + 5), "wrap mode of s (single and matrix views)", 's');
    o.addEnum("wrap-t", &wrapT_, std::vector<std::string>(kModeNames, kModeNames + 5), "wrap mode of t (single and matrix views)", 't');
    o.addEnum("filter", &filter_, {"nearest", "linear"}, "texture filter (single and matrix views)", 'f');
    o.addFloat("range", &range_, 0.0f, 3.0f, "(s,t) run from -range to 1 + range", '+', '-', 0.5f);
    o.addBool("npot", &npot_, "a 7x5 texture instead of 8x8 (non-power-of-two)", 'n');
    o.addFloat("shift", &xf_.shift.x, -1.0f, 1.0f, "texture matrix: shift of s", ']', '[', 0.125f);
    o.addFloat("rotate", &xf_.angleDeg, -180.0f, 180.0f, "texture matrix: rotation of (s,t) in degrees", 'r', 'R', 15.0f);
    o.addFloat("scale", &xf_.scale.x, 0.25f, 4.0f, "texture matrix: scale of s and t", '>', '<', 0.25f);
    o.addFloat("shear", &xf_.shear, -2.0f, 2.0f, "texture matrix: shear, s += shear t", 'k', 'K', 0.25f);
    o.addBool("animate", &animate_, "turn the texture matrix's rotation (window)", 'a');
    o.addText("texture", &texturePath_, "a PNG or BMP file to wrap instead of the gradient", [this](const std::string& v) {
      if (v.empty()) throw ts::Error("--texture: the file name is empty");
      fileTexture_ = ts::fileTexture(v);
    });
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {{"wrap_modes", "Buss VI.4 (seeds 001, 002)",
             "An 8x8 texture on a quad whose (s,t) run from -1 to 2, with the five wrap modes (columns) and GL_NEAREST "
             "/ GL_LINEAR (rows); the unit square is outlined, the border colour is magenta. GL_CLAMP with GL_LINEAR "
             "blends half the border in along the square's edges; GL_CLAMP_TO_EDGE none.",
             {"--view", "modes"}, 1280, 640},
            {"texture_matrix", "Buss VI.4 (seed 001)",
             "The texture matrix: (s,t) rotated by 30 degrees, scaled by 1.5 and sheared by 0.25 about the texture's "
             "centre (glMatrixMode(GL_TEXTURE)). Left: texture space with the image of the unit square; right: the quad.",
             {"--view", "matrix", "--rotate", "30", "--scale", "1.5", "--shear", "0.25", "--wrap-s", "mirrored"}, 1024, 512},
            {"texture_environment", "Buss VI.4 (texture environment)",
             "A plane lit per vertex (orange, a white highlight) under an RGBA texture, combined by each texture "
             "environment (GL_BLEND with GL_TEXTURE_ENV_COLOR light blue; GL_DECAL's texture has an alpha ramp). "
             "GL_MODULATE multiplies the highlight by the texel; GL_SEPARATE_SPECULAR_COLOR adds it after texturing.",
             {"--view", "env"}, 1200, 520}};
  }
  // The animation turns the `rotate` option itself, 30 degrees a second, so
  // the window keeps drawing and F12 saves the state it shows; the frame the
  // key is taken on is left still, so the state line printed for the key is
  // the state the key made.
  void update(double seconds) override {
    if (!animate_) animFrames_ = 0;
    else if (++animFrames_ > 1) xf_.angleDeg = float(std::remainder(xf_.angleDeg + 30.0 * seconds, 360.0));
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;

 private:
  ts::TextureDesc texture(GLenum s, GLenum t, bool linear) const {
    ts::TextureDesc d = texturePath_.empty() ? ts::gradientTexture(npot_ ? 7 : 8, npot_ ? 5 : 8) : fileTexture_;
    d.wrapS = s, d.wrapT = t;
    d.minFilter = d.magFilter = linear ? GL_LINEAR : GL_NEAREST;
    d.border = kBorderColour;
    return d;
  }
  glm::mat4 matrix() const {
    wrapmath::TexTransform x = xf_;
    x.scale.y = x.scale.x;
    return wrapmath::textureMatrix(x);
  }
  // The texture-space picture: the quad over [lo, hi]^2, the integer grid,
  // the unit square (or its image under the texture matrix).
  void addTextureSpace(ts::Frame& f, const ts::Rect& vp, const std::string& id, int tex, bool matrixOutline) const;
  int mismatchPass(ts::Renderer& r, GLenum mode, int w, int h, Found* found) const;

  // The environment view: a plane lit per vertex (wrap_math.hpp's phong)
  // under the RGBA texture, in mode `env`; `separate` sends the specular part
  // as the secondary colour (GL_COLOR_SUM), else it is in the primary colour.
  ts::Frame envFrame(int width, int height, const Found* found) const;
  int view_ = 0, wrapS_ = 1, wrapT_ = 1, filter_ = 0, env_ = 1;
  bool separate_ = true;
  float range_ = 1.0f;
  bool npot_ = false, animate_ = false;
  long animFrames_ = 0;
  wrapmath::TexTransform xf_;
  std::string texturePath_;
  ts::TextureDesc fileTexture_;
};

void WrapModes::addTextureSpace(ts::Frame& f, const ts::Rect& vp, const std::string& id, int tex, bool matrixOutline) const {
  const float lo = -range_, hi = 1.0f + range_;
  ts::Panel p;
  p.id = id;
  p.viewport = vp;
  p.projection = glm::ortho(lo, hi, lo, hi, -1.0f, 1.0f);
  p.batches.push_back(stQuad({lo, lo}, {hi, hi}, {lo, lo}, {hi, hi}, tex));
  std::vector<glm::vec2> grid;
  for (int k = int(std::ceil(lo)); k <= int(std::floor(hi)); ++k)
    grid.insert(grid.end(), {{float(k), lo}, {float(k), hi}, {lo, float(k)}, {hi, float(k)}});
  p.batches.push_back(ts::lineSegments(grid, kGrid, 1.0f, "integer_grid"));
  std::vector<glm::vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  if (matrixOutline)  // where the quad's corners land in texture space: M (s, t, 0, 1)
    for (auto& c : square) c = glm::vec2(wrapmath::transformST(matrix(), c.x, c.y));
  p.batches.push_back(ts::lineLoop(square, kSquare, 2.0f, "unit_square"));
  f.panels.push_back(p);
}

ts::Frame WrapModes::build(int width, int height, const ts::Measurements& measured) const {
  namespace L = ts::layout;
  ts::Frame f;
  f.width = width, f.height = height;
  f.clearColor = {0.12f, 0.12f, 0.14f, 1.0f};
  const Found* found = measured.detailAs<Found>();
  const L::Box area{6, 6, float(width) - 6, float(height) - 6};
  if (view_ == 0) {  // the book figure: columns = modes, rows = filters
    L::FlowSpec spec;
    spec.n = 10, spec.linesAbove = 1, spec.linesBelow = 1, spec.gap = 8;
    std::vector<L::Cell> cells = L::flow(area, spec);
    for (int k = 0; k < 10; ++k) {
      const int m = k % 5;
      const bool linear = k >= 5;
      int tex = f.addTexture(texture(kModes[m], kModes[m], linear));
      addTextureSpace(f, cells[size_t(k)].picture, std::string(kModeNames[m]) + (linear ? "_linear" : "_nearest"), tex, false);
      L::caption(f, cells[size_t(k)].above, std::string(kModeGL[m]) + (linear ? " linear" : " nearest"), kWhite,
                 cells[size_t(k)].scale);
      std::string note;
      if (found && linear && m >= 2) note = "border at s=0: " + fmt("%.0f%%", found->borderAt0.at(m));
      else if (found && !linear) note = fmt("%.0f texel mismatches", found->mismatches.at(m));
      if (!note.empty()) L::caption(f, cells[size_t(k)].below, note, kMeasured, cells[size_t(k)].scale);
    }
    return f;
  }
  if (view_ == 3) return envFrame(width, height, found);
  const GLenum ws = kModes[wrapS_], wt = kModes[wrapT_];
  int tex = f.addTexture(texture(ws, wt, filter_ == 1));
  const std::string state = std::string("s ") + kModeGL[wrapS_] + ", t " + kModeGL[wrapT_];
  if (view_ == 1) {
    L::FlowSpec spec;
    spec.n = 1, spec.linesAbove = 1, spec.linesBelow = 2;
    L::Cell c = L::flow(area, spec)[0];
    addTextureSpace(f, c.picture, "texture_space", tex, false);
    // The quad's fragment colours run from orange to blue: the environment
    // (key e) combines them with the texels, GL_BLEND with kEnvColour.
    ts::Batch& q = f.panels.back().batches.front();
    q.texEnv = kEnvs[env_];
    q.envColor = kEnvColour;
    for (auto& v : q.vertices) v.color = glm::mix(glm::vec4(0.95f, 0.6f, 0.2f, 1), glm::vec4(0.3f, 0.5f, 0.95f, 1), v.pos.x > 0.5f ? 1.0f : 0.0f);
    L::caption(f, c.above, state + (filter_ ? ", linear, " : ", nearest, ") + kEnvGL[env_], kWhite, c.scale);
    if (found)
      L::caption(f, c.below,
                 fmt("seed 002's MIRROR differs from GL_MIRRORED_REPEAT at %.0f", found->seedDiffers) +
                     fmt(" of %.0f integer s (the opposite edge)", found->integers),
                 kMeasured, c.scale);
    return f;
  }
  // The texture matrix: texture space with the image of the unit square,
  // and the quad (s,t in [0,1]) drawn with M on the texture matrix stack.
  L::FlowSpec spec;
  spec.n = 2, spec.linesAbove = 1, spec.linesBelow = 1;
  std::vector<L::Cell> cells = L::flow(area, spec);
  addTextureSpace(f, cells[0].picture, "texture_space", tex, true);
  L::caption(f, cells[0].above, "texture space: M (unit square)", kWhite, cells[0].scale);
  L::caption(f, cells[0].below, state, kWhite, cells[0].scale);
  ts::Panel q;
  q.id = "quad";
  q.viewport = cells[1].picture;
  q.projection = glm::ortho(-0.1f, 1.1f, -0.1f, 1.1f, -1.0f, 1.0f);
  ts::Batch b = stQuad({0, 0}, {1, 1}, {0, 0}, {1, 1}, tex);
  b.textureMatrix = matrix();
  q.batches.push_back(b);
  f.panels.push_back(q);
  L::caption(f, cells[1].above,
             fmt("glMatrixMode(GL_TEXTURE): rotate %.0f", xf_.angleDeg) + fmt(", scale %.2f", xf_.scale.x) +
                 fmt(", shear %.2f", xf_.shear) + fmt(", shift %.3f", xf_.shift.x),
             kWhite, cells[1].scale);
  if (found && found->matrixMismatches >= 0)
    L::caption(f, cells[1].below, fmt("%.0f probe texels differ from M applied on the CPU", found->matrixMismatches),
               kMeasured, cells[1].scale);
  return f;
}

ts::Frame WrapModes::envFrame(int width, int height, const Found* found) const {
  namespace L = ts::layout;
  ts::Frame f;
  f.width = width, f.height = height;
  f.clearColor = {0.12f, 0.12f, 0.14f, 1.0f};
  L::FlowSpec spec;
  spec.n = 6, spec.linesAbove = 1, spec.linesBelow = 1, spec.gap = 8;
  std::vector<L::Cell> cells = L::flow({6, 6, float(width) - 6, float(height) - 6}, spec);
  // The texture: RGBA with an alpha ramp for GL_DECAL (whose alpha is the
  // fragment's, so the picture stays opaque); opaque for the others, whose
  // alpha would be At or Af At and show the page through the figure (the
  // measurement checks every mode's alpha on a grid instead).
  ts::TextureDesc opaque = texture(GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, true), ramp = opaque;
  if (texturePath_.empty()) {
    ramp = ts::gradientTexture(npot_ ? 7 : 8, npot_ ? 5 : 8, true);
    ramp.wrapS = ramp.wrapT = GL_CLAMP_TO_EDGE;
  }
  const int texOpaque = f.addTexture(opaque), texRamp = f.addTexture(ramp);
  const int n = 16;  // 16 x 16 cells; the highlight's centre is vertex (8, 8)
  const glm::dvec3 light(0.5, 0.5, 0.6), colour(0.9, 0.55, 0.25);
  for (int k = 0; k < 6; ++k) {
    const GLenum env = k < 5 ? kEnvs[k] : GL_MODULATE;
    const bool sep = k == 5 && separate_;
    ts::Panel p;
    p.id = k < 5 ? std::string("env_") + kEnvNames[k] : "env_separate_specular";
    p.viewport = cells[size_t(k)].picture;
    p.projection = glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f);
    ts::Batch b;
    b.role = "lit_surface";
    b.texture = env == GL_DECAL ? texRamp : texOpaque;
    b.texEnv = env;
    b.envColor = kEnvColour;
    b.colorSum = sep;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (glm::ivec2 c : {glm::ivec2(0, 0), {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}) {
          glm::dvec3 pos(double(i + c.x) / n, double(j + c.y) / n, 0.0);
          wrapmath::Lit lit = wrapmath::phong(pos, {0, 0, 1}, light, light, colour, 0.25, 40.0);
          ts::Vertex v;
          v.pos = glm::vec3(pos);
          v.tex = {pos.x, pos.y, 0, 1};
          glm::dvec3 primary = sep ? lit.diffuse : glm::min(lit.diffuse + lit.specular, glm::dvec3(1.0));
          v.color = glm::vec4(glm::vec3(primary), 1.0f);
          v.secondary = glm::vec3(float(sep ? lit.specular : 0.0));
          b.vertices.push_back(v);
        }
    p.batches.push_back(b);
    f.panels.push_back(p);
    const L::Cell& cell = cells[size_t(k)];
    L::caption(f, cell.above, k < 5 ? kEnvGL[k] : sep ? "MODULATE + SEPARATE_SPECULAR" : "MODULATE (single colour)", kWhite,
               cell.scale);
    std::string note;
    if (found && found->peak[0] >= 0 && (k == 1 || k == 5))
      note = fmt("highlight peak %.2f", found->peak[k == 5 && separate_ ? 1 : 0]);
    else if (found && k == 0 && found->envMismatches >= 0)
      note = fmt("table: %.0f mismatches", found->envMismatches);
    if (!note.empty()) L::caption(f, cell.below, note, kMeasured, cell.scale);
  }
  return f;
}

// Texel-index renders of mode `mode` on a w x h texture: pass 1, the quad
// over [lo, hi]^2 at two pixels per texel (centres a quarter texel inside);
// pass 2, one pixel per integer s, each a quad of constant s = k.  Returns
// the mismatches with the formula; counts seed 002's MIRROR differences.
int WrapModes::mismatchPass(ts::Renderer& r, GLenum mode, int w, int h, Found* found) const {
  const int lo = int(std::floor(-range_)), hi = int(std::ceil(1.0f + range_)), n = hi - lo;
  auto decoded = [](ts::Rgba c) {
    int i, j;
    ts::decodeTexelIndex(c, &i, &j);
    return glm::ivec2(i == 4095 ? wrapmath::kBorder : i, j == 4095 ? wrapmath::kBorder : j);
  };
  int bad = 0;
  {
    ts::Frame f;
    f.width = 2 * n * w, f.height = 2 * n * h;
    int tex = f.addTexture(indexTexture(w, h, mode));
    ts::Panel p;
    p.viewport = {0, 0, f.width, f.height};
    p.projection = glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f);
    p.batches.push_back(stQuad({0, 0}, {1, 1}, {lo, lo}, {hi, hi}, tex));
    f.panels.push_back(p);
    ts::Image img = r.renderOffscreen(f);
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) {
        double s = lo + n * (x + 0.5) / f.width, t = lo + n * (f.height - y - 0.5) / f.height;
        glm::ivec2 want(wrapmath::nearestTexel(mode, s, w), wrapmath::nearestTexel(mode, t, h));
        glm::ivec2 got = decoded(img.at(x, y));
        if (want.x == wrapmath::kBorder || want.y == wrapmath::kBorder) want = glm::ivec2(wrapmath::kBorder);
        if (got.x == wrapmath::kBorder || got.y == wrapmath::kBorder) got = glm::ivec2(wrapmath::kBorder);
        bad += got != want;
      }
  }
  ts::Frame f;
  f.width = n + 1, f.height = 1;
  int tex = f.addTexture(indexTexture(w, h, mode));
  ts::Panel p;
  p.viewport = {0, 0, f.width, 1};
  p.projection = glm::ortho(0.0f, float(f.width), 0.0f, 1.0f, -1.0f, 1.0f);
  const double t = 0.3;  // t inside the texture, away from texel boundaries for the sizes used
  for (int k = 0; k <= n; ++k) p.batches.push_back(stQuad({k, 0}, {k + 1, 1}, {lo + k, t}, {lo + k, t}, tex));
  f.panels.push_back(p);
  ts::Image img = r.renderOffscreen(f);
  for (int k = 0; k <= n; ++k) {
    glm::ivec2 got = decoded(img.at(k, 0));
    bad += got.x != wrapmath::nearestTexel(mode, lo + k, w);
    if (mode == GL_MIRRORED_REPEAT && w == 8) {
      ++found->integers;
      found->seedDiffers += got.x != wrapmath::seedMirrorTexel(lo + k, w);
    }
  }
  return bad;
}

ts::Measurements WrapModes::measure(ts::Renderer& r) {
  ts::Measurements out;
  Found found;
  int total = 0;
  for (int m = 0; m < 5; ++m) {
    int bad = mismatchPass(r, kModes[m], 8, 8, &found);
    int npot = mismatchPass(r, kModes[m], 37, 23, &found);
    found.mismatches[m] = bad + npot;
    total += bad + npot;
    out.push_back({std::string("texel_mismatches[") + kModeNames[m] + "]", double(bad), "pixels whose texel differs from the formula (8x8)"});
    out.push_back({std::string("npot_texel_mismatches[") + kModeNames[m] + "]", double(npot), "the same on a 37x23 texture"});
  }
  out.insert(out.begin(), ts::Measurement{"wrap_texel_mismatches", double(total), "every mode, both passes and sizes: pixels whose texel differs from the spec's wrap formula"});
  out.insert(out.begin() + 1, ts::Measurement{"seed_mirror_differs", double(found.seedDiffers), "integer s where seed 002's MIRROR picks another texel than GL_MIRRORED_REPEAT"});
  out.push_back({"seed_mirror_integers", double(found.integers), "integer s compared"});
  // The border's share with GL_LINEAR: a white 8x8 texture, black border,
  // one pixel per probe s at t = 1/2; share = 1 - red.
  const double probes[] = {-0.25, 0.0, 1.0, 1.25};
  const char* const probeNames[] = {"-0.25", "0", "1", "1.25"};
  for (int m = 2; m < 5; ++m) {
    ts::Frame f;
    f.width = 4, f.height = 1;
    ts::TextureDesc white = ts::checkerboard(8, 1, {255, 255, 255, 255}, {255, 255, 255, 255});
    white.wrapS = white.wrapT = kModes[m];
    white.border = {0, 0, 0, 1};
    int tex = f.addTexture(white);
    ts::Panel p;
    p.viewport = {0, 0, 4, 1};
    p.projection = glm::ortho(0.0f, 4.0f, 0.0f, 1.0f, -1.0f, 1.0f);
    for (int k = 0; k < 4; ++k) p.batches.push_back(stQuad({k, 0}, {k + 1, 1}, {probes[k], 0.5}, {probes[k], 0.5}, tex));
    f.panels.push_back(p);
    ts::Image img = r.renderOffscreen(f);
    for (int k = 0; k < 4; ++k) {
      double pct = 100.0 * (1.0 - img.at(k, 0).r / 255.0);
      if (k == 1) found.borderAt0[m] = pct;
      out.push_back({std::string("border_pct[") + kModeNames[m] + "@" + probeNames[k] + "]", pct,
                     fmt("%% border colour read by GL_LINEAR (formula: %.0f)", 100.0 * wrapmath::borderShare(kModes[m], probes[k], 8))});
    }
  }
  // The texture matrix: a 64x64 texel-index render of the unit quad with M,
  // probes on a 9x9 grid, against M applied on the CPU and GL_REPEAT.
  {
    const int N = 64, W = 72;
    ts::Frame f;
    f.width = f.height = W;
    ts::TextureDesc t = ts::texelIndexTexture(N);
    t.wrapS = t.wrapT = GL_REPEAT;
    int tex = f.addTexture(t);
    ts::Panel p;
    p.viewport = {0, 0, W, W};
    p.projection = glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f);
    ts::Batch b = stQuad({0, 0}, {1, 1}, {0, 0}, {1, 1}, tex);
    b.textureMatrix = matrix();
    p.batches.push_back(b);
    f.panels.push_back(p);
    ts::Image img = r.renderOffscreen(f);
    int checked = 0, bad = 0;
    for (int py = 4; py < W; py += 8)
      for (int px = 4; px < W; px += 8) {
        glm::dvec2 st = wrapmath::transformST(matrix(), (px + 0.5) / W, (W - py - 0.5) / W);
        glm::dvec2 u = st * double(N);
        if (std::abs(u.x - std::round(u.x)) < 0.05 || std::abs(u.y - std::round(u.y)) < 0.05) continue;  // on a texel edge
        int i, j;
        ts::decodeTexelIndex(img.at(px, py), &i, &j);
        ++checked;
        bad += i != wrapmath::nearestTexel(GL_REPEAT, st.x, N) || j != wrapmath::nearestTexel(GL_REPEAT, st.y, N);
      }
    found.matrixMismatches = bad;
    out.push_back({"texture_matrix_mismatches", double(bad), "probe pixels whose texel differs from M (s,t) on the CPU"});
    out.push_back({"texture_matrix_probes", double(checked), "probes compared (those a twentieth of a texel from an edge)"});
  }
  // The environment table: every mode on a grid of 6 fragment colours x 100
  // texels (5 x 5 colours x 4 alphas), one pixel each, read back with its
  // alpha and compared with the table; 1 step of 8 bits is rounding.
  {
    auto img = std::make_shared<ts::Image>(100, 1);
    const int v[5] = {0, 64, 128, 191, 255}, a[4] = {0, 85, 170, 255};
    for (int k = 0; k < 100; ++k) img->set(k, 0, {uint8_t(v[k % 5]), uint8_t(v[(k / 5) % 5]), uint8_t(v[4 - k % 5]), uint8_t(a[k / 25])});
    ts::TextureDesc t;
    t.name = "env_grid";
    t.image = img;
    t.minFilter = t.magFilter = GL_NEAREST;
    const glm::vec4 frags[6] = {{1, 1, 1, 1}, {0, 0, 0, 1}, {0.2f, 0.6f, 1.0f, 0.4f}, {0.8f, 0.4f, 0.2f, 0.0f}, {0.6f, 0.6f, 0.6f, 0.8f}, {1.0f, 0.2f, 0.4f, 1.0f}};
    ts::Frame f;
    f.width = 100, f.height = 30;
    int tex = f.addTexture(t);
    ts::Panel p;
    p.viewport = {0, 0, 100, 30};
    p.projection = glm::ortho(0.0f, 1.0f, 0.0f, 30.0f, -1.0f, 1.0f);
    for (int m = 0; m < 5; ++m)
      for (int c = 0; c < 6; ++c) {
        ts::Batch b = stQuad({0, 29 - (m * 6 + c)}, {1, 30 - (m * 6 + c)}, {0, 0.5}, {1, 0.5}, tex);
        b.texEnv = kEnvs[m];
        b.envColor = kEnvColour;
        for (auto& x : b.vertices) x.color = frags[c];
        p.batches.push_back(b);
      }
    f.panels.push_back(p);
    ts::Image got = r.renderOffscreen(f);
    int bad = 0;
    for (int m = 0; m < 5; ++m) {
      int badMode = 0;
      for (int c = 0; c < 6; ++c)
        for (int k = 0; k < 100; ++k) {
          ts::Rgba tx = img->at(k, 0), g = got.at(k, m * 6 + c);
          glm::dvec4 want = wrapmath::texEnv(kEnvs[m], glm::dvec4(frags[c]), glm::dvec4(tx.r, tx.g, tx.b, tx.a) / 255.0,
                                             glm::dvec4(kEnvColour)) * 255.0;
          badMode += std::abs(g.r - want.r) > 1 || std::abs(g.g - want.g) > 1 || std::abs(g.b - want.b) > 1 ||
                     std::abs(g.a - want.a) > 1;
        }
      bad += badMode;
      out.push_back({std::string("env_mismatches[") + kEnvNames[m] + "]", double(badMode),
                     "of 600 fragment x texel pairs: more than 1 step of 8 bits from the table"});
    }
    found.envMismatches = bad;
    out.push_back({"env_table_mismatches", double(bad), "every mode: pairs more than 1 step of 8 bits from the table"});
  }
  // The highlight: the env view drawn without labels; the brightest pixel
  // (mean of R, G, B) of the GL_MODULATE panel, specular in the primary
  // colour, and of the same with GL_SEPARATE_SPECULAR_COLOR.
  {
    WrapModes v = *this;
    v.view_ = 3;
    for (int k = 0; k < 2; ++k) {
      v.separate_ = k == 1;
      ts::Frame f = v.envFrame(600, 400, nullptr);
      f.labels.clear();
      ts::Image img = r.renderOffscreen(f);
      const ts::Rect vp = f.panel(k == 0 ? "env_modulate" : "env_separate_specular")->viewport;
      double peak = 0;
      for (int y = vp.y; y < vp.y + vp.h; ++y)
        for (int x = vp.x; x < vp.x + vp.w; ++x) {
          ts::Rgba c = img.at(x, y);
          peak = std::max(peak, (c.r + c.g + c.b) / (3.0 * 255.0));
        }
      found.peak[k] = peak;
    }
    out.push_back({"highlight_peak[modulate]", found.peak[0], "brightest pixel (mean RGB) with the specular in the primary colour, times the texel"});
    out.push_back({"highlight_peak[separate_specular]", found.peak[1], "the same with GL_SEPARATE_SPECULAR_COLOR: specular added after texturing"});
  }
  out.detail = found;
  return out;
}
}  // namespace

TM_REGISTER_SCENE(WrapModes);
