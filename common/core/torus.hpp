// common/core/torus.hpp — the torus of Buss VI.1.2 (Figure VI.6), shared by
// demos/torus and demos/bump_mapping: its mesh, and its local frame (the
// point, the unit normal, the partial derivatives and the unit tangents)
// at any (s, t).  Plain data, no GL.
//
// The surface, R the major and r the minor radius, θ around the ring (the
// y axis), φ around the tube:
//   Q(θ, φ) = ((R + r cos φ) sin θ, r sin φ, (R + r cos φ) cos θ)
//           = c(θ) + r N,  c(θ) = R (sin θ, 0, cos θ) the tube's centre line,
//   N(θ, φ) = (cos φ sin θ, sin φ, cos φ cos θ), the unit normal.
// The texture coordinates are the book's s = θ/360°, t = φ/360°, that is
// θ = 2π s, φ = 2π t.  The partial derivatives, with the unit tangents
//   T = dTh = (cos θ, 0, -sin θ)                    along θ (around the ring),
//   B = dPh = (-sin φ sin θ, cos φ, -sin φ cos θ)  along φ (around the tube):
//   Q_θ = (R + r cos φ) T,  Q_φ = r B,  N_θ = cos φ T,  N_φ = B,
// and by the chain rule d/ds = 2π d/dθ, d/dt = 2π d/dφ:
//   Q_s = 2π (R + r cos φ) T,  Q_t = 2π r B,  N_s = 2π cos φ T,  N_t = 2π B.
// T, B, N are orthonormal and right-handed (T x B = N): the tangent frame a
// normal map's (x, y, z) is read in.  |Q_s| = 2π (R + r cos φ) is why a
// texel is longer on the outer equator (φ = 0) than on the inner one
// (φ = 180°): a bump map's slopes depend on where on the ring it lies.
//
// These formulas are written once, in common/core/torus_frame.inl, in the
// part of GLSL that is also C++ with glm: torus.cpp compiles it
// (torusFrame) and shaders evaluate it per pixel (kTorusFrameGLSL).
#pragma once
#include <glm/glm.hpp>

#include "common/core/mesh.hpp"

namespace ts {
constexpr double kTau = 2 * 3.14159265358979323846;  // 2π: a full turn, θ = kTau s

// The torus's size and tessellation.  The defaults are Figure VI.6's: a fat
// ring (its hole still wide enough to see into), 7.5° by 15° cells (smooth
// silhouettes; even counts, so grid vertices sit at θ, φ = 180°).
struct TorusShape {
  double R = 1.0, r = 0.4;
  int nu = 48, nv = 24;  // cells around the ring (θ) and around the tube (φ)
};

// The mesh: nu x nv cells, grid vertex (i, j) at θ = 360° i/nu, φ = 360° j/nv
// from ts::torusPoint (mesh.hpp: Q = c + r N from the wrapped indices, so
// both seams are bit-identical), with texture coordinates
// (s, t) = (i/nu, j/nv) + stOffset from the unwrapped ones (the seam column
// i = nu carries s = 1: GL_REPEAT does the rest).
Mesh torusMesh(const TorusShape& t, glm::dvec2 stOffset = glm::dvec2(0.0));

// The local frame at (θ, φ).  The derivatives are by s and t (the texture's
// coordinates), as a bump map needs them.
struct TorusFrame {
  glm::dvec3 Q, N;    // the point and its unit normal
  glm::dvec3 Qs, Qt;  // ∂Q/∂s, ∂Q/∂t
  glm::dvec3 Ns, Nt;  // ∂N/∂s, ∂N/∂t
  glm::dvec3 T, B;    // the unit tangents along θ and φ: Qs/|Qs|, Qt/|Qt|
};
// thetaRad, phiRad: θ and φ in radians.
TorusFrame torusFrame(double R, double r, double thetaRad, double phiRad);
// The same at the texture coordinates (s, t): θ = 2π s, φ = 2π t.
inline TorusFrame torusFrameAt(double R, double r, glm::dvec2 st) { return torusFrame(R, r, kTau * st.x, kTau * st.y); }

// torus_frame.inl's lines as GLSL text: they expect float th, ph, R, r and
// TAU, and out vec3 N, Q, Qs, Qt, Ns, Nt to be declared around them.
extern const char* const kTorusFrameGLSL;
}  // namespace ts
