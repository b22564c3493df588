// demos/jitter/jitter_gl.hpp — how Figure VI.7's images are made with
// OpenGL, shared by the demo and its tests.
//
// Two ways to put n x n samples in a pixel:
//  * The Red Book's accumulation-buffer jitter (regular and jitter-global):
//    the plane is drawn n*n times, each time with the projection shifted by
//    a sub-pixel offset (accPerspective), and the passes are averaged:
//        glClear(GL_ACCUM_BUFFER_BIT);
//        for each pass: draw; glAccum(GL_ACCUM, 1/n^2);
//    (here the first pass is loaded with GL_LOAD instead, see below)
//        glAccum(GL_RETURN, 1);
//    The accumulation buffer belongs to the default framebuffer (OSMesa, a
//    GLX window).  EGL has none: there each pass is rendered into an FBO and
//    the 8-bit passes are summed on the CPU and rounded (FBO averaging).  So
//    is it where glAccum would not average the stored values (accumStatus).
//    Every pixel gets the same offsets — that is what "one jitter for the
//    whole image" means.
//  * Per-pixel jitter in one pass: a fragment shader evaluates the analytic
//    checkerboard at n x n points of its own pixel, jittered by a hash of
//    (seed, pixel, sample) — the same integer hash as jitter_math.hpp — and
//    averages them.  The plane's (x, z) at any window point comes from the
//    homography jitter::pixelToPlane.
// The checkerboard is procedural in both (the plane's (x, z) in, a colour
// out), so no texture filtering enters the comparison.
#pragma once
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdlib>
#include <cstdint>
#include <string>
#include <vector>

#include "common/gl/context.hpp"
#include "common/core/error.hpp"
#include "common/core/frame.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"
#include "jitter_math.hpp"
#include "jitter_zone.hpp"

namespace jitter {
constexpr const char* kSourceFile = "demos/jitter/jitter_gl.hpp";

// GLSL shared by both programs: the hash of jitter_math.hpp and the colour
// at a window point, through the homography window (px, py, 1) -> plane
// (X, Z, S) of jitter::pixelToPlane.  GLSL 1.20, what macOS's legacy
// OpenGL 2.1 context compiles: the 32-bit unsigned integers of the hash
// (spelt "unsigned int", the extension's own spelling), their ^ >> and
// wrapping *, and the integer % from GL_EXT_gpu_shader4, which Mesa and
// Apple's 2.1 context offer.
inline std::string glslCommon() {
  return R"(#version 120
#extension GL_EXT_gpu_shader4 : require
uniform vec4 h0, h1, h2;  // rows of the homography
uniform vec4 checker;     // (side of a check, dark, light, far z), colours in 8-bit units
uniform vec4 sky;         // rgb, 8-bit units
unsigned int hash32(unsigned int x) {  // lowbias32, as jitter::hash32
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}
float unitFloat(unsigned int h) { return float(h >> 8u) * (1.0 / 16777216.0); }
vec3 colourAt(vec2 p) {
  vec3 q = vec3(p, 1.0);
  vec3 xzs = vec3(dot(h0.xyz, q), dot(h1.xyz, q), dot(h2.xyz, q));
  if (xzs.z > 0.0) {
    vec2 xz = xzs.xy / xzs.z;
    if (xz.y >= -checker.w) {
      vec2 c = floor(xz / checker.x);
      float s = c.x + c.y;
      float odd = s - 2.0 * floor(s * 0.5);
      return vec3(odd > 0.5 ? checker.z : checker.y);
    }
  }
  return sky.rgb;
}
)";
}

// The plane drawn as geometry through the (shifted) projection.  Each
// fragment finds its point of the plane by inverting that same projection
// at its window position: what perspective-correct interpolation of (x, z)
// computes, but exactly, so the result does not depend on how the
// framebuffer is stored (window-system buffers are y-inverted in Mesa, FBOs
// are not, and interpolation rounds differently in the two).
inline const char* groundVS() {
  return R"(#version 120
void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; })";
}
inline std::string groundFS() {
  return glslCommon() + R"(
void main() { gl_FragColor = vec4(colourAt(gl_FragCoord.xy) / 255.0, 1.0); })";
}

