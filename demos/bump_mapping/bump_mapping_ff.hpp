// demos/bump_mapping/bump_mapping_ff.hpp — the two fixed-function methods, no
// shaders (seed 001):
//
//   B4  emboss, multipass: "copy the height field, shift it slightly,
//       subtract it from the original".  Per vertex the light is projected
//       on the tangent plane, (T.L, B.L), and the heights' coordinates are
//       shifted by that many texels (times kEmbossShift) toward the light:
//         pass 1  0.5 H(s, t)                          GL_MODULATE, colour 0.5
//         pass 2  + 0.5 (1 - H(s + ds, t + dt))        glBlendFunc(GL_ONE, GL_ONE)
//                 = 0.5 + 0.5 (H - H'), in [0, 1]
//         pass 3  * 2 diffuse                          glBlendFunc(GL_DST_COLOR, GL_SRC_COLOR)
//       so the picture is diffuse (1 + H - H'), with the diffuse term lit
//       per vertex (both lights) and the shift toward light 1.  With the
//       light along the normal the shift is 0 and so is the bump: measured.
//   B5  DOT3: the normal map in texture unit 0 under GL_COMBINE /
//       GL_DOT3_RGB, the light in tangent space as the vertex colour
//       0.5 + 0.5 I (T.L, B.L, N.L): the unit computes
//       4 ((t - 0.5) . (c - 0.5)) = I n.L, clamped to [0, 1], per pixel; unit 1
//       multiplies by the albedo (GL_CONSTANT).  One additive pass per light
//       over an ambient pass.  No specular term.
// Drawn in immediate mode (the GL listing shows the first vertices of each
// pass) from the same torus mesh the shaders use, into a
// framebuffer of its own (bump_mapping_gl.hpp's offscreen), and read back.
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "bump_mapping_gl.hpp"
#include "bump_mapping_math.hpp"
#include "bump_mapping_methods.hpp"
#include "common/core/mesh.hpp"
#include "common/core/torus.hpp"
#include "common/gl/render.hpp"

