#include "demos/multitexture/multitexture_textures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "common/core/error.hpp"
#include "common/core/texture_generators.hpp"

namespace ts::multitex {
namespace {
uint8_t u8(double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }
TextureDesc desc(const std::string& name, std::vector<std::pair<std::string, std::string>> params, Image img) {
  TextureDesc t;
  t.name = name;
  t.params = std::move(params);
  t.image = std::make_shared<const Image>(std::move(img));
  return t;
}
Image flipped(Image img) {
  img.flipVertical();
  return img;
}
}  // namespace

bool inTree(double x, double y) {
  const bool trunk = std::abs(x - 0.5) < 0.07 && y < 0.4;
  const double ex = (x - 0.5) / 0.4, ey = (y - 0.62) / 0.34;
  return trunk || ex * ex + ey * ey < 1.0;
}
Image treeImage() {
  constexpr int n = 64;
  Image t(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) / n, y = (j + 0.5) / n;
      const bool trunk = std::abs(x - 0.5) < 0.07 && y < 0.4;
      const uint8_t shade = uint8_t(110 + ((i * 7 + j * 13) % 5) * 12);  // a little texture in the leaves
      Rgba c = trunk && y < 0.3 ? Rgba{110, 70, 30, 255} : Rgba{40, shade, 30, 255};
      if (!inTree(x, y)) c = {40, 120, 30, 0};
      t.set(i, j, c);
    }
  return t;
}
Image bricksImage() {
  Image b(128, 128);
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i < 128; ++i) {
      const int row = j / 16, x = (i + (row % 2) * 16) % 32;
      const bool mortar = j % 16 < 2 || x < 2;
      const uint8_t v = uint8_t(150 + ((i * 5 + j * 11 + row * 7) % 9) * 8);
      b.set(i, j, mortar ? Rgba{170, 165, 150, 255} : Rgba{v, uint8_t(v / 3 + 20), uint8_t(v / 4 + 10), 255});
    }
  return b;
}
double lightAt(double x, double y) {
  const double h = kLightHeight, d = std::sqrt((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) + h * h);
  return 0.15 + 0.85 * std::pow(h / d, 3.0);
}
Image lightMapImage(int n) {
  Image m(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint8_t v = u8(lightAt((i + 0.5) / n, (j + 0.5) / n));
      m.set(i, j, {v, v, v, 255});
    }
  return m;
}
Image spotImage() {
  constexpr int n = 32;
  Image m(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double r = std::hypot((i + 0.5) / n - 0.5, (j + 0.5) / n - 0.5);
      const uint8_t v = u8(0.2 + 0.8 * std::clamp((0.42 - r) / 0.12, 0.0, 1.0));
      m.set(i, j, {v, v, v, 255});
    }
  return m;
}
Image perPixelLitImage(const Image& base, int w) {
  Image out(w, w);
  for (int row = 0; row < w; ++row)
    for (int x = 0; x < w; ++x) {
      const Rgba b = base.at(x * base.width / w, row * base.height / w);
      const double l = lightAt((x + 0.5) / w, (row + 0.5) / w);
      out.set(x, row, {u8(b.r / 255.0 * l), u8(b.g / 255.0 * l), u8(b.b / 255.0 * l), 255});
    }
  return out;
}
Image glossImage(int w, int h) {
  Image g(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const uint8_t v = i < w / 2 ? 255 : uint8_t(kGlossLow * 255.0 + 0.5);
      g.set(i, j, {v, v, v, 255});
    }
  return g;
}
std::vector<Image> abcdImages() {
  std::vector<Image> t(4, Image(kAbcdSize, kAbcdSize));
  for (int j = 0; j < kAbcdSize; ++j)
    for (int i = 0; i < kAbcdSize; ++i) {
      const double x = (i + 0.5) / kAbcdSize, y = (j + 0.5) / kAbcdSize;
      const uint8_t a = uint8_t(60 + 120 * x), b = ((i / 8 + j / 8) % 2) ? 240 : 90;
      const uint8_t c = (i / 4) % 2 ? 135 : 40, d = uint8_t(70 + 65 * std::cos(18.0 * std::hypot(x - 0.5, y - 0.5)));
      t[0].set(i, j, {a, uint8_t(a / 2), uint8_t(180 - a / 2), 255});
      t[1].set(i, j, {b, b, uint8_t(b * 3 / 4), 255});
      t[2].set(i, j, {c, uint8_t(c / 2), c, 255});
      t[3].set(i, j, {d, d, uint8_t(135 - d / 2), 255});
    }
  return t;
}
Image abcdCpuImage(const std::vector<Image>& t, int w, bool framebufferOnly) {
  Image out(w, w);
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) {
      const int i = x * kAbcdSize / w, j = (w - 1 - y) * kAbcdSize / w;
      const Rgba A = t[0].at(i, j), B = t[1].at(i, j), C = t[2].at(i, j), D = t[3].at(i, j);
      uint8_t o[3];
      const uint8_t ca[3] = {A.r, A.g, A.b}, cb[3] = {B.r, B.g, B.b}, cc[3] = {C.r, C.g, C.b}, cd[3] = {D.r, D.g, D.b};
      for (int k = 0; k < 3; ++k) {
        const double ab = std::round(ca[k] * cb[k] / 255.0);
        o[k] = framebufferOnly ? u8(std::round(std::min(255.0, ab + cc[k])) * cd[k] / 255.0 / 255.0)
                               : u8((ab + std::round(cc[k] * cd[k] / 255.0)) / 255.0);
      }
      out.set(x, y, {o[0], o[1], o[2], 255});
    }
  return out;
}

