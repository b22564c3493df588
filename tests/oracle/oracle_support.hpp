// tests/oracle/oracle_support.hpp — what the oracle's GL tests share: render
// a Frame with the suite's Renderer at the frame's size, verify it against
// the CPU reference, and put failure images in the build tree.
#pragma once
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "common/gl/context.hpp"
#include "common/core/frame.hpp"
#include "common/gl/render.hpp"
#include "common/core/textures.hpp"
#include "reference/verify.hpp"
#include "tests/support/gl_test.hpp"

#ifndef TS_ORACLE_OUT_DIR
#define TS_ORACLE_OUT_DIR "oracle_failures"
#endif

namespace oracle {
// Failure images land here (the build tree), never in the source tree.
inline std::string outDir(const std::string& sub = "") {
  return std::string(TS_ORACLE_OUT_DIR) + (sub.empty() ? "" : "/" + sub);
}

inline ts::Image render(const ts::Frame& f, bool labels = false) {
  ts::Renderer& r = ts::test::renderer();
  ts::Context& ctx = r.context();
  if (ctx.width() != f.width || ctx.height() != f.height) ctx.resize(f.width, f.height);
  return r.render(f, labels);
}

inline ref::VerifyOptions options(const std::string& name, const std::string& sub = "") {
  ref::VerifyOptions o;
  o.name = name;
  o.outputDir = outDir(sub);
  return o;
}

// A small texture whose texels all differ clearly (so any wrong texel, or a
// coordinate off by a fraction of a texel under GL_LINEAR, shows).
inline ts::TextureDesc colourful(int size) {
  auto img = std::make_shared<ts::Image>(size, size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      img->set(i, j,
               {uint8_t(40 + (i * 53 + j * 17) % 200), uint8_t(30 + (j * 61 + i * 7) % 210),
                uint8_t(20 + ((i + 3) * (j + 5) * 29) % 220), 255});
  ts::TextureDesc t;
  t.name = "oracle_colourful";  // not a sidecar generator: GL tests only
  t.params = {{"size", std::to_string(size)}};
  t.image = img;
  return t;
}

// A panel filling the frame with a unit-square orthographic projection.
inline ts::Panel unitPanel(int w, int h, const std::string& id = "p") {
  ts::Panel p;
  p.id = id;
  p.viewport = {0, 0, w, h};
  p.projection = glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f);
  return p;
}

// A quad [x0,x1]x[y0,y1] as two triangles, (s,t) from st0 to st1.
inline ts::Batch quad(glm::vec2 p0, glm::vec2 p1, glm::vec2 st0, glm::vec2 st1, int texture, GLenum env = GL_REPLACE) {
  ts::Batch b;
  b.role = "surface";
  b.texture = texture;
  b.texEnv = env;
  auto v = [&](float a, float c) {
    ts::Vertex x;
    x.pos = {glm::mix(p0.x, p1.x, a), glm::mix(p0.y, p1.y, c), 0.0f};
    x.tex = {glm::mix(st0.x, st1.x, a), glm::mix(st0.y, st1.y, c), 0.0f, 1.0f};
    return x;
  };
  for (auto [a, c] : {std::pair{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}})
    b.vertices.push_back(v(a, c));
  return b;
}

// A checkerboard plane y = 0, x in [-1, 1], z in [-zFar, -zNear] seen by a
// perspective camera above it: the slanted plane of Figure VI.2.
inline ts::Frame slantedPlane(int w, int h, ts::TextureDesc tex, float repeats = 8.0f) {
  ts::Frame f;
  f.width = w;
  f.height = h;
  f.clearColor = {0.1f, 0.1f, 0.15f, 1.0f};
  int t = f.addTexture(std::move(tex));
  ts::Panel p;
  p.id = "plane";
  p.viewport = {0, 0, w, h};
  p.projection = glm::perspective(glm::radians(60.0f), float(w) / float(h), 0.1f, 100.0f);
  p.modelview = glm::lookAt(glm::vec3(0, 0.6f, 0.4f), glm::vec3(0, 0, -3.0f), glm::vec3(0, 1, 0));
  ts::Batch b;
  b.role = "plane";
  b.texture = t;
  const float x0 = -1.2f, x1 = 1.2f, z0 = 0.0f, z1 = -8.0f;
  auto v = [&](float a, float c) {
    ts::Vertex x;
    x.pos = {glm::mix(x0, x1, a), 0.0f, glm::mix(z0, z1, c)};
    x.tex = {a * repeats * 0.3f, c * repeats, 0.0f, 1.0f};
    return x;
  };
  for (auto [a, c] : {std::pair{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}})
    b.vertices.push_back(v(a, c));
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}
}  // namespace oracle
