// common/gl/gl_record.cpp — see gl_record.hpp.  How it works: each GL pointer
// of common/gl/gl.hpp is swapped for rec<I>, a wrapper made by a template from
// the function's own type; the wrapper turns its arguments into plain numbers
// (Raw), lets describe() read them as the GL reads them (a hint per function
// says which integer is an enum, which pointer is a matrix or a texture's
// pixels), makes the real call, and keeps the Call.
#include "common/gl/gl_record.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>
#include <map>
#include <type_traits>
#include <unordered_map>

#include "common/core/error.hpp"

namespace ts::gl {
namespace {

// ---- enum names, generated from the GL headers at configure time ----------
struct EnumEntry {
  unsigned long long value;
  const char* name;
};
const EnumEntry kEnums[] = {
#include "gl_enums.inc"
};

// A vendor or ARB suffix: GL_FOO_EXT is a second name for GL_FOO.
bool suffixed(const char* name) {
  static const char* const kSuffixes[] = {"_ARB",  "_EXT",  "_KHR",   "_OES",   "_NV",      "_AMD", "_ATI",
                                          "_SGIS", "_SGIX", "_APPLE", "_MESA",  "_INTEL",   "_IBM", "_SUN",
                                          "_HP",   "_3DFX", "_NVX",   "_OML",   "_INGR",    "_PGI", "_REND",
                                          "_S3",   "_WIN",  "_SGI",   "_MESAX", "_GREMEDY", "_OVR", "_QCOM",
                                          "_IMG",  "_ARM",  "_ANGLE", "_NVX",   "_SUNX"};
  size_t n = std::strlen(name);
  for (const char* s : kSuffixes) {
    size_t k = std::strlen(s);
    if (n > k && std::strcmp(name + n - k, s) == 0) return true;
  }
  return false;
}

const std::unordered_map<unsigned long long, const char*>& namesByValue() {
  static const auto* table = [] {
    auto* m = new std::unordered_map<unsigned long long, const char*>();
    // Header order: gl.h's core names first; a suffixed name only where no
    // core name exists.
    for (const EnumEntry& e : kEnums)
      if (!suffixed(e.name)) m->emplace(e.value, e.name);
    for (const EnumEntry& e : kEnums) m->emplace(e.value, e.name);
    return m;
  }();
  return *table;
}

// ---- arguments as plain numbers --------------------------------------------
struct Raw {
  long long i = 0;
  double f = 0;
  const void* p = nullptr;
  enum { Integer, Unsigned, Real, RealDouble, Ptr } type = Integer;
};

// A call's arguments, held by its wrapper on the stack (no allocation per call).
struct Raws {
  const Raw* data;
  size_t count;
  size_t size() const { return count; }
  const Raw& operator[](size_t k) const { return data[k]; }
};

template <typename T>
Raw toRaw(T v) {
  Raw r;
  if constexpr (std::is_pointer_v<T>) {
    r.p = reinterpret_cast<const void*>(v);
    r.type = Raw::Ptr;
  } else if constexpr (std::is_floating_point_v<T>) {
    r.f = double(v);
    r.type = std::is_same_v<T, double> ? Raw::RealDouble : Raw::Real;
  } else if constexpr (std::is_unsigned_v<T>) {
    r.i = (long long)(v);
    r.type = Raw::Unsigned;
  } else {
    r.i = (long long)(v);
    r.type = Raw::Integer;
  }
  return r;
}

// ---- per-function hints -----------------------------------------------------
// One letter per parameter (missing letters: read from the C type):
//   e enum   P primitive mode   F blend factor   b bitfield   B boolean
//   x enum or number, as the pname before it says   u object name / unsigned
//   m 16 floats read   v a vector read (length from the pname)   4 four floats read
//   T texture pixels read (size from the call's width, height, format, type)
//   o names written (count = first argument)   n names read (count = first argument)
//   S shader strings (count, strings, lengths)   s one C string read
//   M count x 16 floats read   N count x 9 floats read   V count x 4 floats read
//   D four doubles read (glClipPlane's equation)
//   - pointer, not kept
// A leading '?' marks a query: it reads state and draws nothing.
const std::map<std::string, std::string>& hints() {
  static const std::map<std::string, std::string> h = {
      {"glAccum", "e"},
      {"glBegin", "P"},
      {"glBindTexture", "eu"},
      {"glBlendFunc", "FF"},
      {"glBlendFuncSeparate", "FFFF"},
      {"glClear", "b"},
      {"glPushAttrib", "b"},
      {"glCopyTexImage2D", "eie"},
      {"glCopyTexSubImage2D", "ei"},
      {"glCullFace", "e"},
      {"glDeleteTextures", "in"},
      {"glDepthFunc", "e"},
      {"glDepthMask", "B"},
      {"glDisable", "e"},
      {"glDisableClientState", "e"},
      {"glDrawArrays", "P"},
      {"glDrawElements", "Pie-"},
      {"glEnable", "e"},
      {"glEnableClientState", "e"},
      {"glFrontFace", "e"},
      {"glGenTextures", "io"},
      {"glHint", "ee"},
      {"glLoadMatrixf", "m"},
      {"glMatrixMode", "e"},
      {"glMultMatrixf", "m"},
      {"glPixelStorei", "e"},
      {"glPolygonMode", "ee"},
      {"glShadeModel", "e"},
      {"glTexEnvf", "eex"},
      {"glTexEnvfv", "eev"},
      {"glTexEnvi", "eex"},
      {"glTexGenfv", "eev"},
      {"glTexGeni", "eex"},
      {"glTexImage2D", "eieiiieeT"},
      {"glCompressedTexImage2D", "eieiiii-"},
      {"glTexImage3D", "eieiiiieeT"},
      {"glClipPlane", "eD"},
      {"glTexSubImage2D", "eiiiiieeT"},
      {"glTexParameterf", "eex"},
      {"glTexParameterfv", "eev"},
      {"glTexParameteri", "eex"},
      {"glLightfv", "eev"},
      {"glLightModeli", "ex"},
      {"glMaterialfv", "eev"},
      {"glReadBuffer", "e"},
      {"glDrawBuffer", "e"},
      {"glColorMask", "BBBB"},
      {"glStencilFunc", "eiu"},
      {"glStencilOp", "eee"},
      {"glActiveTexture", "e"},
      {"glClientActiveTexture", "e"},
      {"glMultiTexCoord4f", "e"},
      {"glMultiTexCoord2f", "e"},
      {"glAlphaFunc", "e"},
      {"glCreateShader", "e"},
      {"glShaderSource", "uiS"},
      {"glGetUniformLocation", "us"},
      {"glGetAttribLocation", "us"},
      {"glBindAttribLocation", "uus"},
      {"glUniformMatrix4fv", "iiBM"},
      {"glUniformMatrix3fv", "iiBN"},
      {"glUniform4fv", "iiV"},
      {"glGenerateMipmap", "e"},
      {"glBindFramebuffer", "eu"},
      {"glBindRenderbuffer", "eu"},
      {"glRenderbufferStorage", "eeii"},
      {"glFramebufferTexture2D", "eeeui"},
      {"glFramebufferRenderbuffer", "eeeu"},
      {"glGenFramebuffers", "io"},
      {"glGenRenderbuffers", "io"},
      {"glDeleteFramebuffers", "in"},
      {"glDeleteRenderbuffers", "in"},
      {"glBlitFramebuffer", "iiiiiiiibe"},
      {"glGenBuffers", "io"},
      {"glDeleteBuffers", "in"},
      {"glBindBuffer", "eu"},
      {"glBufferData", "ei-e"},
      {"glGenVertexArrays", "io"},
      {"glDeleteVertexArrays", "in"},
      {"glVertexAttribPointer", "uieBi-"},
      {"glReadPixels", "iiiiee-"},
      {"glColorPointer", "ie--"},
      {"glTexCoordPointer", "ie--"},
      {"glVertexPointer", "ie--"},
      {"glNormalPointer", "e--"},
      {"glDebugMessageControl", "eeei-B"},
      // Queries: they read state and draw nothing.
      {"glGetError", "?"},
      {"glGetFloatv", "?e-"},
      {"glGetIntegerv", "?e-"},
      {"glGetString", "?e"},
      {"glGetStringi", "?eu"},
      {"glGetTexImage", "?eiee-"},
      {"glGetTexLevelParameteriv", "?eie-"},
      {"glIsEnabled", "?e"},
      {"glGetProgramiv", "?ue-"},
      {"glGetShaderiv", "?ue-"},
      {"glGetProgramInfoLog", "?ui--"},
      {"glGetShaderInfoLog", "?ui--"},
      {"glCheckFramebufferStatus", "?e"},
      {"glFinish", "?"},
      {"glFlush", "?"},
      {"glDebugMessageCallback", "?--"},
  };
  return h;
}

// Parameters named by a pname whose value is a number, never an enum.
bool numericPname(long long pname) {
  switch (pname) {
    case GL_TEXTURE_MAX_LEVEL:
    case GL_TEXTURE_BASE_LEVEL:
    case GL_TEXTURE_MIN_LOD:
    case GL_TEXTURE_MAX_LOD:
    case GL_TEXTURE_LOD_BIAS:
    case GL_TEXTURE_MAX_ANISOTROPY_EXT:
    case GL_UNPACK_ALIGNMENT:
    case GL_PACK_ALIGNMENT:
    case GL_UNPACK_ROW_LENGTH:
    case GL_PACK_ROW_LENGTH:
    case GL_UNPACK_SKIP_PIXELS:
    case GL_UNPACK_SKIP_ROWS:
    case GL_PACK_SKIP_PIXELS:
    case GL_PACK_SKIP_ROWS:
    case GL_RGB_SCALE:
    case GL_ALPHA_SCALE:
    case GL_LIGHT_MODEL_TWO_SIDE:
    case GL_LIGHT_MODEL_LOCAL_VIEWER:
    case GL_GENERATE_MIPMAP: return true;
    default: return false;
  }
}

// How many floats a ...fv call reads for its pname.
int vectorLength(long long pname) {
  switch (pname) {
    case GL_SHININESS:
    case GL_SPOT_EXPONENT:
    case GL_SPOT_CUTOFF:
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION:
    case GL_TEXTURE_LOD_BIAS:
    case GL_TEXTURE_MAX_ANISOTROPY_EXT:
    case GL_TEXTURE_MIN_LOD:
    case GL_TEXTURE_MAX_LOD: return 1;
    case GL_SPOT_DIRECTION:
    case GL_COLOR_INDEXES: return 3;
    default: return 4;
  }
}

int components(long long format) {
  switch (format) {
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_LUMINANCE:
    case GL_DEPTH_COMPONENT:
    case GL_RED_INTEGER: return 1;
    case GL_RG:
    case GL_LUMINANCE_ALPHA:
    case GL_DEPTH_STENCIL: return 2;
    case GL_RGB:
    case GL_BGR: return 3;
    default: return 4;
  }
}
int typeBytes(long long type) {
  switch (type) {
    case GL_UNSIGNED_SHORT:
    case GL_SHORT:
    case GL_HALF_FLOAT: return 2;
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT:
    case GL_UNSIGNED_INT_24_8: return 4;
    default: return 1;
  }
}

Arg describe(char hint, const Raw& r, const Raws& all, size_t index, const char* fn) {
  Arg a;
  a.i = r.i;
  a.f = r.f;
  a.isDouble = r.type == Raw::RealDouble;
  auto floatsAt = [&](size_t n) {
    const float* v = static_cast<const float*>(r.p);
    a.kind = Arg::Kind::Floats;
    if (v) a.floats.assign(v, v + n);
  };
  switch (hint) {
    case 'e':
    case 'P':
    case 'F': a.kind = Arg::Kind::Enum; return a;
    case 'b': a.kind = Arg::Kind::Bitfield; return a;
    case 'B': a.kind = Arg::Kind::Boolean; return a;
    case 'u': a.kind = Arg::Kind::Uint; return a;
    case 'i': a.kind = Arg::Kind::Int; return a;
    case 'x': {
      long long pname = index > 0 ? all[index - 1].i : 0;
      long long v = r.type == Raw::Real || r.type == Raw::RealDouble ? (long long)(r.f) : r.i;
      bool integral = r.type == Raw::Real || r.type == Raw::RealDouble ? double(v) == r.f : true;
      if (!numericPname(pname) && integral && v >= 0x100 && enumName((unsigned long long)(v))[0]) {
        a.kind = Arg::Kind::Enum;
        a.i = v;
      } else {
        a.kind = r.type == Raw::Real || r.type == Raw::RealDouble ? Arg::Kind::Float : Arg::Kind::Int;
      }
      return a;
    }
    case 'm': floatsAt(16); return a;
    case 'D': {
      const double* v = static_cast<const double*>(r.p);
      a.kind = Arg::Kind::Floats;
      a.isDouble = true;
      if (v) a.floats.assign(v, v + 4);  // the plane's doubles, kept as the floats GL stores them as
      return a;
    }
    case 'v': floatsAt(size_t(vectorLength(index > 0 ? all[index - 1].i : 0))); return a;
    case 'M': floatsAt(size_t(std::max<long long>(0, all[1].i)) * 16); return a;
    case 'N': floatsAt(size_t(std::max<long long>(0, all[1].i)) * 9); return a;
    case 'V': floatsAt(size_t(std::max<long long>(0, all[1].i)) * 4); return a;
    case 'n': {
      a.kind = Arg::Kind::Ints;
      const GLuint* v = static_cast<const GLuint*>(r.p);
      if (v)
        for (long long k = 0; k < all[0].i; ++k) a.ints.push_back(v[k]);
      return a;
    }
    case 'o': a.kind = Arg::Kind::Ints; return a;  // filled after the call
    case 's':
      a.kind = Arg::Kind::Text;
      if (r.p) a.text.emplace_back(static_cast<const char*>(r.p));
      return a;
    case 'S': {
      // glShaderSource(shader, count, strings, lengths): strings and lengths together.
      a.kind = Arg::Kind::Text;
      const char* const* strings = static_cast<const char* const*>(r.p);
      const GLint* lengths = index + 1 < all.size() ? static_cast<const GLint*>(all[index + 1].p) : nullptr;
      for (long long k = 0; strings && k < all[1].i; ++k)
        a.text.push_back(lengths && lengths[k] >= 0 ? std::string(strings[k], size_t(lengths[k]))
                                                    : std::string(strings[k]));
      return a;
    }
    case 'T': {
      // Pixels: glTexImage2D (w, h at 3, 4; format, type at 6, 7),
      // glTexSubImage2D (w, h at 4, 5; format, type at 6, 7) and glTexImage3D
      // (w, h, depth at 3, 4, 5; format, type at 7, 8), its slices read as
      // h x depth rows one after the other (GL_UNPACK_IMAGE_HEIGHT 0).
      bool sub = std::strcmp(fn, "glTexSubImage2D") == 0, volume = std::strcmp(fn, "glTexImage3D") == 0;
      long long w = all[sub ? 4 : 3].i, h = all[sub ? 5 : 4].i, format = all[6].i, type = all[7].i;
      if (volume) h *= all[5].i, format = all[7].i, type = all[8].i;
      a.kind = Arg::Kind::Pixels;
      a.ints = {w, h, format, type};
      if (r.p && w > 0 && h > 0) {
        // The texels GL reads: rows of GL_UNPACK_ROW_LENGTH pixels (w when 0), from pixel GL_UNPACK_SKIP_PIXELS
        // of row GL_UNPACK_SKIP_ROWS on (a sub-image of a larger picture, uploaded without a copy).
        GLint align = 4, rowLength = 0, skipPixels = 0, skipRows = 0;
        p_glGetIntegerv(GL_UNPACK_ALIGNMENT, &align);  // through the real pointer: not recorded
        p_glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
        p_glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skipPixels);
        p_glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skipRows);
        const size_t pixel = size_t(components(format) * typeBytes(type));
        size_t row = size_t(w) * pixel;
        size_t rowRead = size_t(rowLength > 0 ? rowLength : w) * pixel;
        size_t stride = (rowRead + size_t(align) - 1) / size_t(align) * size_t(align);
        auto copy = std::make_shared<std::vector<unsigned char>>();
        const unsigned char* src = static_cast<const unsigned char*>(r.p) + size_t(skipRows) * stride +
                                   size_t(skipPixels) * pixel;
        copy->reserve(row * size_t(h));
        for (long long y = 0; y < h; ++y)
          copy->insert(copy->end(), src + size_t(y) * stride, src + size_t(y) * stride + row);
        a.bytes = std::move(copy);
      }
      return a;
    }
    case '-': a.kind = Arg::Kind::Pointer; return a;
    default: break;
  }
  // No hint: the C type says.
  switch (r.type) {
    case Raw::Ptr: a.kind = Arg::Kind::Pointer; break;
    case Raw::Real:
    case Raw::RealDouble: a.kind = Arg::Kind::Float; break;
    case Raw::Unsigned: a.kind = Arg::Kind::Uint; break;
    default: a.kind = Arg::Kind::Int; break;
  }
  return a;
}

