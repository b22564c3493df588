// Parallax mapping with anisotropic filtering that knows what the relief
// hides (seed 003, Romanyuk & Archangel 2017), measured against a reference.
//
// The claim of the seed: anisotropic filtering under parallax mapping
// averages, inside the pixel's footprint ellipse, texels that higher relief
// hides from the eye; excluding them (a ray traced per texel, or the cheaper
// walk of each row of the footprint from both ends that stops at the first
// hidden texel) should give truer colours.  The paper never measures it; this
// demo does.  A relief plane (bricks with deep mortar, a synthetic step/ridge
// map, or a flat map) is seen at a grazing angle through parallax occlusion
// mapping (parallax_aniso_gl.hpp) and filtered six ways:
//   M0 naive, texture() (implicit derivatives of the shifted coordinate: the
//   artifact), M1 trilinear and M2 hardware anisotropic 16x (textureGrad with
//   the unshifted gradients; whether the driver's anisotropic filter uses them
//   is measured: llvmpipe's does not), M3 EWA in the shader (Heckbert,
//   texelFetch), M4 EWA without hidden texels (every texel traced), M5 the
//   seed's row walk,
// and compared with R, n x n (--rays; the figures 12 x 12) stratified jittered
// rays per pixel traced finely on the CPU, weighted by the same Gaussian
// kernel (parallax_aniso_math.hpp).  Printed and written as CSV (parallax_aniso_measure.hpp; --csv FILE,
// make_figures writes parallax_modes.csv): PSNR and SSIM over the whole
// frame, the high-anisotropy pixels and the occlusion band (footprints that
// cross an occluding edge), ms per frame, lookups per pixel, the renderer.
//
// The ranking view (v ranking; parallax_aniso_ranking.hpp, its GLSL in
// parallax_aniso_ranking_gl.hpp) measures the seed's other claim, that parallax
// mapping is the most realistic of bump, normal, parallax and displacement
// mapping: the five (parallax both as one offset step and as the march) light
// the same bricks at the same angle, c = albedo (ka + (1 - ka) max(0, N . L)),
// and each is ranked by PSNR against a reference traced through the height
// field and shaded at the true hit with the true normal.  Displacement is real
// geometry: glDrawElements(GL_TRIANGLE_STRIP) of a grid --grid texels fine,
// raised to the heights, with the depth test.  Listing:
// book_figures/parallax_ranking.gl.txt.
//
// Keys (each is also a flag, see --help):
//   m  mode            t  map: bricks | step | flat      a  live view: sweep the azimuth
//   + / -  height scale          ] / [  view angle (elevation)
//   z / Z  azimuth               c  split-screen compare (mode | --against)
//   b  the mode compared against  v  view: single | modes | error | live | ranking | causes | seed-f
//   e / E  ranking view: texels between the displacement grid's vertices
//   r / R  render width          x  max-height pyramid acceleration
//   g  gradients M1/M2 give textureGrad: x1 | x4 (does the filter use them?
//      trilinear blurs; llvmpipe's anisotropic filter does not change)
// The live view (parallax_aniso_live.hpp) draws the mode every frame at the
// window's size: M2 there is what "interactive" is measured on (the overlay,
// h, shows live_ms_per_frame and live_fps).  Flags only: --rays N, --seed,
// --time N (each mode's median of N frames, for the CSV), --csv FILE.
//
// What the GL does (parallax_aniso_gl.hpp: ReliefGL::pass, into an FBO): a GLSL
// program per mode over one glBegin(GL_TRIANGLES) of glVertex2f(±1, ±1), no
// texture coordinates: the camera comes as glUniform3f (eye, fwd, rightV,
// upV), each fragment marches its own ray.  M2 is M1 plus ReliefGL::bind's
// glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 16).
// Listings: book_figures/parallax_modes.gl.txt, parallax_step.gl.txt (each
// mode's pass, then the frame), parallax_error_band.gl.txt (the frame only).
//
// The causes view (parallax_aniso_causes.hpp, _causes_gl.hpp; figure
// parallax_causes and parallax_seed_F, listings book_figures/parallax_causes.gl.txt
// and parallax_seed_F.gl.txt; views causes and seed-f) measures the
// seed's own equations one by one:
//   Eq. (2), corrected:  dU/dx = u(x+1, y) - u(x, y),  dV/dx = v(x+1, y) - v(x, y)
//   of the SHIFTED coordinate, against the Camera's analytic derivatives:
//   a fraction of a texel on the relief, tens of texels at its steps (M0's
//   fringes); the seed's printed dV/dx = v(x+1, y) - u(x, y) is wrong everywhere;
//   Eq. (3), Fig. 3: the footprint area pi F / sqrt(A C - B^2/4) from those
//   differences over the plain one's; Fig. 4: the share of hidden texels in
//   the footprint by its size; Fig. 6: texels the row walk counts twice with
//   and without M5's stop index; and M3 with the seed's F = (Ux Vy + Uy Vx)^2
//   (ts::ewa::glsl(true)) beside the corrected F = (Ux Vy - Uy Vx)^2.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "common/gl/context.hpp"
#include "common/core/error.hpp"
#include "common/gl/figure.hpp"
#include "common/gl/render.hpp"
#include "common/core/textures.hpp"
#include "common/core/layout.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/core/text.hpp"
#include "common/core/user_texture.hpp"
#include "common/core/scene.hpp"
#include "parallax_aniso_measure.hpp"
#include "parallax_aniso_gl.hpp"
#include "parallax_aniso_live.hpp"
#include "parallax_aniso_views.hpp"
#include "parallax_aniso_causes_gl.hpp"
#include "parallax_aniso_math.hpp"
#include "parallax_aniso_ranking.hpp"

