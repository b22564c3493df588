// Seed 001 ¶25–32, Buss VI intro — several textures on one surface, before
// and after lighting: alpha cutouts, light maps, gloss maps, AB + CD, the pear.
//
// The claims, each measured on GL's own renders (multitexture_measure.hpp):
//  - the alpha test (glAlphaFunc(GL_GREATER, 0.5)) discards a cutout tree's
//    transparent texels, so they write no depth: drawn first, without it they
//    hide the sky drawn behind them; blending alone hides it too (it needs
//    back-to-front order) but gives soft edges where the test gives hard ones;
//  - a cross tree (two quads at 90°) is never edge-on: its width over a turn
//    is max(|cos θ|, |sin θ|) >= 0.7071, one quad's |cos θ| goes to 0;
//  - a light map: c = base ⊗ L, L at 8² .. 64² against per-pixel lighting;
//    moved by the texture matrix (a spot that travels: key a);
//  - a gloss map: i = t_d ⊗ i_diff + g · i_spec, in two passes; the highlight
//    under g = 1 is 5 times that under g = 0.2, the diffuse unchanged;
//  - AB + CD: two units (GL_COMBINE) make AB in one pass, CD added in a
//    second; one unit needs an intermediate buffer (a copy to a texture):
//    the framebuffer alone makes (AB + C) D;
//  - the pear, i = t_d ⊗ i_diff + t_g · t_r: one pass with
//    GL_ATI_texture_env_combine3's GL_MODULATE_ADD_ATI (A·C + B), two without.
//
// Keys (each is also a flag, see --help):
//   v  view: alpha | lightmap | gloss | abcd     a  animate the spot
//   s / S  the spot's position (0..11)          (--texture FILE: the base picture)
//
// The GL that carries it (Frames, multitexture_frames.hpp, drawn by common/gl/render.cpp):
//   glEnable(GL_ALPHA_TEST); glAlphaFunc(GL_GREATER, 0.5f);
//   glActiveTexture(GL_TEXTURE1); glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
//   glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE);     // PREVIOUS x TEXTURE = AB
//   glBlendFunc(GL_ONE, GL_ONE);                                // + CD, + g i_spec
//   glBlendFunc(GL_DST_COLOR, GL_ZERO);                         // x B, one unit
//   AB stored: a texture rendered from a frame of its own (a nested frame, multitexture_frames.hpp)
//   glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE_ADD_ATI);  // t_r t_g + t_d i_diff
//   glActiveTexture(GL_TEXTURE1); glMatrixMode(GL_TEXTURE); glLoadMatrixf(M1);  // the moving spot
// Listings: book_figures/alpha_cutout_tree.gl.txt, light_map_resolution.gl.txt, gloss_map.gl.txt,
// multitexture_ab_cd.gl.txt.
#include <string>

#include "common/core/error.hpp"
#include "common/core/layout.hpp"
#include "demos/multitexture/multitexture_textures.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/core/user_texture.hpp"
#include "common/gl/render.hpp"
#include "multitexture_gl.hpp"
#include "multitexture_math.hpp"
#include "multitexture_measure.hpp"
#include "multitexture_views.hpp"

namespace {
using namespace mt;
using ts::layout::fmt;
namespace L = ts::layout;

class Multitexture final : public ts::Scene {
 public:
  std::string id() const override { return "multitexture"; }
  std::string title() const override { return "Seed 001 - multitexturing: alpha, light maps, gloss maps, AB + CD"; }
  std::string about() const override {
    return "Several textures on one surface, each measured on GL's renders: a cutout tree with and without the alpha\n"
           "test (the sky its transparent texels hide: 0 with the "
           "test), a cross tree's width over a turn (never below\n"
           "0.7071), light maps of 8^2 to 64^2 against per-pixel lighting, a gloss map's highlights (ratio 5 for\n"
           "g = 1 and 0.2), AB + CD with two texture units, with one unit and a stored copy, and with the framebuffer\n"
           "alone ((AB + C) D), and the pear t_d i_diff + t_g t_r in one GL_MODULATE_ADD_ATI stage against two passes.";
  }
  int defaultWidth() const override { return 1280; }
  int defaultHeight() const override { return 440; }
  std::vector<std::string> claim() const override {
    if (view_ == 0) return {"cutout_hidden_px*", "cross_tree_min_width"};
    if (view_ == 1) return {"light_map_rms*"};
    if (view_ == 2) return {"gloss_peak_ratio", "pear_passes*"};
    return {"abcd_max_diff*", "abcd_passes*"};
  }

