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
// mapping (parallax_gl.hpp) and filtered six ways:
//   M0 naive (implicit derivatives of the shifted coordinate: the artifact),
//   M1 trilinear and M2 hardware anisotropic 16x (textureGrad with the
//   unshifted gradients; whether the driver's anisotropic filter uses them is
//   measured: llvmpipe's does not),
//   M3 EWA in the shader (Heckbert), M4 EWA without hidden texels (every
//   texel traced), M5 the seed's row walk,
// and compared with R, a reference of n x n (--rays; the figures 12 x 12) stratified jittered rays per
// pixel traced finely on the CPU and weighted by the same Gaussian kernel
// (relief.hpp).  Printed and written as CSV (--csv FILE; make_figures writes
// parallax_modes.csv beside the figure): PSNR and SSIM over the whole frame,
// over the high-anisotropy pixels and over the occlusion band (pixels whose
// footprint crosses an occluding edge), milliseconds per frame and texture
// lookups per pixel, and the renderer.
//
// Keys (each is also a flag, see --help):
//   m  mode            t  map: bricks | step | flat
//   + / -  height scale          ] / [  view angle (elevation)
//   z / Z  azimuth               c  split-screen compare (mode | --against)
//   b  the mode compared against  v  view: single | modes | error | live
//   r / R  render width          x  max-height pyramid acceleration
//   a  live view: sweep the azimuth
//   g  gradients M1/M2 give textureGrad: x1 | x4 (does the filter use them?
//      trilinear blurs; llvmpipe's anisotropic filter does not change)
// The live view (v until "live", or --view live) draws the mode every frame at
// the window's size: M2 there is what "interactive" is measured on (the
// overlay, h, shows live_ms_per_frame and live_fps).
// Flags only: --rays N (reference rays per side), --seed, --time N (time each
// mode, median of N frames, for the CSV), --csv FILE.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "common/context.hpp"
#include "common/error.hpp"
#include "common/figure.hpp"
#include "common/render.hpp"
#include "common/textures.hpp"
#include "common/layout.hpp"
#include "common/orbit_camera.hpp"
#include "common/text.hpp"
#include "common/user_texture.hpp"
#include "common/scene.hpp"
#include "measure.hpp"
#include "parallax_gl.hpp"
#include "relief.hpp"

namespace {
using namespace pax;
enum View { kSingle, kModes, kError, kLive };
const char* const kMaps[] = {"bricks", "step", "flat"};
using ts::layout::kWhite, ts::layout::kAmber;
const glm::vec4 kGrey{0.62f, 0.62f, 0.66f, 1.0f};

ts::TextureDesc imageTexture(const ts::Image& img, const std::string& what) {
  return ts::renderedImageTexture(img, "parallax_render", what, "parallax_aniso");
}

// |error| against the reference inside the occlusion band, x4, on a heat
// scale (black 0 .. yellow 64 levels); outside the band the reference, dimmed.
ts::Image bandError(const ts::Image& img, const Table& t) {
  ts::Image out(img.width, img.height);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      size_t p = size_t(y) * size_t(img.width) + size_t(x);
      const uint8_t* a = &img.pixels[p * 4];
      const uint8_t* r = &t.referenceImage.pixels[p * 4];
      if (!t.bandMask[p]) {
        double l = (0.299 * r[0] + 0.587 * r[1] + 0.114 * r[2]) * 0.25;
        out.set(x, y, {u8(l), u8(l), u8(l + 8), 255});
        continue;
      }
      double e = 0;
      for (int c = 0; c < 3; ++c) e += std::abs(double(a[c]) - double(r[c]));
      double v = std::clamp(e / 3.0 / 64.0, 0.0, 1.0);
      glm::dvec3 col = v < 0.5 ? glm::mix(glm::dvec3(30, 20, 60), glm::dvec3(220, 40, 40), v * 2)
                               : glm::mix(glm::dvec3(220, 40, 40), glm::dvec3(255, 240, 80), v * 2 - 1);
      out.set(x, y, {u8(col.r), u8(col.g), u8(col.b), 255});
    }
  return out;
}

