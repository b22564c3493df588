// Wrap modes, the texture matrix and the texture environment, measured
// (Buss VI.4; seeds 001, 002).
//
// The claim: outside the unit square, what a texture shows is one
// glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S/T, mode) call, and each
// mode is a formula on the texel index (wrap_modes_math.hpp, from the spec's table
// 8.20): GL_REPEAT i mod N; GL_MIRRORED_REPEAT (N-1) - mirror((i mod 2N) - N);
// GL_CLAMP_TO_EDGE clamp(i, 0, N-1); GL_CLAMP_TO_BORDER clamp(i, -1, N) with
// the border colour outside; GL_CLAMP clamps s to [0,1], and GL_LINEAR then
// blends the border in: half of it at s = 0 and s = 1 (the dark seam),
// where GL_CLAMP_TO_EDGE blends none and GL_CLAMP_TO_BORDER all of it
// outside.  Seed 002's MIRROR program agrees with GL_MIRRORED_REPEAT except
// at integer s, where it returns the opposite edge.  The texture matrix
// (glMatrixMode(GL_TEXTURE); glLoadMatrixf) moves (s,t) before all of it:
// (s', t', r', q') = M (s, t, r, q), here T(shift) R(angle) Sh(shear) S(scale)
// about the texture's centre.  The texture environment (glTexEnvi(
// GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode)) combines fragment colour Cf and
// texel Ct (GL 2.1 table 3.22, RGBA): REPLACE Ct; MODULATE Cf Ct; DECAL
// Cf (1 - At) + Ct At; BLEND Cf (1 - Ct) + Cc Ct (Cc = GL_TEXTURE_ENV_COLOR);
// ADD Cf + Ct.  GL_MODULATE after lighting darkens the highlight under a
// dark texel; GL_SEPARATE_SPECULAR_COLOR adds the specular after texturing.
//
// Keys (each is also a flag, see --help):
//   v  view: modes (5 modes x nearest/linear) | single | matrix | env
//   e  texture environment (single view)   p  separate specular colour (env view)
//   s / t  wrap mode of s / of t (single and matrix views)   f  nearest | linear
//   + / -  range: (s,t) run from -range to 1 + range          n  a 7x5 texture (NPOT)
//   ] / [  } / {  shift s / t of the texture matrix   r / R  rotate   > / <  scale   k / K  shear
//   a  animate the rotation
//
// What the GL does, all in common/gl/render.cpp: Renderer::texture makes the
// glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S/T, mode) and
// GL_TEXTURE_BORDER_COLOR calls; Renderer::draw sends each quad
// (wrap_modes_gl.hpp: stQuad) as glTexCoord4f(s, t, 0, 1) + glVertex3f, s and
// t from -range to 1 + range, loads a batch's texture matrix around it, and
// makes glTexEnvi (with glTexEnvfv(GL_TEXTURE_ENV_COLOR) for GL_BLEND; for
// the separate specular glEnable(GL_COLOR_SUM) and glSecondaryColor3f per
// vertex, lit on the CPU).  Listings: book_figures/wrap_modes.gl.txt,
// texture_matrix.gl.txt, texture_environment.gl.txt.
//
// Measured (measure()): the quad drawn again with a texture whose texels hold
// their indices (common/core/textures.hpp), every pixel's texel against the
// formula, with pixel centres a quarter texel inside and, in a second pass,
// exactly at every integer s (0 mismatches each, for 8x8 and 37x23 texels);
// the texels seed 002's MIRROR picks at the integers (all differ); the share
// of the border colour GL_LINEAR reads at s = -1/4, 0, 1, 5/4 against the
// formula; the texel under probe points with the texture matrix on; each
// texture environment on a grid of fragment colours x texels x alphas
// against the table; the highlight's peak with and without
// GL_SEPARATE_SPECULAR_COLOR.  The passes are in wrap_modes_gl.hpp.
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <map>

