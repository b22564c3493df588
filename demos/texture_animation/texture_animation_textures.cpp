// demos/texture_animation/texture_animation_textures.cpp — the demo's textures (texture_animation_textures.hpp),
// and their generator for the sidecar reader.
#include "demos/texture_animation/texture_animation_textures.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/gl_enums.hpp"
#include "common/core/texture_generators.hpp"
#include "demos/texture_animation/texture_animation_math.hpp"

namespace ts::texanim {
namespace {
// A shade in [0, 1) from two integers: the same on every platform (32-bit unsigned arithmetic).
double hash(uint32_t i, uint32_t j) {
  uint32_t h = i * 73856093u ^ j * 19349663u;
  h ^= h >> 15, h *= 0x2c1b3c6du, h ^= h >> 12, h *= 0x297a2d39u, h ^= h >> 15;
  return double(h & 0xffffu) / 65536.0;
}
uint8_t u8(double v) { return uint8_t(v < 0 ? 0 : v > 255 ? 255 : v + 0.5); }
}  // namespace

TextureDesc waterTexture(int size) {
  Image img(size, size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      // Streaks: a shade that runs six texels down its column, and each texel's own, so no two rows match.
      const double b = 0.3 + 0.55 * hash(uint32_t(i), uint32_t(j / 6) + 1000u) + 0.15 * hash(uint32_t(i), uint32_t(j));
      img.set(i, j, {u8(20 + 90 * b), u8(70 + 150 * b), u8(120 + 135 * b), 255});
    }
  TextureDesc t;
  t.name = "texture_animation_water";
  t.params = {{"size", std::to_string(size)}};
  t.image = std::make_shared<const Image>(std::move(img));
  t.minFilter = t.magFilter = GL_NEAREST;
  t.wrapS = t.wrapT = GL_REPEAT;
  return t;
}

Image flameFrame(int size, int k, int n) {
  Image img(size, size);
  const double kPi = 3.14159265358979323846;
  const double phase = 2 * kPi * double(((k % n) + n) % n) / n;
  const double tall = 0.78 + 0.12 * std::sin(2 * phase + 1.0);  // the flame's height flickers
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const double u = (i + 0.5) / size, v = (j + 0.5) / size;
      const double t = (v - 0.08) / tall;  // 0 at the flame's foot, 1 at its tip
      // The tongue: centred on a line that sways more towards the tip, narrowing to the tip.
      const double c = 0.5 + 0.08 * t * std::sin(2 * kPi * 1.3 * t - phase);
      const double w = 0.24 * (1 - t) * std::sqrt(std::min(1.0, 5 * std::max(t, 0.0)));
      const double q = t <= 0 || t >= 1 || w <= 0 ? 0.0 : 1 - std::abs(u - c) / w;
      if (q <= 0) {
        img.set(i, j, {60, 20, 0, 0});  // transparent: the same texel in every frame
        continue;
      }
      const double grain = 0.12 * (hash(uint32_t(i), uint32_t(j) + 4096u * uint32_t(k % n)) - 0.5);
      const double heat = std::clamp(q * (1 - 0.5 * t) + grain, 0.0, 1.0);
      img.set(i, j,
              {255, u8(70 + 185 * heat), u8(20 + 200 * heat * heat * heat),
               u8(std::clamp(1.6 * q + grain, 0.0, 1.0) * 255)});
    }
  return img;
}

namespace {
// Seconds as the sidecar writes them: every digit a float holds, read back the same.
std::string secondsText(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", s);
  return b;
}
TextureDesc picture(const std::string& name, std::vector<std::pair<std::string, std::string>> params, Image img,
                    GLenum filter) {
  TextureDesc t;
  t.name = name;
  t.params = std::move(params);
  t.image = std::make_shared<const Image>(std::move(img));
  t.minFilter = t.magFilter = filter;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}
// A picture made row 0 at the top (as a readback beside it), as a texture (row 0 at t = 0).
Image upsideDown(Image img) {
  img.flipVertical();
  return img;
}
}  // namespace

