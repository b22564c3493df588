// Section VI.1.3 — mipmapping, popping, and the over-blur anisotropic
// filtering removes.
//
// The claims (Buss VI.1.3): level k+1 of a mipmap is the 2x2 average of
// level k, and the whole chain costs about a third more memory.  Drawing
// each pixel from the one level nearest the screen resolution makes the
// picture "pop" when the distance changes and the chosen level jumps;
// blending the two nearest levels (trilinear) removes it.  Mipmaps over-blur
// surfaces seen at a slant, where the pixel's footprint is long in one
// texture direction and short in the other: anisotropic filtering addresses
// that.
//
// Views: filmstrip (the first: the popping itself) — frames 1/4 level
// apart, the current filter above, trilinear below; single — a textured
// plane facing the eye at a distance (left half the texture, right half a
// texture whose mip levels are coloured, so the level GL chose is visible;
// the outlined square is the probe's size); plot — the mean colour of the probe against distance (steps =
// popping, ramps = none); slant — a ground plane to the horizon: an 8x8
// supersampled reference and the seven filters.
//
// Keys (each is also a flag, see --help):
//   v  view: filmstrip | single | plot | slant      f  minification filter
//   d / D  farther / nearer (log2 distance +-1/8)    b / B  LOD bias +-1/4
//   a / A  max anisotropy +-2 (2..16)                c  levels: texture | colours | split
//   t  texture: labelled grid | checkerboard         g  gamma-correct (linear-light) mip averages
//   m  move: animate the distance (after a 30-frame pause; counted in frames)
//
// What the GL does: common/gl/render.cpp: Renderer::texture uploads the chain
// built on the CPU, one glTexImage2D(GL_TEXTURE_2D, k, ...) per level k, and
// sets glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter),
// glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, bias) and
// glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, n) (where
// the extension is; n = 1 but for the anisotropic filter); Renderer::draw
// sends each plane (mipmap_popping_sweep.hpp: facingBatch, probeBatch, addSlant) as
// glTexCoord4f(s, t, 0, 1) + glVertex3f, (s, t) the plane's own (x, y) (the
// slant's (x, -z)), and GL picks the level from their screen derivatives.
// The slant's reference panel is a GLSL program (mipmap_popping_sweep.hpp: referenceFS,
// 8 x 8 texture2D lookups of level 0 per pixel).  Listings:
// book_figures/mip_popping_filmstrip.gl.txt, mip_anisotropic.gl.txt;
// mip_popping_plot.gl.txt draws only the plot (the sweep's renders are
// mipmap_popping_sweep.hpp's, through Renderer::renderOffscreen).
//
// The distance: the camera's focal length is 256 pixels and the 256-texel
// texture repeats once per world unit, so at distance d a pixel covers d
// texels and --distance-log2 x is the LOD (mipmap_popping_math.hpp derives it).
//
// Measured (printed, and on screen), every pass at a fixed size through
// Renderer::renderOffscreen (mipmap_popping_sweep.hpp): the chain's memory overhead (~1/3);
// the level GL used at the current distance, read back from the coloured
// levels, next to the analytic LOD; the popping measure of every filter —
// the largest jump of the probe's mean colour (coloured levels, 32 x 32
// pixels) between consecutive distances of a sweep in 1/16-level steps; and
// each filter's RMS error in the far field of the slanted plane against the
// supersampled reference (GL at 8x8 the resolution, GL_NEAREST on level 0,
// box-downsampled on the CPU).
//
// What Mesa does (record the renderer with every number): llvmpipe computes
// the LOD as log2(rho^2)/2 with a log2 that is linear between powers of
// two (up to 0.043 level low, so trilinear's blend is not quite linear in
// the LOD), one LOD per 2x2 quad; softpipe takes rho as the largest
// derivative component.  Both filter anisotropically with an EWA on one
// level, floor(LOD): on the coloured probe "anisotropic" switches level at
// integers as abruptly as GL_*_MIPMAP_NEAREST does at k + 1/2 (popping 210),
// though on a real texture the wide EWA kernel hides the switch.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"
#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "mipmap_popping_math.hpp"
#include "mipmap_popping_views.hpp"
#include "mipmap_popping_sweep.hpp"

