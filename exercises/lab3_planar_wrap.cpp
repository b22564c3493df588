// exercises/lab3_planar_wrap.cpp — seed 002's lab, task 3.
//
// The statement (seed 002): "Program z poprzedniego punktu rozbudować o
// funkcję wyznaczającą współrzędne tekstury (owinięcie płaskie) wzdłuż
// dowolnej osi" — extend the previous program with a function computing
// the texture coordinates of a planar wrap along any axis.  The seed prints
// the planar wrap along each axis as
//     x) tu = s·z − cz;  tv = s·y − cy
//     y) tu = s·x − cx;  tv = s·z − cz
//     z) tu = s·x − cx;  tv = s·x − cy      (as printed)
// with s a scale and c a centre.  One of the three is misprinted: find it.
//
// Write: (tu, tv) of the point p for a planar wrap along `axis` (0 = X,
// 1 = Y, 2 = Z), scale `scale` and centre `c`, in the seed's form (tu and
// tv are s times a coordinate minus the centre's coordinate, as above).
//
// Checked against OpenGL's GL_OBJECT_LINEAR texgen with the planes of the
// corrected formulas: a sphere drawn both ways with a texture whose texels
// hold their indices, along X, Y and Z: 0 pixels differ.
#include "exercise.hpp"

glm::dvec2 exercise::planarWrap(glm::dvec3 p, int axis, double scale, glm::dvec3 c) {
  (void)p, (void)axis, (void)scale, (void)c;
  TS_EXERCISE_NOT_DONE("lab3_planar_wrap");
}
