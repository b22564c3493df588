// common/core/texture_generators.hpp — the named texture generators: each
// remakes a texture from the name and params its sidecar records, so that a
// figure's JSON alone gives back its textures (reference/sidecar_reader.cpp's
// remakeTexture asks them in turn).  The shared generators (checkerboard,
// line grid, ...) are the core's own; a generator only one demo uses lives in
// the demo's folder and registers itself there with
//   TS_REGISTER_TEXTURE_GENERATOR("mydemo_*", mydemo::remake);
// in a GL-free file demos/<name>/<name>_textures.cpp (demos/CMakeLists.txt
// links those into every program that reads sidecars).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"

namespace ts {
using TextureParams = std::vector<std::pair<std::string, std::string>>;
// Remakes the texture `name` with `params` into *out; false when `name` is
// not this generator's.  Throws ts::Error on a bad param.
using TextureRemake = bool (*)(const std::string& name, const TextureParams& params, TextureDesc* out);
struct TextureGenerator {
  std::string label;  // the names it makes, for messages: "checkerboard", "multitexture_*"
  TextureRemake remake;
};

// The core's generators first, then the registered ones by label.
std::vector<TextureGenerator> textureGenerators();
bool registerTextureGenerator(const std::string& label, TextureRemake remake);
// The first generator that makes `name`; false when none does.
bool remakeRegisteredTexture(const std::string& name, const TextureParams& params, TextureDesc* out);
// "checkerboard, line_grid, ...": every generator's label.
std::string textureGeneratorLabels();

// A generator's params, as the sidecar records them (strings); each throws
// ts::Error("sidecar: texture '<name>': ...") when the param is missing or
// malformed.
int intParam(const TextureParams& p, const std::string& key, const std::string& name);
std::string strParam(const TextureParams& p, const std::string& key, const std::string& name);
Rgba rgbaParam(const TextureParams& p, const std::string& key, const std::string& name);
}  // namespace ts

#define TS_TEXTURE_GENERATOR_CONCAT2(a, b) a##b
#define TS_TEXTURE_GENERATOR_CONCAT(a, b) TS_TEXTURE_GENERATOR_CONCAT2(a, b)
#define TS_REGISTER_TEXTURE_GENERATOR(label, remake)                              \
  static const bool TS_TEXTURE_GENERATOR_CONCAT(ts_texture_generator_registered_, \
                                                __LINE__) = ::ts::registerTextureGenerator(label, remake)
