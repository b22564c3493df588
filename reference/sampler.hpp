// reference/sampler.hpp — texture sampling as the OpenGL specification
// writes it, on the CPU, in double precision.
//
// Two uses: the exact value (the reference image), and the set of values a
// conformant implementation may return (the verifier): every texel a
// GL_NEAREST lookup may pick when the coordinate is within `eps` texels of a
// texel boundary, the range a GL_LINEAR lookup spans when the coordinate
// moves by up to `eps` texels, and every mip level (and blend weight) an LOD
// anywhere in [lodLo, lodHi] selects.  Values are colours in [0, 1].
//
// Wrap modes: GL 4.6 §8.14.2 / table 8.20 on integer texel indices (what the
// sampler uses), and seed 002's formulas on normalised coordinates (WRAP:
// u - floor(u); MIRROR: fmod(ceil(u), 2) ? u - floor(u) : 1 - (u - floor(u));
// CLAMP: clamp to [0, 1]; BORDER: the border colour outside [0, 1]), kept
// for the tests that show the two agree.
#pragma once
#include <array>
#include <memory>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"

namespace ref {
using Colour = std::array<float, 4>;  // RGBA in [0, 1]

// A per-channel range of legal colours.
struct Box {
  Colour lo{}, hi{};
  static Box point(const Colour& c) { return {c, c}; }
};
using Boxes = std::vector<Box>;

Colour toColour(ts::Rgba c);
ts::Rgba toRgba(const Colour& c);  // round to nearest, clamped

// Seed 002, normalised coordinate -> [0, 1] (BORDER returns s unchanged: the
// caller uses the border colour when it is outside [0, 1]).
double wrapCoordSeed(GLenum mode, double s);
// GL's integer wrap of a texel index for a level `size` texels wide.  For
// GL_CLAMP_TO_BORDER (and GL_CLAMP) the result may be -1 or `size`, meaning
// the border colour.  GL_CLAMP here is its GL_LINEAR row of the
// compatibility profile's table 8.20 (clamp(coord, -1, size)); with
// GL_NEAREST it is clamp(coord, 0, size - 1): wrapTexelNearest.
int wrapTexelNearest(GLenum mode, int i, int size);
int wrapTexel(GLenum mode, int i, int size);

// The screen-space derivatives of (s, t) at a pixel (normalised texture
// coordinates per pixel).
struct Deriv {
  double dsdx = 0, dsdy = 0, dtdx = 0, dtdy = 0;
};

// One texel a filter reads: its mip level, its indices after wrapping (-1
// or the level's size where the wrap mode gives the border colour), its
// weight in the filtered value, and its value.
struct WeightedTexel {
  int level = 0, i = 0, j = 0;
  double weight = 0;
  Colour rgba{};
};

// What GL's filter does at one coordinate and LOD (GL 4.6 §8.14): which
// levels it reads, which texels, with which weights.  The filtered value is
// the weighted sum of the texels, and Texture::sample() is exactly that sum.
struct Footprint {
  // lambda = lambda_base + the texture's LOD bias, clamped to
  // [TEXTURE_MIN_LOD, TEXTURE_MAX_LOD] = [-1000, 1000] (GL's defaults, the
  // only values a Frame uses): the clamp is on lambda, not on the bias.
  double lambda = 0;
  bool magnified = false;      // lambda <= 0: level 0 with the mag filter
  GLenum filter = GL_NEAREST;  // the filter within a level: GL_NEAREST or GL_LINEAR
  int level0 = 0, level1 = 0;  // the levels read; they differ only for *_MIPMAP_LINEAR
  double levelWeight = 0;      // weight of level1 (the fraction of lambda); level0 has 1 - it
  // NEAREST: one texel; LINEAR: four; *_MIPMAP_LINEAR: both levels' texels,
  // times (1 - levelWeight) and levelWeight.  The weights sum to 1.
  std::array<WeightedTexel, 8> texels{};
  int count = 0;
  Colour value() const;  // sum of weight * rgba
};

// How the scale factor rho is allowed to be computed.
enum class LodModel {
  Exact,    // rho = max(|(du/dx, dv/dx)|, |(du/dy, dv/dy)|), GL's ideal formula
  Bounded,  // anything from max(|du/dx|, |du/dy|, |dv/dx|, |dv/dy|) (softpipe) to Exact (llvmpipe)
  Spec,     // GL's allowed approximations: max(mu, mv) .. mu + mv
};

class Texture {
 public:
  explicit Texture(const ts::TextureDesc& d);
  const ts::TextureDesc& desc() const { return desc_; }
  int levels() const { return int(levels_.size()); }
  const ts::Image& level(int d) const { return levels_[size_t(d)]; }
  int width(int d = 0) const { return levels_[size_t(d)].width; }
  int height(int d = 0) const { return levels_[size_t(d)].height; }
  bool mipmapped() const;  // the min filter uses mip levels
  // Texel (i, j) of level d after wrapping (border colour outside).
  Colour texel(int d, int i, int j) const;
  // The same for a GL_NEAREST lookup (GL_CLAMP wraps differently there).
  Colour texelNearest(int d, int i, int j) const;
  // Level d's filter at (s, t): the exact value.
  Colour nearest(int d, double s, double t) const;
  Colour linear(int d, double s, double t) const;
  // lambda_base (without the texture's LOD bias) from the derivatives.
  double lod(const Deriv& g) const;
  void lodRange(const Deriv& g, LodModel m, double* lo, double* hi) const;
  // The same as scale factors rho (texels per pixel): lambda = log2(rho).
  void rhoRange(const Deriv& g, LodModel m, double* lo, double* hi) const;
  // The full GL filter (min/mag choice, mip selection, bias) at lambda_base:
  // the texels it reads and their weights, and their weighted sum.
  Footprint footprint(double s, double t, double lambdaBase) const;
  Colour sample(double s, double t, double lambdaBase) const { return footprint(s, t, lambdaBase).value(); }
  // Every value legal for a coordinate within eps texels of (s, t) (eps for
  // NEAREST and LINEAR separately) and a lambda_base in [lodLo, lodHi].
  // Appends boxes to `out`.
  void legal(double s, double t, double lodLo, double lodHi, double epsNearest, double epsLinear, Boxes* out) const;

