// demos/wrap_modes/wrap_modes_gl.hpp — the measurement passes of
// demos/wrap_modes: small frames rendered offscreen with GL and read back,
// each compared with the formulas of wrap_modes_math.hpp.  Every pass draws with
// ts::Renderer (common/gl/render.cpp), the same calls as the figures.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "common/gl/render.hpp"
#include "common/core/textures.hpp"
#include "wrap_modes_math.hpp"

namespace wrap {
// A texel-index texture of any size (a crop of the square one): the NPOT
// case.  Border (1,1,1,1) decodes to index 4095, which no texel has.
inline ts::TextureDesc indexTexture(int w, int h, GLenum mode) {
  ts::TextureDesc t = ts::texelIndexTexture(std::max(w, h));
  auto img = std::make_shared<ts::Image>(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) img->set(i, j, t.image->at(i, j));
  t.image = img;
  t.params = {{"width", std::to_string(w)}, {"height", std::to_string(h)}};
  t.wrapS = t.wrapT = mode;
  t.border = glm::vec4(1.0f);
  return t;
}

// A quad over `vp` (ortho 0..1) whose corners carry (s,t) from lo to hi.
inline ts::Batch stQuad(glm::vec2 p0, glm::vec2 p1, glm::dvec2 lo, glm::dvec2 hi, int tex) {
  ts::Batch b;
  b.role = "surface";
  b.texture = tex;
  for (int i : {0, 1, 2, 0, 2, 3}) {
    glm::vec2 c(i == 1 || i == 2, i >= 2);
    b.vertices.push_back({{glm::mix(p0, p1, c), 0},
                          {glm::mix(lo.x, hi.x, double(c.x)), glm::mix(lo.y, hi.y, double(c.y)), 0, 1},
                          {1, 1, 1, 1}});
  }
  return b;
}

inline ts::Panel pixelPanel(int w, int h, float sx, float sy) {
  ts::Panel p;
  p.viewport = {0, 0, w, h};
  p.projection = glm::ortho(0.0f, sx, 0.0f, sy, -1.0f, 1.0f);
  return p;
}

// Texel-index renders of `mode` on a w x h texture over [lo, hi]^2: pass 1,
// the quad at two pixels per texel (centres a quarter texel inside); pass 2,
// one pixel per integer s, each a quad of constant s = k (t = 0.3, inside a
// texel for the sizes used).  Returns the pixels whose texel differs from
// the formula; with `seed`, counts where seed 002's MIRROR picks another
// texel than GL did at the integers.
struct SeedCount {
  int differs = 0, integers = 0;
};
inline int texelMismatches(ts::Renderer& r, GLenum mode, int w, int h, int lo, int hi, SeedCount* seed) {
  const int n = hi - lo;
  auto decoded = [](ts::Rgba c) {
    int i, j;
    ts::decodeTexelIndex(c, &i, &j);  // the border (1,1,1,1) decodes to 4095
    return glm::ivec2(i == 4095 ? wrap::kBorder : i, j == 4095 ? wrap::kBorder : j);
  };
  int bad = 0;
  {
    ts::Frame f;
    f.width = 2 * n * w, f.height = 2 * n * h;
    int tex = f.addTexture(indexTexture(w, h, mode));
    ts::Panel p = pixelPanel(f.width, f.height, 1, 1);
    p.batches.push_back(stQuad({0, 0}, {1, 1}, {lo, lo}, {hi, hi}, tex));
    f.panels.push_back(p);
    ts::Image img = r.renderOffscreen(f);
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) {
        double s = lo + n * (x + 0.5) / f.width, t = lo + n * (f.height - y - 0.5) / f.height;
        glm::ivec2 want(wrap::nearestTexel(mode, s, w), wrap::nearestTexel(mode, t, h));
        glm::ivec2 got = decoded(img.at(x, y));
        if (want.x == wrap::kBorder || want.y == wrap::kBorder) want = glm::ivec2(wrap::kBorder);
        if (got.x == wrap::kBorder || got.y == wrap::kBorder) got = glm::ivec2(wrap::kBorder);
        bad += got != want;
      }
  }
  ts::Frame f;
  f.width = n + 1, f.height = 1;
  int tex = f.addTexture(indexTexture(w, h, mode));
  ts::Panel p = pixelPanel(f.width, 1, float(f.width), 1);
  for (int k = 0; k <= n; ++k) p.batches.push_back(stQuad({k, 0}, {k + 1, 1}, {lo + k, 0.3}, {lo + k, 0.3}, tex));
  f.panels.push_back(p);
  ts::Image img = r.renderOffscreen(f);
  for (int k = 0; k <= n; ++k) {
    int got = decoded(img.at(k, 0)).x;
    bad += got != wrap::nearestTexel(mode, lo + k, w);
    if (seed) {
      ++seed->integers;
      seed->differs += got != wrap::seedMirrorTexel(lo + k, w);
    }
  }
  return bad;
}

