// demos/parallax_aniso/parallax_aniso_gl.hpp — the GLSL of the parallax demo and
// its own GL passes (three textures per draw, float probe targets), shared by
// the demo, its tests and its benchmark.
//
// One fragment shader source draws every mode (compiled once per mode, see
// below).  Each fragment builds its view ray
// from the camera (no geometry: the relief plane is analytic, as in
// demos/jitter), finds where it enters the top of the relief, and runs
// parallax occlusion mapping: a linear march of 12..40 steps (more the more
// grazing the ray) refined by intersecting the ray with the straight line
// between the last two heights read (Tatarchuk's POM refinement: no further
// lookup), heights read with textureGrad and the top plane's analytic
// gradients (no implicit derivatives inside the data-dependent loop).
// Then the albedo at the shifted coordinate uvS by
//   M0 naive     texture(albedo, uvS): implicit derivatives of the shifted
//                coordinate, which jump at every occluding edge
//   M1 trilinear textureGrad with the unshifted gradients, anisotropy 1
//   M2 aniso16   the same with GL_TEXTURE_MAX_ANISOTROPY 16 (the hardware's
//                anisotropic filter; on llvmpipe an EWA on one level, whose
//                footprint and level come from the coordinate's own quad
//                differences, not from the gradients given: rendered with
//                them x4, M2 does not change by a pixel on llvmpipe, M1
//                and softpipe's M2 change almost everywhere (gradScale,
//                Table::gradChangeM2).  So there M2 filters the footprint
//                M0's lookup sees, the shifted coordinate's, with 16 probes.)
//   M3 ewa       Heckbert's EWA in the shader: the ellipse of the unshifted
//                gradients around uvS, unit reconstruction term, Gaussian
//                weights, texelFetch row by row (only texels inside the
//                ellipse are read), two mip levels blended
//   M4 ewa-vis   M3 without the texels whose surface point is hidden from
//                the eye by higher relief (every texel traced, once)
//   M5 ewa-rows  the seed's cheaper walk: each row of the ellipse from its
//                left end until the first hidden texel, then from its right
//                end back until a hidden texel (or the stop of the first
//                walk: that index is the "buffer" that keeps a texel from
//                being counted twice); the untraced middle is dropped.
// The visibility trace (hiddenTexel, mirrored by pax::hiddenTexel) reads the
// heights of the level being filtered with texelFetch.  With `accel` on, each
// ellipse first reads the max-height pyramid once (<= 4 lookups) for the
// highest relief over every texel its traces can read; a trace stops as soon
// as its ray is less than the tolerance below that height, because no later
// sample can then find relief above the ray — the same answer, fewer lookups
// (most visible texels are on tops, where the trace then ends at once).
// Counting mode writes the number of texture lookups (texture, textureGrad,
// textureLod and texelFetch calls, whatever the hardware filter reads behind
// one call) and of excluded texels into the colour, as 16-bit integers.
//
// Every (mode, counting, texel path) is its own program, the choices
// compiled in as constants: llvmpipe runs both sides of a branch under a lane
// mask and enters every loop, so one program with `uniform int mode` made M2
// pay for the EWA code it never used (M1 at 800 x 600 took 127 ms instead
// of 70 ms).  The probe programs (MODE -1) keep a uniform `probe`.
#pragma once
#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"
#include "common/gl/render_target.hpp"
#include "common/core/ewa.hpp"
#include "parallax_aniso_math.hpp"

