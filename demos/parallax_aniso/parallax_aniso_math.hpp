// demos/parallax_aniso/parallax_aniso_math.hpp — the mathematics of the parallax /
// anisotropic-filtering demo, free of OpenGL so tests can check it by hand:
//
//  * (the relief textures themselves, bricks, step and flat, are made in
//    common/core/relief_maps.hpp);
//  * the camera: a relief plane z = 0 seen from a height at a grazing angle;
//    the view ray of any window point, its texture coordinate on the top of
//    the relief and the parallax offset per unit of depth;
//  * Heckbert's EWA footprint ellipse A U^2 + B U V + C V^2 = F and its
//    Gaussian weights (the same formulas the GLSL uses);
//  * the supersampled reference: stratified jittered rays per pixel, each
//    traced finely through the height field, weighted by the EWA kernel;
//  * PSNR and SSIM over masks.
//
// Conventions.  Texture coordinates (u, v) are world (x, y) divided by the
// tile size; a height map stores h in [0, 1] (1 = top of the relief), the
// depth below the top plane is d = 1 - h, in units of the height scale S
// (world units).  A view ray that enters the top plane at uv0 is at
// uv0 + d * Vp at depth d, with Vp = dir.xy / (-dir.z) * S / tile (the
// parallax offset per unit depth, in texture coordinates).  Texel (i, j) of
// a level of size n has its centre at ((i + 0.5) / n, (j + 0.5) / n).
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "common/core/ewa.hpp"
#include "common/core/image.hpp"
#include "common/core/relief_maps.hpp"
#include "common/core/scene.hpp"

