// Seed 001 ¶19–24 — texture memory: S3TC/DXT1 compression, caching, clipmaps.
//
// The claims (seed 001): DXT1 stores each 4x4 block in 64 bits — two
// colours in RGB565 and two more interpolated between them, 2 bits per
// texel to pick one — so 4 bits per texel, 4:1 against 16-bit and 6:1
// against 24-bit texels: "a 512² texture in a 256²'s memory"; it is lossy,
// and "bad for normal maps".  Texture memory is also managed: tiles are
// cached, and a clipmap keeps only a window of each large level.
//
// The mapping equation of the codec (texture_compression_math.hpp, the encoder and decoder
// written out): per block, c0 > c1 gives c2 = (2 c0 + c1)/3, c3 = (c0 + 2 c1)/3;
// c0 <= c1 gives the 3-colour mode, c2 = (c0 + c1)/2 and c3 = black (seed
// 001 leaves it out; key 3 shows it); each texel = palette[its 2 bits].
//
// Keys (each is also a flag, see --help):
//   v  view: blocks | equal-memory | memory   t  picture: photo | checker | normals
//   3  every block in the 3-colour mode        b / B, n / N  the block shown: x, y
//   d  decode: GL's | the CPU's (what the demo shows where a driver has no S3TC)
//   --texture FILE  your picture, compressed (sides not multiples of 4 are
//                   padded by repeating the last row and column, as the format needs)
//
// What the GL does (texture_compression_gl.hpp; the listing's first section):
//   glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 512, 512, 0, 131072, blocks);
//   glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
//   glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);   // GL's decode, shown
// (GL_EXT_texture_compression_s3tc: llvmpipe and softpipe have it, docs/platform.md "Extensions";
// without it the demo says so and shows the CPU decode.)  The pictures are
// then drawn as plain textures (book_figures/dxt1_blocks.gl.txt).
//
// Measured: GL's compressed size against 256 x 256 at 16 bits, the bits per
// texel and the ratios, the most colours in any decoded block (4), GL's
// decode against the CPU's (within 1 level), PSNR of the photo, checker and
// normal map, the normal map's angle error, 512² DXT1 against 256² RGB565 at
// equal memory; an LRU tile cache's hit rate with and without prefetching,
// and a 65536² clipmap's texels against its whole mip chain.
#include <cstdio>
#include <string>

#include "common/core/layout.hpp"
#include "common/core/user_texture.hpp"
#include "common/core/scene.hpp"
#include "common/gl/gl_listing.hpp"
#include "common/gl/render.hpp"
#include "texture_compression_gl.hpp"
#include "texture_compression_math.hpp"
#include "texture_compression_measure.hpp"
#include "texture_compression_views.hpp"

namespace {
using namespace dxt;
using ts::layout::fmt;

class TextureCompression final : public ts::Scene {
 public:
  std::string id() const override { return "texture_compression"; }
  std::string title() const override { return "Seed 001 - texture memory: DXT1 compression, caching, clipmaps"; }
  std::string about() const override {
    return "A 512 x 512 picture (a photograph-like brick texture, a checkerboard, a normal map) compressed to DXT1 by\n"
           "the encoder in texture_compression_math.hpp, uploaded with glCompressedTexImage2D and decoded by GL.\n"
           "Prints the compressed size (131,072 bytes: a 256 x 256 texture's at 16 bits), 4 bits per texel, at most\n"
           "4 colours per block, GL's decode against the CPU's, PSNR, the normal map's angle error, DXT1 512 against\n"
           "RGB565 256 at equal memory, an LRU tile cache's hit rate "
           "with and without prefetching, and a clipmap's size.";
  }
  int defaultWidth() const override { return 1280; }
  int defaultHeight() const override { return 440; }
  std::vector<std::string> claim() const override { return {"dxt1_bytes[512]", "bits_per_texel"}; }

