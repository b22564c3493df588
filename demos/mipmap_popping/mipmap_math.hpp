// demos/mipmap_popping/mipmap_math.hpp — the mathematics of mipmapping and
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

namespace mipmap {
constexpr int kTexels = 256;             // the textures are 256 x 256: levels 0..8
constexpr int kLevels = 9;
constexpr double kTexelsPerUnit = 256;   // D: the texture repeats once per world unit
constexpr double kFocalPixels = 256;     // F of the facing-plane camera
constexpr double kPlaneHalf = 32;        // the facing plane is 64 x 64 world units

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

// --- level of detail -------------------------------------------------------
struct Jacobian {
  double dudx = 0, dudy = 0, dvdx = 0, dvdy = 0;  // texels per pixel
};
inline double rhoExact(const Jacobian& j) {
  return std::max(std::hypot(j.dudx, j.dvdx), std::hypot(j.dudy, j.dvdy));
}
// GL allows any rho in [max(mu, mv), mu + mv].  Mesa's two rasterisers stay
// inside the lower part: softpipe takes the largest component max(mu, mv)
// (the interval's low end), llvmpipe the exact lengths; the tests allow
// that range [lo, hi].  (For the facing plane lo = hi.)
inline void rhoBounded(const Jacobian& j, double* lo, double* hi) {
  double mu = std::max(std::abs(j.dudx), std::abs(j.dudy)), mv = std::max(std::abs(j.dvdx), std::abs(j.dvdy));
  *lo = std::max(mu, mv);
  *hi = rhoExact(j);
}

// The level a *_MIPMAP_NEAREST filter uses at lambda (bias included).
inline int nearestLevel(double lambda, int levels = kLevels) {
  if (lambda <= 0.5) return 0;
  return std::min(levels - 1, int(std::ceil(lambda + 0.5)) - 1);
}
// The two levels and the weight of the second for *_MIPMAP_LINEAR.
struct LevelBlend {
  int lo = 0, hi = 0;
  double weight = 0;  // of `hi`
};
inline LevelBlend linearLevels(double lambda, int levels = kLevels) {
  if (lambda <= 0) return {0, 0, 0};
  if (lambda >= levels - 1) return {levels - 1, levels - 1, 0};
  int k = int(std::floor(lambda));
  return {k, k + 1, lambda - k};
}
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

// --- cameras and planes ----------------------------------------------------
// A pinhole camera: world -> camera rotation R and eye E; focal length F in
// pixels; (cx, cy) the principal point, panel-relative GL pixels.
struct Camera {
  glm::dmat3 rot{1.0};
  glm::dvec3 eye{0.0};
  double focal = kFocalPixels;
  double cx = 0, cy = 0;
  double nearZ = 0.05, farZ = 4000;
  glm::mat4 projection(int w, int h) const {
    // Pixel x of the panel sees camera-space x/(-z) = (x - cx)/F.
    double n = nearZ;
    return glm::frustum(float(-cx / focal * n), float((w - cx) / focal * n), float(-cy / focal * n),
                        float((h - cy) / focal * n), float(n), float(farZ));
  }
  glm::mat4 modelview() const {
    glm::dmat4 m(rot);
    m = m * glm::translate(glm::dmat4(1.0), -eye);
    return glm::mat4(m);
  }
};
struct Plane {
  glm::dvec3 origin{0.0}, e1{1, 0, 0}, e2{0, 1, 0};  // e1, e2 orthonormal
  double density = kTexelsPerUnit;                    // texels per world unit
  glm::dvec3 normal() const { return glm::cross(e1, e2); }
};

// (a, b) on the plane and the texel-space Jacobian at panel-relative GL
// pixel coordinates (x, y) (y up).  Returns false when the ray misses the
// plane (at or above the horizon).
inline bool planeAt(const Camera& c, const Plane& p, double x, double y, glm::dvec2* ab, Jacobian* j) {
  glm::dmat3 rt = glm::transpose(c.rot);
  glm::dvec3 r = rt * glm::dvec3((x - c.cx) / c.focal, (y - c.cy) / c.focal, -1.0);
  glm::dvec3 rx = rt * glm::dvec3(1.0 / c.focal, 0, 0), ry = rt * glm::dvec3(0, 1.0 / c.focal, 0);
  glm::dvec3 n = p.normal();
  double nr = glm::dot(n, r);
  if (std::abs(nr) < 1e-15) return false;
  double lambda = glm::dot(n, p.origin - c.eye) / nr;
  if (lambda <= 0) return false;
  glm::dvec3 P = c.eye + lambda * r;
  if (ab) *ab = {glm::dot(P - p.origin, p.e1), glm::dot(P - p.origin, p.e2)};
  if (j) {
    glm::dvec3 dPx = lambda * (rx - r * (glm::dot(n, rx) / nr)), dPy = lambda * (ry - r * (glm::dot(n, ry) / nr));
    j->dudx = p.density * glm::dot(p.e1, dPx);
    j->dudy = p.density * glm::dot(p.e1, dPy);
    j->dvdx = p.density * glm::dot(p.e2, dPx);
    j->dvdy = p.density * glm::dot(p.e2, dPy);
  }
  return true;
}

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

// The slanted view: a ground plane y = 0 seen from height 1, the camera
// pitched down so the horizon is a tenth of the panel from its top; focal
// length from a 60 degree horizontal field of view.  Texture: s = x, t = -z
// (one repeat per world unit, t growing away from the eye).
constexpr double kSlantFovX = 60.0;
// yawDeg, pitchDeg, zoom: the mouse's orbit (common/core/orbit_camera.hpp): the
// eye stays, the view turns about the vertical and tilts, the lens zooms.
inline Camera slantCamera(int w, int h, double yawDeg = 0, double pitchDeg = 0, double zoom = 1) {
  Camera c;
  c.cx = w / 2.0, c.cy = h / 2.0;
  c.focal = (w / 2.0) / std::tan(glm::radians(kSlantFovX / 2));
  double pitch = std::atan(0.4 * h / c.focal);  // horizon at 0.4 h above the centre
  pitch += glm::radians(pitchDeg);
  c.focal *= zoom;
  c.rot = glm::dmat3(glm::rotate(glm::dmat4(1.0), pitch, glm::dvec3(1, 0, 0)));
  if (yawDeg != 0) c.rot = c.rot * glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(yawDeg), glm::dvec3(0, 1, 0)));
  c.eye = {0, 1, 0};
  c.nearZ = 0.05;
  c.farZ = 4000;
  return c;
}
inline Plane groundPlane() {
  Plane p;
  p.origin = {0, 0, 0};
  p.e1 = {1, 0, 0};
  p.e2 = {0, 0, -1};  // n = e1 x e2 = (0, 1, 0)
  return p;
}
constexpr double kGroundHalfWidth = 400, kGroundDepth = 200;

