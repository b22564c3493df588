// tests/reliability/corpus_gen.hpp — makes the image corpus: well-formed
// PNG and BMP files of every kind the loaders promise to read (with the
// pixels they must decode to) and malformed ones (with the words the one-line
// error must contain).  make_corpus writes them to tests/reliability/corpus/;
// reliability_test checks the committed files against this code and decodes
// every one.  The PNGs are written by hand (zlib only), so they can hold
// what libpng would refuse to write: bad CRCs, lying lengths, zero sizes.
#pragma once
#include <zlib.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/core/bmp.hpp"
#include "common/core/jpeg.hpp"
#include "common/core/image.hpp"

namespace corpus {
using Bytes = std::vector<uint8_t>;

struct Case {
  std::string name;  // file name in the corpus
  Bytes bytes;
  bool good = false;  // must decode...
  ts::Image expect;   // ...to these pixels
  std::string error;  // bad: a phrase the error line must contain
  int tolerance = 0;  // good: largest channel difference allowed (JPEG is lossy; 0 elsewhere)
};

inline void be32(Bytes& v, uint32_t x) {
  for (int k = 3; k >= 0; --k) v.push_back(uint8_t(x >> (8 * k)));
}
inline void le32(Bytes& v, uint32_t x) {
  for (int k = 0; k < 4; ++k) v.push_back(uint8_t(x >> (8 * k)));
}
inline void le16(Bytes& v, uint16_t x) {
  v.push_back(uint8_t(x));
  v.push_back(uint8_t(x >> 8));
}

inline void chunk(Bytes& out, const std::string& type, const Bytes& data, bool badCrc = false) {
  be32(out, uint32_t(data.size()));
  Bytes body(type.begin(), type.end());
  body.insert(body.end(), data.begin(), data.end());
  out.insert(out.end(), body.begin(), body.end());
  uint32_t crc = uint32_t(crc32(0L, body.data(), uInt(body.size())));
  be32(out, badCrc ? crc ^ 0x5a5a5a5au : crc);
}

inline Bytes zlibCompress(const Bytes& raw) {
  uLongf len = compressBound(uLong(raw.size()));
  Bytes z(len);
  compress2(z.data(), &len, raw.data(), uLong(raw.size()), 9);
  z.resize(len);
  return z;
}

inline Bytes pngSignature() { return {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}; }

inline Bytes ihdr(uint32_t w, uint32_t h, int depth, int type, int interlace = 0) {
  Bytes d;
  be32(d, w);
  be32(d, h);
  d.insert(d.end(), {uint8_t(depth), uint8_t(type), 0, 0, uint8_t(interlace)});
  return d;
}

// Samples per pixel of a PNG colour type.
inline int channels(int type) { return type == 0 ? 1 : type == 2 ? 3 : type == 3 ? 1 : type == 4 ? 2 : 4; }

// The source picture every good file encodes, as 16-bit samples per
// channel (R, G, B, A); 8-bit files use the high byte.
struct Sample16 {
  uint16_t r, g, b, a;
};
inline Sample16 pattern(int x, int y) {
  auto v = [](int k) { return uint16_t((k & 255) * 257 ^ (k >> 8 & 0xff)); };
  return {v(x * 37 + y * 11), v(x * 5 + y * 29 + 64), v((x ^ y) * 13 + 7), v(255 - x * 7 - y * 3)};
}
constexpr int kPaletteSize = 13;
inline ts::Rgba paletteColour(int i) {
  return {uint8_t(i * 19), uint8_t(250 - i * 17), uint8_t(i * i), uint8_t(i % 3 ? 255 : 40 + i * 9)};
}

// Packs row y of the picture for a colour type and depth (palette: index
// (x + y) % kPaletteSize; grey: the G channel).
inline Bytes packRow(int w, int y, int depth, int type, const std::vector<int>& xs) {
  Bytes bits;
  std::vector<uint32_t> samples;
  for (int x : xs) {
    Sample16 s = pattern(x, y);
    std::vector<uint16_t> c;
    if (type == 0) c = {s.g};
    else if (type == 2) c = {s.r, s.g, s.b};
    else if (type == 3) c = {uint16_t((x + y) % kPaletteSize)};
    else if (type == 4) c = {s.g, s.a};
    else c = {s.r, s.g, s.b, s.a};
    for (uint16_t v : c) {
      if (type == 3) samples.push_back(v);
      else samples.push_back(depth == 16 ? v : depth == 8 ? v >> 8 : v >> (16 - depth));
    }
  }
  (void)w;
  Bytes row;
  if (depth >= 8) {
    for (uint32_t v : samples) {
      if (depth == 16) row.push_back(uint8_t(v >> 8));
      row.push_back(uint8_t(v));
    }
  } else {
    int per = 8 / depth, n = 0;
    uint8_t cur = 0;
    for (uint32_t v : samples) {
      cur |= uint8_t(v << (8 - depth * (n % per + 1)));
      if (++n % per == 0) row.push_back(cur), cur = 0;
    }
    if (n % per) row.push_back(cur);
  }
  return row;
}

// What the loader must return for that file: RGBA8, high byte of 16-bit
// samples, grey replicated, 1/2/4-bit grey scaled to 0..255.
inline ts::Image expected(int w, int h, int depth, int type) {
  ts::Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Sample16 s = pattern(x, y);
      auto to8 = [&](uint16_t v) -> uint8_t {
        if (depth >= 8) return uint8_t(v >> 8);
        int k = v >> (16 - depth), max = (1 << depth) - 1;
        return uint8_t(k * 255 / max);
      };
      ts::Rgba c;
      if (type == 0) c = {to8(s.g), to8(s.g), to8(s.g), 255};
      else if (type == 2) c = {to8(s.r), to8(s.g), to8(s.b), 255};
      else if (type == 3) c = paletteColour((x + y) % kPaletteSize);
      else if (type == 4) c = {to8(s.g), to8(s.g), to8(s.g), to8(s.a)};
      else c = {to8(s.r), to8(s.g), to8(s.b), to8(s.a)};
      img.set(x, y, c);
    }
  return img;
}

