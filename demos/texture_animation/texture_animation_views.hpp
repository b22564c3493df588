// demos/texture_animation/texture_animation_views.hpp — the flipbook's, the torch's and the moving light's
// pictures and their measurement (texture_animation_gl.hpp's passes against texture_animation_math.hpp's CPU
// answers), and the row of pictures the figures show them in.
#pragma once
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
// The pictures measure() made, for build(): GL's readbacks (row 0 the top) with the calls that drew them.
struct Pictures {
  Image flipWhole, flipPartial, flipChanges;  // frame k (whole), frame k + 1 (partial), what changed k -> k+1
  gl::CallList flipWholeCalls, flipPartialCalls;
  Image torchRight, torchWrong, torchCpu, torchWrongMask;
  gl::CallList torchRightCalls, torchWrongCalls;
  Image litCpu, litDynamic, litStale, lightMap;
  gl::CallList litDynamicCalls, litStaleCalls;
};

inline const glm::vec4 kChanged{1.0f, 0.0f, 1.0f, 1.0f};    // magenta: a texel that changed
inline const glm::vec4 kUploaded{1.0f, 0.9f, 0.0f, 1.0f};   // yellow: the rectangle a partial upload sends
inline const glm::vec4 kWrong{1.0f, 0.15f, 0.1f, 1.0f};     // red: a pixel off the CPU's composite
inline const glm::vec4 kLightNow{1.0f, 0.9f, 0.0f, 1.0f};   // yellow: the light at --time
inline const glm::vec4 kLightThen{0.0f, 0.9f, 1.0f, 1.0f};  // cyan: the light at time 0 (the stale map's)
inline Rgba rgba(const glm::vec4& c) { return {uint8_t(c.r * 255), uint8_t(c.g * 255), uint8_t(c.b * 255), 255}; }

// An image made `zoom` times larger, texel for texel (row order kept).
inline Image magnified(const Image& img, int zoom) {
  Image out(img.width * zoom, img.height * zoom);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) out.set(x, y, img.at(x / zoom, y / zoom));
  return out;
}
inline Rgba dimmed(Rgba c) { return {uint8_t(c.r / 3), uint8_t(c.g / 3), uint8_t(c.b / 3), 255}; }