// --- probes ----------------------------------------------------------------
struct Mean {
  double r = 0, g = 0, b = 0;
};
inline Mean meanOf(const ts::Image& img, ts::Rect r) {
  Mean m;
  long n = 0;
  for (int y = std::max(0, r.y); y < std::min(img.height, r.y + r.h); ++y)
    for (int x = std::max(0, r.x); x < std::min(img.width, r.x + r.w); ++x) {
      ts::Rgba c = img.at(x, y);
      m.r += c.r, m.g += c.g, m.b += c.b, ++n;
    }
  if (n) m.r /= double(n), m.g /= double(n), m.b /= double(n);
  return m;
}
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

// Reads a colour of the mip-level-colours texture back as a level: the k
// (and blend weight f towards k + 1) whose (1 - f) C_k + f C_{k+1} is
// nearest to `c`.  Returns k + f; *residual is the distance left (8-bit).
inline double levelFromColour(const Mean& c, int levels = kLevels, double* residual = nullptr) {
  auto col = [](int k) {
    ts::Rgba q = ts::mipLevelColour(k);
    return glm::dvec3(q.r, q.g, q.b);
  };
  glm::dvec3 x(c.r, c.g, c.b);
  double best = 1e300, at = 0;
  for (int k = 0; k < levels; ++k) {
    glm::dvec3 a = col(k);
    double d0 = glm::length(x - a);
    if (d0 < best) best = d0, at = k;
    if (k + 1 < levels) {
      glm::dvec3 b = col(k + 1), ab = b - a;
      double f = std::clamp(glm::dot(x - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
      double d = glm::length(x - (a + f * ab));
      if (d < best - 1e-9) best = d, at = k + f;
    }
  }
  if (residual) *residual = best;
  return at;
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
      out.set(x, y, {uint8_t((s[0] + n / 2) / n), uint8_t((s[1] + n / 2) / n), uint8_t((s[2] + n / 2) / n),
                     uint8_t((s[3] + n / 2) / n)});
    }
  return out;
}
// RMS difference (8-bit units, over R, G, B) between two images where
// mask[y * w + x] is set.
inline double rmsError(const ts::Image& a, const ts::Image& b, const std::vector<char>& mask, long* count = nullptr) {
  double sum = 0;
  long n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (!mask[size_t(y) * size_t(a.width) + size_t(x)]) continue;
      ts::Rgba p = a.at(x, y), q = b.at(x, y);
      double dr = p.r - q.r, dg = p.g - q.g, db = p.b - q.b;
      sum += dr * dr + dg * dg + db * db;
      n += 3;
    }
  if (count) *count = n / 3;
  return n ? std::sqrt(sum / double(n)) : 0.0;
}
}  // namespace mipmap
