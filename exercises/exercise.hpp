// exercises/exercise.hpp — what every exercise file includes: the functions
// a student writes, one per file, and the stub's "not done yet".
//
// Each exercise file holds the exercise's statement, the function with its
// signature and units, and a body that says it is not done.  Replace the
// body; `bash scripts/exercise.sh NAME` builds it and checks it with the
// suite's own measurements (README.md in this folder says how each is
// checked).  The reference solutions are not here: they are the demos'.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <stdexcept>

#include "common/core/image.hpp"

namespace exercise {
// What a stub throws; the checker reports it as "not done yet".
struct NotDone : std::runtime_error {
  using std::runtime_error::runtime_error;
};
#define TS_EXERCISE_NOT_DONE(name) throw ::exercise::NotDone(name ": not done yet")

// vi1_back_seam.cpp: s of the cylinder at θ in [0°, 360°).
double cylinderS(double thetaDegrees);
// vi2_torus_front.cpp: (s, t) of the torus at (θ, φ) in [0°, 360°).
glm::dvec2 torusST(double thetaDegrees, double phiDegrees);
// lab1_blit.cpp: the texture mapped by nearest neighbour onto width x height pixels.
ts::Image blit(const ts::Image& texture, int width, int height);
// mirror_wrap.cpp: the texel GL_MIRRORED_REPEAT with GL_NEAREST reads at s.
int mirrorTexel(double s, int size);
// scanline.cpp: a triangle's vertex, in pixels (x right, y down), with its
// texture coordinates; plot(x, y, s, t) for each pixel the triangle covers.
struct ScanVertex {
  double x = 0, y = 0, s = 0, t = 0;
};
using Plot = std::function<void(int x, int y, double s, double t)>;
void scanlineTriangle(const ScanVertex v[3], const Plot& plot);
// lab2_cube.cpp: (s, t) of a cube corner as a vertex of face 0..5 (+X, -X, +Y, -Y, +Z, -Z).
glm::dvec2 cubeST(int face, glm::dvec3 corner);
// lab3_planar_wrap.cpp: (tu, tv) of a planar wrap along axis 0, 1, 2 (X, Y, Z).
glm::dvec2 planarWrap(glm::dvec3 p, int axis, double scale, glm::dvec3 c);
// sphere_map.cpp: GL_SPHERE_MAP's (s, t) from the eye-space position and unit normal.
glm::dvec2 sphereMap(glm::dvec3 eyePosition, glm::dvec3 eyeNormal);
// bump_gradient.cpp: Blinn's bumped normal from seed 002's height differences.
glm::dvec3 bumpNormal(glm::dvec3 Qs, glm::dvec3 Qt, double gx, double gy, double ds, double dt, double scale);
}  // namespace exercise
