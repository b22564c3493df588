// common/gl/cost_workloads.cpp — the cost claims' frames (see the header for what each claim is).
#include "common/gl/cost_workloads.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "common/core/error.hpp"

namespace ts::costs {
namespace {
const char* const kFile = "common/gl/cost_workloads.cpp";

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
  gl::check("making a texture");
  return tex;
}

// ---- 1. hyperbolic against screen-linear interpolation ---------------------------------------------------------
// The quad's vertices carry (x, y, w) and the vertex shader writes clip position (x w, y w, 0, w): the frame is
// covered exactly, the top edge 8 times farther than the bottom, so every pixel is shaded in both modes and only
// the varying's qualifier differs.  The texture coordinates are affine in the quad's own plane (s = x w / 16,
// t = w / 16): a floor receding from the viewer, drawn right only by hyperbolic interpolation; at its far edge one
// texel a pixel of a 256-pixel frame, so that no frame aliases.
constexpr float kFar = 8;  // w of the top edge

class Interpolation final : public Workload {
 public:
  Interpolation(Renderer& r, bool perspective, int extra) : r_(r) {
    const std::string q = perspective ? "smooth" : "noperspective";
    auto declare = [&](const char* dir) {
      return extra ? q + " " + dir + " vec4 more[" + std::to_string(extra) + "];\n" : std::string();
    };
    const std::string loop = "for (int i = 0; i < " + std::to_string(extra) + "; ++i) ";
    key_ = "costs_interp_" + q + std::to_string(extra);
    src_ = {kFile,
            "#version 130\n" + q + " out vec2 uv;\n" + declare("out") + "void main() { uv = gl_MultiTexCoord0.xy;\n" +
                (extra ? "  " + loop + "more[i] = gl_Vertex * float(i + 1);\n" : "") +
                "  gl_Position = vec4(gl_Vertex.xy * gl_Vertex.z, 0.0, gl_Vertex.z); }\n",
            "#version 130\n" + q + " in vec2 uv;\n" + declare("in") +
                "uniform sampler2D tex;\n"
                "void main() { vec2 c = uv;\n" +
                (extra ? "  " + loop + "c += 1e-6 * more[i].xy * more[i].zw;\n" : "") +
                "  gl_FragColor = texture(tex, c); }\n"};
    tex_ = makeTexture(256, 256, checker(256, 16, {230, 230, 230}, {40, 40, 160}), GL_LINEAR, false);
    for (auto [x, y, w] : {std::array<float, 3>{-1, -1, 1}, {1, -1, 1}, {1, 1, kFar}, {-1, 1, kFar}})
      mesh_.vertex(x, y, w, x * w / 16, w / 16);
    mesh_.quad(0, 1, 2, 3);
    counters["triangles"] = double(mesh_.triangles());
  }
  ~Interpolation() override { glDeleteTextures(1, &tex_); }
  void begin() override {
    const GLuint prog = r_.program(key_, src_);  // made again after a Renderer::release (a recorded frame)
    glUseProgram(prog);
    glUniform1i(glGetUniformLocation(prog, "tex"), 0);
    glBindTexture(GL_TEXTURE_2D, tex_);
    mesh_.bind();
    glDisable(GL_DEPTH_TEST);
  }
  void frame() override {
    glClear(GL_COLOR_BUFFER_BIT);
    mesh_.draw();
  }
  void end() override {
    mesh_.unbind();
    glUseProgram(0);
  }