class ParallaxAniso final : public ts::Scene {
 public:
  std::string id() const override { return "parallax_aniso"; }
  std::string title() const override { return "Parallax mapping with visibility-aware anisotropic filtering (seed 003)"; }
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

  std::vector<std::string> claim() const override { return {"ewa_psnr_all", "ewa_vis_psnr_all"}; }

  void addOptions(ts::Options& o) override {
    o.addEnum("mode", &mode_, {kModeKeys[0], kModeKeys[1], kModeKeys[2], kModeKeys[3], kModeKeys[4], kModeKeys[5],
                               kModeKeys[6]},
              "M0 naive | M1 trilinear | M2 aniso 16x | M3 EWA | M4 EWA visible texels | M5 EWA row walk | "
              "reference",
              'm');
    o.addEnum("map", &map_, {kMaps[0], kMaps[1], kMaps[2]}, "relief: bricks with deep mortar | step/ridge | flat",
              't');
    o.addFloat("height-scale", &heightScale_, 0.0f, 0.2f, "depth of the relief, world units (a tile is 2)", '+', '-',
               0.01f);
    o.addFloat("angle", &angle_, 14.0f, 80.0f, "view angle: elevation of the central ray above the plane, degrees",
               ']', '[', 2.0f);
    o.addFloat("azimuth", &azimuth_, -45.0f, 45.0f, "turn of the view about the normal, degrees", 'z', 'Z', 3.0f);
    o.addBool("compare", &compare_, "split screen: left half the mode, right half --against", 'c');
    o.addEnum("against", &against_, {kModeKeys[0], kModeKeys[1], kModeKeys[2], kModeKeys[3], kModeKeys[4],
                                     kModeKeys[5], kModeKeys[6]},
              "the mode of the right half in split-screen compare", 'b');
    o.addEnum("view", &view_, {"single", "modes", "error", "live"},
              "single: one mode (or the split screen); modes: all seven with their numbers; error: the occlusion "
              "band's error for M2, M3, M4; live: the mode (or the split screen) drawn every frame at the window's "
              "size, timed (no reference, no table)",
              'v');
    o.addBool("animate", &animate_, "live view: sweep the azimuth back and forth (10 degrees a second)", 'a');
    o.addInt("res", &res_, 80, 800, "width of the measured renders (height 3/4 of it; the figures use 320)", 'r', 'R', 80);
    o.addInt("rays", &rays_, 2, 32, "reference rays per side of the kernel square (n x n; the figures use 12)");
    o.addInt("time", &timeRuns_, 0, 50,
             "time each mode over N frames (median, into the CSV's ms_per_frame); 0 = do not time (the figures use 3)");
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
        {"parallax_modes", "Seed 003: parallax + anisotropic filtering",
         "Bricks with deep mortar seen at 20 degrees through parallax occlusion mapping, 320x240 each: M0 naive "
         "lookup (implicit derivatives of the shifted coordinate: fringes along every occluding edge), M1 trilinear, "
         "M2 hardware anisotropic 16x, M3 EWA in the shader, M4 EWA without the texels higher relief hides, M5 the "
         "seed's row walk, and the reference (12x12 traced rays per pixel, the same Gaussian kernel). Under each: "
         "PSNR against the reference over the whole frame and over the occlusion band, and lookups per pixel. The "
         "table is in parallax_modes.csv.",
         {"--view", "modes", "--map", "bricks", "--res", "320", "--rays", "12", "--time", "3"}, 1360, 660},
        {"parallax_error_band", "Seed 003: error in the occlusion band",
         "The occlusion band (pixels whose footprint crosses an occluding edge, where the reference's rays hit "
         "depths more than half the relief apart) and the error against the reference inside it for M2 (hardware "
         "anisotropic), M3 (EWA) and M4 (EWA without hidden texels): |error| x4, black none, red 32, yellow 64 "
         "levels or more.",
         {"--view", "error", "--map", "bricks", "--res", "320", "--rays", "12", "--time", "3"}, 1360, 340},
        {"parallax_step", "Seed 003: the step map",
         "The synthetic step map (ridges of height 1 and floors of height 0, 32 texels each) at 20 degrees: every "
         "mode and the reference, as in parallax_modes.",
         {"--view", "modes", "--map", "step", "--res", "320", "--rays", "12", "--time", "3"}, 1360, 660},
    };
  }

  std::vector<std::pair<std::string, std::string>> figureFiles() const override {
    if (!table_) return {};
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
    std::string key = stateKey();
    if (!table_ || key != tableKey_) {
      Relief& rel = relief();
      MeasureOptions mo;
      mo.refRays = rays_;
      mo.seed = uint32_t(seed_);
      mo.accel = accel_;
      mo.gradScale = gradScale();
      mo.timingRuns = timeRuns_;
      // One table per state: make_figures draws its figures of this demo
      // with one scene, and two of them share a state (only the view differs).
      table_ = std::make_shared<Table>(measureAll(gl, camera(), rel, mo));
      tableKey_ = key;
      textures_.clear();
      for (const Row& row : table_->rows) textures_.push_back(imageTexture(row.image, kModeKeys[row.mode]));
      textures_.push_back(imageTexture(table_->referenceImage, "reference"));
      errorTextures_.clear();
      for (int m : {kAniso16, kEwa, kEwaVis})
        errorTextures_.push_back(imageTexture(bandError(table_->rows[size_t(m)].image, *table_),
                                              std::string("band_error_") + kModeKeys[m]));
      ts::Image band(table_->cam.width, table_->cam.height);
      for (size_t p = 0; p < table_->bandMask.size(); ++p) {
        const uint8_t* c = &table_->referenceImage.pixels[p * 4];
        bool in = table_->bandMask[p];
        for (int k = 0; k < 3; ++k) band.pixels[p * 4 + size_t(k)] = in ? uint8_t(k == 0 ? 255 : k == 1 ? 200 : 40) : uint8_t(c[k] / 2);
      }
      errorTextures_.push_back(imageTexture(band, "occlusion_band"));
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
      m.push_back({k + "_psnr_all", row.psnrAll, std::string(kModeLabels[row.mode]) + ": PSNR (dB) vs the reference, whole frame"});
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
    m.detail = Shown{table_, textures_, errorTextures_};
    return m;
  }

  ts::Frame build(int width, int height, const ts::Measurements& measured) const override {
    ts::Frame f;
    f.width = width;
    f.height = height;
    f.clearColor = {0.12f, 0.12f, 0.14f, 1.0f};
    if (view_ == kLive) {
      buildLive(f, measured.detailAs<Live>());
      return f;
    }
    const Shown* shown = measured.detailAs<Shown>();
    if (!shown) {  // a window before the first measurement: what is coming
      f.labels.push_back({16.0f, 6.0f,
                          std::string("Seed 003  ") + kMaps[map_] + ", view angle " + fmtNum("%.0f", angle_) +
                              " deg, height " + fmtNum("%.2f", heightScale_) + gradientsNote(),
                          kWhite, 1, ts::Align::Left});
      f.labels.push_back({float(width / 2), float(height / 2), "rendering the modes and tracing the reference...",
                          kAmber, 1, ts::Align::Center});
      return f;
    }
    if (view_ == kModes) buildModes(f, *shown);
    else if (view_ == kError) buildError(f, *shown);
    else buildSingle(f, *shown);
    return f;
  }

 private:
  // What measure() found, for the pictures (its detail): the table and its
  // images as textures; or, in the live view, the texture it drew.
  struct Shown {
    std::shared_ptr<const Table> table;
    std::vector<ts::TextureDesc> textures, errorTextures;
    const ts::TextureDesc& of(int mode) const { return textures[size_t(mode == kReference ? 6 : mode)]; }
  };
  struct Live {
    ts::TextureDesc texture;
    glm::ivec2 size{0}, modes{-1};
    double scale = 1, fps = 0;  // drawn smaller while the view moves (window only): shown in the picture
  };
  Camera camera() const {
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
    std::snprintf(b, sizeof b, "%d %.4f %.3f %.3f %d %d %d %d %d %d", map_, heightScale_, angle_, azimuth_, res_,
                  rays_, seed_, accel_ ? 1 : 0, timeRuns_, gradients_);
    return b + picture_.path() + " " + std::to_string(camera_.yaw) + " " + std::to_string(camera_.pitch) + " " +
           std::to_string(camera_.zoom);
  }
  Relief& relief() {
    // --texture FILE: the file is the albedo (its own 2x2 chain, at the
    // heights' size, which the EWA shaders assume); the name keys the GL cache.
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

  void addImage(ts::Frame& f, const std::string& id, ts::Rect rect, const ts::TextureDesc& tex, float s0 = 0,
                float s1 = 1) const {
    f.panels.push_back(ts::layout::texturePanel(id, rect, f.addTexture(tex), "image", s0, s1));
  }
  static std::string numbers(const Table& table, int mode) {
    if (mode == kReference) return std::to_string(table.refRays) + "x" + std::to_string(table.refRays) + " rays, CPU";
    const Row& r = table.rows[size_t(mode)];
    // A map with no occluding edge (flat) has an empty band: no number to show.
    std::string band = table.bandPixels ? "band " + fmtNum("%.1f", r.psnrBand) + " dB" : std::string("no band");
    return fmtNum("%.1f", r.psnrAll) + " dB  " + band + "  " + fmtNum("%.0f", r.lookupsPerPixel) + " lk/px";
  }
  std::string header(const Table& table) const {
    return std::string("Seed 003  ") + kMaps[map_] + ", view angle " + fmtNum("%.0f", camera().elevationDeg) + " deg, height " +
           fmtNum("%.2f", heightScale_) + gradientsNote() + ", " + table.renderer;
  }
  float gradScale() const { return gradients_ ? 4.0f : 1.0f; }
  // Said in the picture whenever M1/M2 are not given the true gradients.
  std::string gradientsNote() const { return gradients_ ? ", M1/M2 gradients x4" : ""; }

  void buildSingle(ts::Frame& f, const Shown& shown) const {
    namespace L = ts::layout;
    const Table& table = *shown.table;
    const int line = 17;
    int availW = f.width - 32, availH = f.height - 4 * line;
    double s = std::min(double(availW) / table.cam.width, double(availH) / table.cam.height);
    int w = std::max(1, int(table.cam.width * s)), h = std::max(1, int(table.cam.height * s));
    ts::Rect rect{(f.width - w) / 2, 2 * line, w, h};
    L::caption(f, {16, 6, float(f.width - 4), float(2 * line - 2)}, header(table), kWhite, 1, ts::Align::Left);
    const L::Box under{4, float(rect.y + h + 6), float(f.width - 4), float(f.height - 2)};
    if (!compare_) {
      addImage(f, "image", rect, shown.of(mode_));
      L::caption(f, under, std::string(kModeLabels[mode_]) + ":  " + numbers(table, mode_), kAmber, 1);
      return;
    }
    ts::Rect left{rect.x, rect.y, w / 2, h}, right{rect.x + w / 2, rect.y, w - w / 2, h};
    addImage(f, "left", left, shown.of(mode_), 0.0f, 0.5f);
    addImage(f, "right", right, shown.of(against_), 0.5f, 1.0f);
    ts::Panel canvas;
    canvas.id = "divider";
    canvas.viewport = {0, 0, f.width, f.height};
    canvas.projection = glm::ortho(0.0f, float(f.width), float(f.height), 0.0f, -1.0f, 1.0f);
    canvas.batches.push_back(ts::lineSegments({{float(right.x), float(rect.y)}, {float(right.x), float(rect.y + h)}},
                                              kWhite, 2.0f, "divider"));
    f.panels.push_back(canvas);
    const float mid = float(right.x);
    L::caption(f, {under.x0, under.y0, mid - 4, under.y1}, std::string(kModeLabels[mode_]) + ": " + numbers(table, mode_),
               kAmber, 1);
    L::caption(f, {mid + 4, under.y0, under.x1, under.y1},
               std::string(kModeLabels[against_]) + ": " + numbers(table, against_), kAmber, 1);
  }

  // The live view: the chosen mode (M0..M5; R is the CPU reference, seconds
  // a frame, so it is not drawn live) at the target's full size, drawn by
  // ReliefGL::drawLive straight into a texture, timed with glFinish.  The
  // milliseconds go to the measurements (stdout, the `h` overlay), not into
  // the picture, so a --png of the live view stays reproducible.
  // In a window, while the view moves (--animate, or a key in the last half
  // second) a mode too slow for 20 frames a second is drawn smaller and
  // upscaled (the picture says the scale and the fps); still, it is drawn at
  // full size again.  --png never scales.
  ts::Measurements measureLive(ts::Renderer& r, ReliefGL& gl) {
    const int fullW = std::max(1, r.pictureWidth()), fullH = std::max(1, r.pictureHeight());
    double now = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    // What the draw costs depends on all but the azimuth (which the sweep turns).
    char key[160];
    std::snprintf(key, sizeof key, "%d %.4f %.3f %d %d %d %d %d %d %dx%d", map_, heightScale_, angle_, accel_ ? 1 : 0,
                  gradients_, mode_, compare_ ? 1 : 0, against_, view_, fullW, fullH);
    if (key != liveKey_) {  // a new draw: its own timings (the fps printed after m is the new mode's)
      liveMs_.clear();
      liveSettled_ = false;
      if (!liveKey_.empty()) liveMovedAt_ = now;  // (the first picture is no movement)
      liveKey_ = key;
    }
    if (azimuth_ != liveAzimuth_) {
      if (liveAzimuth_ < 1e9f) liveMovedAt_ = now;
      liveAzimuth_ = azimuth_;
    }
    const bool moving = windowed_ && (animate_ || now - liveMovedAt_ < 0.5);
    if (!moving) liveScale_ = 1.0;
    Camera c = camera();
    c.width = std::max(1, int(std::lround(fullW * liveScale_)));
    c.height = std::max(1, int(std::lround(fullH * liveScale_)));
    auto liveMode = [](int m) { return m == kReference ? -1 : m; };
    int left = liveMode(mode_), right = compare_ ? liveMode(against_) : -1;
    if (left < 0) left = right, right = -1;  // the reference cannot be drawn live: the other half fills the view
    ts::Measurements m;
    if (left < 0) return m;
    PassOptions o;
    o.accel = accel_;
    o.gradScale = gradScale();
    auto t0 = std::chrono::steady_clock::now();
    GLuint tex = gl.drawLive(c, relief(), left, right, o);
    glFinish();
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (liveScale_ != liveMsScale_) liveMs_.clear(), liveMsScale_ = liveScale_;  // a median at one scale
    liveMs_.push_back(ms);
    if (liveMs_.size() > 15) liveMs_.erase(liveMs_.begin());
    std::vector<double> sorted = liveMs_;
    std::sort(sorted.begin(), sorted.end());
    double median = sorted[sorted.size() / 2];
    const double shownScale = liveScale_;
    // The next frame's scale while moving: the draw's time is about
    // proportional to its pixels, so scale x sqrt(budget / ms) meets the
    // budget (35 ms leaves the rest of a 20 fps frame to the window); left
    // alone within 70-115 % of it (each new size is a new target texture).
    if (moving && (ms > 1.15 * kLiveBudgetMs || (ms < 0.7 * kLiveBudgetMs && liveScale_ < 1.0))) {
      double want = liveScale_ * std::sqrt(kLiveBudgetMs / std::max(1e-3, ms));
      liveScale_ = std::clamp(std::floor(std::min(1.0, want) * 16.0) / 16.0, 0.25, 1.0);
    }
    if (windowed_ && !liveSettled_ && liveMs_.size() == 15) {  // the new state's speed, once it has settled
      liveSettled_ = true;
      std::printf("live: %s at %dx%d, drawn at scale %.2f: %.1f ms a draw (%.1f fps), median of 15 frames\n",
                  kModeLabels[left], fullW, fullH, shownScale, median, 1000.0 / median);
      std::fflush(stdout);
    }
    Live live;
    live.texture.name = "parallax_live";
    live.texture.params = {{"left", kModeKeys[left]}, {"right", right < 0 ? "-" : kModeKeys[right]},
                           {"size", std::to_string(c.width) + "x" + std::to_string(c.height)},
                           {"made_by", "ReliefGL::drawLive in the parallax_aniso demo's measure()"}};
    live.texture.glTexture = tex;
    live.texture.minFilter = live.texture.magFilter = shownScale < 1.0 ? GL_LINEAR : GL_NEAREST;
    live.texture.wrapS = live.texture.wrapT = GL_CLAMP_TO_EDGE;
    live.size = {c.width, c.height};
    live.modes = {left, right};
    live.scale = shownScale;
    live.fps = 1000.0 / (ms + 1e-9);
    m.detail = live;
    m.push_back({"live_ms_per_frame", median, "the live view's draw, median of the last " +
                                                  std::to_string(liveMs_.size()) + " frames (glFinish)"});
    m.push_back({"live_fps", 1000.0 / median, "frames per second that draw allows (20 = interactive)"});
    m.push_back({"live_scale", shownScale, "the draw's size / the window's (below 1 while the view moves and the "
                                           "mode is too slow for 20 fps; 1 at rest and in --png)"});
    return m;
  }

  static constexpr int kLiveBar = 22;  // the dark bars under the live view's two lines of text
  void buildLive(ts::Frame& f, const Live* live) const {
    const int line = 17;
    auto bar = [&](const char* id, int y) {
      ts::Panel p;
      p.id = id;
      p.viewport = {0, y, f.width, kLiveBar};
      p.clear = true;
      p.clearColor = f.clearColor;
      f.panels.push_back(p);
    };
    const Camera cam = camera();  // the mouse's orbit included
    std::string head = std::string("Seed 003  ") + kMaps[map_] + ", view angle " + fmtNum("%.0f", cam.elevationDeg) +
                       " deg, azimuth " + fmtNum("%.0f", cam.azimuthDeg) + " deg, height " + fmtNum("%.2f", heightScale_) +
                       gradientsNote() + ", live";
    namespace L = ts::layout;
    if (!live || !live->texture.glTexture) {
      L::Column c(f, {16, 6, float(f.width - 4), float(f.height - 2)});
      c.add(head, kWhite, 1, ts::Align::Left);
      c.add("R (the reference) is traced on the CPU and is not drawn live: m picks a mode", kAmber, 1, ts::Align::Left);
      return;
    }
    addImage(f, "live", {0, 0, f.width, f.height}, live->texture);
    bar("top_bar", 0);
    bar("bottom_bar", f.height - kLiveBar);
    // A narrow window gets a shorter header, never one cut before its gradients note.
    for (const std::string& h : {std::string(kMaps[map_]) + gradientsNote() + ", live", std::string(kMaps[map_]) + gradientsNote()})
      if (ts::text::width(head, 1) > float(f.width - 21)) head = h;
    L::caption(f, {16, 4, float(f.width - 4), float(kLiveBar)}, head, kWhite, 1, ts::Align::Left);
    std::string sizeText = std::to_string(live->size.x) + "x" + std::to_string(live->size.y);
    if (live->scale < 1.0)
      sizeText += " (scale " + fmtNum("%.2f", live->scale) + " while moving, draw " + fmtNum("%.0f", live->fps) + " fps)";
    if (live->modes.y < 0) {
      L::caption(f, {4, float(f.height - line - 2), float(f.width - 4), float(f.height)},
                 std::string(kModeLabels[live->modes.x]) + ", " + sizeText, kAmber, 1);
      return;
    }
    L::caption(f, {4, float(f.height - line - 2), float(f.width / 2 - 4), float(f.height)}, kModeLabels[live->modes.x],
               kAmber, 1);
    L::caption(f, {float(f.width / 2 + 4), float(f.height - line - 2), float(f.width - 4), float(f.height)},
               kModeLabels[live->modes.y], kAmber, 1);
    ts::Panel canvas;
    canvas.id = "divider";
    canvas.viewport = {0, 0, f.width, f.height};
    canvas.projection = glm::ortho(0.0f, float(f.width), float(f.height), 0.0f, -1.0f, 1.0f);
    float x = float(f.width / 2);
    canvas.batches.push_back(ts::lineSegments({{x, 0.0f}, {x, float(f.height)}}, kWhite, 2.0f, "divider"));
    f.panels.push_back(canvas);
  }

  // The panels of the modes and error views: shrunk to fit, or enlarged by a
  // whole factor when two or more fit (each rendered pixel stays a block of
  // equal pixels: small --res renders stay readable and comparable).
  static double panelScale(double fit) { return fit >= 2.0 ? std::floor(fit) : std::min(1.0, fit); }

  void buildModes(ts::Frame& f, const Shown& shown) const {
    namespace L = ts::layout;
    const Table& table = *shown.table;
    const int line = 17, gap = 12;
    const int W = table.cam.width, H = table.cam.height;
    // Four cells a row (two rows), or two (four rows) in a tall window.
    auto fit = [&](int cols) {
      int rows = 8 / cols;
      return std::min(double(f.width - (cols + 1) * gap) / (cols * W),
                      double(f.height - 2 * line - rows * (3 * line + 6)) / (rows * H));
    };
    const int cols = fit(2) > fit(4) * 1.05 ? 2 : 4;
    double s = panelScale(fit(cols));
    int w = std::max(1, int(W * s)), h = std::max(1, int(H * s));
    int left = std::max(0, (f.width - cols * w - (cols - 1) * gap) / 2);
    L::caption(f, {4, 4, float(f.width - 4), float(2 * line - 2)}, header(table), kWhite, 1);
    auto column = [&](int x, float y0, float y1) {
      return L::Box{std::max(0.0f, float(x - gap / 2)), y0, std::min(float(f.width), float(x + w + gap / 2)), y1};
    };
    const int order[7] = {kNaive, kTrilinear, kAniso16, kReference, kEwa, kEwaVis, kEwaRows};
    for (int k = 0; k < 7; ++k) {
      int col = k % cols, row = k / cols;
      int x = left + col * (w + gap), y = 2 * line + row * (h + 3 * line + 6) + line;
      addImage(f, std::string("image_") + kModeKeys[order[k]], {x, y, w, h}, shown.of(order[k]));
      L::caption(f, column(x, float(y - line), float(y - 1)), kModeLabels[order[k]], kWhite, 1);
      L::caption(f, column(x, float(y + h + 3), float(y + h + 2 * line + 3)), numbers(table, order[k]), kAmber, 1);
    }
    // The eighth cell: the band in numbers.
    int x = left + (7 % cols) * (w + gap), y = 2 * line + (7 / cols) * (h + 3 * line + 6) + line;
    L::Column c(f, {float(x), float(y), std::min(float(f.width - 2), float(x + std::max(w, 240))), float(f.height - 2)});
    c.add("occlusion band: " + std::to_string(table.bandPixels) + " px", kGrey, 1, ts::Align::Left);
    c.add("mode     PSNR    SSIM", kGrey, 1, ts::Align::Left);
    for (int m = 0; m < kShaderModes; ++m) {
      const Row& r = table.rows[size_t(m)];
      c.add(std::string("M") + std::to_string(m) + "    " +
                (table.bandPixels ? fmtNum("%6.2f", r.psnrBand) + "  " + fmtNum("%6.4f", r.ssimBand)
                                  : std::string("     -       -")),
            m >= kEwa ? kAmber : kWhite, 1, ts::Align::Left);
    }
    // (Milliseconds are in the CSV, not here: the figure must regenerate byte-identically.)
    c.add("PSNR in dB against R;", kGrey, 1, ts::Align::Left);
    c.add("lk/px: texture lookups per pixel", kGrey, 1, ts::Align::Left);
  }

  void buildError(ts::Frame& f, const Shown& shown) const {
    namespace L = ts::layout;
    const Table& table = *shown.table;
    const int line = 17, gap = 12;
    const int W = table.cam.width, H = table.cam.height;
    // Four in a row, or 2 x 2 in a tall window.
    auto fit = [&](int cols) {
      int rows = 4 / cols;
      return std::min(double(f.width - (cols + 1) * gap) / (cols * W), double(f.height - 2 * line - rows * 3 * line) / (rows * H));
    };
    const int cols = fit(2) > fit(4) * 1.05 ? 2 : 4;
    double s = panelScale(fit(cols));
    int w = std::max(1, int(W * s)), h = std::max(1, int(H * s));
    int left = std::max(0, (f.width - cols * w - (cols - 1) * gap) / 2);
    L::caption(f, {4, 4, float(f.width - 4), float(2 * line - 2)}, header(table), kWhite, 1);
    auto column = [&](int x, float y0, float y1) {
      return L::Box{std::max(0.0f, float(x - gap / 2)), y0, std::min(float(f.width), float(x + w + gap / 2)), y1};
    };
    const char* titles[4] = {"occlusion band", "M2 aniso 16x |error|", "M3 EWA |error|", "M4 EWA visible |error|"};
    const int modes[4] = {-1, kAniso16, kEwa, kEwaVis};
    for (int k = 0; k < 4; ++k) {
      int x = left + (k % cols) * (w + gap), y = 2 * line + line / 2 + (k / cols) * (h + 3 * line);
      addImage(f, std::string("error_") + std::to_string(k), {x, y, w, h}, shown.errorTextures[size_t(k == 0 ? 3 : k - 1)]);
      L::caption(f, column(x, float(y - line), float(y - 1)), titles[k], kWhite, 1);
      std::string n = k == 0 ? std::to_string(table.bandPixels) + " px"
                             : "band PSNR " + fmtNum("%.2f", table.rows[size_t(modes[k])].psnrBand) + " dB, SSIM " +
                                   fmtNum("%.3f", table.rows[size_t(modes[k])].ssimBand);
      L::caption(f, column(x, float(y + h + 4), float(y + h + 2 * line)), n, kAmber, 1);
    }
  }

  int mode_ = kEwa, map_ = 0, against_ = kEwaVis, view_ = kSingle, res_ = 160, rays_ = 6, seed_ = 1, timeRuns_ = 0;
  float heightScale_ = 0.06f, angle_ = 20.0f, azimuth_ = 12.0f;
  bool compare_ = false, accel_ = true, animate_ = false;
  int gradients_ = 0;  // 0: x1, 1: x4
  int sweep_ = 1;
  std::vector<double> liveMs_;  // the live draw's ms per frame, scaled to full size
  static constexpr double kLiveBudgetMs = 35.0;
  double liveScale_ = 1.0, liveMsScale_ = 1.0, liveMovedAt_ = -1e9;
  float liveAzimuth_ = 1e9f;
  std::string liveKey_;
  bool windowed_ = false, liveSettled_ = false;
  std::string csvPath_;

  std::unique_ptr<Relief> relief_;
  ts::UserTexture picture_;  // --texture FILE: the albedo
  ts::OrbitCamera camera_;   // --yaw --pitch --zoom: the mouse
  std::shared_ptr<Table> table_;
  std::string tableKey_;
  std::vector<ts::TextureDesc> textures_, errorTextures_;
};
}  // namespace

TM_REGISTER_SCENE(ParallaxAniso);
