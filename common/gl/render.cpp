#include "common/gl/render.hpp"
#include "common/gl/render_target.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>

#include "common/gl/context.hpp"
#include "common/core/error.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "common/core/test_hooks.hpp"

namespace ts {
Renderer::~Renderer() {
  attachments_.clear();  // their destructors delete their objects
  release();
}

int Renderer::pictureWidth() { return pictureW_ > 0 ? pictureW_ : ctx_.width(); }
int Renderer::pictureHeight() { return pictureH_ > 0 ? pictureH_ : ctx_.height(); }

void Renderer::release() {
  for (auto& [k, id] : textures_) glDeleteTextures(1, &id);
  for (auto& [k, id] : programs_) glDeleteProgram(id);
  if (fontTexture_) glDeleteTextures(1, &fontTexture_);
  textures_.clear();
  programs_.clear();
  fontTexture_ = 0;
}

static bool powerOfTwo(int v) { return v > 0 && (v & (v - 1)) == 0; }
static int nextPowerOfTwo(int v) {
  int p = 1;
  while (p < v) p *= 2;
  return p;
}

static void upload(const Image& img, int level) {
  glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
}

GLuint Renderer::texture(const TextureDesc& t) {
  auto it = textures_.find(t.key());
  GLuint id = 0;
  if (t.depth > 1) return texture3D(t);
  if (t.cube) return textureCube(t);
  if (t.glTexture) {
    id = t.glTexture;
    glBindTexture(GL_TEXTURE_2D, id);
  } else if (it != textures_.end()) {
    id = it->second;
    glBindTexture(GL_TEXTURE_2D, id);
  } else {
    if (!t.image) throw Error("texture '" + t.name + "' has no image", kExitFailure);
    // Sizes the context cannot take are refused with the reason, not left to
    // a GL error (or, worse, an incomplete texture that samples black).
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (maxSize > 0 && (t.image->width > maxSize || t.image->height > maxSize))
      throw Error("texture '" + t.name + "' is " + std::to_string(t.image->width) + "x" +
                  std::to_string(t.image->height) + ", over this context's GL_MAX_TEXTURE_SIZE " +
                  std::to_string(maxSize));
    std::shared_ptr<const Image> level0 = t.image;
    // A test can take this path on any context (test_hooks.hpp): every
    // context here has NPOT textures.
    bool npot = !test_hooks::noNpotTextures() &&
                (gl::version() >= 20 || gl::hasExtension("GL_ARB_texture_non_power_of_two"));
    if ((!powerOfTwo(level0->width) || !powerOfTwo(level0->height)) && !npot) {
      // GL 1.x without NPOT support: resample to powers of two, and say so.
      int w = nextPowerOfTwo(level0->width), h = nextPowerOfTwo(level0->height);
      note("note: texture '" + t.name + "' " + std::to_string(level0->width) + "x" + std::to_string(level0->height) +
           " resized bilinearly to " + std::to_string(w) + "x" + std::to_string(h) +
           " (the context lacks non-power-of-two textures)");
      level0 = std::make_shared<Image>(resizeBilinear(*level0, w, h));
    }
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (t.mipmaps) {
      // The book's chain, built on the CPU so it is the same on every driver.
      std::vector<Image> chain = t.mipLevels ? *t.mipLevels : buildMipChain(*level0, t.linearLightMips);
      for (size_t k = 0; k < chain.size(); ++k) upload(chain[k], int(k));
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, int(chain.size()) - 1);
    } else {
      upload(*level0, 0);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    }
    gl::check(("uploading texture " + t.key()).c_str());
    textures_[t.key()] = id;
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GLint(t.minFilter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GLint(t.magFilter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(t.wrapS));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(t.wrapT));
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, glm::value_ptr(t.border));
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, t.lodBias);
  if (gl::hasAnisotropicFiltering()) glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, t.maxAnisotropy);
  gl::check(("setting the parameters of texture " + t.key()).c_str());
  return id;
}