namespace {
using namespace mipmap;

using namespace mipmap::views;  // the views, their options' values, the results they draw

using ts::layout::fmt;

// The window's animation: after kHoldFrames frames at the chosen distance,
// log2 distance moves kStepPerFrame per frame, bouncing between the ends of
// the distance range.  Counted in frames, not seconds, so a given frame
// always shows the same picture (the window tests compare screenshots).
constexpr int kHoldFrames = 30;
constexpr double kStepPerFrame = 1.0 / 64;

class MipmapPopping final : public ts::Scene {
 public:
  std::string id() const override { return "mipmap_popping"; }
  std::string title() const override { return "Section VI.1.3 - mipmapping and popping"; }
  std::string about() const override {
    return "A textured plane facing the eye at a distance you choose (or moving), drawn with any of the\n"
           "minification filters: level k+1 of the mipmap is the book's 2x2 average of level k (optionally in\n"
           "linear light); coloured levels show which level GL chose.  Prints the chain's memory overhead (~1/3),\n"
           "the level observed against the analytic LOD, the popping measure of every filter (the largest jump of\n"
           "a probe's mean colour between consecutive distances, 1/16 level apart) and, for a plane seen at a\n"
           "slant, each filter's far-field error against an 8x8 supersampled reference.";
  }
  int defaultWidth() const override { return 1024; }
  int defaultHeight() const override { return 512; }

  std::vector<std::string> claim() const override { return {"popping_ratio", "mip_overhead"}; }