namespace pax {
constexpr const char* kSourceFile = "demos/parallax_aniso/parallax_aniso_gl.hpp";
enum Mode { kNaive, kTrilinear, kAniso16, kEwa, kEwaVis, kEwaRows, kShaderModes, kReference = kShaderModes };
inline const char* const kModeKeys[] = {"naive", "trilinear", "aniso16", "ewa", "ewa-vis", "ewa-rows", "reference"};
inline const char* const kModeLabels[] = {"M0 naive",       "M1 trilinear",    "M2 aniso 16x", "M3 EWA",
                                          "M4 EWA visible", "M5 EWA row walk", "R reference"};

inline const char* vertexShader() { return "#version 120\nvoid main() { gl_Position = gl_Vertex; }\n"; }

// One compiled program (see above).  centreLookups: a uniform branch in the
// innermost loop cost llvmpipe a third of M3's speed.
struct Variant {
  int mode = 0;                  // 0..5, or -1 for the probe program
  bool count = false;            // write lookups / excluded texels instead of the colour
  bool parallax = true;          // false: no march, the flat top (the benchmark's floor)
  bool unshiftedLookup = false;  // the march runs, the albedo is read at the unshifted coordinate (benchmark)
  bool centreLookups = false;
  bool plainTrace = false;  // the visibility trace reads every sample's texel (tests, benchmark)
  bool seedF = false;       // EWA with seed 003's F, sign slip and all (the causes view)
  std::string key() const {
    return "parallax_aniso_m" + std::to_string(mode) + (count ? "_count" : "") + (parallax ? "" : "_flat") +
           (unshiftedLookup ? "_unshifted" : "") + (centreLookups ? "_centre" : "") + (plainTrace ? "_plain" : "") +
           (seedF ? "_seedF" : "");
  }
};
// GLSL 1.20, what macOS's legacy OpenGL 2.1 context compiles: texture2DLod
// and texture2DGradARB from GL_ARB_shader_texture_lod; texelFetch2D, the
// integer % and >> from GL_EXT_gpu_shader4 (Mesa and Apple's 2.1 context
// offer both).
// The view ray, its entry on the relief's top and the parallax occlusion march, in GLSL: the modes' shader and
// the ranking's (parallax_aniso_ranking_gl.hpp) both paste it, after defining FETCH (a lookup counter, or nothing)
// and declaring the uniforms it reads (heightTex, eye, fwd, rightV, upV, viewport, relief, pomSteps).
inline const char* const kMarchGLSL = R"(vec3 rayDir(vec2 p) {
  vec2 n = p / viewport * 2.0 - 1.0;
  return fwd + n.x * rightV + n.y * upV;
}
vec2 topUV(vec3 d) { return (eye.xy + (eye.z / -d.z) * d.xy) * relief.x; }

float depthGrad(vec2 uv, vec2 gx, vec2 gy) {
  FETCH;
  return 1.0 - texture2DGradARB(heightTex, uv, gx, gy).r;
}
// Parallax occlusion mapping: returns the depth where the ray meets the relief.
// The march stops at the first step k whose ray depth d_k is at or below the
// relief's depth h_k.  Between the step before (ray above: d - h < 0) and
// this one (d - h >= 0) both are taken as straight lines in d, and they
// cross where d - h is zero:
//   d* = lo + (hi - lo) a / (a + b),  a = h_lo - lo > 0,  b = hi - h_hi >= 0.
// A ray that meets the relief at the first step takes the relief as flat
// from its entry to that step: it meets it at d* = h_1 (0 on a top, where
// most rays end after one lookup; reading the entry point too cost every
// pixel a lookup).  The last step (d = 1) always meets the relief: no depth
// is below the floor.
float pom(vec2 uv0, vec2 Vp, vec2 gx, vec2 gy, float cosView) {
  int n = int(mix(pomSteps.y, pomSteps.x, cosView) + 0.5);
  float stepD = 1.0 / float(n), lo = 0.0, hi = 1.0, hLo = 0.0, hHi = 1.0;
  for (int k = 1; k <= n; ++k) {
    float d = float(k) * stepD;
    float h = depthGrad(uv0 + Vp * d, gx, gy);
    if (d >= h) {
      hi = d;
      hHi = h;
      break;
    }
    lo = d;
    hLo = h;
  }
  if (lo == 0.0) return hHi;
  float a = hLo - lo, b = hi - hHi;
  return lo + (hi - lo) * a / (a + b);
}
)";