namespace pax {
using ts::relief::kTexSize;                 // every relief map is 512 x 512
constexpr double kAlpha = 2.0;              // Gaussian falloff of the EWA kernel: w = exp(-alpha q), q = Q/F in [0, 1]
constexpr double kMaxAniso = 16.0;          // the EWA's longest axis / shortest axis before the level is raised
constexpr double kHiddenEps = 1.5 / 255.0;  // a texel is hidden when relief rises above its ray by more than this

// ---------------------------------------------------------------- textures
// The maps themselves live in common/ (textures/make_textures writes them too).
using ts::relief::bricksTexel;
using ts::relief::chain;
using ts::relief::halve;
using ts::relief::hash32;
using ts::relief::makeRelief;
using ts::relief::Relief;
using ts::relief::stepTexel;
using ts::relief::u8;
using ts::relief::unit;

// Bilinear lookup at level 0 with GL_REPEAT, as GL_LINEAR does (8-bit units).
// std::floor's value without the library call a baseline x86-64 build makes
// for it (no SSE4.1 rounding instruction): the reference calls it some 500
// million times a table.  Exact for |x| < 2^62; -0 comes back as +0, which
// changes no sum below (x - floor(x) and the texel index are the same).
inline double floorFast(double x) {
  const double t = double((long long)x);
  return t > x ? t - 1.0 : t;
}

inline glm::dvec4 bilinear(const ts::Image& img, glm::dvec2 uv) {
  const double x = uv.x * img.width - 0.5, y = uv.y * img.height - 0.5;
  const double fx = floorFast(x), fy = floorFast(y);
  const double ax = x - fx, ay = y - fy;
  // GL_REPEAT: a mask when the size is a power of two (the relief maps'; the
  // same texel as the modulo, without its divisions), else the modulo.
  const bool pow2 = (img.width & (img.width - 1)) == 0 && (img.height & (img.height - 1)) == 0;
  auto at = [&](long i, long j) {
    if (pow2) i &= long(img.width) - 1, j &= long(img.height) - 1;
    else i = ((i % img.width) + img.width) % img.width, j = ((j % img.height) + img.height) % img.height;
    const uint8_t* p = &img.pixels[(size_t(j) * size_t(img.width) + size_t(i)) * 4];
    return glm::dvec4(p[0], p[1], p[2], p[3]);
  };
  const long i = long(fx), j = long(fy);
  return glm::mix(glm::mix(at(i, j), at(i + 1, j), ax), glm::mix(at(i, j + 1), at(i + 1, j + 1), ax), ay);
}
// Depth (1 - h) at uv, bilinear at level 0.
inline double depthAt(const Relief& r, glm::dvec2 uv) { return 1.0 - bilinear(r.height[0], uv).r / 255.0; }

// ---------------------------------------------------------------- camera
struct Camera {
  int width = 320, height = 240;
  double elevationDeg = 20.0;  // angle between the central view ray and the plane
  double azimuthDeg = 12.0;    // turn of the view about the plane's normal (0 = looking along +v)
  double fovyDeg = 24.0;
  double eyeHeight = 1.0;     // world units above the top of the relief
  double tile = 2.0;          // world units per repeat of the texture
  double heightScale = 0.06;  // world units from the top of the relief to h = 0
  glm::dvec3 eye() const { return {0.37, 0.21, eyeHeight}; }
  glm::dvec3 forward() const {
    double e = glm::radians(elevationDeg), a = glm::radians(azimuthDeg);
    return {std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), -std::sin(e)};
  }
  // Screen right and up, scaled so that ndc (x, y) in [-1, 1] spans the view.
  glm::dvec3 right() const {
    double a = glm::radians(azimuthDeg), t = std::tan(glm::radians(fovyDeg) / 2) * width / double(height);
    return glm::dvec3(std::cos(a), -std::sin(a), 0.0) * t;
  }
  glm::dvec3 up() const {
    glm::dvec3 f = forward(), r = glm::normalize(right());
    return glm::normalize(glm::cross(r, f)) * std::tan(glm::radians(fovyDeg) / 2);
  }
  // The view ray through window point p (GL convention: origin at the
  // bottom-left corner, pixel centres at i + 0.5).
  glm::dvec3 ray(glm::dvec2 p) const { return ray(basis(), p); }
  // forward(), right() and up() once, for a loop over many rays (each costs
  // sines and tangents); ray(basis(), p) is ray(p), bit for bit.
  struct Basis {
    glm::dvec3 f, r, u;
  };
  Basis basis() const { return {forward(), right(), up()}; }
  glm::dvec3 ray(const Basis& b, glm::dvec2 p) const {
    glm::dvec2 n = p / glm::dvec2(width, height) * 2.0 - 1.0;
    return b.f + n.x * b.r + n.y * b.u;
  }
  glm::dvec2 topUV(glm::dvec3 d) const {
    glm::dvec3 e = eye();
    double t = e.z / -d.z;
    return glm::dvec2(e.x + t * d.x, e.y + t * d.y) / tile;
  }
  // Parallax offset per unit depth (texture coordinates).
  glm::dvec2 parallax(glm::dvec3 d) const { return glm::dvec2(d.x, d.y) / (-d.z) * heightScale / tile; }
  // The screen derivatives of the top plane's (u, v) at p, in texture
  // coordinates per pixel (central differences over one pixel).
  void gradients(glm::dvec2 p, glm::dvec2* gx, glm::dvec2* gy) const {
    *gx = topUV(ray(p + glm::dvec2(0.5, 0))) - topUV(ray(p - glm::dvec2(0.5, 0)));
    *gy = topUV(ray(p + glm::dvec2(0, 0.5))) - topUV(ray(p - glm::dvec2(0, 0.5)));
  }
};

// ---------------------------------------------------------------- EWA
// Heckbert's ellipse from the screen derivatives, with the corrected F (the
// seed prints Ux Vy + Uy Vx: a sign slip), shared with the filter zoo through
// common/core/ewa.hpp (its GLSL twin, ts::ewa::glsl(), is pasted into this
// demo's shader): A = Vx^2 + Vy^2, B = -2 (Ux Vx + Uy Vy), C = Ux^2 + Uy^2,
// F = (Ux Vy - Uy Vx)^2; with the unit reconstruction filter A += 1, C += 1,
// F = A C - B^2 / 4.
using ts::ewa::Ellipse;
using ts::ewa::ellipse;
// The Gaussian weight of a texel at offset (U, V) from the centre: 0 outside.
inline double ewaWeight(const Ellipse& e, double U, double V) { return ts::ewa::weight(e, U, V, kAlpha); }
// The level EWA reads: log2 of the short semi-axis (in level-0 texels), or of
// the long one / kMaxAniso when the ellipse is thinner than that; >= 0.
inline double ewaLod(const Ellipse& plain) { return ts::ewa::lod(plain, kMaxAniso); }

