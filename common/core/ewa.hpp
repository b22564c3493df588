// common/core/ewa.hpp — Heckbert's elliptical weighted average (EWA), once,
// for every demo that filters with it: the parallax demo's shader EWA
// (demos/parallax_aniso, seed 003) and the filter zoo's (demos/filter_zoo).
//
// The footprint of a pixel in texture space is the ellipse
//     A U^2 + B U V + C V^2 = F,   U = u - u0, V = v - v0,
// from the screen derivatives (Ux, Vx) = d(u,v)/dx and (Uy, Vy) = d(u,v)/dy:
//     A = Vx^2 + Vy^2,  B = -2 (Ux Vx + Uy Vy),  C = Ux^2 + Uy^2,
//     F = (Ux Vy - Uy Vx)^2.
// Seed 003 prints F = (Ux Vy + Uy Vx)^2: a sign slip (with it F is not the
// squared Jacobian determinant, and Q/F is not the screen distance squared).
// The corrected F is the one here, in C++ (ellipse) and in GLSL (kGlsl), so
// the two demos cannot drift apart.
//
// The filter (ewaFilter): the level is log2 of the ellipse's short semi-axis
// in level-0 texels, or of the long one / maxAniso when it is thinner than
// that (never below 0), two levels blended by the fraction; on level L the
// ellipse of the derivatives in level-L texels with the unit reconstruction
// filter added (A += 1, C += 1, F = A C - B^2/4, never smaller than a texel)
// is walked row by row, and each texel inside (Q <= F; centre i + 1/2)
// weighted by exp(-alpha Q/F).  No GL.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace ts::ewa {
// `reconstruction` adds the unit reconstruction filter: A += 1, C += 1, and
// F becomes A C - B^2 / 4 (which is (Ux Vy - Uy Vx)^2 without the term: the
// Lagrange identity), so the ellipse is never smaller than a texel.
struct Ellipse {
  double A = 0, B = 0, C = 0, F = 0;
  double Q(double U, double V) const { return A * U * U + B * U * V + C * V * V; }
  // Semi-axes, longest first (F > 0).
  glm::dvec2 radii() const {
    double m = 0.5 * (A + C), d = 0.5 * std::sqrt((A - C) * (A - C) + B * B);
    double lo = std::max(m - d, 1e-300), hi = std::max(m + d, 1e-300);
    return {std::sqrt(F / lo), std::sqrt(F / hi)};
  }
};
inline Ellipse ellipse(double Ux, double Vx, double Uy, double Vy, bool reconstruction) {
  Ellipse e;
  e.A = Vx * Vx + Vy * Vy;
  e.B = -2.0 * (Ux * Vx + Uy * Vy);
  e.C = Ux * Ux + Uy * Uy;
  e.F = (Ux * Vy - Uy * Vx) * (Ux * Vy - Uy * Vx);
  if (reconstruction) {
    e.A += 1.0;
    e.C += 1.0;
    e.F = e.A * e.C - 0.25 * e.B * e.B;
  }
  return e;
}
// The Gaussian weight exp(-alpha Q/F) of a texel at offset (U, V) from the
// centre: 0 outside the ellipse.
inline double weight(const Ellipse& e, double U, double V, double alpha) {
  double q = e.Q(U, V) / e.F;
  return q <= 1.0 ? std::exp(-alpha * q) : 0.0;
}
// The level EWA reads: log2 of the short semi-axis (in level-0 texels), or of
// the long one / maxAniso when the ellipse is thinner than that; >= 0.
inline double lod(const Ellipse& plain, double maxAniso) {
  glm::dvec2 r = plain.radii();
  return std::max(0.0, std::log2(std::max({r.y, r.x / maxAniso, 1e-30})));
}

// The same coefficients and semi-axes in GLSL (1.20 and later), for shaders
// to paste in: vec4 ellipse(vec2 gx, vec2 gy, bool recon) with
// gx = (Ux, Vx), gy = (Uy, Vy), returning (A, B, C, F); vec2 radii(vec4 e).
// seedF: F as seed 003 prints it, (Ux Vy + Uy Vx)^2, to show what the slip
// does (demos/parallax_aniso's causes view); with the reconstruction term
// its F is that plus A + C + 1 (the corrected one is det^2 + A + C + 1, the
// Lagrange identity).  The default text is the corrected function alone.
inline std::string glsl(bool seedF = false) {
  const char* head = R"(
vec4 ellipse(vec2 gx, vec2 gy, bool recon) {  // gx = (Ux, Vx), gy = (Uy, Vy)
  float A = gx.y * gx.y + gy.y * gy.y;
  float B = -2.0 * (gx.x * gx.y + gy.x * gy.y);
  float C = gx.x * gx.x + gy.x * gy.x;
)";
  const char* corrected = R"(  float det = gx.x * gy.y - gy.x * gx.y;
  float F = det * det;
  if (recon) { A += 1.0; C += 1.0; F = A * C - 0.25 * B * B; }
)";
  const char* seed = R"(  float slip = gx.x * gy.y + gy.x * gx.y;  // seed 003's F: + where Heckbert has -
  float F = slip * slip;
  if (recon) { A += 1.0; C += 1.0; F += A + C - 1.0; }
)";
  return std::string(head) + (seedF ? seed : corrected) + R"(  return vec4(A, B, C, F);
}
vec2 radii(vec4 e) {  // semi-axes, longest first
  float m = 0.5 * (e.x + e.z), d = 0.5 * sqrt((e.x - e.z) * (e.x - e.z) + e.y * e.y);
  return vec2(sqrt(e.w / max(m - d, 1e-30)), sqrt(e.w / max(m + d, 1e-30)));
}
)";
}

