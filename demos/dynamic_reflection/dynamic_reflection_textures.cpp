// demos/dynamic_reflection/dynamic_reflection_textures.cpp — the demo's own
// texture generator, found by the sidecar reader through the registry
// (common/core/texture_generators.hpp): the face-ID cube map.
#include "common/core/texture_generators.hpp"
#include "dynamic_reflection_textures.hpp"

namespace {
bool remake(const std::string& name, const ts::TextureParams&, ts::TextureDesc* out) {
  if (name != "dynamic_reflection_face_ids") return false;
  *out = dynref::faceIdCube();
  return true;
}
}  // namespace

TS_REGISTER_TEXTURE_GENERATOR("dynamic_reflection_*", remake);
