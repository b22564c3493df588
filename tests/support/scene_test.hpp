// tests/support/scene_test.hpp — a registered demo in a state, on the test
// context (tests/support/gl_test.hpp): what every figure test needs to say
// "this demo, these flags, measure it, draw it at this size" in one line.
#pragma once
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/core/measure_run.hpp"
#include "common/core/scene.hpp"
#include "tests/support/gl_test.hpp"

namespace ts::test {
// The demo `id` with its flags parsed, as make_figures and --png do.
struct Demo {
  std::unique_ptr<Scene> scene;
  Options opts;
  Measurements measured;  // the last measure(); empty before it
  Demo(const std::string& id, const std::vector<std::string>& flags) : scene(makeScene(id)) {
    if (!scene) throw std::runtime_error(id + " is not registered (is its scene linked into this test?)");
    scene->addOptions(opts);
    opts.parse(flags);
  }
  // The same on a test program's own renderer (and so on its context)
  // instead of the shared renderer(): for a program whose context needs what
  // gl_test.hpp's lacks, e.g. an accumulation buffer.  `r` must outlive this.
  Demo(const std::string& id, const std::vector<std::string>& flags, Renderer& r) : Demo(id, flags) { own_ = &r; }
  // Measures, and keeps the result for frame() to draw, as the window does.
  Measurements measure() { return measured = scene->measure(drawWith()); }
  // The frame at w x h; the test context is resized to it first, as a
  // --png render of that size would be.
  Frame frame(int w, int h) {
    Context& ctx = own_ ? own_->context() : context();
    if (ctx.width() != w || ctx.height() != h) ctx.resize(w, h);
    return scene->build(w, h, measured);
  }
  // frame() drawn and read back (labels off unless asked: the font is not
  // what the tests are about).
  Image render(int w, int h, Frame* frameOut = nullptr, bool labels = false) {
    Frame f = frame(w, h);
    Image img = drawWith().render(f, labels);
    if (frameOut) *frameOut = std::move(f);
    return img;
  }

 private:
  Renderer* own_ = nullptr;  // null: the shared renderer()
  Renderer& drawWith() { return own_ ? *own_ : renderer(); }
};

// The panel `id` of a frame; throws (a test error naming it) when absent.
inline const Panel& panelOf(const Frame& f, const std::string& id) {
  const Panel* p = f.panel(id);
  if (!p) throw std::runtime_error("frame has no panel " + id);
  return *p;
}

// The stages a window's worker is handed (ts::measureStage) while `d`
// measures as in a window.  stopAfter > 0: the request is superseded once
// that many stages are in, so the measurement stops at its next check (a
// test failure if it does not); 0: it runs to the end, its result in
// d.measured.
inline std::vector<Measurements> measureInStages(Demo& d, size_t stopAfter = 0) {
  std::atomic<uint64_t> latest{1};
  std::atomic<bool> quit{false};
  std::atomic<double> progress{0};
  std::vector<Measurements> stages;
  MeasureRun run{&latest, &quit, 1, &progress, [&](Measurements&& m) {
                   stages.push_back(std::move(m));
                   if (stopAfter && stages.size() >= stopAfter) latest.store(2);  // the rest is not needed
                 }};
  setMeasureRun(&run);
  bool cancelled = false;
  try {
    d.measure();
  } catch (const MeasureCancelled&) {
    cancelled = true;
  }
  setMeasureRun(nullptr);
  EXPECT_EQ(cancelled, stopAfter > 0) << "superseded after " << stopAfter << " stages: " << stages.size() << " came";
  return stages;
}

// The value of the measurement `name`; a test failure (and NaN) when absent.
inline double value(const Measurements& m, const std::string& name) {
  for (const auto& x : m)
    if (x.name == name) return x.value;
  ADD_FAILURE() << "no measurement named " << name << " in\n" << formatMeasurements(m);
  return std::nan("");
}
}  // namespace ts::test
