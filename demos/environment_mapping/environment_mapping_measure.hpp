// demos/environment_mapping/environment_mapping_measure.hpp — what the environment mapping
// demo measures from its read-backs (environment_mapping_gl.hpp) and the pictures it makes
// of them.
//
// Direction error.  A measurement pass reads maps whose texels hold their own
// directions, so each pixel returns the direction the map gave there (after
// GL's per-vertex interpolation or not, and bilinear filtering); the
// reference pass returns the exact r.  The error is the angle between the two
// in degrees: colours would say less (two directions can share a colour, and
// 8 bits quantise), a direction is what a map stores.
// Where it concentrates: each pixel is put in a region of its map by its
// reference r: lat-long "pole" (|latitude| > 75°) / "seam" (within 30° of
// λ = ±180°: a triangle of the coarse meshes spans that much of r, and per
// vertex the whole triangle tears) / "body"; cube "edge" (second largest |component| > 0.9 of the
// largest) / "face"; sphere "rim" (radius in the map > 0.9) / "centre";
// paraboloid "rim" (|r_z| < 0.15, where the two discs meet) / "centre".
#pragma once
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "common/core/image.hpp"
#include "environment_mapping_gl.hpp"
#include "environment_mapping_math.hpp"

namespace envmap {
using envmap::dvec3;
using envmap::Param;

inline std::string regionOf(int param, dvec3 r, const glm::dmat3& sphereEye) {
  r = glm::normalize(r);
  switch (param) {
    case envmap::kLatLong: {
      const double lat = envmap::deg(std::asin(std::clamp(r.y, -1.0, 1.0))), lon = envmap::deg(std::atan2(-r.x, -r.z));
      return std::abs(lat) > 75 ? "pole" : std::abs(lon) > 150 ? "seam" : "body";
    }
    case envmap::kCube: {
      dvec3 a = glm::abs(r);
      std::sort(&a[0], &a[0] + 3);
      return a[1] > 0.9 * a[2] ? "edge" : "face";
    }
    case envmap::kSphere: {
      const glm::dvec2 st = envmap::sphereST(sphereEye * r);
      return glm::length(st * 2.0 - 1.0) > 0.9 ? "rim" : "centre";
    }
    default: return std::abs(r.z) < 0.15 ? "rim" : "centre";
  }
}

struct ErrorStats {
  int pixels = 0;
  double mean = 0, p95 = 0, max = 0;
  std::string maxRegion;                     // the region of the largest error
  std::map<std::string, double> regionMean;  // mean error per region
  std::map<std::string, int> regionPixels;
};
// Pixels covered in both read-backs; `perPixel` (optional) gets each pixel's
// error, -1 off the object.
inline ErrorStats errorStats(int param, const envmap::Pixels& lookup, const envmap::Pixels& ref,
                             const glm::dmat3& sphereEye, std::vector<float>* perPixel = nullptr) {
  ErrorStats s;
  std::vector<double> all;
  if (perPixel) perPixel->assign(size_t(ref.w) * size_t(ref.h), -1.0f);
  for (int y = 0; y < ref.h; ++y)
    for (int x = 0; x < ref.w; ++x) {
      if (ref.at(x, y).a < 0.5f || lookup.at(x, y).a < 0.5f) continue;
      const dvec3 r = ref.direction(x, y);
      const double e = envmap::angleDeg(lookup.direction(x, y), r);
      all.push_back(e);
      if (perPixel) (*perPixel)[size_t(y) * size_t(ref.w) + size_t(x)] = float(e);
      const std::string region = param >= 0 ? regionOf(param, r, sphereEye) : "all";
      s.regionMean[region] += e, s.regionPixels[region] += 1;
      if (e > s.max) s.max = e, s.maxRegion = region;
    }
  s.pixels = int(all.size());
  if (all.empty()) return s;
  for (double e : all) s.mean += e;
  s.mean /= double(all.size());
  std::nth_element(all.begin(), all.begin() + long(all.size() * 95 / 100), all.end());
  s.p95 = all[all.size() * 95 / 100];
  for (auto& [k, v] : s.regionMean) v /= s.regionPixels[k];
  return s;
}

// Resolution: how large, in degrees, the texel a pixel reads is along its
// longer side (the angle between the directions at its opposite edges, in s
// and in t), and its aspect (longer / shorter side).  The direction error above says a map points the right way;
// this says how coarse the world is where it points: a sphere map's rim
// texels are long and thin (each still spans 4 (2/n)^2 sr), a cube face's
// centre texels are larger than its corners', lat-long's shrink along λ
// toward the poles.  Averaged per region over the pixels of `ref`, at their
// exact r.
struct TexelShape {
  double extentDeg = 0, aspect = 0;
};
inline std::map<std::string, TexelShape> texelShape(int param, int faceTexels, const envmap::Pixels& ref,
                                                    const glm::dmat3& sphereView, const glm::dmat3& eye) {
  const envmap::Size sz = envmap::mapSize(Param(param), faceTexels);
  const glm::dmat3 toWorld = glm::transpose(sphereView);
  std::map<std::string, TexelShape> sum;
  std::map<std::string, int> n;
  for (int y = 0; y < ref.h; ++y)
    for (int x = 0; x < ref.w; ++x) {
      if (ref.at(x, y).a < 0.5f) continue;
      const dvec3 r = ref.direction(x, y);
      int face = 0;
      const glm::dvec2 st = envmap::mapST(Param(param), r, sphereView, &face);
      const double hs = 0.5 / sz.w, ht = 0.5 / sz.h;
      auto dir = [&](double s, double t) { return envmap::texelDir(Param(param), face, s, t, toWorld); };
      const double a = envmap::angleDeg(dir(st.x - hs, st.y), dir(st.x + hs, st.y)),
                   b = envmap::angleDeg(dir(st.x, st.y - ht), dir(st.x, st.y + ht));
      const std::string region = regionOf(param, r, eye);
      sum[region].extentDeg += std::max(a, b), sum[region].aspect += std::max(a, b) / std::max(1e-9, std::min(a, b));
      n[region] += 1;
    }
  for (auto& [k, v] : sum) v.extentDeg /= n[k], v.aspect /= n[k];
  return sum;
}

// ---- pictures (ts::Image, row 0 at the top) -------------------------------
// The reference read-back (directions) shown as the world's colours there.
inline ts::Image referenceImage(const envmap::Pixels& p) {
  ts::Image img(p.w, p.h);
  for (int y = 0; y < p.h; ++y)
    for (int x = 0; x < p.w; ++x) {
      const int gy = p.h - 1 - y;
      img.set(x, y, envmap::toRgba(p.at(x, gy).a > 0.5f ? envmap::worldColour(p.direction(x, gy)) : kBackground));
    }
  return img;
}
// The error picture's scale: per pixel the maps are off by hundredths of a degree, per vertex by
// degrees; a larger 95th percentile (a stale sphere map) takes the next of 1, 2, 5 x 10^k above it.
inline double errorScale(bool perVertex, double p95) {
  double scale = perVertex ? 4.0 : 0.25;
  for (double step = 1; scale < p95; step *= 10)
    for (double m : {1.0, 2.0, 5.0})
      if (scale < p95) scale = std::max(scale, m * step);
  return scale;
}
// Error in degrees on a heat scale: black 0, red at `scaleDeg`/2, yellow to
// white at `scaleDeg` and above.
inline glm::dvec3 heat(double e, double scaleDeg) {
  const double v = std::clamp(e / scaleDeg, 0.0, 1.0);
  return {std::min(1.0, 2 * v), std::clamp(2 * v - 1, 0.0, 1.0), std::clamp(4 * v - 3, 0.0, 1.0)};
}
inline ts::Image errorImage(const std::vector<float>& e, int w, int h, double scaleDeg) {
  ts::Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = e[size_t(h - 1 - y) * size_t(w) + size_t(x)];
      img.set(x, y, envmap::toRgba(v < 0 ? kBackground : heat(v, scaleDeg)));
    }
  return img;
}
// The texels of the map the object reads (the direction each pixel of
// `looked` returned, taken back to the map), in the unwrapped layout of
// ts::envmaps::unwrappedMap (row 0 at the top), grown by two texels.
struct LitTexels {
  int w = 0, h = 0;
  std::vector<char> hit;  // w x h, row 0 at the top
};
inline LitTexels litTexels(int param, int faceTexels, const glm::dmat3& sphereView, const envmap::Pixels& looked) {
  const envmap::Size sz = envmap::mapSize(Param(param), faceTexels),
                     all = envmap::unwrappedSize(Param(param), faceTexels);
  const int W = all.w, H = all.h;
  std::vector<char> hit(size_t(W) * size_t(H), 0);
  // Where texel (face, i, j) of the map lands in the unwrapped picture.
  auto place = [&](int face, int i, int j) {
    if (param == envmap::kCube) return glm::ivec2((face % 3) * sz.w + i, (face / 3) * sz.h + j);  // t down
    return glm::ivec2(i, sz.h - 1 - j);                                                           // t up
  };
  for (int y = 0; y < looked.h; ++y)
    for (int x = 0; x < looked.w; ++x) {
      if (looked.at(x, y).a < 0.5f) continue;
      int face = 0;
      const glm::dvec2 st = envmap::mapST(Param(param), looked.direction(x, y), sphereView, &face);
      const int i = std::clamp(int(st.x * sz.w), 0, sz.w - 1), j = std::clamp(int(st.y * sz.h), 0, sz.h - 1);
      const glm::ivec2 q = place(face, i, j);
      hit[size_t(q.y) * size_t(W) + size_t(q.x)] = 1;
    }
  // A picture has fewer pixels than the map has texels where the object is
  // small: grow the lit texels by two so the region reads as one.
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<char> grown = hit;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        if (hit[size_t(y) * size_t(W) + size_t(x)])
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
              if (x + dx >= 0 && y + dy >= 0 && x + dx < W && y + dy < H)
                grown[size_t(y + dy) * size_t(W) + size_t(x + dx)] = 1;
    hit.swap(grown);
  }
  return {W, H, hit};
}
}  // namespace envmap