  void addOptions(ts::Options& o) override {
    o.addEnum("view", &view_, {"filmstrip", "single", "plot", "slant"},
              "frames at several distances | single plane | probe colour vs distance | slanted plane", 'v');
    std::vector<std::string> names;
    for (int f = 0; f < kFilterCount; ++f) names.push_back(filterName(f));
    o.addEnum("filter", &filter_, names, "minification filter (anisotropic = trilinear + max anisotropy)", 'f');
    o.addFloat("distance-log2", &distLog2_, float(kMinLog2), float(kMaxLog2),
               "log2 of the plane's distance; the distance is the texels per pixel, so this is the LOD", 'd', 'D',
               0.125f);
    o.addFloat("lod-bias", &bias_, -4.0f, 4.0f, "GL_TEXTURE_LOD_BIAS added to the LOD", 'b', 'B', 0.25f);
    o.addInt("anisotropy", &aniso_, 2, 16, "GL_TEXTURE_MAX_ANISOTROPY of the anisotropic filter (2..16)", 'a', 'A', 2);
    o.addEnum("levels", &levels_, {"texture", "colours", "split"},
              "the texture | each mip level one colour | left texture, right colours", 'c');
    o.addEnum("pattern", &texture_, {"grid", "checker"}, "labelled grid or checkerboard (256 x 256)", 't');
    picture_.addOption(o, "the pattern (mip chain built from it)");
    camera_.addOptions(o);  // the slanted plane's view
    o.addBool("linear-light", &linearLight_, "average the mip levels in linear light (gamma-correct) instead of sRGB",
              'g');
    o.addBool("animate", &animate_, "window: move the plane to and fro (starts after 30 frames)", 'm');
  }

  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"mip_popping_filmstrip",
         "Section VI.1.3",
         "A plane facing the eye at eight distances, 1/4 level apart (left half: the texture; right half: a texture "
         "whose mip levels are coloured). Top: GL_NEAREST_MIPMAP_NEAREST uses one level and jumps to the next at "
         "LOD k + 1/2 (popping). Bottom: GL_LINEAR_MIPMAP_LINEAR blends the two nearest levels: the colour, and the "
         "blur, change smoothly.",
         {"--view", "filmstrip", "--filter", "nearest-mipmap-nearest", "--distance-log2", "2.875", "--levels", "split"},
         1024,
         400,
         "One level per pixel pops: the colour jumps by {popping[nearest_mipmap_nearest]} (8-bit) at a level change, "
         "{popping_ratio} times trilinear's largest step; the chain costs {mip_overhead} more memory."},
        {"mip_popping_plot",
         "Section VI.1.3",
         "Mean colour of a probe region (coloured mip levels) against log2 distance, in steps of 1/16 level. "
         "GL_NEAREST_MIPMAP_NEAREST (top) steps from one level's colour to the next: popping. "
         "GL_LINEAR_MIPMAP_LINEAR (bottom) ramps between them. The popping measure is the largest jump between "
         "neighbouring distances.",
         {"--view", "plot", "--filter", "nearest-mipmap-nearest", "--distance-log2", "2.875"},
         1024,
         640,
         "Largest step of the probe's mean colour, distances 1/16 level apart: {popping[nearest_mipmap_nearest]} "
         "with GL_NEAREST_MIPMAP_NEAREST, {popping[linear_mipmap_linear]} with GL_LINEAR_MIPMAP_LINEAR."},
        {"mip_anisotropic",
         "Section VI.1.3",
         "A ground plane seen at a slant: the supersampled reference (8x8 samples of level 0 per pixel) and the "
         "seven filters. GL_NEAREST and GL_LINEAR alias; the mipmap filters choose their level from the long side "
         "of the pixel's footprint and over-blur the distance, most visibly trilinear "
         "(GL_LINEAR_MIPMAP_LINEAR); anisotropic filtering (16) keeps the detail across the view. Numbers: RMS "
         "error against the reference in the far field (LOD 1.5 to 5, between the white lines).",
         {"--view", "slant", "--filter", "linear-mipmap-linear", "--anisotropy", "16", "--levels", "texture"},
         1280,
         640,
         "Far-field RMS error against the supersampled reference: trilinear {far_error[linear_mipmap_linear]} "
         "(over-blur), anisotropic 16x {far_error[anisotropic]}, GL_NEAREST {far_error[nearest]} (aliasing)."},
        {"inspect_aniso_footprint",
         "Section VI.1.3 (inside a pixel)",
         "One far pixel of the slanted plane (GL_LINEAR_MIPMAP_LINEAR), looked inside with --inspect X,Y "
         "--footprints: on level 0 of the texture, its exact preimage (white) is long and thin; trilinear filtering "
         "reads a square of side 2^lambda (yellow) from the long side, the texels outlined, and so over-blurs across; "
         "the EWA ellipse (magenta) is what an anisotropic filter reads instead.",
         {"--view", "slant", "--filter", "linear-mipmap-linear", "--anisotropy", "16", "--levels", "texture",
          "--inspect", "760,400", "--footprints"},
         1280,
         640,
         "The footprint is {inspect_anisotropy[1]} times longer than wide; trilinear reads at lambda "
         "{inspect_lambda[1]} (rho {inspect_rho[1]} texels), blurring the short side."},
    };
  }

  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;
  void update(double) override {
    if (animate_) ++animFrames_;
    else animFrames_ = 0;
  }

 private:
  // The plane's log2 distance as drawn (the option, or the animation).
  double shownLog2() const {
    if (!animate_ || animFrames_ <= kHoldFrames) return distLog2_;
    double span = kMaxLog2 - kMinLog2, x = distLog2_ - kMinLog2 + kStepPerFrame * (animFrames_ - kHoldFrames);
    double p = std::fmod(x, 2 * span);
    return kMinLog2 + (p <= span ? p : 2 * span - p);
  }
  using Result = mipmap::views::Result;  // what measure() found (null: not measured yet)
  // The drawing (mipmap_popping_views.hpp) for the current flags.
  mipmap::views::Views views() const { return {look(), levels_, animate_, shownLog2()}; }
  mipmap::Look look() const { return {filter_, aniso_, bias_, texture_, linearLight_, &picture_, camera_}; }

  int view_ = kFilmstrip, filter_ = kNearestMipNearest, aniso_ = 16, levels_ = kSplit, texture_ = 0;
  ts::UserTexture picture_;  // --texture FILE
  ts::OrbitCamera camera_;   // --yaw --pitch --zoom: the mouse, on the slanted plane
  float distLog2_ = 2.375f, bias_ = 0.0f;
  bool linearLight_ = false, animate_ = false;
  long animFrames_ = 0;
};

ts::Frame MipmapPopping::build(int width, int height, const ts::Measurements& measured) const {
  const Result* m = measured.detailAs<Result>();
  ts::Frame f = ts::layout::blankFrame(width, height);
  // The planes' (s, t) are their (x, y) or (x, -z): glTexCoord4f(s, t, 0, 1) in Renderer::draw
  // (mipmap_popping_sweep.hpp).
  switch (view_) {
    case kSingle: views().buildSingle(f, m); break;
    case kFilmstrip: views().buildFilmstrip(f, m); break;
    case kPlot: views().buildPlot(f, m); break;
    default: views().buildSlant(f, m); break;
  }
  return f;
}

