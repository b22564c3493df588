// tests/unit/zoo_test.cpp — the filter zoo's mathematics
// (demos/filter_zoo/filter_zoo_math.hpp) without GL: every closed form the zoo draws
// against a computation of this test's own, exactly, and the orderings of
// the CPU methods against the exact area integral with their margins.
// The GL methods' numbers are the figure test's (demos/filter_zoo/filter_zoo_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>

#include "demos/filter_zoo/filter_zoo_math.hpp"

namespace {
using namespace zoo;

// ---------------------------------------------------------------- 1. magnification
// Claim: with GL_NEAREST and texel floor((x + 1/2) 256 / W), 256 texels over
// 300 pixels give 44 texels two pixels and 212 one; over 512 every texel two;
// over 200, 56 texels none.  Recounted here from the pixel intervals each
// texel's span [i, i + 1) * W / 256 holds (pixel centres x + 1/2 inside it).
TEST(ZooMagnification, TexelCounts) {
  for (int W : {300, 512, 200, 256, 257, 100}) {
    SCOPED_TRACE(W);
    std::vector<int> texel;
    for (int x = 0; x < W; ++x) texel.push_back(nearestTexel(x, W));
    const TexelCounts c = countTexels(texel);
    // Independently: texel i gets the pixel centres in [i W / 256, (i + 1) W / 256).
    int want[4] = {0, 0, 0, 0};  // unseen, once, twice, more
    for (int i = 0; i < 256; ++i) {
      // centres x + 1/2 with i W <= (x + 1/2) 256 < (i + 1) W, in integers: 2 i W <= (2x + 1) 256 < 2 (i + 1) W
      int n = 0;
      for (int x = 0; x < W; ++x) n += 2L * i * W <= (2L * x + 1) * 256 && (2L * x + 1) * 256 < 2L * (i + 1) * W;
      ++want[std::min(n, 3)];
    }
    EXPECT_EQ(c.unseen, want[0]);
    EXPECT_EQ(c.once, want[1]);
    EXPECT_EQ(c.twice, want[2]);
    EXPECT_EQ(c.more, want[3]);
  }
  std::vector<int> t300, t512, t200;
  for (int x = 0; x < 300; ++x) t300.push_back(nearestTexel(x, 300));
  for (int x = 0; x < 512; ++x) t512.push_back(nearestTexel(x, 512));
  for (int x = 0; x < 200; ++x) t200.push_back(nearestTexel(x, 200));
  EXPECT_EQ(countTexels(t300).twice, 44);
  EXPECT_EQ(countTexels(t300).once, 212);
  EXPECT_EQ(countTexels(t512).twice, 256);
  EXPECT_EQ(countTexels(t200).unseen, 56);
  EXPECT_EQ(countTexels(t200).once, 200);
}

// ---------------------------------------------------------------- 2, 3. memory and levels
// Claim: a mip chain of 256^2 costs 1 + (1 - 4^-8)/3 = 4/3 (0.3333 overhead),
// a ripmap (2 - 2^-8)^2 = 3.98439 (overhead 2.98439, seed 001's "3x").
TEST(ZooMemory, MipAndRipmap) {
  EXPECT_NEAR(mipMemoryRatio(256, 256), 1.0 + (1.0 - std::pow(4.0, -8)) / 3.0, 1e-15);
  EXPECT_NEAR(mipMemoryRatio(256, 256) - 1, 0.3333, 5e-5);
  EXPECT_NEAR(ripmapMemoryRatio(256, 256), std::pow(2.0 - std::pow(2.0, -8), 2.0), 1e-12);
  EXPECT_NEAR(ripmapMemoryRatio(256, 256), 3.98439, 5e-6);
  EXPECT_NEAR(ripmapMemoryRatio(256, 256) - 1, 2.98439, 5e-6);
  // The built ripmap holds that many texels, and its levels are W/2^i x H/2^j.
  ts::Image base(256, 256);
  const Ripmap r(base);
  EXPECT_EQ(r.nu, 9);
  EXPECT_EQ(r.nv, 9);
  EXPECT_EQ(r.at(3, 5).w, 32);
  EXPECT_EQ(r.at(3, 5).h, 8);
  EXPECT_NEAR(double(r.texels()) / (256.0 * 256.0), ripmapMemoryRatio(256, 256), 1e-15);
  // Non-square: 32 x 64.
  EXPECT_NEAR(ripmapMemoryRatio(32, 64), (63.0 / 32) * (127.0 / 64), 1e-15);
}

// Claim: a SAT of 8-bit texels needs ceil(log2(255 W H + 1)) bits a channel:
// 24 at 256^2 (3x an 8-bit texture; seed 001 says ">= 16"), 26 at 512^2, 28
// at 1024^2; 32-bit float sums are exact while 255 W H <= 2^24, which 512^2
// passes.
TEST(ZooMemory, SatBitsAndFloats) {
  for (long long s : {256LL, 512LL, 1024LL, 100LL, 4096LL}) {
    SCOPED_TRACE(s);
    EXPECT_EQ(satBits(s, s), int(std::ceil(std::log2(255.0 * double(s) * double(s) + 1))));
  }
  EXPECT_EQ(satBits(256, 256), 24);
  EXPECT_EQ(satBits(512, 512), 26);
  EXPECT_EQ(satBits(1024, 1024), 28);
  EXPECT_EQ(satBits(256, 256) / 8, 3);
  EXPECT_TRUE(floatHoldsSat(256, 256));
  EXPECT_FALSE(floatHoldsSat(512, 512));
  EXPECT_LT(255.0 * 256 * 256, std::ldexp(1.0, 24));
  EXPECT_GT(255.0 * 512 * 512, std::ldexp(1.0, 24));
  // Summed in floats (rows, then columns, as a GPU would): every entry exact
  // at 256^2 of the worst texture (all 255), the first wrong one at 257^2, a
  // quarter wrong at 512^2.
  const ts::Image white(1, 1, {255, 255, 255, 255});
  EXPECT_EQ(floatSatMismatches(white, 256), 0);
  EXPECT_EQ(floatSatMismatches(white, 257), 1);
  EXPECT_GT(floatSatMismatches(white, 512), 512 * 512 / 5);
}

// Claim: GL gives a 32 x 64 texture 7 levels (64, 32, ..., 1 on the long
// side, 1 x 1 last); seed 001's "until either dimension is one texel" gives 6.
TEST(ZooLevels, NonSquare) {
  EXPECT_EQ(glLevelCount(32, 64), 7);
  EXPECT_EQ(seedLevelCount(32, 64), 6);
  // GL's count is floor(log2(max side)) + 1, the seed's floor(log2(min side)) + 1.
  for (auto [w, h] : std::vector<std::pair<int, int>>{{256, 256}, {1, 8}, {37, 23}, {512, 4}}) {
    EXPECT_EQ(glLevelCount(w, h), int(std::floor(std::log2(std::max(w, h)))) + 1) << w << "x" << h;
    EXPECT_EQ(seedLevelCount(w, h), int(std::floor(std::log2(std::min(w, h)))) + 1) << w << "x" << h;
  }
  EXPECT_EQ(int(ts::buildMipChain(ts::Image(32, 64)).size()), 7);  // the chain the suite uploads
}

// ---------------------------------------------------------------- 4, 5. footprints
// Claim: log2(rho_edge / rho_max) = 1/2 for a footprint at 45 degrees, 0
// along the axes, between for the angles between.
TEST(ZooFootprints, TheTwoLodForms) {
  EXPECT_NEAR(lodFormGap(footprint(1, 1, 45)), 0.5, 1e-12);
  EXPECT_NEAR(lodFormGap(footprint(5, 5, 45)), 0.5, 1e-12);
  EXPECT_NEAR(lodFormGap(footprint(3, 3, 0)), 0.0, 1e-12);
  EXPECT_NEAR(lodFormGap(footprint(3, 3, 90)), 0.0, 1e-12);
  // A square footprint at angle a: rho_edge = 1, rho_max = max(|cos a|, |sin a|).
  for (double a = 0; a <= 90; a += 7.5)
    EXPECT_NEAR(lodFormGap(footprint(1, 1, a)), -std::log2(std::max(std::cos(a * kPi / 180), std::sin(a * kPi / 180))),
                1e-12)
        << a;
}

// Claim: SAT's box over the true footprint, (|u_x| + |u_y|)(|v_x| + |v_y|) /
// |u_x v_y - u_y v_x|, is 1 axis-aligned and 5.0625 for 8:1 at 45 degrees.
TEST(ZooFootprints, SatBoxRatio) {
  EXPECT_NEAR(satBoxRatio(footprint(8, 1, 0)), 1.0, 1e-12);
  EXPECT_NEAR(satBoxRatio(footprint(8, 1, 90)), 1.0, 1e-12);
  EXPECT_NEAR(satBoxRatio(footprint(8, 1, 45)), 81.0 / 16.0, 1e-12);
  EXPECT_NEAR(satBoxRatio(footprint(8, 1, 45)), 5.0625, 1e-12);
  // By hand at 45: both sides (8 + 1)/sqrt 2, area 8: (81/2)/8.
  EXPECT_NEAR(satBoxRatio(footprint(2, 2, 45)), 2.0, 1e-12);  // a square at 45: its box is twice it
}

// ---------------------------------------------------------------- the structures
// A random texture for exact sums.
ts::Image noise(int w, int h, unsigned seed) {
  ts::Image img(w, h);
  std::mt19937 rng(seed);
  for (auto& p : img.pixels) p = uint8_t(rng() & 255);
  return img;
}
// The mean of texels [i0, i1) x [j0, j1), wrapped.
glm::dvec4 bruteMean(const ts::Image& img, long i0, long j0, long i1, long j1) {
  glm::dvec4 s(0.0);
  for (long j = j0; j < j1; ++j)
    for (long i = i0; i < i1; ++i) {
      const ts::Rgba c = img.at(int(((i % img.width) + img.width) % img.width),
                                int(((j % img.height) + img.height) % img.height));
      s += glm::dvec4(c.r, c.g, c.b, c.a);
    }
  return s / double((i1 - i0) * (j1 - j0));
}

// Claim: the SAT's average over a box equals the texels' mean, for boxes on
// the texel grid anywhere (wrapping), and for any box the area-weighted mean
// (= the exact area integral of the box), with 16 table reads.
TEST(ZooStructures, SatAveragesBoxesExactly) {
  const ts::Image img = noise(16, 8, 3);
  const Sat s(img);
  const ts::AreaIntegral exact(img);
  long reads = 0;
  for (auto b : std::vector<std::array<long, 4>>{{0, 0, 16, 8}, {3, 2, 9, 7}, {-5, -3, 20, 11}, {14, 6, 18, 9}}) {
    reads = 0;
    const glm::dvec4 got = s.boxAverage(double(b[0]), double(b[1]), double(b[2]), double(b[3]), &reads);
    const glm::dvec4 want = bruteMean(img, b[0], b[1], b[2], b[3]);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1e-9);
    EXPECT_EQ(reads, 16);
  }
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> pos(-40, 40), size(0.1, 30);
  for (int n = 0; n < 200; ++n) {
    const double u0 = pos(rng), v0 = pos(rng), u1 = u0 + size(rng), v1 = v0 + size(rng);
    const glm::dvec4 got = s.boxAverage(u0, v0, u1, v1, nullptr);
    const glm::dvec4 want = exact.average({{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}});
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1e-7) << n;
  }
}