inline std::string fragmentShader(const Variant& v) {
  return std::string("#version 120\n#extension GL_ARB_shader_texture_lod : require\n") +
         "#extension GL_EXT_gpu_shader4 : require\n#define MODE " + std::to_string(v.mode) + "\n#define COUNT " +
         (v.count ? "1" : "0") + "\n#define PARALLAX " + (v.parallax ? "1" : "0") + "\n#define UNSHIFTED_LOOKUP " +
         (v.unshiftedLookup ? "1" : "0") + "\n#define CENTRE_LOOKUPS " + (v.centreLookups ? "1" : "0") +
         "\n#define PLAIN_TRACE " + (v.plainTrace ? "1" : "0") + R"(
uniform sampler2D albedo;     // RGBA8, mipmapped (the 2x2 averages)
uniform sampler2D heightTex;  // R = height, mipmapped (2x2 averages)
uniform sampler2D heightMax;  // R = the max-height pyramid
uniform vec3 eye, fwd, rightV, upV;
uniform vec2 viewport;        // the pass's size in pixels
uniform vec4 relief;          // (1 / tile, heightScale / tile, texture size, number of levels - 1)
uniform vec2 pomSteps;        // (fewest, most) linear steps
uniform float gradScale;      // M1/M2: scale of the gradients given to the albedo lookup (1; see PassOptions)
// accel stays a uniform: compiled in, it let LLVM round the ellipse's row
// ends differently in the two programs, and the images with and without the
// bound must match byte for byte.
uniform int accel;
const int mode = MODE, countMode = COUNT;
#if MODE < 0
uniform int probe;
#else
const int probe = 0;
#endif
uniform vec4 probeA, probeB;  // probe inputs
const float ALPHA = 2.0, MAXANISO = 16.0, EPS = 1.5 / 255.0;
int fetches = 0, excluded = 0;
#if COUNT
#define FETCH fetches++
#else
#define FETCH
#endif

)" + kMarchGLSL +
         ts::ewa::glsl(v.seedF) /* ellipse(), radii(): common/core/ewa.hpp */ + R"(
ivec2 wrapT(ivec2 t, int size) { return ivec2((t.x % size + size) % size, (t.y % size + size) % size); }
// Texel t of level L (wrapped).  texelFetch, or with centreLookups a
// filtered lookup at the texel's centre — the same value (at a texel centre
// of one level the bilinear weights are 1 and 0) but 40% slower on llvmpipe.
// softpipe (Mesa 22.3) needs the second: its texelFetch returns wrong texels
// when the lanes of a quad fetch different texels inside a loop (measured
// with the step-map probe: plainly hidden texels came out visible).
vec4 texelAt(sampler2D s, ivec2 t, int L, int size) {
#if CENTRE_LOOKUPS
  return texture2DLod(s, (vec2(wrapT(t, size)) + 0.5) / float(size), float(L));
#else
  return texelFetch2D(s, wrapT(t, size), L);
#endif
}
float depthTexel(ivec2 t, int L, int size) {
  FETCH;
  return 1.0 - texelAt(heightTex, t, L, size).r;
}
// Is texel t of level L hidden from the eye?  Vt = parallax per unit depth in
// texels of level L.  Mirrors pax::hiddenTexel.
// The smallest depth (highest relief) over texels lo..hi (inclusive, texel
// indices of level L, any span): the max-height pyramid read at the level
// where the box fits in 2 x 2 cells.  A lower bound, never above the truth.
float minDepthOver(vec2 lo, vec2 hi, int L) {
  int size = int(relief.z) >> L;
  int k = 0;
  float scale = 1.0;
  while (k < int(relief.w) - L && (floor(hi.x / scale) - floor(lo.x / scale) > 1.0 ||
                                   floor(hi.y / scale) - floor(lo.y / scale) > 1.0)) {
    k++;
    scale *= 2.0;
  }
  if (floor(hi.x / scale) - floor(lo.x / scale) > 1.0 || floor(hi.y / scale) - floor(lo.y / scale) > 1.0) return 0.0;
  int sizeK = max(1, size >> k);
  ivec2 b0 = ivec2(floor(lo / scale)), b1 = ivec2(floor(hi / scale));
  float top = 0.0;
  for (int by = b0.y; by <= b1.y; ++by)
    for (int bx = b0.x; bx <= b1.x; ++bx) {
      FETCH;
      top = max(top, texelAt(heightMax, ivec2(bx, by), L + k, sizeK).r);
    }
  return 1.0 - top;
}

