// demos/mipmap_popping/mipmap_popping_sweep.hpp — the demo's pictures as Frame data and its
// measurement passes (GL renders through Renderer::renderOffscreen at fixed
// sizes, so the numbers do not depend on the window).  Shared by the demo
// and its tests.
//
//  * Popping: a grid of 32 x 32 panels, each the facing plane at one
//    distance of a sweep (log2 distance -1 .. 7.5 in steps of 1/16), drawn
//    with the mip-level-colours texture.  The LOD is uniform over each panel
//    (mipmap_popping_math.hpp, 2), so its mean colour says which level(s) GL used; the
//    popping measure is the largest jump of that mean between neighbours.
//  * Far-field error: a ground plane seen at a slant (384 x 192), rendered
//    with each filter and compared with a supersampled reference: the same
//    view rendered by GL at 8x8 the resolution with GL_NEAREST on level 0
//    only, box-downsampled on the CPU.  Only the far field counts: pixels
//    whose analytic LOD is 1.5 .. 5 (the long side of the footprint covers
//    2.8 to 32 texels while the short side covers far fewer: the mipmap
//    filters must blur across to match the long side).  The reference's
//    samples are 1/8 pixel apart, so it resolves single texels up to LOD 3
//    and the texture's 32-texel cells up to LOD 8; the plane ends 200 units
//    away (about LOD 13), where llvmpipe's EWA would otherwise spend a
//    second per frame on footprints thousands of texels long.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <string>
#include <vector>

#include "common/gl/render.hpp"
#include "common/core/textures.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/core/user_texture.hpp"
#include "mipmap_popping_math.hpp"

namespace mipmap {
constexpr double kMinLog2 = -1.0, kMaxLog2 = 7.5;  // the distance range (log2)
}

