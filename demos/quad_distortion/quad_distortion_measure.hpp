// demos/quad_distortion/quad_distortion_measure.hpp — the measurement of
// demos/quad_distortion, read from a render of the square whose texel
// (i, j) holds R = i, G = j (GL_NEAREST): the picture then says which texel
// every pixel took.  Two things follow:
//  * the texel each pixel took is compared with the analytic map (the
//    triangles' affine maps, the bilinear map or the homography);
//  * the diagonal is cut into 8 segments; beside each, on either side, in a
//    band 1.5 .. N/16 pixels wide, s and t (in texels) are fitted by
//    quadratics in (a, b); the gradients of the two fits at the segment's
//    centre give the angle between the checker lines on either side.
//    Affine triangles: the angle of predictedKinkDeg; bilinear and
//    projective: ~0, the gradient is continuous.
// Kept out of quad_distortion.cpp so that file shows the figure first.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/core/image.hpp"
#include "common/core/probe.hpp"
#include "common/core/textures.hpp"
#include "quad_distortion_math.hpp"

namespace quad {
inline glm::dvec2 segmentCentre(quad::Diagonal d, int seg, int segments) {
  double u = (seg + 0.5) / segments;
  return d == quad::Diagonal::TopLeftBottomRight ? glm::dvec2(u, 1 - u) : glm::dvec2(u, u);
}

// The kink (degrees) in `img`, an N x N texel-index render of the unit square
// split along `diagonal` with a texture of T texels a side; `analytic` maps
// (a, b) to the (s, t) the variant should show.  *texelError: the largest
// distance (texels of T) between the texel taken and the analytic one.
template <typename Analytic>
double kinkDeg(const ts::Image& img, int T, quad::Diagonal diagonal, Analytic analytic, double* texelError) {
  const int N = img.width;
  // Samples per diagonal segment and side: [segment][side][s or t].
  constexpr int kSegments = 8;
  std::vector<ts::probe::Sample> samples[kSegments][2][2];
  const double band = N / 16.0;
  double worst = 0;
  for (int y = 0; y < N; ++y)
    for (int x = 0; x < N; ++x) {
      glm::dvec2 ab((x + 0.5) / N, 1.0 - (y + 0.5) / N);
      glm::dvec2 want = analytic(ab) * double(T);
      int i = 0, j = 0;
      ts::decodeTexelIndex(img.at(x, y), &i, &j);
      // Unwrap the index to the repeat the analytic value is in.
      double si = i + T * std::round((want.x - i - 0.5) / T) + 0.5;
      double ti = j + T * std::round((want.y - j - 0.5) / T) + 0.5;
      worst = std::max({worst, std::abs(std::floor(want.x) + 0.5 - si), std::abs(std::floor(want.y) + 0.5 - ti)});
      // Signed distance (pixels) from the diagonal, positive in the second
      // triangle, and position along it in [0, 1].
      bool tlbr = diagonal == quad::Diagonal::TopLeftBottomRight;
      double d = (tlbr ? ab.x + ab.y - 1.0 : ab.y - ab.x) * N / std::sqrt(2.0);
      double along = tlbr ? (ab.x - ab.y + 1.0) / 2.0 : (ab.x + ab.y) / 2.0;
      if (std::abs(d) < 1.5 || std::abs(d) > band || along <= 0 || along >= 1) continue;
      int seg = std::min(kSegments - 1, int(along * kSegments));
      glm::dvec2 c = segmentCentre(diagonal, seg, kSegments);
      int side = d < 0 ? 0 : 1;
      // Local coordinates around the segment's centre keep the fit well
      // conditioned and its gradient at (0, 0) the gradient on the diagonal.
      samples[seg][side][0].push_back({ab.x - c.x, ab.y - c.y, si});
      samples[seg][side][1].push_back({ab.x - c.x, ab.y - c.y, ti});
    }
  *texelError = worst;
  double kink = 0;
  for (auto& seg : samples)
    for (int k = 0; k < 2; ++k) {
      ts::probe::Fit a = ts::probe::fit(seg[0][k], true), b = ts::probe::fit(seg[1][k], true);
      kink = std::max(kink, quad::angleDeg({a.c[1], a.c[2]}, {b.c[1], b.c[2]}));
    }
  return kink;
}
}  // namespace quad
