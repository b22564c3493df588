// Unit tests of the reference sampler (no GL): wrap formulas at known
// coordinates (the GL spec's and seed 002's, which must agree), nearest and
// linear values, LOD, mip selection, and the legal sets the verifier uses.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/core/textures.hpp"
#include "reference/sampler.hpp"

namespace {
using ref::Colour;

// A 2x2 texture: (0,0) black, (1,0) white, (0,1) red, (1,1) blue.
ts::TextureDesc tiny(GLenum wrap, GLenum filter) {
  auto img = std::make_shared<ts::Image>(2, 2);
  img->set(0, 0, {0, 0, 0, 255});
  img->set(1, 0, {255, 255, 255, 255});
  img->set(0, 1, {255, 0, 0, 255});
  img->set(1, 1, {0, 0, 255, 255});
  ts::TextureDesc t;
  t.name = "tiny";
  t.image = img;
  t.wrapS = t.wrapT = wrap;
  t.minFilter = t.magFilter = filter;
  t.border = {0.0f, 1.0f, 0.0f, 1.0f};
  return t;
}

void expectColour(const Colour& got, std::array<float, 4> want, float eps = 1e-6f) {
  for (size_t k = 0; k < 4; ++k) EXPECT_NEAR(got[k], want[k], eps) << "channel " << k;
}

TEST(Wrap, GLIntegerFormulas) {
  // REPEAT: i mod size.
  EXPECT_EQ(ref::wrapTexel(GL_REPEAT, -1, 4), 3);
  EXPECT_EQ(ref::wrapTexel(GL_REPEAT, 4, 4), 0);
  EXPECT_EQ(ref::wrapTexel(GL_REPEAT, 9, 4), 1);
  EXPECT_EQ(ref::wrapTexel(GL_REPEAT, -9, 4), 3);
  // MIRRORED_REPEAT, size 4: 0 1 2 3 | 3 2 1 0 | 0 1 2 3 ... and mirrored below 0.
  const int up[] = {0, 1, 2, 3, 3, 2, 1, 0, 0, 1, 2, 3};
  for (int i = 0; i < 12; ++i) EXPECT_EQ(ref::wrapTexel(GL_MIRRORED_REPEAT, i, 4), up[i]) << i;
  const int down[] = {0, 1, 2, 3, 3, 2, 1, 0};  // i = -1, -2, ...
  for (int i = 0; i < 8; ++i) EXPECT_EQ(ref::wrapTexel(GL_MIRRORED_REPEAT, -1 - i, 4), down[i]) << -1 - i;
  // CLAMP_TO_EDGE: clamp to [0, size-1]; CLAMP_TO_BORDER: [-1, size] (outside = border).
  EXPECT_EQ(ref::wrapTexel(GL_CLAMP_TO_EDGE, -5, 4), 0);
  EXPECT_EQ(ref::wrapTexel(GL_CLAMP_TO_EDGE, 7, 4), 3);
  EXPECT_EQ(ref::wrapTexel(GL_CLAMP_TO_BORDER, -5, 4), -1);
  EXPECT_EQ(ref::wrapTexel(GL_CLAMP_TO_BORDER, 7, 4), 4);
  EXPECT_EQ(ref::wrapTexel(GL_CLAMP_TO_BORDER, 2, 4), 2);
}

TEST(Wrap, Seed002FormulasAtKnownCoordinates) {
  // WRAP: the fractional part.
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_REPEAT, 1.25), 0.25);
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_REPEAT, -0.25), 0.75);
  // MIRROR: fmod(ceil(u), 2) ? u - floor(u) : 1 - (u - floor(u)).
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_MIRRORED_REPEAT, 0.3), 0.3);
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_MIRRORED_REPEAT, 1.25), 0.75);
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_MIRRORED_REPEAT, 2.4), 0.4);
  EXPECT_NEAR(ref::wrapCoordSeed(GL_MIRRORED_REPEAT, 3.9), 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_MIRRORED_REPEAT, -0.25), 0.25);
  EXPECT_NEAR(ref::wrapCoordSeed(GL_MIRRORED_REPEAT, -1.3), 0.7, 1e-12);
  // CLAMP: to [0, 1].
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_CLAMP_TO_EDGE, 1.7), 1.0);
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_CLAMP_TO_EDGE, -0.2), 0.0);
  // BORDER: unchanged (outside [0, 1] the border colour is used).
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_CLAMP_TO_BORDER, 1.7), 1.7);
}