// ---- the wrappers -----------------------------------------------------------
enum FunctionIndex {
#define TS_GL_INDEX(name) k_##name,
  TS_GL_FUNCTIONS(TS_GL_INDEX)
#undef TS_GL_INDEX
      kFunctionCount
};
const char* const kNames[] = {
#define TS_GL_NAME(name) #name,
    TS_GL_FUNCTIONS(TS_GL_NAME)
#undef TS_GL_NAME
};
// Per thread, as the pointer table they stand in for (gl.hpp): each thread's
// real pointers and innermost Recording.
__thread void* g_real[kFunctionCount];
__thread Recording* g_recording = nullptr;
std::atomic<int> g_alive{0};  // Recordings alive, all threads

// The hint of each function, looked up once (vertices are many).
const std::string& hintOf(int index) {
  static const std::vector<std::string> byIndex = [] {
    std::vector<std::string> v(kFunctionCount);
    for (int k = 0; k < kFunctionCount; ++k) {
      auto it = hints().find(kNames[k]);
      if (it != hints().end()) v[size_t(k)] = it->second;
    }
    return v;
  }();
  return byIndex[size_t(index)];
}

Call begin(int index, const Raws& raws) {
  Call c;
  c.name = kNames[index];
  std::string_view hint = hintOf(index);
  if (!hint.empty() && hint[0] == '?') {
    c.query = true;
    hint.remove_prefix(1);
  }
  // Exactly as many as the call has: a recording of a fixed-function mesh
  // holds a million calls, and the vector's growth (1, 2, 4) would leave a
  // 3-argument glVertex3f with room for 4 (an Arg is over 100 bytes).
  c.args.reserve(raws.size());
  for (size_t k = 0; k < raws.size(); ++k)
    c.args.push_back(describe(k < hint.size() ? hint[k] : ' ', raws[k], raws, k, c.name));
  // glShaderSource's lengths were read with its strings.
  if (std::strcmp(c.name, "glShaderSource") == 0 && c.args.size() == 4) c.args.pop_back();
  return c;
}

