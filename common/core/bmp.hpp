// common/core/bmp.hpp — 24-bit uncompressed Windows BMP files, the format the
// book's own code (Buss's RgbImage) reads, and 32-bit ones (B, G, R, A, or
// any channel order given by BI_BITFIELDS / BI_ALPHABITFIELDS masks; alpha
// kept unless every pixel's is 0, which writers use for "unused").  Every
// header field is checked against the file's length before a pixel is read;
// anything else (other bit depths, RLE, OS/2 headers) is refused with a
// message saying what the file is.
#pragma once
#include <cstdint>
#include <string>

#include "common/core/image.hpp"

namespace ts {
// Decodes a BMP held in memory into RGBA8 (alpha 255), row 0 = the top row,
// whether the file stores rows bottom-up (positive height) or top-down
// (negative height).  Throws ts::Error "<name>: <what is wrong>".
Image decodeBmp(const uint8_t* data, size_t size, const std::string& name);
// Reads a file (see readFileBytes for what is refused) and decodes it.
Image readBmp(const std::string& path);
// Encodes a 24-bit bottom-up BMP (alpha dropped); used by tests and fuzz seeds.
std::vector<uint8_t> encodeBmp32(const Image& img, bool bitfields);  // with alpha
std::vector<uint8_t> encodeBmp(const Image& img);
}  // namespace ts
