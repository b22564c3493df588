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
#include <utility>
#include <vector>
#include <string>

#include "common/core/image.hpp"
#include "demos/texture_animation/texture_animation_math.hpp"
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

// The figures print the measurement's numbers (Label::printed), never their own.
TEST(TextureAnimation, FigurePrintsTheMeasurement) {
  const std::vector<std::pair<std::vector<std::string>, std::vector<const char*>>> views = {
      {{"--speed", "2", "--time", "1.25"},
       {"scroll_texel_mismatches", "scroll_texel_mismatches[wrong_speed]", "scroll_shift_px[found]",
        "scroll_shift_px[expected]"}},
      {{"--view", "flipbook", "--time", "1.25"},
       {"flipbook_bytes_per_frame[whole]", "flipbook_bytes_per_frame[partial]", "flipbook_mismatches",
        "flipbook_mismatches[next_frame]", "flipbook_bytes_shown[partial]"}},
      {{"--view", "torch", "--time", "1.25"}, {"torch_order_error_px[right]", "torch_order_error_px[wrong]"}},
      {{"--view", "lightmap", "--time", "1.25"},
       {"dynamic_lightmap_rms_levels", "dynamic_lightmap_rms_levels[stale]", "lightmap_bytes_per_frame"}}};
  for (const auto& [flags, names] : views) {
    SCOPED_TRACE(flags[1]);
    Demo d("texture_animation", flags);
    d.measure();
    const ts::Frame f = d.frame(960, 440);
    std::set<std::string> printed;
    for (const ts::Label& l : f.labels)
      for (const ts::Label::Printed& p : l.printed) printed.insert(p.name);
    for (const char* name : names) EXPECT_TRUE(printed.count(name)) << name;
  }
}

namespace ta = ts::texanim;

// The flipbook: every picture shown is its frame's texels, and the bytes counted from the glTexSubImage2D calls are
// what the frames make them: 4 bytes a texel of the whole frame, or of the rectangle bounding the texels that
// changed since the frame before (recomputed here from the generator's frames).
TEST(TextureAnimation, FlipbookUploadsWholeOrTheChangedRectangle) {
  std::vector<ts::Image> frames;
  for (int k = 0; k < ta::kFlipFrames; ++k) frames.push_back(ta::flameFrame(ta::kFlipTexels, k, ta::kFlipFrames));
  double partialSum = 0;
  for (int k = 1; k <= ta::kFlipFrames; ++k)
    partialSum += 4.0 * ta::changedRect(frames[size_t(k - 1)], frames[size_t(k % ta::kFlipFrames)]).texels();
  const double whole = 4.0 * ta::kFlipTexels * ta::kFlipTexels;
  for (const char* time : {"1.25", "0", "1.75"}) {
    SCOPED_TRACE(std::string("time ") + time);
    const ts::Measurements m = Demo("texture_animation", {"--view", "flipbook", "--time", time}).measure();
    const int k = int(std::floor(std::stod(time) * kFramesPerSecond + 1e-6)) % ta::kFlipFrames;
    const ta::TexRect shown = ta::changedRect(frames[size_t(k)], frames[size_t((k + 1) % ta::kFlipFrames)]);
    EXPECT_EQ(value(m, "flipbook_uploads"), ta::kFlipFrames + 1);
    EXPECT_EQ(value(m, "flipbook_bytes_first_frame"), whole);
    EXPECT_EQ(value(m, "flipbook_bytes_per_frame[whole]"), whole);
    EXPECT_DOUBLE_EQ(value(m, "flipbook_bytes_per_frame[partial]"), partialSum / ta::kFlipFrames);
    EXPECT_LT(value(m, "flipbook_bytes_per_frame[partial]"), whole) << "a partial upload sends less";
    EXPECT_EQ(value(m, "flipbook_bytes_shown[partial]"), 4.0 * shown.texels());
    EXPECT_EQ(value(m, "flipbook_rect_w"), shown.w);
    EXPECT_EQ(value(m, "flipbook_rect_h"), shown.h);
    EXPECT_EQ(value(m, "flipbook_mismatches"), 0);
    EXPECT_EQ(value(m, "flipbook_mismatches[whole]"), 0);
    EXPECT_EQ(value(m, "flipbook_mismatches[partial]"), 0);
    EXPECT_GT(value(m, "flipbook_mismatches[next_frame]"), 0) << "the control finds the other frame";
  }
}

