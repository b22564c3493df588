// demos/bump_mapping/bump_mapping_gl.hpp — the GLSL of the bump-mapping demo: one
// fragment shader for every method (which one is a uniform), the torus
// drawn as a Frame batch for B1-B3, and the reference R, the same heights
// displacing a finely tessellated torus, drawn by a pass of its own (a
// vertex buffer of a 1024 x 512 grid: too many vertices for a sidecar).
//
// Everything is per pixel from the interpolated (s, t): the torus point
// Q(s, t), its partials Q_s, Q_t, the unit normal N and its partials, in
// model coordinates, then turned into eye space, where the two lights are.
//   B1  seed 004 (Blinn): n' = n + P_u (n x Q_t)/|n| + P_w (Q_s x n)/|n|,
//       n = Q_s x Q_t, P_u, P_w central differences of P = scale h over a texel.
//   B2  seed 002 literally: g_x = j(x+1, y) - j(x-1, y), g_y = j(x, y+1) -
//       j(x, y-1) on the 8-bit texels (y counts raster rows downwards), divided
//       by 255 and added to the x and y of the interpolated eye-space normal.
//   B3  a tangent-space normal map (bump_mapping_math.hpp's normalMap) in the tangent
//       frame (T, B, N) computed per vertex and interpolated.
//   R   Q' = Q + P N, drawn as geometry; its normal the exact Q'_s x Q'_t
//       with Q'_s = Q_s + P_s N + P N_s (the term seed 004 drops).
// The numbers the text names (each method's id, the albedo) are written into
// it from C++ (glsl() below), and frameAt's formulas are the torus's own
// (common/core/torus_frame.inl).
// Lighting: Phong, two directional lights, ambient + sum of diffuse and
// specular (exponent 40).  `opts.x` = 1 writes the eye-space normal as the
// colour 0.5 + 0.5 n instead (the measurements' normal renders).
#pragma once
#include <glm/gtc/type_ptr.hpp>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "bump_mapping_methods.hpp"
#include "common/core/torus.hpp"
#include "common/gl/context.hpp"

#include "common/core/error.hpp"
#include "common/core/frame.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/gl_record.hpp"
#include "common/gl/render.hpp"

namespace bump {
constexpr const char* kSourceFile = "demos/bump_mapping/bump_mapping_gl.hpp";

// The surface's colour and its ambient share, used by the shader below
// (written into its text as ALBEDO and AMBIENT) and by the fixed-function
// passes (bump_mapping_ff.hpp).
const glm::vec3 kAlbedo{0.78f, 0.74f, 0.68f};
constexpr float kAmbient = 0.1f;

// The shader text names its numbers: METHOD_<KEY> for each method's shader
// id (kMethods), ALBEDO and AMBIENT.  glsl() writes their values in before
// the text goes to GL, as a #define would, but on the CPU: each number is
// written once, here in C++, and the program GL compiles (and the GL
// listing shows) holds the numbers themselves.
inline std::string glslNumber(float v) {  // the shortest text that reads back as v
  char buf[32];
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, double(v));
    if (std::strtof(buf, nullptr) == v) break;
  }
  std::string s = buf;
  return s.find_first_of(".e") == std::string::npos ? s + ".0" : s;  // 1 -> 1.0: a float in GLSL
}
inline std::string glsl(const std::string& text) {
  std::map<std::string, std::string> value = {
      {"ALBEDO", "vec3(" + glslNumber(kAlbedo.r) + ", " + glslNumber(kAlbedo.g) + ", " + glslNumber(kAlbedo.b) + ")"},
      {"AMBIENT", glslNumber(kAmbient)}};
  for (const MethodInfo& m : kMethods) {
    std::string name = std::string("METHOD_") + m.key;
    for (char& c : name) c = char(std::toupper(static_cast<unsigned char>(c)));
    value[name] = std::to_string(m.shaderId);
  }
  // Word by word (runs of letters, digits and _): a word that is a name
  // above becomes its value, everything else is copied.
  std::string out;
  for (size_t i = 0; i < text.size();) {
    size_t j = i;
    while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
    if (j == i) {
      out += text[i++];
      continue;
    }
    const std::string word = text.substr(i, j - i);
    const auto it = value.find(word);
    out += it != value.end() ? it->second : word;
    i = j;
  }
  return out;
}

