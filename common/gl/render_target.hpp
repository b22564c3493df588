// common/gl/render_target.hpp — the suite's one render target: a framebuffer
// object a pass draws into and reads back.
//
//   RenderTarget t;
//   t.make({w, h}, "a measurement pass");    // glGenFramebuffers, attachments
//   {
//     RenderTarget::Bind bound(t);            // glBindFramebuffer, glDrawBuffer,
//     ... draw ...                            //   glViewport(0, 0, w, h)
//     Image img = t.readRGBA8();              // glReadPixels
//   }                                         // the previous framebuffer,
//                                             //   buffers and viewport again
//
// Every framebuffer object of the suite is one of these: Renderer::offscreen
// (measurement passes, the bump-mapping passes), the EGL context's target,
// the environment-mapping and parallax passes.
#pragma once
#include <vector>

#include "common/core/image.hpp"
#include "common/gl/gl.hpp"

namespace ts {

struct TargetFormat {
  int width = 0, height = 0;
  enum Colour { kRGBA8, kRGBA32F } colour = kRGBA8;
  enum Depth { kNoDepth, kDepth24, kDepth24Stencil8 } depth = kDepth24Stencil8;
  // The colour attachment as a texture (GL_NEAREST, one level) that can be
  // sampled afterwards (a live view shows it as it is), or a renderbuffer.
  bool colourTexture = false;
  bool operator==(const TargetFormat& o) const {
    return width == o.width && height == o.height && colour == o.colour && depth == o.depth &&
           colourTexture == o.colourTexture;
  }
  bool operator!=(const TargetFormat& o) const { return !(*this == o); }
};

class RenderTarget {
 public:
  RenderTarget() = default;
  ~RenderTarget() { free(); }  // the context must still be current
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // Makes the framebuffer and its attachments, unless it already has this
  // format.  Throws ts::Error naming `what` when the context has no
  // framebuffer objects (GL 3.0) or the framebuffer is incomplete.
  void make(const TargetFormat& f, const char* what);
  // Deletes the GL objects (the context must be current); make() again.
  void free();
  const TargetFormat& format() const { return format_; }
  GLuint framebuffer() const { return fbo_; }
  GLuint colourTexture() const { return colourTex_; }  // 0 unless format().colourTexture

  // The colour attachment read back, row 0 = top.  Call while bound.
  Image readRGBA8() const;
  // The same as RGBA floats, in GL's row order (row 0 = bottom).
  std::vector<float> readFloat() const;

  // While a Bind lives, the target is the framebuffer, its colour attachment
  // the draw and read buffer, and the viewport covers it.  Its destructor
  // restores what it changed: the framebuffer binding, the draw and read
  // buffers and the viewport.
  class Bind {
   public:
    explicit Bind(const RenderTarget& t);
    ~Bind();
    Bind(const Bind&) = delete;
    Bind& operator=(const Bind&) = delete;

   private:
    GLint fbo_ = 0, draw_ = 0, read_ = 0, viewport_[4] = {0, 0, 0, 0};
  };

 private:
  TargetFormat format_;
  GLuint fbo_ = 0, colourTex_ = 0, colourRb_ = 0, depthRb_ = 0;
};

}  // namespace ts
