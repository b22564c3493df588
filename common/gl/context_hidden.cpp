// The hidden-window backend: a GLFW window that is never shown, whose
// context renders into a framebuffer object of the requested size (the
// window's own framebuffer may be smaller than the picture, and a hidden
// window's may not be drawn at all).  It needs only what the window needs:
// on Windows it is the one offscreen backend (no OSMesa or EGL there); on
// Linux it needs a display (X or Xvfb) and is what --backend auto ends at
// when neither OSMesa nor EGL loads.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <memory>
#include <string>

#include "common/core/error.hpp"
#include "common/gl/context.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render_target.hpp"

namespace ts {
namespace {
std::string g_hiddenError;
void onHiddenGlfwError(int, const char* msg) { g_hiddenError = msg ? msg : "unknown"; }
void* hiddenProc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

class HiddenContext final : public Context {
 public:
  HiddenContext(GLFWwindow* w, bool ownsGlfw, int width, int height)
      : win_(w), ownsGlfw_(ownsGlfw), wantW_(width), wantH_(height) {}
  ~HiddenContext() override {
    if (glfwGetCurrentContext() == win_) {
      target_.free();  // while the context is current
      glfwMakeContextCurrent(nullptr);
    }
    glfwDestroyWindow(win_);
    if (ownsGlfw_) glfwTerminate();
  }
  void adopt() override {
    glfwMakeContextCurrent(win_);
    std::string missing;
    if (!gl::load(hiddenProc, &missing) || !gl::p_glGenFramebuffers)
      throw Error("the hidden window's context lacks " +
                  (missing.empty() ? std::string("framebuffer objects") : missing));
    gl::enableDebugOutput();
    resize(wantW_, wantH_);
  }
  void detach() override {
    if (glfwGetCurrentContext() != win_) return;
    target_.free();
    glfwMakeContextCurrent(nullptr);
  }
  Backend backend() const override { return Backend::Hidden; }
  void resize(int w, int h) override {
    target_.make({w, h}, "the hidden window's context");
    glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer());
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    gl::check("creating the hidden window's framebuffer");
    width_ = w;
    height_ = h;
  }
  void bindTarget() override { glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer()); }

 private:
  GLFWwindow* win_;
  bool ownsGlfw_;
  int wantW_, wantH_;  // the target adopt() makes
  RenderTarget target_;
};
}  // namespace

std::unique_ptr<Context> createHiddenContext(const ContextOptions& o, std::string* why, bool forAnotherThread) {
  if (glLibraryHidden("hidden")) {
    *why = "hidden windows hidden by TS_HIDE_GL_LIBS";
    return nullptr;
  }
  // A program that already has GLFW running (a window open) keeps it: only
  // a context that started GLFW ends it.
  GLFWerrorfun previous = glfwSetErrorCallback(onHiddenGlfwError);
  const bool running = glfwGetCurrentContext() != nullptr;
  g_hiddenError.clear();
  if (!running && !glfwInit()) {
    *why = "no display to open a hidden window on (" + g_hiddenError + ")";
    glfwSetErrorCallback(previous);
    return nullptr;
  }
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  glfwWindowHint(GLFW_FOCUSED, GLFW_FALSE);
  // 2.1 and no profile: a compatibility context, as the window gets.
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  GLFWwindow* win = glfwCreateWindow(16, 16, "texture suite (hidden)", nullptr, nullptr);
  glfwDefaultWindowHints();
  if (!win) {
    *why = "cannot open a hidden window (" + g_hiddenError + ")";
    if (!running) glfwTerminate();
    glfwSetErrorCallback(previous);
    return nullptr;
  }
  glfwSetErrorCallback(previous);
  std::unique_ptr<HiddenContext> c(new HiddenContext(win, !running, o.width, o.height));
  if (forAnotherThread) return c;  // adopt() on that thread does the rest
  glfwMakeContextCurrent(win);
  std::string missing;
  if (!gl::load(hiddenProc, &missing) || !gl::p_glGenFramebuffers) {
    *why = "the hidden window's context lacks " + (missing.empty() ? std::string("framebuffer objects") : missing);
    return nullptr;
  }
  gl::enableDebugOutput();
  (void)o.accumBuffer;  // a framebuffer object has no accumulation buffer, as EGL's
  c->resize(o.width, o.height);
  return c;
}
}  // namespace ts
