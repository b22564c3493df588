// tests/unit/textures_probe_test.cpp — the procedural textures, the book's
// mip chain (common/core/textures.cpp) and the probe helpers (common/core/probe.cpp).
// No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/parallel.hpp"
#include "common/core/probe.hpp"
#include "common/core/textures.hpp"

namespace {
const ts::Rgba kA{32, 32, 32, 255}, kB{224, 224, 224, 255};  // checkerboard()'s defaults

// Claim: level k+1 texel (i, j) is the mean of level k's texels in columns
// 2i..2i+1 and rows 2j..2j+1, rounded half up, in every channel (alpha too).
TEST(MipChain, LevelOneIsTheRoundedMeanOfEach2x2Block) {
  std::mt19937 rng(7);
  ts::Image l0(16, 8);
  for (auto& p : l0.pixels) p = uint8_t(rng());
  std::vector<ts::Image> chain = ts::buildMipChain(l0);
  ASSERT_GE(chain.size(), 2u);
  const ts::Image& l1 = chain[1];
  ASSERT_EQ(l1.width, 8);
  ASSERT_EQ(l1.height, 4);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 8; ++i)
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) sum += l0.pixels[((2 * j + dy) * 16 + 2 * i + dx) * 4 + c];
        int want = int(std::floor(sum / 4.0 + 0.5));
        EXPECT_EQ(l1.pixels[(j * 8 + i) * 4 + c], want) << "texel " << i << "," << j << " channel " << c;
      }
  // Rounding: a block 0,0,0,2 has mean 0.5 -> 1; 0,0,0,1 has mean 0.25 -> 0.
  ts::Image two(2, 2, {0, 0, 0, 0});
  two.set(1, 1, {2, 1, 0, 0});
  EXPECT_EQ(ts::buildMipChain(two)[1].at(0, 0), (ts::Rgba{1, 0, 0, 0}));
}

// Claim: a 2^k x 2^k level 0 gives k+1 levels halving to 1x1; a non-square
// one halves each side until 1 (clamped), so log2(max side)+1 levels.
TEST(MipChain, ChainLength) {
  for (int n : {1, 2, 8, 64, 256}) {
    std::vector<ts::Image> chain = ts::buildMipChain(ts::Image(n, n));
    ASSERT_EQ(int(chain.size()), int(std::lround(std::log2(n))) + 1) << n;
    for (size_t k = 0; k < chain.size(); ++k) EXPECT_EQ(chain[k].width, n >> k);
  }
  std::vector<ts::Image> rect = ts::buildMipChain(ts::Image(8, 2));
  ASSERT_EQ(rect.size(), 4u);
  EXPECT_EQ(rect[1].width, 4);
  EXPECT_EQ(rect[1].height, 1);
  EXPECT_EQ(rect[3].width, 1);
  EXPECT_EQ(rect[3].height, 1);
}

// Claim: the chain costs about one third more memory (Buss VI.1.3):
// sum 4^-k for k = 1..8 = (1 - 4^-8)/3.
TEST(MipChain, OverheadIsAboutOneThird) {
  double o = ts::mipChainOverhead(ts::buildMipChain(ts::Image(256, 256)));
  EXPECT_NEAR(o, 1.0 / 3.0, 0.005 / 3.0);
  EXPECT_NEAR(o, (1.0 - std::pow(4.0, -8)) / 3.0, 1e-12);
  EXPECT_EQ(ts::mipChainOverhead({}), 0.0);
}

// Claim: averaging in linear light differs from averaging sRGB values: black
// and white average to 128 as values but to sRGB(0.5) = 188 in linear light.
TEST(MipChain, LinearLightAverage) {
  ts::Image bw(2, 2, {0, 0, 0, 255});
  bw.set(1, 0, {255, 255, 255, 255});
  bw.set(0, 1, {255, 255, 255, 255});
  EXPECT_EQ(ts::buildMipChain(bw, false)[1].at(0, 0), (ts::Rgba{128, 128, 128, 255}));
  EXPECT_EQ(ts::buildMipChain(bw, true)[1].at(0, 0), (ts::Rgba{188, 188, 188, 255}));
}