// The texel rows inside the reconstructed ellipse `e` (F = A C - B^2/4) around c (texel units, texel (i, j)
// centred at (i + 1/2, j + 1/2)): row(j, i0, i1) for each row j that holds texel centres i0..i1.  The rows span
// V in [-sqrt(A), sqrt(A)].
template <class Row>
void forEachRow(const Ellipse& e, glm::dvec2 c, const Row& row) {
  c -= 0.5;
  const double vr = std::sqrt(e.A);
  const long j0 = long(std::ceil(c.y - vr)), j1 = long(std::floor(c.y + vr));
  for (long j = j0; j <= j1; ++j) {
    const double V = double(j) - c.y;
    const double disc = e.B * e.B * V * V - 4.0 * e.A * (e.C * V * V - e.F);
    if (disc < 0) continue;
    const double sq = std::sqrt(disc);
    const long i0 = long(std::ceil(c.x + (-e.B * V - sq) / (2.0 * e.A)));
    const long i1 = long(std::floor(c.x + (-e.B * V + sq) / (2.0 * e.A)));
    row(j, i0, i1);
  }
}

// EWA on level L of size (w, h): the texels inside the reconstructed
// ellipse of derivatives (Ux, Vx), (Uy, Vy) given in level-L texels around
// (u, v) (level-L texel units, texel (i, j) centred at (i + 1/2, j + 1/2)),
// each weighted exp(-alpha Q/F).  `texel(i, j)` returns a texel (wrapping
// as the caller likes) as glm::dvec4; `*reads` counts the texels read.
template <class Texel>
glm::dvec4 ewaLevel(const Texel& texel, double u, double v, double Ux, double Vx, double Uy, double Vy, double alpha,
                    long* reads) {
  const Ellipse e = ellipse(Ux, Vx, Uy, Vy, true);
  const glm::dvec2 c(u - 0.5, v - 0.5);
  glm::dvec4 sum(0.0);
  double wsum = 0;
  forEachRow(e, {u, v}, [&](long j, long i0, long i1) {
    const double V = double(j) - c.y;
    for (long i = i0; i <= i1; ++i) {
      const double U = double(i) - c.x;
      const double w = std::exp(-alpha * std::min(1.0, e.Q(U, V) / e.F));
      sum += w * texel(i, j);
      wsum += w;
      if (reads) ++*reads;
    }
  });
  if (wsum <= 0) {  // no texel centre inside (cannot happen with the reconstruction term): the nearest texel
    if (reads) ++*reads;
    return texel(long(std::floor(u)), long(std::floor(v)));
  }
  return sum / wsum;
}

// The whole filter over a chain of `levels` levels, level 0 being w0 x h0
// texels: `texel(L, i, j)`.  (u, v) and the derivatives in level-0 texels;
// the level from `lod` (plus `bias`), clamped to the last level; two levels
// blended by its fraction.
template <class Texel>
glm::dvec4 ewaFilter(const Texel& texel, int levels, double u, double v, double Ux, double Vx, double Uy, double Vy,
                     double alpha, double maxAniso, double bias = 0, long* reads = nullptr) {
  double l = lod(ellipse(Ux, Vx, Uy, Vy, false), maxAniso) + bias;
  l = std::clamp(l, 0.0, double(levels - 1));
  const int L0 = int(std::floor(l));
  const double f = l - L0;
  auto at = [&](int L) {
    const double s = std::ldexp(1.0, -L);
    return ewaLevel([&](long i, long j) { return texel(L, i, j); }, u * s, v * s, Ux * s, Vx * s, Uy * s, Vy * s, alpha,
                    reads);
  };
  const glm::dvec4 a = at(L0);
  if (f <= 0 || L0 >= levels - 1) return a;
  return glm::mix(a, at(L0 + 1), f);
}
}  // namespace ts::ewa
