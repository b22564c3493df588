// common/app/window_input.cpp — the window's keys, mouse and dropped files, and the options they change.
#include <imgui.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/app/window_parts.hpp"
#include "common/core/error.hpp"
#include "common/core/orbit_camera.hpp"

namespace ts::window_parts {
namespace {
// Keys without a character travel in Input::keys as these codes, so typed
// keys and --keys take one path.
constexpr char kKeyReset = keys::kReset, kKeyHelp = keys::kHelp, kKeySave = keys::kSave, kKeyLeft = keys::kLeft,
               kKeyRight = keys::kRight, kKeyUp = keys::kUp, kKeyDown = keys::kDown;

// The mouse handlers, shared by GLFW's callbacks and the test hook below.
void mouseButton(Input* in, bool press, double x, double y) {
  if (press) in->pressX = x, in->pressY = y;
  else if (in->dragging && !in->lightDrag && std::abs(x - in->pressX) + std::abs(y - in->pressY) <= 2)
    in->clicked = true, in->clickX = x, in->clickY = y;
  in->dragging = press;
  in->lastX = x, in->lastY = y;
}
void mouseMove(Input* in, double x, double y) {
  if (in->dragging) {
    (in->lightDrag ? in->lightX : in->dragX) += x - in->lastX;
    (in->lightDrag ? in->lightY : in->dragY) += y - in->lastY;
  }
  in->lastX = x, in->lastY = y, in->knowPos = true;
}
void mouseWheel(Input* in, double clicks) { in->wheel += clicks; }
bool mouseTaken() { return ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse; }

void onMouseButton(GLFWwindow* w, int button, int action, int) {
  auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
  if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT) return;
  if (action == GLFW_PRESS && mouseTaken()) return;  // a drag on the overlay moves the overlay
  if (action == GLFW_PRESS) in->lightDrag = button == GLFW_MOUSE_BUTTON_RIGHT;
  // Where the pointer was at the last motion event, not where it is now: a
  // slow frame takes a whole drag's events at once, in order.
  if (!in->knowPos) glfwGetCursorPos(w, &in->lastX, &in->lastY), in->knowPos = true;
  mouseButton(in, action == GLFW_PRESS, in->lastX, in->lastY);
}
void onCursor(GLFWwindow* w, double x, double y) { mouseMove(static_cast<Input*>(glfwGetWindowUserPointer(w)), x, y); }
void onScroll(GLFWwindow* w, double, double dy) {
  if (!mouseTaken()) mouseWheel(static_cast<Input*>(glfwGetWindowUserPointer(w)), dy);
}
void onDrop(GLFWwindow* w, int n, const char** paths) {
  auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
  for (int i = 0; i < n; ++i) in->dropped.push_back(paths[i]);
}

// TS_TEST_MOUSE (common/core/test_hooks.hpp): mouse events given before the
// first frame, through the handlers above (xdotool drives the same ones
// through GLFW in a real X session).
void testMouse(Input* in) {
  for (const test_hooks::MouseEvent& m : test_hooks::mouseEvents()) {
    if (m.what == "press" || m.what == "rpress") in->lightDrag = m.what == "rpress", mouseButton(in, true, m.a, m.b);
    else if (m.what == "move") mouseMove(in, m.a, m.b);
    else if (m.what == "release") mouseButton(in, false, in->lastX, in->lastY);
    else if (m.what == "wheel") mouseWheel(in, m.a);
    else if (m.what == "drop") in->dropped.push_back(m.path);
  }
}

// The gathered drag and wheel as orbit options, by name (a demo without them
// does not move).  Degrees per pixel of drag; 10 % of zoom per wheel click.
// Values are rounded (0.1 degree, 0.001 zoom) so the printed state remakes
// exactly the same picture.
bool mouseToOptions(Input* in, Options& opts) {
  constexpr double kDegreesPerPixel = 0.4;
  bool changed = false;
  if (in->dragX != 0)
    changed |= opts.adjust(OrbitCamera::kYaw, [&](double v) {
      return std::round(std::remainder(v + in->dragX * kDegreesPerPixel, 360.0) * 10) / 10;
    });
  if (in->dragY != 0)
    changed |= opts.adjust(OrbitCamera::kPitch,
                           [&](double v) { return std::round((v + in->dragY * kDegreesPerPixel) * 10) / 10; });
  if (in->wheel != 0)
    changed |= opts.adjust(OrbitCamera::kZoom,
                           [&](double v) { return std::round(v * std::pow(1.1, in->wheel) * 1000) / 1000; });
  if (in->lightX != 0)
    changed |= opts.adjust("light1-az", [&](double v) {
      return std::round(std::remainder(v + in->lightX * kDegreesPerPixel, 360.0) * 10) / 10;
    });
  if (in->lightY != 0)
    changed |= opts.adjust("light1-el",
                           [&](double v) { return std::round((v - in->lightY * kDegreesPerPixel) * 10) / 10; });
  in->dragX = in->dragY = in->wheel = in->lightX = in->lightY = 0;
  return changed;
}

void onChar(GLFWwindow* w, unsigned int cp) {
  auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
  if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard) return;
  if (cp < 128) in->keys += char(cp);
}
void onKey(GLFWwindow* w, int key, int, int action, int) {
  auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  switch (key) {
    case GLFW_KEY_ESCAPE:  // closes the help card first, then the window
      if (action == GLFW_PRESS) (in->help ? in->help = false : in->quit = true);
      break;
    case GLFW_KEY_BACKSPACE: in->keys += kKeyReset; break;
    case GLFW_KEY_F1: in->keys += kKeyHelp; break;
    case GLFW_KEY_F12: in->keys += kKeySave; break;
    case GLFW_KEY_LEFT: in->keys += kKeyLeft; break;
    case GLFW_KEY_RIGHT: in->keys += kKeyRight; break;
    case GLFW_KEY_UP: in->keys += kKeyUp; break;
    case GLFW_KEY_DOWN: in->keys += kKeyDown; break;
    default: break;
  }
}
}  // namespace

