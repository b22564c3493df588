// common/gl/render.hpp — draws a Frame with OpenGL and measures what it drew.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <typeindex>
#include <typeinfo>

#include "common/core/frame.hpp"
#include "common/gl/gl.hpp"
#include "common/core/image.hpp"

namespace ts {
class Context;

// A shader or program info log as one line, each message prefixed with
// "file:line:col" counted in the C++ file that holds the shader source
// (firstLine = the line where the source starts; 0 = unknown, then
// "file: <stage> shader line N").  Used in compile and link errors.
std::string formatShaderLog(const std::string& log, const std::string& file, int firstLine, const char* stage);

class Renderer {
 public:
  explicit Renderer(Context& ctx) : ctx_(ctx) {}
  // Deletes every GL object it owns, its attachments' too: destroy a
  // Renderer while its context is still current (RAII: declare it after the
  // context, or reset it before the context goes).
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws the whole frame into the context's current target.  The target
  // must be at least frame.width x frame.height.  `labels` off leaves the
  // text out (measurement passes).
  void draw(const Frame& frame, bool labels = true);
  // The same over what the target holds, without clearing it (the window's
  // inspect mode draws a picked pixel's footprint over the figure).
  void drawOver(const Frame& frame);
  // draw() and read back: the picture as the PNG will hold it.
  Image render(const Frame& frame, bool labels = true);
  // Draws into a private framebuffer object (render_target.hpp) of the
  // frame's size and reads it back: measurement passes get the same pixels whatever the window's size,
  // and leave the window's own target untouched.
  Image renderOffscreen(const Frame& frame);
  // The same without the readback: `then()` runs while the private framebuffer still holds the picture and
  // is bound for reading (a pass that copies what it drew into a texture, glCopyTexSubImage2D), then the
  // framebuffer is deleted.
  void drawOffscreen(const Frame& frame, const std::function<void()>& then);
  // The GL name of a 3D texture (TextureDesc::depth > 1), bound to GL_TEXTURE_3D.
  GLuint texture3D(const TextureDesc& t);
  // The GL name of a cube map (TextureDesc::cube), bound to GL_TEXTURE_CUBE_MAP.
  GLuint textureCube(const TextureDesc& t);
  // A pass of one's own into a private RenderTarget (render_target.hpp) of
  // w x h (RGBA8 colour, 24-bit depth, 8-bit stencil), bound with its colour
  // attachment as the draw buffer and the viewport over it while `draw(fbo)`
  // makes the GL calls, then read back (row 0 = top).  It restores what it
  // changes: the framebuffer binding, the draw and read buffers, the
  // viewport.  `what` names the pass in errors.
  Image offscreen(int w, int h, const char* what, const std::function<void(GLuint fbo)>& draw);
  Context& context() { return ctx_; }
  // The size the picture will be drawn at: the context's, unless a window
  // lays the figure out in part of it beside its panels (a live view, which
  // draws its picture inside measure(), draws at this size).
  int pictureWidth();
  int pictureHeight();
  void setPictureSize(int w, int h) { pictureW_ = w, pictureH_ = h; }  // 0, 0: the context's
  // The GL texture for a description (uploaded once per key, then cached;
  // filters and wrap modes are set on every bind).
  GLuint texture(const TextureDesc& t);
  // Deletes the cached texture of this description, if any: the next
  // texture() uploads it again (and a recorded pass shows how).
  void forgetTexture(const TextureDesc& t);
  GLuint program(const std::string& key, const Program& p);
  // Drops the cached textures and programs (before recording a picture, so
  // that the record shows how each is made: see recordPicture in
  // gl_listing.hpp).  Attachments stay.
  void release();

  // GL objects a demo keeps for this renderer's context beyond a Frame (the
  // parallax passes' programs, textures and target): made as T(*this) on
  // first use, owned by the renderer, deleted by T's destructor when the
  // renderer goes, while its context is still current.
  struct Attachment {
    virtual ~Attachment() = default;
  };
  template <class T>
  T& attachment() {
    std::unique_ptr<Attachment>& slot = attachments_[std::type_index(typeid(T))];
    if (!slot) slot = std::make_unique<T>(*this);
    return static_cast<T&>(*slot);
  }

 private:
  void drawLabels(const Frame& frame);
  void drawFrame(const Frame& frame, bool labels, bool clear);
  void bindFrameTarget(const Frame& frame);  // drawFrame's first step
  Context& ctx_;
  std::map<std::type_index, std::unique_ptr<Attachment>> attachments_;
  int pictureW_ = 0, pictureH_ = 0;
  std::map<std::string, GLuint> textures_;
  std::map<std::string, GLuint> programs_;
  GLuint fontTexture_ = 0;
  GLuint overrideTarget_ = 0;  // set while renderOffscreen draws
};
}  // namespace ts