// Is texel t of level L hidden from the eye?  Vt = parallax per unit depth in
// texels of level L; dmin = a lower bound of the depth over every texel the
// trace can read (0 when unknown).  Mirrors pax::hiddenTexel.
// The trace samples the ray at n points, half a texel apart: sample k at
// s = d0 k / n above the texel, over the texel under c - Vt s; hidden when
// that texel's depth is above the ray by more than EPS.
bool hiddenTexel(ivec2 t, int L, vec2 Vt, float dmin) {
  int size = int(relief.z) >> L;
  float d0 = depthTexel(t, L, size);
  if (d0 <= EPS) return false;
  vec2 c = vec2(t) + 0.5;
  int n = int(ceil(2.0 * d0 * length(Vt)));
#if PLAIN_TRACE
  // Every sample reads its texel (kept to test the trace below against).
  bool hidden = false;
  for (int k = 1; k <= n; ++k) {
    float s = d0 * float(k) / float(n);
    // With `accel`: once the ray is less than EPS below the highest relief
    // around, no later sample can find relief above it — stop (same answer).
    if (accel != 0 && d0 - s - EPS <= dmin) break;
    vec2 p = c - Vt * s;
    if (depthTexel(ivec2(floor(p)), L, size) < d0 - s - EPS) {
      hidden = true;
      break;
    }
  }
  return hidden;
#else
  // The same samples, but a texel is read once for a run of samples over it:
  // the ray only rises, so if the run's first sample does not find the
  // texel above the ray, its later ones cannot (and t itself, depth d0, is
  // never above it).  The inner loop advances to the first sample over
  // another texel without a lookup, so each pass of the outer loop is one
  // lookup for every lane: 37-40% fewer lookups than reading every sample,
  // the same answer (tested against PLAIN_TRACE, byte for byte), and M4/M5
  // 15-21% faster on llvmpipe (bench_parallax, plain-trace).  `accel`
  // is checked at the samples read only: it holds for every sample after
  // the first that meets it, so it stops the trace before the same read.
  ivec2 last = t;
  int k = 0;
  for (;;) {
    ivec2 T = last;
    float s = 0.0;
    while (T == last && k < n) {
      k++;
      s = d0 * float(k) / float(n);
      T = ivec2(floor(c - Vt * s));
    }
    if (T == last) return false;  // the last sample was over the texel read last
    if (accel != 0 && d0 - s - EPS <= dmin) return false;
    if (depthTexel(T, L, size) < d0 - s - EPS) return true;
    last = T;
  }
#endif
}

// EWA on level L: vis 0 = every texel, 1 = visible texels only, 2 = row walk.
vec3 ewaLevel(vec2 uvS, vec2 gx, vec2 gy, vec2 Vp, int L, int vis) {
  int size = int(relief.z) >> L;
  float s = float(size);
  vec4 e = ellipse(gx * s, gy * s, true);
  float A = e.x, B = e.y, C = e.z, F = e.w;
  vec2 c = uvS * s - 0.5;
  vec2 Vt = Vp * s;
  vec3 sum = vec3(0.0);
  float wsum = 0.0;
  float vr = )" +
         // The rows of A U^2 + B U V + C V^2 = F span V^2 <= 4 A F / (4 A C - B^2): sqrt(A) for the corrected F.
         (v.seedF ? "sqrt(4.0 * A * F / max(4.0 * A * C - B * B, 1e-30))" : "sqrt(A)") + R"(;
  int j0 = int(ceil(c.y - vr)), j1 = int(floor(c.y + vr));
  float dmin = 0.0;
  if (accel != 0 && vis != 0) {
    // Every texel a trace can read: the ellipse's box, swept toward the eye by
    // the parallax of the full depth.
    vec2 box = vec2(sqrt(C), vr);
    vec2 lo = floor(min(c - box, c - box - Vt)), hi = floor(max(c + box, c + box - Vt)) + 1.0;
    dmin = minDepthOver(lo, hi, L);
  }
  for (int j = j0; j <= j1; ++j) {
    float V = float(j) - c.y;
    float disc = B * B * V * V - 4.0 * A * (C * V * V - F);
    if (disc < 0.0) continue;
    float sq = sqrt(disc);
    int i0 = int(ceil(c.x + (-B * V - sq) / (2.0 * A))), i1 = int(floor(c.x + (-B * V + sq) / (2.0 * A)));
    int stop = i1 + 1;  // vis 2: where the walk from the left stopped
    for (int i = i0; i <= i1; ++i) {
      if (vis != 0 && hiddenTexel(ivec2(i, j), L, Vt, dmin)) {
        excluded++;
        stop = i;
        if (vis == 2) break;
        continue;
      }
      float U = float(i) - c.x;
      float w = exp(-ALPHA * min(1.0, (A * U * U + B * U * V + C * V * V) / F));
      FETCH;
      sum += w * texelAt(albedo, ivec2(i, j), L, size).rgb;
      wsum += w;
    }
    if (vis == 2 && stop <= i1) {
      int i = i1;
      for (; i > stop; --i) {
        if (hiddenTexel(ivec2(i, j), L, Vt, dmin)) break;
        float U = float(i) - c.x;
        float w = exp(-ALPHA * min(1.0, (A * U * U + B * U * V + C * V * V) / F));
        FETCH;
        sum += w * texelAt(albedo, ivec2(i, j), L, size).rgb;
        wsum += w;
      }
      excluded += i - stop;  // the hidden texel found (if any) and the untraced middle
    }
  }
  if (wsum <= 0.0) {  // everything hidden at this level: the texel under uvS
    FETCH;
    return texture2DLod(albedo, uvS, float(L)).rgb;
  }
  return sum / wsum;
}

