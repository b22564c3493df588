// tests/exercises/exercise_checks.cpp — see exercise_checks.hpp.
#include "exercise_checks.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <stdexcept>

#include "common/core/layout.hpp"
#include "common/core/mesh.hpp"
#include "common/core/textures.hpp"
#include "common/gl/render.hpp"
#include "common/core/torus.hpp"
#include "demos/bump_mapping/bump_mapping_math.hpp"
#include "demos/cylinder_seam/cylinder_seam_measure.hpp"
#include "demos/torus/torus_measure.hpp"
#include "demos/wrap_modes/wrap_modes_math.hpp"
#include "exercises/exercise.hpp"
#include "reference/raster.hpp"

namespace exercise_check {
namespace {
// A value the checked code returned that is no number.
struct NotANumber : std::runtime_error {
  using std::runtime_error::runtime_error;
};
double finite(double v, const std::string& call) {
  if (!std::isfinite(v)) throw NotANumber(call + " returned " + (std::isnan(v) ? "NaN" : "infinity"));
  return v;
}

// One check's line: what was measured, what was expected, pass or fail.
bool line(bool pass, const std::string& text) {
  std::printf("  %s: %s\n", text.c_str(), pass ? "pass" : "FAIL");
  return pass;
}
std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// The picture: yours | reference | difference (red where a channel differs
// by more than 1), side by side; returns the differing pixels' count.
// `counted` (may be null): which pixels count as differing, when the
// check decides it (ties a verifier accepts), row by row.
int comparison(const ts::Image& mine, const ts::Image& ref, const std::string& path,
               const std::vector<bool>* counted = nullptr) {
  const int w = ref.width, h = ref.height;
  ts::Image out(3 * w + 16, h, {30, 30, 34, 255}), diff(w, h, {0, 0, 0, 255});
  int differing = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const ts::Rgba a = x < mine.width && y < mine.height ? mine.at(x, y) : ts::Rgba{0, 0, 0, 255}, b = ref.at(x, y);
      const bool differs = counted ? bool((*counted)[size_t(y) * size_t(w) + size_t(x)])
                                   : std::abs(a.r - b.r) > 1 || std::abs(a.g - b.g) > 1 || std::abs(a.b - b.b) > 1;
      differing += differs;
      diff.set(x, y,
               differs ? ts::Rgba{255, 40, 40, 255}
                       : ts::Rgba{uint8_t(b.r / 4), uint8_t(b.g / 4), uint8_t(b.b / 4), 255});
    }
  out.blit(mine, 0, 0), out.blit(ref, w + 8, 0), out.blit(diff, 2 * w + 16, 0);
  ts::writePng(path, out);
  std::printf("  picture: %s (yours | reference | difference: %d pixels differ)\n", path.c_str(), differing);
  return differing;
}

// A mesh drawn with `texture` at 256 x 256 through `projection` and `modelview`.
ts::Image meshPicture(ts::Renderer& r, const ts::Mesh& mesh, const ts::TextureDesc& texture,
                      const glm::mat4& projection, const glm::mat4& modelview) {
  ts::Frame f = ts::layout::blankFrame(256, 256);
  ts::Panel p;
  p.id = "picture";
  p.viewport = {0, 0, 256, 256};
  p.projection = projection, p.modelview = modelview, p.depthTest = true;
  ts::Batch b = ts::meshBatch(mesh, f.addTexture(texture));
  b.texEnv = GL_REPLACE;
  p.batches.push_back(b);
  f.panels.push_back(p);
  return r.renderOffscreen(f);
}

// Exercise VI.1: cylinder_seam's measurement (cylinder_seam_measure.hpp) of a
// cylinder whose columns get the checked s, at 6 and 10 slices (a patch
// centred on θ = 180° in both).
bool checkBackSeam(const Functions& fn, ts::Renderer& r, const std::string& picture) {
  bool ok = true;
  for (int slices : {6, 10}) {
    cylinder::Params cp;
    cp.slices = slices;
    cp.sOfTheta = [&](double th) { return finite(fn.cylinderS(th), "cylinderS(" + fmt("%g", th) + ")"); };
    const std::vector<cylinder::PatchResult> res = cylinder::measurePatches(r, cp);
    // The patch where the texture's edges meet: the one whose s, as the
    // render shows it, passes a whole number inside it.
    std::vector<int> seams;
    double worstSpan = res[0].span, worstErr = 0;
    for (int k = 0; k < slices; ++k) {
      const double a = cylinder::sOf(cp, k), b = a + res[size_t(k)].span;
      if (std::floor(std::min(a, b) + 1e-9) != std::floor(std::max(a, b) - 1e-9)) seams.push_back(k);
      if (std::abs(res[size_t(k)].span - 1.0 / slices) > std::abs(worstSpan - 1.0 / slices))
        worstSpan = res[size_t(k)].span;
      worstErr = std::max(worstErr, res[size_t(k)].texelErr);
    }
    const std::string n = std::to_string(slices) + " slices: ";
    if (seams.size() == 1) {
      const double centre = std::fmod(cylinder::thetaDeg(slices, seams[0]) + 180.0 / slices + 360.0, 360.0);
      ok &= line(std::abs(centre - 180.0) < 1e-6,
                 n + "the texture's edges meet in the patch at theta = " + fmt("%.1f", centre) + " deg, expected 180");
    } else {
      ok &= line(false, n + "the texture's edges meet in " + std::to_string(seams.size()) +
                            " patches, expected 1 (at theta = 180 deg)");
    }
    ok &= line(std::abs(worstSpan - 1.0 / slices) < 0.01,
               n + "every patch forwards: the worst shows ds = " + fmt("%+.4f", worstSpan) + ", expected " +
                   fmt("%+.4f", 1.0 / slices) + " each");
    ok &= line(worstErr < 1.5, n + "the render shows the s given: largest error " + fmt("%.2f", worstErr) +
                                   " texels of 2048, expected < 1.5");
  }
  // The picture: the cylinder from behind (the seam's side), yours and the suite's.
  cylinder::Params mine, ref;
  mine.slices = ref.slices = 10;
  mine.sOfTheta = [&](double th) { return finite(fn.cylinderS(th), "cylinderS"); };
  const Functions sol = reference(Impl::Solution);
  ref.sOfTheta = sol.cylinderS;
  const glm::mat4 proj = glm::perspective(glm::radians(40.0f), 1.0f, 0.5f, 20.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 1.2f, -4.5f), glm::vec3(0), glm::vec3(0, 1, 0));
  const ts::TextureDesc label = ts::labelledGrid(512, 8);
  comparison(meshPicture(r, cylinder::mesh(mine), label, proj, view),
             meshPicture(r, cylinder::mesh(ref), label, proj, view), picture);
  return ok;
}

