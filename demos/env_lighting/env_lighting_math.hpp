// demos/env_lighting/env_lighting_math.hpp — the lights, the specular term
// baked into a cube map, and the error bound the tests hold the map to.
// GL-free: the texture generator (env_lighting_textures.cpp) and the CPU
// reference use it too.
//
// The lights are directional: light k has the unit direction L_k (towards
// the light) and the colour C_k.  The specular term of a surface point whose
// mirror direction is r (unit, r = v - 2 (v.n) n, Buss VI.3) is Phong's
//   S(r) = sum_k C_k max(0, r.L_k)^n
// It depends on r alone, so it can be stored by direction like any
// environment (seed 001 ¶44: "the highlights of any number of lights at a
// fixed cost, per pixel"): the cube map's texel whose centre looks along d
// holds S(d), clamped to [0, 1] and rounded to 8 bits.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/core/env_maps.hpp"
#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "common/core/kept.hpp"
#include "common/core/parallel.hpp"

namespace envlight {
constexpr double kPi = 3.14159265358979323846;
constexpr double kShininess = 32.0;  // Phong's exponent n: a highlight 12 degrees of r wide at half its peak
constexpr int kMaxLights = 16;
inline const int kLightCounts[] = {1, 4, 16};

struct Light {
  glm::dvec3 dir;     // unit, towards the light
  glm::dvec3 colour;  // RGB in [0, 1]
};

// n lights spread evenly over the directions the sphere's picture shows
// well, a cone of 72 degrees about the eye (+z): a golden-angle spiral of n
// points of equal area, each with its own hue, so that a highlight in the
// picture says which light made it.
inline std::vector<Light> lights(int n) {
  std::vector<Light> out;
  const double zMin = std::cos(72.0 * kPi / 180.0), golden = kPi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - (k + 0.5) / n * (1.0 - zMin), rho = std::sqrt(1.0 - z * z), phi = 0.6 + k * golden;
    // The colour: hue k/n of an HSV wheel at saturation 0.55 and value 0.85 (so no channel passes 0.85).
    const double hue = 6.0 * k / n;
    const glm::dvec3 wheel(std::clamp(std::abs(hue - 3.0) - 1.0, 0.0, 1.0),
                           std::clamp(2.0 - std::abs(hue - 2.0), 0.0, 1.0),
                           std::clamp(2.0 - std::abs(hue - 4.0), 0.0, 1.0));
    out.push_back({{rho * std::cos(phi), rho * std::sin(phi), z}, 0.85 * (1.0 - 0.55 + 0.55 * wheel)});
  }
  return out;
}

// Phong's specular sum at the mirror direction r (unit), unclamped.  A
// light behind r adds pow(0, n) = 0: left out, the same sum (s is never -0).
inline glm::dvec3 specular(glm::dvec3 r, const std::vector<Light>& ls) {
  glm::dvec3 s(0.0);
  for (const Light& l : ls) {
    const double c = glm::dot(r, l.dir);
    if (c > 0.0) s += l.colour * std::pow(c, kShininess);
  }
  return s;
}

// The map: 6 faces of face x face texels, each S at its centre's direction
// (ts::envmaps::cubeDir: GL's face table), GL_LINEAR, no mipmaps.  Named
// "env_lighting_map" with its parameters, which the generator remakes.
// The map's texels for (nLights, face), made once per process (on both
// cores): a figure draws the same map in several passes and views, and each
// texel costs a pow() per light.  A few are kept; the pictures are shared, never changed.
inline std::shared_ptr<const ts::Image> lightingMapTexels(int nLights, int face) {
  static ts::Kept<std::pair<int, int>, std::shared_ptr<const ts::Image>> made(8);
  return made.get({nLights, face}, [&] {
    const std::vector<Light> ls = lights(nLights);
    auto img = std::make_shared<ts::Image>(face, 6 * face);
    ts::evenAndOdd(6 * face, [&](int y) {  // face f's row j is image row f face + j
      for (int i = 0; i < face; ++i) {
        const glm::dvec3 d = ts::envmaps::cubeDir(y / face, (i + 0.5) / face, (y % face + 0.5) / face);
        img->set(i, y, ts::envmaps::toRgba(specular(d, ls)));
      }
    });
    return std::shared_ptr<const ts::Image>(img);
  });
}
inline ts::TextureDesc lightingMap(int nLights, int face) {
  std::shared_ptr<const ts::Image> img = lightingMapTexels(nLights, face);
  ts::TextureDesc t;
  t.name = "env_lighting_map";
  t.params = {{"lights", std::to_string(nLights)}, {"face", std::to_string(face)}};
  t.image = img;
  t.cube = true;
  t.minFilter = t.magFilter = GL_LINEAR;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}

// The error the map's resolution allows, in 8-bit levels, derived (not fitted):
// a texel's side spans at most h = 2/face radians of direction (at a face's
// centre: the face's side is 2 at distance 1).  Bilinear interpolation of a
// function f between samples h apart errs by at most h^2/8 (|f_uu| + |f_vv|);
// for one light, f = C max(0, cos θ)^n, whose second derivative along any
// direction is largest at the peak, n C (a peak of brightness C <= 0.85).
// So the interpolation error is at most 255 C n h^2 / 4 levels.  Rounding
// adds kRoundingLevels: half a level for the texel, half for each of the two
// pictures' pixels, and one for GL_LINEAR's fixed-point weights (llvmpipe
// blends 8-bit texels with 8-bit weights; the map of 256 texels a face, whose
// interpolation part is 0.1 level, is measured 2 levels from Phong at most).
// This bounds every pixel whose r is away from its face's edges, where the
// filter reads only that face; nearer an edge GL_LINEAR clamps to the face
// (GL_TEXTURE_CUBE_MAP_SEAMLESS is off, the compatibility default), an error
// of first order in h, which the measurement reports apart.
constexpr double kRoundingLevels = 2.0;
inline double texelAngleDeg(int face) { return 2.0 / face * 180.0 / kPi; }
inline double interpolationBoundLevels(int face) {
  const double h = 2.0 / face;
  return 255.0 * 0.85 * kShininess * h * h / 4.0;
}
inline double errorBoundLevels(int face) { return interpolationBoundLevels(face) + kRoundingLevels; }
}  // namespace envlight