TextureDesc flameTexture(int size, int k, int n, bool opaque) {
  Image img = flameFrame(size, k, n);
  if (opaque)
    for (size_t i = 3; i < img.pixels.size(); i += 4) img.pixels[i] = 255;
  return picture("texture_animation_flame",
                 {{"size", std::to_string(size)},
                  {"frame", std::to_string(k)},
                  {"frames", std::to_string(n)},
                  {"opaque", opaque ? "1" : "0"}},
                 std::move(img), GL_NEAREST);
}

TextureDesc lightMapTexture(int texels, double seconds) {
  return picture("texture_animation_light_map", {{"texels", std::to_string(texels)}, {"seconds", secondsText(seconds)}},
                 lightMapImage(texels, lightPosition(seconds)), GL_LINEAR);
}

TextureDesc litTexture(double seconds) {
  return picture("texture_animation_lit", {{"seconds", secondsText(seconds)}},
                 upsideDown(perPixelLit(*waterTexture(kFlipTexels).image, kLitPixels, lightPosition(seconds))),
                 GL_LINEAR);
}

TextureDesc lightMapPictureTexture(double seconds) {
  const glm::dvec3 now = lightPosition(seconds);
  return picture("texture_animation_light_map_picture", {{"seconds", secondsText(seconds)}},
                 upsideDown(lightMapPicture(lightMapImage(kLightTexels, now), kLitPixels, now, lightPosition(0))),
                 GL_LINEAR);
}

TextureDesc changesTexture(int k) {
  const Image a = flameFrame(kFlipTexels, k, kFlipFrames), b = flameFrame(kFlipTexels, k + 1, kFlipFrames);
  return picture("texture_animation_changes", {{"frame", std::to_string(k)}},
                 upsideDown(changesPicture(a, b, changedRect(a, b))), GL_LINEAR);
}

TextureDesc torchTexture(int k) {
  const Image wall = *waterTexture(kFlipTexels).image;
  const Image back = flameFrame(kFlipTexels, backFlameFrame(k), kFlipFrames);
  const Image front = flameFrame(kFlipTexels, frontFlameFrame(k), kFlipFrames);
  return picture("texture_animation_torch", {{"frame", std::to_string(k)}},
                 upsideDown(torchComposite(wall, back, front)), GL_LINEAR);
}

namespace {
double secondsParam(const TextureParams& params, const std::string& name) {
  const std::string s = strParam(params, "seconds", name);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end || !(v >= -1e6 && v <= 1e6))
    throw Error("sidecar: texture '" + name + "': bad seconds '" + s + "'");
  return v;
}
int rangedParam(const TextureParams& params, const std::string& key, const std::string& name, int lo, int hi) {
  const int v = intParam(params, key, name);
  if (v < lo || v > hi) throw Error("sidecar: texture '" + name + "': " + key + " out of range");
  return v;
}
bool remake(const std::string& name, const TextureParams& params, TextureDesc* out) {
  if (name == "texture_animation_water") *out = waterTexture(rangedParam(params, "size", name, 1, 4096));
  else if (name == "texture_animation_flame")
    *out = flameTexture(rangedParam(params, "size", name, 1, 4096), rangedParam(params, "frame", name, 0, 1 << 20),
                        rangedParam(params, "frames", name, 1, 1024), rangedParam(params, "opaque", name, 0, 1) == 1);
  else if (name == "texture_animation_light_map")
    *out = lightMapTexture(rangedParam(params, "texels", name, 1, 4096), secondsParam(params, name));
  else if (name == "texture_animation_lit") *out = litTexture(secondsParam(params, name));
  else if (name == "texture_animation_light_map_picture") *out = lightMapPictureTexture(secondsParam(params, name));
  else if (name == "texture_animation_changes") *out = changesTexture(rangedParam(params, "frame", name, 0, 1 << 20));
  else if (name == "texture_animation_torch") *out = torchTexture(rangedParam(params, "frame", name, 0, 1 << 20));
  else return false;
  return true;
}
}  // namespace
}  // namespace ts::texanim

// The sidecar reader finds it through the registry (common/core/texture_generators.hpp).
TS_REGISTER_TEXTURE_GENERATOR("texture_animation_*", ts::texanim::remake);
