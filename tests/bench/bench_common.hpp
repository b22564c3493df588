// tests/bench/bench_common.hpp — what the two benchmark programs share: the
// registered figures, a scene set to a figure's state, default flags, and a
// console reporter that also prints the medians as markdown tables.
//
// Speed is measured here, never asserted: these programs are not CTest tests.
#pragma once
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/core/options.hpp"
#include "common/core/scene.hpp"

namespace ts::bench {
// One registered book figure and the demo (scene) it belongs to.
struct Figure {
  std::string demo;
  FigureSpec spec;
};

inline std::vector<Figure> registeredFigures() {
  std::vector<Figure> out;
  for (const auto& reg : sceneRegistry())
    for (const auto& spec : reg.make()->figures()) out.push_back({reg.id, spec});
  return out;
}

// A scene in a figure's state (its flags parsed, as make_figures does).
// Not movable: the options point into the scene.
struct SceneState {
  explicit SceneState(const Figure& f) : scene(makeScene(f.demo)) {
    scene->addOptions(opts);
    opts.parse(ts::sceneFlags(f.spec.flags));  // a footprint figure: the picture it inspects
  }
  SceneState(const SceneState&) = delete;
  SceneState& operator=(const SceneState&) = delete;
  std::unique_ptr<Scene> scene;
  Options opts;
};

// argv with `defaults` inserted before the user's flags, so that a flag given
// on the command line wins (benchmark parses left to right).
class Args {
 public:
  Args(int argc, char** argv, std::initializer_list<const char*> defaults) {
    strings_.push_back(argv[0]);
    for (const char* d : defaults) strings_.push_back(d);
    for (int i = 1; i < argc; ++i) strings_.push_back(argv[i]);
    for (auto& s : strings_) pointers_.push_back(s.data());
    pointers_.push_back(nullptr);
    argc_ = int(strings_.size());
  }
  int* argc() { return &argc_; }
  char** argv() { return pointers_.data(); }

 private:
  std::vector<std::string> strings_;
  std::vector<char*> pointers_;
  int argc_ = 0;
};

// The default flags of both programs: five repetitions of at least 0.2 s
// each (one iteration when it takes longer), aggregates only.
#define TS_BENCH_DEFAULT_FLAGS \
  "--benchmark_repetitions=5", "--benchmark_report_aggregates_only=true", "--benchmark_min_time=0.2"

// An extra aggregate beside mean/median/stddev/cv: on a shared machine the
// fastest repetition is the one least disturbed by other processes.
inline double minimum(const std::vector<double>& v) {
  double m = std::numeric_limits<double>::infinity();
  for (double x : v) m = std::min(m, x);
  return v.empty() ? 0.0 : m;
}

// Run::error_occurred (benchmark <= 1.7) became Run::skipped (1.8+).
template <class R>
auto runFailed(const R& r, int) -> decltype(static_cast<bool>(r.skipped)) {
  return static_cast<bool>(r.skipped);
}
template <class R>
auto runFailed(const R& r, long) -> decltype(static_cast<bool>(r.error_occurred)) {
  return static_cast<bool>(r.error_occurred);
}

// The console output as usual, plus every benchmark's median (or its single
// run, with --benchmark_repetitions=1) kept for the summary tables.
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  SummaryReporter() : ConsoleReporter(isatty(1) ? OO_ColorTabular : OO_Tabular) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      const std::string& name = r.run_name.function_name;
      if (runFailed(r, 0)) {
        errors_[name] = r.error_message;
        continue;
      }
      if (r.run_type == Run::RT_Aggregate) {
        if (r.aggregate_name == "median") median_[name] = r;
      } else {
        single_[name] = r;
      }
    }
  }

  // Median real time of a benchmark in milliseconds; NaN if it did not run.
  double ms(const std::string& name) const {
    const Run* r = find(name);
    if (!r) return std::numeric_limits<double>::quiet_NaN();
    return r->GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r->time_unit) * 1e3;
  }
  // Median of a user counter; NaN if absent.
  double counter(const std::string& name, const std::string& key) const {
    const Run* r = find(name);
    if (!r) return std::numeric_limits<double>::quiet_NaN();
    auto it = r->counters.find(key);
    return it == r->counters.end() ? std::numeric_limits<double>::quiet_NaN() : double(it->second.value);
  }
  const std::map<std::string, std::string>& errors() const { return errors_; }
  // Whether any benchmark whose name starts with `prefix` reported (e.g. a
  // figure left out by --benchmark_filter did not).
  bool ran(const std::string& prefix) const {
    for (const auto* m : {&median_, &single_}) {
      auto it = m->lower_bound(prefix);
      if (it != m->end() && it->first.compare(0, prefix.size(), prefix) == 0) return true;
    }
    return false;
  }
  bool empty() const { return median_.empty() && single_.empty() && errors_.empty(); }
  // "median of 5" or "1 run".
  std::string statistic() const {
    if (median_.empty()) return "1 run";
    return "median of " + std::to_string(median_.begin()->second.repetitions) + " repetitions";
  }

 private:
  const Run* find(const std::string& name) const {
    auto m = median_.find(name);
    if (m != median_.end()) return &m->second;
    auto s = single_.find(name);
    return s != single_.end() ? &s->second : nullptr;
  }
  std::map<std::string, Run> median_, single_;
  std::map<std::string, std::string> errors_;
};

