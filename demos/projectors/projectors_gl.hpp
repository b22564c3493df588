// demos/projectors/projectors_gl.hpp — the objects of demos/projectors and the
// three ways their texture coordinates reach GL: glTexCoord4f per vertex
// (computed on the CPU by projectors_math.hpp), glTexGen (linear projectors, a
// ts::TexGen in the batch: render.cpp makes glTexGeni/glTexGenfv), and per
// fragment in GLSL (the non-linear projectors: the same formulas spelled in
// kProjectorGLSL below, evaluated at each pixel's object position).
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/mesh.hpp"
#include "projectors_math.hpp"

namespace proj {
enum class Object { Cube, Cylinder, Sphere, Torus, Bumpy };
enum class Coords { Cpu, TexGen, Glsl };

// Triangles (three entries each): position, normal, and (cubes) their own (s, t).
using Shape = std::vector<CubeVertex>;

inline Shape fromMesh(const ts::Mesh& m) {
  Shape s;
  for (unsigned k : m.triangles()) s.push_back({m.points[k].pos, m.points[k].normal, m.st[k]});
  return s;
}
// The cube's quads as triangles (0 1 2, 0 2 3 of each face).
inline Shape cubeShape(bool shared8) {
  std::vector<CubeVertex> q = shared8 ? cube8() : cube24();
  Shape s;
  for (int f = 0; f < 6; ++f)
    for (int k : {0, 1, 2, 0, 2, 3}) s.push_back(q[size_t(4 * f + k)]);
  return s;
}
// The sphere of radius 1, `n` slices (stacks n/2), with Eq. VI.2's (s, t).
inline ts::Mesh sphereMesh(int n) {
  return ts::parametricGrid(
      n, n / 2, true, false, [n](int i, int j) { return ts::spherePoint(1.0, n, n / 2, i, j); },
      [n](int i, int j) { return glm::dvec2(double(i) / n, double(j) / (n / 2)); });
}
// A closed shape with varied normals: the unit sphere with bumps,
// r = 1 + 0.12 sin 3θ cos 4φ (scaled to fit the unit cube).
inline ts::Mesh bumpyMesh(int n) {
  auto point = [n](int i, int j) {
    double th = 2 * kPi * i / n, ph = -kPi / 2 + kPi * j / (n / 2);
    auto at = [](double t, double p) {
      double r = (1 + 0.12 * std::sin(3 * t) * std::cos(4 * p)) / 1.12;
      return glm::dvec3(r * std::sin(t) * std::cos(p), r * std::sin(p), r * std::cos(t) * std::cos(p));
    };
    ts::SurfacePoint sp;
    sp.pos = at(th, ph);
    const double e = 1e-4;
    glm::dvec3 dt = at(th + e, ph) - at(th - e, ph), dp = at(th, ph + e) - at(th, ph - e);
    glm::dvec3 nn = glm::cross(dt, dp);
    sp.normal = glm::length(nn) > 1e-12 ? glm::normalize(nn) : glm::dvec3(0, ph > 0 ? 1 : -1, 0);
    return sp;
  };
  return ts::parametricGrid(n, n / 2, true, false, point,
                            [n](int i, int j) { return glm::dvec2(double(i) / n, double(j) / (n / 2)); });
}
inline Shape shape(Object o, bool shared8 = false) {
  switch (o) {
    case Object::Cube: return cubeShape(shared8);
    case Object::Cylinder:
      return fromMesh(ts::parametricGrid(
          48, 8, true, false, [](int i, int j) { return ts::cylinderPoint(1.0, 2.0, 48, 8, i, j); },
          [](int i, int j) { return glm::dvec2(i / 48.0, j / 8.0); }));
    case Object::Sphere: return fromMesh(sphereMesh(64));
    case Object::Torus:
      return fromMesh(ts::parametricGrid(
          48, 24, true, true, [](int i, int j) { return ts::torusPoint(0.7, 0.3, 48, 24, i, j); },
          [](int i, int j) { return glm::dvec2(i / 48.0, j / 24.0); }));
    case Object::Bumpy: return fromMesh(bumpyMesh(64));
  }
  return {};
}

// glTexCoord4f per vertex, from projectors_math.hpp (the box by the vertex normal).
inline ts::Batch perVertexBatch(const Shape& s, Projector pr, Axis ax, Formula f, int texture, bool ownSt = false) {
  ts::Batch b;
  b.texture = texture;
  b.texEnv = GL_REPLACE;
  for (const CubeVertex& v : s) {
    glm::dvec2 st = ownSt ? v.st : project(pr, ax, f, v.pos, v.normal);
    b.vertices.push_back({glm::vec3(v.pos), glm::vec4(float(st.x), float(st.y), 0.0f, 1.0f)});
  }
  return b;
}
// glTexGen: GL computes (s, t) (and r for the solid texture) from the
// vertex; the batch sends positions only.
inline ts::Batch texGenBatch(const Shape& s, const ts::TexGen& g, int texture) {
  ts::Batch b;
  b.texture = texture;
  b.texEnv = GL_REPLACE;
  b.texGen = g;
  for (const CubeVertex& v : s) b.vertices.push_back({glm::vec3(v.pos)});
  return b;
}
// The planar projection of (axis, formula) as OBJECT_LINEAR or EYE_LINEAR
// planes; eye planes given under `planeModelview`.  Solid: s, t, r from x, y, z.
inline ts::TexGen planarTexGen(Axis ax, Formula f, GLenum mode, const glm::mat4& planeModelview, bool solid = false) {
  ts::TexGen g;
  g.mode = mode;
  g.planeModelview = planeModelview;
  if (solid) {
    g.coords = ts::TexGen::S | ts::TexGen::T | ts::TexGen::R;
    g.planes[0] = {float(kS), 0, 0, float(-kC)};
    g.planes[1] = {0, float(kS), 0, float(-kC)};
    g.planes[2] = {0, 0, float(kS), float(-kC)};
    return g;
  }
  auto p = planarPlanes(ax, f);
  g.coords = ts::TexGen::S | ts::TexGen::T;
  g.planes[0] = glm::vec4(p[0]);
  g.planes[1] = glm::vec4(p[1]);
  return g;
}

// Per fragment: the vertex sends its object position (gl_Vertex) and normal
// (as its texture coordinate); the fragment evaluates seed 002's formula.
// uniform `mode` = (projector 0..3, axis 0..2, formula 0 printed | 1 corrected,
// 0 texture2D with implicit derivatives | 1 texture2DGradARB with the derivatives
// of whichever of tu, fract(tu) has no cut between the pixels).
inline const char* kProgramName = "projector";
inline ts::Program projectorProgram() {
  ts::Program p;
  p.file = "demos/projectors/projectors_gl.hpp";
  p.vertex = R"(#version 120
varying vec3 obj, nrm;
void main() {
  obj = gl_Vertex.xyz;
  nrm = gl_MultiTexCoord0.xyz;
  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
)";
  p.fragment = R"(#version 120
#extension GL_ARB_shader_texture_lod : require
const float PI = 3.14159265358979;
uniform sampler2D tex;
uniform vec4 mode;
varying vec3 obj, nrm;
// (a, b, along) for axis X, Y, Z: seed 002's order (projectors_math.hpp: across).
vec3 across(int ax, vec3 p) { return ax == 0 ? vec3(p.z, p.y, p.x) : ax == 1 ? vec3(p.x, p.z, p.y) : p; }
void main() {
  int pr = int(mode.x + 0.5), ax = int(mode.y + 0.5);
  bool printed = mode.z < 0.5;
  vec3 n = normalize(nrm), q;
  if (pr == 3) {  // box: the axis of the normal's largest component
    vec3 a = abs(n);
    ax = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
    pr = 0;
    printed = false;
  }
  q = across(ax, obj);
  vec2 st;
  if (pr == 0) {
    st = 0.5 * q.xy + 0.5;
    if (ax == 2 && printed) st.y = 0.5 * obj.x + 0.5;  // seed 002: tv = s*x - cx
  } else {
    float u = printed ? atan(q.x / q.y) / (2.0 * PI) : atan(q.x, q.y) / (2.0 * PI);
    float v = 0.5 * q.z + 0.5;
    if (pr == 2) {
      float x = q.z / length(obj);
      v = (printed ? atan(x) : asin(clamp(x, -1.0, 1.0))) / PI + 0.5;
    }
    st = vec2(u, v);
  }
  if (mode.w > 0.5) {
    vec2 dx = dFdx(st), dy = dFdy(st);
    float u2 = fract(st.x);  // the same angle, cut at u = 0 instead of ±1/2
    float dx2 = dFdx(u2), dy2 = dFdy(u2);
    if (abs(dx2) < abs(dx.x)) dx.x = dx2;
    if (abs(dy2) < abs(dy.x)) dy.x = dy2;
    gl_FragColor = texture2DGradARB(tex, st, dx, dy);
  } else {
    gl_FragColor = texture2D(tex, st);
  }
}
)";
  return p;
}
inline ts::Batch glslBatch(const Shape& s, Projector pr, Axis ax, Formula f, int texture, bool grad = false) {
  ts::Batch b;
  b.texture = texture;
  b.program = kProgramName;
  b.uniforms.push_back(
      {"mode", glm::vec4(float(int(pr)), float(int(ax)), f == Formula::Printed ? 0.0f : 1.0f, grad ? 1.0f : 0.0f)});
  for (const CubeVertex& v : s) b.vertices.push_back({glm::vec3(v.pos), glm::vec4(glm::vec3(v.normal), 1.0f)});
  return b;
}

