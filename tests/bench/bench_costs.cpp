// bench_costs — the cost claims of the sources, timed on this renderer (OSMesa, llvmpipe): whole frames
// (clear, draw, glFinish; no readback), ms per frame, with counters for what each frame did.
//
// The claims, briefly quoted (translated), and the family that times each:
//   1. Buss VI.1.1: "the drawback of hyperbolic interpolation is that it requires extra computation and
//      therefore may be slower".  -> costs/interpolation/{smooth,noperspective}/{256,512,1024}: one receding
//      quad filling a square frame, its texture coordinate a `smooth` (hyperbolic) or `noperspective`
//      (screen-linear) varying; nothing else differs.  {smooth,noperspective}_8vec4/1024 add 8 vec4 varyings
//      of the same kind, to magnify the per-attribute part.
//   2. Buss VI.1: without texture maps surfaces "would need to be rendered with very small polygons"; texture
//      maps give "good results with a minimal computational load".  Seed 001 ¶1: a brick image on a polygon
//      instead of exact geometry "saves modelling work and memory, and speeds up drawing".  Seed 003's
//      opening: small surface objects "whose creation with polygons would be excessively resource-
//      intensive".  -> costs/detail/{parallax_quad,bump_quad,displaced_grid}: the same brick relief (one
//      256^2 height map) at the same view and the same diffuse lighting, as a 2-triangle quad whose fragment
//      shader reads the height map (bump: normal from 4 neighbours; parallax: a 16-step search along the view
//      ray, then the bump normal) against a grid with one vertex per texel displaced on the CPU, per-vertex
//      normals from the same differences; displaced_grid_vertices_only draws the grid with
//      GL_RASTERIZER_DISCARD, its vertex work alone.
//   3. Seed 001 ¶18-19 (texture caching): "group polygons that use the same texture ... avoid texture
//      switches".  -> costs/switches/{sorted,unsorted,sorted_batched}: 2,048 small quads, 32 textures;
//      sorted binds 32 times, unsorted once per quad (a neighbour never shares its texture), both with one
//      draw call per quad; sorted_batched also draws each texture's quads in one call (what grouping allows).
//   4. Buss VI.1.3: only the low-resolution mipmaps of distant textures need to be kept "in more accessible
//      memory locations (e.g. in cache or on the graphics chip)" — mipmapping is widely said to be faster when
//      minifying, besides removing aliasing.  -> costs/minify/{mipmapped,bilinear_mip,unmipmapped}/{2048,4096}:
//      a texture minified 16x onto a 1024^2 frame with GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_NEAREST
//      (the same 4 taps as GL_LINEAR, on the right level) and GL_LINEAR (4 taps 16 texels apart on level 0);
//      costs/minify/one_to_one/4096, GL_LINEAR at 1 texel a pixel, is the control for the memory access, and
//      costs/minify/clear_only the frame's fixed part (clear and glFinish, nothing drawn).
//
// The GL calls that carry each claim: glTexCoord arrays with a `smooth`/`noperspective` varying (1),
// glDrawElements of 2 triangles against 130,050 (2), glBindTexture per group or per quad (3),
// glTexParameteri(GL_TEXTURE_MIN_FILTER, ...) on a texture made with GL_GENERATE_MIPMAP (4).
//
// Vertices come from client arrays (the suite's loader has no buffer objects), so the displaced grid's
// 65,536 vertices and 390,150 indices are handed to GL each frame, as a GL 1.1 program's would be.
// Speed is measured, never asserted; compare variants as ratios within one run, and record the load.
// To see what is timed: TS_BENCH_COSTS_PNG=dir writes the first frame of each benchmark to dir/<name>.png.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "bench_common.hpp"
#include "common/core/image.hpp"
#include "common/gl/context.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"

