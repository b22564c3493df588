// demos/mipmap_popping/mipmap_popping_math.hpp — the mathematics of mipmapping and
// popping (Buss VI.1.3), shared by the demo and its tests.
//
// 1. Level of detail from the analytic derivatives.
//
//    A pinhole camera with focal length F pixels (the distance from the eye
//    to the image plane, measured in pixels) sees the pixel at
//    panel-relative GL coordinates (x, y) (origin bottom-left, pixel
//    centres at +0.5) along the ray r = ((x - cx)/F, (y - cy)/F, -1) in
//    camera space, (cx, cy) the panel's centre.  A textured plane is
//    P(a, b) = P0 + a e1 + b e2 (e1, e2 orthonormal, n = e1 x e2) with
//    texel coordinates u = D a + u0, v = D b + v0 (D texels per world unit).
//    The ray meets it at P = E + lambda r with lambda = n.(P0 - E) / n.r, and
//    differentiating (r depends linearly on x and y, dr/dx = e_x / F):
//        dP/dx = lambda (rx - r (n.rx) / (n.r)),   rx = R^T (1/F, 0, 0),
//    and the same for y; du/dx = D e1.dP/dx, dv/dx = D e2.dP/dx, ...  OpenGL
//    (4.6 §8.14.1) turns the four derivatives into the scale factor
//        rho = max( |(du/dx, dv/dx)|, |(du/dy, dv/dy)| )
//    and lambda_base = log2 rho, the level of detail; implementations may use
//    any f with max(mu, mv) <= f <= mu + mv, mu = max(|du/dx|, |du/dy|),
//    mv = max(|dv/dx|, |dv/dy|) (softpipe takes the max of the absolute
//    components, llvmpipe the exact lengths).  lambda = lambda_base + bias.
//
// 2. The facing plane (the popping experiment).  The plane z = -d faces the
//    eye, e1 = x, e2 = y: n.(P0 - E) = -d, n.r = -1, so lambda = d and
//    dP/dx = (d/F) e_x: every pixel has
//        du/dx = dv/dy = D d / F,   du/dy = dv/dx = 0,   rho = D d / F.
//    The LOD is the same over the whole plane, so the mean colour of any
//    probe region inside it shows exactly which level(s) GL used.  The demo
//    takes D = 256 (the 256-texel texture repeats once per world unit) and
//    F = 256 pixels, so rho = d: the distance *is* the number of texels per
//    pixel, and distance 2^x gives lambda_base = x.  That holds at any window
//    size, because the focal length is fixed in pixels (a larger window sees
//    more of the plane, at the same texel density).
//
// 3. Which level GL uses (4.6 §8.14.3), c = 0 (the switch-over point with a
//    GL_LINEAR or GL_NEAREST magnification filter and a mipmapped minifier):
//      lambda <= 0                   magnification: level 0
//      *_MIPMAP_NEAREST              level ceil(lambda + 1/2) - 1
//                                    (round to nearest, .5 rounds down),
//                                    clamped to the last level q
//      *_MIPMAP_LINEAR               levels floor(lambda), floor(lambda) + 1
//                                    blended with weight frac(lambda)
//                                    (the last level alone past q)
//      GL_NEAREST, GL_LINEAR         level 0 only, whatever lambda is.
//    So with a distance changing smoothly, a MIPMAP_NEAREST filter switches
//    level abruptly at lambda = k + 1/2 (popping); MIPMAP_LINEAR moves the
//    blend weight continuously (no popping).
//
// 4. Memory: level k of an N x N texture has (N/2^k)^2 texels, so the chain
//    adds N^2 (1/4 + 1/16 + ...) = N^2 (1 - 4^-q)/3 < N^2/3: about a third.
//
// Header-only so the demo and the tests share one copy.
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "common/core/textures.hpp"
#include "common/core/mip_lod.hpp"
#include "common/core/slant_plane.hpp"

