// tests/window/window_test.cpp — the "real windows" tests.
//
// For every registered scene (so every demo program; new demos are covered
// by linking their scene, see CMakeLists.txt) and under a fresh Xvfb, in two
// levels (--subset=smoke|full, --demo=ID for one demo's cases):
// smoke (CTest window_smoke, the quick level):
//   <id>.key_<char>_<option>      the demo's first key: --keys <char> changes
//                                 the state the way Options::handleKey does
//                                 on a fresh Options; the window's stdout
//                                 state line says so; its screenshot matches
//                                 the --png render of that state, and so do
//                                 the numbers it prints.
//   <id>.help_and_save            the key, then F12: PNG + sidecar, and the
//                                 printed command remakes the picture; the
//                                 key, then ?: the help card is on screen.
//   <id>.state_flags_round_trip   parse(stateFlags()) reproduces the state,
//                                 for the initial state and after each key
//                                 (the flags a figure's sidecar command uses).
// full (CTest window_full_<id>, the full level):
//   <id>.window_matches_png       the window opens, draws 3 frames, exits 0,
//                                 and left of its side panel its screenshot
//                                 matches the --png render (side_panel.hpp).
//   <id>.key_<char>_<option>      every other key of every option, as above.
//   <id>.live_view_matches_png    for a demo with a live view (Scene::live,
//                                 started with --view live): as above, in
//                                 that view (clock readings not compared)
//   <id>.gl_pane_*                the GL pane beside the figure, and the calls
//                                 a key changed marked in it.
//   <id>.gl_pane_marks_hold_with_real_keys   the demo started as a student
//                                 does, real X key events (xdotool): l, then
//                                 the first key that changes a GL call; the
//                                 screen (ImageMagick's import) shows its
//                                 marked lines in the pane 2 s after the key,
//                                 across its measurement's re-record, none
//                                 before it or 6 s after.
//   <id>.inspect_mode_clicks_a_pixel   at --size 640x480 and 1280x720, real X
//                                 events (xdotool): the inspect key (i, or I
//                                 where an option takes i), a click on the
//                                 textured pixel nearest the figure's centre
//                                 (by the reference, or on the screen for a
//                                 picture made when measuring): the card
//                                 names that pixel, has GL's and the
//                                 reference's colours
//                                 and a finite lambda where it has one; F12's
//                                 command carries --inspect X,Y and, run with
//                                 --png, its card names the same panel and
//                                 batch; q ends the demo with 0.
//   <id>.resize_sequence          the window resized to 640x480, 700x1000 and
//                                 1280x720 in turn: at each size the figure
//                                 is the --png render at its new size.
//   <id>.reset_equals_arrow       Backspace resets, = is +, the right arrow turns.
//   <id>.mouse_orbit, mouse_light a left drag and the wheel turn the orbit; a
//                                 right drag moves the light (bump_mapping).
//   <id>.drop_file                a dropped picture is --texture FILE.
//   <id>.never_frozen, close_while_measuring   (quad_distortion, parallax_aniso)
// No case's verdict depends on how long a run takes (see kHangSeconds).
//
// Each window run is exactly what a student would type:
//   xvfb-run -a -s "-screen 0 1600x1200x24" build/bin/<id> --size 800x480 --frames 3
//            [--keys K] --screenshot W.png     (one line)
//   build/bin/<id> --size 800x480 --png P.png [--name=value of what changed]
// and the images, stdout/stderr and commands are kept in
// <build>/tests/window/out/<id>/<test>/ (plus diff.png when they differ).
//
// Environment: TS_WINDOW_PNG_BACKEND=osmesa|egl (default: auto) picks the
// --png backend; TS_WINDOW_SIZE=WxH overrides 800x480.
// `window_test --compare A.png B.png [DIFF.png]` prints the statistics the
// bounds below are about.
//
// No xvfb-run on PATH: the program prints why and exits 77, which CTest
// reports as "Skipped" (SKIP_RETURN_CODE), never as passed.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "common/core/error.hpp"
#include "common/app/gl_pane.hpp"
#include "common/core/layout.hpp"
#include "common/app/side_panel.hpp"
#include "common/app/window.hpp"
#include "common/core/image.hpp"
#include "common/core/options.hpp"
#include "common/core/scene.hpp"
#include "reference/inspect.hpp"

#ifndef TS_BIN_DIR
#define TS_BIN_DIR "build/bin"
#endif
#ifndef TS_OUT_DIR
#define TS_OUT_DIR "build/tests/window/out"
#endif

namespace {
constexpr int kSkip = 77;  // CTest SKIP_RETURN_CODE
const char* const kXvfbScreen = "-screen 0 1600x1200x24";
constexpr int kFrames = 3;
// The window and --png size: 800x480 unless TS_WINDOW_SIZE=WxH says otherwise.
int gWidth = 800, gHeight = 480;

// No verdict here depends on how long anything takes (the machine may be
// busy; bench_window times the window).  A run that has not ended after
// kHangSeconds is a hang: its process group (xvfb-run, Xvfb, the demo) is
// killed and the case fails.  Measured quiet: 0.5-4.5 s a run, 28 s under a
// two-loop load, up to 20 s under ASan; TS_WINDOW_HANG_SECONDS=S changes it.
double envSeconds(const char* name, double fallback) {
  const char* e = std::getenv(name);
  char* end = nullptr;
  double v = e && *e ? std::strtod(e, &end) : 0.0;
  return e && *e && end && !*end && v > 0 ? v : fallback;
}
const double kHangSeconds = envSeconds("TS_WINDOW_HANG_SECONDS", 300.0);

// --- window vs --png tolerance ------------------------------------------
// Measured on Debian 12 / Mesa 22.3.6 / llvmpipe, 800x480, every state this
// test visits (default + each key), RGB only (the window's back buffer alpha
// is not part of the picture; measured equal anyway):
//  * GLX window vs OSMesa --png (the default: --backend auto picks OSMesa):
//    bit-identical, 0 pixels differ, apart from the measured-kink label
//    (quad_distortion measures at 480 px in an 800x480 window, 512 px
//    offscreen: "18.5 deg" vs "18.4 deg", 20-45 pixels differing by 224, 6-13
//    of them with no match within one pixel; see the report).
//  * GLX window vs EGL --png (the fallback once Mesa drops OSMesa): EGL draws
//    into an FBO, the window and OSMesa into y-inverted window-system
//    buffers, so GL_NEAREST ties at texel boundaries land one pixel over:
//    up to 1377 pixels (0.36%, filter=nearest) differ by up to 192, all
//    within one pixel of a matching pixel except 4 at line crossings.
//    Linear filtering differs by <= 2 in up to 85 pixels.
// What a real disagreement costs, window (after a key) vs the --png of the
// default state: the edges key 2188 px (0.57%), 2169 of them with no match
// within one pixel; the filter key 13487 px; others 10-55% of the picture.
// So two bounds, per --png backend:
//  - "differ": the fraction of pixels whose largest channel difference is
//    more than 2 (rounding of blends and linear filtering is not a
//    disagreement);
//  - "unexplained": pixels that differ by more than 2 from every pixel in the
//    other image's 3x3 neighbourhood (both ways): a one-pixel shift of an
//    edge is explained, a missing line, a different colour or texture is not.
// OSMesa: measured 0 and 0 -> at most 0.01% (38 px) differ, none
//   unexplained.  Catches a changed digit in a label too.
// EGL: measured 0.36% and 4 -> at most 0.75% differ, at most 16
//   unexplained (a digit of a label can slip through here; the measurement
//   check below catches the numbers that labels show).
constexpr int kSmallDiff = 2;
struct Bounds {
  double maxFraction;
  long maxUnexplained;
};
constexpr Bounds kOsmesaBounds{0.0001, 0}, kEglBounds{0.0075, 16};
// Measurements printed by the window and by --png (4 decimals) must agree
// to the last digit or so: measured identical for OSMesa and EGL renders of
// the same size.
constexpr double kMeasurementAbs = 1e-3, kMeasurementRel = 1e-4;

std::string binDir() {
  const char* e = std::getenv("TS_WINDOW_BIN_DIR");
  return e && *e ? e : TS_BIN_DIR;
}
std::string outDir() {
  const char* e = std::getenv("TS_WINDOW_OUT_DIR");
  return e && *e ? e : TS_OUT_DIR;
}

std::string findOnPath(const std::string& prog) {
  const char* path = std::getenv("PATH");
  std::stringstream ss(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    std::string p = (dir.empty() ? "." : dir) + "/" + prog;
    if (access(p.c_str(), X_OK) == 0) return p;
  }
  return "";
}

void mkdirs(const std::string& path) {
  std::string cur;
  std::stringstream ss(path);
  std::string part;
  if (!path.empty() && path[0] == '/') cur = "/";
  while (std::getline(ss, part, '/')) {
    if (part.empty()) continue;
    cur += part + "/";
    mkdir(cur.c_str(), 0755);
  }
}

std::string readFile(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// `p` from the root when it is relative (to the working folder).
std::string absolute(const std::string& p) {
  if (p.empty() || p[0] == '/') return p;
  char cwd[4096];
  return getcwd(cwd, sizeof cwd) ? std::string(cwd) + "/" + p : p;
}

std::string quote(const std::string& a) {
  if (!a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_=./+,:") ==
                        std::string::npos)
    return a;
  std::string q = "'";
  for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
std::string commandLine(const std::vector<std::string>& argv) {
  std::string s;
  for (const auto& a : argv) s += (s.empty() ? "" : " ") + quote(a);
  return s;
}

// A child process in its own process group, stdout and stderr to files.
struct Proc {
  std::vector<std::string> argv;
  std::string outPath, errPath;
  pid_t pid = -1;
  std::chrono::steady_clock::time_point start;
  // Results.
  int exitCode = -1;  // -1: killed by a signal or timed out
  bool timedOut = false;
  double seconds = 0;
  std::string out, err;

  void spawn() {
    start = std::chrono::steady_clock::now();
    pid = fork();
    if (pid == 0) {
      setpgid(0, 0);
      int o = open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      int e = open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      int n = open("/dev/null", O_RDONLY);
      if (o < 0 || e < 0 || n < 0) _exit(126);
      dup2(n, 0);
      dup2(o, 1);
      dup2(e, 2);
      std::vector<char*> args;
      for (auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      execvp(args[0], args.data());
      std::fprintf(stderr, "cannot run %s\n", args[0]);
      _exit(127);
    }
    if (pid > 0) setpgid(pid, pid);  // either side may win the race
  }
  // Returns true once the process has ended (or was killed for taking too long).
  bool poll() {
    if (done) return true;
    if (pid <= 0) {
      err = "fork failed";
      return done = true;
    }
    // Wait without reaping, so that the process group id stays ours while
    // what is left of the group (xvfb-run's Xvfb) is killed; then reap.
    siginfo_t info{};
    info.si_pid = 0;
    waitid(P_PID, id_t(pid), &info, WEXITED | WNOHANG | WNOWAIT);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (info.si_pid != pid) {
      if (seconds <= kHangSeconds) return false;
      timedOut = true;
    }
    kill(-pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!timedOut && WIFEXITED(status)) exitCode = WEXITSTATUS(status);
    out = readFile(outPath);
    err = readFile(errPath);
    return done = true;
  }
  bool done = false;
  std::string describe() const {
    std::ostringstream o;
    o << "$ " << commandLine(argv) << "\n  exit " << exitCode
      << (timedOut ? " (killed: no end after TS_WINDOW_HANG_SECONDS)" : "") << " after " << seconds
      << " s\n  stderr: " << (err.empty() ? "(empty)" : err) << "\n";
    return o.str();
  }
};

struct Diff {
  long pixels = 0;
  long anyDiff = 0;      // pixels whose largest RGB channel difference is > 0
  long overSmall = 0;    // ... is > kSmallDiff, at the same position
  long unexplained = 0;  // ... > kSmallDiff from every pixel of the other image's 3x3 neighbourhood
  int maxDiff = 0, maxAlphaDiff = 0;
  int worstX = -1, worstY = -1, unexplainedX = -1, unexplainedY = -1;
};
int channelDiff(ts::Rgba p, ts::Rgba q) {
  return std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)});
}
// Whether pixel (x, y) of `a` matches some pixel of `b` within one pixel.
bool nearMatch(const ts::Image& a, const ts::Image& b, int x, int y) {
  ts::Rgba p = a.at(x, y);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int u = x + dx, v = y + dy;
      if (u >= 0 && v >= 0 && u < b.width && v < b.height && channelDiff(p, b.at(u, v)) <= kSmallDiff) return true;
    }
  return false;
}
// Compares RGB (the window's back buffer alpha is not part of the picture).
// `picture`: the second image dimmed; yellow where pixels differ but a
// neighbour matches (a one-pixel shift), red where nothing near matches.
Diff compare(const ts::Image& a, const ts::Image& b, ts::Image* picture) {
  Diff d;
  d.pixels = long(a.width) * a.height;
  *picture = ts::Image(a.width, a.height);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      ts::Rgba p = a.at(x, y), q = b.at(x, y);
      int m = channelDiff(p, q);
      d.maxAlphaDiff = std::max(d.maxAlphaDiff, std::abs(p.a - q.a));
      uint8_t g = uint8_t((q.r + q.g + q.b) / 12);
      ts::Rgba show{g, g, g, 255};
      if (m > 0) ++d.anyDiff;
      if (m > kSmallDiff) {
        ++d.overSmall;
        show = {255, 220, 0, 255};
        if (!nearMatch(a, b, x, y) || !nearMatch(b, a, x, y)) {
          if (d.unexplained++ == 0) {
            d.unexplainedX = x;
            d.unexplainedY = y;
          }
          show = {255, 0, 0, 255};
        }
      }
      if (m > d.maxDiff) {
        d.maxDiff = m;
        d.worstX = x;
        d.worstY = y;
      }
      picture->set(x, y, show);
    }
  return d;
}

