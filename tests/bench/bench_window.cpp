// bench_window — frames per second of every registered figure in a window
// at 1024x768, swap interval 0 (needs a display: run it under
//   xvfb-run -a -s "-screen 0 1280x1024x24" build/bin/bench_window
// as scripts/bench.sh does).  Two measurements per figure:
//
//   <figure>/window_draw  in this process, one GLFW window: per frame
//                         glfwPollEvents + scene update + build + Renderer::draw
//                         + glfwSwapBuffers (the window loop without the overlay)
//   <figure>/window_loop  the demo program itself, overlay included: the time of
//                         `<demo> --size 1024x768 --frames N2 <flags>` minus that of
//                         --frames N1, divided by N2 - N1, each timed from the
//                         demo's first output (printed after its start-up
//                         measurement) to its exit; the first frame's texture
//                         uploads and the teardown cancel out
//
//   parallax_live/<mode>/window_loop
//                         the parallax demo's live view, the way a student
//                         runs it: `parallax_aniso --size 1024x560 --view live
//                         --animate --mode <mode> --frames N` (the demo's
//                         default window; every frame draws the mode while
//                         the view turns, at the live view's render scale), as
//                         window_loop above; 20 frames per second (a turning view
//                         still reads as motion) is the bar for every mode but M4/M5
//
//   <demo>/responsiveness
//                         never frozen: the demo at its default
//                         window size, every key of its options typed one a
//                         second (TS_TEST_KEY_INTERVAL_MS) while the window
//                         logs its frames (TS_TEST_FRAME_LOG): the time from
//                         the spawn to the first picture (goal 0.5 s), and
//                         after each key the longest wait for a frame until
//                         the frame that shows the key's measurement (or the
//                         next key): goal 100 ms.  Reported: the first
//                         picture, the median and the worst key.
//
//   <demo>/complete/<W>x<H>
//                         a complete picture at once: the demo at its default
//                         size and at 1280x720, left alone, its frames logged
//                         with a hash of the figure's pixels
//                         (TS_TEST_FRAME_LOG, TS_TEST_FRAME_PIXELS): the time
//                         from the spawn to the first frame, to the first
//                         frame drawn from a measurement (a first stage,
//                         ts::measureStage, or the result: every picture
//                         present, CPU ones perhaps coarse), and to the frame
//                         from which the figure's pixels no longer change
//                         (the numbers and refined pictures in; the last
//                         frame is --frames 30 after the result).  Goal: the
//                         pictures within 0.5 s.  No test asserts these.
//
// Reported time is per frame; the fps counter is its inverse.  Medians of 5
// repetitions by default; any benchmark flag overrides.
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "common/app/inspect_view.hpp"
#include "bench_common.hpp"
#include "common/gl/context.hpp"
#include "common/core/error.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"

extern char** environ;

namespace {
using ts::bench::Figure;
using Clock = std::chrono::steady_clock;

constexpr int kWidth = 1024, kHeight = 768;

GLFWwindow* g_window = nullptr;
std::string g_glfwError;

// The default framebuffer of the benchmark's window as a ts::Context.
class WindowTarget final : public ts::Context {
 public:
  explicit WindowTarget(GLFWwindow* w) : win_(w) { sync(); }
  ts::Backend backend() const override { return ts::Backend::Window; }
  void resize(int, int) override { sync(); }
  void bindTarget() override {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_BACK);
  }
  void sync() { glfwGetFramebufferSize(win_, &width_, &height_); }

 private:
  GLFWwindow* win_;
};
std::unique_ptr<WindowTarget> g_target;
std::map<std::string, double> g_drawSeconds;  // figure -> seconds per frame in window_draw

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