vec3 ewa(vec2 uvS, vec2 gx, vec2 gy, vec2 Vp, int vis) {
  vec4 plain = ellipse(gx * relief.z, gy * relief.z, false);
  vec2 r = radii(plain);
  float lod = max(0.0, log2(max(max(r.y, r.x / MAXANISO), 1e-30)));
  lod = min(lod, relief.w);
  int L0 = int(floor(lod));
  float f = lod - float(L0);
  vec3 a = ewaLevel(uvS, gx, gy, Vp, L0, vis);
  if (f <= 0.0 || L0 >= int(relief.w)) return a;
  return mix(a, ewaLevel(uvS, gx, gy, Vp, L0 + 1, vis), f);
}

void main() {
  if (probe == 1) {  // the ellipse of gradients probeA = (Ux, Vx, Uy, Vy); probeB.x = reconstruction
    gl_FragColor = ellipse(probeA.xy, probeA.zw, probeB.x > 0.5);
    return;
  }
  if (probe == 2) {  // hiddenTexel of texel (probeA.xy + pixel) of level probeA.z, Vt = probeB.xy
    ivec2 t = ivec2(probeA.xy) + ivec2(gl_FragCoord.xy);
    int L = int(probeA.z);
    vec2 c = vec2(t) + 0.5;
    float dmin = accel != 0
        ? minDepthOver(floor(min(c, c - probeB.xy)) - 1.0, floor(max(c, c - probeB.xy)) + 1.0, L) : 0.0;
    gl_FragColor = vec4(hiddenTexel(t, L, probeB.xy, dmin) ? 1.0 : 0.0, float(fetches) / 255.0, 0.0, 1.0);
    return;
  }
  vec2 p = gl_FragCoord.xy;
  vec3 d = rayDir(p);
  vec2 uv0 = topUV(d);
  vec2 gx = topUV(rayDir(p + vec2(0.5, 0.0))) - topUV(rayDir(p - vec2(0.5, 0.0)));
  vec2 gy = topUV(rayDir(p + vec2(0.0, 0.5))) - topUV(rayDir(p - vec2(0.0, 0.5)));
  vec2 Vp = d.xy / (-d.z) * relief.y;
#if PARALLAX
  float depth = pom(uv0, Vp, gx, gy, abs(normalize(d).z));
#else
  float depth = 0.0;
#endif
#if UNSHIFTED_LOOKUP
  // Benchmark only: what the filters cost where the lookup coordinate is
  // smooth (no jumps at occluding edges); the depth is kept alive below.
  vec2 uvS = uv0;
#else
  vec2 uvS = uv0 + Vp * depth;
#endif
  vec3 col;
  if (mode == 0) {
    FETCH;
    col = texture2D(albedo, uvS).rgb;
  } else if (mode == 1 || mode == 2) {
    FETCH;
    col = texture2DGradARB(albedo, uvS, gx * gradScale, gy * gradScale).rgb;
  } else {
    col = ewa(uvS, gx, gy, Vp, mode - 3);
  }
#if UNSHIFTED_LOOKUP
  col += depth * 1e-6;
#endif
  if (countMode != 0)
    gl_FragColor = vec4(float(fetches % 256), float((fetches / 256) % 256), float(excluded % 256),
                        float((excluded / 256) % 256)) / 255.0;
  else
    gl_FragColor = vec4(col, 1.0);
}
)";
}