// A whole PNG of the picture; interlace 1 = Adam7 (the seven passes each
// filtered and stored one after the other in the same zlib stream).
inline Bytes makePng(int w, int h, int depth, int type, int interlace = 0) {
  Bytes out = pngSignature();
  chunk(out, "IHDR", ihdr(uint32_t(w), uint32_t(h), depth, type, interlace));
  if (type == 3) {
    Bytes plte, trns;
    for (int i = 0; i < kPaletteSize; ++i) {
      ts::Rgba c = paletteColour(i);
      plte.insert(plte.end(), {c.r, c.g, c.b});
      trns.push_back(c.a);
    }
    chunk(out, "PLTE", plte);
    chunk(out, "tRNS", trns);
  }
  Bytes raw;
  struct Pass {
    int x0, y0, dx, dy;
  };
  std::vector<Pass> passes = interlace ? std::vector<Pass>{{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4},
                                                           {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}}
                                       : std::vector<Pass>{{0, 0, 1, 1}};
  for (const Pass& p : passes) {
    std::vector<int> xs;
    for (int x = p.x0; x < w; x += p.dx) xs.push_back(x);
    if (xs.empty()) continue;
    for (int y = p.y0; y < h; y += p.dy) {
      raw.push_back(0);  // filter: none
      Bytes r = packRow(w, y, depth, type, xs);
      raw.insert(raw.end(), r.begin(), r.end());
    }
  }
  chunk(out, "IDAT", zlibCompress(raw));
  chunk(out, "IEND", {});
  return out;
}

// A PNG whose IHDR says w x h but whose IDAT is `raw` (filter bytes included).
inline Bytes pngWithRaw(uint32_t w, uint32_t h, int depth, int type, const Bytes& raw) {
  Bytes out = pngSignature();
  chunk(out, "IHDR", ihdr(w, h, depth, type));
  chunk(out, "IDAT", zlibCompress(raw));
  chunk(out, "IEND", {});
  return out;
}

