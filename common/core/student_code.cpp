// common/core/student_code.cpp — the exercises' checker as a child process.
#include "common/core/student_code.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "common/core/child_process.hpp"
#include "common/core/test_hooks.hpp"

namespace ts::student {
namespace {
// The checker stops the student's code after 10 s an exercise; the whole
// run (a GL context, a few renders) gets room beyond that on a busy host.
constexpr double kCheckerSeconds = 120.0;

std::vector<std::string> command(std::vector<std::string> args) {
  args.insert(args.begin(), programPath("exercise_check"));
  // A test runs the suite's solutions or a wrong one (test_hooks.hpp).
  const std::string impl = test_hooks::exerciseImpl();
  if (!impl.empty()) args.push_back("--" + impl);
  return args;
}

std::string noChecker(const ProcessResult& p) {
  if (!p.started || p.exitCode == 127)
    return "no exercise checker beside this program: build it with bash scripts/exercise.sh";
  if (p.timedOut) return "the exercise checker did not finish";
  return "";
}
}  // namespace

Report check(const std::string& exercise) {
  Report r;
  // The checker's picture (yours | reference | difference) goes to a
  // folder of its own, removed after: the script is where it is kept.
  std::string dir = makeTempFolder("ts_exercise_");
  std::vector<std::string> args = {exercise};
  if (!dir.empty()) args.insert(args.end(), {"--out", dir});
  const ProcessResult p = runProcess(command(args), "", kCheckerSeconds);
  if (!dir.empty()) {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
  if (std::string why = noChecker(p); !why.empty()) {
    r.verdict = exercise + ": " + why;
    return r;
  }
  std::istringstream in(p.out);
  const std::string head = exercise + ": ";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(head, 0) == 0) r.verdict = line, r.ran = true;
    if (line.rfind("  ", 0) != 0) continue;
    const bool pass = line.size() > 6 && line.compare(line.size() - 6, 6, ": pass") == 0;
    const bool fail = line.size() > 6 && line.compare(line.size() - 6, 6, ": FAIL") == 0;
    if (pass || fail) r.checks.push_back({pass, line.substr(2)});
  }
  r.pass = r.ran && r.verdict == head + "PASS";
  if (!r.ran) r.verdict = head + "the checker gave no verdict (exit status " + std::to_string(p.exitCode) + ")";
  return r;
}

bool eval(const std::string& fn, const std::vector<std::vector<double>>& in, std::vector<std::vector<double>>* out,
          std::string* why) {
  std::string input;
  char b[64];
  for (const auto& row : in) {
    for (double v : row) std::snprintf(b, sizeof b, "%.17g ", v), input += b;
    input += "\n";
  }
  const ProcessResult p = runProcess(command({"--eval", fn}), input, kCheckerSeconds);
  if (std::string w = noChecker(p); !w.empty()) return *why = w, false;
  out->clear();
  std::istringstream lines(p.out);
  std::string failure;
  for (std::string line; std::getline(lines, line);) {
    if (line.find(": FAIL") != std::string::npos) {
      failure = line;
      continue;
    }
    if (line.empty() || line.find(": ") != std::string::npos) continue;  // "cylinderS: done"
    std::istringstream row(line);
    std::vector<double> v;
    for (double x; row >> x;) v.push_back(x);
    out->push_back(v);
  }
  if (p.exitCode != 0 || out->size() != in.size()) {
    *why = failure.empty() ? "the exercise checker could not evaluate " + fn : failure;
    return false;
  }
  return true;
}

const std::vector<double>& Table::at(const std::vector<double>& x) const {
  size_t best = 0;
  double bd = 1e300;
  for (size_t k = 0; k < in.size() && bd > 0; ++k) {
    double d = 0;
    for (size_t c = 0; c < x.size() && c < in[k].size(); ++c) d += (x[c] - in[k][c]) * (x[c] - in[k][c]);
    if (d < bd) bd = d, best = k;
  }
  return out.at(best);
}

Table table(const std::string& fn, std::vector<std::vector<double>> in) {
  Table t;
  t.fn = fn, t.in = std::move(in);
  if (!eval(fn, t.in, &t.out, &t.failure) && t.failure.empty()) t.failure = fn + ": failed";
  return t;
}

std::string summary(const Measurements& ms) {
  double passed = -1, total = -1;
  std::string verdict;
  for (const auto& m : ms) {
    if (m.name == "exercise_checks_passed") passed = m.value;
    if (m.name == "exercise_checks_total") total = m.value;
    if (m.name == "exercise_verdict") verdict = m.meaning;
  }
  if (passed < 0) return "your code: checking ...";
  if (total > 0)
    return "your code: " + std::to_string(int(passed)) + " of " + std::to_string(int(total)) + " checks pass";
  return verdict;
}

void addTo(Measurements& ms, const std::string& exercise, const Report& r) {
  int passed = 0;
  for (const Check& c : r.checks) passed += c.pass;
  ms.push_back({"exercise_checks_passed", double(passed), exercise + ": checks your code passes (" + r.verdict + ")"});
  ms.push_back(
      {"exercise_checks_total", double(r.checks.size()), "checks made (none: the code is not done or did not run)"});
  for (size_t k = 0; k < r.checks.size(); ++k)
    ms.push_back({"exercise_check[" + std::to_string(k + 1) + "]", r.checks[k].pass ? 1.0 : 0.0, r.checks[k].text});
  ms.push_back({"exercise_verdict", r.pass ? 1.0 : 0.0, r.verdict});
}
}  // namespace ts::student
