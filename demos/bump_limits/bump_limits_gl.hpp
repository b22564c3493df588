// demos/bump_limits/bump_limits_gl.hpp — the bump-limits demo's GL: one fragment shader for every per-pixel
// method, drawn over a quad by a pixel pass (common/gl/pixel_pass.hpp) and read back, and the fixed-function pass
// that shows a baked shading texture.
//
// The plane is seen from straight above, `zoom` pixels a texel: pixel centre (x + 1/2, y + 1/2) (y up) is the
// texture point s = (x + 1/2) / (zoom kTexels), GL_REPEAT beyond the tile.  Per pixel (bumplim::Pass):
//   method blinn      n = normalize(-dz/dx, -dz/dy, 1), the slopes central differences of the heights `step`
//                     texels apart (seed 004, Blinn, on a plane); the heights mipmapped or not
//   method normalmap  n = normalize(2 N(s, t) - 1)                     the normal map, GL_LINEAR
//   method offset     n = normalize((0, 0, 1) + bu e1 + bv e2)         the offset-vector map, GL_LINEAR
//   shading           c = A + (1 - A) max(n . L, 0) [lit]              A = kAmbient, grey
//   horizon           lit = elevation(L) > mix(H_k0, H_k0+1, frac)     H the horizon map (GL_LINEAR) at the
//                     light's azimuth between the two nearest of the 8 directions
//   output normals    0.5 + 0.5 n; masks: red = (n . L > 0), green = horizon-lit
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bump_limits_math.hpp"
#include "common/core/frame.hpp"
#include "common/core/textures.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/gl_record.hpp"
#include "common/gl/pixel_pass.hpp"
#include "common/gl/render.hpp"

namespace bumplim {
constexpr float kAmbient = 0.1f;
enum class Method { kBlinn = 0, kNormalMap = 1, kOffset = 2 };
enum class Output { kShade = 0, kNormal = 1, kMasks = 2 };

inline const char* kVertexShader = R"(#version 110
void main() { gl_Position = ftransform(); gl_TexCoord[0] = gl_MultiTexCoord0; }
)";
inline const char* kFragmentShader = R"(#version 110
uniform sampler2D heights, map, horizon0, horizon1;
uniform int method, outputKind, horizon;
uniform vec3 light;         // unit, z up
uniform vec2 lightAngles;   // azimuth, elevation (radians)
uniform float texels, heightMax, step, offsetRange, ambient;
float pick(int k) {         // the horizon map's angle in direction k (0..7), radians
  vec4 a = texture2D(horizon0, gl_TexCoord[0].st), b = texture2D(horizon1, gl_TexCoord[0].st);
  float v = k == 0 ? a.r : k == 1 ? a.g : k == 2 ? a.b : k == 3 ? a.a :
            k == 4 ? b.r : k == 5 ? b.g : k == 6 ? b.b : b.a;
  return v * 1.5707963;
}
void main() {
  vec2 st = gl_TexCoord[0].st;
  vec3 n;
  if (method == 0) {        // Blinn: the heights' central differences, `step` texels apart
    float d = step / texels;
    float dx = texture2D(heights, st + vec2(d, 0.0)).r - texture2D(heights, st - vec2(d, 0.0)).r;
    float dy = texture2D(heights, st + vec2(0.0, d)).r - texture2D(heights, st - vec2(0.0, d)).r;
    n = normalize(vec3(-dx, -dy, 2.0 * step / heightMax));
  } else if (method == 1) { // the normal map
    n = normalize(texture2D(map, st).rgb * 2.0 - 1.0);
  } else {                  // the offset-vector map: n + bu e1 + bv e2, e1, e2 the plane's x and y
    vec2 b = (texture2D(map, st).rg * 2.0 - 1.0) * offsetRange;
    n = normalize(vec3(b, 1.0));
  }
  float nl = dot(n, light);
  float lit = 1.0;
  if (horizon == 1) {
    float k = lightAngles.x / 0.78539816;
    int k0 = int(floor(k));
    float a = k - float(k0);
    float h = mix(pick(k0 - 8 * (k0 / 8)), pick(k0 + 1 - 8 * ((k0 + 1) / 8)), a);
    lit = lightAngles.y > h ? 1.0 : 0.0;
  }
  if (outputKind == 1) gl_FragColor = vec4(0.5 + 0.5 * n, 1.0);
  else if (outputKind == 2) gl_FragColor = vec4(nl > 0.0 ? 1.0 : 0.0, lit, 0.0, 1.0);
  else gl_FragColor = vec4(vec3(ambient + (1.0 - ambient) * max(nl, 0.0) * lit), 1.0);
}
)";

// One pass of the shader.
struct Pass {
  Method method = Method::kBlinn;
  Output output = Output::kShade;
  bool horizon = false, mipmapped = false;
  double azDeg = 30, elevDeg = 20;
  double step = 1;  // texels between the central differences
  int size = 256;   // pixels a side
  double zoom = 4;  // pixels a texel
};

// The textures the shader reads, made for this pass (and deleted after it).
struct Inputs {
  ts::Image heights = heightImage(), normals = normalMapImage(), offsets = offsetMapImage();
  std::vector<ts::Image> horizons;
};