 private:
  // The texels level d's GL_NEAREST / GL_LINEAR filter reads at (s, t), each
  // weighted by `weight` times its filter weight, appended to `out`.
  void addNearest(int d, double s, double t, double weight, Footprint* out) const;
  void addLinear(int d, double s, double t, double weight, Footprint* out) const;
  void levelValues(GLenum filter, int d, double s, double t, double epsNearest, double epsLinear, Boxes* out) const;
  // Every value a level can give (all its texels, and the border colour
  // where it can be reached): the answer when the jitter spans many texels.
  Box levelRange(int d) const;
  ts::TextureDesc desc_;
  std::vector<ts::Image> levels_;
  std::vector<Box> ranges_;
};

// The texture environment of OpenGL 1.x (GL 2.1 §3.8.13, table 3.22), for
// an RGBA texture: the fragment's primary colour `f` (Cf, Af), the texel
// `t` (Ct, At) and GL_TEXTURE_ENV_COLOR `c` (Cc):
//   GL_REPLACE   C = Ct                    A = At
//   GL_MODULATE  C = Cf Ct                 A = Af At
//   GL_DECAL     C = Cf (1 - At) + Ct At   A = Af
//   GL_BLEND     C = Cf (1 - Ct) + Cc Ct   A = Af At
//   GL_ADD       C = min(1, Cf + Ct)       A = Af At
Colour texEnv(GLenum mode, const Colour& f, const Colour& t, const Colour& c);
// The same over boxes of fragment and texel colours: each channel is
// multilinear in (Cf, Ct, Af, At), so its extremes lie on the corners.
Box texEnvBox(GLenum mode, const Box& f, const Box& t, const Colour& c);
bool texEnvModelled(GLenum mode);
// GL_COLOR_SUM: the secondary colour added to RGB after texturing, clamped.
Colour colourSum(const Colour& c, const Colour& secondary);

// Combines two sets of level values with blend weights f in [f0, f1]:
// (1 - f) a + f b for every pair, as boxes.
void blendBoxes(const Boxes& a, const Boxes& b, double f0, double f1, Boxes* out);
}  // namespace ref
