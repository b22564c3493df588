// exercises/vi1_back_seam.cpp — Buss, Exercise VI.1.
//
// The statement.  The side of a cylinder, p(θ, y) = (r sin θ, y, r cos θ),
// gets the texture by Eq. VI.1, s = θ/360°, t = (y + h/2)/h, so "the left
// and right edges of the texture map meet at the front line of the
// cylinder" (x = 0, z = r).  Exercise VI.1: change the texture coordinates
// so that they meet at the back line instead (x = 0, z = −r).
//
// Write: s at the angle θ, in degrees, θ in [0°, 360°) (θ = 0 is the front,
// θ = 180° the back).  The texture wraps with GL_REPEAT, so s may leave
// [0, 1]: s + 1 shows what s shows.  The checker gives each column of the
// cylinder's mesh its s from your function (the last column, θ = 360°, is
// θ = 0° one turn on: your s(0) + 1).
//
// Checked by cylinder_seam's own measurement, from a render with a texture
// whose texels hold their indices: the texture's edges (an integer s) must
// meet in the patch at θ = 180°, and every patch must show its slice of the
// texture forwards, Δs = 1/slices.  See it: build/bin/cylinder_seam.
#include "exercise.hpp"

double exercise::cylinderS(double thetaDegrees) {
  (void)thetaDegrees;
  TS_EXERCISE_NOT_DONE("vi1_back_seam");
}