#include "common/core/error.hpp"
#include "common/core/layout.hpp"
#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "wrap_modes_math.hpp"
#include "wrap_modes_gl.hpp"
#include "wrap_modes_views.hpp"  // the texture-space panel and the env view's lit planes

namespace {
using wrap::kModes, wrap::kModeNames, wrap::kModeGL;  // the five wrap modes (wrap_modes_math.hpp)
const glm::vec4 kBorderColour{0.85f, 0.1f, 0.75f, 1.0f};
const glm::vec4 &kWhite = ts::layout::kWhite, &kMeasured = ts::layout::kAmber;
using ts::layout::fmt, wrap::stQuad;
using wrap::views::kEnvs, wrap::views::kEnvNames, wrap::views::kEnvGL, wrap::views::kEnvColour;
using wrap::views::Found;  // what measure() found, for the captions

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
    o.addEnum(
        "view", &view_, {"modes", "single", "matrix", "env"},
        "modes: 5 modes x 2 filters; single: one state; matrix: the texture matrix; env: the texture environments",
        'v');
    o.addEnum("env", &env_, std::vector<std::string>(kEnvNames, kEnvNames + 5),
              "texture environment of the single view's quad (on vertex colours)", 'e');
    o.addBool("separate-specular", &separate_,
              "env view, last panel: GL_SEPARATE_SPECULAR_COLOR (specular added after texturing)", 'p');
    o.addEnum("wrap-s", &wrapS_, std::vector<std::string>(kModeNames, kModeNames + 5),
              "wrap mode of s (single and matrix views)", 's');
    o.addEnum("wrap-t", &wrapT_, std::vector<std::string>(kModeNames, kModeNames + 5),
              "wrap mode of t (single and matrix views)", 't');
    o.addEnum("filter", &filter_, {"nearest", "linear"}, "texture filter (single and matrix views)", 'f');
    o.addFloat("range", &range_, 0.0f, 3.0f, "(s,t) run from -range to 1 + range", '+', '-', 0.5f);
    o.addBool("npot", &npot_, "a 7x5 texture instead of 8x8 (non-power-of-two)", 'n');
    o.addFloat("shift", &xf_.shift.x, -1.0f, 1.0f, "texture matrix: shift of s", ']', '[', 0.125f);
    o.addFloat("shift-t", &xf_.shift.y, -1.0f, 1.0f, "texture matrix: shift of t", '}', '{', 0.125f);
    o.addFloat("rotate", &xf_.angleDeg, -180.0f, 180.0f, "texture matrix: rotation of (s,t) in degrees", 'r', 'R',
               15.0f);
    o.addFloat("scale", &xf_.scale.x, 0.25f, 4.0f, "texture matrix: scale of s and t", '>', '<', 0.25f);
    o.addFloat("shear", &xf_.shear, -2.0f, 2.0f, "texture matrix: shear, s += shear t", 'k', 'K', 0.25f);
    o.addBool("animate", &animate_, "turn the texture matrix's rotation (window)", 'a');
    o.addText("texture", &texturePath_, "a PNG or BMP file to wrap instead of the gradient",
              [this](const std::string& v) {
                if (v.empty()) throw ts::Error("--texture: the file name is empty");
                fileTexture_ = ts::fileTexture(v);
              });
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"wrap_modes",
         "Buss VI.4 (seeds 001, 002)",
         "An 8x8 texture on a quad whose (s,t) run from -1 to 2, with the five wrap modes (columns) and GL_NEAREST "
         "/ GL_LINEAR (rows); the unit square is outlined, the border colour is magenta. GL_CLAMP with GL_LINEAR "
         "blends half the border in along the square's edges; GL_CLAMP_TO_EDGE none.",
         {"--view", "modes"},
         1280,
         640,
         "{wrap_texel_mismatches} pixels differ from the wrap formulas; seed 002's MIRROR is wrong at "
         "{seed_mirror_differs} of {seed_mirror_integers} integer s; GL_CLAMP with GL_LINEAR reads "
         "{border_pct[clamp@0]}% border at the edge."},
        {"texture_matrix",
         "Buss VI.4 (seed 001)",
         "The texture matrix: (s,t) rotated by 30 degrees, scaled by 1.5 and sheared by 0.25 about the texture's "
         "centre (glMatrixMode(GL_TEXTURE)). Left: texture space with the image of the unit square; right: the quad.",
         {"--view", "matrix", "--rotate", "30", "--scale", "1.5", "--shear", "0.25", "--wrap-s", "mirrored"},
         1024,
         512,
         "The texture matrix maps (s,t) as M (s,t) on the CPU does: {texture_matrix_mismatches} of "
         "{texture_matrix_probes} probes differ."},
        {"texture_environment",
         "Buss VI.4 (texture environment)",
         "A plane lit per vertex (orange, a white highlight) under an RGBA texture, combined by each texture "
         "environment (GL_BLEND with GL_TEXTURE_ENV_COLOR light blue; GL_DECAL's texture has an alpha ramp). "
         "GL_MODULATE multiplies the highlight by the texel; GL_SEPARATE_SPECULAR_COLOR adds it after texturing.",
         {"--view", "env"},
         1200,
         560,
         "Every environment matches its table ({env_table_mismatches} mismatches); GL_MODULATE dims the "
         "highlight to {highlight_peak[modulate]}, GL_SEPARATE_SPECULAR_COLOR keeps "
         "{highlight_peak[separate_specular]}."}};
  }
  // The animation turns the `rotate` option itself, 30 degrees a second, so the window keeps drawing and
  // F12 saves the state it shows; the frame the key is taken on is left still, so the state line printed
  // for the key is the state the key made.
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
    wrap::TexTransform x = xf_;
    x.scale.y = x.scale.x;
    return wrap::textureMatrix(x);
  }
  // The environment view (wrap_modes_views.hpp): a plane lit per vertex under the RGBA texture in each mode; separate_
  // sends the specular as the secondary colour (GL_COLOR_SUM), else it is in the primary colour.
  ts::Frame envFrame(int width, int height, const Found* found) const {
    // GL_DECAL's texture has an alpha ramp (its alpha is the fragment's: the picture stays opaque); the others'
    // is opaque, or their At / Af At would show the page through (measure() checks every mode's alpha).
    ts::TextureDesc opaque = texture(GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, true), ramp = opaque;
    if (texturePath_.empty()) {
      ramp = ts::gradientTexture(npot_ ? 7 : 8, npot_ ? 5 : 8, true);
      ramp.wrapS = ramp.wrapT = GL_CLAMP_TO_EDGE;
    }
    return wrap::views::envFrame(width, height, opaque, ramp, separate_, found);
  }
  int view_ = 0, wrapS_ = 1, wrapT_ = 1, filter_ = 0, env_ = 0;
  bool separate_ = true, npot_ = false, animate_ = false;
  float range_ = 1.0f;
  long animFrames_ = 0;
  wrap::TexTransform xf_;
  std::string texturePath_;
  ts::TextureDesc fileTexture_;
};

