// tests/unit/projectors_test.cpp — the closed forms of demos/projectors
// (projectors_math.hpp): seed 002's wraps as printed against corrected, box
// mapping's stretch, the slide projector's planes, the cube's vertices.
// Expected values are computed here independently (by hand or with the
// library's trigonometry on the numbers the demo prints).  No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "demos/projectors/projectors_math.hpp"

namespace {
using proj::Axis;
using proj::Formula;
constexpr double kPi = 3.14159265358979323846;

glm::dvec3 randomUnit(std::mt19937& g) {
  std::normal_distribution<double> n;
  return glm::normalize(glm::dvec3(n(g), n(g), n(g)));
}

TEST(Projectors, PlanarZAsPrintedPutsEveryPointOnTheDiagonal) {
  std::mt19937 g(7);
  for (int k = 0; k < 1000; ++k) {
    glm::dvec3 p = randomUnit(g);
    glm::dvec2 st = proj::planar(Axis::Z, Formula::Printed, p);
    EXPECT_EQ(st.x, st.y);  // s = t everywhere
    glm::dvec2 c = proj::planar(Axis::Z, Formula::Corrected, p);
    EXPECT_DOUBLE_EQ(c.x, (p.x + 1) / 2);
    EXPECT_DOUBLE_EQ(c.y, (p.y + 1) / 2);
  }
  // The other axes as printed are already right: (z, y) and (x, z).
  glm::dvec3 p(0.2, -0.4, 0.6);
  EXPECT_EQ(proj::planar(Axis::X, Formula::Printed, p), glm::dvec2(0.8, 0.3));
  EXPECT_EQ(proj::planar(Axis::Y, Formula::Printed, p), glm::dvec2(0.6, 0.8));
  auto planes = proj::planarPlanes(Axis::Z, Formula::Printed);
  EXPECT_EQ(planes[0], planes[1]);
}

TEST(Projectors, CylindricalAsPrintedSpansAQuarterAndCollidesOppositePoints) {
  const double r = 1 / std::sqrt(2.0);
  for (Axis ax : {Axis::X, Axis::Y, Axis::Z}) {
    double lo = 1, hi = -1, clo = 1, chi = -1;
    for (int k = 0; k < 3600; ++k) {
      double th = 2 * kPi * (k + 0.5) / 3600;
      glm::dvec3 p(0.0);
      // a = sin θ, b = cos θ in the axis's own order (proj::across).
      if (ax == Axis::X) p = {0.0, std::cos(th), std::sin(th)};
      if (ax == Axis::Y) p = {std::sin(th), 0.0, std::cos(th)};
      if (ax == Axis::Z) p = {std::sin(th), std::cos(th), 0.0};
      double u = proj::angleU(ax, Formula::Printed, p), c = proj::angleU(ax, Formula::Corrected, p);
      lo = std::min(lo, u), hi = std::max(hi, u), clo = std::min(clo, c), chi = std::max(chi, c);
      EXPECT_EQ(u, proj::angleU(ax, Formula::Printed, -p));                             // p and -p collide
      EXPECT_NEAR(std::abs(c - proj::angleU(ax, Formula::Corrected, -p)), 0.5, 1e-12);  // half a turn apart
    }
    EXPECT_NEAR(lo, -0.25, 1e-3);
    EXPECT_NEAR(hi, 0.25, 1e-3);
    EXPECT_NEAR(clo, -0.5, 1e-3);
    EXPECT_NEAR(chi, 0.5, 1e-3);
  }
  // (1,1)/√2 and (-1,-1)/√2 across Z: both 0.125 as printed.
  EXPECT_NEAR(proj::angleU(Axis::Z, Formula::Printed, {r, r, 0}), 0.125, 1e-15);
  EXPECT_NEAR(proj::angleU(Axis::Z, Formula::Printed, {-r, -r, 0}), 0.125, 1e-15);
  EXPECT_NEAR(proj::angleU(Axis::Z, Formula::Corrected, {-r, -r, 0}), -0.375, 1e-15);
  // b = 0: the printed quotient divides by zero (IEEE gives ±inf, arctg ±π/2).
  EXPECT_NEAR(std::abs(proj::angleU(Axis::Z, Formula::Printed, {1, 0, 0})), 0.25, 1e-15);
  // Corrected along Y is Buss's Eq. VI.1: s = θ/360 for p = (sin θ, y, cos θ).
  for (double deg = -179; deg < 180; deg += 7)
    EXPECT_NEAR(proj::angleU(Axis::Y, Formula::Corrected, {std::sin(deg * kPi / 180), 0.3, std::cos(deg * kPi / 180)}),
                deg / 360, 1e-12);
}

TEST(Projectors, SphericalAsPrintedReachesOnlyAQuarter) {
  // tv - 1/2 (the raw sv/π · angle): the pole and 45° latitude.
  const double s45 = std::sin(kPi / 4);
  for (Axis ax : {Axis::X, Axis::Y, Axis::Z}) {
    glm::dvec3 pole(0.0), mid(0.0);
    pole[int(ax)] = 1.0;
    mid[int(ax)] = s45;
    mid[(int(ax) + 1) % 3] = s45;
    EXPECT_NEAR(proj::latitudeV(ax, Formula::Printed, pole), 0.25, 1e-15);
    EXPECT_NEAR(proj::latitudeV(ax, Formula::Printed, mid), std::atan(s45) / kPi, 1e-15);
    EXPECT_NEAR(proj::latitudeV(ax, Formula::Printed, mid), 0.1959, 5e-5);
    EXPECT_NEAR(proj::latitudeV(ax, Formula::Corrected, pole), 0.5, 1e-15);
    EXPECT_NEAR(proj::latitudeV(ax, Formula::Corrected, mid), 0.25, 1e-15);
    // The printed tv covers [0.25, 0.75]: half the rows.
    EXPECT_NEAR(proj::spherical(ax, Formula::Printed, -pole).y, 0.25, 1e-15);
    EXPECT_NEAR(proj::spherical(ax, Formula::Printed, pole).y, 0.75, 1e-15);
  }
}

TEST(Projectors, BoxMappingStretchIsAtMostRootThree) {
  std::mt19937 g(11);
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    glm::dvec3 n = randomUnit(g);
    double s = proj::boxStretch(n);
    EXPECT_LE(s, std::sqrt(3.0) + 1e-12);
    EXPECT_GE(s, 1.0);
    worst = std::max(worst, s);
  }
  EXPECT_GT(worst, 1.6);
  EXPECT_NEAR(proj::boxStretch({1, 1, 1}), 1.7320508075688772, 1e-12);
  EXPECT_NEAR(proj::planarStretch(80), 5.7587704831436335, 1e-12);  // 1/cos 80°
  EXPECT_NEAR(proj::planarStretch(80), 5.76, 0.005);
  // The box picks the largest component's axis and that axis's planar map.
  EXPECT_EQ(proj::boxAxis({0.1, -0.9, 0.3}), Axis::Y);
  EXPECT_EQ(proj::box({0.2, 0.4, 0.9}, {0.2, 0.4, 0.9}), glm::dvec2(0.6, 0.7));
}

