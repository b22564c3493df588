// Section VI.1.3 and seeds 001, 003, 004 — minification beyond mipmaps: the
// filter zoo against the exact footprint integral.
//
// The claims.  Buss's ideal filter averages the texels under a pixel's
// preimage weighted by area (Rogers, seed 004, does it by hand): that is the
// reference here, computed exactly for every pixel (common/core/area_filter.hpp:
// the preimage of the pixel square under the plane's homography, integrated
// over the texels it covers).  Against it: GL_NEAREST and GL_LINEAR alias;
// mipmaps (GL_NEAREST_MIPMAP_NEAREST, trilinear) over-blur a footprint that
// is long one way ("no way to make enough mipmaps for all directions");
// a ripmap (levels W/2^i x H/2^j) and a summed-area table (the average over a
// rectangle) fit footprints along the texture's axes, and lose when the
// footprint turns: at 45 degrees the SAT's box is 5.06 times an 8:1
// footprint (seed 001: "blurry along the diagonals, the same problem for
// ripmaps"); the probe line (seed 001 ¶17-18) and EWA (seed 003) follow the
// footprint's turn.  And the numbers the seeds get wrong: a ripmap costs
// 3.98x (the seed: 3x, the overhead), a SAT of a 256^2 8-bit texture 24 bits
// a sum (the seed: >= 16), 32 x 64 has 7 levels (the seed's rule: 6).
//
// Views (v): methods — every method side by side at one azimuth, RMS and
// texels read under each; azimuths — methods x azimuths 0, 22.5, 45;
// supports — one pixel (--pick X,Y of the 384 x 192 picture) on level 0 of
// the texture with every method's support over its exact preimage; memory —
// memory against error; kernels — trilinear with mip chains made by six
// kernels in sRGB values and in linear light; bias — LOD bias -1..+1 against
// error and flicker.
//
// Keys (each is also a flag, see --help):
//   v  view                                m  method (highlighted; the supports view's picture)
//   a / A  azimuth +-22.5 degrees (arrows)  s  scene: slanted plane | zone plate | magnification
//   b / B  LOD bias +-1/4                  k  mip kernel (the kernels view's highlight)
//   g  linear-light kernel                 t  texture: checkerboard | labelled grid
//   a click on a picture: its pixel in the supports view (--pick X,Y)
//
// What the GL does (filter_zoo_measure.hpp): the GL methods draw the scene's outline
// as triangles with glTexCoord4f(s q, t q, 0, q), (s/q, t/q) the scene's
// homography at every pixel (filter_zoo_math.hpp: viewFrame), with
// glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST |
// GL_LINEAR | GL_NEAREST_MIPMAP_NEAREST | GL_LINEAR_MIPMAP_LINEAR),
// glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 16) for
// anisotropic and GL_TEXTURE_LOD_BIAS; they are rendered offscreen at
// 384 x 192 and read back.  Ripmap, SAT, probe line, EWA and the exact
// integral are computed on the CPU in double precision (filter_zoo_math.hpp), so
// their pictures do not depend on the driver.  Every picture is shown as a
// GL_NEAREST texture; listings: book_figures/filter_zoo_*.gl.txt.
//
// Measured (printed, and on screen): magnification counts read from a
// texel-index render; memory per method; levels of 32 x 64; the two LOD
// forms (the reference's log2(rho_edge/rho_max) at 45 degrees, and which
// form this rasterizer uses: the level its trilinear filter reads at 0 and
// 45 degrees); SAT's box ratio; every method's RMS against the exact
// integral at 0, 22.5 and 45 degrees and its texels read per pixel; the
// last mip level that keeps level 0's colours under a nearest sample and
// where GL_NEAREST_MIPMAP_NEAREST's picture parts from GL_NEAREST's (the
// checkerboard's levels 1..5 are the same board, so over the far field the
// two draw the same picture); in the supports view, the picked pixel's
// footprint; in the kernels and bias views, each kernel's and each bias's
// numbers, and the mean each 1 x 1 level stands for.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <future>
#include <memory>
#include <utility>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"
#include "filter_zoo_math.hpp"
#include "filter_zoo_measure.hpp"
#include "filter_zoo_views.hpp"