namespace bump {
constexpr float kEmbossShift = 2.0f;  // texels toward the light, at |tangent part of L| = 1
// The material, kAlbedo and kAmbient, is the shader's (bump_mapping_gl.hpp).

struct FixedInputs {
  ts::TorusShape torus;
  glm::vec2 rep{1.0f}, texSize{256.0f};
  glm::vec3 light[2];                 // eye space, unit
  float intensity[2] = {0.0f, 0.0f};  // the lights' (the shader's l0.w, l1.w)
  ts::TextureDesc heights, inverted, normalMap;
  bool embossTermOnly = false;  // B4: passes 1 and 2 only (0.5 + 0.5 (H - H'))
};

struct FixedVertex {
  glm::vec3 pos;
  glm::vec2 st;  // the heights' coordinates (s rep.x, t rep.y)
  glm::vec2 shifted;
  glm::vec4 colour;   // per pass
  glm::vec3 n, t, b;  // the tangent frame: normal, tangents along θ and φ
};

// The torus's triangles, each vertex with its tangent frame: the mesh's
// normal, and the unit tangents T, B of ts::torusFrame at its (s, t) (the
// shader's normalize(Qs), normalize(Qt): the same formulas,
// common/core/torus_frame.inl).
inline std::vector<FixedVertex> fixedVertices(const ts::TorusShape& tp, glm::vec2 rep) {
  ts::Mesh m = ts::torusMesh(tp);
  std::vector<FixedVertex> out;
  for (unsigned k : m.triangles()) {
    FixedVertex v;
    v.pos = glm::vec3(m.points[k].pos);
    v.st = glm::vec2(m.st[k]) * rep;
    const ts::TorusFrame fr = ts::torusFrameAt(tp.R, tp.r, m.st[k]);
    v.n = glm::vec3(m.points[k].normal);
    v.t = glm::vec3(fr.T);
    v.b = glm::vec3(fr.B);
    out.push_back(v);
  }
  return out;
}

// B4 (kEmboss) or B5 (kDot3) of the frame `f`'s first panel (its matrices).
inline ts::Image renderFixedFunction(ts::Renderer& r, const ts::Frame& f, int method, const FixedInputs& in) {
  std::vector<FixedVertex> vs = fixedVertices(in.torus, in.rep);
  const glm::mat3 toModel = glm::transpose(glm::mat3(f.panels.front().modelview));  // a rotation: its inverse
  glm::vec3 L[2] = {glm::normalize(toModel * in.light[0]), glm::normalize(toModel * in.light[1])};
  // Immediate mode, one call per attribute: the GL listing then shows the
  // first vertices of each pass, emboss's shifted (s, t) and DOT3's light
  // colour among them.
  auto drawWith = [&](bool shiftedCoords, bool textured) {
    glBegin(GL_TRIANGLES);
    for (const FixedVertex& v : vs) {
      glColor4f(v.colour.r, v.colour.g, v.colour.b, v.colour.a);
      const glm::vec2& c = shiftedCoords ? v.shifted : v.st;
      if (textured) glTexCoord2f(c.x, c.y);
      glVertex3f(v.pos.x, v.pos.y, v.pos.z);
    }
    glEnd();
  };
  auto bind = [&](const ts::TextureDesc& d) {
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, r.texture(d));
  };
  return ts::Image(offscreen(r, f, method == kEmboss ? "drawing the emboss passes" : "drawing the DOT3 passes", [&] {
    glActiveTexture(GL_TEXTURE0);
    if (method == kEmboss) {
      for (FixedVertex& v : vs) {
        glm::vec2 tl(glm::dot(v.t, L[0]), glm::dot(v.b, L[0]));
        v.shifted = v.st + kEmbossShift * tl / in.texSize;
        v.colour = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
      }
      bind(in.heights);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
      drawWith(false, true);  // 0.5 H
      glDepthFunc(GL_LEQUAL);
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);
      bind(in.inverted);
      drawWith(true, true);  // + 0.5 (1 - H')
      glDisable(GL_TEXTURE_2D);
      if (!in.embossTermOnly) {
        for (FixedVertex& v : vs) {
          float d = kAmbient;
          for (int k = 0; k < 2; ++k) d += in.intensity[k] * std::max(0.0f, glm::dot(v.n, L[k]));
          v.colour = glm::vec4(kAlbedo * d, 1.0f);
        }
        glBlendFunc(GL_DST_COLOR, GL_SRC_COLOR);  // * 2 diffuse
        drawWith(false, false);
      }
    } else {
      for (FixedVertex& v : vs) v.colour = glm::vec4(kAlbedo * kAmbient, 1.0f);
      glDisable(GL_TEXTURE_2D);
      drawWith(false, false);  // ambient
      glDepthFunc(GL_LEQUAL);
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);
      bind(in.normalMap);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
      glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB);
      glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);
      glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_COLOR);
      glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR);
      glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_SRC_COLOR);
      glActiveTexture(GL_TEXTURE1);
      bind(in.normalMap);  // unit 1 needs a texture to be enabled; it reads only the constant
      const glm::vec4 albedo(kAlbedo, 1.0f);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
      glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE);
      glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PREVIOUS);
      glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_COLOR);
      glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_CONSTANT);
      glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_SRC_COLOR);
      glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &albedo.x);
      glActiveTexture(GL_TEXTURE0);
      for (int k = 0; k < 2; ++k) {
        for (FixedVertex& v : vs) {
          glm::vec3 lt(glm::dot(v.t, L[k]), glm::dot(v.b, L[k]), glm::dot(v.n, L[k]));
          v.colour = glm::vec4(0.5f + 0.5f * in.intensity[k] * lt, 1.0f);
        }
        drawWith(false, true);  // + albedo I n.L
      }
      glActiveTexture(GL_TEXTURE1);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
      glDisable(GL_TEXTURE_2D);
      glActiveTexture(GL_TEXTURE0);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
      glDisable(GL_TEXTURE_2D);
    }
    glDisable(GL_BLEND);
    glDepthFunc(GL_LESS);
  }));
}
}  // namespace bump
