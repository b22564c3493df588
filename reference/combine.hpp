// reference/combine.hpp — the second texture unit's environment
// (Batch::texture1 / texEnv1 / combine1): a classic environment (sampler.hpp's
// texEnv with the unit before's result as the fragment colour) or GL_COMBINE
// (GL 2.1 §3.8.13 table 3.24 plus GL_ATI_texture_env_combine3's
// GL_MODULATE_ADD_ATI), per colour and over boxes of colours.
#pragma once
#include "common/core/frame.hpp"
#include "sampler.hpp"

namespace ref {
// Unit 1's result from `previous` (unit 0's result), its texel and the
// fragment's primary colour.  GL_CONSTANT reads (0, 0, 0, 0): unit 1's
// environment colour is GL's default.
Colour unitEnv(GLenum env, const ts::Combine& c, const Colour& previous, const Colour& texel, const Colour& primary);
// The same over boxes: every channel is multilinear in the sources' colours
// and alphas (then clamped, which is monotone), so its extremes lie on the
// corners.
Box unitEnvBox(GLenum env, const ts::Combine& c, const Box& previous, const Box& texel, const Box& primary);
// Whether the reference models this environment on unit 1.
bool unitEnvModelled(GLenum env, const ts::Combine& c);
}  // namespace ref