namespace {
using namespace pax;
using namespace pax::views;  // the views, what they show (views::Shown, views::Live) and their textures

class ParallaxAniso final : public ts::Scene {
 public:
  std::string id() const override { return "parallax_aniso"; }
  std::string title() const override {
    return "Parallax mapping with visibility-aware anisotropic filtering (seed 003)";
  }
  std::string about() const override {
    return "A relief (bricks with deep mortar, a step/ridge map, or flat) seen at a grazing angle through parallax\n"
           "occlusion mapping, its albedo filtered six ways: M0 naive (implicit derivatives of the shifted\n"
           "coordinate), M1 trilinear, M2 hardware anisotropic 16x, M3 EWA (Heckbert) in the shader, M4 EWA without\n"
           "the texels higher relief hides (every texel traced), M5 the seed's cheaper row walk.  Measured against a\n"
           "reference of n x n traced rays per pixel (same Gaussian kernel): PSNR and SSIM over the frame, the\n"
           "high-anisotropy pixels and the occlusion band; ms per frame and texture lookups per pixel.";
  }
  int defaultWidth() const override { return 1024; }  // fits a laptop's 1280x720 (the figures are larger)
  int defaultHeight() const override { return 560; }

  std::vector<std::string> claim() const override {
    if (view_ == kRanking) return {"relief_rank_psnr_db*", "relief_rank[*"};
    if (view_ == kCauses)
      return {"eq2_derivative_error_texels*", "footprint_area_ratio*", "hidden_texel_share*", "double_counted_texels*"};
    if (view_ == kSeedF) return {"seed_F_error_px", "seed_F_psnr_db"};
    return {"ewa_psnr_all", "ewa_vis_psnr_all"};
  }
  void addOptions(ts::Options& o) override {
    o.addEnum("mode", &mode_,
              {kModeKeys[0], kModeKeys[1], kModeKeys[2], kModeKeys[3], kModeKeys[4], kModeKeys[5], kModeKeys[6]},
              "M0 naive | M1 trilinear | M2 aniso 16x | M3 EWA | M4 EWA visible texels | M5 EWA row walk | "
              "reference",
              'm');
    o.addEnum("map", &map_, {kMaps[0], kMaps[1], kMaps[2]}, "relief: bricks with deep mortar | step/ridge | flat", 't');
    o.addFloat("height-scale", &heightScale_, 0.0f, 0.2f, "depth of the relief, world units (a tile is 2)", '+', '-',
               0.01f);
    o.addFloat("angle", &angle_, 14.0f, 80.0f, "view angle: elevation of the central ray above the plane, degrees", ']',
               '[', 2.0f);
    o.addFloat("azimuth", &azimuth_, -45.0f, 45.0f, "turn of the view about the normal, degrees", 'z', 'Z', 3.0f);
    o.addBool("compare", &compare_, "split screen: left half the mode, right half --against", 'c');
    o.addEnum("against", &against_,
              {kModeKeys[0], kModeKeys[1], kModeKeys[2], kModeKeys[3], kModeKeys[4], kModeKeys[5], kModeKeys[6]},
              "the mode of the right half in split-screen compare", 'b');
    o.addEnum("view", &view_, {"single", "modes", "error", "live", "ranking", "causes", "seed-f"},
              "single: one mode (or the split screen); modes: all seven with their numbers; error: the occlusion "
              "band's error for M2, M3, M4; live: the mode (or the split screen) drawn every frame at the window's "
              "size, timed (no reference, no table); ranking: bump, normal, parallax, parallax occlusion and "
              "displacement mapping lit by one light, ranked against a traced reference "
              "(parallax_aniso_ranking.hpp); causes: seed 003's equations measured one by one (Eq. 2, Eq. 3, "
              "Fig. 4, Fig. 6); seed-f: M3 with the seed's F beside the corrected one",
              'v');
    o.addBool("animate", &animate_, "live view: sweep the azimuth back and forth (10 degrees a second)", 'a');
    o.addInt("res", &res_, 80, 800, "width of the measured renders (height 3/4 of it; the figures use 320)", 'r', 'R',
             80);
    o.addInt("rays", &rays_, 2, 32, "reference rays per side of the kernel square (n x n; the figures use 12)");
    o.addInt("time", &timeRuns_, 0, 50,
             "time each mode over N frames (median, into the CSV's ms_per_frame); 0 = do not time (the figures do "
             "not: a timing would make the gallery differ run to run; bench_parallax times the modes)");
    o.addInt("grid", &gridTexels_, 1, 64, "ranking view: texels between the displacement grid's vertices", 'e', 'E', 1);
    o.addInt("seed", &seed_, 0, 1000000, "seed of the reference's jitter");
    o.addBool("accel", &accel_, "max-height pyramid skip in the visibility trace (same result, fewer lookups)", 'x');
    o.addEnum("gradients", &gradients_, {"x1", "x4"},
              "the gradients M1 and M2 give textureGrad: x1 the unshifted coordinate's, x4 four times longer -- "
              "trilinear M1 turns blurrier; a filter that ignores them (llvmpipe's anisotropic M2) does not change",
              'g');
    picture_.addOption(o, "the albedo (resampled to 512x512)");
    camera_.addOptions(o);  // added to --azimuth and --angle; zoom narrows the field of view
    o.addFile("csv", &csvPath_, "write the measured table as CSV to FILE", [](const std::string& v) {
      if (!v.empty()) ts::checkWritable(v);
    });
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"parallax_modes",
         "Seed 003: parallax + anisotropic filtering",
         "Bricks with deep mortar seen at 20 degrees through parallax occlusion mapping, 320x240 each: M0 naive "
         "lookup (implicit derivatives of the shifted coordinate: fringes along every occluding edge), M1 trilinear, "
         "M2 hardware anisotropic 16x, M3 EWA in the shader, M4 EWA without the texels higher relief hides, M5 the "
         "seed's row walk, and the reference (12x12 traced rays per pixel, the same Gaussian kernel). Under each: "
         "PSNR against the reference over the whole frame and over the occlusion band, and lookups per pixel. The "
         "table is in parallax_modes.csv.",
         {"--view", "modes", "--map", "bricks", "--res", "320", "--rays", "12"},
         1360,
         700,
         "PSNR against the traced reference: M3 EWA {ewa_psnr_all} dB, M4 without hidden texels {ewa_vis_psnr_all} "
         "dB, at {ewa_lookups} and {ewa_vis_lookups} lookups per pixel."},
        {"parallax_error_band",
         "Seed 003: error in the occlusion band",
         "The occlusion band (pixels whose footprint crosses an occluding edge, where the reference's rays hit "
         "depths more than half the relief apart) and the error against the reference inside it for M2 (hardware "
         "anisotropic), M3 (EWA) and M4 (EWA without hidden texels): |error| x4, black none, red 32, yellow 64 "
         "levels or more.",
         {"--view", "error", "--map", "bricks", "--res", "320", "--rays", "12"},
         1360,
         370,
         "PSNR inside the occlusion band ({band_pixels} pixels): M2 {aniso16_psnr_band} dB, M3 {ewa_psnr_band} dB, "
         "M4 {ewa_vis_psnr_band} dB."},
        // The state of parallax_modes but the view: its table and reference are reused (before the step map's).
        {"parallax_causes",
         "Seed 003: its equations, measured",
         "Seed 003's causes on the bricks at 20 degrees, 320x240: Eq. 2's forward differences of the parallax-shifted "
         "coordinate against the analytic derivatives (small on the relief, tens of texels at its steps: the footprint "
         "M0's lookup takes), the seed's printed Eq. 2 (v minus u), the footprint area from the shifted differences "
         "over the plain one (Eq. 3, Fig. 3), the share of hidden texels in the footprint by its size (Fig. 4), and "
         "in the notes the texels the row walk counts twice with and without its buffer (Fig. 6).",
         {"--view", "causes", "--map", "bricks", "--res", "320", "--rays", "12"},
         1360,
         520,
         "Eq. 2 on the shifted coordinate errs by {eq2_derivative_error_texels[frame]} texels (median) over the "
         "frame, {eq2_derivative_error_texels[steps]} at steps; the footprint's hidden share rises from "
         "{hidden_texel_share[footprint<=8]} to {hidden_texel_share[footprint>128]}."},
        {"parallax_seed_F",
         "Seed 003: its F, rendered",
         "M3 (EWA in the shader) on the bricks at 20 degrees with Heckbert's F = (Ux Vy - Uy Vx)^2 and with the "
         "seed's printed F = (Ux Vy + Uy Vx)^2, and their difference: the slip changes the ellipse wherever the "
         "footprint is sheared (both Uy and Vx non-zero).",
         {"--view", "seed-f", "--map", "bricks", "--res", "320", "--rays", "12"},
         1100,
         400,
         "The seed's F changes {seed_F_error_px} px of M3: {seed_F_psnr_db} dB against the reference, the corrected "
         "F {corrected_F_psnr_db} dB."},
        {"parallax_step",
         "Seed 003: the step map",
         "The synthetic step map (ridges of height 1 and floors of height 0, 32 texels each) at 20 degrees: every "
         "mode and the reference, as in parallax_modes.",
         {"--view", "modes", "--map", "step", "--res", "320", "--rays", "12"},
         1360,
         700,
         "On the step map leaving out hidden texels costs: M4 {ewa_vis_psnr_all} dB against M3's {ewa_psnr_all} dB "
         "over the whole frame."},
        {"parallax_ranking",
         "Seed 003: relief methods ranked",
         "The bricks at 20 degrees lit by one directional light (Lambert), 240x180: bump mapping (Blinn), normal "
         "mapping, parallax mapping (one offset step), parallax occlusion mapping (the demo's march) and "
         "displacement mapping (a grid displaced by the heights, drawn as geometry), each held against a "
         "reference traced through the height field and shaded at the true hit with the true normal; under "
         "them the |error| of each, and the ranking by PSNR.",
         {"--view", "ranking", "--map", "bricks", "--res", "240", "--rays", "3", "--grid", "2"},
         1360,
         640,
         "PSNR against the traced reference: bump {relief_rank_psnr_db[bump]} dB, parallax "
         "{relief_rank_psnr_db[parallax]} dB, parallax occlusion {relief_rank_psnr_db[pom]} dB, "
         "displacement {relief_rank_psnr_db[displacement]} dB."},
    };
  }
  std::vector<std::pair<std::string, std::string>> figureFiles() const override {
    // The modes' table, beside the figures that show it (the causes, seed-F
    // and ranking views draw other numbers: the table kept from the last
    // modes figure is not theirs).
    if (!table_ || (view_ != kSingle && view_ != kModes && view_ != kError)) return {};
    return {{".csv", csv(*table_)}};
  }
  bool live() const override { return view_ == kLive; }
  void update(double seconds) override {
    windowed_ = true;  // a window: the live view may render smaller while it moves
    if (!animate_ || view_ != kLive) return;
    azimuth_ += float(sweep_ * 10.0 * seconds);
    if (azimuth_ > 30.0f) azimuth_ = 30.0f, sweep_ = -1;
    if (azimuth_ < -30.0f) azimuth_ = -30.0f, sweep_ = 1;
  }
  ts::Measurements measure(ts::Renderer& r) override {
    ReliefGL& gl = r.attachment<ReliefGL>();  // the passes' GL objects live as long as r
    if (view_ == kLive) return measureLive(r, gl);
    if (view_ == kRanking) return measureRanking(r);
    std::string key = stateKey();
    if (!table_ || key != tableKey_) {
      Relief& rel = relief();
      // A window's first stage (ts::measureStage).  The single view: its
      // pictures and numbers, complete (singleStage).  The modes and error
      // views: what GL draws at once, the modes' pictures, with the reference
      // traced with kStageRays^2 rays a pixel (a quarter of the work at the
      // default 6 x 6) and the pictures made from it tagged as refining; no
      // numbers until the table's.  Elsewhere (--png, make_figures, the
      // tests) this does not run.
      if (ts::measureStaged() && (view_ == kSingle || view_ == kModes || view_ == kError)) {
        MeasureOptions first;
        first.refRays = std::min(rays_, kStageRays);
        first.seed = uint32_t(seed_);
        first.accel = accel_;
        first.gradScale = gradScale();
        first.firstStage = true;
        ts::Measurements stage;
        stage.detail = view_ == kSingle ? singleStage(gl, rel, first)
                                        : shownOf(std::make_shared<Table>(measureAll(gl, camera(), rel, first)));
        ts::measureStage(std::move(stage));
      }
      MeasureOptions mo;
      mo.refRays = rays_;
      mo.seed = uint32_t(seed_);
      mo.accel = accel_;
      mo.gradScale = gradScale();
      mo.timingRuns = timeRuns_;
      mo.record = &r;  // the pictures' calls for the GL listing (not the live view's: it draws every frame)
      // One table per state: make_figures draws this demo's figures with one scene; two differ only in view.
      table_ = std::make_shared<Table>(measureAll(gl, camera(), rel, mo));
      tableKey_ = key;
      shown_ = shownOf(table_);  // its pictures as textures
      if (!csvPath_.empty()) ts::writeFileAtomic(csvPath_, csv(*table_));
      std::string table = textTable(*table_);
      if (!table.empty() && table.back() == '\n') table.pop_back();
      ts::note(table);
    }
    ts::Measurements m;
    for (const Row& row : table_->rows) {
      std::string k = kModeKeys[row.mode];
      for (char& ch : k)
        if (ch == '-') ch = '_';
      m.push_back({k + "_psnr_all", row.psnrAll,
                   std::string(kModeLabels[row.mode]) + ": PSNR (dB) vs the reference, whole frame"});
      m.push_back({k + "_psnr_band", row.psnrBand, "PSNR (dB) over the occlusion band"});
      m.push_back({k + "_ssim_band", row.ssimBand, "SSIM over the occlusion band"});
      m.push_back({k + "_psnr_aniso", row.psnrAniso, "PSNR (dB) over the high-anisotropy pixels"});
      m.push_back({k + "_lookups", row.lookupsPerPixel, "texture lookups per pixel"});
    }
    m.push_back({"band_pixels", double(table_->bandPixels), "pixels in the occlusion band"});
    if (table_->gradChangeM1 >= 0 && table_->gradChangeM2 >= 0) {
      m.push_back({"m1_grad_x4_changed_px", double(table_->gradChangeM1),
                   "pixels of M1 that change when textureGrad's gradients are x4 (trilinear must change)"});
      m.push_back({"m2_grad_x4_changed_px", double(table_->gradChangeM2),
                   "pixels of M2 that change when textureGrad's gradients are x4 (0: the driver ignores them)"});
    }
    m.detail = shown_;
    // Seed 003's equations measured (parallax_aniso_causes_gl.hpp), once per state.
    if (view_ == kCauses || view_ == kSeedF) {
      if (!causes_ || causesKey_ != key) causes_ = causes::measure(gl, *table_, relief(), accel_, &r), causesKey_ = key;
      causes::addMeasurements(m, *causes_);
      m.detail = causes_;
    }
    return m;
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override {
    ts::Frame f = ts::layout::blankFrame(width, height);
    if (view_ == kLive) {
      views().buildLive(f, measured.detailAs<Live>());
      return f;
    }
    if (view_ == kCauses || view_ == kSeedF) {  // its detail is the causes' result (measure())
      auto c = measured.detailAs<std::shared_ptr<const causes::Result>>();
      if (c) causes::build(f, **c, measured, views().header(), view_ == kSeedF);
      else views().buildWaiting(f);
      return f;
    }
    if (view_ == kRanking) {
      if (const rank::RankShown* shown = measured.detailAs<rank::RankShown>())
        rank::buildRanking(f, measured, *shown, views().header() + ", one directional light (Lambert)");
      else views().buildWaiting(f);
      return f;
    }
    const Shown* shown = measured.detailAs<Shown>();
    if (!shown) views().buildWaiting(f);  // a window before the first measurement: what is coming
    else if (view_ == kModes) views().buildModes(f, *shown);
    else if (view_ == kError) views().buildError(f, *shown);
    else views().buildSingle(f, *shown);
    return f;
  }

 private:
  // The drawing (parallax_aniso_views.hpp) for the current flags.
  Views views() const { return {map_, mode_, against_, gradients_, compare_, heightScale_, camera()}; }
  Camera camera() const {  // no texture coordinates: it becomes glUniform3f(eye, fwd, rightV, upV) in ReliefGL::pass
    Camera c;
    c.width = res_;
    c.height = std::max(1, res_ * 3 / 4);
    c.elevationDeg = angle_;
    c.azimuthDeg = azimuth_;
    c.heightScale = heightScale_;
    if (!camera_.isDefault()) {  // the mouse: yaw turns, pitch raises the view ray, zoom is a longer lens
      c.azimuthDeg += camera_.yaw;
      c.elevationDeg = std::clamp(c.elevationDeg + camera_.pitch, 5.0, 89.0);
      c.fovyDeg = glm::degrees(2 * std::atan(std::tan(glm::radians(c.fovyDeg) / 2) / camera_.zoom));
    }
    return c;
  }
  std::string stateKey() const {
    char b[256];
    std::snprintf(b, sizeof b, "%d %.4f %.3f %.3f %d %d %d %d %d %d", map_, heightScale_, angle_, azimuth_, res_, rays_,
                  seed_, accel_ ? 1 : 0, timeRuns_, gradients_);
    return b + picture_.path() + " " + std::to_string(camera_.yaw) + " " + std::to_string(camera_.pitch) + " " +
           std::to_string(camera_.zoom);
  }
  Relief& relief() {
    // --texture FILE: the albedo (its own 2x2 chain at the heights' size, as EWA assumes); the name keys the GL cache.
    std::string name = picture_.active() ? std::string(kMaps[map_]) + " + " + picture_.path() : kMaps[map_];
    if (!relief_ || relief_->name != name) {
      relief_ = std::make_unique<Relief>(makeRelief(kMaps[map_]));
      if (picture_.active()) {
        const ts::Image& a0 = relief_->albedo[0];
        relief_->albedo = ts::buildMipChain(ts::resizeBilinear(picture_.image(), a0.width, a0.height));
        relief_->name = name;
      }
    }
    return *relief_;
  }

  float gradScale() const { return gradients_ ? 4.0f : 1.0f; }
  // The live view (parallax_aniso_live.hpp): the mode drawn at the window's size, timed.
  ts::Measurements measureLive(ts::Renderer& r, ReliefGL& gl) {
    char state[160];
    std::snprintf(state, sizeof state, "%d %.4f %.3f %d %d %d %d %d %d", map_, heightScale_, angle_, accel_ ? 1 : 0,
                  gradients_, mode_, compare_ ? 1 : 0, against_, view_);
    LiveTimer::Ask a;
    a.cam = camera();
    a.mode = mode_;
    a.against = compare_ ? against_ : -1;
    a.options.accel = accel_;
    a.options.gradScale = gradScale();
    a.state = state;
    a.windowed = windowed_;
    a.animate = animate_;
    return live_.draw(r, gl, relief(), a);
  }

  // The ranking view (parallax_aniso_ranking.hpp): the five methods against the lit, traced reference.
  ts::Measurements measureRanking(ts::Renderer& r) {
    std::string key = stateKey() + " grid " + std::to_string(gridTexels_);
    if (!ranking_.ranking || key != rankingKey_) {
      rank::Setup s;
      s.cam = camera();
      s.rays = rays_;
      s.gridTexels = gridTexels_;
      s.seed = uint32_t(seed_);
      ranking_ = rank::rankShownOf(std::make_shared<rank::Ranking>(rank::measureRanking(r, relief(), s, true)));
      rankingKey_ = key;
    }
    ts::Measurements m;
    rank::addMeasurements(m, *ranking_.ranking);
    m.detail = ranking_;
    return m;
  }

  // The single view's first stage: the one or two pictures it shows and
  // their numbers, complete (the reference traced with all its rays: it is
  // what the numbers are against); the table's other modes, the listing and
  // the gradient test follow.  The same passes as the table's, so the final
  // table changes nothing this view draws.
  Shown singleStage(ReliefGL& gl, const Relief& rel, MeasureOptions o) const {
    std::vector<int> modes;
    for (int m : {mode_, compare_ ? against_ : mode_})
      if (m != kReference && std::find(modes.begin(), modes.end(), m) == modes.end()) modes.push_back(m);
    o.refRays = rays_, o.firstStage = false, o.record = nullptr, o.timingRuns = 0;
    Table measured = measureAll(gl, camera(), rel, o, modes);
    auto t = std::make_shared<Table>(std::move(measured));
    std::vector<Row> rows(static_cast<size_t>(kShaderModes));  // Table::rows is indexed by mode
    for (int m = 0; m < kShaderModes; ++m) rows[size_t(m)].mode = m;
    for (Row& r : t->rows) rows[size_t(r.mode)] = std::move(r);
    t->rows = std::move(rows);
    Shown s;
    s.textures.resize(size_t(kShaderModes) + 1);  // Shown::of: the modes, then the reference
    for (int m : modes) s.textures[size_t(m)] = imageTexture(t->rows[size_t(m)].image, kModeKeys[m]);
    s.textures.back() = imageTexture(t->referenceImage, "reference");
    s.table = std::move(t);
    return s;
  }
  static constexpr int kStageRays = 3;  // the first stage's reference: 3 x 3 rays a pixel (fewer leave pixels black)
  int gridTexels_ = 2;
  rank::RankShown ranking_;
  std::string rankingKey_;
  int mode_ = kEwa, map_ = 0, against_ = kEwaVis, view_ = kSingle, res_ = 160, rays_ = 6, seed_ = 1, timeRuns_ = 0;
  float heightScale_ = 0.06f, angle_ = 20.0f, azimuth_ = 12.0f;
  bool compare_ = false, accel_ = true, animate_ = false;
  int gradients_ = 0;  // 0: x1, 1: x4
  int sweep_ = 1;
  bool windowed_ = false;
  LiveTimer live_;
  std::string csvPath_;

  std::unique_ptr<Relief> relief_;
  ts::UserTexture picture_;  // --texture FILE: the albedo
  ts::OrbitCamera camera_;   // --yaw --pitch --zoom: the mouse
  std::shared_ptr<Table> table_;
  std::string tableKey_;
  std::shared_ptr<const causes::Result> causes_;  // the causes view's measurement (its state: tableKey_)
  std::string causesKey_;
  Shown shown_;
};
}  // namespace

TS_REGISTER_SCENE(ParallaxAniso);