// Claim: the ripmap lookup reads 4 levels x 4 texels, picks i from
// log2 max(|u_x|, |u_y|) and j from log2 max(|v_x|, |v_y|), and for whole
// levels is the bilinear lookup of level (i, j), whose texels are the box
// means of 2^i x 2^j texels (within the 8-bit rounding of each halving).
TEST(ZooStructures, Ripmap) {
  const ts::Image img = noise(64, 64, 9);
  const Ripmap r(img);
  Jacobian j;
  j.dudx = 8, j.dvdy = 2;  // axis-aligned: i = 3, j = 1
  EXPECT_NEAR(ripmapLevels(j, 0).x, 3.0, 1e-12);
  EXPECT_NEAR(ripmapLevels(j, 0).y, 1.0, 1e-12);
  EXPECT_NEAR(ripmapLevels(j, 1).x, 4.0, 1e-12);  // the bias adds to both
  long reads = 0;
  const glm::dvec4 got = ripmap(r, 20.0, 13.0, j, 0, &reads);
  EXPECT_EQ(reads, 4);  // whole levels: one level, 4 texels
  const glm::dvec4 want = bilinear(r.at(3, 1), 20.0 / 8, 13.0 / 2, nullptr);
  for (int c = 0; c < 4; ++c) EXPECT_DOUBLE_EQ(got[c], want[c]);
  j.dudx = 6, j.dvdy = 3;  // fractional both ways: 16 reads
  reads = 0;
  ripmap(r, 20.0, 13.0, j, 0, &reads);
  EXPECT_EQ(reads, 16);
  // Level (2, 1): each texel the mean of 4 x 2 texels of level 0, within rounding.
  for (int jj = 0; jj < r.at(2, 1).h; jj += 5)
    for (int i = 0; i < r.at(2, 1).w; i += 3) {
      const glm::dvec4 m = bruteMean(img, 4 * i, 2 * jj, 4 * i + 4, 2 * jj + 2);
      EXPECT_NEAR(r.at(2, 1).at(i, jj).r, m.r, 1.5) << i << "," << jj;
    }
}

