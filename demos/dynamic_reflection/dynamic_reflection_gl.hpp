// demos/dynamic_reflection/dynamic_reflection_gl.hpp — the cube pass drawn
// straight into a GL_TEXTURE_CUBE_MAP, no CPU round trip: the pass's frame
// (cubeFrame with `intoTexture`, its faces' projections not y-negated, so a
// face's t = 0 is its panel's bottom row, as glCopyTexSubImage2D copies it)
// is drawn into a private framebuffer and each face's panel copied into its
// face by
//   glCopyTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, 0, 0, x, y, w, w)
// then the eye pass binds that texture as it is (TextureDesc::glTexture).  The
// faces come back to the CPU (glGetTexImage) only where a picture or a
// measurement needs their texels.
#pragma once
#include <memory>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"

namespace dynref {
// A cube map of w x w RGBA8 faces with no texels yet (the cube pass fills them).  The caller deletes it.
inline GLuint makeCubeMap(int w) {
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_CUBE_MAP, id);
  for (int f = 0; f < 6; ++f)
    glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA8, w, w, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
  return id;
}

// Draws a cube pass (cubeFrame(..., intoTexture = true), any subset of its faces) and copies each face's
// panel into that face of `cube`.  Panel f sits f w from the frame's top: GL's y of its bottom row is
// height - (f + 1) w.
inline void renderIntoCube(ts::Renderer& r, const ts::Frame& pass, GLuint cube) {
  r.drawOffscreen(pass, [&] {
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    for (const ts::Panel& p : pass.panels) {
      const int w = p.viewport.w, face = p.viewport.y / w;
      glCopyTexSubImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, 0, 0, p.viewport.x,
                          pass.height - p.viewport.y - w, w, w);
    }
  });
}

// The cube map as a frame's texture: bound as it is, linear, clamped (as the uploaded maps were).
inline ts::TextureDesc cubeMapTexture(GLuint cube, const std::string& what) {
  ts::TextureDesc t;
  t.name = "dynamic_reflection_cube";
  t.params = {{"pass", what}, {"gl", std::to_string(cube)}};
  t.cube = true;
  t.glTexture = cube;
  t.minFilter = t.magFilter = GL_LINEAR;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}

// The six faces read back (glGetTexImage; a row of RGBA8 is 4-aligned), stacked t = 0 first as
// TextureDesc::cube holds them.
inline ts::Image readCubeMap(GLuint cube, int w) {
  ts::Image out(w, 6 * w);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  for (int f = 0; f < 6; ++f)
    glGetTexImage(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                  out.pixels.data() + size_t(f) * size_t(w) * size_t(w) * 4);
  return out;
}
}  // namespace dynref
