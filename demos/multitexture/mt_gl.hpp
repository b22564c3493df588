// demos/multitexture/mt_gl.hpp — the GL passes the demo measures, in legacy
// fixed-function GL as seed 001 and Buss teach them: the alpha test, two
// texture units (glActiveTexture, GL_COMBINE), blending passes
// (glBlendFunc(GL_ONE, GL_ONE) adds), the texture matrix and
// GL_ATI_texture_env_combine3's GL_MODULATE_ADD_ATI.  The cutout and cross
// trees, the light maps (unit 1's texture matrix moves the spot), the gloss
// map's passes and AB + CD are Frames (mt_frames.hpp); what stays here is
// the turning trees' widths and the pear (the Frame can describe its two
// coordinate sets and GL_LEQUAL, but the oracle's check of its blended mesh
// layers is too slow yet: tests/oracle/sidecar_exemptions.hpp).  Each pass draws into a
// private target (Renderer::offscreen) in pixel coordinates and is read back;
// every function restores the state it changes (glPushAttrib).
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <functional>
#include <vector>

#include "common/core/image.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"
#include "mt_math.hpp"

namespace mt {
inline GLuint upload(const ts::Image& img, GLenum filter, GLenum wrap, GLenum internal = GL_RGBA8) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GLint(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GLint(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(wrap));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(wrap));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
  return t;
}

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

// Unit `u` as GL_COMBINE: rgb = function(source0, source1[, source2]).
inline void combine(int u, GLenum function, GLenum s0, GLenum s1, GLenum s2 = GL_CONSTANT, GLenum op2 = GL_SRC_COLOR) {
  glActiveTexture(GLenum(GL_TEXTURE0 + u));
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GLint(function));
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GLint(s0)), glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GLint(s1)), glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GLint(s2)), glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GLint(op2));
  glActiveTexture(GL_TEXTURE0);
}
// ---- alpha ------------------------------------------------------------------
enum Cutout { kNoAlphaTest, kAlphaTest, kBlend };
// The cutout tree's hidden-sky and edge passes are Frames (mt_frames.hpp).
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
        for (glm::vec3 p : {glm::vec3(-0.5f, -0.2f, 0), glm::vec3(0.5f, -0.2f, 0), glm::vec3(0.5f, 0.2f, 0), glm::vec3(-0.5f, 0.2f, 0)})
          glVertex3f(p.x, p.y, p.z);
        if (cross)
          for (glm::vec3 p : {glm::vec3(0, -0.2f, -0.5f), glm::vec3(0, -0.2f, 0.5f), glm::vec3(0, 0.2f, 0.5f), glm::vec3(0, 0.2f, -0.5f)})
            glVertex3f(p.x, p.y, p.z);
        glEnd();
      }
  });
}
// The cross tree at three angles, the light maps, the moving spot and the
// gloss map's two passes are Frames too (mt_frames.hpp).

// ---- AB + CD ------------------------------------------------------------
// The three paths are Frames (mt_frames.hpp): kMultitexture two units
// (GL_COMBINE) and an additive pass; kStored one unit, A x B rendered first
// into the texture the last pass adds; kFramebufferOnly A, x B, + C, x D.
enum Abcd { kMultitexture, kStored, kFramebufferOnly };

// ---- the pear: i = t_d ⊗ i_diff + t_g · t_r --------------------------------
// A lathe (pearProfile), 48 x 32 quads, seen along -z, orthographic.  Per
// vertex: i_diff (Lambert, a light up-left-front) as the colour; (u, v) for
// the skin; the sphere-map coordinates of the reflected view direction
// (what GL_SPHERE_MAP texgen would give, computed here) for t_r.
struct PearVertex {
  glm::vec3 p;
  glm::vec2 uv, sphere;
  float diffuse;
};
inline PearVertex pearVertex(int i, int j) {
  const double u = i / 48.0, v = j / 32.0, a = 6.283185307179586 * u;
  const glm::dvec2 c = pearProfile(v), d = (pearProfile(std::min(1.0, v + 1e-3)) - pearProfile(std::max(0.0, v - 1e-3)));
  const glm::dvec3 p(c.x * std::sin(a), c.y, c.x * std::cos(a));
  glm::dvec3 n = glm::normalize(glm::dvec3(d.y * std::sin(a), -d.x, d.y * std::cos(a)));
  if (glm::length(d) < 1e-9) n = {0, v < 0.5 ? -1 : 1, 0};
  const glm::dvec3 refl = glm::reflect(glm::dvec3(0, 0, -1), n);
  const double m = 2.0 * std::sqrt(refl.x * refl.x + refl.y * refl.y + (refl.z + 1) * (refl.z + 1));
  const double lambert = std::max(0.0, glm::dot(n, glm::normalize(glm::dvec3(-0.5, 0.6, 0.7))));
  return {glm::vec3(p), glm::vec2(u, v), glm::vec2(refl.x / m + 0.5, refl.y / m + 0.5), float(0.15 + 0.7 * lambert)};
}
// skinUnit / sphereUnit: the unit that gets (u, v) / the sphere-map (s, t).
inline void pearMesh(int skinUnit, int sphereUnit) {
  for (int j = 0; j < 32; ++j) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i <= 48; ++i)
      for (int dj = 1; dj >= 0; --dj) {
        const PearVertex q = pearVertex(i, j + dj);
        glColor4f(q.diffuse, q.diffuse, q.diffuse, 1);
        glMultiTexCoord2f(GLenum(GL_TEXTURE0 + skinUnit), q.uv.x, q.uv.y);
        glMultiTexCoord2f(GLenum(GL_TEXTURE0 + sphereUnit), q.sphere.x, q.sphere.y);
        glVertex3f(q.p.x, q.p.y, q.p.z);
      }
    glEnd();
  }
}
// kCombine3: one pass, two units.  Unit 0: t_d GL_MODULATE i_diff (its alpha
//   t_g passes on); unit 1: GL_MODULATE_ADD_ATI, t_r x PREVIOUS's alpha +
//   PREVIOUS.
// kTwoPasses: pass 1 t_d GL_MODULATE i_diff; pass 2 t_r (unit 0) x t_g
//   (unit 1, GL_MODULATE), added (GL_ONE, GL_ONE, depth GL_LEQUAL).
enum Pear { kCombine3, kTwoPasses };
inline ts::Image pearPasses(ts::Renderer& r, GLuint skin, GLuint gloss, GLuint sky, int method) {
  return pass(r, 192, 192, "the pear", [&] {
    glClearColor(0.12f, 0.12f, 0.14f, 1), glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION), glLoadIdentity(), glOrtho(-1, 1, -1, 1, -2, 2);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST), glDepthFunc(GL_LEQUAL);
    if (method == kCombine3) {
      unit(0, skin, GL_MODULATE), unit(1, sky, GL_COMBINE);
      combine(1, GL_MODULATE_ADD_ATI, GL_TEXTURE, GL_PREVIOUS, GL_PREVIOUS, GL_SRC_ALPHA);
      pearMesh(0, 1);
      return;
    }
    unit(0, skin, GL_MODULATE), pearMesh(0, 1);
    glColor4f(1, 1, 1, 1);
    unit(0, sky, GL_REPLACE), unit(1, gloss, GL_MODULATE);
    glEnable(GL_BLEND), glBlendFunc(GL_ONE, GL_ONE);
    pearMesh(1, 0);
  });
}
}  // namespace mt
