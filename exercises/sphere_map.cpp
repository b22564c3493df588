// exercises/sphere_map.cpp — OpenGL's sphere map (seeds 001, 002; Buss VI.3).
//
// The statement.  Seed 002 computes a sphere map's coordinates from the
// normal alone, u = Nx/2 + 1/2, v = Ny/2 + 1/2.  OpenGL's GL_SPHERE_MAP
// texgen reflects the direction from the eye to the vertex about the normal,
// both in eye space, and maps the reflection r to
//     m = 2 sqrt(rx² + ry² + (rz + 1)²),  s = rx/m + 1/2,  t = ry/m + 1/2.
// The two agree only for a vertex on the line of sight.
//
// Write: GL_SPHERE_MAP's (s, t) for a vertex at `eyePosition` with the unit
// normal `eyeNormal`, both in eye coordinates (the eye at the origin,
// looking down −z).
//
// Checked against OpenGL: 1,000 points drawn with GL_SPHERE_MAP texgen and
// a texture whose texels hold their indices: every (s, t) within 1.5 texels
// of 2048 of what GL returned.
#include "exercise.hpp"

glm::dvec2 exercise::sphereMap(glm::dvec3 eyePosition, glm::dvec3 eyeNormal) {
  (void)eyePosition, (void)eyeNormal;
  TS_EXERCISE_NOT_DONE("sphere_map");
}