namespace mipmap {
constexpr int kTexels = 256;  // the textures are 256 x 256: levels 0..8
constexpr int kLevels = 9;
constexpr double kTexelsPerUnit = 256;  // D: the texture repeats once per world unit
constexpr double kFocalPixels = 256;    // F of the facing-plane camera
constexpr double kPlaneHalf = 32;       // the facing plane is 64 x 64 world units

// The seven minification filters of the demo, in the order of --filter.
enum Filter {
  kNearest,
  kLinear,
  kNearestMipNearest,
  kLinearMipNearest,
  kNearestMipLinear,
  kLinearMipLinear,
  kAnisotropic,
  kFilterCount
};
inline const char* filterName(int f) {
  static const char* const k[] = {"nearest",
                                  "linear",
                                  "nearest-mipmap-nearest",
                                  "linear-mipmap-nearest",
                                  "nearest-mipmap-linear",
                                  "linear-mipmap-linear",
                                  "anisotropic"};
  return k[f];
}
inline const char* filterGLName(int f) {
  static const char* const k[] = {"GL_NEAREST",
                                  "GL_LINEAR",
                                  "GL_NEAREST_MIPMAP_NEAREST",
                                  "GL_LINEAR_MIPMAP_NEAREST",
                                  "GL_NEAREST_MIPMAP_LINEAR",
                                  "GL_LINEAR_MIPMAP_LINEAR",
                                  "anisotropic (trilinear + EXT_texture_filter_anisotropic)"};
  return k[f];
}
// Measurement names use underscores: "popping[nearest_mipmap_nearest]".
inline std::string filterKey(int f) {
  std::string s = filterName(f);
  for (char& c : s)
    if (c == '-') c = '_';
  return s;
}
inline GLenum minFilterEnum(int f) {
  switch (f) {
    case kNearest: return GL_NEAREST;
    case kLinear: return GL_LINEAR;
    case kNearestMipNearest: return GL_NEAREST_MIPMAP_NEAREST;
    case kLinearMipNearest: return GL_LINEAR_MIPMAP_NEAREST;
    case kNearestMipLinear: return GL_NEAREST_MIPMAP_LINEAR;
    default: return GL_LINEAR_MIPMAP_LINEAR;  // trilinear, and under anisotropic filtering
  }
}
// The magnification filter that goes with it (nearest-within-level filters
// magnify with GL_NEAREST).
inline GLenum magFilterEnum(int f) {
  return f == kNearest || f == kNearestMipNearest || f == kNearestMipLinear ? GL_NEAREST : GL_LINEAR;
}
inline bool usesMipmaps(int f) { return f != kNearest && f != kLinear; }
inline bool blendsLevels(int f) { return f == kNearestMipLinear || f == kLinearMipLinear || f == kAnisotropic; }

// Applies a filter (and the anisotropy level, the LOD bias) to a texture.
inline void applyFilter(ts::TextureDesc& t, int filter, int anisotropy, float lodBias) {
  t.minFilter = minFilterEnum(filter);
  t.magFilter = magFilterEnum(filter);
  t.maxAnisotropy = filter == kAnisotropic ? float(anisotropy) : 1.0f;
  t.lodBias = lodBias;
}

// --- level of detail (common/core/mip_lod.hpp) ----------------------------
using ts::lod::Jacobian;
using ts::lod::LevelBlend;
using ts::lod::rhoBounded;
using ts::lod::rhoExact;
// The level a *_MIPMAP_NEAREST filter uses at lambda (bias included).
inline int nearestLevel(double lambda, int levels = kLevels) { return ts::lod::nearestLevel(lambda, levels); }
// The two levels and the weight of the second for *_MIPMAP_LINEAR.
inline LevelBlend linearLevels(double lambda, int levels = kLevels) { return ts::lod::linearLevels(lambda, levels); }
// The "effective" level of a filter at lambda: what the probe should show
// in units of levels (k for nearest-level filters, k + weight for blends).
inline double effectiveLevel(int filter, double lambda, int levels = kLevels) {
  if (!usesMipmaps(filter)) return 0;
  if (blendsLevels(filter)) {
    LevelBlend b = linearLevels(lambda, levels);
    return b.lo + b.weight;
  }
  return nearestLevel(lambda, levels);
}

// --- cameras and planes (common/core/slant_plane.hpp) ---------------------
// A pinhole camera (focal length 256 pixels by default: kFocalPixels), a
// plane (256 texels per world unit: kTexelsPerUnit), where a pixel's ray
// meets it with the Jacobian there.
using ts::slant::Camera;
using ts::slant::Plane;
using ts::slant::planeAt;
static_assert(kFocalPixels == 256 && kTexelsPerUnit == 256, "ts::slant's defaults are this demo's");

// The facing plane at distance d, seen by a camera at the origin looking
// down -z with the principal point at the centre of a w x h panel.
inline Camera facingCamera(int w, int h, double d) {
  Camera c;
  c.cx = w / 2.0, c.cy = h / 2.0;
  c.nearZ = d / 2, c.farZ = d * 2;
  return c;
}
inline Plane facingPlane(double d) {
  Plane p;
  p.origin = {0, 0, -d};
  return p;
}
// lambda_base of the facing plane at distance d: log2(D d / F).
inline double facingLod(double d) { return std::log2(kTexelsPerUnit * d / kFocalPixels); }
inline double facingDistance(double lodBase) { return kFocalPixels / kTexelsPerUnit * std::exp2(lodBase); }

// The slanted view (common/core/slant_plane.hpp): a ground plane y = 0 seen
// from height 1, the camera pitched down so the horizon is a tenth of the
// panel from its top; focal length from a 60 degree horizontal field of
// view.  Texture: s = x, t = -z (one repeat per world unit, t growing away
// from the eye).
using ts::slant::groundPlane;
using ts::slant::kGroundDepth;
using ts::slant::kGroundHalfWidth;
using ts::slant::kSlantFovX;
using ts::slant::slantCamera;

// --- probes ----------------------------------------------------------------
using ts::lod::Mean;  // (common/core/mip_lod.hpp)
using ts::lod::meanOf;
inline double largestChannelDiff(const Mean& a, const Mean& b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}
// The popping measure: the largest jump of the probe's mean colour (largest
// channel, 8-bit units) between consecutive distances of a sweep.
inline double poppingMeasure(const std::vector<Mean>& sweep, int* where = nullptr) {
  double worst = 0;
  for (size_t k = 1; k < sweep.size(); ++k) {
    double d = largestChannelDiff(sweep[k - 1], sweep[k]);
    if (d > worst) {
      worst = d;
      if (where) *where = int(k);
    }
  }
  return worst;
}

// Reads a colour of the mip-level-colours texture back as a level: k + f
// (common/core/mip_lod.hpp).
inline double levelFromColour(const Mean& c, int levels = kLevels, double* residual = nullptr) {
  return ts::lod::levelOfColour(c, levels, residual);
}

// --- supersampled reference ------------------------------------------------
// Box-downsamples a k-times larger image (kw x kh) to w x h: the mean of each
// k x k block, in 8-bit values (the arithmetic GL's filters use on RGBA8).
inline ts::Image boxDownsample(const ts::Image& big, int k) {
  int w = big.width / k, h = big.height / k;
  ts::Image out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      long s[4] = {0, 0, 0, 0};
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
          ts::Rgba c = big.at(x * k + i, y * k + j);
          s[0] += c.r, s[1] += c.g, s[2] += c.b, s[3] += c.a;
        }
      long n = long(k) * k;
      out.set(x, y,
              {uint8_t((s[0] + n / 2) / n), uint8_t((s[1] + n / 2) / n), uint8_t((s[2] + n / 2) / n),
               uint8_t((s[3] + n / 2) / n)});
    }
  return out;
}
using ts::lod::rmsError;  // RMS over R, G, B where a mask is set (common/core/mip_lod.hpp)
}  // namespace mipmap
