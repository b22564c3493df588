// common/gl/gl.hpp — the one way every file in this suite reaches OpenGL.
//
// Why a loader instead of linking libGL or libOSMesa:
//   libOSMesa.so exports every GL entry point and dispatches to OSMesa
//   contexts only; glvnd's libGL.so.1 exports them too and dispatches to
//   GLX/EGL contexts only (docs/platform.md, "How GL calls bind"). A program whose GL
//   calls bind at link time to one of them cannot use the other's contexts,
//   so one binary could not offer --backend osmesa|egl|window.  Instead no
//   executable links a GL library: every GL function is a pointer fetched at
//   run time from the backend that made the context (OSMesaGetProcAddress,
//   eglGetProcAddress, glfwGetProcAddress).  The GL code of the suite (the
//   Frame renderer common/gl/render.cpp, the window, and the demos that draw
//   passes of their own: VI.7's jitter, the parallax shaders) writes plain glBegin(...)
//   — the macros below turn it into a call through the pointer.  Calling a GL
//   function missing from TS_GL_FUNCTIONS fails at link time (undefined
//   glFoo), never silently at run time: add the name to the list.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1  // declarations only: used for decltype below
#endif
#if defined(_WIN32) && !(defined(WINGDIAPI) && defined(APIENTRY))
// Windows' GL/gl.h wants these two and otherwise includes <windows.h> for
// them, whose macros (near, far, ERROR, ...) break ordinary C++ names in the
// demos.  The values are <windows.h>'s.
#ifndef APIENTRY
#define APIENTRY __stdcall
#endif
#ifndef WINGDIAPI
#define WINGDIAPI __declspec(dllimport)
#endif
#endif
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

// Every GL function the suite calls.  Keep alphabetical within a group.
// One line per GL version, as the comments group them: not reflowed.
// clang-format off
#define TS_GL_FUNCTIONS(X)                                                     \
  /* GL 1.x fixed function */                                                  \
  X(glAccum) X(glBegin) X(glBindTexture) X(glBlendFunc) X(glClear)             \
  X(glClearColor) X(glClearDepth) X(glColor4f) X(glColorPointer)               \
  X(glDeleteTextures) X(glDepthFunc) X(glDepthMask) X(glDisable)               \
  X(glDisableClientState) X(glTexSubImage2D)                                   \
  X(glDrawElements) X(glEnable) X(glEnableClientState) X(glEnd) X(glFinish)    \
  X(glFlush) X(glFrustum) X(glGenTextures) X(glGetError) X(glGetFloatv)        \
  X(glGetIntegerv) X(glGetString) X(glGetTexImage) X(glHint) X(glIsEnabled)    \
  X(glLineWidth) X(glLoadIdentity) X(glLoadMatrixf) X(glMatrixMode)            \
  X(glOrtho) X(glPixelStorei) X(glPointSize) X(glPopAttrib) X(glPopMatrix)     \
  X(glPushAttrib) X(glPushMatrix) X(glReadBuffer) X(glReadPixels)              \
  X(glScissor) X(glShadeModel) X(glTexCoord2f) X(glTexCoord4f)                 \
  X(glTexCoordPointer) X(glTexEnvfv) X(glTexEnvi) X(glTexImage2D) X(glTexParameterf)         \
  X(glTexParameterfv) X(glTexParameteri) X(glVertex2f) X(glVertex3f)           \
  X(glVertexPointer) X(glViewport) X(glDrawBuffer)                             \
  X(glNormal3f) X(glTexCoord3f) X(glTexGeni) X(glTexGenfv) X(glClipPlane)      \
  X(glAlphaFunc) X(glRotatef) X(glScalef) X(glTranslatef)                     \
  /* GL 1.2 */                                                                 \
  X(glTexImage3D)                                                              \
  /* GL 1.3+ multitexture, compressed textures */                             \
  X(glActiveTexture) X(glCompressedTexImage2D) X(glGetTexLevelParameteriv)     \
  X(glMultiTexCoord2f) X(glCopyTexImage2D) X(glMultiTexCoord4f)              \
  X(glCopyTexSubImage2D)                                                       \
  /* GL 1.4 */                                                                 \
  X(glBlendFuncSeparate) X(glSecondaryColor3f)                                 \
  /* GL 2.0+ shaders */                                                        \
  X(glAttachShader) X(glCompileShader) X(glCreateProgram) X(glCreateShader)    \
  X(glDeleteProgram) X(glDeleteShader) X(glGetProgramInfoLog)                  \
  X(glGetProgramiv) X(glGetShaderInfoLog) X(glGetShaderiv)                     \
  X(glGetUniformLocation) X(glLinkProgram) X(glShaderSource) X(glUniform1f)    \
  X(glUniform1i) X(glUniform2f) X(glUniform3f) X(glUniform4f) X(glUseProgram)  \
  X(glBindAttribLocation) X(glGetAttribLocation)                               \
  X(glUniformMatrix3fv)                                                        \
  /* GL 3.0+ framebuffer objects */                                            \
  X(glBindFramebuffer) X(glBindRenderbuffer) X(glCheckFramebufferStatus)       \
  X(glDeleteFramebuffers) X(glDeleteRenderbuffers)                             \
  X(glFramebufferRenderbuffer) X(glFramebufferTexture2D) X(glGenFramebuffers)  \
  X(glGenRenderbuffers) X(glRenderbufferStorage) X(glGetStringi)               \
  /* GL 4.3 / KHR_debug */                                                     \
  X(glDebugMessageCallback)
