#include "window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "context.hpp"
#include "error.hpp"
#include "gl.hpp"
#include "gl_pane.hpp"
#include "render.hpp"

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

struct Input {
  std::string keys;  // characters typed since the last frame
  bool quit = false;
  bool overlay = true;
};

void onChar(GLFWwindow* w, unsigned int cp) {
  auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
  if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard) return;
  if (cp < 128) in->keys += char(cp);
}
void onKey(GLFWwindow* w, int key, int, int action, int) {
  auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
  if (action == GLFW_PRESS && key == GLFW_KEY_ESCAPE) in->quit = true;
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
}  // namespace

int runWindow(Scene& scene, Options& opts, const CommonFlags& flags, int width, int height) {
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
  GLFWwindow* win = glfwCreateWindow(width, height, scene.title().c_str(), nullptr, nullptr);
  if (!win) {
    glfwTerminate();
    throw Error("cannot open a " + std::to_string(width) + "x" + std::to_string(height) + " window (" + g_glfwError +
                "); render offscreen with --png FILE");
  }
  glfwMakeContextCurrent(win);
  glfwSwapInterval(flags.frames ? 0 : 1);
  std::string missing;
  if (!gl::load(glfwProc, &missing)) {
    glfwDestroyWindow(win);
    glfwTerminate();
    throw Error("the window's OpenGL context lacks " + missing);
  }
  Input input;
  input.keys = flags.keys;
  glfwSetWindowUserPointer(win, &input);
  glfwSetCharCallback(win, onChar);
  glfwSetKeyCallback(win, onKey);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the student's folder
  ImGui_ImplGlfw_InitForOpenGL(win, true);  // chains to the callbacks above
  GLuint fontTex = 0;
  {
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
  }

  WindowContext ctx(win);
  Renderer renderer(ctx);
  std::printf("%s | %s\nkeys: %s  h: overlay  l: OpenGL calls  esc/q: quit\n", scene.title().c_str(),
              ctx.describe().c_str(), opts.keysText().c_str());
  Measurements m;
  bool dirty = true;
  GlPane pane;
  bool record = false, afterKey = false;  // the GL pane needs a new recording
  int recordedW = 0, recordedH = 0;
  int frame = 0;
  double last = glfwGetTime();
  int status = kExitOk;
  try {
    while (!glfwWindowShouldClose(win) && !input.quit) {
      glfwPollEvents();
      // One synthesised or typed key per frame, through the same handler.
      if (!input.keys.empty()) {
        char k = input.keys.front();
        input.keys.erase(0, 1);
        if (k == 'q') input.quit = true;
        else if (k == 'h') input.overlay = !input.overlay;
        else if (k == 'l') pane.visible = !pane.visible, record = pane.visible, afterKey = false;
        else if (opts.handleKey(k)) dirty = true, record = pane.visible, afterKey = true;
      }
      double now = glfwGetTime();
      scene.update(now - last);
      last = now;
      ctx.sync();
      if (ctx.width() < 1 || ctx.height() < 1) continue;  // minimised
      if (dirty || scene.live()) {
        m = scene.measure(renderer);
        if (dirty) {
          std::printf("%s\n%s", opts.stateText().c_str(), formatMeasurements(m).c_str());
          std::fflush(stdout);
        }
        dirty = false;
      }
      // With the GL pane open the figure is laid out in the rest of the window.
      int paneW = pane.visible ? glPaneWidth(ctx.width()) : 0;
      int figureW = std::max(1, ctx.width() - paneW);
      Frame f = scene.build(figureW, ctx.height());
      if (pane.visible && (record || figureW != recordedW || ctx.height() != recordedH)) {
        pane.record(renderer, f, afterKey, now, true);  // draws the picture, recording its calls
        record = afterKey = false;
        recordedW = figureW;
        recordedH = ctx.height();
      } else {
        renderer.draw(f);
      }
      ++frame;
      bool lastFrame = flags.frames && frame >= flags.frames && input.keys.empty();
      // The screenshot is the figure alone (it must match --png), unless
      // TS_SCREENSHOT_OVERLAY=1 asks for the window as the student sees it.
      const char* withOverlay = std::getenv("TS_SCREENSHOT_OVERLAY");
      bool overlayShot = withOverlay && *withOverlay == '1';
      if (lastFrame && !flags.screenshot.empty() && !overlayShot) writePng(flags.screenshot, ctx.readPixels());
      if (input.overlay || pane.visible) {
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
      }
      if (pane.visible) pane.draw(figureW, paneW, ctx.height(), now);
      if (input.overlay) {
        ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowBgAlpha(0.75f);
        ImGui::Begin(scene.title().c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize);
        for (const auto& [name, value] : opts.state()) ImGui::Text("%-14s %s", name.c_str(), value.c_str());
        ImGui::Separator();
        for (const auto& x : m) ImGui::Text("%-22s %10.4f", x.name.c_str(), x.value);
        ImGui::Separator();
        ImGui::TextWrapped("keys: %s  h: overlay  l: OpenGL calls  esc/q: quit", opts.keysText().c_str());
        ImGui::End();
      }
      if (input.overlay || pane.visible) {
        ImGui::Render();
        drawImGui(ImGui::GetDrawData(), ctx.width(), ctx.height());
      }
      if (lastFrame && !flags.screenshot.empty() && overlayShot) writePng(flags.screenshot, ctx.readPixels());
      gl::check("drawing the window");
      glfwSwapBuffers(win);
      if (lastFrame) break;
    }
  } catch (const Error&) {
    status = -1;
    renderer.release();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(win);
    glfwTerminate();
    throw;
  }
  renderer.release();
  glDeleteTextures(1, &fontTex);
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(win);
  glfwTerminate();
  return status;
}
}  // namespace ts
