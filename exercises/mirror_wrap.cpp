// exercises/mirror_wrap.cpp — seed 002's MIRROR addressing.
//
// The statement (seed 002): in the MIRROR mode, "each time a coordinate
// passes a whole number, the texture is mirrored": past the first multiple
// of one the coordinate runs from 0 to 1, past the next from 1 to 0, and so
// on.  The seed writes it as a short program,
//     float fTest = fmod(ceil(u), 2);
//     if (fTest) u = u - floor(u); else u = 1 - (u - floor(u));
// which is not quite GL's GL_MIRRORED_REPEAT: find where it differs.
//
// Write: the texel index in [0, size) that GL_MIRRORED_REPEAT with
// GL_NEAREST reads at texture coordinate s, for a texture `size` texels
// wide (texel i covers s in [i/size, (i+1)/size)).  Any s: negative, at
// integers, far from [0, 1].
//
// Checked against GL: a strip drawn with a texture whose texels hold their
// indices, s from −3 to 3 across it, every pixel and every integer s: 0
// mismatches.  See it: build/bin/wrap_modes (key w: the wrap mode).
#include "exercise.hpp"

int exercise::mirrorTexel(double s, int size) {
  (void)s, (void)size;
  TS_EXERCISE_NOT_DONE("mirror_wrap");
}
