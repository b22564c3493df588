// tests/unit/octant_test.cpp — Rogers' worked examples (seed 004) recomputed
// from first principles, as the oracle for demos/octant_mapping's numbers.
// It includes none of the demo's code: the mapping is solved here from the
// corner conditions, the view is built with Rogers' row-vector matrices
// ([x y z] [T]), the inverse uses the seed's own formulas (φ = acos y,
// θ = asin(x / sin φ)), the pattern is a 64 x 64 array of booleans, and the
// texel count uses a crossing-number point-in-polygon test (the demo uses
// edge cross products).  demos/octant_mapping/octant_mapping_test.cpp asserts
// that the demo measures the same answers.
//
// Conventions of the inverse count (the ones under which the seed's 5/18
// comes out, found by this test): texel (i, j) covers [i, i+1] x [j, j+1]
// in units of 1/64 with its centre at (i + ½, j + ½); the grid's lines are
// texel columns and rows 0, 15, 31, 47, 63 (⌊63 k/4⌋, the grid that gives
// Catmull's 7/16); the preimage is the quadrilateral through the pixel's
// corners mapped back, (u, w) rounded to 3 decimals as the seed tabulates
// them; a texel counts when its centre is inside.  Unrounded, and over the
// true curved preimage, the same conventions give 4/17: the whole difference
// is texel (47, 46), on a line, whose centre is 0.005 texels outside the
// exact quadrilateral.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace {
const double kPi = std::acos(-1.0);
using V3 = std::array<double, 3>;
using M3 = std::array<std::array<double, 3>, 3>;

// Row vector times matrix, as Rogers writes [x y z][T].
V3 rowTimes(const V3& v, const M3& m) {
  V3 r{};
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) r[size_t(j)] += v[size_t(k)] * m[size_t(k)][size_t(j)];
  return r;
}
M3 times(const M3& a, const M3& b) {
  M3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[size_t(i)][size_t(j)] += a[size_t(i)][size_t(k)] * b[size_t(k)][size_t(j)];
  return r;
}
M3 transpose(const M3& a) {
  M3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[size_t(i)][size_t(j)] = a[size_t(j)][size_t(i)];
  return r;
}
// Rogers' rotations for row vectors (Procedural Elements, 3-D transformations).
M3 rogersRotY(double deg) {
  const double a = deg * kPi / 180, c = std::cos(a), s = std::sin(a);
  return {{{c, 0, -s}, {0, 1, 0}, {s, 0, c}}};
}
M3 rogersRotX(double deg) {
  const double a = deg * kPi / 180, c = std::cos(a), s = std::sin(a);
  return {{{1, 0, 0}, {0, c, s}, {0, -s, c}}};
}
// First -45° about y, then 35° about x: [x' y' z'] = [x y z][T].
M3 T() { return times(rogersRotY(-45), rogersRotX(35)); }

// The mapping θ = A u + B, φ = C w + D from the corner conditions, each pair
// of equations solved by Cramer's rule.
struct Coeffs {
  double A, B, C, D;
};
Coeffs solveMapping() {
  // u = 0 -> θ = 0, u = 1 -> θ = π/2:  [0 1; 1 1] [A; B] = [0; π/2]
  auto solve = [](double x0, double y0, double x1, double y1, double* a, double* b) {
    const double det = x0 * 1 - 1 * x1;
    *a = (y0 * 1 - 1 * y1) / det;
    *b = (x0 * y1 - y0 * x1) / det;
  };
  Coeffs c{};
  solve(0, 0, 1, kPi / 2, &c.A, &c.B);
  solve(0, kPi / 2, 1, kPi / 4, &c.C, &c.D);
  return c;
}
V3 sphere(double theta, double phi) {
  return {std::sin(theta) * std::sin(phi), std::cos(phi), std::cos(theta) * std::sin(phi)};
}

