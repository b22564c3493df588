// demos/environment_mapping/environment_mapping_gl.hpp — the GL passes of the environment
// mapping demo: an object (sphere, torus, flat mirror) drawn with each
// parameterization, per vertex or per pixel, into a float framebuffer, read
// back.
//
// What the GL does:
//   per vertex, cube map   fixed function: glTexGeni(GL_S/T/R,
//       GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP) gives each vertex the eye-space
//       r = u - 2 (n.u) n (u the unit vector from the eye to the vertex, Buss
//       VI.3's r = v - 2(v.n)n), GL interpolates (s,t,r) and picks the face per
//       fragment; the texture matrix turns eye space into the world's.
//   per vertex, sphere map fixed function: GL_SPHERE_MAP texgen, the (s,t) of
//       environment_mapping_math.hpp's formula per vertex, interpolated linearly.
//   per vertex, lat-long and paraboloid: the same in a vertex shader (there is
//       no texgen for them): (s,t) per vertex, interpolated.
//   per pixel, all four: a fragment shader computes r from the interpolated
//       position and normal, then the map's (s,t) (or the cube lookup) itself.
//   the reference: the same r per pixel, written out as a direction (no map).
// The maps are GL_LINEAR, no mipmaps, at equal memory (environment_mapping_math.hpp's
// mapSize).  A pass either reads the world's colours (the pictures) or maps
// whose texels hold their own directions (d + 1)/2 in RGBA32F (the
// measurement): then each pixel of the read-back is the direction the map
// returned there, filtered as the colour would be, and its angle to the
// reference's r is the error in degrees.  The figures' pictures use the same
// shaders with FRAME 1 in batches of a ts::Frame (environment_mapping_views.hpp).
#pragma once
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/gl/gl.hpp"
#include "common/core/mesh.hpp"
#include "common/gl/render.hpp"
#include "common/gl/render_target.hpp"
#include "environment_mapping_math.hpp"

namespace envmap {
using envmap::Param;
enum Object { kSphereObject, kTorus, kMirror, kObjects };
inline const char* const kObjectKeys[] = {"sphere", "torus", "mirror"};
constexpr int kSeedSphere = 4, kSeedCube = 5;
// The map a pass reads: the seeds' variants read the sphere and the cube map.
inline int mapOf(int param) {
  return param == kSeedSphere ? envmap::kSphere : param == kSeedCube ? envmap::kCube : param;
}
constexpr double kMirrorTiltDeg = 35.0;  // the mirror leans back: it reflects the upper world

// Meshes coarse enough that per-vertex interpolation shows.
inline ts::Mesh objectMesh(int object) {
  auto noTex = [](int, int) { return glm::dvec2(0.0); };
  if (object == kSphereObject)
    return ts::parametricGrid(
        24, 12, true, false, [](int i, int j) { return ts::spherePoint(1.0, 24, 12, i, j); }, noTex);
  if (object == kTorus)
    return ts::parametricGrid(
        32, 16, true, true, [](int i, int j) { return ts::torusPoint(1.0, 0.4, 32, 16, i, j); }, noTex);
  const double a = envmap::rad(kMirrorTiltDeg);
  return ts::parametricGrid(
      8, 8, false, false,
      [a](int i, int j) {
        const double x = -1.2 + 0.3 * i, y = -1.2 + 0.3 * j;
        ts::SurfacePoint p;
        p.pos = {x, y * std::cos(a), -y * std::sin(a)};
        p.normal = {0, std::sin(a), std::cos(a)};
        return p;
      },
      noTex);
}

struct Pass {
  int param = -1;  // -1: the reference, r itself; kSeedSphere: seed 002's (N_x/2 + 1/2, N_y/2 + 1/2) on the sphere map;
                   // kSeedCube: seed 002's R = 2 N_z N - I on the cube map (per pixel)
  int object = kSphereObject;
  bool perVertex = false;
  bool directions = true;                  // texels hold directions (measure) | the world's colours (picture)
  glm::mat4 projection{1.0f}, view{1.0f};  // view: world -> eye (the object at the world's origin)
  glm::mat4 model{1.0f};                   // the object turned in the world
  glm::dmat3 sphereView{1.0};              // the rotation of the eye the sphere map was made for (world -> its eye);
                                           // it is read in this pass's eye space, as GL_SPHERE_MAP texgen does
  glm::dmat3 eyeRotation() const { return glm::dmat3(glm::mat3(view)); }
  int faceTexels = 64;
  int w = 256, h = 256;
  // Lat-long per vertex with (s, t) computed here, per triangle corner, and sent as glTexCoord2f to fixed
  // function: 0 as they come, 1 with the +1 rule across the seam (plusOneRule); -1: the vertex shader's.
  int seamRule = -1;
};

// Lat-long's (s, t) at each corner of each triangle, in the order of objectMesh(p.object).triangles(): r per
// vertex as the vertex shader computes it, but here, because the +1 rule needs a triangle's three s at once and
// a vertex shader sees one vertex.  So a triangle across the seam gets its own copies of its corners' (s, t).
inline std::vector<glm::vec2> latlongCornerST(const Pass& p, bool plusOne) {
  const ts::Mesh m = objectMesh(p.object);
  const glm::dmat4 modelview(p.view * p.model);
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(modelview)));
  const glm::dmat3 toWorld = glm::transpose(glm::dmat3(glm::mat3(p.view)));
  std::vector<glm::vec2> st;
  for (unsigned i : m.triangles()) {
    const ts::SurfacePoint& v = m.points[i];
    const glm::dvec3 eye(modelview * glm::dvec4(v.pos, 1.0));
    const glm::dvec3 r = toWorld * glm::reflect(glm::normalize(eye), glm::normalize(normalMatrix * v.normal));
    st.push_back(glm::vec2(envmap::latlongST(r)));
  }
  if (plusOne)
    for (size_t k = 0; k + 2 < st.size(); k += 3) envmap::plusOneRule(&st[k]);
  return st;
}
// A read-back: RGBA floats, row 0 at the bottom (GL's order); alpha 0 where
// the object is not.
struct Pixels {
  int w = 0, h = 0;
  std::vector<float> v;
  glm::vec4 at(int x, int y) const {
    const float* p = &v[(size_t(y) * size_t(w) + size_t(x)) * 4];
    return {p[0], p[1], p[2], p[3]};
  }
  glm::dvec3 direction(int x, int y) const { return glm::normalize(glm::dvec3(at(x, y)) * 2.0 - 1.0); }
};