namespace {
const char* const kFile = "tests/bench/bench_costs.cpp";

// ---- shared GL setup ---------------------------------------------------------------------------------------
struct Rig {
  Rig() {
    ts::ContextOptions o;
    o.width = o.height = 512;
    ctx = ts::createOffscreenContext(ts::Backend::OSMesa, o);
    renderer = std::make_unique<ts::Renderer>(*ctx);
    glDisable(GL_DEBUG_OUTPUT);  // a shipped program runs without the suite's error reports
  }
  ~Rig() { renderer->release(); }
  // A square frame of n x n pixels, the viewport over it.
  void frame(int n) {
    if (ctx->width() != n || ctx->height() != n) ctx->resize(n, n);
    glViewport(0, 0, n, n);
  }
  GLuint program(const std::string& key, const std::string& vs, const std::string& fs) {
    return renderer->program(key, {kFile, vs, fs});
  }
  std::unique_ptr<ts::Context> ctx;
  std::unique_ptr<ts::Renderer> renderer;
};
Rig& rig() {
  static Rig r;
  return r;
}

// Indexed triangles from client arrays: xyz positions, 4 texture-coordinate components a vertex.
struct Mesh {
  std::vector<float> xyz, st;
  std::vector<GLuint> idx;
  void vertex(float x, float y, float z, float s, float t, float r = 0, float q = 1) {
    xyz.insert(xyz.end(), {x, y, z});
    st.insert(st.end(), {s, t, r, q});
  }
  void quad(GLuint a, GLuint b, GLuint c, GLuint d) { idx.insert(idx.end(), {a, b, c, a, c, d}); }
  size_t triangles() const { return idx.size() / 3; }
  void bind() const {
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, xyz.data());
    glTexCoordPointer(4, GL_FLOAT, 0, st.data());
  }
  // Indices [first, first + count) of idx; all of them by default.
  void draw(size_t first = 0, size_t count = size_t(-1)) const {
    count = std::min(count, idx.size() - first);
    glDrawElements(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT, idx.data() + first);
  }
};

GLuint makeTexture(int w, int h, const std::vector<uint8_t>& rgba, GLint minFilter, bool mipmaps) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, minFilter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, minFilter == GL_NEAREST ? GL_NEAREST : GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  if (mipmaps) glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);  // GL 1.4: levels made on upload
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  ts::gl::check("making a texture");
  return tex;
}

// A checkerboard of `cell`-texel squares in two colours, with a little per-texel variation so that no two
// neighbouring texels are equal (the minified frames then depend on every texel).
std::vector<uint8_t> checker(int n, int cell, glm::u8vec3 a, glm::u8vec3 b) {
  std::vector<uint8_t> px(size_t(n) * size_t(n) * 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      glm::u8vec3 c = ((x / cell + y / cell) & 1) ? a : b;
      uint8_t* p = &px[(size_t(y) * size_t(n) + size_t(x)) * 4];
      int v = (x * 7 + y * 13) % 32;
      for (int k = 0; k < 3; ++k) p[k] = uint8_t(std::clamp(int(c[k]) - 16 + v, 0, 255));
      p[3] = 255;
    }
  return px;
}

// The running benchmark's name, for the pictures below.
std::string g_running;

// One timed frame: clear, draw, glFinish (llvmpipe renders on its own threads: real time is the cost).
// With TS_BENCH_COSTS_PNG=dir the first frame of each benchmark is written to dir/<name>.png, to see
// that the variants compared draw the same thing.
template <class Draw>
void timeFrames(benchmark::State& st, Draw&& draw) {
  draw();
  glFinish();  // warm: programs linked, textures made resident
  ts::gl::check("the first frame");
  if (const char* dir = std::getenv("TS_BENCH_COSTS_PNG")) {
    std::string file = g_running;
    std::replace(file.begin(), file.end(), '/', '_');
    ts::writePng(std::string(dir) + "/" + file + ".png", rig().ctx->readPixels());
  }
  for (auto _ : st) {
    draw();
    glFinish();
  }
}

void counters(benchmark::State& st, std::initializer_list<std::pair<const char*, double>> kv) {
  for (const auto& [k, v] : kv) st.counters[k] = v;
  st.counters["fps"] = benchmark::Counter(double(st.iterations()), benchmark::Counter::kIsRate);
}

template <class F>
void guarded(benchmark::State& st, F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}

// ---- 1. hyperbolic against screen-linear interpolation -------------------------------------------------------
// The quad's vertices carry (x, y, w) and the vertex shader writes clip position (x w, y w, 0, w): the frame is
// covered exactly, the top edge 8 times farther than the bottom, so every pixel is shaded in both modes and
// only the varying's qualifier differs.
constexpr float kFar = 8;  // w of the top edge