// A 3D texture (TextureDesc::depth > 1): the slices stacked in `image` are
// exactly glTexImage3D's layout (rows of slice 0, then slice 1, ...).
GLuint Renderer::texture3D(const TextureDesc& t) {
  auto it = textures_.find(t.key());
  GLuint id = 0;
  if (it != textures_.end()) {
    id = it->second;
    glBindTexture(GL_TEXTURE_3D, id);
  } else {
    if (!t.image || t.image->height % t.depth != 0)
      throw Error("3D texture '" + t.name + "' needs an image of depth stacked slices", kExitFailure);
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_3D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, t.image->width, t.image->height / t.depth, t.depth, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, t.image->pixels.data());
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 0);
    gl::check(("uploading 3D texture " + t.key()).c_str());
    textures_[t.key()] = id;
  }
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GLint(t.minFilter));
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GLint(t.magFilter));
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GLint(t.wrapS));
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GLint(t.wrapT));
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GLint(t.wrapR));
  gl::check(("setting the parameters of 3D texture " + t.key()).c_str());
  return id;
}

// A cube map (TextureDesc::cube): the six faces stacked in `image`, in GL's
// order +X, -X, +Y, -Y, +Z, -Z, each to GL_TEXTURE_CUBE_MAP_POSITIVE_X + f.
GLuint Renderer::textureCube(const TextureDesc& t) {
  auto it = textures_.find(t.key());
  GLuint id = 0;
  if (t.glTexture) {  // drawn by the scene itself (glCopyTexSubImage2D into its faces): bound as it is
    id = t.glTexture;
    glBindTexture(GL_TEXTURE_CUBE_MAP, id);
  } else if (it != textures_.end()) {
    id = it->second;
    glBindTexture(GL_TEXTURE_CUBE_MAP, id);
  } else {
    const int w = t.image ? t.image->width : 0;
    if (!t.image || w < 1 || t.image->height != 6 * w)
      throw Error("cube map '" + t.name + "' needs an image of six stacked square faces", kExitFailure);
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_CUBE_MAP, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int f = 0; f < 6; ++f)
      glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA8, w, w, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   t.image->pixels.data() + size_t(f) * size_t(w) * size_t(w) * 4);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
    gl::check(("uploading cube map " + t.key()).c_str());
    textures_[t.key()] = id;
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GLint(t.minFilter));
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GLint(t.magFilter));
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GLint(t.wrapS));
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GLint(t.wrapT));
  gl::check(("setting the parameters of cube map " + t.key()).c_str());
  return id;
}

void Renderer::forgetTexture(const TextureDesc& t) {
  auto it = textures_.find(t.key());
  if (it == textures_.end()) return;
  glDeleteTextures(1, &it->second);
  textures_.erase(it);
}

// The 1-based line of `file` where the shader text `src` begins (it is a raw
// string literal there), or 0 when the file cannot be read or does not hold
// the text.  Looked up only to word an error message.
static int sourceLine(const std::string& file, const std::string& src) {
  if (file.empty() || src.empty()) return 0;
  std::vector<std::string> candidates{file};
#ifdef TS_SOURCE_DIR
  candidates.push_back(std::string(TS_SOURCE_DIR) + "/" + file);
#endif
  for (const std::string& path : candidates) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) continue;
    std::string text;
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0 && text.size() < (size_t(8) << 20)) text.append(buf, n);
    std::fclose(f);
    size_t at = text.find(src);
    if (at == std::string::npos) continue;
    return 1 + int(std::count(text.begin(), text.begin() + long(at), '\n'));
  }
  return 0;
}

// A GL info log as one line: each "0:LINE(COL): ..." message (Mesa's form;
// "0(LINE) : ..." is also understood) becomes "file:LINE':COL: ..." with
// LINE' counted in the C++ file holding the shader, when that is known.
std::string formatShaderLog(const std::string& log, const std::string& file, int firstLine, const char* stage) {
  std::string out;
  size_t pos = 0;
  while (pos < log.size()) {
    size_t end = log.find('\n', pos);
    if (end == std::string::npos) end = log.size();
    std::string line = log.substr(pos, end - pos);
    pos = end + 1;
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    if (line.empty()) continue;
    int src = 0, ln = 0, col = 0, used = 0;
    std::string where;
    if (std::sscanf(line.c_str(), "%d:%d(%d)%n", &src, &ln, &col, &used) == 3 && used > 0) {
    } else if (std::sscanf(line.c_str(), "%d(%d)%n", &src, &ln, &used) == 2 && used > 0) {
      col = 0;
    } else {
      used = 0;
      ln = 0;
    }
    std::string msg = line.substr(size_t(used));
    while (!msg.empty() && (msg[0] == ':' || msg[0] == ' ')) msg.erase(0, 1);
    if (ln > 0 && firstLine > 0)
      where = file + ":" + std::to_string(firstLine + ln - 1) + (col > 0 ? ":" + std::to_string(col) : "");
    else if (ln > 0) where = file + ": " + stage + " shader line " + std::to_string(ln);
    else where = file;
    if (!out.empty()) out += "; ";
    out += where + ": " + msg;
  }
  return out.empty() ? file + ": (the driver gave no log)" : out;
}

