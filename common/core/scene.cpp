// common/core/scene.cpp — the scene registry, the measurements' printed form,
// notes on stderr, and the progress a long measure() reports.
#include "common/core/scene.hpp"

#include <algorithm>
#include <cstdio>

#include "common/core/error.hpp"
#include "common/core/measure_run.hpp"

namespace ts {
static bool g_quietNotes = false;
void setQuietNotes(bool quiet) { g_quietNotes = quiet; }
void note(const std::string& line) {
  if (g_quietNotes) return;
  std::fprintf(stderr, "%s\n", line.c_str());
  std::fflush(stderr);
}

std::vector<RegisteredScene>& sceneRegistry() {
  static std::vector<RegisteredScene> r;
  return r;
}
bool registerScene(const std::string& id, SceneFactory make) {
  sceneRegistry().push_back({id, std::move(make)});
  return true;
}
std::unique_ptr<Scene> makeScene(const std::string& id) {
  for (auto& s : sceneRegistry())
    if (s.id == id) return s.make();
  return nullptr;
}

std::string formatMeasurements(const Measurements& m) {
  std::string out;
  for (const auto& x : m) {
    char line[512];
    std::snprintf(line, sizeof line, "%-28s %12.4f   %s\n", x.name.c_str(), x.value, x.meaning.c_str());
    out += line;
  }
  return out;
}

namespace {
thread_local MeasureRun* tl_run = nullptr;
std::atomic<MeasureRun*> g_run{nullptr};
}  // namespace

void setMeasureRun(MeasureRun* run) {
  tl_run = run;
  g_run.store(run);
}

void measureProgress(double fraction) {
  MeasureRun* r = tl_run;
  if (!r) return;
  r->progress->store(std::clamp(fraction, 0.0, 1.0));
  if (r->cancelled()) throw MeasureCancelled();
}

bool measureStaged() { return tl_run && tl_run->stage; }

void measureStage(Measurements partial) {
  MeasureRun* r = tl_run;
  if (!r || !r->stage) return;
  if (r->cancelled()) throw MeasureCancelled();
  partial.refining = true;
  r->stage(std::move(partial));
}

bool measureCancelled(double fraction) {
  if (tl_run && fraction >= 0) tl_run->progress->store(std::clamp(fraction, 0.0, 1.0));
  MeasureRun* r = g_run.load();
  return r && r->cancelled();
}
}  // namespace ts
