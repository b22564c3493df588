// demos/dynamic_reflection/dynamic_reflection_textures.cpp — the demo's own
// texture generator, found by the sidecar reader through the registry
// (common/core/texture_generators.hpp): the face-ID and texel-ID cube maps.
#include "common/core/error.hpp"
#include "common/core/texture_generators.hpp"
#include "dynamic_reflection_textures.hpp"

namespace {
bool remake(const std::string& name, const ts::TextureParams& params, ts::TextureDesc* out) {
  if (name == "dynamic_reflection_face_ids") return *out = dynref::faceIdCube(), true;
  if (name == "dynamic_reflection_texel_ids") {
    const int face = ts::intParam(params, "face", name);
    if (face < 1 || face > 512) throw ts::Error("sidecar: texture '" + name + "': face must be 1..512");
    return *out = dynref::texelIdCube(face), true;
  }
  return false;
}
}  // namespace

TS_REGISTER_TEXTURE_GENERATOR("dynamic_reflection_*", remake);
