// common/core/gl_call.hpp — one recorded GL call as plain data (see gl_record.hpp,
// which records them).  No GL headers: a Frame (frame.hpp) carries the calls
// that rendered a picture it shows (TextureDesc::renderedBy) without calling GL.
#pragma once
#include <algorithm>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

namespace ts::gl {

// What an argument holds beyond a number, kept out of line: most arguments
// (a vertex's coordinates, an enum) hold none, and a recording of a mesh drawn
// call by call holds a million arguments.  Each member below is one pointer
// (8 bytes, where a vector is 24 and a shared_ptr 16), read as the vector or
// the pointer it stands for.
template <class T>
class ArgArray {
 public:
  ArgArray() = default;
  ArgArray(std::initializer_list<T> v) { *this = v; }
  ArgArray(const ArgArray& o) : p_(o.p_ ? std::make_unique<std::vector<T>>(*o.p_) : nullptr) {}
  ArgArray(ArgArray&&) noexcept = default;
  ArgArray& operator=(const ArgArray& o) {
    if (this != &o) p_ = o.p_ ? std::make_unique<std::vector<T>>(*o.p_) : nullptr;
    return *this;
  }
  ArgArray& operator=(ArgArray&&) noexcept = default;
  ArgArray& operator=(std::initializer_list<T> v) {
    p_ = v.size() ? std::make_unique<std::vector<T>>(v) : nullptr;
    return *this;
  }
  using value_type = T;
  using iterator = T*;
  using const_iterator = const T*;
  size_t size() const { return p_ ? p_->size() : 0; }
  bool empty() const { return size() == 0; }
  const T& operator[](size_t k) const { return (*p_)[k]; }
  T& operator[](size_t k) { return (*p_)[k]; }
  T* begin() { return p_ ? p_->data() : nullptr; }
  T* end() { return begin() + size(); }
  const T* begin() const { return p_ ? p_->data() : nullptr; }
  const T* end() const { return begin() + size(); }
  void push_back(T v) { vec().push_back(std::move(v)); }
  template <class... A>
  void emplace_back(A&&... a) {
    vec().emplace_back(std::forward<A>(a)...);
  }
  template <class It>
  void assign(It first, It last) {
    vec().assign(first, last);
  }
  bool operator==(const std::vector<T>& v) const { return size() == v.size() && std::equal(begin(), end(), v.begin()); }

 private:
  std::vector<T>& vec() {
    if (!p_) p_ = std::make_unique<std::vector<T>>();
    return *p_;
  }
  std::unique_ptr<std::vector<T>> p_;
};
template <class T>
class ArgShared {  // a shared_ptr<const T>, as one pointer
 public:
  ArgShared() = default;
  ArgShared(std::shared_ptr<const T> p) { *this = std::move(p); }
  ArgShared(const ArgShared& o) : p_(o.p_ ? std::make_unique<std::shared_ptr<const T>>(*o.p_) : nullptr) {}
  ArgShared(ArgShared&&) noexcept = default;
  ArgShared& operator=(const ArgShared& o) {
    if (this != &o) p_ = o.p_ ? std::make_unique<std::shared_ptr<const T>>(*o.p_) : nullptr;
    return *this;
  }
  ArgShared& operator=(ArgShared&&) noexcept = default;
  ArgShared& operator=(std::shared_ptr<const T> p) {
    p_ = p ? std::make_unique<std::shared_ptr<const T>>(std::move(p)) : nullptr;
    return *this;
  }
  explicit operator bool() const { return p_ != nullptr; }
  const T& operator*() const { return **p_; }
  const T* operator->() const { return p_ ? p_->get() : nullptr; }
  std::shared_ptr<const T> get() const { return p_ ? *p_ : nullptr; }

 private:
  std::unique_ptr<std::shared_ptr<const T>> p_;
};

// One argument, as a C programmer would write it back.
struct Arg {
  enum class Kind : unsigned char {
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
  ArgArray<float> floats;
  ArgArray<long long> ints;
  ArgArray<std::string> text;
  ArgShared<std::vector<unsigned char>> bytes;
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
