// The sources' cost claims, drawn and timed on the student's own GL.
//
// The claims (each the frames common/gl/cost_workloads.cpp draws; tests/bench/bench_costs.cpp times the same
// frames quietly, and the README gives its numbers with a verdict each):
//   1. Buss VI.1.1: hyperbolic (perspective-correct) interpolation "requires extra computation and therefore may
//      be slower" than screen-linear interpolation.
//   2. Buss VI.1, seed 001 §1-2, seed 003's opening: a texture gives detail at a "minimal computational load";
//      the same detail as geometry needs very small polygons.
//   3. Seed 001 §18-19: group polygons by texture; texture switches cost.
//   4. Buss VI.1.3: minified textures read from small mip levels, which stay in fast memory.
// What the picture shows is the same on every machine: each claim's two frames side by side and what differs
// between them, measured (the screen-linear floor against both equations, the grid's triangles against the
// quad's, the binds and draws recorded, the aliasing of a texture minified without mipmaps).  What each frame
// costs depends on the machine, so it is never in the picture: a window times every frame on its own GL, one
// frame a window frame in turn, and the side panel lists cost_ms_per_frame[...] and each claim's
// cost_timed_ratio[...] with its verdict on this machine (supported above 1.1, contradicted below 0.9).
//
// The equations (claim 1): the quad has w = 1 at the bottom, 8 at the top; at a pixel (x, y) in device coordinates
//   smooth (hyperbolic):          1/w = 1 - 7/16 (y + 1),  s = x w / 16,  t = w / 16     (one division a pixel)
//   noperspective (screen-linear): t = (1 + 3.5 (y + 1)) / 16, s affine in each triangle  (no division)
// Claim 4: GL_LINEAR_MIPMAP_LINEAR reads level lambda = log2(16) = 4, 4 x 4 texels pre-averaged per texel; GL_LINEAR
// reads 4 texels of level 0, 16 texels apart: scattered reads, and aliasing.
//
// The GL calls that carry each claim (listing: book_figures/texture_costs.gl.txt, each picture's calls):
//   1. "smooth out vec2 uv;" against "noperspective out vec2 uv;" in the GLSL 1.30 shaders, glDrawElements of 2
//      triangles;
//   2. glDrawElements(GL_TRIANGLES, 6, ...) with a fragment shader that reads the height map, against
//      glDrawElements(GL_TRIANGLES, 390150, ...) of a grid displaced on the CPU;
//   3. glBindTexture(GL_TEXTURE_2D, tex[t]) once per texture (sorted) or once per quad (unsorted);
//   4. glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE) at upload, then
//      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR or GL_LINEAR).
//
// Keys (each is also a flag, see --help):
//   c  the claim shown: all (the figure) | interpolation | detail | switches | minify (its two frames, larger)
// The window times for a few seconds after it opens (the panel says "still timing" until every frame has its
// samples).
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/gl/render.hpp"
#include "texture_costs_measure.hpp"

namespace {
namespace K = ts::costs_demo;
namespace L = ts::layout;

class TextureCosts final : public ts::Scene {
 public:
  std::string id() const override { return "texture_costs"; }
  std::string title() const override { return "What texturing costs: the sources' claims, drawn and timed"; }
  std::string about() const override {
    return "Four cost claims of the sources, each as two frames drawn the same way as the benchmark draws them:\n"
           "hyperbolic against screen-linear interpolation, relief as a bump-mapped quad against a displaced grid,\n"
           "2,048 quads over 32 textures sorted by texture or not, a texture minified 16x with and without mipmaps.\n"
           "The figure measures what each pair shows; a window also times every frame on this machine's GL and\n"
           "lists the ratios, with a verdict per claim, in its panel.";
  }
  std::vector<std::string> claim() const override {
    return {"costs_interp_off_share[noperspective_vs_hyperbolic]", "costs_binds*", "cost_timed_ratio*"};
  }
  void addOptions(ts::Options& o) override {
    o.addEnum("claim", &claim_, {"all", "interpolation", "detail", "switches", "minify"},
              "the claim shown: all four (the figure) | one claim's two frames, larger", 'c');
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {{"texture_costs",
             "What texturing costs: four claims of the sources, drawn (Buss VI.1; seeds 001, 003)",
             "Each claim's two frames, drawn as tests/bench/bench_costs.cpp times them: the quad's texture "
             "coordinate interpolated hyperbolically or screen-linearly; bricks as a bump-mapped quad or a displaced "
             "grid; 2,048 quads bound sorted by texture or not; a texture minified 16x with or without mipmaps. "
             "Timings are machine-dependent: the window's panel and the benchmark give them.",
             {},
             1100,
             760,
             "Screen-linear is off the true floor at {costs_interp_off_share[noperspective_vs_hyperbolic]} of "
             "the pixels; the grid draws {costs_detail_triangles[displaced_grid]} triangles for the quad's "
             "{costs_detail_triangles[bump_quad]}; unsorted binds {costs_binds[unsorted]} times for sorted's "
             "{costs_binds[sorted]}."}};
  }
  // A window times the frames a little each frame until every variant has its samples.
  bool live() const override { return windowed_ && !timerDone_; }
  void update(double) override { windowed_ = true; }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override {
    ts::Measurements m;
    if (!pictures_ || &r != picturesFor_) {
      measured_.clear();
      pictures_ = std::make_shared<K::Pictures>(K::measurePictures(r, measured_));
      picturesFor_ = &r;
    }
    m = measured_;
    if (windowed_) {
      K::Timer& t = r.attachment<K::Timer>();
      t.step();
      t.report(m);
      timerDone_ = t.done();
    }
    m.detail = pictures_;
    return m;
  }