// The pattern: 64 x 64, a line texel where its column or row is ⌊63 k/4⌋.
struct Pattern {
  std::array<std::array<bool, 64>, 64> black{};
  Pattern() {
    std::array<bool, 64> line{};
    for (int k = 0; k <= 4; ++k) line[size_t(63 * k / 4)] = true;
    for (int i = 0; i < 64; ++i)
      for (int j = 0; j < 64; ++j) black[size_t(i)][size_t(j)] = line[size_t(i)] || line[size_t(j)];
  }
};

// Pixel corner (Px, Py) -> (u, w) by the seed's formulas.
struct Corner {
  double xv, yv, zv, x, y, z, phi, theta, u, w;
};
Corner back(int Px, int Py) {
  Corner c{};
  c.xv = Px / 16.0 - 1, c.yv = Py / 16.0 - 1;
  c.zv = std::sqrt(1 - (c.xv * c.xv + c.yv * c.yv));
  const V3 p = rowTimes({c.xv, c.yv, c.zv}, transpose(T()));  // [x y z] = [x' y' z'][T]^-1
  c.x = p[0], c.y = p[1], c.z = p[2];
  c.phi = std::acos(c.y);
  c.theta = std::asin(c.x / std::sin(c.phi));
  c.u = c.theta / (kPi / 2);
  c.w = (kPi / 2 - c.phi) / (kPi / 4);
  return c;
}

// Crossing number: is (px, py) inside the polygon?
bool inside(const std::vector<std::array<double, 2>>& poly, double px, double py) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto& a = poly[i];
    const auto& b = poly[j];
    if ((a[1] > py) != (b[1] > py) && px < (b[0] - a[0]) * (py - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
  }
  return in;
}
struct Count {
  int texels = 0, lines = 0;
  bool has4746 = false;
};
Count countCentres(const std::vector<std::array<double, 2>>& texelPoly) {
  static const Pattern pat;
  Count c;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j)
      if (inside(texelPoly, i + 0.5, j + 0.5)) {
        ++c.texels;
        c.lines += pat.black[size_t(i)][size_t(j)];
        c.has4746 |= i == 47 && j == 46;
      }
  return c;
}
std::vector<std::array<double, 2>> pixelQuad(int Px, int Py, bool round3) {
  std::vector<std::array<double, 2>> q;
  for (auto [x, y] : {std::array<int, 2>{Px, Py}, {Px + 1, Py}, {Px + 1, Py + 1}, {Px, Py + 1}}) {
    Corner c = back(x, y);
    if (round3) c.u = std::round(c.u * 1000) / 1000, c.w = std::round(c.w * 1000) / 1000;
    q.push_back({c.u * 64, c.w * 64});
  }
  return q;
}
// Where a point of the pattern lands on the raster.
std::array<double, 3> toRaster(double u, double w) {
  const Coeffs m = solveMapping();
  const V3 p = rowTimes(sphere(m.A * u + m.B, m.C * w + m.D), T());
  return {16 * (p[0] + 1), 16 * (p[1] + 1), p[2]};
}

TEST(OctantOracle, MappingFromTheCorners) {
  const Coeffs m = solveMapping();
  EXPECT_NEAR(m.A, kPi / 2, 1e-15);
  EXPECT_NEAR(m.B, 0.0, 1e-15);
  EXPECT_NEAR(m.C, -kPi / 4, 1e-15);
  EXPECT_NEAR(m.D, kPi / 2, 1e-15);
}

