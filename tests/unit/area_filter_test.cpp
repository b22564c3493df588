// tests/unit/area_filter_test.cpp — the exact area filter
// (common/core/area_filter.hpp) against areas worked out by hand.  No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "common/core/area_filter.hpp"

namespace {
using ts::Polygon2;

double weightSum(const std::vector<ts::TexelWeight>& w) {
  double s = 0;
  for (const auto& t : w) s += t.weight;
  return s;
}

// Claim: a pixel preimage that is exactly one texel square reads that texel alone.
TEST(AreaFilter, OneTexelSquareReadsOneTexel) {
  const auto w = ts::exactAreaWeights({{3, 5}, {4, 5}, {4, 6}, {3, 6}});
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].i, 3);
  EXPECT_EQ(w[0].j, 5);
  EXPECT_DOUBLE_EQ(w[0].weight, 1.0);
}

// Claim: a unit square shifted by (½, ¼) splits 3/8, 3/8, 1/8, 1/8 over four texels.
TEST(AreaFilter, ShiftedSquareSplitsByArea) {
  const auto w = ts::exactAreaWeights({{0.5, 0.25}, {1.5, 0.25}, {1.5, 1.25}, {0.5, 1.25}});
  ASSERT_EQ(w.size(), 4u);
  const double want[4] = {0.375, 0.375, 0.125, 0.125};  // (0,0) (1,0) (0,1) (1,1)
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(w[k].weight, want[k], 1e-15) << k;
}

// Claim: the diamond |u-2| + |v-2| ≤ 1 (area 2) gives each of its four texels 1/4,
// and the clip of a triangle against a box has the area worked out by hand.
TEST(AreaFilter, DiamondAndTriangle) {
  const auto w = ts::exactAreaWeights({{2, 1}, {3, 2}, {2, 3}, {1, 2}});
  ASSERT_EQ(w.size(), 4u);
  for (const auto& t : w) EXPECT_NEAR(t.weight, 0.25, 1e-15);
  // The triangle (0,0) (4,0) (0,4) clipped to [1,2]²: the whole square lies below u+v=4.
  EXPECT_NEAR(ts::signedArea(ts::clipToBox({{0, 0}, {4, 0}, {0, 4}}, 1, 1, 2, 2)), 1.0, 1e-15);
  // ... and to [1,3]²: the square minus the corner beyond u + v = 4, area 4 − 2 = 2.
  EXPECT_NEAR(ts::signedArea(ts::clipToBox({{0, 0}, {4, 0}, {0, 4}}, 1, 1, 3, 3)), 2.0, 1e-14);
}

// Claim: for random parallelograms the weights sum to 1, the texels read stay
// within the bounding box, and a constant texture averages to that constant.
TEST(AreaFilter, RandomQuadsAreConsistent) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-20, 20), size(0.01, 9);
  ts::Image flat(16, 16, {10, 20, 30, 255});
  for (int n = 0; n < 500; ++n) {
    const glm::dvec2 c(pos(rng), pos(rng));
    const double a = size(rng), b = size(rng), th = pos(rng);
    const glm::dvec2 e1(a * std::cos(th), a * std::sin(th)), e2(-b * std::sin(th), b * std::cos(th));
    const Polygon2 quad{c, c + e1, c + e1 + e2, c + e2};  // a parallelogram
    const auto w = ts::exactAreaWeights(quad);
    EXPECT_NEAR(weightSum(w), 1.0, 1e-9) << n;
    // Cost follows the footprint: never more texels than its bounding box holds.
    const double bu = std::fabs(e1.x) + std::fabs(e2.x) + 2, bv = std::fabs(e1.y) + std::fabs(e2.y) + 2;
    EXPECT_LE(double(w.size()), bu * bv) << n;
    const glm::dvec4 avg = ts::exactAreaAverage(flat, quad);
    EXPECT_NEAR(avg.r, 10, 1e-7);
    EXPECT_NEAR(avg.b, 30, 1e-7);
  }
}

// Claim: a degenerate (zero-area) preimage reads the texel under its corner.
TEST(AreaFilter, DegenerateIsPointSampling) {
  const auto w = ts::exactAreaWeights({{2.5, 7.5}, {2.5, 7.5}, {2.5, 7.5}, {2.5, 7.5}});
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].i, 2);
  EXPECT_EQ(w[0].j, 7);
}
}  // namespace