TEST(Wrap, SeedAndGLAgreeAwayFromTexelBoundaries) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  for (GLenum mode : {GL_REPEAT, GL_MIRRORED_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER})
    for (int size : {1, 4, 7, 256})
      for (int n = 0; n < 2000; ++n) {
        double s = u(rng);
        double x = s * size;
        if (std::abs(x - std::round(x)) < 1e-6) continue;  // on a boundary the floor is a tie
        int gl = ref::wrapTexel(mode, int(std::floor(x)), size);
        double w = ref::wrapCoordSeed(mode, s);
        int seed;
        if (mode == GL_CLAMP_TO_BORDER && (w < 0 || w > 1)) seed = w < 0 ? -1 : size;
        else seed = std::min(size - 1, int(std::floor(w * size)));
        ASSERT_EQ(gl, seed) << "mode " << mode << " size " << size << " s " << s;
      }
}

TEST(Sampler, NearestAndLinearValues) {
  ref::Texture n(tiny(GL_REPEAT, GL_NEAREST));
  expectColour(n.nearest(0, 0.25, 0.25), {0, 0, 0, 1});
  expectColour(n.nearest(0, 0.75, 0.25), {1, 1, 1, 1});
  expectColour(n.nearest(0, 0.25, 0.75), {1, 0, 0, 1});
  expectColour(n.nearest(0, 1.75, -0.25), {0, 0, 1, 1});  // wraps to (0.75, 0.75)
  ref::Texture l(tiny(GL_REPEAT, GL_LINEAR));
  expectColour(l.linear(0, 0.25, 0.25), {0, 0, 0, 1});               // a texel centre: that texel
  expectColour(l.linear(0, 0.5, 0.25), {0.5f, 0.5f, 0.5f, 1});       // between black and white
  expectColour(l.linear(0, 0.5, 0.5), {0.5f, 0.25f, 0.5f, 1});       // the four averaged
  expectColour(l.linear(0, 0.375, 0.25), {0.25f, 0.25f, 0.25f, 1});  // a quarter of the way
  // At s = 0 the footprint straddles the edge: REPEAT blends with the far
  // column, CLAMP_TO_EDGE with itself, CLAMP_TO_BORDER with the border.
  expectColour(l.linear(0, 0.0, 0.25), {0.5f, 0.5f, 0.5f, 1});
  expectColour(ref::Texture(tiny(GL_CLAMP_TO_EDGE, GL_LINEAR)).linear(0, 0.0, 0.25), {0, 0, 0, 1});
  expectColour(ref::Texture(tiny(GL_CLAMP_TO_BORDER, GL_LINEAR)).linear(0, 0.0, 0.25), {0, 0.5f, 0, 1});
  expectColour(ref::Texture(tiny(GL_MIRRORED_REPEAT, GL_LINEAR)).linear(0, 0.0, 0.25), {0, 0, 0, 1});
  // Mirrored: s in (1, 2) runs backwards, so s = 1.25 is texel 1's centre.
  expectColour(ref::Texture(tiny(GL_MIRRORED_REPEAT, GL_NEAREST)).nearest(0, 1.3, 0.2), {1, 1, 1, 1});
  expectColour(ref::Texture(tiny(GL_MIRRORED_REPEAT, GL_NEAREST)).nearest(0, 1.7, 0.2), {0, 0, 0, 1});
}

TEST(Sampler, MatchesTheCheckerboardsOwnLookup) {
  ts::Rgba a{10, 20, 30, 255}, b{200, 210, 220, 255};
  ts::TextureDesc d = ts::checkerboard(64, 8, a, b);
  d.minFilter = d.magFilter = GL_NEAREST;
  ref::Texture t(d);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int n = 0; n < 1000; ++n) {
    double s = u(rng), q = u(rng);
    EXPECT_EQ(ref::toRgba(t.sample(s, q, 0.0)), ts::checkerAt(64, 8, a, b, s, q)) << s << "," << q;
  }
}

