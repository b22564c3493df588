#include "common/core/jpeg.hpp"

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>

// jpeglib.h needs size_t and FILE declared first.
#include <jpeglib.h>

#include "common/core/error.hpp"

namespace ts {
namespace {
// libjpeg's default error handler prints and calls exit(); ours keeps the
// message and longjmps back to decodeJpeg, which throws ts::Error.
struct ErrorManager {
  jpeg_error_mgr pub;
  std::jmp_buf back;
  char message[JMSG_LENGTH_MAX];
};
void onError(j_common_ptr cinfo) {
  auto* err = reinterpret_cast<ErrorManager*>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, err->message);
  std::longjmp(err->back, 1);
}
// Warnings (corrupt data that libjpeg can still decode) are errors here: a
// picture with "premature end of data" would show grey blocks silently.
void onMessage(j_common_ptr cinfo, int level) {
  if (level < 0) onError(cinfo);
}
// A progressive file may hold thousands of tiny scans, each a pass over the
// whole coefficient buffer (a few hundred bytes that take minutes): more
// scans than any encoder writes are refused.
constexpr int kMaxScans = 256;
struct Progress {
  jpeg_progress_mgr pub;
  ErrorManager* err;
};
void onProgress(j_common_ptr cinfo) {
  auto* dinfo = reinterpret_cast<j_decompress_ptr>(cinfo);
  if (dinfo->is_decompressor && dinfo->input_scan_number > kMaxScans) {
    auto* p = reinterpret_cast<Progress*>(cinfo->progress);
    std::snprintf(p->err->message, sizeof p->err->message, "more than %d scans (refused)", kMaxScans);
    std::longjmp(p->err->back, 1);
  }
}
}  // namespace

Image decodeJpeg(const uint8_t* data, size_t size, const std::string& name) {
  if (size < 3 || data[0] != 0xff || data[1] != 0xd8 || data[2] != 0xff)
    throw Error(name + ": not a JPEG file (bad signature)");
  // Everything with a destructor exists before setjmp; longjmp skips the
  // destructors of anything made after it.
  Image img;
  jpeg_decompress_struct cinfo;
  ErrorManager err;
  std::memset(&cinfo, 0, sizeof cinfo);
  cinfo.err = jpeg_std_error(&err.pub);
  err.pub.error_exit = onError;
  err.pub.emit_message = onMessage;
  err.message[0] = '\0';
  Progress progress;
  progress.pub.progress_monitor = onProgress;
  progress.err = &err;
  if (setjmp(err.back)) {  // from libjpeg (onError, onProgress): nothing made after this line is alive
    jpeg_destroy_decompress(&cinfo);
    throw Error(name + ": malformed JPEG: " + err.message);
  }
  // Our own refusals throw directly (libjpeg is not on the stack then).
  auto refuse = [&](const std::string& why) {
    jpeg_destroy_decompress(&cinfo);
    return Error(name + ": malformed JPEG: " + why);
  };
  jpeg_create_decompress(&cinfo);
  cinfo.progress = &progress.pub;
  // A progressive file keeps every coefficient of the picture in memory
  // (2 bytes a sample): bounded, so the worst allowed file fails cleanly.
  cinfo.mem->max_memory_to_use = long(1) << 30;
  jpeg_mem_src(&cinfo, data, static_cast<unsigned long>(size));
  jpeg_read_header(&cinfo, TRUE);
  // The limits apply to the header's size, before anything is allocated.
  {  // scoped: a later longjmp must find no live string
    std::string bad = checkImageSize(cinfo.image_width, cinfo.image_height);
    if (!bad.empty()) throw refuse(bad);
  }
  // 8 bits per channel in, RGB out (grey, YCbCr; CMYK is refused below).
  if (cinfo.jpeg_color_space == JCS_CMYK || cinfo.jpeg_color_space == JCS_YCCK) {
    jpeg_destroy_decompress(&cinfo);
    throw Error(name + ": unsupported JPEG: CMYK colour (save it as an RGB JPEG or a PNG)");
  }
  cinfo.out_color_space = JCS_EXT_RGBA;
  // The exact integer IDCT and no fancy upsampling would be faster; the
  // defaults (islow IDCT, fancy upsampling) are libjpeg-turbo's reference
  // output, the same on every machine.
  jpeg_start_decompress(&cinfo);
  if (cinfo.output_components != 4 || cinfo.output_width != cinfo.image_width ||
      cinfo.output_height != cinfo.image_height)
    throw refuse("unexpected output layout");
  img.width = int(cinfo.output_width);
  img.height = int(cinfo.output_height);
  img.pixels.resize(size_t(img.width) * size_t(img.height) * 4);
  while (cinfo.output_scanline < cinfo.output_height) {
    JSAMPROW row = &img.pixels[size_t(cinfo.output_scanline) * size_t(img.width) * 4];
    if (jpeg_read_scanlines(&cinfo, &row, 1) != 1) throw refuse("the file ends early (truncated)");
  }
  jpeg_finish_decompress(&cinfo);
  jpeg_destroy_decompress(&cinfo);
  return img;
}

std::vector<uint8_t> encodeJpeg(const Image& img, int quality) {
  if (img.empty()) throw Error("cannot encode an empty image", kExitFailure);
  jpeg_compress_struct cinfo;
  ErrorManager err;
  std::memset(&cinfo, 0, sizeof cinfo);
  cinfo.err = jpeg_std_error(&err.pub);
  err.pub.error_exit = onError;
  unsigned char* out = nullptr;
  unsigned long outSize = 0;
  std::vector<uint8_t> bytes;
  std::vector<uint8_t> rgb(size_t(img.width) * 3);
  if (setjmp(err.back)) {
    jpeg_destroy_compress(&cinfo);
    std::free(out);
    throw Error(std::string("JPEG encoding failed: ") + err.message, kExitFailure);
  }
  jpeg_create_compress(&cinfo);
  jpeg_mem_dest(&cinfo, &out, &outSize);
  cinfo.image_width = JDIMENSION(img.width);
  cinfo.image_height = JDIMENSION(img.height);
  cinfo.input_components = 3;
  cinfo.in_color_space = JCS_RGB;
  jpeg_set_defaults(&cinfo);
  jpeg_set_quality(&cinfo, quality, TRUE);
  for (int c = 0; c < cinfo.num_components; ++c)  // 4:4:4: no chroma subsampling
    cinfo.comp_info[c].h_samp_factor = cinfo.comp_info[c].v_samp_factor = 1;
  jpeg_start_compress(&cinfo, TRUE);
  while (cinfo.next_scanline < cinfo.image_height) {
    const uint8_t* src = &img.pixels[size_t(cinfo.next_scanline) * size_t(img.width) * 4];
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) rgb[size_t(x) * 3 + size_t(c)] = src[size_t(x) * 4 + size_t(c)];
    JSAMPROW row = rgb.data();
    jpeg_write_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_compress(&cinfo);
  bytes.assign(out, out + outSize);
  jpeg_destroy_compress(&cinfo);
  std::free(out);
  return bytes;
}
}  // namespace ts