// What changed from frame a to frame b: b's texels dimmed, the changed ones magenta, the rectangle's border yellow;
// row 0 the top, kFlipZoom pixels a texel (as the readbacks beside it).
inline Image changesPicture(const Image& a, const Image& b, const TexRect& r) {
  Image out(a.width, a.height);
  for (int j = 0; j < a.height; ++j)
    for (int i = 0; i < a.width; ++i) {
      const bool border = r.contains(i, j) && (i == r.x || i == r.x + r.w - 1 || j == r.y || j == r.y + r.h - 1);
      const Rgba c = border ? rgba(kUploaded) : a.at(i, j) != b.at(i, j) ? rgba(kChanged) : dimmed(b.at(i, j));
      out.set(i, a.height - 1 - j, c);
    }
  return magnified(out, kFlipZoom);
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
// The light map (row 0 the bottom) magnified to w x w, row 0 the top, with the light's place over the wall now
// (yellow) and at time 0 (cyan) marked by a cross.
inline Image lightMapPicture(const Image& map, int w, const glm::dvec3& now, const glm::dvec3& then) {
  Image out(w, w);
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) out.set(x, y, map.at(x * map.width / w, (w - 1 - y) * map.height / w));
  for (const auto& [p, c] : {std::pair{then, kLightThen}, std::pair{now, kLightNow}}) {
    const int cx = int(p.x * w), cy = w - 1 - int(p.y * w);
    for (int d = -6; d <= 6; ++d)
      for (int t = -1; t <= 1; ++t) {
        if (cx + d >= 0 && cx + d < w && cy + t >= 0 && cy + t < w) out.set(cx + d, cy + t, rgba(c));
        if (cx + t >= 0 && cx + t < w && cy + d >= 0 && cy + d < w) out.set(cx + t, cy + d, rgba(c));
      }
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
  pic.flipWhole = whole.shown[size_t(shown)], pic.flipWholeCalls = whole.calls;
  pic.flipPartial = partial.shown[size_t(shown + 1)], pic.flipPartialCalls = partial.calls;
  pic.flipChanges = changesPicture(frames[size_t(shown)], frames[size_t(next)], partial.rects[size_t(shown + 1)]);

  // The torch at frame k.
  const Image wall = *waterTexture(kFlipTexels).image;
  const Image& back = frames[size_t(backFlameFrame(k))];
  const Image& front = frames[size_t(frontFlameFrame(k))];
  pic.torchCpu = torchComposite(wall, back, front);
  pic.torchRight = torchPass(r, wall, back, front, kRightOrder, &pic.torchRightCalls);
  pic.torchWrong = torchPass(r, wall, back, front, kSceneOrder, &pic.torchWrongCalls);
  const Image frontToBack = torchPass(r, wall, back, front, kFrontToBack, nullptr);
  const int levels = 2 * kTorchLevelsPerLayer;  // two flames blended over the opaque layers
  pic.torchWrongMask = wrongMask(pic.torchWrong, pic.torchCpu, levels);
  put("torch_order_error_px[right]", wrongPixels(pic.torchRight, pic.torchCpu, levels),
      "pixels more than 2 levels off the CPU's composite: opaque first, flames back to front, depth writes off");
  put("torch_order_error_px[wrong]", wrongPixels(pic.torchWrong, pic.torchCpu, levels),
      "the same, every layer in the scene's order (front flame first) with depth writes on");
  put("torch_order_error_px[front_to_back]", wrongPixels(frontToBack, pic.torchCpu, levels),
      "the same, opaque first and depth writes off but the flames front to back (the back one blended last)");
  put("torch_tolerance_levels", levels, "levels a pixel may differ: one rounding a blended layer");
  measureProgress(0.6);

  // The moving light: the map recomputed for this frame's light, and one left as it was at time 0.
  const glm::dvec3 now = lightPosition(seconds), then = lightPosition(0);
  const Image base = wall;
  const Image mapNow = lightMapImage(kLightTexels, now), mapThen = lightMapImage(kLightTexels, then);
  pic.litCpu = perPixelLit(base, kLitPixels, now);
  const Image mapBefore = lightMapImage(kLightTexels, lightPosition(seconds - frameSeconds));
  const LightRun dynamic = lightMapPass(r, base, {mapBefore, mapNow}), stale = lightMapPass(r, base, {mapThen});
  pic.litDynamic = dynamic.shown, pic.litDynamicCalls = dynamic.calls;
  pic.litStale = stale.shown, pic.litStaleCalls = stale.calls;
  pic.lightMap = lightMapPicture(mapNow, kLitPixels, now, then);
  put("dynamic_lightmap_rms_levels", rmsRgb(pic.litDynamic, pic.litCpu),
      "8-bit levels RMS: base x the light map recomputed for this frame's light (GL) against per-pixel lighting");
  put("dynamic_lightmap_rms_levels[stale]", rmsRgb(pic.litStale, pic.litCpu),
      "the same with the light map computed for time 0 and never re-uploaded");
  put("dynamic_lightmap_rms_levels[predicted]", rmsRgb(lightMapped(base, kLitPixels, mapNow), pic.litCpu),
      "the same computed on the CPU: the map's bilinear interpolation against per-pixel lighting");
  put("dynamic_lightmap_gl_vs_cpu_rms", rmsRgb(pic.litDynamic, lightMapped(base, kLitPixels, mapNow)),
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
  const Image* image;
  L::Text title, note;
  gl::CallList calls;
};
// The pictures side by side (or in a grid) above a legend and a band for the numbers, as many lines as they take
// at the frame's width (a small window wraps them rather than cutting them).
inline void pictureRow(Frame& f, const std::vector<Picture>& ps, const std::vector<LegendEntry>& legend,
                       const L::Text& numbers) {
  const int lines = std::max(2, L::captionLines(numbers.text, 1, float(f.width - 16)));
  // The key on one line when its entries fit the width, else a line an entry (L::legend wraps them).
  float keyWidth = 0;
  for (const LegendEntry& e : legend) keyWidth += text::width(e.meaning, 1) + L::lineHeight(1) + 16;
  const int keyLines = keyWidth <= float(f.width - 16) ? 1 : int(legend.size());
  const float band = L::lineHeight(1) * float(lines) + 8;
  const float key = legend.empty() ? 0 : L::lineHeight(1) * float(keyLines) + 4;
  const L::Box area{8, 8, float(f.width - 8), float(f.height) - 8 - band - key};
  const std::vector<L::Cell> cells = L::flow(area, {int(ps.size()), 1.0f, 1, 1, 10, 2, 150});
  for (size_t k = 0; k < ps.size() && k < cells.size(); ++k) {
    TextureDesc t = renderedImageTexture(*ps[k].image, "texture_animation", ps[k].title.text, "texture_animation");
    // A panel's pixel centre may fall on a texel edge, where GL_NEAREST's tie goes either way.
    t.minFilter = t.magFilter = GL_LINEAR;
    t.renderedBy = ps[k].calls;
    f.panels.push_back(L::picturePanel(f, "picture_" + std::to_string(k), cells[k].picture, t));
    L::caption(f, cells[k].above, ps[k].title, L::kWhite, cells[k].scale);
    L::caption(f, cells[k].below, ps[k].note, L::kAmber, cells[k].scale);
  }
  if (!legend.empty())
    L::legend(f, {8, float(f.height) - band - key, float(f.width - 8), float(f.height) - band}, legend, 1);
  L::caption(f, {8, float(f.height) - band, float(f.width - 8), float(f.height - 4)}, numbers, L::kAmber, 1);
}
}  // namespace ts::texanim
