// demos/multitexture/multitexture_gl.hpp — the GL passes the demo measures, in legacy
// fixed-function GL as seed 001 and Buss teach them: the alpha test, two
// texture units (glActiveTexture, GL_COMBINE), blending passes
// (glBlendFunc(GL_ONE, GL_ONE) adds), the texture matrix and
// GL_ATI_texture_env_combine3's GL_MODULATE_ADD_ATI.  The cutout and cross
// trees, the light maps (unit 1's texture matrix moves the spot), the gloss
// map's passes, AB + CD and the pear are Frames (multitexture_frames.hpp); what stays
// here is the turning trees' widths.  Each pass draws into a private target
// (Renderer::offscreen) in pixel coordinates and is read back; every
// function restores the state it changes (glPushAttrib).
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <functional>
#include <vector>

#include "common/core/image.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"
#include "multitexture_math.hpp"

namespace mt {
// Unit `u` textured with `t` in mode `env` (0 = unit off).
inline void unit(int u, GLuint t, GLenum env) {
  glActiveTexture(GLenum(GL_TEXTURE0 + u));
  if (!t) {
    glDisable(GL_TEXTURE_2D);
  } else {
    glEnable(GL_TEXTURE_2D), glBindTexture(GL_TEXTURE_2D, t);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GLint(env));
  }
  glActiveTexture(GL_TEXTURE0);
}
// A w x h offscreen pass with the state saved around it and pixel
// coordinates (x right, y up, z in [-1, 1], +1 nearest).
inline ts::Image pass(ts::Renderer& r, int w, int h, const char* what, const std::function<void()>& draw) {
  return opaque(r.offscreen(w, h, what, [&](GLuint) {
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glMatrixMode(GL_PROJECTION), glPushMatrix(), glLoadIdentity(), glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW), glPushMatrix(), glLoadIdentity();
    glDisable(GL_DEPTH_TEST), glDisable(GL_BLEND), glDisable(GL_CULL_FACE), glDisable(GL_LIGHTING);
    glClearColor(0, 0, 0, 1), glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(0), unit(0, 0, 0), unit(1, 0, 0);
    draw();
    glMatrixMode(GL_PROJECTION), glPopMatrix();
    glMatrixMode(GL_MODELVIEW), glPopMatrix();
    glPopAttrib();
  }));
}

// ---- alpha ------------------------------------------------------------------
enum Cutout { kNoAlphaTest, kAlphaTest, kBlend };
// The cutout tree's hidden-sky and edge passes are Frames (multitexture_frames.hpp).
// Silhouette widths turning about the vertical axis, orthographic: strip k
// (8 rows) shows the quad(s) at angle k * step; one quad of width 1 (128
// pixels of 256 over x in [-1, 1]); the cross adds the quad at 90 degrees.
inline ts::Image turningWidths(ts::Renderer& r, int steps, double step) {
  return pass(r, 256, 2 * steps * 8, "the turning trees", [&] {
    glMatrixMode(GL_PROJECTION), glLoadIdentity(), glOrtho(-1, 1, -0.05, 0.05, -2, 2);
    glMatrixMode(GL_MODELVIEW);
    glColor4f(1, 1, 1, 1);
    for (int cross = 0; cross < 2; ++cross)
      for (int k = 0; k < steps; ++k) {
        glViewport(0, (cross * steps + k) * 8, 256, 8);
        glLoadIdentity(), glRotatef(float(k * step), 0, 1, 0);
        glBegin(GL_QUADS);
        for (glm::vec3 p : {glm::vec3(-0.5f, -0.2f, 0), glm::vec3(0.5f, -0.2f, 0), glm::vec3(0.5f, 0.2f, 0),
                            glm::vec3(-0.5f, 0.2f, 0)})
          glVertex3f(p.x, p.y, p.z);
        if (cross)
          for (glm::vec3 p : {glm::vec3(0, -0.2f, -0.5f), glm::vec3(0, -0.2f, 0.5f), glm::vec3(0, 0.2f, 0.5f),
                              glm::vec3(0, 0.2f, -0.5f)})
            glVertex3f(p.x, p.y, p.z);
        glEnd();
      }
  });
}
// The cross tree at three angles, the light maps, the moving spot and the
// gloss map's two passes are Frames too (multitexture_frames.hpp).

// ---- AB + CD ------------------------------------------------------------
// The three paths are Frames (multitexture_frames.hpp): kMultitexture two units
// (GL_COMBINE) and an additive pass; kStored one unit, A x B rendered first
// into the texture the last pass adds; kFramebufferOnly A, x B, + C, x D.
enum Abcd { kMultitexture, kStored, kFramebufferOnly };

// ---- the pear: i = t_d ⊗ i_diff + t_g · t_r --------------------------------
// Its passes are Frames too (multitexture_frames.hpp pearPanel): kCombine3 one pass,
// unit 1 GL_COMBINE with GL_MODULATE_ADD_ATI; kTwoPasses the skin, then the
// sphere map x the gloss added (GL_ONE, GL_ONE, depth GL_LEQUAL).
enum Pear { kCombine3, kTwoPasses };
}  // namespace mt