// The torus demo's default camera (torus.cpp: tilt 35 deg, turn 0).
glm::mat4 torusModelview(const torus::Params& p) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -float(torus::eyeDistance(p))));
  return glm::rotate(m, glm::radians(35.0f), glm::vec3(1, 0, 0));
}

// Exercise VI.2: the torus demo's measurement (torus_measure.hpp).
bool checkTorusFront(const Functions& fn, ts::Renderer& r, const std::string& picture) {
  torus::Params tp;
  tp.stOfAngles = [&](double th, double ph) {
    const glm::dvec2 st = fn.torusST(th, ph);
    const std::string call = "torusST(" + fmt("%g", th) + ", " + fmt("%g", ph) + ")";
    return glm::dvec2(finite(st.x, call), finite(st.y, call));
  };
  const glm::mat4 proj = glm::perspective(glm::radians(35.0f), 1.0f, 0.5f, 20.0f);
  const torus::Found fd = torus::find(r, tp, proj, torusModelview(tp));
  const glm::dvec3 want(0.0, 0.0, tp.R + tp.r);
  bool ok = line(fd.visible, std::string("the texture centre (1/2, 1/2) is seen in the render from the front: ") +
                                 (fd.visible ? "yes" : "no") + ", expected yes");
  const double d = fd.visible ? glm::distance(fd.point, want) : std::numeric_limits<double>::infinity();
  ok &= line(d <= 0.01, "it lands at (" + fmt("%.3f", fd.point.x) + ", " + fmt("%.3f", fd.point.y) + ", " +
                            fmt("%.3f", fd.point.z) + "), expected (0, 0, " + fmt("%.1f", want.z) +
                            ") = R + r on the z axis: distance " + (fd.visible ? fmt("%.4f", d) : "-") +
                            ", within 0.01");
  torus::Params ref;
  ref.mapping = torus::Mapping::Front;
  const ts::TextureDesc checker = ts::labelledGrid(512, 8);
  comparison(meshPicture(r, torus::mesh(tp), checker, proj, torusModelview(tp)),
             meshPicture(r, torus::mesh(ref), checker, proj, torusModelview(ref)), picture);
  return ok;
}

// The image GL draws: a screen-aligned quad with `texture`, GL_NEAREST,
// its row 0 at the top (t = 0 up there), at w x h.
ts::Image glBlit(ts::Renderer& r, const ts::TextureDesc& texture, int w, int h) {
  ts::Frame f = ts::layout::blankFrame(w, h);
  ts::Panel p = ts::layout::unitPanel("quad", {0, 0, w, h});
  ts::TextureDesc t = texture;
  t.minFilter = t.magFilter = GL_NEAREST;
  ts::Batch b;
  b.role = "quad";
  b.texture = f.addTexture(t);
  b.texEnv = GL_REPLACE;
  for (glm::vec2 c :
       {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 0), glm::vec2(1, 1), glm::vec2(0, 1)})
    b.vertices.push_back({glm::vec3(c, 0.0f), glm::vec4(c.x, 1.0f - c.y, 0.0f, 1.0f), glm::vec4(1.0f)});
  p.batches.push_back(b);
  f.panels.push_back(p);
  return r.renderOffscreen(f);
}
// How many texel columns take 1 pixel, 2 pixels, ... along row 0 of an
// image of texel indices.
std::map<int, int> pixelsPerColumn(const ts::Image& img, int texels) {
  std::vector<int> count(size_t(texels), 0);
  for (int x = 0; x < img.width; ++x) {
    int i = 0, j = 0;
    ts::decodeTexelIndex(img.at(x, 0), &i, &j);
    if (i >= 0 && i < texels) ++count[size_t(i)];
  }
  std::map<int, int> out;
  for (int c : count) ++out[c];
  return out;
}

// Seed 002's lab, task 1: the student's blit against GL's GL_NEAREST quad.
bool checkBlit(const Functions& fn, ts::Renderer& r, const std::string& picture) {
  const ts::TextureDesc tex = ts::texelIndexTexture(256);
  bool ok = true;
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{300, 200}, {512, 512}, {200, 300}}) {
    const std::string n = std::to_string(w) + "x" + std::to_string(h) + ": ";
    const ts::Image mine = fn.blit(*tex.image, w, h), gl = glBlit(r, tex, w, h);
    if (mine.width != w || mine.height != h) {
      ok &= line(false, n + "your image is " + std::to_string(mine.width) + "x" + std::to_string(mine.height) +
                            ", expected " + std::to_string(w) + "x" + std::to_string(h));
      continue;
    }
    // A pixel differs when its texel is not GL's, except at a tie: where the
    // pixel centre's texel coordinate (x + 1/2) 256 / w is a whole number,
    // GL may take either neighbour (its interpolation is in float), and so
    // may you.
    auto tie = [](int x, int size) { return (2 * x + 1) * 256 % (2 * size) == 0; };
    int differ = 0;
    std::vector<bool> counted(size_t(w) * size_t(h), false);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        int mi = 0, mj = 0, gi = 0, gj = 0;
        ts::decodeTexelIndex(mine.at(x, y), &mi, &mj);
        ts::decodeTexelIndex(gl.at(x, y), &gi, &gj);
        const bool iOk = mi == gi || (tie(x, w) && std::abs(mi - gi) == 1);
        const bool jOk = mj == gj || (tie(y, h) && std::abs(mj - gj) == 1);
        counted[size_t(y) * size_t(w) + size_t(x)] = mine.at(x, y).a != 255 || !(iOk && jOk);
        differ += counted[size_t(y) * size_t(w) + size_t(x)];
      }
    ok &= line(differ == 0, n + std::to_string(differ) + " pixels differ from GL_NEAREST's, expected 0");
    // The counts along a row, against the closed form: pixel x shows texel
    // floor((2x + 1) 256 / 2w), in integers.
    std::map<int, int> want;
    {
      std::vector<int> per(256, 0);
      for (int x = 0; x < w; ++x) ++per[size_t((2 * x + 1) * 256 / (2 * w))];
      for (int c : per) ++want[c];
    }
    std::map<int, int> m = pixelsPerColumn(mine, 256);
    if (w == 300) {
      ok &= line(m[2] == want[2], "across 300 pixels " + std::to_string(m[2]) +
                                      " texel columns take 2 pixels, expected " + std::to_string(want[2]));
      ok &= line(m[1] == want[1],
                 "across 300 pixels " + std::to_string(m[1]) + " take 1, expected " + std::to_string(want[1]));
    }
    if (w == 200)
      ok &= line(m[0] == want[0], "across 200 pixels " + std::to_string(m[0]) +
                                      " texel columns are never shown, expected " + std::to_string(want[0]));
    if (w == 300) comparison(mine, gl, picture, &counted);
  }
  return ok;
}

