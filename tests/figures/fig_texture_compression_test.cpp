// tests/figures/fig_texture_compression_test.cpp — seed 001's texture-memory
// claims (demos/texture_compression): DXT1's size and ratios, its blocks'
// colours, GL's decode against the suite's, and the memory numbers, each
// against a value computed here; and the codec (dxt_math.hpp) on blocks
// whose answer is known.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "demos/texture_compression/dxt_math.hpp"
#include "demos/texture_compression/dxt_measure.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::value;

// Claim: RGB565 keeps 5/6/5 bits and unpacks by bit replication (0 -> 0, max -> 255).
TEST(Dxt1Codec, Rgb565RoundTrip) {
  EXPECT_EQ(dxt::pack565({255, 255, 255}), 0xFFFF);
  EXPECT_EQ(dxt::unpack565(0xFFFF), glm::ivec3(255, 255, 255));
  EXPECT_EQ(dxt::unpack565(0x0000), glm::ivec3(0, 0, 0));
  EXPECT_EQ(dxt::unpack565(dxt::pack565({255, 0, 0})), glm::ivec3(255, 0, 0));
}

// Claim: a block of two colours that RGB565 holds exactly decodes exactly,
// in the 4-colour mode (c0 > c1); the palette's third and fourth colours are
// the 2:1 and 1:2 mixes; the 3-colour mode (c0 <= c1) has the midpoint and black.
TEST(Dxt1Codec, BlocksAndPalettes) {
  ts::Image img(4, 4);
  for (int k = 0; k < 16; ++k) img.set(k % 4, k / 4, k % 3 ? ts::Rgba{255, 0, 0, 255} : ts::Rgba{0, 0, 255, 255});
  const auto blocks = dxt::encode(img);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_GT(blocks[0].c0, blocks[0].c1);
  const ts::Image back = dxt::decode(blocks, 4, 4);
  EXPECT_EQ(dxt::maxDiff(back, img), 0);
  const auto four = dxt::palette(0xF800, 0x001F);  // red > blue
  EXPECT_EQ(four[2], glm::ivec4((2 * 255) / 3, 0, 255 / 3, 255));
  EXPECT_EQ(four[3], glm::ivec4(255 / 3, 0, (2 * 255) / 3, 255));
  const auto three = dxt::palette(0x001F, 0xF800);  // blue <= red
  EXPECT_EQ(three[2], glm::ivec4(255 / 2, 0, 255 / 2, 255));
  EXPECT_EQ(three[3], glm::ivec4(0, 0, 0, 0));
  // 8 bytes a block, c0 first, little-endian.
  const auto b = dxt::bytes(blocks);
  ASSERT_EQ(b.size(), 8u);
  EXPECT_EQ(b[0] | (b[1] << 8), blocks[0].c0);
}

class TextureCompressionFigure : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    demo = new ts::test::Demo("texture_compression", {"--view", "blocks", "--picture", "photo"});
    ms = demo->measure();
  }
  static void TearDownTestSuite() { delete demo; }
  static ts::test::Demo* demo;
  static ts::Measurements ms;
};
ts::test::Demo* TextureCompressionFigure::demo = nullptr;
ts::Measurements TextureCompressionFigure::ms;

// Claim (seed 001): a 512^2 DXT1 texture takes 131,072 bytes, the memory of a
// 256^2 texture at 16 bits: 4 bits a texel, 4:1 and 6:1.
TEST_F(TextureCompressionFigure, SizeAndRatios) {
  ASSERT_EQ(value(ms, "s3tc_supported"), 1.0) << "this Mesa offers S3TC (../shared/PLATFORM.md)";
  EXPECT_EQ(value(ms, "compressed_bytes[512]"), 512.0 * 512.0 / 16.0 * 8.0);  // 64 bits per 4x4 block
  EXPECT_EQ(value(ms, "compressed_bytes[512]"), 256.0 * 256.0 * 2.0);
  EXPECT_EQ(value(ms, "bits_per_texel"), 4.0);
  EXPECT_EQ(value(ms, "ratio_vs_rgb565"), 4.0);
  EXPECT_EQ(value(ms, "ratio_vs_rgb888"), 6.0);
}

// Claim: a decoded block holds at most 4 colours, and GL decodes the
// suite's blocks as dxt_math.hpp does, within one 8-bit level (the
// specification leaves the 2:1 mixes' rounding to the implementation).
TEST_F(TextureCompressionFigure, BlocksAndGlDecode) {
  EXPECT_LE(value(ms, "max_colours_per_block"), 4.0);
  EXPECT_GE(value(ms, "max_colours_per_block"), 3.0) << "a photo's blocks use the mixes";
  EXPECT_GE(value(ms, "gl_vs_cpu_max_diff"), 0.0);
  EXPECT_LE(value(ms, "gl_vs_cpu_max_diff"), 1.0);
}

// Claim: lossy, and worse for a normal map's directions than its PSNR
// suggests; at equal memory, 512^2 DXT1 is closer to the picture than 256^2
// RGB565 magnified.
TEST_F(TextureCompressionFigure, LossAndEqualMemory) {
  EXPECT_GT(value(ms, "psnr[photo]"), 25.0);
  EXPECT_LT(value(ms, "psnr[photo]"), 60.0) << "lossy";
  EXPECT_GT(value(ms, "psnr[checker]"), value(ms, "psnr[photo]")) << "two colours a block are easy";
  EXPECT_GT(value(ms, "normal_error_deg[mean]"), 1.0);
  EXPECT_GT(value(ms, "normal_error_deg[max]"), 20.0);
  EXPECT_LT(value(ms, "rms_equal_memory[dxt1_512]"), 0.5 * value(ms, "rms_equal_memory[rgb565_256]"));
}

// Claim (seed 001): a clipmap of 65536^2 with 512^2 levels holds 2,184,533
// texels against 5,726,623,061 for the whole chain: computed here as
// 8 levels of 512^2 plus the chain below 512, and (4^17 - 1) / 3.
TEST_F(TextureCompressionFigure, ClipmapAndCache) {
  const double small = (std::pow(4.0, 9) - 1) / 3;  // 256^2 + ... + 1
  EXPECT_EQ(value(ms, "clipmap_texels"), 8 * 512.0 * 512.0 + small);
  EXPECT_EQ(value(ms, "chain_texels"), (std::pow(4.0, 17) - 1) / 3);
  EXPECT_NEAR(value(ms, "clipmap_saving"), 2621.44, 0.01);
  // A cache smaller than the view's tiles (7 x 7 = 49) misses nearly all;
  // one that holds them misses only the tiles entering; prefetching with
  // room to spare misses almost none.
  EXPECT_LT(value(ms, "cache_hit_rate[40]"), 0.05);
  EXPECT_GT(value(ms, "cache_hit_rate[64]"), 0.9);
  EXPECT_GT(value(ms, "cache_hit_rate_prefetch[64]"), value(ms, "cache_hit_rate[64]") + 0.03);
  EXPECT_GT(value(ms, "cache_hit_rate_prefetch[128]"), 0.99);
}

// Claim: the 3-colour mode (c0 <= c1) is worse on the photo: its palette
// has one colour fewer between the ends (the fourth is black).
TEST(TextureCompressionModes, ThreeColourModeCostsQuality) {
  ts::test::Demo four("texture_compression", {}), three("texture_compression", {"--three-colour"});
  EXPECT_GT(value(four.measure(), "psnr[photo]"), value(three.measure(), "psnr[photo]") + 1.0);
}
}  // namespace
