// common/app/window_parts.hpp — the window's parts shared by its files: the GL context, the input, the frame loop.
#pragma once
#include "common/app/window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <string>
#include <utility>
#include <vector>

#include "common/app/gl_pane.hpp"
#include "common/app/inspect_mode.hpp"
#include "common/app/measure_worker.hpp"
#include "common/app/side_panel.hpp"
#include "common/core/test_hooks.hpp"
#include "common/gl/context.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render.hpp"

// runWindow's parts, one concern a file:
//   window.cpp          the window's life: open, run the frame loop, close
//   window_input.cpp    keys, mouse and dropped files, and what they change
//   window_frame.cpp    the frame loop's steps: wait, measure, draw, present
//   window_save.cpp     --screenshot and F12's picture, sidecar and command
//   window_overlay.cpp  Dear ImGui: the side panel, the GL pane, the help card
namespace ts::window_parts {
// The window's framebuffer as a Context: the renderer draws into its back
// buffer, at the size the window manager gives it.
class WindowContext final : public Context {
 public:
  explicit WindowContext(GLFWwindow* w) : win_(w) {
    sync();
    GLint bits = 0;
    glGetIntegerv(GL_ACCUM_RED_BITS, &bits);
    accum_ = bits > 0;
  }
  bool hasAccumBuffer() const override { return accum_; }
  Backend backend() const override { return Backend::Window; }
  void resize(int, int) override { sync(); }  // the window manager decides
  void bindTarget() override {
    if (gl::p_glBindFramebuffer) glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_BACK);
  }
  void sync() { glfwGetFramebufferSize(win_, &width_, &height_); }

 private:
  GLFWwindow* win_;
  bool accum_ = false;
};

struct Input {
  std::string keys;  // characters typed since the last frame
  bool quit = false;
  bool overlay = true;
  bool help = false;
  // The mouse, gathered between frames: a left drag (pixels) and the wheel
  // (clicks) turn the orbit options (OrbitCamera's names); files dropped on
  // the window go to --texture.
  bool dragging = false, knowPos = false;
  double lastX = 0, lastY = 0, dragX = 0, dragY = 0, wheel = 0;
  // A right drag moves the demo's light instead (options light1-az and
  // light1-el, degrees, where a demo has them: bump_mapping).
  bool lightDrag = false;
  double lightX = 0, lightY = 0;
  // A left press and release in (nearly) the same place: a click, which the
  // inspect mode takes as a pick.
  bool clicked = false;
  double pressX = 0, pressY = 0, clickX = 0, clickY = 0;
  std::vector<std::string> dropped;
};

// Sends the window's keys, mouse and dropped files to `in`, queues --keys,
// and replays TS_TEST_MOUSE, all before the first frame (window_input.cpp).
void connectInput(GLFWwindow* win, const CommonFlags& flags, Input* in);
// Starts Dear ImGui on the window (side panel, GL pane, help card) and
// uploads its font atlas; returns that texture, which closeWindow deletes
// (window_overlay.cpp).
GLuint startImGui(GLFWwindow* win);

// The frame loop: what it carries from one frame to the next, and a method
// per step of a frame, declared in the order runWindow calls them (each is
// defined in the file of its concern: the list above).
class FrameLoop {
 public:
  FrameLoop(Scene& sc, Options& op, const CommonFlags& fl, GLFWwindow* w, WindowContext& c, Renderer& r,
            MeasureWorker* wk, Input& in)
      : scene(sc), opts(op), flags(fl), win(w), ctx(c), renderer(r), worker(wk), input(in) {}

  bool running() const;
  void waitForEvents();
  // While a measurement runs in a window left alone (no key, drag, wheel,
  // click or drop for 2 s): frames a few a second, the cores the worker's.
  bool aloneWhileMeasuring() const;
  void applyMouse();
  void applyKey();
  void advanceClock();
  bool updateSize();
  void layOut();
  void startMeasuring();
  void collectMeasurement();
  Frame drawPicture();
  void saveIfAsked(const Frame& f);
  void inspectPixel(const Frame& f);
  bool isLastFrame();
  void takeScreenshot(bool lastFrame, bool overlayDrawn);
  void drawOverlay();
  void present();

 private:
  void clickScene();  // a click on the figure outside the inspect mode
  void keyChanged();  // the GL pane marks what the next pictures change

  // What the loop works on.
  Scene& scene;
  Options& opts;
  const CommonFlags& flags;
  GLFWwindow* win;
  WindowContext& ctx;
  Renderer& renderer;
  MeasureWorker* worker;
  Input& input;

  // The numbers shown, and the measurement under way.
  Measurements m;
  bool dirty = true;                 // the state changed since it was last measured
  bool measuring = false;            // a request is out: the numbers shown are stale
  bool measureHere = false;          // the worker has no context: the loop measures itself
  bool measuredOnce = false;         // a measurement is in
  int measuredW = 0, measuredH = 0;  // the figure size the numbers shown were (or are being) measured at
  bool savePending = false;          // F12 pressed
  // The test hooks (common/core/test_hooks.hpp).
  test_hooks::KeyLog testLog;                          // TS_TEST_FRAME_LOG, TS_TEST_KEY_WHEN
  const bool framePixels = test_hooks::framePixels();  // TS_TEST_FRAME_PIXELS
  uint64_t pixelHash = 0;                              // the figure's, this frame
  std::vector<std::pair<int, int>> resizes = test_hooks::resizes();
  const bool resizing = !resizes.empty();
  // The inspect mode (key i): a clicked pixel's loupe and card.
  InspectMode inspect{opts, flags};
  std::string inspectedState;  // the state and measurement the card is of
  // The GL pane.
  GlPane pane;
  bool record = false, resultIn = false;  // the GL pane needs a new recording (of a new measurement)
  int recordedW = 0, recordedH = 0;       // the figure size of its last recording
  // Pacing and counting frames.
  bool redraw = true;        // draw again without waiting for an event
  bool busy = false;         // this frame was drawn without waiting for an event
  double lastAction = -1e9;  // glfwGetTime() of the last key, drag, wheel, click or drop taken
  double fps = 0, fpsSince = glfwGetTime();
  int fpsFrame = 0;
  int frame = 0;
  // --frames N counts the frames drawn once the first measurement is in (the
  // start-up's frames while it runs vary with the machine's load).
  int counted = 0;
  double now = 0, last = glfwGetTime();
  WindowSplit split;  // where the figure, the side panel and the GL pane go
};
}  // namespace ts::window_parts