// Seed 002's MIRROR: the student's texel against GL_MIRRORED_REPEAT's, read
// from points drawn one per pixel at exactly the coordinates checked.
bool checkMirror(const Functions& fn, ts::Renderer& r, const std::string& picture) {
  bool ok = true;
  ts::Image strips(1000, 2 * 24 + 8, {30, 30, 34, 255}), glStrips = strips;
  int row = 0;
  for (int size : {8, 37}) {
    std::vector<double> between, integers;
    for (int k = 0; k < 1000; ++k) between.push_back(-3.0 + 6.0 * (k + 0.5) / 1000.0);  // never an integer
    for (int k = -3; k <= 3; ++k) integers.push_back(k);
    // Just beside the integers (1e-4: far above float's precision at |s| <= 3).
    for (double s : {-2.0, -1.0, 1.0, 2.0}) between.push_back(s + 1e-4), between.push_back(s - 1e-4);
    for (const auto* set : {&between, &integers}) {
      const std::vector<double>& ss = *set;
      const int w = int(ss.size());
      ts::Frame f = ts::layout::blankFrame(w, 1);
      ts::Panel p = ts::layout::unitPanel("points", {0, 0, w, 1});
      ts::TextureDesc t = ts::texelIndexTexture(size);
      t.minFilter = t.magFilter = GL_NEAREST;
      t.wrapS = GL_MIRRORED_REPEAT;
      ts::Batch b;
      b.role = "samples";
      b.prim = ts::Prim::Points;
      b.texture = f.addTexture(t);
      b.texEnv = GL_REPLACE;
      for (int k = 0; k < w; ++k)
        b.vertices.push_back({glm::vec3((k + 0.5f) / float(w), 0.5f, 0.0f),
                              glm::vec4(float(ss[size_t(k)]), 0.5f / size, 0.0f, 1.0f), glm::vec4(1.0f)});
      p.batches.push_back(b);
      f.panels.push_back(p);
      const ts::Image gl = r.renderOffscreen(f);
      int mismatches = 0;
      for (int k = 0; k < w; ++k) {
        int gi = 0, gj = 0;
        ts::decodeTexelIndex(gl.at(k, 0), &gi, &gj);
        const int mine = fn.mirrorTexel(ss[size_t(k)], size);
        if (mine < 0 || mine >= size)
          throw std::runtime_error("mirrorTexel(" + fmt("%g", ss[size_t(k)]) + ", " + std::to_string(size) +
                                   ") returned " + std::to_string(mine) + ", outside 0.." + std::to_string(size - 1));
        // At a texel boundary (s size a whole number, but s not: the
        // integers are checked apart) GL's float arithmetic may take either
        // texel, and so may you.
        const double u = ss[size_t(k)] * size, sNow = ss[size_t(k)];
        const bool tie = set == &between && std::abs(u - std::round(u)) < 1e-6;
        const int lo = wrap::nearestTexel(GL_MIRRORED_REPEAT, sNow - 1e-7, size),
                  hi = wrap::nearestTexel(GL_MIRRORED_REPEAT, sNow + 1e-7, size);
        const bool accepted = mine == gi || (tie && (mine == lo || mine == hi));
        mismatches += !accepted;
        if (accepted) gi = mine;            // the picture shows what counts
        if (set == &between && k < 1000) {  // the picture: a grey level per texel, yours over GL's
          const uint8_t a = uint8_t(255 * mine / (size - 1)), g = uint8_t(255 * gi / (size - 1));
          for (int y = 0; y < 24; ++y)
            strips.set(k, row * 32 + y, {a, a, a, 255}), glStrips.set(k, row * 32 + y, {g, g, g, 255});
        }
      }
      ok &= line(mismatches == 0,
                 std::to_string(size) + " texels, " +
                     (set == &between ? std::to_string(w) + " coordinates from -3 to 3 between integers"
                                      : std::string("the 7 integers s = -3..3")) +
                     ": " + std::to_string(mismatches) + " texels differ from GL_MIRRORED_REPEAT's, expected 0");
    }
    ++row;
  }
  comparison(strips, glStrips, picture);
  return ok;
}

