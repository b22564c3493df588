// demos/texture_residency/texture_residency_gl.hpp — the demo's own GL: the size queries (GL_MAX_TEXTURE_SIZE, a
// proxy texture's answer and what the program does with a 0), and the clipmap's stack of 512^2 textures made once
// with no data and kept up to date by glTexSubImage2D of the strips a move exposes, stored toroidally (texel i of
// level l at i mod 512, which GL_REPEAT reads back).  Each pass restores the state it changes and deletes its
// textures; the uploads are recorded (gl::Recording) so that the texels are counted from the calls made.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "common/gl/gl.hpp"
#include "common/gl/gl_record.hpp"
#include "common/gl/pixel_pass.hpp"
#include "common/gl/render.hpp"
#include "texture_residency_math.hpp"

namespace ts::residency {
// ---- the size rules ---------------------------------------------------------------------------------------------
// The width GL would give an RGBA8 size x size texture: glTexImage2D on GL_PROXY_TEXTURE_2D allocates nothing,
// and GL_TEXTURE_WIDTH reads 0 when the size does not fit.
inline int proxyWidth(int size) {
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  GLint w = 0;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  return int(w);
}
struct SizeRules {
  int maxSize = 0;       // GL_MAX_TEXTURE_SIZE: this backend's
  int fitsWidth = 0;     // the proxy's width for 1024^2 (fits: 1024)
  int tooBigWidth = -1;  // the proxy's width for (2 max)^2 (does not fit: 0)
  int halvings = 0;      // how often the program halved (2 max) until the proxy said it fits
  int settled = 0;       // the size it settled on
  int settledWidth = 0;  // the proxy's width for it (= settled)
  gl::CallList calls;
};
inline SizeRules querySizes() {
  SizeRules s;
  gl::Recording rec;
  GLint max = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  s.maxSize = int(max);
  s.fitsWidth = proxyWidth(1024);
  // What a program does with a size that does not fit: halve it until the proxy gives a width.
  int size = 2 * s.maxSize;
  s.tooBigWidth = proxyWidth(size);
  for (int w = s.tooBigWidth; w == 0 && size > 1; w = proxyWidth(size)) size /= 2, ++s.halvings;
  s.settled = size;
  s.settledWidth = proxyWidth(size);
  s.calls = std::make_shared<const std::vector<gl::Call>>(rec.take());
  return s;
}

// ---- the clipmap ------------------------------------------------------------------------------------------------
// The stack: one 512^2 GL_RGBA8 texture a clipped level, GL_NEAREST (the level is chosen by the window, and the
// picture is then exact), GL_REPEAT (the toroidal addressing).
class ClipStack {
 public:
  ClipStack() {
    glGenTextures(kClipLevels, tex_.data());
    for (GLuint t : tex_) {
      glBindTexture(GL_TEXTURE_2D, t);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kClip, kClip, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    }
  }
  ~ClipStack() { glDeleteTextures(kClipLevels, tex_.data()); }
  ClipStack(const ClipStack&) = delete;
  ClipStack& operator=(const ClipStack&) = delete;
  // Level l's texels of the virtual rectangle r, into their toroidal places (one glTexSubImage2D a piece).
  void upload(int l, const TexelRect& r) {
    glBindTexture(GL_TEXTURE_2D, tex_[size_t(l)]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (const Piece& p : toroidalPieces(r)) {
      std::vector<unsigned char> texels(size_t(p.w) * size_t(p.h) * 4);
      for (int j = 0; j < p.h; ++j)
        for (int i = 0; i < p.w; ++i) {
          const Rgba c = virtualTexel(l, p.vx + i, p.vy + j);
          unsigned char* q = &texels[(size_t(j) * size_t(p.w) + size_t(i)) * 4];
          q[0] = c.r, q[1] = c.g, q[2] = c.b, q[3] = c.a;
        }
      glTexSubImage2D(GL_TEXTURE_2D, 0, p.sx, p.sy, p.w, p.h, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    }
  }
  // Every level's whole window at e (the first load, or a reload).
  void load(const Eye& e) {
    for (int l = 0; l < kClipLevels; ++l) upload(l, {windowOrigin(e, l).x, windowOrigin(e, l).y, kClip, kClip});
  }
  // The eye moved from `from` to `to`: each level gets only the strips that entered its window.
  void move(const Eye& from, const Eye& to) {
    for (int l = 0; l < kClipLevels; ++l)
      for (const TexelRect& r : exposed(from, to, l)) upload(l, r);
  }
  // The view at eye e, read back (row 0 the top): the levels drawn coarsest first, each a quad over its window,
  // its texture coordinates the window's level-l texels over 512 (GL_REPEAT wraps them onto the storage).
  Image draw(Renderer& r, const Eye& e) {
    return pixelPass(r, kViewPx, kViewPx, "the clipmap's view", [&] {
      glMatrixMode(GL_TEXTURE), glPushMatrix(), glLoadIdentity();
      glEnable(GL_TEXTURE_2D);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
      for (int l = kClipLevels - 1; l >= 0; --l) {
        const Eye w = windowOrigin(e, l);
        const double scale = double(1 << l) / kTexelsPerPixel;  // pixels a level-l texel
        const float x0 = float((w.x * double(1 << l) - viewOriginX(e)) / kTexelsPerPixel);
        const float y0 = float((w.y * double(1 << l) - viewOriginY(e)) / kTexelsPerPixel);
        const float side = float(kClip * scale);
        // The window's first texel sits at storage (w mod 512): its texture coordinate, kept in [0, 1).
        float s0 = float(mod(w.x, kClip)) / kClip, t0 = float(mod(w.y, kClip)) / kClip, ds = 1, dt = 1;
        float px0 = x0, py0 = y0, pw = side, ph = side;
        if (l == kClipLevels - 1) {
          // The coarsest level's window is its whole period (16384 / 32 = 512): every point of the view is in its
          // storage, so its quad covers the whole view (the window's edge may fall a pixel inside it).
          s0 -= x0 / side, t0 -= y0 / side, ds = dt = float(kViewPx) / side;
          px0 = py0 = 0, pw = ph = float(kViewPx);
        }
        glBindTexture(GL_TEXTURE_2D, tex_[size_t(l)]);
        glBegin(GL_QUADS);
        for (int c = 0; c < 4; ++c) {
          const float a = float(c == 1 || c == 2), b = float(c >= 2);
          glTexCoord2f(s0 + a * ds, t0 + b * dt);
          glVertex2f(px0 + a * pw, py0 + b * ph);
        }
        glEnd();
      }
      glMatrixMode(GL_TEXTURE), glPopMatrix();
      glMatrixMode(GL_MODELVIEW);
    });
  }
  // The flight view at eye e, read back (row 0 the top): the windows as ground quads in perspective, coarsest first.
  Image drawFlight(Renderer& r, const Eye& e) {
    const Camera c = flightCamera(e);
    const glm::mat4 p(c.projection), v(c.view);
    return r.offscreen(kFlightW, kFlightH, "the clipmap's flight", [&](GLuint) {
      glPushAttrib(GL_ALL_ATTRIB_BITS);
      glMatrixMode(GL_PROJECTION), glPushMatrix(), glLoadMatrixf(&p[0][0]);
      glMatrixMode(GL_MODELVIEW), glPushMatrix(), glLoadMatrixf(&v[0][0]);
      glMatrixMode(GL_TEXTURE), glPushMatrix(), glLoadIdentity();
      glDisable(GL_DEPTH_TEST), glDisable(GL_BLEND), glDisable(GL_CULL_FACE), glDisable(GL_LIGHTING);
      glUseProgram(0);
      glClearColor(kSky.r / 255.0f, kSky.g / 255.0f, kSky.b / 255.0f, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      glEnable(GL_TEXTURE_2D);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
      for (int l = kClipLevels - 1; l >= 0; --l) {
        const Eye w = windowOrigin(e, l);
        const float s0 = float(mod(w.x, kClip)) / kClip, t0 = float(mod(w.y, kClip)) / kClip;
        const float x0 = float(w.x) * float(1 << l), y0 = float(w.y) * float(1 << l), side = float(kClip << l);
        glBindTexture(GL_TEXTURE_2D, tex_[size_t(l)]);
        glBegin(GL_QUADS);
        for (int k = 0; k < 4; ++k) {
          const float a = float(k == 1 || k == 2), b = float(k >= 2);
          glTexCoord2f(s0 + a, t0 + b);
          glVertex3f(x0 + a * side, y0 + b * side, 0);
        }
        glEnd();
      }
      glMatrixMode(GL_TEXTURE), glPopMatrix();
      glMatrixMode(GL_PROJECTION), glPopMatrix();
      glMatrixMode(GL_MODELVIEW), glPopMatrix();
      glPopAttrib();
    });
  }
  // Level l's storage as GL holds it (glGetTexImage), row 0 = storage row 0 (t = 0).
  Image storage(int l) {
    Image img(kClip, kClip);
    glBindTexture(GL_TEXTURE_2D, tex_[size_t(l)]);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
    return img;
  }

 private:
  std::array<GLuint, kClipLevels> tex_{};
};

// The texels each glTexSubImage2D of `calls` sent (its width x height), in order.
inline std::vector<long long> uploadedTexels(const std::vector<gl::Call>& calls) {
  std::vector<long long> out;
  for (const gl::Call& c : calls)
    if (std::string(c.name) == "glTexSubImage2D" && c.args.size() > 5) out.push_back(c.args[4].i * c.args[5].i);
  return out;
}
}  // namespace ts::residency
