#include "common/core/bmp.hpp"

#include <cstdio>
#include <cstring>

#include "common/core/error.hpp"

namespace ts {
namespace {
uint32_t le32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}
uint16_t le16(const uint8_t* p) { return uint16_t(p[0] | p[1] << 8); }
void put32(std::vector<uint8_t>& v, uint32_t x) {
  for (int k = 0; k < 4; ++k) v.push_back(uint8_t(x >> (8 * k)));
}
void put16(std::vector<uint8_t>& v, uint16_t x) {
  v.push_back(uint8_t(x));
  v.push_back(uint8_t(x >> 8));
}
}  // namespace

Image decodeBmp(const uint8_t* data, size_t size, const std::string& name) {
  auto bad = [&](const std::string& what) { return Error(name + ": malformed BMP: " + what); };
  if (size < 2 || data[0] != 'B' || data[1] != 'M') throw Error(name + ": not a BMP file (bad signature)");
  // BITMAPFILEHEADER (14 bytes) + at least the 4-byte size of the info header.
  if (size < 18) throw bad("the file ends inside the file header (truncated)");
  uint32_t pixelOffset = le32(data + 10);
  uint32_t infoSize = le32(data + 14);
  if (infoSize == 12)
    throw Error(name + ": unsupported BMP: OS/2 (BITMAPCOREHEADER) files are not read; save as 24-bit Windows BMP");
  if (infoSize < 40 || infoSize > 1024)
    throw bad("info header size " + std::to_string(infoSize) + " is not a Windows BITMAPINFOHEADER (40..124)");
  if (size < 14 + size_t(infoSize)) throw bad("the file ends inside the info header (truncated)");
  const uint8_t* ih = data + 14;
  int32_t width = int32_t(le32(ih + 4)), height = int32_t(le32(ih + 8));
  uint16_t planes = le16(ih + 12), bits = le16(ih + 14);
  uint32_t compression = le32(ih + 16);
  if (planes != 1) throw bad("planes is " + std::to_string(planes) + ", must be 1");
  if (bits != 24 && bits != 32)
    throw Error(name + ": unsupported BMP: " + std::to_string(bits) + " bits per pixel (24- and 32-bit BMP are read)");
  // 32-bit pixels: BI_RGB is B, G, R, A in that byte order; BI_BITFIELDS (3)
  // and BI_ALPHABITFIELDS (6) say where each channel lies with masks, held in
  // the V3..V5 header or, after a 40-byte header, in the 12 (16) bytes after it.
  uint32_t mask[4] = {0x00ff0000u, 0x0000ff00u, 0x000000ffu, 0xff000000u};  // R, G, B, A
  bool bitfields = compression == 3 || compression == 6;
  if (compression != 0 && !(bits == 32 && bitfields))
    throw Error(name + ": unsupported BMP: compression " + std::to_string(compression) + " with " +
                std::to_string(bits) + " bits per pixel (uncompressed BI_RGB, or BI_BITFIELDS at 32 bits, is read)");
  if (bitfields) {
    size_t at = infoSize >= 52 ? 14 + 40 : 14 + size_t(infoSize);
    int count = (infoSize >= 56 || compression == 6) ? 4 : 3;
    if (size < at + 4 * size_t(count)) throw bad("the file ends inside the bitfield masks (truncated)");
    for (int c = 0; c < 4; ++c) mask[c] = c < count ? le32(data + at + 4 * size_t(c)) : 0;
    for (int c = 0; c < 4; ++c) {
      uint32_t m = mask[c];
      if (m && ((m >> __builtin_ctz(m)) & ((m >> __builtin_ctz(m)) + 1)) != 0) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%08x", unsigned(m));
        throw bad(std::string("bitfield mask ") + hex + " is not one run of bits");
      }
      for (int d = 0; d < c; ++d)
        if (m & mask[d]) throw bad("bitfield masks overlap");
    }
    if (!mask[0] && !mask[1] && !mask[2]) throw bad("the red, green and blue masks are all zero");
  }
  if (width < 0) throw bad("negative width " + std::to_string(width) + " in the header");
  bool topDown = height < 0;
  uint64_t w = uint64_t(int64_t(width)), h = topDown ? uint64_t(-int64_t(height)) : uint64_t(height);
  std::string sizeProblem = checkImageSize(w, h);
  if (!sizeProblem.empty()) throw bad(sizeProblem);
  uint64_t bpp = bits / 8, stride = (w * bpp + 3) / 4 * 4;  // rows are padded to 4 bytes
  uint64_t need = stride * h;
  if (pixelOffset < 14 + uint64_t(infoSize) || pixelOffset > size)
    throw bad("pixel data offset " + std::to_string(pixelOffset) + " lies outside the file (" + std::to_string(size) +
              " bytes)");
  if (size - pixelOffset < need)
    throw bad("truncated: " + std::to_string(w) + "x" + std::to_string(h) + " pixels need " + std::to_string(need) +
              " bytes after offset " + std::to_string(pixelOffset) + ", the file has " +
              std::to_string(size - pixelOffset));
  Image img;
  img.width = int(w);
  img.height = int(h);
  img.pixels.resize(size_t(w) * size_t(h) * 4);
  // A channel under mask m, scaled to 0..255 (a 5-bit field 31 -> 255).
  auto channel = [](uint32_t px, uint32_t m) -> uint8_t {
    if (!m) return 255;
    int shift = __builtin_ctz(m);
    uint32_t maxv = m >> shift, v = (px & m) >> shift;
    return uint8_t((uint64_t(v) * 255 + maxv / 2) / maxv);
  };
  bool anyAlpha = false;
  for (uint64_t y = 0; y < h; ++y) {
    const uint8_t* src = data + pixelOffset + stride * (topDown ? y : h - 1 - y);
    uint8_t* dst = &img.pixels[size_t(y * w * 4)];
    for (uint64_t x = 0; x < w; ++x) {
      if (bits == 24) {  // stored blue, green, red
        dst[4 * x] = src[3 * x + 2];
        dst[4 * x + 1] = src[3 * x + 1];
        dst[4 * x + 2] = src[3 * x];
        dst[4 * x + 3] = 255;
        continue;
      }
      uint32_t px = le32(src + 4 * x);
      for (int c = 0; c < 4; ++c) dst[4 * x + size_t(c)] = channel(px, mask[c]);
      anyAlpha |= mask[3] && (px & mask[3]) != 0;
    }
  }
  // Many writers leave the fourth byte of a plain 32-bit BMP zero ("unused"):
  // an all-zero alpha means no alpha, not an invisible picture.
  if (bits == 32 && !anyAlpha)
    for (size_t i = 3; i < img.pixels.size(); i += 4) img.pixels[i] = 255;
  return img;
}