// Seed 002's scanline texturer: the student's plots against the suite's CPU
// rasterizer (reference/raster.hpp, OpenGL's fill rule) on four cases.
struct ScanCase {
  const char* name;
  std::vector<std::array<exercise::ScanVertex, 3>> triangles;
};
bool checkScanline(const Functions& fn, ts::Renderer&, const std::string& picture) {
  using exercise::ScanVertex;
  auto st = [](double x, double y) { return ScanVertex{x, y, x / 64.0, y / 64.0}; };
  const std::vector<ScanCase> cases = {
      {"seed 002's triangle (8,4) (56,20) (20,60)",
       {{ScanVertex{8, 4, 0, 0}, ScanVertex{56, 20, 1, 0}, ScanVertex{20, 60, 0, 1}}}},
      {"a flat-top triangle (8,8) (56,8) (30,50)", {{st(8, 8), st(56, 8), st(30, 50)}}},
      {"a flat-bottom triangle (30,6) (8,50) (56,50)", {{st(30, 6), st(8, 50), st(56, 50)}}},
      {"two triangles sharing the edge (56,8)-(8,56)",
       {{st(8, 8), st(56, 8), st(8, 56)}, {st(56, 8), st(56, 56), st(8, 56)}}},
  };
  constexpr int S = 64, Z = 3;
  ts::Image mineAll(4 * S * Z, S * Z, {0, 0, 0, 255}), refAll = mineAll;
  std::vector<bool> counted(size_t(4 * S * Z) * size_t(S * Z), false);
  bool ok = true;
  for (size_t c = 0; c < cases.size(); ++c) {
    std::vector<int> count(S * S, 0), refCount(S * S, 0);
    std::vector<glm::dvec2> mineST(S * S), refST(S * S);
    long outside = 0, plotted = 0;
    for (const auto& tri : cases[c].triangles) {
      fn.scanline(tri.data(), [&](int x, int y, double s, double t) {
        if (++plotted > 1000000) throw std::runtime_error("scanlineTriangle plotted more than a million pixels");
        if (x < 0 || y < 0 || x >= S || y >= S) return void(++outside);
        count[size_t(y * S + x)]++;
        mineST[size_t(y * S + x)] = {finite(s, "plot's s"), finite(t, "plot's t")};
      });
      ref::ScreenVertex r[3];
      for (int k = 0; k < 3; ++k)
        r[k].x = tri[size_t(k)].x, r[k].y = tri[size_t(k)].y, r[k].a[0] = tri[size_t(k)].s,
        r[k].a[1] = tri[size_t(k)].t;
      ref::scanTriangle(r[0], r[1], r[2], 2, {0, 0, S, S}, ref::FillRule::GLTopLeft,
                        [&](int x, int y, const double* a) {
                          refCount[size_t(y * S + x)]++;
                          refST[size_t(y * S + x)] = {a[0], a[1]};
                        });
    }
    long missing = 0, extra = outside, other = 0, twice = 0;
    for (int p = 0; p < S * S; ++p) {
      const int m = count[size_t(p)], g = refCount[size_t(p)];
      missing += m == 0 && g > 0;
      extra += m > 0 && g == 0;
      twice += m > 1;
      const bool sameST = m == 0 || g == 0 || glm::length(mineST[size_t(p)] - refST[size_t(p)]) <= 1e-6;
      other += !sameST;
      const bool bad = (m == 0) != (g == 0) || m > 1 || !sameST;
      // The picture: (s, t) as red and green, three times the size; blue where covered twice.
      auto colour = [](int n, glm::dvec2 v) {
        return n == 0 ? ts::Rgba{0, 0, 0, 255}
                      : ts::Rgba{uint8_t(std::clamp(v.x, 0.0, 1.0) * 255), uint8_t(std::clamp(v.y, 0.0, 1.0) * 255),
                                 uint8_t(n > 1 ? 255 : 60), 255};
      };
      for (int dy = 0; dy < Z; ++dy)
        for (int dx = 0; dx < Z; ++dx) {
          const int X = int(c) * S * Z + (p % S) * Z + dx, Y = (p / S) * Z + dy;
          mineAll.set(X, Y, colour(m, mineST[size_t(p)]));
          refAll.set(X, Y, colour(g, refST[size_t(p)]));
          counted[size_t(Y) * size_t(4 * S * Z) + size_t(X)] = bad;
        }
    }
    ok &= line(missing + extra + other + twice == 0, std::string(cases[c].name) + ": " + std::to_string(missing) +
                                                         " pixels missing, " + std::to_string(extra) + " extra, " +
                                                         std::to_string(other) + " with other (s,t), " +
                                                         std::to_string(twice) + " covered twice; expected 0");
  }
  comparison(mineAll, refAll, picture, &counted);
  return ok;
}

// The cube's faces: outward normal, up (the texture's top), right = up x n.
struct Face {
  const char* name;
  glm::dvec3 n, up;
  glm::dvec3 right() const { return glm::cross(up, n); }
};
const Face kFaces[6] = {{"+X", {1, 0, 0}, {0, 1, 0}},  {"-X", {-1, 0, 0}, {0, 1, 0}}, {"+Y", {0, 1, 0}, {0, 0, -1}},
                        {"-Y", {0, -1, 0}, {0, 0, 1}}, {"+Z", {0, 0, 1}, {0, 1, 0}},  {"-Z", {0, 0, -1}, {0, 1, 0}}};

// Seed 002's task 2: each face drawn head-on from outside, (s, t) read at
// (+-0.9, +-0.9) of its right and up axes from a texel-index render.
bool checkCube(const Functions& fn, ts::Renderer& r, const std::string& picture) {
  constexpr int S = 128;
  const ts::TextureDesc tex = ts::texelIndexTexture(256);
  const ts::TextureDesc label = ts::labelledGrid(256, 4);
  bool ok = true;
  ts::Image mineAll(6 * S, S), refAll(6 * S, S);
  const Functions sol = reference(Impl::Solution);
  for (int f = 0; f < 6; ++f) {
    const Face& face = kFaces[f];
    auto draw = [&](const ts::TextureDesc& t, const std::function<glm::dvec2(int, glm::dvec3)>& st) {
      ts::Frame fr = ts::layout::blankFrame(S, S);
      ts::Panel p;
      p.id = std::string("face_") + face.name;
      p.viewport = {0, 0, S, S};
      p.projection = glm::ortho(-1.2f, 1.2f, -1.2f, 1.2f, 0.5f, 10.0f);
      p.modelview = glm::lookAt(glm::vec3(3.0 * face.n), glm::vec3(0.0f), glm::vec3(face.up));
      ts::Batch b;
      b.role = "face";
      b.texture = fr.addTexture(t);
      b.texEnv = GL_REPLACE;
      const glm::dvec3 c[4] = {face.n - face.right() - face.up, face.n + face.right() - face.up,
                               face.n + face.right() + face.up, face.n - face.right() + face.up};
      glm::dvec2 v[4];
      for (int k = 0; k < 4; ++k) {
        v[k] = st(f, c[k]);
        finite(v[k].x, "cubeST"), finite(v[k].y, "cubeST");
      }
      for (int k : {0, 1, 2, 0, 2, 3})
        b.vertices.push_back({glm::vec3(c[k]), glm::vec4(float(v[k].x), float(v[k].y), 0.0f, 1.0f), glm::vec4(1.0f)});
      p.batches.push_back(b);
      fr.panels.push_back(p);
      return r.renderOffscreen(fr);
    };
    const ts::Image img = draw(tex, fn.cubeST);
    // (a, b) on the face -> its pixel: x from -1.2 to 1.2 across, y down.
    auto read = [&](double a, double b) {
      const int x = int((a + 1.2) / 2.4 * S), y = int((1.2 - b) / 2.4 * S);
      int i = 0, j = 0;
      ts::decodeTexelIndex(img.at(x, y), &i, &j);
      return glm::dvec2((i + 0.5) / 256, (j + 0.5) / 256);
    };
    const glm::dvec2 bl = read(-0.9, -0.9), br = read(0.9, -0.9), tr = read(0.9, 0.9), tl = read(-0.9, 0.9);
    const double err = std::max({glm::length(bl - glm::dvec2(0.05, 0.05)), glm::length(br - glm::dvec2(0.95, 0.05)),
                                 glm::length(tr - glm::dvec2(0.95, 0.95)), glm::length(tl - glm::dvec2(0.05, 0.95))});
    std::string how = "";
    if (br.x < bl.x) how = " (mirrored left-right)";
    else if (tl.y < bl.y) how = " (upside down)";
    else if (std::abs(tl.x - bl.x) > 0.3 || std::abs(br.y - bl.y) > 0.3) how = " (turned)";
    char b[240];
    std::snprintf(
        b, sizeof b,
        "face %s: (s,t) near its corners (%.2f,%.2f) (%.2f,%.2f) (%.2f,%.2f) (%.2f,%.2f)%s, expected (0.05,0.05) "
        "(0.95,0.05) (0.95,0.95) (0.05,0.95) within 0.02",
        face.name, bl.x, bl.y, br.x, br.y, tr.x, tr.y, tl.x, tl.y, how.c_str());
    ok &= line(err <= 0.02, b);
    mineAll.blit(draw(label, fn.cubeST), f * S, 0);
    refAll.blit(draw(label, sol.cubeST), f * S, 0);
  }
  comparison(mineAll, refAll, picture);
  return ok;
}

