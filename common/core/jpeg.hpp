// common/core/jpeg.hpp — JPEG files through libjpeg-turbo (Debian's libjpeg62-turbo).
// libjpeg's own error handler calls exit(); this one longjmps back and
// throws ts::Error "<name>: malformed JPEG: <libjpeg's reason>", so a bad
// file is one line and exit status 2 like any other.  Sizes over the limits
// of image.hpp are refused from the header, before the pixels are allocated;
// corrupt data libjpeg would decode with a warning is refused too.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "common/core/image.hpp"

namespace ts {
// Decodes baseline or progressive JPEG (grey or YCbCr, 8-bit) to RGBA8,
// alpha 255, row 0 = the top row.  CMYK files are refused with a message.
Image decodeJpeg(const uint8_t* data, size_t size, const std::string& name);
// Encodes RGB (alpha dropped, 4:4:4) at `quality` 1..100; for tests and seeds.
std::vector<uint8_t> encodeJpeg(const Image& img, int quality = 90);
}  // namespace ts
