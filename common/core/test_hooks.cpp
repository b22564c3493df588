#include "common/core/test_hooks.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace ts::test_hooks {
namespace {
std::atomic<long> g_frames{0};
const char* env(const char* name) {
  const char* v = std::getenv(name);
  return v && *v ? v : nullptr;
}
}  // namespace

std::vector<MouseEvent> mouseEvents() {
  std::vector<MouseEvent> r;
  const char* spec = env("TS_TEST_MOUSE");
  if (!spec) return r;
  std::stringstream all(spec);
  for (std::string ev; std::getline(all, ev, ';');) {
    std::istringstream e(ev);
    MouseEvent m;
    e >> m.what;
    bool ok = false;
    if (m.what == "press" || m.what == "rpress" || m.what == "move") ok = bool(e >> m.a >> m.b);
    else if (m.what == "release") ok = true;
    else if (m.what == "wheel") ok = bool(e >> m.a);
    else if (m.what == "drop") ok = bool(e >> std::ws && std::getline(e, m.path));
    if (ok) r.push_back(m);
    else if (!m.what.empty()) std::fprintf(stderr, "TS_TEST_MOUSE: cannot read '%s'\n", ev.c_str());
  }
  return r;
}

std::vector<std::pair<int, int>> resizes() {
  std::vector<std::pair<int, int>> sizes;
  const char* spec = env("TS_TEST_RESIZE");
  std::istringstream in(spec ? spec : "");
  for (std::string s; in >> s;) {
    int w = 0, h = 0;
    char x = 0;
    std::istringstream one(s);
    if (one >> w >> x >> h && x == 'x' && w > 0 && h > 0) sizes.push_back({w, h});
    else std::fprintf(stderr, "TS_TEST_RESIZE: cannot read '%s'\n", s.c_str());
  }
  return sizes;
}

std::string sizedName(const std::string& png, int w, int h) {
  std::string stem = png.size() > 4 && png.compare(png.size() - 4, 4, ".png") == 0 ? png.substr(0, png.size() - 4)
                                                                                   : png;
  return stem + "." + std::to_string(w) + "x" + std::to_string(h) + ".png";
}

KeyLog::KeyLog() {
  if (const char* p = env("TS_TEST_FRAME_LOG")) f_ = std::fopen(p, "w");
  if (const char* w = env("TS_TEST_KEY_WHEN")) {
    if (std::strcmp(w, "measured") == 0) when_ = When::Measured;
    else if (std::strcmp(w, "measuring") == 0) when_ = When::Measuring;
    else std::fprintf(stderr, "TS_TEST_KEY_WHEN: '%s' is neither measured nor measuring\n", w);
  }
  if (const char* k = env("TS_TEST_KEY_INTERVAL_MS")) keyInterval_ = std::max(0.0, std::strtod(k, nullptr) / 1000.0);
}
KeyLog::~KeyLog() {
  if (f_) std::fclose(f_);
}
double KeyLog::clock() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
void KeyLog::line(const char* what, const std::string& rest) {
  if (!f_) return;
  std::fprintf(f_, "%s %.4f%s%s\n", what, clock(), rest.empty() ? "" : " ", rest.c_str());
  std::fflush(f_);
}
bool KeyLog::keyDue(bool measuring, double progress, bool measuredOnce) const {
  if (untilKey() > 0) return false;
  if (when_ == When::Measured) return measuredOnce && !measuring;
  // While the measurement the key supersedes runs (if the last key started one).
  if (when_ == When::Measuring && taken_ > 0) return !measuring || progress > 0.0;
  return true;
}
void KeyLog::keyTaken() {
  ++taken_;
  lastKey_ = clock();
}
double KeyLog::untilKey() const { return keyInterval_ <= 0 ? 0.0 : std::max(0.0, lastKey_ + keyInterval_ - clock()); }

long slowMeasureMs() {
  const char* v = env("TS_TEST_SLOW_MEASURE_MS");
  return v ? std::max(0L, std::strtol(v, nullptr, 10)) : 0L;
}
long slowMeasureFrames() {
  const char* v = env("TS_TEST_SLOW_MEASURE_FRAMES");
  return v ? std::max(0L, std::strtol(v, nullptr, 10)) : 0L;
}
void frameDrawn() { g_frames.fetch_add(1); }
long framesDrawn() { return g_frames.load(); }

bool framePixels() {
  const char* v = env("TS_TEST_FRAME_PIXELS");
  return v && std::strcmp(v, "0") != 0;
}

bool screenshotWithOverlay() {
  const char* v = env("TS_SCREENSHOT_OVERLAY");
  return v && *v == '1';
}

bool glLibraryHidden(const char* lib) {
  const char* v = env("TS_HIDE_GL_LIBS");
  if (!v) return false;
  const std::string list = std::string(",") + v + ",";
  return list.find(std::string(",") + lib + ",") != std::string::npos;
}

bool noNpotTextures() {
  const char* v = env("TS_GL_NO_NPOT");
  return v && *v != '0';
}

long writePauseMs() {
  const char* v = env("TS_TEST_WRITE_PAUSE_MS");
  return v ? std::max(0L, std::strtol(v, nullptr, 10)) : 0L;
}

std::string exerciseImpl() {
  const char* v = env("TS_EXERCISE_IMPL");
  const std::string s = v ? v : "";
  return s == "solutions" || s == "wrong" ? s : "";
}

std::string oracleOutDir() {
  const char* v = env("TS_ORACLE_OUT");
  return v ? v : "";
}

}  // namespace ts::test_hooks
