// demos/procedural_texture/procedural_texture_textures.cpp — the demo's textures (procedural_texture_textures.hpp),
// and their generator for the sidecar reader.
#include "demos/procedural_texture/procedural_texture_textures.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/gl_enums.hpp"
#include "common/core/texture_generators.hpp"
#include "demos/procedural_texture/procedural_texture_math.hpp"

namespace ts::proc {
namespace {
uint8_t u8(double v) { return uint8_t(v < 0 ? 0 : v > 255 ? 255 : v + 0.5); }
TextureDesc described(const std::string& name, std::vector<std::pair<std::string, std::string>> params, Image img,
                      GLenum filter) {
  TextureDesc t;
  t.name = name;
  t.params = std::move(params);
  t.image = std::make_shared<const Image>(std::move(img));
  t.minFilter = t.magFilter = filter;
  t.wrapS = t.wrapT = t.wrapR = GL_CLAMP_TO_EDGE;
  return t;
}
}  // namespace

Rgba stoneColour(double v) {
  v = std::clamp(0.5 + 2.2 * (v - 0.5), 0.0, 1.0);  // the sum's values gather round 1/2: spread them
  return {u8(30 + 210 * v), u8(40 + 180 * v), u8(60 + 130 * v), 255};
}
Rgba marbleColour(double v) { return {u8(70 + 180 * v), u8(60 + 180 * v), u8(80 + 170 * v), 255}; }

TextureDesc solidTexture(int kind, int oct, int stripes, int turbulencePercent) {
  // 64^3 texels take tens of milliseconds, and the window builds its frame each time it draws: made once for
  // each state (the measurement's thread asks too, hence the lock).
  if (kind == 0) stripes = turbulencePercent = 0;  // the noise has neither: its parameters say so
  static std::mutex lock;
  static std::map<std::tuple<int, int, int, int>, TextureDesc> made;
  const auto key = std::make_tuple(kind, oct, stripes, turbulencePercent);
  {
    std::lock_guard<std::mutex> hold(lock);
    auto it = made.find(key);
    if (it != made.end()) return it->second;
  }
  const int n = kSolidTexels;
  Image img(n, n * n);  // slice k in rows k n .. k n + n - 1 (TextureDesc::depth)
  const Lattice& l = lattice();
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = (i + 0.5) / n, y = (j + 0.5) / n, z = (k + 0.5) / n;
        img.set(i, k * n + j,
                kind == 0 ? stoneColour(octaves(l, x, y, z, oct))
                          : marbleColour(marble(l, x, y, z, stripes, turbulencePercent / 100.0, oct)));
      }
  TextureDesc t = described("procedural_texture_solid",
                            {{"kind", std::to_string(kind)},
                             {"octaves", std::to_string(oct)},
                             {"stripes", std::to_string(stripes)},
                             {"turbulence_percent", std::to_string(turbulencePercent)}},
                            std::move(img), GL_LINEAR);
  t.depth = n;
  std::lock_guard<std::mutex> hold(lock);
  if (made.size() >= 16) made.clear();  // a few states' worth (1 MiB each)
  made.emplace(key, t);
  return t;
}

TextureDesc noise2DTexture(int oct) {
  Image img(kNoise2DWidth, kNoise2DHeight);
  for (int j = 0; j < kNoise2DHeight; ++j)
    for (int i = 0; i < kNoise2DWidth; ++i)
      img.set(i, j,
              stoneColour(
                  octaves(lattice(), 3 * (i + 0.5) / kNoise2DWidth, 1.5 * (j + 0.5) / kNoise2DHeight, 0.5, oct)));
  TextureDesc t = described("procedural_texture_noise2d", {{"octaves", std::to_string(oct)}}, std::move(img),
                            GL_LINEAR);
  t.wrapS = GL_REPEAT;  // round the sphere: u wraps, and the last column meets the first at the seam
  return t;
}

TextureDesc marblePlaneTexture(int stripes, int turbulencePercent, int oct) {
  const int n = kMarblePixels;
  Image img(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      img.set(i, j,
              marbleColour(
                  marble(lattice(), (i + 0.5) / n, (j + 0.5) / n, 0.5, stripes, turbulencePercent / 100.0, oct)));
  return described("procedural_texture_marble",
                   {{"stripes", std::to_string(stripes)},
                    {"turbulence_percent", std::to_string(turbulencePercent)},
                    {"octaves", std::to_string(oct)}},
                   std::move(img), GL_NEAREST);
}

namespace {
int ranged(const TextureParams& params, const std::string& key, const std::string& name, int lo, int hi) {
  const int v = intParam(params, key, name);
  if (v < lo || v > hi) throw Error("sidecar: texture '" + name + "': " + key + " out of range");
  return v;
}
bool remake(const std::string& name, const TextureParams& p, TextureDesc* out) {
  if (name == "procedural_texture_solid")
    *out = solidTexture(ranged(p, "kind", name, 0, 1), ranged(p, "octaves", name, 1, kMaxOctaves),
                        ranged(p, "stripes", name, 0, 64), ranged(p, "turbulence_percent", name, 0, 1000));
  else if (name == "procedural_texture_noise2d") *out = noise2DTexture(ranged(p, "octaves", name, 1, kMaxOctaves));
  else if (name == "procedural_texture_marble")
    *out = marblePlaneTexture(ranged(p, "stripes", name, 1, 64), ranged(p, "turbulence_percent", name, 0, 1000),
                              ranged(p, "octaves", name, 1, kMaxOctaves));
  else return false;
  return true;
}
}  // namespace
}  // namespace ts::proc

// The sidecar reader finds it through the registry (common/core/texture_generators.hpp).
TS_REGISTER_TEXTURE_GENERATOR("procedural_texture_*", ts::proc::remake);