namespace {
// Claim: ts::AreaIntegral (Green's theorem along the outline) gives the same
// average as clipping every texel (exactAreaAverage), for small and large,
// thin and turned footprints, anywhere in the plane (GL_REPEAT), either
// orientation, and its cost is the outline's texel crossings: it does not
// grow with the texture's size.
TEST(AreaIntegral, AgreesWithClippingEveryTexel) {
  ts::Image tex(37, 23);
  std::mt19937 rng(11);
  for (auto& p : tex.pixels) p = uint8_t(rng() & 255);
  const ts::AreaIntegral fast(tex);
  std::uniform_real_distribution<double> pos(-300, 300), size(0.001, 60), ang(0, 6.3), thin(0.02, 1);
  double worst = 0;
  for (int n = 0; n < 400; ++n) {
    const glm::dvec2 c(pos(rng), pos(rng));
    const double a = size(rng), b = a * thin(rng), th = ang(rng), sk = thin(rng) - 0.5;
    const glm::dvec2 e1(a * std::cos(th), a * std::sin(th)), e2(b * (-std::sin(th) + sk), b * std::cos(th));
    Polygon2 quad{c, c + e1, c + e1 + e2 * 1.3, c + e2};  // a convex quadrilateral, not a parallelogram
    if (n % 2) std::reverse(quad.begin(), quad.end());    // clockwise too
    const glm::dvec4 want = ts::exactAreaAverage(tex, quad), got = fast.average(quad);
    for (int k = 0; k < 4; ++k) worst = std::max(worst, std::fabs(want[k] - got[k]));
  }
  EXPECT_LT(worst, 1e-6) << "largest difference, 8-bit units";
  // A constant texture averages to the constant; a texel square reads the texel.
  ts::Image flat(8, 8, {10, 20, 30, 255});
  EXPECT_NEAR(ts::AreaIntegral(flat).average({{-3.2, 5.1}, {40.7, 6.0}, {41.0, 19.5}, {-2.0, 18.0}}).g, 20, 1e-9);
  EXPECT_DOUBLE_EQ(fast.average({{3, 5}, {4, 5}, {4, 6}, {3, 6}}).r, tex.at(3, 5).r);
  EXPECT_DOUBLE_EQ(fast.average({{3 + 37, 5 - 46}, {4 + 37, 5 - 46}, {4 + 37, 6 - 46}, {3 + 37, 6 - 46}}).r,
                   tex.at(3, 5).r);
  // The cost: of a 10 x 3 texel rectangle only the vertical edges have dv, and
  // each crosses 3 grid lines: 4 pieces each.
  long pieces = 0;
  fast.average({{0.5, 0.5}, {10.5, 0.5}, {10.5, 3.5}, {0.5, 3.5}}, &pieces);
  EXPECT_EQ(pieces, 8);
  // The same outline on a texture 64 times larger costs the same.
  ts::Image big(37 * 8, 23 * 8);
  long piecesBig = 0;
  ts::AreaIntegral(big).average({{0.5, 0.5}, {10.5, 0.5}, {10.5, 3.5}, {0.5, 3.5}}, &piecesBig);
  EXPECT_EQ(piecesBig, pieces);
}

// Claim: the tables' layout (16 x 16 tiles of packed 24-bit sums and 8-bit
// texels, read two channels at a time, and the two-pass
// walk with prefetching that tables over 8 MB take) changes no result: on a
// 256 x 256 and a 4096 x 4096 texture of random texels, footprints from one
// texel to thousands, thin and turned, anywhere in the plane, agree with
// clipping every texel (exactAreaAverage) as closely as on the small texture
// above, and cost the same pieces on both sizes.
TEST(AreaIntegral, LargeTexturesGiveTheSameAverages) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0, 1), ang(0, 6.3);
  long piecesSmall = 0, piecesLarge = 0;
  for (int side : {256, 4096}) {
    SCOPED_TRACE("side " + std::to_string(side));
    ts::Image tex(side, side);
    for (auto& p : tex.pixels) p = uint8_t(rng() >> 24);
    const ts::AreaIntegral fast(tex);
    std::mt19937 shapes(17);  // the same footprints on both textures
    double worst = 0;
    for (int n = 0; n < 24; ++n) {
      const glm::dvec2 c(-2000 + 4000 * std::generate_canonical<double, 53>(shapes),
                         -2000 + 4000 * std::generate_canonical<double, 53>(shapes));
      const double a = 0.5 + 80 * std::generate_canonical<double, 53>(shapes),
                   b = a * (0.02 + std::generate_canonical<double, 53>(shapes)),
                   th = 6.3 * std::generate_canonical<double, 53>(shapes);
      const glm::dvec2 e1(a * std::cos(th), a * std::sin(th)), e2(-b * std::sin(th), b * std::cos(th));
      const Polygon2 quad{c, c + e1, c + e1 + e2 * 1.2, c + e2};
      long p = 0;
      const glm::dvec4 want = ts::exactAreaAverage(tex, quad), got = fast.average(quad, &p);
      (side == 256 ? piecesSmall : piecesLarge) += p;
      for (int k = 0; k < 4; ++k) worst = std::max(worst, std::fabs(want[k] - got[k]));
    }
    EXPECT_LT(worst, 1e-6) << "largest difference, 8-bit units";
  }
  EXPECT_EQ(piecesSmall, piecesLarge);
}

