// demos/texture_animation/texture_animation_test.cpp — the waterfall's claim, from the demo's own renders:
// the figure's frames show, pixel by pixel, the texel the texture matrix's translation names (the equation in
// texture_animation.cpp's header), and the measurement's frames read back from GL match each other moved by
// exactly speed x frame time x pixels a texel, and by no other shift.
//
// Tolerance.  GL_NEAREST has no rounding of colour: a pixel shows one texel's colour exactly.  Where a texel
// edge passes within a hundredth of a texel of a pixel's centre the rasterizer's interpolation of t may pick
// either neighbour, so those pixels are left out of the probe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "common/core/image.hpp"
#include "demos/texture_animation/texture_animation_textures.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::Demo;
using ts::test::value;

constexpr int kTexels = 32;          // the demo's texture and quad: one copy of 32 x 32 texels
constexpr int kFramesPerSecond = 4;  // the demo's measured frames are 1/4 s apart
constexpr int kPixelsPerTexel = 4;   // in its measurement

// Every pixel of the figure's frame panels is the texel at (s, t + speed time / h), taken round the texture.
TEST(TextureAnimation, FramesShowTheTranslatedTexels) {
  const ts::TextureDesc tex = ts::texanim::waterTexture(kTexels);
  for (const auto& [speed, time] : {std::pair{2, 1.25}, std::pair{5, 0.5}}) {
    SCOPED_TRACE("speed " + std::to_string(speed));
    Demo d("texture_animation", {"--speed", std::to_string(speed), "--time", std::to_string(time)});
    d.measure();
    ts::Frame f;
    const ts::Image img = d.render(960, 440, &f);
    for (int i = 0; i < 2; ++i) {
      const ts::Rect q = ts::test::panelOf(f, "frame_" + std::to_string(i)).viewport;
      const double seconds = time + double(i) / kFramesPerSecond;
      int probed = 0, wrong = 0;
      for (int y = q.y; y < q.y + q.h; ++y)
        for (int x = q.x; x < q.x + q.w; ++x) {
          const double s = (x + 0.5 - q.x) / q.w, t = (q.y + q.h - y - 0.5) / q.h;
          const double u = s * kTexels, v = t * kTexels + speed * seconds;
          const double edge = std::min({u - std::floor(u), std::ceil(u) - u, v - std::floor(v), std::ceil(v) - v});
          if (edge < 0.01) continue;
          const int ti = int(std::floor(u)) % kTexels, tj = int(std::floor(v)) % kTexels;
          const ts::Rgba want = tex.image->at(ti, tj), got = img.at(x, y);
          wrong += want.r != got.r || want.g != got.g || want.b != got.b;
          ++probed;
        }
      EXPECT_GT(probed, q.w * q.h / 2) << "frame " << i;
      EXPECT_EQ(wrong, 0) << "frame " << i;
    }
  }
}

// The measured frames k and k+1 match moved by the matrix's speed, and only by it; a wrong speed does not.
TEST(TextureAnimation, PictureMovesByExactlyTheMatrixSpeed) {
  for (int speed : {1, 2, 5, 0}) {
    SCOPED_TRACE("speed " + std::to_string(speed));
    const ts::Measurements m =
        Demo("texture_animation", {"--speed", std::to_string(speed), "--time", "1.25"}).measure();
    const int expected = speed * kPixelsPerTexel / kFramesPerSecond;
    EXPECT_EQ(value(m, "scroll_shift_px[expected]"), expected);
    EXPECT_EQ(value(m, "scroll_texel_mismatches"), 0);
    EXPECT_EQ(value(m, "scroll_shift_px[found]"), expected);
    EXPECT_GT(value(m, "scroll_texel_mismatches[wrong_speed]"), 0) << "the control finds the wrong shift";
    if (speed > 0) EXPECT_GT(value(m, "scroll_frame_changed_pixels"), 0) << "the water moved";
    else EXPECT_EQ(value(m, "scroll_frame_changed_pixels"), 0) << "speed 0: nothing moves";
  }
}

// The figure prints the measurement's numbers (Label::printed), never its own.
TEST(TextureAnimation, FigurePrintsTheMeasurement) {
  Demo d("texture_animation", {"--speed", "2", "--time", "1.25"});
  d.measure();
  const ts::Frame f = d.frame(960, 440);
  std::set<std::string> printed;
  for (const ts::Label& l : f.labels)
    for (const ts::Label::Printed& p : l.printed) printed.insert(p.name);
  for (const char* name : {"scroll_texel_mismatches", "scroll_texel_mismatches[wrong_speed]", "scroll_shift_px[found]",
                           "scroll_shift_px[expected]"})
    EXPECT_TRUE(printed.count(name)) << name;
}
}  // namespace