namespace mipmap {
using namespace mipmap;

// How the texture is sampled: the demo's state that matters to a pass.
struct Look {
  int filter = kNearestMipNearest;
  int anisotropy = 16;
  float lodBias = 0;
  int texture = 0;  // 0 labelled grid, 1 checkerboard
  bool linearLight = false;
  const ts::UserTexture* picture = nullptr;  // --texture FILE: its chain replaces the pattern's
  ts::OrbitCamera orbit{};                   // --yaw --pitch --zoom: the slanted plane's camera
};
inline Camera slantCamera(int w, int h, const ts::OrbitCamera& o) {
  return mipmap::slantCamera(w, h, o.yaw, o.pitch, o.zoom);
}

// The texture (256 x 256, the book's 2x2 mip chain) with the look's filter.
inline ts::TextureDesc texture(const Look& l) {
  ts::TextureDesc t = l.texture == 0 ? ts::labelledGrid(kTexels, 8) : ts::checkerboard(kTexels, 8);
  t.mipmaps = true;
  t.linearLightMips = l.linearLight;
  applyFilter(t, l.filter, l.anisotropy, l.lodBias);
  return l.picture ? l.picture->orDefault(t) : t;
}
// Level k filled with ts::mipLevelColour(k).
inline ts::TextureDesc colouredTexture(const Look& l) {
  ts::TextureDesc t = ts::mipLevelColours(kTexels);
  applyFilter(t, l.filter, l.anisotropy, l.lodBias);
  return t;
}

// The facing plane at distance d, x in [x0, x1], y in [-kPlaneHalf,
// kPlaneHalf]: (s, t) = (x, y) world units (one texture repeat per unit).
inline ts::Batch facingBatch(double d, int texture, double x0, double x1) {
  ts::Batch b;
  b.role = "plane";
  b.texture = texture;
  const float z = float(-d), y0 = float(-kPlaneHalf), y1 = float(kPlaneHalf);
  const glm::vec2 c[4] = {{float(x0), y0}, {float(x1), y0}, {float(x1), y1}, {float(x0), y1}};
  // (s, t) = (x, y): glTexCoord4f(x, y, 0, 1) in Renderer::draw (common/gl/render.cpp)
  for (int k : {0, 1, 2, 0, 2, 3}) b.vertices.push_back({{c[k], z}, {c[k], 0, 1}, glm::vec4(1.0f)});
  return b;
}

// --- popping ---------------------------------------------------------------
constexpr int kCell = 32, kColumns = 16;

// The facing plane as the probe pass draws it: the same plane (same (s, t)
// per point, so the same LOD) cut to a quad whose two triangles share an
// edge that stays at least 22 pixels from the kCell x kCell probe around
// the view axis.  (softpipe computes the LOD of the 2x2 quads straddling a
// triangle edge from the neighbouring triangle's helper pixels: up to a
// fifth of a level off along the diagonal.  Keeping the edge out of the
// probe keeps that out of the measurement.)  Extent in pixels: x -24 .. 88,
// y -88 .. 24; the shared diagonal is the line y = x - 64.
inline ts::Batch probeBatch(double d, int texture) {
  const double k = d / kFocalPixels;  // world units per pixel at distance d
  ts::Batch b;
  b.role = "probe_plane";
  b.texture = texture;
  const float z = float(-d);
  const glm::vec2 c[4] = {{float(-24 * k), float(-88 * k)},
                          {float(88 * k), float(-88 * k)},
                          {float(88 * k), float(24 * k)},
                          {float(-24 * k), float(24 * k)}};
  // (s, t) = (x, y): glTexCoord4f(x, y, 0, 1) in Renderer::draw (common/gl/render.cpp)
  for (int i : {0, 1, 2, 0, 2, 3}) b.vertices.push_back({{c[i], z}, {c[i], 0, 1}, glm::vec4(1.0f)});
  return b;
}
constexpr double kSweepStep = 1.0 / 16;
inline std::vector<double> sweepLods(double lo = kMinLog2, double hi = kMaxLog2, double step = kSweepStep) {
  std::vector<double> v;
  for (int k = 0; lo + k * step <= hi + 1e-9; ++k) v.push_back(lo + k * step);
  return v;
}
// One frame: a kCell x kCell panel per distance, coloured levels (or the
// texture).
inline ts::Frame sweepFrame(const Look& l, const std::vector<double>& lods, bool coloured = true) {
  ts::Frame f;
  int n = int(lods.size()), rows = (n + kColumns - 1) / kColumns;
  f.width = kColumns * kCell;
  f.height = std::max(1, rows) * kCell;
  f.clearColor = {0, 0, 0, 1};
  int t = f.addTexture(coloured ? colouredTexture(l) : texture(l));
  for (int k = 0; k < n; ++k) {
    ts::Panel p;
    p.id = "sweep_" + std::to_string(k);
    p.viewport = {(k % kColumns) * kCell, (k / kColumns) * kCell, kCell, kCell};
    double d = facingDistance(lods[size_t(k)]);
    Camera cam = facingCamera(kCell, kCell, d);
    p.projection = cam.projection(kCell, kCell);
    p.modelview = cam.modelview();
    p.batches.push_back(probeBatch(d, t));
    f.panels.push_back(p);
  }
  return f;
}
inline std::vector<Mean> probeSweep(ts::Renderer& r, const Look& l, const std::vector<double>& lods,
                                    bool coloured = true) {
  ts::Frame f = sweepFrame(l, lods, coloured);
  ts::Image img = r.renderOffscreen(f);
  std::vector<Mean> out;
  for (const auto& p : f.panels) out.push_back(meanOf(img, p.viewport));
  return out;
}
inline Mean probeAt(ts::Renderer& r, const Look& l, double log2Distance) {
  return probeSweep(r, l, {log2Distance}).front();
}

// --- the slanted plane -----------------------------------------------------
constexpr int kSlantW = 384, kSlantH = 192, kSuper = 8;  // referenceFS() hard-codes 8
constexpr double kFarLodLo = 1.5, kFarLodHi = 5.0;
constexpr double kStripRatio = 2;  // strips at depth 0, 0.5, 1, 2, 4, ...

enum SlantKind { kTextured, kColoured, kReferenceProgram };

// GLSL 1.20 (softpipe's GL 3.3 compatibility context runs it): k x k samples
// per pixel, each mapped exactly to (s, t) by the homography of the ground
// plane, looked up with GL_NEAREST in level 0, averaged.
inline const char* referenceVS() {
  return R"(#version 120
void main() { gl_Position = ftransform(); })";
}
inline const char* referenceFS() {
  // kSuper = 8 samples per side, a constant so the loops unroll.
  return R"(#version 120
uniform sampler2D tex;
uniform vec4 h0, h1, h2;    // (s q, t q, q) = H (x, y, 1), (x, y) panel pixels, y up
uniform vec4 origin;        // the panel's GL origin (x, y)
uniform vec4 extent;        // the plane: |s| <= x, 0 <= t <= y
uniform vec4 background;
void main() {
  vec2 p = floor(gl_FragCoord.xy - origin.xy);
  vec4 sum = vec4(0.0);
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 8; ++i) {
      vec3 q = vec3(p + (vec2(float(i), float(j)) + 0.5) / 8.0, 1.0);
      vec3 h = vec3(dot(h0.xyz, q), dot(h1.xyz, q), dot(h2.xyz, q));
      vec2 st = h.xy / max(h.z, 1e-30);
      bool on = h.z > 0.0 && abs(st.x) <= extent.x && st.y >= 0.0 && st.y <= extent.y;
      sum += on ? texture2D(tex, st) : background;
    }
  }
  gl_FragColor = sum / 64.0;
})";
}