// clang-format on

namespace ts::gl {
// One table per thread: a thread's GL calls go to the context that thread
// made current, through the pointers that thread loaded (the window's
// thread from GLFW, a measurement worker from its own OSMesa or EGL context:
// common/app/measure_worker.hpp).  OSMesa's entry points are its own, so one
// table could not serve a window and an OSMesa context at once.  __thread,
// not thread_local: the pointers need no constructor, and an extern
// thread_local is read through a wrapper function that UBSan's null check
// misreads as a null load (every GL call failed under ASan + UBSan).
#define TS_GL_DECLARE_POINTER(name) extern __thread decltype(&::name) p_##name;
TS_GL_FUNCTIONS(TS_GL_DECLARE_POINTER)
#undef TS_GL_DECLARE_POINTER

using ProcLoader = void* (*)(const char* name);

// Fills every pointer of the calling thread's table from `loader`.  Returns false (and names the first
// missing core function in *missing) if a function the suite needs for
// GL 2.1 fixed function is absent.  Later functions may be null: callers that
// need them check gl::has(...)/the GL version first.
bool load(ProcLoader loader, std::string* missing);
bool loaded();
// "4.5 (Compatibility Profile) Mesa 22.3.6" etc.; "" when no context.
std::string versionString();
std::string rendererString();
// Parsed major*10+minor of GL_VERSION, e.g. 45.
int version();
bool hasExtension(const char* name);
// Whether GL_TEXTURE_MAX_ANISOTROPY may be set: GL 4.6, or either extension
// that offers it (EXT or ARB: the same enum, 0x84FE).  The suite's one query.
bool hasAnisotropicFiltering();

// Checks glGetError(); returns "" or a description like
// "GL_INVALID_ENUM after upload texture".
std::string errorString(const char* stage);
// Throws ts::Error if glGetError() reports an error after `stage`.
void check(const char* stage);
// Where the context has KHR_debug (GL 4.3 or the extension), turns on
// synchronous debug output; errors reported through it are quoted by
// errorString/check.  Returns whether it did.
bool enableDebugOutput();
}  // namespace ts::gl