static GLuint compile(GLenum type, const Program& p, const std::string& key) {
  const std::string& src = type == GL_VERTEX_SHADER ? p.vertex : p.fragment;
  const char* stage = type == GL_VERTEX_SHADER ? "vertex" : "fragment";
  GLuint s = glCreateShader(type);
  const char* text = src.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
    std::string log(size_t(std::clamp(len, 1, 1 << 16)), '\0');
    glGetShaderInfoLog(s, GLsizei(log.size()), nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    glDeleteShader(s);
    const std::string why = formatShaderLog(log, p.file, sourceLine(p.file, src), stage);
    throw Error(std::string(stage) + " shader of program '" + key + "' does not compile: " + why, kExitFailure);
  }
  gl::check((std::string("compiling the ") + stage + " shader of program " + key).c_str());
  return s;
}

GLuint Renderer::program(const std::string& key, const Program& p) {
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second;
  GLuint vs = compile(GL_VERTEX_SHADER, p, key), fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, p, key);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  GLuint prog = glCreateProgram();
  glAttachShader(prog, vs);
  glAttachShader(prog, fs);
  glLinkProgram(prog);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(prog, GL_INFO_LOG_LENGTH, &len);
    std::string log(size_t(std::clamp(len, 1, 1 << 16)), '\0');
    glGetProgramInfoLog(prog, GLsizei(log.size()), nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    glDeleteProgram(prog);
    throw Error("program '" + key + "' does not link: " + formatShaderLog(log, p.file, 0, "linked"), kExitFailure);
  }
  gl::check(("linking program " + key).c_str());
  programs_[key] = prog;
  return prog;
}

static GLenum glPrim(Prim p) {
  switch (p) {
    case Prim::Triangles: return GL_TRIANGLES;
    case Prim::Lines: return GL_LINES;
    case Prim::LineStrip: return GL_LINE_STRIP;
    case Prim::LineLoop: return GL_LINE_LOOP;
    case Prim::Points: return GL_POINTS;
  }
  return GL_TRIANGLES;
}

void Renderer::draw(const Frame& f, bool labels) { drawFrame(f, labels, true); }

void Renderer::drawOver(const Frame& f) { drawFrame(f, true, false); }

// ---- drawFrame's steps, in the order it takes them ----
// The figures' listings (.gl.txt) record these calls in this order and are
// compared byte for byte: a step keeps its calls where they are, and sets a
// piece of state only when its frame, panel or batch asks for it.

// The target: the measurement pass's framebuffer while renderOffscreen
// draws, else the context's own (which must hold the whole frame).
void Renderer::bindFrameTarget(const Frame& f) {
  if (overrideTarget_) {
    glBindFramebuffer(GL_FRAMEBUFFER, overrideTarget_);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
  } else {
    if (f.width > ctx_.width() || f.height > ctx_.height())
      throw Error("frame " + std::to_string(f.width) + "x" + std::to_string(f.height) + " is larger than the target",
                  kExitFailure);
    ctx_.bindTarget();
  }
}

// The whole frame's viewport, and its clear (drawOver keeps what is there).
static void clearFrame(const Frame& f, bool clear) {
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, f.width, f.height);
  if (clear) {
    glClearColor(f.clearColor.r, f.clearColor.g, f.clearColor.b, f.clearColor.a);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
}

// The fixed state every batch of the frame is drawn with (FixedState, which
// the sidecar records): no lighting, no culling, the shading model and the
// perspective-correction hint.
static void setFixedState(const Frame& f) {
  static_assert(!FixedState::lighting && !FixedState::cullFace, "the sidecar says what is drawn with");
  glDisable(GL_LIGHTING);
  glDisable(GL_CULL_FACE);
  glShadeModel(FixedState::shadeModel);
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, f.perspectiveHint);
}