// The homography (panel pixel x, y, 1) -> (s q, t q, q) of the ground plane
// (common/core/slant_plane.hpp).
using ts::slant::groundHomography;

// The ground plane in panel p (its viewport set), as strips at z = 0, -1, -2,
// -4, ... so no triangle spans the whole depth range.
inline void addSlant(ts::Frame& f, ts::Panel& p, const Look& l, SlantKind kind, int frameHeight) {
  Camera cam = slantCamera(p.viewport.w, p.viewport.h, l.orbit);
  p.projection = cam.projection(p.viewport.w, p.viewport.h);
  p.modelview = cam.modelview();
  p.clear = true;
  p.clearColor = {0.30f, 0.36f, 0.45f, 1.0f};
  ts::Batch b;
  b.role = kind == kReferenceProgram ? "ground_reference" : "ground";
  ts::TextureDesc t = kind == kColoured ? colouredTexture(l) : texture(l);
  if (kind == kReferenceProgram) {
    t.mipmaps = false;
    t.minFilter = t.magFilter = GL_NEAREST;
    t.maxAnisotropy = 1;
    t.lodBias = 0;
  }
  b.texture = f.addTexture(t);
  // Trapezoids just wider than the 60 degree view (half-width 0.6 (|z| + 1)
  // + 0.5 at depth |z|): no vertex lies far outside the frustum, so neither
  // GL's clipper nor the CPU reference has to interpolate over huge
  // off-screen triangles.
  std::vector<double> zs{0.0};
  for (double z = 0.5; z < kGroundDepth; z *= kStripRatio) zs.push_back(-z);
  zs.push_back(-kGroundDepth);
  auto half = [](double z) { return float(std::min(kGroundHalfWidth, 0.6 * (std::abs(z) + 1) + 0.5)); };
  for (size_t k = 0; k + 1 < zs.size(); ++k) {
    float z0 = float(zs[k]), z1 = float(zs[k + 1]), w0 = half(zs[k]), w1 = half(zs[k + 1]);
    const glm::vec3 c[4] = {{-w0, 0, z0}, {w0, 0, z0}, {w1, 0, z1}, {-w1, 0, z1}};
    // (s, t) = (x, -z): glTexCoord4f(x, -z, 0, 1) in Renderer::draw (the reference's shader ignores them)
    for (int i : {0, 1, 2, 0, 2, 3}) b.vertices.push_back({c[i], {c[i].x, -c[i].z, 0, 1}, glm::vec4(1.0f)});
  }
  if (kind == kReferenceProgram) {
    b.program = "supersampled_reference";
    glm::dmat3 H = groundHomography(cam);  // glm: H[col][row]
    auto row = [&](int i) { return glm::vec4(float(H[0][i]), float(H[1][i]), float(H[2][i]), 0.0f); };
    b.uniforms = {{"h0", row(0)},
                  {"h1", row(1)},
                  {"h2", row(2)},
                  {"origin", {float(p.viewport.x), float(frameHeight - p.viewport.y - p.viewport.h), float(kSuper), 0}},
                  {"extent", {float(kGroundHalfWidth), float(kGroundDepth), 0, 0}},
                  {"background", p.clearColor}};
    bool have = false;
    for (const auto& pr : f.programs) have |= pr.first == b.program;
    if (!have)
      f.programs.push_back(
          {b.program, {"demos/mipmap_popping/mipmap_popping_sweep.hpp", referenceVS(), referenceFS()}});
  }
  p.batches.push_back(b);
}

