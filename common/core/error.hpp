// common/core/error.hpp — one exception type for everything a user can cause.
// Demos catch it in demo_main.cpp and print exactly one line on stderr.
#pragma once
#include <stdexcept>
#include <string>

namespace ts {
// Exit statuses shared by every program of the suite.
enum ExitCode : int {
  kExitOk = 0,
  kExitFailure = 1,  // a check failed / rendering error
  kExitUsage = 2,    // bad flags, bad input file, no display, no context
};

// A note for the user that is neither an error nor the measurement (a backend
// fallback, a resized texture, which averaging path a demo took): one line
// on stderr, silenced by --quiet.
void note(const std::string& line);
void setQuietNotes(bool quiet);

struct Error : std::runtime_error {
  explicit Error(const std::string& what, int code = kExitUsage) : std::runtime_error(what), exit_code(code) {}
  int exit_code;
};
}  // namespace ts
