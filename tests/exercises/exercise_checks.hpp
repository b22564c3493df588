// tests/exercises/exercise_checks.hpp — the checks of exercises/, each made
// of the suite's own measurements (exercise_check.cpp runs them, each in a
// child process).
#pragma once
#include <glm/vec2.hpp>

#include <functional>
#include <string>
#include <vector>

#include "common/core/image.hpp"
#include "exercises/exercise.hpp"

namespace ts {
class Renderer;
}

namespace exercise_check {
// Whose code is checked: the student's (exercises/*.cpp), the suite's
// solutions, a deliberately wrong one, or one that crashes, loops or
// returns NaN (the tests of the checker itself).
enum class Impl { Mine, Solution, Wrong, Crash, Hang, Nan };

// The functions an exercise asks for (exercises/exercise.hpp).
struct Functions {
  std::function<double(double)> cylinderS;
  std::function<glm::dvec2(double, double)> torusST;
  std::function<ts::Image(const ts::Image&, int, int)> blit;
  std::function<int(double, int)> mirrorTexel;
  std::function<void(const exercise::ScanVertex*, const exercise::Plot&)> scanline;
  std::function<glm::dvec2(int, glm::dvec3)> cubeST;
  std::function<glm::dvec2(glm::dvec3, int, double, glm::dvec3)> planarWrap;
  std::function<glm::dvec2(glm::dvec3, glm::dvec3)> sphereMap;
  std::function<glm::dvec3(glm::dvec3, glm::dvec3, double, double, double, double, double)> bumpNormal;
};
// The suite's own implementations of `impl` (empty for Impl::Mine).
Functions reference(Impl impl);

struct Exercise {
  const char* name;    // "vi1_back_seam": exercises/<name>.cpp
  const char* source;  // "Buss, Exercise VI.1"
  const char* see;     // the demo command that shows the reference
  // Measures and prints each check's line; true when all pass.
  std::function<bool(const Functions&, ts::Renderer&, const std::string& picture)> check;
  // The demo opened with the student's code, its panel showing these checks
  // live (common/core/student_code.hpp); null when no demo takes it.
  const char* mine = nullptr;
};
const std::vector<Exercise>& exercises();
const Exercise* find(const std::string& name);
std::string namesList();

// Runs one exercise: its checks' report on stdout, the picture (yours |
// reference | difference) as <outDir>/<name>.png.  A stub's NotDone, and a
// NaN or error from the code checked, is the exercise's failure, in one line.
bool run(const Exercise& ex, const Functions& f, ts::Renderer& r, const std::string& outDir);
}  // namespace exercise_check