// The border colour's share (percent) in GL_LINEAR lookups at the probes:
// a white 8x8 texture, black border, one pixel per probe s at t = 1/2;
// share = 1 - red.
constexpr std::array<double, 4> kEdgeProbes = {-0.25, 0.0, 1.0, 1.25};
inline std::array<double, 4> borderPercent(ts::Renderer& r, GLenum mode) {
  ts::Frame f;
  f.width = 4, f.height = 1;
  ts::TextureDesc white = ts::checkerboard(8, 1, {255, 255, 255, 255}, {255, 255, 255, 255});
  white.wrapS = white.wrapT = mode;
  white.border = {0, 0, 0, 1};
  int tex = f.addTexture(white);
  ts::Panel p = pixelPanel(4, 1, 4, 1);
  for (int k = 0; k < 4; ++k)
    p.batches.push_back(stQuad({k, 0}, {k + 1, 1}, {kEdgeProbes[size_t(k)], 0.5}, {kEdgeProbes[size_t(k)], 0.5}, tex));
  f.panels.push_back(p);
  ts::Image img = r.renderOffscreen(f);
  std::array<double, 4> out{};
  for (int k = 0; k < 4; ++k) out[size_t(k)] = 100.0 * (1.0 - img.at(k, 0).r / 255.0);
  return out;
}

// The texture matrix: a 64x64 texel-index render of the unit quad with M,
// probes on a 9x9 grid, against M applied on the CPU (GL_REPEAT); probes
// within a twentieth of a texel of an edge are left out.
inline int matrixMismatches(ts::Renderer& r, const glm::mat4& m, int* checked) {
  const int N = 64, W = 72;
  ts::Frame f;
  f.width = f.height = W;
  ts::TextureDesc t = ts::texelIndexTexture(N);
  t.wrapS = t.wrapT = GL_REPEAT;
  int tex = f.addTexture(t);
  ts::Panel p = pixelPanel(W, W, 1, 1);
  ts::Batch b = stQuad({0, 0}, {1, 1}, {0, 0}, {1, 1}, tex);
  b.textureMatrix = m;
  p.batches.push_back(b);
  f.panels.push_back(p);
  ts::Image img = r.renderOffscreen(f);
  int bad = 0;
  *checked = 0;
  for (int py = 4; py < W; py += 8)
    for (int px = 4; px < W; px += 8) {
      glm::dvec2 st = wrap::transformST(m, (px + 0.5) / W, (W - py - 0.5) / W), u = st * double(N);
      if (std::abs(u.x - std::round(u.x)) < 0.05 || std::abs(u.y - std::round(u.y)) < 0.05) continue;
      int i, j;
      ts::decodeTexelIndex(img.at(px, py), &i, &j);
      ++*checked;
      bad += i != wrap::nearestTexel(GL_REPEAT, st.x, N) || j != wrap::nearestTexel(GL_REPEAT, st.y, N);
    }
  return bad;
}

