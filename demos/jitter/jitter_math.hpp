// demos/jitter/jitter_math.hpp — the mathematics of Figure VI.7 (jittered
// supersampling), without OpenGL, shared by the demo and its tests.
//
// The scene: an infinite checkerboard on the plane y = 0 seen from a camera
// at height 1 pitched down a little, so that the checks shrink towards the
// horizon until they are far smaller than a pixel (the picture of the book's
// Figure X.9).  The checkerboard is analytic: (x, z) on the plane -> dark or
// light, so any sample position in any pixel has an exact colour.
//
// Pixels are addressed as OpenGL does: pixel (i, j) of a W x H viewport
// covers [i, i+1) x [j, j+1) in window coordinates, j counted from the
// bottom.  A sample position inside a pixel is (sx, sy) in [0, 1)^2; the
// pixel centre is (0.5, 0.5).
//
// The sample patterns of VI.1.4, n x n per pixel (the book: n = 3):
//   regular        subpixel centres ((a + 1/2)/n, (b + 1/2)/n);
//   jitter-global  one random point in each subpixel, the same for every
//                  pixel (the Red Book's accumulation-buffer jitter);
//   jitter-pixel   one random point in each subpixel, drawn independently
//                  for every pixel (what the book requires).
// The random numbers come from a hash of (seed, pixel, sample) — the same
// 32-bit integer arithmetic in C++ and in the GLSL of the demo — so every
// pattern is deterministic and the CPU knows where the GPU sampled.
//
// The error of an image against the reference (box filter over the pixel,
// 16 x 16 stratified samples) is split in two (analyse, below): the part of
// each pixel's error that its neighbours' errors predict — interference,
// structured aliasing — and the unpredictable rest — noise.
#pragma once
#include "common/core/hash.hpp"
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <thread>
#include <vector>

