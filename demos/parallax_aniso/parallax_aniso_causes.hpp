// demos/parallax_aniso/parallax_aniso_causes.hpp — the causes view of the parallax
// demo: seed 003's own equations, measured one by one on the CPU (no GL here;
// the seed's F rendered by the shader is in parallax_aniso_causes_gl.hpp).
//
//  1. Eq. (2), corrected: the derivatives of (u, v) as forward differences of
//     neighbouring pixels, du/dx = u(x+1, y) - u(x, y), dv/dx = v(x+1, y) -
//     v(x, y), ..., taken of the parallax-SHIFTED coordinate uvS (where each
//     pixel's view ray meets the relief, traceFine), against the analytic
//     derivatives of the top plane the Camera gives (what M1..M5 use).  On a
//     top or a floor they agree to a fraction of a texel; across an occluding
//     step uvS jumps by the parallax of the depth difference, tens of texels:
//     that jump is the footprint M0's texture() lookup takes (its fringes).
//     The seed prints dv/dx = v(x+1, y) - u(x, y): the typo variant, measured
//     too, is wrong everywhere.
//  2. Eq. (3), Fig. 3: the footprint's area (Heckbert: pi F / sqrt(A C -
//     B^2/4), texels of level 0) from the shifted coordinate's differences
//     over the area from the plain (top plane's) differences.
//  3. Fig. 4: the share of hidden texels (hiddenTexel) among the level-0
//     texels inside the footprint (the reconstructed ellipse around uvS),
//     binned by the footprint's area: the bigger the footprint, the likelier
//     it reaches behind higher relief.
//  4. Fig. 6: texels counted twice by the row walk from both ends.  M5's
//     "buffer" is one integer per row, `stop`, the index where the walk from
//     the left met its first hidden texel: the walk from the right runs only
//     if there was one (stop <= i1) and never past it.  Counted here, walking
//     exactly as the GLSL M5 does (both levels, the same ellipse and trace),
//     with that integer and without it (the walk from the right always runs,
//     to its first hidden texel or the row's start); and the seed's own walk
//     (from the right only after a hidden texel) without the bound.
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "common/core/ewa.hpp"
#include "common/core/image.hpp"
#include "parallax_aniso_math.hpp"

namespace pax::causes {
// One footprint-size bin of Fig. 4: level-0 texels inside the footprint
// (area of the plain ellipse) in (lo, hi].
struct Bin {
  std::string name;  // the measurement's name
  double lo = 0, hi = 0;
  long pixels = 0, texels = 0, hidden = 0;
  double share = 0, sampleError = 0;  // mean of the pixels' shares, its standard error
};

struct Cpu {
  int width = 0, height = 0, stride = 4;  // Fig. 4 and 6 sample every stride-th pixel each way
  // Per pixel, row 0 = top.
  std::vector<glm::dvec2> uvS;      // the shifted coordinate at the pixel centre
  std::vector<double> depth;        // the depth its ray reached (0 top .. 1 floor)
  std::vector<double> eq2Error;     // |forward difference - analytic|, texels of level 0 (max over the four)
  std::vector<double> eq2Typo;      // the same with the seed's printed dv/dx, dv/dy
  std::vector<uint8_t> steps;       // the ray depths of a forward neighbour more than half the relief apart
  std::vector<double> areaRatio;    // footprint area from the shifted differences / from the plain ones
  std::vector<double> hiddenShare;  // sampled pixels' hidden share (NaN between samples)
  double eq2Frame = 0, eq2Steps = 0, eq2TypoFrame = 0;
  long stepPixels = 0;
  double areaRatioMedian = 0, areaRatioStepsMedian = 0, areaRatioStepsP90 = 0;
  std::vector<Bin> bins;
  long walkedTexels = 0;  // texels the row walk (with its buffer) counted over the sampled pixels
  long doubleBuffer = 0, doubleNoBuffer = 0, doubleSeedNoBound = 0;
};

inline double median(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return std::isnan(x); }), v.end());
  if (v.empty()) return std::nan("");
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}
inline double quantile(std::vector<double> v, double q) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return std::isnan(x); }), v.end());
  if (v.empty()) return std::nan("");
  size_t k = std::min(v.size() - 1, size_t(q * double(v.size())));
  std::nth_element(v.begin(), v.begin() + long(k), v.end());
  return v[k];
}

// Heckbert's footprint area pi F / sqrt(A C - B^2/4) of the derivatives
// (Ux, Vx), (Uy, Vy) (texels), the corrected F: pi |Ux Vy - Uy Vx|.
inline double footprintArea(glm::dvec2 gx, glm::dvec2 gy) {
  const ts::ewa::Ellipse e = ts::ewa::ellipse(gx.x, gx.y, gy.x, gy.y, false);
  const double g = e.A * e.C - 0.25 * e.B * e.B;
  return g > 0 ? glm::pi<double>() * e.F / std::sqrt(g) : 0.0;
}

