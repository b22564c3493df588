// demos/texture_animation/texture_animation_gl.hpp — the GL passes behind the flipbook, the torch and the moving
// light, in fixed-function GL as seed 001 teaches them: one texture made once (glTexImage2D with no data) and
// refilled each frame by glTexSubImage2D, whole or only the rectangle that changed; blending with the depth
// writes off (glDepthMask) for the transparent flames; a light map re-uploaded and modulating the base on unit 1.
// Each pass draws into a private target (Renderer::offscreen) in pixel coordinates and is read back (row 0 the
// top); every pass restores the state it changes (glPushAttrib) and deletes its textures.  The calls are recorded
// (gl::Recording) so that the uploads are counted from the calls made, and the figure's listing shows them.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "common/gl/gl.hpp"
#include "common/gl/gl_record.hpp"
#include "common/gl/pixel_pass.hpp"
#include "common/gl/render.hpp"
#include "texture_animation_math.hpp"

namespace ts::texanim {
// A pass in window pixels (common/gl/pixel_pass.hpp), read back opaque: the flames' clear texels leave alpha 0
// where GL_REPLACE wrote them, and the colour is what counts.
inline Image opaquePass(Renderer& r, int w, int h, const char* what, const std::function<void()>& draw) {
  Image img = pixelPass(r, w, h, what, draw);
  for (size_t k = 3; k < img.pixels.size(); k += 4) img.pixels[k] = 255;
  return img;
}
// Refills the rectangle `rect` of the bound texture from the same rectangle of `frame` (packed first: with
// GL_UNPACK_ALIGNMENT 1 the rows follow each other).
inline void upload(const Image& frame, const TexRect& rect) {
  const Image part = subImage(frame, rect);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, rect.x, rect.y, rect.w, rect.h, GL_RGBA, GL_UNSIGNED_BYTE, part.pixels.data());
}
// A rectangle of pixels at depth z, its texture coordinates 0..1 over it (unit 1's too when `unit1`).
inline void quad(const PixRect& p, float z, bool unit1 = false) {
  glBegin(GL_QUADS);
  for (int c = 0; c < 4; ++c) {
    const float s = float(c == 1 || c == 2), t = float(c >= 2);
    glTexCoord2f(s, t);
    if (unit1) glMultiTexCoord2f(GL_TEXTURE1, s, t);
    glVertex3f(float(p.x) + s * float(p.w), float(p.y) + t * float(p.h), z);
  }
  glEnd();
}
// The bytes each glTexSubImage2D of `calls` sent, in order.
inline std::vector<double> uploadedBytes(const std::vector<gl::Call>& calls) {
  std::vector<double> out;
  for (const gl::Call& c : calls)
    if (std::string(c.name) == "glTexSubImage2D")
      out.push_back(c.args.size() > 8 && c.args[8].bytes ? double(c.args[8].bytes->size()) : 0.0);
  return out;
}

// ---- the flipbook ---------------------------------------------------------------------------------------------
// The loop played once and back to its first frame (kFlipFrames + 1 uploads): the first upload whole, each
// other one whole, or (partial) only the rectangle where the frame differs from the one before.
struct FlipbookRun {
  std::vector<Image> shown;     // each upload's picture, read back
  std::vector<int> frameShown;  // the frame each shows
  std::vector<double> bytes;    // each step's glTexSubImage2D bytes, from the recorded calls (0: nothing changed)
  std::vector<TexRect> rects;   // what each uploaded
  gl::CallList calls;
};
inline FlipbookRun flipbookPass(Renderer& r, const std::vector<Image>& frames, bool partial) {
  FlipbookRun run;
  const int n = int(frames.size()), w = kFlipTexels * kFlipZoom;
  r.release();  // the record shows every object made
  gl::Recording rec;
  // Colour only: the flipbook shows the frames' colours (the torch's flames keep their alpha).
  const GLuint tex = texture2D(kFlipTexels, kFlipTexels, nullptr, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_RGB8);
  for (int step = 0; step <= n; ++step) {
    const int k = step % n;
    const TexRect whole{0, 0, kFlipTexels, kFlipTexels};
    const TexRect rect = step == 0 || !partial ? whole : changedRect(frames[size_t((step - 1) % n)], frames[size_t(k)]);
    const size_t before = rec.calls().size();
    run.shown.push_back(opaquePass(r, w, w, "the flipbook", [&] {
      glEnable(GL_TEXTURE_2D), glBindTexture(GL_TEXTURE_2D, tex);
      if (rect.texels() > 0) upload(frames[size_t(k)], rect);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
      quad({0, 0, w, w}, 0);
    }));
    run.frameShown.push_back(k), run.rects.push_back(rect);
    // This step's uploads, from the calls it made.
    double bytes = 0;
    for (double b : uploadedBytes({rec.calls().begin() + long(before), rec.calls().end()})) bytes += b;
    run.bytes.push_back(bytes);
  }
  glDeleteTextures(1, &tex);
  run.calls = std::make_shared<const std::vector<gl::Call>>(rec.take());
  return run;
}

