// tests/unit/image_test.cpp — ts::Image and PNG in and out (common/core/image.cpp).
// No GL.  Files go into a fresh directory under $TMPDIR, removed at the end.
#include <dirent.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <zlib.h>

#include "common/core/error.hpp"
#include "common/gl/figure.hpp"
#include "common/core/image.hpp"

namespace {
class TempDir {
 public:
  TempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string tmpl = std::string(base && *base ? base : "/tmp") + "/ts_image_test.XXXXXX";
    std::vector<char> buf(tmpl.begin(), tmpl.end());
    buf.push_back('\0');
    if (!mkdtemp(buf.data())) std::abort();
    path_ = buf.data();
  }
  ~TempDir() { std::system(("rm -rf '" + path_ + "'").c_str()); }
  const std::string& path() const { return path_; }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

std::vector<std::string> listDir(const std::string& dir) {
  std::vector<std::string> out;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      std::string n = e->d_name;
      if (n != "." && n != "..") out.push_back(n);
    }
    closedir(d);
  }
  return out;
}
std::vector<uint8_t> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void writeBytes(const std::string& path, const std::vector<uint8_t>& b) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

ts::Image randomImage(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  ts::Image img(w, h);
  for (auto& p : img.pixels) p = uint8_t(rng());
  return img;
}

// Runs f, expects a ts::Error, returns its message.
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const ts::Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ts::Error thrown";
  return "";
}

// Claim: at(), set() and blit() address pixels with (0,0) at the top-left;
// flipVertical swaps the rows; set() outside the image is ignored.
TEST(Image, Addressing) {
  ts::Image img(3, 2, {1, 2, 3, 4});
  EXPECT_EQ(img.at(2, 1), (ts::Rgba{1, 2, 3, 4}));
  img.set(2, 0, {9, 9, 9, 9});
  EXPECT_EQ(img.pixels[(0 * 3 + 2) * 4], 9);
  img.set(3, 0, {7, 7, 7, 7});   // outside: ignored
  img.set(-1, 0, {7, 7, 7, 7});  // outside: ignored
  img.flipVertical();
  EXPECT_EQ(img.at(2, 1), (ts::Rgba{9, 9, 9, 9}));
  EXPECT_EQ(img.at(2, 0), (ts::Rgba{1, 2, 3, 4}));
  ts::Image dst(4, 4, {0, 0, 0, 255});
  dst.blit(img, 3, -1);  // only img's column 0, row 1 lands, at (3, 0)
  EXPECT_EQ(dst.at(3, 0), img.at(0, 1));
  EXPECT_EQ(dst.at(3, 1), (ts::Rgba{0, 0, 0, 255}));
  EXPECT_THROW(ts::Image(ts::kMaxImageDimension + 1, 1), ts::Error);
}

// Claim: readPng(writePng(x)) == x for a random RGBA image (alpha included),
// and the file starts with the PNG signature.
TEST(Png, RoundTripOfARandomImage) {
  TempDir dir;
  ts::Image img = randomImage(77, 53, 11);
  ts::writePng(dir / "r.png", img);
  std::vector<uint8_t> bytes = readBytes(dir / "r.png");
  const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  ASSERT_GE(bytes.size(), 8u);
  EXPECT_TRUE(std::equal(sig, sig + 8, bytes.begin()));
  ts::Image back = ts::readPng(dir / "r.png");
  EXPECT_EQ(back.width, 77);
  EXPECT_EQ(back.height, 53);
  EXPECT_TRUE(back.pixels == img.pixels);
  // The in-memory encoder writes exactly the file's bytes.
  EXPECT_TRUE(ts::encodePng(img) == bytes);
}

// Claim: encoding is deterministic (same pixels -> same bytes), and a one-bit
// change to the pixels changes the bytes.
TEST(Png, EncodingIsDeterministic) {
  ts::Image img = randomImage(64, 64, 5);
  std::vector<uint8_t> a = ts::encodePng(img), b = ts::encodePng(ts::Image(img));
  EXPECT_TRUE(a == b);
  img.pixels[1000] ^= 1;
  EXPECT_FALSE(ts::encodePng(img) == a);
  EXPECT_THROW(ts::encodePng(ts::Image()), ts::Error);
}