// A full-viewport quad; every fragment samples its own pixel n x n times.
inline const char* pixelJitterVS() {
  return R"(#version 120
void main() { gl_Position = gl_Vertex; })";
}
inline std::string pixelJitterFS() {
  return glslCommon() + R"(
uniform vec4 params;  // (n, seed, sample to show as its position or -1, 0)
void main() {
  vec2 pix = floor(gl_FragCoord.xy);  // the viewport starts at (0, 0)
  int n = int(params.x);
  unsigned int px = unsigned int(pix.x), py = unsigned int(pix.y);
  unsigned int key = hash32(unsigned int(params.y) ^ hash32(px ^ hash32(py + 0x632be5abu)));
  int show = int(params.z);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < n * n; ++k) {
    int a = k % n, b = k / n;
    unsigned int kk = 2u * unsigned int(k);
    vec2 s = vec2((float(a) + unitFloat(hash32(key + kk))) / float(n),
                  (float(b) + unitFloat(hash32(key + kk + 1u))) / float(n));
    if (k == show) {
      gl_FragColor = vec4(s, 0.0, 1.0);
      return;
    }
    sum += colourAt(pix + s);
  }
  gl_FragColor = vec4(sum / (255.0 * float(n * n)), 1.0);
})";
}

// Pure random sampling (the contrast Buss VI.1.4 draws): the same one pass, but the n x n points
// fall anywhere in the pixel (no strata), keyed by the seed xor
// jitter::kRandomSalt — jitter::randomIn, bit for bit.  They can cluster.
inline std::string pixelRandomFS() {
  return glslCommon() + R"(
uniform vec4 params;  // (n, seed, sample to show as its position or -1, 0)
void main() {
  vec2 pix = floor(gl_FragCoord.xy);
  int n = int(params.x);
  unsigned int px = unsigned int(pix.x), py = unsigned int(pix.y);
  unsigned int key = hash32((unsigned int(params.y) ^ 0x27d4eb2fu) ^ hash32(px ^ hash32(py + 0x632be5abu)));
  int show = int(params.z);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < n * n; ++k) {
    unsigned int kk = 2u * unsigned int(k);
    vec2 s = vec2(unitFloat(hash32(key + kk)), unitFloat(hash32(key + kk + 1u)));
    if (k == show) {
      gl_FragColor = vec4(s, 0.0, 1.0);
      return;
    }
    sum += colourAt(pix + s);
  }
  gl_FragColor = vec4(sum / (255.0 * float(n * n)), 1.0);
})";
}

// The uniforms of glslCommon for a homography.
inline std::vector<ts::Uniform> commonUniforms(const Camera& c, const glm::dmat3& h) {
  auto row = [&](int r) { return glm::vec4(float(h[0][r]), float(h[1][r]), float(h[2][r]), 0.0f); };
  return {{"h0", row(0)},
          {"h1", row(1)},
          {"h2", row(2)},
          {"checker", glm::vec4(float(c.check), float(kDark), float(kLight), float(c.farZ))},
          {"sky", glm::vec4(float(kSky[0]), float(kSky[1]), float(kSky[2]), 0.0f)}};
}

inline glm::vec4 skyColour() { return {kSky[0] / 255.0f, kSky[1] / 255.0f, kSky[2] / 255.0f, 1.0f}; }

// The half-width of the drawn plane at depth z: wider than the view frustum
// (horizontal half-angle < 45 degrees) everywhere.
inline double bandHalfWidth(double z) { return std::abs(z) + 10.0; }

// One pass of the Red Book method: the plane drawn with the projection
// shifted so that every pixel is sampled at `samplePos` (in [0,1)^2).  The
// plane is four trapezoids, z in [5, -10, -100, -1000, -farZ], sharing their
// edges exactly (no T-junctions); (x, z) rides along in the texture
// coordinates for the sidecar, the shader recomputes it exactly.
inline ts::Frame groundPass(const Camera& c, glm::dvec2 samplePos) {
  ts::Frame f;
  f.width = c.width;
  f.height = c.height;
  f.clearColor = skyColour();
  f.programs.push_back({"jitter_ground", {kSourceFile, groundVS(), groundFS()}});
  ts::Panel p;
  p.id = "ground";
  p.viewport = {0, 0, c.width, c.height};
  p.projection = glm::mat4(pixelShift(c, samplePos) * projection(c));
  p.modelview = glm::mat4(view(c));
  ts::Batch b;
  b.role = "plane";
  b.program = "jitter_ground";
  b.uniforms = commonUniforms(c, pixelToPlane(c, pixelShift(c, samplePos)));
  const double zs[] = {5.0, -10.0, -100.0, -1000.0, -c.farZ};
  for (int k = 0; k + 1 < 5; ++k) {
    double z0 = zs[k], z1 = zs[k + 1], w0 = bandHalfWidth(z0), w1 = bandHalfWidth(z1);
    glm::dvec2 q[4] = {{-w0, z0}, {w0, z0}, {w1, z1}, {-w1, z1}};
    for (int i : {0, 1, 2, 0, 2, 3}) {
      ts::Vertex v;
      v.pos = glm::vec3(float(q[i].x), 0.0f, float(q[i].y));
      v.tex = glm::vec4(float(q[i].x), float(q[i].y), 0.0f, 1.0f);
      b.vertices.push_back(v);
    }
  }
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}