// Claim: the probe line takes N = min(ceil(P_max/P_min), 16) trilinear probes
// at lambda = log2(P_max / N) spaced along the major axis, 8N texels.
TEST(ZooStructures, ProbeLine) {
  const ProbeLine p = probeLine(footprint(8, 1, 30), 0);
  EXPECT_EQ(p.n, 8);
  EXPECT_NEAR(p.lambda, 0.0, 1e-12);
  EXPECT_NEAR(glm::length(p.axis), 8.0, 1e-12);
  // The probes are 1 apart along the axis, centred on the pixel.
  EXPECT_NEAR(glm::length(p.at({0, 0}, 1) - p.at({0, 0}, 0)), 1.0, 1e-12);
  EXPECT_NEAR(glm::length(p.at({0, 0}, 0) + p.at({0, 0}, 7)), 0.0, 1e-12);
  const ProbeLine q = probeLine(footprint(12, 5, 0), 0);
  EXPECT_EQ(q.n, 3);  // ceil(2.4)
  EXPECT_NEAR(q.lambda, std::log2(12.0 / 3), 1e-12);
  const ProbeLine r = probeLine(footprint(100, 2, 10), 0.5);
  EXPECT_EQ(r.n, 16);  // ceil(50) clamped at 16
  EXPECT_NEAR(r.lambda, std::log2(100.0 / 16) + 0.5, 1e-12);
  // Reads: 8 per probe between levels.
  const ts::Image img = noise(64, 64, 1);
  std::vector<Level> chain;
  for (const ts::Image& l : ts::buildMipChain(img)) chain.emplace_back(l);
  long reads = 0;
  probes(chain, 30, 30, footprint(13, 5, 0), 0, &reads);  // N = 3 at lambda log2(13/3) = 2.12: two levels each
  EXPECT_EQ(reads, 3 * 8);
}