namespace {
using namespace zoo;
using namespace zoo::views;
using ts::layout::fmt;

class FilterZoo final : public ts::Scene {
 public:
  std::string id() const override { return "filter_zoo"; }
  std::string title() const override { return "Section VI.1.3 - the filter zoo against the exact footprint integral"; }
  std::string about() const override {
    return "Minification filters side by side on the mipmap demo's "
           "slanted plane with the texture turned 0, 22.5 and 45\n"
           "degrees (and on a zone plate, and magnified): GL_NEAREST, "
           "GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, trilinear,\n"
           "GL's anisotropic 16x (GL renders), a ripmap, a summed-area table, the probe line and EWA (on the CPU),\n"
           "each against the exact area integral over the pixel's preimage.  Prints the RMS and texels read of every\n"
           "method, the memory each costs, the seeds' numbers corrected, and the mip kernels' and LOD bias's effect.";
  }
  int defaultWidth() const override { return 1024; }
  int defaultHeight() const override { return 560; }

  std::vector<std::string> claim() const override { return {"rms_exact[sat@*", "rms_exact[probes@*"}; }

  void addOptions(ts::Options& o) override {
    o.addEnum(
        "view", &view_, {kViewKeys[0], kViewKeys[1], kViewKeys[2], kViewKeys[3], kViewKeys[4], kViewKeys[5]},
        "methods side by side | methods x azimuths | one pixel's supports | memory vs error | mip kernels | LOD bias",
        'v');
    std::vector<std::string> methods;
    for (int m = 0; m < kMethodCount; ++m) methods.push_back(methodKey(m));
    o.addEnum("method", &method_, methods, "the method highlighted (and pictured in the supports view)", 'm');
    o.addFloat("azimuth", &azimuth_, 0.0f, 90.0f, "the texture's turn on the plane, degrees", 'a', 'A', 22.5f);
    o.addEnum(
        "scene", &scene_, {kSceneKeys[0], kSceneKeys[1], kSceneKeys[2]},
        "the mipmap demo's slanted plane | a zone plate (2.5 texels a pixel) | magnified (256 texels over 300 pixels)",
        's');
    o.addFloat("lod-bias", &bias_, -1.0f, 1.0f, "LOD bias added to every method's level (GL_TEXTURE_LOD_BIAS for GL's)",
               'b', 'B', 0.25f);
    std::vector<std::string> kernels;
    for (int k = 0; k < kKernelCount; ++k) kernels.push_back(kernelKey(k));
    o.addEnum("kernel", &kernel_, kernels, "the mip kernel highlighted in the kernels view", 'k');
    o.addBool("linear-light", &linearLight_, "the kernels view's highlight: the chain made in linear light", 'g');
    o.addEnum("pattern", &pattern_, {"checker", "grid"},
              "the slanted plane's texture: checkerboard | labelled grid (256 x 256)", 't');
    o.addText("pick", &pick_,
              "the supports view's pixel X,Y in the 384 x 192 picture (0,0 top left); in the window, click a picture",
              [](const std::string& s) {
                const std::array<int, 2> p = ts::parsePixel(s, "--pick");
                if (p[0] < 0 || p[1] < 0 || p[0] >= kImageW || p[1] >= kImageH)
                  throw ts::Error("--pick " + s + ": outside the 384 x 192 picture");
              });
  }

  std::vector<ts::FigureSpec> figures() const override { return figureSpecs(); }  // filter_zoo_views.hpp

  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;
  std::vector<std::pair<std::string, std::string>> click(int x, int y, int width, int height) const override;

 private:
  Views views() const {
    Views v;
    v.scene = scene_, v.method = method_, v.pattern = pattern_, v.kernel = kernel_;
    v.azimuth = azimuth_, v.bias = bias_, v.linearLight = linearLight_;
    const std::array<int, 2> p = ts::parsePixel(pick_, "--pick");
    v.pickX = p[0], v.pickY = p[1];
    return v;
  }