// Two triangles over the whole viewport (clip coordinates -1..1): the
// fragment shader is then run once per pixel.
inline void fullViewport(ts::Batch& b) {
  for (auto q :
       {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
    ts::Vertex v;
    v.pos = glm::vec3(q, 0.0f);
    b.vertices.push_back(v);
  }
}

// The single pass of jitter-pixel.  showSample >= 0 writes that sample's
// position in its pixel into (R, G) instead of a colour (for the tests).
// random: pure random points per pixel instead (pixelRandomFS).
inline ts::Frame pixelJitterPass(const Camera& c, int n, uint32_t seed, int showSample = -1, bool random = false) {
  ts::Frame f;
  f.width = c.width;
  f.height = c.height;
  f.clearColor = skyColour();
  const char* program = random ? "jitter_random" : "jitter_pixel";
  f.programs.push_back({program, {kSourceFile, pixelJitterVS(), random ? pixelRandomFS() : pixelJitterFS()}});
  ts::Panel p;
  p.id = random ? "pixel_random" : "pixel_jitter";
  p.viewport = {0, 0, c.width, c.height};
  ts::Batch b;
  b.role = "full_viewport";
  b.program = program;
  b.uniforms = commonUniforms(c, pixelToPlane(c));
  b.uniforms.push_back({"params", glm::vec4(float(n), float(seed), float(showSample), 0.0f)});
  fullViewport(b);
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}

// ------------------------------------------------------------ the zone plate
// Where aliasing sets in, read from GL renders (jitter_zone.hpp has the CPU model
// and the measure): bands of zone::kGlBandRows rows, band b at frequency
// (b + 1) zone::kStep cycles per pixel, each row the signal
// cos(2 pi f x + phase) across zone::kGlWidth columns, sampled by one pass of
// a fragment shader at the pattern's n x n points of its pixel (regular: the
// subpixel centres; jittered: the hash of jitter-pixel) and averaged, written
// as 0.5 + 0.5 * average.  The measure reads the 8-bit pixels back.
inline std::string zoneFS() {
  return glslCommon() + R"(
uniform vec4 zone;  // (n, seed, 0 regular | 1 jittered per pixel, phase)
uniform vec4 band;  // (cycles per pixel per band, rows per band, 0, 0)
void main() {
  vec2 pix = floor(gl_FragCoord.xy);
  int n = int(zone.x);
  float f = (floor(pix.y / band.y) + 1.0) * band.x;
  uint key = hash32(uint(zone.y) ^ hash32(uint(pix.x) ^ hash32(uint(pix.y) + 0x632be5abu)));
  float sum = 0.0;
  for (int k = 0; k < n * n; ++k) {
    int a = k % n;
    uint kk = 2u * uint(k);
    float sx = zone.z > 0.5 ? (float(a) + unitFloat(hash32(key + kk))) / float(n) : (float(a) + 0.5) / float(n);
    sum += cos(6.283185307 * f * (pix.x + sx) + zone.w);
  }
  gl_FragColor = vec4(vec3(0.5 + 0.5 * sum / float(n * n)), 1.0);
})";
}
inline ts::Frame zonePass(int n, uint32_t seed, bool jittered, double phase) {
  ts::Frame f;
  f.width = zone::kGlWidth;
  f.height = zone::kGlBands * zone::kGlBandRows;
  f.clearColor = {0, 0, 0, 1};
  f.programs.push_back({"jitter_zone", {kSourceFile, pixelJitterVS(), zoneFS()}});
  ts::Panel p;
  p.id = "zone_plate";
  p.viewport = {0, 0, f.width, f.height};
  ts::Batch b;
  b.role = "full_viewport";
  b.program = "jitter_zone";
  b.uniforms = {{"zone", glm::vec4(float(n), float(seed), jittered ? 1.0f : 0.0f, float(phase))},
                {"band", glm::vec4(float(zone::kStep), float(zone::kGlBandRows), 0.0f, 0.0f)}};
  fullViewport(b);
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}
// The onset read from the GL renders (phases 0 and pi/2): the lowest band
// whose alias RMS reaches zone::kThreshold of its box-filtered truth's.
// `first` (if given) gets the render at phase 0.
inline zone::Sweep zoneSweepGl(ts::Renderer& r, int n, uint32_t seed, bool jittered, ts::Image* first = nullptr) {
  std::vector<double> ee(size_t(zone::kGlBands), 0.0), tt(ee);
  for (double phi : {0.0, zone::kPi / 2}) {
    const ts::Image img = r.renderOffscreen(zonePass(n, seed, jittered, phi));
    if (first && phi == 0.0) *first = img;
    for (int j = 0; j < img.height; ++j) {
      const int bandIndex = j / zone::kGlBandRows;
      const double f = (bandIndex + 1) * zone::kStep;
      for (int i = 0; i < img.width; ++i) {
        const double v = 2.0 * (img.at(i, img.height - 1 - j).r / 255.0) - 1.0, t = zone::truth(f, phi, i);
        ee[size_t(bandIndex)] += (v - t) * (v - t), tt[size_t(bandIndex)] += t * t;
      }
    }
  }
  zone::Sweep s;
  const double perBand = 2.0 * zone::kGlWidth * zone::kGlBandRows;
  for (int b = 0; b < zone::kGlBands; ++b) {
    if (std::sqrt(tt[size_t(b)] / perBand) < zone::kTruthFloor) continue;
    const double f = (b + 1) * zone::kStep, rho = std::sqrt(ee[size_t(b)] / tt[size_t(b)]);
    s.f.push_back(f), s.rho.push_back(rho);
    if (s.onset < 0 && rho >= zone::kThreshold) s.onset = f;
  }
  return s;
}
// jitter.cpp's zone-plate numbers: the CPU model's (zone::measure) and the GL renders'.
// `keep` gets the renders and sweeps for the zone view.
inline void zoneMeasure(ts::Renderer& r, ts::Measurements& out, int n, uint32_t seed, zone::Plate* keep) {
  zone::measure(out, n, seed);
  const std::string nn = std::to_string(n) + "x" + std::to_string(n);
  zone::Plate plate;
  plate.n = n;
  for (int k = 0; k < 3; ++k)
    plate.sweeps[size_t(k)] = zoneSweepGl(r, k == 0 ? 1 : n, seed, k == 2, &plate.images[size_t(k)]);
  for (int k : n == 1 ? std::vector<int>{0} : std::vector<int>{0, 1})
    out.push_back({"alias_onset_gl[" + std::string(k == 0 ? "1x1" : nn) + "]", plate.sweeps[size_t(k)].onset,
                   "the same onset read from a GL render of the zone plate (8-bit pixels), regular samples"});
  out.push_back(
      {"alias_onset_gl[jitter_pixel_" + nn + "]", plate.sweeps[2].onset, "the same, GL, jittered per pixel (noise)"});
  plate.valid = true;
  *keep = std::move(plate);
}

