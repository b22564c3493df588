// demos/wrap_modes/wrap_modes_views.hpp — the secondary pictures of
// demos/wrap_modes: the texture-space panel (the quad over [lo, hi]^2 with
// the integer grid and the unit square) that every view but env shows, and
// the env view's six lit planes.  Kept out of wrap_modes.cpp so that file
// shows the figure's state, its captions and its measurement first.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/gl/render.hpp"
#include "wrap_modes_math.hpp"
#include "wrap_modes_gl.hpp"

namespace wrap::views {
// The texture environments, in the order of the env view's panels.
inline const GLenum kEnvs[] = {GL_REPLACE, GL_MODULATE, GL_DECAL, GL_BLEND, GL_ADD};
inline const char* const kEnvNames[] = {"replace", "modulate", "decal", "blend", "add"};
inline const char* const kEnvGL[] = {"GL_REPLACE", "GL_MODULATE", "GL_DECAL", "GL_BLEND", "GL_ADD"};
inline const glm::vec4 kEnvColour{0.2f, 0.6f, 1.0f, 1.0f};  // GL_TEXTURE_ENV_COLOR for GL_BLEND
inline const glm::vec4 kSquare{1.0f, 0.85f, 0.1f, 1.0f}, kGrid{0.55f, 0.55f, 0.6f, 1.0f};

// What measure() found, for the captions.
struct Found {
  std::map<int, int> mismatches;      // mode index -> texel mismatches (both passes, both sizes)
  std::map<int, double> borderAt0;    // mode index -> % border at s = 0 (linear)
  int seedDiffers = 0, integers = 0;  // seed 002's MIRROR vs GL at integer s
  int matrixMismatches = -1;
  int envMismatches = -1;
  double peak[2] = {-1, -1};  // the highlight's peak (mean of R, G, B): specular in the primary colour | separate
};

// The texture-space picture: the quad over [lo, hi]^2 (lo = -range, hi = 1 +
// range) textured with f.textures[tex], the integer grid, the unit square
// (or, with `matrix`, its image under the texture matrix).
inline void addTextureSpace(ts::Frame& f, const ts::Rect& vp, const std::string& id, int tex, float range,
                            const glm::mat4* matrix = nullptr) {
  const float lo = -range, hi = 1.0f + range;
  ts::Panel p;
  p.id = id;
  p.viewport = vp;
  // A whole number of pixels per texel where the picture is larger than the
  // texels it shows: then no texel edge passes through a pixel centre, where
  // GL may take either texel (and OSMesa and EGL do differ there).
  const ts::TextureDesc& t = f.textures[size_t(tex)];
  const int tw = int(std::lround(t.image ? t.image->width * (hi - lo) : 0.0)),
            th = int(std::lround(t.image ? t.image->height * (hi - lo) : 0.0));
  if (tw > 0 && th > 0 && tw <= vp.w && th <= vp.h)
    p.viewport = ts::layout::centred(vp, vp.w / tw * tw, vp.h / th * th);
  p.projection = glm::ortho(lo, hi, lo, hi, -1.0f, 1.0f);
  p.batches.push_back(wrap::stQuad({lo, lo}, {hi, hi}, {lo, lo}, {hi, hi}, tex));
  std::vector<glm::vec2> grid;
  for (int k = int(std::ceil(lo)); k <= int(std::floor(hi)); ++k)
    grid.insert(grid.end(), {{float(k), lo}, {float(k), hi}, {lo, float(k)}, {hi, float(k)}});
  p.batches.push_back(ts::lineSegments(grid, kGrid, 1.0f, "integer_grid"));
  std::vector<glm::vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  if (matrix)  // where the quad's corners land in texture space: M (s, t, 0, 1)
    for (auto& c : square) c = glm::vec2(wrap::transformST(*matrix, c.x, c.y));
  p.batches.push_back(ts::lineLoop(square, kSquare, 2.0f, "unit_square"));
  f.panels.push_back(p);
}

// The environment view: a plane lit per vertex (wrap_modes_math.hpp's phong)
// under an RGBA texture in each mode (`ramp`, with an alpha ramp, for
// GL_DECAL; `opaque` for the others), and GL_MODULATE once more in the last
// panel, where `separate` sends the specular part as the secondary colour
// (GL_COLOR_SUM), else it is in the primary colour.
inline ts::Frame envFrame(int width, int height, const ts::TextureDesc& opaque, const ts::TextureDesc& ramp,
                          bool separate, const Found* found) {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(width, height);
  L::FlowSpec spec;
  spec.n = 6, spec.linesAbove = 1, spec.linesBelow = 1, spec.gap = 8;
  std::vector<L::Cell> cells = L::flow({6, 6, float(width) - 6, float(height) - 6}, spec);
  const int texOpaque = f.addTexture(opaque), texRamp = f.addTexture(ramp);
  for (int k = 0; k < 6; ++k) {
    const GLenum env = k < 5 ? kEnvs[k] : GL_MODULATE;
    const bool sep = k == 5 && separate;
    ts::Panel p = L::unitPanel(k < 5 ? std::string("env_") + kEnvNames[k] : "env_separate_specular",
                               cells[size_t(k)].picture);
    ts::Batch b = wrap::litPlane(env == GL_DECAL ? texRamp : texOpaque, env, kEnvColour, sep);
    p.batches.push_back(b);
    f.panels.push_back(p);
    const L::Cell& cell = cells[size_t(k)];
    L::caption(f, cell.above,
               k < 5 ? kEnvGL[k]
               : sep ? "MODULATE + SEPARATE_SPECULAR"
                     : "MODULATE (single colour)",
               L::kWhite, cell.scale);
    std::string note;
    if (found && found->peak[0] >= 0 && (k == 1 || k == 5))
      note = L::fmt("highlight peak %.2f", found->peak[k == 5 && separate ? 1 : 0]);
    else if (found && k == 0 && found->envMismatches >= 0)
      note = L::fmt("table: %.0f mismatches", found->envMismatches);
    if (!note.empty()) L::caption(f, cell.below, note, L::kAmber, cell.scale);
  }
  return f;
}
}  // namespace wrap::views
