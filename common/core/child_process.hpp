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
// Program `name` of the suite beside the running one (".exe" added on Windows).
std::string programPath(const std::string& name);
// A new, empty folder in the system's temporary folder, named prefix + 16
// random hex digits; "" if none could be made.
std::string makeTempFolder(const std::string& prefix);

// The two other calls to the operating system the programs make, here so
// that no file of the demos sees <windows.h> (whose macros, near and far
// among them, break ordinary names):
// the console shows UTF-8 ("°", "—" in titles and numbers): Windows' must be
// told; elsewhere a no-op.
void useUtf8Console();
// The calling thread runs below the others: nice 5 on Linux (per thread,
// inherited by the threads it starts, llvmpipe's among them), Windows'
// "below normal".
void lowerThreadPriority();
}  // namespace ts