// Claim: checkerboard(256, 8) has 32-texel squares, texel (0,0) (s=t=0) is
// colour a, square (i, j) is a iff i+j is even, image row j is t — and
// checkerAt at every texel centre agrees with the image.
TEST(Checkerboard, LayoutMatchesCheckerAt) {
  ts::TextureDesc t = ts::checkerboard(256, 8);
  ASSERT_TRUE(t.image);
  const ts::Image& img = *t.image;
  ASSERT_EQ(img.width, 256);
  ASSERT_EQ(img.height, 256);
  EXPECT_EQ(img.at(0, 0), kA);
  EXPECT_EQ(img.at(31, 31), kA);
  EXPECT_EQ(img.at(32, 0), kB);
  EXPECT_EQ(img.at(0, 32), kB);
  EXPECT_EQ(img.at(32, 32), kA);
  EXPECT_EQ(img.at(255, 0), kB);  // square (7, 0): odd
  for (int j = 0; j < 256; ++j)
    for (int i = 0; i < 256; ++i) {
      ts::Rgba want = ((i / 32 + j / 32) % 2 == 0) ? kA : kB;
      ASSERT_EQ(img.at(i, j), want) << i << "," << j;
      ASSERT_EQ(ts::checkerAt(256, 8, kA, kB, (i + 0.5) / 256, (j + 0.5) / 256), want) << i << "," << j;
    }
  EXPECT_EQ(t.name, "checkerboard");
  EXPECT_THROW(ts::checkerboard(0, 1), ts::Error);
  EXPECT_THROW(ts::checkerboard(16, 17), ts::Error);
}

// Claim: checkerAt wraps like GL_REPEAT (s and s+1, s-1 give the same colour)
// and switches colour exactly at the check edges.
TEST(Checkerboard, CheckerAtWrapsAndSwitchesAtEdges) {
  for (double s : {0.01, 0.3, 0.77})
    for (double t : {0.02, 0.5, 0.9}) {
      ts::Rgba c = ts::checkerAt(256, 8, kA, kB, s, t);
      EXPECT_EQ(ts::checkerAt(256, 8, kA, kB, s + 1, t - 1), c);
      EXPECT_EQ(ts::checkerAt(256, 8, kA, kB, s - 3, t + 2), c);
    }
  EXPECT_EQ(ts::checkerAt(256, 8, kA, kB, 0.125 - 1e-6, 0.01), kA);
  EXPECT_EQ(ts::checkerAt(256, 8, kA, kB, 0.125 + 1e-6, 0.01), kB);
  EXPECT_EQ(ts::checkerAt(256, 8, kA, kB, 1.0, 0.01), kA);  // s = 1 wraps to texel 0
}

// Claim: every texel of texelIndexTexture(2048) decodes to its own (i, j),
// and the texture is sampled GL_NEAREST (the point of it).
TEST(TexelIndex, RoundTrip) {
  ts::TextureDesc t = ts::texelIndexTexture(2048);
  ASSERT_TRUE(t.image);
  EXPECT_EQ(t.minFilter, GLenum(GL_NEAREST));
  EXPECT_EQ(t.magFilter, GLenum(GL_NEAREST));
  long bad = 0;
  for (int j = 0; j < 2048; ++j)
    for (int i = 0; i < 2048; ++i) {
      int di = -1, dj = -1;
      ts::decodeTexelIndex(t.image->at(i, j), &di, &dj);
      bad += di != i || dj != j;
    }
  EXPECT_EQ(bad, 0);
  int i = 0, j = 0;
  ts::decodeTexelIndex({255, 255, 0xff, 255}, &i, &j);  // the 12-bit maximum
  EXPECT_EQ(i, 4095);
  EXPECT_EQ(j, 4095);
  EXPECT_THROW(ts::texelIndexTexture(4097), ts::Error);
}

// Claim: a size up to 2048 is made once per process (the same picture for
// every pass that asks), 4096 afresh each time, and either decodes right.
TEST(TexelIndex, KeptUpTo2048) {
  EXPECT_EQ(ts::texelIndexTexture(2048).image, ts::texelIndexTexture(2048).image);
  EXPECT_EQ(ts::texelIndexTexture(64).image, ts::texelIndexTexture(64).image);
  const ts::TextureDesc a = ts::texelIndexTexture(4096), b = ts::texelIndexTexture(4096);
  EXPECT_NE(a.image, b.image);
  int i = -1, j = -1;
  ts::decodeTexelIndex(a.image->at(4095, 2049), &i, &j);
  EXPECT_EQ(i, 4095);
  EXPECT_EQ(j, 2049);
}