// Claim: an 8-bit texture's running sums are exact integers in 24 bits, so
// the widest image (ts::kMaxImageDimension texels of 255) sums exactly; the
// linear-light table (doubles) agrees with the 8-bit one on the same texels.
TEST(AreaIntegral, WidestRowAndTheTwoTables) {
  const int w = ts::kMaxImageDimension;
  const ts::AreaIntegral widest(ts::Image(w, 2, {255, 255, 255, 255}));
  EXPECT_DOUBLE_EQ(widest.average({{w - 800.25, 0.5}, {w + 0.75, 0.5}, {w + 0.75, 1.5}, {w - 800.25, 1.5}}).r, 255.0);
  ts::Image tex(64, 32);
  std::mt19937 rng(3);
  for (auto& p : tex.pixels) p = uint8_t(rng() & 255);
  std::vector<glm::dvec4> numbers;
  for (int j = 0; j < tex.height; ++j)
    for (int i = 0; i < tex.width; ++i) {
      const ts::Rgba c = tex.at(i, j);
      numbers.push_back({c.r, c.g, c.b, c.a});
    }
  const ts::AreaIntegral bytes(tex), reals(tex.width, tex.height, numbers);
  const Polygon2 quad{{-7.3, 3.1}, {90.2, 10.4}, {95.0, 44.9}, {-3.3, 30.0}};
  const glm::dvec4 a = bytes.average(quad), b = reals.average(quad);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(a[k], b[k], 1e-9);
  EXPECT_EQ(bytes.tableBytes(), size_t(5 * 16) * 32 * 16);     // 65 columns of sums: 5 tiles of 16 x 16, 16 bytes each
  EXPECT_EQ(reals.tableBytes(), size_t(5 * 4) * 16 * 8 * 32);  // doubles: tiles of 16 x 8, 32 bytes each
}
}  // namespace

// Claim: averageOfEdges, from edges shared by neighbouring polygons (a grid
// of quadrilaterals whose corners are a smooth, perspective-like map, as a
// picture's pixel preimages are) and each walked once in one direction,
// gives average()'s value to 1e-9 (8-bit units), on the 8-bit and the
// number tables, with the grid far from the origin (the edges' shifts of
// whole periods differ from the cells').  Control: an edge added with the
// wrong sign is off by far more.
TEST(AreaIntegral, SharedEdgesGiveTheAverage) {
  ts::Image tex(29, 17);
  std::mt19937 rng(5);
  for (auto& p : tex.pixels) p = uint8_t(rng() & 255);
  std::vector<glm::dvec4> numbers;
  for (int j = 0; j < tex.height; ++j)
    for (int i = 0; i < tex.width; ++i) numbers.push_back(glm::dvec4(tex.at(i, j).r / 255.0, 0.5, 0.25, 1.0));
  using Edge = ts::AreaIntegral::Edge;
  for (const ts::AreaIntegral& ai : {ts::AreaIntegral(tex), ts::AreaIntegral(tex.width, tex.height, numbers)}) {
    const int n = 12;
    auto corner = [](int i, int j) {  // a homography: cells from 1/3 texel to tens of texels
      const double q = 1.0 + 0.07 * j;
      return glm::dvec2((-350.0 + 9.0 * i + 2.0 * j) / (q * 0.02 + 0.01 * i),
                        (-410.0 + 31.0 * j * j / 4.0 + 3.0 * i) / q);
    };
    double worst = 0, control = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Polygon2 cell{corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1)};
        const Edge bottom = ai.edge(cell[0], cell[1]), right = ai.edge(cell[1], cell[2]),
                   top = ai.edge(corner(i, j + 1), corner(i + 1, j + 1)),
                   left = ai.edge(corner(i, j), corner(i, j + 1));
        const Edge* edges[4] = {&bottom, &right, &top, &left};
        const int signs[4] = {1, 1, -1, -1}, wrong[4] = {1, 1, 1, -1};
        const glm::dvec4 want = ai.average(cell), got = ai.averageOfEdges(cell, edges, signs),
                         off = ai.averageOfEdges(cell, edges, wrong);
        for (int k = 0; k < 4; ++k) {
          worst = std::max(worst, std::fabs(want[k] - got[k]));
          control = std::max(control, std::fabs(want[k] - off[k]));
        }
      }
    EXPECT_LT(worst, 1e-9);
    EXPECT_GT(control, 1e-3);
  }
}