// `extra` more vec4 varyings with the same qualifier, folded into the coordinate so that none is optimised
// away: the per-attribute part of the cost, magnified (the claim's case is extra = 0).
void interpolation(benchmark::State& st, bool perspective, int n, int extra) {
  guarded(st, [&] {
    Rig& r = rig();
    r.frame(n);
    const std::string q = perspective ? "smooth" : "noperspective";
    auto declare = [&](const char* dir) {
      return extra ? q + " " + dir + " vec4 more[" + std::to_string(extra) + "];\n" : std::string();
    };
    const std::string loop = "for (int i = 0; i < " + std::to_string(extra) + "; ++i) ";
    const GLuint prog = r.program("costs_interp_" + q + std::to_string(extra),
                                  "#version 130\n" + q + " out vec2 uv;\n" + declare("out") +
                                      "void main() { uv = gl_MultiTexCoord0.xy;\n" +
                                      (extra ? "  " + loop + "more[i] = gl_Vertex * float(i + 1);\n" : "") +
                                      "  gl_Position = vec4(gl_Vertex.xy * gl_Vertex.z, 0.0, gl_Vertex.z); }\n",
                                  "#version 130\n" + q + " in vec2 uv;\n" + declare("in") +
                                      "uniform sampler2D tex;\n"
                                      "void main() { vec2 c = uv;\n" +
                                      (extra ? "  " + loop + "c += 1e-6 * more[i].xy * more[i].zw;\n" : "") +
                                      "  gl_FragColor = texture(tex, c); }\n");
    const GLuint tex = makeTexture(256, 256, checker(256, 16, {230, 230, 230}, {40, 40, 160}), GL_LINEAR, false);
    // The texture coordinates are affine in the quad's own plane (s from x w, t from w): a floor receding
    // from the viewer, drawn right only by hyperbolic interpolation.
    Mesh m;
    for (auto [x, y, w] : {std::array<float, 3>{-1, -1, 1}, {1, -1, 1}, {1, 1, kFar}, {-1, 1, kFar}})
      m.vertex(x, y, w, x * w * 2, w * 2);
    m.quad(0, 1, 2, 3);
    glUseProgram(prog);
    glUniform1i(glGetUniformLocation(prog, "tex"), 0);
    m.bind();
    glDisable(GL_DEPTH_TEST);
    timeFrames(st, [&] {
      glClear(GL_COLOR_BUFFER_BIT);
      m.draw();
    });
    glUseProgram(0);
    glDeleteTextures(1, &tex);
    counters(st, {{"pixels", double(n) * n}, {"triangles", double(m.triangles())}});
  });
}

// ---- 2. detail as texture against detail as geometry --------------------------------------------------------
constexpr int kRelief = 256;     // height map texels a side; the grid has one vertex per texel
constexpr float kDepth = 0.08f;  // mortar depth below the brick faces, object units (the wall is 2 wide)
constexpr int kDetailFrame = 768;
constexpr int kParallaxSteps = 16;
// kGridVertices: the grid with GL_RASTERIZER_DISCARD, the control that splits its cost: vertices fetched,
// shaded and clipped (llvmpipe does this on the calling thread), nothing rasterised.
enum Detail { kParallax, kBump, kGrid, kGridVertices };
const char* const kDetailKeys[] = {"parallax_quad", "bump_quad", "displaced_grid", "displaced_grid_vertices_only"};

// Bricks 64 x 32 texels, rows offset by half a brick, 2-texel mortar and a 6-texel bevel: height 0 in the mortar,
// 1 on a brick's face.
float brickHeight(int x, int y) {
  const int row = y / 32, bx = (x + (row & 1) * 32) % 64, by = y % 32;
  const int edge = std::min({bx, 63 - bx, by, 31 - by});
  return std::clamp((float(edge) - 2.f) / 6.f, 0.f, 1.f);
}

