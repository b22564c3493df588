// demos/texture_residency/texture_residency_textures.cpp — the size view's marker texture
// (texture_residency_textures.hpp), and its generator for the sidecar reader.
#include "demos/texture_residency/texture_residency_textures.hpp"

#include <memory>
#include <string>

#include "common/core/error.hpp"
#include "common/core/gl_enums.hpp"
#include "common/core/texture_generators.hpp"
#include "demos/texture_residency/texture_residency_math.hpp"

namespace ts::residency {
TextureDesc markerTexture(int size) {
  Image img(size, size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const bool dark = ((i * 8 / size) + (j * 8 / size)) % 2 == 0;
      img.set(i, j, inMarker(size, i, j) ? kMarkerColour : dark ? Rgba{50, 70, 120, 255} : Rgba{200, 205, 215, 255});
    }
  TextureDesc t;
  t.name = "texture_residency_marker";
  t.params = {{"size", std::to_string(size)}};
  t.image = std::make_shared<const Image>(std::move(img));
  t.minFilter = t.magFilter = GL_NEAREST;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}

namespace {
bool remake(const std::string& name, const TextureParams& params, TextureDesc* out) {
  if (name != "texture_residency_marker") return false;
  const int size = intParam(params, "size", name);
  if (size < 64 || size > 4096 || (size & (size - 1)) != 0)
    throw Error("sidecar: texture '" + name + "': size must be a power of two from 64 to 4096");
  *out = markerTexture(size);
  return true;
}
}  // namespace
}  // namespace ts::residency

// The sidecar reader finds it through the registry (common/core/texture_generators.hpp).
TS_REGISTER_TEXTURE_GENERATOR("texture_residency_*", ts::residency::remake);