// Uniforms (all vec4): torus = (R, r, height scale, method: kMethods' shader
// id), rep = (repeats along s, along t, texture width, height), l0/l1 =
// (eye-space direction to the light, intensity), opts = (normals as colour,
// no specular, mipmaps, 0).
// frameAt's body is common/core/torus_frame.inl, the same lines
// common/core/torus.cpp compiles as C++ (ts::torusFrame, used by the
// fixed-function passes): the torus's formulas are written once.
inline const std::string kCommonGLSL = std::string(R"(
uniform sampler2D tex;
uniform vec4 torus, rep, l0, l1, opts;
const float TAU = 6.28318530718;
// The torus and its partials at (s, t), model coordinates.
void frameAt(vec2 st, out vec3 Q, out vec3 N, out vec3 Qs, out vec3 Qt, out vec3 Ns, out vec3 Nt) {
  float th = TAU * st.x, ph = TAU * st.y, R = torus.x, r = torus.y;
)") + ts::kTorusFrameGLSL + R"(}
// P = scale h and its partials in s and t: central differences over one
// texel of mip level `lod` (2^lod texels of level 0), read at that level.
vec3 heightAt(vec2 st, float lod) {
  float k = exp2(lod);
  vec2 uv = st * rep.xy, du = vec2(k / rep.z, 0.0), dv = vec2(0.0, k / rep.w);
  float P = torus.z * texture2DLod(tex, uv, lod).r;
  float Ps = torus.z * (texture2DLod(tex, uv + du, lod).r - texture2DLod(tex, uv - du, lod).r) *
             rep.z * rep.x / (2.0 * k);
  float Pt = torus.z * (texture2DLod(tex, uv + dv, lod).r - texture2DLod(tex, uv - dv, lod).r) *
             rep.w * rep.y / (2.0 * k);
  return vec3(P, Ps, Pt);
}
)";

// The tangent frame per vertex, in eye space: T = Qs/|Qs|, B = Qt/|Qt|
// (the unit tangents along θ and φ) and N, interpolated for B2 and B3.
inline const char* const kMeshVS = R"(
varying vec2 st;
varying vec3 peye, tT, tB, tN;
void main() {
  vec3 Q, N, Qs, Qt, Ns, Nt;
  st = gl_MultiTexCoord0.xy;
  frameAt(st, Q, N, Qs, Qt, Ns, Nt);
  mat3 m = mat3(gl_ModelViewMatrix);
  tT = m * normalize(Qs), tB = m * normalize(Qt), tN = m * N;  // the tangent frame, per vertex
  peye = (gl_ModelViewMatrix * gl_Vertex).xyz;
  gl_Position = ftransform();
}
)";

// The reference's grid: gl_Vertex.xy is (s, t); the vertex is displaced.
inline const char* const kReferenceVS = R"(
varying vec2 st;
varying vec3 peye, tT, tB, tN;
void main() {
  vec3 Q, N, Qs, Qt, Ns, Nt;
  st = gl_Vertex.xy;
  frameAt(st, Q, N, Qs, Qt, Ns, Nt);
  vec4 p = vec4(Q + heightAt(st, 0.0).x * N, 1.0);
  tT = tB = tN = vec3(0.0);
  peye = (gl_ModelViewMatrix * p).xyz;
  gl_Position = gl_ModelViewProjectionMatrix * p;
}
)";