// The level-0 texels inside the reconstructed ellipse of (gx, gy) (texels)
// around c (texel units, centres at i + 1/2), row by row as ts::ewa::ewaLevel
// walks them: f(j, rowStart, rowEnd).
template <class F>
void ellipseTexels(glm::dvec2 c, glm::dvec2 gx, glm::dvec2 gy, const F& f) {
  ts::ewa::forEachRow(ts::ewa::ellipse(gx.x, gx.y, gy.x, gy.y, true), c, f);
}

// Fig. 6: the row walk of M5 on one row [i0, i1] of level L, `hidden(i)` the
// visibility trace.  Returns how many texels of the row were counted twice:
// `buffer` walks as the GLSL does (stop index); without it the walk from the
// right always runs to its first hidden texel; `seedNoBound` starts it only
// after a hidden texel (the seed's text) but does not stop at `stop`.
enum class Walk { kBuffer, kNoBuffer, kSeedNoBound };
template <class Hidden>
long rowWalkDoubles(long i0, long i1, const Hidden& hidden, Walk walk, long* counted) {
  if (i1 < i0) return 0;
  std::vector<int> n(size_t(i1 - i0 + 1), 0);
  long stop = i1 + 1;
  for (long i = i0; i <= i1; ++i) {
    if (hidden(i)) {
      stop = i;
      break;
    }
    n[size_t(i - i0)]++;
  }
  const bool runRight = walk == Walk::kNoBuffer || stop <= i1;
  const long bound = walk == Walk::kBuffer ? stop : i0 - 1;
  if (runRight)
    for (long i = i1; i > bound; --i) {
      if (hidden(i)) break;
      n[size_t(i - i0)]++;
    }
  long twice = 0;
  for (int k : n) {
    twice += k > 1;
    if (counted) *counted += k > 0;
  }
  return twice;
}

// The bins of Fig. 4 (level-0 texels in the footprint).
inline std::vector<Bin> footprintBins() {
  return {{"hidden_texel_share[footprint<=8]", 0, 8},
          {"hidden_texel_share[footprint8..32]", 8, 32},
          {"hidden_texel_share[footprint32..128]", 32, 128},
          {"hidden_texel_share[footprint>128]", 128, 1e30}};
}

