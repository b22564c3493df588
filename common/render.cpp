#include "render.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "context.hpp"
#include "error.hpp"
#include "text.hpp"
#include "textures.hpp"

namespace ts {
Renderer::~Renderer() {
  // The context may already be gone; GL objects die with it.
}

void Renderer::release() {
  for (auto& [k, id] : textures_) glDeleteTextures(1, &id);
  for (auto& [k, id] : programs_) glDeleteProgram(id);
  if (fontTexture_) glDeleteTextures(1, &fontTexture_);
  textures_.clear();
  programs_.clear();
  fontTexture_ = 0;
}

static void upload(const Image& img, int level) {
  glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               img.pixels.data());
}

GLuint Renderer::texture(const TextureDesc& t) {
  auto it = textures_.find(t.key());
  GLuint id = 0;
  if (it != textures_.end()) {
    id = it->second;
    glBindTexture(GL_TEXTURE_2D, id);
  } else {
    if (!t.image) throw Error("texture '" + t.name + "' has no image", kExitFailure);
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (t.mipmaps) {
      // The book's chain, built on the CPU so it is the same on every driver.
      std::vector<Image> chain = t.mipLevels ? *t.mipLevels : buildMipChain(*t.image, t.linearLightMips);
      for (size_t k = 0; k < chain.size(); ++k) upload(chain[k], int(k));
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, int(chain.size()) - 1);
    } else {
      upload(*t.image, 0);
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
  if (gl::hasExtension("GL_EXT_texture_filter_anisotropic") || gl::version() >= 46)
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, t.maxAnisotropy);
  gl::check(("setting the parameters of texture " + t.key()).c_str());
  return id;
}

static GLuint compile(GLenum type, const std::string& src, const std::string& where) {
  GLuint s = glCreateShader(type);
  const char* p = src.c_str();
  glShaderSource(s, 1, &p, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {0};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    glDeleteShader(s);
    std::string l = log;
    while (!l.empty() && (l.back() == '\n' || l.back() == ' ')) l.pop_back();
    for (char& c : l)
      if (c == '\n') c = ' ';
    throw Error(where + ": " + (type == GL_VERTEX_SHADER ? "vertex" : "fragment") + " shader: " + l, kExitFailure);
  }
  return s;
}

GLuint Renderer::program(const std::string& key, const Program& p) {
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second;
  std::string where = p.file + " (program " + key + ")";
  GLuint vs = compile(GL_VERTEX_SHADER, p.vertex, where), fs = compile(GL_FRAGMENT_SHADER, p.fragment, where);
  GLuint prog = glCreateProgram();
  glAttachShader(prog, vs);
  glAttachShader(prog, fs);
  glLinkProgram(prog);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {0};
    glGetProgramInfoLog(prog, sizeof log, nullptr, log);
    glDeleteProgram(prog);
    throw Error(where + ": link: " + log, kExitFailure);
  }
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

void Renderer::draw(const Frame& f, bool labels) {
  if (overrideTarget_) {
    glBindFramebuffer(GL_FRAMEBUFFER, overrideTarget_);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
  } else {
    if (f.width > ctx_.width() || f.height > ctx_.height())
      throw Error("frame " + std::to_string(f.width) + "x" + std::to_string(f.height) + " is larger than the target",
                  kExitFailure);
    ctx_.bindTarget();
  }
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, f.width, f.height);
  glClearColor(f.clearColor.r, f.clearColor.g, f.clearColor.b, f.clearColor.a);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_CULL_FACE);
  glShadeModel(GL_SMOOTH);
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, f.perspectiveHint);
  for (const Panel& p : f.panels) {
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
      glDepthFunc(GL_LESS);
    } else {
      glDisable(GL_DEPTH_TEST);
    }
    for (const Batch& b : p.batches) {
      if (b.texture >= 0) {
        glEnable(GL_TEXTURE_2D);
        texture(f.textures.at(size_t(b.texture)));
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GLint(b.texEnv));
      } else {
        glDisable(GL_TEXTURE_2D);
      }
      GLuint prog = 0;
      if (!b.program.empty()) {
        const Program* src = nullptr;
        for (const auto& [k, pr] : f.programs)
          if (k == b.program) src = &pr;
        if (!src) throw Error("batch uses unknown program '" + b.program + "'", kExitFailure);
        prog = program(b.program, *src);
        glUseProgram(prog);
        GLint tex = glGetUniformLocation(prog, "tex");
        if (tex >= 0) glUniform1i(tex, 0);
        for (const Uniform& u : b.uniforms) {
          GLint loc = glGetUniformLocation(prog, u.name.c_str());
          if (loc >= 0) glUniform4f(loc, u.value.x, u.value.y, u.value.z, u.value.w);
        }
      }
      if (b.blend) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      } else {
        glDisable(GL_BLEND);
      }
      glLineWidth(b.lineWidth);
      glPointSize(b.pointSize);
      // The book's way: one glTexCoord per glVertex.  (s, t, r, q) are all
      // sent; q != 1 gives projective texture mapping.
      glBegin(glPrim(b.prim));
      for (const Vertex& v : b.vertices) {
        glColor4f(v.color.r, v.color.g, v.color.b, v.color.a);
        glTexCoord4f(v.tex.x, v.tex.y, v.tex.z, v.tex.w);
        glVertex3f(v.pos.x, v.pos.y, v.pos.z);
      }
      glEnd();
      if (prog) glUseProgram(0);
    }
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
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
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

Image Renderer::renderOffscreen(const Frame& f) {
  if (!gl::p_glGenFramebuffers) throw Error("measurement passes need framebuffer objects (GL 3.0)", kExitFailure);
  GLint drawBuffer = 0, readBuffer = 0, boundFbo = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &drawBuffer);
  glGetIntegerv(GL_READ_BUFFER, &readBuffer);
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &boundFbo);
  GLuint fbo = 0, rb[2] = {0, 0};
  glGenFramebuffers(1, &fbo);
  glGenRenderbuffers(2, rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, f.width, f.height);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, f.width, f.height);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  Image img(f.width, f.height);
  std::string failure;
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    failure = "measurement framebuffer " + std::to_string(f.width) + "x" + std::to_string(f.height) + " is incomplete";
  } else {
    overrideTarget_ = fbo;
    try {
      draw(f, false);
    } catch (const Error& e) {
      failure = e.what();
    }
    overrideTarget_ = 0;
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, f.width, f.height, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
    img.flipVertical();
  }
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(boundFbo));
  glDeleteFramebuffers(1, &fbo);
  glDeleteRenderbuffers(2, rb);
  glDrawBuffer(GLenum(drawBuffer));
  glReadBuffer(GLenum(readBuffer));
  if (!failure.empty()) throw Error(failure, kExitFailure);
  gl::check("a measurement pass");
  return img;
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
