// OSMesa and EGL-surfaceless contexts.  Both libraries are opened with
// dlopen(), not linked, so that (a) a machine without OSMesa (Mesa >= 25.1)
// still runs every program through EGL, and (b) no GL entry point binds at
// link time (see gl.hpp for why).  Windows and macOS have neither library:
// there the hidden-window backend (context_hidden.cpp) is the only offscreen
// one, and the dlopen code below is compiled out (TS_HAVE_DLOPEN_BACKENDS).
#if !defined(_WIN32) && !defined(__APPLE__)
#define TS_HAVE_DLOPEN_BACKENDS 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#endif

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "common/gl/context.hpp"
#include "common/core/error.hpp"
#include "common/gl/gl.hpp"
#include "common/gl/render_target.hpp"
#include "common/core/test_hooks.hpp"

namespace ts {
Backend parseBackend(const std::string& name) {
  if (name == "auto") return Backend::Auto;
  if (name == "osmesa") return Backend::OSMesa;
  if (name == "egl") return Backend::EGL;
  if (name == "hidden") return Backend::Hidden;
  if (name == "window") return Backend::Window;
  throw Error("unknown backend '" + name + "' (expected osmesa, egl, hidden, window or auto)");
}

const char* backendName(Backend b) {
  switch (b) {
    case Backend::Auto: return "auto";
    case Backend::OSMesa: return "osmesa";
    case Backend::EGL: return "egl";
    case Backend::Hidden: return "hidden";
    case Backend::Window: return "window";
  }
  return "?";
}

Image Context::readPixels() const {
  Image img(width_, height_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
  gl::check("glReadPixels");
  img.flipVertical();  // GL's row 0 is the bottom one
  return img;
}

std::string Context::describe() const {
  return std::string(backendName(backend())) + " | " + gl::versionString() + " | " + gl::rendererString();
}

// A library a test hides (test_hooks.hpp) is taken as not installed, so the
// fallback and the "install these packages" paths run on a machine that has
// everything.
bool glLibraryHidden(const char* lib) { return test_hooks::glLibraryHidden(lib); }

#if TS_HAVE_DLOPEN_BACKENDS
namespace {
bool hidden(const char* lib) { return glLibraryHidden(lib); }

// ---------------------------------------------------------------- OSMesa
// Values from GL/osmesa.h (stable ABI); spelled out so that the suite builds
// where the header is gone too.
constexpr int kOsmesaFormat = 0x22, kOsmesaDepthBits = 0x30, kOsmesaStencilBits = 0x31, kOsmesaAccumBits = 0x32,
              kOsmesaProfile = 0x33, kOsmesaCompatProfile = 0x35;
using OSMesaContextHandle = void*;
using PfnCreateAttribs = OSMesaContextHandle (*)(const int*, OSMesaContextHandle);
using PfnDestroy = void (*)(OSMesaContextHandle);
using PfnMakeCurrent = unsigned char (*)(OSMesaContextHandle, void*, GLenum, GLsizei, GLsizei);
using PfnGetProc = void* (*)(const char*);

PfnGetProc g_osmesaGetProc = nullptr;
void* osmesaProc(const char* name) { return g_osmesaGetProc(name); }

class OSMesaContext final : public Context {
 public:
  static std::unique_ptr<Context> create(const ContextOptions& o, std::string* why) {
    void* lib = hidden("osmesa") ? nullptr : dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (!lib && !hidden("osmesa")) lib = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
      *why = hidden("osmesa") ? "libOSMesa.so.8 hidden by TS_HIDE_GL_LIBS" : "libOSMesa.so.8 not found";
      return nullptr;
    }
    auto create = reinterpret_cast<PfnCreateAttribs>(dlsym(lib, "OSMesaCreateContextAttribs"));
    auto destroy = reinterpret_cast<PfnDestroy>(dlsym(lib, "OSMesaDestroyContext"));
    auto make = reinterpret_cast<PfnMakeCurrent>(dlsym(lib, "OSMesaMakeCurrent"));
    auto getProc = reinterpret_cast<PfnGetProc>(dlsym(lib, "OSMesaGetProcAddress"));
    if (!create || !destroy || !make || !getProc) {
      *why = "libOSMesa lacks OSMesaCreateContextAttribs";
      return nullptr;
    }
    const int attribs[] = {
        kOsmesaFormat,          GL_RGBA,        kOsmesaDepthBits,     24, kOsmesaStencilBits, 8, kOsmesaAccumBits,
        o.accumBuffer ? 16 : 0, kOsmesaProfile, kOsmesaCompatProfile, 0};
    OSMesaContextHandle ctx = create(attribs, nullptr);
    if (!ctx) {
      *why = "OSMesaCreateContextAttribs failed";
      return nullptr;
    }
    std::unique_ptr<OSMesaContext> c(new OSMesaContext(ctx, destroy, make, o.accumBuffer));
    c->resize(o.width, o.height);
    g_osmesaGetProc = getProc;
    std::string missing;
    if (!gl::load(osmesaProc, &missing)) {
      *why = "OSMesa context lacks " + missing;
      return nullptr;
    }
    gl::enableDebugOutput();
    return c;
  }
  ~OSMesaContext() override { destroy_(ctx_); }
  Backend backend() const override { return Backend::OSMesa; }
  bool hasAccumBuffer() const override { return accum_; }
  void resize(int w, int h) override {
    buffer_.assign(size_t(w) * size_t(h) * 4, 0);
    if (!make_(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, w, h))
      throw Error("OSMesaMakeCurrent failed for " + std::to_string(w) + "x" + std::to_string(h), kExitFailure);
    width_ = w;
    height_ = h;
  }

 private:
  OSMesaContext(OSMesaContextHandle c, PfnDestroy d, PfnMakeCurrent m, bool accum)
      : ctx_(c), destroy_(d), make_(m), accum_(accum) {}
  OSMesaContextHandle ctx_;
  PfnDestroy destroy_;
  PfnMakeCurrent make_;
  bool accum_;
  std::vector<uint8_t> buffer_;
};

// ---------------------------------------------------------------- EGL
struct EglApi {
  PFNEGLGETPROCADDRESSPROC getProcAddress = nullptr;
  PFNEGLINITIALIZEPROC initialize = nullptr;
  PFNEGLTERMINATEPROC terminate = nullptr;
  PFNEGLBINDAPIPROC bindAPI = nullptr;
  PFNEGLCREATECONTEXTPROC createContext = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroyContext = nullptr;
  PFNEGLMAKECURRENTPROC makeCurrent = nullptr;
  PFNEGLQUERYSTRINGPROC queryString = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay = nullptr;
  PFNEGLQUERYDEVICESEXTPROC queryDevices = nullptr;
};
EglApi g_egl;
void* eglProc(const char* name) { return reinterpret_cast<void*>(g_egl.getProcAddress(name)); }

class EglContext final : public Context {
 public:
  static std::unique_ptr<Context> create(const ContextOptions& o, std::string* why) {
    void* lib = hidden("egl") ? nullptr : dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
      *why = hidden("egl") ? "libEGL.so.1 hidden by TS_HIDE_GL_LIBS" : "libEGL.so.1 not found";
      return nullptr;
    }
    EglApi& e = g_egl;
    e.getProcAddress = reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(dlsym(lib, "eglGetProcAddress"));
    if (!e.getProcAddress) {
      *why = "libEGL lacks eglGetProcAddress";
      return nullptr;
    }
#define TS_EGL(field, name) e.field = reinterpret_cast<decltype(e.field)>(dlsym(lib, name))
    TS_EGL(initialize, "eglInitialize");
    TS_EGL(terminate, "eglTerminate");
    TS_EGL(bindAPI, "eglBindAPI");
    TS_EGL(createContext, "eglCreateContext");
    TS_EGL(destroyContext, "eglDestroyContext");
    TS_EGL(makeCurrent, "eglMakeCurrent");
    TS_EGL(queryString, "eglQueryString");
#undef TS_EGL
    e.getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        e.getProcAddress("eglGetPlatformDisplayEXT"));
    e.queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(e.getProcAddress("eglQueryDevicesEXT"));
    if (!e.initialize || !e.createContext || !e.makeCurrent || !e.getPlatformDisplay) {
      *why = "libEGL lacks EGL_EXT_platform_base";
      return nullptr;
    }
    // Surfaceless first (no device node needed); the device platform second.
    EGLDisplay dpy = e.getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (dpy == EGL_NO_DISPLAY || !e.initialize(dpy, &major, &minor)) {
      dpy = EGL_NO_DISPLAY;
      EGLDeviceEXT devices[4];
      EGLint n = 0;
      if (e.queryDevices && e.queryDevices(4, devices, &n) && n > 0) {
        dpy = e.getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
        if (dpy != EGL_NO_DISPLAY && !e.initialize(dpy, &major, &minor)) dpy = EGL_NO_DISPLAY;
      }
    }
    if (dpy == EGL_NO_DISPLAY) {
      *why = "no EGL surfaceless or device display";
      return nullptr;
    }
    if (!e.bindAPI(EGL_OPENGL_API)) {
      *why = "EGL cannot bind desktop OpenGL";
      return nullptr;
    }
    const EGLint attribs[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
    EGLContext ctx = e.createContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (ctx == EGL_NO_CONTEXT || !e.makeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
      *why = "eglCreateContext (compatibility profile, no config) failed";
      return nullptr;
    }
    std::string missing;
    if (!gl::load(eglProc, &missing) || !gl::p_glGenFramebuffers) {
      *why = "EGL context lacks " + (missing.empty() ? std::string("framebuffer objects") : missing);
      return nullptr;
    }
    gl::enableDebugOutput();
    std::unique_ptr<EglContext> c(new EglContext(dpy, ctx));
    c->resize(o.width, o.height);
    return c;
  }
  ~EglContext() override {
    release();
    g_egl.makeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    g_egl.destroyContext(dpy_, ctx_);
  }
  Backend backend() const override { return Backend::EGL; }
  void resize(int w, int h) override {
    // No window system: the picture goes to a framebuffer object, the
    // suite's one render target (render_target.hpp), bound for good.
    target_.make({w, h}, "the EGL context");
    glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer());
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    gl::check("creating the EGL framebuffer");
    width_ = w;
    height_ = h;
  }
  void bindTarget() override { glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer()); }

 private:
  EglContext(EGLDisplay d, EGLContext c) : dpy_(d), ctx_(c) {}
  void release() { target_.free(); }
  EGLDisplay dpy_;
  EGLContext ctx_;
  RenderTarget target_;
};
}  // namespace
#endif  // TS_HAVE_DLOPEN_BACKENDS