// A panel: its viewport and scissor, its clear, its projection and modelview
// matrices, and whether it tests depth.
static void setUpPanel(const Frame& f, const Panel& p) {
  // The frame's rows count from the top; GL's from the bottom.
  int glY = f.height - p.viewport.y - p.viewport.h;
  glViewport(p.viewport.x, glY, p.viewport.w, p.viewport.h);
  glScissor(p.viewport.x, glY, p.viewport.w, p.viewport.h);
  glEnable(GL_SCISSOR_TEST);
  if (p.clear) {
    glClearColor(p.clearColor.r, p.clearColor.g, p.clearColor.b, p.clearColor.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(glm::value_ptr(p.projection));
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(glm::value_ptr(p.modelview));
  if (p.depthTest) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(FixedState::depthFunc);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
}

// What unit 0's texture is bound as: a 3D texture and a cube map have
// targets of their own (GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP).
static bool unit0Is3D(const Frame& f, const Batch& b) {
  return b.texture >= 0 && f.textures.at(size_t(b.texture)).depth > 1;
}
static bool unit0IsCube(const Frame& f, const Batch& b) {
  return b.texture >= 0 && f.textures.at(size_t(b.texture)).cube;
}

// Unit 0: the batch's texture enabled on its target and bound, and its
// environment (how the texel and the vertex colour combine); no texture
// turns texturing off.
static void bindUnit0(Renderer& r, const Frame& f, const Batch& b) {
  const bool tex3D = unit0Is3D(f, b), texCube = unit0IsCube(f, b);
  if (b.texture >= 0) {
    glEnable(tex3D ? GL_TEXTURE_3D : texCube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D);
    if (tex3D || texCube) glDisable(GL_TEXTURE_2D);
    r.texture(f.textures.at(size_t(b.texture)));
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GLint(b.texEnv));
    // The constant colour only GL_BLEND reads: set where it is used, so
    // every other batch's listing stays as it was.
    if (b.texEnv == GL_BLEND) glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, glm::value_ptr(b.envColor));
  } else {
    glDisable(GL_TEXTURE_2D);
  }
}

// The active unit's texture matrix, loaded for one batch and back to the
// identity after its glEnd.  Only a batch whose matrix is not the identity
// touches it, so the other figures' calls are unchanged.
static void loadTextureMatrix(const glm::mat4& m) {
  glMatrixMode(GL_TEXTURE);
  glLoadMatrixf(glm::value_ptr(m));
  glMatrixMode(GL_MODELVIEW);
}
static void resetTextureMatrix() {
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
}

// The texture coordinates glTexGen makes, and the switch of each.
static const GLenum kGenCoord[4] = {GL_S, GL_T, GL_R, GL_Q};
static const GLenum kGenEnable[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q};

// glTexGen's environment-mapping modes (GL_SPHERE_MAP, GL_REFLECTION_MAP,
// GL_NORMAL_MAP): the mode only, no planes (they read the normal, which the
// vertex loop sends with glNormal3f).
static void enableNormalTexGen(const TexGen& g) {
  for (int k = 0; k < 4; ++k) {
    if (!(g.coords & (1u << k))) continue;
    glTexGeni(kGenCoord[k], GL_TEXTURE_GEN_MODE, GLint(g.mode));
    glEnable(kGenEnable[k]);
  }
}

// glTexGen: texture coordinates GL makes from the vertex (planes) or from
// the normal (environment maps) instead of the batch's own.  The planes are
// given under the batch's planeModelview (GL keeps eye planes multiplied by
// its inverse), then the panel's modelview goes back.
static void enableTexGen(const Panel& p, const Batch& b) {
  if (b.texGen.needsNormal()) {
    enableNormalTexGen(b.texGen);
  } else if (b.texGen.on()) {
    const bool eye = b.texGen.mode == GL_EYE_LINEAR;
    if (eye) glLoadMatrixf(glm::value_ptr(b.texGen.planeModelview));
    for (int k = 0; k < 4; ++k) {
      if (!(b.texGen.coords & (1u << k))) continue;
      glTexGeni(kGenCoord[k], GL_TEXTURE_GEN_MODE, GLint(b.texGen.mode));
      glTexGenfv(kGenCoord[k], eye ? GL_EYE_PLANE : GL_OBJECT_PLANE, glm::value_ptr(b.texGen.planes[k]));
      glEnable(kGenEnable[k]);
    }
    if (eye) glLoadMatrixf(glm::value_ptr(p.modelview));
  }
}