inline Bytes bmpHeader(int32_t w, int32_t h, uint16_t bits, uint32_t compression, uint32_t pixelBytes,
                       uint32_t infoSize = 40, uint16_t planes = 1, uint32_t offset = 0) {
  Bytes out{'B', 'M'};
  le32(out, 14 + infoSize + pixelBytes);
  le32(out, 0);
  le32(out, offset ? offset : 14 + infoSize);
  le32(out, infoSize);
  le32(out, uint32_t(w));
  le32(out, uint32_t(h));
  le16(out, planes);
  le16(out, bits);
  le32(out, compression);
  le32(out, pixelBytes);
  le32(out, 2835);
  le32(out, 2835);
  le32(out, 0);
  le32(out, 0);
  while (out.size() < 14 + size_t(infoSize)) out.push_back(0);
  return out;
}

inline ts::Image rgbPicture(int w, int h) {
  ts::Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Sample16 s = pattern(x, y);
      img.set(x, y, {uint8_t(s.r >> 8), uint8_t(s.g >> 8), uint8_t(s.b >> 8), 255});
    }
  return img;
}

// The same picture stored top-down (negative height).
inline Bytes bmpTopDown(const ts::Image& img) {
  uint32_t stride = (uint32_t(img.width) * 3 + 3) / 4 * 4;
  Bytes out = bmpHeader(img.width, -img.height, 24, 0, stride * uint32_t(img.height));
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      ts::Rgba c = img.at(x, y);
      out.insert(out.end(), {c.b, c.g, c.r});
    }
    for (uint32_t k = uint32_t(img.width) * 3; k < stride; ++k) out.push_back(0);
  }
  return out;
}

inline Bytes cut(Bytes b, size_t keep) {
  b.resize(std::min(keep, b.size()));
  return b;
}

// Offset of the first chunk of `type` in a PNG (its length field), or 0.
inline size_t findChunk(const Bytes& png, const std::string& type) {
  size_t at = 8;
  while (at + 8 <= png.size()) {
    uint32_t len = uint32_t(png[at]) << 24 | uint32_t(png[at + 1]) << 16 | uint32_t(png[at + 2]) << 8 | png[at + 3];
    if (std::string(png.begin() + long(at) + 4, png.begin() + long(at) + 8) == type) return at;
    at += 12 + len;
  }
  return 0;
}

// A JPEG's first SOFn marker segment (its length field), or 0.
inline size_t findSof(const Bytes& jpg) {
  for (size_t at = 2; at + 9 < jpg.size(); ++at)
    if (jpg[at] == 0xff && (jpg[at + 1] == 0xc0 || jpg[at + 1] == 0xc2)) return at + 2;
  return 0;
}
// The JPEG of `img` with the SOF's height and width replaced.
inline Bytes jpegWithSize(const ts::Image& img, uint16_t w, uint16_t h) {
  Bytes b = ts::encodeJpeg(img, 90);
  size_t sof = findSof(b);
  if (sof + 6 < b.size())
    b[sof + 3] = uint8_t(h >> 8), b[sof + 4] = uint8_t(h), b[sof + 5] = uint8_t(w >> 8), b[sof + 6] = uint8_t(w);
  return b;
}
// A 32-bit BI_BITFIELDS BMP (40-byte header, three masks after it) of
// w x h pixels all 0xffffffff, with the masks given.
inline Bytes bmp32Masks(int32_t w, int32_t h, uint32_t r, uint32_t g, uint32_t b) {
  Bytes out{'B', 'M'};
  uint32_t pixels = uint32_t(w) * 4 * uint32_t(h);
  le32(out, 66 + pixels);
  le32(out, 0);
  le32(out, 66);
  le32(out, 40);
  le32(out, uint32_t(w));
  le32(out, uint32_t(h));
  le16(out, 1);
  le16(out, 32);
  le32(out, 3);
  le32(out, pixels);
  for (int k = 0; k < 4; ++k) le32(out, 0);
  le32(out, r), le32(out, g), le32(out, b);
  out.insert(out.end(), pixels, 0xff);
  return out;
}