// z = kDepth (h - 1) over x = 2u - 1: dz/dx = kDepth dh/du / 2, dh/du from central differences.
const char* const kDetailFS = R"(
uniform sampler2D height;
uniform vec3 eye, light;  // object space
uniform float depth, texel;
varying vec3 p;
varying vec4 st;
float h(vec2 uv) { return texture2D(height, uv).r; }
vec3 bumpNormal(vec2 uv) {
  float dx = h(uv + vec2(texel, 0.0)) - h(uv - vec2(texel, 0.0));
  float dy = h(uv + vec2(0.0, texel)) - h(uv - vec2(0.0, texel));
  return normalize(vec3(-depth * dx / (4.0 * texel), -depth * dy / (4.0 * texel), 1.0));
}
void main() {
  vec2 uv = st.xy;
  vec3 n;
#if METHOD == 0
  // Steep parallax (seed 003): walk down the view ray in STEPS layers until it is below the relief.
  vec3 v = normalize(eye - p);
  vec2 stepUv = -v.xy / v.z * 0.5 * depth / float(STEPS);
  float layer = depth / float(STEPS), d = 0.0;
  for (int i = 0; i < STEPS; ++i) {
    if (depth * (1.0 - h(uv)) <= d) break;
    uv += stepUv;
    d += layer;
  }
  n = bumpNormal(uv);
#elif METHOD == 1
  n = bumpNormal(uv);
#else
  n = vec3(st.zw, sqrt(max(0.0, 1.0 - dot(st.zw, st.zw))));  // the vertex normal, z rebuilt (it faces +z)
#endif
  vec3 albedo = mix(vec3(0.55, 0.55, 0.5), vec3(0.7, 0.3, 0.2), h(uv));
  gl_FragColor = vec4(albedo * (0.2 + 0.8 * max(dot(normalize(n), light), 0.0)), 1.0);
}
)";

Mesh detailMesh(Detail d, const std::vector<float>& hm) {
  Mesh m;
  const int n = kRelief;
  auto u = [&](int i) { return (float(i) + 0.5f) / float(n); };  // texel centres: the grid samples them exactly
  if (d != kGrid && d != kGridVertices) {
    m.vertex(2 * u(0) - 1, 2 * u(0) - 1, 0, u(0), u(0));
    m.vertex(2 * u(n - 1) - 1, 2 * u(0) - 1, 0, u(n - 1), u(0));
    m.vertex(2 * u(n - 1) - 1, 2 * u(n - 1) - 1, 0, u(n - 1), u(n - 1));
    m.vertex(2 * u(0) - 1, 2 * u(n - 1) - 1, 0, u(0), u(n - 1));
    m.quad(0, 1, 2, 3);
    return m;
  }
  auto H = [&](int x, int y) { return hm[size_t(std::clamp(y, 0, n - 1) * n + std::clamp(x, 0, n - 1))]; };
  const float texel = 1.f / float(n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      glm::vec3 nrm = glm::normalize(glm::vec3(-kDepth * (H(x + 1, y) - H(x - 1, y)) / (4 * texel),
                                               -kDepth * (H(x, y + 1) - H(x, y - 1)) / (4 * texel), 1));
      m.vertex(2 * u(x) - 1, 2 * u(y) - 1, kDepth * (H(x, y) - 1), u(x), u(y), nrm.x, nrm.y);
    }
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const GLuint a = GLuint(y * n + x);
      m.quad(a, a + 1, a + 1 + GLuint(n), a + GLuint(n));
    }
  return m;
}