// Seed 002's task 3: the planar wrap against the corrected formulas, at
// 1,000 points along each axis (scale 0.75, a centre off the origin), and a
// sphere drawn with the wrap per vertex against the same sphere drawn with
// GL_OBJECT_LINEAR texgen whose planes are the corrected formulas'
// (Batch::texGen), both through a texel-index texture.
bool checkPlanarWrap(const Functions& fn, ts::Renderer& r, const std::string& picture) {
  const Functions sol = reference(Impl::Solution);
  const glm::dvec3 c(0.1, -0.2, 0.3);
  const double k = 0.75;
  bool ok = true;
  uint32_t seed = 12345;
  auto rnd = [&]() { return (seed = seed * 1664525u + 1013904223u) / 4294967296.0 * 4.0 - 2.0; };
  ts::Image mineAll(3 * 160, 160), glAll(3 * 160, 160);
  std::vector<bool> counted(size_t(3 * 160) * 160, false);
  for (int axis = 0; axis < 3; ++axis) {
    int mismatches = 0;
    double worst = 0;
    for (int n = 0; n < 1000; ++n) {
      const glm::dvec3 p(rnd(), rnd(), rnd());
      const glm::dvec2 m = fn.planarWrap(p, axis, k, c), want = sol.planarWrap(p, axis, k, c);
      finite(m.x, "planarWrap"), finite(m.y, "planarWrap");
      const double d = glm::length(m - want);
      worst = std::max(worst, d);
      mismatches += d > 1e-9;
    }
    const std::string name = std::string("along ") + "XYZ"[axis];
    ok &= line(mismatches == 0, name + ": " + std::to_string(mismatches) +
                                    " of 1000 points differ from the corrected formula " + "(largest " +
                                    fmt("%.3f", worst) + "), expected 0");
    // The sphere, per vertex (yours) and by GL_OBJECT_LINEAR texgen.
    const ts::Mesh sphere = ts::parametricGrid(
        48, 24, true, false, [](int i, int j) { return ts::spherePoint(1.0, 48, 24, i, j); },
        [&](int i, int j) { return fn.planarWrap(ts::spherePoint(1.0, 48, 24, i % 48, j).pos, axis, k, c); });
    auto draw = [&](bool texgen) {
      ts::Frame f = ts::layout::blankFrame(160, 160);
      ts::Panel p;
      p.id = "sphere";
      p.viewport = {0, 0, 160, 160};
      p.projection = glm::perspective(glm::radians(40.0f), 1.0f, 0.5f, 20.0f);
      p.modelview = glm::lookAt(glm::vec3(2.2f, 1.6f, 2.6f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
      p.depthTest = true;
      ts::Batch b = ts::meshBatch(sphere, f.addTexture(ts::texelIndexTexture(256)));
      b.texEnv = GL_REPLACE;
      if (texgen) {  // s = plane_s . (x, y, z, 1), t = plane_t . (x, y, z, 1)
        const float kf = float(k);
        const glm::vec4 planes[3][2] = {{{0, 0, kf, -float(c.z)}, {0, kf, 0, -float(c.y)}},
                                        {{kf, 0, 0, -float(c.x)}, {0, 0, kf, -float(c.z)}},
                                        {{kf, 0, 0, -float(c.x)}, {0, kf, 0, -float(c.y)}}};
        b.texGen.mode = GL_OBJECT_LINEAR;
        b.texGen.coords = ts::TexGen::S | ts::TexGen::T;
        b.texGen.planes[0] = planes[axis][0], b.texGen.planes[1] = planes[axis][1];
      }
      p.batches.push_back(b);
      f.panels.push_back(p);
      return r.renderOffscreen(f);
    };
    const ts::Image mine = draw(false), gl = draw(true);
    int differ = 0, shown = 0;
    for (int y = 0; y < 160; ++y)
      for (int x = 0; x < 160; ++x) {
        if (gl.at(x, y) == gl.at(0, 0) && mine.at(x, y) == mine.at(0, 0))
          continue;  // the background (the corner's colour)
        ++shown;
        int mi = 0, mj = 0, gi = 0, gj = 0;
        ts::decodeTexelIndex(mine.at(x, y), &mi, &mj);
        ts::decodeTexelIndex(gl.at(x, y), &gi, &gj);
        // The same texel, or its neighbour (per-vertex float coordinates and
        // texgen's float planes round apart at texel edges); 256 wraps.
        auto near = [](int a, int b) {
          const int d = std::abs(a - b) % 256;
          return std::min(d, 256 - d) <= 1;
        };
        const bool bad = !(near(mi, gi) && near(mj, gj));
        differ += bad;
        counted[size_t(y) * 480 + size_t(axis * 160 + x)] = bad;
      }
    mineAll.blit(mine, axis * 160, 0), glAll.blit(gl, axis * 160, 0);
    ok &= line(differ == 0, name + ": the sphere's " + std::to_string(shown) + " pixels, " + std::to_string(differ) +
                                " with another texel than GL_OBJECT_LINEAR texgen's, expected 0");
  }
  comparison(mineAll, glAll, picture, &counted);
  return ok;
}

// GL_SPHERE_MAP: 1,000 points drawn with that texgen, one per pixel, their
// eye-space positions and normals given directly (the modelview is the
// identity), read back through a 2048-texel index texture.
bool checkSphereMap(const Functions& fn, ts::Renderer& r, const std::string& picture) {
  constexpr int W = 40, H = 25, N = 2048;
  std::vector<glm::dvec3> pos, nor;
  uint32_t seed = 777;
  auto rnd = [&]() { return (seed = seed * 1664525u + 1013904223u) / 4294967296.0; };
  for (int k = 0; k < W * H; ++k) {
    const double x = -1.0 + 2.0 * ((k % W) + 0.5) / W, y = -1.0 + 2.0 * ((k / W) + 0.5) / H, z = -2.0 - 4.0 * rnd();
    glm::dvec3 n(rnd() * 2 - 1, rnd() * 2 - 1, rnd() + 0.2);
    pos.push_back({x, y, z}), nor.push_back(glm::normalize(n));
  }
  const ts::TextureDesc tex = ts::texelIndexTexture(N);
  const ts::Image img = r.offscreen(W, H, "the sphere map check", [&](GLuint) {
    glViewport(0, 0, W, H);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_TEXTURE_2D);
    r.texture(tex);  // bound, GL_NEAREST
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glPointSize(1.0f);
    glBegin(GL_POINTS);
    for (size_t k = 0; k < pos.size(); ++k) {
      glNormal3f(float(nor[k].x), float(nor[k].y), float(nor[k].z));
      glVertex3f(float(pos[k].x), float(pos[k].y), float(pos[k].z));
    }
    glEnd();
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_2D);
  });
  int far = 0;
  double worst = 0;
  ts::Image mine(W, H), gl(W, H);
  for (int k = 0; k < W * H; ++k) {
    const int x = k % W, y = H - 1 - k / W;  // the image's row 0 is the top
    int i = 0, j = 0;
    ts::decodeTexelIndex(img.at(x, y), &i, &j);
    const glm::dvec2 got((i + 0.5) / N, (j + 0.5) / N);
    const glm::dvec2 m = fn.sphereMap(pos[size_t(k)], nor[size_t(k)]);
    finite(m.x, "sphereMap"), finite(m.y, "sphereMap");
    const double d = std::max(std::abs(m.x - got.x), std::abs(m.y - got.y)) * N;
    worst = std::max(worst, d);
    far += d > 1.5;
    auto colour = [](glm::dvec2 v) {
      return ts::Rgba{uint8_t(std::clamp(v.x, 0.0, 1.0) * 255), uint8_t(std::clamp(v.y, 0.0, 1.0) * 255), 128, 255};
    };
    mine.set(x, y, colour(m)), gl.set(x, y, colour(got));
  }
  const bool ok = line(far == 0, std::to_string(far) +
                                     " of 1000 points more than 1.5 texels of 2048 from GL_SPHERE_MAP's (s,t) "
                                     "(largest " +
                                     fmt("%.1f", worst) + " texels), expected 0");
  ts::Image big(W * 8, H * 8), bigGl(W * 8, H * 8);
  for (int y = 0; y < H * 8; ++y)
    for (int x = 0; x < W * 8; ++x) big.set(x, y, mine.at(x / 8, y / 8)), bigGl.set(x, y, gl.at(x / 8, y / 8));
  comparison(big, bigGl, picture);
  return ok;
}

