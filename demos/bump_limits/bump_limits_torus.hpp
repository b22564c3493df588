// demos/bump_limits/bump_limits_torus.hpp — view torus: self-shadowing on bump_mapping's two-light torus
// (common/core/torus.hpp, R = 1, r = 0.4), its heights the plane's field (bump_limits_math.hpp) repeated
// kRepS x kRepT times over (s, t), displaced along the smooth normal by kHeightWorld h.
//
// The displaced torus is a height field over the tube: a point p lies at (theta, phi) = (atan2(p.x, p.z),
// atan2(p.y, |p.xz| - R)) and distance rho = |(|p.xz| - R, p.y)| from the tube's centre line, and is inside when
//   rho < r + P(s, t),  P = kHeightWorld h(kRepS kTexels s, kRepT kTexels t),  s = theta / 2 pi, t = phi / 2 pi.
// The reference (CPU): from the displaced point X = Q + P N at each pixel's (s, t) (read back from GL), a ray
// towards each light, sphere-traced to the shell rho = r + kHeightWorld and marched kRayStep apart inside it: the
// pixel is in that light's shadow when a step lands inside.  The horizon map (CPU): per texel of one tile in s
// (the torus turns into itself every 1/kRepS of a turn, so one tile in s holds every texel; all of t, the outer
// and inner equators differ) and for kDirections azimuths a_k in the smooth frame (T, B), the larger of the
// near horizon, the largest elevation above the tangent plane of the displaced surface seen along the path
// (s, t) + sigma (cos a_k / |Q_s|, sin a_k / |Q_t|), and the far one, the lowest elevation at which a ray leaves
// the smooth torus the bumps ride on (the ring across the hole), in [-90, 90] degrees, 8 bits.
// The shader (GL): Blinn's perturbed normal
//   n' = normalize(N - (P_s / |Q_s|) T - (P_t / |Q_t|) B)        (P_s, P_t central differences of the heights)
//   c  = A + sum_i I_i max(n' . L_i, 0) lit_i,  lit_i = [elevation(L_i) > mix(H_k0, H_k0+1, frac)]  (horizon)
// with the light's azimuth and elevation taken in (T, B, N) per pixel, for both lights.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "bump_limits_gl.hpp"
#include "common/core/torus.hpp"

namespace bumplim {
constexpr double kTorusR = 1.0, kTorusr = 0.4;
constexpr int kRepS = 8, kRepT = 2;         // the height tile's repeats around the ring and around the tube
constexpr double kHeightWorld = 0.08;       // world units of the tallest bump (h = 1)
constexpr double kRayStep = 0.004;          // world units a step of the ray march inside the shell
constexpr double kHorizonFirst = 0.004;     // the horizon path's first step, world units
constexpr double kHorizonGrowth = 0.08;     // each next step kHorizonGrowth x the distance so far (at least the first)
constexpr double kHorizonReachWorld = 0.8;  // how far along the surface the horizon path looks
constexpr int kTorusPixels = 256;           // the pictures, pixels a side
constexpr double kTorusTiltDeg = 30;        // the eye above the torus's plane, as bump_mapping's default
constexpr float kTorusIntensity[2] = {0.55f, 0.35f};
// The lights of bump_mapping (azimuth, elevation in the eye's frame, degrees): light 1 up left, light 2 right.
constexpr double kTorusLights[2][2] = {{-45, 40}, {60, -10}};

// A world point of the displaced torus at (s, t), and its smooth frame.
struct TorusField {
  Field tile;
  double P(double s, double t) const {
    return kHeightWorld / kHeightMax * tile.at(s * kRepS * kTexels, t * kRepT * kTexels);
  }
  glm::dvec3 X(double s, double t, double scale = 1) const {
    const ts::TorusFrame f = ts::torusFrameAt(kTorusR, kTorusr, {s, t});
    return f.Q + scale * P(s, t) * f.N;
  }
  // Inside the displaced torus?
  bool inside(const glm::dvec3& p, double scale = 1) const {
    const double rxz = std::sqrt(p.x * p.x + p.z * p.z), dr = rxz - kTorusR;
    const double rho = std::sqrt(dr * dr + p.y * p.y);
    if (rho >= kTorusr + scale * kHeightWorld) return false;
    const double s = std::atan2(p.x, p.z) / ts::kTau, t = std::atan2(p.y, dr) / ts::kTau;
    return rho < kTorusr + scale * P(s, t);
  }
};
// The eye's frame: world -> eye is a rotation by the tilt about x (bump_mapping: the eye above the ring's plane).
inline glm::dvec3 eyeToWorld(const glm::dvec3& e) {
  const double a = -kTorusTiltDeg * kPi / 180;  // the inverse rotation
  return {e.x, std::cos(a) * e.y - std::sin(a) * e.z, std::sin(a) * e.y + std::cos(a) * e.z};
}
inline glm::dvec3 worldToEye(const glm::dvec3& w) {
  const double a = kTorusTiltDeg * kPi / 180;
  return {w.x, std::cos(a) * w.y - std::sin(a) * w.z, std::sin(a) * w.y + std::cos(a) * w.z};
}
// Light k towards the light, world units (bump_mapping's toLight: eye space, then into the world).
inline glm::dvec3 torusLight(int k) {
  const double az = kTorusLights[k][0] * kPi / 180, el = kTorusLights[k][1] * kPi / 180;
  return eyeToWorld({std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)});
}

