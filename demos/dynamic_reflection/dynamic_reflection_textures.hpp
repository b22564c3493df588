// demos/dynamic_reflection/dynamic_reflection_textures.hpp — the face-ID cube
// map: six faces of one flat colour each (GL_NEAREST), so a reflector drawn
// with it shows by colour which faces it reads.  GL-free; its generator
// (dynamic_reflection_textures.cpp) lets a sidecar remake it.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>

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

namespace dynref {
// The texel-ID cube map: texel (i, j) of face f holds (i mod 256, j mod 256, f + 8 (i / 256) + 16 (j / 256)),
// GL_NEAREST, so a render reading it says which texel each pixel took.  No texel is (., ., 255): a clear
// colour with blue 255 is no texel.
inline ts::TextureDesc texelIdCube(int face) {
  ts::Image img(face, 6 * face);
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < face; ++j)
      for (int i = 0; i < face; ++i)
        img.set(i, f * face + j,
                {uint8_t(i % 256), uint8_t(j % 256), uint8_t(f + 8 * (i / 256) + 16 * (j / 256)), 255});
  ts::TextureDesc t;
  t.name = "dynamic_reflection_texel_ids";
  t.params = {{"face", std::to_string(face)}};
  t.image = std::make_shared<const ts::Image>(std::move(img));
  t.cube = true;
  t.minFilter = t.magFilter = GL_NEAREST;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}
}  // namespace dynref