// ---------------------------------------------------------------- tracing
// The first point where the ray entering at uv0 meets the relief: steps of at
// most half a texel of level 0, then bisection.  Returns the depth reached.
inline double traceFine(const Relief& r, glm::dvec2 uv0, glm::dvec2 Vp) {
  const double len = glm::length(Vp) * kTexSize;
  const int n = std::max(2, int(std::ceil(len / 0.5)));
  double prev = 0.0;
  for (int k = 1; k <= n; ++k) {
    double d = double(k) / n;
    if (d >= depthAt(r, uv0 + Vp * d)) {
      double lo = prev, hi = d;
      for (int it = 0; it < 14; ++it) {
        double m = 0.5 * (lo + hi);
        (m >= depthAt(r, uv0 + Vp * m) ? hi : lo) = m;
      }
      return hi;
    }
    prev = d;
  }
  return 1.0;
}

// traceFine, faster and bit for bit the same (renderReference traces some
// ten million rays per table with it).  Three things change, none the
// result: (1) a step is only looked up when it may hit: `Skip` holds, per
// cell between four texels of level 0 (the four a bilinear lookup in it
// reads), the largest of their heights, and so the least depth any lookup
// there can return (1 - that height / 255, less a margin far above
// rounding): a step above that depth cannot meet the relief; (2) the lookups
// that remain read a copy of the red channel alone, with the same arithmetic
// as bilinear(); (3) traceBatch halves the hit intervals of several rays
// side by side.  One ray's 14 halvings are a chain, each waiting on the
// last one's lookup and division; the chains of different rays overlap.
// The steps, the test and the halvings are traceFine's.
struct Skip {
  int size = 0;              // cells per side (= the map's, 512)
  std::vector<uint8_t> top;  // row-major, cell (i, j) = texels i..i+1, j..j+1 (wrapping): their largest height
  std::vector<uint8_t> red;  // the heights (level 0's red channel), row-major
  double leastOf[256];       // the least depth a lookup can return in a cell whose top is t
  explicit Skip(const Relief& r) {
    const ts::Image& h = r.height[0];
    size = h.width;
    red.resize(size_t(size) * size_t(size));
    top.resize(red.size());
    for (size_t p = 0; p < red.size(); ++p) red[p] = h.pixels[p * 4];
    auto at = [&](int i, int j) { return red[size_t(j & (size - 1)) * size_t(size) + size_t(i & (size - 1))]; };
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i)
        top[size_t(j) * size_t(size) + size_t(i)] = std::max({at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
    for (int t = 0; t < 256; ++t) leastOf[t] = 1.0 - t / 255.0 - 1e-9;
  }
  double least(long i, long j) const { return leastOf[top[size_t(j) * size_t(size) + size_t(i)]]; }
};
// depthAt's value, from the red channel alone (a square power-of-two map of
// `size` texels a side): each term as glm::mix forms it.
inline double depthFast(const uint8_t* red, long size, glm::dvec2 uv) {
  const double x = uv.x * size - 0.5, y = uv.y * size - 0.5;
  const double fx = floorFast(x), fy = floorFast(y);
  const double ax = x - fx, ay = y - fy;
  const long i = long(fx), j = long(fy), m = size - 1;
  auto at = [&](long a, long b) { return double(red[size_t(b & m) * size_t(size) + size_t(a & m)]); };
  auto mix = [](double p, double q, double t) {
    const double u = p * (1.0 - t);  // two statements: no contraction the vector form does not have
    const double v = q * t;
    return u + v;
  };
  return 1.0 - mix(mix(at(i, j), at(i + 1, j), ax), mix(at(i, j + 1), at(i + 1, j + 1), ax), ay) / 255.0;
}
// traceFine's walk down to the first step that meets the relief: whether it
// found one, and the interval [*lo, *hi] it leaves to halve.
inline bool stepToHit(const Skip& skip, glm::dvec2 uv0, glm::dvec2 Vp, double* lo, double* hi) {
  const double len = glm::length(Vp) * kTexSize;
  const int n = std::max(2, int(std::ceil(len / 0.5)));
  const long m = kTexSize - 1;
  double prev = 0.0;
  for (int k = 1; k <= n; ++k) {
    double d = double(k) / n;
    const glm::dvec2 p = uv0 + Vp * d;
    const long i = long(floorFast(p.x * kTexSize - 0.5)), j = long(floorFast(p.y * kTexSize - 0.5));
    if (d >= skip.least(i & m, j & m) && d >= depthFast(skip.red.data(), kTexSize, p)) {
      *lo = prev, *hi = d;
      return true;
    }
    prev = d;
  }
  return false;
}
// The depths where `count` rays (uv0[q], Vp[q]) meet the relief, as traceFine
// gives them, into depth[q].
inline void traceBatch(const Relief& r, const Skip& skip, const glm::dvec2* uv0, const glm::dvec2* Vp, int count,
                       double* depth) {
  const ts::Image& h = r.height[0];
  if (h.width != kTexSize || h.height != kTexSize || skip.size != kTexSize) {
    for (int q = 0; q < count; ++q) depth[q] = traceFine(r, uv0[q], Vp[q]);
    return;
  }
  constexpr int kBatch = 16;
  for (int q0 = 0; q0 < count; q0 += kBatch) {
    double iv[kBatch][2];  // [lo, hi] of each ray that found a step
    int which[kBatch], hits = 0;
    for (int q = q0; q < std::min(count, q0 + kBatch); ++q)
      if (stepToHit(skip, uv0[q], Vp[q], &iv[hits][0], &iv[hits][1])) which[hits++] = q;
      else depth[q] = 1.0;
    for (int it = 0; it < 14; ++it)
      for (int b = 0; b < hits; ++b) {
        const int q = which[b];
        const double mid = 0.5 * (iv[b][0] + iv[b][1]);
        iv[b][mid >= depthFast(skip.red.data(), kTexSize, uv0[q] + Vp[q] * mid)] = mid;  // hit: hi, else lo
      }
    for (int b = 0; b < hits; ++b) depth[which[b]] = iv[b][1];
  }
}
inline double traceFast(const Relief& r, const Skip& skip, glm::dvec2 uv0, glm::dvec2 Vp) {
  double depth = 1.0;
  traceBatch(r, skip, &uv0, &Vp, 1, &depth);
  return depth;
}

// Visibility of texel (i, j) of level `L` (texel-exact, nearest heights of
// that level): its surface point, at depth 1 - h, is hidden when, walking
// from it toward the eye in half-texel steps, the relief rises above the ray
// by more than kHiddenEps.  `Vt` = parallax offset per unit depth in texels
// of level L.  Mirrors the GLSL function hiddenTexel.
inline bool hiddenTexel(const std::vector<ts::Image>& heights, int L, int i, int j, glm::dvec2 Vt) {
  const ts::Image& img = heights[size_t(L)];
  auto depth = [&](long x, long y) {
    x = ((x % img.width) + img.width) % img.width;
    y = ((y % img.height) + img.height) % img.height;
    return 1.0 - img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) * 4] / 255.0;
  };
  const double d0 = depth(i, j);
  if (d0 <= kHiddenEps) return false;
  const glm::dvec2 c(i + 0.5, j + 0.5);
  const int n = int(std::ceil(2.0 * d0 * glm::length(Vt)));
  for (int k = 1; k <= n; ++k) {
    double s = d0 * double(k) / n;
    glm::dvec2 p = c - Vt * s;
    if (depth(long(std::floor(p.x)), long(std::floor(p.y))) < d0 - s - kHiddenEps) return true;
  }
  return false;
}

