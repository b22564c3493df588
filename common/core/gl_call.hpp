// common/core/gl_call.hpp — one recorded GL call as plain data (see gl_record.hpp,
// which records them).  No GL headers: a Frame (frame.hpp) carries the calls
// that rendered a picture it shows (TextureDesc::renderedBy) without calling GL.
#pragma once
#include <memory>
#include <string>
#include <vector>

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
  const char* name = "";  // "glTexParameteri"
  std::vector<Arg> args;
  bool hasResult = false;  // glGenLists, glCreateShader, glGetUniformLocation ...
  long long result = 0;
  bool query = false;  // glGet*, glIsEnabled, glCheckFramebufferStatus: reads state, draws nothing
};

// The calls that made one picture, shared (a frame is built every window frame).
using CallList = std::shared_ptr<const std::vector<Call>>;
}  // namespace ts::gl