// The reference: is the displaced surface's point at (s, t) in the shadow of the directional light L?
inline bool torusShadowed(const TorusField& f, double s, double t, const glm::dvec3& L) {
  const glm::dvec3 x0 = f.X(s, t);
  const double shell = kTorusr + kHeightWorld, bound = kTorusR + shell;
  double sigma = kRayStep;
  for (int n = 0; n < 100000; ++n) {
    const glm::dvec3 p = x0 + sigma * L;
    if (glm::dot(p, p) > bound * bound && glm::dot(p, L) > 0) return false;  // left the torus's sphere for good
    const double rxz = std::sqrt(p.x * p.x + p.z * p.z), dr = rxz - kTorusR;
    const double rho = std::sqrt(dr * dr + p.y * p.y);
    if (rho > shell) {
      sigma += rho - shell + kRayStep;  // the shell is a torus: rho - shell is the distance to it
      continue;
    }
    if (f.inside(p)) return true;
    sigma += kRayStep;
  }
  return false;
}

// The horizon map: two images (directions 0-3, 4-7), kTexels wide (one tile in s) and kRepT kTexels tall (all of
// t); texel (i, j) at s = (i + 1/2) / (kRepS kTexels), t = (j + 1/2) / (kRepT kTexels).  Each angle a byte,
// (angle / pi + 1/2) 255.  `scale` scales the heights (0: the smooth torus's horizon, a control).
inline double torusHorizonAngle(const TorusField& f, double s, double t, double azRad, double scale = 1) {
  const ts::TorusFrame fr = ts::torusFrameAt(kTorusR, kTorusr, {s, t});
  const glm::dvec3 x0 = fr.Q + scale * f.P(s, t) * fr.N;
  const double ls = glm::length(fr.Qs), lt = glm::length(fr.Qt);
  const glm::dvec2 dir(std::cos(azRad) / ls, std::sin(azRad) / lt);
  double best = -kPi / 2;
  for (double sigma = kHorizonFirst; sigma <= kHorizonReachWorld;
       sigma += std::max(kHorizonFirst, kHorizonGrowth * sigma)) {
    const glm::dvec3 d = f.X(s + sigma * dir.x, t + sigma * dir.y, scale) - x0;
    const double up = glm::dot(d, fr.N);
    best = std::max(best, std::atan2(up, glm::length(d - up * fr.N)));
  }
  return best;
}
// The far part of the horizon, which a path along the surface does not see: the ring across the hole.  The torus
// the bumps ride on (radius r + kHeightWorld times the tile's mean h) turns into itself about y, so this depends on
// t and the azimuth alone: the lowest elevation at which a ray from the smooth point leaves that torus for good,
// bisected to an eighth of an 8-bit step.
inline double meanBump(const TorusField& f) {
  double sum = 0;
  for (double z : f.tile.z) sum += z;
  return sum / double(f.tile.z.size()) / kHeightMax;
}
inline bool smoothRayHits(const glm::dvec3& from, const glm::dvec3& d, double radius) {
  const double bound = kTorusR + radius;
  for (double sigma = 2 * kRayStep; sigma < 4 * bound;) {
    const glm::dvec3 p = from + sigma * d;
    const double rxz = std::sqrt(p.x * p.x + p.z * p.z), dr = rxz - kTorusR;
    const double gap = std::sqrt(dr * dr + p.y * p.y) - radius;  // the distance to that torus
    if (gap < 0) return true;
    sigma += std::max(gap, kRayStep / 2);
  }
  return false;
}
inline double farHorizonAngle(double t, double azRad, double radius) {
  const ts::TorusFrame fr = ts::torusFrameAt(kTorusR, kTorusr, {0, t});
  const glm::dvec3 from = fr.Q + (radius - kTorusr) * fr.N;
  const glm::dvec3 along = std::cos(azRad) * fr.T + std::sin(azRad) * fr.B;
  double lo = -kPi / 2, hi = kPi / 2;  // hits at lo (into the tube), leaves at hi (along the normal)
  while (hi - lo > kPi / 255 / 8) {
    const double e = 0.5 * (lo + hi);
    (smoothRayHits(from, std::cos(e) * along + std::sin(e) * fr.N, radius) ? lo : hi) = e;
  }
  return hi;
}
// The horizon angles (radians) of every texel of the map, kDirections a texel, row by row.
struct HorizonAngles {
  std::vector<double> a;  // (j kTexels + i) kDirections + k
  double at(int i, int j, int k) const { return a[(size_t(j) * kTexels + size_t(i)) * kDirections + size_t(k)]; }
};
inline HorizonAngles torusHorizonAngles(const TorusField& f, double scale = 1) {
  const int w = kTexels, h = kRepT * kTexels;
  const double radius = kTorusr + scale * kHeightWorld * meanBump(f);
  HorizonAngles out;
  out.a.resize(size_t(w) * h * kDirections);
  for (int j = 0; j < h; ++j) {
    const double t = (j + 0.5) / h;
    double far[kDirections];
    for (int k = 0; k < kDirections; ++k) far[k] = farHorizonAngle(t, k * 2 * kPi / kDirections, radius);
    for (int i = 0; i < w; ++i) {
      const double s = (i + 0.5) / (kRepS * kTexels);
      for (int k = 0; k < kDirections; ++k)
        out.a[(size_t(j) * w + size_t(i)) * kDirections + size_t(k)] =
            std::max(far[k], torusHorizonAngle(f, s, t, k * 2 * kPi / kDirections, scale));
    }
  }
  return out;
}
inline std::vector<ts::Image> torusHorizonMaps(const HorizonAngles& h) {
  const int w = kTexels, rows = kRepT * kTexels;
  std::vector<ts::Image> maps(2, ts::Image(w, rows));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < w; ++i) {
      uint8_t a[kDirections];
      for (int k = 0; k < kDirections; ++k) a[k] = u8(h.at(i, j, k) / kPi + 0.5);
      maps[0].set(i, j, {a[0], a[1], a[2], a[3]});
      maps[1].set(i, j, {a[4], a[5], a[6], a[7]});
    }
  return maps;
}
inline std::vector<ts::Image> torusHorizonMaps(const TorusField& f, double scale = 1) {
  return torusHorizonMaps(torusHorizonAngles(f, scale));
}