inline std::vector<Case> makeCases() {
  std::vector<Case> cs;
  auto good = [&](const std::string& name, Bytes b, ts::Image img) {
    cs.push_back({name, std::move(b), true, std::move(img), ""});
  };
  auto bad = [&](const std::string& name, Bytes b, const std::string& why) {
    cs.push_back({name, std::move(b), false, {}, why});
  };

  // ---- well-formed: every colour type, 8 and 16 bits, odd (non-power-of-two) sizes
  struct Kind {
    const char* name;
    int depth, type, interlace;
  } kinds[] = {{"grey1", 1, 0, 0},
               {"grey4", 4, 0, 0},
               {"grey8", 8, 0, 0},
               {"grey16", 16, 0, 0},
               {"grey_alpha8", 8, 4, 0},
               {"grey_alpha16", 16, 4, 0},
               {"palette4", 4, 3, 0},
               {"palette8", 8, 3, 0},
               {"rgb8", 8, 2, 0},
               {"rgb16", 16, 2, 0},
               {"rgba8", 8, 6, 0},
               {"rgba16", 16, 6, 0},
               {"rgba8_interlaced", 8, 6, 1},
               {"grey16_interlaced", 16, 0, 1},
               {"palette8_interlaced", 8, 3, 1}};
  for (const Kind& k : kinds)
    good(std::string("good_") + k.name + "_37x23.png", makePng(37, 23, k.depth, k.type, k.interlace),
         expected(37, 23, k.depth, k.type));
  good("good_rgb8_1x1.png", makePng(1, 1, 8, 2), expected(1, 1, 8, 2));
  good("good_rgba8_interlaced_3x2.png", makePng(3, 2, 8, 6, 1), expected(3, 2, 8, 6));  // passes with no pixels
  ts::Image pic = rgbPicture(5, 3);                                                     // 15 bytes a row, padded to 16
  good("good_bmp24_5x3.bmp", ts::encodeBmp(pic), pic);
  {
    // 32-bit: B, G, R, A (alpha kept); the same as BI_ALPHABITFIELDS masks
    // in another channel order; all-zero alpha = opaque; 5-bit masks scaled.
    ts::Image alpha = rgbPicture(5, 3);
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 5; ++x) {
        ts::Rgba c = alpha.at(x, y);
        c.a = uint8_t(40 * x + 20 * y + 10);
        alpha.set(x, y, c);
      }
    good("good_bmp32_alpha_5x3.bmp", ts::encodeBmp32(alpha, false), alpha);
    good("good_bmp32_bitfields_alpha_5x3.bmp", ts::encodeBmp32(alpha, true), alpha);
    Bytes zero = ts::encodeBmp32(pic, false);
    for (size_t i = 54 + 3; i < zero.size(); i += 4) zero[i] = 0;
    good("good_bmp32_zero_alpha_5x3.bmp", zero, pic);
    ts::Image white(2, 2, {255, 255, 255, 255});
    good("good_bmp32_bitfields_555_2x2.bmp", bmp32Masks(2, 2, 0x7c00, 0x03e0, 0x001f), white);
  }
  {
    // JPEG is lossy: a flat colour and a picture of 8x8 flat blocks come
    // back within a few levels (4:4:4, no chroma subsampling).
    ts::Image flat(16, 8, {200, 120, 40, 255});
    good("good_jpeg_flat_16x8.jpg", ts::encodeJpeg(flat, 95), flat);
    cs.back().tolerance = 3;
    ts::Image blocks(32, 24);
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 32; ++x) blocks.set(x, y, {uint8_t(64 + 40 * (x / 8)), uint8_t(60 + 60 * (y / 8)), 128, 255});
    good("good_jpeg_blocks_32x24.jpg", ts::encodeJpeg(blocks, 100), blocks);
    cs.back().tolerance = 4;
  }
  good("good_bmp24_topdown_5x3.bmp", bmpTopDown(pic), pic);
  ts::Image big = rgbPicture(64, 33);
  good("good_bmp24_64x33.bmp", ts::encodeBmp(big), big);
  good("good_png_named_bmp.bmp", makePng(7, 5, 8, 6), expected(7, 5, 8, 6));  // content decides, not the name
  {
    Bytes b = ts::encodeBmp(pic);  // bfSize lies (the reader trusts the real length)
    b[2] = 0xff, b[3] = 0xff, b[4] = 0xff, b[5] = 0x7f;
    good("good_bmp24_lying_file_size.bmp", b, pic);
  }

  // ---- malformed: nothing, or not an image
  bad("empty.png", {}, "is empty");
  bad("text.png", Bytes{'h', 'e', 'l', 'l', 'o', '\n'}, "not a PNG, JPEG or BMP");
  bad("gif_magic.png", Bytes{'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0, 0, 0, 0}, "not a PNG, JPEG or BMP");
  bad("jpeg_magic.jpg", Bytes{0xff, 0xd8, 0xff, 0xe0, 0, 16, 'J', 'F', 'I', 'F', 0}, "malformed JPEG");
  {
    // ---- JPEG: libjpeg's own errors and warnings, as one line each
    ts::Image img = rgbPicture(37, 23);
    Bytes j = ts::encodeJpeg(img, 90);
    bad("jpeg_cut_in_half.jpg", cut(j, j.size() / 2), "Premature end");
    bad("jpeg_cut_in_header.jpg", cut(j, 40), "malformed JPEG");
    bad("jpeg_huge_65000x65000.jpg", jpegWithSize(img, 65000, 65000), "over the limit");
    bad("jpeg_16385x1.jpg", jpegWithSize(img, 16385, 1), "over the limit");
    bad("jpeg_zero_width.jpg", jpegWithSize(img, 0, 23), "malformed JPEG");
    bad("jpeg_no_image.jpg", Bytes{0xff, 0xd8, 0xff, 0xd9}, "malformed JPEG");
    Bytes noise = j;
    for (size_t i = noise.size() / 2; i < noise.size() / 2 + 40; ++i) noise[i] = uint8_t(i * 73);
    bad("jpeg_corrupt_scan.jpg", noise, "malformed JPEG");
    Bytes sof = j;
    size_t at = findSof(sof);
    if (at + 2 < sof.size()) sof[at + 2] = 12;  // 12-bit samples: not what libjpeg62 reads
    bad("jpeg_12bit.jpg", sof, "malformed JPEG");
  }
  {
    Bytes b = makePng(4, 4, 8, 2);
    b[1] = 'Q';
    bad("png_wrong_magic.png", b, "not a PNG, JPEG or BMP");
    Bytes c = makePng(4, 4, 8, 2);
    c[4] = '\n';  // the CR-LF check of the signature (a file mangled by a text transfer)
    bad("png_crlf_mangled.png", c, "bad signature");
  }
  // ---- PNG: truncated
  Bytes ok = makePng(37, 23, 8, 6);
  bad("png_signature_only.png", cut(ok, 8), "truncated");
  bad("png_cut_in_ihdr.png", cut(ok, 20), "truncated");
  bad("png_cut_after_ihdr.png", cut(ok, 33), "truncated");
  bad("png_cut_in_idat.png", cut(ok, ok.size() / 2), "truncated");
  bad("png_cut_before_iend.png", cut(ok, ok.size() - 12), "truncated");
  bad("png_cut_one_byte_short.png", cut(ok, ok.size() - 1), "truncated");
  // ---- PNG: bad CRCs
  {
    Bytes b = pngSignature();
    chunk(b, "IHDR", ihdr(4, 4, 8, 2), true);
    Bytes rest(ok.begin() + 33, ok.end());
    b.insert(b.end(), rest.begin(), rest.end());
    bad("png_bad_crc_ihdr.png", b, "CRC");
    Bytes d = ok;
    size_t idat = findChunk(d, "IDAT");
    uint32_t len = uint32_t(d[idat]) << 24 | uint32_t(d[idat + 1]) << 16 | uint32_t(d[idat + 2]) << 8 | d[idat + 3];
    d[idat + 8 + len] ^= 0x01;  // the IDAT's stored CRC, data intact
    bad("png_bad_crc_idat.png", d, "CRC");
  }
  // ---- PNG: zero, huge and lying dimensions
  bad("png_zero_width.png", pngWithRaw(0, 4, 8, 2, Bytes(4, 0)), "zero width");
  bad("png_zero_height.png", pngWithRaw(4, 0, 8, 2, Bytes(1, 0)), "zero height");
  bad("png_huge_100000x100000.png", pngWithRaw(100000, 100000, 8, 2, Bytes(64, 0)), "over the limit");
  bad("png_huge_16384x16384.png", pngWithRaw(16384, 16384, 8, 6, Bytes(64, 0)), "over the limit");
  bad("png_huge_2pow31.png", pngWithRaw(0x80000000u, 1, 8, 2, Bytes(64, 0)), "over the limit");
  bad("png_huge_4294967295x1.png", pngWithRaw(0xffffffffu, 1, 8, 2, Bytes(64, 0)), "over the limit");
  {
    Bytes raw;
    for (int y = 0; y < 2; ++y) {
      raw.push_back(0);
      raw.insert(raw.end(), 64 * 3, uint8_t(40 * y));
    }
    bad("png_header_says_64x64_data_for_2_rows.png", pngWithRaw(64, 64, 8, 2, raw), "image data");
  }
  {
    Bytes b = pngSignature();
    Bytes d = ihdr(4, 4, 8, 2);
    d.insert(d.end(), 7, 0);  // IHDR claims 20 bytes
    chunk(b, "IHDR", d);
    bad("png_ihdr_length_20.png", b, "13-byte IHDR");
    Bytes c = pngSignature();
    chunk(c, "gAMA", {0, 0, 0xb1, 0x8f});
    chunk(c, "IHDR", ihdr(4, 4, 8, 2));
    bad("png_first_chunk_not_ihdr.png", c, "13-byte IHDR");
  }
  // ---- PNG: invalid header fields and streams
  bad("png_bit_depth_7.png", pngWithRaw(4, 4, 7, 2, Bytes(4 * 13, 0)), "IHDR");
  bad("png_colour_type_5.png", pngWithRaw(4, 4, 8, 5, Bytes(4 * 13, 0)), "IHDR");
  bad("png_rgb_depth_4.png", pngWithRaw(4, 4, 4, 2, Bytes(4 * 7, 0)), "IHDR");
  {
    Bytes b = pngSignature();
    chunk(b, "IHDR", ihdr(4, 4, 8, 2, 2));
    chunk(b, "IDAT", zlibCompress(Bytes(4 * 13, 0)));
    chunk(b, "IEND", {});
    bad("png_interlace_method_2.png", b, "IHDR");
  }
  bad("png_palette_without_plte.png", pngWithRaw(4, 4, 8, 3, Bytes(4 * 5, 0)), "PLTE");
  {
    Bytes raw;
    for (int y = 0; y < 4; ++y) {
      raw.push_back(uint8_t(y == 2 ? 9 : 0));  // filter type 9 does not exist
      raw.insert(raw.end(), 12, uint8_t(y));
    }
    bad("png_filter_type_9.png", pngWithRaw(4, 4, 8, 2, raw), "filter");
  }
  {
    Bytes b = pngSignature();
    chunk(b, "IHDR", ihdr(4, 4, 8, 2));
    chunk(b, "IDAT", Bytes{'n', 'o', 't', ' ', 'z', 'l', 'i', 'b', 0, 1, 2, 3});
    chunk(b, "IEND", {});
    bad("png_idat_not_zlib.png", b, "malformed PNG");
    Bytes c = pngSignature();
    chunk(c, "IHDR", ihdr(4, 4, 8, 2));
    chunk(c, "IEND", {});
    bad("png_no_idat.png", c, "malformed PNG");
    Bytes d = pngSignature();
    chunk(d, "IHDR", ihdr(4, 4, 8, 2));
    be32(d, 0x7fffffffu);  // a chunk announcing 2 GiB, then the end of the file
    d.insert(d.end(), {'I', 'D', 'A', 'T', 1, 2, 3});
    bad("png_idat_length_2gib.png", d, "malformed PNG");
    Bytes e = pngSignature();
    chunk(e, "IHDR", ihdr(4, 4, 8, 2));
    be32(e, 0xfffffff0u);  // over 2^31: not a valid PNG length at all
    e.insert(e.end(), {'I', 'D', 'A', 'T', 1, 2, 3});
    bad("png_chunk_length_over_2pow31.png", e, "malformed PNG");
  }
  // ---- BMP
  Bytes bmp = ts::encodeBmp(pic);
  bad("bmp_magic_only.bmp", Bytes{'B', 'M'}, "truncated");
  bad("bmp_cut_in_file_header.bmp", cut(bmp, 10), "truncated");
  bad("bmp_cut_in_info_header.bmp", cut(bmp, 30), "truncated");
  bad("bmp_cut_in_pixels.bmp", cut(bmp, bmp.size() - 5), "truncated");
  bad("bmp_no_pixels.bmp", cut(bmp, 54), "truncated");
  bad("bmp_zero_width.bmp", bmpHeader(0, 3, 24, 0, 0), "zero width");
  bad("bmp_zero_height.bmp", bmpHeader(5, 0, 24, 0, 0), "zero height");
  bad("bmp_negative_width.bmp", bmpHeader(-5, 3, 24, 0, 48), "negative width");
  bad("bmp_huge_100000x100000.bmp", bmpHeader(100000, 100000, 24, 0, 16), "over the limit");
  bad("bmp_height_int_min.bmp", bmpHeader(4, INT32_MIN, 24, 0, 16), "over the limit");
  bad("bmp_huge_width_2pow31_minus_1.bmp", bmpHeader(0x7fffffff, 1, 24, 0, 16), "over the limit");
  bad(
      "bmp_header_says_1000x1000_data_for_5x3.bmp",
      [&] {
        Bytes b = bmpHeader(1000, 1000, 24, 0, 48);
        b.insert(b.end(), 48, 0x80);
        return b;
      }(),
      "truncated");
  bad("bmp_8bit_palette.bmp", bmpHeader(4, 4, 8, 0, 16), "8 bits per pixel");
  bad("bmp_16bit.bmp", bmpHeader(4, 4, 16, 0, 32), "16 bits per pixel");
  bad("bmp32_cut_in_pixels.bmp", bmpHeader(4, 4, 32, 0, 60), "truncated");
  bad("bmp32_mask_not_one_run.bmp", bmp32Masks(2, 2, 0x00ff00ff, 0x0000ff00, 0xff), "not one run");
  bad("bmp32_masks_overlap.bmp", bmp32Masks(2, 2, 0x00ff0000, 0x00ffff00, 0xff), "overlap");
  bad("bmp32_masks_all_zero.bmp", bmp32Masks(2, 2, 0, 0, 0), "all zero");
  bad("bmp32_cut_in_masks.bmp", cut(bmp32Masks(2, 2, 0xff, 0xff00, 0xff0000), 60), "bitfield masks");
  bad("bmp_rle8.bmp", bmpHeader(4, 4, 24, 1, 16), "compression 1");
  bad("bmp_bitfields.bmp", bmpHeader(4, 4, 24, 3, 48), "compression 3");
  bad(
      "bmp_os2_core_header.bmp",
      [] {
        Bytes b{'B', 'M'};
        le32(b, 26 + 12);
        le32(b, 0);
        le32(b, 26);
        le32(b, 12);
        le16(b, 2), le16(b, 2), le16(b, 1), le16(b, 24);
        b.insert(b.end(), 16, 0);
        return b;
      }(),
      "OS/2");
  bad("bmp_info_size_7.bmp", bmpHeader(4, 4, 24, 0, 48, 40) /* patched below */, "info header size");
  cs.back().bytes[14] = 7;
  bad("bmp_info_size_huge.bmp", bmpHeader(4, 4, 24, 0, 48), "info header size");
  cs.back().bytes[14] = 0xff, cs.back().bytes[17] = 0x7f;
  bad("bmp_planes_2.bmp", bmpHeader(4, 4, 24, 0, 48, 40, 2), "planes");
  bad(
      "bmp_pixel_offset_past_end.bmp",
      [&] {
        Bytes b = bmpHeader(5, 3, 24, 0, 48, 40, 1, 0x10000000u);
        b.insert(b.end(), 48, 0);
        return b;
      }(),
      "outside the file");
  bad(
      "bmp_pixel_offset_inside_header.bmp",
      [&] {
        Bytes b = bmpHeader(5, 3, 24, 0, 48, 40, 1, 20);
        b.insert(b.end(), 48, 0);
        return b;
      }(),
      "outside the file");
  return cs;
}
}  // namespace corpus