constexpr const char* kFile = "demos/environment_mapping/environment_mapping_gl.hpp";
// GLSL shared by both stages: the map coordinates of environment_mapping_math.hpp.
inline const char* mapFunctions() {
  return R"(
const float PI = 3.14159265358979;
#if FRAME  // drawn as a ts::Frame (a figure's nested frame): uniforms are vec4s (the columns), the normal is (s, t, r)
uniform vec4 toWorld0, toWorld1, toWorld2, sphereEye0, sphereEye1, sphereEye2;
#define toWorld mat3(toWorld0.xyz, toWorld1.xyz, toWorld2.xyz)
#define sphereEye mat3(sphereEye0.xyz, sphereEye1.xyz, sphereEye2.xyz)
#define NORMAL gl_MultiTexCoord0.xyz
#else
uniform mat3 toWorld;    // eye -> world (the view's rotation, transposed)
uniform mat3 sphereEye;  // world -> this eye (the sphere map is read in eye space)
#define NORMAL gl_Normal
#endif
vec3 reflectWorld(vec3 p, vec3 n) { return toWorld * reflect(normalize(p), normalize(n)); }
vec2 latlong(vec3 d) {
  d = normalize(d);
  return vec2(atan(-d.x, -d.z) / (2.0 * PI) + 0.5, asin(clamp(d.y, -1.0, 1.0)) / PI + 0.5);
}
vec2 sphereST(vec3 r) {
  float m = 2.0 * sqrt(r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0));
  return r.xy / m + 0.5;
}
vec2 disc(vec3 d, float side) { d = normalize(d); return d.xy / (2.0 * (1.0 + side * d.z)) + 0.5; }
vec2 paraboloid(vec2 front, vec2 back, float z) {
  return z >= 0.0 ? vec2(front.x / 2.0, front.y) : vec2((back.x + 1.0) / 2.0, back.y);
}
)";
}
inline std::string header(int param, bool perVertex, bool frame) {
  return "#version 120\n#define PARAM " + std::to_string(param) + "\n#define PER_VERTEX " + (perVertex ? "1" : "0") +
         "\n#define FRAME " + (frame ? "1" : "0");
}
inline std::string vertexShader(int param, bool perVertex, bool frame = false) {
  return header(param, perVertex, frame) + mapFunctions() + R"(
varying vec3 posEye, nEye;
varying vec4 coord;    // per vertex: the map coordinates (paraboloid: front xy, back zw)
varying float side;    // per vertex: r_z, which paraboloid half
void main() {
  vec4 pe = gl_ModelViewMatrix * gl_Vertex;
  posEye = pe.xyz;
  nEye = gl_NormalMatrix * NORMAL;
  gl_Position = gl_ProjectionMatrix * pe;
  vec3 r = reflectWorld(posEye, nEye);
  side = r.z;
#if PARAM == 0
  coord = vec4(latlong(r), 0.0, 0.0);
#elif PARAM == 2
  coord = vec4(sphereST(sphereEye * r), 0.0, 0.0);
#elif PARAM == 4
  coord = vec4(normalize(nEye).xy * 0.5 + 0.5, 0.0, 0.0);  // seed 002: u = N_x/2 + 1/2
#else
  coord = vec4(disc(r, 1.0), disc(r, -1.0));
#endif
}
)";
}
inline std::string fragmentShader(int param, bool perVertex, bool frame = false) {
  return header(param, perVertex, frame) + mapFunctions() + R"(
#if FRAME && (PARAM == 1 || PARAM == 5)
uniform samplerCube tex;  // a Frame's program reads unit 0 as "tex"
#define mapCube tex
#elif FRAME
uniform sampler2D tex;
#define map2d tex
#else
uniform sampler2D map2d;
uniform samplerCube mapCube;
#endif
varying vec3 posEye, nEye;
varying vec4 coord;
varying float side;
void main() {
  vec3 r = reflectWorld(posEye, nEye);
#if PARAM < 0
  gl_FragColor = vec4(normalize(r) * 0.5 + 0.5, 1.0);
#elif PARAM == 1
  gl_FragColor = textureCube(mapCube, r);
#elif PARAM == 5
  // seed 002: R = 2 N_z N - I, I the unit vector to the eye (eye space)
  vec3 n = normalize(nEye);
  gl_FragColor = textureCube(mapCube, toWorld * (2.0 * n.z * n + normalize(posEye)));
#else
#if PER_VERTEX && PARAM == 3
  vec2 st = paraboloid(coord.xy, coord.zw, side);
#elif PER_VERTEX
  vec2 st = coord.xy;
#elif PARAM == 0
  vec2 st = latlong(r);
#elif PARAM == 2
  vec2 st = sphereST(sphereEye * r);
#elif PARAM == 4
  vec2 st = normalize(nEye).xy * 0.5 + 0.5;
#else
  vec2 st = paraboloid(disc(r, 1.0), disc(r, -1.0), r.z);
#endif
  gl_FragColor = texture2D(map2d, st);
#endif
}
)";
}

