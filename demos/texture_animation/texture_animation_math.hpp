// demos/texture_animation/texture_animation_math.hpp — the CPU's answers the GL passes of the flipbook, the
// torch and the moving light are measured against (texture_animation_gl.hpp).  GL-free.  Textures are indexed
// as GL uploads them: texel (i, j), row j = 0 at t = 0 (the bottom); readbacks (Renderer::offscreen) have row 0
// at the top, so a readback's pixel (x, y) is window row h - 1 - y.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <utility>

#include "common/core/image.hpp"
#include "demos/texture_animation/texture_animation_textures.hpp"

namespace ts::texanim {
// ---- the flipbook ----------------------------------------------------------------------------------------
constexpr int kFlipTexels = 64;  // each frame 64 x 64 RGBA
constexpr int kFlipFrames = 8;   // the loop's frames
constexpr int kFlipZoom = 2;     // shown at 2 x 2 pixels a texel, GL_NEAREST: every pixel one texel

// A rectangle of texels, (x, y) its lower-left texel (y up, as glTexSubImage2D's xoffset, yoffset).
struct TexRect {
  int x = 0, y = 0, w = 0, h = 0;
  int texels() const { return w * h; }
  bool contains(int i, int j) const { return i >= x && i < x + w && j >= y && j < y + h; }
};

// The smallest rectangle holding every texel where a and b differ (w = h = 0: none).
inline TexRect changedRect(const Image& a, const Image& b) {
  int x0 = a.width, y0 = a.height, x1 = -1, y1 = -1;
  for (int j = 0; j < a.height; ++j)
    for (int i = 0; i < a.width; ++i)
      if (a.at(i, j) != b.at(i, j))
        x0 = std::min(x0, i), y0 = std::min(y0, j), x1 = std::max(x1, i), y1 = std::max(y1, j);
  if (x1 < 0) return {};
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

// The texels of `r` packed row after row, as glTexSubImage2D reads them with GL_UNPACK_ALIGNMENT 1.
inline Image subImage(const Image& img, const TexRect& r) {
  Image out(r.w, r.h);
  for (int j = 0; j < r.h; ++j)
    for (int i = 0; i < r.w; ++i) out.set(i, j, img.at(r.x + i, r.y + j));
  return out;
}

// Pixels of a readback (row 0 the top) of `tex` drawn at `zoom` pixels a texel from the lower-left corner whose
// colour is not the texel's: what a frame shown against another frame's texels counts too.
inline int zoomMismatches(const Image& readback, const Image& tex, int zoom) {
  int n = 0;
  for (int y = 0; y < readback.height; ++y)
    for (int x = 0; x < readback.width; ++x) {
      const Rgba a = readback.at(x, y), b = tex.at(x / zoom, (readback.height - 1 - y) / zoom);
      n += a.r != b.r || a.g != b.g || a.b != b.b;
    }
  return n;
}

// ---- the torch ---------------------------------------------------------------------------------------------
// A 192 x 192 picture in window pixels (y up): the wall (the water texture, 64 texels at 3 pixels a texel,
// opaque), the torch's handle (an untextured opaque rectangle), and two flame quads (flipbook frames at 2 pixels
// a texel, alpha), the back one farther than the front one; depth = the order front to back.
constexpr int kTorchPixels = 192;
constexpr int kWallZoom = 3;
struct PixRect {
  int x, y, w, h;  // lower-left pixel, y up
  bool contains(int px, int py) const { return px >= x && px < x + w && py >= y && py < y + h; }
};
constexpr PixRect kHandle{84, 0, 24, 72};
constexpr PixRect kBackFlame{24, 56, kFlipTexels* kFlipZoom, kFlipTexels* kFlipZoom};
constexpr PixRect kFrontFlame{48, 40, kFlipTexels* kFlipZoom, kFlipTexels* kFlipZoom};
constexpr float kWallZ = -0.9f, kHandleZ = -0.5f, kBackZ = -0.3f, kFrontZ = 0.0f;  // larger z is nearer
inline const Rgba kHandleColour{110, 70, 40, 255};
// The flipbook frames the flames show at frame k: two tongues out of step.
inline int backFlameFrame(int k) { return ((k % kFlipFrames) + kFlipFrames) % kFlipFrames; }
inline int frontFlameFrame(int k) { return (backFlameFrame(k) + 3) % kFlipFrames; }

// c = s a + d (1 - a), in 8 bits, as glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) gives it (GL may round the
// other way: each blended layer is allowed one level, kTorchLevelsPerLayer).
inline uint8_t over(uint8_t s, uint8_t d, uint8_t a) { return uint8_t(std::lround((s * a + d * (255.0 - a)) / 255.0)); }
constexpr int kTorchLevelsPerLayer = 1;

// The right picture, layer by layer on the CPU: the opaque wall and handle, then the flames back to front.
// Row 0 the top, as a readback.
inline Image torchComposite(const Image& wall, const Image& back, const Image& front) {
  Image out(kTorchPixels, kTorchPixels);
  for (int y = 0; y < kTorchPixels; ++y)
    for (int x = 0; x < kTorchPixels; ++x) {
      const int py = kTorchPixels - 1 - y;
      Rgba c = wall.at(x / kWallZoom, py / kWallZoom);
      if (kHandle.contains(x, py)) c = kHandleColour;
      for (const auto& [rect, tex] : {std::pair{kBackFlame, &back}, std::pair{kFrontFlame, &front}}) {
        if (!rect.contains(x, py)) continue;
        const Rgba s = tex->at((x - rect.x) / kFlipZoom, (py - rect.y) / kFlipZoom);
        c = {over(s.r, c.r, s.a), over(s.g, c.g, s.a), over(s.b, c.b, s.a), 255};
      }
      out.set(x, y, c);
    }
  return out;
}

// Pixels whose colour differs from the reference's by more than `levels` in some channel.
inline int wrongPixels(const Image& got, const Image& want, int levels) {
  int n = 0;
  for (int y = 0; y < got.height; ++y)
    for (int x = 0; x < got.width; ++x) {
      const Rgba a = got.at(x, y), b = want.at(x, y);
      n += std::abs(a.r - b.r) > levels || std::abs(a.g - b.g) > levels || std::abs(a.b - b.b) > levels;
    }
  return n;
}

// ---- the moving light --------------------------------------------------------------------------------------
// A wall of unit side (the water texture, 64 texels, 4 pixels a texel, GL_NEAREST) lit by a point light circling
// over it: L(x, y) = a + (1 - a) (h / d)^3, Lambert's cos / d^2 with the wall's normal (0, 0, 1), 1 under the
// light.  The light map holds L at its texel centres (32 x 32, GL_LINEAR), modulating the base (GL_MODULATE).
constexpr int kLitPixels = 256;
constexpr int kLightTexels = 32;
constexpr double kLightPeriod = 8.0;  // seconds a turn
constexpr double kLightOrbit = 0.28, kLightHeight = 0.2, kAmbient = 0.15;

inline glm::dvec3 lightPosition(double seconds) {
  const double a = 2 * 3.14159265358979323846 * seconds / kLightPeriod;
  return {0.5 + kLightOrbit * std::cos(a), 0.5 + kLightOrbit * std::sin(a), kLightHeight};
}
inline double irradiance(const glm::dvec3& light, double x, double y) {
  const double d = glm::length(light - glm::dvec3(x, y, 0));
  return kAmbient + (1 - kAmbient) * std::pow(light.z / d, 3.0);
}
inline uint8_t level(double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

// The light map for `light`: grey, opaque, n x n, row 0 the bottom.
inline Image lightMapImage(int n, const glm::dvec3& light) {
  Image img(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint8_t l = level(irradiance(light, (i + 0.5) / n, (j + 0.5) / n));
      img.set(i, j, {l, l, l, 255});
    }
  return img;
}

// base x L per pixel, L from `lightAt(x, y)` at the pixel's centre; w x w, row 0 the top.
template <class F>
Image litPicture(const Image& base, int w, F lightAt) {
  Image out(w, w);
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) {
      const double sx = (x + 0.5) / w, sy = 1 - (y + 0.5) / w;
      const Rgba b = base.at(int(sx * base.width), int(sy * base.height));
      const double l = lightAt(sx, sy);
      out.set(x, y, {level(b.r / 255.0 * l), level(b.g / 255.0 * l), level(b.b / 255.0 * l), 255});
    }
  return out;
}
// The per-pixel lighting: L computed at every pixel.
inline Image perPixelLit(const Image& base, int w, const glm::dvec3& light) {
  return litPicture(base, w, [&](double x, double y) { return irradiance(light, x, y); });
}
// What GL_LINEAR reads of the map between its texel centres (clamped to the edge): the prediction of GL's picture.
inline double bilinear(const Image& map, double x, double y) {
  const double u = x * map.width - 0.5, v = y * map.height - 0.5;
  const int i0 = int(std::floor(u)), j0 = int(std::floor(v));
  const double fu = u - i0, fv = v - j0;
  auto at = [&](int i, int j) {
    return map.at(std::clamp(i, 0, map.width - 1), std::clamp(j, 0, map.height - 1)).r / 255.0;
  };
  return (1 - fv) * ((1 - fu) * at(i0, j0) + fu * at(i0 + 1, j0)) +
         fv * ((1 - fu) * at(i0, j0 + 1) + fu * at(i0 + 1, j0 + 1));
}
inline Image lightMapped(const Image& base, int w, const Image& map) {
  return litPicture(base, w, [&](double x, double y) { return bilinear(map, x, y); });
}

// ---- the pictures the figures show beside GL's (texture_animation_textures.cpp remakes them from the sidecar) ----
inline const glm::vec4 kChanged{1.0f, 0.0f, 1.0f, 1.0f};    // magenta: a texel that changed
inline const glm::vec4 kUploaded{1.0f, 0.9f, 0.0f, 1.0f};   // yellow: the rectangle a partial upload sends
inline const glm::vec4 kWrong{1.0f, 0.15f, 0.1f, 1.0f};     // red: a pixel off the CPU's composite
inline const glm::vec4 kLightNow{1.0f, 0.9f, 0.0f, 1.0f};   // yellow: the light at --time
inline const glm::vec4 kLightThen{0.0f, 0.9f, 1.0f, 1.0f};  // cyan: the light at time 0 (the stale map's)
inline Rgba rgba(const glm::vec4& c) { return {uint8_t(c.r * 255), uint8_t(c.g * 255), uint8_t(c.b * 255), 255}; }

// An image made `zoom` times larger, texel for texel (row order kept).
inline Image magnified(const Image& img, int zoom) {
  Image out(img.width * zoom, img.height * zoom);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) out.set(x, y, img.at(x / zoom, y / zoom));
  return out;
}
inline Rgba dimmed(Rgba c) { return {uint8_t(c.r / 3), uint8_t(c.g / 3), uint8_t(c.b / 3), 255}; }

// What changed from frame a to frame b: b's texels dimmed, the changed ones magenta, the rectangle's border yellow;
// row 0 the top, kFlipZoom pixels a texel (as the readbacks beside it).
inline Image changesPicture(const Image& a, const Image& b, const TexRect& r) {
  Image out(a.width, a.height);
  for (int j = 0; j < a.height; ++j)
    for (int i = 0; i < a.width; ++i) {
      const bool border = r.contains(i, j) && (i == r.x || i == r.x + r.w - 1 || j == r.y || j == r.y + r.h - 1);
      const Rgba c = border ? rgba(kUploaded) : a.at(i, j) != b.at(i, j) ? rgba(kChanged) : dimmed(b.at(i, j));
      out.set(i, a.height - 1 - j, c);
    }
  return magnified(out, kFlipZoom);
}
// The light map (row 0 the bottom) magnified to w x w, row 0 the top, with the light's place over the wall now
// (yellow) and at time 0 (cyan) marked by a cross.
inline Image lightMapPicture(const Image& map, int w, const glm::dvec3& now, const glm::dvec3& then) {
  Image out(w, w);
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) out.set(x, y, map.at(x * map.width / w, (w - 1 - y) * map.height / w));
  for (const auto& [p, c] : {std::pair{then, kLightThen}, std::pair{now, kLightNow}}) {
    const int cx = int(p.x * w), cy = w - 1 - int(p.y * w);
    for (int d = -6; d <= 6; ++d)
      for (int t = -1; t <= 1; ++t) {
        if (cx + d >= 0 && cx + d < w && cy + t >= 0 && cy + t < w) out.set(cx + d, cy + t, rgba(c));
        if (cx + t >= 0 && cx + t < w && cy + d >= 0 && cy + d < w) out.set(cx + t, cy + d, rgba(c));
      }
  }
  return out;
}

}  // namespace ts::texanim