void benchWindowDraw(benchmark::State& st, const Figure& f) {
  try {
    ts::Renderer r(*g_target);
    ts::bench::SceneState s(f);
    ts::Measurements measured = s.scene->measure(r);  // once, as the window does when the state changes
    g_target->sync();
    r.draw(s.scene->build(g_target->width(), g_target->height(), measured));  // uploads textures, compiles shaders
    glfwSwapBuffers(g_window);
    auto last = Clock::now();
    auto start = last;
    for (auto _ : st) {
      glfwPollEvents();
      auto now = Clock::now();
      s.scene->update(seconds(now - last));
      last = now;
      g_target->sync();
      if (s.scene->live())
        measured = s.scene->measure(r);  // a live view draws itself every frame, as the window loop does
      ts::Frame frame = s.scene->build(g_target->width(), g_target->height(), measured);
      r.draw(frame);
      glfwSwapBuffers(g_window);
    }
    double elapsed = seconds(Clock::now() - start);
    st.counters["fps"] = elapsed > 0 ? double(st.iterations()) / elapsed : 0.0;
    if (st.iterations() > 0) g_drawSeconds[f.spec.id] = elapsed / double(st.iterations());
    ts::gl::check("the benchmark's window frames");
    r.release();
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}

// <figure>/inspect_pick: what the window's inspect mode does when a pixel
// is clicked (common/app/inspect_mode.cpp), timed in this process after the
// figure is drawn: the 32 x 32 pixels around it read back, the reference's
// inspection of that one pixel (no re-rasterizing of the frame), its card,
// its footprint mapped into the figure's texture-space views and, for a
// textured pixel, the 256 x 256 footprint cell rendered offscreen.
// The bar: within one frame, under 30 ms, so a pick answers before the next frame.  The pixel: the figure's
// centre (a textured pixel in most figures).
void benchInspectPick(benchmark::State& st, const Figure& f) {
  try {
    ts::Renderer r(*g_target);
    ts::bench::SceneState s(f);
    ts::Measurements measured = s.scene->measure(r);
    g_target->sync();
    const ts::Frame frame = s.scene->build(g_target->width(), g_target->height(), measured);
    r.draw(frame);
    const int x = frame.width / 2, y = frame.height / 2;
    std::vector<uint8_t> around(32 * 32 * 4);
    ts::Image picked(frame.width, frame.height);
    for (auto _ : st) {
      glPixelStorei(GL_PACK_ALIGNMENT, 1);
      glReadPixels(std::max(0, x - 16), std::max(0, frame.height - y - 16), 32, 32, GL_RGBA, GL_UNSIGNED_BYTE,
                   around.data());
      const std::vector<ts::Picked> p = ts::inspectPixels(frame, picked, {{x, y}});
      benchmark::DoNotOptimize(ts::inspectCard(p.front()));
      ts::Frame over;
      benchmark::DoNotOptimize(ts::footprintInTextureViews(frame, p.front().in, &over));
      if (p.front().in.textured && p.front().in.texture >= 0)
        benchmark::DoNotOptimize(r.renderOffscreen(ts::footprintCell(frame, p.front().in, 256, 256)));
    }
    glfwSwapBuffers(g_window);
    r.release();
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}

std::string binDir() {
  char buf[PATH_MAX];
  ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return ".";
  std::string p(buf, size_t(n));
  return p.substr(0, p.rfind('/'));
}

// Runs `<demo> --size 1024x768 --frames N <flags>` and returns the seconds from
// its first output to its exit.  The window loop flushes its first output
// when the first measurement is handed over (from its worker, or a live
// view's first frame), and --frames counts the frames from there, so the
// start-up (window, context, Dear ImGui, measure), whose time varies far more
// than a frame's, is left out; what remains is N frames and the teardown.
// Throws if the demo fails.
double runProgram(const std::string& demo, int width, int height, const std::vector<std::string>& flags, int frames) {
  std::string exe = binDir() + "/" + demo;
  std::vector<std::string> args = {exe, "--size", std::to_string(width) + "x" + std::to_string(height), "--frames",
                                   std::to_string(frames)};
  args.insert(args.end(), flags.begin(), flags.end());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int out[2];
  if (pipe(out) != 0) throw ts::Error(std::string("pipe: ") + std::strerror(errno));
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, out[1], 1);
  posix_spawn_file_actions_addclose(&fa, out[0]);
  posix_spawn_file_actions_addclose(&fa, out[1]);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  int err = posix_spawn(&pid, exe.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  close(out[1]);
  if (err != 0) {
    close(out[0]);
    throw ts::Error("cannot run " + exe + ": " + std::strerror(err));
  }
  // First output, then drain to end of file (the demo's exit).
  char buf[4096];
  bool first = true;
  Clock::time_point t0 = Clock::now();
  for (;;) {
    ssize_t n = read(out[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (first) t0 = Clock::now();
    first = false;
  }
  close(out[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  double t = seconds(Clock::now() - t0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw ts::Error(exe + " --frames " + std::to_string(frames) + " failed (status " + std::to_string(status) + ")");
  if (first) throw ts::Error(exe + " printed nothing: cannot tell its start-up from its frames");
  return t;
}
double runDemo(const Figure& f, int frames) {
  return runProgram(f.demo, kWidth, kHeight, ts::sceneFlags(f.spec.flags), frames);
}

constexpr int kBaseFrames = 10;

// The parallax demo's live view at its default window, 1024 x 560 (see the header).
constexpr int kLiveWidth = 1024, kLiveHeight = 560, kLiveFrames = 30;
const char* const kLiveModes[] = {"naive", "trilinear", "aniso16", "ewa"};
std::vector<std::string> liveFlags(const std::string& mode) { return {"--view", "live", "--animate", "--mode", mode}; }
void benchLiveLoop(benchmark::State& st, const std::string& mode) {
  try {
    double sum = 0;
    for (auto _ : st) {
      double t1 = runProgram("parallax_aniso", kLiveWidth, kLiveHeight, liveFlags(mode), kBaseFrames);
      double t2 = runProgram("parallax_aniso", kLiveWidth, kLiveHeight, liveFlags(mode), kBaseFrames + kLiveFrames);
      double perFrame = std::max(1e-9, (t2 - t1) / kLiveFrames);
      sum += perFrame;
      st.SetIterationTime(perFrame);
    }
    st.counters["fps"] = double(st.iterations()) / sum;
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}

// Idle is idle: a demo's window left alone for 5 s after it has
// started (2 s), CPU seconds it used meanwhile, from /proc/<pid>/stat.
double cpuSeconds(pid_t pid) {
  std::FILE* f = std::fopen(("/proc/" + std::to_string(pid) + "/stat").c_str(), "r");
  if (!f) return -1;
  char buf[2048];
  size_t n = std::fread(buf, 1, sizeof buf - 1, f);
  std::fclose(f);
  buf[n] = 0;
  const char* p = std::strrchr(buf, ')');  // the command name may hold spaces
  unsigned long utime = 0, stime = 0;
  if (!p || std::sscanf(p + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %lu %lu", &utime, &stime) != 2) return -1;
  return double(utime + stime) / double(sysconf(_SC_CLK_TCK));
}

void benchIdleCpu(benchmark::State& st, const std::string& demo) {
  try {
    for (auto _ : st) {
      std::string exe = binDir() + "/" + demo;
      std::vector<std::string> args = {exe, "--size", std::to_string(kWidth) + "x" + std::to_string(kHeight),
                                       "--quiet"};
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      posix_spawn_file_actions_t fa;
      posix_spawn_file_actions_init(&fa);
      posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
      posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
      pid_t pid = 0;
      int err = posix_spawn(&pid, exe.c_str(), &fa, nullptr, argv.data(), environ);
      posix_spawn_file_actions_destroy(&fa);
      if (err != 0) throw ts::Error("cannot run " + exe + ": " + std::strerror(err));
      usleep(2000000);
      double c0 = cpuSeconds(pid);
      usleep(5000000);
      double c1 = cpuSeconds(pid);
      kill(pid, SIGTERM);
      int status = 0;
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      if (c0 < 0 || c1 < 0) throw ts::Error(demo + " ended before its idle seconds were measured");
      st.SetIterationTime(c1 - c0);
      st.counters["cpu_s_per_5_idle_s"] = c1 - c0;
    }
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}

// ---- responsiveness
struct Responsiveness {
  double firstPicture = 0;                       // seconds from the spawn to the first frame
  std::vector<std::pair<char, double>> keyGaps;  // per key: longest wait for a frame, seconds
  std::vector<double> measureSeconds;            // per key whose measurement was shown: key to result
};
std::map<std::string, std::vector<Responsiveness>> g_responsiveness;  // demo -> one per repetition

std::string demoKeys(const std::string& demo) {
  auto scene = ts::makeScene(demo);
  ts::Options o;
  scene->addOptions(o);
  std::string keys;
  for (const auto& it : o.items())
    for (char k : {it.key, it.keyDown})
      if (k && k != 'q' && k != 'h' && k != 'l') keys += k;
  return keys;
}

// `demo` run to its end with `flags`, its output dropped, its window's frame log (TS_TEST_FRAME_LOG) written to a
// temporary file, `env` added to the environment: the log's path (the caller reads and removes it) and the spawn's
// time.
struct LoggedRun {
  std::string exe, logPath;
  Clock::time_point spawned;
  int status = 0;  // waitpid's
};
LoggedRun runWithFrameLog(const std::string& demo, const std::vector<std::string>& flags,
                          const std::vector<std::string>& extraEnv) {
  std::string exe = binDir() + "/" + demo;
  char logPath[] = "/tmp/bench_window_frames_XXXXXX";
  int fd = mkstemp(logPath);
  if (fd < 0) throw ts::Error(std::string("mkstemp: ") + std::strerror(errno));
  close(fd);
  std::vector<std::string> args = {exe};
  args.insert(args.end(), flags.begin(), flags.end());
  std::vector<std::string> env = {std::string("TS_TEST_FRAME_LOG=") + logPath};
  env.insert(env.end(), extraEnv.begin(), extraEnv.end());
  for (char** e = environ; *e; ++e) env.push_back(*e);
  std::vector<char*> argv, envp;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (auto& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  Clock::time_point spawned = Clock::now();
  int err = posix_spawn(&pid, exe.c_str(), &fa, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&fa);
  if (err != 0) throw ts::Error("cannot run " + exe + ": " + std::strerror(err));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return {exe, logPath, spawned, status};
}

Responsiveness runResponsiveness(const std::string& demo, const std::string& keys, double keyInterval) {
  const LoggedRun run = runWithFrameLog(demo, {"--keys", keys + "q", "--quiet"},
                                        {"TS_TEST_KEY_INTERVAL_MS=" + std::to_string(int(keyInterval * 1000))});
  const std::string& exe = run.exe;
  const char* logPath = run.logPath.c_str();
  const Clock::time_point spawned = run.spawned;
  const int status = run.status;
  std::FILE* f = std::fopen(logPath, "r");
  std::vector<std::tuple<std::string, double, std::string>> log;
  char what[16], rest[64];
  double t = 0;
  while (f && std::fscanf(f, "%15s %lf", what, &t) == 2) {
    rest[0] = 0;
    if (!std::fgets(rest, sizeof rest, f)) rest[0] = 0;
    log.emplace_back(what, t, rest);
  }
  if (f) std::fclose(f);
  std::remove(logPath);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw ts::Error(exe + " --keys " + keys + " failed (status " + std::to_string(status) + ")");
  Responsiveness r;
  double t0 = std::chrono::duration<double>(spawned.time_since_epoch()).count();  // steady clock, as the log
  for (const auto& [w, tt, _] : log)
    if (w == "frame") {
      r.firstPicture = tt - t0;
      break;
    }
  for (size_t i = 0; i < log.size(); ++i) {
    if (std::get<0>(log[i]) != "key") continue;
    char key = std::get<2>(log[i]).size() > 1 ? std::get<2>(log[i])[1] : '?';
    if (key == 'q') break;
    double prev = std::get<1>(log[i]), gap = 0;
    bool shown = false;
    for (size_t j = i + 1; j < log.size(); ++j) {
      const auto& [w, tt, _] = log[j];
      if (w == "key") break;
      if (w == "result") {
        shown = true;
        r.measureSeconds.push_back(tt - std::get<1>(log[i]));
        continue;
      }
      gap = std::max(gap, tt - prev);
      prev = tt;
      if (shown) break;  // the frame that shows the key's measurement
    }
    r.keyGaps.push_back({key, gap});
  }
  return r;
}

void benchResponsiveness(benchmark::State& st, const std::string& demo) {
  try {
    std::string keys = demoKeys(demo);
    for (auto _ : st) {
      Responsiveness r = runResponsiveness(demo, keys, 1.0);
      double worst = 0;
      for (const auto& kg : r.keyGaps) worst = std::max(worst, kg.second);
      st.SetIterationTime(r.firstPicture);
      st.counters["first_picture_s"] = r.firstPicture;
      st.counters["worst_key_gap_ms"] = 1000.0 * worst;
      g_responsiveness[demo].push_back(std::move(r));
    }
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}

// ---- a complete picture
struct Completion {
  double firstFrame = NAN, pictures = NAN, settled = NAN;  // seconds from the spawn
  std::string load;                                        // the load average (1, 5, 15 min) after the run
};
std::string loadAverage();
struct CompletionKey {
  std::string demo;
  int w, h;
  bool operator<(const CompletionKey& o) const { return std::tie(demo, w, h) < std::tie(o.demo, o.w, o.h); }
};
std::map<CompletionKey, std::vector<Completion>> g_completion;

Completion runCompletion(const std::string& demo, int width, int height) {
  const LoggedRun run = runWithFrameLog(demo,
                                        {"--size", std::to_string(width) + "x" + std::to_string(height), "--frames",
                                         "30", "--quiet"},
                                        {"TS_TEST_FRAME_PIXELS=1"});
  const std::string& exe = run.exe;
  const char* logPath = run.logPath.c_str();
  const Clock::time_point spawned = run.spawned;
  const int status = run.status;
  // "frame T M P H" (H: the figure's hash), "stage T", "result T".
  std::vector<std::pair<double, std::string>> frames;  // time, hash
  std::vector<double> measured;                        // times of stages and results
  std::FILE* f = std::fopen(logPath, "r");
  char line[256];
  while (f && std::fgets(line, sizeof line, f)) {
    char what[16] = "", hash[32] = "";
    double t = 0, p = 0;
    int m = 0;
    if (std::sscanf(line, "%15s %lf", what, &t) != 2) continue;
    if (!std::strcmp(what, "frame") && std::sscanf(line, "%*s %*f %d %lf %31s", &m, &p, hash) == 3)
      frames.emplace_back(t, hash);
    else if (!std::strcmp(what, "stage") || !std::strcmp(what, "result")) measured.push_back(t);
  }
  if (f) std::fclose(f);
  std::remove(logPath);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw ts::Error(exe + " --frames 30 failed (status " + std::to_string(status) + ")");
  if (frames.empty()) throw ts::Error(exe + " logged no frame with a pixel hash");
  Completion c;
  c.load = loadAverage();
  const double t0 = std::chrono::duration<double>(spawned.time_since_epoch()).count();  // steady clock, as the log
  c.firstFrame = frames.front().first - t0;
  if (!measured.empty())
    for (const auto& [t, h] : frames)
      if (t >= measured.front()) {
        c.pictures = t - t0;
        break;
      }
  size_t k = frames.size() - 1;
  while (k > 0 && frames[k - 1].second == frames.back().second) --k;
  c.settled = frames[k].first - t0;
  return c;
}

void benchCompletion(benchmark::State& st, const std::string& demo, int width, int height) {
  try {
    for (auto _ : st) {
      Completion c = runCompletion(demo, width, height);
      st.SetIterationTime(c.settled);
      st.counters["first_frame_s"] = c.firstFrame;
      st.counters["pictures_s"] = c.pictures;
      st.counters["complete_s"] = c.settled;
      g_completion[{demo, width, height}].push_back(c);
    }
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}

std::string loadAverage() {
  std::FILE* la = std::fopen("/proc/loadavg", "r");
  char load[64] = "?";
  if (la) {
    if (!std::fgets(load, sizeof load, la)) std::snprintf(load, sizeof load, "?");
    std::fclose(la);
  }
  std::string s = load;  // "1.00 0.80 0.50 2/168 9519": the first three
  size_t end = 0;
  for (int k = 0; k < 3 && end != std::string::npos; ++k) end = s.find(' ', end + (k ? 1 : 0));
  return s.substr(0, end);
}

double median(std::vector<double> v);
void completionSummary() {
  if (g_completion.empty()) return;
  std::printf("\n## A complete picture at once: seconds from the spawn (medians; a frame's figure pixels hashed)\n\n"
              "| demo | size | first frame s | pictures s (first stage or result) | complete after s (pixels stop "
              "changing) | load average |\n|---|---|--:|--:|--:|---|\n");
  for (const auto& [key, runs] : g_completion) {
    std::vector<double> first, pictures, settled;
    for (const Completion& c : runs)
      first.push_back(c.firstFrame), pictures.push_back(c.pictures), settled.push_back(c.settled);
    std::printf("| `%s` | %dx%d | %.2f | %.2f | %.2f | %s |\n", key.demo.c_str(), key.w, key.h, median(first),
                median(pictures), median(settled), runs.back().load.c_str());
  }
  std::printf("\nGoal: every picture present within 0.5 s (CPU pictures may be coarse, tagged \"refining\"); "
              "the numbers and refined pictures may follow.\n\n");
}

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

void responsivenessSummary() {
  if (g_responsiveness.empty()) return;
  std::FILE* la = std::fopen("/proc/loadavg", "r");
  char load[64] = "?";
  if (la) {
    if (!std::fgets(load, sizeof load, la)) std::snprintf(load, sizeof load, "?");
    std::fclose(la);
  }
  std::printf(
      "\n## Never frozen: first picture and frame intervals after each key (default window, keys 1 s apart)\n\n"
      "Load average at the end: %s\n"
      "| demo | first picture s (median) | key gap ms: median over keys | worst key (ms) | key to its numbers s "
      "(median) | keys |\n|---|--:|--:|--:|--:|--:|\n",
      load);
  for (const auto& [demo, runs] : g_responsiveness) {
    std::vector<double> first, gaps, measure;
    std::map<char, std::vector<double>> perKey;
    for (const Responsiveness& r : runs) {
      first.push_back(r.firstPicture);
      for (const auto& [k, g] : r.keyGaps) perKey[k].push_back(g);
      measure.insert(measure.end(), r.measureSeconds.begin(), r.measureSeconds.end());
    }
    char worstKey = '?';
    double worst = -1;
    for (const auto& [k, v] : perKey) {
      double m = median(v);
      gaps.push_back(m);
      if (m > worst) worst = m, worstKey = k;
    }
    std::printf("| `%s` | %.2f | %.0f | %c: %.0f | %.2f | %zu |\n", demo.c_str(), median(first), 1000.0 * median(gaps),
                worstKey, 1000.0 * worst, median(measure), perKey.size());
  }
  std::printf("\nGoals: first picture <= 0.5 s, every key gap <= 100 ms (a key gap: from the key to its first frame, "
              "and between frames until the frame that shows the key's measurement).\n\n");
}

constexpr double kExtraSeconds = 1.5;

// Extra frames so that they take about kExtraSeconds (60 to 3000 frames),
// from the figure's window_draw time if it ran, else from a trial run.
int extraFrames(const Figure& f) {
  static std::map<std::string, int> cache;
  auto it = cache.find(f.spec.id);
  if (it != cache.end()) return it->second;
  double perFrame = 0;
  auto d = g_drawSeconds.find(f.spec.id);
  if (d != g_drawSeconds.end()) perFrame = d->second;
  else perFrame = (runDemo(f, kBaseFrames + 100) - runDemo(f, kBaseFrames)) / 100.0;
  int n = perFrame > 0 ? int(std::lround(kExtraSeconds / perFrame)) : 3000;
  n = std::clamp(n, 60, 3000);
  cache[f.spec.id] = n;
  return n;
}

void benchWindowLoop(benchmark::State& st, const Figure& f) {
  try {
    int extra = extraFrames(f);
    double sum = 0;
    for (auto _ : st) {
      double t1 = runDemo(f, kBaseFrames);
      double t2 = runDemo(f, kBaseFrames + extra);
      double perFrame = std::max(1e-9, (t2 - t1) / extra);
      sum += perFrame;
      st.SetIterationTime(perFrame);
    }
    st.counters["fps"] = double(st.iterations()) / sum;
    st.counters["frames"] = extra;
  } catch (const std::exception& e) {
    st.SkipWithError(e.what());
  }
}

std::string name(const Figure& f, const char* what) { return f.spec.id + "/" + what; }

void summary(const ts::bench::SummaryReporter& rep, const std::vector<Figure>& figs, const std::string& renderer) {
  std::printf("\n## Window frames per second at %dx%d, swap interval 0 (wall clock, %s)\n\n- `%s`\n\n", kWidth, kHeight,
              rep.statistic().c_str(), renderer.c_str());
  std::printf("| figure | draw + swap ms/frame | FPS | demo window loop ms/frame (overlay on) | FPS | loop ÷ draw |\n"
              "|---|--:|--:|--:|--:|--:|\n");
  for (const Figure& f : figs) {
    if (!rep.ran(f.spec.id + "/")) continue;
    double draw = rep.ms(name(f, "window_draw")), loop = rep.ms(name(f, "window_loop"));
    std::printf("| `%s` | %s | %s | %s | %s | %s |\n", f.spec.id.c_str(), ts::bench::fmt(draw).c_str(),
                ts::bench::fmt(1000.0 / draw).c_str(), ts::bench::fmt(loop).c_str(),
                ts::bench::fmt(1000.0 / loop).c_str(), ts::bench::ratio(loop, draw).c_str());
  }
  std::printf(
      "\nFPS = 1000 ÷ median ms/frame. draw + swap: this program's own window (poll, update, build, "
      "Renderer::draw, glfwSwapBuffers);\ndemo window loop: `<demo> --size %dx%d --frames N <figure flags>` timed "
      "from its first output (after start-up) to exit, for two N; difference ÷ frames (Dear ImGui overlay "
      "included).\n\n",
      kWidth, kHeight);
  bool live = false;
  for (const char* m : kLiveModes) live = live || rep.ran(std::string("parallax_live/") + m + "/");
  if (!live) return;
  std::printf("\n## The parallax demo's live view at %dx%d (window loop, animated; 20 frames per second = 50 ms)\n\n",
              kLiveWidth, kLiveHeight);
  std::printf("| mode | ms/frame | FPS | x the 50 ms of 20 fps |\n|---|--:|--:|--:|\n");
  for (const char* m : kLiveModes) {
    double ms = rep.ms(std::string("parallax_live/") + m + "/window_loop");
    if (std::isnan(ms)) continue;
    std::printf("| %s | %s | %s | %.2f |\n", m, ts::bench::fmt(ms).c_str(), ts::bench::fmt(1000.0 / ms).c_str(),
                ms / 50.0);
  }
  std::printf("\n");
}

void onGlfwError(int, const char* msg) { g_glfwError = msg ? msg : "unknown"; }
void* glfwProc(const char* n) { return reinterpret_cast<void*>(glfwGetProcAddress(n)); }
}  // namespace

int main(int argc, char** argv) {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) {
    std::fprintf(stderr,
                 "bench_window: no display (%s); run it under xvfb-run -a -s \"-screen 0 1280x1024x24\" (see "
                 "scripts/bench.sh)\n",
                 g_glfwError.c_str());
    return 2;
  }
  // The same hints as common/app/window.cpp: a compatibility context.
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  glfwWindowHint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  g_window = glfwCreateWindow(kWidth, kHeight, "bench_window", nullptr, nullptr);
  if (!g_window) {
    std::fprintf(stderr, "bench_window: cannot open a %dx%d window (%s)\n", kWidth, kHeight, g_glfwError.c_str());
    glfwTerminate();
    return 2;
  }
  glfwMakeContextCurrent(g_window);
  glfwSwapInterval(0);
  std::string missing;
  if (!ts::gl::load(glfwProc, &missing)) {
    std::fprintf(stderr, "bench_window: the window's OpenGL context lacks %s\n", missing.c_str());
    return 2;
  }
  g_target = std::make_unique<WindowTarget>(g_window);
  std::string renderer = g_target->describe() + " | framebuffer " + std::to_string(g_target->width()) + "x" +
                         std::to_string(g_target->height());
  benchmark::AddCustomContext("gl_window", renderer);

  std::vector<Figure> figs = ts::bench::registeredFigures();
  for (const Figure& f : figs) {
    benchmark::RegisterBenchmark(name(f, "window_draw").c_str(), benchWindowDraw, f)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->ComputeStatistics("min", ts::bench::minimum);
    benchmark::RegisterBenchmark(name(f, "inspect_pick").c_str(), benchInspectPick, f)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->ComputeStatistics("min", ts::bench::minimum);
    benchmark::RegisterBenchmark(name(f, "window_loop").c_str(), benchWindowLoop, f)
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime()
        ->Iterations(1)
        ->ComputeStatistics("min", ts::bench::minimum);
  }
  std::vector<std::string> demos;
  for (const Figure& f : figs)
    if (std::find(demos.begin(), demos.end(), f.demo) == demos.end()) demos.push_back(f.demo);
  for (const std::string& d : demos)
    benchmark::RegisterBenchmark((d + "/idle_cpu_5s").c_str(), benchIdleCpu, d)
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime()
        ->Iterations(1);
  for (const std::string& d : demos)
    benchmark::RegisterBenchmark((d + "/responsiveness").c_str(), benchResponsiveness, d)
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime()
        ->Iterations(1);
  for (const std::string& d : demos) {
    auto scene = ts::makeScene(d);
    std::vector<std::pair<int, int>> sizes = {{scene->defaultWidth(), scene->defaultHeight()}, {1280, 720}};
    if (sizes[0] == sizes[1]) sizes.pop_back();
    for (const auto& [w, h] : sizes)
      benchmark::RegisterBenchmark((d + "/complete/" + std::to_string(w) + "x" + std::to_string(h)).c_str(),
                                   benchCompletion, d, w, h)
          ->Unit(benchmark::kMillisecond)
          ->UseManualTime()
          ->Iterations(1);
  }
  for (const char* m : kLiveModes)
    benchmark::RegisterBenchmark((std::string("parallax_live/") + m + "/window_loop").c_str(), benchLiveLoop,
                                 std::string(m))
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime()
        ->Iterations(1)
        ->ComputeStatistics("min", ts::bench::minimum);
  int status = ts::bench::run(argc, argv, [&](const ts::bench::SummaryReporter& rep) {
    summary(rep, figs, renderer);
    responsivenessSummary();
    completionSummary();
  });
  g_target.reset();
  glfwDestroyWindow(g_window);
  glfwTerminate();
  return status;
}