TEST(Lod, FromDerivatives) {
  ref::Texture t(ts::checkerboard(256, 8));
  // 4 texels per pixel along x: lambda = 2.
  EXPECT_NEAR(t.lod({4.0 / 256, 0, 0, 4.0 / 256}), 2.0, 1e-12);
  // Anisotropic: the longer axis decides.
  EXPECT_NEAR(t.lod({4.0 / 256, 0, 0, 1.0 / 256}), 2.0, 1e-12);
  // Magnified: 1/2 texel per pixel, lambda = -1.
  EXPECT_NEAR(t.lod({0.5 / 256, 0, 0, 0.5 / 256}), -1.0, 1e-12);
  // Rotated 45 degrees, 2 texels along each of s and t per x step: exact
  // rho = sqrt(8) (lambda 1.5); the max-abs approximation gives 2 (lambda 1).
  ref::Deriv g{2.0 / 256, -2.0 / 256, 2.0 / 256, 2.0 / 256};
  double lo, hi;
  t.lodRange(g, ref::LodModel::Exact, &lo, &hi);
  EXPECT_NEAR(lo, 1.5, 1e-12);
  EXPECT_NEAR(hi, 1.5, 1e-12);
  t.lodRange(g, ref::LodModel::Bounded, &lo, &hi);
  EXPECT_NEAR(lo, 1.0, 1e-12);
  EXPECT_NEAR(hi, 1.5, 1e-12);
  t.lodRange(g, ref::LodModel::Spec, &lo, &hi);
  EXPECT_NEAR(lo, 1.0, 1e-12);
  EXPECT_NEAR(hi, 2.0, 1e-12);
}

TEST(Lod, MipSelection) {
  ts::TextureDesc d = ts::mipLevelColours(64);  // 7 levels, NEAREST_MIPMAP_NEAREST
  d.magFilter = GL_NEAREST;
  ref::Texture t(d);
  ASSERT_EQ(t.levels(), 7);
  auto level = [&](double lambda) {
    ts::Rgba c = ref::toRgba(t.sample(0.3, 0.6, lambda));
    for (int k = 0; k < 7; ++k)
      if (c == ts::mipLevelColour(k)) return k;
    return -1;
  };
  EXPECT_EQ(level(-2.0), 0);  // magnified
  EXPECT_EQ(level(0.4), 0);   // lambda <= 1/2: level 0
  EXPECT_EQ(level(0.6), 1);   // ceil(lambda + 1/2) - 1
  EXPECT_EQ(level(1.4), 1);
  EXPECT_EQ(level(1.6), 2);
  EXPECT_EQ(level(20.0), 6);  // clamped to the last level
  // LINEAR_MIPMAP_LINEAR at lambda 1.25: 3/4 of level 1 and 1/4 of level 2.
  d.minFilter = GL_LINEAR_MIPMAP_LINEAR;
  ref::Texture tl(d);
  Colour c = tl.sample(0.3, 0.6, 1.25), l1 = ref::toColour(ts::mipLevelColour(1)),
         l2 = ref::toColour(ts::mipLevelColour(2));
  for (size_t k = 0; k < 4; ++k) EXPECT_NEAR(c[k], 0.75 * l1[k] + 0.25 * l2[k], 1e-6);
  // The texture's LOD bias is added to lambda_base.
  d.minFilter = GL_NEAREST_MIPMAP_NEAREST;
  d.lodBias = 1.0f;
  ref::Texture tb(d);
  EXPECT_EQ(ref::toRgba(tb.sample(0.3, 0.6, 0.4)), ts::mipLevelColour(1));
}

TEST(Lod, MagnificationAndMinificationFilters) {
  ts::TextureDesc d = tiny(GL_REPEAT, GL_NEAREST);
  d.minFilter = GL_LINEAR;
  ref::Texture t(d);
  expectColour(t.sample(0.5, 0.25, -0.5), {1, 1, 1, 1});          // lambda <= 0: NEAREST (u = 1.0 -> texel 1)
  expectColour(t.sample(0.5, 0.25, 0.5), {0.5f, 0.5f, 0.5f, 1});  // lambda > 0: LINEAR
}

TEST(Legal, NearestNearATexelBoundaryAllowsBothTexels) {
  ref::Texture t(tiny(GL_REPEAT, GL_NEAREST));
  ref::Boxes b;
  t.legal(0.5 + 1e-4, 0.25, 0, 0, 1.0 / 64, 1.0 / 32, &b);  // u = 1.0002 texels: within eps of the edge
  ASSERT_EQ(b.size(), 2u);
  b.clear();
  t.legal(0.6, 0.25, 0, 0, 1.0 / 64, 1.0 / 32, &b);
  ASSERT_EQ(b.size(), 1u);
  expectColour(b[0].lo, {1, 1, 1, 1});
}

