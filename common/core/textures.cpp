#include "common/core/textures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "common/core/error.hpp"
#include "common/core/kept.hpp"
#include "common/core/text.hpp"

namespace ts {
static std::string str(int v) { return std::to_string(v); }
static std::string str(Rgba c) { return str(c.r) + "," + str(c.g) + "," + str(c.b) + "," + str(c.a); }

// Images are stored top row first (PNG order) but GL's texel row 0 is t = 0,
// the bottom.  Textures are uploaded row 0 first, so the Image's row 0 is
// t = 0 here: generators index rows by t directly.
TextureDesc checkerboard(int size, int checks, Rgba a, Rgba b) {
  if (size < 1 || size > kMaxImageDimension || checks < 1 || checks > size)
    throw Error("checkerboard: size " + str(size) + " with " + str(checks) + " checks is invalid");
  auto img = std::make_shared<Image>(size, size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      int ci = i * checks / size, cj = j * checks / size;
      img->set(i, j, ((ci + cj) % 2 == 0) ? a : b);
    }
  TextureDesc t;
  t.name = "checkerboard";
  t.params = {{"size", str(size)}, {"checks", str(checks)}, {"color_a", str(a)}, {"color_b", str(b)}};
  t.image = img;
  return t;
}

TextureDesc lineGrid(int size, int cells, Rgba line, Rgba background) {
  if (size < 2 || size > kMaxImageDimension || cells < 1 || cells > size - 1)
    throw Error("line_grid: size " + str(size) + " with " + str(cells) + " cells is invalid");
  std::vector<bool> onLine(size_t(size), false);
  for (int k = 0; k <= cells; ++k) onLine[size_t((size - 1) * k / cells)] = true;
  auto img = std::make_shared<Image>(size, size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) img->set(i, j, onLine[size_t(i)] || onLine[size_t(j)] ? line : background);
  TextureDesc t;
  t.name = "line_grid";
  t.params = {{"size", str(size)},
              {"cells", str(cells)},
              {"color_line", str(line)},
              {"color_background", str(background)}};
  t.image = img;
  return t;
}

Rgba checkerAt(int size, int checks, Rgba a, Rgba b, double s, double t) {
  auto texel = [size](double c) {
    double f = c - std::floor(c);
    return std::min(size - 1, int(std::floor(f * size)));
  };
  int i = texel(s), j = texel(t);
  int ci = i * checks / size, cj = j * checks / size;
  return ((ci + cj) % 2 == 0) ? a : b;
}

TextureDesc texelIndexTexture(int size) {
  if (size < 1 || size > 4096) throw Error("texel index texture: size must be 1..4096");
  auto make = [size] {
    auto img = std::make_shared<Image>(size, size);
    uint8_t* p = img->pixels.data();
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i, p += 4)
        p[0] = uint8_t(i & 255), p[1] = uint8_t(j & 255), p[2] = uint8_t((i >> 8) | ((j >> 8) << 4)), p[3] = 255;
    return std::shared_ptr<const Image>(img);
  };
  // Made once per process for sizes up to 2048 (16 MB): a demo's measurement
  // asks for the same one pass after pass.  Larger ones are made each time,
  // so that they do not stay beside a demo's peak.
  static Kept<int, std::shared_ptr<const Image>> kept(2);
  TextureDesc t;
  t.image = size <= 2048 ? kept.get(size, make) : make();
  t.name = "texel_index";
  t.params = {{"size", str(size)}};
  t.minFilter = t.magFilter = GL_NEAREST;
  return t;
}

TextureDesc gradientTexture(int width, int height, bool alphaRamp) {
  if (width < 2 || height < 2 || width > 4096 || height > 4096) throw Error("gradient texture: sizes must be 2..4096");
  auto img = std::make_shared<Image>(width, height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      img->set(i, j,
               {uint8_t(40 + 200 * i / (width - 1)), uint8_t(40 + 200 * j / (height - 1)),
                uint8_t((i + j) % 2 ? 50 : 150), uint8_t(alphaRamp ? 255 - 191 * i / (width - 1) : 255)});
  TextureDesc t;
  t.name = "gradient";
  t.params = {{"width", str(width)}, {"height", str(height)}, {"alpha", alphaRamp ? "ramp" : "opaque"}};
  t.image = img;
  return t;
}

namespace {
std::string digestOf(const Image& img) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a 64
  for (uint8_t b : img.pixels) h = (h ^ b) * 1099511628211ull;
  char digest[20];
  std::snprintf(digest, sizeof digest, "%016llx", static_cast<unsigned long long>(h));
  return digest;
}
}  // namespace

