// tests/unit/envmap_test.cpp — demos/environment_mapping/environment_mapping_math.hpp and common/core/env_maps: the
// four parameterizations, the world and the solid-angle integrals, on the
// CPU.  Every check is a relation (a map and its inverse, one convention
// against another, analytic against numeric), never a stored number.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/core/error.hpp"
#include "demos/environment_mapping/environment_mapping_math.hpp"

namespace {
using namespace envmap;

std::vector<dvec3> directions(int n) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  std::vector<dvec3> out;
  while (int(out.size()) < n) out.push_back(glm::normalize(dvec3(g(rng), g(rng), g(rng))));
  return out;
}

// Each map's (s,t) and its inverse agree, to well under a thousandth of a degree.
TEST(EnvMap, EveryMapInvertsItsCoordinates) {
  const glm::dmat3 I(1.0);
  for (const dvec3& d : directions(2000)) {
    const CubeST c = cubeST(d);
    EXPECT_LT(angleDeg(cubeDir(c.face, c.s, c.t), d), 1e-9);
    const dvec2 ll = latlongST(d), sp = sphereST(d), pb = paraboloidST(d);
    EXPECT_LT(angleDeg(latlongDir(ll.x, ll.y), d), 1e-6);
    if (d.z > -0.999) EXPECT_LT(angleDeg(sphereDir(sp.x, sp.y), d), 1e-5);
    EXPECT_LT(angleDeg(paraboloidDir(pb.x, pb.y), d), 1e-6);
    int face = -1;
    EXPECT_EQ(mapST(kCube, d, I, &face), dvec2(c.s, c.t));
    EXPECT_EQ(face, c.face);
  }
}

// The face is the component of largest magnitude, with its sign.
TEST(EnvMap, CubeFaceIsTheLargestComponent) {
  for (const dvec3& d : directions(2000)) {
    const dvec3 a = glm::abs(d);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    EXPECT_EQ(cubeST(d).face, 2 * axis + (d[axis] < 0 ? 1 : 0));
  }
}

// Seed 001's example: the seed's faces are the GL's mirrored in both axes,
// (s, t) -> (1 - s, 1 - t), on every face of its rule's kind (-Z, where the
// spec's table negates both remaining components); the two conventions pick
// the same face, and differ at the example.
TEST(EnvMap, SeedCubeIsTheGlFaceMirrored) {
  const dvec3 r(-3.2, 5.1, -8.4);
  const CubeST gl = cubeST(r), seed = seedCubeST(r);
  EXPECT_EQ(gl.face, 5);  // -Z: |r_z| is the largest and r_z < 0
  EXPECT_EQ(seed.face, gl.face);
  EXPECT_NEAR(seed.s, 1 - gl.s, 1e-12);
  EXPECT_NEAR(seed.t, 1 - gl.t, 1e-12);
  EXPECT_GT(std::abs(seed.s - gl.s), 0.3);
  for (const dvec3& d : directions(500))
    if (cubeST(d).face == 5) {
      EXPECT_NEAR(seedCubeST(d).s, 1 - cubeST(d).s, 1e-12);
      EXPECT_NEAR(seedCubeST(d).t, 1 - cubeST(d).t, 1e-12);
    }
}

// Seed 002's sphere map u = N_x/2 + 1/2 is GL_SPHERE_MAP's (s,t) when the eye
// looks along -z (I = (0,0,-1), r = I - 2 (N.I) N), and not when it does not:
// then the two directions named differ by the angle between the lines of
// sight.
TEST(EnvMap, SeedSphereMapEqualsGlOnTheAxisOnly) {
  for (const dvec3& n0 : directions(500)) {
    const dvec3 n = n0.z < 0 ? -n0 : n0;
    if (n.z < 0.2) continue;
    const dvec3 onAxis(0, 0, -1);
    const dvec2 seed = seedSphereST(n), gl = sphereST(glm::reflect(onAxis, n));
    EXPECT_NEAR(seed.x, gl.x, 1e-12);
    EXPECT_NEAR(seed.y, gl.y, 1e-12);
    const dvec3 off = glm::normalize(dvec3(0.1, 0.05, -1));
    const dvec3 rOff = glm::reflect(off, n), seedDir = sphereDir(seed.x, seed.y);
    EXPECT_NEAR(angleDeg(rOff, seedDir), angleDeg(off, onAxis), 1e-6);
  }
}

