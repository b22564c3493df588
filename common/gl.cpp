#include "gl.hpp"

#include <cstdio>
#include <cstring>

#include "error.hpp"

namespace ts::gl {
#define TM_GL_DEFINE_POINTER(name) decltype(p_##name) p_##name = nullptr;
TM_GL_FUNCTIONS(TM_GL_DEFINE_POINTER)
#undef TM_GL_DEFINE_POINTER

namespace {
bool g_loaded = false;
// Functions of GL <= 2.1 that every backend must give us; the rest is checked
// by whoever needs it.
const char* const kRequired[] = {
    "glBegin", "glEnd", "glTexImage2D", "glReadPixels", "glViewport",
    "glGetString", "glGetError", "glCreateShader", "glUseProgram"};
}  // namespace

bool load(ProcLoader loader, std::string* missing) {
#define TM_GL_LOAD(name) \
  p_##name = reinterpret_cast<decltype(p_##name)>(loader(#name));
  TM_GL_FUNCTIONS(TM_GL_LOAD)
#undef TM_GL_LOAD
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

bool hasExtension(const char* name) {
  if (!g_loaded) return false;
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

std::string errorString(const char* stage) {
  std::string out;
  for (int i = 0; i < 16; ++i) {  // bounded: a lost context can report forever
    GLenum e = p_glGetError();
    if (e == GL_NO_ERROR) break;
    if (!out.empty()) out += ", ";
    out += errorName(e);
  }
  if (out.empty()) return out;
  return out + " after " + stage;
}

void check(const char* stage) {
  std::string e = errorString(stage);
  if (!e.empty()) throw Error("OpenGL error: " + e, kExitFailure);
}
}  // namespace ts::gl