Image readBmp(const std::string& path) {
  std::vector<uint8_t> bytes = readFileBytes(path);
  return decodeBmp(bytes.data(), bytes.size(), path);
}

std::vector<uint8_t> encodeBmp32(const Image& img, bool bitfields) {
  if (img.empty()) throw Error("cannot encode an empty image", kExitFailure);
  // BITMAPV4HEADER-free: a 40-byte header, then (bitfields) the R, G, B, A
  // masks in a nonstandard order to prove the masks are read: A R G B from
  // the high byte down is 0xAARRGGBB as BI_RGB; here R is in the low byte.
  const uint32_t masks[4] = {0x000000ffu, 0x0000ff00u, 0x00ff0000u, 0xff000000u};
  uint32_t header = 54 + (bitfields ? 16 : 0), pixels = uint32_t(img.width) * 4 * uint32_t(img.height);
  std::vector<uint8_t> out{'B', 'M'};
  put32(out, header + pixels);
  put32(out, 0);
  put32(out, header);
  put32(out, 40);
  put32(out, uint32_t(img.width));
  put32(out, uint32_t(img.height));
  put16(out, 1);
  put16(out, 32);
  put32(out, bitfields ? 6 : 0);  // BI_ALPHABITFIELDS: four masks follow the header
  put32(out, pixels);
  put32(out, 2835);
  put32(out, 2835);
  put32(out, 0);
  put32(out, 0);
  if (bitfields)
    for (uint32_t m : masks) put32(out, m);
  for (int y = img.height - 1; y >= 0; --y)
    for (int x = 0; x < img.width; ++x) {
      Rgba c = img.at(x, y);
      if (bitfields) out.insert(out.end(), {c.r, c.g, c.b, c.a});
      else out.insert(out.end(), {c.b, c.g, c.r, c.a});
    }
  return out;
}

std::vector<uint8_t> encodeBmp(const Image& img) {
  if (img.empty()) throw Error("cannot encode an empty image", kExitFailure);
  uint32_t stride = (uint32_t(img.width) * 3 + 3) / 4 * 4, pixels = stride * uint32_t(img.height);
  std::vector<uint8_t> out{'B', 'M'};
  put32(out, 54 + pixels);
  put32(out, 0);
  put32(out, 54);
  put32(out, 40);
  put32(out, uint32_t(img.width));
  put32(out, uint32_t(img.height));
  put16(out, 1);
  put16(out, 24);
  put32(out, 0);
  put32(out, pixels);
  put32(out, 2835);  // 72 dpi
  put32(out, 2835);
  put32(out, 0);
  put32(out, 0);
  for (int y = img.height - 1; y >= 0; --y) {
    for (int x = 0; x < img.width; ++x) {
      Rgba c = img.at(x, y);
      out.insert(out.end(), {c.b, c.g, c.r});
    }
    while ((out.size() - 54) % 4) out.push_back(0);
  }
  return out;
}
}  // namespace ts