// Seed 002's cube-map reflection R = 2 N_z N - I (I to the eye) is r = 2 (N.I) N - I
// when the eye looks along the axis (I = (0,0,1)), and differs otherwise.
TEST(EnvMap, SeedCubeReflectionIsExactOnTheAxisOnly) {
  for (const dvec3& n0 : directions(300)) {
    const dvec3 n = n0.z < 0 ? -n0 : n0;
    const dvec3 axis(0, 0, 1), off = glm::normalize(dvec3(0.2, -0.1, 1));
    EXPECT_LT(angleDeg(2 * n.z * n - axis, 2 * glm::dot(n, axis) * n - axis), 1e-9);
    if (std::abs(glm::dot(n, off) - n.z) > 0.05)
      EXPECT_GT(angleDeg(2 * n.z * n - off, 2 * glm::dot(n, off) * n - off), 0.1);
  }
}

// Equal memory: every map within a row and a column of the cube's 6 face^2 texels.
TEST(EnvMap, MapsHaveEqualMemory) {
  for (int face : {16, 64, 128})
    for (int p = 0; p < kParams; ++p) {
      const Size sz = mapSize(Param(p), face);
      EXPECT_LE(std::abs(mapTexels(Param(p), face) - 6 * face * face), sz.w + sz.h) << p << " " << face;
    }
}

// Texels per steradian: analytic and numeric agree per texel; the cube's
// ratio tends to 3 sqrt 3 (face centre / corner) from below as the faces get
// finer, lat-long's grows without bound, the paraboloid's tends to 4, the
// sphere map's is 1 (its trouble is shape, not area).
TEST(EnvMap, SolidAngleAnalyticMatchesNumeric) {
  for (int p = 0; p < kParams; ++p) {
    const Uniformity u = uniformity(Param(p), 32);
    EXPECT_LT(u.largestRelDiff, 0.02) << kParamKeys[p];
    EXPECT_NEAR(u.numericRatio() / u.analyticRatio(), 1.0, 0.02) << kParamKeys[p];
  }
  const double cube16 = uniformity(kCube, 16).analyticRatio(), cube64 = uniformity(kCube, 64).analyticRatio();
  EXPECT_LT(cube16, cube64);
  EXPECT_LT(cube64, 3 * std::sqrt(3.0));
  EXPECT_GT(cube64, 0.9 * 3 * std::sqrt(3.0));
  EXPECT_GT(uniformity(kLatLong, 64).analyticRatio(), 1.9 * uniformity(kLatLong, 32).analyticRatio());
  EXPECT_NEAR(uniformity(kSphere, 64).analyticRatio(), 1.0, 1e-9);
  const double para = uniformity(kParaboloid, 64).analyticRatio();
  EXPECT_LT(para, 4.0);
  EXPECT_GT(para, 3.5);
  // The sum over a map's counted texels is the sphere (all of lat-long and the cube).
  double total = 0;
  for (int j = 0; j < 32; ++j)
    total += 2 * kPi * (std::sin((double(j + 1) / 32 - 0.5) * kPi) - std::sin((double(j) / 32 - 0.5) * kPi));
  EXPECT_NEAR(total, 4 * kPi, 1e-9);
}

// The world: colour follows direction (red with x, green with y, blue with z
// away from lines and labels), lines every 15 degrees are dark, each face
// centre carries its label box.
TEST(EnvMap, WorldColourIsLegible) {
  const dvec3 a = worldColour(glm::normalize(dvec3(0.45, 0.1, -0.9))),
              b = worldColour(glm::normalize(dvec3(0.6, 0.1, -0.8)));
  EXPECT_GT(b.r, a.r);
  for (double latDeg : {15.0, 30.0, -45.0}) {
    const double lonDeg = 37.0;  // between meridians, off the labels
    const dvec3 onLine(-std::sin(rad(lonDeg)) * std::cos(rad(latDeg)), std::sin(rad(latDeg)),
                       -std::cos(rad(lonDeg)) * std::cos(rad(latDeg)));
    const dvec3 off(-std::sin(rad(lonDeg)) * std::cos(rad(latDeg + 7)), std::sin(rad(latDeg + 7)),
                    -std::cos(rad(lonDeg)) * std::cos(rad(latDeg + 7)));
    const dvec3 line = worldColour(onLine), base = worldColour(off);
    EXPECT_LT(line.r + line.g + line.b, 0.6 * (base.r + base.g + base.b)) << latDeg;
  }
  for (int f = 0; f < 6; ++f) {
    // Around the centre of each face: the box (near white) or the text (near black), nothing else.
    const dvec3 c = worldColour(cubeDir(f, 0.5 + 0.17, 0.5));
    EXPECT_GT(c.r + c.g + c.b, 2.7) << kFaceNames[f];
  }
}
}  // namespace