void finish(int index, Call& c, const Raws& raws) {
  // Names the call wrote (glGenTextures(1, &id)): read them now.
  const std::string& hint = hintOf(index);
  for (size_t k = 0; k < c.args.size(); ++k) {
    if (k >= hint.size() || hint[k] != 'o') continue;
    const GLuint* v = static_cast<const GLuint*>(raws[k].p);
    if (v)
      for (long long n = 0; n < raws[0].i; ++n) c.args[k].ints.push_back(v[n]);
  }
  if (g_recording) g_recording->append(std::move(c));
}

template <int Index, typename F>
struct Wrapper;
template <int Index, typename R, typename... A>
struct Wrapper<Index, R (*)(A...)> {
  static R APIENTRY call(A... a) {
    auto real = reinterpret_cast<R (*)(A...)>(g_real[Index]);
    if (!g_recording) return real(a...);  // a Recording ending on this thread
    const std::array<Raw, sizeof...(A)> held{toRaw(a)...};
    const Raws raws{held.data(), held.size()};
    Call c = begin(Index, raws);
    if constexpr (std::is_void_v<R>) {
      real(a...);
      finish(Index, c, raws);
    } else {
      R result = real(a...);
      c.hasResult = true;
      if constexpr (std::is_pointer_v<R>) c.result = 0;
      else c.result = (long long)(result);
      finish(Index, c, raws);
      return result;
    }
  }
};