// The n*n sample positions of a multi-pass pattern (Regular, JitterGlobal).
inline std::vector<glm::dvec2> passOffsets(Pattern p, int n, uint32_t seed) {
  std::vector<glm::dvec2> out;
  for (int k = 0; k < n * n; ++k) out.push_back(samplePos(p, n, seed, 0, 0, k));
  return out;
}

// Whether glAccum can average passes of w x h here, and if not why.
enum class AccumStatus { Usable, NoBuffer, TooSmall, NotStoredValues };
// Why glAccum cannot be used ("" when it can).
inline std::string reason(AccumStatus s) {
  switch (s) {
    case AccumStatus::Usable: return "";
    case AccumStatus::NoBuffer: return "the context has no accumulation buffer (EGL contexts have none)";
    case AccumStatus::TooSmall: return "the window is smaller than the image";
    case AccumStatus::NotStoredValues:
      return "this framebuffer's glAccum averages in linear light (an sRGB visual), not the stored values";
  }
  return "?";
}
// Which path the multi-pass images take, for the note the demo prints.
inline std::string describe(AccumStatus s) {
  return s == AccumStatus::Usable ? "averaged with glAccum (the context's accumulation buffer)"
                                  : "averaged in FBOs: " + reason(s);
}

// Two flat passes, 32 and 224, averaged by glAccum into the bottom-left
// 4 x 4 pixels: 128 when the accumulation buffer averages the values the
// colour buffer stores (OSMesa).  Mesa's GLX windows get sRGB-capable
// visuals, and Mesa's glAccum decodes sRGB colour buffers whatever
// GL_FRAMEBUFFER_SRGB says: there it gives 155 (the average in linear
// light), and the window's picture would not be the --png's.
inline bool accumAveragesStoredValues(ts::Renderer& r) {
  ts::Frame f;
  // 4x4 pixels, or the whole target when it is smaller (--size 3x3).
  const int n = std::max(1, std::min({4, r.context().width(), r.context().height()}));
  f.width = f.height = n;
  uint8_t got[4 * 4 * 4] = {0};
  for (int k = 0; k < 2; ++k) {
    float v = (k == 0 ? 32.0f : 224.0f) / 255.0f;
    f.clearColor = {v, v, v, 1.0f};
    r.draw(f, false);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, n, n);
    glAccum(k == 0 ? GL_LOAD : GL_ACCUM, 0.5f);
  }
  glAccum(GL_RETURN, 1.0f);
  glDisable(GL_SCISSOR_TEST);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, n, n, GL_RGBA, GL_UNSIGNED_BYTE, got);
  ts::gl::check("probing the accumulation buffer");
  for (int i = 0; i < n * n; ++i)
    for (int ch = 0; ch < 3; ++ch)
      if (std::abs(int(got[i * 4 + ch]) - 128) > 1) return false;
  return true;
}