void detail(benchmark::State& st, Detail d) {
  guarded(st, [&] {
    Rig& r = rig();
    r.frame(kDetailFrame);
    std::vector<float> hm(size_t(kRelief) * kRelief);
    std::vector<uint8_t> px(hm.size() * 4, 255);
    for (int y = 0; y < kRelief; ++y)
      for (int x = 0; x < kRelief; ++x) {
        const size_t k = size_t(y) * kRelief + size_t(x);
        px[k * 4] = px[k * 4 + 1] = px[k * 4 + 2] = uint8_t(std::lround(brickHeight(x, y) * 255));
        hm[k] = float(px[k * 4]) / 255.f;  // the grid is displaced by the texture's own 8-bit values
      }
    const GLuint tex = makeTexture(kRelief, kRelief, px, GL_LINEAR, false);
    const GLuint prog = r.program(std::string("costs_detail_") + kDetailKeys[d],
                                  "#version 120\nvarying vec3 p;\nvarying vec4 st;\n"
                                  "void main() { p = gl_Vertex.xyz; st = gl_MultiTexCoord0;\n"
                                  "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }\n",
                                  "#version 120\n#define METHOD " + std::to_string(int(std::min(d, kGrid))) +
                                      "\n#define STEPS " + std::to_string(kParallaxSteps) + "\n" + kDetailFS);
    // The wall tilted 60 degrees away, seen from 2.4 units: grazing enough that parallax matters.
    const glm::mat4 proj = glm::perspective(glm::radians(45.f), 1.f, 0.1f, 10.f);
    const glm::mat4 view = glm::rotate(glm::translate(glm::mat4(1), {0, 0, -2.4f}), glm::radians(-60.f), {1, 0, 0});
    const glm::vec3 eye = glm::vec3(glm::inverse(view) * glm::vec4(0, 0, 0, 1));
    const glm::vec3 light = glm::normalize(glm::vec3(0.4f, 0.5f, 0.75f));
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(glm::value_ptr(proj));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(glm::value_ptr(view));
    glUseProgram(prog);
    glUniform1i(glGetUniformLocation(prog, "height"), 0);
    glUniform3f(glGetUniformLocation(prog, "eye"), eye.x, eye.y, eye.z);
    glUniform3f(glGetUniformLocation(prog, "light"), light.x, light.y, light.z);
    glUniform1f(glGetUniformLocation(prog, "depth"), kDepth);
    glUniform1f(glGetUniformLocation(prog, "texel"), 1.f / kRelief);
    const Mesh m = detailMesh(d, hm);
    m.bind();
    glEnable(GL_DEPTH_TEST);
    timeFrames(st, [&] {
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      if (d == kGridVertices) glEnable(GL_RASTERIZER_DISCARD);  // after the clear, which it would discard too
      m.draw();
      glDisable(GL_RASTERIZER_DISCARD);
    });
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0);
    glLoadIdentity();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glDeleteTextures(1, &tex);
    counters(st, {{"pixels", double(kDetailFrame) * kDetailFrame},
                  {"triangles", double(m.triangles())},
                  {"vertices", double(m.xyz.size() / 3)},
                  {"height_texels", double(kRelief) * kRelief}});
  });
}

// ---- 3. texture switches --------------------------------------------------------------------------------------
constexpr int kTextures = 32, kCols = 64, kRows = 32, kQuads = kCols * kRows;  // 2,048 quads of 8 x 16 pixels
enum Order { kSorted, kUnsorted, kSortedBatched };
const char* const kOrderKeys[] = {"sorted", "unsorted", "sorted_batched"};

void switches(benchmark::State& st, Order order) {
  guarded(st, [&] {
    Rig& r = rig();
    r.frame(512);
    std::vector<GLuint> tex;
    for (int t = 0; t < kTextures; ++t)
      tex.push_back(
          makeTexture(16, 16,
                      checker(16, 4, {uint8_t(40 + 6 * t), uint8_t(230 - 6 * t), 90}, {uint8_t(8 * t), 30, 200}),
                      GL_NEAREST, false));
    // Quad q sits at column q % 64, row q / 64 and uses texture q % 32: left and right neighbours never share one.
    // `byTexture` holds the same quads' indices grouped by texture, for the one-call-per-texture order.
    Mesh m;
    std::vector<GLuint> byTexture;
    for (int q = 0; q < kQuads; ++q) {
      const float x = float(q % kCols), y = float(q / kCols);
      const GLuint a = GLuint(m.xyz.size() / 3);
      m.vertex(x, y, 0, 0, 0);
      m.vertex(x + 1, y, 0, 1, 0);
      m.vertex(x + 1, y + 1, 0, 1, 1);
      m.vertex(x, y + 1, 0, 0, 1);
      m.quad(a, a + 1, a + 2, a + 3);
    }
    for (int t = 0; t < kTextures; ++t)
      for (int q = t; q < kQuads; q += kTextures)
        byTexture.insert(byTexture.end(), m.idx.begin() + 6 * q, m.idx.begin() + 6 * q + 6);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, kCols, 0, kRows, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);  // fixed function: the Red Book's own path
    m.bind();
    long binds = 0, draws = 0;
    timeFrames(st, [&] {
      binds = draws = 0;
      glClear(GL_COLOR_BUFFER_BIT);
      if (order == kUnsorted) {
        for (int q = 0; q < kQuads; ++q, ++binds, ++draws) {
          glBindTexture(GL_TEXTURE_2D, tex[size_t(q % kTextures)]);
          m.draw(size_t(q) * 6, 6);
        }
        return;
      }
      const size_t perTexture = byTexture.size() / kTextures;
      for (int t = 0; t < kTextures; ++t, ++binds) {
        glBindTexture(GL_TEXTURE_2D, tex[size_t(t)]);
        if (order == kSortedBatched) {
          glDrawElements(GL_TRIANGLES, GLsizei(perTexture), GL_UNSIGNED_INT, byTexture.data() + size_t(t) * perTexture);
          ++draws;
        } else {
          for (int q = t; q < kQuads; q += kTextures, ++draws) m.draw(size_t(q) * 6, 6);
        }
      }
    });
    glDisable(GL_TEXTURE_2D);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glDeleteTextures(GLsizei(tex.size()), tex.data());
    counters(st, {{"binds", double(binds)},
                  {"draws", double(draws)},
                  {"quads", double(kQuads)},
                  {"triangles", double(kQuads) * 2}});
  });
}