Image pearSkinImage() {
  Image t(128, 128);
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i < 128; ++i) {
      const bool speck = ((i * 37 + j * 91) % 53) < 3;
      const bool band = j > 70 && j < 84;
      const uint8_t g = speck || band ? 25 : 150;
      t.set(i, j, speck ? Rgba{120, 90, 30, g} : Rgba{uint8_t(170 + j / 4), 190, 60, g});
    }
  return t;
}
Image pearGlossImage() {
  Image t = pearSkinImage();
  for (size_t k = 0; k < t.pixels.size(); k += 4)
    t.pixels[k] = t.pixels[k + 1] = t.pixels[k + 2] = t.pixels[k + 3], t.pixels[k + 3] = 255;
  return t;
}
Image pearSkyImage() {
  Image t(128, 128);
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i < 128; ++i) {
      const double x = (i + 0.5) / 64 - 1, y = (j + 0.5) / 64 - 1;
      const bool window = x > 0.1 && x < 0.5 && y > 0.25 && y < 0.65;
      const uint8_t s = u8(0.1 + 0.3 * (y + 1) / 2);
      t.set(i, j, window ? Rgba{255, 250, 235, 255} : Rgba{uint8_t(s / 2), s, uint8_t(std::min(255, s * 2)), 255});
    }
  return t;
}