// A user clip plane, given under the batch's clipModelview (GL keeps
// plane · M⁻¹), as the sidecar records it, then the panel's modelview back.
static void enableClipPlane(const Panel& p, const Batch& b) {
  if (!b.clip) return;
  const double plane[4] = {b.clipPlane.x, b.clipPlane.y, b.clipPlane.z, b.clipPlane.w};
  glLoadMatrixf(glm::value_ptr(b.clipModelview));
  glClipPlane(GL_CLIP_PLANE0, plane);
  glLoadMatrixf(glm::value_ptr(p.modelview));
  glEnable(GL_CLIP_PLANE0);
}

// The batch's shader program, if it names one: made once, then bound with
// its sampler "tex" on unit 0 and the batch's uniforms.  0: fixed function.
static GLuint useProgram(Renderer& r, const Frame& f, const Batch& b) {
  if (b.program.empty()) return 0;
  const Program* src = nullptr;
  for (const auto& [k, pr] : f.programs)
    if (k == b.program) src = &pr;
  if (!src) throw Error("batch uses unknown program '" + b.program + "'", kExitFailure);
  GLuint prog = r.program(b.program, *src);
  glUseProgram(prog);
  GLint tex = glGetUniformLocation(prog, "tex");
  if (tex >= 0) glUniform1i(tex, 0);
  for (const Uniform& u : b.uniforms) {
    GLint loc = glGetUniformLocation(prog, u.name.c_str());
    if (loc >= 0) glUniform4f(loc, u.value.x, u.value.y, u.value.z, u.value.w);
  }
  return prog;
}

// Blending and the alpha test: how the batch's fragments combine with what
// is there, and which are discarded.
static void setBlending(const Batch& b) {
  if (b.blend) {
    glEnable(GL_BLEND);
    // Colour blends over what is there; alpha stays the clear's (opaque):
    // a figure must not let the page show through where it blends.
    if (b.blendFactors())  // the batch's colour factors (adding, multiplying passes)
      glBlendFuncSeparate(b.blendSrc, b.blendDst, FixedState::blendSrcAlpha, FixedState::blendDstAlpha);
    else
      glBlendFuncSeparate(FixedState::blendSrc, FixedState::blendDst, FixedState::blendSrcAlpha,
                          FixedState::blendDstAlpha);
  } else {
    glDisable(GL_BLEND);
  }
  if (b.alphaTest()) {  // discarded fragments write neither colour nor depth
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(b.alphaFunc, b.alphaRef);
  }
}

// Unit 1 (multitexturing): its texture, its environment (GL_COMBINE's
// function, sources and operands) and its texture matrix, set on unit 1,
// then unit 0 is active again.
static void bindUnit1(Renderer& r, const Frame& f, const Batch& b) {
  if (b.texture1 < 0) return;
  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_TEXTURE_2D);
  r.texture(f.textures.at(size_t(b.texture1)));
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GLint(b.texEnv1));
  if (b.texEnv1 == GL_COMBINE) {
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GLint(b.combine1.rgb));
    for (int k = 0; k < 3; ++k) {
      glTexEnvi(GL_TEXTURE_ENV, GLenum(GL_SOURCE0_RGB + k), GLint(b.combine1.source[k]));
      glTexEnvi(GL_TEXTURE_ENV, GLenum(GL_OPERAND0_RGB + k), GLint(b.combine1.operand[k]));
    }
  }
  if (b.textureMatrix1 != glm::mat4(1.0f)) loadTextureMatrix(b.textureMatrix1);
  glActiveTexture(GL_TEXTURE0);
}

// The depth comparison (GL_LEQUAL for a second pass over the same
// surface), the line width and the point size.
static void setRasterState(const Batch& b) {
  if (b.depthFunc) glDepthFunc(b.depthFunc);
  if (!b.depthWrite) glDepthMask(GL_FALSE);
  glLineWidth(b.lineWidth);
  glPointSize(b.pointSize);
}

