// demos/parallax_aniso/parallax_aniso_ranking_gl.hpp — the GL side of the ranking view: five relief methods
// drawn over the same bricks at the same grazing angle, lit by one directional light (Lambert), each into a
// pixel pass (common/gl/pixel_pass.hpp) read back for parallax_aniso_ranking.hpp to hold against its traced
// reference.
//
//   bump          Blinn 1978: the unshifted coordinate uv0, the normal from the height derivatives there
//                 (central differences one texel apart, read with textureGrad: the filtered heights)
//   normal        the unshifted coordinate, the normal read from a stored normal map (the same differences,
//                 made once on the CPU, mipmapped)
//   parallax      Kaneko / Welsh: one offset step, uv0 + Vp d(uv0) (the depth read at the entry point)
//   pom           the demo's march (parallax_aniso_gl.hpp's pom(), repeated here unchanged: 12..40 linear
//                 steps, the secant refinement)
//   displacement  real geometry: a grid of vertices `grid` texels apart over the visible part of the plane,
//                 each raised to its height (bilinear at level 0, the heights the reference traces), drawn
//                 with glDrawElements(GL_TRIANGLE_STRIP) and the depth test; the vertex shader projects
//                 with the demo's camera (eye, fwd, rightV, upV), so its pixels are the other methods' pixels.
// All five read the albedo and the normal map at the coordinate they found, with the unshifted coordinate's
// gradients (as M1 in the demo), and shade  c = albedo (ka + (1 - ka) max(0, N . L)).
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/pixel_pass.hpp"
#include "common/gl/render.hpp"
#include "parallax_aniso_gl.hpp"
#include "parallax_aniso_math.hpp"

namespace pax::rank {
constexpr const char* kRankSourceFile = "demos/parallax_aniso/parallax_aniso_ranking_gl.hpp";
enum Method { kBump, kNormalMap, kParallax, kPom, kDisplacement, kMethods };
inline const char* const kMethodKeys[] = {"bump", "normal", "parallax", "pom", "displacement"};
inline const char* const kMethodLabels[] = {"bump (Blinn)", "normal mapping", "parallax (1 step)", "parallax occlusion",
                                            "displacement"};
constexpr double kAmbient = 0.2;  // the light's ambient share: walls turned from the light stay readable

// The light: a direction toward it (world, unit), and its ambient share.
struct Light {
  glm::dvec3 dir = glm::normalize(glm::dvec3(0.55, -0.35, 0.45));  // from the right, in front, 32 degrees up
  double ambient = kAmbient;
};

// The surface normal of the height field z = S (h(u, v) - 1) at uv: central differences of the bilinear
// level-0 heights one texel apart, world slopes dz/dx = S / tile dh/du.
inline glm::dvec3 heightNormal(const Relief& r, glm::dvec2 uv, double heightScale, double tile) {
  const double e = 1.0 / kTexSize, k = heightScale / tile;
  const double hx = (depthAt(r, uv - glm::dvec2(e, 0)) - depthAt(r, uv + glm::dvec2(e, 0))) / (2 * e);
  const double hy = (depthAt(r, uv - glm::dvec2(0, e)) - depthAt(r, uv + glm::dvec2(0, e))) / (2 * e);
  return glm::normalize(glm::dvec3(-k * hx, -k * hy, 1.0));
}
inline glm::dvec3 lambert(glm::dvec3 albedo, glm::dvec3 n, const Light& l) {
  return albedo * (l.ambient + (1.0 - l.ambient) * std::max(0.0, glm::dot(n, l.dir)));
}
// The normal map: heightNormal at every texel centre, stored n * 127.5 + 127.5, its mip chain the 2x2 averages.
inline std::vector<ts::Image> normalMap(const Relief& r, double heightScale, double tile) {
  ts::Image base(kTexSize, kTexSize);
  for (int j = 0; j < kTexSize; ++j)
    for (int i = 0; i < kTexSize; ++i) {
      glm::dvec3 n = heightNormal(r, {(i + 0.5) / kTexSize, (j + 0.5) / kTexSize}, heightScale, tile);
      base.set(i, j, {u8(n.x * 127.5 + 127.5), u8(n.y * 127.5 + 127.5), u8(n.z * 127.5 + 127.5), 255});
    }
  return chain(base, false);
}

// The texture-space box the camera sees of the relief, from the top (depth 0) to the floor (depth 1): the
// four corner rays at both depths, a texel's margin.  (u0, v0, u1, v1).
inline glm::dvec4 visibleBox(const Camera& cam) {
  glm::dvec4 b(1e30, 1e30, -1e30, -1e30);
  for (glm::dvec2 p :
       {glm::dvec2(0, 0), glm::dvec2(cam.width, 0), glm::dvec2(0, cam.height), glm::dvec2(cam.width, cam.height)})
    for (double d : {0.0, 1.0}) {
      glm::dvec3 ray = cam.ray(p);
      glm::dvec2 uv = cam.topUV(ray) + cam.parallax(ray) * d;
      b = {std::min(b.x, uv.x), std::min(b.y, uv.y), std::max(b.z, uv.x), std::max(b.w, uv.y)};
    }
  const double m = 2.0 / kTexSize;
  return b + glm::dvec4(-m, -m, m, m);
}

// The displaced grid: vertices (u, v, h) every `spacing` texels (on texel centres) over the visible box, and
// one triangle strip through all rows (two repeated indices join a row to the next).
struct Grid {
  int spacing = 0, columns = 0, rows = 0;
  std::vector<float> xyz;
  std::vector<GLuint> strip;
  size_t cells() const { return size_t(std::max(0, columns - 1)) * size_t(std::max(0, rows - 1)); }
};
inline Grid displacedGrid(const Relief& r, const Camera& cam, int spacing) {
  Grid g;
  g.spacing = spacing;
  const glm::dvec4 b = visibleBox(cam) * double(kTexSize);
  const double step = spacing;
  const double i0 = std::floor(b.x / step) * step + 0.5, j0 = std::floor(b.y / step) * step + 0.5;
  g.columns = int(std::ceil((b.z - i0) / step)) + 1;
  g.rows = int(std::ceil((b.w - j0) / step)) + 1;
  g.xyz.reserve(size_t(g.columns) * size_t(g.rows) * 3);
  for (int j = 0; j < g.rows; ++j)
    for (int i = 0; i < g.columns; ++i) {
      glm::dvec2 uv((i0 + i * step) / kTexSize, (j0 + j * step) / kTexSize);
      g.xyz.insert(g.xyz.end(), {float(uv.x), float(uv.y), float(1.0 - depthAt(r, uv))});
    }
  for (int j = 0; j + 1 < g.rows; ++j) {
    if (j > 0) g.strip.push_back(GLuint(j * g.columns));  // degenerate join
    for (int i = 0; i < g.columns; ++i) {
      g.strip.push_back(GLuint(j * g.columns + i));
      g.strip.push_back(GLuint((j + 1) * g.columns + i));
    }
    g.strip.push_back(GLuint((j + 1) * g.columns + g.columns - 1));
  }
  return g;
}

inline const char* rankVertexShader(bool geometry) {
  if (!geometry) return "#version 120\nvoid main() { gl_Position = ftransform(); }\n";
  // The camera's projection of a world point P: q = P - eye = t (fwd + x right + y up) with fwd, right, up
  // orthogonal, so t = q . fwd, x t = q . right / |right|^2 (clip x, w = t); depth over near 0.05, far 40.
  return R"(#version 120
uniform vec3 eye, fwd, rightV, upV;
uniform vec4 relief;  // (1 / tile, heightScale / tile, texture size, levels - 1)
void main() {
  vec3 P = vec3(gl_Vertex.xy / relief.x, (gl_Vertex.z - 1.0) * relief.y / relief.x);
  vec3 q = P - eye;
  float t = dot(q, fwd);
  const float n = 0.05, f = 40.0;
  gl_Position = vec4(dot(q, rightV) / dot(rightV, rightV), dot(q, upV) / dot(upV, upV),
                     (f + n) / (f - n) * t - 2.0 * f * n / (f - n), t);
  gl_TexCoord[0] = vec4(gl_Vertex.xy, 0.0, 1.0);
}
)";
}

