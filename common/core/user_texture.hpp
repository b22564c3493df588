// common/core/user_texture.hpp — `--texture FILE`: the student's own picture on a
// demo's surface.  PNG, JPEG or 24/32-bit BMP, recognised by content
// (image.hpp); a file dropped on the window is set through the same option,
// so it loads exactly as the flag would.  The file's top row is t = 1, like
// every texture of the suite (textures/ is written that way).
//
// Only the picture the student sees changes: a demo's measurement textures
// (texel-index maps, mip-level colours) stay its own, so the numbers it
// prints keep their meaning with any picture.
#pragma once
#include <string>

#include "common/core/frame.hpp"
#include "common/core/options.hpp"

namespace ts {
class UserTexture {
 public:
  // Registers --texture FILE; `instead` ends the help line ("the checkerboard").
  void addOption(Options& o, const std::string& instead);
  bool active() const { return !path_.empty(); }
  // The file's picture with `fallback`'s sampling state (filters, wrap,
  // mipmaps, anisotropy, LOD bias), or `fallback` itself without a file.
  // Explicit mip levels are dropped: the file's chain is the book's 2x2
  // average of its own level 0 (render.cpp builds it when mipmaps is on).
  TextureDesc orDefault(const TextureDesc& fallback) const;
  const std::string& path() const { return path_; }
  // The file's picture, row 0 = t = 0 (empty without a file).
  const Image& image() const;

 private:
  std::string path_;
  TextureDesc file_;
};

// The help line of every --texture option, for tests and the README.
constexpr const char* kTextureFormats = "PNG, JPEG or 24/32-bit BMP";
}  // namespace ts
