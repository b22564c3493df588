// demos/bump_limits/bump_limits_math.hpp — the bump-limits demo's CPU side: the height field on a plane (an
// analytic one, so the displaced surface's exact normal is known everywhere), its 8-bit texels as GL reads them
// (GL_LINEAR, GL_REPEAT), the horizon map, the displaced surface's shadows by a ray march, the stored maps
// (normal map, offset-vector map), the sheared parameterisation's normals, and image statistics.  GL-free:
// shared by the demo and its test.
//
// Units: one texel is one unit along x and y; heights are in the same units, z = kHeightMax h, h in [0, 1].
// The tile is kTexels x kTexels texels and repeats.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/core/image.hpp"

namespace bumplim {
constexpr double kPi = 3.14159265358979323846;
constexpr int kTexels = 64;           // the height tile, texels a side
constexpr double kHeightMax = 6.0;    // texel units: the tallest bump is 6 texels high
constexpr int kDirections = 8;        // the horizon map's directions, 45 degrees apart
constexpr double kHorizonReach = 32;  // texels the horizon search looks along each direction
constexpr double kMarchStep = 0.25;   // texels a step of the shadow ray march and of the horizon search
constexpr double kOffsetRange = 2.0;  // the offset-vector map stores bu, bv in [-2, 2] (8 bits)

// The field: two crossed waves and a diagonal ripple, periodic on the tile (whole cycles), smooth, so the
// displaced surface's normal normalize(-dz/dx, -dz/dy, 1) is exact from the derivative below.
//   h(x, y) = 0.5 + 0.3 sin(2 pi 4x/N) cos(2 pi 4y/N) + 0.15 sin(2 pi (8x + 3y)/N)      (N = kTexels)
inline double heightAt(double x, double y) {
  const double w = 2 * kPi / kTexels;
  return 0.5 + 0.3 * std::sin(w * 4 * x) * std::cos(w * 4 * y) + 0.15 * std::sin(w * (8 * x + 3 * y));
}
// (dz/dx, dz/dy) of the displaced surface z = kHeightMax h.
inline glm::dvec2 slopeAt(double x, double y) {
  const double w = 2 * kPi / kTexels;
  const double hx = 0.3 * w * 4 * std::cos(w * 4 * x) * std::cos(w * 4 * y) +
                    0.15 * w * 8 * std::cos(w * (8 * x + 3 * y));
  const double hy = -0.3 * w * 4 * std::sin(w * 4 * x) * std::sin(w * 4 * y) +
                    0.15 * w * 3 * std::cos(w * (8 * x + 3 * y));
  return kHeightMax * glm::dvec2(hx, hy);
}
inline glm::dvec3 exactNormal(double x, double y) {
  const glm::dvec2 g = slopeAt(x, y);
  return glm::normalize(glm::dvec3(-g.x, -g.y, 1.0));
}

inline uint8_t u8(double v) { return uint8_t(std::clamp(std::lround(v * 255.0), 0L, 255L)); }

// The heights as the texture holds them: texel (i, j) (j = 0 at t = 0) is h at its centre, 8 bits.
inline ts::Image heightImage() {
  ts::Image img(kTexels, kTexels);
  for (int j = 0; j < kTexels; ++j)
    for (int i = 0; i < kTexels; ++i) {
      const uint8_t g = u8(heightAt(i + 0.5, j + 0.5));
      img.set(i, j, {g, g, g, 255});
    }
  return img;
}
// The texels as GL_LINEAR with GL_REPEAT reads them at (x, y) texel units: z = kHeightMax x that.
struct Field {
  std::vector<double> z;  // kHeightMax x texel / 255
  Field() : z(size_t(kTexels) * kTexels) {
    const ts::Image img = heightImage();
    for (int j = 0; j < kTexels; ++j)
      for (int i = 0; i < kTexels; ++i) z[size_t(j) * kTexels + size_t(i)] = kHeightMax * img.at(i, j).r / 255.0;
  }
  double texel(int i, int j) const {
    i = ((i % kTexels) + kTexels) % kTexels, j = ((j % kTexels) + kTexels) % kTexels;
    return z[size_t(j) * kTexels + size_t(i)];
  }
  double at(double x, double y) const {
    const double u = x - 0.5, v = y - 0.5;
    const int i = int(std::floor(u)), j = int(std::floor(v));
    const double a = u - i, b = v - j;
    return (1 - a) * (1 - b) * texel(i, j) + a * (1 - b) * texel(i + 1, j) + (1 - a) * b * texel(i, j + 1) +
           a * b * texel(i + 1, j + 1);
  }
};

// ---- self-shadowing -----------------------------------------------------------------------------------------------
// Direction k of the horizon map: azimuth k x 45 degrees from +x towards +y.
inline glm::dvec2 direction(double azimuthRad) { return {std::cos(azimuthRad), std::sin(azimuthRad)}; }
// The horizon: the largest elevation angle (radians, >= 0) at which the surface seen from (x, y) along the
// azimuth rises above it, searched kMarchStep apart out to kHorizonReach texels.
inline double horizonAngle(const Field& f, double x, double y, double azimuthRad) {
  const glm::dvec2 d = direction(azimuthRad);
  const double z0 = f.at(x, y);
  double best = 0;
  for (double s = kMarchStep; s <= kHorizonReach; s += kMarchStep)
    best = std::max(best, std::atan2(f.at(x + s * d.x, y + s * d.y) - z0, s));
  return best;
}
// The horizon map: two RGBA textures, directions 0-3 and 4-7 in r, g, b, a, each angle / 90 degrees in 8 bits.
inline std::vector<ts::Image> horizonMaps(const Field& f) {
  std::vector<ts::Image> maps(2, ts::Image(kTexels, kTexels));
  for (int j = 0; j < kTexels; ++j)
    for (int i = 0; i < kTexels; ++i) {
      uint8_t a[kDirections];
      for (int k = 0; k < kDirections; ++k) a[k] = u8(horizonAngle(f, i + 0.5, j + 0.5, k * kPi / 4) / (kPi / 2));
      maps[0].set(i, j, {a[0], a[1], a[2], a[3]});
      maps[1].set(i, j, {a[4], a[5], a[6], a[7]});
    }
  return maps;
}
// The displaced surface's shadow at (x, y): the ray from the surface towards the light (elevation `elev`,
// azimuth `az`) marched kMarchStep apart until it is above every height; in shadow when the heights rise over it.
inline bool rayShadowed(const Field& f, double x, double y, double az, double elev) {
  const glm::dvec2 d = direction(az);
  const double z0 = f.at(x, y), rise = std::tan(elev);
  for (double s = kMarchStep; z0 + s * rise <= kHeightMax; s += kMarchStep)
    if (f.at(x + s * d.x, y + s * d.y) > z0 + s * rise) return true;
  return false;
}
// The light's unit vector (z up).
inline glm::dvec3 lightVector(double azDeg, double elevDeg) {
  const double a = azDeg * kPi / 180, e = elevDeg * kPi / 180;
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

// ---- the stored maps ------------------------------------------------------------------------------------------
// The normal map: normalize(-dz/dx, -dz/dy, 1) at each texel centre, 0.5 + 0.5 n in 8 bits.
inline ts::Image normalMapImage() {
  ts::Image img(kTexels, kTexels);
  for (int j = 0; j < kTexels; ++j)
    for (int i = 0; i < kTexels; ++i) {
      const glm::dvec3 n = exactNormal(i + 0.5, j + 0.5);
      img.set(i, j, {u8(0.5 + 0.5 * n.x), u8(0.5 + 0.5 * n.y), u8(0.5 + 0.5 * n.z), 255});
    }
  return img;
}
// The offset-vector map (seed 001): the normal's offsets (bu, bv) along two vectors perpendicular to n (here the
// plane's x and y): n' = n + bu e1 + bv e2 with bu = -dz/dx, bv = -dz/dy, each 0.5 + 0.5 b / kOffsetRange in 8 bits.
inline ts::Image offsetMapImage() {
  ts::Image img(kTexels, kTexels);
  for (int j = 0; j < kTexels; ++j)
    for (int i = 0; i < kTexels; ++i) {
      const glm::dvec2 g = slopeAt(i + 0.5, j + 0.5);
      img.set(i, j, {u8(0.5 - 0.5 * g.x / kOffsetRange), u8(0.5 - 0.5 * g.y / kOffsetRange), 128, 255});
    }
  return img;
}

// ---- the sheared parameterisation ------------------------------------------------------------------------------
// The surface p(s, t) = s Ps + t Pt + z(s, t) n with Ps = (1, 0, 0), Pt = (cos theta, sin theta, 0) (texel units),
// n = (0, 0, 1), z the field's height at texture point (s, t).  Its true normal is
//   (Ps + z_s n) x (Pt + z_t n) = N + z_s (n x Pt) + z_t (Ps x n),   N = Ps x Pt, n = N / |N|,
// which is Blinn's n' = N + z_s (N x Pt)/|N| + z_t (Ps x N)/|N| term for term on a plane: his formula carries the
// shear.  A method that takes the texture's axes for orthogonal unit vectors (a normal map or offset map baked for
// a square, unsheared texture) uses normalize(-z_s, -z_t, 1) in the frame (Ps, n x Ps, n).  `aspect` stretches
// Pt to that length (a texture that is not square on the surface): the same equations hold.
inline glm::dvec3 shearedTrueNormal(double s, double t, double thetaRad, double aspect = 1) {
  const glm::dvec2 g = slopeAt(s, t);
  const glm::dvec3 Ps(1, 0, 0), Pt(aspect * std::cos(thetaRad), aspect * std::sin(thetaRad), 0), n(0, 0, 1);
  return glm::normalize(glm::cross(Ps + g.x * n, Pt + g.y * n));
}
inline glm::dvec3 shearedBlinnNormal(double s, double t, double thetaRad, double aspect = 1) {
  const glm::dvec2 g = slopeAt(s, t);
  const glm::dvec3 Ps(1, 0, 0), Pt(aspect * std::cos(thetaRad), aspect * std::sin(thetaRad), 0);
  const glm::dvec3 N = glm::cross(Ps, Pt);  // |N| = aspect sin theta
  const double len = glm::length(N);
  return glm::normalize(N + g.x * glm::cross(N, Pt) / len + g.y * glm::cross(Ps, N) / len);
}
inline glm::dvec3 shearedOrthogonalNormal(double s, double t, double /*thetaRad*/, double /*aspect*/ = 1) {
  const glm::dvec2 g = slopeAt(s, t);
  return glm::normalize(glm::dvec3(-g.x, -g.y, 1.0));  // frame (Ps, n x Ps, n) = (x, y, z)
}
inline double angleDeg(glm::dvec3 a, glm::dvec3 b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) * 180.0 / kPi;
}
// The mean angle (degrees) between a method's normal and the true one over the tile, at 4 x 4 points a texel.
template <class Method>
double shearError(double thetaDeg, Method method, double aspect = 1) {
  const double th = thetaDeg * kPi / 180;
  double sum = 0;
  int n = 0;
  for (int j = 0; j < kTexels * 4; ++j)
    for (int i = 0; i < kTexels * 4; ++i, ++n)
      sum += angleDeg(method((i + 0.5) / 4, (j + 0.5) / 4, th, aspect),
                      shearedTrueNormal((i + 0.5) / 4, (j + 0.5) / 4, th, aspect));
  return sum / n;
}

// ---- image statistics -----------------------------------------------------------------------------------------
inline glm::dvec3 decodeNormal(ts::Rgba c) { return glm::dvec3(c.r, c.g, c.b) / 255.0 * 2.0 - 1.0; }
// Root mean square difference (8-bit levels) of the grey (r) channel.
inline double rmsGrey(const ts::Image& a, const ts::Image& b) {
  double se = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const double d = double(a.at(x, y).r) - double(b.at(x, y).r);
      se += d * d;
    }
  return std::sqrt(se / (double(a.width) * a.height));
}
inline int maxDiffGrey(const ts::Image& a, const ts::Image& b) {
  int m = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) m = std::max(m, std::abs(int(a.at(x, y).r) - int(b.at(x, y).r)));
  return m;
}
// The mean of each k x k block (all channels): the box filter down to the display's resolution.
inline ts::Image boxDown(const ts::Image& img, int k) {
  ts::Image out(img.width / k, img.height / k);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      double s[4] = {0, 0, 0, 0};
      for (int dy = 0; dy < k; ++dy)
        for (int dx = 0; dx < k; ++dx) {
          const ts::Rgba c = img.at(x * k + dx, y * k + dy);
          s[0] += c.r, s[1] += c.g, s[2] += c.b, s[3] += c.a;
        }
      const double n = double(k) * k;
      out.set(x, y, {u8(s[0] / n / 255), u8(s[1] / n / 255), u8(s[2] / n / 255), u8(s[3] / n / 255)});
    }
  return out;
}
// The mean angle (degrees) of a normal render's normals from the plane's (0, 0, 1).
inline double meanTiltDeg(const ts::Image& normals) {
  double sum = 0;
  for (int y = 0; y < normals.height; ++y)
    for (int x = 0; x < normals.width; ++x) sum += angleDeg(decodeNormal(normals.at(x, y)), {0, 0, 1});
  return sum / (double(normals.width) * normals.height);
}
}  // namespace bumplim
