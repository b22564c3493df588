// demos/texture_animation/texture_animation_textures.cpp — the waterfall's texture
// (texture_animation_textures.hpp), and its generator for the sidecar reader.
#include "demos/texture_animation/texture_animation_textures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

#include "common/core/error.hpp"
#include "common/core/gl_enums.hpp"
#include "common/core/texture_generators.hpp"

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
bool remake(const std::string& name, const TextureParams& params, TextureDesc* out) {
  if (name != "texture_animation_water") return false;
  const int size = intParam(params, "size", name);
  if (size < 1 || size > 4096) throw Error("sidecar: texture '" + name + "': size out of range");
  *out = waterTexture(size);
  return true;
}
}  // namespace
}  // namespace ts::texanim

// The sidecar reader finds it through the registry (common/core/texture_generators.hpp).
TS_REGISTER_TEXTURE_GENERATOR("texture_animation_*", ts::texanim::remake);