// ---- the polynomial texture map (Malzbender's PTM) --------------------------------------------------------------
// Per texel six coefficients of the luminance as a biquadratic in the light's projection (lu, lv) = (L . T, L . B):
//   lum(lu, lv) = a0 lu^2 + a1 lv^2 + a2 lu lv + a3 lu + a4 lv + a5,
// fitted by least squares to the self-shadowed diffuse term max(n' . L, 0) [elevation(L) > horizon(azimuth(L))]
// (the horizon angles unrounded) at kPtmAzimuths x kPtmElevations light directions over the hemisphere.  Stored
// as two RGBA textures, each coefficient (a - lo) / (hi - lo) in 8 bits, lo and hi the coefficient's range over
// the map (uniforms).
constexpr int kPtmAzimuths = 16;
constexpr double kPtmElevationsDeg[] = {3, 10, 20, 30, 45, 60, 75, 90};
struct Ptm {
  std::vector<double> a;  // 6 a texel, row by row as the horizon map
  double lo[6], hi[6];
  std::vector<ts::Image> maps;
  double fitRms = 0;  // RMS of the fit against its samples, 0..1
};
// The bumped normal at texel (i, j) of the map, in the smooth frame (T, B, N).
inline glm::dvec3 localBumpNormal(const TorusField& f, double s, double t) {
  const ts::TorusFrame fr = ts::torusFrameAt(kTorusR, kTorusr, {s, t});
  const double x = s * kRepS * kTexels, y = t * kRepT * kTexels, k = kHeightWorld / kHeightMax;
  const double ps = k * (f.tile.at(x + 1, y) - f.tile.at(x - 1, y)) * kRepS * kTexels / 2;
  const double pt = k * (f.tile.at(x, y + 1) - f.tile.at(x, y - 1)) * kRepT * kTexels / 2;
  return glm::normalize(glm::dvec3(-ps / glm::length(fr.Qs), -pt / glm::length(fr.Qt), 1));
}
// The horizon model's self-shadowed diffuse term for a light at (azimuth, elevation) in the frame, at texel (i, j).
inline double horizonShading(const HorizonAngles& h, int i, int j, const glm::dvec3& n, double az, double el,
                             bool shadows = true) {
  const double k = az / (2 * kPi / kDirections);
  const int k0 = int(std::floor(k)) % kDirections, k1 = (k0 + 1) % kDirections;
  const double a = k - std::floor(k), hor = (1 - a) * h.at(i, j, k0) + a * h.at(i, j, k1);
  const glm::dvec3 L(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  return el > hor || !shadows ? std::max(glm::dot(n, L), 0.0) : 0.0;
}
// `shadows` false: fitted to the diffuse term alone (a control: how much of the fit's error the shadows make).
inline Ptm fitPtm(const TorusField& f, const HorizonAngles& h, bool shadows = true) {
  const int w = kTexels, rows = kRepT * kTexels;
  Ptm p;
  p.a.resize(size_t(w) * rows * 6);
  double se = 0;
  long samples = 0;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < w; ++i) {
      const glm::dvec3 n = localBumpNormal(f, (i + 0.5) / (kRepS * kTexels), (j + 0.5) / rows);
      double M[6][7] = {};
      std::vector<std::pair<std::array<double, 6>, double>> rowsFit;
      for (double elDeg : kPtmElevationsDeg)
        for (int q = 0; q < (elDeg < 90 ? kPtmAzimuths : 1); ++q) {
          const double az = (q + 0.5) * 2 * kPi / kPtmAzimuths, el = elDeg * kPi / 180;
          const double lu = std::cos(el) * std::cos(az), lv = std::cos(el) * std::sin(az);
          const std::array<double, 6> b{lu * lu, lv * lv, lu * lv, lu, lv, 1};
          const double y = horizonShading(h, i, j, n, az, el, shadows);
          rowsFit.push_back({b, y});
          for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 6; ++c) M[r][c] += b[size_t(r)] * b[size_t(c)];
            M[r][6] += b[size_t(r)] * y;
          }
        }
      for (int c = 0; c < 6; ++c) {  // Gauss-Jordan with partial pivoting on the normal equations
        int piv = c;
        for (int r = c + 1; r < 6; ++r)
          if (std::fabs(M[r][c]) > std::fabs(M[piv][c])) piv = r;
        for (int k = 0; k < 7; ++k) std::swap(M[c][k], M[piv][k]);
        for (int r = 0; r < 6; ++r)
          if (r != c) {
            const double m = M[r][c] / M[c][c];
            for (int k = c; k < 7; ++k) M[r][k] -= m * M[c][k];
          }
      }
      double* a = &p.a[(size_t(j) * w + size_t(i)) * 6];
      for (int c = 0; c < 6; ++c) a[c] = M[c][6] / M[c][c];
      for (const auto& [b, y] : rowsFit) {
        double v = 0;
        for (int c = 0; c < 6; ++c) v += a[c] * b[size_t(c)];
        se += (v - y) * (v - y), ++samples;
      }
    }
  p.fitRms = std::sqrt(se / double(samples));
  for (int c = 0; c < 6; ++c) {
    p.lo[c] = 1e9, p.hi[c] = -1e9;
    for (size_t t = 0; t < p.a.size() / 6; ++t)
      p.lo[c] = std::min(p.lo[c], p.a[t * 6 + size_t(c)]), p.hi[c] = std::max(p.hi[c], p.a[t * 6 + size_t(c)]);
    if (p.hi[c] <= p.lo[c]) p.hi[c] = p.lo[c] + 1;
  }
  p.maps.assign(2, ts::Image(w, rows));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < w; ++i) {
      uint8_t b[8] = {0, 0, 0, 0, 0, 0, 0, 255};
      for (int c = 0; c < 6; ++c)
        b[c] = u8((p.a[(size_t(j) * w + size_t(i)) * 6 + size_t(c)] - p.lo[c]) / (p.hi[c] - p.lo[c]));
      p.maps[0].set(i, j, {b[0], b[1], b[2], b[3]});
      p.maps[1].set(i, j, {b[4], b[5], 0, 255});
    }
  return p;
}