// Claim: EWA (common/core/ewa.hpp, shared with the parallax demo) has the
// corrected F = (Ux Vy - Uy Vx)^2, reads the texels inside its ellipse, and
// averages a constant texture to the constant.
TEST(ZooStructures, EwaShared) {
  const ts::ewa::Ellipse e = ts::ewa::ellipse(1.0, 2.0, 3.0, 1.0, false);
  EXPECT_DOUBLE_EQ(e.F, 25.0);  // (1*1 - 3*2)^2; the seed's (1*1 + 3*2)^2 would be 49
  std::vector<Level> chain;
  for (const ts::Image& l : ts::buildMipChain(ts::Image(64, 64, {40, 80, 120, 255}))) chain.emplace_back(l);
  long reads = 0;
  const glm::dvec4 c = ewa(chain, 10.3, 20.7, footprint(6, 1.5, 20), 0, &reads);
  EXPECT_NEAR(c.g, 80.0, 1e-9);
  EXPECT_GT(reads, 4);
  // Unit footprint (a texel a pixel): level 0, the reconstructed ellipse of
  // radius sqrt 2 around the centre of texel (10, 20): the texels whose
  // centres lie within it, 9 here (the 3 x 3 around it: corners at sqrt 2).
  reads = 0;
  ewa(chain, 10.5, 20.5, footprint(1, 1, 0), 0, &reads);
  EXPECT_EQ(reads, 9);
}

