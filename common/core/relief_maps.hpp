// common/core/relief_maps.hpp — the relief maps the suite makes: bricks with deep
// mortar, a synthetic step/ridge map and a flat map (albedo and height, with
// their mip chains and the max-height pyramid), deterministic and
// byte-identical everywhere.  The parallax demo draws them
// (demos/parallax_aniso), textures/make_textures writes them as PNG files.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "common/core/hash.hpp"
#include "common/core/image.hpp"

namespace ts::relief {
constexpr int kTexSize = 512;  // every relief map is 512 x 512

struct Relief {
  std::string name;                  // "bricks" | "step" | "flat"
  std::vector<ts::Image> albedo;     // mip chain, level 0 = 512 x 512 (2x2 averages)
  std::vector<ts::Image> height;     // mip chain of the heights (R = G = B = h * 255), 2x2 averages
  std::vector<ts::Image> heightMax;  // max-height pyramid: each texel the largest height of the 2x2 below it
};

using ts::hash32;  // lowbias32
inline double unit(uint32_t h) { return double(h >> 8) * (1.0 / 16777216.0); }
inline uint8_t u8(double v) { return uint8_t(std::clamp(std::lround(v), 0L, 255L)); }

// The book's 2x2 average (rounded half up), or the 2x2 maximum.
inline ts::Image halve(const ts::Image& a, bool takeMax) {
  ts::Image out(std::max(1, a.width / 2), std::max(1, a.height / 2));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) {
        int v[4], k = 0;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx)
            v[k++] = a.pixels[(size_t(std::min(2 * y + dy, a.height - 1)) * size_t(a.width) +
                               size_t(std::min(2 * x + dx, a.width - 1))) *
                                  4 +
                              size_t(c)];
        int r = takeMax ? std::max({v[0], v[1], v[2], v[3]}) : (v[0] + v[1] + v[2] + v[3] + 2) / 4;
        out.pixels[(size_t(y) * size_t(out.width) + size_t(x)) * 4 + size_t(c)] = uint8_t(r);
      }
  return out;
}
inline std::vector<ts::Image> chain(const ts::Image& base, bool takeMax) {
  std::vector<ts::Image> c{base};
  while (c.back().width > 1 || c.back().height > 1) c.push_back(halve(c.back(), takeMax));
  return c;
}

// Bricks in running bond: 8 courses of 64 texels, bricks 128 long, joints 10
// texels wide and deep (h about 0.1), brick faces at h 0.88..0.98 with a
// rounded 3-texel edge; red-brown bricks, each its own shade, light mortar.
inline void bricksTexel(int x, int y, double* h, glm::dvec3* rgb) {
  const int course = y / 64, yy = y % 64;
  const int shift = (course % 2) * 64;
  const int xs = (x + shift) % kTexSize, brick = xs / 128, xx = xs % 128;
  const double dist = std::min({double(xx) - 4.5, 122.5 - double(xx), double(yy) - 4.5, 58.5 - double(yy)});
  const uint32_t id = hash32(uint32_t(course * 16 + brick) * 2654435761u + 17u);
  const double n = unit(hash32(uint32_t(y * kTexSize + x) ^ 0x9e3779b9u));
  if (dist < 0.0) {  // mortar
    *h = 0.08 + 0.04 * n;
    *rgb = glm::dvec3(205, 200, 188) + (n - 0.5) * 30.0;
    return;
  }
  const double top = 0.88 + 0.10 * unit(id) + 0.02 * (n - 0.5);
  const double r = std::clamp(dist / 3.0, 0.0, 1.0);
  *h = 0.45 + (top - 0.45) * std::sqrt(r * (2.0 - r));
  const double shade = 0.8 + 0.4 * unit(hash32(id));
  *rgb = glm::dvec3(150, 62, 44) * shade + (n - 0.5) * 36.0;
}

// The synthetic step map: ridges along u, 32 texels at the top (h = 1)
// then 32 texels of floor (h = 0), repeating along v; orange checks on the
// ridges, blue checks on the floor (8-texel checks, so blur shows).
inline void stepTexel(int x, int y, double* h, glm::dvec3* rgb) {
  const bool ridge = (y % 64) < 32;
  const bool odd = ((x / 8) + (y / 8)) % 2 == 1;
  *h = ridge ? 1.0 : 0.0;
  *rgb = ridge ? (odd ? glm::dvec3(235, 160, 50) : glm::dvec3(200, 110, 30))
               : (odd ? glm::dvec3(60, 120, 200) : glm::dvec3(30, 70, 140));
}

// Every map the parallax demo uses, made on the CPU (deterministic, byte-identical).
inline Relief makeRelief(const std::string& name) {
  Relief r;
  r.name = name;
  ts::Image a(kTexSize, kTexSize), hi(kTexSize, kTexSize);
  for (int y = 0; y < kTexSize; ++y)
    for (int x = 0; x < kTexSize; ++x) {
      double h = 1.0;
      glm::dvec3 c;
      if (name == "step") stepTexel(x, y, &h, &c);
      else bricksTexel(x, y, &h, &c);
      if (name == "flat") h = 1.0;  // the bricks' albedo on a flat top: nothing can be hidden
      a.set(x, y, {u8(c.r), u8(c.g), u8(c.b), 255});
      uint8_t hv = u8(h * 255.0);
      hi.set(x, y, {hv, hv, hv, 255});
    }
  r.albedo = chain(a, false);
  r.height = chain(hi, false);
  r.heightMax = chain(hi, true);
  return r;
}

}  // namespace ts::relief