TextureDesc treeTexture() { return desc("multitexture_tree", {{"size", "64"}}, treeImage()); }
TextureDesc bricksTexture() { return desc("multitexture_bricks", {{"size", "128"}}, bricksImage()); }
TextureDesc lightMapTexture(int n) {
  return desc("multitexture_light_map", {{"size", std::to_string(n)}}, lightMapImage(n));
}
TextureDesc spotTexture() { return desc("multitexture_spot", {{"size", "32"}}, spotImage()); }
TextureDesc perPixelLitTexture(int w) {
  return desc("multitexture_per_pixel_lit", {{"base", "multitexture_bricks"}, {"size", std::to_string(w)}},
              perPixelLitImage(bricksImage(), w));
}
TextureDesc glossTexture(int w, int h) {
  return desc("multitexture_gloss", {{"width", std::to_string(w)}, {"height", std::to_string(h)}}, glossImage(w, h));
}
TextureDesc abcdTexture(int k) {
  if (k < 0 || k > 3) throw Error("multitexture_abcd: texture must be A, B, C or D");
  return desc("multitexture_abcd", {{"texture", std::string(1, char('A' + k))}}, abcdImages()[size_t(k)]);
}
TextureDesc abcdCpuTexture(int w, const std::string& what) {
  const std::vector<Image> t = abcdImages();
  Image img;
  if (what == "sum" || what == "framebuffer_only") {
    img = abcdCpuImage(t, w, what != "sum");
  } else if (what == "error_x4") {
    const Image a = abcdCpuImage(t, w, true), b = abcdCpuImage(t, w, false);
    img = Image(w, w);
    for (int y = 0; y < w; ++y)
      for (int x = 0; x < w; ++x) {
        auto e = [](int p, int q) { return uint8_t(std::min(255, 4 * std::abs(p - q))); };
        const Rgba p = a.at(x, y), q = b.at(x, y);
        img.set(x, y, {e(p.r, q.r), e(p.g, q.g), e(p.b, q.b), 255});
      }
  } else {
    throw Error("multitexture_abcd_cpu: picture must be sum, framebuffer_only or error_x4, not '" + what + "'");
  }
  return desc("multitexture_abcd_cpu", {{"picture", what}, {"size", std::to_string(w)}}, flipped(img));
}

TextureDesc pearSkinTexture() { return desc("multitexture_pear_skin", {{"size", "128"}}, pearSkinImage()); }
TextureDesc pearGlossTexture() { return desc("multitexture_pear_gloss", {{"size", "128"}}, pearGlossImage()); }
TextureDesc pearSkyTexture() { return desc("multitexture_pear_sky", {{"size", "128"}}, pearSkyImage()); }

bool remake(const std::string& name, const std::vector<std::pair<std::string, std::string>>& p, TextureDesc* out) {
  auto param = [&](const char* key) -> std::string {
    for (const auto& [k, v] : p)
      if (k == key) return v;
    throw Error(name + ": missing param '" + key + "'");
  };
  auto size = [&](const char* key, int lo, int hi) {
    const std::string v = param(key);
    char* end = nullptr;
    const long n = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end || n < lo || n > hi)
      throw Error(name + ": param '" + key + "' must be " + std::to_string(lo) + ".." + std::to_string(hi));
    return int(n);
  };
  if (name == "multitexture_tree") return *out = treeTexture(), true;
  if (name == "multitexture_bricks") return *out = bricksTexture(), true;
  if (name == "multitexture_light_map") return *out = lightMapTexture(size("size", 1, 1024)), true;
  if (name == "multitexture_spot") return *out = spotTexture(), true;
  if (name == "multitexture_per_pixel_lit") return *out = perPixelLitTexture(size("size", 1, 2048)), true;
  if (name == "multitexture_gloss") return *out = glossTexture(size("width", 1, 1024), size("height", 1, 1024)), true;
  if (name == "multitexture_abcd") {
    const std::string k = param("texture");
    if (k.size() != 1 || k[0] < 'A' || k[0] > 'D') throw Error(name + ": texture must be A, B, C or D");
    return *out = abcdTexture(k[0] - 'A'), true;
  }
  if (name == "multitexture_pear_skin") return *out = pearSkinTexture(), true;
  if (name == "multitexture_pear_gloss") return *out = pearGlossTexture(), true;
  if (name == "multitexture_pear_sky") return *out = pearSkyTexture(), true;
  if (name == "multitexture_abcd_cpu") return *out = abcdCpuTexture(size("size", 1, 2048), param("picture")), true;
  return false;
}
}  // namespace ts::multitex

// The sidecar reader finds these through the registry (common/core/texture_generators.hpp).
TS_REGISTER_TEXTURE_GENERATOR("multitexture_*", ts::multitex::remake);
