// common/image.hpp — an RGBA8 image in memory, PNG in and out.
// Rows are stored top to bottom (as in a PNG file); GL readback is flipped
// once, in Context::readPixels, so nothing else has to think about it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace ts {
struct Rgba {
  uint8_t r = 0, g = 0, b = 0, a = 255;
  bool operator==(const Rgba& o) const { return r == o.r && g == o.g && b == o.b && a == o.a; }
  bool operator!=(const Rgba& o) const { return !(*this == o); }
};

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // width*height*4, row 0 = top

  Image() = default;
  Image(int w, int h, Rgba fill = {0, 0, 0, 255});
  bool empty() const { return width == 0 || height == 0; }
  Rgba at(int x, int y) const;  // (0,0) = top-left
  void set(int x, int y, Rgba c);
  // Copies `src` into this image with its top-left at (x, y), clipped.
  void blit(const Image& src, int x, int y);
  void flipVertical();
};

// Largest width or height any image of the suite may have; checked before any
// allocation (flags and files alike).
constexpr int kMaxImageDimension = 16384;

// Writes a PNG deterministically (fixed zlib level, no time or text chunks),
// atomically: into "<path>.tmp-<pid>" in the same directory, then rename().
// An unwritable path throws ts::Error naming the path; no file is left.
void writePng(const std::string& path, const Image& img);
// Encodes to memory (used by writePng and the benchmark).
std::vector<uint8_t> encodePng(const Image& img);
// Reads any PNG libpng understands and converts to RGBA8.  Throws ts::Error
// "<path>: <what is wrong>" on a missing, unreadable or malformed file.
Image readPng(const std::string& path);

// Writes `bytes` to `path` atomically (temporary file, then rename).
void writeFileAtomic(const std::string& path, const std::string& bytes);
}  // namespace ts