inline AccumStatus accumStatus(ts::Renderer& r, int w, int h) {
  ts::Context& ctx = r.context();
  if (!ctx.hasAccumBuffer()) return AccumStatus::NoBuffer;
  if ((ctx.width() < w || ctx.height() < h) && ctx.backend() == ts::Backend::Window) return AccumStatus::TooSmall;
  return accumAveragesStoredValues(r) ? AccumStatus::Usable : AccumStatus::NotStoredValues;
}

// glAccum on the default framebuffer (the Red Book), bottom-left w x h.
inline ts::Image accumulateWithAccumBuffer(ts::Renderer& r, const std::vector<ts::Frame>& passes) {
  ts::Context& ctx = r.context();
  const int w = passes.front().width, h = passes.front().height;
  if (ctx.width() < w || ctx.height() < h) ctx.resize(std::max(ctx.width(), w), std::max(ctx.height(), h));
  const float weight = 1.0f / float(passes.size());
  for (size_t k = 0; k < passes.size(); ++k) {
    r.draw(passes[k], false);  // binds the default framebuffer, clears, draws
    glFinish();
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, w, h);
    // The Red Book clears the buffer and accumulates every pass; loading the
    // first pass is the same sum.  (Mesa 22's glClear(GL_ACCUM_BUFFER_BIT)
    // with a scissor box leaves a GLX window's accumulation buffer as it was:
    // measured, every image then carried the previous one.)
    glAccum(k == 0 ? GL_LOAD : GL_ACCUM, weight);
  }
  glAccum(GL_RETURN, 1.0f);
  glDisable(GL_SCISSOR_TEST);
  glFinish();
  ts::Image img(w, h);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
  ts::gl::check("accumulating the jitter passes with glAccum");
  img.flipVertical();
  for (size_t i = 3; i < img.pixels.size(); i += 4) img.pixels[i] = 255;
  return img;
}

// FBO averaging: each pass into its own FBO (Renderer::renderOffscreen), the
// 8-bit passes summed exactly and rounded half up once.  Differs from glAccum
// by at most one 8-bit step per channel (the accumulation buffer holds
// 16-bit values, so its rounding of a sum that ends in .5 can go either way).
inline ts::Image accumulateWithFbo(ts::Renderer& r, const std::vector<ts::Frame>& passes) {
  const int w = passes.front().width, h = passes.front().height;
  std::vector<uint32_t> sum(size_t(w) * size_t(h) * 4, 0);
  for (const ts::Frame& f : passes) {
    ts::Image one = r.renderOffscreen(f);
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += one.pixels[i];
  }
  const uint32_t n = uint32_t(passes.size());
  ts::Image img(w, h);
  for (size_t i = 0; i < sum.size(); ++i) img.pixels[i] = uint8_t((2 * sum[i] + n) / (2 * n));
  return img;
}
}  // namespace jitter