// The textures of one relief map, described for Renderer::texture (the
// suite's one upload path): albedo, heights and the max-height pyramid, every
// level uploaded from the CPU chains (the same on every driver).
struct ReliefTextures {
  std::string name;
  ts::TextureDesc albedo, height, heightMax;
  int levels = 0;
};

struct PassOptions {
  bool count = false;    // write lookups / excluded texels instead of the colour
  bool accel = true;     // max-height pyramid skip in the visibility trace
  bool parallax = true;  // false: no parallax march (what the rest of a mode costs; benchmark only)
  // The march runs but the albedo is read at the unshifted coordinate: what
  // the jumps of the shifted coordinate at occluding edges cost a filter
  // that takes its footprint from the coordinate (benchmark only).
  bool unshiftedLookup = false;
  // The visibility trace reads the texel of every sample instead of once per
  // run of samples over the same texel: the same answer, more lookups (what
  // the tests and the benchmark compare against).
  bool plainTrace = false;
  float minSteps = 12, maxSteps = 40;
  // Texels read as lookups at their centres instead of texelFetch: -1 = only
  // on softpipe (whose texelFetch misbehaves in divergent loops), 0/1 = force.
  int centreLookups = -1;
  // M1/M2 only: the gradients handed to the albedo's textureGrad are scaled
  // by this.  A filter that uses them must change its answer at x4 (the
  // trilinear one does); one that does not, does not (Table::gradientTest).
  float gradScale = 1;
  bool seedF = false;  // EWA modes: seed 003's F = (Ux Vy + Uy Vx)^2 (common/core/ewa.hpp, glsl(true))
};

inline bool isSoftpipe() { return ts::gl::rendererString().find("softpipe") != std::string::npos; }

// Everything the demo, the tests and the benchmark need on the GL side.
// Made per renderer (Renderer::attachment<ReliefGL>()), so its GL objects
// go with the renderer, while their context is current.
// The camera as kMarchGLSL reads it: eye, fwd, rightV, upV (rayDir's frame) and the pass's viewport.
inline void setCameraUniforms(GLuint prog, const Camera& cam) {
  auto v3 = [&](const char* n, glm::dvec3 v) {
    glUniform3f(glGetUniformLocation(prog, n), float(v.x), float(v.y), float(v.z));
  };
  v3("eye", cam.eye());
  v3("fwd", cam.forward());
  v3("rightV", cam.right());
  v3("upV", cam.up());
  glUniform2f(glGetUniformLocation(prog, "viewport"), float(cam.width), float(cam.height));
}

class ReliefGL final : public ts::Renderer::Attachment {
 public:
  explicit ReliefGL(ts::Renderer& r) : r_(r) {}
  ~ReliefGL() override { release(); }
  ReliefGL(const ReliefGL&) = delete;
  ReliefGL& operator=(const ReliefGL&) = delete;
  // Drops the GL objects (the context must be current): the next pass makes
  // them again, so that a recorded pass (ts::recordRender) shows how.
  void release() {
    for (auto& t : textures_)
      for (const ts::TextureDesc* d : {&t.albedo, &t.height, &t.heightMax}) r_.forgetTexture(*d);
    target_.free();
  }

  const ReliefTextures& textures(const Relief& rel) {
    for (auto& t : textures_)
      if (t.name == rel.name) return t;
    ReliefTextures t;
    t.name = rel.name;
    t.levels = int(rel.albedo.size());
    auto describe = [&](const char* map, const std::vector<ts::Image>& chain, GLenum minFilter) {
      ts::TextureDesc d;
      d.name = "relief_" + rel.name + "_" + map;
      d.image = std::make_shared<ts::Image>(chain.front());
      d.mipmaps = true;
      d.mipLevels = std::make_shared<std::vector<ts::Image>>(chain);
      d.minFilter = minFilter;
      d.magFilter = minFilter == GL_NEAREST_MIPMAP_NEAREST ? GL_NEAREST : GL_LINEAR;
      d.wrapS = d.wrapT = GL_REPEAT;
      return d;
    };
    t.albedo = describe("albedo", rel.albedo, GL_LINEAR_MIPMAP_LINEAR);
    t.height = describe("height", rel.height, GL_LINEAR_MIPMAP_LINEAR);
    t.heightMax = describe("height_max", rel.heightMax, GL_NEAREST_MIPMAP_NEAREST);
    textures_.push_back(t);
    return textures_.back();
  }