// ---- the torch ------------------------------------------------------------------------------------------------
// kRightOrder: the opaque wall and handle first (depth writes on), then the flames back to front with blending and
// the depth writes off.  kSceneOrder: every layer in the order a scene lists it (front flame, back flame, handle,
// wall), blending on and depth writes on throughout.  kFrontToBack: opaque first and depth writes off as in the
// right order, but the flames front to back: the back flame is blended over the front one.
enum TorchOrder { kRightOrder, kSceneOrder, kFrontToBack };
inline Image torchPass(Renderer& r, const Image& wall, const Image& back, const Image& front, TorchOrder order,
                       gl::CallList* calls) {
  r.release();
  gl::Recording rec;
  const Image img = opaquePass(r, kTorchPixels, kTorchPixels, "the torch", [&] {
    const GLuint tw = texture2D(wall.width, wall.height, &wall, GL_NEAREST, GL_REPEAT);
    const GLuint tb = texture2D(kFlipTexels, kFlipTexels, &back, GL_NEAREST, GL_CLAMP_TO_EDGE);
    const GLuint tf = texture2D(kFlipTexels, kFlipTexels, &front, GL_NEAREST, GL_CLAMP_TO_EDGE);
    glEnable(GL_DEPTH_TEST), glDepthFunc(GL_LESS);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    auto wallQuad = [&] {
      glEnable(GL_TEXTURE_2D), glBindTexture(GL_TEXTURE_2D, tw);
      quad({0, 0, kTorchPixels, kTorchPixels}, kWallZ);
    };
    auto handle = [&] {
      glDisable(GL_TEXTURE_2D);
      glColor4f(kHandleColour.r / 255.0f, kHandleColour.g / 255.0f, kHandleColour.b / 255.0f, 1.0f);
      quad(kHandle, kHandleZ);
      glColor4f(1, 1, 1, 1);
    };
    auto flame = [&](GLuint t, const PixRect& p, float z) {
      glEnable(GL_TEXTURE_2D), glBindTexture(GL_TEXTURE_2D, t);
      quad(p, z);
    };
    if (order != kSceneOrder) {
      glDisable(GL_BLEND), glDepthMask(GL_TRUE);
      wallQuad(), handle();
      glEnable(GL_BLEND), glDepthMask(GL_FALSE);  // transparent: tested against the opaque depth, never written
      if (order == kRightOrder) flame(tb, kBackFlame, kBackZ), flame(tf, kFrontFlame, kFrontZ);
      else flame(tf, kFrontFlame, kFrontZ), flame(tb, kBackFlame, kBackZ);
      glDepthMask(GL_TRUE);
    } else {
      glEnable(GL_BLEND), glDepthMask(GL_TRUE);
      flame(tf, kFrontFlame, kFrontZ), flame(tb, kBackFlame, kBackZ);
      handle(), wallQuad();
    }
    const GLuint all[3] = {tw, tb, tf};
    glDeleteTextures(3, all);
  });
  if (calls) *calls = std::make_shared<const std::vector<gl::Call>>(rec.take());
  return img;
}

// ---- the moving light -----------------------------------------------------------------------------------------
// The base (unit 0, GL_REPLACE, GL_NEAREST) times the light map (unit 1, GL_MODULATE, GL_LINEAR), the map made once
// with no data and refilled by glTexSubImage2D for each map in `maps` (a frame each); the last frame read back.
struct LightRun {
  Image shown;
  std::vector<double> bytes;
  gl::CallList calls;
};
inline LightRun lightMapPass(Renderer& r, const Image& base, const std::vector<Image>& maps) {
  LightRun run;
  r.release();
  gl::Recording rec;
  const GLuint tb = texture2D(base.width, base.height, &base, GL_NEAREST, GL_REPEAT);
  const GLuint tl = texture2D(kLightTexels, kLightTexels, nullptr, GL_LINEAR, GL_CLAMP_TO_EDGE);
  for (const Image& map : maps)
    run.shown = opaquePass(r, kLitPixels, kLitPixels, "the light-mapped wall", [&] {
      glActiveTexture(GL_TEXTURE1);
      glEnable(GL_TEXTURE_2D), glBindTexture(GL_TEXTURE_2D, tl);
      upload(map, {0, 0, kLightTexels, kLightTexels});  // the map recomputed for this frame's light
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
      glActiveTexture(GL_TEXTURE0);
      glEnable(GL_TEXTURE_2D), glBindTexture(GL_TEXTURE_2D, tb);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
      quad({0, 0, kLitPixels, kLitPixels}, 0, true);
      glActiveTexture(GL_TEXTURE1), glDisable(GL_TEXTURE_2D), glActiveTexture(GL_TEXTURE0);
    });
  const GLuint all[2] = {tb, tl};
  glDeleteTextures(2, all);
  run.calls = std::make_shared<const std::vector<gl::Call>>(rec.take());
  run.bytes = uploadedBytes(*run.calls);
  return run;
}
}  // namespace ts::texanim