// Claim: evenAndOdd calls f once for each index, whichever thread, and an
// exception from either half reaches the caller after both halves stopped.
TEST(EvenAndOdd, EachIndexOnceAndExceptionsReachTheCaller) {
  for (int n : {0, 1, 2, 7, 1000}) {
    std::vector<int> calls(size_t(n), 0);
    ts::evenAndOdd(n, [&](int y) { ++calls[size_t(y)]; });
    EXPECT_EQ(std::count(calls.begin(), calls.end(), 1), n) << n;
  }
  for (int bad : {4, 5}) {  // thrown on the caller's half, then on the other's
    std::atomic<int> done{0};
    EXPECT_THROW(ts::evenAndOdd(10,
                                [&](int y) {
                                  if (y == bad) throw ts::Error("row " + std::to_string(y));
                                  ++done;
                                }),
                 ts::Error);
    EXPECT_LE(done.load(), 9);
  }
}

// Claim: probe::fit recovers the coefficients of an exact quadratic (and of a
// plane with quadratic = false) with zero residual; a plane fitted to curved
// data leaves a residual.
TEST(Probe, FitRecoversAKnownQuadratic) {
  const double c[6] = {1.5, -2.0, 0.75, 3.0, -1.25, 0.5};
  std::vector<ts::probe::Sample> s, plane;
  for (int y = -5; y <= 5; ++y)
    for (int x = -5; x <= 5; ++x) {
      double X = x * 0.1, Y = y * 0.13;
      s.push_back({X, Y, c[0] + c[1] * X + c[2] * Y + c[3] * X * X + c[4] * X * Y + c[5] * Y * Y});
      plane.push_back({X, Y, c[0] + c[1] * X + c[2] * Y});
    }
  ts::probe::Fit f = ts::probe::fit(s, true);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(f.c[size_t(k)], c[k], 1e-9) << "c" << k;
  EXPECT_NEAR(f.rms, 0.0, 1e-9);
  EXPECT_EQ(f.samples, 121);
  EXPECT_NEAR(f.dx(0.2, 0.3), c[1] + 2 * c[3] * 0.2 + c[4] * 0.3, 1e-9);
  EXPECT_NEAR(f.dy(0.2, 0.3), c[2] + c[4] * 0.2 + 2 * c[5] * 0.3, 1e-9);
  ts::probe::Fit p = ts::probe::fit(plane, false);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.c[size_t(k)], c[k], 1e-9);
  EXPECT_EQ(p.c[3], 0.0);
  EXPECT_GT(ts::probe::fit(s, false).rms, 0.01);
}

// Claim: tolerance(bits) is one step of a bits-wide channel in 8-bit units,
// rounded up: 8 bits -> 1, 5 bits -> ceil(255/31) = 9, 1 bit -> 255.
TEST(Probe, Tolerance) {
  EXPECT_EQ(ts::probe::tolerance(8), 1);
  EXPECT_EQ(ts::probe::tolerance(5), int(std::ceil(255.0 / 31.0)));
  EXPECT_EQ(ts::probe::tolerance(5), 9);
  EXPECT_EQ(ts::probe::tolerance(4, 2.0), 34);
  EXPECT_EQ(ts::probe::tolerance(1), 255);
}

// Claim: rect/images/countDiffering count exactly the pixels outside the
// tolerance, and report the first one.
TEST(Probe, RectAndImageComparison) {
  ts::Image a(10, 10, {100, 100, 100, 255});
  a.set(3, 4, {102, 100, 100, 255});
  a.set(5, 6, {101, 100, 100, 255});
  ts::probe::Result r = ts::probe::rect(a, {2, 2, 6, 6}, {100, 100, 100, 255}, 1);
  EXPECT_EQ(r.checked, 36);
  EXPECT_EQ(r.failed, 1);
  EXPECT_EQ(r.firstX, 3);
  EXPECT_EQ(r.firstY, 4);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(ts::probe::rect(a, {-5, -5, 8, 8}, {100, 100, 100, 255}, 1).ok());  // clipped, (0..2)^2
  EXPECT_EQ(ts::probe::rect(a, {-5, -5, 8, 8}, {100, 100, 100, 255}, 1).checked, 9);
  EXPECT_FALSE(ts::probe::Result().ok());  // nothing checked is not a pass
  ts::Image b(10, 10, {100, 100, 100, 255});
  EXPECT_EQ(ts::probe::countDiffering(a, b, 0), 2);
  EXPECT_EQ(ts::probe::countDiffering(a, b, 1), 1);
  EXPECT_EQ(ts::probe::images(a, b, 2).failed, 0);
  EXPECT_FALSE(ts::probe::images(a, ts::Image(9, 10), 255).ok());
}
}  // namespace