// (The comments after the METHOD_ names stand where they stand in the text
// GL gets, once the names are numbers.)
inline const char* const kFS = R"(
varying vec2 st;
varying vec3 peye, tT, tB, tN;
// The mip level a pixel's footprint asks for (opts.z = 1: mipmapped
// heights or normal map), else level 0.
float lodHere() {
  vec2 t = st * rep.xy * rep.zw;
  float m = max(length(dFdx(t)), length(dFdy(t)));
  return opts.z > 0.5 ? max(0.0, log2(max(m, 1e-6))) : 0.0;
}
vec3 phong(vec3 n, vec3 L, float I) {
  vec3 albedo = ALBEDO, V = normalize(-peye);
  float d = max(dot(n, L), 0.0);
  float sp = d > 0.0 ? pow(max(dot(reflect(-L, n), V), 0.0), 40.0) : 0.0;
  return I * (albedo * d + vec3(0.35) * sp * (1.0 - opts.y));
}
void main() {
  vec3 Q, N, Qs, Qt, Ns, Nt, n;
  frameAt(st, Q, N, Qs, Qt, Ns, Nt);
  mat3 m = mat3(gl_ModelViewMatrix);
  int method = int(torus.w + 0.5);
  if (method == METHOD_BLINN) {                     // B1: seed 004, Blinn
    vec3 P = heightAt(st, lodHere()), nv = cross(Qs, Qt);
    float len = length(nv);
    n = m * (nv + P.y * cross(nv, Qt) / len + P.z * cross(Qs, nv) / len);
  } else if (method == METHOD_SEED002) {              // B2: seed 002, literally
    ivec2 size = ivec2(rep.zw), x = ivec2(floor(st * rep.xy * rep.zw));
    #define J(dx, dy) texelFetch2D(tex, ivec2((x.x + dx + 4 * size.x) % size.x, (x.y + dy + 4 * size.y) % size.y), 0).r
    float gx = J(1, 0) - J(-1, 0);       // j(x+1, y) - j(x-1, y), / 255
    float gy = J(0, -1) - J(0, 1);       // j(x, y+1) - j(x, y-1): raster row y+1 is texel row y-1
    n = normalize(tN);
    n.x += gx, n.y += gy;
  } else if (method == METHOD_NORMALMAP) {              // B3: the normal map in the per-vertex tangent frame
    vec3 t = texture2DLod(tex, st * rep.xy, lodHere()).rgb * 2.0 - 1.0;
    n = normalize(tT) * t.x + normalize(tB) * t.y + normalize(tN) * t.z;
  } else if (method == METHOD_REFERENCE) {              // R: the displaced surface's own normal
    vec3 P = heightAt(st, 0.0);
    n = m * cross(Qs + P.y * N + P.x * Ns, Qt + P.z * N + P.x * Nt);
  } else {
    n = m * N;
  }
  n = normalize(n);
  if (opts.x > 0.5) {
    gl_FragColor = vec4(0.5 + 0.5 * n, 1.0);
    return;
  }
  vec3 c = ALBEDO * AMBIENT + phong(n, normalize(l0.xyz), l0.w) + phong(n, normalize(l1.xyz), l1.w);
  gl_FragColor = vec4(c, 1.0);
}
)";

// GLSL 1.20, what macOS's legacy OpenGL 2.1 context compiles.  A vertex
// shader has texture2DLod without an extension; the fragment shader takes it
// from GL_ARB_shader_texture_lod, and texelFetch2D and the integer % of B2
// from GL_EXT_gpu_shader4 (both offered by Mesa and by Apple's 2.1 context).
inline const char* const kVertexHeader = "#version 120";
inline const char* const kFragmentHeader =
    "#version 120\n#extension GL_ARB_shader_texture_lod : require\n#extension GL_EXT_gpu_shader4 : require";
inline ts::Program meshProgram() {
  return {kSourceFile, glsl(kVertexHeader + kCommonGLSL + kMeshVS), glsl(kFragmentHeader + kCommonGLSL + kFS)};
}
inline ts::Program referenceProgram() {
  return {kSourceFile, glsl(kVertexHeader + kCommonGLSL + kReferenceVS), glsl(kFragmentHeader + kCommonGLSL + kFS)};
}