void swapIn() {
#define TS_GL_SWAP_IN(name)                             \
  g_real[k_##name] = reinterpret_cast<void*>(p_##name); \
  if (p_##name) p_##name = &Wrapper<k_##name, decltype(p_##name)>::call;
  TS_GL_FUNCTIONS(TS_GL_SWAP_IN)
#undef TS_GL_SWAP_IN
}
void swapOut() {
#define TS_GL_SWAP_OUT(name) p_##name = reinterpret_cast<decltype(p_##name)>(g_real[k_##name]);
  TS_GL_FUNCTIONS(TS_GL_SWAP_OUT)
#undef TS_GL_SWAP_OUT
}

// ---- formatting -------------------------------------------------------------
// The fewest significant digits of any decimal that reads back as v (as a
// float unless isDouble): std::to_chars's shortest form.  No "%.*g" with
// fewer digits can read back as v, so number() starts there instead of at 1
// (its loop was most of the time a listing took).
int shortestDigits(double v, bool isDouble) {
  char s[64];
  const std::to_chars_result r = isDouble ? std::to_chars(s, s + sizeof s, v, std::chars_format::scientific)
                                          : std::to_chars(s, s + sizeof s, float(v), std::chars_format::scientific);
  int n = 0;
  for (const char* p = s; p < r.ptr && *p != 'e'; ++p) n += *p >= '0' && *p <= '9';
  return std::max(1, n);
}

// The shortest decimal that reads back as the same float (or double): the
// fewest digits of "%.*g" that do, or of "%.*f" where that is plain and as
// exact.  Written and read with std::to_chars and std::from_chars (the same
// text as printf, the same value as strtod/strtof, without printf's
// arbitrary-precision path: a listing holds tens of thousands of numbers).
std::string number(double v, bool isDouble) {
  if (std::isnan(v)) return "NAN";
  if (std::isinf(v)) return v > 0 ? "INFINITY" : "-INFINITY";
  char buf[64];
  auto same = [&](const char* end) {
    if (isDouble) {
      double r = 0;
      if (std::from_chars(buf, end, r).ec != std::errc())
        r = std::strtod(std::string(buf, size_t(end - buf)).c_str(), nullptr);
      return r == v;
    }
    float r = 0;  // out of float's range: strtof's infinity or denormal, as before
    if (std::from_chars(buf, end, r).ec != std::errc())
      r = std::strtof(std::string(buf, size_t(end - buf)).c_str(), nullptr);
    return r == float(v);
  };
  const char* end = buf;
  for (int digits = shortestDigits(v, isDouble); digits <= 17; ++digits) {
    end = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits).ptr;
    if (same(end)) break;
  }
  // 20 rather than 2e+01: plain decimals where they are as exact.
  if (std::memchr(buf, 'e', size_t(end - buf)) && std::fabs(v) >= 1e-5 && std::fabs(v) < 1e9) {
    for (int places = 0; places <= 24; ++places) {
      const char* fixedEnd = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, places).ptr;
      if (same(fixedEnd)) return std::string(buf, size_t(fixedEnd - buf));
    }
  }
  return std::string(buf, size_t(end - buf));
}

}  // namespace