  void addOptions(ts::Options& o) override {
    o.addEnum("view", &view_, {"alpha", "lightmap", "gloss", "abcd"},
              "cutout and cross trees | light maps | gloss map and the pear | AB + CD", 'v');
    o.addBool("animate", &animate_, "move the spot (the light map's texture matrix) around the wall", 'a');
    o.addInt("spot", &spot_, 0, kSpotFrames - 1, "the spot's position on its circle, in twelfths", 's', 'S', 1);
    picture_.addOption(o, "the bricks (the light map's and the gloss map's base)");
  }

  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"alpha_cutout_tree",
         "Seed 001 (multitexturing: alpha)",
         "A cutout tree drawn before the sky behind it: without the alpha test its transparent texels write depth and "
         "hide the sky; blending hides it too; the alpha test discards them.  Its edge magnified: blending mixes sky "
         "and tree, the test cuts.  A cross tree at 0, 30 and 45 degrees.",
         {"--view", "alpha"},
         1280,
         440,
         "Drawn first, the tree's transparent texels hide "
         "{cutout_hidden_px[no_alpha_test]} sky pixels without the alpha "
         "test, {cutout_hidden_px[alpha_test]} with it; a cross tree is never narrower than {cross_tree_min_width} "
         "(one quad: {single_quad_min_width})."},
        {"light_map_resolution",
         "Seed 001 (multitexturing: light maps)",
         "A wall's bricks times a light map of 8^2, 16^2, 32^2 and 64^2 texels (unit 1, GL_MODULATE, bilinear) against "
         "the CPU's per-pixel lighting; last, a spot light map moved by the texture matrix.",
         {"--view", "lightmap", "--spot", "2"},
         1280,
         360,
         "RMS against per-pixel lighting: {light_map_rms[8]} levels at 8^2 ({light_map_bytes[8]} bytes), "
         "{light_map_rms[64]} at 64^2 ({light_map_bytes[64]} bytes)."},
        {"gloss_map",
         "Seed 001 (multitexturing: gloss maps, the pear)",
         "A plane lit by two lights, diffuse only, then with the gloss map (g = 1 left, 0.2 right) times the specular "
         "added in a second pass, the specular alone (x 2); the pear t_d i_diff + t_g t_r in one "
         "GL_MODULATE_ADD_ATI stage and in two passes.",
         {"--view", "gloss"},
         1280,
         360,
         "The highlight under g = 1 is {gloss_peak_ratio} times the one under g = 0.2, the diffuse unchanged; the pear "
         "takes {pear_passes[combine3]} pass with GL_ATI_texture_env_combine3, {pear_passes[two_passes]} without."},
        {"multitexture_ab_cd",
         "Seed 001 (multitexturing: AB + CD)",
         "A, B, C, D; AB + CD on the CPU; with two texture units and an additive pass; with one unit, a multiplying "
         "blend and a stored copy; with the framebuffer alone, which makes (AB + C) D; that one's error x 4.",
         {"--view", "abcd"},
         1280,
         330,
         "Two units: {abcd_passes[multitexture]} passes, within {abcd_max_diff[multitexture]} level of the CPU; one "
         "unit and a copy: {abcd_passes[stored]} passes, within {abcd_max_diff[stored]}; the framebuffer alone is off "
         "by {abcd_max_diff[framebuffer_only]} levels."},
    };
  }

  void update(double seconds) override {
    if (!animate_) return;
    clock_ += seconds;
    if (clock_ >= 0.25) clock_ = 0, spot_ = (spot_ + 1) % kSpotFrames;
  }
  bool animating() const override { return animate_; }

  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override {
    ts::Measurements ms;
    ts::Image base = basePicture();
    if (picture_.active()) base = ts::resizeBilinear(picture_.image(), 128, 128);
    ms.detail = runAll(r, base, picture_.active(), ms);
    return ms;
  }

 private:
  int view_ = 0, spot_ = 0;
  bool animate_ = false;
  double clock_ = 0;
  ts::UserTexture picture_;  // --texture FILE
};