// Seed 002's differences as Blinn's normal, measured as bump_mapping
// measures its methods: the angle to the truly displaced surface's normal
// at the same (s, t), on the demo's torus, heights and height scale.
bool checkBumpGradient(const Functions& fn, ts::Renderer&, const std::string&) {
  const bump::Heights H = bump::procedural(256);  // repeated rep = (4, 2) times around
  const double R = 1.0, r = 0.4, scale = 0.04;
  const double ds = 1.0 / (H.w * H.rep.x), dt = 1.0 / (H.h * H.rep.y);
  double sum = 0, worst = 0, tiltSum = 0;
  int n = 0;
  for (int y = 0; y < H.h; y += 8)
    for (int x = 0; x < H.w; x += 8) {
      const glm::dvec2 st((x + 0.5) * ds, (y + 0.5) * dt);
      const ts::TorusFrame f = ts::torusFrameAt(R, r, st);
      const double gx = H.at(x + 1, y) - H.at(x - 1, y), gy = H.at(x, y + 1) - H.at(x, y - 1);
      const glm::dvec3 mine = fn.bumpNormal(f.Qs, f.Qt, gx, gy, ds, dt, scale);
      for (int k = 0; k < 3; ++k) finite(mine[k], "bumpNormal");
      if (glm::length(mine) < 1e-12) throw std::runtime_error("bumpNormal returned the zero vector");
      // The displaced surface Q + P N, P = scale h: its normal from P's
      // derivatives by a fourth-order stencil (the answer's are second-order).
      auto d4 = [&](int dx, int dy) {
        return (-H.at(x + 2 * dx, y + 2 * dy) + 8.0 * H.at(x + dx, y + dy) - 8.0 * H.at(x - dx, y - dy) +
                H.at(x - 2 * dx, y - 2 * dy)) /
               12.0;
      };
      const double P = scale * H.at(x, y), Ps = scale * d4(1, 0) / ds, Pt = scale * d4(0, 1) / dt;
      const glm::dvec3 truth = glm::cross(f.Qs + Ps * f.N + P * f.Ns, f.Qt + Pt * f.N + P * f.Nt);
      const double a = glm::degrees(
          std::acos(std::clamp(glm::dot(glm::normalize(mine), glm::normalize(truth)), -1.0, 1.0)));
      sum += a, worst = std::max(worst, a), ++n;
      tiltSum += glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(truth), f.N), -1.0, 1.0)));
    }
  std::printf("  (the displaced surface's normals lean %.2f deg from the smooth torus's on average)\n", tiltSum / n);
  return line(sum / n <= 1.0, "mean angle to the displaced surface's normal over " + std::to_string(n) +
                                  " texels: " + fmt("%.2f", sum / n) + " deg (largest " + fmt("%.2f", worst) +
                                  "), expected at most 1");
}