// Everything above for one camera and relief.  The traces run in two threads
// (rows interleaved), as the reference does.
inline Cpu measureCpu(const Camera& cam, const Relief& rel, int stride = 4) {
  Cpu out;
  const int W = cam.width, H = cam.height;
  out.width = W, out.height = H, out.stride = stride;
  const double N = kTexSize;
  // The shifted coordinate at every pixel centre and one more column and row
  // (the forward neighbours of the last ones); GL rows (0 = bottom) here.
  std::vector<glm::dvec2> uvS(size_t(W + 1) * size_t(H + 1)), uv0(uvS.size());
  std::vector<double> dep(uvS.size());
  auto traceRows = [&](int y0, int step) {
    for (int gy = y0; gy <= H; gy += step)
      for (int x = 0; x <= W; ++x) {
        glm::dvec3 d = cam.ray({x + 0.5, gy + 0.5});
        glm::dvec2 u0 = cam.topUV(d), Vp = cam.parallax(d);
        double t = traceFine(rel, u0, Vp);
        size_t k = size_t(gy) * size_t(W + 1) + size_t(x);
        uv0[k] = u0, dep[k] = t, uvS[k] = u0 + Vp * t;
      }
  };
  {
    std::thread th(traceRows, 1, 2);
    traceRows(0, 2);
    th.join();
  }
  const size_t n = size_t(W) * size_t(H);
  out.uvS.resize(n), out.depth.resize(n), out.eq2Error.resize(n), out.eq2Typo.resize(n), out.steps.resize(n);
  out.areaRatio.resize(n), out.hiddenShare.assign(n, std::nan(""));
  std::vector<double> stepErr, stepRatio;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int gy = H - 1 - y;
      auto at = [&](int i, int j) { return size_t(j) * size_t(W + 1) + size_t(i); };
      const size_t k = at(x, gy), kx = at(x + 1, gy), ky = at(x, gy + 1);
      const size_t p = size_t(y) * size_t(W) + size_t(x);
      out.uvS[p] = uvS[k], out.depth[p] = dep[k];
      // Eq. (2), corrected, of the shifted coordinate; the analytic derivatives of the top plane.
      const glm::dvec2 fx = uvS[kx] - uvS[k], fy = uvS[ky] - uvS[k];
      glm::dvec2 ax, ay;
      cam.gradients({x + 0.5, gy + 0.5}, &ax, &ay);
      const glm::dvec2 ex = glm::abs(fx - ax) * N, ey = glm::abs(fy - ay) * N;
      out.eq2Error[p] = std::max({ex.x, ex.y, ey.x, ey.y});
      // The seed's printed Eq. (2): dv/dx = v(x+1, y) - u(x, y), dv/dy = v(x, y+1) - u(x, y).
      const double tvx = uvS[kx].y - uvS[k].x, tvy = uvS[ky].y - uvS[k].x;
      out.eq2Typo[p] = std::max({ex.x, ey.x, std::abs(tvx - ax.y) * N, std::abs(tvy - ay.y) * N});
      out.steps[p] = std::abs(dep[kx] - dep[k]) > 0.5 || std::abs(dep[ky] - dep[k]) > 0.5;
      // Eq. (3), Fig. 3: the footprint from the shifted differences over the plain one's.
      const double plain = footprintArea((uv0[kx] - uv0[k]) * N, (uv0[ky] - uv0[k]) * N);
      out.areaRatio[p] = plain > 0 ? footprintArea(fx * N, fy * N) / plain : std::nan("");
      if (out.steps[p]) {
        stepErr.push_back(out.eq2Error[p]);
        stepRatio.push_back(out.areaRatio[p]);
        out.stepPixels++;
      }
    }
  out.eq2Frame = median(out.eq2Error);
  out.eq2Steps = median(stepErr);
  out.eq2TypoFrame = median(out.eq2Typo);
  out.areaRatioMedian = median(out.areaRatio);
  out.areaRatioStepsMedian = median(stepRatio);
  out.areaRatioStepsP90 = quantile(stepRatio, 0.9);

  // Fig. 4 and Fig. 6 over every stride-th pixel (the middle of each block).
  out.bins = footprintBins();
  std::vector<std::vector<double>> shares(out.bins.size());
  const int levels = int(rel.height.size());
  for (int y = stride / 2; y < H; y += stride)
    for (int x = stride / 2; x < W; x += stride) {
      if (ts::measureCancelled()) return out;
      const int gy = H - 1 - y;
      const size_t p = size_t(y) * size_t(W) + size_t(x);
      glm::dvec2 gx, gyv;
      cam.gradients({x + 0.5, gy + 0.5}, &gx, &gyv);
      const glm::dvec3 d = cam.ray({x + 0.5, gy + 0.5});
      const glm::dvec2 Vp = cam.parallax(d);
      // Fig. 4: every level-0 texel inside the footprint, traced.
      long inside = 0, hid = 0;
      ellipseTexels(out.uvS[p] * N, gx * N, gyv * N, [&](long j, long i0, long i1) {
        for (long i = i0; i <= i1; ++i) {
          ++inside;
          hid += hiddenTexel(rel.height, 0, int(i), int(j), Vp * N);
        }
      });
      const double area = footprintArea(gx * N, gyv * N);
      for (size_t b = 0; b < out.bins.size(); ++b)
        if (area > out.bins[b].lo && area <= out.bins[b].hi && inside > 0) {
          out.bins[b].pixels++, out.bins[b].texels += inside, out.bins[b].hidden += hid;
          shares[b].push_back(double(hid) / double(inside));
        }
      if (inside > 0) out.hiddenShare[p] = double(hid) / double(inside);
      // Fig. 6: M5's walk on its levels (ts::ewa::lod of the plain ellipse,
      // two levels when the fraction is not 0), each row three ways.
      double l = ewaLod(ellipse(gx.x * N, gx.y * N, gyv.x * N, gyv.y * N, false));
      l = std::min(l, double(levels - 1));
      const int L0 = int(std::floor(l));
      for (int L = L0; L <= L0 + ((l - L0 > 0 && L0 < levels - 1) ? 1 : 0); ++L) {
        const double s = N / double(1 << L);
        const glm::dvec2 Vt = Vp * s;
        ellipseTexels(out.uvS[p] * s, gx * s, gyv * s, [&](long j, long i0, long i1) {
          std::vector<signed char> memo(size_t(std::max(0L, i1 - i0 + 1)), -1);
          auto hidden = [&](long i) {
            signed char& m = memo[size_t(i - i0)];
            if (m < 0) m = hiddenTexel(rel.height, L, int(i), int(j), Vt) ? 1 : 0;
            return m == 1;
          };
          out.doubleBuffer += rowWalkDoubles(i0, i1, hidden, Walk::kBuffer, &out.walkedTexels);
          out.doubleNoBuffer += rowWalkDoubles(i0, i1, hidden, Walk::kNoBuffer, nullptr);
          out.doubleSeedNoBound += rowWalkDoubles(i0, i1, hidden, Walk::kSeedNoBound, nullptr);
        });
      }
    }
  for (size_t b = 0; b < out.bins.size(); ++b) {
    Bin& bin = out.bins[b];
    const std::vector<double>& v = shares[b];
    if (v.empty()) {
      bin.share = bin.sampleError = std::nan("");
      continue;
    }
    double m = 0, q = 0;
    for (double x : v) m += x;
    m /= double(v.size());
    for (double x : v) q += (x - m) * (x - m);
    bin.share = m;
    bin.sampleError = v.size() > 1 ? std::sqrt(q / double(v.size() - 1) / double(v.size())) : std::nan("");
  }
  return out;
}

