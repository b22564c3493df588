#include "common/core/image.hpp"

#include <fcntl.h>
#include <png.h>
#include <sys/stat.h>
#include <unistd.h>
#ifdef _WIN32
#include <io.h>
#include <windows.h>
// Windows: every file here is opened in binary mode (text mode would turn
// each \n byte of a PNG into \r\n); there is no exec to close a descriptor
// on, no FIFO to block on, and _commit is fsync.
#define O_CLOEXEC O_BINARY
#define O_NONBLOCK 0
#define fsync _commit
#endif

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "common/core/bmp.hpp"
#include "common/core/error.hpp"
#include "common/core/jpeg.hpp"
#include "common/core/test_hooks.hpp"

namespace ts {
int maxChannelDiff(const Image& a, const Image& b) {
  int d = 0;
  for (size_t k = 0; k < a.pixels.size() && k < b.pixels.size(); ++k)
    if (k % 4 != 3) d = std::max(d, std::abs(int(a.pixels[k]) - int(b.pixels[k])));
  return d;
}
double rmsRgb(const Image& a, const Image& b) {
  double s = 0;
  for (size_t k = 0; k < a.pixels.size() && k < b.pixels.size(); ++k)
    if (k % 4 != 3) s += (double(a.pixels[k]) - double(b.pixels[k])) * (double(a.pixels[k]) - double(b.pixels[k]));
  return a.width && a.height ? std::sqrt(s / (double(a.width) * a.height * 3)) : 0.0;
}

Image::Image(int w, int h, Rgba fill) : width(w), height(h) {
  if (w < 0 || h < 0 || w > kMaxImageDimension || h > kMaxImageDimension)
    throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range");
  pixels.resize(size_t(w) * size_t(h) * 4);  // zeros
  if (fill == Rgba{0, 0, 0, 0}) return;
  const uint8_t q[4] = {fill.r, fill.g, fill.b, fill.a};
  for (size_t i = 0; i < pixels.size(); i += 4) std::memcpy(&pixels[i], q, 4);
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
  if (why) {
    std::string after = (why->rfind("(after: ", 0) == 0) ? *why : std::string();
    *why = std::string(msg ? msg : "libpng error");
    if (!after.empty()) *why += " " + after.substr(0, after.size() - 1);
  }
  png_longjmp(png, 1);
}
void pngWarning(png_structp png, png_const_charp msg) {
  // Warnings stay quiet, but the last one is kept: libpng often warns with
  // the precise reason ("Image width is zero in IHDR") and then fails with a
  // vaguer error ("Invalid IHDR data").
  auto* why = static_cast<std::string*>(png_get_error_ptr(png));
  if (why && msg) *why = std::string("(after: ") + msg + ") ";
}

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
  png_set_IHDR(png, info, png_uint_32(img.width), png_uint_32(img.height), 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  for (int y = 0; y < img.height; ++y) rows[size_t(y)] = const_cast<png_bytep>(&img.pixels[size_t(y) * img.width * 4]);
  png_set_rows(png, info, rows.data());
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

// ------------------------------------------------------------ atomic writes
namespace {
bool writeAll(int fd, const char* p, size_t n) {
  // A test may pause half-way through every file (test_hooks.hpp), kill the
  // run in the middle of a write, and check that no half-written file
  // appears under the final name.
  static const long pauseMs = test_hooks::writePauseMs();
  size_t half = pauseMs > 0 ? n / 2 : n, done = 0;
  while (done < n) {
    if (done == half && pauseMs > 0) ::usleep(useconds_t(pauseMs) * 1000);
    size_t want = (done < half ? half : n) - done;
    ssize_t k = ::write(fd, p + done, want);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    done += size_t(k);
  }
  return true;
}
}  // namespace

void writeFileAtomic(const std::string& path, const std::string& bytes) {
  // The content is first written to a file with no name (O_TMPFILE) in the
  // target's directory, so a run killed mid-write leaves nothing behind; it
  // is then linked as ".<name>.tmp-<pid>" and renamed over `path` (rename is
  // atomic: readers see the old file or the new one, never a mix).  Where
  // O_TMPFILE is not supported the named temporary is written directly.
  size_t slash = path.rfind('/');
  std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  std::string tmp = (slash == std::string::npos ? "" : path.substr(0, slash + 1)) + "." + base + ".tmp-" +
                    std::to_string(::getpid());
  auto fail = [&](int e, bool removeTmp) {
    if (removeTmp) ::unlink(tmp.c_str());
    throw Error("cannot write " + path + ": " + std::strerror(e));
  };
  if (base.empty()) fail(EISDIR, false);
  bool named = false;
#ifdef O_TMPFILE
  int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
#else
  int fd = -1;
  errno = EOPNOTSUPP;
#endif
  if (fd < 0) {
    if (errno == ENOENT || errno == ENOTDIR || errno == EACCES || errno == EROFS) fail(errno, false);
    fd = ::open(tmp.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0666);
    if (fd < 0) fail(errno, false);
    named = true;
  }
  if (!writeAll(fd, bytes.data(), bytes.size()) || ::fsync(fd) != 0) {
    int e = errno;
    ::close(fd);
    fail(e, named);
  }
#ifdef O_TMPFILE
  if (!named) {
    std::string self = "/proc/self/fd/" + std::to_string(fd);
    if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW) != 0) {
      // No /proc: write the named temporary the plain way.
      ::close(fd);
      fd = ::open(tmp.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0666);
      if (fd < 0) fail(errno, false);
      if (!writeAll(fd, bytes.data(), bytes.size()) || ::fsync(fd) != 0) {
        int e = errno;
        ::close(fd);
        fail(e, true);
      }
    }
  }
#endif
  if (::close(fd) != 0) fail(errno, true);
#ifdef _WIN32
  // Windows' rename() refuses an existing target; this replaces it.
  if (!MoveFileExA(tmp.c_str(), path.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH))
    fail(GetLastError() == ERROR_ACCESS_DENIED ? EACCES : EIO, true);
#else
  if (std::rename(tmp.c_str(), path.c_str()) != 0) fail(errno, true);
#endif
}