// Claim: a missing file, a file that is not a PNG, an empty file and a
// truncated PNG each throw ts::Error whose message starts with the path.
TEST(Png, ReadErrorsNameThePath) {
  TempDir dir;
  std::string missing = dir / "missing.png";
  EXPECT_EQ(errorOf([&] { ts::readPng(missing); }).rfind(missing + ":", 0), 0u);

  std::string text = dir / "text.png";
  writeBytes(text, std::vector<uint8_t>(100, 'x'));
  std::string e = errorOf([&] { ts::readPng(text); });
  EXPECT_EQ(e.rfind(text + ":", 0), 0u) << e;
  EXPECT_NE(e.find("not a PNG"), std::string::npos) << e;

  std::string empty = dir / "empty.png";
  writeBytes(empty, {});
  EXPECT_EQ(errorOf([&] { ts::readPng(empty); }).rfind(empty + ":", 0), 0u);

  std::vector<uint8_t> good = ts::encodePng(randomImage(40, 40, 3));
  for (size_t keep : {size_t(8), size_t(20), size_t(40), good.size() / 2, good.size() - 13}) {
    std::string cut = dir / ("cut" + std::to_string(keep) + ".png");
    writeBytes(cut, std::vector<uint8_t>(good.begin(), good.begin() + long(keep)));
    std::string m = errorOf([&] { ts::readPng(cut); });
    EXPECT_EQ(m.rfind(cut + ":", 0), 0u) << "kept " << keep << " bytes: " << m;
  }
  // A well-formed header announcing 20000 x 1 pixels (over the 16384 limit,
  // CRC fixed up so only the size is wrong) is refused before allocating.
  std::vector<uint8_t> big = ts::encodePng(randomImage(1, 1, 4));
  // IHDR: length at 8, "IHDR" at 12, width at 16..19, CRC over 12..28 at 29..32.
  big[16] = 0, big[17] = 0, big[18] = 0x4e, big[19] = 0x20;
  uLong crc = crc32(0L, big.data() + 12, 17);
  for (int k = 0; k < 4; ++k) big[size_t(29 + k)] = uint8_t(crc >> (24 - 8 * k));
  std::string huge = dir / "huge.png";
  writeBytes(huge, big);
  std::string hm = errorOf([&] { ts::readPng(huge); });
  EXPECT_EQ(hm.rfind(huge + ":", 0), 0u) << hm;
  // The directory holds only what the test wrote.
  EXPECT_EQ(listDir(dir.path()).size(), 8u);
}

