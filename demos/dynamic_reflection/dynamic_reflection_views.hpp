// demos/dynamic_reflection/dynamic_reflection_views.hpp — the demo's passes as
// ts::Frames, so each is drawn by common/gl/render.cpp, recorded for the
// listings, and (nested in a figure through TextureDesc::renderedFrom)
// recomputed by the CPU reference.
//
// The cube pass: one frame of w x 6w pixels, six panels, one a face.  Panel f
// is face f's viewport (glViewport(0, f w, w, w) from the top), its
// projection gluPerspective(90, 1, near, far) (60 for the fov_60 variant)
// with y negated, its modelview the face's camera at the sphere's centre
// (dynamic_reflection_math.hpp's table).  The y negation puts the face's
// t = 0 in its panel's top row: the picture, read back top row first, is then
// the six faces stacked as TextureDesc::cube wants them, t = 0 first (the
// test probes it so).  The demo instead draws the pass with `intoTexture`, no
// y negation, and copies each panel into its face on the GPU with
// glCopyTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, ...), whose t = 0
// is the panel's bottom row (dynamic_reflection_gl.hpp).  Each panel draws the environment (a cube of side 40 round the
// camera, (s, t, r) = its corner's direction into the environment cube map)
// and the ball.
//
// The eye pass: the reflector with glTexGeni(GL_S/T/R, GL_TEXTURE_GEN_MODE,
// GL_REFLECTION_MAP), the texture matrix the view's rotation transposed (eye
// space r -> world r), the cube map bound; the ball and the environment
// drawn directly where the figure shows them.
#pragma once
#include <glm/glm.hpp>

#include <string>

#include "common/core/env_maps.hpp"
#include "common/core/frame.hpp"
#include "common/core/mesh.hpp"
#include "common/core/torus.hpp"
#include "dynamic_reflection_math.hpp"
#include "dynamic_reflection_textures.hpp"

namespace dynref {
inline const glm::vec4 kBallColour{1.0f, 0.55f, 0.1f, 1.0f};  // the ball in the pictures
inline const glm::vec4 kMaskColour{1.0f, 0.0f, 0.0f, 1.0f};   // the ball in the measurement's passes
constexpr int kEnvFace = 256;                                 // the environment cube map's face side

enum Reflector { kSphere, kFlatMirror, kTorus, kReflectors };
inline const char* const kReflectorKeys[] = {"sphere", "flat_mirror", "torus"};

// The reflectors and the ball as triangles, in world coordinates.
inline ts::Mesh sphereMesh(double r, int slices, int stacks) {
  return ts::parametricGrid(
      slices, stacks, true, false, [=](int i, int j) { return ts::spherePoint(r, slices, stacks, i, j); },
      [](int, int) { return glm::dvec2(0.0); });
}
inline ts::Mesh reflectorMesh(int reflector) {
  auto noTex = [](int, int) { return glm::dvec2(0.0); };
  if (reflector == kSphere) return sphereMesh(kSphereRadius, 64, 32);
  if (reflector == kTorus) {
    // Tilted 60 degrees toward the eye, so its hole and both sides of its tube face it.
    const double a = 60.0 * kPi / 180.0;
    return ts::parametricGrid(
        48, 24, true, true,
        [a](int i, int j) {
          ts::SurfacePoint p = ts::torusPoint(0.9, 0.35, 48, 24, i, j);
          auto turn = [a](glm::dvec3 v) {
            return glm::dvec3(v.x, v.y * std::cos(a) - v.z * std::sin(a), v.y * std::sin(a) + v.z * std::cos(a));
          };
          p.pos = turn(p.pos), p.normal = turn(p.normal);
          return p;
        },
        noTex);
  }
  // The flat mirror: a square of side 2 leaning back 35 degrees from facing +Z.
  const double a = 35.0 * kPi / 180.0;
  return ts::parametricGrid(
      8, 8, false, false,
      [a](int i, int j) {
        const double x = -1 + 0.25 * i, y = -1 + 0.25 * j;
        ts::SurfacePoint p;
        p.pos = {x, y * std::cos(a), -y * std::sin(a)};
        p.normal = {0, std::sin(a), std::cos(a)};
        return p;
      },
      noTex);
}
// The ball centred at `c` (ballCentre(time) for the sphere's, kNearBall for the flat mirror's).
inline ts::Batch ballBatch(glm::dvec3 c, glm::vec4 colour, double radius = kBallRadius) {
  ts::Mesh m = sphereMesh(radius, 24, 12);
  for (ts::SurfacePoint& p : m.points) p.pos += c;
  return ts::meshBatch(m, -1, colour, "ball");
}
// The environment: a cube of side 40 round the camera, each corner's (s, t, r) its direction.
inline ts::Batch skyBatch(int texture, glm::vec3 centre) {
  ts::Batch b;
  b.role = "environment";
  b.texture = texture;
  b.texEnv = GL_REPLACE;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1}) {
      glm::vec3 c[4];
      for (int k = 0; k < 4; ++k) {
        glm::vec3 p(0.0f);
        p[axis] = float(sign);
        p[(axis + 1) % 3] = (k == 1 || k == 2) ? 1.0f : -1.0f;
        p[(axis + 2) % 3] = k >= 2 ? 1.0f : -1.0f;
        c[k] = p;
      }
      for (int k : {0, 1, 2, 0, 2, 3}) b.vertices.push_back({centre + 20.0f * c[k], glm::vec4(c[k], 1.0f)});
    }
  return b;
}
inline ts::TextureDesc environmentCube() { return ts::envmaps::environmentMap(ts::envmaps::kCube, kEnvFace); }

