// tests/unit/quadmap_test.cpp — the mathematics of Figure VI.1
// (demos/quad_distortion/quad_distortion_math.hpp), checked against values derived by
// hand and against each other.  No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "demos/quad_distortion/quad_distortion_math.hpp"

namespace {
using quad::Corners;
using quad::Diagonal;

constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = 1e-12;

// The book's corners: (s,t) at the square's (0,0) (1,0) (1,1) (0,1).
const Corners kBook{glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0.75, 0.75), glm::dvec2(0, 1)};
// A parallelogram (x0 - x1 + x2 - x3 = 0): an affine image of the square.
const Corners kParallelogram{glm::dvec2(0.125, 0.25), glm::dvec2(0.875, 0.375), glm::dvec2(1.25, 1.125),
                             glm::dvec2(0.5, 1.0)};

void expectNear(glm::dvec2 got, glm::dvec2 want, double eps, const char* what) {
  EXPECT_NEAR(got.x, want.x, eps) << what;
  EXPECT_NEAR(got.y, want.y, eps) << what;
}

// A random convex quadrilateral: the unit square's corners jittered by < 0.3,
// so no three corners are ever in a line and the winding stays the same.
Corners randomQuad(std::mt19937& rng) {
  std::uniform_real_distribution<double> j(-0.3, 0.3);
  Corners c;
  const auto& P = quad::squareCorners();
  for (size_t i = 0; i < 4; ++i) c[i] = P[i] + glm::dvec2(j(rng), j(rng));
  return c;
}

// Claim: affineThrough(p0,p1,p2 -> s0,s1,s2) maps each of the three points to
// its target, for random (non-degenerate) triangles.
TEST(QuadMap, AffineThroughReproducesItsThreeCorners) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int n = 0; n < 100; ++n) {
    glm::dvec2 p[3], s[3];
    for (auto& v : p) v = {u(rng), u(rng)};
    for (auto& v : s) v = {u(rng), u(rng)};
    glm::dvec2 e1 = p[1] - p[0], e2 = p[2] - p[0];
    if (std::abs(e1.x * e2.y - e1.y * e2.x) < 0.1) continue;  // nearly degenerate: skip
    quad::Affine A = quad::affineThrough(p[0], p[1], p[2], s[0], s[1], s[2]);
    for (int k = 0; k < 3; ++k) expectNear(A(p[k]), s[k], 1e-9, "corner");
    // ... and the gradients are its matrix's rows: a step along a moves s by m[0][0].
    glm::dvec2 q(u(rng), u(rng));
    EXPECT_NEAR(A(q + glm::dvec2(1, 0)).x - A(q).x, A.gradient(0).x, 1e-9);
    EXPECT_NEAR(A(q + glm::dvec2(0, 1)).y - A(q).y, A.gradient(1).y, 1e-9);
  }
}

// Claim: for each diagonal, split() gives two affine maps that reproduce the
// corners of their own triangles and agree with each other along the
// diagonal (the texture is continuous; only its gradient jumps).
TEST(QuadMap, SplitMapsReproduceCornersAndAgreeOnTheDiagonal) {
  const auto& P = quad::squareCorners();
  std::mt19937 rng(2);
  for (int n = 0; n < 50; ++n) {
    Corners st = n == 0 ? kBook : randomQuad(rng);
    // tl-br: first = (00,10,01), second = (10,11,01); diagonal (0,1)-(1,0).
    quad::Split a = quad::split(st, Diagonal::TopLeftBottomRight);
    for (int i : {0, 1, 3}) expectNear(a.first(P[size_t(i)]), st[size_t(i)], 1e-9, "tl-br first");
    for (int i : {1, 2, 3}) expectNear(a.second(P[size_t(i)]), st[size_t(i)], 1e-9, "tl-br second");
    // bl-tr: first = (00,10,11), second = (00,11,01); diagonal (0,0)-(1,1).
    quad::Split b = quad::split(st, Diagonal::BottomLeftTopRight);
    for (int i : {0, 1, 2}) expectNear(b.first(P[size_t(i)]), st[size_t(i)], 1e-9, "bl-tr first");
    for (int i : {0, 2, 3}) expectNear(b.second(P[size_t(i)]), st[size_t(i)], 1e-9, "bl-tr second");
    for (double u = 0; u <= 1.0; u += 0.125) {
      expectNear(a.first({u, 1 - u}), a.second({u, 1 - u}), 1e-9, "tl-br diagonal");
      expectNear(b.first({u, u}), b.second({u, u}), 1e-9, "bl-tr diagonal");
    }
  }
}