// Lines of the window's stdout that are state lines ("name=value ...").
std::vector<std::string> stateLines(const std::string& out, const ts::Options& o) {
  std::vector<std::string> r;
  if (o.items().empty()) return r;
  std::string head = o.items().front().name + "=";
  std::stringstream ss(out);
  std::string line;
  while (std::getline(ss, line))
    if (line.rfind(head, 0) == 0) r.push_back(line);
  return r;
}

// The measurement lines "name value meaning" (formatMeasurements): in the
// window's stdout the block after the last state line, in --png's stdout
// everything after the title line.
struct Number {
  std::string name;
  double value = 0;
};
std::vector<Number> measurements(const std::string& out, const ts::Options& o, bool window) {
  std::vector<std::string> lines;
  std::stringstream ss(out);
  std::string line;
  while (std::getline(ss, line)) lines.push_back(line);
  size_t from = 1;  // --png: after the title
  if (window && o.items().empty()) {
    from = 3;  // title, keys, the (empty) state line
  } else if (window) {
    std::string head = o.items().front().name + "=";
    from = lines.size();
    for (size_t i = 0; i < lines.size(); ++i)
      if (lines[i].rfind(head, 0) == 0) from = i + 1;
  }
  std::vector<Number> r;
  for (size_t i = from; i < lines.size(); ++i) {
    std::istringstream in(lines[i]);
    Number n;
    if (in >> n.name >> n.value) r.push_back(n);
  }
  return r;
}
bool isTiming(const std::string& name);
// The names of the computed measurements (timings left out: see isTiming).
std::string names(const std::vector<Number>& v) {
  std::string s;
  for (const auto& n : v)
    if (!isTiming(n.name)) s += n.name + " ";
  return s;
}

std::string keyLabel(char k) {
  if (std::isalnum(static_cast<unsigned char>(k))) return std::string(1, k);
  switch (k) {
    case '+': return "plus";
    case '-': return "minus";
    case ' ': return "space";
    case '[': return "lbracket";
    case ']': return "rbracket";
    case '<': return "less";
    case '>': return "greater";
    case ',': return "comma";
    case '.': return "period";
    case '=': return "equals";
    default: {
      char b[8];
      std::snprintf(b, sizeof b, "x%02x", unsigned(static_cast<unsigned char>(k)));
      return b;
    }
  }
}

// A fresh scene and its options (the state the program starts in).
struct Fresh {
  std::unique_ptr<ts::Scene> scene;
  ts::Options opts;
  explicit Fresh(const std::string& id) : scene(ts::makeScene(id)) {
    if (scene) scene->addOptions(opts);
  }
};

// "--name=value" for every option whose value differs from the default: the
// flags that reproduce the state with --png.  (Built from state() rather
// than stateFlags(): see state_flags_round_trip for why.)
std::vector<std::string> flagsFor(const std::string& id, const ts::Options& o) {
  Fresh d(id);
  std::vector<std::string> r;
  auto want = o.state(), def = d.opts.state();
  for (size_t i = 0; i < want.size(); ++i)
    if (i >= def.size() || want[i].second != def[i].second) r.push_back("--" + want[i].first + "=" + want[i].second);
  return r;
}

// One window run and one --png run of the same state, compared.
// Measurements that are clock readings (a live view's ms per frame and fps).
// A measurement timed, not computed (two runs never agree), by its name without the "[...]" of its variant:
// parallax_aniso's live_ms_per_frame and live_fps, texture_costs's cost_ms_per_frame[...] and cost_timed_ratio[...].
// A window may time what --png does not (texture_costs times its frames in a window only): the names compared
// between the two leave them out.
bool isTiming(const std::string& name) {
  const std::string base = name.substr(0, name.find('['));
  auto ends = [&](const std::string& s) {
    return base.size() >= s.size() && base.compare(base.size() - s.size(), s.size(), s) == 0;
  };
  return ends("_ms_per_frame") || ends("_fps") || ends("_timed_ratio");
}

// windowFlags: given to the window program too (the state it starts in).
void windowVsPng(const std::string& id, const std::string& testName, const std::string& keys,
                 const ts::Options& expected, const std::string& changed, bool windowFlags = false) {
  std::string dir = outDir() + "/" + id + "/" + testName;
  const char* backend = std::getenv("TS_WINDOW_PNG_BACKEND");  // osmesa | egl | auto (default)
  mkdirs(dir);
  std::string prog = binDir() + "/" + id;
  ASSERT_EQ(access(prog.c_str(), X_OK), 0) << "no program " << prog << " for the registered scene '" << id << "'";
  std::string W = dir + "/window.png", P = dir + "/png.png";
  std::remove(W.c_str());
  std::remove(P.c_str());
  std::string size = std::to_string(gWidth) + "x" + std::to_string(gHeight);
  // The side panel is open: the figure takes the window left of it.
  int figureW = ts::splitWindow(gWidth, true, false).figureW;
  std::string figureSize = std::to_string(figureW) + "x" + std::to_string(gHeight);

  Proc win, png;
  win.argv = {"xvfb-run", "-a", "-s", kXvfbScreen, prog, "--size", size, "--frames", std::to_string(kFrames)};
  if (!keys.empty()) win.argv.insert(win.argv.end(), {"--keys", keys});
  if (windowFlags)
    for (const auto& f : flagsFor(id, expected)) win.argv.push_back(f);
  win.argv.insert(win.argv.end(), {"--screenshot", W});
  win.outPath = dir + "/window.stdout";
  win.errPath = dir + "/window.stderr";
  png.argv = {prog, "--size", figureSize, "--png", P};
  if (backend && *backend) png.argv.insert(png.argv.end(), {"--backend", backend});
  for (const auto& f : flagsFor(id, expected)) png.argv.push_back(f);
  png.outPath = dir + "/png.stdout";
  png.errPath = dir + "/png.stderr";
  // The two runs are independent: run them side by side.
  win.spawn();
  png.spawn();
  while (!(win.poll() & png.poll())) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::ofstream(dir + "/commands.txt") << commandLine(win.argv) << "\n" << commandLine(png.argv) << "\n";

  ASSERT_EQ(win.exitCode, 0) << win.describe();
  ASSERT_EQ(png.exitCode, 0) << png.describe();

  // The state lines: the window prints stateText() on its first frame and
  // after every key that changed something.  The first key is taken on the
  // first frame, before that print, so with --keys K there is one line, the
  // state after K; without keys, one line, the initial state.
  Fresh initial(id);
  if (windowFlags) initial.opts.parse(flagsFor(id, expected));
  std::vector<std::string> lines = stateLines(win.out, expected);
  if (!expected.items().empty()) {
    ASSERT_FALSE(lines.empty()) << "the window printed no state line\n" << win.describe() << "stdout:\n" << win.out;
    EXPECT_EQ(lines.back(), expected.stateText()) << "the last state line the window printed (--keys '" << keys << "')";
    for (const auto& l : lines)
      EXPECT_TRUE(l == initial.opts.stateText() || l == expected.stateText()) << "unexpected state line: " << l;
    EXPECT_LE(lines.size(), keys.size() + 1) << "more state lines than changes";
    if (!changed.empty()) {
      EXPECT_NE((" " + lines.back() + " ").find(" " + changed + " "), std::string::npos)
          << "the state line after --keys " << keys << " lacks '" << changed << "': " << lines.back();
    }
  }

  ts::Image w, p;
  try {
    w = ts::readPng(W);
  } catch (const std::exception& e) {
    FAIL() << "no screenshot: " << e.what() << "\n" << win.describe();
  }
  try {
    p = ts::readPng(P);
  } catch (const std::exception& e) {
    FAIL() << "no --png render: " << e.what() << "\n" << png.describe();
  }
  ASSERT_EQ(p.width, figureW);
  ASSERT_EQ(p.height, gHeight);
  ASSERT_EQ(w.width, gWidth) << "the window's framebuffer is not the requested size (a window manager?)";
  ASSERT_EQ(w.height, p.height) << "the window's framebuffer is not the requested size (a window manager?)";
  ts::Image left(figureW, gHeight), picture;  // the figure's part of the window
  for (int y = 0; y < gHeight; ++y)
    for (int x = 0; x < figureW; ++x) left.set(x, y, w.at(x, y));
  Diff d = compare(left, p, &picture);
  double frac = double(d.overSmall) / double(d.pixels);
  std::printf("[ measured ] %s/%s: window %.2f s, png %.2f s; max channel diff %d at (%d,%d); %ld px differ at all, "
              "%ld px (%.4f%%) by more than %d, %ld with no match within one pixel; max alpha diff %d\n",
              id.c_str(), testName.c_str(), win.seconds, png.seconds, d.maxDiff, d.worstX, d.worstY, d.anyDiff,
              d.overSmall, 100.0 * frac, kSmallDiff, d.unexplained, d.maxAlphaDiff);
  if (d.anyDiff) ts::writePng(dir + "/diff.png", picture);
  std::string where = "\n  window " + W + "\n  png    " + P + "\n  diff   " + dir +
                      "/diff.png (yellow: differs, a neighbour matches; red: nothing within one pixel matches)";
  // The bounds of the backend --png used ("<title> | osmesa | ..." on stdout).
  bool egl = png.out.find(" | egl | ") != std::string::npos;
  Bounds bounds = egl ? kEglBounds : kOsmesaBounds;
  where += std::string("\n  bounds for --png backend ") + (egl ? "egl" : "osmesa");
  EXPECT_LE(frac, bounds.maxFraction) << d.overSmall << " of " << d.pixels << " pixels differ by more than "
                                      << kSmallDiff << where;
  EXPECT_LE(d.unexplained, bounds.maxUnexplained) << d.unexplained << " pixels differ by more than " << kSmallDiff
                                                  << " from every pixel within one pixel of them, first at ("
                                                  << d.unexplainedX << "," << d.unexplainedY << ")" << where;

  // The numbers the figure exists to show: the same in the window (printed
  // after its last state line) as in the --png render (after its title).
  std::vector<Number> wm = measurements(win.out, expected, true), pm = measurements(png.out, expected, false);
  EXPECT_EQ(names(wm), names(pm)) << "the window and --png print different measurements";
  for (size_t i = 0; i < std::min(wm.size(), pm.size()); ++i) {
    if (wm[i].name != pm[i].name) continue;
    if (isTiming(wm[i].name)) continue;  // timed, not computed: two runs never agree
    double tol = kMeasurementAbs + kMeasurementRel * std::abs(pm[i].value);
    EXPECT_NEAR(wm[i].value, pm[i].value, tol)
        << wm[i].name << ": the window measured " << wm[i].value << ", --png " << pm[i].value
        << " (the window's target is " << gWidth << "x" << gHeight << ")";
  }
}