  int view_ = kMethods, method_ = kProbes, scene_ = kSlant, kernel_ = kBox, pattern_ = kChecker;
  float azimuth_ = 45.0f, bias_ = 0.0f;
  bool linearLight_ = false;
  std::string pick_ = "250,100";
};

ts::Frame FilterZoo::build(int width, int height, const ts::Measurements& measured) const {
  const Result* m = measured.detailAs<Result>();
  // A first stage (coarseRow) has pictures, not the numbers these views plot.
  if (measured.refining && (view_ == kKernels || view_ == kBias || view_ == kMemory)) m = nullptr;
  ts::Frame f = ts::layout::blankFrame(width, height);
  const Views v = views();
  switch (view_) {
    case kAzimuthGrid: v.buildAzimuths(f, m, measured); break;
    case kSupports: v.buildSupports(f, m, measured); break;
    case kMemory: v.buildMemory(f, m, measured); break;
    case kKernels: v.buildKernels(f, m, measured); break;
    case kBias: v.buildBias(f, m); break;
    default: v.buildMethods(f, m); break;
  }
  return f;
}

// A click on a picture (a method's, in any view but memory and bias) picks
// its pixel: the supports view shows that pixel's footprint, with the
// clicked method (and azimuth) as the current ones.  The panels are found
// in a frame built over stand-in pictures (1 x 1), where they lie in the
// real one.
std::vector<std::pair<std::string, std::string>> FilterZoo::click(int x, int y, int width, int height) const {
  if (view_ == kMemory || view_ == kBias || view_ == kKernels) return {};
  Result stand;
  stand.scene = scene_;
  ts::TextureDesc one;
  one.name = "stand_in";
  one.image = std::make_shared<ts::Image>(1, 1);
  std::vector<double> azs(kAzimuths.begin(), kAzimuths.end());
  azs.push_back(azimuth_);
  for (double az : azs) {
    Row row;
    row.azimuth = az;
    row.pictures.fill(one);
    stand.rows.push_back(row);
  }
  ts::Measurements m;
  m.detail = stand;
  const ts::Frame f = build(width, height, m);
  for (const ts::Panel& p : f.panels) {
    if (!p.viewport.contains(x, y) || p.viewport.w <= 0 || p.viewport.h <= 0) continue;
    std::string method;
    double az = azimuth_;
    if (p.id == "picture") method = methodKey(method_);
    else if (p.id.rfind("method_", 0) == 0) method = p.id.substr(7);
    else if (p.id.rfind("az", 0) == 0 && p.id.find('_') != std::string::npos) {
      const size_t u = p.id.find('_');
      az = std::stod(p.id.substr(2, u - 2)), method = p.id.substr(u + 1);
    } else {
      continue;
    }
    const int px = std::clamp(int((x - p.viewport.x + 0.5) * kImageW / p.viewport.w), 0, kImageW - 1);
    const int py = std::clamp(int((y - p.viewport.y + 0.5) * kImageH / p.viewport.h), 0, kImageH - 1);
    return {{"pick", std::to_string(px) + "," + std::to_string(py)},
            {"view", kViewKeys[kSupports]},
            {"method", method},
            {"azimuth", fmt("%g", az)}};
  }
  return {};
}

ts::Measurements FilterZoo::measure(ts::Renderer& r) {
  Result res;
  res.renderer = ts::gl::rendererString();
  res.scene = scene_;
  ts::Measurements ms;
  std::vector<double> azs;
  if (scene_ == kSlant) azs.assign(kAzimuths.begin(), kAzimuths.end());
  if (std::find(azs.begin(), azs.end(), double(azimuth_)) == azs.end()) azs.push_back(azimuth_);

  std::unique_ptr<Row> currentRow;  // measured first in a window (its second stage)
  if (ts::measureStaged() && view_ != kKernels && view_ != kBias && view_ != kMemory) {
    // 0. In a window, a first stage at once: the GL methods' pictures, the
    // CPU methods' coarse (coarseRow), refined in place by what follows.
    // Once the coarse pictures are made, the current azimuth's CPU work (the
    // exact integral, the CPU methods, the reads counted: some 0.45
    // CPU-seconds, no GL) starts on a thread of its own, beside GL's
    // pictures (llvmpipe draws the anisotropic filter in about 0.1 s) and the
    // window's first frames.  It keeps to one thread until the stage is
    // handed over (RowShare), so that the stage is not delayed much, then
    // takes both cores; the second stage finds it made.
    std::future<void> cpu;  // waited for last, however this ends
    struct Share {          // closed for the first stage, open again however it ends
      Share() { RowShare::get().set(false); }
      ~Share() { RowShare::get().set(true); }
    } share;
    auto startCpu = [&] {
      if (!cpu.valid()) cpu = std::async(std::launch::async, cpuRowWork, scene_, pattern_, double(azimuth_), bias_);
    };
    Result first = res;
    for (size_t k = 0; k < azs.size(); ++k) {
      if (view_ != kAzimuthGrid && azs[k] != double(azimuth_)) continue;  // the other views show one azimuth
      if (azs[k] == double(azimuth_)) first.current = int(first.rows.size());
      first.rows.push_back(coarseRow(r, scene_, pattern_, azs[k], bias_, startCpu));
    }
    ts::Measurements stage;
    stage.detail = first;
    ts::measureStage(std::move(stage));
    RowShare::get().set(true);
    // A second stage: the current azimuth's row in full, before anything
    // else.  It is all the methods view shows (pictures, RMS, reads), so that
    // view is complete here; the other azimuths' rows and the numbers follow.
    cpu.get();
    currentRow = std::make_unique<Row>(measureRow(r, scene_, pattern_, azimuth_, bias_, true));
    for (Row& row : first.rows)
      if (row.azimuth == double(azimuth_)) row = *currentRow;
    ts::Measurements second;
    second.detail = first;
    ts::measureStage(std::move(second));
  }

  // 1. Magnification counts, read from texel-index renders.
  auto counts = [&](int pixels) { return countTexels(texelsShown(r, pixels)); };
  res.mag300 = counts(300), res.mag512 = counts(512), res.mag200 = counts(200);
  ms.push_back({"mag_texels_twice[300]", double(res.mag300.twice),
                "GL_NEAREST, 256 texels over 300 pixels: texels shown twice"});
  ms.push_back({"mag_texels_once[300]", double(res.mag300.once), "... texels shown once (unequal pixel counts)"});
  ms.push_back(
      {"mag_texels_twice[512]", double(res.mag512.twice), "256 texels over 512 pixels: texels shown twice (all)"});
  ms.push_back({"min_texels_unseen[200]", double(res.mag200.unseen), "256 texels over 200 pixels: texels never shown"});

  // 2. Memory, 3. levels.
  ms.push_back({"mip_memory_ratio", mipMemoryRatio(kTexels, kTexels), "a 256^2 mip chain over the texture (4/3)"});
  ms.push_back(
      {"ripmap_memory_ratio", ripmapMemoryRatio(kTexels, kTexels), "a 256^2 ripmap over the texture, (2 - 2^-8)^2"});
  ms.push_back({"ripmap_overhead", ripmapMemoryRatio(kTexels, kTexels) - 1, "what seed 001 calls 3x"});
  for (int s : {256, 512, 1024})
    ms.push_back({"sat_bits[" + std::to_string(s) + "]", double(satBits(s, s)),
                  "bits a SAT entry needs at " + std::to_string(s) + "^2, 8-bit texels"});
  ms.push_back({"sat_memory_ratio", satBits(kTexels, kTexels) / 8.0,
                "a 256^2 SAT over the 8-bit texture (its bits a channel / 8)"});
  const ts::Image white(1, 1, {255, 255, 255, 255});
  for (int s : {256, 512})
    ms.push_back({"sat_float_inexact[" + std::to_string(s) + "]", double(floatSatMismatches(white, s)),
                  "SAT entries of an all-255 " + std::to_string(s) + "^2 texture that 32-bit float sums get wrong"});
  ms.push_back({"levels[32x64]", double(ts::buildMipChain(ts::Image(32, 64)).size()),
                "levels of a 32 x 64 texture in GL (to 1 x 1)"});
  ms.push_back({"levels_seed[32x64]", double(seedLevelCount(32, 64)), "seed 001's rule: until either side is 1"});

  // 4. The two LOD forms: the reference on a flat view turned 45 degrees, and GL.
  const View turned = flatView(64, 64, 45, 4, {128, 128});
  ms.push_back(
      {"lod_form_gap_45deg", lodFormGap(turned.jacobian(32.5, 32.5)), "log2(rho_edge / rho_max), footprint at 45 deg"});
  ms.push_back(
      {"lod_form_gap_0deg", lodFormGap(flatView(64, 64, 0, 4, {128, 128}).jacobian(32.5, 32.5)), "... along the axes"});
  res.lodGl0 = glLevelAt(r, 0, 2.5), res.lodGl45 = glLevelAt(r, 45, 2.5);
  ms.push_back({"lod_gl[0deg]", res.lodGl0,
                "the level GL's trilinear filter reads where rho_edge = 2^2.5, footprint along the axes"});
  ms.push_back(
      {"lod_gl[45deg]", res.lodGl45, "... the same footprint turned 45 deg (edge form: 2.5; largest component: 2.0)"});
  ms.push_back({"lod_gl_drop_45deg", res.lodGl0 - res.lodGl45,
                "0: this rasterizer uses GL's edge form (llvmpipe); 0.5: the largest-component form (softpipe)"});

  // 5. SAT's box.
  ms.push_back({"sat_box_ratio[8to1_45deg]", satBoxRatio(footprint(8, 1, 45)),
                "SAT's bounding box over an 8:1 footprint at 45 deg"});
  ms.push_back({"sat_box_ratio[8to1_0deg]", satBoxRatio(footprint(8, 1, 0)), "... along the axes"});

  // 6, 7. Every method against the exact integral.
  ts::measureProgress(0.1);
  for (size_t k = 0; k < azs.size(); ++k) {
    ts::measureProgress(0.1 + 0.5 * double(k) / double(azs.size()));
    const bool current = azs[k] == double(azimuth_);
    res.rows.push_back(current && currentRow ? *currentRow : measureRow(r, scene_, pattern_, azs[k], bias_, current));
    if (current) res.current = int(k);
  }
  const std::string where = scene_ == kSlant ? "" : std::string(kSceneKeys[scene_]) + "_";
  for (const Row& row : res.rows) {
    if (scene_ == kSlant && row.azimuth != kAzimuths[0] && row.azimuth != kAzimuths[1] && row.azimuth != kAzimuths[2])
      continue;
    for (int m = kNearest; m < kMethodCount; ++m)
      ms.push_back({"rms_exact[" + std::string(methodKey(m)) + "@" + where + azKey(row.azimuth) + "]",
                    row.rms[size_t(m)],
                    std::string(methodTitle(m)) + " against the exact area integral (8-bit RMS), texture turned " +
                        azKey(row.azimuth) + " deg"});
  }
  // GL_NEAREST_MIPMAP_NEAREST against GL_NEAREST: where the chain's levels
  // keep level 0's colours under a nearest sample, the two pictures agree.
  if (scene_ == kSlant) {
    ms.push_back(
        {"last_level_like_level0",
         double(lastLevelLikeLevel0(ts::buildMipChain(*sceneTexture(scene_, pattern_).image))),
         "the last mip level in which a nearest sample takes level 0's colour everywhere (GL_NEAREST_MIPMAP_NEAREST = "
         "GL_NEAREST up to lambda = it + 0.5)"});
    long inMask = 0;
    double fromLod = HUGE_VAL;
    for (const Row& row : res.rows) inMask += row.nmnDiffersInMask, fromLod = std::min(fromLod, row.nmnDiffersFromLod);
    ms.push_back(
        {"nmn_nearest_differ_far", double(inMask),
         "far-field pixels where GL_NEAREST_MIPMAP_NEAREST's picture differs from GL_NEAREST's (every azimuth)"});
    ms.push_back({"nmn_nearest_differ_lod_min", fromLod,
                  "the lowest exact LOD of a pixel where the two pictures differ (every azimuth)"});
  }
  const Row& cur = res.rows[size_t(res.current)];
  for (int m = 0; m < kMethodCount; ++m)
    if (cur.reads[size_t(m)] >= 0)
      ms.push_back(
          {"texels_per_pixel[" + std::string(methodKey(m)) + "]", cur.reads[size_t(m)],
           m == kExact ? "texels the exact integral weighs, mean per pixel" : "texels read per pixel, mean, counted"});

  // 8, 9. The kernels and the bias, in their views.
  if (view_ == kKernels) {
    res.kernels = measureKernels(r, pattern_, azimuth_, bias_);
    for (const KernelRow& k : res.kernels) {
      const std::string key = std::string(kernelKey(k.kernel)) + (k.linear ? "_linear" : "_srgb");
      ms.push_back({"rms_kernel[" + key + "]", k.rms,
                    std::string("trilinear with this chain against the exact integral") +
                        (k.linear ? " of linear light" : "") + " (far field)"});
      ms.push_back({"mip_top[" + key + "]", k.top, "the chain's 1 x 1 level (grey)"});
    }
    // What every 1 x 1 level stands for, and how far the kernels' chains end from it.
    const ts::TextureDesc board = sceneTexture(kSlant, pattern_);
    const ts::Image& base = *board.image;
    for (bool lin : {false, true}) {
      const std::string domain = lin ? "linear" : "srgb";
      const double mean = meanGrey(base, lin);
      double worst = 0;
      for (const KernelRow& k : res.kernels)
        if (k.linear == lin) worst = std::max(worst, std::abs(k.top - mean));
      ms.push_back({"mip_mean[" + domain + "]", mean,
                    std::string("the texture's mean grey in double precision, of its ") +
                        (lin ? "linear-light values, encoded" : "sRGB values")});
      ms.push_back({"mip_top_max_error[" + domain + "]", worst,
                    "the largest |1 x 1 level - that mean| over the kernels (8-bit rounding at each level)"});
    }
  }
  if (view_ == kSupports) {
    const std::array<int, 2> px = ts::parsePixel(pick_, "--pick");
    const PickedPixel p = pickedPixel(scene_, azimuth_, px[0], px[1], bias_);
    if (p.on) {
      ms.push_back({"pick_preimage_texels", p.preimageTexels,
                    "the picked pixel's exact preimage: its area in texels of level 0"});
      ms.push_back({"pick_sat_box_ratio", p.satBoxRatio,
                    "SAT's box over the picked pixel's footprint (the derivative parallelogram)"});
      ms.push_back({"pick_lambda", p.lambda, "the picked pixel's lambda, log2 rho_edge (+ bias)"});
      ms.push_back({"pick_texels_per_pixel", p.texelsPerPixel,
                    "the picked pixel's rho_edge: texels a pixel along its longer side"});
      ms.push_back({"pick_probes", double(p.probe.n), "the probe line's probes at the picked pixel"});
      ms.push_back({"pick_probe_lambda", p.probe.lambda, "... and the level they read, log2(P_max / N)"});
    }
  }
  if (view_ == kBias) {
    res.bias = measureBias(r, pattern_, azimuth_, &res.flickerExact);
    for (const BiasRow& b : res.bias) {
      ms.push_back(
          {"rms_bias[" + fmt("%g", b.bias) + "]", b.rms, "trilinear at this LOD bias against the exact integral"});
      ms.push_back({"flicker[" + fmt("%g", b.bias) + "]", b.flicker,
                    "RMS of a frame's change, the plane moving 1/8 texel a frame"});
    }
    ms.push_back({"flicker_exact", res.flickerExact, "RMS of the exact picture's own change a frame"});
  }
  ms.detail = res;
  return ms;
}
}  // namespace

TS_REGISTER_SCENE(FilterZoo);