namespace jitter {
// Every measured image has this size, whatever the window or figure size.
constexpr int kImageW = 288, kImageH = 192;
// Samples per side of the reference (16 x 16 = 256 per pixel).
constexpr int kReferenceSide = 16;

// The colours, 8-bit values (the shader writes exactly these).
constexpr int kDark = 32, kLight = 224;
constexpr std::array<int, 3> kSky{150, 185, 225};

struct Camera {
  int width = kImageW, height = kImageH;
  double eyeHeight = 1.0;
  double pitchDeg = 14.0;  // looking down by this much
  double fovyDeg = 40.0;
  double check = 0.25;  // side of a check on the plane
  double farZ = 1.0e4;  // the drawn plane ends at z = -farZ (the horizon gap is < 0.05 px)
  double zNear = 0.05, zFar = 2.0e4;
};

inline glm::dmat4 projection(const Camera& c) {
  return glm::perspective(glm::radians(c.fovyDeg), double(c.width) / double(c.height), c.zNear, c.zFar);
}
inline glm::dmat4 view(const Camera& c) {
  glm::dmat4 v = glm::rotate(glm::dmat4(1.0), glm::radians(c.pitchDeg), glm::dvec3(1, 0, 0));
  return glm::translate(v, glm::dvec3(0, -c.eyeHeight, 0));
}
// The Red Book's accPerspective, as a matrix applied after the projection:
// the image moves by (dx, dy) pixels, so the pixel centre of the shifted
// image samples the original at centre - (dx, dy).  To sample pixel (i, j)
// at (i + sx, j + sy), shift by (0.5 - sx, 0.5 - sy).
inline glm::dmat4 pixelShift(const Camera& c, glm::dvec2 samplePos) {
  glm::dvec2 d = glm::dvec2(0.5) - samplePos;
  return glm::translate(glm::dmat4(1.0), glm::dvec3(2.0 * d.x / c.width, 2.0 * d.y / c.height, 0.0));
}

// The homography from window coordinates of the viewport (px, py) to the
// plane: H (px, py, 1) = (X, Z, S); the point is (X/S, Z/S) and it is in
// front of the eye iff S > 0.  (clip = M (x, 0, z, 1) is a projective map of
// the plane; H is its inverse composed with window -> NDC.)
// `after` is applied after the projection (a pixelShift: then H is the
// homography of the shifted image, H(p) = H0(p - shift)).
inline glm::dmat3 pixelToPlane(const Camera& c, const glm::dmat4& after = glm::dmat4(1.0)) {
  glm::dmat4 m = after * projection(c) * view(c);
  // Rows x_clip, y_clip, w_clip of M restricted to (x, z, 1).
  glm::dmat3 g;  // column-major: g[col][row]
  const int rows[3] = {0, 1, 3};
  for (int r = 0; r < 3; ++r) {
    g[0][r] = m[0][rows[r]];
    g[1][r] = m[2][rows[r]];
    g[2][r] = m[3][rows[r]];
  }
  glm::dmat3 ndc(1.0);
  ndc[0][0] = 2.0 / c.width;
  ndc[1][1] = 2.0 / c.height;
  ndc[2][0] = -1.0;
  ndc[2][1] = -1.0;
  return glm::inverse(g) * ndc;
}

// 0 = dark, 1 = light: the check containing (x, z).
inline int checkAt(double x, double z, double check) {
  double s = std::floor(x / check) + std::floor(z / check);
  return int(s - 2.0 * std::floor(s / 2.0));
}
// The colour (8-bit units, as doubles) at window position (px, py).
inline glm::dvec3 colourAt(const Camera& c, const glm::dmat3& h, double px, double py) {
  glm::dvec3 p = h * glm::dvec3(px, py, 1.0);
  if (p.z > 0.0) {
    double x = p.x / p.z, z = p.y / p.z;
    if (z >= -c.farZ) {
      double v = checkAt(x, z, c.check) ? kLight : kDark;
      return glm::dvec3(v);
    }
  }
  return glm::dvec3(kSky[0], kSky[1], kSky[2]);
}

// ---------------------------------------------------------------- patterns
// Chris Wellons' "lowbias32" integer hash (common/core/hash.hpp); the GLSL copy is
// in jitter_gl.hpp.
using ts::hash32;
// 24 random bits as a float in [0, 1): exact in single precision, so the GPU
// and the CPU agree bit for bit.
inline float unitFloat(uint32_t h) { return float(h >> 8) * (1.0f / 16777216.0f); }

// The per-pixel key of jitter-pixel (and of the reference with its own seed).
inline uint32_t pixelKey(uint32_t seed, uint32_t i, uint32_t j) {
  return hash32(seed ^ hash32(i ^ hash32(j + 0x632be5abu)));
}
// The key of jitter-global: one for the whole image.
inline uint32_t globalKey(uint32_t seed) { return hash32(seed ^ 0x5bd1e995u); }
// The reference's fixed seed (independent of --seed).
constexpr uint32_t kReferenceSeed = 0xa511e9b3u;

// Sample k = b*n + a (subpixel column a, row b from the bottom) jittered by
// the key: ((a + u)/n, (b + v)/n) with u, v in [0, 1), so it stays inside
// subpixel (a, b).  Computed in float as the shader does.
inline glm::dvec2 jittered(uint32_t key, int n, int k) {
  int a = k % n, b = k / n;
  float u = unitFloat(hash32(key + 2u * uint32_t(k))), v = unitFloat(hash32(key + 2u * uint32_t(k) + 1u));
  return {double((float(a) + u) / float(n)), double((float(b) + v) / float(n))};
}
inline glm::dvec2 regular(int n, int k) { return {(k % n + 0.5) / n, (k / n + 0.5) / n}; }

// Pure random sampling (Buss VI.1.4 contrasts it with jittering): n x n points anywhere in the
// pixel, drawn independently per pixel, no strata — so they can cluster
// (Buss: "pure random sampling clusters"), and at 9 samples its error
// exceeds jittered sampling's.  The demo's mode "random" renders it with GL
// (jitter_gl.hpp, pixelRandomFS: the same hash); renderCpu models it.
inline glm::dvec2 randomIn(uint32_t key, int k) {
  return {double(unitFloat(hash32(key + 2u * uint32_t(k)))), double(unitFloat(hash32(key + 2u * uint32_t(k) + 1u)))};
}
constexpr uint32_t kRandomSalt = 0x27d4eb2fu;  // keeps random's points apart from jitter-pixel's

enum class Pattern { Regular, JitterGlobal, JitterPixel, Reference, Random };
// The key pixel (i, j)'s samples are drawn with (none for Regular).
inline uint32_t keyOf(Pattern p, uint32_t seed, int i, int j) {
  switch (p) {
    case Pattern::Regular: return 0;
    case Pattern::JitterGlobal: return globalKey(seed);
    case Pattern::JitterPixel: return pixelKey(seed, uint32_t(i), uint32_t(j));
    case Pattern::Reference: return pixelKey(kReferenceSeed, uint32_t(i), uint32_t(j));
    case Pattern::Random: return pixelKey(seed ^ kRandomSalt, uint32_t(i), uint32_t(j));
  }
  return 0;
}
// Sample k of n x n in the pixel whose key is `key` (keyOf).  Reference ignores n (16 x 16).
inline glm::dvec2 sampleOf(Pattern p, int n, uint32_t key, int k) {
  switch (p) {
    case Pattern::Regular: return regular(n, k);
    case Pattern::JitterGlobal:
    case Pattern::JitterPixel: return jittered(key, n, k);
    case Pattern::Reference: return jittered(key, kReferenceSide, k);
    case Pattern::Random: return randomIn(key, k);
  }
  return {0.5, 0.5};
}
// Sample k of n x n in pixel (i, j).  Reference ignores n and seed (16 x 16).
inline glm::dvec2 samplePos(Pattern p, int n, uint32_t seed, int i, int j, int k) {
  return sampleOf(p, n, keyOf(p, seed, i, j), k);
}
inline int sideOf(Pattern p, int n) { return p == Pattern::Reference ? kReferenceSide : n; }

// ---------------------------------------------------------------- images
// A float RGB image in 8-bit units, rows top first (as ts::Image): row r
// holds GL pixel row j = height - 1 - r.
struct FloatImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // width * height * 3
  FloatImage() = default;
  FloatImage(int w, int h) : width(w), height(h), rgb(size_t(w) * size_t(h) * 3, 0.0f) {}
  float* at(int x, int row) { return &rgb[(size_t(row) * size_t(width) + size_t(x)) * 3]; }
  const float* at(int x, int row) const { return &rgb[(size_t(row) * size_t(width) + size_t(x)) * 3]; }
};

