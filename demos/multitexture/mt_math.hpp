// demos/multitexture/mt_math.hpp — the textures the demo combines and the
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

namespace mt {
inline uint8_t u8(double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

// ---- alpha: the cutout tree ----------------------------------------------
// 64 x 64 RGBA: a brown trunk and an elliptical green crown, alpha 255; alpha
// 0 everywhere else.  The transparent texels keep the leaves' green (not
// black), so that filtering across an edge mixes green with green: with the
// alpha test the edge shows no dark fringe, only a binary outline.  Every
// colour has blue <= 40, the sky behind it has blue 255, so a pixel's blue
// tells how much sky it shows.
constexpr int kTreeSize = 64;
inline const ts::Rgba kSky{100, 150, 255, 255};
inline bool inTree(double x, double y) {
  const bool trunk = std::abs(x - 0.5) < 0.07 && y < 0.4;
  const double ex = (x - 0.5) / 0.4, ey = (y - 0.62) / 0.34;
  return trunk || ex * ex + ey * ey < 1.0;
}
inline ts::Image treeTexture() {
  ts::Image t(kTreeSize, kTreeSize);
  for (int j = 0; j < kTreeSize; ++j)
    for (int i = 0; i < kTreeSize; ++i) {
      const double x = (i + 0.5) / kTreeSize, y = (j + 0.5) / kTreeSize;
      const bool trunk = std::abs(x - 0.5) < 0.07 && y < 0.4;
      const uint8_t shade = uint8_t(110 + ((i * 7 + j * 13) % 5) * 12);  // a little texture in the leaves
      ts::Rgba c = trunk && y < 0.3 ? ts::Rgba{110, 70, 30, 255} : ts::Rgba{40, shade, 30, 255};
      if (!inTree(x, y)) c = {40, 120, 30, 0};
      t.set(i, j, c);
    }
  return t;
}

// ---- the light map ----------------------------------------------------------
// A point light at height h over the centre of the unit square: irradiance
// on the plane ∝ cos / d² = h / d³, scaled to 1 below the light, plus an
// ambient term.  The per-pixel lighting the light map approximates.
inline double lightAt(double x, double y) {
  const double h = 0.3, d = std::sqrt((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) + h * h);
  return 0.15 + 0.85 * std::pow(h / d, 3.0);
}
// The light map at n x n: the lighting sampled at its texel centres (GL_LUMINANCE8).
inline ts::Image lightMap(int n) {
  ts::Image m(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint8_t v = u8(lightAt((i + 0.5) / n, (j + 0.5) / n));
      m.set(i, j, {v, v, v, 255});
    }
  return m;
}
// A spot, 32 x 32: bright inside radius 0.3 of its centre, a soft rim, the
// ambient level at its border (GL_CLAMP_TO_EDGE keeps it outside).
inline ts::Image spotMap() {
  constexpr int n = 32;
  ts::Image m(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double r = std::hypot((i + 0.5) / n - 0.5, (j + 0.5) / n - 0.5);
      const uint8_t v = u8(0.2 + 0.8 * std::clamp((0.42 - r) / 0.12, 0.0, 1.0));
      m.set(i, j, {v, v, v, 255});
    }
  return m;
}
// The base picture x the per-pixel lighting, as the CPU computes it for a
// w x w readback of the base (w = 2 x its size, GL_NEAREST: texel = pixel / 2).
inline ts::Image perPixelLit(const ts::Image& base, int w) {
  ts::Image out(w, w);
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) {
      const int row = w - 1 - y;  // window row
      const ts::Rgba b = base.at(x * base.width / w, row * base.height / w);
      const double l = lightAt((x + 0.5) / w, (row + 0.5) / w);
      out.set(x, y, {u8(b.r / 255.0 * l), u8(b.g / 255.0 * l), u8(b.b / 255.0 * l), 255});
    }
  return out;
}

// ---- the gloss map ----------------------------------------------------------
// A plane 2 x 1 (x in [0, 2]), viewed from straight above, two point lights
// at height 0.35 over (0.5, 0.5) and (1.5, 0.5): one highlight in each half.
// The gloss map g is 1 on the left half, 0.2 (51/255) on the right.
// Per vertex (Gouraud): i_diff = 0.1 + 0.3 Σ n·l, i_spec = 0.6 Σ (n·h)^80.
constexpr double kSpecular = 0.6, kGlossLow = 51.0 / 255.0;
inline glm::dvec2 glossLighting(double x, double y) {
  double diff = 0.1, spec = 0.0;
  for (double lx : {0.5, 1.5}) {
    const glm::dvec3 l = glm::normalize(glm::dvec3(lx - x, 0.5 - y, 0.35));
    const glm::dvec3 h = glm::normalize(l + glm::dvec3(0, 0, 1));
    diff += 0.3 * l.z, spec += kSpecular * std::pow(h.z, 80.0);
  }
  return {diff, spec};
}
inline ts::Image glossMap(int w, int h) {
  ts::Image g(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const uint8_t v = i < w / 2 ? 255 : uint8_t(kGlossLow * 255.0 + 0.5);
      g.set(i, j, {v, v, v, 255});
    }
  return g;
}

// ---- AB + CD ------------------------------------------------------------
// Four 64 x 64 textures with values kept so that AB + CD <= 1 (no clamping):
// A a ramp, B a checkerboard, C stripes, D a ring pattern.
constexpr int kAbcdSize = 64;
inline std::vector<ts::Image> abcdTextures() {
  std::vector<ts::Image> t(4, ts::Image(kAbcdSize, kAbcdSize));
  for (int j = 0; j < kAbcdSize; ++j)
    for (int i = 0; i < kAbcdSize; ++i) {
      const double x = (i + 0.5) / kAbcdSize, y = (j + 0.5) / kAbcdSize;
      const uint8_t a = uint8_t(60 + 120 * x), b = ((i / 8 + j / 8) % 2) ? 240 : 90;
      const uint8_t c = (i / 4) % 2 ? 135 : 40, d = uint8_t(70 + 65 * std::cos(18.0 * std::hypot(x - 0.5, y - 0.5)));
      t[0].set(i, j, {a, uint8_t(a / 2), uint8_t(180 - a / 2), 255});
      t[1].set(i, j, {b, b, uint8_t(b * 3 / 4), 255});
      t[2].set(i, j, {c, uint8_t(c / 2), c, 255});
      t[3].set(i, j, {d, d, uint8_t(135 - d / 2), 255});
    }
  return t;
}
// The CPU's AB + CD (or (AB + C) D when `framebufferOnly`), each product
// rounded to 8 bits as the framebuffer stores it, for a w x w readback
// (texel = pixel * 64 / w, GL_NEAREST).
inline ts::Image abcdCpu(const std::vector<ts::Image>& t, int w, bool framebufferOnly) {
  ts::Image out(w, w);
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) {
      const int i = x * kAbcdSize / w, j = (w - 1 - y) * kAbcdSize / w;
      const ts::Rgba A = t[0].at(i, j), B = t[1].at(i, j), C = t[2].at(i, j), D = t[3].at(i, j);
      uint8_t o[3];
      const uint8_t ca[3] = {A.r, A.g, A.b}, cb[3] = {B.r, B.g, B.b}, cc[3] = {C.r, C.g, C.b}, cd[3] = {D.r, D.g, D.b};
      for (int k = 0; k < 3; ++k) {
        const double ab = std::round(ca[k] * cb[k] / 255.0);
        o[k] = framebufferOnly ? u8(std::round(std::min(255.0, ab + cc[k])) * cd[k] / 255.0 / 255.0)
                               : u8((ab + std::round(cc[k] * cd[k] / 255.0)) / 255.0);
      }
      out.set(x, y, {o[0], o[1], o[2], 255});
    }
  return out;
}

