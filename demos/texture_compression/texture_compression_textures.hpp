// demos/texture_compression/texture_compression_textures.hpp — the texture-compression demo's pictures
// (seed 001 ¶19–24) as a named generator, so that a figure's sidecar alone
// remakes them (reference/sidecar_reader.cpp's remakeTexture, through the generator
// registry: texture_compression_textures.cpp registers it): the 512 x 512
// picture, its DXT1 decode, the error, and the same memory at RGB565, whole
// or a crop of them.  The codec itself is common/core/dxt1.hpp.
//
// GL's decode and the CPU's: the S3TC extension gives the palette as
// fractions (c2 = 2/3 c0 + 1/3 c1, the RGB565 ends as c/31, c/63), not as an
// integer rounding, so a driver's decode may differ from dxt1.hpp's by one
// 8-bit level (Mesa's does: the demo's gl_vs_cpu_max_diff = 1).  A remade
// "decoded_gl" picture therefore carries TextureDesc::texelSlack = 1: the
// reference allows its texels one level either way.
#pragma once
#include <string>
#include <vector>

#include "common/core/dxt1.hpp"
#include "common/core/frame.hpp"
#include "common/core/image.hpp"

namespace ts::dxt1 {
enum Picture : int { kPhoto, kChecker, kNormals, kPictureCount };
inline const char* const kPictureNames[] = {"photo", "checker", "normals"};

// 512 x 512: the parallax demo's bricks (a photograph's variety of colour),
// a checkerboard, and a normal map made from the bricks' heights
// (n = normalize(-4 dh/dx, -4 dh/dy, 1), stored as 127.5 (n + 1)).
Image picture(int which);
// Every block turned to the 3-colour mode (c0 <= c1: the palette's third
// colour the midpoint, the fourth black), its indices chosen again.
std::vector<Block> threeColour(const std::vector<Block>& blocks, const Image& img);
// 256 x 256 at 16 bits, the memory of 512 x 512 in DXT1: each 2x2 averaged,
// quantised to RGB565, then magnified back to 512 x 512 (bilinear).
Image rgb565Half(const Image& img);
// |picture - decode| x 8 per channel (alpha 255): the error the demo shows.
Image errorImage(const Image& img, const Image& decoded);

// What a "dxt1_picture" texture shows of a picture.
enum class Show { Original, DecodedGl, DecodedCpu, Error, Rgb565 };
// The crop of the picture shown (x, y from its top left); w = 0: all of it.
struct Crop {
  int x = 0, y = 0, w = 0, h = 0;
};
// The texture "dxt1_picture" of `shown` (rows from the top, as the demo
// holds it), params: picture, three_colour, show, crop.  `shown` must be
// what those params make (for DecodedGl: GL's decode, which the remade CPU
// decode matches within texelSlack).  Filters and wraps: the caller's.
TextureDesc pictureTexture(int which, bool three, Show show, Crop crop, const Image& shown);
// The generator `name` with `params` (as the sidecar records them); false
// when `name` is not "dxt1_picture".  Throws ts::Error on a bad param.
bool remake(const std::string& name, const std::vector<std::pair<std::string, std::string>>& params, TextureDesc* out);
}  // namespace ts::dxt1
