// common/core/test_hooks.hpp — the suite's one test seam.
//
// Every environment variable that tests and benchmarks set is read here and
// nowhere else; production code asks these functions.  A student never sets
// them.  Every hook of the window waits on an event (a frame drawn, a
// measurement handed over, a measurement under way), never on the clock
// alone, so that a test's verdict does not depend on how busy the machine is.
//
// The window and the measurement worker:
//
//   TS_TEST_MOUSE="press X Y; move X Y; release; wheel N; drop FILE"
//       mouse events given before the first frame ("rpress X Y": the right
//       button), through the window's own mouse handlers.
//   TS_TEST_RESIZE="WxH WxH ..."
//       once the window would have ended (--frames), resize it to each size
//       in turn and draw --frames frames again; the last frame at each size,
//       the first included, is written as <screenshot>.WxH.png.
//   TS_TEST_FRAME_LOG=FILE
//       a line per event, times in seconds of the steady clock: "frame T M P"
//       after each swap (M 1 while a measurement is out, P its progress),
//       "key T C" when a key is taken, "result T" when a measurement is
//       handed over.
//   TS_TEST_FRAME_PIXELS=1
//       (benchmarks: bench_window) with TS_TEST_FRAME_LOG, each "frame"
//       line ends with a hash of the figure's pixels (read back before the
//       overlay), "frame T M P H", and a first stage of a measurement
//       (ts::measureStage) logs "stage T": when the picture is complete is
//       when H stops changing.
//   TS_TEST_KEY_WHEN=measured|measuring
//       when --keys takes its next key: "measured" once the numbers of the
//       state so far are in (no measurement out); "measuring" (after the
//       first key) once a measurement is out and has reported progress, so
//       the key lands while it runs, as a student's does.  Unset: one key a
//       frame.
//   TS_TEST_KEY_INTERVAL_MS=N
//       (benchmarks: bench_window) take a key at most every N ms, so that a
//       key's latency is timed one key at a time.  No test uses it: a test
//       waits on events.
//   TS_TEST_SLOW_MEASURE_MS=N, TS_TEST_SLOW_MEASURE_FRAMES=F
//       every measurement of the worker first spends at least N ms, in 10 ms
//       steps that report progress and stop when superseded, and does not
//       end before the window has drawn F frames since it began: a window
//       that stopped drawing while measuring never gets its result.
//   TS_SCREENSHOT_OVERLAY=1
//       --screenshot takes the window as the student sees it (side panel,
//       GL pane, help card) instead of the figure alone.
//
// The GL layer, files and the exercises:
//
//   TS_HIDE_GL_LIBS=osmesa,egl
//       behave as if that library were not installed, so the fallback and
//       the "install these packages" paths run on a machine that has all.
//   TS_GL_NO_NPOT=1
//       textures take the path of a GL 1.x context without non-power-of-two
//       textures (resampled, with a note) on any context.
//   TS_TEST_WRITE_PAUSE_MS=N
//       every file written pauses N ms half-way, so a test can kill a run in
//       the middle of a write and find no half-written file.
//   TS_EXERCISE_IMPL=solutions|wrong
//       the exercise checker a demo starts runs the suite's solutions or a
//       deliberately wrong one instead of the student's code.
//   TS_ORACLE_OUT=DIR
//       where the oracle writes the images of a failed check (default
//       oracle_failures/).
#pragma once
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace ts::test_hooks {

// TS_TEST_MOUSE, parsed.  what: press | rpress | move | release | wheel | drop.
struct MouseEvent {
  std::string what;
  double a = 0, b = 0;
  std::string path;  // drop
};
std::vector<MouseEvent> mouseEvents();

// TS_TEST_RESIZE, parsed; and the screenshot's name at a size.
std::vector<std::pair<int, int>> resizes();
std::string sizedName(const std::string& png, int w, int h);

// The frame log and the pacing of --keys.
class KeyLog {
 public:
  KeyLog();
  ~KeyLog();
  KeyLog(const KeyLog&) = delete;
  KeyLog& operator=(const KeyLog&) = delete;
  static double clock();  // seconds of the steady clock
  void line(const char* what, const std::string& rest = "");
  // Whether --keys may take its next key now.  measuring: a measurement is
  // out; progress: its progress; measuredOnce: a result has been handed over.
  // No side effect: keyTaken() says a key was taken.
  bool keyDue(bool measuring, double progress, bool measuredOnce) const;
  void keyTaken();
  double untilKey() const;  // seconds until TS_TEST_KEY_INTERVAL_MS allows a key

 private:
  enum class When { Frame, Measured, Measuring };
  std::FILE* f_ = nullptr;
  When when_ = When::Frame;
  int taken_ = 0;
  double keyInterval_ = 0, lastKey_ = -1e9;
};

// The slowed measurement (TS_TEST_SLOW_MEASURE_MS / _FRAMES).
long slowMeasureMs();
long slowMeasureFrames();
// The window calls this after every frame it shows; the slowed measurement
// counts them.
void frameDrawn();
long framesDrawn();

// TS_TEST_FRAME_PIXELS=1: the frame log hashes each frame's figure.
bool framePixels();
// TS_SCREENSHOT_OVERLAY=1: the screenshot with the overlay.
bool screenshotWithOverlay();

// TS_HIDE_GL_LIBS: whether `lib` (osmesa, egl) is to be taken as missing.
bool glLibraryHidden(const char* lib);
// TS_GL_NO_NPOT: whether to treat the context as lacking NPOT textures.
bool noNpotTextures();
// TS_TEST_WRITE_PAUSE_MS: the pause half-way through every file written.
long writePauseMs();
// TS_EXERCISE_IMPL: "solutions", "wrong", or "" (the student's code).
std::string exerciseImpl();
// TS_ORACLE_OUT: the oracle's folder for failure images, "" when unset.
std::string oracleOutDir();

}  // namespace ts::test_hooks
