// Unit tests of the reference rasterizer (no GL): pixel-centre sampling, the
// top-left rule (triangles sharing edges cover every pixel exactly once),
// affine versus hyperbolic interpolation on a known triangle, and the
// viewport transform of a Frame's panel.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "common/core/textures.hpp"
#include "reference/raster.hpp"
#include "reference/reference.hpp"

namespace {
using ref::FillRule;
using ref::PixelRect;
using ref::ScreenVertex;

ScreenVertex sv(double x, double y, double a0 = 0, double a1 = 0) {
  ScreenVertex v;
  v.x = x, v.y = y;
  v.a[0] = a0, v.a[1] = a1;
  return v;
}

// Coverage counts of a list of triangles.
std::vector<int> cover(const std::vector<std::array<ScreenVertex, 3>>& tris, int w, int h, FillRule rule) {
  std::vector<int> n(size_t(w * h), 0);
  for (const auto& t : tris)
    ref::scanTriangle(t[0], t[1], t[2], 0, {0, 0, w, h}, rule,
                      [&](int x, int y, const double*) { ++n[size_t(y * w + x)]; });
  return n;
}

TEST(Raster, SamplesAtPixelCentres) {
  // A rectangle from x = 0.5 to 3.5 holds the centres 0.5, 1.5, 2.5: left in, right out.
  auto n = cover({{sv(0.5, 0.2), sv(3.5, 0.2), sv(3.5, 1.2)}, {sv(0.5, 0.2), sv(3.5, 1.2), sv(0.5, 1.2)}}, 6, 2,
                 FillRule::ImageTopLeft);
  EXPECT_EQ((std::vector<int>{1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0}), n);
  // Shifted by 0.1: centres 1.5, 2.5, 3.5.
  n = cover({{sv(0.6, 0.2), sv(3.6, 0.2), sv(3.6, 1.2)}, {sv(0.6, 0.2), sv(3.6, 1.2), sv(0.6, 1.2)}}, 6, 2,
            FillRule::ImageTopLeft);
  EXPECT_EQ((std::vector<int>{0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0}), n);
  // The attribute handed over is the value at the centre: a = x there.
  ref::scanTriangle(sv(0, 0, 0), sv(8, 0, 8), sv(0, 8, 0), 1, {0, 0, 8, 8}, FillRule::GLTopLeft,
                    [](int x, int, const double* a) { EXPECT_NEAR(a[0], x + 0.5, 1e-12); });
}

TEST(Raster, HorizontalEdgesThroughCentresFollowTheRule) {
  // Two triangles meet along y = 2.5 (image rows, y down), which runs
  // through the centres of row 2: `above` has it as its bottom edge in the
  // image, `below` as its top edge.
  std::vector<std::array<ScreenVertex, 3>> above{{sv(4, 0), sv(0, 2.5), sv(8, 2.5)}};
  std::vector<std::array<ScreenVertex, 3>> below{{sv(0, 2.5), sv(8, 2.5), sv(4, 5)}};
  auto row2 = [](const std::vector<int>& n) {
    int c = 0;
    for (int x = 0; x < 8; ++x) c += n[size_t(2 * 8 + x)];
    return c;
  };
  // ImageTopLeft (y down): the image-top edge is in — row 2 is `below`'s.
  EXPECT_EQ(row2(cover(above, 8, 6, FillRule::ImageTopLeft)), 0);
  EXPECT_EQ(row2(cover(below, 8, 6, FillRule::ImageTopLeft)), 8);
  // GLTopLeft (GL's window y up): the image-bottom edge is GL's top edge.
  EXPECT_EQ(row2(cover(above, 8, 6, FillRule::GLTopLeft)), 8);
  EXPECT_EQ(row2(cover(below, 8, 6, FillRule::GLTopLeft)), 0);
}

// Every pixel centre inside a mesh of triangles sharing edges is covered
// exactly once, centres exactly on shared edges included.
void expectExactlyOnce(const std::vector<std::array<ScreenVertex, 3>>& tris, int w, int h, FillRule rule,
                       PixelRect inner) {
  auto n = cover(tris, w, h, rule);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int c = n[size_t(y * w + x)];
      ASSERT_LE(c, 1) << "pixel " << x << "," << y << " drawn twice";
      if (x >= inner.x0 && x < inner.x1 && y >= inner.y0 && y < inner.y1) {
        ASSERT_EQ(c, 1) << "pixel " << x << "," << y << " missed";
      }
    }
}