  // The live view: `left` over the whole camera, or with right >= 0 `left` on
  // the left half and `right` on the right half (split-screen compare: one
  // frame's work, each pixel drawn once), into the passes' own RGBA8 target
  // texture (GL_NEAREST), returned; valid until the next draw.  The previous
  // framebuffer is bound again on return.
  GLuint drawLive(const Camera& cam, const Relief& rel, int left, int right, const PassOptions& o) {
    ts::RenderTarget::Bind bound(target(cam.width, cam.height, false));
    if (right < 0) {
      glDisable(GL_SCISSOR_TEST);
      pass(cam, rel, left, o);
    } else {
      glEnable(GL_SCISSOR_TEST);
      glScissor(0, 0, cam.width / 2, cam.height);
      pass(cam, rel, left, o);
      glScissor(cam.width / 2, 0, cam.width - cam.width / 2, cam.height);
      pass(cam, rel, right, o);
      glDisable(GL_SCISSOR_TEST);
    }
    return target_.colourTexture();
  }

 private:
  // One mode over the bound target's viewport (and scissor, if enabled).
  void pass(const Camera& cam, const Relief& rel, int mode, const PassOptions& o) {
    if (mode < 0 || mode >= kShaderModes)
      throw ts::Error("no shader for mode " + std::to_string(mode), ts::kExitFailure);
    Variant v;
    v.mode = mode;
    v.count = o.count;
    v.parallax = o.parallax;
    v.unshiftedLookup = o.unshiftedLookup;
    v.plainTrace = o.plainTrace;
    v.seedF = o.seedF;
    v.centreLookups = o.centreLookups < 0 ? isSoftpipe() : o.centreLookups != 0;
    GLuint prog = program(v);
    glUseProgram(prog);
    setCamera(prog, cam);
    const ReliefTextures& t = textures(rel);
    bind(prog, t, mode == kAniso16 ? 16.0f : 1.0f);
    glUniform4f(glGetUniformLocation(prog, "relief"), float(1.0 / cam.tile), float(cam.heightScale / cam.tile),
                float(kTexSize), float(t.levels - 1));
    glUniform2f(glGetUniformLocation(prog, "pomSteps"), o.minSteps, o.maxSteps);
    glUniform1f(glGetUniformLocation(prog, "gradScale"), o.gradScale);
    glUniform1i(glGetUniformLocation(prog, "accel"), o.accel ? 1 : 0);
    quad();
    glUseProgram(0);
    ts::gl::check("drawing a parallax pass");
  }

