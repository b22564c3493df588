// tests/support/gl_test.hpp — what a GL test declares, in a few lines
// (piglit's way): one offscreen context per test program, its backend chosen
// by the environment so the same tests run on every context type:
//   TS_TEST_BACKEND=osmesa (default) | egl      GALLIUM_DRIVER=llvmpipe | softpipe
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "common/gl/context.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"

namespace ts::test {
// The process-wide context and renderer (created on first use, 512x512).
inline Context& context() {
  static std::unique_ptr<Context> ctx = [] {
    const char* b = std::getenv("TS_TEST_BACKEND");
    ContextOptions o;
    o.width = o.height = 512;
    return createOffscreenContext(parseBackend(b && *b ? b : "osmesa"), o);
  }();
  return *ctx;
}
inline Renderer& renderer() {
  static Renderer r(context());
  return r;
}
inline std::string rendererString() {
  context();
  return gl::rendererString();
}
inline bool isSoftpipe() { return rendererString().find("softpipe") != std::string::npos; }

// Skips the current test, visibly, when the context lacks a GL version.
#define TS_REQUIRE_GL_VERSION(v)                                                                            \
  do {                                                                                                      \
    if (::ts::gl::version() < (v))                                                                          \
      GTEST_SKIP() << "needs GL " << (v) / 10 << "." << (v) % 10 << ", have " << ::ts::gl::versionString(); \
  } while (0)
}  // namespace ts::test