ts::Frame WrapModes::build(int width, int height, const ts::Measurements& measured) const {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(width, height);
  const Found* found = measured.detailAs<Found>();
  const L::Box area{6, 6, float(width) - 6, float(height) - 6};
  if (view_ == 0) {  // the book figure: columns = modes, rows = filters
    // The key of the outlines and the border colour on the bottom line.
    const float keyH = L::lineHeight(1) + 4;
    L::FlowSpec spec;
    spec.n = 10, spec.linesAbove = 1, spec.linesBelow = 1, spec.gap = 8;
    std::vector<L::Cell> cells = L::flow({area.x0, area.y0, area.x1, area.y1 - keyH}, spec);
    L::legend(f, {area.x0 + 4, area.y1 - keyH + 4, area.x1, area.y1},
              {{wrap::views::kSquare, "the unit square, s and t in [0,1]"},
               {wrap::views::kGrid, "integer s and t"},
               {kBorderColour, "the border colour (GL_TEXTURE_BORDER_COLOR)"}},
              1);
    for (int k = 0; k < 10; ++k) {
      const int m = k % 5;
      const bool linear = k >= 5;
      int tex = f.addTexture(texture(kModes[m], kModes[m], linear));
      wrap::views::addTextureSpace(f, cells[size_t(k)].picture,
                                   std::string(kModeNames[m]) + (linear ? "_linear" : "_nearest"), tex, range_);
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
    wrap::views::addTextureSpace(f, c.picture, "texture_space", tex, range_);
    // Fragment colours orange to blue: the environment (key e) combines them with the texels, GL_BLEND with kEnvColour.
    ts::Batch& q = f.panels.back().batches.front();
    q.texEnv = kEnvs[env_];
    q.envColor = kEnvColour;
    for (auto& v : q.vertices)
      v.color = glm::mix(glm::vec4(0.95f, 0.6f, 0.2f, 1), glm::vec4(0.3f, 0.5f, 0.95f, 1),
                         v.pos.x > 0.5f ? 1.0f : 0.0f);
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
  // Two lines above: the left title and the key of its lines; the call that loads M and its parameters.
  L::FlowSpec spec;
  spec.n = 2, spec.linesAbove = 2, spec.linesBelow = 1;
  std::vector<L::Cell> cells = L::flow(area, spec);
  const glm::mat4 m = matrix();
  wrap::views::addTextureSpace(f, cells[0].picture, "texture_space", tex, range_, &m);
  L::caption(f, L::halves(cells[0].above).first, "texture space: M (unit square)", kWhite, cells[0].scale);
  L::legend(f, L::halves(cells[0].above).second,
            {{wrap::views::kSquare, "the unit square under M"}, {wrap::views::kGrid, "integer s and t"}},
            cells[0].scale);
  L::caption(f, cells[0].below, state, kWhite, cells[0].scale);
  ts::Panel q;
  q.id = "quad";
  q.viewport = cells[1].picture;
  q.projection = glm::ortho(-0.1f, 1.1f, -0.1f, 1.1f, -1.0f, 1.0f);
  ts::Batch b = stQuad({0, 0}, {1, 1}, {0, 0}, {1, 1},
                       tex);  // glTexCoord4f(s, t, 0, 1) in Renderer::draw, GL then applies M
  b.textureMatrix = matrix();
  q.batches.push_back(b);
  f.panels.push_back(q);
  // The call above, the state's parameters below it, as set (%g: no digits the option does not have).
  L::caption(f, L::halves(cells[1].above).first, "glMatrixMode(GL_TEXTURE)", kWhite, cells[1].scale);
  L::caption(f, L::halves(cells[1].above).second,
             "rotate " + L::given("texture matrix: rotation, degrees", xf_.angleDeg, "%g") + ", scale " +
                 L::given("texture matrix: scale of s and t", xf_.scale.x, "%g") + ", shear " +
                 L::given("texture matrix: shear, s += shear t", xf_.shear, "%g") + ", shift (" +
                 L::given("texture matrix: shift of s", xf_.shift.x, "%g") + ", " +
                 L::given("texture matrix: shift of t", xf_.shift.y, "%g") + ")",
             kWhite, cells[1].scale);
  if (found && found->matrixMismatches >= 0)
    L::caption(f, cells[1].below,
               L::measuredText(measured,
                               "{texture_matrix_mismatches|%.0f} of {texture_matrix_probes|%.0f} probe texels differ "
                               "from M applied on the CPU"),
               kMeasured, cells[1].scale);
  return f;
}

// Measured in small offscreen passes (wrap_modes_gl.hpp), each read back and compared with
// wrap_modes_math.hpp's formulas.
ts::Measurements WrapModes::measure(ts::Renderer& r) {
  ts::Measurements out;
  Found found;
  const int lo = int(std::floor(-range_)), hi = int(std::ceil(1.0f + range_));
  wrap::SeedCount seed;
  int total = 0;
  for (int m = 0; m < 5; ++m) {
    int bad = wrap::texelMismatches(r, kModes[m], 8, 8, lo, hi, kModes[m] == GL_MIRRORED_REPEAT ? &seed : nullptr);
    int npot = wrap::texelMismatches(r, kModes[m], 37, 23, lo, hi, nullptr);
    found.mismatches[m] = bad + npot;
    total += bad + npot;
    out.push_back({std::string("texel_mismatches[") + kModeNames[m] + "]", double(bad),
                   "pixels whose texel differs from the formula (8x8)"});
    out.push_back(
        {std::string("npot_texel_mismatches[") + kModeNames[m] + "]", double(npot), "the same on a 37x23 texture"});
  }
  found.seedDiffers = seed.differs, found.integers = seed.integers;
  out.insert(
      out.begin(),
      ts::Measurement{"wrap_texel_mismatches", double(total),
                      "every mode, both passes and sizes: pixels whose texel differs from the spec's wrap formula"});
  out.insert(out.begin() + 1,
             ts::Measurement{"seed_mirror_differs", double(seed.differs),
                             "integer s where seed 002's MIRROR picks another texel than GL_MIRRORED_REPEAT"});
  out.push_back({"seed_mirror_integers", double(seed.integers), "integer s compared"});
  const char* const probeNames[] = {"-0.25", "0", "1", "1.25"};
  for (int m = 2; m < 5; ++m) {
    std::array<double, 4> pct = wrap::borderPercent(r, kModes[m]);
    found.borderAt0[m] = pct[1];
    for (size_t k = 0; k < 4; ++k)
      out.push_back({std::string("border_pct[") + kModeNames[m] + "@" + probeNames[k] + "]", pct[k],
                     fmt("%% border colour read by GL_LINEAR (formula: %.0f)",
                         100.0 * wrap::borderShare(kModes[m], wrap::kEdgeProbes[k], 8))});
  }
  int probes = 0;
  found.matrixMismatches = wrap::matrixMismatches(r, matrix(), &probes);
  out.push_back({"texture_matrix_mismatches", double(found.matrixMismatches),
                 "probe pixels whose texel differs from M (s,t) on the CPU"});
  out.push_back(
      {"texture_matrix_probes", double(probes), "probes compared (those a twentieth of a texel from an edge)"});
  found.envMismatches = 0;
  for (int m = 0; m < 5; ++m) {
    int bad = wrap::envMismatches(r, kEnvs[m], kEnvColour);
    found.envMismatches += bad;
    out.push_back({std::string("env_mismatches[") + kEnvNames[m] + "]", double(bad),
                   "of 600 fragment x texel pairs: more than 1 step of 8 bits from the table"});
  }
  out.push_back({"env_table_mismatches", double(found.envMismatches),
                 "every mode: pairs more than 1 step of 8 bits from the table"});
  // The highlight: the env view without labels, the brightest pixel of the GL_MODULATE panel (specular in
  // the primary colour) and of the same with GL_SEPARATE_SPECULAR_COLOR.
  WrapModes v = *this;
  for (int k = 0; k < 2; ++k) {
    v.separate_ = k == 1;
    ts::Frame f = v.envFrame(600, 400, nullptr);
    f.labels.clear();
    found.peak[k] = wrap::peakBrightness(r.renderOffscreen(f),
                                         f.panel(k == 0 ? "env_modulate" : "env_separate_specular")->viewport);
  }
  out.push_back({"highlight_peak[modulate]", found.peak[0],
                 "brightest pixel (mean RGB) with the specular in the primary colour, times the texel"});
  out.push_back({"highlight_peak[separate_specular]", found.peak[1],
                 "the same with GL_SEPARATE_SPECULAR_COLOR: specular added after texturing"});
  out.detail = found;
  return out;
}
}  // namespace

TS_REGISTER_SCENE(WrapModes);
