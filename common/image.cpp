#include "image.hpp"

#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>

#include "error.hpp"

namespace ts {
Image::Image(int w, int h, Rgba fill) : width(w), height(h) {
  if (w < 0 || h < 0 || w > kMaxImageDimension || h > kMaxImageDimension)
    throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range");
  pixels.resize(size_t(w) * size_t(h) * 4);
  for (size_t i = 0; i < pixels.size(); i += 4) {
    pixels[i] = fill.r; pixels[i + 1] = fill.g; pixels[i + 2] = fill.b; pixels[i + 3] = fill.a;
  }
}

Rgba Image::at(int x, int y) const {
  const uint8_t* p = &pixels[(size_t(y) * width + x) * 4];
  return {p[0], p[1], p[2], p[3]};
}

void Image::set(int x, int y, Rgba c) {
  if (x < 0 || y < 0 || x >= width || y >= height) return;
  uint8_t* p = &pixels[(size_t(y) * width + x) * 4];
  p[0] = c.r; p[1] = c.g; p[2] = c.b; p[3] = c.a;
}

void Image::blit(const Image& src, int x0, int y0) {
  for (int y = 0; y < src.height; ++y) {
    int dy = y0 + y;
    if (dy < 0 || dy >= height) continue;
    int xs = std::max(0, -x0), xe = std::min(src.width, width - x0);
    if (xs >= xe) continue;
    std::memcpy(&pixels[(size_t(dy) * width + x0 + xs) * 4], &src.pixels[(size_t(y) * src.width + xs) * 4],
                size_t(xe - xs) * 4);
  }
}

void Image::flipVertical() {
  size_t row = size_t(width) * 4;
  std::vector<uint8_t> tmp(row);
  for (int y = 0; y < height / 2; ++y) {
    uint8_t* a = &pixels[size_t(y) * row];
    uint8_t* b = &pixels[size_t(height - 1 - y) * row];
    std::memcpy(tmp.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, tmp.data(), row);
  }
}

namespace {
struct PngFailure {
  std::string what;
};
void pngError(png_structp png, png_const_charp msg) {
  // libpng requires this not to return; throwing through C frames is not
  // safe, so we longjmp back as libpng documents.
  auto* why = static_cast<std::string*>(png_get_error_ptr(png));
  if (why) *why = msg ? msg : "libpng error";
  png_longjmp(png, 1);
}
void pngWarning(png_structp, png_const_charp) {}  // warnings stay quiet

void appendBytes(png_structp png, png_bytep data, png_size_t len) {
  auto* out = static_cast<std::vector<uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + len);
}
void flushNothing(png_structp) {}
}  // namespace

std::vector<uint8_t> encodePng(const Image& img) {
  if (img.empty()) throw Error("cannot encode an empty image", kExitFailure);
  std::vector<uint8_t> out;
  std::string why;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &why, pngError, pngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    throw Error("out of memory encoding PNG", kExitFailure);
  }
  std::vector<png_bytep> rows(size_t(img.height));  // allocated before setjmp
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error("PNG encoding failed: " + why, kExitFailure);
  }
  png_set_write_fn(png, &out, appendBytes, flushNothing);
  // Fixed settings so the same pixels always give the same bytes.
  png_set_compression_level(png, 6);
  png_set_filter(png, 0, PNG_FILTER_SUB | PNG_FILTER_UP | PNG_FILTER_PAETH);
  png_set_IHDR(png, info, png_uint_32(img.width), png_uint_32(img.height), 8, PNG_COLOR_TYPE_RGBA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  for (int y = 0; y < img.height; ++y)
    rows[size_t(y)] = const_cast<png_bytep>(&img.pixels[size_t(y) * img.width * 4]);
  png_set_rows(png, info, rows.data());
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

void writeFileAtomic(const std::string& path, const std::string& bytes) {
  std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw Error("cannot write " + path + ": " + std::strerror(errno));
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  ok = (std::fflush(f) == 0) && ok;
  ok = (std::fclose(f) == 0) && ok;
  if (!ok) {
    int e = errno;
    std::remove(tmp.c_str());
    throw Error("cannot write " + path + ": " + std::strerror(e));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    int e = errno;
    std::remove(tmp.c_str());
    throw Error("cannot write " + path + ": " + std::strerror(e));
  }
}

void writePng(const std::string& path, const Image& img) {
  std::vector<uint8_t> bytes = encodePng(img);
  writeFileAtomic(path, std::string(bytes.begin(), bytes.end()));
}

Image readPng(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!f) throw Error(path + ": cannot open: " + std::strerror(errno));
  unsigned char sig[8];
  if (std::fread(sig, 1, 8, f.get()) != 8 || png_sig_cmp(sig, 0, 8) != 0)
    throw Error(path + ": not a PNG file (bad signature)");
  std::string why;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &why, pngError, pngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw Error(path + ": out of memory");
  }
  // Everything with a destructor lives outside the setjmp/longjmp region.
  Image img;
  std::vector<png_bytep> rows;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw Error(path + ": malformed PNG: " + why);
  }
  png_init_io(png, f.get());
  png_set_sig_bytes(png, 8);
  png_set_user_limits(png, kMaxImageDimension, kMaxImageDimension);  // refuse before allocating
  png_read_info(png, info);
  png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
  int depth = png_get_bit_depth(png, info), type = png_get_color_type(png, info);
  if (depth == 16) png_set_strip_16(png);
  if (type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (type == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if (type == PNG_COLOR_TYPE_GRAY || type == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
  if (!(type & PNG_COLOR_MASK_ALPHA) && !png_get_valid(png, info, PNG_INFO_tRNS))
    png_set_filler(png, 0xff, PNG_FILLER_AFTER);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (png_get_rowbytes(png, info) != size_t(w) * 4) longjmp(png_jmpbuf(png), 1);
  img.width = int(w);
  img.height = int(h);
  img.pixels.resize(size_t(w) * h * 4);
  rows.resize(h);
  for (png_uint_32 y = 0; y < h; ++y) rows[y] = &img.pixels[size_t(y) * w * 4];
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return img;
}
}  // namespace ts
