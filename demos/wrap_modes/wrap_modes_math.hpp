// demos/wrap_modes/wrap_modes_math.hpp — the formulas demos/wrap_modes measures GL
// against, written from the specification (and seed 002's program) without
// OpenGL, so the tests and the CPU can evaluate them.
//
// Wrap (OpenGL 4.6 compatibility profile §8.14.2, table 8.20): a coordinate s
// of a level `size` texels wide becomes u = s size (GL_CLAMP first clamps s to
// [0, 1]); GL_NEAREST takes texel i = wrap(floor(u)); GL_LINEAR blends
// i0 = wrap(floor(u - 1/2)) and i1 = wrap(i0' + 1) with weight frac(u - 1/2).
//   GL_REPEAT           wrap(i) = i mod size
//   GL_MIRRORED_REPEAT  wrap(i) = (size - 1) - mirror((i mod 2 size) - size),
//                       mirror(a) = a >= 0 ? a : -(1 + a)
//   GL_CLAMP_TO_EDGE    wrap(i) = clamp(i, 0, size - 1)
//   GL_CLAMP_TO_BORDER  wrap(i) = clamp(i, -1, size)   (-1, size: the border colour)
//   GL_CLAMP            NEAREST: clamp(i, 0, size - 1); LINEAR: clamp(i, -1, size)
// Seed 002's MIRROR, literally:
//   float fTest = fmod(ceil(u), 2); if (fTest) u = u - floor(u); else u = 1 - (u - floor(u));
// It agrees with GL_MIRRORED_REPEAT everywhere but at integer u, where it
// returns the opposite edge (u = 1 -> 0, u = 2 -> 1, u = 0 -> 1).
#pragma once
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "common/core/gl_enums.hpp"

