// reference/inspect.hpp — look inside one pixel: everything the reference
// renderer (reference.hpp) computes for it, spelled out for a student.
//
// For pixel (x, y) the inspector walks the panels whose viewport (= scissor)
// holds it and their batches in draw order, exactly as Reference draws the
// frame but for the one pixel only: a triangle covers the pixel when
// raster.hpp's exact test of the centre (x + 1/2, y + 1/2) says so (the same
// top-left rule as the scanline rasterizer), the depth test keeps the nearest
// fragment (GL_LESS, the panel's depth test on) or else the last one drawn,
// lines, points and labels paint over what is beneath.  The last thing that
// wrote the pixel is described.
//
// For a textured triangle, at the centre, in closed form from the
// screen-space planes of a/w and 1/w (geometry.hpp):
//   (s, t, r, q)  = (s/w, t/w, r/w, q/w) / (1/w)          the interpolated coordinate
//   (s/q, t/q)    = (s/w) / (q/w), (t/w) / (q/w)           the coordinate looked up
//   (u, v)        = (s/q) w0, (t/q) h0                     in texels of level 0 (w0 x h0)
//   du/dx etc.    for f = N/D with N, D screen-linear: df/dx = (N_x D - N D_x) / D^2
//   rho           = max(|(du/dx, dv/dx)|, |(du/dy, dv/dy)|)  (GL's formula, "rhoEdge")
//                   and max(|du/dx|, |dv/dx|, |du/dy|, |dv/dy|) (the cheaper bound, "rhoMax")
//   lambda_base   = log2(rho);  lambda = clamp(lambda_base + bias, -1000, 1000)
//   the texels the GL filter reads (sampler.hpp's Footprint) and their weights,
//   the filtered value, then the texture environment and the colour sum.
// And the pixel's footprint in texture space (texels of level 0): the
// preimage of the pixel square (its corners mapped through the exact
// perspective map), the parallelogram the derivatives span, and Heckbert's
// EWA ellipse.
#pragma once
#include <array>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "reference.hpp"
#include "sampler.hpp"
#include "volume.hpp"

namespace ref {
// A texel the filter reads: level, i, j (after wrapping; -1 or the level's
// size = the border colour), weight, rgba (0..1).
using InspectTexel = WeightedTexel;

struct Inspection {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();  // not applicable here

  enum class What { Background, Triangle, Line, Point, Label };
  int x = 0, y = 0;  // the pixel (image coordinates, top-left origin)
  What what = What::Background;
  // Indices into Frame::panels and the panel's batches; batch -1 for the
  // background (panel: the last panel whose viewport holds the pixel, -1
  // if none) and for a label (panel -1 too).
  int panel = -1, batch = -1;
  std::string panelName, batchRole;
  bool textured = false;  // the reference samples a texture for this pixel
  bool program = false;   // the batch is drawn by a GLSL program (the note says which values come from it)
  std::string note;       // what the pixel is, in words, and what is not modelled

  // A triangle's fragment at the pixel centre.
  double z = kNone;                                   // window depth in [0, 1]
  Colour primary{}, secondary{};                      // interpolated vertex colours (secondary: alpha 0)
  double s = kNone, t = kNone, r = kNone, q = kNone;  // interpolated (s, t, r, q), after the texture matrix
  double sq = kNone, tq = kNone;                      // (s/q, t/q); for the bilinear program its map of them
  // The texture (when the batch names one).
  int texture = -1;
  std::string textureName;
  int width0 = 0, height0 = 0;  // level 0
  GLenum minFilter = 0, magFilter = 0, texEnv = 0;
  double u = kNone, v = kNone;  // (s/q) w0, (t/q) h0: texels of level 0
  double dudx = kNone, dvdx = kNone, dudy = kNone, dvdy = kNone;
  double rhoEdge = kNone;  // max(|(du/dx, dv/dx)|, |(du/dy, dv/dy)|): GL's formula
  double rhoMax = kNone;   // max(|du/dx|, |dv/dx|, |du/dy|, |dv/dy|)
  // lambda_base = log2(rhoEdge) (-1000 for rho = 0); lambda = lambda_base +
  // bias clamped to [TEXTURE_MIN_LOD, TEXTURE_MAX_LOD] = [-1000, 1000], as
  // GL does: the sum is clamped, not the bias.  The level index is then
  // limited to the texture's last level.
  double lambdaBase = kNone, bias = kNone, lambda = kNone;
  bool magnified = false;  // lambda <= 0: level 0 with the mag filter
  GLenum filter = 0;       // the filter within a level: GL_NEAREST or GL_LINEAR
  int level0 = 0, level1 = 0;
  double levelWeight = 0;  // *_MIPMAP_LINEAR: the weight of level1 (level0 has 1 - it)
  // Every texel the filter reads, weights summing to 1: NEAREST one texel,
  // LINEAR four, *_MIPMAP_LINEAR both levels' texels times (1 - w) and w.
  std::vector<InspectTexel> texels;
  Colour filtered{};  // sum of weight * rgba: the filtered texel

