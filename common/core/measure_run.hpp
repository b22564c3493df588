// common/core/measure_run.hpp — the measurement a thread runs, which
// ts::measureProgress and ts::measureCancelled (scene.hpp) report to.  The
// window's measurement worker (common/app/measure_worker.cpp) sets it while
// it measures; elsewhere (--png, figures) none is set and both do nothing.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>

#include "common/core/scene.hpp"

namespace ts {
struct MeasureRun {
  const std::atomic<uint64_t>* latest;  // the newest request number
  const std::atomic<bool>* quit;
  uint64_t id;
  std::atomic<double>* progress;
  // Where measureStage hands a stage (empty: stages are not shown).
  std::function<void(Measurements&&)> stage;
  bool cancelled() const { return quit->load() || latest->load() != id; }
};
// This thread's run, and the process's (threads a measurement starts itself,
// such as the parallax reference's rows, ask the latter): nullptr = none.
void setMeasureRun(MeasureRun* run);
}  // namespace ts