[[noreturn]] void crash() {
  std::raise(SIGSEGV);
  std::abort();
}
[[noreturn]] void hang() {
  // Unsigned: it wraps (a signed counter's overflow would be UB, which UBSan
  // turns into a crash instead of the endless loop this stands for).
  for (volatile unsigned spin = 0;; spin = spin + 1u) {
  }
}
}  // namespace

Functions reference(Impl impl) {
  Functions f;
  switch (impl) {
    case Impl::Mine: break;
    case Impl::Solution:
      // cylinder_seam_math.hpp: Exercise VI.1 adds 1/2 (Seam::Back); GL_REPEAT does the rest.
      f.cylinderS = [](double th) { return th / 360.0 + 0.5; };
      // torus_math.hpp: the front mapping adds offset(Mapping::Front) = (1/2, 1/2).
      f.torusST = [](double th, double ph) {
        return glm::dvec2(th, ph) / 360.0 + torus::offset(torus::Mapping::Front);
      };
      // wrap_modes_math.hpp: GL_NEAREST's texel at s = (x + 1/2) / w, t = (y + 1/2) / h.
      f.blit = [](const ts::Image& t, int w, int h) {
        ts::Image out(w, h);
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x)
            out.set(x, y,
                    t.at(wrap::nearestTexel(GL_CLAMP_TO_EDGE, (x + 0.5) / w, t.width),
                         wrap::nearestTexel(GL_CLAMP_TO_EDGE, (y + 0.5) / h, t.height)));
        return out;
      };
      f.mirrorTexel = [](double s, int size) { return wrap::nearestTexel(GL_MIRRORED_REPEAT, s, size); };
      // reference/raster.hpp: the seed's algorithm made to follow OpenGL's rules.
      f.scanline = [](const exercise::ScanVertex* v, const exercise::Plot& plot) {
        ref::ScreenVertex r[3];
        for (int k = 0; k < 3; ++k) r[k].x = v[k].x, r[k].y = v[k].y, r[k].a[0] = v[k].s, r[k].a[1] = v[k].t;
        ref::scanTriangle(r[0], r[1], r[2], 2, {-4096, -4096, 4096, 4096}, ref::FillRule::GLTopLeft,
                          [&](int x, int y, const double* a) { plot(x, y, a[0], a[1]); });
      };
      // Each face's own planar map: s along its right, t along its up (Buss: 24 vertices).
      f.cubeST = [](int face, glm::dvec3 c) {
        const Face& fc = kFaces[face];
        return glm::dvec2(glm::dot(c, fc.right()) + 1, glm::dot(c, fc.up) + 1) / 2.0;
      };
      // Seed 002's planar wraps, along Z corrected (tv from y, not x).
      f.planarWrap = [](glm::dvec3 p, int axis, double s, glm::dvec3 c) {
        if (axis == 0) return glm::dvec2(s * p.z - c.z, s * p.y - c.y);
        if (axis == 1) return glm::dvec2(s * p.x - c.x, s * p.z - c.z);
        return glm::dvec2(s * p.x - c.x, s * p.y - c.y);
      };
      // OpenGL 2.1 §2.12.4: u = the unit vector to the vertex, r = u - 2 n (n . u).
      f.sphereMap = [](glm::dvec3 e, glm::dvec3 n) {
        const glm::dvec3 u = glm::normalize(e), rf = u - 2.0 * glm::dot(n, u) * n;
        const double m = 2.0 * std::sqrt(rf.x * rf.x + rf.y * rf.y + (rf.z + 1) * (rf.z + 1));
        return glm::dvec2(rf.x / m + 0.5, rf.y / m + 0.5);
      };
      // bump_mapping_gl.hpp's B1: P_s, P_t from the central differences, then seed 004's (Blinn's) form.
      f.bumpNormal = [](glm::dvec3 Qs, glm::dvec3 Qt, double gx, double gy, double ds, double dt, double scale) {
        const double Ps = scale * gx / (2 * ds), Pt = scale * gy / (2 * dt);
        const glm::dvec3 nv = glm::cross(Qs, Qt);
        const double len = glm::length(nv);
        return nv + Ps * glm::cross(nv, Qt) / len + Pt * glm::cross(Qs, nv) / len;
      };
      break;
    case Impl::Wrong:
      // The book's own s = θ/360: the seam stays at the front.
      f.cylinderS = [](double th) { return th / 360.0; };
      // s moved, t = φ/360 unchanged: the centre lands at φ = 180°, inside.
      f.torusST = [](double th, double ph) { return glm::dvec2(th / 360.0 + 0.5, ph / 360.0); };
      // The pixel's corner, not its centre: texel floor(x · 256 / w).
      f.blit = [](const ts::Image& t, int w, int h) {
        ts::Image out(w, h);
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) out.set(x, y, t.at(x * t.width / w, y * t.height / h));
        return out;
      };
      // Seed 002's program as printed.
      f.mirrorTexel = [](double s, int size) { return wrap::seedMirrorTexel(s, size); };
      // No fill rule: every centre on an edge is in, so a shared edge is drawn twice.
      f.scanline = [](const exercise::ScanVertex* v, const exercise::Plot& plot) {
        auto edge = [&](int a, int b, double x, double y) {
          return (v[b].x - v[a].x) * (y - v[a].y) - (v[b].y - v[a].y) * (x - v[a].x);
        };
        const double area = edge(0, 1, v[2].x, v[2].y);
        for (int y = 0; y < 64; ++y)
          for (int x = 0; x < 64; ++x) {
            const double w0 = edge(1, 2, x + 0.5, y + 0.5) / area, w1 = edge(2, 0, x + 0.5, y + 0.5) / area,
                         w2 = edge(0, 1, x + 0.5, y + 0.5) / area;
            if (w0 >= 0 && w1 >= 0 && w2 >= 0)
              plot(x, y, w0 * v[0].s + w1 * v[1].s + w2 * v[2].s, w0 * v[0].t + w1 * v[1].t + w2 * v[2].t);
          }
      };
      // One projection along Z for every face, as for a flat picture.
      f.cubeST = [](int, glm::dvec3 c) { return glm::dvec2(c.x + 1, c.y + 1) / 2.0; };
      // Seed 002's planar wrap as printed: along Z, tv from x.
      f.planarWrap = [](glm::dvec3 p, int axis, double s, glm::dvec3 c) {
        if (axis == 0) return glm::dvec2(s * p.z - c.z, s * p.y - c.y);
        if (axis == 1) return glm::dvec2(s * p.x - c.x, s * p.z - c.z);
        return glm::dvec2(s * p.x - c.x, s * p.x - c.y);
      };
      // Seed 002's sphere map: from the normal alone.
      f.sphereMap = [](glm::dvec3, glm::dvec3 n) { return glm::dvec2(n.x / 2 + 0.5, n.y / 2 + 0.5); };
      // The differences added to the unit normal as they are, along the unit tangents (no texel size, no scale).
      f.bumpNormal = [](glm::dvec3 Qs, glm::dvec3 Qt, double gx, double gy, double, double, double) {
        return glm::normalize(glm::cross(Qs, Qt)) + gx * glm::normalize(Qs) + gy * glm::normalize(Qt);
      };
      break;
    case Impl::Crash:
      f.cylinderS = [](double) -> double { crash(); };
      f.torusST = [](double, double) -> glm::dvec2 { crash(); };
      f.blit = [](const ts::Image&, int, int) -> ts::Image { crash(); };
      f.mirrorTexel = [](double, int) -> int { crash(); };
      f.scanline = [](const exercise::ScanVertex*, const exercise::Plot&) { crash(); };
      f.cubeST = [](int, glm::dvec3) -> glm::dvec2 { crash(); };
      f.planarWrap = [](glm::dvec3, int, double, glm::dvec3) -> glm::dvec2 { crash(); };
      f.sphereMap = [](glm::dvec3, glm::dvec3) -> glm::dvec2 { crash(); };
      f.bumpNormal = [](glm::dvec3, glm::dvec3, double, double, double, double, double) -> glm::dvec3 { crash(); };
      break;
    case Impl::Hang:
      f.cylinderS = [](double) -> double { hang(); };
      f.torusST = [](double, double) -> glm::dvec2 { hang(); };
      f.blit = [](const ts::Image&, int, int) -> ts::Image { hang(); };
      f.mirrorTexel = [](double, int) -> int { hang(); };
      f.scanline = [](const exercise::ScanVertex*, const exercise::Plot&) { hang(); };
      f.cubeST = [](int, glm::dvec3) -> glm::dvec2 { hang(); };
      f.planarWrap = [](glm::dvec3, int, double, glm::dvec3) -> glm::dvec2 { hang(); };
      f.sphereMap = [](glm::dvec3, glm::dvec3) -> glm::dvec2 { hang(); };
      f.bumpNormal = [](glm::dvec3, glm::dvec3, double, double, double, double, double) -> glm::dvec3 { hang(); };
      break;
    case Impl::Nan:
      f.cylinderS = [](double) { return std::nan(""); };
      f.torusST = [](double, double) { return glm::dvec2(std::nan("")); };
      f.blit = [](const ts::Image& t, int w, int h) {  // a blit has no number to be NaN: a wrong size
        (void)t;
        return ts::Image(w / 2, h);
      };
      f.mirrorTexel = [](double, int size) { return size * 2; };  // out of range
      f.scanline = [](const exercise::ScanVertex*, const exercise::Plot& plot) { plot(10, 10, std::nan(""), 0.0); };
      f.cubeST = [](int, glm::dvec3) { return glm::dvec2(std::nan("")); };
      f.planarWrap = [](glm::dvec3, int, double, glm::dvec3) { return glm::dvec2(std::nan("")); };
      f.sphereMap = [](glm::dvec3, glm::dvec3) { return glm::dvec2(std::nan("")); };
      f.bumpNormal = [](glm::dvec3, glm::dvec3, double, double, double, double, double) {
        return glm::dvec3(std::nan(""));
      };
      break;
  }
  return f;
}