// The maps as textures (common/core/env_maps.cpp, the generator the reference
// remakes from a sidecar): every texel is the world's colour at its centre's
// direction, in GL's upload order (a cube's face f in rows f w .. f w + w - 1,
// row 0 of a face its t = 0); the parameters written are enough to make the
// same texels again; bad parameters are refused.
TEST(EnvMap, TheMapTexturesAreTheWorldAndRemakeFromTheirParameters) {
  const glm::dmat3 view(glm::dvec3(std::cos(0.3), 0, std::sin(0.3)), glm::dvec3(0, 1, 0),
                        glm::dvec3(-std::sin(0.3), 0, std::cos(0.3)));
  for (int p = 0; p < kParams; ++p)
    for (bool unwrapped : {false, true}) {
      const ts::TextureDesc t = unwrapped ? unwrappedMap(Param(p), 8, view) : environmentMap(Param(p), 8, view);
      const Size sz = unwrapped ? unwrappedSize(Param(p), 8) : mapSize(Param(p), 8);
      ASSERT_EQ(t.image->width, sz.w) << kParamKeys[p];
      ASSERT_EQ(t.image->height, sz.h * (p == kCube && !unwrapped ? 6 : 1)) << kParamKeys[p];
      EXPECT_EQ(t.cube, p == kCube && !unwrapped);
      const ts::TextureDesc again = environmentMapFromParams(t.params);
      EXPECT_EQ(again.image->pixels, t.image->pixels) << kParamKeys[p] << (unwrapped ? " unwrapped" : "");
      EXPECT_EQ(again.key(), t.key());
    }
  const Size sz = mapSize(kCube, 8);
  const ts::TextureDesc cube = environmentMap(kCube, 8);
  for (int f = 0; f < 6; ++f)
    for (int j : {0, 5})
      for (int i : {1, 7}) {
        const ts::Rgba got = cube.image->at(i, f * sz.h + j),
                       want = toRgba(worldColour(cubeDir(f, (i + 0.5) / 8, (j + 0.5) / 8)));
        EXPECT_EQ(glm::ivec3(got.r, got.g, got.b), glm::ivec3(want.r, want.g, want.b));
      }
  const glm::dmat3 toWorld = glm::transpose(view);
  const ts::TextureDesc sphere = environmentMap(kSphere, 8, view);
  const Size ss = mapSize(kSphere, 8);
  const ts::Rgba got = sphere.image->at(ss.w / 2, ss.h / 2);
  const ts::Rgba want = toRgba(worldColour(toWorld * sphereDir((ss.w / 2 + 0.5) / ss.w, (ss.h / 2 + 0.5) / ss.h)));
  EXPECT_EQ(glm::ivec3(got.r, got.g, got.b), glm::ivec3(want.r, want.g, want.b));
  EXPECT_THROW(environmentMapFromParams({{"param", "mercator"}, {"face", "8"}}), ts::Error);
  EXPECT_THROW(environmentMapFromParams({{"param", "cube"}, {"face", "0"}}), ts::Error);
  EXPECT_THROW(environmentMapFromParams({{"param", "sphere"}, {"face", "8"}}), ts::Error);  // no sphere_view
  EXPECT_THROW(environmentMapFromParams({{"param", "sphere"}, {"face", "8"}, {"sphere_view", "1 0 0 0 1 0 0 0"}}),
               ts::Error);
  EXPECT_THROW(environmentMapFromParams({{"param", "cube"}, {"face", "8"}, {"layout", "cross"}}), ts::Error);
}