// ---- 4. minification with and without mipmaps ----------------------------------------------------------------
// 2048^2 (16 MiB, level 0) fits this machine's 32 MiB L3 cache; 4096^2 (64 MiB) does not.  Repeated so that
// 16 texels of level 0 fall across each pixel either way (`scale`); one_to_one reads level 0 at 1 texel a
// pixel, the coherent access mipmapping is said to restore.
constexpr int kMinifyFrame = 1024;
struct MinFilter {
  const char* key;
  GLint filter;
};
const MinFilter kMinFilters[] = {{"mipmapped", GL_LINEAR_MIPMAP_LINEAR},
                                 {"bilinear_mip", GL_LINEAR_MIPMAP_NEAREST},
                                 {"unmipmapped", GL_LINEAR}};

void minify(benchmark::State& st, MinFilter f, int size, int scale) {
  guarded(st, [&] {
    Rig& r = rig();
    r.frame(kMinifyFrame);
    // One texture of each size with its levels (made once, by GL); only the minification filter differs
    // between variants.
    static std::map<int, GLuint> made;
    if (!made.count(size))
      made[size] = makeTexture(size, size, checker(size, 5, {240, 200, 60}, {20, 60, 140}), GL_LINEAR_MIPMAP_LINEAR,
                               true);
    const GLuint tex = made[size];
    const float repeat = float(kMinifyFrame * scale) / float(size);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f.filter);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    Mesh m;
    m.vertex(-1, -1, 0, 0, 0);
    m.vertex(1, -1, 0, repeat, 0);
    m.vertex(1, 1, 0, repeat, repeat);
    m.vertex(-1, 1, 0, 0, repeat);
    m.quad(0, 1, 2, 3);
    m.bind();
    timeFrames(st, [&] {
      glClear(GL_COLOR_BUFFER_BIT);
      m.draw();
    });
    glDisable(GL_TEXTURE_2D);
    counters(st, {{"pixels", double(kMinifyFrame) * kMinifyFrame},
                  {"texels_per_pixel", double(scale) * scale},
                  {"texture_texels", double(size) * size}});
  });
}
// The part of every minify frame that is not texturing.
void clearOnly(benchmark::State& st) {
  guarded(st, [&] {
    rig().frame(kMinifyFrame);
    timeFrames(st, [] { glClear(GL_COLOR_BUFFER_BIT); });
    counters(st, {{"pixels", double(kMinifyFrame) * kMinifyFrame}});
  });
}