// Sends the window's keys, mouse and dropped files to `in`, queues --keys,
// and replays TS_TEST_MOUSE, all before the first frame.
void connectInput(GLFWwindow* win, const CommonFlags& flags, Input* in) {
  in->keys = flags.keys;
  glfwSetWindowUserPointer(win, in);
  glfwSetCharCallback(win, onChar);
  glfwSetKeyCallback(win, onKey);
  glfwSetMouseButtonCallback(win, onMouseButton);
  glfwSetCursorPosCallback(win, onCursor);
  glfwSetScrollCallback(win, onScroll);
  glfwSetDropCallback(win, onDrop);
  testMouse(in);
}

// The mouse: a drag or the wheel turns the orbit options; a dropped file
// is --texture FILE (a bad one: one line, the picture stays).
void FrameLoop::applyMouse() {
  if (input.dragX != 0 || input.dragY != 0 || input.wheel != 0 || input.lightX != 0 || input.lightY != 0 ||
      input.clicked || !input.dropped.empty())
    lastAction = glfwGetTime();
  if (mouseToOptions(&input, opts)) dirty = true, record = pane.visible, keyChanged();
  for (const std::string& path : input.dropped) {
    if (!opts.has("texture")) {
      std::fprintf(stderr, "%s: %s: this demo maps no picture (--texture)\n", scene.id().c_str(), path.c_str());
      continue;
    }
    try {
      opts.set("texture", path);
      dirty = true, record = pane.visible, keyChanged();
    } catch (const Error& e) {
      std::fprintf(stderr, "%s: %s\n", scene.id().c_str(), e.what());
    }
  }
  input.dropped.clear();
  if (input.clicked && inspect.active()) inspect.click(input.clickX, input.clickY, split.figureW, ctx.height());
  else if (input.clicked && input.clickX >= 0 && input.clickX < split.figureW) clickScene();
  input.clicked = false;
}

// A click on the figure outside the inspect mode: the options the scene
// sets for it (Scene::click), as flags; a changed state is measured again.
void FrameLoop::clickScene() {
  const std::string before = opts.stateText();
  for (const auto& [name, value] : scene.click(int(input.clickX), int(input.clickY), split.figureW, ctx.height())) {
    try {
      opts.set(name, value);
    } catch (const Error& e) {
      std::fprintf(stderr, "%s: %s\n", scene.id().c_str(), e.what());
    }
  }
  if (opts.stateText() != before) {
    testLog.line("click", opts.stateText());
    dirty = true, record = pane.visible, keyChanged();
  }
}

// One synthesised or typed key per frame, through the same handler.
void FrameLoop::applyKey() {
  if (input.keys.empty() || !testLog.keyDue(measuring, worker->progress(), measuredOnce)) return;
  testLog.keyTaken();
  lastAction = glfwGetTime();
  char k = input.keys.front();
  testLog.line("key", std::string(1, std::isprint(static_cast<unsigned char>(k)) ? k : '?'));
  input.keys.erase(0, 1);
  // = is + (the same key without shift) where no option takes =.
  if (k == '=') {
    bool taken = false;
    for (const auto& it : opts.items()) taken |= it.key == '=' || it.keyDown == '=';
    if (!taken) k = '+';
  }
  if (k == kKeyLeft || k == kKeyRight) k = opts.keyOf({"turn", "rotation", "azimuth"}, k == kKeyRight);
  else if (k == kKeyUp || k == kKeyDown) k = opts.keyOf({"tilt", "angle", "elevation"}, k == kKeyUp);
  if (k == 'q') input.quit = true;
  else if (k == 'h') input.overlay = !input.overlay;
  else if (k == '?' || k == kKeyHelp) input.help = !input.help;
  else if (k == kKeySave) savePending = true;
  else if (k == 'l') pane.visible = !pane.visible, record = pane.visible;
  else if (k == inspect.key()) inspect.toggle();
  else if (k == kKeyReset) opts.resetToDefaults(), dirty = true, record = pane.visible, keyChanged();
  else if (opts.handleKey(k)) dirty = true, record = pane.visible, keyChanged();
}

// A key or the mouse changed the state: the GL pane marks what the next
// pictures draw differently from the listing before it.
void FrameLoop::keyChanged() {
  if (pane.visible) pane.keyPressed(glfwGetTime());
}
}  // namespace ts::window_parts