// The torch: drawn opaque first, then the flames back to front with depth writes off, GL's picture is the CPU's
// composite within a level a blended layer; in the scene's order with depth written it is not, at least wherever
// the front flame's clear texels hid a wall or handle the composite shows brighter than the tolerance.
TEST(TextureAnimation, TorchNeedsOpaqueFirstThenBackToFront) {
  for (const char* time : {"1.25", "0.5"}) {
    SCOPED_TRACE(std::string("time ") + time);
    const ts::Measurements m = Demo("texture_animation", {"--view", "torch", "--time", time}).measure();
    const int k = int(std::floor(std::stod(time) * kFramesPerSecond + 1e-6));
    const ts::Image wall = *ts::texanim::waterTexture(ta::kFlipTexels).image;
    const ts::Image back = ta::flameFrame(ta::kFlipTexels, ta::backFlameFrame(k), ta::kFlipFrames);
    const ts::Image front = ta::flameFrame(ta::kFlipTexels, ta::frontFlameFrame(k), ta::kFlipFrames);
    const ts::Image cpu = ta::torchComposite(wall, back, front);
    const int tol = int(value(m, "torch_tolerance_levels"));
    EXPECT_EQ(tol, 2 * ta::kTorchLevelsPerLayer);
    // Where the front quad's texel is clear, the wrong order leaves the clear colour (black) blended by alpha 0.
    int hidden = 0;
    for (int y = 0; y < ta::kTorchPixels; ++y)
      for (int x = 0; x < ta::kTorchPixels; ++x) {
        const int py = ta::kTorchPixels - 1 - y;
        if (!ta::kFrontFlame.contains(x, py)) continue;
        const ts::Rgba s = front.at((x - ta::kFrontFlame.x) / ta::kFlipZoom, (py - ta::kFrontFlame.y) / ta::kFlipZoom);
        const ts::Rgba c = cpu.at(x, y);
        hidden += s.a == 0 && std::max({c.r, c.g, c.b}) > tol;
      }
    EXPECT_GT(hidden, 0);
    EXPECT_EQ(value(m, "torch_order_error_px[right]"), 0);
    EXPECT_GE(value(m, "torch_order_error_px[wrong]"), hidden);
    // Front to back, the back flame is blended last: only where both flames cover a pixel with some opacity can the
    // order show (elsewhere one of the blends leaves the colour as it was).
    int overlap = 0;
    for (int y = 0; y < ta::kTorchPixels; ++y)
      for (int x = 0; x < ta::kTorchPixels; ++x) {
        const int py = ta::kTorchPixels - 1 - y;
        if (!ta::kFrontFlame.contains(x, py) || !ta::kBackFlame.contains(x, py)) continue;
        const ts::Rgba f = front.at((x - ta::kFrontFlame.x) / ta::kFlipZoom, (py - ta::kFrontFlame.y) / ta::kFlipZoom);
        const ts::Rgba b = back.at((x - ta::kBackFlame.x) / ta::kFlipZoom, (py - ta::kBackFlame.y) / ta::kFlipZoom);
        overlap += f.a > 0 && b.a > 0;
      }
    EXPECT_GT(value(m, "torch_order_error_px[front_to_back]"), 0);
    EXPECT_LE(value(m, "torch_order_error_px[front_to_back]"), overlap);
  }
}

// The moving light: the map recomputed for the frame's light is as close to per-pixel lighting as its bilinear
// interpolation allows (the CPU's prediction, within GL's rounding), and closer than the map of time 0 once the
// light has moved; at time 0 the two maps are the same map and the same picture.
TEST(TextureAnimation, RecomputedLightMapFollowsTheLight) {
  for (const char* time : {"1.25", "3", "0"}) {
    SCOPED_TRACE(std::string("time ") + time);
    const ts::Measurements m = Demo("texture_animation", {"--view", "lightmap", "--time", time}).measure();
    EXPECT_EQ(value(m, "lightmap_bytes_per_frame"), 4.0 * ta::kLightTexels * ta::kLightTexels);
    EXPECT_LT(value(m, "dynamic_lightmap_gl_vs_cpu_rms"), 1.0) << "GL's picture is the CPU's prediction, rounded";
    EXPECT_NEAR(value(m, "dynamic_lightmap_rms_levels"), value(m, "dynamic_lightmap_rms_levels[predicted]"), 1.0);
    const glm::dvec3 now = ta::lightPosition(std::stod(time)), then = ta::lightPosition(0);
    EXPECT_NEAR(value(m, "light_moved"), glm::length(glm::dvec2(now - then)), 1e-9);
    if (std::stod(time) == 0) {
      EXPECT_EQ(value(m, "dynamic_lightmap_rms_levels[stale]"), value(m, "dynamic_lightmap_rms_levels"));
    } else {
      EXPECT_GT(value(m, "dynamic_lightmap_rms_levels[stale]"), value(m, "dynamic_lightmap_rms_levels"))
          << "the stale map lights where the light was";
    }
  }
}

// The flipbook's, the torch's and the light map's pictures are GL's readbacks of passes a Frame does not draw
// (glTexSubImage2D into a texture made once, glBlendFunc); each comes with a Frame describing what the pass drew,
// which the sidecar nests in the figure so that the CPU reference recomputes it.  That Frame, rendered, is the pass's
// picture (within a level), and the next flipbook frame's is not (the control).
TEST(TextureAnimation, EachPassIsTheFrameTheSidecarNests) {
  for (const char* view : {"flipbook", "torch", "lightmap"}) {
    SCOPED_TRACE(view);
    const ts::Measurements m = Demo("texture_animation", {"--view", view, "--time", "1.25"}).measure();
    int passes = 0;
    for (const ts::Measurement& x : m)
      if (x.name.rfind("pass_frame_mismatch_px[", 0) == 0) {
        EXPECT_EQ(x.value, 0) << x.name;
        ++passes;
      }
    EXPECT_EQ(passes, 6) << "the flipbook's two pictures, the torch's two and the light map's two";
    EXPECT_GT(value(m, "pass_frame_control_px[next_frame]"), 0) << "the next frame's Frame draws another picture";
  }
}
}  // namespace