ts::Frame Multitexture::build(int width, int height, const ts::Measurements& measured) const {
  ts::Frame f = ts::layout::blankFrame(width, height);
  const Result* m = measured.detailAs<Result>();
  if (!m) {
    ts::layout::caption(f, {8, 8, float(width - 8), float(height - 8)}, "rendering ...", ts::layout::kWhite, 2);
    return f;
  }
  // A label's numbers are the measurements it names (layout::measuredText).
  auto M = [&](const std::string& templ) { return ts::layout::measuredText(measured, templ); };
  if (view_ == 0) {
    views::pictures(f,
                    {{{}, "no alpha test", M("{cutout_hidden_px[no_alpha_test]|%.0f} sky pixels hidden")},
                     {{},
                      "GL_GREATER " + L::given("glAlphaFunc's reference", frames::kAlphaRef, "%g"),
                      M("{cutout_hidden_px[alpha_test]|%.0f} hidden")},
                     {{}, "blending, no test", M("{cutout_hidden_px[blend]|%.0f} hidden")},
                     {{}, "edge x16, blending", M("{edge_fringe_px[blend]|%.0f} fringe pixels")},
                     {{}, "edge x16, alpha test", M("{edge_fringe_px[alpha_test]|%.0f} fringe pixels")},
                     {{},
                      "cross tree, " + L::given("the tree's turn, degrees", frames::kCrossTurnDeg, "%g") + " deg",
                      M("width >= {cross_tree_min_width|%.4f}")}},
                    1.0f,
                    "Cutout tree drawn first, then the sky behind it (depth test).  Silhouette width over a full turn "
                    "(orthographic, 5-degree steps): one quad " +
                        M("{single_quad_min_width|%.4f}") + " .. " + M("{single_quad_max_width|%.4f}") +
                        " (|cos|), cross tree " + M("{cross_tree_min_width|%.4f}") + " .. " +
                        M("{cross_tree_max_width|%.4f}") + " (max(|cos|, |sin|) >= " +
                        L::given("cos 45 deg", std::cos(glm::radians(45.0)), "%.4f") + ").");
    // The cutout passes are the Frames measure() rendered (multitexture_frames.hpp), drawn in their panels.
    const ts::Image tree = treeTexture();
    for (ts::Panel& p : f.panels)
      for (int k = 0; k < 6; ++k)
        if (p.id == "picture_" + std::to_string(k))
          p = k < 3   ? frames::hiddenPanel(f, tree, k, p.id, p.viewport)
              : k < 5 ? frames::edgePanel(f, tree, k == 3 ? kBlend : kAlphaTest, p.id, p.viewport)
                      : frames::crossTreePanel(f, frames::kCrossTurnDeg, p.id, p.viewport);
  } else if (view_ == 1) {
    // The light-mapped walls and the spot are Frames (multitexture_frames.hpp); the CPU's picture a generator.
    std::vector<views::Picture> ps = {{m->userBase ? m->perPixel : ts::Image(), "per-pixel (CPU)", "base x lighting"}};
    if (!m->userBase) ps[0].texture = ts::multitex::perPixelLitTexture(256);
    for (int k = 0; k < 4; ++k) {
      const std::string n = std::to_string(kLightSizes[k]);
      const L::Text side = L::given("the light map's side, texels", kLightSizes[k], "%g");
      ps.push_back({{}, "light map " + side + "^2", M("RMS {light_map_rms[" + n + "]|%.2f}, ") + side + "^2 bytes"});
    }
    ps.push_back({{},
                  "spot, texture matrix",
                  "position " + L::given("the spot's frame", spot_, "%g") + (animate_ ? " (moving)" : "")});
    views::pictures(f, ps, 1.0f,
                    "c = base x L: unit 0 the bricks (GL_REPLACE), unit 1 the light map (GL_MODULATE, GL_LINEAR); the "
                    "light a point at height " +
                        L::given("the light's height over the wall", ts::multitex::kLightHeight, "%g") +
                        " over the centre, L its irradiance at the texel centres (1 byte a texel).");
    for (ts::Panel& p : f.panels)
      for (int k = 1; k <= 5; ++k)
        if (p.id == "picture_" + std::to_string(k))
          p.batches = {
              frames::lightMapped(f, m->base, m->userBase, k < 5 ? kLightSizes[k - 1] : 0, spot_, kSpotFrames)};
  } else if (view_ == 2) {
    // The pears are a nested frame (multitexture_frames.hpp pearsFrame): its picture is GL's render, and the
    // sidecar holds the frame, so the reference recomputes it (TextureDesc::renderedFrom).
    ts::TextureDesc pears = ts::renderedImageTexture(m->pearsImage, "multitexture", "the pears", "multitexture");
    pears.image = std::make_shared<const ts::Image>(m->pearsImage);  // row 0 the top, as rendered
    pears.renderedFrom = m->pears;
    views::pictures(
        f,
        {{{}, "t_d x i_diff (pass 1)", "the diffuse alone"},
         {{},
          "+ g x i_spec (pass 2, GL_ONE, GL_ONE)",
          "g = " + L::given("the gloss left", 1, "%g") + " left, " +
              L::given("the gloss right", ts::multitex::kGlossLow, "%.1f") + " right"},
         {{}, "the specular added, x 2", M("peaks {gloss_peak[g=1]|%.0f}") + M(" : {gloss_peak[g=0.2]|%.0f}")},
         {{},
          "pear: MODULATE_ADD_ATI | two passes",
          m->combine3 ? M("{pear_passes[combine3]|%.0f} pass") + M(" | {pear_passes[two_passes]|%.0f} passes")
                      : std::string("no GL_ATI_texture_env_combine3 here"),
          m->pearsCalls,
          pears}},
        2.0f,
        "i = t_d x i_diff + g x i_spec in two passes: highlight ratio " + M("{gloss_peak_ratio|%.3f}") + " (g " +
            L::given("the gloss left", 1, "%g") + " / " + L::given("the gloss right", ts::multitex::kGlossLow, "%.1f") +
            " = " + L::given("the glosses' ratio", 1 / ts::multitex::kGlossLow, "%g") + "), diffuse changed by " +
            M("{gloss_diffuse_change|%.0f}") +
            " levels.  The pear: t_d i_diff + t_g t_r, one combine3 stage against two passes: " +
            M("{pear_combine3_vs_two_passes_max_diff|%.0f}") + " levels apart.");
    // The plane's passes are Frames (multitexture_frames.hpp): diffuse; + g i_spec; g i_spec added twice.
    for (ts::Panel& p : f.panels)
      for (int k = 0; k < 3; ++k)
        if (p.id == "picture_" + std::to_string(k))
          p = frames::glossPanel(f, m->base, m->userBase, k, p.id, p.viewport);
  } else {
    const std::vector<ts::Image> t = abcdTextures();
    const views::Picture cpu({}, "AB + CD (CPU)", "the reference", nullptr, ts::multitex::abcdCpuTexture(128, "sum"));
    const views::Picture error({}, "(AB+C)D - (AB+CD), x 4", M("GL's: RMS {abcd_rms[framebuffer_only]|%.1f} levels"),
                               nullptr, ts::multitex::abcdCpuTexture(128, "error_x4"));
    views::pictures(
        f,
        {{{}, "A B / C D", "the four textures"},
         cpu,
         {{},
          "two units + add",
          M("{abcd_passes[multitexture]|%.0f} passes") + M(", max {abcd_max_diff[multitexture]|%.0f}")},
         {{}, "one unit + a copy", M("{abcd_passes[stored]|%.0f} passes") + M(", max {abcd_max_diff[stored]|%.0f}")},
         {{},
          "framebuffer: (AB+C)D",
          M("{abcd_passes[framebuffer_only]|%.0f} passes") + M(", max {abcd_max_diff[framebuffer_only]|%.0f}")},
         error},
        1.0f,
        "Multiplying needs the framebuffer (GL_DST_COLOR, GL_ZERO), "
        "adding too (GL_ONE, GL_ONE): with one unit, AB must "
        "be stored (a texture rendered first) before CD is made; the sequence A, x B, + C, x D gives (AB + C) D.");
    // The three GL paths are the Frames measure() rendered (multitexture_frames.hpp), drawn in their panels.
    for (int k = kMultitexture; k <= kFramebufferOnly; ++k)
      for (ts::Panel& p : f.panels)
        if (p.id == "picture_" + std::to_string(2 + k)) p.batches = frames::abcdBatches(f, t, k, m->abcdAb);
    for (ts::Panel& p : f.panels)
      if (p.id == "picture_0") p = frames::abcdQuadrants(f, p.id, p.viewport);
  }
  return f;
}
}  // namespace

TS_REGISTER_SCENE(Multitexture);
