// demos/env_lighting/env_lighting_measure.hpp — the measurement: the sphere
// drawn with the map and with per-pixel Phong (env_lighting_views.hpp) at
// kMeasureSize^2, read back, and compared pixel by pixel inside the disc;
// then the same programs built with COUNT 1 read back their own counts.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include <glm/glm.hpp>

#include "common/core/env_maps.hpp"
#include "common/core/image.hpp"
#include "common/core/scene.hpp"
#include "common/gl/render.hpp"
#include "demos/env_lighting/env_lighting_views.hpp"

namespace envlight {
constexpr int kMeasureSize = 256;
// Map sizes: two to show the error falls with the size, and one so fine (0.45 degrees a texel) that what
// is left is the rounding of texels and pixels to 8 bits, the floor no size removes.
inline const int kMeasuredFaces[] = {32, 128, 256};

// The pixels whose centres lie well inside the sphere's outline (radius
// 0.98 of the 64-gon's 0.9988): both methods cover exactly these.
inline bool inDisc(int x, int y, int size) {
  const double u = ((x + 0.5) / size * 2 - 1) * kExtent, v = ((y + 0.5) / size * 2 - 1) * kExtent;
  return u * u + v * v < 0.98 * 0.98;
}

// The mirror direction at a pixel's centre, from the sphere's exact normal
// there (seen orthographically along -z; row 0 of the image at the top).
inline glm::dvec3 mirrorAt(int x, int y, int size) {
  const double u = ((x + 0.5) / size * 2 - 1) * kExtent, v = -((y + 0.5) / size * 2 - 1) * kExtent;
  const glm::dvec3 n(u, v, std::sqrt(std::max(0.0, 1 - u * u - v * v)));
  return glm::reflect(glm::dvec3(0, 0, -1), n);
}
// How far, in texels of a face of `face` texels, direction r is from its cube face's edge.
inline double texelsFromEdge(glm::dvec3 r, int face) {
  const ts::envmaps::CubeST c = ts::envmaps::cubeST(r);
  return std::min({c.s, 1 - c.s, c.t, 1 - c.t}) * face;
}

struct Difference {
  double rms = 0;       // 8-bit levels over R, G, B of the disc's pixels
  int max = 0;          // the largest, anywhere on the disc
  int maxInterior = 0;  // the largest where r is at least 2 texels from its face's edge
  int maxEdge = 0;      // the largest nearer the edges, where GL_LINEAR clamps to the face (no seamless filtering)
};
inline Difference compare(const ts::Image& a, const ts::Image& b, int face) {
  double sum = 0;
  long n = 0;
  Difference d;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (!inDisc(x, y, a.width)) continue;
      const ts::Rgba p = a.at(x, y), q = b.at(x, y);
      const bool interior = texelsFromEdge(mirrorAt(x, y, a.width), face) >= 2.0;
      for (int e : {p.r - q.r, p.g - q.g, p.b - q.b}) {
        sum += double(e) * e, ++n, d.max = std::max(d.max, std::abs(e));
        int& m = interior ? d.maxInterior : d.maxEdge;
        m = std::max(m, std::abs(e));
      }
    }
  d.rms = n ? std::sqrt(sum / double(n)) : 0.0;
  return d;
}

// The counts a program writes with COUNT 1 (red: light evaluations, green:
// map lookups), the largest and smallest over the disc's pixels.
struct Counts {
  int evaluationsMax = 0, evaluationsMin = 1 << 30, lookupsMax = 0, lookupsMin = 1 << 30;
};
inline Counts countsOf(const ts::Image& img) {
  Counts c;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      if (!inDisc(x, y, img.width)) continue;
      const ts::Rgba p = img.at(x, y);
      c.evaluationsMax = std::max(c.evaluationsMax, int(p.r)), c.evaluationsMin = std::min(c.evaluationsMin, int(p.r));
      c.lookupsMax = std::max(c.lookupsMax, int(p.g)), c.lookupsMin = std::min(c.lookupsMin, int(p.g));
    }
  return c;
}