// Example 1: the line u = 1/4, to 3 decimals (seed 004's table, corrected),
// and exactly against radicals at w = 1/2 (θ = π/8, φ = 3π/8).
TEST(OctantOracle, ForwardTableToThreeDecimals) {
  const Coeffs m = solveMapping();
  const double want[5][3] = {{0.383, 0.000, 0.924},
                             {0.375, 0.195, 0.906},
                             {0.354, 0.383, 0.854},
                             {0.318, 0.556, 0.768},
                             {0.271, 0.707, 0.653}};
  const double wantPhi[5] = {kPi / 2, 7 * kPi / 16, 3 * kPi / 8, 5 * kPi / 16, kPi / 4};
  for (int k = 0; k < 5; ++k) {
    const double w = k / 4.0, theta = m.A * 0.25 + m.B, phi = m.C * w + m.D;
    EXPECT_NEAR(theta, kPi / 8, 1e-15);   // the seed prints "p/2"
    EXPECT_NEAR(phi, wantPhi[k], 1e-15);  // the seed prints 7/(16p), ... for 7π/16, ...
    const V3 p = sphere(theta, phi);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(p[size_t(a)], want[k][a], 5e-4 + 1e-12) << "w = " << w << ", coordinate " << a;
  }
  const V3 mid = sphere(kPi / 8, 3 * kPi / 8);
  EXPECT_NEAR(mid[0], std::sqrt(2.0) / 4, 1e-15);
  EXPECT_NEAR(mid[1], std::sqrt(2 - std::sqrt(2.0)) / 2, 1e-15);
  EXPECT_NEAR(mid[2], (2 + std::sqrt(2.0)) / 4, 1e-15);
  // The seed's printed x, y, z (2 decimals) are right.
  const double printed[5][3] = {
      {0.38, 0, 0.92}, {0.38, 0.20, 0.91}, {0.35, 0.38, 0.85}, {0.32, 0.56, 0.77}, {0.27, 0.71, 0.65}};
  for (int k = 0; k < 5; ++k)
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(printed[k][a], want[k][a], 5e-3 + 1e-12);
}

// Example 2: four halvings of θ in [0, π/2] and φ in [π/4, π/2] from the
// corner θ = 0, φ = π/2 give θ in [0, π/32], φ in [31π/64, π/2], that is
// (u, w) in [0, 1/16]^2: 4 x 4 texels, 7 of them on lines.
TEST(OctantOracle, CatmullSevenSixteenths) {
  double th0 = 0, th1 = kPi / 2, ph0 = kPi / 4, ph1 = kPi / 2;
  for (int k = 0; k < 4; ++k) th1 = (th0 + th1) / 2, ph0 = (ph0 + ph1) / 2;
  EXPECT_NEAR(th1, kPi / 32, 1e-15);
  EXPECT_NEAR(ph0, 31 * kPi / 64, 1e-15);
  const double u1 = th1 / (kPi / 2), w1 = (kPi / 2 - ph0) / (kPi / 4);
  EXPECT_NEAR(u1, 1.0 / 16, 1e-15);
  EXPECT_NEAR(w1, 1.0 / 16, 1e-15);
  // The seed's 59π/64 would be w = -27/16, off the pattern.
  EXPECT_NEAR((kPi / 2 - 59 * kPi / 64) / (kPi / 4), -27.0 / 16, 1e-15);
  const Pattern pat;
  const int n = int(std::lround(u1 * 64));
  int black = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) black += pat.black[size_t(i)][size_t(j)];
  EXPECT_EQ(n * n, 16);
  EXPECT_EQ(black, 7);
  EXPECT_DOUBLE_EQ(double(black) / (n * n), 0.4375);
}

// Catmull's stopping rule: at 4 levels the corner fragment covers one pixel
// centre, (5, 9), and at 3 levels more than one.  A centre is covered when
// its preimage (the seed's inverse formulas) lies in the fragment.
TEST(OctantOracle, CatmullNeedsFourLevels) {
  auto covered = [](int level, std::vector<std::array<int, 2>>* which) {
    const double side = 1.0 / (1 << level);
    int n = 0;
    for (int Px = 0; Px < 32; ++Px)
      for (int Py = 0; Py < 32; ++Py) {
        const double xv = (Px + 0.5) / 16 - 1, yv = (Py + 0.5) / 16 - 1;
        if (xv * xv + yv * yv >= 1) continue;
        const double zv = std::sqrt(1 - xv * xv - yv * yv);
        const V3 p = rowTimes({xv, yv, zv}, transpose(T()));
        if (p[2] < 0) continue;
        const double phi = std::acos(p[1]);
        const double s = p[0] / std::sin(phi);
        if (std::fabs(s) > 1) continue;
        const double u = std::asin(s) / (kPi / 2), w = (kPi / 2 - phi) / (kPi / 4);
        if (u >= 0 && u < side && w >= 0 && w < side) {
          ++n;
          if (which) which->push_back({Px, Py});
        }
      }
    return n;
  };
  EXPECT_GT(covered(3, nullptr), 1);
  std::vector<std::array<int, 2>> which;
  EXPECT_EQ(covered(4, &which), 1);
  ASSERT_EQ(which.size(), 1u);
  EXPECT_EQ(which[0][0], 5);
  EXPECT_EQ(which[0][1], 9);
}

