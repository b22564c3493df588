// demos/env_lighting/env_lighting_views.hpp — the lit sphere as a ts::Frame:
// one batch of triangles drawn by one GLSL 1.20 program, the method chosen
// by #define, so that the figure, the measurement and the benchmark draw the
// very same calls.  GL-free (a Frame is plain data; common/gl/render.cpp
// draws it).
//
// The sphere (radius 1, 64 x 32 quads, at the origin) is seen along -z under
// an orthographic projection, so every pixel's eye ray is v = (0, 0, -1) and
// the mirror direction is r = reflect(v, n), n the interpolated normal
// (sent as (s, t, r): a Frame's program reads gl_MultiTexCoord0).  Methods:
//   map    one textureCube(tex, r): the lighting map of env_lighting_math.hpp
//   phong  for each light k: C_k pow(max(0, r.L_k), n), summed (the lights as
//          uniform arrays lightDir[k], lightColour[k])
//   diff   both, |map - phong| x 8, clamped: the error made visible
// Each method's fragment shader counts what it does per pixel in two
// variables, `lookups` (cube-map reads) and `evaluations` (one light's
// Phong term), and with COUNT 1 it writes them out as (evaluations/255,
// lookups/255) instead of a colour: the measurement reads the counts back
// from the program as built rather than asserting them.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/mesh.hpp"
#include "demos/env_lighting/env_lighting_math.hpp"

namespace envlight {
enum Method { kMap, kPhong, kDiff, kMethods };
inline const char* const kMethodKeys[] = {"map", "phong", "diff"};
constexpr float kDiffGain = 8.0f;                               // the difference image's magnification
inline const glm::vec3 kBase{0.10f, 0.10f, 0.12f};              // the sphere's own colour under the highlights
inline const glm::vec4 kBackground{0.22f, 0.22f, 0.25f, 1.0f};  // around the sphere
constexpr double kExtent = 1.05;  // the orthographic window: [-1.05, 1.05] on the short side
constexpr const char* kFile = "demos/env_lighting/env_lighting_views.hpp";

inline std::string vertexShader() {
  return R"(#version 120
varying vec3 nEye;
void main() {
  nEye = gl_NormalMatrix * gl_MultiTexCoord0.xyz;  // the normal, sent as (s, t, r)
  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
)";
}
inline std::string fragmentShader(Method m, int nLights, bool count) {
  return "#version 120\n#define METHOD " + std::to_string(int(m)) + "\n#define LIGHTS " + std::to_string(nLights) +
         "\n#define COUNT " + (count ? "1" : "0") + "\n#define SHININESS " + std::to_string(kShininess) +
         "\n#define DIFF_GAIN " + std::to_string(kDiffGain) + "\n#define BASE vec3(" + std::to_string(kBase.r) + ", " +
         std::to_string(kBase.g) + ", " + std::to_string(kBase.b) + ")" + R"(
uniform samplerCube tex;              // the lighting map (unit 0)
uniform vec4 lightDir[LIGHTS];        // L_k, unit, towards the light
uniform vec4 lightColour[LIGHTS];     // C_k
varying vec3 nEye;
float lookups = 0.0, evaluations = 0.0;  // what this pixel did, counted as it is done
vec3 mapLookup(vec3 r) {
  lookups += 1.0;
  return textureCube(tex, r).rgb;
}
vec3 phongLight(int k, vec3 r) {
  evaluations += 1.0;
  return lightColour[k].rgb * pow(max(0.0, dot(r, lightDir[k].xyz)), SHININESS);
}
void main() {
  vec3 r = reflect(vec3(0.0, 0.0, -1.0), normalize(nEye));  // orthographic: one eye ray for every pixel
  vec3 c = vec3(0.0);
#if METHOD != 1
  vec3 fromMap = mapLookup(r);
#endif
#if METHOD != 0
  vec3 phong = vec3(0.0);
  for (int k = 0; k < LIGHTS; ++k) phong += phongLight(k, r);
  phong = clamp(phong, 0.0, 1.0);  // as the map's 8-bit texels hold it
#endif
#if METHOD == 0
  c = BASE + fromMap;
#elif METHOD == 1
  c = BASE + phong;
#else
  c = min(abs(fromMap - phong) * DIFF_GAIN, 1.0);
#endif
#if COUNT
  gl_FragColor = vec4(evaluations / 255.0, lookups / 255.0, 0.0, 1.0);
#else
  gl_FragColor = vec4(c, 1.0);
#endif
}
)";
}

inline std::string programName(Method m, int nLights, bool count) {
  return std::string("envlight_") + kMethodKeys[m] + "_" + std::to_string(nLights) + (count ? "_count" : "");
}

// The sphere panel of method m with nLights lights and a map of `face`
// texels a side, in `viewport` of a frame; adds its program and texture to f.
inline ts::Panel spherePanel(ts::Frame& f, const std::string& id, const ts::Rect& viewport, Method m, int nLights,
                             int face, bool count = false) {
  ts::Panel p;
  p.id = id;
  p.viewport = viewport;
  const double ax = viewport.w >= viewport.h ? double(viewport.w) / viewport.h : 1.0,
               ay = viewport.w >= viewport.h ? 1.0 : double(viewport.h) / viewport.w;
  p.projection = glm::ortho(float(-kExtent * ax), float(kExtent * ax), float(-kExtent * ay), float(kExtent * ay), -2.0f,
                            2.0f);
  p.depthTest = true;
  p.clear = true;
  p.clearColor = kBackground;
  ts::Batch b;
  b.role = "sphere";
  b.program = programName(m, nLights, count);
  bool have = false;
  for (const auto& pr : f.programs) have = have || pr.first == b.program;
  if (!have) f.programs.push_back({b.program, {kFile, vertexShader(), fragmentShader(m, nLights, count)}});
  if (m != kPhong) b.texture = f.addTexture(lightingMap(nLights, face));
  if (m != kMap) {
    const std::vector<Light> ls = lights(nLights);
    for (int k = 0; k < nLights; ++k) {
      b.uniforms.push_back({"lightDir[" + std::to_string(k) + "]", glm::vec4(glm::vec3(ls[size_t(k)].dir), 0.0f)});
      b.uniforms.push_back(
          {"lightColour[" + std::to_string(k) + "]", glm::vec4(glm::vec3(ls[size_t(k)].colour), 1.0f)});
    }
  }
  const ts::Mesh mesh = ts::parametricGrid(
      64, 32, true, false, [](int i, int j) { return ts::spherePoint(1.0, 64, 32, i, j); },
      [](int, int) { return glm::dvec2(0.0); });
  for (unsigned i : mesh.triangles()) {
    ts::Vertex v;
    v.pos = glm::vec3(mesh.points[i].pos);
    v.tex = glm::vec4(glm::vec3(mesh.points[i].normal), 1.0f);
    b.vertices.push_back(v);
  }
  p.batches.push_back(b);
  return p;
}

// A frame of w x h holding that one panel (the measurement's and the benchmark's).
inline ts::Frame sphereFrame(Method m, int nLights, int face, int w, int h, bool count = false) {
  ts::Frame f;
  f.width = w, f.height = h;
  f.clearColor = kBackground;
  f.panels.push_back(spherePanel(f, "sphere", {0, 0, w, h}, m, nLights, face, count));
  return f;
}
}  // namespace envlight