constexpr int kSolid = 64;
// A kSolid³ GL_TEXTURE_3D of the slices stacked in `img` (slice k in rows
// k*kSolid ..), GL_NEAREST, clamped to the edge in s, t and r.
inline ts::TextureDesc solidTexture(const std::string& name, std::shared_ptr<ts::Image> img) {
  ts::TextureDesc t;
  t.name = name;
  t.params = {{"size", std::to_string(kSolid)}};
  t.image = std::move(img);
  t.depth = kSolid;
  t.minFilter = t.magFilter = GL_NEAREST;
  t.wrapS = t.wrapT = t.wrapR = GL_CLAMP_TO_EDGE;
  return t;
}

// The solid texture: 64³ texels holding their own indices (R = 4i, G = 4j,
// B = 4k), GL_NEAREST: a render names the 3D texel each pixel took.
inline ts::TextureDesc solidIndexTexture() {
  auto img = std::make_shared<ts::Image>(kSolid, kSolid * kSolid);
  for (int k = 0; k < kSolid; ++k)
    for (int j = 0; j < kSolid; ++j)
      for (int i = 0; i < kSolid; ++i)
        img->set(i, k * kSolid + j, {uint8_t(4 * i), uint8_t(4 * j), uint8_t(4 * k), 255});
  return solidTexture("solid_index", img);
}
// A solid wood-like texture for the window: rings around the Y axis.
inline ts::TextureDesc solidRingsTexture() {
  auto img = std::make_shared<ts::Image>(kSolid, kSolid * kSolid);
  for (int k = 0; k < kSolid; ++k)
    for (int j = 0; j < kSolid; ++j)
      for (int i = 0; i < kSolid; ++i) {
        double x = (i + 0.5) / kSolid - 0.5, z = (k + 0.5) / kSolid - 0.5, y = (j + 0.5) / kSolid;
        double ring = std::fmod(std::sqrt(x * x + z * z) * 14 + 0.8 * y, 1.0);
        bool dark = ring < 0.35;
        img->set(i, k * kSolid + j, dark ? ts::Rgba{120, 70, 30, 255} : ts::Rgba{215, 165, 100, 255});
      }
  return solidTexture("solid_rings", img);
}
}  // namespace proj