// A minimal PNG writer (no libpng): one IDAT, filter 0 on every row, so the
// tests below can make colour types and depths encodePng never writes.
std::vector<uint8_t> rawPng(int w, int h, int depth, int colorType, const std::vector<std::vector<uint8_t>>& rows,
                            const std::vector<std::pair<std::string, std::vector<uint8_t>>>& extra = {}) {
  std::vector<uint8_t> out{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  auto be32 = [](std::vector<uint8_t>& v, uint32_t x) {
    for (int k = 3; k >= 0; --k) v.push_back(uint8_t(x >> (8 * k)));
  };
  auto chunk = [&](const std::string& type, const std::vector<uint8_t>& data) {
    be32(out, uint32_t(data.size()));
    std::vector<uint8_t> body(type.begin(), type.end());
    body.insert(body.end(), data.begin(), data.end());
    out.insert(out.end(), body.begin(), body.end());
    be32(out, uint32_t(crc32(0L, body.data(), uInt(body.size()))));
  };
  std::vector<uint8_t> ihdr;
  be32(ihdr, uint32_t(w));
  be32(ihdr, uint32_t(h));
  ihdr.insert(ihdr.end(), {uint8_t(depth), uint8_t(colorType), 0, 0, 0});
  chunk("IHDR", ihdr);
  for (const auto& [type, data] : extra) chunk(type, data);
  std::vector<uint8_t> raw;
  for (const auto& r : rows) {
    raw.push_back(0);
    raw.insert(raw.end(), r.begin(), r.end());
  }
  uLongf len = compressBound(uLong(raw.size()));
  std::vector<uint8_t> z(len);
  compress(z.data(), &len, raw.data(), uLong(raw.size()));
  z.resize(len);
  chunk("IDAT", z);
  chunk("IEND", {});
  return out;
}

// Claim: readPng converts every colour type and depth to RGBA8: grey (8 and
// 1 bit), grey + alpha, palette with a tRNS alpha, RGB with a tRNS colour
// key, and 16-bit RGB (high byte kept), with alpha 255 where none is given.
TEST(Png, ReadsEveryColourTypeAsRgba8) {
  TempDir dir;
  struct Case {
    const char* name;
    std::vector<uint8_t> png;
    std::vector<ts::Rgba> want;  // row 0, left to right
  } cases[] = {
      {"grey8", rawPng(2, 1, 8, 0, {{0, 200}}), {{0, 0, 0, 255}, {200, 200, 200, 255}}},
      {"grey1",
       rawPng(4, 1, 1, 0, {{0xa0}}),
       {{255, 255, 255, 255}, {0, 0, 0, 255}, {255, 255, 255, 255}, {0, 0, 0, 255}}},
      {"grey_alpha", rawPng(1, 1, 8, 4, {{100, 50}}), {{100, 100, 100, 50}}},
      {"palette_trns",
       rawPng(2, 1, 8, 3, {{1, 0}}, {{"PLTE", {10, 20, 30, 40, 50, 60}}, {"tRNS", {128}}}),
       {{40, 50, 60, 255}, {10, 20, 30, 128}}},
      {"rgb_key",
       rawPng(2, 1, 8, 2, {{1, 2, 3, 7, 8, 9}}, {{"tRNS", {0, 7, 0, 8, 0, 9}}}),
       {{1, 2, 3, 255}, {7, 8, 9, 0}}},
      {"rgb16", rawPng(1, 1, 16, 2, {{0x12, 0x34, 0xff, 0x00, 0x00, 0x80}}), {{0x12, 0xff, 0x00, 255}}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    std::string path = dir / (std::string(c.name) + ".png");
    writeBytes(path, c.png);
    ts::Image img;
    try {
      img = ts::readPng(path);
    } catch (const ts::Error& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    ASSERT_EQ(img.width, int(c.want.size()));
    ASSERT_EQ(img.height, 1);
    for (int x = 0; x < img.width; ++x) EXPECT_EQ(img.at(x, 0), c.want[size_t(x)]) << "pixel " << x;
  }
}

// Claim: writePng into a directory that does not exist, or onto a path that
// is a directory, throws ts::Error naming the path and leaves no file (no
// "*.tmp-*" leftovers) behind.  As a non-root user, also a read-only
// directory.
TEST(Png, WriteFailuresLeaveNoFile) {
  TempDir dir;
  ts::Image img = randomImage(8, 8, 1);
  std::string nodir = dir / "nosuch/x.png";
  EXPECT_NE(errorOf([&] { ts::writePng(nodir, img); }).find(nodir), std::string::npos);

  std::string sub = dir / "sub";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  EXPECT_NE(errorOf([&] { ts::writePng(sub, img); }).find(sub), std::string::npos);
  EXPECT_EQ(listDir(dir.path()), std::vector<std::string>{"sub"});
  EXPECT_TRUE(listDir(sub).empty());

  if (geteuid() != 0) {  // root writes anywhere: only meaningful for others
    std::string ro = dir / "ro";
    ASSERT_EQ(mkdir(ro.c_str(), 0555), 0);
    EXPECT_NE(errorOf([&] { ts::writePng(ro + "/x.png", img); }).find(ro + "/x.png"), std::string::npos);
    EXPECT_TRUE(listDir(ro).empty());
    chmod(ro.c_str(), 0755);
  }
  // A successful write leaves exactly the file, no temporary.
  ts::writePng(dir / "ok.png", img);
  std::vector<std::string> names = listDir(dir.path());
  for (const auto& n : names) EXPECT_EQ(n.find(".tmp-"), std::string::npos) << n;
  EXPECT_EQ(readBytes(dir / "ok.png"), ts::encodePng(img));
}

// Claim: checkWritable (run before any rendering) accepts a writable path
// leaving nothing behind, and refuses a missing folder naming the path.
TEST(CheckWritable, GoodAndMissingFolder) {
  TempDir dir;
  EXPECT_NO_THROW(ts::checkWritable(dir / "out.png"));
  EXPECT_TRUE(listDir(dir.path()).empty());
  std::string bad = dir / "nosuch/out.png";
  EXPECT_NE(errorOf([&] { ts::checkWritable(bad); }).find(bad), std::string::npos);
  EXPECT_THROW(ts::checkWritable(""), ts::Error);
}

// Claim: checkWritable also refuses a path that is an existing folder, so
// "--png somedir" fails before rendering.  KNOWN BUG (common/gl/figure.cpp,
// checkWritable): it only probes "<path>.tmp-<pid>" beside the folder, which
// succeeds; the demo renders the whole figure and only then fails at the
// rename ("cannot write somedir: Is a directory").  Enable once
// checkWritable stat()s the path and refuses a directory.
TEST(CheckWritable, RefusesAFolder) {
  TempDir dir;
  std::string sub = dir / "sub";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  EXPECT_THROW(ts::checkWritable(sub), ts::Error);
}

// Claim: writePng replaces an existing file atomically with the new content.
TEST(Png, OverwriteReplacesContent) {
  TempDir dir;
  ts::writePng(dir / "f.png", randomImage(5, 5, 1));
  ts::Image b = randomImage(6, 4, 2);
  ts::writePng(dir / "f.png", b);
  EXPECT_TRUE(ts::readPng(dir / "f.png").pixels == b.pixels);
  EXPECT_EQ(listDir(dir.path()).size(), 1u);
}
}  // namespace