// ---------------------------------------------------------------- views and the exact reference
// Claim: the view's Jacobian is the derivative of its homography (checked by
// central differences), the slanted plane's LOD is rotation-invariant in
// GL's form, and the preimage of a pixel is the homography of its corners.
TEST(ZooViews, HomographyAndJacobian) {
  for (double az : {0.0, 22.5, 45.0}) {
    const View v = slantView(384, 192, az);
    for (auto p : std::vector<glm::dvec2>{{100.5, 40.5}, {200.5, 120.5}, {350.5, 20.5}}) {
      const Jacobian j = v.jacobian(p.x, p.y);
      const double h = 1e-4;
      const glm::dvec2 dx = (v.uv(p.x + h, p.y) - v.uv(p.x - h, p.y)) / (2 * h);
      const glm::dvec2 dy = (v.uv(p.x, p.y + h) - v.uv(p.x, p.y - h)) / (2 * h);
      EXPECT_NEAR(j.dudx, dx.x, 1e-5 * (1 + std::abs(dx.x)));
      EXPECT_NEAR(j.dvdx, dx.y, 1e-5 * (1 + std::abs(dx.y)));
      EXPECT_NEAR(j.dudy, dy.x, 1e-5 * (1 + std::abs(dy.x)));
      EXPECT_NEAR(j.dvdy, dy.y, 1e-5 * (1 + std::abs(dy.y)));
      // Turning the texture does not change rho (GL's form) nor the preimage's area.
      const View v0 = slantView(384, 192, 0);
      EXPECT_NEAR(ts::lod::rhoExact(j), ts::lod::rhoExact(v0.jacobian(p.x, p.y)), 1e-9 * ts::lod::rhoExact(j));
    }
    // The same plane as the mipmap demo's: texel (u, v) / 256 turned back is (s, t) of ts::slant.
    const ts::slant::Camera cam = ts::slant::slantCamera(384, 192);
    glm::dvec2 ab;
    ASSERT_TRUE(ts::slant::planeAt(cam, ts::slant::groundPlane(), 150.5, 50.5, &ab, nullptr));
    const glm::dvec2 uv = v.uv(150.5, 50.5) / double(kTexels);
    const double a = az * kPi / 180;
    EXPECT_NEAR(std::cos(a) * uv.x + std::sin(a) * uv.y, ab.x, 1e-9);
    EXPECT_NEAR(-std::sin(a) * uv.x + std::cos(a) * uv.y, ab.y, 1e-9);
  }
}

const ts::Image& checker() {
  static const ts::Image img = *ts::checkerboard(kTexels, 8).image;
  return img;
}

// Claim: the exact reference per pixel of the slanted plane at 0, 22.5 and
// 45 degrees is the area average over the pixel's preimage: ts::AreaIntegral
// (the picture's) equals clipping the preimage against every texel square
// (ts::exactAreaAverage) at pixels across the plane, near and far.
TEST(ZooViews, ExactReferencePerPixel) {
  const ts::AreaIntegral fast(checker());
  for (double az : {0.0, 22.5, 45.0}) {
    const View v = slantView(384, 192, az);
    double worst = 0;
    int checked = 0;
    for (int row = 30; row < 192; row += 9)
      for (int col = 3; col < 384; col += 41) {
        if (!v.coversPixel(col, row)) continue;
        const ts::Polygon2 p = v.preimage(col, row);
        const glm::dvec4 a = fast.average(p), b = ts::exactAreaAverage(checker(), p);
        worst = std::max(worst, std::fabs(a.r - b.r));
        ++checked;
      }
    EXPECT_GT(checked, 100);
    EXPECT_LT(worst, 1e-6) << "azimuth " << az;
  }
}

