// Lighting from an environment map: the highlights of any number of lights
// from one texture lookup (seed 001 ¶44-45).
//
// The claim (seed 001 ¶44): Gouraud shading loses highlights between
// vertices; an environment map that holds the lighting gives "the highlights
// of any number of light sources at a fixed cost, per pixel".  Phong's
// specular term of directional lights depends on the mirror direction r
// alone,
//   S(r) = sum_k C_k max(0, r.L_k)^n          (n = 32, L_k towards light k)
// so it can be baked into a cube map by direction, texel by texel, and read
// back per pixel by one textureCube(map, r), r = v - 2 (v.n) n (Buss VI.3).
// Against per-pixel Phong with the same lights (a GLSL loop over them) the
// map differs only by its resolution and GL_LINEAR filtering (and 8-bit
// texels); the error falls with the map's size, and the cost stays one
// lookup a pixel whether there are 1, 4 or 16 lights, while Phong makes one
// evaluation a light.  The map is fixed to the world: lights that move mean
// a new map (seed 001 ¶45's "lighting environment map of the whole scene").
//
// Keys (each is also a flag, see --help):
//   n  lights: 1 | 4 | 16
//   m  method: map (one lookup) | phong (a loop over the lights) | diff (|map - phong| x 8)
//   s  the map's size: 16 | 32 | 64 | 128 texels a face's side
//   v  view: single (the method chosen) | grid (every method for 1, 4 and 16 lights)
//
// The equations (env_lighting_math.hpp):
//   the map's texel (face f, i, j):  S(cubeDir(f, (i + 1/2)/N, (j + 1/2)/N)), clamped, 8 bits
//   a pixel, map:    BASE + textureCube(map, r)            1 lookup, 0 light evaluations
//   a pixel, Phong:  BASE + clamp(sum_k C_k pow(max(0, r.L_k), n))   0 lookups, one evaluation a light
//   the error bound: bilinear interpolation over texels h = 2/N radians apart errs by at most
//                    h^2/8 (|f_uu| + |f_vv|) <= 255 C n h^2 / 4 levels (+1 for 8-bit rounding)
//
// What the GL does (common/gl/render.cpp draws the Frame of env_lighting_views.hpp):
//   glGenTextures; glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
//   glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA8, N, N, 0, GL_RGBA, GL_UNSIGNED_BYTE, face f);
//   glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER / _MAG_FILTER, GL_LINEAR);
//   glCreateShader / glShaderSource / glLinkProgram (GLSL 1.20, METHOD and LIGHTS by #define);
//   glUseProgram; glUniform4f(glGetUniformLocation(p, "lightDir[k]"), ...) for Phong's lights;
//   glBegin(GL_TRIANGLES) of glTexCoord4f(normal) + glVertex3f, the sphere.
// Listings: book_figures/env_lighting_lights.gl.txt (the grid), env_lighting_map16.gl.txt.
//
// Measured (env_lighting_measure.hpp): the sphere at 256^2 with the map and
// with Phong, read back, the RMS and largest difference in 8-bit levels over
// the pixels inside its outline, for 1, 4 and 16 lights, at this map size and
// at 32, 128 and 256 texels a face (256: the floor the 8-bit texels and pixels
// leave; the RMS above it, in quadrature, is the interpolation error); the
// largest apart inside the faces (held to the bound) and near their edges,
// where GL_LINEAR clamps to one face; and each program built with COUNT 1,
// which writes the lookups and light evaluations its pixels made: read back,
// not typed.  Found: at 32 texels the largest errors are at the faces' edges
// (10-12 levels against 2-5 inside), a first-order error no bound in h^2 covers.
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/gl/render.hpp"
#include "demos/env_lighting/env_lighting_math.hpp"
#include "demos/env_lighting/env_lighting_measure.hpp"
#include "demos/env_lighting/env_lighting_views.hpp"

