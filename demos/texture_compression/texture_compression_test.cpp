// demos/texture_compression/texture_compression_test.cpp — seed 001's texture-memory
// claims (demos/texture_compression): DXT1's size and ratios, its blocks'
// colours, GL's decode against the suite's, and the memory numbers, each
// against a value computed here; and the codec (texture_compression_math.hpp) on blocks
// whose answer is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

#include "demos/texture_compression/texture_compression_math.hpp"
#include "demos/texture_compression/texture_compression_measure.hpp"
#include "demos/texture_compression/texture_compression_views.hpp"
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

// Claim: sides that are not multiples of 4 are padded as the format needs:
// ceil(W/4) x ceil(H/4) blocks, the padding the last column and row
// repeated, and the decode exactly W x H.
TEST(Dxt1Codec, PaddingToWholeBlocks) {
  ts::Image img(6, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 6; ++x) img.set(x, y, (x + y) % 2 ? ts::Rgba{255, 0, 0, 255} : ts::Rgba{0, 0, 255, 255});
  const auto blocks = dxt::encode(img);
  ASSERT_EQ(blocks.size(), 4u);  // 2 x 2 blocks
  const ts::Image back = dxt::decode(blocks, 6, 5);
  EXPECT_EQ(back.width, 6);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(dxt::maxDiff(back, img), 0) << "two colours RGB565 holds exactly decode exactly";
  // The block over column 4..7 holds columns 6 and 7 as copies of column 5.
  const auto px = dxt::blockTexels(img, 1, 1);
  EXPECT_EQ(px[3], px[1]);   // (7, 4) is (5, 4)
  EXPECT_EQ(px[15], px[1]);  // (7, 7) is (5, 4)
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
  ASSERT_EQ(value(ms, "s3tc_supported"), 1.0) << "this Mesa offers S3TC (docs/platform.md, Extensions)";
  EXPECT_EQ(value(ms, "dxt1_bytes[512]"), 512.0 * 512.0 / 16.0 * 8.0);  // 64 bits per 4x4 block
  EXPECT_EQ(value(ms, "dxt1_bytes[512]"), 256.0 * 256.0 * 2.0);
  EXPECT_EQ(value(ms, "bits_per_texel"), 4.0);
  EXPECT_EQ(value(ms, "ratio_vs_rgb565"), 4.0);
  EXPECT_EQ(value(ms, "ratio_vs_rgb888"), 6.0);
}

// Claim: a decoded block holds at most 4 colours, and GL decodes the
// suite's blocks as texture_compression_math.hpp does, within one 8-bit level (the
// specification leaves the 2:1 mixes' rounding to the implementation).
TEST_F(TextureCompressionFigure, BlocksAndGlDecode) {
  EXPECT_LE(value(ms, "dxt1_max_colours_per_block"), 4.0);
  EXPECT_GE(value(ms, "dxt1_max_colours_per_block"), 3.0) << "a photo's blocks use the mixes";
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
  // The error concentrates at the bricks' edges, where a block's normals turn.
  EXPECT_GT(value(ms, "normal_error_deg[edge_blocks]"), 2.0 * value(ms, "normal_error_deg[flat_blocks]"));
  EXPECT_LT(value(ms, "rms_equal_memory[dxt1_512]"), 0.5 * value(ms, "rms_equal_memory[rgb565_256]"));
}

// Claim (seed 001): a clipmap of 65536^2 with 512^2 levels holds 2,184,533
// texels against 5,726,623,061 for the whole chain: computed here as
// 8 levels of 512^2 plus the chain below 512, and (4^17 - 1) / 3.
TEST_F(TextureCompressionFigure, ClipmapAndCache) {
  const double small = (std::pow(4.0, 9) - 1) / 3;  // 256^2 + ... + 1
  EXPECT_EQ(value(ms, "clipmap_texels[65536/512]"), 8 * 512.0 * 512.0 + small);
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

// The memory figure: the hit-rate axis runs past 100 %, so the curves'
// plateaus near 100 stay clear of the plot's top border; its notes print the
// measurements and both curves have a key.
TEST_F(TextureCompressionFigure, MemoryPlotHasHeadroom) {
  ts::test::Demo d("texture_compression", {"--view", "memory"});
  d.measured = ms;
  const ts::Frame f = d.frame(1024, 520);
  const ts::Panel* plot = nullptr;
  for (const ts::Panel& p : f.panels)
    for (const ts::Batch& b : p.batches)
      if (b.role == "lru_prefetch") plot = &p;
  ASSERT_NE(plot, nullptr);
  float highest = 1e9f;  // the curve's highest point, pixels from the top
  for (const ts::Batch& b : plot->batches)
    if (b.role == "lru_prefetch" || b.role == "lru")
      for (const ts::Vertex& v : b.vertices)
        highest = std::min(highest,
                           ts::panelToPixels(*plot, plot->projection * plot->modelview * glm::vec4(v.pos, 1.0f)).y);
  EXPECT_GE(highest - float(plot->viewport.y), 0.05f * float(plot->viewport.h))
      << "the plateau runs into the top border";
  size_t printed = 0;
  for (const ts::Label& l : f.labels) {
    EXPECT_EQ(l.text.find("..."), std::string::npos) << l.text;
    printed += l.printed.size();
  }
  EXPECT_EQ(printed, 5u) << "clipmap, chain, saving, DXT1 bytes, RGB565 bytes";
  EXPECT_EQ(f.legend.size(), 2u);
}

// Claim: the 3-colour mode (c0 <= c1) is worse on the photo: its palette
// has one colour fewer between the ends (the fourth is black).
TEST(TextureCompressionModes, ThreeColourModeCostsQuality) {
  ts::test::Demo four("texture_compression", {}), three("texture_compression", {"--three-colour"});
  EXPECT_GT(value(four.measure(), "psnr[photo]"), value(three.measure(), "psnr[photo]") + 1.0);
}
// Claim (seed 001: "a 512^2 texture in a 256^2's memory"): at equal memory
// the magnified views show the same RMS the figure prints, DXT1's lower.
TEST_F(TextureCompressionFigure, EqualMemoryFigureNumbers) {
  const dxt::Result* r = ms.detailAs<dxt::Result>();
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->rmsDxt1, value(ms, "rms_equal_memory[dxt1_512]"));
  EXPECT_EQ(r->rmsRgb565, value(ms, "rms_equal_memory[rgb565_256]"));
  EXPECT_NEAR(r->rmsRgb565, dxt::rms(r->original, dxt::rgb565Half(r->original)), 1e-12);
  EXPECT_EQ(r->rgb565.width, 512);
}