  void addOptions(ts::Options& o) override {
    o.addEnum("view", &view_, {"blocks", "equal-memory", "memory"},
              "the picture and its DXT1 blocks | DXT1 against RGB565 at "
              "half the size, magnified | the tile cache and the clipmap",
              'v');
    o.addEnum("picture", &picture_, {kPictureNames[0], kPictureNames[1], kPictureNames[2]},
              "photo-like bricks | checkerboard | normal map (from the bricks' heights)", 't');
    o.addBool("three-colour", &three_, "every block in the 3-colour mode (c0 <= c1: midpoint and black)", '3');
    o.addInt("block-x", &bx_, 0, 127, "the block magnified: column", 'b', 'B', 1);
    o.addInt("block-y", &by_, 0, 127, "the block magnified: row", 'n', 'N', 1);
    o.addEnum("decode", &cpuDecode_, {"gl", "cpu"},
              "show GL's decode of the blocks | the CPU's (dxt1.hpp), as where the driver lacks S3TC", 'd');
    file_.addOption(o, "the picture chosen by --picture");
  }

  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"dxt1_blocks",
         "Seed 001 (texture compression)",
         "A photograph-like texture, 512 x 512, compressed to DXT1 by the suite's encoder and decoded by GL; the error "
         "magnified 8 times; one block magnified with its two RGB565 colours and the two between them.",
         {"--view", "blocks", "--picture", "photo", "--block-x", "40", "--block-y", "14"},
         1280,
         440,
         "{dxt1_bytes[512]} bytes, the same as 256 x 256 at 16 bits: {bits_per_texel} bits per texel, "
         "{ratio_vs_rgb888}:1 against 24-bit texels; PSNR {psnr[photo]} "
         "dB; at most {dxt1_max_colours_per_block} colours in a "
         "block; GL's decode within {gl_vs_cpu_max_diff} levels of the CPU's."},
        {"dxt1_normal_map",
         "Seed 001 (texture compression)",
         "A normal map compressed to DXT1: the blocks' two-colour lines cannot follow the normals' directions, the "
         "error concentrates at the bricks' edges.",
         {"--view", "blocks", "--picture", "normals", "--block-x", "30", "--block-y", "14"},
         1280,
         440,
         "\"Bad for normal maps\": after DXT1 the normals are off by {normal_error_deg[mean]} degrees on average, "
         "{normal_error_deg[max]} at most (PSNR {psnr[normals]} dB): {normal_error_deg[edge_blocks]} in blocks on the "
         "bricks' edges against {normal_error_deg[flat_blocks]} in flat ones."},
        {"dxt1_equal_memory",
         "Seed 001 (texture compression)",
         "The same memory two ways, magnified: 64 x 64 texels of "
         "the picture at 512 x 512, of DXT1 at 512 x 512 (4 bits a "
         "texel), and of RGB565 at 256 x 256 (16 bits a texel) magnified back.",
         {"--view", "equal-memory", "--picture", "photo", "--block-x", "40", "--block-y", "14"},
         1280,
         520,
         "\"A 512^2 texture in a 256^2's memory\": in {dxt1_bytes[512]} bytes each, DXT1 at 512^2 is "
         "{rms_equal_memory[dxt1_512]} RMS from the picture, RGB565 at 256^2 {rms_equal_memory[rgb565_256]}."},
        {"texture_memory",
         "Seed 001 (texture memory)",
         "An LRU cache of texture tiles along a camera path, with and without prefetching the tiles the view moves "
         "into next; below, a clipmap's size.",
         {"--view", "memory"},
         1024,
         520,
         "A 65536^2 clipmap with 512^2 levels holds {clipmap_texels[65536/512]} "
         "texels, the whole mip chain {chain_texels} "
         "({clipmap_saving} times more); prefetching lifts a 64-tile cache's hit rate from {cache_hit_rate[64]} to "
         "{cache_hit_rate_prefetch[64]}, but a 48-tile one, too small for the view and what it prefetches, falls "
         "from {cache_hit_rate[48]} to {cache_hit_rate_prefetch[48]}."},
    };
  }

  ts::Frame build(int width, int height, const ts::Measurements& measured) const override {
    ts::Frame f = ts::layout::blankFrame(width, height);
    const Result* m = measured.detailAs<Result>();
    if (!m || m->picture != picture_) {
      ts::layout::caption(f, {8, 8, float(width - 8), float(height - 8)}, "compressing ...", ts::layout::kWhite, 2);
      return f;
    }
    const ts::layout::Text numbers = summary(measured);
    const int bx = std::min(bx_, blocksAcross(m->original.width) - 1),
              by = std::min(by_, blocksAcross(m->original.height) - 1);
    if (view_ == 0) views::buildBlocks(f, *m, measured, bx, by, numbers);
    else if (view_ == 1) views::buildEqualMemory(f, *m, measured, bx, by, numbers);
    else views::buildMemory(f, *m, memoryNotes(measured, *m));
    return f;
  }

  ts::Measurements measure(ts::Renderer& r) override;

 private:
  ts::layout::Text summary(const ts::Measurements& ms) const {
    const std::string size = file_.active() ? "file" : "512";
    const std::string shown = file_.active() ? std::string("file") : kPictureNames[picture_];
    return ts::layout::measuredText(
        ms, "{dxt1_bytes[" + size +
                "]|%.0f} bytes ({bits_per_texel|%.0f} bits a texel, "
                "{ratio_vs_rgb565|%.0f}:1 against RGB565, {ratio_vs_rgb888|%.0f}:1 against RGB888); "
                "PSNR {psnr[" +
                shown +
                "]|%.1f} dB; at most {dxt1_max_colours_per_block|%.0f} colours "
                "a block; GL's and the CPU's decodes differ by {gl_vs_cpu_max_diff|%.0f} at most" +
                (picture_ == kNormals && !file_.active()
                     ? "; the normals turn by {normal_error_deg[mean]|%.1f} deg on average, "
                       "{normal_error_deg[max]|%.0f} at most: {normal_error_deg[edge_blocks]|%.1f} "
                       "in blocks on the bricks' edges, {normal_error_deg[flat_blocks]|%.1f} in flat ones"
                     : ""));
  }

  // The memory view's notes: the clipmap against the whole chain, and DXT1's bytes against RGB565's.
  ts::layout::Text memoryNotes(const ts::Measurements& ms, const Result& m) const {
    namespace L = ts::layout;
    auto side = [](const char* what, double v) {
      const L::Text n = L::given(what, v, "%.0f");
      return n + " x " + n;
    };
    L::Text t = "clipmap of a " + side("clipmap: the texture's side, texels", double(kClipmapSide)) + " texture, " +
                side("clipmap: a level's largest side, texels", double(kClipmapLevel)) + " a level: " +
                L::measuredText(ms, "{clipmap_texels[65536/512]|%.0f} texels; the whole chain {chain_texels|%.0f} "
                                    "({clipmap_saving|%.0f} times).  ");
    if (m.fromFile) return t + L::measuredText(ms, "DXT1: the file's picture in {dxt1_bytes[file]|%.0f} bytes.");
    return t + "DXT1: a " + side("the picture's side, texels", m.original.width) + " texture in " +
           L::measuredText(ms, "{dxt1_bytes[512]|%.0f} bytes, as many as a ") +
           side("RGB565 texture's side, texels", 256) + " one's at " + L::given("RGB565: bits a texel", 16, "%.0f") +
           L::measuredText(ms, " bits ({rgb565_bytes[256]|%.0f}).");
  }
  int view_ = 0, picture_ = kPhoto, bx_ = 40, by_ = 14, cpuDecode_ = 0;
  bool three_ = false;
  ts::UserTexture file_;  // --texture FILE: the shown picture
};

