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
//   exercise_check --eval FN         FN (cylinderS, torusST) at each row of
//                                    numbers on stdin: a demo opened with
//                                    the student's code draws with them
// Each exercise runs in a child process of its own, with its own offscreen
// GL context: a crash, an endless loop or a NaN is that exercise's failure,
// reported in one line, and the next one runs.  Exit status: 0 when every
// check passes, 1 when one fails, 2 on bad usage.
//
// The reference solutions are the demos' (cylinder_seam_math.hpp's back seam,
// torus_math.hpp's front mapping, wrap_modes_math.hpp's GL formulas), never in
// exercises/.
#ifdef _WIN32
#include <io.h>
#include <process.h>

#include <filesystem>
// The exit status is the child's own status there: no signals.
#define WIFSIGNALED(s) ((void)(s), false)
#define WTERMSIG(s) ((void)(s), 0)
#define WIFEXITED(s) ((void)(s), true)
#define WEXITSTATUS(s) (s)
static const char* strsignal(int) { return "signal"; }
#else
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iostream>
#include <sstream>
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

// Runs `body` in a child process, its stdout passed on as it comes (when
// `echo`) and kept; kills it after `limit` seconds.
struct ChildEnd {
  std::string text;
  bool timedOut = false;
  int status = 0;
  bool started = true;
};
#ifdef _WIN32
// Windows has no fork: the check runs in this process, its stdout caught in
// a temporary file.  A crash or an endless loop there ends or stops the
// whole checker (the demo that asked for a verdict reports that, and stops
// it after its own time limit); the exercises are built and graded on
// Linux (scripts/exercise.sh), where each runs isolated.
ChildEnd inChild(double, bool echo, const std::function<int()>& body) {
  ChildEnd end;
  std::fflush(stdout);
  std::error_code ec;
  const std::filesystem::path path = std::filesystem::temp_directory_path(ec) /
                                     ("ts_check_" + std::to_string(_getpid()) + ".txt");
  std::FILE* tmp = ec ? nullptr : std::fopen(path.string().c_str(), "w+b");
  if (!tmp) return end.started = false, end;
  const int saved = _dup(_fileno(stdout));
  _dup2(_fileno(tmp), _fileno(stdout));
  end.status = body();
  std::fflush(stdout);
  _dup2(saved, _fileno(stdout));
  _close(saved);
  std::rewind(tmp);
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, tmp)) > 0;) end.text.append(buf, n);
  std::fclose(tmp);
  std::filesystem::remove(path, ec);
  if (echo) std::fwrite(end.text.data(), 1, end.text.size(), stdout), std::fflush(stdout);
  return end;
}
#else
ChildEnd inChild(double limit, bool echo, const std::function<int()>& body) {
  ChildEnd end;
  std::fflush(stdout);
  int pipefd[2];
  if (pipe(pipefd) != 0) return end.started = false, end;
  const pid_t pid = fork();
  if (pid < 0) return end.started = false, end;
  if (pid == 0) {
    close(pipefd[0]);
    dup2(pipefd[1], STDOUT_FILENO);
    const int code = body();
    std::fflush(stdout);
    _exit(code);
  }
  close(pipefd[1]);
  const auto start = std::chrono::steady_clock::now();
  while (true) {
    pollfd p{pipefd[0], POLLIN, 0};
    const double left = limit - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (left <= 0) {
      end.timedOut = true;
      break;
    }
    if (poll(&p, 1, int(std::min(left, 1.0) * 1000) + 1) <= 0) continue;
    char buf[4096];
    const ssize_t n = read(pipefd[0], buf, sizeof buf);
    if (n <= 0) break;  // the child ended (or closed its output)
    end.text.append(buf, size_t(n));
    if (echo) std::fwrite(buf, 1, size_t(n), stdout), std::fflush(stdout);
  }
  close(pipefd[0]);
  if (end.timedOut) kill(pid, SIGKILL);
  waitpid(pid, &end.status, 0);
  return end;
}
#endif

// How the child ended, as the exercise's verdict line: its own last line
// naming the exercise, or one line for a hang, a crash or no report.
std::string verdictOf(const char* name, const ChildEnd& end, double limit) {
  const std::string head = std::string(name) + ": ";
  if (!end.started) return head + "FAIL: cannot start its check (pipe or fork)";
  if (end.timedOut) {
    char b[160];
    std::snprintf(b, sizeof b, "%s: FAIL: your code did not finish within %.0f s (an endless loop?)", name, limit);
    return b;
  }
  if (WIFSIGNALED(end.status))
    return head + "FAIL: your code crashed (signal " + std::to_string(WTERMSIG(end.status)) + ", " +
           strsignal(WTERMSIG(end.status)) + ")";
  std::string verdict;
  for (size_t at = end.text.find(head); at != std::string::npos; at = end.text.find(head, at + 1))
    if (at == 0 || end.text[at - 1] == '\n') verdict = end.text.substr(at, end.text.find('\n', at) - at);
  if (!verdict.empty()) return verdict;
  // No verdict: the code died in a way the process survived long enough
  // to exit (a sanitizer's report, exit()); say so in one line.
  return head + "FAIL: your code crashed (exit status " +
         std::to_string(WIFEXITED(end.status) ? WEXITSTATUS(end.status) : -1) + ", no report)";
}