namespace wrap {
// The five wrap modes: GL enum, the flag value, the name in the listings.
inline const GLenum kModes[] = {GL_REPEAT, GL_MIRRORED_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER};
inline const char* const kModeNames[] = {"repeat", "mirrored", "clamp", "edge", "border"};
inline const char* const kModeGL[] = {"GL_REPEAT", "GL_MIRRORED_REPEAT", "GL_CLAMP", "GL_CLAMP_TO_EDGE",
                                      "GL_CLAMP_TO_BORDER"};
constexpr int kBorder = -1;  // "the border colour" as a texel index

inline int floorMod(int a, int m) {
  int r = a % m;
  return r < 0 ? r + m : r;
}

// wrap(i) of table 8.20; `nearest` picks GL_CLAMP's NEAREST row.  Returns a
// texel in [0, size) or kBorder.
inline int wrapIndex(GLenum mode, int i, int size, bool nearest) {
  switch (mode) {
    case GL_REPEAT: return floorMod(i, size);
    case GL_MIRRORED_REPEAT: {
      int a = floorMod(i, 2 * size) - size;
      return (size - 1) - (a >= 0 ? a : -(1 + a));
    }
    case GL_CLAMP_TO_EDGE: return std::clamp(i, 0, size - 1);
    case GL_CLAMP:
      if (nearest) return std::clamp(i, 0, size - 1);
      [[fallthrough]];
    case GL_CLAMP_TO_BORDER: {
      int c = std::clamp(i, -1, size);
      return c < 0 || c >= size ? kBorder : c;
    }
  }
  return kBorder;
}

// u = s size, with GL_CLAMP's clamp of s to [0, 1] first.
inline double texelCoord(GLenum mode, double s, int size) {
  return (mode == GL_CLAMP ? std::clamp(s, 0.0, 1.0) : s) * size;
}

// The texel GL_NEAREST returns at s.
inline int nearestTexel(GLenum mode, double s, int size) {
  return wrapIndex(mode, int(std::floor(texelCoord(mode, s, size))), size, true);
}

// GL_LINEAR along one axis: the two texels and the weight of the second.
struct LinearTaps {
  int i0 = 0, i1 = 0;
  double w1 = 0;
};
inline LinearTaps linearTaps(GLenum mode, double s, int size) {
  double u = texelCoord(mode, s, size) - 0.5;
  int i = int(std::floor(u));
  return {wrapIndex(mode, i, size, false), wrapIndex(mode, i + 1, size, false), u - i};
}
// The share of the border colour in a GL_LINEAR lookup at s (one axis, the
// other axis inside the texture): 0, 1/2 or 1 at the edges, the classic
// dark seam of GL_CLAMP.
inline double borderShare(GLenum mode, double s, int size) {
  LinearTaps t = linearTaps(mode, s, size);
  return (t.i0 == kBorder ? 1 - t.w1 : 0.0) + (t.i1 == kBorder ? t.w1 : 0.0);
}

// Seed 002's MIRROR, as the lab sheet writes it (u in texture units).
inline double seedMirror(double u) {
  double fTest = std::fmod(std::ceil(u), 2.0);
  if (fTest != 0.0) u = u - std::floor(u);
  else u = 1 - (u - std::floor(u));
  return u;
}
// The texel the seed's coordinate selects with GL_NEAREST (its u = 1 is the
// last texel: a sampler clamps the index to the texture).
inline int seedMirrorTexel(double s, int size) {
  return std::clamp(int(std::floor(seedMirror(s) * size)), 0, size - 1);
}

// The texture matrix of the demo: about the texture's centre (1/2, 1/2),
// T(c) * T(shift) * R(angle) * Sh(shear) * S(scale) * T(-c), applied by GL
// to (s, t, r, q) as a column vector.
struct TexTransform {
  glm::vec2 shift{0.0f};
  float angleDeg = 0.0f;
  glm::vec2 scale{1.0f};
  float shear = 0.0f;  // s += shear * t
};
inline glm::mat4 textureMatrix(const TexTransform& x) {
  glm::mat4 m(1.0f);
  auto translate = [](glm::vec2 d) {
    glm::mat4 t(1.0f);
    t[3] = glm::vec4(d, 0.0f, 1.0f);
    return t;
  };
  const float a = glm::radians(x.angleDeg), c = std::cos(a), s = std::sin(a);
  glm::mat4 r(1.0f);
  r[0] = {c, s, 0, 0};
  r[1] = {-s, c, 0, 0};
  glm::mat4 sh(1.0f);
  sh[1][0] = x.shear;
  glm::mat4 sc(1.0f);
  sc[0][0] = x.scale.x, sc[1][1] = x.scale.y;
  m = translate({0.5f, 0.5f}) * translate(x.shift) * r * sh * sc * translate({-0.5f, -0.5f});
  return m;
}
// (s, t) after the matrix, with the division by q GL makes.
inline glm::dvec2 transformST(const glm::mat4& m, double s, double t) {
  glm::dvec4 v = glm::dmat4(m) * glm::dvec4(s, t, 0.0, 1.0);
  return {v.x / v.w, v.y / v.w};
}

// The texture environment's table (GL 2.1 table 3.22) for an RGBA texture:
// fragment colour f, texel t, GL_TEXTURE_ENV_COLOR c.
inline glm::dvec4 texEnv(GLenum mode, glm::dvec4 f, glm::dvec4 t, glm::dvec4 c) {
  glm::dvec4 o(0.0);
  for (int k = 0; k < 3; ++k) {
    switch (mode) {
      case GL_REPLACE: o[k] = t[k]; break;
      case GL_MODULATE: o[k] = f[k] * t[k]; break;
      case GL_DECAL: o[k] = f[k] * (1 - t[3]) + t[k] * t[3]; break;
      case GL_BLEND: o[k] = f[k] * (1 - t[k]) + c[k] * t[k]; break;
      case GL_ADD: o[k] = std::min(1.0, f[k] + t[k]); break;
    }
  }
  o[3] = mode == GL_REPLACE ? t[3] : mode == GL_DECAL ? f[3] : f[3] * t[3];
  return o;
}
// The lit surface of the environment view: per-vertex lighting computed on
// the CPU (the suite draws with GL_LIGHTING off), the Phong model of Buss
// III with a point light and a local viewer: diffuse part
// Cm (ambient + (1 - ambient) max(0, n.l)) and specular part max(0, n.h)^e.
// GL's single colour puts both in the primary colour (clamped), which
// GL_MODULATE then multiplies by the texel; GL_SEPARATE_SPECULAR_COLOR sends
// the specular part as the secondary colour, added after texturing.
struct Lit {
  glm::dvec3 diffuse{0.0};
  double specular = 0;
};
inline Lit phong(glm::dvec3 p, glm::dvec3 n, glm::dvec3 light, glm::dvec3 eye, glm::dvec3 colour, double ambient,
                 double shininess) {
  glm::dvec3 l = glm::normalize(light - p), v = glm::normalize(eye - p), h = glm::normalize(l + v);
  Lit o;
  o.diffuse = colour * (ambient + (1 - ambient) * std::max(0.0, glm::dot(n, l)));
  o.specular = glm::dot(n, l) > 0 ? std::pow(std::max(0.0, glm::dot(n, h)), shininess) : 0.0;
  return o;
}
}  // namespace wrap
