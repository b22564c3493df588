// demos/texture_animation/texture_animation_views.hpp — the flipbook's, the torch's and the moving light's
// pictures and their measurement (texture_animation_gl.hpp's passes against texture_animation_math.hpp's CPU
// answers), and the row of pictures the figures show them in.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "texture_animation_gl.hpp"

namespace ts::texanim {
// The pictures measure() made, for build(), as the figures' textures: GL's readbacks with the calls that drew
// them and, where a Frame describes the pass, that Frame (a nested frame the CPU reference recomputes); the CPU's
// pictures as generator textures (texture_animation_textures.hpp).
struct Pictures {
  TextureDesc flipWhole, flipPartial, flipChanges;  // frame k (whole), frame k + 1 (partial), what changed k -> k+1
  TextureDesc torchRight, torchWrong, torchCpu, torchWrongMask;
  TextureDesc litCpu, litDynamic, litStale, lightMap;
};

// ---- the passes as Frames -------------------------------------------------------------------------------------
// What a pass of texture_animation_gl.hpp drew, as plain data: a w x w frame of one panel showing the unit square,
// texture coordinates (0, 0) to (1, 1) as the pass's quad, unit 0 `tex` (GL_REPLACE) and, when given, `light` on
// unit 1 (GL_MODULATE, reading unit 0's coordinates as the pass's glMultiTexCoord2f does).  The figure holds GL's
// readback of the pass to it, and measure() checks that it draws the same picture (pass_frame_mismatch_px).
inline Frame quadFrame(int w, const TextureDesc& tex, const TextureDesc* light = nullptr) {
  Frame f;
  f.width = f.height = w;
  f.clearColor = {0, 0, 0, 1};
  Panel p = layout::unitPanel("pass", {0, 0, w, w});
  Batch b;
  b.role = "quad";
  b.texture = f.addTexture(tex);
  b.texEnv = GL_REPLACE;
  if (light) b.texture1 = f.addTexture(*light), b.texEnv1 = GL_MODULATE;
  for (int c : {0, 1, 2, 0, 2, 3}) {
    const glm::vec2 q(c == 1 || c == 2, c >= 2);
    b.vertices.push_back({{q, 0.0f}, {q, 0.0f, 1.0f}, {1, 1, 1, 1}});
  }
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}
// The flipbook's picture of frame k: its texels, colour only (the flipbook's texture is GL_RGB8), kFlipZoom pixels
// a texel.  The wall lit through the light map computed for the light at `mapSeconds`.
inline Frame flipFrame(int k) {
  return quadFrame(kFlipTexels * kFlipZoom, flameTexture(kFlipTexels, k, kFlipFrames, true));
}
inline Frame litFrame(double mapSeconds) {
  const TextureDesc map = lightMapTexture(kLightTexels, mapSeconds);
  return quadFrame(kLitPixels, waterTexture(kFlipTexels), &map);
}
// The torch at flipbook frame k as a Frame, in window pixels as its pass (glOrtho(0, w, 0, h, -1, 1), larger z
// nearer), depth tested: the wall (the water, kWallZoom pixels a texel), the handle, the two flames (their frames'
// texels with alpha, kFlipZoom pixels a texel) blended (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA).  The right order
// draws the wall and handle opaque, then the flames back to front with the depth writes off (Batch::depthWrite);
// the scene's order draws front flame, back flame, handle, wall, every layer blended with depth writes on.
inline Frame torchFrame(int k, TorchOrder order) {
  Frame f;
  f.width = f.height = kTorchPixels;
  f.clearColor = {0, 0, 0, 1};
  Panel p;
  p.id = "torch";
  p.viewport = {0, 0, kTorchPixels, kTorchPixels};
  p.projection = glm::ortho(0.0f, float(kTorchPixels), 0.0f, float(kTorchPixels), -1.0f, 1.0f);
  p.depthTest = true;
  const bool scene = order == kSceneOrder;
  auto quad = [&](const std::string& role, int texture, const PixRect& r, float z, glm::vec4 colour, bool flame) {
    Batch b;
    b.role = role;
    b.texture = texture;
    b.texEnv = GL_REPLACE;
    b.blend = scene || flame;
    if (b.blend) b.blendSrc = GL_SRC_ALPHA, b.blendDst = GL_ONE_MINUS_SRC_ALPHA;
    b.depthWrite = scene || !flame;
    for (int c : {0, 1, 2, 0, 2, 3}) {
      const float s = float(c == 1 || c == 2), t = float(c >= 2);
      b.vertices.push_back({{float(r.x) + s * float(r.w), float(r.y) + t * float(r.h), z}, {s, t, 0.0f, 1.0f}, colour});
    }
    p.batches.push_back(b);
  };
  const int wall = f.addTexture(waterTexture(kFlipTexels));
  const int back = f.addTexture(flameTexture(kFlipTexels, backFlameFrame(k), kFlipFrames, false));
  const int front = f.addTexture(flameTexture(kFlipTexels, frontFlameFrame(k), kFlipFrames, false));
  const glm::vec4 white(1.0f), handle(kHandleColour.r / 255.0f, kHandleColour.g / 255.0f, kHandleColour.b / 255.0f, 1);
  auto wallQuad = [&] { quad("wall", wall, {0, 0, kTorchPixels, kTorchPixels}, kWallZ, white, false); };
  auto handleQuad = [&] { quad("handle", -1, kHandle, kHandleZ, handle, false); };
  if (order == kRightOrder) {
    wallQuad(), handleQuad();
    quad("back flame", back, kBackFlame, kBackZ, white, true),
        quad("front flame", front, kFrontFlame, kFrontZ, white, true);
  } else {
    quad("front flame", front, kFrontFlame, kFrontZ, white, true),
        quad("back flame", back, kBackFlame, kBackZ, white, true);
    handleQuad(), wallQuad();
  }
  f.panels.push_back(p);
  return f;
}

// GL's readback of a pass as a figure's texture, with the Frame that describes it and the calls that drew it.
inline TextureDesc passTexture(Renderer& r, const Image& shown, const Frame& described, const std::string& what,
                               const gl::CallList& calls, Measurements& ms) {
  // The description is checked here: its own render against the pass's picture, pixel for pixel.
  const Image own = r.renderOffscreen(described);
  ms.push_back({"pass_frame_mismatch_px[" + what + "]", double(wrongPixels(own, shown, 1)),
                "pixels where the Frame describing the " + what +
                    " pass (the sidecar's nested frame) renders more "
                    "than a level off the pass's own picture"});
  TextureDesc t = nestedPictureTexture(shown, described, "texture_animation_pass", what);
  t.renderedBy = calls;
  return t;
}
// A picture computed from GL's (the torch's mask of wrong pixels), shown as it was made: no generator remakes it.
inline TextureDesc glPicture(const Image& img, const std::string& what, const gl::CallList& calls) {
  TextureDesc t = renderedImageTexture(img, "texture_animation", what, "texture_animation");
  // A panel's pixel centre may fall on a texel edge, where GL_NEAREST's tie goes either way.
  t.minFilter = t.magFilter = GL_LINEAR;
  t.renderedBy = calls;
  return t;
}

// The reference dimmed, the pixels `wrongPixels` counts red.
inline Image wrongMask(const Image& got, const Image& want, int levels) {
  Image out = want;
  for (int y = 0; y < got.height; ++y)
    for (int x = 0; x < got.width; ++x) {
      const Rgba a = got.at(x, y), b = want.at(x, y);
      const bool off = std::abs(a.r - b.r) > levels || std::abs(a.g - b.g) > levels || std::abs(a.b - b.b) > levels;
      out.set(x, y, off ? rgba(kWrong) : dimmed(b));
    }
  return out;
}
// ---- measuring --------------------------------------------------------------------------------------------------
// Frame k of the flipbook (k = the whole frames in --time), the torch at frame k, the light at `seconds`.
inline Pictures measureAnimations(Renderer& r, int k, double seconds, double frameSeconds, Measurements& ms) {
  Pictures pic;
  auto put = [&](const std::string& n, double v, const std::string& meaning) { ms.push_back({n, v, meaning}); };
  std::vector<Image> frames;
  for (int i = 0; i < kFlipFrames; ++i) frames.push_back(flameFrame(kFlipTexels, i, kFlipFrames));
  const int shown = k % kFlipFrames, next = (shown + 1) % kFlipFrames;
  // The flipbook: the loop played through whole uploads and through partial ones.
  const FlipbookRun whole = flipbookPass(r, frames, false), partial = flipbookPass(r, frames, true);
  measureProgress(0.3);
  auto mean = [](const std::vector<double>& v, size_t from) {
    double s = 0;
    for (size_t i = from; i < v.size(); ++i) s += v[i];
    return v.size() > from ? s / double(v.size() - from) : 0.0;
  };
  int wrongWhole = 0, wrongPartial = 0, control = 0;
  for (size_t s = 0; s < whole.shown.size(); ++s) {
    const int f = whole.frameShown[s];
    wrongWhole += zoomMismatches(whole.shown[s], frames[size_t(f)], kFlipZoom);
    wrongPartial += zoomMismatches(partial.shown[s], frames[size_t(f)], kFlipZoom);
    control += zoomMismatches(partial.shown[s], frames[size_t((f + 1) % kFlipFrames)], kFlipZoom);
  }
  put("flipbook_bytes_per_frame[whole]", mean(whole.bytes, 1),
      "bytes glTexSubImage2D sent a frame after the first, the whole frame each time (counted from the calls)");
  put("flipbook_bytes_per_frame[partial]", mean(partial.bytes, 1),
      "bytes glTexSubImage2D sent a frame after the first, only the rectangle that changed (counted from the calls)");
  put("flipbook_bytes_first_frame", partial.bytes.empty() ? 0.0 : partial.bytes[0],
      "bytes of the first upload, whole in both ways");
  put("flipbook_uploads", double(uploadedBytes(*partial.calls).size()),
      "glTexSubImage2D calls the partial playing of the loop made (and back to its first frame)");
  put("flipbook_bytes_shown[partial]", partial.bytes[size_t(shown + 1)],
      "bytes the partial upload of frame k + 1 (the figure's) sent");
  put("flipbook_rect_w", partial.rects[size_t(shown + 1)].w, "texels: the width of frame k + 1's upload");
  put("flipbook_rect_h", partial.rects[size_t(shown + 1)].h, "texels: its height");
  int changed = 0;
  for (int j = 0; j < kFlipTexels; ++j)
    for (int i = 0; i < kFlipTexels; ++i) changed += frames[size_t(shown)].at(i, j) != frames[size_t(next)].at(i, j);
  put("flipbook_changed_texels", changed, "texels where frame k + 1 differs from frame k");
  put("flipbook_mismatches", wrongWhole + wrongPartial,
      "pixels of every frame shown (whole and partial uploads) that are not that frame's texel (GL_NEAREST, x2)");
  put("flipbook_mismatches[whole]", wrongWhole, "the same, whole uploads only");
  put("flipbook_mismatches[partial]", wrongPartial, "the same, partial uploads only");
  put("flipbook_mismatches[next_frame]", control,
      "the partial uploads' pictures against the next frame's texels instead (a control that must find some)");
  pic.flipWhole = passTexture(r, whole.shown[size_t(shown)], flipFrame(shown), "flipbook_whole", whole.calls, ms);
  pic.flipPartial = passTexture(r, partial.shown[size_t(shown + 1)], flipFrame(next), "flipbook_partial", partial.calls,
                                ms);
  pic.flipChanges = changesTexture(shown);
  put("pass_frame_control_px[next_frame]",
      wrongPixels(r.renderOffscreen(flipFrame(next)), whole.shown[size_t(shown)], 1),
      "pixels where the Frame of the next flipbook frame renders more than a level off frame k's pass (a control "
      "that must find some)");

  // The torch at frame k.
  const Image wall = *waterTexture(kFlipTexels).image;
  const Image& back = frames[size_t(backFlameFrame(k))];
  const Image& front = frames[size_t(frontFlameFrame(k))];
  const Image torchCpu = torchComposite(wall, back, front);
  gl::CallList rightCalls, wrongCalls;
  const Image torchRight = torchPass(r, wall, back, front, kRightOrder, &rightCalls);
  const Image torchWrong = torchPass(r, wall, back, front, kSceneOrder, &wrongCalls);
  const Image frontToBack = torchPass(r, wall, back, front, kFrontToBack, nullptr);
  const int levels = 2 * kTorchLevelsPerLayer;  // two flames blended over the opaque layers
  pic.torchCpu = torchTexture(k);
  pic.torchRight = passTexture(r, torchRight, torchFrame(k, kRightOrder), "torch_right", rightCalls, ms);
  pic.torchWrong = passTexture(r, torchWrong, torchFrame(k, kSceneOrder), "torch_scene_order", wrongCalls, ms);
  pic.torchWrongMask = glPicture(wrongMask(torchWrong, torchCpu, levels), "the scene's order: pixels off", nullptr);
  put("torch_order_error_px[right]", wrongPixels(torchRight, torchCpu, levels),
      "pixels more than 2 levels off the CPU's composite: opaque first, flames back to front, depth writes off");
  put("torch_order_error_px[wrong]", wrongPixels(torchWrong, torchCpu, levels),
      "the same, every layer in the scene's order (front flame first) with depth writes on");
  put("torch_order_error_px[front_to_back]", wrongPixels(frontToBack, torchCpu, levels),
      "the same, opaque first and depth writes off but the flames front to back (the back one blended last)");
  put("torch_tolerance_levels", levels, "levels a pixel may differ: one rounding a blended layer");
  measureProgress(0.6);

  // The moving light: the map recomputed for this frame's light, and one left as it was at time 0.
  const glm::dvec3 now = lightPosition(seconds), then = lightPosition(0);
  const Image base = wall;
  const Image mapNow = lightMapImage(kLightTexels, now), mapThen = lightMapImage(kLightTexels, then);
  const Image litCpu = perPixelLit(base, kLitPixels, now);
  const Image mapBefore = lightMapImage(kLightTexels, lightPosition(seconds - frameSeconds));
  const LightRun dynamic = lightMapPass(r, base, {mapBefore, mapNow}), stale = lightMapPass(r, base, {mapThen});
  pic.litCpu = litTexture(seconds);
  pic.litDynamic = passTexture(r, dynamic.shown, litFrame(seconds), "light_map_now", dynamic.calls, ms);
  pic.litStale = passTexture(r, stale.shown, litFrame(0), "light_map_stale", stale.calls, ms);
  pic.lightMap = lightMapPictureTexture(seconds);
  put("dynamic_lightmap_rms_levels", rmsRgb(dynamic.shown, litCpu),
      "8-bit levels RMS: base x the light map recomputed for this frame's light (GL) against per-pixel lighting");
  put("dynamic_lightmap_rms_levels[stale]", rmsRgb(stale.shown, litCpu),
      "the same with the light map computed for time 0 and never re-uploaded");
  put("dynamic_lightmap_rms_levels[predicted]", rmsRgb(lightMapped(base, kLitPixels, mapNow), litCpu),
      "the same computed on the CPU: the map's bilinear interpolation against per-pixel lighting");
  put("dynamic_lightmap_gl_vs_cpu_rms", rmsRgb(dynamic.shown, lightMapped(base, kLitPixels, mapNow)),
      "GL's light-mapped picture against the CPU's bilinear prediction of it (rounding only)");
  put("lightmap_bytes_per_frame", dynamic.bytes.empty() ? 0.0 : dynamic.bytes.back(),
      "bytes glTexSubImage2D sent a frame: the whole light map (counted from the calls)");
  put("light_moved", glm::length(glm::dvec2(now - then)), "the light's distance from its time-0 place, wall widths");
  put("light_x", now.x, "the light's x over the wall at --time (wall widths)");
  put("light_y", now.y, "the light's y over the wall at --time (wall widths)");
  return pic;
}

// ---- the figures' row of pictures -----------------------------------------------------------------------------
namespace L = ts::layout;
struct Picture {
  const TextureDesc* texture;
  L::Text title, note;
};
// The pictures side by side (or in a grid) above a legend and the numbers (layout::pictureFigure).
inline void pictureRow(Frame& f, const std::vector<Picture>& ps, const std::vector<LegendEntry>& legend,
                       const L::Text& numbers) {
  std::vector<L::Captioned> captions;
  for (const Picture& p : ps) captions.push_back({p.title, p.note});
  L::pictureFigure(
      f, captions,
      [&](size_t k, const Rect& r) {
        f.panels.push_back(L::picturePanel(f, "picture_" + std::to_string(k), r, *ps[k].texture));
      },
      legend, {numbers}, {0, 1.0f, 1, 1, 10, 2, 150}, 2);
}
}  // namespace ts::texanim
