#include "common/app/window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

#include <algorithm>
#include <sys/stat.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/gl/context.hpp"
#include "common/core/error.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/figure.hpp"
#include "common/app/gl_pane.hpp"
#include "common/app/inspect_mode.hpp"
#include "common/app/measure_worker.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/app/side_panel.hpp"
#include "common/core/sidecar.hpp"
#include "common/core/test_hooks.hpp"
#include "common/gl/render.hpp"

namespace ts {
namespace {
std::string g_glfwError;
void onGlfwError(int, const char* msg) { g_glfwError = msg ? msg : "unknown"; }
void* glfwProc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

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

// Keys without a character travel in Input::keys as these codes, so typed
// keys and --keys take one path.
constexpr char kKeyReset = keys::kReset, kKeyHelp = keys::kHelp, kKeySave = keys::kSave, kKeyLeft = keys::kLeft,
               kKeyRight = keys::kRight, kKeyUp = keys::kUp, kKeyDown = keys::kDown;

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

// The mouse handlers, shared by GLFW's callbacks and the test hook below.
void mouseButton(Input* in, bool press, double x, double y) {
  if (press) in->pressX = x, in->pressY = y;
  else if (in->dragging && !in->lightDrag && std::abs(x - in->pressX) + std::abs(y - in->pressY) <= 2)
    in->clicked = true, in->clickX = x, in->clickY = y;
  in->dragging = press;
  in->lastX = x, in->lastY = y;
}
void mouseMove(Input* in, double x, double y) {
  if (in->dragging) (in->lightDrag ? in->lightX : in->dragX) += x - in->lastX, (in->lightDrag ? in->lightY : in->dragY) += y - in->lastY;
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
    changed |= opts.adjust(OrbitCamera::kZoom, [&](double v) { return std::round(v * std::pow(1.1, in->wheel) * 1000) / 1000; });
  if (in->lightX != 0)
    changed |= opts.adjust("light1-az", [&](double v) {
      return std::round(std::remainder(v + in->lightX * kDegreesPerPixel, 360.0) * 10) / 10;
    });
  if (in->lightY != 0)
    changed |= opts.adjust("light1-el", [&](double v) { return std::round((v - in->lightY * kDegreesPerPixel) * 10) / 10; });
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

// F12: the window's picture as PNG + sidecar under a name not yet taken
// (<demo>-<n>.png in the working folder), and the command that remakes it.
void saveState(Scene& scene, const Options& opts, const Frame& f, const Image& window, const std::vector<std::string>& extra) {
  std::string base;
  for (int n = 1; n < 10000; ++n) {
    base = scene.id() + "-" + std::to_string(n);
    struct stat st;
    if (::stat((base + ".png").c_str(), &st) != 0 && ::stat((base + ".json").c_str(), &st) != 0) break;
  }
  Image picture(f.width, f.height);  // the figure's part of the window (the GL pane takes the rest)
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) picture.set(x, y, window.at(x, y));
  std::vector<std::string> flags = {"--json", base + ".json"};
  for (const std::string& s : opts.stateFlags()) flags.push_back(s);
  for (const std::string& s : extra) flags.push_back(s);  // the inspect mode's pick
  SidecarInfo info;
  info.demo = scene.id();
  info.figureId = base;
  info.caption = scene.title();
  info.command = figureCommand(scene.id(), base + ".png", f.width, f.height, flags);
  info.state = opts.state();
  info.renderer = gl::rendererString() + " | " + gl::versionString();
  writePng(base + ".png", picture);
  writeFileAtomic(base + ".json", sidecarJson(f, info));
  std::printf("saved %s.png and %s.json; remake them with:\n  %s\n", base.c_str(), base.c_str(), info.command.c_str());
  std::fflush(stdout);
}

// The help card (? or F1): the figure's claim, what to look for, every key.
void drawHelp(Scene& scene, const Options& opts, int w, int h, bool* open, char inspectKey) {
  float cw = std::min(float(w) - 40.0f, 720.0f), ch = std::min(float(h) - 40.0f, 560.0f);
  ImGui::SetNextWindowPos(ImVec2((float(w) - cw) / 2, (float(h) - ch) / 2), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(cw, ch), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.95f);
  ImGui::Begin("Help (? or F1 or Esc closes it)", open, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                              ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
  ImGui::TextWrapped("%s", scene.title().c_str());
  ImGui::Separator();
  std::string about = scene.about();  // single line breaks of the source are spaces here
  for (size_t k = 0; k + 1 < about.size(); ++k)
    if (about[k] == '\n' && about[k + 1] != '\n' && (k == 0 || about[k - 1] != '\n')) about[k] = ' ';
  ImGui::TextWrapped("%s", about.c_str());
  ImGui::Separator();
  ImGui::TextUnformatted("The demo's keys (each is also a flag: --help lists them):");
  for (const auto& it : opts.items()) {
    if (!it.key && !it.keyDown) continue;
    std::string keys = it.keyDown ? std::string(1, it.key) + "/" + std::string(1, it.keyDown) : std::string(1, it.key);
    ImGui::Bullet();
    ImGui::TextWrapped("%s  %s: %s", keys.c_str(), it.name.c_str(), it.help.c_str());
  }
  ImGui::Separator();
  ImGui::TextWrapped("Window keys: arrows turn and tilt (where the demo has them), = acts as +, Backspace resets every "
                     "option, a left drag orbits and the wheel zooms (3D views: --yaw, --pitch, --zoom), a picture file dropped on "
                     "the window is mapped (--texture), F12 saves the picture and its sidecar and prints the command that remakes them, l shows "
                     "the OpenGL calls beside the picture, h hides the side panel, ? or F1 this card, Esc or q quits.");
  ImGui::TextWrapped("%c inspects a pixel: click one of the figure, and the side panel shows it magnified and what happens "
                     "inside it: (s,t,r,q), the derivatives, rho, lambda, the mip levels, the texels read and their weights, "
                     "the reference's colour beside GL's, and its footprint on the texture (also in a texture-space view, where the "
                     "demo has one); with the GL pane open (l), the calls that set its texture turn cyan (--inspect X,Y "
                     "does it from the command line).",
                     inspectKey);
  if (opts.has("pixel"))
    ImGui::TextWrapped("Outside the inspect mode a click on a raster picks its pixel (--pixel X,Y).");
  if (opts.has("light1-az") && opts.has("light1-el"))
    ImGui::TextWrapped("A right drag moves light 1 (--light1-az left and right, --light1-el up and down).");
  ImGui::End();
}

// Dear ImGui's draw lists, drawn with fixed-function vertex arrays through
// the suite's own GL pointers (the stock OpenGL backends bind GL themselves).
void drawImGui(ImDrawData* d, int fbw, int fbh) {
  glPushAttrib(GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT | GL_TRANSFORM_BIT | GL_SCISSOR_BIT | GL_TEXTURE_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glViewport(0, 0, fbw, fbh);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glOrtho(d->DisplayPos.x, d->DisplayPos.x + d->DisplaySize.x, d->DisplayPos.y + d->DisplaySize.y, d->DisplayPos.y,
          -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  ImVec2 scale = d->FramebufferScale;
  for (int n = 0; n < d->CmdListsCount; ++n) {
    const ImDrawList* list = d->CmdLists[n];
    const ImDrawVert* vb = list->VtxBuffer.Data;
    const ImDrawIdx* ib = list->IdxBuffer.Data;
    glVertexPointer(2, GL_FLOAT, sizeof(ImDrawVert), &vb->pos);
    glTexCoordPointer(2, GL_FLOAT, sizeof(ImDrawVert), &vb->uv);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(ImDrawVert), &vb->col);
    for (const ImDrawCmd& c : list->CmdBuffer) {
      if (c.UserCallback) continue;
      float x0 = (c.ClipRect.x - d->DisplayPos.x) * scale.x, y0 = (c.ClipRect.y - d->DisplayPos.y) * scale.y;
      float x1 = (c.ClipRect.z - d->DisplayPos.x) * scale.x, y1 = (c.ClipRect.w - d->DisplayPos.y) * scale.y;
      if (x1 <= x0 || y1 <= y0) continue;
      glScissor(int(x0), int(float(fbh) - y1), int(x1 - x0), int(y1 - y0));
      glBindTexture(GL_TEXTURE_2D, GLuint(reinterpret_cast<intptr_t>(c.GetTexID())));
      glDrawElements(GL_TRIANGLES, GLsizei(c.ElemCount), sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT,
                     ib + c.IdxOffset);
    }
  }
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glMatrixMode(GL_MODELVIEW);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glPopAttrib();
}

// ---- The steps of runWindow, in the order it takes them ----

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

// Starts Dear ImGui on the window (side panel, GL pane, help card) and
// uploads its font atlas; returns that texture, which closeWindow deletes.
GLuint startImGui(GLFWwindow* win) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the student's folder
  ImGui_ImplGlfw_InitForOpenGL(win, true);  // chains to the callbacks of connectInput
  GLuint fontTex = 0;
  unsigned char* px = nullptr;
  int w = 0, h = 0;
  ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&px, &w, &h);
  glGenTextures(1, &fontTex);
  glBindTexture(GL_TEXTURE_2D, fontTex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  ImGui::GetIO().Fonts->SetTexID(reinterpret_cast<ImTextureID>(intptr_t(fontTex)));
  return fontTex;
}

// The first lines on stdout: the demo, the GL it runs on, and its keys.
void printGreeting(const Scene& scene, const Options& opts, const WindowContext& ctx) {
  std::printf("%s | %s\nkeys: %s  h: side panel  l: OpenGL calls  ?/F1: help  F12: save  Backspace: reset  "
              "arrows: turn/tilt  esc/q: quit\n",
              scene.title().c_str(),
              ctx.describe().c_str(), opts.keysText().c_str());
}

// The frame loop: what it carries from one frame to the next, and a method
// per step of a frame, declared in the order runWindow calls them.
class FrameLoop {
 public:
  FrameLoop(Scene& sc, Options& op, const CommonFlags& fl, GLFWwindow* w, WindowContext& c, Renderer& r,
            MeasureWorker* wk, Input& in)
      : scene(sc), opts(op), flags(fl), win(w), ctx(c), renderer(r), worker(wk), input(in) {}

  // Until Esc, q or the window's close button.
  bool running() const { return !glfwWindowShouldClose(win) && !input.quit; }

  // Polls the events, or sleeps until one comes while nothing needs a frame.
  void waitForEvents() {
    // Idle is idle: with nothing animating, no key waiting and no test
    // counting frames, wait for an event instead of drawing again (while a
    // changed line of the GL pane is highlighted, wake to fade it).
    // While a measurement runs (and nothing else asks for frames) the loop
    // draws about 30 frames a second for the progress, leaving the cores to
    // the worker; --frames (tests) counts those frames too.
    // A --keys key may wait for an event (TS_TEST_KEY_WHEN) or a time
    // (TS_TEST_KEY_INTERVAL_MS): the loop then waits instead of spinning.
    bool keyReady = !input.keys.empty() && testLog.keyDue(measuring, worker->progress(), measuredOnce);
    double keyWait = input.keys.empty() ? 0.0 : testLog.untilKey();
    busy = dirty || redraw || scene.live() || keyReady || !input.dropped.empty() ||
           (flags.frames && !measuring && input.keys.empty());
    if (busy) glfwPollEvents();
    else if (keyWait > 0) glfwWaitEventsTimeout(measuring ? std::min(keyWait, 1.0 / 30) : keyWait);
    else if (measuring || !input.keys.empty()) glfwWaitEventsTimeout(1.0 / 30);  // the progress moves; the worker wakes us when done
    else if (scene.animating()) glfwWaitEventsTimeout(0.05);  // an animation that steps now and then
    else if (pane.visible && glfwGetTime() < pane.marksUntil() + 0.1)  // the marks fade on time
      glfwWaitEventsTimeout(0.25);
    else
      glfwWaitEvents();
    redraw = false;
  }

  // The mouse: a drag or the wheel turns the orbit options; a dropped file
  // is --texture FILE (a bad one: one line, the picture stays).
  void applyMouse() {
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
  void clickScene() {
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
  void applyKey() {
    if (input.keys.empty() || !testLog.keyDue(measuring, worker->progress(), measuredOnce)) return;
    testLog.keyTaken();
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
  void keyChanged() {
    if (pane.visible) pane.keyPressed(glfwGetTime());
  }

  // The scene's clock (animations) and the frames per second.
  void advanceClock() {
    now = glfwGetTime();
    std::string stateBefore = opts.stateText();
    scene.update(now - last);
    if (opts.stateText() != stateBefore) redraw = true;  // an animation moved: keep drawing
    last = now;
    // Frames per second over the last half second of frames drawn.
    if (now - fpsSince >= 0.5) {
      fps = double(frame - fpsFrame) / (now - fpsSince);
      fpsSince = now;
      fpsFrame = frame;
    }
  }

  // Takes the window's size now; false while it is minimised.
  bool updateSize() {
    ctx.sync();
    return ctx.width() >= 1 && ctx.height() >= 1;
  }

  // The side panel and the GL pane dock right of the figure, which is laid
  // out in the rest of the window: nothing covers it.
  void layOut() {
    split = splitWindow(ctx.width(), input.overlay, pane.visible);
    renderer.setPictureSize(split.figureW, ctx.height());  // a live view draws at the figure's size
  }

  // Measures a changed state: here (a live view, or a worker without a
  // context) or by a request to the worker.
  void startMeasuring() {
    if (worker->failed() && !measureHere) {  // no context for the worker: measure here, as before
      note("note: measuring in the window's thread (" + worker->failure() + ")");
      measureHere = true;
      dirty |= measuring;
      measuring = false;
    }
    int figureW = split.figureW;
    // The numbers belong to the picture at its size (as --png at that size
    // measures them): a resized figure is measured again.
    if (!scene.live() && measuredW && (figureW != measuredW || ctx.height() != measuredH)) dirty = true;
    if (scene.live() || (dirty && measureHere)) {
      if (measuring) worker->cancel(), measuring = false;  // a live view measures every frame itself
      m = scene.measure(renderer);
      measuredOnce = true;
      measuredW = figureW, measuredH = ctx.height();
      if (dirty) {
        std::printf("%s\n%s", opts.stateText().c_str(), formatMeasurements(m).c_str());
        std::fflush(stdout);
      }
      dirty = false;
    } else if (dirty) {
      worker->request(opts.stateFlags(), figureW, ctx.height());  // measured at the figure's size, as --png
      measuredW = figureW, measuredH = ctx.height();
      measuring = true;
      dirty = false;
    }
  }

  // Takes the worker's numbers once they are in, and prints them.
  void collectMeasurement() {
    MeasureWorker::Result res;
    if (scene.live() || !worker->take(&res)) return;
    if (!res.error.empty()) throw Error(res.error, res.errorCode);  // as if measured here
    m = std::move(res.measured);
    measuredOnce = true;
    testLog.line("result");
    if (pane.visible) record = resultIn = true;  // the picture with the new numbers: its calls again
    measuring = worker->busy();
    std::printf("%s\n%s", res.stateText.c_str(), formatMeasurements(m).c_str());
    std::fflush(stdout);
  }

  // Draws the figure, recording its GL calls when the GL pane needs a new
  // listing, and counts the frame.
  Frame drawPicture() {
    int figureW = split.figureW;
    Frame f = scene.build(figureW, ctx.height(), m);
    if (pane.visible && (record || figureW != recordedW || ctx.height() != recordedH)) {
      pane.record(renderer, f, now, true, resultIn);  // draws the picture, recording its calls
      record = resultIn = false;
      recordedW = figureW;
      recordedH = ctx.height();
    } else {
      renderer.draw(f);
    }
    ++frame;
    if (measuredOnce) ++counted;
    return f;
  }

  // F12 while measuring saves when the numbers are in: the picture, its
  // sidecar and the command that remakes them must agree.
  void saveIfAsked(const Frame& f) {
    if (!savePending || measuring) return;
    std::vector<std::string> pick;  // the inspect mode's pick goes into the command
    if (!inspect.flag().empty()) pick = {"--inspect", inspect.flag().substr(11)};
    saveState(scene, opts, f, ctx.readPixels(), pick), savePending = false;
  }

  // The inspect mode's card, again when the pick, the state or its numbers
  // changed (read from the figure just drawn, before the overlay).
  void inspectPixel(const Frame& f) {
    const std::string state = opts.stateText() + "|" + std::to_string(f.width) + "x" + std::to_string(f.height) + "|" +
                              std::to_string(m.size()) + (measuring ? "|measuring" : "");
    const bool inspected = inspect.update(renderer, f, state != inspectedState);
    inspectedState = state;
    // The GL pane marks the picked batch's texture calls: listed again on every
    // pick (the same batch's too: the marks are printed again), and when the
    // mode is turned off (-1: none).
    if (inspected || inspect.batchOrdinal() != pane.pickedOrdinal())
      pane.pick(inspect.batchOrdinal()), record = redraw = pane.visible;
  }

  // --frames N (tests): the last frame shows the measurement of the last
  // state.  TS_TEST_RESIZE (tests): at what would be the last frame, keep
  // that frame as <screenshot>.WxH.png, resize to the next size and go on.
  bool isLastFrame() {
    bool lastFrame = flags.frames && counted >= flags.frames && input.keys.empty() && !measuring && !dirty && !savePending;
    if (lastFrame && resizing && !flags.screenshot.empty())
      writePng(test_hooks::sizedName(flags.screenshot, ctx.width(), ctx.height()), ctx.readPixels());
    if (lastFrame && !resizes.empty()) {
      glfwSetWindowSize(win, resizes.front().first, resizes.front().second);
      resizes.erase(resizes.begin());
      counted = 0;
      return false;
    }
    return lastFrame;
  }

  // --screenshot on the last frame, called before and after the overlay is
  // drawn: the figure alone (it must match --png), unless
  // TS_SCREENSHOT_OVERLAY=1 asks for the window as the student sees it.
  void takeScreenshot(bool lastFrame, bool overlayDrawn) {
    if (!lastFrame || flags.screenshot.empty()) return;
    if (test_hooks::screenshotWithOverlay() == overlayDrawn) writePng(flags.screenshot, ctx.readPixels());
  }

  // The side panel, the GL pane and the help card (Dear ImGui), each if open.
  void drawOverlay() {
    inspect.drawFootprint(renderer);  // key i: the pick's footprint in the figure's texture-space views
    bool imgui = input.overlay || pane.visible || input.help;
    if (imgui) {
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
    }
    if (pane.visible) pane.draw(split.paneX, split.paneW, ctx.height(), now);
    if (input.overlay) {
      PanelStatus status;
      status.fps = fps;
      status.idle = !busy && !measuring;
      // The measurement's status: running, how far, and whether the numbers shown are an older state's.
      status.measuring = measuring;
      status.progress = measuring ? worker->progress() : 0.0;
      status.stale = measuring && !m.empty();
      drawSidePanel(scene, opts, m, status, split.panelX, split.panelW, ctx.height(),
                    [&] { inspect.drawPanel(float(split.panelW)); });
    }
    if (input.help) drawHelp(scene, opts, ctx.width(), ctx.height(), &input.help, inspect.key());
    if (imgui) {
      ImGui::Render();
      drawImGui(ImGui::GetDrawData(), ctx.width(), ctx.height());
    }
  }

  // Shows the frame, and logs it for the test hooks.
  void present() {
    gl::check("drawing the window");
    glfwSwapBuffers(win);
    char progress[32];
    std::snprintf(progress, sizeof progress, "%d %.3f", measuring ? 1 : 0, measuring ? worker->progress() : 1.0);
    testLog.line("frame", progress);
    test_hooks::frameDrawn();
  }

 private:
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
  test_hooks::KeyLog testLog;  // TS_TEST_FRAME_LOG, TS_TEST_KEY_WHEN
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
  bool redraw = true;  // draw again without waiting for an event
  bool busy = false;   // this frame was drawn without waiting for an event
  double fps = 0, fpsSince = glfwGetTime();
  int fpsFrame = 0;
  int frame = 0;
  // --frames N counts the frames drawn once the first measurement is in (the
  // start-up's frames while it runs vary with the machine's load).
  int counted = 0;
  double now = 0, last = glfwGetTime();
  WindowSplit split;  // where the figure, the side panel and the GL pane go
};

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

int runWindow(Scene& scene, Options& opts, const CommonFlags& flags, int width, int height) {
  GLFWwindow* win = openWindow(scene, flags, width, height);  // the window and its GL context
  Input input;
  connectInput(win, flags, &input);  // keys, mouse, dropped files; --keys, TS_TEST_MOUSE
  GLuint fontTex = startImGui(win);  // the overlay's Dear ImGui and its font texture
  WindowContext ctx(win);
  auto renderer = std::make_unique<Renderer>(ctx);  // destroyed before the window, by closeWindow
  printGreeting(scene, opts, ctx);  // the demo, its GL and its keys on stdout
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