TEST(Projectors, SlidePlanesAreTheRowsOfBiasProjectionView) {
  glm::dmat4 P = glm::perspective(0.6, 1.0, 0.5, 20.0);
  glm::dmat4 V = glm::lookAt(glm::dvec3(2, 3, 4), glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0));
  auto planes = proj::slidePlanes(P, V);
  std::mt19937 g(3);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int k = 0; k < 100; ++k) {
    glm::dvec3 w(u(g), u(g), u(g));
    glm::dvec4 clip = P * V * glm::dvec4(w, 1.0);
    glm::dvec4 c = proj::slideCoords(planes, w);
    EXPECT_NEAR(c.x, 0.5 * clip.x + 0.5 * clip.w, 1e-9);
    EXPECT_NEAR(c.y, 0.5 * clip.y + 0.5 * clip.w, 1e-9);
    EXPECT_NEAR(c.w, clip.w, 1e-9);
    // q is the depth in front of the projector: negative behind it.
    glm::dvec4 eye = V * glm::dvec4(w, 1.0);
    EXPECT_NEAR(c.w, -eye.z, 1e-9);
  }
  // The projector's axis lands on the slide's centre.
  glm::dvec4 c = proj::slideCoords(planes, {0, 0, 0});
  EXPECT_NEAR(c.x / c.w, 0.5, 1e-12);
  EXPECT_NEAR(c.y / c.w, 0.5, 1e-12);
}

TEST(Projectors, CubeNeeds24VerticesNot8) {
  auto c24 = proj::cube24(), c8 = proj::cube8();
  ASSERT_EQ(c24.size(), 24u);
  EXPECT_EQ(proj::distinctPositions(c24), 8);
  // Every corner is on 3 faces, and no single (s,t) serves all three: more
  // than 8 distinct (position, s, t) pairs (14 in this layout; drawn as 24).
  EXPECT_GT(proj::distinctVertices(c24), 8);
  for (const auto& v : c24)
    EXPECT_EQ(std::count_if(c24.begin(), c24.end(), [&](const proj::CubeVertex& w) { return w.pos == v.pos; }), 3);
  EXPECT_EQ(proj::distinctVertices(c8), 8);
  int good24 = 0, good8 = 0, smeared8 = 0, mirrored8 = 0;
  for (int f = 0; f < 6; ++f) {
    // Outward: the corners counter-clockwise around the face's normal.
    glm::dvec3 a = c24[size_t(4 * f)].pos, b = c24[size_t(4 * f + 1)].pos, d = c24[size_t(4 * f + 3)].pos;
    EXPECT_GT(glm::dot(glm::cross(b - a, d - a), c24[size_t(4 * f)].normal), 0);
    good24 += std::abs(proj::faceStArea(c24, f) - 1.0) < 1e-12;
    double s8 = proj::faceStArea(c8, f);
    good8 += std::abs(s8 - 1.0) < 1e-12;
    smeared8 += std::abs(s8) < 1e-12;
    mirrored8 += s8 < -1e-12;
  }
  EXPECT_EQ(good24, 6);
  EXPECT_EQ(good8, 1);      // +Z only
  EXPECT_EQ(smeared8, 4);   // ±X (s constant), ±Y (t constant)
  EXPECT_EQ(mirrored8, 1);  // -Z
}
}  // namespace
