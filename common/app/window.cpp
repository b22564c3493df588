// common/app/window.cpp — runWindow: opens the window and its GL context, runs the frame loop, closes them.
#include "common/app/window.hpp"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "common/app/window_parts.hpp"
#include "common/core/error.hpp"

namespace ts {
namespace window_parts {
namespace {
std::string g_glfwError;
void onGlfwError(int, const char* msg) { g_glfwError = msg ? msg : "unknown"; }
void* glfwProc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

// ---- The steps of runWindow that open and close the window, in its order ----
// (connectInput is in window_input.cpp, startImGui in window_overlay.cpp.)

// Opens a width x height window with a compatibility-profile GL context (an
// accumulation buffer where the demo wants one) and loads GL's entry points.
GLFWwindow* openWindow(Scene& scene, const CommonFlags& flags, int width, int height) {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit())
    throw Error("no display to open a window on (" + g_glfwError + "); render offscreen with --png FILE");
  // Any version >= 2.1 without a profile hint gives a compatibility context,
  // which the fixed-function demos need.
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  glfwWindowHint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  if (scene.wantsAccumBuffer()) {
    glfwWindowHint(GLFW_ACCUM_RED_BITS, 16);
    glfwWindowHint(GLFW_ACCUM_GREEN_BITS, 16);
    glfwWindowHint(GLFW_ACCUM_BLUE_BITS, 16);
    glfwWindowHint(GLFW_ACCUM_ALPHA_BITS, 16);
  }
  // Without --size, a screen smaller than the demo's default size (a
  // 640x480 projector, a 700-wide half screen) gets a window that fits it:
  // the figure and the panel lay themselves out in whatever they are given.
  if (!flags.width) {
    int x = 0, y = 0, w = 0, h = 0;
    if (GLFWmonitor* mon = glfwGetPrimaryMonitor()) glfwGetMonitorWorkarea(mon, &x, &y, &w, &h);
    if (w > 0 && h > 0) width = std::min(width, w), height = std::min(height, h);
  }
  GLFWwindow* win = glfwCreateWindow(width, height, scene.title().c_str(), nullptr, nullptr);
  if (!win) {
    glfwTerminate();
    throw Error("cannot open a " + std::to_string(width) + "x" + std::to_string(height) + " window (" + g_glfwError +
                "); render offscreen with --png FILE");
  }
  glfwMakeContextCurrent(win);
  glfwSwapInterval(flags.frames ? 0 : 1);  // --frames (tests) does not wait for the display's refresh
  std::string missing;
  if (!gl::load(glfwProc, &missing)) {
    glfwDestroyWindow(win);
    glfwTerminate();
    throw Error("the window's OpenGL context lacks " + missing);
  }
  return win;
}

// The first lines on stdout: the demo, the GL it runs on, and its keys.
void printGreeting(const Scene& scene, const Options& opts, const WindowContext& ctx) {
  std::printf("%s | %s\nkeys: %s  h: side panel  l: OpenGL calls  ?/F1: help  F12: save  Backspace: reset  "
              "arrows: turn/tilt  esc/q: quit\n",
              scene.title().c_str(), ctx.describe().c_str(), opts.keysText().c_str());
}

// Closes in the order the parts depend on: the worker stops, the renderer's
// GL objects (the demos' attachments among them) go while the window's
// context is current, then ImGui, the window and GLFW.  fontTex: the font
// atlas to delete (null after an error: it goes with the context).
void closeWindow(GLFWwindow* win, std::unique_ptr<Renderer>& renderer, std::unique_ptr<MeasureWorker>& worker,
                 const GLuint* fontTex) {
  worker->stop();  // a measurement still running stops at its next progress report
  renderer.reset();
  if (fontTex) glDeleteTextures(1, fontTex);
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(win);  // the window is gone at once ...
  glfwTerminate();
  worker.reset();  // ... and the process ends when the worker has let go
}
}  // namespace
}  // namespace window_parts

int runWindow(Scene& scene, Options& opts, const CommonFlags& flags, int width, int height) {
  using namespace window_parts;  // the parts in window_parts.hpp

  GLFWwindow* win = openWindow(scene, flags, width, height);  // the window and its GL context
  Input input;
  connectInput(win, flags, &input);  // keys, mouse, dropped files; --keys, TS_TEST_MOUSE
  GLuint fontTex = startImGui(win);  // the overlay's Dear ImGui and its font texture
  WindowContext ctx(win);
  auto renderer = std::make_unique<Renderer>(ctx);  // destroyed before the window, by closeWindow
  printGreeting(scene, opts, ctx);                  // the demo, its GL and its keys on stdout
  // Measurements run on a worker thread with a context of its own (see
  // measure_worker.hpp); the loop keeps drawing meanwhile.  If the worker
  // cannot make a context, the loop measures itself.
  auto worker = std::make_unique<MeasureWorker>(scene.id(), scene.wantsAccumBuffer(), glfwPostEmptyEvent);
  FrameLoop loop(scene, opts, flags, win, ctx, *renderer, worker.get(), input);
  try {
    while (loop.running()) {
      loop.waitForEvents();              // poll, or sleep while nothing needs a frame
      loop.applyMouse();                 // drag, wheel, dropped files
      loop.applyKey();                   // one typed or --keys key
      loop.advanceClock();               // animations, frames per second
      if (!loop.updateSize()) continue;  // minimised: nothing to draw
      loop.layOut();                     // figure | side panel | GL pane
      loop.startMeasuring();             // a changed state: measure here, or ask the worker
      loop.collectMeasurement();         // the worker's numbers, once in
      Frame f = loop.drawPicture();      // the figure (its GL calls recorded for the pane when needed)
      loop.saveIfAsked(f);               // F12
      loop.inspectPixel(f);              // key i: the clicked pixel's loupe and card
      bool last = loop.isLastFrame();    // --frames N reached (TS_TEST_RESIZE: resize and go on)
      loop.takeScreenshot(last, false);  // --screenshot of the figure alone ...
      loop.drawOverlay();                // side panel, GL pane, help card
      loop.takeScreenshot(last, true);   // ... or of the whole window (TS_SCREENSHOT_OVERLAY=1)
      loop.present();                    // swap buffers, frame log
      if (last) break;
    }
  } catch (const Error&) {
    closeWindow(win, renderer, worker, nullptr);  // then the error goes on to the demo's main
    throw;
  }
  closeWindow(win, renderer, worker, &fontTex);  // Esc, q, the close button or --frames N
  return kExitOk;
}
}  // namespace ts