std::string floatLiteral(double v) {
  std::string s = number(v, false);
  if (!std::isfinite(v)) return s;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s + "f";
}

namespace {
std::string enumText(const Arg& a, char group) {
  unsigned long long v = (unsigned long long)(a.i);
  static const char* const kPrims[] = {"GL_POINTS",     "GL_LINES",          "GL_LINE_LOOP",    "GL_LINE_STRIP",
                                       "GL_TRIANGLES",  "GL_TRIANGLE_STRIP", "GL_TRIANGLE_FAN", "GL_QUADS",
                                       "GL_QUAD_STRIP", "GL_POLYGON"};
  if (group == 'P' && v < 10) return kPrims[v];
  if (v == 0) return group == 'F' ? "GL_ZERO" : "GL_NONE";
  if (v == 1 && group == 'F') return "GL_ONE";
  const char* n = enumName(v);
  if (n[0]) return n;
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%llX", v);
  return buf;
}

std::string bitfieldText(long long v) {
  if (v == 0xFFFFFFFFLL) return "GL_ALL_ATTRIB_BITS";  // glPushAttrib's everything
  static const std::pair<long long, const char*> kBits[] = {{GL_COLOR_BUFFER_BIT, "GL_COLOR_BUFFER_BIT"},
                                                            {GL_DEPTH_BUFFER_BIT, "GL_DEPTH_BUFFER_BIT"},
                                                            {GL_STENCIL_BUFFER_BIT, "GL_STENCIL_BUFFER_BIT"},
                                                            {GL_ACCUM_BUFFER_BIT, "GL_ACCUM_BUFFER_BIT"}};
  std::string out;
  for (auto [bit, name] : kBits)
    if (v & bit) {
      out += (out.empty() ? "" : " | ") + std::string(name);
      v &= ~bit;
    }
  if (v || out.empty()) out += (out.empty() ? "" : " | ") + std::to_string(v);
  return out;
}

std::string quoted(const std::string& s) {
  std::string o = "\"";
  for (char ch : s) {
    switch (ch) {
      case '\n': o += "\\n\"\n    \""; break;  // one source line per shader line
      case '\t': o += "\\t"; break;
      case '"': o += "\\\""; break;
      case '\\': o += "\\\\"; break;
      default: o += ch;
    }
  }
  return o + "\"";
}
}  // namespace