// ---------------------------------------------------------------- pictures
// A heat scale 0..1: dark blue, red, yellow (as the error view's).
inline glm::dvec3 heat(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v < 0.5 ? glm::mix(glm::dvec3(30, 20, 60), glm::dvec3(220, 40, 40), v * 2)
                 : glm::mix(glm::dvec3(220, 40, 40), glm::dvec3(255, 240, 80), v * 2 - 1);
}
// Eq. (2)'s error on a log scale: black below 1/16 texel, dark blue 1/16,
// red 1, yellow 16 texels or more.
inline ts::Image eq2Picture(const Cpu& c, const std::vector<double>& err) {
  ts::Image out(c.width, c.height);
  for (size_t p = 0; p < err.size(); ++p) {
    double e = err[p];
    glm::dvec3 col = e < 1.0 / 16 ? glm::dvec3(0) : heat((std::log2(e) + 4.0) / 8.0);
    out.set(int(p % size_t(c.width)), int(p / size_t(c.width)), {u8(col.r), u8(col.g), u8(col.b), 255});
  }
  return out;
}
// Area ratio: grey 1 (the same footprint), blue smaller (to 1/4), magenta larger
// (to 16 times and more).
inline ts::Image areaPicture(const Cpu& c) {
  ts::Image out(c.width, c.height);
  for (size_t p = 0; p < c.areaRatio.size(); ++p) {
    double r = c.areaRatio[p];
    glm::dvec3 grey(110, 110, 115), col = grey;
    if (std::isnan(r) || r <= 0) col = glm::dvec3(40, 80, 255);
    else if (r < 1) col = glm::mix(grey, glm::dvec3(40, 80, 255), std::min(1.0, -std::log2(r) / 2));
    else col = glm::mix(grey, glm::dvec3(230, 60, 200), std::min(1.0, std::log2(r) / 4));
    out.set(int(p % size_t(c.width)), int(p / size_t(c.width)), {u8(col.r), u8(col.g), u8(col.b), 255});
  }
  return out;
}
// The sampled hidden shares as stride x stride blocks on the heat scale:
// black none hidden, red half, yellow all.
inline ts::Image hiddenPicture(const Cpu& c) {
  ts::Image out(c.width, c.height);
  const int s = c.stride;
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      int sx = std::min(c.width - 1, (x / s) * s + s / 2), sy = std::min(c.height - 1, (y / s) * s + s / 2);
      double v = c.hiddenShare[size_t(sy) * size_t(c.width) + size_t(sx)];
      glm::dvec3 col = std::isnan(v) || v <= 0 ? glm::dvec3(0) : heat(v);
      out.set(x, y, {u8(col.r), u8(col.g), u8(col.b), 255});
    }
  return out;
}
// The largest difference of a channel between a and b, levels.
inline int maxDiff(const ts::Image& a, const ts::Image& b) {
  int m = 0;
  for (size_t p = 0; p < a.pixels.size(); ++p)
    if (p % 4 != 3) m = std::max(m, std::abs(int(a.pixels[p]) - int(b.pixels[p])));
  return m;
}
// |a - b| (mean of the channels) on the heat scale: black equal, red 4
// levels, yellow 8 or more (the slip's changes are small).
inline ts::Image diffPicture(const ts::Image& a, const ts::Image& b) {
  ts::Image out(a.width, a.height);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      size_t p = (size_t(y) * size_t(a.width) + size_t(x)) * 4;
      double e = 0;
      for (int k = 0; k < 3; ++k) e += std::abs(double(a.pixels[p + size_t(k)]) - double(b.pixels[p + size_t(k)]));
      glm::dvec3 col = e == 0 ? glm::dvec3(0) : heat(e / 3.0 / 8.0);
      out.set(x, y, {u8(col.r), u8(col.g), u8(col.b), 255});
    }
  return out;
}
}  // namespace pax::causes
