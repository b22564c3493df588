#include "common/gl/gl.hpp"

#include <cstdio>
#include <cstring>
#include <string>

#include "common/core/error.hpp"
#include "common/core/kept.hpp"

namespace ts::gl {
#define TS_GL_DEFINE_POINTER(name) __thread decltype(p_##name) p_##name = nullptr;
TS_GL_FUNCTIONS(TS_GL_DEFINE_POINTER)
#undef TS_GL_DEFINE_POINTER

namespace {
thread_local bool g_loaded = false;  // per thread, as the table
// Functions of GL <= 2.1 that every backend must give us; the rest is checked
// by whoever needs it.
const char* const kRequired[] = {"glBegin",     "glEnd",      "glTexImage2D",   "glReadPixels", "glViewport",
                                 "glGetString", "glGetError", "glCreateShader", "glUseProgram"};
}  // namespace

bool load(ProcLoader loader, std::string* missing) {
#define TS_GL_LOAD(name) p_##name = reinterpret_cast<decltype(p_##name)>(loader(#name));
  TS_GL_FUNCTIONS(TS_GL_LOAD)
#undef TS_GL_LOAD
  for (const char* name : kRequired) {
    if (!loader(name)) {
      if (missing) *missing = name;
      g_loaded = false;
      return false;
    }
  }
  g_loaded = true;
  return true;
}

bool loaded() { return g_loaded; }

static std::string str(GLenum e) {
  if (!g_loaded) return "";
  const GLubyte* s = p_glGetString(e);
  return s ? reinterpret_cast<const char*>(s) : "";
}
std::string versionString() { return str(GL_VERSION); }
std::string rendererString() { return str(GL_RENDERER); }

int version() {
  int major = 0, minor = 0;
  std::sscanf(versionString().c_str(), "%d.%d", &major, &minor);
  return major * 10 + minor;
}

bool hasAnisotropicFiltering() {
  return version() >= 46 || hasExtension("GL_EXT_texture_filter_anisotropic") ||
         hasExtension("GL_ARB_texture_filter_anisotropic");
}

// What hasExtension answered, by the context's renderer and version (a
// process may hold an offscreen context and a window's, of different
// versions): the renderer makes textures by the hundred, each asking for
// anisotropic filtering, and each answer walks some 200 extension names.
static bool hasExtensionUncached(const char* name);

bool hasExtension(const char* name) {
  if (!g_loaded) return false;
  static Kept<std::string, bool> answers(64);
  return answers.get(rendererString() + "|" + versionString() + "|" + name, [&] { return hasExtensionUncached(name); });
}

static bool hasExtensionUncached(const char* name) {
  if (version() >= 30 && p_glGetStringi) {
    GLint n = 0;
    p_glGetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; ++i) {
      const GLubyte* e = p_glGetStringi(GL_EXTENSIONS, GLuint(i));
      if (e && std::strcmp(reinterpret_cast<const char*>(e), name) == 0) return true;
    }
    return false;
  }
  std::string all = str(GL_EXTENSIONS);
  std::string key = std::string(name);
  size_t pos = 0;
  while ((pos = all.find(key, pos)) != std::string::npos) {
    size_t end = pos + key.size();
    if ((pos == 0 || all[pos - 1] == ' ') && (end == all.size() || all[end] == ' ')) return true;
    pos = end;
  }
  return false;
}

static const char* errorName(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    default: return "unknown GL error";
  }
}

// KHR_debug: the driver's own words for an error ("glTexImage2D(invalid
// width)"), kept until the next check() so its message can quote them.
namespace {
thread_local std::string g_debugErrors;  // the callback is synchronous: the failing call's thread
void APIENTRY onDebugMessage(GLenum, GLenum type, GLuint, GLenum, GLsizei length, const GLchar* message, const void*) {
  if (type != GL_DEBUG_TYPE_ERROR || !message || g_debugErrors.size() > 1024) return;
  if (!g_debugErrors.empty()) g_debugErrors += "; ";
  g_debugErrors += length > 0 ? std::string(message, size_t(length)) : std::string(message);
  while (!g_debugErrors.empty() && (g_debugErrors.back() == '\n' || g_debugErrors.back() == ' '))
    g_debugErrors.pop_back();
}
}  // namespace

bool enableDebugOutput() {
  if (!g_loaded || !p_glDebugMessageCallback || (version() < 43 && !hasExtension("GL_KHR_debug"))) return false;
  g_debugErrors.clear();
  p_glEnable(GL_DEBUG_OUTPUT);
  p_glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // the callback runs in the failing call
  p_glDebugMessageCallback(onDebugMessage, nullptr);
  p_glGetError();  // enabling must not leave an error for the first check
  return true;
}

std::string errorString(const char* stage) {
  std::string out;
  for (int i = 0; i < 16; ++i) {  // bounded: a lost context can report forever
    GLenum e = p_glGetError();
    if (e == GL_NO_ERROR) break;
    if (!out.empty()) out += ", ";
    out += errorName(e);
  }
  std::string driver;
  driver.swap(g_debugErrors);
  if (out.empty()) return out;
  return out + " after " + stage + (driver.empty() ? "" : " (driver: " + driver + ")");
}

void check(const char* stage) {
  std::string e = errorString(stage);
  if (!e.empty()) throw Error("OpenGL error: " + e, kExitFailure);
}
}  // namespace ts::gl