// The GL objects of the passes, owned by the renderer (Renderer::attachment).
class EnvGL : public ts::Renderer::Attachment {
 public:
  explicit EnvGL(ts::Renderer& r) : r_(r) {}
  ~EnvGL() override {
    for (auto& t : textures_) glDeleteTextures(1, &t.second);
    freeTarget();
  }
  EnvGL(const EnvGL&) = delete;
  EnvGL& operator=(const EnvGL&) = delete;

  Pixels draw(const Pass& p) {
    GLint prevProgram = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &prevProgram);
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    Pixels out{p.w, p.h, {}};
    {
      ts::RenderTarget::Bind bound(target(p.w, p.h));
      glDisable(GL_SCISSOR_TEST);
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      glDisable(GL_BLEND);
      glDisable(GL_CULL_FACE);
      glDisable(GL_LIGHTING);
      glMatrixMode(GL_PROJECTION);
      glPushMatrix();
      glLoadMatrixf(glm::value_ptr(p.projection));
      glMatrixMode(GL_MODELVIEW);
      glPushMatrix();
      glLoadMatrixf(glm::value_ptr(p.view * p.model));
      glMatrixMode(GL_TEXTURE);
      glPushMatrix();
      glLoadIdentity();
      const glm::mat3 toWorld = glm::transpose(glm::mat3(p.view));
      const bool texgen = p.perVertex && (p.param == envmap::kCube || p.param == envmap::kSphere);
      const bool cornerST = p.seamRule >= 0;  // (s, t) sent by glTexCoord2f, computed per triangle
      const bool fixedFunction = texgen || cornerST;
      GLuint tex = p.param >= 0 ? texture(p) : 0;
      const GLenum target = mapOf(p.param) == envmap::kCube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
      glActiveTexture(GL_TEXTURE0);
      if (tex) glBindTexture(target, tex);
      if (fixedFunction) {
        glUseProgram(0);
        if (texgen) {
          const GLint mode = p.param == envmap::kCube ? GL_REFLECTION_MAP : GL_SPHERE_MAP;
          glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, mode), glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, mode);
          if (p.param == envmap::kCube) glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, mode);  // GL_SPHERE_MAP: s and t only
          glEnable(GL_TEXTURE_GEN_S), glEnable(GL_TEXTURE_GEN_T);
          if (p.param == envmap::kCube) glEnable(GL_TEXTURE_GEN_R);
        }
        glEnable(target);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        if (p.param == envmap::kCube) glLoadMatrixf(glm::value_ptr(glm::mat4(toWorld)));  // eye-space r -> the world's
      } else {
        const std::string key = "envmap_p" + std::to_string(p.param) + (p.perVertex ? "_v" : "_f");
        GLuint prog = r_.program(key,
                                 {kFile, vertexShader(p.param, p.perVertex), fragmentShader(p.param, p.perVertex)});
        glUseProgram(prog);
        glUniformMatrix3fv(glGetUniformLocation(prog, "toWorld"), 1, GL_FALSE, glm::value_ptr(toWorld));
        // The lookup is in this eye's space, as GL_SPHERE_MAP's is: a map made
        // for another eye (sphereView) is read as if it were this one's.
        const glm::mat3 sphereEye(p.view);
        glUniformMatrix3fv(glGetUniformLocation(prog, "sphereEye"), 1, GL_FALSE, glm::value_ptr(sphereEye));
        glUniform1i(glGetUniformLocation(prog, target == GL_TEXTURE_CUBE_MAP ? "mapCube" : "map2d"), 0);
      }
      const ts::Mesh m = objectMesh(p.object);
      const std::vector<glm::vec2> st = cornerST ? latlongCornerST(p, p.seamRule == 1) : std::vector<glm::vec2>{};
      size_t corner = 0;
      glBegin(GL_TRIANGLES);
      for (unsigned i : m.triangles()) {
        const ts::SurfacePoint& v = m.points[i];
        if (cornerST) glTexCoord2f(st[corner].x, st[corner].y);
        ++corner;
        glNormal3f(float(v.normal.x), float(v.normal.y), float(v.normal.z));
        glVertex3f(float(v.pos.x), float(v.pos.y), float(v.pos.z));
      }
      glEnd();
      out.v = target_.readFloat();
      glUseProgram(GLuint(prevProgram));
      glMatrixMode(GL_TEXTURE);
      glPopMatrix();
      glMatrixMode(GL_MODELVIEW);
      glPopMatrix();
      glMatrixMode(GL_PROJECTION);
      glPopMatrix();
      glMatrixMode(GL_MODELVIEW);
      glBindTexture(target, 0);
    }  // the previous framebuffer, buffers and viewport
    glPopAttrib();
    ts::gl::check("an environment mapping pass");
    return out;
  }

  // Drops the map pass `p` reads and the target: the next draw makes them
  // again, so that its recorded calls (ts::recordRender) show how.
  void forget(const Pass& p) {
    freeTarget();
    auto it = textures_.find(mapKey(p));
    if (it == textures_.end()) return;
    glDeleteTextures(1, &it->second);
    textures_.erase(it);
  }

  // One cube-map lookup of direction r read back: the texel colour of a
  // texel-index cube (face in B, (i, j) in R and G) at n x n per face,
  // GL_NEAREST: which face and texel the GL chose (seed 001's example).
  glm::ivec3 cubeTexelOf(glm::dvec3 r, int n) {
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_CUBE_MAP, t);
    std::vector<float> texels(size_t(n) * size_t(n) * 4);
    for (int f = 0; f < 6; ++f) {
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          float* q = &texels[(size_t(j) * size_t(n) + size_t(i)) * 4];
          q[0] = float(i), q[1] = float(j), q[2] = float(f), q[3] = 1;
        }
      glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA32F, n, n, 0, GL_RGBA, GL_FLOAT,
                   texels.data());
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
    if (textures_.count("cube_index")) glDeleteTextures(1, &textures_["cube_index"]);
    textures_["cube_index"] = t;  // deleted with the others
    // A one-pixel pass: a fixed-function point whose (s,t,r) is r itself.
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    float px[4] = {0, 0, 0, 0};
    {
      ts::RenderTarget::Bind bound(target(1, 1));
      glDisable(GL_SCISSOR_TEST);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glUseProgram(0);
      glDisable(GL_DEPTH_TEST);
      glEnable(GL_TEXTURE_CUBE_MAP);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
      glMatrixMode(GL_PROJECTION), glPushMatrix(), glLoadIdentity();
      glMatrixMode(GL_MODELVIEW), glPushMatrix(), glLoadIdentity();
      glBegin(GL_TRIANGLES);
      for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(3, -1), glm::vec2(-1, 3)}) {
        glTexCoord3f(float(r.x), float(r.y), float(r.z));
        glVertex2f(c.x, c.y);
      }
      glEnd();
      const std::vector<float> v = target_.readFloat();
      std::copy(v.begin(), v.begin() + 4, px);
      glMatrixMode(GL_PROJECTION), glPopMatrix();
      glMatrixMode(GL_MODELVIEW), glPopMatrix();
      glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    }
    glPopAttrib();
    ts::gl::check("the cube-map read-back");
    return {int(px[0]), int(px[1]), int(px[2])};
  }

 private:
  // The map of a pass, baked once per (parameterization, contents, size,
  // sphere view) and kept.
  static std::string mapKey(Pass p) {
    p.param = mapOf(p.param);  // the seeds' coordinates read the same maps
    if (p.param < 0) return "";
    std::string key = std::string(envmap::kParamKeys[p.param]) + (p.directions ? "_dir_" : "_colour_") +
                      std::to_string(p.faceTexels);
    if (p.param == envmap::kSphere)
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) key += "_" + std::to_string(p.sphereView[c][k]);
    return key;
  }
  GLuint texture(Pass p) {
    const std::string key = mapKey(p);
    p.param = mapOf(p.param);
    const envmap::Size sz = envmap::mapSize(Param(p.param), p.faceTexels);
    auto it = textures_.find(key);
    if (it != textures_.end()) return it->second;
    const glm::dmat3 toWorld = glm::transpose(p.sphereView);
    std::vector<float> texels(size_t(sz.w) * size_t(sz.h) * 4);
    auto fill = [&](int face) {
      for (int j = 0; j < sz.h; ++j)
        for (int i = 0; i < sz.w; ++i) {
          glm::dvec3 d = envmap::texelDir(Param(p.param), face, (i + 0.5) / sz.w, (j + 0.5) / sz.h, toWorld);
          glm::dvec3 c = p.directions ? (d + 1.0) / 2.0 : envmap::worldColour(d);
          float* q = &texels[(size_t(j) * size_t(sz.w) + size_t(i)) * 4];
          q[0] = float(c.x), q[1] = float(c.y), q[2] = float(c.z), q[3] = 1;
        }
    };
    GLuint t;
    glGenTextures(1, &t);
    const GLenum target = p.param == envmap::kCube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    glBindTexture(target, t);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (int f = 0; f < (p.param == envmap::kCube ? 6 : 1); ++f) {
      fill(f);
      const GLenum face = p.param == envmap::kCube ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f) : GL_TEXTURE_2D;
      glTexImage2D(face, 0, GL_RGBA32F, sz.w, sz.h, 0, GL_RGBA, GL_FLOAT, texels.data());
    }
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, p.param == envmap::kLatLong ? GL_REPEAT : GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(target, 0);
    textures_[key] = t;
    return t;
  }
  // The passes' target: RGBA32F colour (the measurements read floats) and a
  // depth buffer, remade when the size changes.
  ts::RenderTarget& target(int w, int h) {
    target_.make({w, h, ts::TargetFormat::kRGBA32F, ts::TargetFormat::kDepth24}, "an environment mapping pass");
    return target_;
  }
  void freeTarget() { target_.free(); }
  ts::Renderer& r_;
  std::map<std::string, GLuint> textures_;
  ts::RenderTarget target_;
};
}  // namespace envmap