// The CPU render of a pattern: box filter of n x n samples per pixel.
inline FloatImage renderCpu(const Camera& c, Pattern p, int n, uint32_t seed) {
  const glm::dmat3 h = pixelToPlane(c);
  const int side = sideOf(p, n), count = side * side;
  FloatImage img(c.width, c.height);
  // Rows on two threads (the reference is 256 samples a pixel), each taking
  // the next row not yet taken: every pixel's samples depend on (i, j, k)
  // alone, so the image is the one a single thread makes.
  std::atomic<int> next{0};
  auto rows = [&] {
    for (int j; (j = next.fetch_add(1)) < c.height;)
      for (int i = 0; i < c.width; ++i) {
        glm::dvec3 sum(0.0);
        const uint32_t key = keyOf(p, seed, i, j);  // once a pixel, not once a sample
        for (int k = 0; k < count; ++k) {
          glm::dvec2 s = sampleOf(p, n, key, k);
          sum += colourAt(c, h, i + s.x, j + s.y);
        }
        float* o = img.at(i, c.height - 1 - j);
        for (int ch = 0; ch < 3; ++ch) o[ch] = float(sum[ch] / count);
      }
  };
  std::thread other(rows);
  rows();
  other.join();
  return img;
}

// ---------------------------------------------------------------- errors
// The error of an image (8-bit RGBA, rows top first: a ts::Image's pixels)
// against the reference, one number per pixel: the mean over R, G, B of
// (image - reference) / 255, so errors are fractions of full scale.
inline std::vector<double> errorImage(const uint8_t* rgba, const FloatImage& ref) {
  std::vector<double> e(size_t(ref.width) * size_t(ref.height));
  for (size_t p = 0; p < e.size(); ++p) {
    double s = 0;
    for (int ch = 0; ch < 3; ++ch) s += double(rgba[p * 4 + size_t(ch)]) - double(ref.rgb[p * 3 + size_t(ch)]);
    e[p] = s / (3.0 * 255.0);
  }
  return e;
}

// The error split in two by linear prediction.  One linear rule, fitted by
// least squares over the whole image, predicts each pixel's error from the
// errors of the 24 pixels around it (5 x 5 less the centre).  Interference
// patterns repeat — along a row, across rows — so a good part of them is
// predictable: that part is the structured aliasing.  Independent per-pixel
// errors (what jitter leaves) cannot be predicted from their neighbours:
// the residual is the noise.  rms^2 = aliasing^2 + noise^2 exactly, all
// three over the pixels at least kPredictRadius from the border.  White noise
// "explains" only about 24/N of its own energy (N ~ 52000 pixels): ~2% of its
// RMS.  (A low-pass blur does not separate the two here: the checkerboard's
// interference near the horizon alternates from pixel to pixel, so a blur
// removes it along with the grain.)
constexpr int kPredictRadius = 2;