ts::Measurements TextureCompression::measure(ts::Renderer& r) {
  Result out;
  ts::Measurements ms;
  out.picture = picture_, out.threeColour = three_;
  // Every picture: PSNR (and the normal map's angles); the shown one kept.
  for (int p = 0; p < kPictureCount; ++p) {
    ts::measureProgress(0.1 + 0.25 * p);
    const bool file = p == picture_ && file_.active();
    const ts::Image img = file ? file_.image() : picture(p);
    const std::string name = file ? "file" : kPictureNames[p], size = file ? "file" : "512";
    std::vector<Block> blocks = encode(img);
    if (three_) blocks = threeColour(blocks, img);
    const ts::Image cpu = decode(blocks, img.width, img.height);
    ms.push_back({"psnr[" + name + "]", psnr(img, cpu), "dB, DXT1 (the CPU decode) against the picture"});
    if (p == kNormals && !file) {
      const glm::dvec2 a = normalAngles(img, cpu);
      ms.push_back({"normal_error_deg[mean]", a.x, "mean angle between the normals before and after DXT1, degrees"});
      ms.push_back({"normal_error_deg[max]", a.y, "largest angle, degrees"});
      const AnglesByBlock where = normalAnglesByBlock(img, cpu);
      ms.push_back({"normal_error_deg[edge_blocks]", where.edge,
                    "mean angle in blocks whose normals turn by more than 15 degrees (a brick's edge), degrees"});
      ms.push_back({"normal_error_deg[flat_blocks]", where.flat,
                    "mean angle in blocks whose normals lie within 15 degrees (the bricks' grain), degrees"});
      if (p == picture_) {
        const int bx = std::min(bx_, blocksAcross(img.width) - 1), by = std::min(by_, blocksAcross(img.height) - 1);
        ms.push_back({"normal_error_deg[shown_block]", blockMaxAngle(img, cpu, bx, by),
                      "largest angle in the block shown, degrees"});
      }
    }
    if (p != picture_) continue;
    GlResult g;
    out.calls = ts::recordRender(r, [&] { g = glRoundTrip(bytes(blocks), img.width, img.height); });
    out.glDecode = g.supported && g.compressed && cpuDecode_ == 0;
    out.original = img, out.blocks = blocks, out.decoded = out.glDecode ? g.decoded : cpu;
    out.name = file ? file_.path().substr(file_.path().find_last_of('/') + 1) : kPictureNames[p];
    out.error = errorImage(img, cpu), out.fromFile = file;
    const double texels = double(img.width) * img.height, bits = 8.0 * double(bytes(blocks).size()) / texels;
    ms.push_back({"s3tc_supported", g.supported ? 1.0 : 0.0,
                  "GL_EXT_texture_compression_s3tc (renderer: " + ts::gl::rendererString() + ")"});
    ms.push_back({"gl_decode_shown", out.glDecode ? 1.0 : 0.0,
                  "1: the picture shows GL's decode; 0: the CPU's (--decode cpu, or no S3TC)"});
    ms.push_back({"dxt1_bytes[" + size + "]", g.supported ? double(g.bytes) : double(bytes(blocks).size()),
                  g.supported ? "GL_TEXTURE_COMPRESSED_IMAGE_SIZE of the DXT1 texture"
                              : "bytes of the blocks (no S3TC in this GL)"});
    if (!file)
      ms.push_back(
          {"rgb565_bytes[256]", 256.0 * 256.0 * 2.0, "a 256 x 256 texture at 16 bits (seed 001: the same memory)"});
    else
      ms.push_back({"padded_texels", double(blocksAcross(img.width) * blocksAcross(img.height) * 16) - texels,
                    "texels the blocks cover beyond the picture (sides padded "
                    "to multiples of 4, the last row and column repeated)"});
    ms.push_back({"bits_per_texel", bits, "of the blocks, over the picture's own texels"});
    ms.push_back({"ratio_vs_rgb565", 16.0 / bits, "16-bit texels : DXT1"});
    ms.push_back({"ratio_vs_rgb888", 24.0 / bits, "24-bit texels : DXT1"});
    ms.push_back({"dxt1_max_colours_per_block", double(maxColoursPerBlock(out.decoded)),
                  "distinct colours in any decoded 4x4 block"});
    ms.push_back({"gl_vs_cpu_max_diff", g.supported && g.compressed ? double(maxDiff(g.decoded, cpu)) : -1.0,
                  "largest channel difference, GL's decode against dxt1.hpp's (8-bit levels; -1: no S3TC)"});
    out.rgb565 = rgb565Half(img), out.rmsDxt1 = rms(img, cpu), out.rmsRgb565 = rms(img, out.rgb565);
    ms.push_back({"rms_equal_memory[dxt1_" + size + "]", out.rmsDxt1, "RMS against the picture: DXT1 at full size"});
    ms.push_back({"rms_equal_memory[rgb565_" + std::string(file ? "half" : "256") + "]", out.rmsRgb565,
                  "RMS: half the size at RGB565 (the same bytes), magnified bilinearly back"});
  }
  ts::measureProgress(0.85);
  for (int n : cacheSizes()) out.plain.push_back(lruRun(n, false)), out.prefetched.push_back(lruRun(n, true));
  for (size_t k = 0; k < cacheSizes().size(); ++k) {
    const std::string n = "[" + std::to_string(cacheSizes()[k]) + "]";
    ms.push_back({"cache_hit_rate" + n, out.plain[k].hitRate(), "LRU tile cache of this many tiles: hits / requests"});
    ms.push_back(
        {"cache_hit_rate_prefetch" + n, out.prefetched[k].hitRate(), "the same, prefetching the next column and row"});
  }
  static_assert(kClipmapSide == 65536 && kClipmapLevel == 512, "the measurements' names say 65536/512");
  ms.push_back({"clipmap_texels[65536/512]", double(clipmapTexels(kClipmapSide, kClipmapLevel)),
                "a 65536^2 texture's mip chain, each level at most 512^2"});
  ms.push_back({"chain_texels", double(chainTexels(kClipmapSide)), "the whole mip chain of 65536^2"});
  ms.push_back({"clipmap_saving",
                double(chainTexels(kClipmapSide)) / double(clipmapTexels(kClipmapSide, kClipmapLevel)),
                "chain / clipmap"});
  ms.detail = out;
  return ms;
}
}  // namespace

TS_REGISTER_SCENE(TextureCompression);
