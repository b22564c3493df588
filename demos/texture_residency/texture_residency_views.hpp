// demos/texture_residency/texture_residency_views.hpp — the three views' measurements (the GL passes of
// texture_residency_gl.hpp and Frames rendered offscreen, against texture_residency_math.hpp's equations) and
// their figures' layouts.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/mip_lod.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "demos/texture_residency/texture_residency_textures.hpp"
#include "texture_residency_gl.hpp"

namespace ts::residency {
namespace L = ts::layout;

// What measure() leaves for build() beyond the numbers: the size queries' calls (the listing shows them), and
// the clipmap's pictures (GL readbacks, row 0 the top) with the calls that made them.
struct Detail {
  gl::CallList sizeCalls;
  Image clipView, clipLevels[kClipLevels];      // the figure's: windows outlined, the last move's strips whitened
  Image clipViewRaw, clipStorage[kClipLevels];  // as GL drew and holds them (the tests probe these)
  Image flight, flightRaw;  // the same stack in perspective (row 0 the top): outlined for the figure, and as GL drew it
  gl::CallList clipCalls;
};

// Names a distance in a measurement: "1.5", "3".
inline std::string distanceKey(double d) { return L::fmt(d == std::floor(d) ? "%.0f" : "%.1f", d); }

// ---- the size rules -----------------------------------------------------------------------------------------------
// A panel `id` showing the marker texture of `size` on the unit square, s and t from 0 to 1 whatever the size.
inline Panel sizePanel(Frame& f, const std::string& id, const Rect& viewport, int size) {
  Panel p = L::unitPanel(id, viewport);
  p.batches.push_back(L::unitSquare(f.addTexture(markerTexture(size)), "surface"));
  return p;
}
// The marker's pixels in a render of one size panel (row 0 the top): their centroid, x right and y up from the
// panel's bottom-left, in pixels.
struct Centroid {
  double x = 0, y = 0;
  long n = 0;
};
inline Centroid markerCentroid(const Image& img, const Rect& panel) {
  Centroid c;
  for (int y = panel.y; y < panel.y + panel.h; ++y)
    for (int x = panel.x; x < panel.x + panel.w; ++x)
      if (img.at(x, y) == kMarkerColour) c.x += x - panel.x + 0.5, c.y += panel.y + panel.h - y - 0.5, ++c.n;
  if (c.n) c.x /= double(c.n), c.y /= double(c.n);
  return c;
}
inline void measureSizes(Renderer& r, Measurements& ms, Detail& d) {
  auto put = [&](const std::string& n, double v, const std::string& meaning) { ms.push_back({n, v, meaning}); };
  const SizeRules q = querySizes();
  d.sizeCalls = q.calls;
  put("max_texture_size", q.maxSize, "GL_MAX_TEXTURE_SIZE: this backend's own (never printed on the figure)");
  put("proxy_width[1024]", q.fitsWidth, "GL_TEXTURE_WIDTH of a 1024^2 GL_RGBA8 proxy: it fits");
  put("proxy_width[2max]", q.tooBigWidth,
      "GL_TEXTURE_WIDTH of a proxy twice GL_MAX_TEXTURE_SIZE a side: 0, it does not fit");
  put("proxy_halvings", q.halvings, "times the program halved that size until the proxy gave a width");
  put("proxy_settled_size", q.settled,
      "the size the halving settled on: the backend's own (never printed on the figure)");
  put("proxy_width[settled]", q.settledWidth, "GL_TEXTURE_WIDTH of the proxy of that size: it, as it fits");
  const int n = kSizePanelPx;
  double x64 = 0, y64 = 0;
  for (int size : kSizes) {
    Frame f;
    f.width = f.height = n;
    f.panels.push_back(sizePanel(f, "size", {0, 0, n, n}, size));
    const Centroid c = markerCentroid(r.renderOffscreen(f), {0, 0, n, n});
    const std::string k = "[" + std::to_string(size) + "]";
    if (size == kSizes[0]) x64 = c.x, y64 = c.y;
    put("marker_px_x" + k, c.x, "the marker's centroid in the 256 px render, pixels from the left");
    put("marker_px_y" + k, c.y, "the same, pixels from the bottom");
    put("marker_offset_px" + k, std::max(std::abs(c.x - x64), std::abs(c.y - y64)),
        "how far the marker lies from where the 64^2 texture puts it, pixels (a 64^2 texel is 4)");
    put("marker_pixels" + k, double(c.n), "pixels of the marker's colour");
  }
}

// ---- residency by distance ----------------------------------------------------------------------------------------
// The level-colour texture (each level one flat colour), read with GL_LINEAR_MIPMAP_LINEAR: the colour says which
// two levels were blended and by how much.
inline TextureDesc levelTexture() {
  TextureDesc t = mipLevelColours(kLevelTexels);
  t.minFilter = GL_LINEAR_MIPMAP_LINEAR, t.magFilter = GL_LINEAR;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}
// The unit quad facing the eye at distance d, in a square panel whose vertical field of view has tan(fov/2) = 0.375.
inline Panel distancePanel(const std::string& id, const Rect& viewport, int texture, double d) {
  Panel p;
  p.id = id, p.viewport = viewport;
  p.projection = glm::perspective(float(2 * std::atan(kTanHalfFov)), 1.0f, 0.1f, 100.0f);
  Batch b;
  b.role = "surface";
  b.texture = texture;
  for (int k : {0, 1, 2, 0, 2, 3}) {
    const glm::vec2 c(k == 1 || k == 2, k >= 2);
    b.vertices.push_back({{c.x - 0.5f, c.y - 0.5f, float(-d)}, {c, 0.0f, 1.0f}, {1, 1, 1, 1}});
  }
  p.batches.push_back(b);
  return p;
}
inline void measureResidency(Renderer& r, Measurements& ms) {
  auto put = [&](const std::string& n, double v, const std::string& meaning) { ms.push_back({n, v, meaning}); };
  const int n = kDistancePanelPx;
  for (double d : kDistances) {
    Frame f;
    f.width = f.height = n;
    f.panels.push_back(distancePanel("distance", {0, 0, n, n}, f.addTexture(levelTexture()), d));
    const Image img = r.renderOffscreen(f);
    // The middle half of the quad: its colour is flat (a facing plane has one lambda).
    const int side = int(quadPixels(d)), c = n / 2;
    const lod::Mean m = lod::meanOf(img, {c - side / 4, c - side / 4, std::max(1, side / 2), std::max(1, side / 2)});
    double residual = 0;
    const double level = lod::levelOfColour(m, kLevels, &residual);
    const int finest = int(std::floor(level + 1e-9));
    const std::string k = "[" + distanceKey(d) + "]";
    put("levels_read" + k, level, "k + f decoded from the colour: levels k and k + 1 blended, f of k + 1");
    put("finest_level_read" + k, finest, "the finest level GL read at this distance");
    put("second_level_read" + k, std::min(finest + 1, kLevels - 1),
        "the other level GL_LINEAR_MIPMAP_LINEAR blends in");
    put("blend_weight" + k, level - finest, "the weight of that second level, decoded from the colour");
    put("level_colour_residual" + k, residual,
        "8-bit distance of the colour from the nearest blend of two level colours");
    put("resident_fraction" + k, residentFraction(finest),
        "texels of the levels from the finest read down to the 1x1, over the whole chain's");
  }
  put("chain_over_level0", double(chainTexels(kLevelTexels)) / double(kLevelTexels * kLevelTexels),
      "the whole chain's texels over level 0's (about 4/3)");
}

// ---- the clipmap -------------------------------------------------------------------------------------------------
inline const glm::vec4 kExposedColour{1.0f, 1.0f, 1.0f, 1.0f};  // white: the strips the last move uploaded
inline const glm::vec4 kSeamColour{0.0f, 0.0f, 0.0f, 1.0f};     // black: where the window's first texel is stored
inline glm::vec4 levelColour(int l) {
  const Rgba c = mipLevelColour(l);
  return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f};
}
inline Rgba rgba(const glm::vec4& c) { return {uint8_t(c.r * 255), uint8_t(c.g * 255), uint8_t(c.b * 255), 255}; }