ts::Measurements MipmapPopping::measure(ts::Renderer& r) {
  Result out;
  out.renderer = ts::gl::rendererString();
  out.anisotropy = ts::gl::hasExtension("GL_EXT_texture_filter_anisotropic") ||
                   ts::gl::hasExtension("GL_ARB_texture_filter_anisotropic") || ts::gl::version() >= 46;
  if (out.anisotropy) glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &out.maxAnisotropy);

  // 1. The chain's memory.
  ts::TextureDesc tex = mipmap::texture(look());
  std::vector<ts::Image> chain = ts::buildMipChain(*tex.image, linearLight_);
  out.overhead = ts::mipChainOverhead(chain);
  ts::Rgba top = chain.back().at(0, 0);
  out.topLevel = (top.r + top.g + top.b) / 3.0;

  // 2. The level observed at the current distance.
  Mean now = mipmap::probeAt(r, look(), distLog2_);
  out.levelObserved = levelFromColour(now, kLevels, &out.residual);

  // 3. Popping: every filter over the sweep.
  out.sweepLods = mipmap::sweepLods();
  for (int fl = 0; fl < kFilterCount; ++fl) {
    ts::measureProgress(0.1 + 0.6 * fl / kFilterCount);  // a window shows it; a newer key stops here
    mipmap::Look lk = look();
    lk.filter = fl;
    out.sweepMeans.push_back(mipmap::probeSweep(r, lk, out.sweepLods));
    out.popping[fl] = poppingMeasure(out.sweepMeans.back());
  }

  // 4. Far-field error on the slanted plane against the supersampled reference.
  ts::measureProgress(0.7);
  mipmap::SlantErrors se = mipmap::slantErrors(r, look());
  for (int fl = 0; fl < kFilterCount; ++fl) out.farError[fl] = se.error[fl];
  out.farPixels = se.pixels;

  const double lambda = distLog2_ + bias_;
  ts::Measurements ms;
  ms.push_back({"mip_overhead", out.overhead, "bytes of levels 1.. over level 0's bytes (the book: about 1/3)"});
  ms.push_back({"mip_levels", double(chain.size()), "levels of the 256 x 256 chain (256 .. 1)"});
  ms.push_back({"mip_top_level_value", out.topLevel,
                std::string("the 1x1 level: mean of the texture, averaged in ") +
                    (linearLight_ ? "linear light" : "sRGB values")});
  ms.push_back({"lod_analytic", lambda, "log2(texels per pixel) + bias at the current distance"});
  ms.push_back(
      {"level_expected", effectiveLevel(filter_, lambda), "level (k + blend weight) GL's rules give at that LOD"});
  ms.push_back({"level_observed", out.levelObserved, "level read back from the coloured levels at that distance"});
  for (int fl = 0; fl < kFilterCount; ++fl)
    ms.push_back({"popping[" + filterKey(fl) + "]", out.popping[fl],
                  "largest probe mean jump (8-bit) between distances 1/16 level apart"});
  double tri = out.popping[kLinearMipLinear];
  ms.push_back({"popping_ratio", tri > 0 ? out.popping[kNearestMipNearest] / tri : 0.0,
                "popping of NEAREST_MIPMAP_NEAREST / LINEAR_MIPMAP_LINEAR"});
  for (int fl = 0; fl < kFilterCount; ++fl)
    ms.push_back({"far_error[" + filterKey(fl) + "]", out.farError[fl],
                  fl == kAnisotropic ? "RMS vs 8x8 supersampled reference, slanted plane far field (renderer: " +
                                           out.renderer + ", max anisotropy " + std::to_string(aniso_) + ")"
                                     : "RMS vs 8x8 supersampled reference, slanted plane far field"});
  ms.push_back({"far_pixels", double(out.farPixels), "pixels in the far field"});
  ms.push_back({"anisotropy_supported", out.anisotropy ? 1.0 : 0.0,
                "EXT/ARB_texture_filter_anisotropic (max " + fmt("%g", out.maxAnisotropy) + ")"});
  ms.detail = out;
  return ms;
}
}  // namespace

TS_REGISTER_SCENE(MipmapPopping);