// What a cube pass holds: the world's colours and the ball (the pictures), or black and the ball in
// kMaskColour (the measurement's "ball or not").
enum Content { kColours, kMask };
// `intoTexture`: for glCopyTexSubImage2D into the cube map's faces (dynamic_reflection_gl.hpp), whose t = 0
// is the bottom row of what it copies: the projection is not y-negated.  `faces`: a bit a face, the faces
// drawn (the others' panels left out: rendering only the faces a reflector reads).
inline ts::Frame cubeFrame(int faceTexels, glm::dvec3 ball, int variant, int content, double radius = kBallRadius,
                           bool intoTexture = false, unsigned faces = 0x3f) {
  ts::Frame f;
  f.width = faceTexels, f.height = 6 * faceTexels;
  f.clearColor = {0, 0, 0, 1};
  const int env = content == kColours ? f.addTexture(environmentCube()) : -1;
  const glm::mat4 flipY = glm::scale(glm::mat4(1.0f), glm::vec3(1, intoTexture ? 1 : -1, 1));
  for (int face = 0; face < 6; ++face) {
    if (!(faces >> face & 1u)) continue;
    ts::Panel p;
    p.id = std::string("face_") + ts::envmaps::kFaceNames[face];
    p.viewport = {0, face * faceTexels, faceTexels, faceTexels};
    p.projection = flipY * glm::perspective(glm::radians(faceFovDeg(variant)), 1.0f, 0.1f, kFar);
    p.modelview = faceView(face, variant);
    p.depthTest = true;
    if (env >= 0) p.batches.push_back(skyBatch(env, glm::vec3(0.0f)));
    p.batches.push_back(ballBatch(ball, content == kColours ? kBallColour : kMaskColour, radius));
    f.panels.push_back(p);
  }
  return f;
}

// The eye's picture, n x n: `reflector` reading cube map `cube` (a texture of the frame) by r, and with
// `scene` the ball at `ball` drawn directly beside it (the environment is only in the mirror: drawn
// behind it, its few texels magnified to the eye's narrow view would hide the sphere's outline).
inline ts::Frame eyeFrame(int n, const ts::TextureDesc& cube, int reflector, bool scene, glm::dvec3 ball,
                          double radius = kBallRadius) {
  ts::Frame f;
  f.width = f.height = n;
  f.clearColor = scene ? glm::vec4(glm::vec3(ts::envmaps::kBackground), 1.0f) : glm::vec4(0, 0, 0, 1);
  const int tex = f.addTexture(cube);
  ts::Panel p;
  p.id = std::string("eye_") + kReflectorKeys[reflector];
  p.viewport = {0, 0, n, n};
  p.projection = eyeProjection();
  p.modelview = eyeView();
  p.depthTest = true;
  if (scene) p.batches.push_back(ballBatch(ball, kBallColour, radius));
  const ts::Mesh m = reflectorMesh(reflector);
  ts::Batch b;
  b.role = std::string("mirror ") + kReflectorKeys[reflector];
  b.texture = tex;
  b.texEnv = GL_REPLACE;
  b.texGen.mode = GL_REFLECTION_MAP;
  b.texGen.coords = ts::TexGen::S | ts::TexGen::T | ts::TexGen::R;
  b.textureMatrix = glm::mat4(glm::transpose(glm::mat3(eyeView())));  // eye-space r -> the world's
  for (unsigned i : m.triangles()) {
    ts::Vertex v;
    v.pos = glm::vec3(m.points[i].pos);
    v.normal = glm::vec3(m.points[i].normal);
    b.vertices.push_back(v);
  }
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}
}  // namespace dynref
