// demos/dynamic_reflection/dynamic_reflection_planar.hpp — the flat mirror
// two ways: the scene rendered mirrored in its plane, and the cube map made
// at its centre; the traced reference of both; the texel-ID cube map that
// counts the texels the cube-map mirror reads.
//
// The mirror: a square of side 2 through the origin, leaning back 35 degrees
// (dynamic_reflection_views.hpp's kFlatMirror), unit normal n = (0, sin 35,
// cos 35).  A small ball (kNearBallRadius) sits in front of it where the
// eye's line of sight to the mirror's centre goes after reflecting, 2 units
// out and 0.4 to the side.
//
// Planar reflection by rendering (two passes):
//   1. the scene drawn with the modelview V R, R = I - 2 n n^T (the
//      reflection in the plane n.x = 0), so the eye sees the world as the
//      mirror shows it; glClipPlane(GL_CLIP_PLANE0, -n) given in world
//      coordinates keeps only what lies behind the plane once mirrored (what
//      was in front of the mirror): nothing behind the mirror comes through it;
//   2. the mirror drawn with that picture as its texture, each vertex's
//      (s, t, r, q) = ((x_c + w_c)/2, (y_c + w_c)/2, 0, w_c) from its clip
//      coordinates, so every pixel reads the first pass's pixel at its own
//      place: the stencil's job (only the mirror shows the mirrored world)
//      done by the texture.
// Per pixel that is the exact reflection: only rasterization differs from the
// traced one.  The cube map made at the mirror's centre returns the world in
// direction r as seen from the centre, whatever the point of the mirror; for
// a ball this near that is a different place, and a flat mirror's r barely
// changes across it, so a handful of texels spreads over all its pixels.
#pragma once
#include <glm/glm.hpp>

#include <memory>
#include <optional>
#include <string>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "dynamic_reflection_math.hpp"
#include "dynamic_reflection_views.hpp"

namespace dynref {
constexpr double kMirrorTiltDeg = 35.0, kNearBallRadius = 0.3;
inline dvec3 mirrorNormal() {
  const double a = kMirrorTiltDeg * kPi / 180.0;
  return {0, std::sin(a), std::cos(a)};
}
inline dvec3 mirrorUp() {  // the mirror's own y axis (x is the world's)
  const double a = kMirrorTiltDeg * kPi / 180.0;
  return {0, std::cos(a), -std::sin(a)};
}
inline dvec3 nearBall() { return 2.0 * glm::reflect(glm::normalize(-kEye), mirrorNormal()) + dvec3(0.4, 0, 0); }
// R = I - 2 n n^T: the reflection in the plane n.x = 0 (its own inverse).
inline glm::mat4 reflectionMatrix() {
  const glm::dvec3 n = mirrorNormal();
  glm::dmat4 m(1.0);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[c][r] -= 2 * n[c] * n[r];
  return glm::mat4(m);
}

// The traced flat mirror at pixel (x, y) of an n x n picture: off it, the environment in r, or the ball.
inline Seen traceFlat(int x, int y, int n, dvec3* r = nullptr) {
  const Ray e = eyeRay(x, y, n);
  const dvec3 nrm = mirrorNormal();
  const double dn = glm::dot(e.d, nrm);
  if (std::abs(dn) < 1e-12) return kOff;
  const double t = -glm::dot(e.o, nrm) / dn;
  if (t <= 0) return kOff;
  const dvec3 p = e.o + t * e.d;
  if (std::abs(p.x) > 1 || std::abs(glm::dot(p, mirrorUp())) > 1) return kOff;
  const Ray refl{p, glm::reflect(e.d, nrm)};
  if (r) *r = refl.d;
  return hitSphere(refl, nearBall(), kNearBallRadius) ? kBall : kEnvironment;
}

// Pass 1: the scene mirrored, as the eye sees it through the mirror, n x n.
inline ts::Frame mirroredFrame(int n, int content) {
  ts::Frame f;
  f.width = f.height = n;
  f.clearColor = {0, 0, 0, 1};
  ts::Panel p;
  p.id = "mirrored";
  p.viewport = {0, 0, n, n};
  p.projection = eyeProjection();
  p.modelview = eyeView() * reflectionMatrix();
  p.depthTest = true;
  const glm::mat4 R = reflectionMatrix();
  auto clipped = [&](ts::Batch b) {
    b.clip = true;
    b.clipPlane = glm::vec4(-glm::vec3(mirrorNormal()), 0.0f);  // world coordinates: behind the plane
    b.clipModelview = eyeView();
    return b;
  };
  // The environment round the mirrored eye R e, so that mirrored it surrounds the eye.
  if (content == kColours)
    p.batches.push_back(
        clipped(skyBatch(f.addTexture(environmentCube()), glm::vec3(R * glm::vec4(glm::vec3(kEye), 1)))));
  p.batches.push_back(clipped(ballBatch(nearBall(), content == kColours ? kBallColour : kMaskColour, kNearBallRadius)));
  f.panels.push_back(p);
  return f;
}
// Pass 2: the mirror reading pass 1's picture (`mirrored`, a texture of it) at each pixel's own place.  A nested
// frame's picture has its top row first (TextureDesc::renderedFrom), so t runs down it: t = 1 - (y + 1) / 2.
inline ts::Frame planarMirrorFrame(int n, const ts::TextureDesc& mirrored, bool scene) {
  ts::Frame f;
  f.width = f.height = n;
  f.clearColor = scene ? glm::vec4(glm::vec3(ts::envmaps::kBackground), 1.0f) : glm::vec4(0, 0, 0, 1);
  const int tex = f.addTexture(mirrored);
  ts::Panel p;
  p.id = "eye_planar";
  p.viewport = {0, 0, n, n};
  p.projection = eyeProjection();
  p.modelview = eyeView();
  p.depthTest = true;
  if (scene) p.batches.push_back(ballBatch(nearBall(), kBallColour, kNearBallRadius));
  const ts::Mesh m = reflectorMesh(kFlatMirror);
  ts::Batch b;
  b.role = "mirror (planar)";
  b.texture = tex;
  b.texEnv = GL_REPLACE;
  const glm::mat4 pv = eyeProjection() * eyeView();
  for (unsigned i : m.triangles()) {
    ts::Vertex v;
    v.pos = glm::vec3(m.points[i].pos);
    const glm::vec4 c = pv * glm::vec4(v.pos, 1.0f);
    v.tex = {(c.x + c.w) / 2, mirrored.renderedFrom ? (c.w - c.y) / 2 : (c.y + c.w) / 2, 0.0f, c.w};
    b.vertices.push_back(v);
  }
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}
}  // namespace dynref