inline GLuint uploadMipmapped(const ts::Image& img) {
  GLuint t = ts::texture2D(img.width, img.height, &img, GL_LINEAR, GL_REPEAT);
  const std::vector<ts::Image> chain = ts::buildMipChain(img);
  for (size_t l = 1; l < chain.size(); ++l)
    glTexImage2D(GL_TEXTURE_2D, GLint(l), GL_RGBA8, chain[l].width, chain[l].height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 chain[l].pixels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(chain.size() - 1));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  return t;
}

// The plane from above: a quad over the whole pass, texture coordinates from 0 to size / (zoom kTexels).
inline void planeQuad(int size, double zoom) {
  const float s = float(size / (zoom * kTexels));
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2f(0, 0);
  glTexCoord2f(s, 0), glVertex2f(float(size), 0);
  glTexCoord2f(s, s), glVertex2f(float(size), float(size));
  glTexCoord2f(0, s), glVertex2f(0, float(size));
  glEnd();
}

inline ts::Image shaderPass(ts::Renderer& r, const Inputs& in, const Pass& p) {
  const GLuint prog = r.program("bump_limits",
                                {"demos/bump_limits/bump_limits_gl.hpp", kVertexShader, kFragmentShader});
  return ts::pixelPass(r, p.size, p.size, "bump limits", [&] {
    GLuint tex[4] = {0, 0, 0, 0};
    glActiveTexture(GL_TEXTURE0);
    tex[0] = p.mipmapped ? uploadMipmapped(in.heights) : ts::imageTexture(in.heights, GL_LINEAR);
    glActiveTexture(GL_TEXTURE1);
    tex[1] = ts::imageTexture(p.method == Method::kOffset ? in.offsets : in.normals, GL_LINEAR);
    for (int k = 0; k < 2 && p.horizon; ++k) {
      glActiveTexture(GL_TEXTURE2 + GLenum(k));
      tex[2 + k] = ts::imageTexture(in.horizons[size_t(k)], GL_LINEAR);
    }
    glActiveTexture(GL_TEXTURE0);
    glUseProgram(prog);
    auto loc = [&](const char* n) { return glGetUniformLocation(prog, n); };
    glUniform1i(loc("heights"), 0), glUniform1i(loc("map"), 1);
    glUniform1i(loc("horizon0"), 2), glUniform1i(loc("horizon1"), 3);
    glUniform1i(loc("method"), int(p.method)), glUniform1i(loc("outputKind"), int(p.output));
    glUniform1i(loc("horizon"), p.horizon ? 1 : 0);
    const glm::dvec3 L = lightVector(p.azDeg, p.elevDeg);
    glUniform3f(loc("light"), float(L.x), float(L.y), float(L.z));
    const double az = std::fmod(std::fmod(p.azDeg, 360.0) + 360.0, 360.0);
    glUniform2f(loc("lightAngles"), float(az * kPi / 180), float(p.elevDeg * kPi / 180));
    glUniform1f(loc("texels"), float(kTexels)), glUniform1f(loc("heightMax"), float(kHeightMax));
    glUniform1f(loc("step"), float(p.step)), glUniform1f(loc("offsetRange"), float(kOffsetRange));
    glUniform1f(loc("ambient"), kAmbient);
    planeQuad(p.size, p.zoom);
    glUseProgram(0);
    glDeleteTextures(4, tex);
  });
}

// Baked shading shown with no shader: the baked texture (GL_NEAREST), GL_REPLACE, `zoom` pixels a texel.
inline ts::Image bakedPass(ts::Renderer& r, const ts::Image& baked, int size, double zoom) {
  return ts::pixelPass(r, size, size, "baked shading", [&] {
    glActiveTexture(GL_TEXTURE0);
    GLuint t = ts::imageTexture(baked, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    planeQuad(size, zoom);
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &t);
  });
}

// A picture measure() made, as a figure's texture.  GL_LINEAR: a panel's pixel centre may fall on a texel edge,
// where GL_NEAREST's tie goes either way (OSMesa's buffer and a framebuffer object break it differently).
inline ts::TextureDesc shownPicture(const ts::Image& img, const std::string& what) {
  ts::TextureDesc t = ts::renderedImageTexture(img, "bump_limits", what, "bump_limits");
  t.minFilter = t.magFilter = GL_LINEAR;
  return t;
}
// The same with the calls that drew it.  No Frame describes it: the shader is the demo's own pass (per-pixel
// horizon lookups, central differences), not a Frame batch.
inline ts::TextureDesc glPicture(const ts::Image& img, const std::string& what, const ts::gl::CallList& calls) {
  ts::TextureDesc t = shownPicture(img, what);
  t.renderedBy = calls;
  return t;
}
// Runs `draw` recording its GL calls (the listing of the figure's pictures).
inline ts::gl::CallList recorded(ts::Renderer& r, const std::function<void()>& draw) {
  r.release();
  ts::gl::Recording rec;
  draw();
  return std::make_shared<const std::vector<ts::gl::Call>>(rec.take());
}
}  // namespace bumplim
