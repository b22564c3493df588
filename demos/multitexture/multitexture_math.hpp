// demos/multitexture/multitexture_math.hpp — the textures the demo combines and the
// CPU's answers GL is measured against (seed 001 ¶25–32, Buss VI intro).
// CPU only.  Every texture here is indexed as GL uploads it: texel (i, j),
// row j = 0 at t = 0 (the bottom); GL readbacks (Renderer::offscreen) have
// row 0 at the top, so a pixel (x, y) of a readback is window row h-1-y.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/core/image.hpp"
#include "demos/multitexture/multitexture_textures.hpp"

namespace mt {
inline uint8_t u8(double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

// The tree, the bricks, the light and spot maps, the gloss map and A, B, C,
// D are named generators in demos/multitexture/multitexture_textures.hpp (the
// sidecar remakes them); here under the demo's names.
using ts::multitex::kSky;
using ts::multitex::inTree;
using ts::multitex::lightAt;
inline ts::Image treeTexture() { return ts::multitex::treeImage(); }
inline ts::Image lightMap(int n) { return ts::multitex::lightMapImage(n); }
// The base x the per-pixel lighting for a w x w readback (row 0 the top).
inline ts::Image perPixelLit(const ts::Image& base, int w) {
  ts::Image img = ts::multitex::perPixelLitImage(base, w);
  img.flipVertical();
  return img;
}

// ---- the gloss map ----------------------------------------------------------
// A plane 2 x 1 (x in [0, 2]), viewed from straight above, two point lights
// at height 0.35 over (0.5, 0.5) and (1.5, 0.5): one highlight in each half.
// The gloss map g is 1 on the left half, 0.2 (51/255) on the right.
// Per vertex (Gouraud): i_diff = 0.1 + 0.3 Σ n·l, i_spec = 0.6 Σ (n·h)^80.
constexpr double kSpecular = 0.6;
using ts::multitex::kGlossLow;
inline glm::dvec2 glossLighting(double x, double y) {
  double diff = 0.1, spec = 0.0;
  for (double lx : {0.5, 1.5}) {
    const glm::dvec3 l = glm::normalize(glm::dvec3(lx - x, 0.5 - y, 0.35));
    const glm::dvec3 h = glm::normalize(l + glm::dvec3(0, 0, 1));
    diff += 0.3 * l.z, spec += kSpecular * std::pow(h.z, 80.0);
  }
  return {diff, spec};
}

// ---- AB + CD ------------------------------------------------------------
// Four 64 x 64 textures with AB + CD <= 1; the CPU's AB + CD (or (AB + C) D),
// each product rounded to 8 bits, for a w x w readback (row 0 the top).
using ts::multitex::kAbcdSize;
inline std::vector<ts::Image> abcdTextures() { return ts::multitex::abcdImages(); }
inline ts::Image abcdCpu(const std::vector<ts::Image>& t, int w, bool framebufferOnly) {
  return ts::multitex::abcdCpuImage(t, w, framebufferOnly);
}

// ---- the pear ------------------------------------------------------------
// A surface of revolution about y, radius r(v) at height y(v), v in [0, 1]:
// a pear's profile (a big sphere below, a small one above, blended).
inline glm::dvec2 pearProfile(double v) {  // (radius, height)
  const double neck = std::clamp((v - 0.3) / 0.45, 0.0, 1.0);
  const double r = std::sqrt(std::sin(3.14159265358979 * v)) * (0.52 - 0.24 * neck * neck * (3 - 2 * neck));
  return {r, -0.8 + 1.6 * v};
}
// Its pictures (the skin t_d with the gloss t_g as alpha, t_g as grey, the
// sphere map t_r) are named generators: ts::multitex::pearSkinImage, ...

// ---- measuring the readbacks ---------------------------------------------
// The largest channel difference and the RMS over RGB: common/core/image.hpp.
inline int maxDiff(const ts::Image& a, const ts::Image& b) { return ts::maxChannelDiff(a, b); }
inline double rms(const ts::Image& a, const ts::Image& b) { return ts::rmsRgb(a, b); }
// Opaque copy (GL's passes leave the alpha they blended).
inline ts::Image opaque(ts::Image img) {
  for (size_t k = 3; k < img.pixels.size(); k += 4) img.pixels[k] = 255;
  return img;
}
}  // namespace mt
