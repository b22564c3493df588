// demos/texture_animation/texture_animation_textures.cpp — the waterfall's texture
// (texture_animation_textures.hpp), and its generator for the sidecar reader.
#include "demos/texture_animation/texture_animation_textures.hpp"

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
