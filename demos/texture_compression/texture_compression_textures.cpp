// demos/texture_compression/texture_compression_textures.cpp — see texture_compression_textures.hpp.
#include "demos/texture_compression/texture_compression_textures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "common/core/error.hpp"
#include "common/core/relief_maps.hpp"
#include "common/core/texture_generators.hpp"
#include "common/core/textures.hpp"

namespace ts::dxt1 {
Image picture(int which) {
  if (which == kChecker) return *checkerboard(512, 16).image;
  const relief::Relief rel = relief::makeRelief("bricks");
  if (which == kPhoto) return rel.albedo[0];
  const Image& h = rel.height[0];
  Image out(h.width, h.height);
  auto at = [&](int x, int y) { return h.at((x + h.width) % h.width, (y + h.height) % h.height).r / 255.0; };
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) {
      const glm::dvec3 n = glm::normalize(
          glm::dvec3(-4 * (at(x + 1, y) - at(x - 1, y)), -4 * (at(x, y + 1) - at(x, y - 1)), 1.0));
      auto u8 = [](double v) { return uint8_t(std::lround(std::clamp(127.5 * (v + 1.0), 0.0, 255.0))); };
      out.set(x, y, {u8(n.x), u8(n.y), u8(n.z), 255});
    }
  return out;
}

std::vector<Block> threeColour(const std::vector<Block>& blocks, const Image& img) {
  std::vector<Block> out = blocks;
  for (size_t k = 0; k < out.size(); ++k) {
    Block& b = out[k];
    if (b.c0 > b.c1) std::swap(b.c0, b.c1);
    assign(&b, blockTexels(img, int(k) % blocksAcross(img.width), int(k) / blocksAcross(img.width)));
  }
  return out;
}

Image rgb565Half(const Image& img) {
  Image half(std::max(1, img.width / 2), std::max(1, img.height / 2));
  for (int y = 0; y < half.height; ++y)
    for (int x = 0; x < half.width; ++x) {
      glm::dvec3 s(0.0);
      for (int k = 0; k < 4; ++k) {
        const Rgba c = img.at(std::min(2 * x + k % 2, img.width - 1), std::min(2 * y + k / 2, img.height - 1));
        s += glm::dvec3(c.r, c.g, c.b) / 4.0;
      }
      const glm::ivec3 q = unpack565(pack565(s));
      half.set(x, y, {uint8_t(q.r), uint8_t(q.g), uint8_t(q.b), 255});
    }
  return resizeBilinear(half, img.width, img.height);
}

Image errorImage(const Image& img, const Image& decoded) {
  Image e(img.width, img.height);
  for (size_t k = 0; k < img.pixels.size(); ++k)
    e.pixels[k] = k % 4 == 3 ? 255 : uint8_t(std::min(255, 8 * std::abs(int(img.pixels[k]) - int(decoded.pixels[k]))));
  return e;
}

namespace {
const char* const kShowNames[] = {"original", "decoded_gl", "decoded_cpu", "error", "rgb565"};

// The whole picture `show` makes, rows from the top.
Image made(int which, bool three, Show show) {
  const Image img = picture(which);
  if (show == Show::Original) return img;
  if (show == Show::Rgb565) return rgb565Half(img);
  std::vector<Block> blocks = encode(img);
  if (three) blocks = threeColour(blocks, img);
  Image cpu = decode(blocks, img.width, img.height);
  if (show == Show::Error) return errorImage(img, cpu);
  // GL_COMPRESSED_RGB_S3TC_DXT1_EXT has no alpha: the 3-colour mode's black
  // reads back opaque; dxt1.hpp's decode marks it with alpha 0.
  if (show == Show::DecodedGl)
    for (size_t k = 3; k < cpu.pixels.size(); k += 4) cpu.pixels[k] = 255;
  return cpu;
}

Image cropOf(const Image& img, Crop c) {
  if (c.w == 0) return img;
  Image out(c.w, c.h);
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x) out.set(x, y, img.at(c.x + x, c.y + y));
  return out;
}
}  // namespace

TextureDesc pictureTexture(int which, bool three, Show show, Crop crop, const Image& shown) {
  TextureDesc t;
  t.name = "dxt1_picture";
  t.params = {{"picture", kPictureNames[which]},
              {"three_colour", three ? "1" : "0"},
              {"show", kShowNames[int(show)]},
              {"crop", crop.w == 0 ? "all"
                                   : std::to_string(crop.x) + "," + std::to_string(crop.y) + "," +
                                         std::to_string(crop.w) + "," + std::to_string(crop.h)}};
  Image flipped = shown;
  flipped.flipVertical();  // texture row 0 is t = 0, the bottom
  t.image = std::make_shared<const Image>(std::move(flipped));
  return t;
}

bool remake(const std::string& name, const std::vector<std::pair<std::string, std::string>>& p, TextureDesc* out) {
  if (name != "dxt1_picture") return false;
  auto param = [&](const char* key) -> std::string {
    for (const auto& [k, v] : p)
      if (k == key) return v;
    throw Error(name + ": missing param '" + key + "'");
  };
  auto oneOf = [&](const char* key, const char* const* names, int n) {
    const std::string v = param(key);
    for (int k = 0; k < n; ++k)
      if (v == names[k]) return k;
    throw Error(name + ": param '" + key + "' is not one the generator knows ('" + v + "')");
  };
  const int which = oneOf("picture", kPictureNames, kPictureCount);
  const std::string three = param("three_colour");
  if (three != "0" && three != "1") throw Error(name + ": param 'three_colour' must be 0 or 1");
  const Show show = Show(oneOf("show", kShowNames, 5));
  Crop c;
  const std::string cs = param("crop");
  if (cs != "all") {
    char tail = 0;
    if (std::sscanf(cs.c_str(), "%d,%d,%d,%d%c", &c.x, &c.y, &c.w, &c.h, &tail) != 4 || c.x < 0 || c.y < 0 || c.w < 1 ||
        c.h < 1 || c.x + c.w > 512 || c.y + c.h > 512)
      throw Error(name + ": param 'crop' must be 'all' or x,y,w,h inside the 512 x 512 picture");
  }
  const Image whole = made(which, three == "1", show);
  if (c.w > whole.width - c.x || c.h > whole.height - c.y) throw Error(name + ": the crop leaves the picture");
  *out = pictureTexture(which, three == "1", show, c, cropOf(whole, c));
  if (show == Show::DecodedGl) out->texelSlack = 1.0f;  // the extension's fractions: texture_compression_textures.hpp
  return true;
}
}  // namespace ts::dxt1

// The sidecar reader finds it through the registry (common/core/texture_generators.hpp).
TS_REGISTER_TEXTURE_GENERATOR("dxt1_picture", ts::dxt1::remake);