// The environment table: `mode` on 6 fragment colours x 100 texels (5 x 5
// colours x 4 alphas), one pixel each, read back with alpha; the pairs more
// than one 8-bit step from the table (of 600).
inline int envMismatches(ts::Renderer& r, GLenum mode, glm::vec4 envColour) {
  auto img = std::make_shared<ts::Image>(100, 1);
  const int v[5] = {0, 64, 128, 191, 255}, a[4] = {0, 85, 170, 255};
  for (int k = 0; k < 100; ++k)
    img->set(k, 0, {uint8_t(v[k % 5]), uint8_t(v[(k / 5) % 5]), uint8_t(v[4 - k % 5]), uint8_t(a[k / 25])});
  ts::TextureDesc t;
  t.name = "env_grid";
  t.image = img;
  t.minFilter = t.magFilter = GL_NEAREST;
  const glm::vec4 frags[6] = {{1, 1, 1, 1},
                              {0, 0, 0, 1},
                              {0.2f, 0.6f, 1.0f, 0.4f},
                              {0.8f, 0.4f, 0.2f, 0.0f},
                              {0.6f, 0.6f, 0.6f, 0.8f},
                              {1.0f, 0.2f, 0.4f, 1.0f}};
  ts::Frame f;
  f.width = 100, f.height = 6;
  int tex = f.addTexture(t);
  ts::Panel p = pixelPanel(100, 6, 1, 6);
  for (int c = 0; c < 6; ++c) {
    ts::Batch b = stQuad({0, 5 - c}, {1, 6 - c}, {0, 0.5}, {1, 0.5}, tex);
    b.texEnv = mode;
    b.envColor = envColour;
    for (auto& x : b.vertices) x.color = frags[c];
    p.batches.push_back(b);
  }
  f.panels.push_back(p);
  ts::Image got = r.renderOffscreen(f);
  int bad = 0;
  for (int c = 0; c < 6; ++c)
    for (int k = 0; k < 100; ++k) {
      ts::Rgba tx = img->at(k, 0), g = got.at(k, c);
      glm::dvec4 want = wrap::texEnv(mode, glm::dvec4(frags[c]), glm::dvec4(tx.r, tx.g, tx.b, tx.a) / 255.0,
                                     glm::dvec4(envColour)) *
                        255.0;
      bad += std::abs(g.r - want.r) > 1 || std::abs(g.g - want.g) > 1 || std::abs(g.b - want.b) > 1 ||
             std::abs(g.a - want.a) > 1;
    }
  return bad;
}

// The lit plane of the environment view: 16 x 16 cells of the unit square,
// lit per vertex (wrap::phong: point light and eye at (1/2, 1/2, 0.6),
// so the specular peak, 1, is at vertex (8, 8)).  `separate`: the specular
// part as the secondary colour with GL_COLOR_SUM; else in the primary colour.
inline ts::Batch litPlane(int tex, GLenum env, glm::vec4 envColour, bool separate) {
  const int n = 16;
  const glm::dvec3 light(0.5, 0.5, 0.6), colour(0.9, 0.55, 0.25);
  ts::Batch b;
  b.role = "lit_surface";
  b.texture = tex;
  b.texEnv = env;
  b.envColor = envColour;
  b.colorSum = separate;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      for (glm::ivec2 c : {glm::ivec2(0, 0), {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}) {
        glm::dvec3 pos(double(i + c.x) / n, double(j + c.y) / n, 0.0);
        wrap::Lit lit = wrap::phong(pos, {0, 0, 1}, light, light, colour, 0.25, 40.0);
        ts::Vertex v;
        v.pos = glm::vec3(pos);
        v.tex = {pos.x, pos.y, 0, 1};
        glm::dvec3 primary = separate ? lit.diffuse : glm::min(lit.diffuse + lit.specular, glm::dvec3(1.0));
        v.color = glm::vec4(glm::vec3(primary), 1.0f);
        v.secondary = glm::vec3(float(separate ? lit.specular : 0.0));
        b.vertices.push_back(v);
      }
  return b;
}

// The brightest pixel of a rectangle, as the mean of R, G, B in [0, 1].
inline double peakBrightness(const ts::Image& img, const ts::Rect& vp) {
  double peak = 0;
  for (int y = vp.y; y < vp.y + vp.h; ++y)
    for (int x = vp.x; x < vp.x + vp.w; ++x) {
      ts::Rgba c = img.at(x, y);
      peak = std::max(peak, (c.r + c.g + c.b) / (3.0 * 255.0));
    }
  return peak;
}
}  // namespace wrap
