// demos/dynamic_reflection/dynamic_reflection_math.hpp — the dynamic
// reflection demo's scene and its CPU reference, no GL: the mirror sphere,
// the ball's path, the eye, the six cube-map cameras (the GL spec's face
// table) and the ray tracer the renders are measured against.
//
// The scene (world coordinates, y up): a mirror sphere of radius 1 at the
// origin; a ball of radius kBallRadius whose centre goes round the sphere
// at kBallOrbit, kBallHeight above its equator, at angle
//   theta(time) = kTheta0 - kThetaRate * time   (degrees; x = orbit sin theta, z = orbit cos theta)
// and, infinitely far, the environment of common/core/env_maps (colour =
// direction).  The eye looks at the origin from kEye.
//
// The cube map's cameras (GL spec, table "selection of cube map images",
// common/core/env_maps.hpp's cubeST): a face's texel (s, t) holds the world
// in direction cubeDir(face, s, t), so a camera at the centre rendering face
// f looks along the face's axis with
//   +X: right -Z, up -Y    -X: right +Z, up -Y    +Y: right +X, up +Z
//   -Y: right +X, up -Z    +Z: right +X, up -Y    -Z: right -X, up -Y
// and a 90 degree field of view, so the face's edges are the cube's
// (tan 45 = 1: s = 0 and 1 are the face's corners' directions).  A window's
// x is s and its y is t (glViewport's origin is t = 0).
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <optional>

#include "common/core/env_maps.hpp"

namespace dynref {
using glm::dvec3;
constexpr double kPi = 3.14159265358979323846;
constexpr double kSphereRadius = 1.0;
constexpr double kBallRadius = 0.9, kBallOrbit = 6.0, kBallHeight = 1.5;
constexpr double kTheta0 = 75.0, kThetaRate = 30.0;  // degrees, degrees a time unit
inline const dvec3 kEye{0.0, 1.2, 5.5};
constexpr float kEyeFovDeg = 26.0f, kNear = 0.5f, kFar = 60.0f;

inline dvec3 ballCentre(double time) {
  const double th = (kTheta0 - kThetaRate * time) * kPi / 180.0;
  return {kBallOrbit * std::sin(th), kBallHeight, kBallOrbit * std::cos(th)};
}
inline glm::mat4 eyeView() { return glm::lookAt(glm::vec3(kEye), glm::vec3(0.0f), glm::vec3(0, 1, 0)); }
inline glm::mat4 eyeProjection() { return glm::perspective(glm::radians(kEyeFovDeg), 1.0f, kNear, kFar); }

// The cube map's wrong cameras, the ones a student makes.
enum Variant { kRight, kFaceFlipped, kFov60, kVariants };
inline const char* const kVariantKeys[] = {"right", "face_flipped", "fov_60"};
// The face the flipped variant gets wrong: +Z, where the ball's reflection is read.
constexpr int kFlippedFace = 4;

// Face f's camera at the origin: its right and up axes and where it looks (the table above).
struct FaceAxes {
  dvec3 right, up, forward;
};
inline FaceAxes faceAxes(int face) {
  static const FaceAxes t[] = {{{0, 0, -1}, {0, -1, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, -1, 0}, {-1, 0, 0}},
                               {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},   {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
                               {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}}};
  return t[face];
}
// Its view matrix (gluLookAt(0,0,0, forward, up)); the flipped variant's face turned upside down, the
// mistake of giving every side face up = +Y.
inline glm::mat4 faceView(int face, int variant) {
  const FaceAxes a = faceAxes(face);
  const dvec3 up = variant == kFaceFlipped && face == kFlippedFace ? -a.up : a.up;
  return glm::lookAt(glm::vec3(0.0f), glm::vec3(a.forward), glm::vec3(up));
}
inline float faceFovDeg(int variant) { return variant == kFov60 ? 60.0f : 90.0f; }

// ---- the CPU reference ------------------------------------------------------
// The ray from the eye through pixel (x, y) of an n x n picture (row 0 at the top), at its centre.
struct Ray {
  dvec3 o, d;
};
inline Ray eyeRay(int x, int y, int n) {
  // The eye is fixed: its inverse once, not per pixel (a 4x4 inverse was a twentieth of a window's start).
  static const glm::dmat4 inv = glm::inverse(glm::dmat4(eyeProjection()) * glm::dmat4(eyeView()));
  const double nx = (x + 0.5) / n * 2 - 1, ny = 1 - (y + 0.5) / n * 2;
  glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
  const dvec3 p = dvec3(a) / a.w, q = dvec3(b) / b.w;
  return {p, glm::normalize(q - p)};
}
// The nearest t > 0 where the ray meets the sphere (centre c, radius r).
inline std::optional<double> hitSphere(const Ray& ray, dvec3 c, double r) {
  const dvec3 oc = ray.o - c;
  const double b = glm::dot(oc, ray.d), disc = b * b - (glm::dot(oc, oc) - r * r);
  if (disc < 0) return std::nullopt;
  const double s = std::sqrt(disc);
  if (-b - s > 1e-9) return -b - s;
  if (-b + s > 1e-9) return -b + s;
  return std::nullopt;
}
// What the eye sees at pixel (x, y) in the mirror sphere: off it, the environment in the reflected
// direction, or the ball (the reflected ray meets it).  `r` gets the reflected direction.  With
// `fromCentre` the reflected ray leaves from the sphere's centre instead of the surface: what a perfect
// cube map made at the centre shows, so the dynamic map's error against it is all but the parallax.
enum Seen { kOff, kEnvironment, kBall };
inline Seen trace(int x, int y, int n, double time, dvec3* r = nullptr, bool fromCentre = false) {
  const Ray e = eyeRay(x, y, n);
  const std::optional<double> t = hitSphere(e, dvec3(0.0), kSphereRadius);
  if (!t) return kOff;
  const dvec3 p = e.o + *t * e.d, nrm = glm::normalize(p);
  const Ray refl{fromCentre ? dvec3(0.0) : p, glm::reflect(e.d, nrm)};
  if (r) *r = refl.d;
  return hitSphere(refl, ballCentre(time), kBallRadius) ? kBall : kEnvironment;
}
}  // namespace dynref
