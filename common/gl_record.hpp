// common/gl_record.hpp — the GL calls behind a picture, recorded as they are made.
//
// Every GL call of the suite goes through a pointer of common/gl.hpp.  While
// a gl::Recording is alive, those pointers point at recording wrappers: each
// call is kept with its arguments (what the pointed-to data *is*: the 16
// floats of a matrix, a texture's pixels, a shader's source) and then made
// as usual.  When the Recording ends the real pointers are back, so with no
// recording the cost is exactly nothing (no branch on any call).
//
// Only calls made on the thread that started the recording are kept: a
// measurement on another thread's context is not the picture's.  Callers
// scope a Recording around the drawing of a picture and never around the
// measurement passes (texel-index renders, readbacks), so the two stay apart.
//
//   ts::gl::Recording rec;          // from here on, calls are kept
//   renderer.draw(frame);
//   for (const ts::gl::Call& c : rec.calls()) puts(ts::gl::formatCall(c).c_str());
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "gl.hpp"

namespace ts::gl {

// One argument, as a C programmer would write it back.
struct Arg {
  enum class Kind {
    Int,       // GLint, GLsizei: 256
    Uint,      // an object name (texture 3, program 2) or an unsigned count
    Float,     // 0.5f (GLdouble arguments too)
    Enum,      // GL_LINEAR_MIPMAP_LINEAR; `i` holds the value
    Bitfield,  // GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT
    Boolean,   // GL_TRUE / GL_FALSE
    Floats,    // an array the call reads: glLoadMatrixf's 16, a colour's 4
    Ints,      // an array of integers the call reads or writes (glGenTextures' names)
    Text,      // strings the call reads (glShaderSource, glGetUniformLocation's name)
    Pixels,    // image data the call reads (glTexImage2D): `bytes` holds a copy
    Pointer,   // anything else (null, client arrays, query outputs): not kept
    Code,      // C code standing for the argument (`text[0]`): set by a program
               // generator, never by the recorder (e.g. "texture[1]")
  };
  Kind kind = Kind::Int;
  bool isDouble = false;  // a GLdouble parameter (glOrtho, glClearDepth)
  long long i = 0;
  double f = 0;
  std::vector<float> floats;
  std::vector<long long> ints;
  std::vector<std::string> text;
  std::shared_ptr<const std::vector<unsigned char>> bytes;
};

struct Call {
  const char* name = "";   // "glTexParameteri"
  std::vector<Arg> args;
  bool hasResult = false;  // glGenLists, glCreateShader, glGetUniformLocation ...
  long long result = 0;
  bool query = false;      // glGet*, glIsEnabled, glCheckFramebufferStatus: reads state, draws nothing
};

// The name of an enum value (the first core name the GL headers give it:
// GL_TEXTURE_MAX_ANISOTROPY rather than ..._EXT), or "" when unknown.
const char* enumName(unsigned long long value);
// The value of an enum name, for parsing listings back; false when the
// headers do not define it.
bool enumValue(const std::string& name, unsigned long long* value);

// One call as a line of C: glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
// Arrays read by the call are written as C99 compound literals
// (glLoadMatrixf((const GLfloat[16]){1, 0, ...})); pixel data as a comment
// naming what it is (/* 256x256 GL_RGBA GL_UNSIGNED_BYTE, 262144 bytes */ NULL).
// A float as a C float literal that reads back as the same float: 0.9f, 1.0f.
std::string floatLiteral(double v);

// floatSuffix: float constants as C float literals (0.9f), so a compiler
// gives exactly the recorded float (an exported program's vertices).
std::string formatCall(const Call& c, bool floatSuffix = false);

class Recording {
 public:
  Recording();   // starts recording on this thread (one Recording at a time)
  ~Recording();  // restores the real pointers
  Recording(const Recording&) = delete;
  Recording& operator=(const Recording&) = delete;
  const std::vector<Call>& calls() const { return calls_; }
  std::vector<Call> take() { return std::move(calls_); }
  // Used by the wrappers: one call made while recording.
  void append(Call c) { calls_.push_back(std::move(c)); }
  // True while any Recording is alive.
  static bool active();

 private:
  std::vector<Call> calls_;
};
}  // namespace ts::gl
