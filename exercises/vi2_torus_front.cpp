// exercises/vi2_torus_front.cpp — Buss, Exercise VI.2.
//
// The statement.  The torus p(θ, φ) = ((R + r cos φ) sin θ, r sin φ,
// (R + r cos φ) cos θ), θ, φ in [0°, 360°), gets the texture by s = θ/360°,
// t = φ/360° (Figure VI.6).  Exercise VI.2: where does the centre of the
// texture map, (s, t) = (1/2, 1/2), land on the torus?  Change the
// assignment of texture coordinates so that it lands at the front of the
// torus, on the positive z axis.
//
// Write: (s, t) at (θ, φ), in degrees, each in [0°, 360°).  GL_REPEAT wraps
// the texture: s + 1 shows what s shows.  The last column and row of the
// mesh (θ or φ = 360°) get your value at 0° plus one turn.
//
// Checked by the torus demo's own measurement: the texture centre found in
// a render whose texels hold their indices, and the point of the torus a
// ray through it hits, must lie within 0.01 of (0, 0, R + r).  See it:
// build/bin/torus.
#include "exercise.hpp"

glm::dvec2 exercise::torusST(double thetaDegrees, double phiDegrees) {
  (void)thetaDegrees, (void)phiDegrees;
  TS_EXERCISE_NOT_DONE("vi2_torus_front");
}