// ---------------------------------------------------------------- reference
struct Reference {
  int width = 0, height = 0;
  std::vector<glm::dvec3> rgb;      // row 0 = top, 8-bit units
  std::vector<double> depthSpread;  // max - min hit depth over the pixel's kernel rays
  ts::Image image() const {
    ts::Image out(width, height);
    for (size_t p = 0; p < rgb.size(); ++p)
      for (int c = 0; c < 3; ++c) out.pixels[p * 4 + size_t(c)] = u8(rgb[p][c]);
    return out;
  }
};

// n x n stratified rays over the kernel's square [-1, 1]^2 pixels around each
// pixel centre, jittered by a hash of (seed, pixel, ray); those inside the
// unit disc are traced (traceFine) and weighted exp(-alpha r^2): the same
// Gaussian as the EWA (Q / F = r^2 is the screen distance squared).  The
// albedo at each hit is bilinear at level 0.  Rows in parallel (2 threads).
// `progress` (may be null) is told the fraction of rows done, from the
// calling thread; ts::measureCancelled() stops the rows early (a superseded
// measurement in a window: the caller's next ts::measureProgress throws).
inline Reference renderReference(const Camera& cam, const Relief& r, int n, uint32_t seed,
                                 const std::function<void(double)>& progress = nullptr) {
  Reference out;
  out.width = cam.width;
  out.height = cam.height;
  out.rgb.assign(size_t(cam.width) * size_t(cam.height), glm::dvec3(0));
  out.depthSpread.assign(out.rgb.size(), 0.0);
  const Skip skip(r);
  const Camera::Basis basis = cam.basis();
  auto rows = [&](int y0, int step) {
    std::vector<glm::dvec2> uv0(size_t(n) * size_t(n)), Vp(uv0.size());  // a pixel's rays
    std::vector<double> r2s(uv0.size()), depths(uv0.size());
    for (int y = y0; y < cam.height; y += step) {
      if (ts::measureCancelled()) return;
      if (progress && y0 == 0) progress(double(y) / cam.height);
      for (int x = 0; x < cam.width; ++x) {
        const int gy = cam.height - 1 - y;  // GL row
        // The pixel's rays first, then their depths together (traceBatch), then
        // the sum in the rays' order.
        const uint32_t key = hash32(seed * 0x9e3779b9u ^ hash32(uint32_t(x) ^ hash32(uint32_t(gy) + 0x632be5abu)));
        int count = 0;
        for (int b = 0; b < n; ++b)
          for (int a = 0; a < n; ++a) {
            uint32_t k = key + 2u * uint32_t(b * n + a);
            double ox = -1.0 + 2.0 * (a + unit(hash32(k))) / n, oy = -1.0 + 2.0 * (b + unit(hash32(k + 1))) / n;
            double r2 = ox * ox + oy * oy;
            if (r2 >= 1.0) continue;
            glm::dvec3 d = cam.ray(basis, glm::dvec2(x + 0.5 + ox, gy + 0.5 + oy));
            uv0[size_t(count)] = cam.topUV(d), Vp[size_t(count)] = cam.parallax(d), r2s[size_t(count)] = r2;
            ++count;
          }
        traceBatch(r, skip, uv0.data(), Vp.data(), count, depths.data());  // = traceFine's, bit for bit
        glm::dvec3 sum(0);
        double wsum = 0, dmin = 2, dmax = -1;
        for (size_t q = 0; q < size_t(count); ++q) {
          const double depth = depths[q], w = std::exp(-kAlpha * r2s[q]);
          sum += w * glm::dvec3(bilinear(r.albedo[0], uv0[q] + Vp[q] * depth));
          wsum += w;
          dmin = std::min(dmin, depth);
          dmax = std::max(dmax, depth);
        }
        size_t p = size_t(y) * size_t(cam.width) + size_t(x);
        out.rgb[p] = wsum > 0 ? sum / wsum : glm::dvec3(0);
        out.depthSpread[p] = dmax - dmin;
      }
    }
  };
  std::thread t(rows, 1, 2);
  rows(0, 2);
  t.join();
  return out;
}