// Example 3: pixel (21, 15)'s corners (the seed's tables, corrected) ...
TEST(OctantOracle, InversePixelCorners) {
  struct Want {
    int Px, Py;
    double zv, x, y, z, phiDeg, thetaDeg, u, w;
  } want[] = {{21, 15, 0.948, 0.795, 0.492, 0.353, 60.50, 66.04, 0.734, 0.656},
              {22, 15, 0.925, 0.826, 0.479, 0.296, 61.36, 70.30, 0.781, 0.636},
              {22, 16, 0.927, 0.802, 0.532, 0.272, 57.88, 71.28, 0.792, 0.714},
              {21, 16, 0.950, 0.771, 0.545, 0.329, 56.99, 66.88, 0.743, 0.734}};
  for (const Want& c : want) {
    const Corner b = back(c.Px, c.Py);
    EXPECT_NEAR(b.zv, c.zv, 5e-4 + 1e-12);
    EXPECT_NEAR(b.x, c.x, 5e-4 + 1e-12);
    EXPECT_NEAR(b.y, c.y, 5e-4 + 1e-12);
    EXPECT_NEAR(b.z, c.z, 5e-4 + 1e-12);
    EXPECT_NEAR(b.phi * 180 / kPi, c.phiDeg, 5e-3 + 1e-12);
    EXPECT_NEAR(b.theta * 180 / kPi, c.thetaDeg, 5e-3 + 1e-12);
    EXPECT_NEAR(b.u, c.u, 5e-4 + 1e-12);
    EXPECT_NEAR(b.w, c.w, 5e-4 + 1e-12);
    // On the unit sphere.
    EXPECT_NEAR(b.x * b.x + b.y * b.y + b.z * b.z, 1.0, 1e-12);
  }
  // The seed's z = 0.341 at the first corner is off the sphere: |p|^2 = 0.991.
  const double n2 = 0.795 * 0.795 + 0.493 * 0.493 + 0.341 * 0.341;
  EXPECT_NEAR(n2, 0.991, 5e-4);
}

// ... and the count: 5/18 with the corners rounded as printed, 4/17 without.
TEST(OctantOracle, InversePixelCount) {
  const Count rounded = countCentres(pixelQuad(21, 15, true));
  EXPECT_EQ(rounded.texels, 18);
  EXPECT_EQ(rounded.lines, 5);
  EXPECT_NEAR(double(rounded.lines) / rounded.texels, 5.0 / 18, 1e-15);
  EXPECT_TRUE(rounded.has4746);
  const Count exact = countCentres(pixelQuad(21, 15, false));
  EXPECT_EQ(exact.texels, 17);
  EXPECT_EQ(exact.lines, 4);
  EXPECT_FALSE(exact.has4746);
  // The true, curved preimage: texel centres whose sphere point lands in the
  // pixel square [21, 22] x [15, 16].
  const Pattern pat;
  int texels = 0, lines = 0;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      const auto r = toRaster((i + 0.5) / 64, (j + 0.5) / 64);
      if (r[2] >= 0 && r[0] >= 21 && r[0] <= 22 && r[1] >= 15 && r[1] <= 16)
        ++texels, lines += pat.black[size_t(i)][size_t(j)];
    }
  EXPECT_EQ(texels, 17);
  EXPECT_EQ(lines, 4);
  // Texel (47, 46)'s centre lands just left of the pixel's left edge x = 21.
  const auto r = toRaster(47.5 / 64, 46.5 / 64);
  EXPECT_LT(r[0], 21.0);
  EXPECT_GT(r[0], 21.0 - 1e-3);
}
}  // namespace