// Claim: Split::inFirst puts each corner's neighbourhood in the triangle the
// header documents (tl-br: (0,0) side first; bl-tr: (1,0) side first).
TEST(QuadMap, SplitSidesAreTheDocumentedTriangles) {
  quad::Split s = quad::split(kBook, Diagonal::TopLeftBottomRight);
  EXPECT_TRUE(s.inFirst({0.1, 0.1}, Diagonal::TopLeftBottomRight));
  EXPECT_FALSE(s.inFirst({0.9, 0.9}, Diagonal::TopLeftBottomRight));
  EXPECT_TRUE(s.inFirst({0.9, 0.1}, Diagonal::BottomLeftTopRight));
  EXPECT_FALSE(s.inFirst({0.1, 0.9}, Diagonal::BottomLeftTopRight));
  // With the book's corners the lower-left triangle is the identity map, so
  // at(...) there returns the point itself; in the upper right it does not.
  expectNear(s.at({0.2, 0.3}, Diagonal::TopLeftBottomRight)({0.2, 0.3}), {0.2, 0.3}, kEps, "identity half");
  glm::dvec2 ur = s.at({0.9, 0.9}, Diagonal::TopLeftBottomRight)({0.9, 0.9});
  EXPECT_GT(glm::length(ur - glm::dvec2(0.9, 0.9)), 0.1);
}

// Claim: the homography sends the square's four corners to the four (s,t)
// corners (checked through projective() and through the (sq,tq,0,q) vertex
// coordinates GL receives), for the book's quad and random convex quads.
TEST(QuadMap, HomographyMapsSquareCornersToTheQuad) {
  const auto& P = quad::squareCorners();
  std::mt19937 rng(3);
  for (int n = 0; n < 50; ++n) {
    Corners st = n == 0 ? kBook : randomQuad(rng);
    glm::dmat3 H = quad::homography(st);
    for (size_t i = 0; i < 4; ++i) {
      expectNear(quad::projective(H, P[i]), st[i], 1e-9, "corner");
      glm::dvec4 v = quad::projectiveTexCoord(H, P[i]);
      EXPECT_EQ(v.z, 0.0);
      EXPECT_GT(v.w, 0.0) << "q must stay positive over a convex quad";
      expectNear(glm::dvec2(v.x, v.y) / v.w, st[i], 1e-9, "(sq,tq)/q");
    }
  }
}

// Claim: a parallelogram needs no projective division: q == 1 exactly at
// every point, and the map equals the (then identical) triangle maps.  The
// book's quad is not a parallelogram and its q differs from 1 inside.
TEST(QuadMap, HomographyOfAParallelogramIsAffine) {
  glm::dmat3 H = quad::homography(kParallelogram);
  quad::Split s = quad::split(kParallelogram, Diagonal::TopLeftBottomRight);
  for (double a = 0; a <= 1.0; a += 0.25)
    for (double b = 0; b <= 1.0; b += 0.25) {
      EXPECT_EQ(quad::projectiveTexCoord(H, {a, b}).w, 1.0);
      expectNear(quad::projective(H, {a, b}), s.first({a, b}), 1e-12, "affine");
    }
  glm::dmat3 B = quad::homography(kBook);
  EXPECT_GT(std::abs(quad::projectiveTexCoord(B, {0.5, 0.5}).w - 1.0), 0.01);
}

// Claim: the kink for the book's corners, split tl-br, is atan(1/3).
// By hand: the lower-left triangle (0,0),(1,0),(0,1) keeps its corners, so
// its map is the identity: grad s = (1, 0).  The upper-right triangle sends
// (1,0)->(1,0), (1,1)->(0.75,0.75), (0,1)->(0,1): a step +b from (1,0) moves
// (s,t) by (-0.25, 0.75), and a step -a from (1,1) moves it by (-0.75, 0.25),
// so ds/da = 0.75, ds/db = -0.25: grad s = (0.75, -0.25).  The angle between
// (1,0) and (0.75,-0.25) is atan(0.25/0.75) = atan(1/3) = 18.4349 deg (t is
// symmetric: (0,1) against (-0.25,0.75), the same angle).
// The other diagonal, bl-tr: grad s = (1,-0.25) below, (0.75,0) above:
// atan(1/4) = 14.0362 deg.  A parallelogram: one affine map, no kink.
TEST(QuadMap, PredictedKinkMatchesHandDerivation) {
  const double tlbr = std::atan(1.0 / 3.0) * 180.0 / kPi, bltr = std::atan(0.25) * 180.0 / kPi;
  EXPECT_NEAR(quad::predictedKinkDeg(kBook, Diagonal::TopLeftBottomRight), tlbr, 1e-9);
  EXPECT_NEAR(quad::predictedKinkDeg(kBook, Diagonal::BottomLeftTopRight), bltr, 1e-9);
  EXPECT_NEAR(tlbr, 18.4349488, 1e-6);
  quad::Split s = quad::split(kBook, Diagonal::TopLeftBottomRight);
  expectNear(s.first.gradient(0), {1.0, 0.0}, 1e-12, "grad s lower-left");
  expectNear(s.second.gradient(0), {0.75, -0.25}, 1e-12, "grad s upper-right");
  expectNear(s.second.gradient(1), {-0.25, 0.75}, 1e-12, "grad t upper-right");
  for (Diagonal d : {Diagonal::TopLeftBottomRight, Diagonal::BottomLeftTopRight})
    EXPECT_NEAR(quad::predictedKinkDeg(kParallelogram, d), 0.0, 1e-5);
}