// The batch itself, the book's way: one glTexCoord per glVertex.  (s, t, r,
// q) are all sent; q != 1 gives projective texture mapping.
static void sendVertices(const Batch& b) {
  const bool unit1 = b.texture1 >= 0;
  glBegin(glPrim(b.prim));
  for (const Vertex& v : b.vertices) {
    glColor4f(v.color.r, v.color.g, v.color.b, v.color.a);
    if (b.colorSum) glSecondaryColor3f(v.secondary.r, v.secondary.g, v.secondary.b);
    glTexCoord4f(v.tex.x, v.tex.y, v.tex.z, v.tex.w);
    if (b.texGen.needsNormal()) glNormal3f(v.normal.x, v.normal.y, v.normal.z);
    if (unit1) {  // unit 0's coordinates, or its own (Batch::coords1)
      const glm::vec4& u = b.coords1 ? v.tex1 : v.tex;
      glMultiTexCoord4f(GL_TEXTURE1, u.x, u.y, u.z, u.w);
    }
    glVertex3f(v.pos.x, v.pos.y, v.pos.z);
  }
  glEnd();
}

// After glEnd: what the batch turned on goes back off, so the next batch
// starts from the fixed state and the panel's.
static void undoBatchState(const Frame& f, const Batch& b, GLuint prog) {
  if (b.colorSum) glDisable(GL_COLOR_SUM);
  if (b.texGen.on())
    for (int k = 0; k < 4; ++k)
      if (b.texGen.coords & (1u << k)) glDisable(kGenEnable[k]);
  if (b.clip) glDisable(GL_CLIP_PLANE0);
  if (b.alphaTest()) glDisable(GL_ALPHA_TEST);
  if (b.depthFunc) glDepthFunc(FixedState::depthFunc);
  if (!b.depthWrite) glDepthMask(GL_TRUE);
  if (b.texture1 >= 0) {
    glActiveTexture(GL_TEXTURE1);
    glDisable(GL_TEXTURE_2D);
    if (b.textureMatrix1 != glm::mat4(1.0f)) resetTextureMatrix();
    glActiveTexture(GL_TEXTURE0);
  }
  if (unit0Is3D(f, b)) glDisable(GL_TEXTURE_3D);
  if (unit0IsCube(f, b)) glDisable(GL_TEXTURE_CUBE_MAP);
  if (b.textureMatrix != glm::mat4(1.0f)) resetTextureMatrix();
  if (prog) glUseProgram(0);
}

// One batch: its state step by step, its vertices, then its state undone.
static void drawBatch(Renderer& r, const Frame& f, const Panel& p, const Batch& b) {
  bindUnit0(r, f, b);
  if (b.textureMatrix != glm::mat4(1.0f)) loadTextureMatrix(b.textureMatrix);
  // GL_SEPARATE_SPECULAR_COLOR's second half: the secondary colour is
  // added after texturing (GL 1.4 colour sum; lighting stays off here).
  if (b.colorSum) glEnable(GL_COLOR_SUM);
  enableTexGen(p, b);
  enableClipPlane(p, b);
  const GLuint prog = useProgram(r, f, b);
  setBlending(b);
  bindUnit1(r, f, b);
  setRasterState(b);
  sendVertices(b);
  undoBatchState(f, b, prog);
}

// The steps, in order:
//   1. bindFrameTarget  the framebuffer drawn into
//   2. clearFrame       the whole frame's viewport and clear
//   3. setFixedState    lighting, culling, shading, perspective hint
//   4. for each panel: setUpPanel (viewport, scissor, matrices, depth test),
//      then for each batch drawBatch:
//        bindUnit0, the texture matrix, colour sum, enableTexGen,
//        enableClipPlane, useProgram, setBlending, bindUnit1,
//        setRasterState, sendVertices (glBegin ... glEnd), undoBatchState
//   5. the frame's state off again, then drawLabels (the text)
void Renderer::drawFrame(const Frame& f, bool labels, bool clear) {
  bindFrameTarget(f);
  clearFrame(f, clear);
  setFixedState(f);
  for (const Panel& p : f.panels) {
    setUpPanel(f, p);
    for (const Batch& b : p.batches) drawBatch(*this, f, p, b);
    gl::check(("drawing panel " + p.id).c_str());
  }
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_TEXTURE_2D);
  if (labels) drawLabels(f);
}

