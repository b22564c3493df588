// common/core/texture_generators.cpp — the generator registry and the core's
// own generators (the textures several demos share).
#include "common/core/texture_generators.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "common/core/env_maps.hpp"
#include "common/core/error.hpp"
#include "common/core/textures.hpp"

namespace ts {
namespace {
[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw Error("sidecar: texture '" + name + "': " + what);
}

bool coreTexture(const std::string& name, const TextureParams& p, TextureDesc* out) {
  if (name == "checkerboard")
    *out = checkerboard(intParam(p, "size", name), intParam(p, "checks", name), rgbaParam(p, "color_a", name),
                        rgbaParam(p, "color_b", name));
  else if (name == "line_grid")
    *out = lineGrid(intParam(p, "size", name), intParam(p, "cells", name), rgbaParam(p, "color_line", name),
                    rgbaParam(p, "color_background", name));
  else if (name == "texel_index") *out = texelIndexTexture(intParam(p, "size", name));
  else if (name == "labelled_grid") *out = labelledGrid(intParam(p, "size", name), intParam(p, "cells", name));
  else if (name == "mip_level_colours") *out = mipLevelColours(intParam(p, "size", name));
  else if (name == "gradient")
    *out = gradientTexture(intParam(p, "width", name), intParam(p, "height", name),
                           strParam(p, "alpha", name) == "ramp");
  else if (name == "environment_map") *out = envmaps::environmentMapFromParams(p);  // common/core/env_maps.hpp
  else return false;
  return true;
}

// The core's generators, in the order the reader has always tried them.
const std::vector<TextureGenerator>& coreGenerators() {
  static const std::vector<TextureGenerator> core = {
      {"checkerboard, line_grid, texel_index, labelled_grid, mip_level_colours, gradient, environment_map",
       coreTexture},
  };
  return core;
}

// Filled before main() by TS_REGISTER_TEXTURE_GENERATOR; a function's static,
// so it exists whichever file registers first.
std::vector<TextureGenerator>& registered() {
  static std::vector<TextureGenerator> r;
  return r;
}
}  // namespace

bool registerTextureGenerator(const std::string& label, TextureRemake remake) {
  auto& r = registered();
  r.push_back({label, remake});
  std::sort(r.begin(), r.end(), [](const TextureGenerator& a, const TextureGenerator& b) { return a.label < b.label; });
  return true;
}

std::vector<TextureGenerator> textureGenerators() {
  std::vector<TextureGenerator> all = coreGenerators();
  all.insert(all.end(), registered().begin(), registered().end());
  return all;
}

bool remakeRegisteredTexture(const std::string& name, const TextureParams& params, TextureDesc* out) {
  for (const auto& g : textureGenerators())
    if (g.remake(name, params, out)) return true;
  return false;
}

std::string textureGeneratorLabels() {
  std::string s;
  for (const auto& g : textureGenerators()) s += (s.empty() ? "" : ", ") + g.label;
  return s;
}

int intParam(const TextureParams& p, const std::string& key, const std::string& name) {
  for (const auto& [k, v] : p)
    if (k == key) {
      char* end = nullptr;
      long x = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end) fail(name, "param " + key + " = '" + v + "' is not an integer");
      return int(x);
    }
  fail(name, "missing param '" + key + "'");
}

std::string strParam(const TextureParams& p, const std::string& key, const std::string& name) {
  for (const auto& [k, v] : p)
    if (k == key) return v;
  fail(name, "missing param '" + key + "'");
}

Rgba rgbaParam(const TextureParams& p, const std::string& key, const std::string& name) {
  std::string v = strParam(p, key, name);
  int c[4];
  char tail = 0;
  if (std::sscanf(v.c_str(), "%d,%d,%d,%d%c", &c[0], &c[1], &c[2], &c[3], &tail) != 4)
    fail(name, "param " + key + " = '" + v + "' is not r,g,b,a");
  for (int x : c)
    if (x < 0 || x > 255) fail(name, "param " + key + " = '" + v + "' is out of 0..255");
  return {uint8_t(c[0]), uint8_t(c[1]), uint8_t(c[2]), uint8_t(c[3])};
}
}  // namespace ts