// Route every call site through the loaded pointers (one line per function
// of TS_GL_FUNCTIONS).  The lists check each other: a name missing here links
// to an undefined ::glFoo, a name missing above is an undeclared pointer.
#define glAccum ts::gl::p_glAccum
#define glAlphaFunc ts::gl::p_glAlphaFunc
#define glCopyTexImage2D ts::gl::p_glCopyTexImage2D
#define glCopyTexSubImage2D ts::gl::p_glCopyTexSubImage2D
#define glMultiTexCoord2f ts::gl::p_glMultiTexCoord2f
#define glMultiTexCoord4f ts::gl::p_glMultiTexCoord4f
#define glRotatef ts::gl::p_glRotatef
#define glScalef ts::gl::p_glScalef
#define glTranslatef ts::gl::p_glTranslatef
#define glBegin ts::gl::p_glBegin
#define glBindTexture ts::gl::p_glBindTexture
#define glBlendFunc ts::gl::p_glBlendFunc
#define glBlendFuncSeparate ts::gl::p_glBlendFuncSeparate
#define glSecondaryColor3f ts::gl::p_glSecondaryColor3f
#define glClear ts::gl::p_glClear
#define glClearColor ts::gl::p_glClearColor
#define glClearDepth ts::gl::p_glClearDepth
#define glColor4f ts::gl::p_glColor4f
#define glColorPointer ts::gl::p_glColorPointer
#define glDeleteTextures ts::gl::p_glDeleteTextures
#define glDepthFunc ts::gl::p_glDepthFunc
#define glDepthMask ts::gl::p_glDepthMask
#define glTexSubImage2D ts::gl::p_glTexSubImage2D
#define glDisable ts::gl::p_glDisable
#define glDisableClientState ts::gl::p_glDisableClientState
#define glDrawElements ts::gl::p_glDrawElements
#define glEnable ts::gl::p_glEnable
#define glEnableClientState ts::gl::p_glEnableClientState
#define glEnd ts::gl::p_glEnd
#define glFinish ts::gl::p_glFinish
#define glFlush ts::gl::p_glFlush
#define glFrustum ts::gl::p_glFrustum
#define glGenTextures ts::gl::p_glGenTextures
#define glGetError ts::gl::p_glGetError
#define glGetFloatv ts::gl::p_glGetFloatv
#define glGetIntegerv ts::gl::p_glGetIntegerv
#define glGetString ts::gl::p_glGetString
#define glGetTexImage ts::gl::p_glGetTexImage
#define glHint ts::gl::p_glHint
#define glIsEnabled ts::gl::p_glIsEnabled
#define glLineWidth ts::gl::p_glLineWidth
#define glLoadIdentity ts::gl::p_glLoadIdentity
#define glLoadMatrixf ts::gl::p_glLoadMatrixf
#define glMatrixMode ts::gl::p_glMatrixMode
#define glOrtho ts::gl::p_glOrtho
#define glPixelStorei ts::gl::p_glPixelStorei
#define glPointSize ts::gl::p_glPointSize
#define glPopAttrib ts::gl::p_glPopAttrib
#define glPopMatrix ts::gl::p_glPopMatrix
#define glPushAttrib ts::gl::p_glPushAttrib
#define glPushMatrix ts::gl::p_glPushMatrix
#define glReadBuffer ts::gl::p_glReadBuffer
#define glReadPixels ts::gl::p_glReadPixels
#define glScissor ts::gl::p_glScissor
#define glShadeModel ts::gl::p_glShadeModel
#define glTexCoord2f ts::gl::p_glTexCoord2f
#define glTexCoord4f ts::gl::p_glTexCoord4f
#define glTexCoordPointer ts::gl::p_glTexCoordPointer
#define glTexEnvfv ts::gl::p_glTexEnvfv
#define glTexEnvi ts::gl::p_glTexEnvi
#define glTexImage2D ts::gl::p_glTexImage2D
#define glTexParameterf ts::gl::p_glTexParameterf
#define glTexParameterfv ts::gl::p_glTexParameterfv
#define glTexParameteri ts::gl::p_glTexParameteri
#define glVertex2f ts::gl::p_glVertex2f
#define glVertex3f ts::gl::p_glVertex3f
#define glVertexPointer ts::gl::p_glVertexPointer
#define glViewport ts::gl::p_glViewport
#define glDrawBuffer ts::gl::p_glDrawBuffer
#define glActiveTexture ts::gl::p_glActiveTexture
#define glCompressedTexImage2D ts::gl::p_glCompressedTexImage2D
#define glGetTexLevelParameteriv ts::gl::p_glGetTexLevelParameteriv
#define glAttachShader ts::gl::p_glAttachShader
#define glCompileShader ts::gl::p_glCompileShader
#define glCreateProgram ts::gl::p_glCreateProgram
#define glCreateShader ts::gl::p_glCreateShader
#define glDeleteProgram ts::gl::p_glDeleteProgram
#define glDeleteShader ts::gl::p_glDeleteShader
#define glGetProgramInfoLog ts::gl::p_glGetProgramInfoLog
#define glGetProgramiv ts::gl::p_glGetProgramiv
#define glGetShaderInfoLog ts::gl::p_glGetShaderInfoLog
#define glGetShaderiv ts::gl::p_glGetShaderiv
#define glGetUniformLocation ts::gl::p_glGetUniformLocation
#define glLinkProgram ts::gl::p_glLinkProgram
#define glShaderSource ts::gl::p_glShaderSource
#define glUniform1f ts::gl::p_glUniform1f
#define glUniform1i ts::gl::p_glUniform1i
#define glUniform2f ts::gl::p_glUniform2f
#define glUniform3f ts::gl::p_glUniform3f
#define glUniform4f ts::gl::p_glUniform4f
#define glUniformMatrix3fv ts::gl::p_glUniformMatrix3fv
#define glNormal3f ts::gl::p_glNormal3f
#define glTexCoord3f ts::gl::p_glTexCoord3f
#define glTexGeni ts::gl::p_glTexGeni
#define glTexGenfv ts::gl::p_glTexGenfv
#define glClipPlane ts::gl::p_glClipPlane
#define glTexImage3D ts::gl::p_glTexImage3D
#define glUseProgram ts::gl::p_glUseProgram
#define glBindAttribLocation ts::gl::p_glBindAttribLocation
#define glGetAttribLocation ts::gl::p_glGetAttribLocation
#define glBindFramebuffer ts::gl::p_glBindFramebuffer
#define glBindRenderbuffer ts::gl::p_glBindRenderbuffer
#define glCheckFramebufferStatus ts::gl::p_glCheckFramebufferStatus
#define glDeleteFramebuffers ts::gl::p_glDeleteFramebuffers
#define glDeleteRenderbuffers ts::gl::p_glDeleteRenderbuffers
#define glFramebufferRenderbuffer ts::gl::p_glFramebufferRenderbuffer
#define glFramebufferTexture2D ts::gl::p_glFramebufferTexture2D
#define glGenFramebuffers ts::gl::p_glGenFramebuffers
#define glGenRenderbuffers ts::gl::p_glGenRenderbuffers
#define glRenderbufferStorage ts::gl::p_glRenderbufferStorage
#define glGetStringi ts::gl::p_glGetStringi
#define glDebugMessageCallback ts::gl::p_glDebugMessageCallback
