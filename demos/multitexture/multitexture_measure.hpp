// demos/multitexture/multitexture_measure.hpp — runs the passes of multitexture_gl.hpp and
// measures them against the CPU (multitexture_math.hpp): what the figures show and
// the named measurements the tests assert.
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "common/core/scene.hpp"
#include "common/gl/gl_listing.hpp"
#include "multitexture_frames.hpp"
#include "multitexture_gl.hpp"

namespace mt {
inline const int kLightSizes[4] = {8, 16, 32, 64};
constexpr int kSpotFrames = 12, kTurnSteps = 72;  // 5 degrees a step
constexpr int kPearPixels = 192;

// The default base picture, 128 x 128: bricks in two reds, grey mortar.
inline ts::Image basePicture() { return ts::multitex::bricksImage(); }

struct Result {
  ts::Image hidden[3], edge[3];                 // by Cutout mode
  std::vector<double> singleWidth, crossWidth;  // per 5 degrees, in quad widths
  ts::Image base;                               // the base picture (bricks, or --texture's)
  bool userBase = false;
  ts::Image lit[4], perPixel;      // by kLightSizes; the CPU's
  ts::Image diffuseOnly, glossed;  // the gloss map's passes
  ts::Image abcdCpu, abcd[3];      // the CPU's AB + CD; by Abcd
  ts::Image abcdAb;                // the one-unit path's intermediate buffer (multitexture_frames.hpp)
  ts::Image pear[2];               // by Pear
  bool combine3 = false;
  std::shared_ptr<const ts::Frame> pears;  // both methods side by side (frames::pearsFrame)
  ts::Image pearsImage;                    // its render (row 0 the top)
  ts::gl::CallList abcdCalls[3], pearCalls[2], glossCalls, pearsCalls;
};

// Pixels of a readback inside the tree's rectangle (64..191) whose texel is
// transparent and which do not show the sky: sky the transparent parts hid.
inline int hiddenSky(const ts::Image& img, const ts::Image& tree) {
  int n = 0;
  for (int y = 64; y < 192; ++y)
    for (int x = 64; x < 192; ++x) {
      const int i = (x - 64) / 2, j = (255 - y - 64) / 2;  // window row 255 - y
      if (tree.at(i, j).a == 0 && img.at(x, y) != kSky) ++n;
    }
  return n;
}
// Pixels showing sky and tree mixed: blue strictly between the tree's (<= 40)
// and the sky's (255) by more than 10% of the range.
inline int fringe(const ts::Image& img) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) n += img.at(x, y).b > 62 && img.at(x, y).b < 233;
  return n;
}
// The lit pixels of each strip's middle row, / 128 (a quad's full width).
inline std::vector<double> widths(const ts::Image& strips, int first, int count) {
  std::vector<double> w;
  for (int k = first; k < first + count; ++k) {
    const int y = strips.height - 1 - (k * 8 + 4);
    int n = 0;
    for (int x = 0; x < strips.width; ++x) n += strips.at(x, y).r > 127;
    w.push_back(n / 128.0);
  }
  return w;
}
inline int countCalls(const ts::gl::CallList& calls, const char* name) {
  int n = 0;
  for (const auto& c : *calls) n += std::string(c.name) == name;
  return n;
}