TEST(Legal, LinearJitterSpansARange) {
  ref::Texture t(tiny(GL_REPEAT, GL_LINEAR));
  ref::Boxes b;
  // u = 0.75 +- 1/8 texel: between black and white; v = 0.5 +- 1/8: across
  // row 0's centre, so 1/8 of row 1 (red, blue; wrapped) may blend in.
  t.legal(0.375, 0.25, 0, 0, 0, 1.0 / 8, &b);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_NEAR(b[0].lo[0], 0.125, 1e-6);                          // u' = 1/8 on row 0
  EXPECT_NEAR(b[0].hi[0], 0.875 * 0.375 + 0.125 * 0.625, 1e-6);  // u' = 3/8, 1/8 of row 1
  EXPECT_NEAR(b[0].lo[1], 0.875 * 0.125, 1e-6);                  // green: only white has it
  EXPECT_NEAR(b[0].hi[1], 0.375, 1e-6);
}

TEST(Legal, LodIntervalAcrossALevelBoundaryAllowsBothLevels) {
  ref::Texture t(ts::mipLevelColours(64));
  ref::Boxes b;
  t.legal(0.3, 0.6, 1.45, 1.55, 0, 0, &b);  // NEAREST_MIPMAP_NEAREST: levels 1 and 2
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(ref::toRgba(b[0].lo), ts::mipLevelColour(1));
  EXPECT_EQ(ref::toRgba(b[1].lo), ts::mipLevelColour(2));
  b.clear();
  t.legal(0.3, 0.6, 1.1, 1.3, 0, 0, &b);  // well inside level 1's range
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(ref::toRgba(b[0].lo), ts::mipLevelColour(1));
}

TEST(Legal, BlendBoxes) {
  ref::Boxes a{ref::Box::point({0, 0, 0, 1})}, c{ref::Box::point({1, 1, 1, 1})}, out;
  ref::blendBoxes(a, c, 0.25, 0.5, &out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].lo[0], 0.25, 1e-6);
  EXPECT_NEAR(out[0].hi[0], 0.5, 1e-6);
}
// At integer coordinates, where the wrap modes part: u = s N is a
// texel boundary and GL_NEAREST takes floor(u), wrapped.  The 2x2 `tiny`:
// row t = 0.25 is black (i = 0), white (i = 1); the border is green.
TEST(Wrap, NearestAtIntegerCoordinates) {
  const Colour black{0, 0, 0, 1}, white{1, 1, 1, 1}, green{0, 1, 0, 1};
  struct Case {
    GLenum mode;
    double s;
    Colour want;
  } cases[] = {
      // REPEAT: i mod 2; s = 1 starts the next copy.
      {GL_REPEAT, 0.0, black},
      {GL_REPEAT, 1.0, black},
      {GL_REPEAT, -1.0, black},
      {GL_REPEAT, 2.0, black},
      // MIRRORED_REPEAT: s = 1 is the start of the mirrored copy (its first
      // texel is the last one), s = 2 the start of the next forward copy,
      // s = -1 the start (from below) of the mirrored copy before 0.
      {GL_MIRRORED_REPEAT, 0.0, black},
      {GL_MIRRORED_REPEAT, 1.0, white},
      {GL_MIRRORED_REPEAT, 2.0, black},
      {GL_MIRRORED_REPEAT, -1.0, white},
      {GL_MIRRORED_REPEAT, 3.0, white},
      // CLAMP_TO_EDGE: s = 1 is clamped to the last texel.
      {GL_CLAMP_TO_EDGE, 1.0, white},
      {GL_CLAMP_TO_EDGE, 0.0, black},
      {GL_CLAMP_TO_EDGE, -1.0, black},
      // CLAMP_TO_BORDER: u = N is index N, outside: the border (also for NEAREST).
      {GL_CLAMP_TO_BORDER, 1.0, green},
      {GL_CLAMP_TO_BORDER, 0.0, black},
      {GL_CLAMP_TO_BORDER, -1.0, green},
      // CLAMP with NEAREST: s clamped to [0, 1], then clamp(i, 0, N - 1): never the border.
      {GL_CLAMP, 1.0, white},
      {GL_CLAMP, 2.0, white},
      {GL_CLAMP, 0.0, black},
      {GL_CLAMP, -1.0, black},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::to_string(c.mode) + " s=" + std::to_string(c.s));
    ref::Texture tex(tiny(c.mode, GL_NEAREST));
    expectColour(tex.nearest(0, c.s, 0.25), c.want);
    expectColour(tex.sample(c.s, 0.25, -1.0), c.want);  // through the full filter path
  }
  // The seed's MIRROR returns the opposite edge at every integer.
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_MIRRORED_REPEAT, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_MIRRORED_REPEAT, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_MIRRORED_REPEAT, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(ref::wrapCoordSeed(GL_MIRRORED_REPEAT, -1.0), 0.0);
}

