// common/gl/render_target.cpp — see render_target.hpp.
#include "common/gl/render_target.hpp"

#include <algorithm>
#include <string>

#include "common/core/error.hpp"

namespace ts {

void RenderTarget::make(const TargetFormat& f, const char* what) {
  if (fbo_ && f == format_) return;
  if (!gl::p_glGenFramebuffers) throw Error(std::string(what) + " needs framebuffer objects (GL 3.0)", kExitFailure);
  free();
  const bool fl = f.colour == TargetFormat::kRGBA32F;
  GLint prevFbo = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &prevFbo);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  if (f.colourTexture) {
    GLint prevTex = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &prevTex);
    glGenTextures(1, &colourTex_);
    glBindTexture(GL_TEXTURE_2D, colourTex_);
    glTexImage2D(GL_TEXTURE_2D, 0, fl ? GL_RGBA32F : GL_RGBA8, f.width, f.height, 0, GL_RGBA,
                 fl ? GL_FLOAT : GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, GLuint(prevTex));
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colourTex_, 0);
  } else {
    glGenRenderbuffers(1, &colourRb_);
    glBindRenderbuffer(GL_RENDERBUFFER, colourRb_);
    glRenderbufferStorage(GL_RENDERBUFFER, fl ? GL_RGBA32F : GL_RGBA8, f.width, f.height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colourRb_);
  }
  if (f.depth != TargetFormat::kNoDepth) {
    const bool stencil = f.depth == TargetFormat::kDepth24Stencil8;
    glGenRenderbuffers(1, &depthRb_);
    glBindRenderbuffer(GL_RENDERBUFFER, depthRb_);
    glRenderbufferStorage(GL_RENDERBUFFER, stencil ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24, f.width, f.height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                              GL_RENDERBUFFER, depthRb_);
  }
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(prevFbo));
  if (!complete) {
    free();
    throw Error("the " + std::to_string(f.width) + "x" + std::to_string(f.height) + " framebuffer of " + what +
                    " is incomplete",
                kExitFailure);
  }
  format_ = f;
  gl::check(what);
}

void RenderTarget::free() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (colourTex_) glDeleteTextures(1, &colourTex_);
  if (colourRb_) glDeleteRenderbuffers(1, &colourRb_);
  if (depthRb_) glDeleteRenderbuffers(1, &depthRb_);
  fbo_ = colourTex_ = colourRb_ = depthRb_ = 0;
  format_ = TargetFormat();
}

Image RenderTarget::readRGBA8() const {
  Image img(format_.width, format_.height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, format_.width, format_.height, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
  img.flipVertical();
  return img;
}

std::vector<float> RenderTarget::readFloat() const {
  std::vector<float> v(size_t(format_.width) * size_t(format_.height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, format_.width, format_.height, GL_RGBA, GL_FLOAT, v.data());
  return v;
}

RenderTarget::Bind::Bind(const RenderTarget& t) {
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo_);
  glGetIntegerv(GL_DRAW_BUFFER, &draw_);
  glGetIntegerv(GL_READ_BUFFER, &read_);
  glGetIntegerv(GL_VIEWPORT, viewport_);
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer());
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glViewport(0, 0, t.format().width, t.format().height);
}

RenderTarget::Bind::~Bind() {
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(fbo_));
  // The draw and read buffers belong to each framebuffer (GL 3.0), so binding
  // the previous one brings its own back; set them only if they differ, and
  // the viewport only if it changed (the GL listings stay free of no-ops).
  GLint now = 0, viewport[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_DRAW_BUFFER, &now);
  if (now != draw_) glDrawBuffer(GLenum(draw_));
  glGetIntegerv(GL_READ_BUFFER, &now);
  if (now != read_) glReadBuffer(GLenum(read_));
  glGetIntegerv(GL_VIEWPORT, viewport);
  if (!std::equal(viewport, viewport + 4, viewport_))
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
}

}  // namespace ts
