// common/gl/context.hpp — where GL commands go: an offscreen OSMesa buffer, an
// EGL surfaceless context rendering into an FBO, or a GLFW window.
#pragma once
#include <memory>
#include <string>

#include "common/core/image.hpp"

namespace ts {
enum class Backend { Auto, OSMesa, EGL, Window };
Backend parseBackend(const std::string& name);  // throws ts::Error
const char* backendName(Backend b);

struct ContextOptions {
  int width = 512, height = 512;
  bool accumBuffer = false;  // OSMesa only: EGL contexts have none
  bool verbose = false;      // print the fallback note on stderr
};

class Context {
 public:
  virtual ~Context() = default;
  virtual Backend backend() const = 0;
  // Changes the size of the offscreen target (a window resizes itself).
  virtual void resize(int width, int height) = 0;
  int width() const { return width_; }
  int height() const { return height_; }
  virtual bool hasAccumBuffer() const { return false; }
  // Binds the target that draw() should render into (the FBO for EGL).
  virtual void bindTarget() {}
  // Reads the current target into an image, top row first.
  Image readPixels() const;
  // "osmesa | 4.5 (Compatibility Profile) Mesa 22.3.6 | llvmpipe (...)"
  std::string describe() const;

 protected:
  int width_ = 0, height_ = 0;
};

// Creates an offscreen context and loads every GL pointer from it.
// Backend::Auto tries OSMesa and falls back to EGL, with a note on stderr.
// Failing everything throws ts::Error naming the Debian packages to install.
std::unique_ptr<Context> createOffscreenContext(Backend backend, const ContextOptions& opts);
}  // namespace ts