// ---- the pear ------------------------------------------------------------
// A surface of revolution about y, radius r(v) at height y(v), v in [0, 1]:
// a pear's profile (a big sphere below, a small one above, blended).
inline glm::dvec2 pearProfile(double v) {  // (radius, height)
  const double neck = std::clamp((v - 0.3) / 0.45, 0.0, 1.0);
  const double r = std::sqrt(std::sin(3.14159265358979 * v)) * (0.52 - 0.24 * neck * neck * (3 - 2 * neck));
  return {r, -0.8 + 1.6 * v};
}
// 128 x 128 pictures for the pear: t_d a yellow-green skin with speckles,
// its alpha the gloss t_g (glossy skin, dull speckles and a dull band), the
// same gloss as a luminance texture, and t_r a sphere map of a sky and a
// bright window.
inline ts::Image pearSkin() {
  ts::Image t(128, 128);
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i < 128; ++i) {
      const bool speck = ((i * 37 + j * 91) % 53) < 3;
      const bool band = j > 70 && j < 84;
      const uint8_t g = speck || band ? 25 : 150;
      t.set(i, j, speck ? ts::Rgba{120, 90, 30, g} : ts::Rgba{uint8_t(170 + j / 4), 190, 60, g});
    }
  return t;
}
inline ts::Image sphereMapSky() {
  ts::Image t(128, 128);
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i < 128; ++i) {
      const double x = (i + 0.5) / 64 - 1, y = (j + 0.5) / 64 - 1;
      const bool window = x > 0.1 && x < 0.5 && y > 0.25 && y < 0.65;
      const uint8_t s = u8(0.1 + 0.3 * (y + 1) / 2);
      t.set(i, j, window ? ts::Rgba{255, 250, 235, 255} : ts::Rgba{uint8_t(s / 2), s, uint8_t(std::min(255, s * 2)), 255});
    }
  return t;
}

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