// Runs one exercise's check in a child process; its report is passed on
// as it comes, or one line says how the child ended.  Returns the verdict
// line ("NAME: PASS", "NAME: FAIL: not done yet ...") for the table.
std::string runIsolated(const exercise_check::Exercise& ex, Impl impl, const std::string& out, double limit) {
  const ChildEnd end = inChild(limit, true, [&] {
    int code = 1;
    try {
      ts::ContextOptions o;
      auto ctx = ts::createOffscreenContext(ts::Backend::Auto, o);
      ts::Renderer r(*ctx);
      code = exercise_check::run(ex, functions(impl), r, out) ? 0 : 1;
    } catch (const std::exception& e) {
      std::printf("%s: FAIL: %s\n", ex.name, e.what());
    }
    return code;
  });
  const std::string verdict = verdictOf(ex.name, end, limit);
  if (end.text.find(verdict) == std::string::npos) std::printf("%s\n", verdict.c_str());
  return verdict;
}

// --eval FN: the function an exercise asks for, at each row of numbers on
// stdin, one row of results a line (a demo opened with the student's code
// draws with them: common/core/student_code.hpp).  In a child process with
// the time limit, like a check: not done, NaN, a crash or a hang is one
// "NAME: FAIL: ..." line and exit status 1.
int evaluate(const std::string& fn, Impl impl, double limit) {
  struct Fn {
    const char* name;
    const char* exercise;
    size_t arity;
  };
  const Fn fns[] = {{"cylinderS", "vi1_back_seam", 1}, {"torusST", "vi2_torus_front", 2}};
  const Fn* f = nullptr;
  for (const Fn& c : fns)
    if (fn == c.name) f = &c;
  if (!f) {
    std::fprintf(stderr, "exercise_check: --eval takes cylinderS or torusST, not '%s'\n", fn.c_str());
    return 2;
  }
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(std::cin, line);) {
    std::istringstream in(line);
    std::vector<double> row;
    for (double v; in >> v;) row.push_back(v);
    if (row.empty()) continue;
    if (row.size() != f->arity) {
      std::fprintf(stderr, "exercise_check: --eval %s takes %zu numbers a line, not '%s'\n", f->name, f->arity,
                   line.c_str());
      return 2;
    }
    rows.push_back(row);
  }
  const exercise_check::Functions code = functions(impl);
  const ChildEnd end = inChild(limit, false, [&] {
    try {
      for (const auto& row : rows) {
        std::vector<double> v;
        if (fn == "cylinderS") v = {code.cylinderS(row[0])};
        else {
          const glm::dvec2 st = code.torusST(row[0], row[1]);
          v = {st.x, st.y};
        }
        for (double x : v)
          if (!std::isfinite(x)) {
            std::printf("%s: FAIL: %s gave %g (not a number) at %g\n", f->exercise, f->name, x, row[0]);
            return 1;
          }
        for (double x : v) std::printf("%.17g ", x);
        std::printf("\n");
      }
    } catch (const exercise::NotDone&) {
      std::printf("%s: FAIL: not done yet (write it in exercises/%s.cpp)\n", f->exercise, f->exercise);
      return 1;
    } catch (const std::exception& e) {
      std::printf("%s: FAIL: %s\n", f->exercise, e.what());
      return 1;
    }
    std::printf("%s: done\n", f->name);
    return 0;
  });
  std::fwrite(end.text.data(), 1, end.text.size(), stdout);
  if (end.started && !end.timedOut && WIFEXITED(end.status) && WEXITSTATUS(end.status) == 0) return 0;
  const std::string verdict = verdictOf(f->exercise, end, limit);
  if (end.text.find(verdict) == std::string::npos) std::printf("%s\n", verdict.c_str());
  return 1;
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
  std::string eval;
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
    } else if (a == "--eval") {
      eval = value();
      if (eval.empty()) return usage("--eval needs a function (cylinderS, torusST)");
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
  if (!eval.empty()) return evaluate(eval, impl, limit);
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