// ---------------------------------------------------------------- masks
// High anisotropy: the top plane's footprint ellipse is more than 4 times
// longer than wide.  Row 0 = top.
inline std::vector<uint8_t> anisotropyMask(const Camera& cam, double threshold = 4.0) {
  std::vector<uint8_t> m(size_t(cam.width) * size_t(cam.height), 0);
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      glm::dvec2 gx, gy;
      cam.gradients({x + 0.5, cam.height - 1 - y + 0.5}, &gx, &gy);
      glm::dvec2 rr = ellipse(gx.x, gx.y, gy.x, gy.y, false).radii();
      m[size_t(y) * size_t(cam.width) + size_t(x)] = rr.x > threshold * rr.y;
    }
  return m;
}
// The occlusion band: pixels whose kernel footprint crosses an occluding edge
// as the reference saw it — its rays hit depths more than half the relief
// apart (some on a top, some far below behind an edge).
inline std::vector<uint8_t> occlusionMask(const Reference& ref, double spread = 0.5) {
  std::vector<uint8_t> m(ref.depthSpread.size());
  for (size_t i = 0; i < m.size(); ++i) m[i] = ref.depthSpread[i] > spread;
  return m;
}

// ---------------------------------------------------------------- metrics
inline double psnr(const ts::Image& a, const ts::Image& b, const std::vector<uint8_t>* mask) {
  double se = 0;
  size_t n = 0;
  for (size_t p = 0; p < size_t(a.width) * size_t(a.height); ++p) {
    if (mask && !(*mask)[p]) continue;
    for (int c = 0; c < 3; ++c) {
      double d = double(a.pixels[p * 4 + size_t(c)]) - double(b.pixels[p * 4 + size_t(c)]);
      se += d * d;
    }
    n += 3;
  }
  if (n == 0) return std::nan("");
  double mse = se / double(n);
  return mse <= 0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

// SSIM (Wang et al. 2004) of the luma, 11 x 11 Gaussian window (sigma 1.5),
// C1 = (0.01 * 255)^2, C2 = (0.03 * 255)^2; the mean of the SSIM map over the
// mask's pixels (each pixel's window centred on it, clipped at the border).
inline double ssim(const ts::Image& a, const ts::Image& b, const std::vector<uint8_t>* mask) {
  const int w = a.width, h = a.height;
  auto luma = [&](const ts::Image& im) {
    std::vector<double> y(size_t(w) * size_t(h));
    for (size_t p = 0; p < y.size(); ++p)
      y[p] = 0.299 * im.pixels[p * 4] + 0.587 * im.pixels[p * 4 + 1] + 0.114 * im.pixels[p * 4 + 2];
    return y;
  };
  std::vector<double> X = luma(a), Y = luma(b);
  double g[11];
  for (int k = 0; k < 11; ++k) g[k] = std::exp(-(k - 5) * (k - 5) / (2 * 1.5 * 1.5));
  const double C1 = 6.5025, C2 = 58.5225;
  double sum = 0;
  size_t n = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      size_t p = size_t(y) * size_t(w) + size_t(x);
      if (mask && !(*mask)[p]) continue;
      double ws = 0, mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
      for (int dy = -5; dy <= 5; ++dy)
        for (int dx = -5; dx <= 5; ++dx) {
          int sx = x + dx, sy = y + dy;
          if (sx < 0 || sy < 0 || sx >= w || sy >= h) continue;
          double wt = g[dx + 5] * g[dy + 5];
          size_t q = size_t(sy) * size_t(w) + size_t(sx);
          ws += wt, mx += wt * X[q], my += wt * Y[q];
          xx += wt * X[q] * X[q], yy += wt * Y[q] * Y[q], xy += wt * X[q] * Y[q];
        }
      mx /= ws, my /= ws;
      double vx = xx / ws - mx * mx, vy = yy / ws - my * my, cxy = xy / ws - mx * my;
      sum += ((2 * mx * my + C1) * (2 * cxy + C2)) / ((mx * mx + my * my + C1) * (vx + vy + C2));
      ++n;
    }
  return n ? sum / double(n) : std::nan("");
}
}  // namespace pax