namespace {
using namespace envlight;
const char* const kMethodTitles[] = {"one map lookup", "per-pixel Phong", "|map - Phong| x 8"};

class EnvLighting final : public ts::Scene {
 public:
  std::string id() const override { return "env_lighting"; }
  std::string title() const override { return "Lighting from an environment map (seed 001 ¶44-45)"; }
  std::string about() const override {
    return "The specular highlights of 1, 4 or 16 directional lights baked into one cube map by direction, read\n"
           "per pixel by one textureCube at the mirror direction, against per-pixel Phong with the same lights (a\n"
           "GLSL loop).  Measured: the RMS difference in 8-bit levels at two map sizes, and the lookups and light\n"
           "evaluations each pixel makes, counted by the shaders themselves.";
  }
  int defaultWidth() const override { return 640; }
  int defaultHeight() const override { return 600; }
  std::vector<std::string> claim() const override { return {"envlight_rms_levels[16]", "envlight_lookups_per_pixel"}; }
  void addOptions(ts::Options& o) override {
    o.addEnum("lights", &lights_, {"1", "4", "16"}, "the number of directional lights", 'n');
    o.addEnum("method", &method_, {"map", "phong", "diff"},
              "map: one cube-map lookup | phong: a loop over the lights | diff: |map - phong| x 8", 'm');
    o.addEnum("face", &face_, {"16", "32", "64", "128"}, "the lighting map's size: texels along a face's side", 's');
    o.addEnum("view", &view_, {"single", "grid"}, "single: the method chosen | grid: every method, 1, 4, 16 lights",
              'v');
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"env_lighting_lights",
         "Seed 001 ¶44-45 (lighting from an environment map)",
         "The highlights of 1, 4 and 16 directional lights on a sphere (rows), from one lookup in a cube map "
         "of 32 texels a face that holds their specular sum by direction (left), from per-pixel Phong's loop "
         "over the lights (middle), and their difference magnified 8 times (right).",
         {"--view", "grid", "--face", "32"},
         1200,
         1280,
         "one lookup a pixel ({envlight_lookups_per_pixel}) against {phong_light_evaluations_per_pixel[16]} "
         "light evaluations for 16 lights; RMS {envlight_rms_levels[16/32]} levels with a 32-texel map, "
         "{envlight_rms_levels[16/128]} with 128; above the 8-bit floor {envlight_rms_above_floor_levels[16/32]} and "
         "{envlight_rms_above_floor_levels[16/128]}"},
        {"env_lighting_map16",
         "Seed 001 ¶44 (lighting from an environment map)",
         "Sixteen lights' highlights from one lookup in a cube map of 32 texels a face, against per-pixel Phong, "
         "their difference 8 times magnified: the map's texels show as a lattice over each highlight and its "
         "faces' edges as lines, where GL_LINEAR without seamless filtering clamps to one face.",
         {"--view", "single", "--method", "diff", "--lights", "16", "--face", "32"},
         640,
         600,
         "RMS {envlight_rms_levels[16]} levels at 32 texels a face, {envlight_rms_levels[16/128]} at 128, "
         "{envlight_rms_levels[16/256]} at 256 (the 8-bit floor); largest {envlight_max_interior_levels[16/32]} "
         "inside the faces, {envlight_max_edge_levels[16/32]} at their edges"}};
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override { return measureAll(r, faceTexels()); }

 private:
  int faceTexels() const { return 16 << face_; }
  int lightCount() const { return kLightCounts[lights_]; }
  // The caption under a picture: what it cost or how far it is from Phong, measured.
  ts::layout::Text costText(const ts::Measurements& m, Method method, int n) const;
  int lights_ = 1, method_ = kMap, face_ = 1, view_ = 0;
};

ts::layout::Text EnvLighting::costText(const ts::Measurements& m, Method method, int n) const {
  namespace L = ts::layout;
  const std::string k = "[" + std::to_string(n) + "]";
  if (method == kMap)
    return L::measuredText(m, "lookups a pixel: {envlight_lookups_per_pixel" + k +
                                  "|%.0f}; lights evaluated: {envlight_evaluations_per_pixel" + k + "|%.0f}");
  if (method == kPhong)
    return L::measuredText(m, "lights evaluated a pixel: {phong_light_evaluations_per_pixel" + k +
                                  "|%.0f}; lookups: {phong_lookups_per_pixel" + k + "|%.0f}");
  return L::measuredText(m, "RMS {envlight_rms_levels" + k + "|%.2f} levels, max {envlight_max_levels" + k + "|%.0f}");
}

