// tests/bench/bench_gl.hpp — the offscreen GL a benchmark program draws with: one OSMesa context of the
// program's size and a Renderer on it, made on first use and kept for every benchmark of the program.
#pragma once
#include <memory>

#include "common/gl/context.hpp"
#include "common/gl/render.hpp"

namespace ts::bench {
struct GLRig {
  explicit GLRig(int width, int height, bool accumBuffer = false) {
    ts::ContextOptions o;
    o.width = width, o.height = height, o.accumBuffer = accumBuffer;
    ctx = ts::createOffscreenContext(ts::Backend::OSMesa, o);
    renderer = std::make_unique<ts::Renderer>(*ctx);
  }
  ~GLRig() { renderer->release(); }
  std::unique_ptr<ts::Context> ctx;
  std::unique_ptr<ts::Renderer> renderer;
};
}  // namespace ts::bench