inline std::string rankFragmentShader(int method) {
  return std::string("#version 120\n#extension GL_ARB_shader_texture_lod : require\n#define METHOD ") +
         std::to_string(method) + R"(
uniform sampler2D albedo, heightTex, normalTex;
uniform vec3 eye, fwd, rightV, upV, lightDir;
uniform vec2 viewport;
uniform vec4 relief;  // (1 / tile, heightScale / tile, texture size, levels - 1)
uniform vec2 pomSteps;
uniform float ambient;

#define FETCH
)" +
         kMarchGLSL /* rayDir, topUV, depthGrad, pom: parallax_aniso_gl.hpp */ + R"(
void main() {
  vec2 p = gl_FragCoord.xy;
  vec3 d = rayDir(p);
  vec2 uv0 = topUV(d);
  vec2 gx = topUV(rayDir(p + vec2(0.5, 0.0))) - topUV(rayDir(p - vec2(0.5, 0.0)));
  vec2 gy = topUV(rayDir(p + vec2(0.0, 0.5))) - topUV(rayDir(p - vec2(0.0, 0.5)));
  vec2 Vp = d.xy / (-d.z) * relief.y;
  vec3 n;
#if METHOD == 0
  // Blinn: the heights' slopes at the unshifted coordinate (one texel apart), no shift.
  vec2 uv = uv0;
  float e = 1.0 / relief.z;
  float hx = (depthGrad(uv - vec2(e, 0.0), gx, gy) - depthGrad(uv + vec2(e, 0.0), gx, gy)) / (2.0 * e);
  float hy = (depthGrad(uv - vec2(0.0, e), gx, gy) - depthGrad(uv + vec2(0.0, e), gx, gy)) / (2.0 * e);
  n = normalize(vec3(-relief.y * hx, -relief.y * hy, 1.0));
#else
#if METHOD == 1
  vec2 uv = uv0;
#elif METHOD == 2
  vec2 uv = uv0 + Vp * depthGrad(uv0, gx, gy);  // one offset step: the depth at the entry point
#elif METHOD == 3
  vec2 uv = uv0 + Vp * pom(uv0, Vp, gx, gy, abs(normalize(d).z));
#else
  vec2 uv = gl_TexCoord[0].xy;  // the displaced grid's own coordinate
  gx = dFdx(uv);
  gy = dFdy(uv);
#endif
  n = normalize(texture2DGradARB(normalTex, uv, gx, gy).rgb * 2.0 - 1.0);
#endif
  vec3 a = texture2DGradARB(albedo, uv, gx, gy).rgb;
  gl_FragColor = vec4(a * (ambient + (1.0 - ambient) * max(0.0, dot(n, lightDir))), 1.0);
}
)";
}