TextureDesc nestedPictureTexture(const Image& img, const Frame& frame, const std::string& generator,
                                 const std::string& what) {
  TextureDesc t;
  t.name = generator;
  t.params = {{"pass", what}, {"digest", digestOf(img)}};
  t.image = std::make_shared<const Image>(img);
  t.renderedFrom = std::make_shared<const Frame>(frame);
  t.minFilter = t.magFilter = GL_LINEAR;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}

TextureDesc renderedImageTexture(const Image& img, const std::string& generator, const std::string& what,
                                 const std::string& demo,
                                 std::vector<std::pair<std::string, std::string>> extraParams) {
  const std::string digest = digestOf(img);
  TextureDesc t;
  t.name = generator;
  t.params = {{"image", what}};
  for (auto& p : extraParams) t.params.push_back(std::move(p));
  t.params.push_back({"size", std::to_string(img.width) + "x" + std::to_string(img.height)});
  t.params.push_back({"made_by", "the " + demo + " demo's measure(): rerun the sidecar's command"});
  t.params.push_back({"digest", digest});
  Image flipped = img;
  flipped.flipVertical();  // texture row 0 is t = 0, the bottom
  t.image = std::make_shared<const Image>(std::move(flipped));
  t.minFilter = t.magFilter = GL_NEAREST;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}

TextureDesc fileTexture(const std::string& path) {
  Image img = readImage(path);  // PNG, JPEG or 24/32-bit BMP, by content
  img.flipVertical();           // a picture's top row is t = 1
  TextureDesc t;
  t.name = "file";
  t.params = {{"path", path}, {"width", str(img.width)}, {"height", str(img.height)}};
  t.image = std::make_shared<Image>(std::move(img));
  return t;
}

Image resizeBilinear(const Image& src, int width, int height) {
  if (src.empty()) throw Error("resizeBilinear: empty source image", kExitFailure);
  Image dst(width, height);
  for (int y = 0; y < height; ++y) {
    double fy = std::clamp((y + 0.5) * src.height / height - 0.5, 0.0, double(src.height - 1));
    int y0 = int(fy), y1 = std::min(y0 + 1, src.height - 1);
    double ay = fy - y0;
    for (int x = 0; x < width; ++x) {
      double fx = std::clamp((x + 0.5) * src.width / width - 0.5, 0.0, double(src.width - 1));
      int x0 = int(fx), x1 = std::min(x0 + 1, src.width - 1);
      double ax = fx - x0;
      Rgba p00 = src.at(x0, y0), p10 = src.at(x1, y0), p01 = src.at(x0, y1), p11 = src.at(x1, y1);
      auto mix = [&](uint8_t a, uint8_t b, uint8_t c, uint8_t d) {
        double v = (a * (1 - ax) + b * ax) * (1 - ay) + (c * (1 - ax) + d * ax) * ay;
        return uint8_t(std::clamp(std::lround(v), 0L, 255L));
      };
      dst.set(x, y,
              {mix(p00.r, p10.r, p01.r, p11.r), mix(p00.g, p10.g, p01.g, p11.g), mix(p00.b, p10.b, p01.b, p11.b),
               mix(p00.a, p10.a, p01.a, p11.a)});
    }
  }
  return dst;
}

void decodeTexelIndex(Rgba c, int* i, int* j) {
  *i = c.r | ((c.b & 15) << 8);
  *j = c.g | ((c.b >> 4) << 8);
}

