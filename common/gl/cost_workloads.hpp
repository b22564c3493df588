// common/gl/cost_workloads.hpp — the frames that time the sources' cost claims, each drawn the same way by the
// benchmark (tests/bench/bench_costs.cpp, quiet, medians) and by the texture_costs demo (live, on the student's
// own machine, in its panel).  One workload = one variant of one claim:
//   1. interpolation  Buss VI.1.1, hyperbolic interpolation costs extra: one receding quad covering the frame, its
//                     texture coordinate a `smooth` (hyperbolic) or `noperspective` (screen-linear) varying.
//   2. detail         Buss VI.1, seed 001 §1-2, seed 003's opening, a texture is cheaper than the same detail as
//                     geometry: the same brick relief as a 2-triangle quad whose fragment shader reads the height
//                     map (bump; parallax: a 16-step search) against a grid with one vertex per texel, displaced.
//   3. switches       seed 001 §18-19, texture switches cost: 2,048 small quads over 32 textures, bound once per
//                     texture (sorted), once per quad (unsorted), or one draw per texture (sorted_batched).
//   4. minify         Buss VI.1.3, mipmaps keep minified reads in cache: a texture minified `scale` x onto the
//                     frame with GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_NEAREST or GL_LINEAR.
// A workload draws into whatever framebuffer is bound, over the viewport the caller set (a square frame: the
// interpolation quad covers it exactly).  begin() sets the state its frames need, frame() clears and draws one,
// end() puts the state back; the constructor makes the textures and programs, the destructor deletes the textures.
// Vertices come from client arrays (the suite's loader has no buffer objects), as a GL 1.1 program's would.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"

namespace ts::costs {
// Indexed triangles from client arrays: xyz positions, 4 texture-coordinate components a vertex.
struct Mesh {
  std::vector<float> xyz, st;
  std::vector<GLuint> idx;
  void vertex(float x, float y, float z, float s, float t, float r = 0, float q = 1);
  void quad(GLuint a, GLuint b, GLuint c, GLuint d);
  size_t triangles() const { return idx.size() / 3; }
  void bind() const;    // glVertexPointer, glTexCoordPointer (client state enabled)
  void unbind() const;  // the client state disabled again
  // Indices [first, first + count) of idx; all of them by default.
  void draw(size_t first = 0, size_t count = size_t(-1)) const;
};

class Workload {
 public:
  virtual ~Workload() = default;
  virtual void begin() = 0;
  virtual void frame() = 0;
  virtual void end() = 0;
  // What one frame did: triangles, binds, draws, texels_per_pixel, ... (counted by frame() as it draws).
  std::map<std::string, double> counters;
};

enum class Detail { Parallax, Bump, Grid, GridVerticesOnly };
enum class Order { Sorted, Unsorted, SortedBatched };
inline const char* const kDetailKeys[] = {"parallax_quad", "bump_quad", "displaced_grid",
                                          "displaced_grid_vertices_only"};
inline const char* const kOrderKeys[] = {"sorted", "unsorted", "sorted_batched"};
constexpr int kReliefTexels = 256;            // the detail claim's height map, texels a side (one grid vertex each)
constexpr int kParallaxSteps = 16;            // the parallax quad's search
constexpr int kTextures = 32, kQuads = 2048;  // the switches claim: 64 x 32 quads, 32 textures

// `extra` more vec4 varyings of the same qualifier (0 in the claim's case): the per-attribute part magnified.
std::unique_ptr<Workload> interpolation(Renderer& r, bool perspective, int extra = 0);
std::unique_ptr<Workload> detail(Renderer& r, Detail d);
std::unique_ptr<Workload> switches(Renderer& r, Order order);
// A size x size checker with GL's own mipmaps (GL_GENERATE_MIPMAP), repeated so that scale x scale texels of
// level 0 fall on each pixel of a `frame`-pixel square.  `minFilter` is the only difference between variants.
std::unique_ptr<Workload> minify(Renderer& r, GLint minFilter, int size, int scale, int frame);

// A checkerboard of `cell`-texel squares in two colours, with a little per-texel variation so that no two
// neighbouring texels are equal (minified frames then depend on every texel).  RGBA8, row 0 first.
std::vector<uint8_t> checker(int n, int cell, glm::u8vec3 a, glm::u8vec3 b);
}  // namespace ts::costs
