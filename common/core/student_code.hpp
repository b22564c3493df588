// common/core/student_code.hpp — a demo opened with a student's code.
//
// `bash scripts/exercise.sh vi1_back_seam` builds the student's file into
// build/bin/exercise_check.  A demo an exercise plugs into (cylinder_seam
// --seam mine, torus --mapping mine) asks that checker, as a child process
// with a time limit, for two things: the student's values at the points the
// demo draws (the picture), and the exercise's checks (the side panel shows
// each with pass or FAIL, the same lines the script prints).  The student's
// code never runs in the window's process: a crash or an endless loop is a
// failed check, not a dead window.
//
// TS_EXERCISE_IMPL=solutions|wrong (tests only) asks for the suite's
// solution or a wrong one instead of the student's code.
#pragma once
#include <string>
#include <vector>

#include "common/core/scene.hpp"

namespace ts::student {
struct Check {
  bool pass = false;
  std::string text;  // "6 slices: the texture's edges meet in the patch at theta = 180.0 deg, expected 180: pass"
};
struct Report {
  bool ran = false;   // the checker ran and gave a verdict
  bool pass = false;  // every check passed
  std::vector<Check> checks;
  std::string verdict;  // "vi1_back_seam: FAIL: not done yet (write it in exercises/vi1_back_seam.cpp)"
};
// The exercise's checks on the student's code (exercise_check EXERCISE).
Report check(const std::string& exercise);
// The student's function `fn` (exercise_check --eval: cylinderS, torusST) at
// each row of `in`.  false, with the checker's one line in *why, when the
// code is not done, fails, crashes, loops or returns NaN.
bool eval(const std::string& fn, const std::vector<std::vector<double>>& in, std::vector<std::vector<double>>* out,
          std::string* why);
// The student's function at the points a demo draws, evaluated once (in
// measure(), on the measurement's thread) and kept in the Measurements'
// detail, so that build() draws with it: `at` gives the row of the input
// nearest x (the demo asks at the very points it gave).
struct Table {
  std::string fn;
  std::vector<std::vector<double>> in, out;
  std::string failure;  // the checker's one line when the code failed
  bool ok() const { return failure.empty() && !in.empty() && in.size() == out.size(); }
  const std::vector<double>& at(const std::vector<double>& x) const;
};
Table table(const std::string& fn, std::vector<std::vector<double>> in);
// The one line a picture shows of the report: "your code: 6 of 6 checks pass"
// or the verdict's reason.
std::string summary(const Measurements& ms);
// The report as measurements: exercise_checks_passed, exercise_checks_total,
// and exercise_check[1..n] = 1 (pass) or 0 (FAIL), each with its line; the
// verdict line as exercise_verdict (1 PASS, 0 FAIL).
void addTo(Measurements& ms, const std::string& exercise, const Report& r);
}  // namespace ts::student