const char* enumName(unsigned long long value) {
  auto it = namesByValue().find(value);
  return it == namesByValue().end() ? "" : it->second;
}

bool enumValue(const std::string& name, unsigned long long* value) {
  static const auto* byName = [] {
    auto* m = new std::unordered_map<std::string, unsigned long long>();
    for (const EnumEntry& e : kEnums) m->emplace(e.name, e.value);
    return m;
  }();
  auto it = byName->find(name);
  if (it == byName->end()) return false;
  if (value) *value = it->second;
  return true;
}

std::string formatCall(const Call& c, bool floatSuffix) {
  auto it = hints().find(c.name);
  std::string hint = it == hints().end() ? std::string() : it->second;
  if (!hint.empty() && hint[0] == '?') hint.erase(0, 1);
  std::string out = std::string(c.name) + "(";
  for (size_t k = 0; k < c.args.size(); ++k) {
    const Arg& a = c.args[k];
    char group = k < hint.size() ? hint[k] : ' ';
    if (k) out += ", ";
    switch (a.kind) {
      case Arg::Kind::Int:
      case Arg::Kind::Uint: out += std::to_string(a.i); break;
      case Arg::Kind::Float: out += floatSuffix && !a.isDouble ? floatLiteral(a.f) : number(a.f, a.isDouble); break;
      case Arg::Kind::Code: out += a.text.empty() ? "0" : a.text[0]; break;
      case Arg::Kind::Enum: out += enumText(a, group); break;
      case Arg::Kind::Bitfield: out += bitfieldText(a.i); break;
      case Arg::Kind::Boolean: out += a.i ? "GL_TRUE" : "GL_FALSE"; break;
      case Arg::Kind::Floats: {
        out += std::string(a.isDouble ? "(const GLdouble[" : "(const GLfloat[") + std::to_string(a.floats.size()) +
               "]){";
        for (size_t n = 0; n < a.floats.size(); ++n)
          out += (n ? ", " : "") +
                 (floatSuffix && !a.isDouble ? floatLiteral(a.floats[n]) : number(a.floats[n], a.isDouble));
        out += "}";
        break;
      }
      case Arg::Kind::Ints: {
        // glGenTextures(1, &id) gives id; glDeleteTextures(1, (const GLuint[1]){3}).
        out += (group == 'o' ? "(GLuint[" : "(const GLuint[") + std::to_string(a.ints.size()) + "]){";
        for (size_t n = 0; n < a.ints.size(); ++n) out += (n ? ", " : "") + std::to_string(a.ints[n]);
        out += "}";
        break;
      }
      case Arg::Kind::Text: {
        if (group == 'S') {
          out += "(const GLchar*[" + std::to_string(a.text.size()) + "]){";
          for (size_t n = 0; n < a.text.size(); ++n) out += (n ? ", " : "") + quoted(a.text[n]);
          out += "}, NULL";
        } else {
          out += a.text.empty() ? "NULL" : quoted(a.text[0]);
        }
        break;
      }
      case Arg::Kind::Pixels: {
        char buf[160];
        std::snprintf(buf, sizeof buf, "NULL /* %lldx%lld %s %s, %zu bytes */", a.ints.size() > 1 ? a.ints[0] : 0,
                      a.ints.size() > 1 ? a.ints[1] : 0,
                      a.ints.size() > 2 ? enumName((unsigned long long)(a.ints[2])) : "",
                      a.ints.size() > 3 ? enumName((unsigned long long)(a.ints[3])) : "",
                      a.bytes ? a.bytes->size() : 0);
        out += buf;
        break;
      }
      case Arg::Kind::Pointer: out += "NULL"; break;
    }
  }
  out += ");";
  if (c.hasResult) {
    if (std::strcmp(c.name, "glCheckFramebufferStatus") == 0)
      out += std::string("  /* = ") + enumName((unsigned long long)(c.result)) + " */";
    else out += "  /* = " + std::to_string(c.result) + " */";
  }
  return out;
}

Recording::Recording() : outer_(g_recording) {
  if (!outer_) swapIn();  // this thread's table: another thread's stays as it is
  g_recording = this;
  g_alive.fetch_add(1);
}

Recording::~Recording() {
  g_recording = outer_;
  if (!outer_) swapOut();
  g_alive.fetch_sub(1);
}

void Recording::append(Call c) {
  if (outer_) outer_->append(c);  // nested: the outer Recording keeps it too
  calls_.push_back(std::move(c));
}

// The wrappers stay in place and pass each call straight on (no Recording
// to keep it); the innermost Recording is back at the end.
NotRecorded::NotRecorded() : saved_(g_recording) { g_recording = nullptr; }
NotRecorded::~NotRecorded() { g_recording = saved_; }

bool Recording::active() { return g_alive.load() > 0; }
bool Recording::activeHere() { return g_recording != nullptr; }
}  // namespace ts::gl
