#include "common/app/measure_worker.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <exception>

#include "common/core/child_process.hpp"
#include "common/core/error.hpp"
#include "common/gl/gl.hpp"
#include "common/core/options.hpp"
#include "common/gl/render.hpp"
#include "common/core/test_hooks.hpp"
#include "common/core/measure_run.hpp"

namespace ts {
MeasureWorker::MeasureWorker(std::string sceneId, bool accumBuffer, void (*wake)())
    : sceneId_(std::move(sceneId)), accum_(accumBuffer), wake_(wake) {
  // No OSMesa or EGL in this build (Windows), or both hidden (the tests'
  // TS_HIDE_GL_LIBS=osmesa,egl): a hidden window, made on this (the main)
  // thread for the worker's.
  if (!haveDlopenBackends() || (glLibraryHidden("osmesa") && glLibraryHidden("egl"))) {
    ContextOptions co;
    co.accumBuffer = accumBuffer;
    hidden_ = createHiddenContext(co, &hiddenWhy_, true);
  }
  thread_ = std::thread([this] { run(); });
}

MeasureWorker::~MeasureWorker() {
  stop();
  if (thread_.joinable()) thread_.join();
  hidden_.reset();  // here, on the thread that made its window
}

void MeasureWorker::stop() {
  std::lock_guard<std::mutex> lock(mu_);
  quit_ = true;
  quitFlag_.store(true);
  cv_.notify_all();
}

uint64_t MeasureWorker::request(std::vector<std::string> flags, int width, int height) {
  std::lock_guard<std::mutex> lock(mu_);
  flags_ = std::move(flags);
  width_ = std::max(1, width);
  height_ = std::max(1, height);
  ++requested_;
  latest_.store(requested_);  // the running measurement stops at its next measureProgress
  progress_.store(0.0);
  cv_.notify_all();
  return requested_;
}

void MeasureWorker::cancel() {
  std::lock_guard<std::mutex> lock(mu_);
  finished_ = ++requested_;
  latest_.store(requested_);
  haveResult_ = false;
}

bool MeasureWorker::take(Result* out) {
  std::lock_guard<std::mutex> lock(mu_);
  if (!haveResult_) return false;
  *out = std::move(result_);
  haveResult_ = false;
  return true;
}

bool MeasureWorker::busy() const {
  std::lock_guard<std::mutex> lock(mu_);
  return !failed_.load() && (finished_ < requested_ || haveResult_);
}

std::string MeasureWorker::failure() const {
  std::lock_guard<std::mutex> lock(mu_);
  return failure_;
}

void MeasureWorker::run() {
  // Below the window's thread, so the drawing loop wins the cores; nice 5,
  // not more, so that on a machine busy with other work the measurement
  // still gets about a third of a core's share.  (Linux: the nice value is
  // per thread and inherited by the threads this one starts, llvmpipe's
  // rasterizer threads among them.)
  lowerThreadPriority();
  std::unique_ptr<Context> ctx;
  Context* context = nullptr;  // ctx, or the hidden window's context (hidden_)
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<Scene> scene;
  Options opts;
  try {
    ContextOptions co;
    co.width = width_;
    co.height = height_;
    co.accumBuffer = accum_;
    co.allowHidden = false;  // GLFW makes windows on the main thread only
    if (hidden_) {
      hidden_->adopt();
      context = hidden_.get();
    } else {
      if (!hiddenWhy_.empty()) throw Error(hiddenWhy_);
      ctx = createOffscreenContext(Backend::Auto, co);
      context = ctx.get();
    }
    renderer = std::make_unique<Renderer>(*context);
    scene = makeScene(sceneId_);
    if (!scene) throw Error("no scene '" + sceneId_ + "'");
    scene->addOptions(opts);
    opts.captureDefaults();
  } catch (const std::exception& e) {
    renderer.reset();
    if (hidden_) hidden_->detach();
    std::lock_guard<std::mutex> lock(mu_);
    failure_ = e.what();
    failed_.store(true);
    if (wake_ && !quit_) wake_();  // under the lock: never after stop() (the window may be gone)
    return;
  }
  // TS_TEST_SLOW_MEASURE_MS / _FRAMES (common/core/test_hooks.hpp): a slowed
  // measurement, so a test can press keys and close the window while one
  // runs, on a machine of any speed and load.
  const long slow = test_hooks::slowMeasureMs(), slowFrames = test_hooks::slowMeasureFrames();
  for (;;) {
    std::vector<std::string> flags;
    int w = 1, h = 1;
    uint64_t id = 0;
    {
      std::unique_lock<std::mutex> lock(mu_);
      cv_.wait(lock, [&] { return quit_ || requested_ > finished_; });
      if (quit_) break;
      id = requested_;
      flags = flags_;
      w = width_;
      h = height_;
    }
    MeasureRun running{&latest_, &quitFlag_, id, &progress_, {}};
    setMeasureRun(&running);  // measureProgress reports here (common/core/scene.cpp)
    Result r;
    r.id = id;
    // A stage of this request (ts::measureStage) goes to the window at once,
    // unless a newer request came meanwhile.
    running.stage = [this, id, &r](Measurements&& partial) {
      std::lock_guard<std::mutex> lock(mu_);
      if (id != requested_ || quit_) return;
      result_ = Result();
      result_.id = id;
      result_.stage = true;
      result_.stateText = r.stateText;
      result_.measured = std::move(partial);
      haveResult_ = true;
      if (wake_) wake_();  // under the lock: never after stop()
    };
    bool cancelled = false;
    try {
      const long frame0 = test_hooks::framesDrawn();
      for (long t = 0; t < slow || test_hooks::framesDrawn() - frame0 < slowFrames; t += 10) {
        measureProgress(std::min(0.99, double(t + 10) / double(std::max(slow, 10L))));
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      measureProgress(0.0);
      opts.resetToDefaults();
      opts.parse(flags);
      r.stateText = opts.stateText();
      if (context->width() != w || context->height() != h) context->resize(w, h);
      context->bindTarget();
      r.measured = scene->measure(*renderer);
      gl::check("a measurement");
    } catch (const MeasureCancelled&) {
      cancelled = true;
    } catch (const Error& e) {
      r.error = e.what();
      r.errorCode = e.exit_code;
      r.measured = Measurements();
    } catch (const std::exception& e) {
      r.error = e.what();
      r.errorCode = kExitFailure;
      r.measured = Measurements();
    }
    setMeasureRun(nullptr);
    {
      std::lock_guard<std::mutex> lock(mu_);
      finished_ = std::max(finished_, id);
      if (!cancelled && id == requested_) {  // a superseded result is not shown
        result_ = std::move(r);
        haveResult_ = true;
        if (wake_ && !quit_) wake_();  // under the lock: never after stop() (the window may be gone)
      }
    }
  }
  // The scene's GL objects go while its context is current, then the context.
  scene.reset();
  renderer.reset();
  ctx.reset();
  if (hidden_) hidden_->detach();  // the main thread destroys it (~MeasureWorker)
}
}  // namespace ts
