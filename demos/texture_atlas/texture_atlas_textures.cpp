// demos/texture_atlas/texture_atlas_textures.cpp — the atlas demo's textures (texture_atlas_textures.hpp), and
// their generator for the sidecar reader.
#include "demos/texture_atlas/texture_atlas_textures.hpp"

#include <algorithm>
#include <memory>
#include <string>

#include "common/core/error.hpp"
#include "common/core/gl_enums.hpp"
#include "common/core/texture_generators.hpp"
#include "common/core/textures.hpp"

namespace ts::atlas {
namespace {
// Sixteen colours far apart, so that a neighbour's texel mixed into a tile shows.
const Rgba kPalette[kTiles] = {{230, 60, 50, 255},  {60, 180, 75, 255},   {255, 225, 25, 255}, {0, 130, 200, 255},
                               {245, 130, 48, 255}, {145, 30, 180, 255},  {70, 240, 240, 255}, {240, 50, 230, 255},
                               {210, 245, 60, 255}, {250, 190, 212, 255}, {0, 128, 128, 255},  {220, 190, 255, 255},
                               {170, 110, 40, 255}, {255, 250, 200, 255}, {128, 0, 0, 255},    {170, 255, 195, 255}};
const Rgba kUnused{90, 90, 90, 255};  // atlas texels no cell covers (past kGrid pitches)
int nextPow2(int v) {
  int p = 1;
  while (p < v) p *= 2;
  return p;
}
void check(int k, int gutter) {
  if (k < 0 || k >= kTiles) throw Error("texture_atlas: tile " + std::to_string(k) + " out of range");
  if (gutter < 0 || gutter > 64) throw Error("texture_atlas: gutter " + std::to_string(gutter) + " out of range");
}
TextureDesc mipmapped(std::string name, TextureParams params, Image img, int maxLevel) {
  TextureDesc t;
  t.name = std::move(name);
  t.params = std::move(params);
  t.mipmaps = true;
  std::vector<Image> chain = buildMipChain(img);
  if (maxLevel >= 0 && size_t(maxLevel + 1) < chain.size()) {
    chain.resize(size_t(maxLevel + 1));
    t.params.push_back({"max_level", std::to_string(maxLevel)});
    t.mipLevels = std::make_shared<const std::vector<Image>>(std::move(chain));
  }
  t.image = std::make_shared<const Image>(std::move(img));
  t.minFilter = GL_LINEAR_MIPMAP_LINEAR, t.magFilter = GL_LINEAR;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}
}  // namespace

int pitch(int gutter) { return kTile + 2 * gutter; }
int atlasSize(int gutter) { return nextPow2(kGrid * pitch(gutter)); }
int tileX(int k, int gutter) { return (k % kGrid) * pitch(gutter) + gutter; }
int tileY(int k, int gutter) { return (k / kGrid) * pitch(gutter) + gutter; }

Image tileImage(int k) {
  check(k, 0);
  const Rgba a = kPalette[k];
  const Rgba b{uint8_t(a.r * 2 / 5), uint8_t(a.g * 2 / 5), uint8_t(a.b * 2 / 5), 255};
  const int check = 4 + 2 * (k % 3);  // checks of 4, 6 or 8 texels: no two neighbours alike
  Image img(kTile, kTile);
  for (int j = 0; j < kTile; ++j)
    for (int i = 0; i < kTile; ++i) img.set(i, j, ((i / check) + (j / check)) % 2 ? b : a);
  return img;
}

Image atlasImage(int gutter) {
  check(0, gutter);
  const int n = atlasSize(gutter), p = pitch(gutter);
  Image img(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) img.set(x, y, kUnused);
  for (int k = 0; k < kTiles; ++k) {
    const Image cell = cellImage(k, gutter);
    for (int j = 0; j < p; ++j)
      for (int i = 0; i < p; ++i) img.set((k % kGrid) * p + i, (k / kGrid) * p + j, cell.at(i, j));
  }
  return img;
}

Image cellImage(int k, int gutter) {
  check(k, gutter);
  const Image tile = tileImage(k);
  const int p = pitch(gutter);
  Image img(p, p);
  // The gutter: each texel the tile's nearest edge texel (the edge replicated, corners included).
  for (int j = 0; j < p; ++j)
    for (int i = 0; i < p; ++i)
      img.set(i, j, tile.at(std::clamp(i - gutter, 0, kTile - 1), std::clamp(j - gutter, 0, kTile - 1)));
  return img;
}

std::vector<Image> levelImages(int size) {
  std::vector<Image> levels;
  for (int k = 0, s = size; s >= 1; ++k, s /= 2) {
    Image img(s, s);
    const Rgba c{uint8_t(std::min(255, kLevelRed * k)), 40, uint8_t(std::max(0, 255 - kLevelRed * k)), 255};
    for (int j = 0; j < s; ++j)
      for (int i = 0; i < s; ++i) img.set(i, j, c);
    levels.push_back(std::move(img));
  }
  return levels;
}

TextureDesc atlasTexture(int gutter, int maxLevel) {
  return mipmapped("texture_atlas_atlas", {{"gutter", std::to_string(gutter)}}, atlasImage(gutter), maxLevel);
}
TextureDesc cellTexture(int k, int gutter, int maxLevel) {
  return mipmapped("texture_atlas_cell", {{"tile", std::to_string(k)}, {"gutter", std::to_string(gutter)}},
                   cellImage(k, gutter), maxLevel);
}
TextureDesc levelTexture(int size) {
  TextureDesc t;
  t.name = "texture_atlas_levels";
  t.params = {{"size", std::to_string(size)}};
  std::vector<Image> levels = levelImages(size);
  t.image = std::make_shared<const Image>(levels[0]);
  t.mipmaps = true;
  t.mipLevels = std::make_shared<const std::vector<Image>>(std::move(levels));
  t.minFilter = GL_LINEAR_MIPMAP_LINEAR, t.magFilter = GL_LINEAR;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}
TextureDesc sourceTexture() {
  TextureDesc t;
  t.name = "texture_atlas_source";
  t.image = std::make_shared<const Image>(atlasImage(0));
  // Shown magnified by a ratio that is not whole: a pixel centre on a texel edge would make GL_NEAREST's tie go
  // either way (OSMesa and an FBO differ there), GL_LINEAR's blend is the same everywhere.
  t.minFilter = t.magFilter = GL_LINEAR;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}
TextureDesc tileTexture(int k) {
  TextureDesc t;
  t.name = "texture_atlas_tile";
  t.params = {{"tile", std::to_string(k)}};
  t.image = std::make_shared<const Image>(tileImage(k));
  t.minFilter = t.magFilter = GL_NEAREST;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}

namespace {
int maxLevelParam(const TextureParams& params, const std::string& name) {
  for (const auto& kv : params)
    if (kv.first == "max_level") {
      const int m = intParam(params, "max_level", name);
      if (m < 0 || m > 16) throw Error("sidecar: texture '" + name + "': max_level out of range");
      return m;
    }
  return -1;
}
bool remake(const std::string& name, const TextureParams& params, TextureDesc* out) {
  if (name == "texture_atlas_atlas") {
    const int g = intParam(params, "gutter", name);
    check(0, g);
    *out = atlasTexture(g, maxLevelParam(params, name));
  } else if (name == "texture_atlas_cell") {
    const int k = intParam(params, "tile", name), g = intParam(params, "gutter", name);
    check(k, g);
    *out = cellTexture(k, g, maxLevelParam(params, name));
  } else if (name == "texture_atlas_levels") {
    const int s = intParam(params, "size", name);
    if (s < 1 || s > 4096) throw Error("sidecar: texture '" + name + "': size out of range");
    *out = levelTexture(s);
  } else if (name == "texture_atlas_source") {
    *out = sourceTexture();
  } else if (name == "texture_atlas_tile") {
    const int k = intParam(params, "tile", name);
    check(k, 0);
    *out = tileTexture(k);
  } else {
    return false;
  }
  return true;
}
}  // namespace
}  // namespace ts::atlas

// The sidecar reader finds it through the registry (common/core/texture_generators.hpp).
TS_REGISTER_TEXTURE_GENERATOR("texture_atlas_*", ts::atlas::remake);