// The GL pane (key l): the figure is laid out beside it, never under it.
// The window run's screenshot (the figure alone) must hold, left of the
// pane, the --png render of the state at the figure's width, and nothing
// right of it; the pane's stdout lines must name the calls the key changed
// (`mustChange`: a substring of one of them; "" = any).
void paneBesideFigure(const std::string& id, const std::string& keys, const ts::Options& expected,
                      const std::string& mustChange, const std::vector<std::string>& env = {}) {
  std::string dir = outDir() + "/" + id + "/gl_pane_" + keyLabel(keys.size() > 1 ? keys[1] : 'l');
  mkdirs(dir);
  std::string prog = binDir() + "/" + id, W = dir + "/window.png", P = dir + "/png.png";
  std::remove(W.c_str());
  std::remove(P.c_str());
  int figureW = ts::splitWindow(gWidth, true, true).figureW;  // side panel and GL pane open
  Proc win, png;
  win.argv = {"xvfb-run",
              "-a",
              "-s",
              kXvfbScreen,
              prog,
              "--size",
              std::to_string(gWidth) + "x" + std::to_string(gHeight),
              "--frames",
              std::to_string(kFrames),
              "--keys",
              keys,
              "--screenshot",
              W};
  if (!env.empty()) {
    win.argv.insert(win.argv.begin(), env.begin(), env.end());
    win.argv.insert(win.argv.begin(), "env");
  }
  win.outPath = dir + "/window.stdout";
  win.errPath = dir + "/window.stderr";
  png.argv = {prog, "--size", std::to_string(figureW) + "x" + std::to_string(gHeight), "--png", P};
  for (const auto& f : flagsFor(id, expected)) png.argv.push_back(f);
  png.outPath = dir + "/png.stdout";
  png.errPath = dir + "/png.stderr";
  win.spawn();
  png.spawn();
  while (!(win.poll() & png.poll())) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_EQ(win.exitCode, 0) << win.describe();
  ASSERT_EQ(png.exitCode, 0) << png.describe();
  ASSERT_NE(win.out.find("gl pane: "), std::string::npos) << "the pane recorded nothing\n" << win.out;
  if (!mustChange.empty()) {
    bool found = false;
    std::istringstream lines(win.out);
    for (std::string l; std::getline(lines, l);)
      found |= l.rfind("gl pane: changed: ", 0) == 0 && l.find(mustChange) != std::string::npos;
    EXPECT_TRUE(found) << "after --keys " << keys << " no changed line holds '" << mustChange << "'\n" << win.out;
  }
  ts::Image w = ts::readPng(W), p = ts::readPng(P);
  ASSERT_EQ(w.width, gWidth);
  ASSERT_EQ(p.width, figureW);
  ts::Image left(figureW, gHeight), picture;
  for (int y = 0; y < gHeight; ++y)
    for (int x = 0; x < figureW; ++x) left.set(x, y, w.at(x, y));
  Diff d = compare(left, p, &picture);
  double frac = double(d.overSmall) / double(d.pixels);
  bool egl = png.out.find(" | egl | ") != std::string::npos;
  Bounds bounds = egl ? kEglBounds : kOsmesaBounds;
  EXPECT_LE(frac, bounds.maxFraction) << "left of the pane the window is not the --png render at " << figureW << "x"
                                      << gHeight << "\n  " << W << "\n  " << P;
  EXPECT_LE(d.unexplained, bounds.maxUnexplained) << W << " vs " << P;
  // Right of the figure (under the pane) nothing of the figure is drawn:
  // one colour, the clear colour.
  ts::Rgba clear = w.at(gWidth - 1, gHeight - 1);
  long other = 0;
  for (int y = 0; y < gHeight; ++y)
    for (int x = figureW; x < gWidth; ++x) other += channelDiff(w.at(x, y), clear) > kSmallDiff;
  EXPECT_EQ(other, 0) << "the figure reaches under the pane (x >= " << figureW << ") in " << W;
}

// A window run with --keys in `dir` (its working folder); returns when done.
// `mouse`: TS_TEST_MOUSE, events fed to the window's mouse handlers.
Proc windowRun(const std::string& id, const std::string& dir, const std::string& keys, bool overlayShot = false,
               const std::string& mouse = "") {
  mkdirs(dir);
  Proc win;
  win.argv = {"env",
              std::string("TS_SCREENSHOT_OVERLAY=") + (overlayShot ? "1" : "0"),
              "TS_TEST_MOUSE=" + mouse,
              "xvfb-run",
              "-a",
              "-s",
              kXvfbScreen,
              binDir() + "/" + id,
              "--size",
              std::to_string(gWidth) + "x" + std::to_string(gHeight),
              "--frames",
              std::to_string(kFrames),
              "--keys",
              keys,
              "--screenshot",
              dir + "/window.png"};
  // Relative to the run's folder: F12 writes there.
  if (win.argv[7][0] != '/') {
    char cwd[4096];
    if (getcwd(cwd, sizeof cwd)) win.argv[7] = std::string(cwd) + "/" + win.argv[7];
  }
  win.outPath = dir + "/window.stdout";
  win.errPath = dir + "/window.stderr";
  std::string here = dir;
  win.argv.insert(win.argv.begin(), {"bash", "-c", "cd \"$0\" && exec \"$@\"", here});
  win.spawn();
  while (!win.poll()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return win;
}

// The usual window keys: Backspace resets every option, = is +, the arrows
// turn and tilt, ? shows the help card, F12 saves the state and prints the
// command that remakes it (which must give the same picture).
// Runs a `build/bin/<id> ...` command as F12 printed it, with this build's
// program, in `dir`, adding --png remade.png (and its sidecar): true when it
// exited 0 (a test failure naming the run otherwise).
bool runPrintedCommand(const std::string& id, const std::string& command, const std::string& dir) {
  Proc remake;
  remake.argv = {"bash", "-c",
                 "cd \"$0\" && exec \"$1\"/" + id + command.substr(10 + id.size()) +
                     " --png remade.png --json remade.json --quiet",
                 dir, binDir()};
  remake.outPath = dir + "/remake.stdout";
  remake.errPath = dir + "/remake.stderr";
  remake.spawn();
  while (!remake.poll()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(remake.exitCode, 0) << remake.describe();
  return remake.exitCode == 0;
}

// The first key of the first option that has one ("" if none).
std::string firstKey(const ts::Options& o) {
  for (const auto& it : o.items())
    if (it.key) return std::string(1, it.key);
  return "";
}

// Backspace, = and the right arrow (the full level).
void resetEqualsArrow(const std::string& id) {
  Fresh initial(id);
  std::string base = outDir() + "/" + id + "/usual_keys";
  // Backspace after a change: the state line is the defaults again.
  std::string change = firstKey(initial.opts);
  ASSERT_FALSE(change.empty());
  Proc reset = windowRun(id, base + "/reset", change + std::string(1, ts::keys::kReset));
  ASSERT_EQ(reset.exitCode, 0) << reset.describe();
  std::vector<std::string> lines = stateLines(reset.out, initial.opts);
  ASSERT_FALSE(lines.empty()) << reset.out;
  EXPECT_EQ(lines.back(), initial.opts.stateText()) << "Backspace did not reset the options";
  // = acts as + where + is a key and = is not.
  bool plus = false, equals = false;
  for (const auto& it : initial.opts.items()) {
    plus |= it.key == '+' || it.keyDown == '+';
    equals |= it.key == '=' || it.keyDown == '=';
  }
  if (plus && !equals) {
    Fresh f(id);
    f.opts.handleKey('+');
    Proc eq = windowRun(id, base + "/equals", "=");
    ASSERT_EQ(eq.exitCode, 0) << eq.describe();
    lines = stateLines(eq.out, f.opts);
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines.back(), f.opts.stateText()) << "= did not act as +";
  }
  // Right arrow = the up key of the turn option (if the demo has one).
  char right = initial.opts.keyOf({"turn", "rotation", "azimuth"}, true);
  if (right) {
    Fresh f(id);
    f.opts.handleKey(right);
    Proc arrow = windowRun(id, base + "/arrow", std::string(1, ts::keys::kRight));
    ASSERT_EQ(arrow.exitCode, 0) << arrow.describe();
    lines = stateLines(arrow.out, f.opts);
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines.back(), f.opts.stateText()) << "the right arrow did not turn";
  }
}

// The smoke level's second case: a key, then F12 saves the state and prints
// the command that remakes it (which must give the same picture); the same
// key, then ? shows the help card: the window as seen changes, the state
// does not.  Two window runs, with the window as the student sees it.
void helpAndSave(const std::string& id) {
  Fresh initial(id);
  std::string base = outDir() + "/" + id + "/help_and_save";
  std::string change = firstKey(initial.opts);
  ASSERT_FALSE(change.empty());
  Fresh changed(id);
  changed.opts.handleKey(change[0]);
  // F12: PNG + sidecar under a new name, and a command that remakes them.
  std::string dir = base + "/save";
  std::remove((dir + "/" + id + "-1.png").c_str());
  std::remove((dir + "/" + id + "-1.json").c_str());
  Proc save = windowRun(id, dir, change + std::string(1, ts::keys::kSave), true);
  Proc help = windowRun(id, base + "/help", change + "?", true);
  ASSERT_EQ(save.exitCode, 0) << save.describe();
  ASSERT_EQ(help.exitCode, 0) << help.describe();
  std::vector<std::string> lines = stateLines(help.out, initial.opts);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.back(), changed.opts.stateText()) << "? changed the state";
  ts::Image scratch;
  Diff d = compare(ts::readPng(dir + "/window.png"), ts::readPng(base + "/help/window.png"), &scratch);
  EXPECT_GT(d.overSmall, long(gWidth) * gHeight / 20) << "the help card is not on screen";
  size_t at = save.out.find("remake them with:\n  ");
  ASSERT_NE(at, std::string::npos) << save.out;
  std::string command = save.out.substr(at + 20, save.out.find('\n', at + 20) - at - 20);
  ASSERT_EQ(command.rfind("build/bin/" + id + " --png " + id + "-1.png", 0), 0u) << command;
  ts::Image saved = ts::readPng(dir + "/" + id + "-1.png");
  ASSERT_EQ(access((dir + "/" + id + "-1.json").c_str(), R_OK), 0) << "no sidecar";
  // The command, run as printed (its program from this build), remakes the picture.
  ASSERT_TRUE(runPrintedCommand(id, command, dir));
  Diff r = compare(saved, ts::readPng(dir + "/remade.png"), &scratch);
  EXPECT_LE(double(r.overSmall) / double(r.pixels), kOsmesaBounds.maxFraction) << "F12's command does not remake it";
}

// A right drag moves the light (demos with --light1-az/--light1-el:
// bump_mapping): 100 px right, 50 px up at 0.4 degree a pixel turns the
// azimuth by +40 and raises the elevation by 20; the picture changes.
void mouseLight(const std::string& id) {
  Fresh initial(id);
  std::string base = outDir() + "/" + id + "/mouse_light";
  Proc plain = windowRun(id, base + "/plain", "");
  Proc moved = windowRun(id, base + "/drag", "", false, "rpress 400 240; move 450 215; move 500 190; release");
  ASSERT_EQ(plain.exitCode, 0) << plain.describe();
  ASSERT_EQ(moved.exitCode, 0) << moved.describe();
  std::vector<std::string> lines = stateLines(moved.out, initial.opts);
  ASSERT_FALSE(lines.empty()) << moved.out;
  Fresh want(id);
  double az = 0, el = 0;
  for (const auto& [n, v] : initial.opts.state()) {
    if (n == "light1-az") az = std::stod(v);
    if (n == "light1-el") el = std::stod(v);
  }
  want.opts.set("light1-az", ts::layout::fmt("%g", std::remainder(az + 40.0, 360.0)));
  want.opts.set("light1-el", ts::layout::fmt("%g", el + 20.0));
  EXPECT_EQ(lines.back(), want.opts.stateText()) << "the right drag did not move the light";
  ts::Image scratch;
  Diff d = compare(ts::readPng(base + "/plain/window.png"), ts::readPng(base + "/drag/window.png"), &scratch);
  EXPECT_GT(d.overSmall, long(gWidth) * gHeight / 100) << "moving the light did not change the picture";
}