// Claim: angleDeg is the angle between two vectors, whatever their lengths.
TEST(QuadMap, AngleDeg) {
  EXPECT_NEAR(quad::angleDeg({1, 0}, {0, 3}), 90.0, 1e-12);
  EXPECT_NEAR(quad::angleDeg({2, 0}, {-1, 0}), 180.0, 1e-12);
  EXPECT_NEAR(quad::angleDeg({1, 1}, {5, 5}), 0.0, 1e-5);  // acos near 1: ~1e-6 deg of round-off
  EXPECT_NEAR(quad::angleDeg({1, 0}, {1, 1}), 45.0, 1e-12);
}

// Claim: bilinear interpolation takes the corner values at the corners, the
// mean at the centre, and the edge midpoints' means on the edges.
TEST(QuadMap, BilinearAtCornersCentreAndEdges) {
  const auto& P = quad::squareCorners();
  std::mt19937 rng(4);
  for (int n = 0; n < 20; ++n) {
    Corners st = n == 0 ? kBook : randomQuad(rng);
    for (size_t i = 0; i < 4; ++i) expectNear(quad::bilinear(st, P[i]), st[i], kEps, "corner");
    expectNear(quad::bilinear(st, {0.5, 0.5}), (st[0] + st[1] + st[2] + st[3]) / 4.0, kEps, "centre");
    expectNear(quad::bilinear(st, {0.5, 0.0}), (st[0] + st[1]) / 2.0, kEps, "bottom edge");
    expectNear(quad::bilinear(st, {1.0, 0.5}), (st[1] + st[2]) / 2.0, kEps, "right edge");
  }
}

// Claim: the split's disagreement is 0 for a parallelogram and, for the book's
// quad split tl-br, |(0.25,0.25)| = 0.3536 (identity vs. the upper-right map
// at corner (0,0): the upper-right map sends (0,0) to (0.25, 0.25)).
TEST(QuadMap, SplitDisagreement) {
  EXPECT_NEAR(quad::splitDisagreement(kParallelogram, Diagonal::TopLeftBottomRight), 0.0, 1e-9);
  EXPECT_NEAR(quad::splitDisagreement(kBook, Diagonal::TopLeftBottomRight), std::sqrt(0.125), 1e-9);
}
}  // namespace

// Claim: the measured-way angle (one-sided differences either side of the
// diagonal) finds the affine split's bend given by the closed form, for both
// diagonals, and no bend for the maps that are smooth across it — so the
// demo's predictions for bilinear and projective are computed, not assumed.
TEST(QuadMap, KinkAcrossTheDiagonalAgreesWithTheClosedForm) {
  const quad::Corners st = {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0.75, 0.75), glm::dvec2(0, 1)};
  for (quad::Diagonal d : {quad::Diagonal::TopLeftBottomRight, quad::Diagonal::BottomLeftTopRight}) {
    quad::Split s = quad::split(st, d);
    double numeric = quad::kinkAcrossDiagonalDeg([&](glm::dvec2 p) { return s.at(p, d)(p); }, d);
    EXPECT_NEAR(numeric, quad::predictedKinkDeg(st, d), 1e-3);
    EXPECT_GT(numeric, 10.0);  // the book's corners bend by 14 or 18 degrees
    EXPECT_LT(quad::kinkAcrossDiagonalDeg([&](glm::dvec2 p) { return quad::bilinear(st, p); }, d), 1e-2);
    glm::dmat3 h = quad::homography(st);
    EXPECT_LT(quad::kinkAcrossDiagonalDeg([&](glm::dvec2 p) { return quad::projective(h, p); }, d), 1e-2);
  }
}
