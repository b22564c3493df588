// demos/parallax_aniso/parallax_aniso_live.hpp — the live view's draw and its
// timing (the parallax_aniso demo's `--view live`).
//
// The chosen mode (M0..M5; R is the CPU reference, seconds a frame, so it is
// not drawn live) at the target's full size, drawn by ReliefGL::drawLive
// straight into a texture, timed with glFinish.  The milliseconds go to the
// measurements (stdout, the `h` overlay), not into the picture, so a --png
// of the live view stays reproducible.
// In a window, while the view moves (--animate, or a key in the last half
// second) a mode too slow for 20 frames a second is drawn smaller and
// upscaled (the picture says the scale and the fps); still, it is drawn at
// full size again.  --png never scales.
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "parallax_aniso_gl.hpp"
#include "parallax_aniso_views.hpp"

namespace pax {
class LiveTimer {
 public:
  // What one live frame asks for: `cam` at the measured size (the draw is
  // at the target's), the modes of the two halves (against < 0: no split),
  // and `state`, everything but the azimuth that changes what a draw costs.
  struct Ask {
    Camera cam;
    int mode = 0, against = -1;
    PassOptions options;
    std::string state;
    bool windowed = false, animate = false;
  };

  ts::Measurements draw(ts::Renderer& r, ReliefGL& gl, const Relief& rel, const Ask& a) {
    const int fullW = std::max(1, r.pictureWidth()), fullH = std::max(1, r.pictureHeight());
    double now = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    const std::string key = a.state + " " + std::to_string(fullW) + "x" + std::to_string(fullH);
    if (key != key_) {  // a new draw: its own timings (the fps printed after m is the new mode's)
      ms_.clear();
      settled_ = false;
      if (!key_.empty()) movedAt_ = now;  // (the first picture is no movement)
      key_ = key;
    }
    if (a.cam.azimuthDeg != azimuth_) {
      if (azimuth_ < 1e9) movedAt_ = now;
      azimuth_ = a.cam.azimuthDeg;
    }
    const bool moving = a.windowed && (a.animate || now - movedAt_ < 0.5);
    if (!moving) scale_ = 1.0;
    Camera c = a.cam;
    c.width = std::max(1, int(std::lround(fullW * scale_)));
    c.height = std::max(1, int(std::lround(fullH * scale_)));
    auto liveMode = [](int m) { return m == kReference ? -1 : m; };
    int left = liveMode(a.mode), right = a.against >= 0 ? liveMode(a.against) : -1;
    if (left < 0) left = right, right = -1;  // the reference cannot be drawn live: the other half fills the view
    ts::Measurements m;
    if (left < 0) return m;
    auto t0 = std::chrono::steady_clock::now();
    GLuint tex = gl.drawLive(c, rel, left, right, a.options);
    glFinish();
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (scale_ != msScale_) ms_.clear(), msScale_ = scale_;  // a median at one scale
    ms_.push_back(ms);
    if (ms_.size() > 15) ms_.erase(ms_.begin());
    std::vector<double> sorted = ms_;
    std::sort(sorted.begin(), sorted.end());
    double median = sorted[sorted.size() / 2];
    const double shownScale = scale_;
    // The next frame's scale while moving: the draw's time is about
    // proportional to its pixels, so scale x sqrt(budget / ms) meets the
    // budget (35 ms leaves the rest of a 20 fps frame to the window); left
    // alone within 70-115 % of it (each new size is a new target texture).
    if (moving && (ms > 1.15 * kBudgetMs || (ms < 0.7 * kBudgetMs && scale_ < 1.0))) {
      double want = scale_ * std::sqrt(kBudgetMs / std::max(1e-3, ms));
      scale_ = std::clamp(std::floor(std::min(1.0, want) * 16.0) / 16.0, 0.25, 1.0);
    }
    if (a.windowed && !settled_ && ms_.size() == 15) {  // the new state's speed, once it has settled
      settled_ = true;
      std::printf("live: %s at %dx%d, drawn at scale %.2f: %.1f ms a draw (%.1f fps), median of 15 frames\n",
                  kModeLabels[left], fullW, fullH, shownScale, median, 1000.0 / median);
      std::fflush(stdout);
    }
    views::Live live;
    live.texture.name = "parallax_live";
    live.texture.params = {{"left", kModeKeys[left]},
                           {"right", right < 0 ? "-" : kModeKeys[right]},
                           {"size", std::to_string(c.width) + "x" + std::to_string(c.height)},
                           {"made_by", "ReliefGL::drawLive in the parallax_aniso demo's measure()"}};
    live.texture.glTexture = tex;
    live.texture.minFilter = live.texture.magFilter = shownScale < 1.0 ? GL_LINEAR : GL_NEAREST;
    live.texture.wrapS = live.texture.wrapT = GL_CLAMP_TO_EDGE;
    live.size = {c.width, c.height};
    live.modes = {left, right};
    live.scale = shownScale;
    live.fps = 1000.0 / (ms + 1e-9);
    m.detail = live;
    m.push_back({"live_ms_per_frame", median,
                 "the live view's draw, median of the last " + std::to_string(ms_.size()) + " frames (glFinish)"});
    m.push_back({"live_fps", 1000.0 / median, "frames per second that draw allows (20 = interactive)"});
    m.push_back({"live_scale", shownScale,
                 "the draw's size / the window's (below 1 while the view moves and the "
                 "mode is too slow for 20 fps; 1 at rest and in --png)"});
    return m;
  }

 private:
  static constexpr double kBudgetMs = 35.0;
  std::vector<double> ms_;  // the live draw's ms per frame, scaled to full size
  double scale_ = 1.0, msScale_ = 1.0, movedAt_ = -1e9, azimuth_ = 1e9;
  std::string key_;
  bool settled_ = false;
};
}  // namespace pax