// The far-field mask of a w x h slant panel: analytic LOD in [lo, hi].
inline std::vector<char> farField(int w, int h, double lo = kFarLodLo, double hi = kFarLodHi,
                                  const ts::OrbitCamera& orbit = {}) {
  Camera cam = slantCamera(w, h, orbit);
  Plane ground = groundPlane();
  std::vector<char> mask(size_t(w) * size_t(h), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      glm::dvec2 ab;
      Jacobian j;
      // Image row y (top-down) is GL row h - 1 - y.
      if (!planeAt(cam, ground, x + 0.5, h - y - 0.5, &ab, &j)) continue;
      if (std::abs(ab.x) > kGroundHalfWidth || ab.y > kGroundDepth) continue;
      double lod = std::log2(rhoExact(j));
      mask[size_t(y) * size_t(w) + size_t(x)] = lod >= lo && lod <= hi;
    }
  return mask;
}

// One slant panel filling a w x h frame.
inline ts::Frame slantFrame(const Look& l, SlantKind kind, int w, int h) {
  ts::Frame f;
  f.width = w, f.height = h;
  ts::Panel p;
  p.id = "slant";
  p.viewport = {0, 0, w, h};
  addSlant(f, p, l, kind, h);
  f.panels.push_back(p);
  return f;
}
// The supersampled reference: GL at k x k the size, GL_NEAREST on level 0,
// box-downsampled.
inline ts::Image slantReference(ts::Renderer& r, const Look& l, int w = kSlantW, int h = kSlantH, int k = kSuper) {
  Look ref = l;
  ref.filter = kNearest;
  ts::Frame f = slantFrame(ref, kTextured, w * k, h * k);
  f.textures[0].mipmaps = false;  // level 0 only
  f.textures[0].lodBias = 0;
  return boxDownsample(r.renderOffscreen(f), k);
}
struct SlantErrors {
  double error[kFilterCount] = {};
  long pixels = 0;
};
inline SlantErrors slantErrors(ts::Renderer& r, const Look& l) {
  SlantErrors e;
  ts::Image ref = slantReference(r, l);
  std::vector<char> mask = farField(kSlantW, kSlantH, kFarLodLo, kFarLodHi, l.orbit);
  for (int fl = 0; fl < kFilterCount; ++fl) {
    Look lk = l;
    lk.filter = fl;
    ts::Image img = r.renderOffscreen(slantFrame(lk, kTextured, kSlantW, kSlantH));
    e.error[fl] = rmsError(img, ref, mask, &e.pixels);
  }
  return e;
}
}  // namespace mipmap
