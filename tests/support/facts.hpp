// tests/support/facts.hpp — the demos' facts files (demos/<name>/facts.tsv,
// docs/facts.md) read by the C++ tests: one fact a row, `KIND KEY VALUES...`,
// `#` to the end of the line a comment.  Read at run time from the source
// tree, so a new demo's facts need no edit here and no rebuild.
#pragma once
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ts::test {
struct Fact {
  std::string kind, key;
  std::vector<std::string> values;
  std::string file;  // where it was read, for messages
};

// The kinds a facts file may hold: a row of any other kind is a typo that
// would drop a fact unseen, so reading fails (as scripts/facts.sh does).
inline bool knownFactKind(const std::string& kind) {
  static const char* const kKinds[] = {"duration",      "backend_bound",     "hidden_bound",
                                       "export_bound",  "wine_bound",        "claim_bound",
                                       "drawn_from_gl", "too_slow_softpipe", "rasterizer_specific",
                                       "glsl_specular", "softpipe_wrong"};
  return std::any_of(std::begin(kKinds), std::end(kKinds), [&](const char* k) { return kind == k; });
}

// Every demos/*/facts.tsv under sourceDir, in the folders' order; throws
// std::runtime_error on an unknown kind or when no demo has a facts file
// (a wrong source folder would otherwise read as "no facts at all").
inline std::vector<Fact> readDemoFacts(const std::string& sourceDir) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(fs::path(sourceDir) / "demos", ec))
    if (fs::is_regular_file(e.path() / "facts.tsv")) files.push_back(e.path() / "facts.tsv");
  if (files.empty()) throw std::runtime_error("no demos/*/facts.tsv under " + sourceDir);
  std::sort(files.begin(), files.end());
  std::vector<Fact> out;
  for (const auto& f : files) {
    std::ifstream in(f);
    int n = 0;
    for (std::string line; std::getline(in, line);) {
      ++n;
      std::istringstream row(line.substr(0, line.find('#')));
      Fact fact;
      if (!(row >> fact.kind)) continue;
      if (!knownFactKind(fact.kind))
        throw std::runtime_error(f.string() + ":" + std::to_string(n) + ": unknown kind '" + fact.kind + "'");
      row >> fact.key;
      for (std::string v; row >> v;) fact.values.push_back(v);
      fact.file = f.string();
      out.push_back(fact);
    }
  }
  return out;
}

// Every demo's facts, read once per process and source folder.
inline const std::vector<Fact>& demoFacts(const std::string& sourceDir) {
  static std::map<std::string, std::vector<Fact>> cache;
  auto it = cache.find(sourceDir);
  if (it == cache.end()) it = cache.emplace(sourceDir, readDemoFacts(sourceDir)).first;
  return it->second;
}

// The keys (figure ids) of one kind's rows.
inline std::vector<std::string> factKeys(const std::string& sourceDir, const std::string& kind) {
  std::vector<std::string> keys;
  for (const auto& f : demoFacts(sourceDir))
    if (f.kind == kind) keys.push_back(f.key);
  return keys;
}

// The first value of the row of `kind` for `key`, or `fallback` without one.
inline long factValue(const std::string& sourceDir, const std::string& kind, const std::string& key, long fallback) {
  for (const auto& f : demoFacts(sourceDir))
    if (f.kind == kind && f.key == key && !f.values.empty()) return std::stol(f.values[0]);
  return fallback;
}
}  // namespace ts::test