const std::vector<Exercise>& exercises() {
  static const std::vector<Exercise> all = {
      {"vi1_back_seam", "Buss, Exercise VI.1", "build/bin/cylinder_seam --seam back --coords right", checkBackSeam,
       "build/bin/cylinder_seam --seam mine"},
      {"vi2_torus_front", "Buss, Exercise VI.2", "build/bin/torus --mapping front", checkTorusFront,
       "build/bin/torus --mapping mine"},
      {"lab1_blit", "seed 002, lab task 1", "build/bin/quad_distortion --filter nearest", checkBlit},
      {"mirror_wrap", "seed 002, MIRROR", "build/bin/wrap_modes", checkMirror},
      {"scanline", "seed 002, the scanline texturer", "build/bin/perspective_correction --interp affine",
       checkScanline},
      {"lab2_cube", "seed 002, lab task 2; Buss VI.1.2", "build/bin/quad_distortion", checkCube},
      {"lab3_planar_wrap", "seed 002, lab task 3", "build/bin/sphere_projections", checkPlanarWrap},
      {"sphere_map", "seeds 001, 002; Buss VI.3", "build/bin/environment_mapping", checkSphereMap},
      {"bump_gradient", "seeds 002, 004", "build/bin/bump_mapping", checkBumpGradient},
  };
  return all;
}

const Exercise* find(const std::string& name) {
  for (const Exercise& e : exercises())
    if (name == e.name) return &e;
  return nullptr;
}

std::string namesList() {
  std::string s;
  for (const Exercise& e : exercises()) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s;
}

bool run(const Exercise& ex, const Functions& f, ts::Renderer& r, const std::string& outDir) {
  std::printf("%s (%s, exercises/%s.cpp)\n", ex.name, ex.source, ex.name);
  std::error_code made;  // std::filesystem: Windows' mkdir() takes no mode
  std::filesystem::create_directory(outDir, made);
  bool ok = false;
  try {
    ok = ex.check(f, r, outDir + "/" + ex.name + ".png");
  } catch (const exercise::NotDone& e) {
    (void)e;
    std::printf("%s: FAIL: not done yet (write it in exercises/%s.cpp)\n", ex.name, ex.name);
    return false;
  } catch (const NotANumber& e) {
    std::printf("%s: FAIL: %s\n", ex.name, e.what());
    return false;
  } catch (const std::exception& e) {
    std::printf("%s: FAIL: %s\n", ex.name, e.what());
    return false;
  }
  std::printf("  the reference in a window: %s\n", ex.see);
  if (ex.mine) std::printf("  yours in a window, these checks in its panel: %s\n", ex.mine);
  std::printf("%s: %s\n", ex.name, ok ? "PASS" : "FAIL");
  return ok;
}
}  // namespace exercise_check