// The window's first stage (demos/filter_zoo/filter_zoo_measure.hpp,
// coarseRow): a CPU method's coarse picture is that method's own picture
// subsampled, each 4 x 4 block its pixel (2, 2), not an approximation of
// another kind; at k = 1 it is the whole picture.  Control: the block's
// pixel (0, 0) is not what it shows.
TEST(ZooCoarseStage, CoarsePictureSubsamplesTheMethodsPicture) {
  const Pyramids p(checker());
  const View v = slantView(96, 48, 30);
  for (int m : {int(kExact), int(kRipmap), int(kSat), int(kProbes), int(kEwa)}) {
    SCOPED_TRACE(methodKey(m));
    const ts::Image full = cpuPicture(m, p, v, 0, {}).image;
    EXPECT_EQ(coarsePicture(m, p, v, 0, 1).pixels, full.pixels);
    const ts::Image coarse = coarsePicture(m, p, v, 0, 4);
    ASSERT_EQ(coarse.width, 24);
    ASSERT_EQ(coarse.height, 12);
    long same = 0, corner = 0;
    for (int r = 0; r < coarse.height; ++r)
      for (int c = 0; c < coarse.width; ++c) {
        same += coarse.at(c, r) == full.at(4 * c + 2, 4 * r + 2);
        corner += coarse.at(c, r) == full.at(4 * c, 4 * r);
      }
    EXPECT_EQ(same, long(coarse.width) * coarse.height);
    EXPECT_LT(corner, same);  // the control: another pixel of the block differs somewhere
  }
}

// The far-field RMS of every CPU method at the three azimuths (computed once).
struct Table {
  std::map<std::string, double> rms, reads;
};
const Table& table() {
  static const Table t = [] {
    Table out;
    const Pyramids p(checker());
    for (double az : {0.0, 22.5, 45.0}) {
      const View v = slantView(384, 192, az);
      const std::vector<char> mask = farField(v, 1.5, 5.0);
      const Picture ex = cpuPicture(kExact, p, v, 0, mask);
      for (int m = kNearest; m < kMethodCount; ++m) {
        if (m == kAniso16) continue;  // GL's own: the figure test
        const Picture pic = cpuPicture(m, p, v, 0, mask);
        const std::string k = std::string(methodKey(m)) + "@" + (az == 0 ? "0" : az == 45 ? "45" : "22.5");
        out.rms[k] = rmsAgainst(pic.image, ex.exact, mask);
        out.reads[methodKey(m)] = pic.meanReads;
      }
    }
    for (auto& [k, v] : out.rms) std::printf("rms_exact[%s] = %.2f\n", k.c_str(), v);
    for (auto& [k, v] : out.reads) std::printf("texels_per_pixel[%s] = %.1f\n", k.c_str(), v);
    return out;
  }();
  return t;
}
double rms(const std::string& m, const char* az) { return table().rms.at(m + "@" + az); }

// Claim (the shape box filters predict, on the checkerboard's far field, LOD
// 1.5..5): ripmap and SAT are close to exact where the footprint runs along
// the texture's axes and worse at 45 degrees, where their box grows (SAT:
// the bounding box); the probe line and EWA follow the footprint's turn and
// stay nearly flat.  Margins: measured SAT +36 %, ripmap +27 %, probes -31 %,
// EWA +3 % from 0 to 45 degrees.
TEST(ZooOrderings, AzimuthShape) {
  EXPECT_GT(rms("sat", "45"), 1.2 * rms("sat", "0"));
  EXPECT_GT(rms("ripmap", "45"), 1.12 * rms("ripmap", "0"));
  EXPECT_LT(rms("probes", "45"), 1.1 * rms("probes", "0"));
  EXPECT_LT(rms("ewa", "45"), 1.1 * rms("ewa", "0"));
  EXPECT_GT(rms("sat", "45") / rms("sat", "0"), rms("ewa", "45") / rms("ewa", "0") + 0.15);
  EXPECT_GT(rms("ripmap", "45") / rms("ripmap", "0"), rms("probes", "45") / rms("probes", "0") + 0.15);
}