TEST(Raster, TwoTrianglesSharingAnEdgeCoverEachPixelOnce) {
  for (FillRule rule : {FillRule::GLTopLeft, FillRule::ImageTopLeft}) {
    // A square on pixel centres split along either diagonal (the diagonal
    // passes through centres), and one off the centres.
    for (double o : {0.5, 0.0, 0.25}) {
      ScreenVertex a = sv(2 + o, 2 + o), b = sv(30 + o, 2 + o), c = sv(30 + o, 30 + o), d = sv(2 + o, 30 + o);
      expectExactlyOnce({{a, b, c}, {a, c, d}}, 34, 34, rule, {3, 3, 30, 30});
      expectExactlyOnce({{a, b, d}, {b, c, d}}, 34, 34, rule, {3, 3, 30, 30});
    }
  }
}

TEST(Raster, AFanAroundAPixelCentreAndARandomMeshCoverOnce) {
  for (FillRule rule : {FillRule::GLTopLeft, FillRule::ImageTopLeft}) {
    // Eight triangles around the centre of pixel (16, 16).
    std::vector<std::array<ScreenVertex, 3>> fan;
    ScreenVertex centre = sv(16.5, 16.5);
    std::vector<ScreenVertex> ring{sv(4.5, 4.5),   sv(16.5, 2.5),  sv(28.5, 4.5), sv(30.5, 16.5),
                                   sv(28.5, 28.5), sv(16.5, 30.5), sv(4.5, 28.5), sv(2.5, 16.5)};
    for (size_t i = 0; i < ring.size(); ++i) fan.push_back({centre, ring[i], ring[(i + 1) % ring.size()]});
    expectExactlyOnce(fan, 34, 34, rule, {7, 7, 26, 26});
    // A jittered grid, two triangles per cell, vertices on random
    // quarter-pixel positions (many centres exactly on edges).
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> j(-6, 6);
    const int n = 6;
    ScreenVertex g[n + 1][n + 1];
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x) {
        bool border = x == 0 || y == 0 || x == n || y == n;
        g[y][x] = sv(4 + 10 * x + (border ? 0 : j(rng) * 0.25), 4 + 10 * y + (border ? 0 : j(rng) * 0.25));
      }
    std::vector<std::array<ScreenVertex, 3>> mesh;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        if ((x + y) % 2) {
          mesh.push_back({g[y][x], g[y][x + 1], g[y + 1][x + 1]});
          mesh.push_back({g[y][x], g[y + 1][x + 1], g[y + 1][x]});
        } else {
          mesh.push_back({g[y][x], g[y][x + 1], g[y + 1][x]});
          mesh.push_back({g[y][x + 1], g[y + 1][x + 1], g[y + 1][x]});
        }
      }
    expectExactlyOnce(mesh, 70, 70, rule, {4, 4, 64, 64});
  }
}

TEST(Raster, AffineAndHyperbolicInterpolationOnAKnownTriangle) {
  // Screen positions with clip w = 1, 2, 4 and s = 0, 1, 0.5.
  const double X[3] = {2, 60, 10}, Y[3] = {3, 20, 55}, W[3] = {1, 2, 4}, S[3] = {0, 1, 0.5};
  ScreenVertex aff[3], hyp[3];
  for (int i = 0; i < 3; ++i) {
    aff[i] = sv(X[i], Y[i], S[i], 1.0);
    hyp[i] = sv(X[i], Y[i], S[i] / W[i], 1.0 / W[i]);
  }
  auto bary = [&](double x, double y, double l[3]) {
    double d = (Y[1] - Y[2]) * (X[0] - X[2]) + (X[2] - X[1]) * (Y[0] - Y[2]);
    l[0] = ((Y[1] - Y[2]) * (x - X[2]) + (X[2] - X[1]) * (y - Y[2])) / d;
    l[1] = ((Y[2] - Y[0]) * (x - X[2]) + (X[0] - X[2]) * (y - Y[2])) / d;
    l[2] = 1 - l[0] - l[1];
  };
  long n = 0;
  ref::scanTriangle(aff[0], aff[1], aff[2], 2, {0, 0, 64, 64}, FillRule::GLTopLeft, [&](int x, int y, const double* a) {
    double l[3];
    bary(x + 0.5, y + 0.5, l);
    EXPECT_NEAR(a[0], l[0] * S[0] + l[1] * S[1] + l[2] * S[2], 1e-9);  // screen-linear
    ++n;
  });
  EXPECT_GT(n, 1000);
  ref::scanTriangle(hyp[0], hyp[1], hyp[2], 2, {0, 0, 64, 64}, FillRule::GLTopLeft, [&](int x, int y, const double* a) {
    double l[3];
    bary(x + 0.5, y + 0.5, l);
    double num = 0, den = 0;
    for (int i = 0; i < 3; ++i) num += l[i] * S[i] / W[i], den += l[i] / W[i];
    EXPECT_NEAR(a[0] / a[1], num / den, 1e-9);  // perspective-correct: (s/w) / (1/w)
  });
  // Where the two differ: halfway (on screen) between the w = 1 and w = 4
  // vertices, affine gives 0.25 and hyperbolic (0 + 0.5/4) / (1 + 1/4) = 0.1.
  ScreenVertex m0 = sv(0, 0, 0, 1), m1 = sv(64, 0, 0.5 / 4, 1.0 / 4), m2 = sv(0, 64, 0, 1);
  ScreenVertex n0 = sv(0, 0, 0, 1), n1 = sv(64, 0, 0.5, 1), n2 = sv(0, 64, 0, 1);
  double hypMid = 0, affMid = 0;
  ref::scanTriangle(m0, m1, m2, 2, {31, 0, 32, 1}, FillRule::GLTopLeft,
                    [&](int, int, const double* a) { hypMid = a[0] / a[1]; });
  ref::scanTriangle(n0, n1, n2, 2, {31, 0, 32, 1}, FillRule::GLTopLeft,
                    [&](int, int, const double* a) { affMid = a[0]; });
  // Pixel 31's centre is x = 31.5, not exactly halfway: compare with the formulas there.
  double u = 31.5 / 64, v = 0.5 / 64;
  EXPECT_NEAR(affMid, u * 0.5, 1e-12);
  EXPECT_NEAR(hypMid, (u * 0.5 / 4) / ((1 - u - v) + u / 4 + v), 1e-12);
  EXPECT_GT(affMid - hypMid, 0.1);
}