 public:
  // One mode drawn into an RGBA8 target of the camera's size and read back
  // (row 0 = top).
  ts::Image render(const Camera& cam, const Relief& rel, int mode, const PassOptions& o = {}) {
    ts::RenderTarget::Bind bound(target(cam.width, cam.height, false));
    glDisable(GL_SCISSOR_TEST);
    pass(cam, rel, mode, o);
    return target_.readRGBA8();
  }
  // One mode drawn into that target, nothing read back (bench_parallax times
  // it, each call finished with glFinish).
  void draw(const Camera& cam, const Relief& rel, int mode, const PassOptions& o = {}) {
    ts::RenderTarget::Bind bound(target(cam.width, cam.height, false));
    glDisable(GL_SCISSOR_TEST);
    pass(cam, rel, mode, o);
  }
  // Milliseconds per frame: the median of `runs` draws, each finished.
  double timeMs(const Camera& cam, const Relief& rel, int mode, int runs, const PassOptions& o = {}) {
    ts::RenderTarget::Bind bound(target(cam.width, cam.height, false));
    glDisable(GL_SCISSOR_TEST);
    pass(cam, rel, mode, o);  // warm: compile, upload, first JIT
    glFinish();
    std::vector<double> ms;
    for (int k = 0; k < runs; ++k) {
      auto t0 = std::chrono::steady_clock::now();
      pass(cam, rel, mode, o);
      glFinish();
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
  }

  // Probe 1: the shader's ellipse of (Ux, Vx, Uy, Vy) -> (A, B, C, F).
  glm::dvec4 probeEllipse(glm::dvec4 g, bool reconstruction) {
    std::vector<float> v = probePass(1, 1, g, glm::dvec4(reconstruction ? 1 : 0, 0, 0, 0), nullptr, 0);
    return {v[0], v[1], v[2], v[3]};
  }
  // Probe 2: hiddenTexel for texels first..first + (w, h) of level L of a map;
  // returns 1/0 per texel, row-major from `first` (j rows, i columns).
  std::vector<int> probeHidden(const Relief& rel, glm::ivec2 first, int w, int h, int L, glm::dvec2 Vt, bool accel,
                               std::vector<int>* lookups = nullptr) {
    std::vector<float> v = probePass(w, h, glm::dvec4(first.x, first.y, L, 0), glm::dvec4(Vt, 0, 0), &rel, accel);
    std::vector<int> out(size_t(w) * size_t(h));
    if (lookups) lookups->resize(out.size());
    for (size_t k = 0; k < out.size(); ++k) {
      out[k] = v[k * 4] > 0.5f;
      if (lookups) (*lookups)[k] = int(std::lround(v[k * 4 + 1] * 255.0f));
    }
    return out;
  }

 private:
  GLuint program(const Variant& v) { return r_.program(v.key(), {kSourceFile, vertexShader(), fragmentShader(v)}); }
  void setCamera(GLuint prog, const Camera& cam) { setCameraUniforms(prog, cam); }
  void bind(GLuint prog, const ReliefTextures& t, float aniso) {
    const ts::TextureDesc* maps[3] = {&t.albedo, &t.height, &t.heightMax};
    const char* names[3] = {"albedo", "heightTex", "heightMax"};
    GLuint albedo = 0;
    for (int k = 0; k < 3; ++k) {
      glActiveTexture(GLenum(GL_TEXTURE0 + k));
      const GLuint id = r_.texture(*maps[k]);  // uploads once, binds, sets the filters
      if (k == 0) albedo = id;
      glUniform1i(glGetUniformLocation(prog, names[k]), k);
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, albedo);
    if (ts::gl::hasAnisotropicFiltering()) glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, aniso);
  }
  void quad() {  // the caller sets the scissor test
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBegin(GL_TRIANGLES);
    const float c[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    for (const auto& v : c) glVertex2f(v[0], v[1]);
    glEnd();
  }
  // The passes' target: colour only, RGBA8 (pictures) or RGBA32F (probes),
  // a texture so that the live view can show it; remade when that changes.
  ts::RenderTarget& target(int w, int h, bool floatTarget) {
    target_.make({w, h, floatTarget ? ts::TargetFormat::kRGBA32F : ts::TargetFormat::kRGBA8, ts::TargetFormat::kNoDepth,
                  true},
                 "a parallax pass");
    return target_;
  }
  std::vector<float> probePass(int w, int h, glm::dvec4 a, glm::dvec4 b, const Relief* rel, bool accel) {
    ts::RenderTarget::Bind bound(target(w, h, true));
    glDisable(GL_SCISSOR_TEST);
    Variant pv;
    pv.mode = -1;     // the probe program: `probe` picks the probe
    pv.count = true;  // probe 2 reports the lookups of each trace
    pv.centreLookups = isSoftpipe();
    GLuint prog = program(pv);
    glUseProgram(prog);
    Camera cam;
    setCamera(prog, cam);
    if (rel) {
      const ReliefTextures& t = textures(*rel);
      bind(prog, t, 1.0f);
      glUniform4f(glGetUniformLocation(prog, "relief"), 0.5f, 0.03f, float(kTexSize), float(t.levels - 1));
    }
    glUniform1i(glGetUniformLocation(prog, "probe"), rel ? 2 : 1);
    glUniform1i(glGetUniformLocation(prog, "accel"), accel ? 1 : 0);
    glUniform4f(glGetUniformLocation(prog, "probeA"), float(a.x), float(a.y), float(a.z), float(a.w));
    glUniform4f(glGetUniformLocation(prog, "probeB"), float(b.x), float(b.y), float(b.z), float(b.w));
    quad();
    glUseProgram(0);
    std::vector<float> v = target_.readFloat();
    ts::gl::check("a parallax probe pass");
    return v;
  }

  ts::Renderer& r_;
  std::vector<ReliefTextures> textures_;
  ts::RenderTarget target_;
};
}  // namespace pax