inline Result runAll(ts::Renderer& r, const ts::Image& base, bool userBase, ts::Measurements& ms) {
  Result out;
  auto put = [&](const std::string& n, double v, const std::string& meaning) { ms.push_back({n, v, meaning}); };
  // Alpha.
  const ts::Image treeImg = treeTexture();
  const char* modes[3] = {"no_alpha_test", "alpha_test", "blend"};
  // The Frames the figure draws (multitexture_frames.hpp: Batch::alphaFunc, blend), rendered by the Renderer.
  auto hiddenFrame = [&](int m) {
    return frames::alone(256, 256,
                         [&](ts::Frame& f, ts::Rect v) { return frames::hiddenPanel(f, treeImg, m, "hidden", v); });
  };
  for (int m = 0; m < 3; ++m) {
    out.hidden[m] = opaque(r.renderOffscreen(hiddenFrame(m)));
    out.edge[m] = opaque(r.renderOffscreen(frames::alone(256, 256, [&](ts::Frame& f, ts::Rect v) {
      return frames::edgePanel(f, treeImg, m, "edge", v);
    })));
    put(std::string("cutout_hidden_px[") + modes[m] + "]", hiddenSky(out.hidden[m], treeImg),
        "sky pixels hidden by the transparent texels' depth, the tree drawn first");
    put(std::string("edge_fringe_px[") + modes[m] + "]", fringe(out.edge[m]),
        "pixels mixing sky and tree at the edge, magnified 16x");
  }
  ts::measureProgress(0.2);
  const ts::Image turning = turningWidths(r, kTurnSteps, 360.0 / kTurnSteps);
  out.singleWidth = widths(turning, 0, kTurnSteps), out.crossWidth = widths(turning, kTurnSteps, kTurnSteps);
  auto lo = [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); };
  auto hi = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
  put("single_quad_min_width", lo(out.singleWidth), "one quad's silhouette, least over a turn (|cos|: 0 edge-on)");
  put("single_quad_max_width", hi(out.singleWidth), "one quad's silhouette, largest (1)");
  put("cross_tree_min_width", lo(out.crossWidth), "two crossed quads: max(|cos|, |sin|), least at 45 deg: 0.7071");
  put("cross_tree_max_width", hi(out.crossWidth), "two crossed quads, largest (1)");
  // Light maps: the Frames the figure draws (multitexture_frames.hpp: unit 1 GL_MODULATE), rendered by the Renderer.
  ts::measureProgress(0.35);
  out.base = base, out.userBase = userBase;
  out.perPixel = perPixelLit(base, 256);
  for (int k = 0; k < 4; ++k) {
    const int n = kLightSizes[k];
    out.lit[k] = opaque(r.renderOffscreen(frames::alone(256, 256, [&](ts::Frame& f, ts::Rect v) {
      ts::Panel p = frames::unitPanel("light_map", v);
      p.batches = {frames::lightMapped(f, base, userBase, n)};
      return p;
    })));
    const std::string s = "[" + std::to_string(n) + "]";
    put("light_map_rms" + s, rms(out.lit[k], out.perPixel),
        "8-bit levels, base x L (GL) against base x per-pixel lighting (CPU)");
    put("light_map_bytes" + s, double(n * n),
        "bytes as GL_LUMINANCE8, 1 a texel (the Frame uploads the same grey as RGBA8, 4 a texel; the base: " +
            std::to_string(base.width * base.height * 4) + " bytes)");
  }
  // Gloss map (two passes, Frames).
  ts::measureProgress(0.5);
  auto glossFrame = [&](int what) {
    return frames::alone(256, 128, [&](ts::Frame& f, ts::Rect v) {
      return frames::glossPanel(f, base, userBase, what, "gloss", v);
    });
  };
  out.diffuseOnly = opaque(r.renderOffscreen(glossFrame(frames::kDiffuseOnly)));
  out.glossCalls = ts::recordRender(r, [&] { out.glossed = opaque(r.renderOffscreen(glossFrame(frames::kGlossed))); });
  int peak[2] = {0, 0}, diffuseChange = 0, far = 0;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 256; ++x) {
      const ts::Rgba f = out.glossed.at(x, y), d = out.diffuseOnly.at(x, y);
      const int s = std::max({int(f.r) - d.r, int(f.g) - d.g, int(f.b) - d.b});
      peak[x >= 128] = std::max(peak[x >= 128], s);
      // Where every vertex of the pixel's cell has i_spec < 0.1/255, pass
      // 2 adds 0 (well below half a level): the diffuse must be untouched.
      const int ci = x / 4, cj = (127 - y) / 4;
      double most = 0;
      for (int v2 = 0; v2 < 4; ++v2) most = std::max(most, glossLighting((ci + v2 % 2) / 32.0, (cj + v2 / 2) / 32.0).y);
      if (most < 0.1 / 255)
        ++far, diffuseChange = std::max(
                   {diffuseChange, std::abs(int(f.r) - d.r), std::abs(int(f.g) - d.g), std::abs(int(f.b) - d.b)});
    }
  put("gloss_peak[g=1]", peak[0], "highest specular step (levels) in the g = 1 half");
  put("gloss_peak[g=0.2]", peak[1], "highest specular step (levels) in the g = 0.2 half");
  put("gloss_peak_ratio", peak[1] ? double(peak[0]) / peak[1] : 0.0, "their ratio: g 1 / 0.2 = 5");
  put("gloss_diffuse_change", diffuseChange, "largest change the gloss pass makes away from the highlights (levels)");
  put("gloss_diffuse_px", far, "pixels where that is checked (i_spec < 0.1/255 at the cell's vertices)");
  put("gloss_passes", countCalls(out.glossCalls, "glBegin"),
      "passes over the plane (glBegin ... glEnd: diffuse, + g i_spec)");
  // AB + CD.
  ts::measureProgress(0.65);
  const std::vector<ts::Image> abcdImg = abcdTextures();
  out.abcdCpu = abcdCpu(abcdImg, 128, false);
  const ts::Image fbCpu = abcdCpu(abcdImg, 128, true);
  const char* methods[3] = {"multitexture", "stored", "framebuffer_only"};
  for (int m = 0; m < 3; ++m) {
    // The Frames the figure draws (multitexture_frames.hpp), rendered by the Renderer;
    // the one-unit path renders its intermediate buffer first (a nested frame).
    int intermediate = 0;
    out.abcdCalls[m] = ts::recordRender(r, [&] {
      if (m == kStored) out.abcdAb = r.renderOffscreen(frames::abFrame(abcdImg));
      const ts::Frame f = frames::abcdFrame(abcdImg, m, out.abcdAb);
      for (const ts::TextureDesc& d : f.textures) intermediate += d.renderedFrom ? 1 : 0;
      out.abcd[m] = opaque(r.renderOffscreen(f));
    });
    const std::string s = std::string("[") + methods[m] + "]";
    put("abcd_max_diff" + s, maxDiff(out.abcd[m], out.abcdCpu), "levels, against the CPU's AB + CD");
    put("abcd_rms" + s, rms(out.abcd[m], out.abcdCpu), "RMS levels, against the CPU's AB + CD");
    put("abcd_passes" + s, countCalls(out.abcdCalls[m], "glBegin"),
        "geometry passes (glBegin ... glEnd over the square)");
    put("abcd_copies" + s, intermediate, "intermediate buffers (a texture rendered from a frame of its own)");
  }
  put("abcd_max_diff[framebuffer_only_vs_cpu_model]", maxDiff(out.abcd[kFramebufferOnly], fbCpu),
      "levels: the framebuffer-only sequence against the CPU's (AB + C) D");
  // The pear.
  ts::measureProgress(0.8);
  out.combine3 = ts::gl::hasExtension("GL_ATI_texture_env_combine3");
  put("combine3_supported", out.combine3 ? 1 : 0,
      "GL_ATI_texture_env_combine3 in the extension string (renderer: " + ts::gl::rendererString() + ")");
  // Each method alone (the Frames of multitexture_frames.hpp: one glBegin a pass), then both side by side: the
  // figure's picture, a nested frame the reference recomputes.
  for (int m = kCombine3; m <= kTwoPasses; ++m) {
    if (m == kCombine3 && !out.combine3) continue;
    out.pearCalls[m] = ts::recordRender(r, [&] {
      out.pear[m] = opaque(r.renderOffscreen(frames::alone(kPearPixels, kPearPixels, [&](ts::Frame& f, ts::Rect v) {
        return frames::pearPanel(f, m, "pear", v);
      })));
    });
    put(std::string("pear_passes[") + (m ? "two_passes" : "combine3") + "]", countCalls(out.pearCalls[m], "glBegin"),
        "passes over the pear (its glBegin calls: the mesh is one batch a pass)");
  }
  out.pears = std::make_shared<const ts::Frame>(frames::pearsFrame(kPearPixels, out.combine3));
  out.pearsCalls = ts::recordRender(r, [&] { out.pearsImage = r.renderOffscreen(*out.pears); });
  if (out.combine3)
    put("pear_combine3_vs_two_passes_max_diff", maxDiff(out.pear[kCombine3], out.pear[kTwoPasses]),
        "levels: one stage A.C + B against two passes (two roundings)");
  return out;
}
}  // namespace mt