inline ts::Measurements measureAll(ts::Renderer& r, int face) {
  ts::Measurements out;
  const int s = kMeasureSize;
  int step = 0;
  const double steps = 3.0 * 5.0;
  for (int n : kLightCounts) {
    const std::string k = "[" + std::to_string(n) + "]";
    const ts::Image phong = r.renderOffscreen(sphereFrame(kPhong, n, face, s, s));
    const Difference d = compare(r.renderOffscreen(sphereFrame(kMap, n, face, s, s)), phong, face);
    out.push_back({"envlight_rms_levels" + k, d.rms,
                   "RMS difference (8-bit levels, R G B, inside the sphere's outline) between one cube-map lookup "
                   "and per-pixel Phong with " +
                       std::to_string(n) + (n == 1 ? " light" : " lights") + ", map " + std::to_string(face) +
                       " texels a face's side"});
    out.push_back({"envlight_max_levels" + k, double(d.max), "largest difference of the same pixels, 8-bit levels"});
    ts::measureProgress(++step / steps);
    for (int f : kMeasuredFaces) {
      const std::string kf = "[" + std::to_string(n) + "/" + std::to_string(f) + "]";
      const Difference df = compare(r.renderOffscreen(sphereFrame(kMap, n, f, s, s)), phong, f);
      out.push_back({"envlight_rms_levels" + kf, df.rms,
                     "the RMS difference with a map of " + std::to_string(f) + " texels a face's side"});
      out.push_back({"envlight_max_levels" + kf, double(df.max), "its largest difference, 8-bit levels"});
      out.push_back({"envlight_max_interior_levels" + kf, double(df.maxInterior),
                     "its largest difference where r is 2 texels or more from a face's edge"});
      out.push_back({"envlight_max_edge_levels" + kf, double(df.maxEdge),
                     "its largest difference nearer the faces' edges (GL_LINEAR clamps to each face)"});
      ts::measureProgress(++step / steps);
    }
    const Counts map = countsOf(r.renderOffscreen(sphereFrame(kMap, n, face, s, s, true)));
    const Counts ph = countsOf(r.renderOffscreen(sphereFrame(kPhong, n, face, s, s, true)));
    ts::measureProgress(++step / steps);
    out.push_back({"envlight_lookups_per_pixel" + k, double(map.lookupsMax),
                   "cube-map lookups a pixel of the map method makes, counted by its shader (largest over the disc)"});
    out.push_back({"envlight_lookups_min" + k, double(map.lookupsMin), "the smallest count over the disc"});
    out.push_back({"envlight_evaluations_per_pixel" + k, double(map.evaluationsMax),
                   "light evaluations a pixel of the map method makes (none: the lights are in the map)"});
    out.push_back(
        {"phong_light_evaluations_per_pixel" + k, double(ph.evaluationsMax),
         "light evaluations a pixel of per-pixel Phong makes, counted by its shader (largest over the disc)"});
    out.push_back({"phong_light_evaluations_min" + k, double(ph.evaluationsMin), "the smallest count over the disc"});
    out.push_back({"phong_lookups_per_pixel" + k, double(ph.lookupsMax), "cube-map lookups a pixel of Phong makes"});
  }
  // The part of the RMS the map's size decides: above the 8-bit floor (the finest map's RMS), in quadrature.
  auto find = [&](const std::string& name) {
    for (const ts::Measurement& m : out)
      if (m.name == name) return m.value;
    return 0.0;
  };
  for (int n : kLightCounts) {
    const std::string k = std::to_string(n) + "/";
    const double floor = find("envlight_rms_levels[" + k + "256]");
    for (int f : {32, 128}) {
      const double rms = find("envlight_rms_levels[" + k + std::to_string(f) + "]");
      out.push_back(
          {"envlight_rms_above_floor_levels[" + k + std::to_string(f) + "]",
           std::sqrt(std::max(0.0, rms * rms - floor * floor)),
           "the RMS above the 8-bit floor (the 256-texel map's RMS), in quadrature: the interpolation error"});
    }
  }
  double lookups = 0;
  for (const ts::Measurement& m : out)
    if (m.name.rfind("envlight_lookups_per_pixel[", 0) == 0) lookups = std::max(lookups, m.value);
  out.push_back({"envlight_lookups_per_pixel", lookups, "cube-map lookups a pixel, the most over 1, 4 and 16 lights"});
  return out;
}
}  // namespace envlight
