#include "bmp.hpp"

#include <cstring>

#include "error.hpp"

namespace ts {
namespace {
uint32_t le32(const uint8_t* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24; }
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
  if (infoSize == 12) throw Error(name + ": unsupported BMP: OS/2 (BITMAPCOREHEADER) files are not read; save as 24-bit Windows BMP");
  if (infoSize < 40 || infoSize > 1024) throw bad("info header size " + std::to_string(infoSize) + " is not a Windows BITMAPINFOHEADER (40..124)");
  if (size < 14 + size_t(infoSize)) throw bad("the file ends inside the info header (truncated)");
  const uint8_t* ih = data + 14;
  int32_t width = int32_t(le32(ih + 4)), height = int32_t(le32(ih + 8));
  uint16_t planes = le16(ih + 12), bits = le16(ih + 14);
  uint32_t compression = le32(ih + 16);
  if (planes != 1) throw bad("planes is " + std::to_string(planes) + ", must be 1");
  if (bits != 24)
    throw Error(name + ": unsupported BMP: " + std::to_string(bits) + " bits per pixel (only 24-bit BMP is read)");
  if (compression != 0)
    throw Error(name + ": unsupported BMP: compression " + std::to_string(compression) + " (only uncompressed BI_RGB is read)");
  if (width < 0) throw bad("negative width " + std::to_string(width) + " in the header");
  bool topDown = height < 0;
  uint64_t w = uint64_t(int64_t(width)), h = topDown ? uint64_t(-int64_t(height)) : uint64_t(height);
  std::string sizeProblem = checkImageSize(w, h);
  if (!sizeProblem.empty()) throw bad(sizeProblem);
  uint64_t stride = (w * 3 + 3) / 4 * 4;  // rows are padded to 4 bytes
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
  for (uint64_t y = 0; y < h; ++y) {
    const uint8_t* src = data + pixelOffset + stride * (topDown ? y : h - 1 - y);
    uint8_t* dst = &img.pixels[size_t(y * w * 4)];
    for (uint64_t x = 0; x < w; ++x) {  // stored blue, green, red
      dst[4 * x] = src[3 * x + 2];
      dst[4 * x + 1] = src[3 * x + 1];
      dst[4 * x + 2] = src[3 * x];
      dst[4 * x + 3] = 255;
    }
  }
  return img;
}

Image readBmp(const std::string& path) {
  std::vector<uint8_t> bytes = readFileBytes(path);
  return decodeBmp(bytes.data(), bytes.size(), path);
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