 private:
  Renderer& r_;
  std::string key_;
  Program src_;
  GLuint tex_ = 0;
  Mesh mesh_;
};

// ---- 2. detail as texture against detail as geometry -----------------------------------------------------------
constexpr float kDepth = 0.08f;  // mortar depth below the brick faces, object units (the wall is 2 wide)

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
  const int n = kReliefTexels;
  auto u = [&](int i) { return (float(i) + 0.5f) / float(n); };  // texel centres: the grid samples them exactly
  if (d != Detail::Grid && d != Detail::GridVerticesOnly) {
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

class DetailWorkload final : public Workload {
 public:
  DetailWorkload(Renderer& r, Detail d) : r_(r), d_(d) {
    const int n = kReliefTexels;
    std::vector<float> hm(size_t(n) * n);
    std::vector<uint8_t> px(hm.size() * 4, 255);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const size_t k = size_t(y) * n + size_t(x);
        px[k * 4] = px[k * 4 + 1] = px[k * 4 + 2] = uint8_t(std::lround(brickHeight(x, y) * 255));
        hm[k] = float(px[k * 4]) / 255.f;  // the grid is displaced by the texture's own 8-bit values
      }
    tex_ = makeTexture(n, n, px, GL_LINEAR, false);
    const int method = std::min(int(d), int(Detail::Grid));
    key_ = std::string("costs_detail_") + kDetailKeys[int(d)];
    src_ = {kFile,
            "#version 120\nvarying vec3 p;\nvarying vec4 st;\n"
            "void main() { p = gl_Vertex.xyz; st = gl_MultiTexCoord0;\n"
            "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }\n",
            "#version 120\n#define METHOD " + std::to_string(method) + "\n#define STEPS " +
                std::to_string(kParallaxSteps) + "\n" + kDetailFS};
    mesh_ = detailMesh(d, hm);
    counters["triangles"] = double(mesh_.triangles());
    counters["vertices"] = double(mesh_.xyz.size() / 3);
    counters["height_texels"] = double(n) * n;
  }
  ~DetailWorkload() override { glDeleteTextures(1, &tex_); }
  void begin() override {
    // The wall tilted 60 degrees away, seen from 2.4 units: grazing enough that parallax matters.
    const glm::mat4 proj = glm::perspective(glm::radians(45.f), 1.f, 0.1f, 10.f);
    const glm::mat4 view = glm::rotate(glm::translate(glm::mat4(1), {0, 0, -2.4f}), glm::radians(-60.f), {1, 0, 0});
    const glm::vec3 eye = glm::vec3(glm::inverse(view) * glm::vec4(0, 0, 0, 1));
    const glm::vec3 light = glm::normalize(glm::vec3(0.4f, 0.5f, 0.75f));
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadMatrixf(glm::value_ptr(proj));
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadMatrixf(glm::value_ptr(view));
    const GLuint prog = r_.program(key_, src_);
    glUseProgram(prog);
    glUniform1i(glGetUniformLocation(prog, "height"), 0);
    glUniform3f(glGetUniformLocation(prog, "eye"), eye.x, eye.y, eye.z);
    glUniform3f(glGetUniformLocation(prog, "light"), light.x, light.y, light.z);
    glUniform1f(glGetUniformLocation(prog, "depth"), kDepth);
    glUniform1f(glGetUniformLocation(prog, "texel"), 1.f / kReliefTexels);
    glBindTexture(GL_TEXTURE_2D, tex_);
    mesh_.bind();
    glEnable(GL_DEPTH_TEST);
  }
  void frame() override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (d_ == Detail::GridVerticesOnly) glEnable(GL_RASTERIZER_DISCARD);  // after the clear, which it would discard
    mesh_.draw();
    glDisable(GL_RASTERIZER_DISCARD);
  }
  void end() override {
    glDisable(GL_DEPTH_TEST);
    mesh_.unbind();
    glUseProgram(0);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopMatrix();
  }

 private:
  Renderer& r_;
  Detail d_;
  std::string key_;
  Program src_;
  GLuint tex_ = 0;
  Mesh mesh_;
};

// ---- 3. texture switches ----------------------------------------------------------------------------------------
// Quad q sits at column q % 64, row q / 64 and uses texture q % 32: left and right neighbours never share one.
// `byTexture_` holds the same quads' indices grouped by texture, for the one-call-per-texture order.
constexpr int kCols = 64, kRows = kQuads / kCols;

class Switches final : public Workload {
 public:
  Switches(Renderer&, Order order) : order_(order) {
    for (int t = 0; t < kTextures; ++t)
      tex_.push_back(
          makeTexture(16, 16,
                      checker(16, 4, {uint8_t(40 + 6 * t), uint8_t(230 - 6 * t), 90}, {uint8_t(8 * t), 30, 200}),
                      GL_NEAREST, false));
    for (int q = 0; q < kQuads; ++q) {
      const float x = float(q % kCols), y = float(q / kCols);
      const GLuint a = GLuint(mesh_.xyz.size() / 3);
      mesh_.vertex(x, y, 0, 0, 0);
      mesh_.vertex(x + 1, y, 0, 1, 0);
      mesh_.vertex(x + 1, y + 1, 0, 1, 1);
      mesh_.vertex(x, y + 1, 0, 0, 1);
      mesh_.quad(a, a + 1, a + 2, a + 3);
    }
    for (int t = 0; t < kTextures; ++t)
      for (int q = t; q < kQuads; q += kTextures)
        byTexture_.insert(byTexture_.end(), mesh_.idx.begin() + 6 * q, mesh_.idx.begin() + 6 * q + 6);
    counters["quads"] = kQuads;
    counters["triangles"] = double(kQuads) * 2;
  }
  ~Switches() override { glDeleteTextures(GLsizei(tex_.size()), tex_.data()); }
  void begin() override {
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(0, kCols, 0, kRows, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);  // fixed function: the Red Book's own path
    mesh_.bind();
  }
  void frame() override {
    long binds = 0, draws = 0;
    glClear(GL_COLOR_BUFFER_BIT);
    if (order_ == Order::Unsorted) {
      for (int q = 0; q < kQuads; ++q, ++binds, ++draws) {
        glBindTexture(GL_TEXTURE_2D, tex_[size_t(q % kTextures)]);
        mesh_.draw(size_t(q) * 6, 6);
      }
    } else {
      const size_t perTexture = byTexture_.size() / kTextures;
      for (int t = 0; t < kTextures; ++t, ++binds) {
        glBindTexture(GL_TEXTURE_2D, tex_[size_t(t)]);
        if (order_ == Order::SortedBatched) {
          glDrawElements(GL_TRIANGLES, GLsizei(perTexture), GL_UNSIGNED_INT,
                         byTexture_.data() + size_t(t) * perTexture);
          ++draws;
        } else {
          for (int q = t; q < kQuads; q += kTextures, ++draws) mesh_.draw(size_t(q) * 6, 6);
        }
      }
    }
    counters["binds"] = double(binds);
    counters["draws"] = double(draws);
  }
  void end() override {
    mesh_.unbind();
    glDisable(GL_TEXTURE_2D);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopMatrix();
  }