// GL_CLAMP with GL_LINEAR: s clamped to [0, 1], and at s = 0 and s = 1 (so
// everywhere outside) the footprint is half border, half edge texel.
TEST(Wrap, ClampLinearBlendsHalfTheBorder) {
  ref::Texture l(tiny(GL_CLAMP, GL_LINEAR));
  expectColour(l.linear(0, 0.0, 0.25), {0, 0.5f, 0, 1});     // black edge texel + green border
  expectColour(l.linear(0, -3.0, 0.25), {0, 0.5f, 0, 1});    // clamped to 0 first
  expectColour(l.linear(0, 1.0, 0.25), {0.5f, 1, 0.5f, 1});  // white + green
  expectColour(l.linear(0, 7.0, 0.25), {0.5f, 1, 0.5f, 1});
  ref::Texture b(tiny(GL_CLAMP_TO_BORDER, GL_LINEAR));
  expectColour(b.linear(0, -3.0, 0.25), {0, 1, 0, 1});  // all border outside
}

// The texture environment's table on a grid of fragment colours x texel
// colours x alphas, against the formulas written out here again.
TEST(TexEnv, TableOnAGrid) {
  const float vals[] = {0.0f, 0.25f, 0.6f, 1.0f};
  const Colour env{0.2f, 0.7f, 0.9f, 0.5f};
  for (float f : vals)
    for (float t : vals)
      for (float fa : vals)
        for (float ta : vals) {
          Colour cf{f, 1 - f, 0.5f, fa}, ct{t, 0.3f, 1 - t, ta};
          for (size_t k = 0; k < 3; ++k) {
            EXPECT_FLOAT_EQ(ref::texEnv(GL_REPLACE, cf, ct, env)[k], ct[k]);
            EXPECT_FLOAT_EQ(ref::texEnv(GL_MODULATE, cf, ct, env)[k], cf[k] * ct[k]);
            EXPECT_FLOAT_EQ(ref::texEnv(GL_DECAL, cf, ct, env)[k], cf[k] * (1 - ta) + ct[k] * ta);
            EXPECT_FLOAT_EQ(ref::texEnv(GL_BLEND, cf, ct, env)[k], cf[k] * (1 - ct[k]) + env[k] * ct[k]);
            EXPECT_FLOAT_EQ(ref::texEnv(GL_ADD, cf, ct, env)[k], std::min(1.0f, cf[k] + ct[k]));
          }
          EXPECT_FLOAT_EQ(ref::texEnv(GL_REPLACE, cf, ct, env)[3], ta);
          EXPECT_FLOAT_EQ(ref::texEnv(GL_DECAL, cf, ct, env)[3], fa);
          for (GLenum m : {GL_MODULATE, GL_BLEND, GL_ADD}) EXPECT_FLOAT_EQ(ref::texEnv(m, cf, ct, env)[3], fa * ta);
          // The box of a point is the point.
          for (GLenum m : {GL_REPLACE, GL_MODULATE, GL_DECAL, GL_BLEND, GL_ADD}) {
            ref::Box b = ref::texEnvBox(m, ref::Box::point(cf), ref::Box::point(ct), env);
            Colour v = ref::texEnv(m, cf, ct, env);
            for (size_t k = 0; k < 4; ++k) {
              EXPECT_FLOAT_EQ(b.lo[k], v[k]);
              EXPECT_FLOAT_EQ(b.hi[k], v[k]);
            }
          }
        }
}
}  // namespace
