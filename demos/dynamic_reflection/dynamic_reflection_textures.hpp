// demos/dynamic_reflection/dynamic_reflection_textures.hpp — the face-ID cube
// map: six faces of one flat colour each (GL_NEAREST), so a reflector drawn
// with it shows by colour which faces it reads.  GL-free; its generator
// (dynamic_reflection_textures.cpp) lets a sidecar remake it.
#pragma once
#include <glm/glm.hpp>

#include <memory>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"

namespace dynref {
// +X red, -X cyan, +Y green, -Y magenta, +Z blue, -Z yellow: a face and its opposite are complements.
inline const ts::Rgba kFaceIds[6] = {{230, 40, 40, 255},  {40, 220, 220, 255}, {40, 200, 60, 255},
                                     {220, 60, 220, 255}, {50, 90, 240, 255},  {235, 215, 40, 255}};
inline glm::vec4 faceIdColour(int f) {
  const ts::Rgba c = kFaceIds[f];
  return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f};
}
constexpr int kIdFace = 4;  // texels a face's side: one colour a face, so any size reads the same
inline ts::TextureDesc faceIdCube() {
  ts::Image img(kIdFace, 6 * kIdFace);
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < kIdFace; ++y)
      for (int x = 0; x < kIdFace; ++x) img.set(x, f * kIdFace + y, kFaceIds[f]);
  ts::TextureDesc t;
  t.name = "dynamic_reflection_face_ids";
  t.image = std::make_shared<const ts::Image>(std::move(img));
  t.cube = true;
  t.minFilter = t.magFilter = GL_NEAREST;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}
}  // namespace dynref