// The reference R: a (nu + 1) x (nv + 1) grid of (s, t), drawn from client
// arrays with glDrawElements into a framebuffer of its own and read back.
// A window's first stage draws a grid of a sixteenth of the vertices
// (CoarseReferencePass): R at once, coarse, refined in place.
template <int Nu, int Nv>
struct ReferenceGrid : ts::Renderer::Attachment {
  static constexpr int kNu = Nu, kNv = Nv;
  explicit ReferenceGrid(ts::Renderer&) {
    for (int j = 0; j <= kNv; ++j)
      for (int i = 0; i <= kNu; ++i) st.push_back(float(i) / kNu), st.push_back(float(j) / kNv);
    for (int j = 0; j < kNv; ++j)
      for (int i = 0; i < kNu; ++i) {
        unsigned a = unsigned(j * (kNu + 1) + i), b = a + 1, c = a + unsigned(kNu + 1), d = c + 1;
        idx.insert(idx.end(), {a, b, d, a, d, c});
      }
  }
  std::vector<float> st;
  std::vector<unsigned> idx;
};
using ReferencePass = ReferenceGrid<1024, 512>;
using CoarseReferencePass = ReferenceGrid<256, 128>;

// A pass of the demo's own into the renderer's render target
// (Renderer::offscreen) of the frame's size, cleared to its colour, with the
// viewport of its first panel: `draw` makes the GL calls; the picture is
// read back (row 0 = top).
template <class Draw>
ts::Image offscreen(ts::Renderer& r, const ts::Frame& f, const char* what, Draw draw) {
  return r.offscreen(f.width, f.height, what, [&](GLuint) {
    const ts::Panel& p = f.panels.front();
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, f.width, f.height);
    glClearColor(f.clearColor.r, f.clearColor.g, f.clearColor.b, f.clearColor.a);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glViewport(p.viewport.x, f.height - p.viewport.y - p.viewport.h, p.viewport.w, p.viewport.h);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(glm::value_ptr(p.projection));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(glm::value_ptr(p.modelview));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    draw();
  });
}

// R as an image: the frame `f` (its first panel holds the torus batch whose
// uniforms and height texture R takes) drawn with that panel's matrices,
// the displaced grid in place of the torus.  `coverageAlpha`: alpha 255
// where the grid covers the pixel, 0 elsewhere, from the same render's
// depth (a pixel covered is one whose depth passed GL_LESS against the
// cleared 1.0, so its stored depth is below 1): which pixels R covers,
// without drawing the grid again for its normals.  The depth is read aside
// from any recording (gl::NotRecorded): the listing is the picture's.
template <class Grid = ReferencePass>
inline ts::Image renderReference(ts::Renderer& r, const ts::Frame& f, bool coverageAlpha = false) {
  Grid& pass = r.attachment<Grid>();
  const ts::Batch& b = f.panels.front().batches.front();
  std::vector<float> depth;
  ts::Image img = offscreen(r, f, "drawing the displaced reference torus", [&] {
    GLuint prog = r.program("bump_reference", referenceProgram());
    glActiveTexture(GL_TEXTURE0);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, r.texture(f.textures.at(size_t(b.texture))));
    glUseProgram(prog);
    glUniform1i(glGetUniformLocation(prog, "tex"), 0);
    for (const ts::Uniform& u : b.uniforms) {
      glm::vec4 v = u.value;
      if (u.name == "torus") v.w = float(kMethods[kReference].shaderId);
      GLint loc = glGetUniformLocation(prog, u.name.c_str());
      if (loc >= 0) glUniform4f(loc, v.x, v.y, v.z, v.w);
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pass.st.data());
    glDrawElements(GL_TRIANGLES, GLsizei(pass.idx.size()), GL_UNSIGNED_INT, pass.idx.data());
    glDisableClientState(GL_VERTEX_ARRAY);
    glUseProgram(0);
    glDisable(GL_TEXTURE_2D);
    if (coverageAlpha) {
      ts::gl::NotRecorded aside;
      depth.resize(size_t(f.width) * size_t(f.height));
      glReadPixels(0, 0, f.width, f.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    }
  });
  for (int y = 0; coverageAlpha && y < img.height; ++y)  // depth row 0 = bottom, the image's = top
    for (int x = 0; x < img.width; ++x)
      img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) * 4 + 3] =
          depth[size_t(img.height - 1 - y) * size_t(img.width) + size_t(x)] < 1.0f ? 255 : 0;
  return img;
}
}  // namespace bump