// The view with each level's window outlined in its level colour (row 0 the top).
inline Image outlinedView(Image img, const Eye& e) {
  for (int l = 0; l < kClipLevels; ++l) {
    const Eye w = windowOrigin(e, l);
    const double s = double(1 << l) / kTexelsPerPixel;
    const int x0 = int(std::lround((w.x * double(1 << l) - viewOriginX(e)) / kTexelsPerPixel));
    const int y0 = int(std::lround((w.y * double(1 << l) - viewOriginY(e)) / kTexelsPerPixel));
    const int side = int(std::lround(kClip * s));
    for (int t = 0; t <= side; ++t)
      for (int k = 0; k < 2; ++k) {
        const int pts[4][2] = {{x0 + t, y0 + k}, {x0 + t, y0 + side - k}, {x0 + k, y0 + t}, {x0 + side - k, y0 + t}};
        for (const auto& p : pts)
          if (p[0] >= 0 && p[0] < img.width && p[1] >= 0 && p[1] < img.height)
            img.set(p[0], img.height - 1 - p[1], mipLevelColour(l));
      }
  }
  return img;
}
// The flight view with the edges between levels drawn in the finer level's colour (row 0 the top).
inline Image outlinedFlight(Image img, const std::vector<int>& levels) {
  const int w = img.width, h = img.height;
  for (int y = 0; y + 1 < h; ++y)
    for (int x = 0; x + 1 < w; ++x) {
      const int a = levels[size_t(y) * w + x], b = levels[size_t(y) * w + x + 1], c = levels[size_t(y + 1) * w + x];
      if (a < 0 || (a == b && a == c)) continue;
      int finer = a;
      for (int o : {b, c})
        if (o >= 0) finer = std::min(finer, o);
      img.set(x, y, mipLevelColour(finer));
    }
  return img;
}
// Level l's storage halved (row 0 the top, t up), the last move's pieces whitened (at least 2 pixels wide, so
// a strip of one texel shows) and the seam (where the window's first texel is stored) black.
inline Image stackPicture(const Image& storage, const std::vector<Piece>& pieces, const Eye& origin) {
  constexpr int kZoom = 2, n = kClip / kZoom;
  Image out(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) out.set(x, n - 1 - y, storage.at(x * kZoom, y * kZoom));
  for (const Piece& p : pieces) {
    const int x0 = p.sx / kZoom, y0 = p.sy / kZoom;
    const int x1 = std::max(x0 + 2, (p.sx + p.w + kZoom - 1) / kZoom),
              y1 = std::max(y0 + 2, (p.sy + p.h + kZoom - 1) / kZoom);
    for (int y = y0; y < std::min(y1, n); ++y)
      for (int x = x0; x < std::min(x1, n); ++x) {
        const Rgba c = out.at(x, n - 1 - y);
        out.set(x, n - 1 - y,
                {uint8_t((c.r + 3 * 255) / 4), uint8_t((c.g + 3 * 255) / 4), uint8_t((c.b + 3 * 255) / 4), 255});
      }
  }
  const int sx = mod(origin.x, kClip) / kZoom, sy = mod(origin.y, kClip) / kZoom;
  for (int t = 0; t < n; ++t) out.set(sx, n - 1 - t, rgba(kSeamColour)), out.set(t, n - 1 - sy, rgba(kSeamColour));
  return out;
}