struct ErrorStats {
  double rms = 0;       // RMS of the error
  double aliasing = 0;  // RMS of its predictable part: interference, moire
  double noise = 0;     // RMS of the unpredictable rest: grain
};

// Solves the symmetric system a x = b (k x k, row-major) by Gaussian
// elimination with partial pivoting; rows with no pivot give 0.
inline std::vector<double> solve(std::vector<double> a, std::vector<double> b, int k) {
  double scale = 0;
  for (int i = 0; i < k; ++i) scale = std::max(scale, std::abs(a[size_t(i * k + i)]));
  const double tiny = 1e-12 * std::max(scale, 1e-300);
  std::vector<int> pivotOf(size_t(k), -1);
  for (int c = 0, r = 0; c < k && r < k; ++c) {
    int p = r;
    for (int i = r + 1; i < k; ++i)
      if (std::abs(a[size_t(i * k + c)]) > std::abs(a[size_t(p * k + c)])) p = i;
    if (std::abs(a[size_t(p * k + c)]) <= tiny) continue;
    for (int j = 0; j < k; ++j) std::swap(a[size_t(r * k + j)], a[size_t(p * k + j)]);
    std::swap(b[size_t(r)], b[size_t(p)]);
    for (int i = r + 1; i < k; ++i) {
      double f = a[size_t(i * k + c)] / a[size_t(r * k + c)];
      for (int j = c; j < k; ++j) a[size_t(i * k + j)] -= f * a[size_t(r * k + j)];
      b[size_t(i)] -= f * b[size_t(r)];
    }
    pivotOf[size_t(c)] = r++;
  }
  std::vector<double> x(size_t(k), 0.0);
  for (int c = k - 1; c >= 0; --c) {
    int r = pivotOf[size_t(c)];
    if (r < 0) continue;
    double v = b[size_t(r)];
    for (int j = c + 1; j < k; ++j) v -= a[size_t(r * k + j)] * x[size_t(j)];
    x[size_t(c)] = v / a[size_t(r * k + c)];
  }
  return x;
}

inline ErrorStats analyse(const std::vector<double>& e, int w, int h, int radius = kPredictRadius) {
  std::vector<int> offsets;  // the neighbours, as index offsets
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx)
      if (dx || dy) offsets.push_back(dy * w + dx);
  const int k = int(offsets.size());
  std::vector<double> ata(size_t(k * k), 0.0), atb(size_t(k), 0.0), v(static_cast<size_t>(k), 0.0);
  double ee = 0;
  long count = 0;
  for (int y = radius; y < h - radius; ++y)
    for (int x = radius; x < w - radius; ++x) {
      const size_t p = size_t(y) * size_t(w) + size_t(x);
      const double t = e[p];
      for (int i = 0; i < k; ++i) v[size_t(i)] = e[size_t(long(p) + offsets[size_t(i)])];
      for (int i = 0; i < k; ++i) {
        if (v[size_t(i)] == 0.0) continue;
        atb[size_t(i)] += v[size_t(i)] * t;
        for (int j = i; j < k; ++j) ata[size_t(i * k + j)] += v[size_t(i)] * v[size_t(j)];
      }
      ee += t * t;
      ++count;
    }
  if (count == 0) return {};
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < i; ++j) ata[size_t(i * k + j)] = ata[size_t(j * k + i)];
  std::vector<double> coef = solve(ata, atb, k);
  double explained = 0;
  for (int i = 0; i < k; ++i) explained += coef[size_t(i)] * atb[size_t(i)];
  explained = std::clamp(explained, 0.0, ee);
  const double n = double(count);
  return {std::sqrt(ee / n), std::sqrt(explained / n), std::sqrt((ee - explained) / n)};
}
// The RMS error of a pattern's n x n samples per pixel in the CPU model
// (renderCpu: the checkerboard is analytic), its pixels rounded to 8 bits as
// GL's are, against `reference`.
inline double cpuRms(Pattern p, int side, uint32_t seed, const FloatImage& reference) {
  const Camera cam;
  const FloatImage img = renderCpu(cam, p, side, seed);
  std::vector<uint8_t> rgba(size_t(cam.width) * size_t(cam.height) * 4, 255);
  for (size_t q = 0; q < size_t(cam.width) * size_t(cam.height); ++q)
    for (int ch = 0; ch < 3; ++ch) rgba[q * 4 + size_t(ch)] = uint8_t(std::lround(img.rgb[q * 3 + size_t(ch)]));
  return analyse(errorImage(rgba.data(), reference), cam.width, cam.height).rms;
}
}  // namespace jitter