bool haveDlopenBackends() {
#if TS_HAVE_DLOPEN_BACKENDS
  return true;
#else
  return false;
#endif
}

std::unique_ptr<Context> createOffscreenContext(Backend backend, const ContextOptions& opts) {
  std::string whyOsmesa, whyEgl, whyHidden;
#if TS_HAVE_DLOPEN_BACKENDS
  if (backend == Backend::OSMesa || backend == Backend::Auto) {
    if (auto c = OSMesaContext::create(opts, &whyOsmesa)) return c;
    if (backend == Backend::OSMesa)
      throw Error("OSMesa backend unavailable (" + whyOsmesa + "); install Debian's libosmesa6 or use --backend egl");
  }
  if (backend == Backend::EGL || backend == Backend::Auto) {
    if (auto c = EglContext::create(opts, &whyEgl)) {
      // The note only when the fallback worked: a failure is one line.
      if (backend == Backend::Auto && opts.verbose) note("note: " + whyOsmesa + "; using the EGL backend");
      return c;
    }
    if (backend == Backend::EGL)
      throw Error("EGL backend unavailable (" + whyEgl + "); install Debian's libegl1 libegl-mesa0 libgl1-mesa-dri");
  }
#else
  if (backend == Backend::OSMesa || backend == Backend::EGL)
    throw Error(std::string("the ") + backendName(backend) +
                " backend exists on Linux only; use --backend hidden or auto");
#endif
  if (backend == Backend::Hidden || (backend == Backend::Auto && opts.allowHidden)) {
    if (auto c = createHiddenContext(opts, &whyHidden)) {
#if TS_HAVE_DLOPEN_BACKENDS
      if (backend == Backend::Auto && opts.verbose)
        note("note: " + whyOsmesa + "; " + whyEgl + "; using the hidden-window backend");
#endif
      return c;
    }
    if (backend == Backend::Hidden) throw Error("hidden-window backend unavailable (" + whyHidden + ")");
  }
  if (backend == Backend::Auto) {
#if TS_HAVE_DLOPEN_BACKENDS
    throw Error("no offscreen OpenGL context: OSMesa: " + whyOsmesa + "; EGL: " + whyEgl +
                (whyHidden.empty() ? std::string() : "; hidden window: " + whyHidden) +
                "; install Debian's libosmesa6, or libegl1 libegl-mesa0 libgl1-mesa-dri");
#else
    throw Error("no offscreen OpenGL context (" +
                (whyHidden.empty() ? std::string("hidden window not allowed here") : whyHidden) +
                "); update the graphics driver");
#endif
  }
  throw Error("backend 'window' is not an offscreen backend");
}
}  // namespace ts
