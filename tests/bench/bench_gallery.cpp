// bench_gallery — the whole book gallery as scripts/figures.sh makes it:
// build/bin/make_figures (beside this program) into a new temporary folder,
// its wall time and its peak memory, with the demos in children two at a
// time (the default) and all in one process (--jobs 1):
//
//   gallery/jobs:2   make_figures --out TMP
//   gallery/jobs:1   make_figures --jobs 1 --out TMP
//
// Counters: peak_sum_MB, the largest sum of the resident memory of every
// make_figures process of the run at one time (sampled every 50 ms from
// /proc: Linux; 0 elsewhere), cpu_s, the CPU seconds (user and system) of
// make_figures and its children (getrusage: what a busy machine does not
// inflate, and what a host of another speed scales), and figures, the PNGs
// it wrote.  One run each
// (a gallery takes a minute): wall clock, the load average printed after
// the table; compare the two as a ratio within one run.  Speed is measured,
// never asserted.
//   bench_gallery --benchmark_filter=jobs:2
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_common.hpp"
#include "common/core/child_process.hpp"

namespace {
namespace fs = std::filesystem;

// The summed VmRSS (kB) of the processes whose command line holds `marker`
// (the run's own output folder: the parent's and every child's).
long residentKb(const std::string& marker) {
  long sum = 0;
#ifdef __linux__
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/proc", ec)) {
    const std::string pid = entry.path().filename().string();
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    try {  // a process may end while it is read ("No such process")
      std::ifstream cmd(entry.path() / "cmdline", std::ios::binary);
      std::string line((std::istreambuf_iterator<char>(cmd)), std::istreambuf_iterator<char>());
      if (line.find(marker) == std::string::npos || line.find("make_figures") == std::string::npos) continue;
      std::ifstream status(entry.path() / "status");
      for (std::string l; std::getline(status, l);)
        if (l.rfind("VmRSS:", 0) == 0) sum += std::atol(l.c_str() + 6);
    } catch (const std::exception&) {
    }
  }
#else
  (void)marker;
#endif
  return sum;
}

// The CPU seconds of this process's waited-for children so far (their own
// waited-for children included).
double childrenCpuSeconds() {
  rusage u{};
  if (getrusage(RUSAGE_CHILDREN, &u) != 0) return 0;
  auto s = [](const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) * 1e-6; };
  return s(u.ru_utime) + s(u.ru_stime);
}

void gallery(benchmark::State& st, int jobs) {
  const std::string program = ts::programPath("make_figures");
  for (auto _ : st) {
    const std::string out = ts::makeTempFolder("bench_gallery-");
    if (out.empty()) {
      st.SkipWithError("cannot make a temporary folder");
      return;
    }
    std::atomic<bool> running{true};
    std::atomic<long> peak{0};
    std::thread sampler([&] {
      while (running) {
        peak = std::max(peak.load(), residentKb(out));
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
    });
    const double cpu0 = childrenCpuSeconds();
    const auto t0 = std::chrono::steady_clock::now();
    ts::ProcessResult r = ts::runProcess({program, "--jobs", std::to_string(jobs), "--out", out}, "", 3600.0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    running = false;
    sampler.join();
    long pngs = 0;
    std::error_code ec;
    for (const auto& f : fs::directory_iterator(out, ec)) pngs += f.path().extension() == ".png";
    fs::remove_all(out, ec);
    if (!r.started || r.timedOut || r.exitCode != 0) {
      st.SkipWithError(("make_figures failed: " + r.out.substr(r.out.size() > 400 ? r.out.size() - 400 : 0)).c_str());
      return;
    }
    st.SetIterationTime(seconds);
    st.counters["peak_sum_MB"] = double(peak.load()) / 1024.0;
    st.counters["cpu_s"] = childrenCpuSeconds() - cpu0;
    st.counters["figures"] = double(pngs);
  }
}
}  // namespace

int main(int argc, char** argv) {
  for (int jobs : {2, 1})
    benchmark::RegisterBenchmark(("gallery/jobs:" + std::to_string(jobs)).c_str(), gallery, jobs)
        ->Iterations(1)
        ->Repetitions(1)
        ->UseManualTime()
        ->Unit(benchmark::kSecond);
  return ts::bench::run(argc, argv);
}
