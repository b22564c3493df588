// common/gl/gl_record.hpp — the GL calls behind a picture, recorded as they are made.
//
// Every GL call of the suite goes through a pointer of common/gl/gl.hpp.  While
// a gl::Recording is alive, those pointers point at recording wrappers: each
// call is kept with its arguments (what the pointed-to data *is*: the 16
// floats of a matrix, a texture's pixels, a shader's source) and then made
// as usual.  When the Recording ends the real pointers are back, so with no
// recording the cost is exactly nothing (no branch on any call).
//
// Recording is per thread, as the pointer table is: a Recording keeps the
// calls of the thread that made it, and threads record independently (the
// window's GL pane while a measurement worker records a picture it renders,
// common/app/measure_worker.hpp).  Recordings on one thread nest: a call is kept
// by every Recording alive on its thread, so an outer one still holds all
// that was drawn while it lived.  Callers scope a Recording around the
// drawing of a picture and never around the measurement passes (texel-index
// renders, readbacks), so the two stay apart.
//
//   ts::gl::Recording rec;          // from here on, calls are kept
//   renderer.draw(frame);
//   for (const ts::gl::Call& c : rec.calls()) puts(ts::gl::formatCall(c).c_str());
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "common/gl/gl.hpp"
#include "common/core/gl_call.hpp"

namespace ts::gl {

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
  Recording();   // starts recording on this thread (inside another: both keep the calls)
  ~Recording();  // the outermost restores this thread's real pointers
  Recording(const Recording&) = delete;
  Recording& operator=(const Recording&) = delete;
  const std::vector<Call>& calls() const { return calls_; }
  std::vector<Call> take() { return std::move(calls_); }
  // Used by the wrappers: one call made while recording.
  void append(Call c);
  // True while any Recording is alive on any thread.
  static bool active();
  // True while a Recording is alive on the calling thread.
  static bool activeHere();

 private:
  std::vector<Call> calls_;
  Recording* outer_ = nullptr;  // the Recording this one is inside (same thread)
};

// Calls a recorded render makes for the measurement rather than the picture
// (a readback of its depth, say): made, and kept by no Recording of this
// thread while a NotRecorded is alive, so the listing stays the picture's
// calls alone.  No Recording may start inside one.
class NotRecorded {
 public:
  NotRecorded();
  ~NotRecorded();
  NotRecorded(const NotRecorded&) = delete;
  NotRecorded& operator=(const NotRecorded&) = delete;

 private:
  Recording* saved_;
};
}  // namespace ts::gl