ts::Frame EnvLighting::build(int width, int height, const ts::Measurements& measured) const {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(width, height);
  const int face = faceTexels();
  const float w = float(width), h = float(height);
  // The bottom band: what the sizes do to the error, and the key of the difference's colours.
  const int footScale = L::scaleFor({0, 0, width, height / 3}, 2);
  // The sizes' story for the lights shown (16 in the grid): the RMS at 32 and 128 texels a face, the floor
  // the 8-bit rounding leaves (the finest map), and where the largest error sits.
  const std::string n = std::to_string(view_ == 1 ? 16 : lightCount()), k = "[" + n + "/";
  auto size = [](int texels) { return L::given("a map's texels along a face's side", texels, "%.0f"); };
  auto rms = [&](int texels) {
    return L::measuredText(measured, "{envlight_rms_levels" + k + std::to_string(texels) + "]|%.2f}");
  };
  const L::Text story =
      L::Text(n + " lights: RMS ") + rms(32) + " levels with " + size(32) + " texels a face, " + rms(128) + " with " +
      size(128) + ", " + rms(256) + " with " + size(256) + " (the 8-bit floor); bound at " + size(32) + ": " +
      L::given("derived error bound at 32 texels a face (levels)", errorBoundLevels(32), "%.1f") + " (a texel " +
      L::given("texel angle at a face's centre, 32 texels (degrees)", texelAngleDeg(32), "%.2f") +
      " deg); above the floor " +
      L::measuredText(measured, "{envlight_rms_above_floor_levels" + k +
                                    "32]|%.2f} and {envlight_rms_above_floor_levels" + k + "128]|%.2f}; ") +
      L::measuredText(measured, "largest {envlight_max_interior_levels" + k + "32]|%.0f} inside the faces, " +
                                    "{envlight_max_edge_levels" + k + "32]|%.0f} at their edges (no seamless filter)");
  // Room for the story's lines at the scale it will be drawn, and one line for the legend.
  const int storyLines = L::captionLines(story.text, footScale, w - 12);
  const float foot = float(storyLines + 1) * L::lineHeight(footScale) + 8;
  const L::Box area{6, 6, w - 6, h - 6 - foot};
  auto title = [](Method method, int n) {
    return std::string(kMethodTitles[method]) + ", " + std::to_string(n) + (n == 1 ? " light" : " lights");
  };
  auto cell = [&](const L::Cell& c, Method method, int n) {
    f.panels.push_back(
        spherePanel(f, std::string(kMethodKeys[method]) + "_" + std::to_string(n), c.picture, method, n, face));
    L::caption(f, c.above, title(method, n), L::kWhite, c.scale);
    L::caption(f, c.below, costText(measured, method, n), L::kAmber, c.scale);
  };
  if (view_ == 1) {
    // A row per number of lights, the three methods across it; a narrow window wraps the captions.
    const float rowH = (area.y1 - area.y0) / 3;
    for (int row = 0; row < 3; ++row) {
      L::FlowSpec spec;
      spec.n = 3, spec.linesAbove = 1, spec.linesBelow = 1, spec.maxScale = 2;
      std::vector<L::Stack> above, below;
      for (int m = 0; m < kMethods; ++m)
        above.push_back({title(Method(m), kLightCounts[row])}),
            below.push_back({costText(measured, Method(m), kLightCounts[row]).text});
      // At most two lines each: more would leave a row's pictures a few pixels tall.
      const L::Box rowBox{area.x0, area.y0 + row * rowH, area.x1, area.y0 + (row + 1) * rowH};
      const std::vector<L::Cell> cells = L::flowFitting(rowBox, spec, above, below, 0, 2);
      for (int m = 0; m < kMethods; ++m) cell(cells[size_t(m)], Method(m), kLightCounts[row]);
    }
  } else {
    L::FlowSpec spec;
    spec.n = 1, spec.linesAbove = 1, spec.linesBelow = 1;
    cell(L::flowFitting(area, spec, {{title(Method(method_), lightCount())}},
                        {{costText(measured, Method(method_), lightCount()).text}})[0],
         Method(method_), lightCount());
  }
  const L::Box band{6, h - 6 - foot, w - 6, h - 6};
  const float y = L::caption(f, {band.x0, band.y0, band.x1, band.y0 + storyLines * L::lineHeight(footScale)}, story,
                             L::kAmber, footScale);
  // The difference panels' colours mean something: each channel is |map - Phong| x 8 (full at 32 levels).
  if (view_ == 1 || method_ == kDiff)
    L::legend(f, {band.x0, y + 2, band.x1, band.y1}, {{{1.0f, 1.0f, 1.0f, 1.0f}, "|map - Phong| x 8, per channel"}},
              footScale);
  return f;
}
}  // namespace

TS_REGISTER_SCENE(EnvLighting);
