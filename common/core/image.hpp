// common/core/image.hpp — an RGBA8 image in memory, PNG in and out.
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
  // (0,0) = top-left.  Inline: the figures' loops call these once a pixel.
  Rgba at(int x, int y) const {
    const uint8_t* p = &pixels[(size_t(y) * size_t(width) + size_t(x)) * 4];
    return {p[0], p[1], p[2], p[3]};
  }
  void set(int x, int y, Rgba c) {  // outside the image: nothing
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    uint8_t* p = &pixels[(size_t(y) * size_t(width) + size_t(x)) * 4];
    p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = c.a;
  }
  // Copies `src` into this image with its top-left at (x, y), clipped.
  void blit(const Image& src, int x, int y);
  void flipVertical();
};

// Two images of one size compared over R, G and B (alpha left out): the
// largest difference in 8-bit levels, and the root mean square difference.
int maxChannelDiff(const Image& a, const Image& b);
double rmsRgb(const Image& a, const Image& b);

// Largest width or height any image of the suite may have; checked before any
// allocation (flags and files alike).
constexpr int kMaxImageDimension = 16384;
// Images read from files are also limited in pixels (64 Mi pixels = 256 MiB
// as RGBA8) and files in bytes, both checked before the pixels are allocated.
constexpr int64_t kMaxFilePixels = int64_t(1) << 26;
constexpr size_t kMaxImageFileBytes = size_t(512) << 20;

// Writes a PNG deterministically (fixed zlib level, no time or text chunks),
// atomically: into "<path>.tmp-<pid>" in the same directory, then rename().
// An unwritable path throws ts::Error naming the path; no file is left.
void writePng(const std::string& path, const Image& img);
// Encodes to memory (used by writePng and the benchmark).
std::vector<uint8_t> encodePng(const Image& img);
// Reads any PNG (grey, grey+alpha, palette, RGB, RGBA; 1..16 bits; tRNS;
// interlaced or not) and converts to RGBA8 (16-bit channels keep their high
// byte).  Throws ts::Error "<path>: <what is wrong>" on a missing, unreadable
// or malformed file; never crashes, whatever the bytes.
Image readPng(const std::string& path);
// The same from memory; `name` is what error messages call the data.
Image decodePng(const uint8_t* data, size_t size, const std::string& name);
// PNG, JPEG (common/core/jpeg.hpp) or 24/32-bit BMP (common/core/bmp.hpp), recognised
// by the first bytes, not by the file name.
Image readImage(const std::string& path);
Image decodeImage(const uint8_t* data, size_t size, const std::string& name);

// A whole regular file in memory.  Refuses, with "<path>: <reason>", what
// cannot be opened, a directory, a FIFO or device, an empty file and a file
// over `limit` bytes (before reading it).
std::vector<uint8_t> readFileBytes(const std::string& path, size_t limit = kMaxImageFileBytes);
// "" when w x h is within the limits above, else why not (for messages).
std::string checkImageSize(uint64_t w, uint64_t h);

// Writes `bytes` to `path` atomically: the content goes to an unnamed file
// (O_TMPFILE) in the same directory, which is then linked as a temporary
// name and renamed over `path`, so an interrupted run leaves either the old
// file or the whole new one, never a half-written one.  Throws ts::Error
// "cannot write <path>: <reason>" and leaves nothing behind on failure.
void writeFileAtomic(const std::string& path, const std::string& bytes);
}  // namespace ts