// Claim: at every azimuth the far field's error falls from nearest and
// bilinear (aliasing) to trilinear (over-blur) to the anisotropic methods;
// the probe line, reading the footprint along its length, is the closest.
TEST(ZooOrderings, MethodsAgainstExact) {
  for (const char* az : {"0", "22.5", "45"}) {
    SCOPED_TRACE(az);
    EXPECT_GT(rms("nearest", az), 1.1 * rms("linear", az));
    EXPECT_GT(rms("linear", az), 1.5 * rms("trilinear", az));
    EXPECT_GT(rms("trilinear", az), 1.5 * rms("ripmap", az));
    EXPECT_GT(rms("trilinear", az), 1.3 * rms("sat", az));
    EXPECT_GT(rms("trilinear", az), 1.3 * rms("ewa", az));
    for (const char* m : {"nearest", "linear", "nmn", "trilinear", "ripmap", "sat", "ewa"})
      EXPECT_LT(1.5 * rms("probes", az), rms(m, az)) << m;
  }
}

// Claim: the texels each method reads per pixel, counted: nearest 1,
// bilinear 4, trilinear 8 (4 where it uses one level), ripmap 16, SAT 16,
// the probe line 8N (N from 1 to 16), EWA about the ellipse's area.
TEST(ZooOrderings, TexelsRead) {
  const auto& r = table().reads;
  EXPECT_DOUBLE_EQ(r.at("nearest"), 1.0);
  EXPECT_DOUBLE_EQ(r.at("linear"), 4.0);
  EXPECT_DOUBLE_EQ(r.at("nmn"), 1.0);
  EXPECT_GT(r.at("trilinear"), 7.9);
  EXPECT_LE(r.at("trilinear"), 8.0);
  EXPECT_GT(r.at("ripmap"), 15.5);
  EXPECT_LE(r.at("ripmap"), 16.0);
  EXPECT_DOUBLE_EQ(r.at("sat"), 16.0);
  EXPECT_GT(r.at("probes"), 8.0 * 2);
  EXPECT_LE(r.at("probes"), 8.0 * 16);
  EXPECT_GT(r.at("ewa"), r.at("ripmap"));
}

// ---------------------------------------------------------------- 8. kernels
// Claim: the box kernel is Buss's 2x2 average (taps 1/2, 1/2: the chain the
// suite builds, byte for byte), the tent Crow's pyramid (1, 3, 3, 1)/8; every
// kernel's taps sum to 1; and the mipmap demo's gamma finding holds for each:
// the checkerboard's 1 x 1 level is 128 averaged in sRGB values, 165-166 in
// linear light (the mean of the linear values 0.7454 and 0.0144 is 0.3799, 165.7 in sRGB).
TEST(ZooKernels, TapsChainsAndGamma) {
  EXPECT_EQ(kernelTaps(kBox), std::vector<double>({0.5}));
  ASSERT_EQ(kernelTaps(kTent).size(), 2u);
  EXPECT_DOUBLE_EQ(kernelTaps(kTent)[0], 3.0 / 8);
  EXPECT_DOUBLE_EQ(kernelTaps(kTent)[1], 1.0 / 8);
  for (int k = 0; k < kKernelCount; ++k) {
    double s = 0;
    for (double t : kernelTaps(k)) s += 2 * t;
    EXPECT_NEAR(s, 1.0, 1e-12) << kernelKey(k);
  }
  EXPECT_LT(kernelTaps(kLanczos3)[2], 0);  // negative lobes
  const std::vector<ts::Image> box = kernelChain(checker(), kBox, false), book = ts::buildMipChain(checker());
  ASSERT_EQ(box.size(), book.size());
  for (size_t l = 0; l < box.size(); ++l) EXPECT_TRUE(box[l].pixels == book[l].pixels) << "level " << l;
  const double lin = (srgbToLinear(224) + srgbToLinear(32)) / 2;
  EXPECT_NEAR(linearToSrgb(lin), 165.7, 0.05);
  for (int k = 0; k < kKernelCount; ++k) {
    SCOPED_TRACE(kernelKey(k));
    EXPECT_NEAR(topValue(kernelChain(checker(), k, false)), 128.0, 0.5);
    EXPECT_NEAR(topValue(kernelChain(checker(), k, true)), 165.7, 1.0);
  }
}
}  // namespace