inline void measureClipmap(Renderer& r, Measurements& ms, Detail& d, int moves = kMoves) {
  auto put = [&](const std::string& n, double v, const std::string& meaning) { ms.push_back({n, v, meaning}); };
  const Eye end = eyeAfter(moves);
  r.release();  // the record shows every object made
  long long reload = 0, moved = 0, lastPerLevel[kClipLevels] = {};
  std::vector<Piece> lastPieces[kClipLevels];
  Image view;
  {
    gl::Recording rec;
    ClipStack stack;
    stack.load(kEyeStart);
    for (long long t : uploadedTexels(rec.calls())) reload += t;
    for (int m = 1; m <= moves; ++m) {
      const size_t before = rec.calls().size();
      if (m < moves) {
        stack.move(eyeAfter(m - 1), eyeAfter(m));
      } else {
        // The last move level by level, so that the figure shows each level's share.
        for (int l = 0; l < kClipLevels; ++l) {
          const size_t at = rec.calls().size();
          for (const TexelRect& x : exposed(eyeAfter(m - 1), eyeAfter(m), l)) {
            stack.upload(l, x);
            for (const Piece& p : toroidalPieces(x)) lastPieces[l].push_back(p);
          }
          for (long long t : uploadedTexels({rec.calls().begin() + long(at), rec.calls().end()})) lastPerLevel[l] += t;
        }
      }
      for (long long t : uploadedTexels({rec.calls().begin() + long(before), rec.calls().end()})) moved += t;
    }
    view = stack.draw(r, end);
    d.flight = stack.drawFlight(r, end);
    for (int l = 0; l < kClipLevels; ++l) {
      d.clipStorage[l] = stack.storage(l);
      d.clipLevels[l] = stackPicture(d.clipStorage[l], lastPieces[l], windowOrigin(end, l));
    }
    d.clipCalls = std::make_shared<const std::vector<gl::Call>>(rec.take());
  }
  measureProgress(0.6);
  // The control: the same path with the last move's uploads left out.
  Image stale;
  {
    ClipStack stack;
    stack.load(kEyeStart);
    for (int m = 1; m < moves; ++m) stack.move(eyeAfter(m - 1), eyeAfter(m));
    stale = stack.draw(r, end);
  }
  std::vector<int> levels;
  const Image want = referenceView(end, &levels);
  d.clipView = outlinedView(view, end), d.clipViewRaw = view;
  long long predicted = 0;
  for (int m = 1; m <= moves; ++m) predicted += exposedTexels(eyeAfter(m - 1), eyeAfter(m));
  put("clipmap_mismatch_px", double(differingPixels(view, want)),
      "pixels of the stack's view (GL, after the moves) that differ at all from the procedural texture sampled on the "
      "CPU at the level and texel the stack selects there");
  put("clipmap_mismatch_px[stale]", double(differingPixels(stale, want)),
      "the same with the last move's glTexSubImage2D calls left out (a control that must find some)");
  std::vector<char> ambiguous;
  std::vector<int> flightLevels;
  const Image flightWant = referenceFlight(end, &ambiguous, &flightLevels);
  long long nAmbiguous = 0;
  for (char a : ambiguous) nAmbiguous += a;
  put("clipmap_flight_mismatch_px", double(differingPixels(d.flight, flightWant, ambiguous)),
      "pixels of the perspective view (GL) that differ from the CPU's ray to the ground, sampled at the level whose "
      "window holds the ground point, leaving out the ambiguous ones");
  d.flightRaw = d.flight, d.flight = outlinedFlight(d.flight, flightLevels);
  put("clipmap_flight_ambiguous_px", double(nAmbiguous),
      "pixels of the perspective view within 1/64 pixel of a texel's or window's edge (not held to one texel)");
  put("clipmap_texels_uploaded[move]", double(moved) / moves,
      "texels glTexSubImage2D sent a move, all levels, mean of the moves (counted from the recorded calls)");
  put("clipmap_texels_uploaded[predicted]", double(predicted) / moves,
      "the same from the equation: the strips that entered each level's window");
  put("clipmap_texels_uploaded[reload]", double(reload), "texels the first load (a reload of every window) sent");
  for (int l = 0; l < kClipLevels; ++l)
    put("clipmap_level_texels_uploaded[" + std::to_string(l) + "]", double(lastPerLevel[l]),
        "texels the last move uploaded into level " + std::to_string(l));
  put("clipmap_stack_texels", double(clipmapTexels(kVirtual, kClip)),
      "texels of a 16384^2 clipmap with levels of at most 512^2, the 1x1 included (the closed form)");
  put("clipmap_chain_texels", double(chainTexels(kVirtual)), "texels of the whole 16384^2 mip chain");
  put("clipmap_saving", double(chainTexels(kVirtual)) / double(clipmapTexels(kVirtual, kClip)), "chain / stack");
  put("clipmap_saving[65536/512]", double(chainTexels(65536)) / double(clipmapTexels(65536, 512)),
      "the same closed form for texture_compression's 65536^2 texture");
  put("clipmap_moves", moves, "moves of the eye");
  put("clipmap_step_x", kStepX, "level-0 texels a move, right");
  put("clipmap_step_y", kStepY, "level-0 texels a move, up");
}
}  // namespace ts::residency