// Claim: where a driver lacks S3TC the demo shows the CPU's decode (here
// --decode cpu takes that path on a GL that has it): the picture is exactly
// dxt1.hpp's decode, and GL's decode (shown otherwise) is within 1 level.
TEST(TextureCompressionModes, CpuDecodeFallback) {
  ts::test::Demo gl("texture_compression", {}), cpu("texture_compression", {"--decode", "cpu"});
  const ts::Measurements mg = gl.measure(), mc = cpu.measure();
  EXPECT_EQ(value(mg, "gl_decode_shown"), 1.0);
  EXPECT_EQ(value(mc, "gl_decode_shown"), 0.0);
  const dxt::Result *rg = mg.detailAs<dxt::Result>(), *rc = mc.detailAs<dxt::Result>();
  ASSERT_TRUE(rg && rc);
  const ts::Image cpuDecode = dxt::decode(rc->blocks, rc->original.width, rc->original.height);
  EXPECT_EQ(dxt::maxDiff(rc->decoded, cpuDecode), 0);
  EXPECT_LE(dxt::maxDiff(rg->decoded, cpuDecode), 1);
  EXPECT_EQ(value(mc, "dxt1_bytes[512]"), 131072.0) << "the size is still asked of GL";
}

// Claim: --texture FILE compresses the student's picture; a 301 x 203 one
// is padded to 76 x 51 blocks (8 bytes each, GL's compressed size), and GL
// still decodes only its 301 x 203 texels, within 1 level of the CPU.
TEST(TextureCompressionModes, YourPictureOddSize) {
  ts::Image img(301, 203);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      img.set(x, y, {uint8_t(x * 255 / 300), uint8_t(y * 255 / 202), uint8_t((x ^ y) & 255), 255});
  const std::string path = testing::TempDir() + "odd_" + std::to_string(getpid()) + ".png";
  ts::writePng(path, img);
  ts::test::Demo d("texture_compression", {"--texture", path});
  const ts::Measurements m = d.measure();
  std::remove(path.c_str());
  EXPECT_EQ(value(m, "dxt1_bytes[file]"), 76.0 * 51.0 * 8.0);
  EXPECT_EQ(value(m, "padded_texels"), 304.0 * 204.0 - 301.0 * 203.0);
  EXPECT_LE(value(m, "gl_vs_cpu_max_diff"), 1.0);
  EXPECT_GE(value(m, "gl_vs_cpu_max_diff"), 0.0);
  const dxt::Result* r = m.detailAs<dxt::Result>();
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->decoded.width, 301);
  EXPECT_EQ(r->decoded.height, 203);
  // A picture smaller than a view's crop (the window test drops a 32 x 24
  // JPEG) is shown whole: 5 x 3 texels, 2 x 1 blocks, 16 bytes.
  ts::Image tiny(5, 3, {200, 30, 40, 255});
  const std::string tinyPath = testing::TempDir() + "tiny_" + std::to_string(getpid()) + ".png";
  ts::writePng(tinyPath, tiny);
  ts::test::Demo t("texture_compression", {"--texture", tinyPath});
  const ts::Measurements mt = t.measure();
  std::remove(tinyPath.c_str());
  EXPECT_EQ(value(mt, "dxt1_bytes[file]"), 16.0);
  EXPECT_EQ(value(mt, "padded_texels"), 8.0 * 4.0 - 15.0);
  EXPECT_FALSE(t.scene->build(640, 300, mt).panels.empty()) << "its views are drawn";
}
}  // namespace