void writePng(const std::string& path, const Image& img) {
  std::vector<uint8_t> bytes = encodePng(img);
  writeFileAtomic(path, std::string(bytes.begin(), bytes.end()));
}

// ------------------------------------------------------------ reading files
std::vector<uint8_t> readFileBytes(const std::string& path, size_t limit) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; the fstat below
  // refuses anything that is not a regular file before reading a byte.
#ifdef _WIN32
  // Windows refuses to open a folder (EACCES): say what it is, as below.
  struct stat dir;
  if (::stat(path.c_str(), &dir) == 0 && S_ISDIR(dir.st_mode))
    throw Error(path + ": is a directory, not an image file");
#endif
  int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw Error(path + ": cannot open: " + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st;
  if (::fstat(fd, &st) != 0) throw Error(path + ": cannot read: " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw Error(path + ": is a directory, not an image file");
  if (!S_ISREG(st.st_mode)) throw Error(path + ": is not a regular file");
  if (st.st_size == 0) throw Error(path + ": is empty (0 bytes)");
  if (uint64_t(st.st_size) > limit)
    throw Error(path + ": is too large (" + std::to_string(st.st_size) + " bytes; the limit is " +
                std::to_string(limit) + ")");
  std::vector<uint8_t> data(size_t(st.st_size));
  size_t got = 0;
  while (got < data.size()) {
    ssize_t k = ::read(fd, data.data() + got, data.size() - got);
    if (k < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (k < 0) throw Error(path + ": cannot read: " + std::strerror(errno));
    if (k == 0) break;  // shrank while we read: decode what is there
    got += size_t(k);
  }
  data.resize(got);
  return data;
}

std::string checkImageSize(uint64_t w, uint64_t h) {
  if (w == 0 || h == 0) return "zero " + std::string(w == 0 ? "width" : "height") + " in the header";
  if (w > uint64_t(kMaxImageDimension) || h > uint64_t(kMaxImageDimension) || w * h > uint64_t(kMaxFilePixels))
    return "header says " + std::to_string(w) + "x" + std::to_string(h) + " pixels, over the limit of " +
           std::to_string(kMaxImageDimension) + " per side and " + std::to_string(kMaxFilePixels) +
           " pixels (refused before allocating)";
  return "";
}

// ------------------------------------------------------------ PNG decoding
namespace {
struct PngSource {
  const uint8_t* data;
  size_t size, pos;
  std::string* why;
};
void readFromMemory(png_structp png, png_bytep out, png_size_t len) {
  auto* src = static_cast<PngSource*>(png_get_io_ptr(png));
  if (len > src->size - src->pos) png_error(png, "the file ends early (truncated)");
  std::memcpy(out, src->data + src->pos, len);
  src->pos += len;
}
uint32_t be32(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }
// Row y of the pixels, the buffer grown (zeroed, within its capacity) to
// hold it.  Not inlined: no temporary of vector::resize lives in
// decodePng's frame between its setjmp and libpng's longjmp.
[[gnu::noinline]] uint8_t* pngRow(std::vector<uint8_t>& pixels, png_uint_32 y, size_t rowBytes) {
  size_t end = (size_t(y) + 1) * rowBytes;
  if (pixels.size() < end) pixels.resize(end);
  return &pixels[end - rowBytes];
}
}  // namespace

Image decodePng(const uint8_t* data, size_t size, const std::string& name) {
  static const uint8_t kSig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size < 8 || std::memcmp(data, kSig, 8) != 0) throw Error(name + ": not a PNG file (bad signature)");
  // The header is checked here, before libpng sees it, so that the size
  // limits apply before anything is allocated and the messages are plain.
  if (size < 8 + 8 + 13 + 4) throw Error(name + ": malformed PNG: the file ends inside the IHDR header (truncated)");
  if (be32(data + 8) != 13 || std::memcmp(data + 12, "IHDR", 4) != 0)
    throw Error(name + ": malformed PNG: the first chunk is not a 13-byte IHDR");
  uint32_t w = be32(data + 16), h = be32(data + 20);
  std::string bad = checkImageSize(w, h);
  if (!bad.empty()) throw Error(name + ": malformed PNG: " + bad);
  // zlib cannot compress better than 1032:1, so a file too short to hold
  // the rows its header announces is refused before the pixels are
  // allocated (a 40-byte file must not cost 256 MiB).
  static const int kChannels[7] = {1, 0, 3, 1, 2, 0, 4};
  int depth = data[24], type = data[25];
  if (type <= 6 && kChannels[type] && depth >= 1 && depth <= 16) {
    uint64_t rawBytes = uint64_t(h) * (1 + (uint64_t(w) * uint64_t(kChannels[type] * depth) + 7) / 8);
    uint64_t rest = size - 33;
    if (rest * 1032 + 1032 < rawBytes)
      throw Error(name + ": malformed PNG: truncated: the header says " + std::to_string(w) + "x" + std::to_string(h) +
                  " pixels but only " + std::to_string(rest) + " bytes follow it");
  }

  std::string why;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &why, pngError, pngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw Error(name + ": out of memory");
  }
  // Everything with a destructor is made before setjmp and only its
  // contents change after it (longjmp skips destructors of anything newer).
  Image img;
  img.width = int(w);
  img.height = int(h);
  const size_t rowBytes = size_t(w) * 4;
  std::vector<uint8_t> firstRow(rowBytes, 0);  // (not firstRow(rowBytes): g++ -O3 -Wclobbered)
  PngSource src{data, size, 8, &why};
  auto fail = [&] {
    png_destroy_read_struct(&png, &info, nullptr);
    throw Error(name + ": malformed PNG: " + why);
  };
  if (setjmp(png_jmpbuf(png))) fail();
  png_set_read_fn(png, &src, readFromMemory);
  png_set_sig_bytes(png, 8);
  png_set_user_limits(png, kMaxImageDimension, kMaxImageDimension);
  png_read_info(png, info);
  if (png_get_image_width(png, info) != w || png_get_image_height(png, info) != h)
    png_error(png, "IHDR changed while reading");
  depth = png_get_bit_depth(png, info);
  type = png_get_color_type(png, info);
  if (depth == 16) png_set_strip_16(png);  // keep the high byte
  if (type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (type == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  bool trns = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
  if (trns) png_set_tRNS_to_alpha(png);
  if (type == PNG_COLOR_TYPE_GRAY || type == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
  if (!(type & PNG_COLOR_MASK_ALPHA) && !trns) png_set_filler(png, 0xff, PNG_FILLER_AFTER);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (png_get_rowbytes(png, info) != rowBytes) png_error(png, "unsupported pixel layout after conversion");
  // What png_read_image does (every row of every pass, in order), except
  // that the pixels are not allocated before the data has shown it holds
  // rows: the first row is decoded into firstRow, and only then is the
  // image's buffer reserved (address space, not memory), each row being
  // added, zeroed as before, just before libpng first writes it.  A header
  // that claims a large image over data that fails early costs the rows
  // decoded, not w*h*4 bytes.
  int passes = png_set_interlace_handling(png);
  png_read_row(png, firstRow.data(), nullptr);
  img.pixels.reserve(rowBytes * h);
  img.pixels.assign(firstRow.begin(), firstRow.end());
  // setjmp again: from here on the buffer's address and capacity stay as
  // they are now; only its length changes (and the rows' contents).
  if (setjmp(png_jmpbuf(png))) fail();
  for (int pass = 0; pass < passes; ++pass)
    for (png_uint_32 y = pass == 0 ? 1 : 0; y < h; ++y) png_read_row(png, pngRow(img.pixels, y, rowBytes), nullptr);
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return img;
}

Image readPng(const std::string& path) {
  std::vector<uint8_t> bytes = readFileBytes(path);
  return decodePng(bytes.data(), bytes.size(), path);
}

Image decodeImage(const uint8_t* data, size_t size, const std::string& name) {
  if (size >= 8 && data[0] == 0x89 && std::memcmp(data + 1, "PNG", 3) == 0) return decodePng(data, size, name);
  if (size >= 2 && data[0] == 'B' && data[1] == 'M') return decodeBmp(data, size, name);
  if (size >= 3 && data[0] == 0xff && data[1] == 0xd8 && data[2] == 0xff) return decodeJpeg(data, size, name);
  throw Error(name + ": not a PNG, JPEG or BMP file (unrecognised first bytes)");
}

Image readImage(const std::string& path) {
  std::vector<uint8_t> bytes = readFileBytes(path);
  return decodeImage(bytes.data(), bytes.size(), path);
}
}  // namespace ts
