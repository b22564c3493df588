// exercises/lab2_cube.cpp — seed 002's lab, task 2 (and Buss VI.1.2's cube).
//
// The statement (seed 002): "Napisać program rysujący teksturowany sześcian
// (współrzędne tekstury dla kolejnych wierzchołków określić ręcznie)" —
// draw a textured cube, with the texture coordinates of its vertices set
// by hand.  Buss (VI.1.2): a vertex of a cube belongs to three faces, and
// each face needs its own (s, t) there: 24 vertices, not 8.
//
// Write: (s, t) for `corner`, a corner of the cube [-1, 1]^3, as a vertex
// of face `face` (0..5: +X, -X, +Y, -Y, +Z, -Z; its outward normal n).  Each
// face must show the whole texture once, the right way round as seen from
// outside, its top towards the face's "up": +Y for the four sides, -Z (the
// back) for the top face +Y, +Z (the front) for the bottom face -Y.  So
// (0, 0) at the corner seen bottom-left, (1, 1) at the top right.
//
// Checked by rendering each face head-on from outside (its up at the top)
// with a texture whose texels hold their indices, and reading (s, t) at
// the face's corners and its screen-space Jacobian: the whole texture,
// s growing to the right and t upwards (not mirrored, not turned).
#include "exercise.hpp"

glm::dvec2 exercise::cubeST(int face, glm::dvec3 corner) {
  (void)face, (void)corner;
  TS_EXERCISE_NOT_DONE("lab2_cube");
}