TEST(Reference, ViewportFromTopLeftAndTexelCentres) {
  // A 100x80 frame, a panel at (10, 20) sized 32x40 from the top-left,
  // filled by a quad in NDC showing a 32x40... texel_index texture: each
  // pixel must take exactly the texel under its centre.
  ts::Frame f;
  f.width = 100, f.height = 80;
  int t = f.addTexture(ts::texelIndexTexture(64));
  ts::Panel p;
  p.id = "p";
  p.viewport = {10, 20, 32, 40};
  p.projection = glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f);
  ts::Batch b;
  b.texture = t;
  for (auto [x, y] : {std::pair{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}}) {
    ts::Vertex v;
    v.pos = {x, y, 0};
    v.tex = {x * 0.5f, y * 0.625f, 0, 1};  // 32 x 40 texels of 64: one texel per pixel
    b.vertices.push_back(v);
  }
  p.batches.push_back(b);
  f.panels.push_back(p);
  ref::Reference r(f);
  ts::Rgba clear = ref::toRgba({0, 0, 0, 1});
  for (int y = 0; y < 80; ++y)
    for (int x = 0; x < 100; ++x) {
      ts::Rgba c = r.image().at(x, y);
      if (!p.viewport.contains(x, y)) {
        ASSERT_EQ(c, clear) << x << "," << y;
        continue;
      }
      int i = 0, j = 0;
      ts::decodeTexelIndex(c, &i, &j);
      // Column x - 10; row from the panel's bottom (t = 0 at the bottom).
      ASSERT_EQ(i, x - 10) << x << "," << y;
      ASSERT_EQ(j, 20 + 40 - 1 - y) << x << "," << y;
    }
}

TEST(Reference, EdgeBandKeepsBothSidesAndClearColour) {
  ts::Frame f;
  f.width = f.height = 40;
  f.clearColor = {0, 0, 1, 1};
  ts::Panel p;
  p.id = "p";
  p.viewport = {0, 0, 40, 40};
  p.projection = glm::ortho(0.0f, 40.0f, 40.0f, 0.0f, -1.0f, 1.0f);
  ts::Batch b;
  for (auto [x, y] : {std::pair{10.f, 10.f}, {30.f, 10.f}, {20.f, 30.f}}) {
    ts::Vertex v;
    v.pos = {x, y, 0};
    v.color = {1, 0, 0, 1};
    b.vertices.push_back(v);
  }
  p.batches.push_back(b);
  f.panels.push_back(p);
  ref::Reference r(f);
  auto count = [&](int x, int y) {
    int n = 0;
    for (int i = r.head(x, y); i >= 0; i = r.candidate(i).next) ++n;
    return n;
  };
  EXPECT_EQ(count(20, 15), 1);  // well inside: the triangle only
  EXPECT_EQ(count(20, 10), 2);  // on the top edge: triangle or clear colour
  EXPECT_EQ(count(2, 2), 0);    // far outside: untouched (the clear colour)
  // EdgePolicy::Exempt: the band is not checked at all.
  ref::RenderOptions o;
  o.edges = ref::EdgePolicy::Exempt;
  ref::Reference e(f, o);
  bool exempt = false;
  for (int i = e.head(20, 10); i >= 0; i = e.candidate(i).next)
    exempt |= e.candidate(i).kind == ref::Candidate::Kind::Exempt && e.candidate(i).why == ref::Exempt::Edge;
  EXPECT_TRUE(exempt);
}
}  // namespace
