// common/gl/context.hpp — where GL commands go: an offscreen OSMesa buffer, an
// EGL surfaceless context rendering into an FBO, a hidden GLFW window
// rendering into an FBO (the offscreen backend of Windows, where there is no
// OSMesa or EGL), or a GLFW window.
#pragma once
#include <memory>
#include <string>

#include "common/core/image.hpp"

namespace ts {
enum class Backend { Auto, OSMesa, EGL, Hidden, Window };
Backend parseBackend(const std::string& name);  // throws ts::Error
const char* backendName(Backend b);

struct ContextOptions {
  int width = 512, height = 512;
  bool accumBuffer = false;  // OSMesa only: EGL contexts have none
  bool verbose = false;      // print the fallback note on stderr
  // Whether Backend::Auto may end at a hidden GLFW window.  GLFW opens
  // windows on the main thread only, so a thread of its own (the
  // measurement worker) says false and, without OSMesa or EGL, measures in
  // the window instead.
  bool allowHidden = true;
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
  // A context made on one thread for another (createHiddenContext with
  // forAnotherThread): adopt() makes it current on the calling thread, loads
  // that thread's GL pointers and makes the target (throws ts::Error);
  // detach() frees the target and leaves the thread without a context, so
  // that the thread that made it can destroy it.  No-ops elsewhere.
  virtual void adopt() {}
  virtual void detach() {}
  // Reads the current target into an image, top row first.
  Image readPixels() const;
  // "osmesa | 4.5 (Compatibility Profile) Mesa 22.3.6 | llvmpipe (...)"
  std::string describe() const;

 protected:
  int width_ = 0, height_ = 0;
};

// Creates an offscreen context and loads every GL pointer from it.
// Backend::Auto tries OSMesa and falls back to EGL, then to a hidden window,
// with a note on stderr (on Windows it is the hidden window, without a note).
// Failing everything throws ts::Error naming the Debian packages to install.
std::unique_ptr<Context> createOffscreenContext(Backend backend, const ContextOptions& opts);
// The hidden-window backend (context_hidden.cpp): nullptr and *why when it
// cannot be made.  Call it from the main thread (GLFW makes windows there
// only).  forAnotherThread: the context is not made current and its GL is
// not loaded; the thread that uses it calls adopt() first and detach() last,
// and the main thread destroys it (the measurement worker's, on Windows).
std::unique_ptr<Context> createHiddenContext(const ContextOptions& opts, std::string* why,
                                             bool forAnotherThread = false);
// Whether this build has the OSMesa and EGL backends (not on Windows).
bool haveDlopenBackends();
// TS_HIDE_GL_LIBS (tests): whether `lib` (osmesa, egl, hidden) is to be
// treated as missing.
bool glLibraryHidden(const char* lib);
}  // namespace ts
