#include "combine.hpp"

#include <algorithm>

namespace ref {
namespace {
float arg(const ts::Combine& c, int k, const Colour& previous, const Colour& texel, const Colour& primary, size_t ch) {
  const Colour zero{0, 0, 0, 0};
  const Colour& s = c.source[k] == GL_TEXTURE         ? texel
                    : c.source[k] == GL_PREVIOUS      ? previous
                    : c.source[k] == GL_PRIMARY_COLOR ? primary
                                                      : zero;
  switch (c.operand[k]) {
    case GL_ONE_MINUS_SRC_COLOR: return 1.0f - s[ch];
    case GL_SRC_ALPHA: return s[3];
    case GL_ONE_MINUS_SRC_ALPHA: return 1.0f - s[3];
    default: return s[ch];  // GL_SRC_COLOR
  }
}
}  // namespace

bool unitEnvModelled(GLenum env, const ts::Combine& c) {
  if (env != GL_COMBINE) return texEnvModelled(env);
  const GLenum f = c.rgb;
  if (f != GL_REPLACE && f != GL_MODULATE && f != GL_ADD && f != GL_ADD_SIGNED && f != GL_SUBTRACT &&
      f != GL_INTERPOLATE && f != GL_MODULATE_ADD_ATI)
    return false;
  for (int k = 0; k < 3; ++k) {
    const GLenum s = c.source[k], o = c.operand[k];
    if (s != GL_TEXTURE && s != GL_PREVIOUS && s != GL_PRIMARY_COLOR && s != GL_CONSTANT) return false;
    if (o != GL_SRC_COLOR && o != GL_ONE_MINUS_SRC_COLOR && o != GL_SRC_ALPHA && o != GL_ONE_MINUS_SRC_ALPHA)
      return false;
  }
  return true;
}

Colour unitEnv(GLenum env, const ts::Combine& c, const Colour& previous, const Colour& texel, const Colour& primary) {
  if (env != GL_COMBINE) return texEnv(env, previous, texel, {0, 0, 0, 0});
  Colour o{};
  for (size_t ch = 0; ch < 3; ++ch) {
    const float a0 = arg(c, 0, previous, texel, primary, ch), a1 = arg(c, 1, previous, texel, primary, ch),
                a2 = arg(c, 2, previous, texel, primary, ch);
    float v = a0;
    switch (c.rgb) {
      case GL_MODULATE: v = a0 * a1; break;
      case GL_ADD: v = a0 + a1; break;
      case GL_ADD_SIGNED: v = a0 + a1 - 0.5f; break;
      case GL_SUBTRACT: v = a0 - a1; break;
      case GL_INTERPOLATE: v = a0 * a2 + a1 * (1.0f - a2); break;
      case GL_MODULATE_ADD_ATI: v = a0 * a2 + a1; break;
      default: break;  // GL_REPLACE
    }
    o[ch] = std::min(1.0f, std::max(0.0f, v));
  }
  o[3] = texel[3] * previous[3];  // GL_COMBINE_ALPHA's default: GL_MODULATE (GL_TEXTURE, GL_PREVIOUS)
  return o;
}

Box unitEnvBox(GLenum env, const ts::Combine& c, const Box& previous, const Box& texel, const Box& primary) {
  Box o{{2, 2, 2, 2}, {-1, -1, -1, -1}};
  // bits: previous C, previous A, texel C, texel A, primary C, primary A.
  // The same corner for R, G and B at once still visits every channel's
  // corners: a channel depends on its own colours and the alphas only.
  for (int corner = 0; corner < 64; ++corner) {
    Colour p = previous.lo, t = texel.lo, f = primary.lo;
    for (size_t k = 0; k < 3; ++k) {
      if (corner & 1) p[k] = previous.hi[k];
      if (corner & 4) t[k] = texel.hi[k];
      if (corner & 16) f[k] = primary.hi[k];
    }
    if (corner & 2) p[3] = previous.hi[3];
    if (corner & 8) t[3] = texel.hi[3];
    if (corner & 32) f[3] = primary.hi[3];
    const Colour v = unitEnv(env, c, p, t, f);
    for (size_t k = 0; k < 4; ++k) o.lo[k] = std::min(o.lo[k], v[k]), o.hi[k] = std::max(o.hi[k], v[k]);
  }
  return o;
}
}  // namespace ref