 private:
  int claim_ = 0;
  bool windowed_ = false, timerDone_ = false;
  std::shared_ptr<K::Pictures> pictures_;
  const ts::Renderer* picturesFor_ = nullptr;
  ts::Measurements measured_;
};

ts::Frame TextureCosts::build(int width, int height, const ts::Measurements& measured) const {
  ts::Frame f = L::blankFrame(width, height);
  const auto* held = measured.detailAs<std::shared_ptr<K::Pictures>>();
  const K::Pictures* p = held ? held->get() : nullptr;
  if (!p) {
    L::caption(f, {8, 8, float(width - 8), float(height - 8)}, "rendering ...", L::kWhite, 2);
    return f;
  }
  auto M = [&](const std::string& templ) { return L::measuredText(measured, templ); };
  struct Shown {
    K::Pic pic;
    L::Text title, note;
    bool listed;  // its calls in the listing (the switches' 2,048 draws are not)
  };
  const std::vector<Shown> shown = {
      {K::kSmooth, "1 smooth", M("{costs_interp_off_share[smooth_vs_hyperbolic]|%.3f} off its equation"), true},
      {K::kNoPerspective, "1 noperspective",
       M("{costs_interp_off_share[noperspective_vs_hyperbolic]|%.2f} off the floor"), true},
      {K::kBumpQuad, "2 bump quad", M("{costs_detail_triangles[bump_quad]} triangles"), true},
      {K::kGrid, "2 displaced grid", M("{costs_detail_triangles[displaced_grid]} triangles"), true},
      {K::kSorted, "3 sorted", M("{costs_binds[sorted]} binds"), false},
      {K::kUnsorted, "3 unsorted", M("{costs_binds[unsorted]} binds"), false},
      {K::kMipmapped, "4 mipmapped", M("RMS {costs_minify_rms[mipmapped]|%.1f} levels"), true},
      {K::kUnmipmapped, "4 GL_LINEAR", M("RMS {costs_minify_rms[unmipmapped]|%.1f} (aliasing)"), true}};
  // One claim: its two pictures (the claims' pictures come in pairs, in order).
  std::vector<Shown> picked;
  for (size_t k = 0; k < shown.size(); ++k)
    if (claim_ == 0 || int(k / 2) == claim_ - 1) picked.push_back(shown[k]);
  std::vector<L::Captioned> captions;
  for (const Shown& s : picked) captions.push_back({s.title, s.note});
  const std::vector<L::Text> notes = {
      M("1: the screen-linear floor is {costs_interp_off_share[noperspective_vs_linear]|%.3f} off its own equation.  "
        "2: {costs_detail_off_share[bump_vs_grid]|%.3f} of the pixels differ.  3: {costs_draws[sorted]} draws either "
        "way, {costs_switch_off_px[unsorted_vs_sorted]} px differ; one draw a texture: {costs_draws[sorted_batched]} "
        "draws, {costs_switch_off_px[batched_vs_sorted]} px differ.  4: the mipmapped mean is "
        "{costs_minify_mean_error[mipmapped]|%.1f} levels off the texture's average."),
      "Off: a channel over 16 levels from the equation.  Times differ by machine: the window's panel and the README "
      "give them, never this picture."};
  L::pictureFigure(
      f, captions,
      [&](size_t k, const ts::Rect& r) {
        const K::Run& run = p->runs[size_t(picked[k].pic)];
        ts::TextureDesc t = ts::renderedImageTexture(run.image, "texture_costs", K::kPictureKeys[picked[k].pic],
                                                     "texture_costs");
        t.minFilter = t.magFilter = GL_LINEAR;
        if (picked[k].listed) t.renderedBy = run.calls;
        f.panels.push_back(L::picturePanel(f, std::string("picture_") + K::kPictureKeys[picked[k].pic], r, t));
      },
      {}, notes, {0, 1.0f, 1, 1, 10, 2, 150}, 1, ts::Align::Left);
  return f;
}
}  // namespace

TS_REGISTER_SCENE(TextureCosts);