void Renderer::drawLabels(const Frame& f) {
  if (f.labels.empty()) return;
  const Image& atlas = text::atlas();
  if (!fontTexture_) {
    glGenTextures(1, &fontTexture_);
    glBindTexture(GL_TEXTURE_2D, fontTexture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    upload(atlas, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  }
  glViewport(0, 0, f.width, f.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, f.width, f.height, 0, -1, 1);  // pixels, y down, like the PNG
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_BLEND);
  // Alpha stays opaque, as in the batches.
  glBlendFuncSeparate(FixedState::blendSrc, FixedState::blendDst, FixedState::blendSrcAlpha, FixedState::blendDstAlpha);
  for (const Label& l : f.labels) {
    float w = text::width(l.text, l.scale), h = text::height(l.scale);
    float x = l.align == Align::Left ? l.x : l.align == Align::Center ? l.x - w / 2 : l.x - w;
    x = float(int(x));
    float y = float(int(l.y));
    if (l.background.a > 0) {
      glDisable(GL_TEXTURE_2D);
      glColor4f(l.background.r, l.background.g, l.background.b, l.background.a);
      float pad = 3.0f * float(l.scale);
      glBegin(GL_QUADS);
      glVertex2f(x - pad, y - pad);
      glVertex2f(x + w + pad, y - pad);
      glVertex2f(x + w + pad, y + h + pad);
      glVertex2f(x - pad, y + h + pad);
      glEnd();
    }
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, fontTexture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(l.color.r, l.color.g, l.color.b, l.color.a);
    glBegin(GL_QUADS);
    float pen = x;
    text::Glyph g;
    for (char c : l.text) {
      if (!text::glyph(c, l.scale, &g)) continue;
      glTexCoord2f(g.u0, g.v0), glVertex2f(pen + g.x0, y + g.y0);
      glTexCoord2f(g.u1, g.v0), glVertex2f(pen + g.x1, y + g.y0);
      glTexCoord2f(g.u1, g.v1), glVertex2f(pen + g.x1, y + g.y1);
      glTexCoord2f(g.u0, g.v1), glVertex2f(pen + g.x0, y + g.y1);
      pen += g.advance;
    }
    glEnd();
  }
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_BLEND);
  gl::check("drawing labels");
}

Image Renderer::offscreen(int w, int h, const char* what, const std::function<void(GLuint fbo)>& draw) {
  // A target of its own for each pass (made, drawn, read, deleted): a pass
  // inside a pass (a measurement that renders a frame) cannot clobber it.
  RenderTarget target;
  target.make({w, h}, what);
  Image img;
  std::string failure;
  {
    RenderTarget::Bind bound(target);
    try {
      draw(target.framebuffer());
    } catch (const Error& e) {
      failure = e.what();
    }
    if (failure.empty()) img = target.readRGBA8();
  }
  target.free();
  if (!failure.empty()) throw Error(failure, kExitFailure);
  gl::check(what);
  return img;
}

void Renderer::drawOffscreen(const Frame& f, const std::function<void()>& then) {
  RenderTarget target;
  target.make({f.width, f.height}, "a pass drawn into a texture");
  std::string failure;
  {
    RenderTarget::Bind bound(target);
    overrideTarget_ = target.framebuffer();  // draw() binds it instead of the context's target
    try {
      draw(f, false);
      then();
    } catch (const Error& e) {
      failure = e.what();
    }
    overrideTarget_ = 0;
  }
  target.free();
  if (!failure.empty()) throw Error(failure, kExitFailure);
  gl::check("a pass drawn into a texture");
}

Image Renderer::renderOffscreen(const Frame& f) {
  return offscreen(f.width, f.height, "a measurement pass", [&](GLuint fbo) {
    overrideTarget_ = fbo;  // draw() binds it instead of the context's target
    try {
      draw(f, false);
    } catch (...) {
      overrideTarget_ = 0;
      throw;
    }
    overrideTarget_ = 0;
  });
}

Image Renderer::render(const Frame& f, bool labels) {
  draw(f, labels);
  glFinish();
  Image full = ctx_.readPixels();
  if (full.width == f.width && full.height == f.height) return full;
  // The target may be larger than the frame (a shared context): crop the
  // bottom-left f.width x f.height, which is where GL drew.
  Image out(f.width, f.height);
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) out.set(x, y, full.at(x, full.height - f.height + y));
  return out;
}
}  // namespace ts
