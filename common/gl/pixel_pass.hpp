// common/gl/pixel_pass.hpp — a demo's own fixed-function pass, drawn in window pixels and read back: for
// the GL a Frame does not describe (glTexSubImage2D into a texture made once, glCopyTexSubImage2D, the unpack
// state), so a student reads the calls themselves.  Renderer::offscreen draws into a private target.
#pragma once
#include <functional>

#include "common/core/image.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"

namespace ts {
// A w x h pass in window pixels (x right, y up, z in [-1, 1], larger z nearer): colour cleared to opaque
// black, depth to the far plane; `draw` issues the calls.  Read back row 0 at the top.  The state the pass
// changes is restored (glPushAttrib), so the renderer's own state is as it was.
inline Image pixelPass(Renderer& r, int w, int h, const char* what, const std::function<void()>& draw) {
  return r.offscreen(w, h, what, [&](GLuint) {
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glMatrixMode(GL_PROJECTION), glPushMatrix(), glLoadIdentity(), glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW), glPushMatrix(), glLoadIdentity();
    glDisable(GL_DEPTH_TEST), glDisable(GL_BLEND), glDisable(GL_CULL_FACE), glDisable(GL_LIGHTING);
    glUseProgram(0);
    glClearColor(0, 0, 0, 1), glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    draw();
    glMatrixMode(GL_PROJECTION), glPopMatrix();
    glMatrixMode(GL_MODELVIEW), glPopMatrix();
    glPopAttrib();
  });
}

// A w x h texture (GL_RGBA8, or `internal`), one level (GL_TEXTURE_MAX_LEVEL 0): `img`'s texels (row 0 at
// t = 0), or none yet (NULL: to be filled by glTexSubImage2D).  Bound to GL_TEXTURE_2D on return.
inline GLuint texture2D(int w, int h, const Image* img, GLenum filter, GLenum wrap, GLenum internal = GL_RGBA8) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               img ? img->pixels.data() : nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GLint(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GLint(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(wrap));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(wrap));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  return t;
}
// `img` as a texture of its size (GL_NEAREST and GL_REPEAT unless told).
inline GLuint imageTexture(const Image& img, GLenum filter = GL_NEAREST, GLenum wrap = GL_REPEAT) {
  return texture2D(img.width, img.height, &img, filter, wrap);
}
}  // namespace ts