TextureDesc labelledGrid(int size, int cells) {
  if (size < 16 || size > 4096 || cells < 1 || cells > 26) throw Error("labelled grid: size 16..4096 and 1..26 cells");
  // Drawn top-down as a picture, then flipped so the picture's top is t = 1.
  Image pic(size, size);
  // Cell k spans pixels [k*size/cells, (k+1)*size/cells): every pixel belongs
  // to a cell even when size is not a multiple of cells.
  auto edge = [&](int k) { return k * size / cells; };
  int cs = size / cells;
  for (int cy = 0; cy < cells; ++cy)
    for (int cx = 0; cx < cells; ++cx) {
      int row = cells - 1 - cy;  // row number counted from the bottom
      // Hue varies with the column, brightness with the row: both
      // directions can be read off any patch.
      Rgba c{uint8_t(60 + 180 * cx / std::max(1, cells - 1)), uint8_t(90 + 120 * row / std::max(1, cells - 1)),
             uint8_t(200 - 150 * cx / std::max(1, cells - 1)), 255};
      for (int y = edge(cy); y < edge(cy + 1); ++y)
        for (int x = edge(cx); x < edge(cx + 1); ++x) {
          bool border = x == edge(cx) || y == edge(cy);
          pic.set(x, y, border ? Rgba{20, 20, 20, 255} : c);
        }
      std::string label = std::string(1, char('A' + cx)) + std::to_string(row + 1);
      int scale = std::clamp(cs / 26, 1, text::kMaxScale);
      float tw = text::width(label, scale);
      text::draw(pic, float(edge(cx)) + (float(cs) - tw) / 2, float(edge(cy)) + (float(cs) - text::height(scale)) / 2,
                 label, {255, 255, 255, 255}, scale);
    }
  // An arrow-free orientation cue: a bright bar along the bottom edge (t = 0).
  for (int y = size - std::max(2, size / 64); y < size; ++y)
    for (int x = 0; x < size; ++x) pic.set(x, y, {250, 220, 40, 255});
  pic.flipVertical();
  TextureDesc t;
  t.name = "labelled_grid";
  t.params = {{"size", str(size)}, {"cells", str(cells)}};
  t.image = std::make_shared<Image>(std::move(pic));
  return t;
}

Rgba mipLevelColour(int level) {
  static const Rgba k[] = {{230, 40, 40, 255},   {40, 200, 40, 255},   {40, 80, 230, 255},  {230, 210, 40, 255},
                           {200, 40, 200, 255},  {40, 200, 200, 255},  {240, 140, 30, 255}, {240, 240, 240, 255},
                           {120, 120, 120, 255}, {20, 20, 20, 255},    {150, 90, 40, 255},  {90, 40, 150, 255},
                           {40, 110, 60, 255},   {250, 170, 180, 255}, {60, 60, 140, 255}};
  return k[size_t(std::max(0, level)) % (sizeof k / sizeof k[0])];
}

TextureDesc mipLevelColours(int size) {
  if (size < 1 || size > kMaxImageDimension || (size & (size - 1)) != 0)
    throw Error("mip level texture: size must be a power of two");
  TextureDesc t;
  t.name = "mip_level_colours";
  t.params = {{"size", str(size)}};
  auto levels = std::make_shared<std::vector<Image>>();
  for (int k = 0, s = size; s >= 1; ++k, s /= 2) levels->emplace_back(s, s, mipLevelColour(k));
  t.image = std::make_shared<Image>(levels->front());
  t.mipLevels = levels;
  t.mipmaps = true;
  t.minFilter = GL_NEAREST_MIPMAP_NEAREST;
  return t;
}

static double toLinear(uint8_t v) {
  double c = v / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
static uint8_t fromLinear(double c) {
  double v = c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
  return uint8_t(std::clamp(std::lround(v * 255.0), 0L, 255L));
}

std::vector<Image> buildMipChain(const Image& level0, bool linearLight) {
  std::vector<Image> chain{level0};
  while (chain.back().width > 1 || chain.back().height > 1) {
    const Image& src = chain.back();
    int w = std::max(1, src.width / 2), h = std::max(1, src.height / 2);
    Image dst(w, h);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        int x0 = std::min(2 * i, src.width - 1), x1 = std::min(2 * i + 1, src.width - 1);
        int y0 = std::min(2 * j, src.height - 1), y1 = std::min(2 * j + 1, src.height - 1);
        Rgba p[4] = {src.at(x0, y0), src.at(x1, y0), src.at(x0, y1), src.at(x1, y1)};
        uint8_t out[4];
        for (int c = 0; c < 4; ++c) {
          auto ch = [c](const Rgba& q) { return c == 0 ? q.r : c == 1 ? q.g : c == 2 ? q.b : q.a; };
          if (linearLight && c < 3) {
            double sum = 0;
            for (auto& q : p) sum += toLinear(ch(q));
            out[c] = fromLinear(sum / 4);
          } else {
            int sum = 0;
            for (auto& q : p) sum += ch(q);
            out[c] = uint8_t((sum + 2) / 4);  // round half up
          }
        }
        dst.set(i, j, {out[0], out[1], out[2], out[3]});
      }
    chain.push_back(std::move(dst));
  }
  return chain;
}

double mipChainOverhead(const std::vector<Image>& chain) {
  if (chain.empty()) return 0;
  double base = double(chain[0].width) * chain[0].height, extra = 0;
  for (size_t k = 1; k < chain.size(); ++k) extra += double(chain[k].width) * chain[k].height;
  return extra / base;
}
}  // namespace ts