// The medians as markdown tables, each variant beside the one its claim compares it with.
void summary(const ts::bench::SummaryReporter& rep) {
  using ts::bench::fmt;
  using ts::bench::ratio;
  auto ms = [&](const std::string& n) { return rep.ms("costs/" + n); };
  auto count = [&](const std::string& n, const char* key) {
    const double v = rep.counter("costs/" + n, key);
    return std::isfinite(v) ? std::to_string(std::llround(v)) : std::string("–");
  };
  std::printf("\n%s, ms per frame (OSMesa, llvmpipe).\n", rep.statistic().c_str());
  if (rep.ran("costs/interpolation/")) {
    std::printf("\n| frame | smooth (hyperbolic) | noperspective (screen-linear) | smooth / noperspective |\n"
                "|---|---|---|---|\n");
    for (const char* n : {"256", "512", "1024", "8vec4/1024"}) {
      const std::string k = n[0] == '8' ? "_" + std::string(n) : "/" + std::string(n);
      const double a = ms("interpolation/smooth" + k), b = ms("interpolation/noperspective" + k);
      const std::string label = n[0] == '8' ? "1024^2, 8 more vec4 varyings" : std::string(n) + "^2";
      std::printf("| %s | %s | %s | %s |\n", label.c_str(), fmt(a).c_str(), fmt(b).c_str(), ratio(a, b).c_str());
    }
  }
  if (rep.ran("costs/detail/")) {
    std::printf("\n| relief, %d^2 frame | triangles | ms | / bump_quad |\n|---|---|---|---|\n", kDetailFrame);
    for (const char* k : kDetailKeys) {
      const std::string n = std::string("detail/") + k;
      std::printf("| %s | %s | %s | %s |\n", k, count(n, "triangles").c_str(), fmt(ms(n)).c_str(),
                  ratio(ms(n), ms("detail/bump_quad")).c_str());
    }
  }
  if (rep.ran("costs/switches/")) {
    std::printf("\n| %d quads, %d textures | binds | draw calls | ms | / sorted |\n|---|---|---|---|---|\n", kQuads,
                kTextures);
    for (const char* k : kOrderKeys) {
      const std::string n = std::string("switches/") + k;
      std::printf("| %s | %s | %s | %s | %s |\n", k, count(n, "binds").c_str(), count(n, "draws").c_str(),
                  fmt(ms(n)).c_str(), ratio(ms(n), ms("switches/sorted")).c_str());
    }
  }
  if (rep.ran("costs/minify/")) {
    std::printf(
        "\n| texture, 16x minified onto %d^2 | mipmapped (trilinear) | bilinear_mip | unmipmapped (GL_LINEAR) | "
        "mipmapped / unmipmapped | bilinear_mip / unmipmapped |\n|---|---|---|---|---|---|\n",
        kMinifyFrame);
    for (int size : {2048, 4096}) {
      const std::string z = "/" + std::to_string(size);
      const double tri = ms("minify/mipmapped" + z), bi = ms("minify/bilinear_mip" + z),
                   lin = ms("minify/unmipmapped" + z);
      std::printf("| %d^2 | %s | %s | %s | %s | %s |\n", size, fmt(tri).c_str(), fmt(bi).c_str(), fmt(lin).c_str(),
                  ratio(tri, lin).c_str(), ratio(bi, lin).c_str());
    }
    std::printf("\nControls: GL_LINEAR at 1 texel a pixel on the 4096^2 texture, %s ms; the clear alone, %s ms.\n",
                fmt(ms("minify/one_to_one/4096")).c_str(), fmt(ms("minify/clear_only")).c_str());
  }
  std::printf("\n");
}
}  // namespace

int main(int argc, char** argv) {
  auto add = [](const std::string& name, auto fn, auto... a) {
    benchmark::RegisterBenchmark(name.c_str(),
                                 [=](benchmark::State& st) {
                                   g_running = name;
                                   fn(st, a...);
                                 })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->ComputeStatistics("min", ts::bench::minimum);  // on a shared machine, the least disturbed repetition
  };
  for (int n : {256, 512, 1024})
    for (bool persp : {true, false})
      add("costs/interpolation/" + std::string(persp ? "smooth/" : "noperspective/") + std::to_string(n), interpolation,
          persp, n, 0);
  for (bool persp : {true, false})
    add("costs/interpolation/" + std::string(persp ? "smooth" : "noperspective") + "_8vec4/1024", interpolation, persp,
        1024, 8);
  for (Detail d : {kParallax, kBump, kGrid, kGridVertices})
    add(std::string("costs/detail/") + kDetailKeys[d], detail, d);
  for (Order o : {kSorted, kUnsorted, kSortedBatched}) add(std::string("costs/switches/") + kOrderKeys[o], switches, o);
  for (int size : {2048, 4096})
    for (const MinFilter& f : kMinFilters)
      add(std::string("costs/minify/") + f.key + "/" + std::to_string(size), minify, f, size, 16);
  // The control: level 0 read at one texel a pixel, where neighbouring pixels share cache lines.
  add("costs/minify/one_to_one/4096", minify, kMinFilters[2], 4096, 1);
  add("costs/minify/clear_only", clearOnly);
  return ts::bench::run(argc, argv, summary);
}
