// common/core/slant_plane.hpp — a textured plane seen by a pinhole camera,
// and the mipmap demo's slanted ground plane: the camera, where a pixel's ray
// meets the plane with the texel-space Jacobian there, and the homography
// from pixels to the plane.  Moved here from demos/mipmap_popping (whose
// mipmap_popping_math.hpp derives the formulas) so the filter zoo (demos/filter_zoo)
// looks at the same plane.  No GL.
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "common/core/mip_lod.hpp"

namespace ts::slant {
using ts::lod::Jacobian;

// A pinhole camera: world -> camera rotation R and eye E; focal length F in
// pixels; (cx, cy) the principal point, panel-relative GL pixels.
struct Camera {
  glm::dmat3 rot{1.0};
  glm::dvec3 eye{0.0};
  double focal = 256;  // the mipmap demo's facing-plane camera: 256 pixels
  double cx = 0, cy = 0;
  double nearZ = 0.05, farZ = 4000;
  glm::mat4 projection(int w, int h) const {
    // Pixel x of the panel sees camera-space x/(-z) = (x - cx)/F.
    double n = nearZ;
    return glm::frustum(float(-cx / focal * n), float((w - cx) / focal * n), float(-cy / focal * n),
                        float((h - cy) / focal * n), float(n), float(farZ));
  }
  glm::mat4 modelview() const {
    glm::dmat4 m(rot);
    m = m * glm::translate(glm::dmat4(1.0), -eye);
    return glm::mat4(m);
  }
};
struct Plane {
  glm::dvec3 origin{0.0}, e1{1, 0, 0}, e2{0, 1, 0};  // e1, e2 orthonormal
  double density = 256;                              // texels per world unit
  glm::dvec3 normal() const { return glm::cross(e1, e2); }
};

// (a, b) on the plane and the texel-space Jacobian at panel-relative GL
// pixel coordinates (x, y) (y up).  Returns false when the ray misses the
// plane (at or above the horizon).
inline bool planeAt(const Camera& c, const Plane& p, double x, double y, glm::dvec2* ab, Jacobian* j) {
  glm::dmat3 rt = glm::transpose(c.rot);
  glm::dvec3 r = rt * glm::dvec3((x - c.cx) / c.focal, (y - c.cy) / c.focal, -1.0);
  glm::dvec3 rx = rt * glm::dvec3(1.0 / c.focal, 0, 0), ry = rt * glm::dvec3(0, 1.0 / c.focal, 0);
  glm::dvec3 n = p.normal();
  double nr = glm::dot(n, r);
  if (std::abs(nr) < 1e-15) return false;
  double lambda = glm::dot(n, p.origin - c.eye) / nr;
  if (lambda <= 0) return false;
  glm::dvec3 P = c.eye + lambda * r;
  if (ab) *ab = {glm::dot(P - p.origin, p.e1), glm::dot(P - p.origin, p.e2)};
  if (j) {
    glm::dvec3 dPx = lambda * (rx - r * (glm::dot(n, rx) / nr)), dPy = lambda * (ry - r * (glm::dot(n, ry) / nr));
    j->dudx = p.density * glm::dot(p.e1, dPx);
    j->dudy = p.density * glm::dot(p.e1, dPy);
    j->dvdx = p.density * glm::dot(p.e2, dPx);
    j->dvdy = p.density * glm::dot(p.e2, dPy);
  }
  return true;
}

// The slanted view: a ground plane y = 0 seen from height 1, the camera
// pitched down so the horizon is a tenth of the panel from its top; focal
// length from a 60 degree horizontal field of view.  Texture: s = x, t = -z
// (one repeat per world unit, t growing away from the eye).
constexpr double kSlantFovX = 60.0;
// yawDeg, pitchDeg, zoom: the mouse's orbit (common/core/orbit_camera.hpp): the
// eye stays, the view turns about the vertical and tilts, the lens zooms.
inline Camera slantCamera(int w, int h, double yawDeg = 0, double pitchDeg = 0, double zoom = 1) {
  Camera c;
  c.cx = w / 2.0, c.cy = h / 2.0;
  c.focal = (w / 2.0) / std::tan(glm::radians(kSlantFovX / 2));
  double pitch = std::atan(0.4 * h / c.focal);  // horizon at 0.4 h above the centre
  pitch += glm::radians(pitchDeg);
  c.focal *= zoom;
  c.rot = glm::dmat3(glm::rotate(glm::dmat4(1.0), pitch, glm::dvec3(1, 0, 0)));
  if (yawDeg != 0) c.rot = c.rot * glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(yawDeg), glm::dvec3(0, 1, 0)));
  c.eye = {0, 1, 0};
  c.nearZ = 0.05;
  c.farZ = 4000;
  return c;
}
inline Plane groundPlane() {
  Plane p;
  p.origin = {0, 0, 0};
  p.e1 = {1, 0, 0};
  p.e2 = {0, 0, -1};  // n = e1 x e2 = (0, 1, 0)
  return p;
}
// The ground plane's extent: |s| <= kGroundHalfWidth, 0 <= t <= kGroundDepth
// (world units; the plane ends 200 units away, about LOD 13).
constexpr double kGroundHalfWidth = 400, kGroundDepth = 200;

// The homography (panel pixel x, y, 1) -> (s q, t q, q) of the ground plane
// seen by camera c (rows; glm: H[col][row]), (s, t) in world units.  The ray
// r = A (x, y, 1) meets y = 0 at E + r (-E.y / r.y); with q = -r.y / E.y:
// s q = E.x q + r.x, t q = -(E.z q + r.z).
inline glm::dmat3 groundHomography(const Camera& c) {
  glm::dmat3 rt = glm::transpose(c.rot);
  // Columns of A: the ray's dependence on x, on y, and the constant.
  glm::dvec3 ax = rt * glm::dvec3(1 / c.focal, 0, 0), ay = rt * glm::dvec3(0, 1 / c.focal, 0),
             a1 = rt * glm::dvec3(-c.cx / c.focal, -c.cy / c.focal, -1);
  glm::dvec3 q(-ax.y / c.eye.y, -ay.y / c.eye.y, -a1.y / c.eye.y);
  glm::dvec3 s = glm::dvec3(ax.x, ay.x, a1.x) + c.eye.x * q, t = -(glm::dvec3(ax.z, ay.z, a1.z) + c.eye.z * q);
  return glm::transpose(glm::dmat3(s, t, q));  // rows s, t, q
}
}  // namespace ts::slant