  // The fragment's colour as Reference draws it: the filtered texel through
  // the texture environment and the colour sum (untextured: the vertex
  // colour; a line, point or label: its colour).
  Colour referenceRgba{};
  // The reference image's pixel, 8-bit: referenceRgba unless the batch
  // blends over what is beneath.
  Colour pixelRgba{};

  // The footprint, in texels of level 0 (u, v): the preimage of the pixel
  // square (corners (x, y), (x+1, y), (x+1, y+1), (x, y+1) mapped through the
  // exact perspective map), the derivative parallelogram (same corner order:
  // centre -/+ d/dx / 2 -/+ d/dy / 2), and the EWA ellipse of Heckbert
  // A du^2 + B du dv + C dv^2 = F around (u, v), the image of the circle of
  // radius one pixel: A = Vx^2 + Vy^2, B = -2 (Ux Vx + Uy Vy), C = Ux^2 + Uy^2,
  // F = (Ux Vy - Uy Vx)^2 with Ux = du/dx, Vx = dv/dx, Uy = du/dy, Vy = dv/dy.
  std::array<glm::dvec2, 4> preimage{}, parallelogram{};
  double ewaA = kNone, ewaB = kNone, ewaC = kNone, ewaF = kNone;
};

// Inspects pixels of one frame (it keeps a copy of the frame and makes each
// texture's levels once, when first needed; not for concurrent use).  The
// options are the reference's: fill rule, interpolation, labels.
class Inspector {
 public:
  explicit Inspector(const ts::Frame& frame, const RenderOptions& options = {});
  ~Inspector();
  // The pixel must lie inside the frame (the caller checks); throws nothing then.
  Inspection at(int x, int y) const;

 private:
  const Texture* texture(int index, std::string* why) const;
  // A 3D texture's slices as a Volume (volume.hpp), made once; null when the texture is no 3D texture.
  const Volume* volume(int index) const;
  Inspection fragment(int x, int y, int panel, int batch, const ScreenPoly& poly) const;
  ts::Frame frame_;
  RenderOptions opts_;
  mutable std::vector<std::unique_ptr<Texture>> textures_;
  mutable std::vector<std::string> textureErrors_;
  struct Slices {
    std::vector<Texture> slices;
    Volume volume;
  };
  mutable std::map<int, std::unique_ptr<Slices>> volumes_;
};

// One pixel of a frame (makes the textures it needs each call).
Inspection inspect(const ts::Frame& f, int x, int y, const RenderOptions& options = {});

// A compact card a student reads: the pixel, what covers it, the
// coordinates, derivatives, rho both ways, lambda, the levels, every texel
// and the colours (0..255).
std::string formatInspection(const Inspection& in);

// The same as JSON, keys: pixel [x, y], panel, batch, st [s/q, t/q],
// stq [s, t, r, q], uv [u, v], derivatives [du/dx, dv/dx, du/dy, dv/dy],
// rho_edge, rho_max, lambda, levels [level0, level1], level_weight,
// texels [{level, i, j, weight, rgba [4] 0..1}], reference_rgba [4] 0..1.
// Values that do not apply (the background, untextured) are null.
nlohmann::json inspectionJson(const Inspection& in);
}  // namespace ref
