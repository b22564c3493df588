// tests/exercises/exercise_check.cpp — checks the exercises of exercises/
// with the suite's own measurements, and prints a short report per check:
// what was measured, what was expected, pass or fail.
//
//   exercise_check NAME... | --all   the student's code (exercises/*.cpp)
//     --solutions                    the suite's reference solutions instead
//     --wrong                        a deliberately wrong solution per exercise
//     --impl crash|hang|nan          a student's code that crashes, loops or
//                                    returns NaN (the tests of the isolation)
//     --out DIR                      the pictures (default build/exercises)
//     --time-limit S                 per exercise (default 10 s)
// Each exercise runs in a child process of its own, with its own offscreen
// GL context: a crash, an endless loop or a NaN is that exercise's failure,
// reported in one line, and the next one runs.  Exit status: 0 when every
// check passes, 1 when one fails, 2 on bad usage.
//
// The reference solutions are the demos' (cylinder_math.hpp's back seam,
// torus_math.hpp's front mapping, wrap_math.hpp's GL formulas), never in
// exercises/.
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/image.hpp"
#include "common/gl/context.hpp"
#include "common/gl/render.hpp"
#include "exercise_checks.hpp"
#include "exercises/exercise.hpp"

namespace {
using exercise_check::Impl;

// The four implementations of `impl` for one exercise's function.
exercise_check::Functions functions(Impl impl) {
  exercise_check::Functions f = exercise_check::reference(impl);
  if (impl != Impl::Mine) return f;
  f.cylinderS = exercise::cylinderS;
  f.torusST = exercise::torusST;
  f.blit = exercise::blit;
  f.mirrorTexel = exercise::mirrorTexel;
  f.scanline = exercise::scanlineTriangle;
  f.cubeST = exercise::cubeST;
  f.planarWrap = exercise::planarWrap;
  f.sphereMap = exercise::sphereMap;
  f.bumpNormal = exercise::bumpNormal;
  return f;
}

// Runs one exercise's check in a child process; its report is passed on
// as it comes, or one line says how the child ended.  Returns the verdict
// line ("NAME: PASS", "NAME: FAIL: not done yet ...") for the table.
std::string runIsolated(const exercise_check::Exercise& ex, Impl impl, const std::string& out, double limit) {
  std::fflush(stdout);
  int pipefd[2];
  if (pipe(pipefd) != 0) return std::string(ex.name) + ": FAIL: cannot start its check (pipe)";
  const pid_t pid = fork();
  if (pid < 0) return std::string(ex.name) + ": FAIL: cannot start its check (fork)";
  if (pid == 0) {
    close(pipefd[0]);
    dup2(pipefd[1], STDOUT_FILENO);
    int code = 1;
    try {
      ts::ContextOptions o;
      auto ctx = ts::createOffscreenContext(ts::Backend::Auto, o);
      ts::Renderer r(*ctx);
      code = exercise_check::run(ex, functions(impl), r, out) ? 0 : 1;
    } catch (const std::exception& e) {
      std::printf("%s: FAIL: %s\n", ex.name, e.what());
    }
    std::fflush(stdout);
    _exit(code);
  }
  close(pipefd[1]);
  const auto start = std::chrono::steady_clock::now();
  std::string text;
  bool timedOut = false;
  while (true) {
    pollfd p{pipefd[0], POLLIN, 0};
    const double left = limit - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (left <= 0) {
      timedOut = true;
      break;
    }
    if (poll(&p, 1, int(std::min(left, 1.0) * 1000) + 1) <= 0) continue;
    char buf[4096];
    const ssize_t n = read(pipefd[0], buf, sizeof buf);
    if (n <= 0) break;  // the child ended (or closed its output)
    text.append(buf, size_t(n));
    std::fwrite(buf, 1, size_t(n), stdout);
    std::fflush(stdout);
  }
  close(pipefd[0]);
  if (timedOut) kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  std::string verdict;
  if (timedOut) {
    char b[160];
    std::snprintf(b, sizeof b, "%s: FAIL: your code did not finish within %.0f s (an endless loop?)", ex.name, limit);
    verdict = b;
  } else if (WIFSIGNALED(status)) {
    verdict = std::string(ex.name) + ": FAIL: your code crashed (signal " + std::to_string(WTERMSIG(status)) + ", " +
              strsignal(WTERMSIG(status)) + ")";
  } else {
    // The child's own verdict: its last line naming the exercise.
    const std::string head = std::string(ex.name) + ": ";
    for (size_t at = text.find(head); at != std::string::npos; at = text.find(head, at + 1))
      if (at == 0 || text[at - 1] == '\n') verdict = text.substr(at, text.find('\n', at) - at);
    if (!verdict.empty()) return verdict;
    // No verdict: the code died in a way the process survived long enough
    // to exit (a sanitizer's report, exit()); say so in one line.
    verdict = head + "FAIL: your code crashed (exit status " +
              std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ", no report)";
  }
  std::printf("%s\n", verdict.c_str());
  return verdict;
}

int usage(const std::string& why) {
  std::fprintf(stderr, "exercise_check: %s (usage: exercise_check NAME...|--all [--solutions|--wrong] [--out DIR])\n",
               why.c_str());
  return 2;
}
}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> names;
  Impl impl = Impl::Mine;
  std::string out = "build/exercises";
  double limit = 10.0;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    auto value = [&]() -> std::string { return k + 1 < argc ? argv[++k] : ""; };
    if (a == "--all") {
      for (const auto& ex : exercise_check::exercises()) names.push_back(ex.name);
    } else if (a == "--solutions") {
      impl = Impl::Solution;
    } else if (a == "--wrong") {
      impl = Impl::Wrong;
    } else if (a == "--impl") {
      const std::string v = value();
      if (v == "crash") impl = Impl::Crash;
      else if (v == "hang") impl = Impl::Hang;
      else if (v == "nan") impl = Impl::Nan;
      else return usage("--impl takes crash, hang or nan, not '" + v + "'");
    } else if (a == "--out") {
      out = value();
      if (out.empty()) return usage("--out needs a folder");
    } else if (a == "--time-limit") {
      const std::string v = value();
      char* end = nullptr;
      limit = std::strtod(v.c_str(), &end);
      if (v.empty() || *end || !(limit > 0 && limit < 3600)) return usage("--time-limit takes seconds in (0, 3600)");
    } else if (!a.empty() && a[0] == '-') {
      return usage("unknown flag " + a);
    } else {
      if (!exercise_check::find(a)) return usage("no exercise named '" + a + "' (" + exercise_check::namesList() + ")");
      names.push_back(a);
    }
  }
  if (names.empty()) return usage("name an exercise or --all");
  int passed = 0;
  std::vector<std::string> verdicts;
  for (const std::string& n : names) {
    verdicts.push_back(runIsolated(*exercise_check::find(n), impl, out, limit));
    passed += verdicts.back() == n + ": PASS";
  }
  if (names.size() > 1) {  // the instructor's table
    std::printf("\n| exercise | result |\n|---|---|\n");
    for (size_t k = 0; k < names.size(); ++k)
      std::printf("| %s | %s |\n", names[k].c_str(), verdicts[k].substr(names[k].size() + 2).c_str());
  }
  std::printf("%d of %zu exercises pass\n", passed, names.size());
  return passed == int(names.size()) ? 0 : 1;
}