// The mouse: a left drag and the wheel, fed through the
// window's own mouse handlers (TS_TEST_MOUSE), turn --yaw/--pitch/--zoom;
// the picture changes; F12's printed command (the state's flags) remakes the
// same picture with --png.  In a demo without those options a drag changes
// nothing.
void mouseOrbit(const std::string& id) {
  Fresh initial(id);
  std::string base = outDir() + "/" + id + "/mouse";
  const std::string drag = "press 400 240; move 430 250; move 500 270; release; wheel 2";
  bool orbit = initial.opts.has("yaw") && initial.opts.has("pitch") && initial.opts.has("zoom");
  std::string dir = base + "/drag";
  for (const char* ext : {".png", ".json"})
    for (int n = 1; n <= 3; ++n) std::remove((dir + "/" + id + "-" + std::to_string(n) + ext).c_str());
  // mipmap_popping's orbit turns its slanted plane: v three times shows it.
  const std::string view = id == "mipmap_popping" ? "vvv" : "";
  Proc plain = windowRun(id, base + "/plain", view);
  Proc moved = windowRun(id, dir, view + std::string(1, ts::keys::kSave), false, drag);
  ASSERT_EQ(plain.exitCode, 0) << plain.describe();
  ASSERT_EQ(moved.exitCode, 0) << moved.describe();
  EXPECT_EQ(moved.err.find("TS_TEST_MOUSE"), std::string::npos) << moved.err;
  std::vector<std::string> lines = stateLines(moved.out, initial.opts);
  ASSERT_FALSE(lines.empty()) << moved.out;
  ts::Image scratch;
  Diff d = compare(ts::readPng(base + "/plain/window.png"), ts::readPng(dir + "/window.png"), &scratch);
  if (!orbit) {
    EXPECT_EQ(lines.back(), initial.opts.stateText()) << "a drag moved a demo without --yaw/--pitch/--zoom";
    EXPECT_EQ(d.overSmall, 0) << "a drag changed the picture of a demo without an orbit";
    return;
  }
  // 100 px right, 30 px down at 0.4 degree a pixel; two wheel clicks: 1.1^2.
  Fresh want(id);
  for (char k : view) want.opts.handleKey(k);
  want.opts.set("yaw", "40");
  want.opts.set("pitch", "12");
  want.opts.set("zoom", "1.21");
  EXPECT_EQ(lines.back(), want.opts.stateText()) << "the drag and the wheel did not turn the orbit";
  // More than 1% of the window: the orbit turns a 3D panel, which in a
  // figure of tables and captions (octant_mapping) is a fifth of it or less.
  EXPECT_GT(d.overSmall, long(gWidth) * gHeight / 100) << "the drag did not change the picture";
  // F12's command remakes the dragged picture.
  size_t at = moved.out.find("remake them with:\n  ");
  ASSERT_NE(at, std::string::npos) << moved.out;
  std::string command = moved.out.substr(at + 20, moved.out.find('\n', at + 20) - at - 20);
  EXPECT_NE(command.find("--yaw=40 --pitch=12 --zoom=1.21"), std::string::npos) << command;
  ASSERT_TRUE(runPrintedCommand(id, command, dir));
  Diff r = compare(ts::readPng(dir + "/" + id + "-1.png"), ts::readPng(dir + "/remade.png"), &scratch);
  EXPECT_LE(double(r.overSmall) / double(r.pixels), kOsmesaBounds.maxFraction) << "the printed flags do not remake it";
}

// A picture file dropped on the window is --texture FILE; a bad one is one
// line on stderr and the window goes on (exit 0).
void dropFile(const std::string& id) {
  std::string dir = outDir() + "/" + id + "/drop";
  mkdirs(dir);
  char cwd[4096];
  std::string here = getcwd(cwd, sizeof cwd) ? cwd : ".";
  std::string good = here + "/tests/reliability/corpus/good_jpeg_blocks_32x24.jpg";
  std::string bad = here + "/tests/reliability/corpus/jpeg_cut_in_half.jpg";
  Proc run = windowRun(id, dir, "", false, "drop " + bad + "; drop " + good);
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  // Exactly one line names the bad file, and says what is wrong with it
  // (some demos print notes of their own on stderr too).
  int naming = 0;
  std::istringstream errLines(run.err);
  for (std::string l; std::getline(errLines, l);)
    if (l.find(bad) != std::string::npos) {
      ++naming;
      EXPECT_NE(l.find("malformed JPEG"), std::string::npos) << l;
    }
  EXPECT_EQ(naming, 1) << run.err;
  Fresh want(id);
  want.opts.set("texture", good);
  std::vector<std::string> lines = stateLines(run.out, want.opts);
  ASSERT_FALSE(lines.empty()) << run.out;
  EXPECT_EQ(lines.back(), want.opts.stateText()) << "the dropped file is not the texture";
}