 private:
  Order order_;
  std::vector<GLuint> tex_;
  Mesh mesh_;
  std::vector<GLuint> byTexture_;
};

// ---- 4. minification with and without mipmaps --------------------------------------------------------------------
// One checker of each size with its levels, made once per renderer (GL makes the levels: seconds for 4096^2 on
// llvmpipe) and kept: only the minification filter differs between variants.
struct MinifyTextures final : Renderer::Attachment {
  explicit MinifyTextures(Renderer&) {}
  ~MinifyTextures() override {
    for (auto& [size, tex] : made) glDeleteTextures(1, &tex);
  }
  GLuint get(int size) {
    if (!made.count(size))
      made[size] = makeTexture(size, size, checker(size, 5, {240, 200, 60}, {20, 60, 140}), GL_LINEAR_MIPMAP_LINEAR,
                               true);
    return made[size];
  }
  std::map<int, GLuint> made;
};

class Minify final : public Workload {
 public:
  Minify(Renderer& r, GLint minFilter, int size, int scale, int frame) : filter_(minFilter) {
    tex_ = r.attachment<MinifyTextures>().get(size);
    const float repeat = float(frame * scale) / float(size);
    mesh_.vertex(-1, -1, 0, 0, 0);
    mesh_.vertex(1, -1, 0, repeat, 0);
    mesh_.vertex(1, 1, 0, repeat, repeat);
    mesh_.vertex(-1, 1, 0, 0, repeat);
    mesh_.quad(0, 1, 2, 3);
    counters["texels_per_pixel"] = double(scale) * scale;
    counters["texture_texels"] = double(size) * size;
  }
  void begin() override {
    glBindTexture(GL_TEXTURE_2D, tex_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter_);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    mesh_.bind();
  }
  void frame() override {
    glClear(GL_COLOR_BUFFER_BIT);
    mesh_.draw();
  }
  void end() override {
    mesh_.unbind();
    glDisable(GL_TEXTURE_2D);
  }

 private:
  GLint filter_;
  GLuint tex_ = 0;
  Mesh mesh_;
};
}  // namespace

void Mesh::vertex(float x, float y, float z, float s, float t, float r, float q) {
  xyz.insert(xyz.end(), {x, y, z});
  st.insert(st.end(), {s, t, r, q});
}
void Mesh::quad(GLuint a, GLuint b, GLuint c, GLuint d) { idx.insert(idx.end(), {a, b, c, a, c, d}); }
void Mesh::bind() const {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, xyz.data());
  glTexCoordPointer(4, GL_FLOAT, 0, st.data());
}
void Mesh::unbind() const {
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
}
void Mesh::draw(size_t first, size_t count) const {
  count = std::min(count, idx.size() - first);
  glDrawElements(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT, idx.data() + first);
}

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

std::unique_ptr<Workload> interpolation(Renderer& r, bool perspective, int extra) {
  return std::make_unique<Interpolation>(r, perspective, extra);
}
std::unique_ptr<Workload> detail(Renderer& r, Detail d) { return std::make_unique<DetailWorkload>(r, d); }
std::unique_ptr<Workload> switches(Renderer& r, Order order) { return std::make_unique<Switches>(r, order); }
std::unique_ptr<Workload> minify(Renderer& r, GLint minFilter, int size, int scale, int frame) {
  return std::make_unique<Minify>(r, minFilter, size, scale, frame);
}
}  // namespace ts::costs