// The ranking's GL objects, per renderer (Renderer::attachment<RankGL>()).  The albedo and heights are the
// demo's own textures (ReliefGL::textures); the normal map is made here, once per map and height scale.
class RankGL final : public ts::Renderer::Attachment {
 public:
  explicit RankGL(ts::Renderer& r) : r_(r) {}
  ~RankGL() override { release(); }
  // Drops the normal map's GL texture: the next pass uploads it again (so that a recorded pass shows how).
  void release() {
    if (!normal_.name.empty()) r_.forgetTexture(normal_);
  }
  RankGL(const RankGL&) = delete;
  RankGL& operator=(const RankGL&) = delete;

  // One method drawn at the camera's size and read back (row 0 = top).  `grid` is the displacement's
  // (ignored by the others).
  ts::Image render(const Camera& cam, const Relief& rel, const Light& light, int method, const Grid* grid) {
    ReliefGL& base = r_.attachment<ReliefGL>();
    const ReliefTextures& t = base.textures(rel);
    const ts::TextureDesc& nmap = normals(rel, cam);
    const bool geometry = method == kDisplacement;
    if (geometry && !grid) throw ts::Error("the displacement method needs its grid", ts::kExitFailure);
    GLuint prog = r_.program("parallax_rank_" + std::string(kMethodKeys[method]),
                             {kRankSourceFile, rankVertexShader(geometry), rankFragmentShader(method)});
    return ts::pixelPass(r_, cam.width, cam.height, "a relief-ranking pass", [&] {
      glUseProgram(prog);
      const ts::TextureDesc* maps[3] = {&t.albedo, &t.height, &nmap};
      const char* names[3] = {"albedo", "heightTex", "normalTex"};
      for (int k = 0; k < 3; ++k) {
        glActiveTexture(GLenum(GL_TEXTURE0 + k));
        r_.texture(*maps[k]);  // uploads once, binds, sets the filters
        glUniform1i(glGetUniformLocation(prog, names[k]), k);
      }
      glActiveTexture(GL_TEXTURE0);
      setCameraUniforms(prog, cam);
      glUniform3f(glGetUniformLocation(prog, "lightDir"), float(light.dir.x), float(light.dir.y), float(light.dir.z));
      glUniform4f(glGetUniformLocation(prog, "relief"), float(1.0 / cam.tile), float(cam.heightScale / cam.tile),
                  float(kTexSize), float(t.levels - 1));
      glUniform2f(glGetUniformLocation(prog, "pomSteps"), 12.0f, 40.0f);
      glUniform1f(glGetUniformLocation(prog, "ambient"), float(light.ambient));
      if (!geometry) {  // every pixel once: a rectangle over the pass, in window pixels
        glBegin(GL_QUADS);
        glVertex2f(0, 0), glVertex2f(float(cam.width), 0);
        glVertex2f(float(cam.width), float(cam.height)), glVertex2f(0, float(cam.height));
        glEnd();
      } else {  // the displaced grid, nearest surface kept
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, grid->xyz.data());
        glDrawElements(GL_TRIANGLE_STRIP, GLsizei(grid->strip.size()), GL_UNSIGNED_INT, grid->strip.data());
        glDisableClientState(GL_VERTEX_ARRAY);
      }
      glUseProgram(0);
      ts::gl::check("drawing a relief-ranking pass");
    });
  }

 private:
  const ts::TextureDesc& normals(const Relief& rel, const Camera& cam) {
    const std::string name = "relief_" + rel.name + "_normals_" + std::to_string(cam.heightScale);
    if (normal_.name == name) return normal_;
    if (!normal_.name.empty()) r_.forgetTexture(normal_);
    std::vector<ts::Image> chainN = normalMap(rel, cam.heightScale, cam.tile);
    normal_ = {};
    normal_.name = name;
    normal_.image = std::make_shared<ts::Image>(chainN.front());
    normal_.mipmaps = true;
    normal_.mipLevels = std::make_shared<std::vector<ts::Image>>(chainN);
    normal_.minFilter = GL_LINEAR_MIPMAP_LINEAR;
    normal_.magFilter = GL_LINEAR;
    normal_.wrapS = normal_.wrapT = GL_REPEAT;
    return normal_;
  }
  ts::Renderer& r_;
  ts::TextureDesc normal_;
};
}  // namespace pax::rank
