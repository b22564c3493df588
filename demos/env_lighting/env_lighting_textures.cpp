// demos/env_lighting/env_lighting_textures.cpp — the lighting cube map remade
// from a sidecar's parameters (lights, face), so that a figure's JSON alone
// gives back its texture (common/core/texture_generators.hpp).
#include <string>

#include "common/core/error.hpp"
#include "common/core/texture_generators.hpp"
#include "demos/env_lighting/env_lighting_math.hpp"

namespace envlight {
namespace {
bool remake(const std::string& name, const ts::TextureParams& p, ts::TextureDesc* out) {
  if (name != "env_lighting_map") return false;
  const int n = ts::intParam(p, "lights", name), face = ts::intParam(p, "face", name);
  if (n < 1 || n > kMaxLights) throw ts::Error("sidecar: texture '" + name + "': lights must be 1..16");
  if (face < 1 || face > 1024) throw ts::Error("sidecar: texture '" + name + "': face must be 1..1024");
  *out = lightingMap(n, face);
  return true;
}
}  // namespace
}  // namespace envlight

TS_REGISTER_TEXTURE_GENERATOR("env_lighting_*", envlight::remake);
