// common/core/child_process.hpp — run another program of the suite and read
// what it prints, with a time limit: how a demo opened with a student's code
// (--seam mine, --mapping mine) asks the exercises' checker
// (build/bin/exercise_check) for the checks and for the student's values,
// so that code which crashes or loops forever stops the checker, never the
// window.
#pragma once
#include <string>
#include <vector>

namespace ts {
struct ProcessResult {
  bool started = false;   // false: the program could not be run (`out` says why)
  bool timedOut = false;  // killed after the time limit
  int exitCode = -1;      // its exit status (-1: killed by a signal)
  std::string out;        // what it wrote on stdout (and stderr, after it)
};
// Runs argv[0] (a path) with `input` on its stdin; kills it after
// `timeoutSeconds`.  Never throws.
ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& input, double timeoutSeconds);
// The folder of the running program (build/bin for the demos).
std::string programFolder();
}  // namespace ts