// ---- the GL pass -------------------------------------------------------------------------------------------------
enum class TorusOutput { kShade = 0, kDiffuse = 1, kS = 2, kT = 3 };
inline std::string torusFragmentShader() {
  return std::string(R"(#version 110
uniform sampler2D heights, horizon0, horizon1, ptm0, ptm1;
uniform vec3 light1, light2;  // world, unit, towards the light
uniform vec4 ptmLo0, ptmHi0;  // the PTM's coefficients a0-a3: their range
uniform vec2 ptmLo1, ptmHi1;  // a4, a5
uniform float R, r, TAU, repS, repT, texels, heightWorld, azShift, ambient, i1, i2;
uniform int outputKind, horizon;
float pick(vec2 hst, int k) {  // the horizon map's angle in direction k (0..7), radians
  vec4 a = texture2D(horizon0, hst), b = texture2D(horizon1, hst);
  float v = k == 0 ? a.r : k == 1 ? a.g : k == 2 ? a.b : k == 3 ? a.a :
            k == 4 ? b.r : k == 5 ? b.g : k == 6 ? b.b : b.a;
  return (v - 0.5) * 3.14159265;
}
float horizonLit(vec2 hst, vec3 L, vec3 T, vec3 B, vec3 N) {  // the light above the horizon at its azimuth?
  float az = mod(atan(dot(L, B), dot(L, T)) + azShift + 2.0 * TAU, TAU);
  float el = asin(clamp(dot(L, N), -1.0, 1.0));
  float k = az / (TAU / 8.0);
  int k0 = int(floor(k));
  float a = k - float(k0);
  k0 = k0 - 8 * (k0 / 8);
  int k1 = k0 + 1 - 8 * ((k0 + 1) / 8);
  return el > mix(pick(hst, k0), pick(hst, k1), a) ? 1.0 : 0.0;
}
float ptm(vec2 hst, vec3 L, vec3 T, vec3 B, vec3 N) {  // the PTM's luminance for light L
  vec4 a = ptmLo0 + (ptmHi0 - ptmLo0) * texture2D(ptm0, hst);
  vec2 b = ptmLo1 + (ptmHi1 - ptmLo1) * texture2D(ptm1, hst).rg;
  float lu = dot(L, T), lv = dot(L, B);
  float lum = a.x * lu * lu + a.y * lv * lv + a.z * lu * lv + a.w * lu + b.x * lv + b.y;
  return dot(L, N) > 0.0 ? max(lum, 0.0) : 0.0;
}
vec2 split16(float v) {  // v in [0, 1] as two bytes, high and low
  float x = floor(clamp(v, 0.0, 1.0) * 65535.0 + 0.5);
  float hi = floor(x / 256.0);
  return vec2(hi, x - 256.0 * hi) / 255.0;
}
void main() {
  float s = gl_TexCoord[0].s, t = gl_TexCoord[0].t;
  float th = TAU * s, ph = TAU * t;
  vec3 N, Q, Qs, Qt, Ns, Nt;
)") + ts::kTorusFrameGLSL +
         R"(
  vec3 T = normalize(Qs), B = normalize(Qt);
  vec2 hs = vec2(s * repS, t * repT), hst = vec2(s * repS, t);
  float d = 1.0 / texels;  // one texel of the tile
  float ps = (texture2D(heights, hs + vec2(d, 0.0)).r - texture2D(heights, hs - vec2(d, 0.0)).r) * heightWorld *
             repS / (2.0 * d);  // dP/ds
  float pt = (texture2D(heights, hs + vec2(0.0, d)).r - texture2D(heights, hs - vec2(0.0, d)).r) * heightWorld *
             repT / (2.0 * d);  // dP/dt
  vec3 n = normalize(N - ps / length(Qs) * T - pt / length(Qt) * B);
  float d1 = max(dot(n, light1), 0.0), d2 = max(dot(n, light2), 0.0);
  float lit1 = horizonLit(hst, light1, T, B, N), lit2 = horizonLit(hst, light2, T, B, N);
  if (outputKind == 1) gl_FragColor = vec4(d1, d2, 0.5 * lit1 + 0.25 * lit2, 1.0);
  else if (outputKind == 2) gl_FragColor = vec4(split16(s), 1.0, 1.0);
  else if (outputKind == 3) gl_FragColor = vec4(split16(t), 1.0, 1.0);
  else if (horizon == 2)
    gl_FragColor = vec4(vec3(ambient + i1 * ptm(hst, light1, T, B, N) + i2 * ptm(hst, light2, T, B, N)), 1.0);
  else if (horizon == 1) gl_FragColor = vec4(vec3(ambient + i1 * d1 * lit1 + i2 * d2 * lit2), 1.0);
  else gl_FragColor = vec4(vec3(ambient + i1 * d1 + i2 * d2), 1.0);
}
)";
}

