// common/app/measure_worker.hpp — the window's measurements, off the drawing loop.
//
// A measurement (Scene::measure) can take seconds: the parallax demo traces
// a reference on the CPU and renders six modes, the mipmap demo sweeps every
// filter.  Run in the window's loop it froze the window for that long after
// every key.  A MeasureWorker runs it on a thread of its own, with its own
// offscreen context (OSMesa or EGL, as --png: the same numbers), its own
// Renderer and its own instance of the scene, set to the state the window's
// scene had when the key was pressed (Options::stateFlags).  The window keeps
// drawing from its own options and the last result handed over
// (Measurements are plain data: images, not GL names), says "measuring" with
// the progress the scene reports (ts::measureProgress) and marks the shown
// numbers stale until the new ones arrive.  A newer request supersedes the
// running one (it stops at its next ts::measureProgress); closing the window
// cancels it the same way.
//
// Live views (Scene::live) draw their picture in measure() every frame, with
// the window's GL: the window keeps calling those itself.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "common/gl/context.hpp"
#include "common/core/scene.hpp"

namespace ts {
class MeasureWorker {
 public:
  // Starts the thread; it makes its context and its scene `sceneId`.
  // `wake` (may be null) is called from the worker when a result is ready,
  // e.g. glfwPostEmptyEvent, so that an idle window wakes for it.
  MeasureWorker(std::string sceneId, bool accumBuffer, void (*wake)());
  ~MeasureWorker();  // cancels what runs and joins (see stop())
  MeasureWorker(const MeasureWorker&) = delete;
  MeasureWorker& operator=(const MeasureWorker&) = delete;

  // Measures the state `flags` (Options::stateFlags) at a target of w x h
  // (the window's framebuffer).  Supersedes any request not yet finished.
  // Returns the request's number (1, 2, ...).
  uint64_t request(std::vector<std::string> flags, int width, int height);
  struct Result {
    uint64_t id = 0;        // the request's number
    std::string stateText;  // Options::stateText() of the measured state
    Measurements measured;
    std::string error;   // a measurement failed: its message (measured is empty)
    int errorCode = 0;   // and its ts::Error exit status
    bool stage = false;  // a first stage (ts::measureStage): the request still runs
  };
  // The newest finished result (or stage of the running request) not taken
  // yet; false if none.
  bool take(Result* out);
  // Still working on request `id` or a newer one (not yet taken or failed).
  bool busy() const;
  double progress() const { return progress_.load(); }  // 0..1 of the running request
  // The thread could not make its context or scene: measure in the window
  // instead (the reason is in failure()).
  bool failed() const { return failed_.load(); }
  std::string failure() const;
  // Cancels the running request (none is pending after it).
  void cancel();
  // Cancels the running request and asks the thread to end; does not wait.
  void stop();

 private:
  void run();
  // Where there is no OSMesa or EGL (Windows), the worker's context is a
  // hidden window made here, on the main thread (GLFW makes windows there
  // only), used on the worker's thread and destroyed here again.
  std::unique_ptr<Context> hidden_;
  std::string hiddenWhy_;
  const std::string sceneId_;
  const bool accum_;
  void (*wake_)();
  mutable std::mutex mu_;
  std::condition_variable cv_;
  bool quit_ = false;
  uint64_t requested_ = 0, finished_ = 0;  // request numbers
  std::vector<std::string> flags_;
  int width_ = 1, height_ = 1;
  bool haveResult_ = false;
  Result result_;
  std::string failure_;
  std::atomic<bool> failed_{false};
  // What a running measurement reads without the lock (ts::measureProgress).
  std::atomic<uint64_t> latest_{0};  // = requested_
  std::atomic<bool> quitFlag_{false};
  std::atomic<double> progress_{0.0};
  std::thread thread_;
};
}  // namespace ts