// A resize sequence: the window opened at the tests' size is
// resized to a small landscape, a portrait and a laptop's size in turn
// (TS_TEST_RESIZE); at each size the figure left of the side panel must be
// the --png render at the figure's size then (so the layout and the numbers
// follow the window), and nothing of the figure is drawn under the panel.
void resizeSequence(const std::string& id) {
  const std::vector<std::pair<int, int>> sizes = {{gWidth, gHeight}, {640, 480}, {700, 1000}, {1280, 720}};
  std::string dir = outDir() + "/" + id + "/resize";
  mkdirs(dir);
  std::string prog = binDir() + "/" + id, W = dir + "/window.png";
  std::string seq;
  for (size_t i = 1; i < sizes.size(); ++i)
    seq += std::to_string(sizes[i].first) + "x" + std::to_string(sizes[i].second) + " ";
  Proc win;
  win.argv = {"env",
              "TS_TEST_RESIZE=" + seq,
              "xvfb-run",
              "-a",
              "-s",
              kXvfbScreen,
              prog,
              "--size",
              std::to_string(gWidth) + "x" + std::to_string(gHeight),
              "--frames",
              std::to_string(kFrames),
              "--screenshot",
              W};
  win.outPath = dir + "/window.stdout";
  win.errPath = dir + "/window.stderr";
  win.spawn();
  // The --png renders of each size run beside the window.
  std::vector<Proc> pngs(sizes.size());
  for (size_t i = 0; i < sizes.size(); ++i) {
    int figureW = ts::splitWindow(sizes[i].first, true, false).figureW;
    std::string tag = std::to_string(sizes[i].first) + "x" + std::to_string(sizes[i].second);
    pngs[i].argv = {prog, "--size", std::to_string(figureW) + "x" + std::to_string(sizes[i].second), "--png",
                    dir + "/png." + tag + ".png"};
    pngs[i].outPath = dir + "/png." + tag + ".stdout";
    pngs[i].errPath = dir + "/png." + tag + ".stderr";
  }
  for (auto& p : pngs) {
    p.spawn();
    while (!p.poll()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  while (!win.poll()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_EQ(win.exitCode, 0) << win.describe();
  for (size_t i = 0; i < sizes.size(); ++i) {
    const auto [ww, wh] = sizes[i];
    std::string tag = std::to_string(ww) + "x" + std::to_string(wh);
    ASSERT_EQ(pngs[i].exitCode, 0) << pngs[i].describe();
    ts::Image w, p, picture;
    try {
      w = ts::readPng(dir + "/window." + tag + ".png");
      p = ts::readPng(dir + "/png." + tag + ".png");
    } catch (const std::exception& e) {
      FAIL() << "at " << tag << ": " << e.what() << "\n" << win.describe();
    }
    ASSERT_EQ(w.width, ww) << "the window was not resized to " << tag << " (a window manager?)";
    ASSERT_EQ(w.height, wh) << "the window was not resized to " << tag;
    int figureW = p.width;
    ts::Image left(figureW, wh);
    for (int y = 0; y < wh; ++y)
      for (int x = 0; x < figureW; ++x) left.set(x, y, w.at(x, y));
    Diff d = compare(left, p, &picture);
    if (d.anyDiff) ts::writePng(dir + "/diff." + tag + ".png", picture);
    bool egl = pngs[i].out.find(" | egl | ") != std::string::npos;
    Bounds bounds = egl ? kEglBounds : kOsmesaBounds;
    std::printf(
        "[ measured ] %s/resize %s: %ld px (%.4f%%) differ by more than %d, %ld with no match within one pixel\n",
        id.c_str(), tag.c_str(), d.overSmall, 100.0 * double(d.overSmall) / double(d.pixels), kSmallDiff,
        d.unexplained);
    EXPECT_LE(double(d.overSmall) / double(d.pixels), bounds.maxFraction)
        << "after resizing to " << tag << " the figure is not the --png render at " << figureW << "x" << wh << " ("
        << dir << ")";
    EXPECT_LE(d.unexplained, bounds.maxUnexplained) << "at " << tag << " (" << dir << ")";
    ts::Rgba clear = w.at(ww - 1, wh - 1);
    long other = 0;
    for (int y = 0; y < wh; ++y)
      for (int x = figureW; x < ww; ++x) other += channelDiff(w.at(x, y), clear) > kSmallDiff;
    EXPECT_EQ(other, 0) << "at " << tag << " the figure reaches under the side panel (x >= " << figureW << ")";
  }
  // The numbers printed last (measured again at the last size) are --png's at that size.
  Fresh f(id);
  std::vector<Number> wm = measurements(win.out, f.opts, true), pm = measurements(pngs.back().out, f.opts, false);
  EXPECT_EQ(names(wm), names(pm)) << "after the resizes the window and --png print different measurements";
  for (size_t i = 0; i < std::min(wm.size(), pm.size()); ++i)
    if (wm[i].name == pm[i].name && !isTiming(wm[i].name)) {
      EXPECT_NEAR(wm[i].value, pm[i].value, kMeasurementAbs + kMeasurementRel * std::abs(pm[i].value))
          << wm[i].name << " after the resizes: the window measured " << wm[i].value << ", --png " << pm[i].value;
    }
}

// parse(stateFlags()) on a fresh Options must give back the state.
void roundTrip(const std::string& id, const ts::Options& state, const std::string& what) {
  Fresh f(id);
  std::vector<std::string> flags = state.stateFlags();
  try {
    f.opts.parse(flags);
  } catch (const ts::Error& e) {
    ADD_FAILURE() << what << ": stateFlags() " << commandLine(flags) << " are rejected by parse(): " << e.what();
    return;
  }
  EXPECT_EQ(f.opts.stateText(), state.stateText()) << what << ": stateFlags() " << commandLine(flags);
}

// --- never frozen -----------------------------------------------------------
// The window's test hooks (common/core/test_hooks.hpp): TS_TEST_SLOW_MEASURE_MS
// and _FRAMES make every measurement of the worker last at least that long
// and that many window frames (in 10 ms steps that report progress and stop
// when superseded), TS_TEST_KEY_WHEN=measuring types each --keys key after the
// first while a measurement runs (=measured: once it is in),
// TS_TEST_FRAME_LOG lists frames, keys and results in order, with
// steady-clock times.  Every check below is on the order of events, never on
// how long they took.
struct LogEvent {
  std::string what;  // frame | key | result
  double t = 0;
  int measuring = 0;
  double progress = 0;
  std::string key;
};
std::vector<LogEvent> readFrameLog(const std::string& path) {
  std::vector<LogEvent> r;
  std::istringstream in(readFile(path));
  for (std::string line; std::getline(in, line);) {
    std::istringstream l(line);
    LogEvent e;
    l >> e.what >> e.t;
    if (e.what == "frame") l >> e.measuring >> e.progress;
    if (e.what == "key") l >> e.key;
    r.push_back(e);
  }
  return r;
}
// The first two keys of a scene that change its state.
std::string twoKeys(const std::string& id) {
  Fresh f(id);
  std::string k;
  for (const auto& it : f.opts.items())
    if (it.key && k.size() < 2 && it.key != 'v') k += it.key;
  return k;
}
Proc hookedRun(const std::string& id, const std::string& dir, const std::vector<std::string>& env,
               const std::vector<std::string>& args) {
  mkdirs(dir);
  Proc win;
  win.argv = {"env", "TS_TEST_FRAME_LOG=" + dir + "/frames.log"};
  for (const auto& e : env) win.argv.push_back(e);
  for (const std::string& a :
       {std::string("xvfb-run"), std::string("-a"), std::string("-s"), std::string(kXvfbScreen), binDir() + "/" + id,
        std::string("--size"), std::to_string(gWidth) + "x" + std::to_string(gHeight)})
    win.argv.push_back(a);
  for (const auto& a : args) win.argv.push_back(a);
  win.outPath = dir + "/window.stdout";
  win.errPath = dir + "/window.stderr";
  std::remove((dir + "/frames.log").c_str());
  win.spawn();
  while (!win.poll()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return win;
}

// Two keys, the second typed while the first one's measurement (slowed to
// at least 2.5 s and 10 window frames) runs: the first picture comes before
// the first measurement ends, frames keep coming (with the progress) while it
// runs, the second key supersedes the first one's measurement (only the last
// state's result is shown and printed), and --frames' last frame waits for
// it.  A window that stopped drawing while measuring would never get its
// result (the slowed measurement waits for 10 frames): the run would hang.
void framesKeepComing(const std::string& id) {
  const double slow = 2.5;
  const int slowFrames = 10;
  std::string dir = outDir() + "/" + id + "/never_frozen", keys = twoKeys(id);
  ASSERT_EQ(keys.size(), 2u);
  Proc win = hookedRun(id, dir,
                       {"TS_TEST_SLOW_MEASURE_MS=2500", "TS_TEST_SLOW_MEASURE_FRAMES=" + std::to_string(slowFrames),
                        "TS_TEST_KEY_WHEN=measuring"},
                       {"--frames", "3", "--keys", keys});
  ASSERT_EQ(win.exitCode, 0) << win.describe();
  std::vector<LogEvent> log = readFrameLog(dir + "/frames.log");
  double firstFrame = -1, firstResult = -1, lastKey = -1, maxGap = 0;
  int results = 0, keysTaken = 0, measuringFrames = 0, framesBeforeSecondKey = 0;
  bool midProgress = false;
  double prevFrame = -1;
  for (const auto& e : log) {
    if (e.what == "frame") {
      if (firstFrame < 0) firstFrame = e.t;
      if (e.measuring) {
        ++measuringFrames;
        midProgress |= e.progress > 0.0 && e.progress < 1.0;
        if (prevFrame >= 0) maxGap = std::max(maxGap, e.t - prevFrame);
        if (keysTaken == 1) ++framesBeforeSecondKey;
      }
      prevFrame = e.t;
    } else if (e.what == "result") {
      if (firstResult < 0) firstResult = e.t;
      ++results;
    } else if (e.what == "key") {
      ++keysTaken;
      lastKey = e.t;
    }
  }
  // Timings are printed for the reader, not checked (bench_window times them).
  std::printf("[ measured ] %s/never_frozen: first frame %.2f s before the first result; %d frames while measuring, "
              "longest interval %.3f s (not checked: bench_window times it)\n",
              id.c_str(), firstResult - firstFrame, measuringFrames, maxGap);
  ASSERT_GE(firstFrame, 0) << "no frame logged\n" << win.describe();
  ASSERT_GE(firstResult, 0) << "no measurement handed over\n" << win.describe();
  EXPECT_LT(firstFrame, firstResult) << "the first picture waited for the measurement";
  EXPECT_EQ(keysTaken, 2);
  EXPECT_GE(framesBeforeSecondKey, 1) << "the second key was not typed while the first one's measurement ran";
  EXPECT_EQ(results, 1) << "the first key's measurement was not superseded by the second key";
  // The slowed measurement lasts at least 2.5 s after the key that asked for it.
  EXPECT_GE(firstResult - lastKey, slow - 0.05) << "the result came before the last key's slowed measurement could end";
  EXPECT_GE(measuringFrames, slowFrames) << "the window did not keep drawing while measuring";
  EXPECT_TRUE(midProgress) << "no frame showed the measurement's progress";
  Fresh f(id);
  for (char k : keys) f.opts.handleKey(k);
  std::vector<std::string> lines = stateLines(win.out, f.opts);
  ASSERT_EQ(lines.size(), 1u) << win.out;
  EXPECT_EQ(lines.back(), f.opts.stateText());
}

// A key, then q while its measurement (slowed to 10 minutes) runs: the window
// closes at once and the process ends (the measurement stops at its next
// progress report), exit status 0, nothing on stderr about leaks.  Had
// closing waited for the measurement, the run would outlast the hang guard
// (kHangSeconds) and be killed: a failure, whatever the machine's load.
void closeDuringMeasurement(const std::string& id) {
  std::string dir = outDir() + "/" + id + "/close_while_measuring", keys = twoKeys(id).substr(0, 1) + "q";
  Proc win = hookedRun(id, dir, {"TS_TEST_SLOW_MEASURE_MS=600000", "TS_TEST_KEY_WHEN=measuring"}, {"--keys", keys});
  ASSERT_FALSE(win.timedOut) << "closing waited for the measurement\n" << win.describe();
  ASSERT_EQ(win.exitCode, 0) << win.describe();
  std::vector<LogEvent> log = readFrameLog(dir + "/frames.log");
  int quitAt = -1, framesAfterQuit = 0, measuringBeforeQuit = 0;
  for (size_t i = 0; i < log.size(); ++i) {
    const auto& e = log[i];
    if (e.what == "key" && e.key == "q") quitAt = int(i);
    if (e.what == "frame" && quitAt >= 0) ++framesAfterQuit;
    if (e.what == "frame" && quitAt < 0 && e.measuring) ++measuringBeforeQuit;
    EXPECT_NE(e.what, "result") << "a 10-minute measurement ended in a run that should have lasted seconds";
  }
  ASSERT_GE(quitAt, 0) << win.describe();
  std::printf("[ measured ] %s/close_while_measuring: run %.2f s (measurement slowed to 10 min)\n", id.c_str(),
              win.seconds);
  EXPECT_GE(measuringBeforeQuit, 1) << "q was not typed while the measurement ran";
  // The frame in which q is taken is finished; none follows it.
  EXPECT_LE(framesAfterQuit, 1) << "frames after q";
  EXPECT_EQ(win.err.find("LeakSanitizer"), std::string::npos) << win.err;
}

// --- the GL pane's marks under real X key events -----------------------------
// The demo is started as a student starts it (no --keys, its own size) under
// an Xvfb of its own; xdotool types real X key events into its window and
// ImageMagick's import reads the screen back, in which the pane's marked
// (yellow) pixels are counted.  Only the frame log (TS_TEST_FRAME_LOG, which
// changes nothing) is added, to know when a frame has been drawn.  Every
// wait is on an event (a file written, a line printed, a frame logged, a
// tool done) or on the time after the key that the check is about; the hang
// guard (kHangSeconds) ends a wait that never ends.  Times are seconds of
// the steady clock, the frame log's clock.
const char* const kMarksScreen = "-screen 0 1280x720x24";
constexpr double kMarksLookAfter = 2.0;  // the marks are read this long after the key ...
// ... by a capture finished before this (the marks last kHighlightSeconds
// from their first recording, which follows the key); a later capture says
// nothing either way, and the key is pressed again.
constexpr double kMarksVoidAfter = 3.9;
// The marks must be gone in a frame drawn this long after the key, and
// kHighlightSeconds + 0.5 s after the key's re-record was printed.
constexpr double kMarksGoneAfter = 6.0;
constexpr int kMarkTries = 3;
// The marked colour, ImVec4(1, 0.85, 0.2) = (255, 217, 51): ImGui's default
// font is drawn without antialiasing here, so the marked pixels are exactly
// that (measured: 1512 px of #FFD933 and nothing near it for two marked
// lines of quad_distortion's filter key).  One marked line gives hundreds.
bool markYellow(ts::Rgba p) { return p.r >= 230 && p.g >= 190 && p.g <= 240 && p.b <= 90; }
constexpr long kMarkedMin = 100;   // a capture with the marks shows more than this in the pane
constexpr long kMarkedSlack = 10;  // before the key and after the marks: the baseline (0), give or take this

double steadyNow() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
void sleepUntil(double t) {
  double left = t - steadyNow();
  if (left > 0) std::this_thread::sleep_for(std::chrono::duration<double>(left));
}

// xdotool's name of the key that types `k` ("" if none here).
std::string xKeyName(char k) {
  if (std::isalnum(static_cast<unsigned char>(k))) return std::string(1, k);
  switch (k) {
    case '+': return "plus";
    case '-': return "minus";
    case '[': return "bracketleft";
    case ']': return "bracketright";
    case '{': return "braceleft";
    case '}': return "braceright";
    case '<': return "less";
    case '>': return "greater";
    case ',': return "comma";
    case '.': return "period";
    case '=': return "equal";
    case ' ': return "space";
    default: return "";
  }
}

// What the window printed after its last state line: how many state lines,
// the last one, and the first GL pane recording after it (K and its lines).
struct PaneReport {
  size_t states = 0;
  std::string lastState;
  int changed = -1;  // K of "gl pane: N lines, K changed by the last key" (-1: no recording yet)
  std::vector<std::string> lines;
  bool recorded = false;  // some "gl pane:" line at all
};
PaneReport paneReport(const std::string& printed, const ts::Options& o) {
  PaneReport r;
  const std::string out = printed.substr(0, printed.rfind('\n') + 1);  // whole lines only
  const std::string head = o.items().empty() ? "\x01" : o.items().front().name + "=";
  const std::string changedTag = "gl pane: changed: ";
  std::istringstream in(out);
  for (std::string l; std::getline(in, l);) {
    int k = -1;
    if (l.rfind(head, 0) == 0) {
      ++r.states;
      r.lastState = l;
      r.changed = -1;
      r.lines.clear();
    } else if (l.rfind(changedTag, 0) == 0) {
      r.recorded = true;
      if (r.changed < 0) r.lines.push_back(l.substr(changedTag.size()));
    } else if (std::sscanf(l.c_str(), "gl pane: %*u lines, %d changed by the last key", &k) == 1) {
      r.recorded = true;
      if (r.changed < 0) r.changed = k;
    }
  }
  return r;
}

// One key pressed in the window, and what the pane showed after it.
struct MarkLook {
  char key = 0;
  int changed = -1;                          // K of the recording after the key's measurement
  std::vector<std::string> lines;            // its changed lines (the first 24)
  long before = -1, marked = -1, gone = -1;  // marked pixels in the pane: just before the key, at 2 s, after 6 s
  double lookDone = 0, goneDone = 0;         // when those two captures finished, seconds after the key
  bool voided = false;                       // the capture at 2 s finished after kMarksVoidAfter
};

// A demo under its own Xvfb, driven by xdotool.
class XDemo {
 public:
  // `screen`: xvfb-run's -s; `args`: the demo's own arguments (none: as a
  // student starts it).  The demo runs in `dir` (F12 writes there).
  XDemo(const std::string& id, const std::string& dir, const char* screen = kMarksScreen,
        std::vector<std::string> args = {})
      : id_(id), dir_(absolute(dir)), screen_(screen), args_(std::move(args)), state_(id) {}
  ~XDemo() {
    if (demo_.pid > 0 && !demo_.done) {  // a failed case: its Xvfb and demo go
      kill(-demo_.pid, SIGKILL);
      demo_.poll();
    }
  }
  XDemo(const XDemo&) = delete;
  XDemo& operator=(const XDemo&) = delete;
  const std::string& why() const { return why_; }

  // Starts the demo, finds its window once it is mapped, waits for its
  // first measurement and moves the pointer over the figure.
  bool start() {
    mkdirs(dir_);
    std::string envFile = dir_ + "/x.env";
    logPath_ = dir_ + "/frames.log";
    std::remove(envFile.c_str());
    std::remove(logPath_.c_str());
    // The shell xvfb-run starts writes the server's DISPLAY and XAUTHORITY
    // (for xdotool and import) and its pid, then becomes the demo.
    demo_.argv = {
        "bash",
        "-c",
        "cd \"$0\" && exec \"$@\"",
        dir_,
        "xvfb-run",
        "-a",
        "-s",
        screen_,
        "sh",
        "-c",
        "printf '%s\\n%s\\n%s\\n' \"$DISPLAY\" \"$XAUTHORITY\" \"$$\" > \"$0.part\" && mv \"$0.part\" \"$0\" && "
        "exec \"$@\"",
        envFile,
        "env",
        "TS_TEST_FRAME_LOG=" + logPath_,
        absolute(binDir()) + "/" + id_};
    demo_.argv.insert(demo_.argv.end(), args_.begin(), args_.end());
    demo_.outPath = dir_ + "/window.stdout";
    demo_.errPath = dir_ + "/window.stderr";
    std::ofstream(dir_ + "/commands.txt") << commandLine(demo_.argv) << "\n";
    demo_.spawn();
    std::string pid;
    if (!waitFor(
            [&] {
              std::istringstream in(readFile(envFile));
              return std::getline(in, display_) && std::getline(in, xauth_) && std::getline(in, pid);
            },
            "the X server (" + envFile + ")"))
      return false;
    std::string found, geometry;
    if (!x({"xdotool", "search", "--sync", "--onlyvisible", "--pid", pid}, &found)) return false;
    window_ = found.substr(0, found.find('\n'));
    if (!x({"xdotool", "getwindowgeometry", window_}, &geometry)) return false;
    size_t at = geometry.find("Position: "), size = geometry.find("Geometry: ");
    if (at == std::string::npos || size == std::string::npos ||
        std::sscanf(geometry.c_str() + at, "Position: %d,%d", &winX_, &winY_) != 2 ||
        std::sscanf(geometry.c_str() + size, "Geometry: %dx%d", &winW_, &winH_) != 2) {
      why_ = "xdotool getwindowgeometry: " + geometry;
      return false;
    }
    return waitFor([&] { return paneReport(out(), state_.opts).states > 0; }, "the first measurement") && poke();
  }

  // l: the pane opens and records the picture's calls.
  bool openPane() {
    return typeKey('l') &&
           waitFor([&] { return paneReport(out(), state_.opts).recorded; },
                   "the pane's first recording (\"gl pane:\")") &&
           poke();
  }

  // Presses `k` and reads the pane: just before the key, kMarksLookAfter
  // after it (once the key's measurement and the recording after it are
  // printed and a frame drawn after them), and after kMarksGoneAfter.
  // `tag` names the captures.  False: the run failed (why()).
  bool look(char k, const std::string& tag, MarkLook* r) {
    r->key = k;
    // A measurement still out (the first one, or the one the pane's opening
    // asks for at the narrower figure) would print its state after the key:
    // the key is pressed once none is.
    if (!settle()) return false;
    if (!capture(tag + ".before.png", &r->before)) return false;
    const size_t states = paneReport(out(), state_.opts).states;
    state_.opts.handleKey(k);  // the state the key makes, as the window's handler does
    const std::string want = state_.opts.stateText();
    const double t0 = steadyNow();
    if (!typeKey(k)) return false;
    PaneReport p;
    if (!waitFor(
            [&] {
              p = paneReport(out(), state_.opts);
              return p.states > states && (p.lastState != want || p.changed >= 0);
            },
            "the key's measurement and the pane's recording after it"))
      return false;
    if (p.lastState != want) {
      why_ = "after '" + std::string(1, k) + "' the window printed the state\n  " + p.lastState + "\nnot\n  " + want;
      return false;
    }
    const double seen = steadyNow();
    r->changed = p.changed;
    r->lines = p.lines;
    if (p.changed == 0) return true;  // the key changes no GL call: nothing to mark
    // A frame drawn after that recording is on the screen, and the time has come.
    if (!poke()) return false;
    sleepUntil(t0 + kMarksLookAfter);
    if (!capture(tag + ".marks.png", &r->marked)) return false;
    r->lookDone = steadyNow() - t0;
    r->voided = r->lookDone > kMarksVoidAfter;
    // The marks first appear at or before `seen`: a frame drawn after both
    // times below has them faded (the window draws one itself as they fade;
    // poke() makes sure of one).
    sleepUntil(std::max(t0 + kMarksGoneAfter, seen + ts::GlPane::kHighlightSeconds + 0.5));
    if (!poke() || !capture(tag + ".gone.png", &r->gone)) return false;
    r->goneDone = steadyNow() - t0;
    return true;
  }

  // q: the window closes and the demo (and xvfb-run) end.  xdotool's own
  // status is not looked at: the window may be gone before it sends the
  // key's release (BadWindow, seen in parallax_aniso).  Had q not reached the
  // window, the demo would not end (the hang guard).
  bool quit() {
    x({"xdotool", "key", "--window", window_, "q"}, nullptr, true);
    while (!demo_.poll()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (demo_.exitCode != 0) {
      why_ = "after q:\n" + demo_.describe();
      return false;
    }
    return true;
  }
  const std::string& window() const { return window_; }
  int left() const { return winX_; }
  int top() const { return winY_; }
  int width() const { return winW_; }
  int height() const { return winH_; }
  const std::string& dir() const { return dir_; }
  // What the demo printed so far.
  std::string printed() const { return out(); }
  // Waits (on the demo's stdout, files, ...) until `ready`; false if the
  // demo ended first (why()).
  bool await(const std::function<bool()>& ready, const std::string& what) { return waitFor(ready, what); }
  // A key by its xdotool name (F12, I, ...).
  bool press(const std::string& xname) { return x({"xdotool", "key", "--window", window_, xname}); }
  // The pointer to window pixel (px, py), then a left click there (press
  // and release at the same place).
  bool click(int px, int py) {
    return x({"xdotool", "mousemove", "--window", window_, std::to_string(px), std::to_string(py), "click", "1"});
  }
  // A frame drawn after now (the pointer moved over the figure's corner).
  bool newFrame() { return poke(); }
  // The screen as a PNG in the case's folder (import -window root).
  bool shoot(const std::string& name) {
    std::remove((dir_ + "/" + name).c_str());
    return x({"import", "-window", "root", "PNG24:" + dir_ + "/" + name});
  }
  std::string geometry() const {
    ts::WindowSplit s = ts::splitWindow(winW_, true, true);
    return std::to_string(winW_) + "x" + std::to_string(winH_) + " at " + std::to_string(winX_) + "," +
           std::to_string(winY_) + ", pane x " + std::to_string(winX_ + s.paneX) + ".." +
           std::to_string(winX_ + s.paneX + s.paneW - 1);
  }

 private:
  std::string out() const { return readFile(demo_.outPath); }

  // Polls until `ready`; false if the demo ended first (or hung: Proc::poll).
  bool waitFor(const std::function<bool()>& ready, const std::string& what) {
    for (;;) {
      if (ready()) return true;
      if (demo_.poll()) {
        why_ = "the demo ended while the test waited for " + what + "\n" + demo_.describe() + "stdout:\n" + demo_.out;
        return false;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  // Runs an X client on the demo's server to its end (its stdout in
  // *output).  `quitting`: the demo may end meanwhile, and the client fail.
  bool x(const std::vector<std::string>& args, std::string* output = nullptr, bool quitting = false) {
    Proc t;
    t.argv = {"env", "DISPLAY=" + display_, "XAUTHORITY=" + xauth_};
    t.argv.insert(t.argv.end(), args.begin(), args.end());
    t.outPath = dir_ + "/x_client.stdout";
    t.errPath = dir_ + "/x_client.stderr";
    t.spawn();
    while (!t.poll()) {
      if (!quitting && demo_.poll()) {
        kill(-t.pid, SIGKILL);
        t.poll();
        why_ = "the demo ended during " + commandLine(args) + "\n" + demo_.describe() + "stdout:\n" + demo_.out;
        return false;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (t.exitCode != 0 && !quitting) {
      why_ = t.describe();
      return false;
    }
    if (output) *output = t.out;
    return true;
  }
  bool typeKey(char k) { return x({"xdotool", "key", "--window", window_, xKeyName(k)}); }
  // Moves the pointer over the figure (a motion event: the window draws a
  // frame, and nothing else changes) and waits for a frame logged after it.
  bool poke() { return frameAfterPointerMove(false); }
  // The same, for a frame with no measurement out (the frame log's "frame T
  // MEASURING PROGRESS"): every state asked for so far is measured and printed.
  bool settle() { return frameAfterPointerMove(true); }
  bool frameAfterPointerMove(bool idle) {
    const double t = steadyNow();
    pointer_ = pointer_ == 4 ? 6 : 4;
    if (!x({"xdotool", "mousemove", "--window", window_, std::to_string(pointer_), std::to_string(pointer_)}))
      return false;
    return waitFor(
        [&] {
          std::istringstream in(readFile(logPath_));
          for (std::string l; std::getline(in, l);) {
            double when = 0;
            int measuring = 0;
            if (std::sscanf(l.c_str(), "frame %lf %d", &when, &measuring) >= 1 && when >= t && !(idle && measuring))
              return true;
          }
          return false;
        },
        idle ? "a frame with no measurement out" : "a frame after the pointer moved");
  }
  // The screen as a PNG in the case's folder, and the marked pixels in the pane.
  bool capture(const std::string& name, long* marked) {
    std::string path = dir_ + "/" + name;
    std::remove(path.c_str());
    if (!x({"import", "-window", "root", "PNG24:" + path})) return false;
    ts::Image shot;
    try {
      shot = ts::readPng(path);
    } catch (const std::exception& e) {
      why_ = std::string("import wrote no PNG: ") + e.what();
      return false;
    }
    ts::WindowSplit s = ts::splitWindow(winW_, true, true);  // the side panel is open, and the pane
    long n = 0;
    for (int y = std::max(0, winY_); y < std::min(shot.height, winY_ + winH_); ++y)
      for (int x = std::max(0, winX_ + s.paneX); x < std::min(shot.width, winX_ + s.paneX + s.paneW); ++x)
        n += markYellow(shot.at(x, y));
    *marked = n;
    return true;
  }

  std::string id_, dir_, screen_;
  std::vector<std::string> args_;
  std::string logPath_, display_, xauth_, window_;
  Fresh state_;  // the state the keys typed so far make
  Proc demo_;
  int winX_ = 0, winY_ = 0, winW_ = 0, winH_ = 0, pointer_ = 0;
  std::string why_;
};

// A key's marks for kHighlightSeconds, across the re-record that its
// measurement brings: the demo's first key (the next one if it changes no GL
// call), plus `extra` keys after it (key, a substring of a line it must
// mark).  A capture at 2 s that finished after kMarksVoidAfter says nothing:
// the key is pressed again, up to kMarkTries times.
void glPaneMarksHold(const std::string& id, const std::vector<std::pair<char, std::string>>& extra) {
  for (const char* tool : {"xdotool", "import"})
    ASSERT_FALSE(findOnPath(tool).empty())
        << tool << " is not on PATH: scripts/setup.sh installs it (xdotool, imagemagick)";
  std::string dir = outDir() + "/" + id + "/gl_pane_marks";
  XDemo demo(id, dir);
  ASSERT_TRUE(demo.start()) << demo.why();
  ASSERT_TRUE(demo.openPane()) << demo.why();
  std::printf("[ window   ] %s/gl_pane_marks: window %s, %s\n", id.c_str(), demo.window().c_str(),
              demo.geometry().c_str());
  int presses = 0;
  auto report = [&](const MarkLook& r) {
    std::printf("[ measured ] %s/gl_pane_marks key '%c': %d lines changed; marked px in the pane: %ld before the key, "
                "%ld at %.2f s%s, %ld at %.2f s\n",
                id.c_str(), r.key, r.changed, r.before, r.marked, r.lookDone, r.voided ? " (void: too late)" : "",
                r.gone, r.goneDone);
    std::fflush(stdout);
  };
  auto tag = [&](char k) { return "press" + std::to_string(++presses) + "_" + keyLabel(k); };
  // The key: the first one, or the first after it that changes a GL call.
  Fresh probe(id);
  std::vector<char> candidates;
  for (const auto& it : probe.opts.items())
    for (char k : {it.key, it.keyDown})
      if (k && k != 'q' && k != 'h' && k != 'l' && !xKeyName(k).empty()) candidates.push_back(k);
  ASSERT_FALSE(candidates.empty()) << "no key to press";
  ASSERT_EQ(std::string(1, candidates.front()), firstKey(probe.opts));
  MarkLook r;
  for (char k : candidates) {
    r = MarkLook{};
    ASSERT_TRUE(demo.look(k, tag(k), &r)) << demo.why();
    if (r.changed > 0) break;
    std::printf("[ note     ] %s/gl_pane_marks: key '%c' changes no GL call (0 changed); the next key\n", id.c_str(),
                k);
  }
  ASSERT_GT(r.changed, 0) << "no key of the demo changed a GL call";
  std::vector<std::pair<char, std::string>> keys = {{r.key, ""}};
  keys.insert(keys.end(), extra.begin(), extra.end());
  bool inconclusive = false;
  for (size_t n = 0; n < keys.size(); ++n) {
    const auto& [k, mustMark] = keys[n];
    if (n > 0) {
      r = MarkLook{};
      ASSERT_TRUE(demo.look(k, tag(k), &r)) << demo.why();
    }
    for (int attempt = 1;; ++attempt) {
      report(r);
      std::string shots = dir + "/press" + std::to_string(presses) + "_" + keyLabel(k) + ".*.png";
      ASSERT_GT(r.changed, 0) << "key '" << k << "' changed no GL call" << (attempt > 1 ? " when pressed again" : "");
      if (!mustMark.empty()) {
        bool found = false;
        for (const auto& l : r.lines) found |= l.find(mustMark) != std::string::npos;
        std::string all;
        for (const auto& l : r.lines) all += "\n  " + l;
        EXPECT_TRUE(found) << "key '" << k << "' marks no line with " << mustMark << ":" << all;
      }
      EXPECT_LE(r.before, kMarkedSlack) << "before key '" << k << "' the pane already shows marks: " << shots;
      EXPECT_LE(r.gone, r.before + kMarkedSlack)
          << "key '" << k << "': marks still shown " << r.goneDone << " s after the key, "
          << ts::GlPane::kHighlightSeconds << " s after they appeared: " << shots;
      if (!r.voided) {
        EXPECT_GT(r.marked, kMarkedMin) << "key '" << k << "' (" << r.changed
                                        << " lines changed): no marked line in the pane " << r.lookDone
                                        << " s after the key, across its re-record: " << shots;
        break;
      }
      std::printf("[ void     ] %s/gl_pane_marks key '%c': the capture finished %.2f s after the key (a busy machine); "
                  "%s\n",
                  id.c_str(), k, r.lookDone, attempt < kMarkTries ? "pressing it again" : "no try left");
      if (attempt == kMarkTries) {
        inconclusive = true;
        break;
      }
      r = MarkLook{};
      ASSERT_TRUE(demo.look(k, tag(k), &r)) << demo.why();
    }
  }
  ASSERT_TRUE(demo.quit()) << demo.why();
  if (inconclusive) {
    char why[160];
    std::snprintf(why, sizeof why,
                  "a key's every capture at %.1f s finished after %.1f s (a busy machine): its marks "
                  "were neither seen nor missed",
                  kMarksLookAfter, kMarksVoidAfter);
    GTEST_SKIP() << why;
  }
}

// --- the inspect mode under real X events -------------------------------------
// The demo started as a student starts it, at a size of its own (--size),
// under an Xvfb of its own large enough for it; xdotool types the inspect key
// and clicks a textured pixel near the figure's centre; the card printed for
// that pixel is read, then F12's command (which carries --inspect X,Y) is run
// with --png, and its card names the same panel and batch.  Every wait is on
// the demo's stdout (or an X client's end); the hang guard ends the rest.
const char* const kInspectScreen = "-screen 0 1600x1200x24";

// The key that toggles the inspect mode, as InspectMode picks it: i, or I
// when one of the demo's options takes i.
char inspectKey(const ts::Options& o) {
  for (const auto& it : o.items())
    if (it.key == 'i' || it.keyDown == 'i') return 'I';
  return 'i';
}

// A printed card: from its "pixel (X, Y)" line to its "difference" line,
// whole lines; "" while not all of it is printed.
struct Card {
  int x = -1, y = -1;  // the pixel its first line names
  std::string text;    // the whole card
  std::string where;   // its first line's panel and batch ("" for the background)
  std::vector<std::string> lines;
  bool has(const std::string& start) const {
    for (const auto& l : lines)
      if (l.rfind(start, 0) == 0) return true;
    return false;
  }
  std::string line(const std::string& start) const {
    for (const auto& l : lines)
      if (l.rfind(start, 0) == 0) return l;
    return "";
  }
};
Card cardAt(const std::string& printed, size_t at) {
  Card c;
  const size_t diff = printed.find("\ndifference", at);
  const size_t end = diff == std::string::npos ? diff : printed.find('\n', diff + 1);
  if (end == std::string::npos) return c;
  c.text = printed.substr(at, end + 1 - at);
  std::istringstream in(c.text);
  for (std::string l; std::getline(in, l);) c.lines.push_back(l);
  const std::string& first = c.lines.front();
  int n = 0;
  if (std::sscanf(first.c_str(), "pixel (%d, %d)%n", &c.x, &c.y, &n) == 2) {
    const size_t bracket = first.find("  [", size_t(n));
    c.where = first.substr(size_t(n), bracket == std::string::npos ? std::string::npos : bracket - size_t(n));
  }
  return c;
}
// The first card in `printed` that names pixel (x, y) in its first line.
Card cardFor(const std::string& printed, int x, int y) {
  const std::string head = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
  for (size_t at = printed.find(head); at != std::string::npos; at = printed.find(head, at + 1))
    if (at == 0 || printed[at - 1] == '\n') return cardAt(printed, at);
  return {};
}

// The pixel to click in a w x h figure, nearest its centre in rings of 8 px
// steps, for which `good` holds (the centre if none does).
std::pair<int, int> nearestCentre(int w, int h, const std::function<bool(int, int)>& good) {
  const int cx = w / 2, cy = h / 2;
  for (int r = 0; r < std::min(w, h) / 2; r += 8)
    for (int dy = -r; dy <= r; dy += 8)
      for (int dx = -r; dx <= r; dx += 8) {
        if (std::max(std::abs(dx), std::abs(dy)) != r) continue;  // the ring's edge only
        const int x = cx + dx, y = cy + dy;
        if (x >= 0 && y >= 0 && x < w && y < h && good(x, y)) return {x, y};
      }
  return {cx, cy};
}
// A textured pixel (so that the card has lambda and a batch), by the
// reference's inspector on the scene's frame built without measurements
// (labels aside, the same geometry); false if there is none near the centre:
// the picture is one the scene renders when it measures (bump_mapping).
bool texturedPixel(const std::string& id, int w, int h, std::pair<int, int>* at) {
  Fresh f(id);
  if (!f.scene) return false;
  const ref::Inspector in(f.scene->build(w, h, {}));
  *at = nearestCentre(w, h, [&](int x, int y) { return in.at(x, y).textured; });
  return in.at(at->first, at->second).textured;
}
// Else a pixel of something drawn, from the screen as the student sees it:
// one whose 9 x 9 neighbourhood in `shot` (the window at (x0, y0)) has no
// pixel of the clear colour at the figure's top left corner (so not thin
// label text).
std::pair<int, int> drawnPixel(const ts::Image& shot, int x0, int y0, int w, int h) {
  const ts::Rgba clear = shot.at(x0, y0);
  return nearestCentre(w, h, [&](int x, int y) {
    for (int dy = -4; dy <= 4; ++dy)
      for (int dx = -4; dx <= 4; ++dx) {
        const int sx = x0 + x + dx, sy = y0 + y + dy;
        if (sx < 0 || sy < 0 || sx >= shot.width || sy >= shot.height || channelDiff(shot.at(sx, sy), clear) <= 2)
          return false;
      }
    return true;
  });
}

void inspectModeClicks(const std::string& id) {
  for (const char* tool : {"xdotool", "import"})
    ASSERT_FALSE(findOnPath(tool).empty())
        << tool << " is not on PATH: scripts/setup.sh installs it (xdotool, imagemagick)";
  Fresh probe(id);
  const char key = inspectKey(probe.opts);
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{640, 480}, {1280, 720}}) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    SCOPED_TRACE("--size " + size);
    XDemo demo(id, outDir() + "/" + id + "/inspect_mode/" + size, kInspectScreen, {"--size", size});
    ASSERT_TRUE(demo.start()) << demo.why();
    ASSERT_EQ(demo.width(), w) << demo.geometry();
    ASSERT_EQ(demo.height(), h) << demo.geometry();
    // The inspect key: the mode says so.
    ASSERT_TRUE(demo.press(xKeyName(key))) << demo.why();
    const std::string on = "inspect: on (click a pixel of the figure)\n";
    ASSERT_TRUE(demo.await([&] { return demo.printed().find(on) != std::string::npos; },
                           std::string("\"inspect: on\" after key ") + key))
        << demo.why();
    // A click in the figure (the side panel open, the pane closed).
    const int figureW = ts::splitWindow(w, true, false).figureW;
    std::pair<int, int> pick;
    if (!texturedPixel(id, figureW, h, &pick)) {
      ASSERT_TRUE(demo.newFrame() && demo.shoot("before.png")) << demo.why();
      pick = drawnPixel(ts::readPng(demo.dir() + "/before.png"), demo.left(), demo.top(), figureW, h);
    }
    const int px = pick.first, py = pick.second;
    ASSERT_TRUE(demo.click(px, py)) << demo.why();
    const std::string tag = "inspect: pixel ";
    Card card;
    int gotX = -1, gotY = -1;
    ASSERT_TRUE(demo.await(
        [&] {
          const std::string out = demo.printed();
          const size_t at = out.find(tag);
          if (at == std::string::npos || std::sscanf(out.c_str() + at, "inspect: pixel %d,%d", &gotX, &gotY) != 2)
            return false;
          const size_t eol = out.find('\n', at);
          if (eol == std::string::npos) return false;
          card = cardAt(out, eol + 1);
          return !card.text.empty();
        },
        "\"inspect: pixel\" and its card after the click"))
        << demo.why();
    EXPECT_EQ(gotX, px) << "the click at " << px << "," << py << " picked another pixel";
    EXPECT_EQ(gotY, py) << "the click at " << px << "," << py << " picked another pixel";
    const std::string head = "pixel (" + std::to_string(px) + ", " + std::to_string(py) + ")";
    EXPECT_EQ(card.lines.front().rfind(head, 0), 0u) << "the card does not name the picked pixel:\n" << card.text;
    EXPECT_TRUE(card.has("GL drew")) << card.text;
    EXPECT_TRUE(card.has("reference")) << card.text;
    double lambdaBase = 0, bias = 0, lambda = 0;
    const std::string lambdaLine = card.line("lambda ");
    if (!lambdaLine.empty()) {
      ASSERT_EQ(std::sscanf(lambdaLine.c_str(), "lambda = log2(rho) %lf + bias %lf = %lf", &lambdaBase, &bias, &lambda),
                3)
          << lambdaLine;
      EXPECT_TRUE(std::isfinite(lambda) && std::isfinite(lambdaBase)) << lambdaLine;
    }
    // The footprint: magnified on level 0 in the side panel for a textured
    // pixel (and in a texture-space view showing its texture, if any).
    const bool textured = card.lines.front().find("textured]") != std::string::npos;
    std::string where;
    ASSERT_TRUE(demo.await(
        [&] {
          const std::string out = demo.printed();
          const size_t at = out.find("inspect: footprint ");
          const size_t eol = at == std::string::npos ? at : out.find('\n', at);
          if (eol == std::string::npos) return false;
          where = out.substr(at, eol - at);
          return true;
        },
        "\"inspect: footprint\" after the card"))
        << demo.why();
    if (textured) {
      EXPECT_EQ(where.rfind("inspect: footprint on level 0 in the side panel", 0), 0u) << where;
    }
    const std::string lambdaShown = lambdaLine.empty() ? "" : "; " + lambdaLine.substr(0, lambdaLine.find("  ("));
    std::printf("[ measured ] %s/inspect_mode %s: click %d,%d -> %s%s\n", id.c_str(), size.c_str(), px, py,
                card.lines.front().c_str(), (lambdaShown + "; " + where).c_str());
    std::fflush(stdout);
    // The screen as the student sees it, the card in the side panel.
    ASSERT_TRUE(demo.newFrame() && demo.shoot("card.png")) << demo.why();
    // F12: the printed command carries the pick.
    const size_t saved = demo.printed().size();
    ASSERT_TRUE(demo.press("F12")) << demo.why();
    std::string command;
    const std::string said = "remake them with:\n  ";
    ASSERT_TRUE(demo.await(
        [&] {
          const std::string out = demo.printed();
          const size_t at = out.find(said, saved);
          const size_t eol = at == std::string::npos ? at : out.find('\n', at + said.size());
          if (eol == std::string::npos) return false;
          command = out.substr(at + said.size(), eol - at - said.size());
          return true;
        },
        "F12's command"))
        << demo.why();
    const std::string flag = "--inspect " + std::to_string(px) + "," + std::to_string(py);
    EXPECT_NE((command + " ").find(" " + flag + " "), std::string::npos) << command;
    ASSERT_EQ(command.rfind("build/bin/" + id + " ", 0), 0u) << command;
    // The GL pane (l) marks the calls that set a picked pixel's texture
    // state: a click, the pane open, on a pixel of something drawn (from the
    // screen, the figure now narrower); its glBegin, and for a textured batch
    // its texture's binding.
    {
      ASSERT_TRUE(demo.press("l")) << demo.why();
      ASSERT_TRUE(
          demo.await([&] { return demo.printed().find("gl pane: ") != std::string::npos; }, "the pane's listing"))
          << demo.why();
      ASSERT_TRUE(demo.newFrame() && demo.shoot("pane.png")) << demo.why();
      const int paneFigureW = ts::splitWindow(w, true, true).figureW;
      const auto [qx, qy] = drawnPixel(ts::readPng(demo.dir() + "/pane.png"), demo.left(), demo.top(), paneFigureW, h);
      const size_t before = demo.printed().size();
      ASSERT_TRUE(demo.click(qx, qy)) << demo.why();
      Card second;
      ASSERT_TRUE(demo.await(
          [&] {
            second = cardFor(demo.printed().substr(before), qx, qy);
            return !second.text.empty();
          },
          "the card of the pixel clicked with the pane open"))
          << demo.why();
      // A card of a batch names it ("panel 1 'canvas'  batch 0 ..."); the
      // background's names only its panel, and has no calls to mark.
      if (second.where.find(" batch ") == std::string::npos) {
        std::printf(
            "[ note ] %s/inspect_mode %s: the pixel found drawn with the pane open, %d,%d, is %s: no batch to mark\n",
            id.c_str(), size.c_str(), qx, qy, second.lines.front().c_str());
      } else {
        int marked = -1;
        std::string out;
        ASSERT_TRUE(demo.await(
            [&] {
              out = demo.printed().substr(before);
              const size_t at = out.find(" lines set the picked pixel's texture state");
              if (at == std::string::npos) return false;
              const size_t bol = out.rfind("gl pane: ", at);
              return std::sscanf(out.c_str() + bol, "gl pane: %d lines", &marked) == 1;
            },
            "the pane's marks (\"gl pane: N lines set the picked pixel's texture state\")"))
            << demo.why();
        EXPECT_GE(marked, 2) << second.lines.front();
        EXPECT_NE(out.find("gl pane: picked: glBegin("), std::string::npos) << out;
        if (second.lines.front().find("textured]") != std::string::npos) {
          EXPECT_NE(out.find("gl pane: picked: glBindTexture(GL_TEXTURE_2D"), std::string::npos) << out;
        }
        std::printf("[ measured ] %s/inspect_mode %s: pane open, click %d,%d -> %s; %d calls marked\n", id.c_str(),
                    size.c_str(), qx, qy, second.lines.front().c_str(), marked);
      }
    }
    // q: the window closes, the demo ends with 0.
    ASSERT_TRUE(demo.quit()) << demo.why();
    // The command with --png: its card of the same pixel, the same panel and batch.
    ASSERT_TRUE(runPrintedCommand(id, command, demo.dir()));
    const std::string remade = readFile(demo.dir() + "/remake.stdout");
    const Card offscreen = cardFor(remade, px, py);
    ASSERT_FALSE(offscreen.text.empty()) << "the --png run printed no card of " << head << ":\n" << remade;
    EXPECT_EQ(offscreen.where, card.where) << "window:\n" << card.text << "--png:\n" << offscreen.text;
  }
}

class Case : public testing::Test {
 public:
  explicit Case(std::function<void()> body) : body_(std::move(body)) {}
  void TestBody() override { body_(); }

 private:
  std::function<void()> body_;
};

void registerCase(const std::string& suite, const std::string& name, std::function<void()> body) {
  testing::RegisterTest(suite.c_str(), name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                        [body]() -> testing::Test* { return new Case(body); });
}

// The two levels: smoke (the quick level: each demo opens, takes its first
// key, matches --png, saves with F12, shows the help card and closes; the
// state flags round-trip) and full (every other case).  A case is in one of
// them, never both.  `only`: one demo's cases ("" = every demo).
enum class Subset { Smoke, Full, All };
Subset gSubset = Subset::All;
std::string gOnly;

void registerAll() {
  const bool smoke = gSubset != Subset::Full, full = gSubset != Subset::Smoke;
  for (const auto& reg : ts::sceneRegistry()) {
    const std::string id = reg.id;
    if (!gOnly.empty() && id != gOnly) continue;
    // registerCase for the full level only.
    auto fullCase = [full](const std::string& suite, const std::string& name, std::function<void()> body) {
      if (full) registerCase(suite, name, std::move(body));
    };
    fullCase(id, "window_matches_png", [id] {
      Fresh f(id);
      ASSERT_TRUE(f.scene);
      windowVsPng(id, "window_matches_png", "", f.opts, "");
    });
    Fresh probe(id);
    std::vector<std::pair<char, std::string>> keys;
    for (const auto& it : probe.opts.items())
      for (char k : {it.key, it.keyDown})
        if (k) keys.push_back({k, it.name});
    for (size_t n = 0; n < keys.size(); ++n) {
      const auto& [k, name] = keys[n];
      std::string test = "key_" + keyLabel(k) + "_" + name;
      char key = k;
      std::string option = name;
      // The first key is the smoke level's; the others the full level's.
      if (n == 0 ? !smoke : !full) continue;
      registerCase(id, test, [id, test, key, option] {
        // The window takes q and h itself (quit, overlay) before the demo's
        // handler: an option bound to either could never be reached.
        ASSERT_TRUE(key != 'q' && key != 'h' && key != 'l')
            << "option --" << option << " uses key '" << key
            << "', which the window reserves (q: quit, h: overlay, l: OpenGL calls)";
        Fresh f(id);
        auto before = f.opts.state();
        ASSERT_TRUE(f.opts.handleKey(key)) << "handleKey('" << key << "') took no option";
        // handleKey acts on the first option with the key: another option
        // bound to the same key would be unreachable.
        auto after = f.opts.state();
        for (size_t i = 0; i < after.size(); ++i)
          ASSERT_TRUE(after[i].first == option || after[i].second == before[i].second)
              << "key '" << key << "' of --" << option << " changes --" << after[i].first
              << " instead: two options share the key";
        std::string changed;
        for (const auto& [n, v] : f.opts.state())
          if (n == option) changed = n + "=" + v;
        windowVsPng(id, test, std::string(1, key), f.opts, changed);
      });
    }
    // A live view (Scene::live: drawn every frame), found with the view key
    // and started with its flags (--view live); the window's frames must
    // still be the --png render of that state.
    {
      Fresh g(id);
      std::string viewKeys;
      for (const auto& it : g.opts.items())
        if (it.name == "view" && it.key)
          for (int n = 0; n < 8 && !g.scene->live(); ++n) {
            g.opts.handleKey(it.key);
            viewKeys += it.key;
          }
      if (g.scene->live())
        fullCase(id, "live_view_matches_png", [id, viewKeys] {
          Fresh f(id);
          for (char k : viewKeys) f.opts.handleKey(k);
          windowVsPng(id, "live_view_matches_png", "", f.opts, "", true);
        });
    }
    // The GL pane beside the figure, opened, then the demo's first key.
    if (!keys.empty()) {
      char first = keys.front().first;
      fullCase(id, "gl_pane_beside_figure", [id, first] {
        Fresh f(id);
        f.opts.handleKey(first);
        paneBesideFigure(id, std::string("l") + first, f.opts, "");
      });
    }
    // Two examples a student meets first: f in quad_distortion changes the filter
    // lines; c in cylinder_seam the seam's s from 0.1 to 1.1.
    if (id == "quad_distortion")
      fullCase(id, "gl_pane_shows_the_filter_change", [id] {
        Fresh f(id);
        f.opts.handleKey('f');
        std::string filter;
        for (const auto& [n, v] : f.opts.state())
          if (n == "filter") filter = v == "linear" ? "GL_LINEAR" : "GL_NEAREST";
        paneBesideFigure(id, "lf", f.opts, "GL_TEXTURE_MAG_FILTER, " + filter + ")");
      });
    if (id == "cylinder_seam")
      fullCase(id, "gl_pane_shows_the_seam_change", [id] {
        Fresh f(id);
        f.opts.handleKey('c');
        paneBesideFigure(id, "lc", f.opts, "glTexCoord4f(1.1, ");
      });
    // A picture the scene rendered itself (environment mapping's object):
    // e turns r per pixel into texgen, and the pane marks the render's
    // glTexGeni lines.  Each key waits for the measurement of the state
    // before it (TS_TEST_KEY_WHEN=measured), so the lines are compared with a
    // recording that had the per-pixel render, not with the picture-less
    // frame before it.
    if (id == "environment_mapping")
      fullCase(id, "gl_pane_shows_the_texgen_change", [id] {
        Fresh f(id);
        f.opts.handleKey('e');
        paneBesideFigure(id, "le", f.opts, "glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);",
                         {"TS_TEST_KEY_WHEN=measured"});
      });
    // The marks of a key hold their 4 s across the re-record its
    // measurement brings, with real X key events.  wrap_modes: after its
    // first key (v: the single view), s marks the GL_TEXTURE_WRAP_S line.
    if (!keys.empty()) {
      std::vector<std::pair<char, std::string>> extra;
      if (id == "wrap_modes") extra.push_back({'s', "GL_TEXTURE_WRAP_S"});
      fullCase(id, "gl_pane_marks_hold_with_real_keys", [id, extra] { glPaneMarksHold(id, extra); });
    }
    // A pixel picked with the mouse at 640x480 and 1280x720, its card read.
    fullCase(id, "inspect_mode_clicks_a_pixel", [id] { inspectModeClicks(id); });
    fullCase(id, "resize_sequence", [id] { resizeSequence(id); });
    fullCase(id, "reset_equals_arrow", [id] { resetEqualsArrow(id); });
    if (smoke) registerCase(id, "help_and_save", [id] { helpAndSave(id); });
    fullCase(id, "mouse_orbit", [id] { mouseOrbit(id); });
    if (probe.opts.has("light1-az") && probe.opts.has("light1-el"))
      fullCase(id, "mouse_light", [id] { mouseLight(id); });
    if (probe.opts.has("texture")) fullCase(id, "drop_file", [id] { dropFile(id); });
    if (id == "quad_distortion" || id == "parallax_aniso") {
      fullCase(id, "never_frozen", [id] { framesKeepComing(id); });
      fullCase(id, "close_while_measuring", [id] { closeDuringMeasurement(id); });
    }
    if (smoke)
      registerCase(id, "state_flags_round_trip", [id, keys] {
        Fresh f(id);
        roundTrip(id, f.opts, "initial state");
        for (const auto& kv : keys) {
          Fresh g(id);
          g.opts.handleKey(kv.first);
          roundTrip(id, g.opts, std::string("after key '") + kv.first + "'");
        }
      });
  }
}
}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  // window_test --compare A.png B.png [DIFF.png]: the statistics the tests
  // use, for measuring tolerances by hand.
  if (argc >= 4 && std::string(argv[1]) == "--compare") {
    try {
      ts::Image a = ts::readPng(argv[2]), b = ts::readPng(argv[3]), picture;
      if (a.width != b.width || a.height != b.height) {
        std::printf("sizes differ: %dx%d vs %dx%d\n", a.width, a.height, b.width, b.height);
        return 1;
      }
      Diff d = compare(a, b, &picture);
      std::printf("max channel diff %d at (%d,%d); %ld px differ; %ld px (%.4f%%) by more than %d, %ld of them with "
                  "no match within one pixel\n",
                  d.maxDiff, d.worstX, d.worstY, d.anyDiff, d.overSmall, 100.0 * double(d.overSmall) / double(d.pixels),
                  kSmallDiff, d.unexplained);
      if (argc >= 5) ts::writePng(argv[4], picture);
      return 0;
    } catch (const std::exception& e) {
      std::printf("%s\n", e.what());
      return 1;
    }
  }
  if (findOnPath("xvfb-run").empty()) {
    std::printf("SKIPPED: xvfb-run is not on PATH (Debian: apt-get install xvfb); the window tests need an X server "
                "of their own. Exiting %d so CTest reports this test as skipped.\n",
                kSkip);
    return kSkip;
  }
  if (const char* sz = std::getenv("TS_WINDOW_SIZE"); sz && *sz) {
    try {
      ts::parseSize(sz, &gWidth, &gHeight);
    } catch (const std::exception& e) {
      std::printf("TS_WINDOW_SIZE: %s\n", e.what());
      return 1;
    }
  }
  // --subset=smoke|full|all (default all) and --demo=ID: which cases.
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--subset=smoke") gSubset = Subset::Smoke;
    else if (a == "--subset=full") gSubset = Subset::Full;
    else if (a == "--subset=all") gSubset = Subset::All;
    else if (a.rfind("--demo=", 0) == 0) gOnly = a.substr(7);
    else {
      std::fprintf(stderr, "window_test: unknown argument '%s' (--subset=smoke|full|all, --demo=ID, gtest flags)\n",
                   a.c_str());
      return 2;
    }
  }
  if (!gOnly.empty() && !ts::makeScene(gOnly)) {
    std::fprintf(stderr, "window_test: --demo=%s: no such scene\n", gOnly.c_str());
    return 2;
  }
  if (ts::sceneRegistry().empty()) {
    std::printf("no scene is registered: nothing links into this program\n");
    return 1;
  }
  registerAll();
  return RUN_ALL_TESTS();
}