struct TorusPass {
  TorusOutput output = TorusOutput::kShade;
  int horizon = 0;  // 0 plain bump mapping, 1 the horizon map, 2 the PTM
  const Ptm* ptm = nullptr;
  double azShiftDeg = 0;  // a control: the horizon looked up this far round from the light
  const std::vector<ts::Image>* maps = nullptr;
};

// The torus seen from kTorusTiltDeg above its plane, orthographic, kTorusPixels a side: a 96 x 48 grid of quads,
// each vertex at its pixel position (the eye's x, y scaled into the pass) with depth the eye's z (nearer larger).
constexpr int kTorusNu = 96, kTorusNv = 48;
constexpr double kTorusHalfExtent = 1.5;  // world units from the centre to the picture's edge
inline glm::dvec3 torusVertexPixel(double s, double t) {
  const glm::dvec3 e = worldToEye(ts::torusFrameAt(kTorusR, kTorusr, {s, t}).Q);
  const double k = kTorusPixels / (2 * kTorusHalfExtent);
  return {kTorusPixels / 2.0 + k * e.x, kTorusPixels / 2.0 + k * e.y, e.z / kTorusHalfExtent};
}

inline ts::Image torusPass(ts::Renderer& r, const TorusPass& p) {
  static const std::string fs = torusFragmentShader();
  const GLuint prog = r.program("bump_limits_torus",
                                {"demos/bump_limits/bump_limits_torus.hpp", kVertexShader, fs.c_str()});
  static const std::vector<ts::Image> none(2, ts::Image(1, 1));
  const std::vector<ts::Image>& maps = p.maps ? *p.maps : none;
  const ts::Image heights = heightImage();
  return ts::pixelPass(r, kTorusPixels, kTorusPixels, "bump limits torus", [&] {
    GLuint tex[5] = {0, 0, 0, 0, 0};
    glActiveTexture(GL_TEXTURE0);
    tex[0] = ts::imageTexture(heights, GL_LINEAR);
    glActiveTexture(GL_TEXTURE1);
    tex[1] = ts::imageTexture(maps[0], GL_LINEAR);
    glActiveTexture(GL_TEXTURE2);
    tex[2] = ts::imageTexture(maps[1], GL_LINEAR);
    for (int k = 0; k < 2 && p.ptm; ++k) {
      glActiveTexture(GL_TEXTURE3 + GLenum(k));
      tex[3 + k] = ts::imageTexture(p.ptm->maps[size_t(k)], GL_LINEAR);
    }
    glActiveTexture(GL_TEXTURE0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);  // pixelPass's glOrtho puts larger z nearer (smaller depth)
    glUseProgram(prog);
    auto loc = [&](const char* n) { return glGetUniformLocation(prog, n); };
    glUniform1i(loc("heights"), 0), glUniform1i(loc("horizon0"), 1), glUniform1i(loc("horizon1"), 2);
    glUniform1i(loc("ptm0"), 3), glUniform1i(loc("ptm1"), 4);
    if (p.ptm) {
      const double *lo = p.ptm->lo, *hi = p.ptm->hi;
      glUniform4f(loc("ptmLo0"), float(lo[0]), float(lo[1]), float(lo[2]), float(lo[3]));
      glUniform4f(loc("ptmHi0"), float(hi[0]), float(hi[1]), float(hi[2]), float(hi[3]));
      glUniform2f(loc("ptmLo1"), float(lo[4]), float(lo[5]));
      glUniform2f(loc("ptmHi1"), float(hi[4]), float(hi[5]));
    }
    const glm::dvec3 L1 = torusLight(0), L2 = torusLight(1);
    glUniform3f(loc("light1"), float(L1.x), float(L1.y), float(L1.z));
    glUniform3f(loc("light2"), float(L2.x), float(L2.y), float(L2.z));
    glUniform1f(loc("R"), float(kTorusR)), glUniform1f(loc("r"), float(kTorusr));
    glUniform1f(loc("TAU"), float(ts::kTau));
    glUniform1f(loc("repS"), float(kRepS)), glUniform1f(loc("repT"), float(kRepT));
    glUniform1f(loc("texels"), float(kTexels)), glUniform1f(loc("heightWorld"), float(kHeightWorld));
    glUniform1f(loc("azShift"), float(p.azShiftDeg * kPi / 180));
    glUniform1f(loc("ambient"), kAmbient);
    glUniform1f(loc("i1"), kTorusIntensity[0]), glUniform1f(loc("i2"), kTorusIntensity[1]);
    glUniform1i(loc("outputKind"), int(p.output)), glUniform1i(loc("horizon"), p.horizon);
    glBegin(GL_QUADS);
    for (int j = 0; j < kTorusNv; ++j)
      for (int i = 0; i < kTorusNu; ++i) {
        const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
        for (int c = 0; c < 4; ++c) {
          const double s = double(ci[c]) / kTorusNu, t = double(cj[c]) / kTorusNv;
          const glm::dvec3 v = torusVertexPixel(s, t);
          glTexCoord2f(float(s), float(t));
          glVertex3f(float(v.x), float(v.y), float(v.z));
        }
      }
    glEnd();
    glUseProgram(0);
    glDeleteTextures(5, tex);
  });
}
}  // namespace bumplim