// Three significant digits or so; "–" for a missing value.
inline std::string fmt(double v) {
  if (!std::isfinite(v)) return "–";
  char b[32];
  double a = std::fabs(v);
  std::snprintf(b, sizeof b, a >= 100 ? "%.0f" : a >= 10 ? "%.1f" : a >= 1 ? "%.2f" : "%.3f", v);
  return b;
}
inline std::string ratio(double num, double den) {
  if (!std::isfinite(num) || !std::isfinite(den) || den <= 0) return "–";
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", num / den);
  return b;
}

// "0.52 0.61 0.40" (1, 5 and 15 minutes) or "?".
inline std::string loadAverage() {
  double a[3] = {0, 0, 0};
  std::FILE* f = std::fopen("/proc/loadavg", "r");
  bool ok = f && std::fscanf(f, "%lf %lf %lf", &a[0], &a[1], &a[2]) == 3;
  if (f) std::fclose(f);
  if (!ok) return "?";
  char b[64];
  std::snprintf(b, sizeof b, "%.2f %.2f %.2f", a[0], a[1], a[2]);
  return b;
}

// This host's speed, to set a run's times against another host's: the
// milliseconds a fixed single-threaded workload takes, the fastest of five
// (the least disturbed).  The workload is the gallery's commonest kind:
// bilinear lookups of a byte map at hashed double-precision coordinates, as
// the parallax reference traces.  A slip in a timing shows as a larger
// ratio to this, whatever the host.
inline double yardstickMs() {
  constexpr int kSize = 512;
  std::vector<unsigned char> map(size_t(kSize) * kSize);
  for (size_t p = 0; p < map.size(); ++p) map[p] = static_cast<unsigned char>((p * 2654435761u) >> 13);
  double best = std::numeric_limits<double>::infinity(), sink = 0;
  for (int run = 0; run < 5; ++run) {
    const auto t0 = std::chrono::steady_clock::now();
    uint32_t h = 12345u;
    double sum = 0;
    for (int k = 0; k < 4000000; ++k) {
      h = h * 1664525u + 1013904223u;
      const double x = double(h >> 8) * (kSize / 16777216.0), y = double((h * 2246822519u) >> 8) * (kSize / 16777216.0);
      const int i = int(x), j = int(y);
      const double ax = x - i, ay = y - j;
      auto at = [&](int a, int b) { return double(map[size_t(b & (kSize - 1)) * kSize + size_t(a & (kSize - 1))]); };
      sum += (at(i, j) * (1 - ax) + at(i + 1, j) * ax) * (1 - ay) +
             (at(i, j + 1) * (1 - ax) + at(i + 1, j + 1) * ax) * ay;
    }
    best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    sink += sum;
  }
  benchmark::DoNotOptimize(sink);
  return best;
}

inline void printErrors(const SummaryReporter& rep) {
  for (const auto& [name, why] : rep.errors()) std::printf("- `%s` skipped: %s\n", name.c_str(), why.c_str());
}

// Runs the registered benchmarks with the summary reporter; returns main()'s status.
inline int run(int argc, char** argv, const std::function<void(const SummaryReporter&)>& summary) {
  Args args(argc, argv, {TS_BENCH_DEFAULT_FLAGS});
  benchmark::Initialize(args.argc(), args.argv());
  if (benchmark::ReportUnrecognizedArguments(*args.argc(), args.argv())) return 2;
  SummaryReporter rep;
  std::string loadBefore = loadAverage();
  const double yardstick = yardstickMs();
  size_t n = benchmark::RunSpecifiedBenchmarks(&rep);
  std::string loadAfter = loadAverage();
  benchmark::Shutdown();
  if (n == 0 || rep.empty()) return 0;  // nothing matched, or --benchmark_list_tests
  std::fflush(stdout);
  summary(rep);
  std::printf(
      "Machine: %ld cores, load average (1, 5, 15 min) %s before the run, %s after. Other processes on these cores "
      "inflate wall-clock times: if the load was high, compare the `min` aggregates or re-run on a quiet machine. "
      "Yardstick %.0f ms (a fixed CPU workload, fastest of 5, before the run): another host's times scale by its "
      "yardstick's ratio to this one.\n",
      sysconf(_SC_NPROCESSORS_ONLN), loadBefore.c_str(), loadAfter.c_str(), yardstick);
  printErrors(rep);
  return rep.errors().empty() ? 0 : 1;
}
// The same for a benchmark whose console table is its summary: the load
// average before and after still printed, and unknown flags refused.
inline int run(int argc, char** argv) {
  return run(argc, argv, [](const SummaryReporter&) {});
}
}  // namespace ts::bench
