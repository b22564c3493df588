// demos/dynamic_reflection/dynamic_reflection_test.cpp — the dynamic cube
// map's claim: rendered this frame, the ball's reflection is far closer to
// the traced one than a map made at time 0; a face flipped or a 60-degree
// field of view is further off than the right cameras; a sphere reads all six
// faces, a flat mirror fewer; six renders a frame.  And, apart from the
// demo's own measurement, the cube pass's faces probed against the GL spec's
// face table: every texel showing the ball points at it.  The flat mirror:
// rendered mirrored in its plane it is all but exact, through the cube map
// made at its centre far off, and it reads far fewer texels than it covers
// pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <glm/glm.hpp>

#include "common/core/env_maps.hpp"
#include "common/core/image.hpp"
#include "demos/dynamic_reflection/dynamic_reflection_gl.hpp"
#include "demos/dynamic_reflection/dynamic_reflection_math.hpp"
#include "demos/dynamic_reflection/dynamic_reflection_views.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::Demo;
using ts::test::value;

// Measured at the default state (time 1.5, 128-texel faces, llvmpipe): static 409 px, dynamic 90 px, a ratio of
// 4.5; what the dynamic map still gets wrong is the parallax between the sphere's centre, where the map is made,
// and its surface (against rays leaving from the centre: 8 px).  Asserted: at least 3 times smaller.
TEST(DynamicReflection, TheMapRenderedThisFrameIsFarCloserThanTheMapOfTimeZero) {
  Demo d("dynamic_reflection", {});
  const ts::Measurements m = d.measure();
  const double stat = value(m, "moving_ball_error_px[static]"), dyn = value(m, "moving_ball_error_px[dynamic]");
  const double ball = value(m, "ball_reflection_px");
  EXPECT_GT(ball, 50);       // the ball's reflection is there to be missed
  EXPECT_GT(stat, ball);     // the old map misses it where it is and shows it where it was
  EXPECT_LT(3 * dyn, stat);  // "much smaller": 4.5x measured
  EXPECT_LT(4 * value(m, "moving_ball_error_px[parallax_free]"), dyn);  // the rest is parallax
  EXPECT_EQ(value(m, "cube_map_renders_per_frame"), 6);
}

// At time 0 the map of time 0 is this frame's: the same render, the same error.
TEST(DynamicReflection, AtTimeZeroStaticAndDynamicAgree) {
  Demo d("dynamic_reflection", {"--time", "0"});
  const ts::Measurements m = d.measure();
  EXPECT_EQ(value(m, "moving_ball_error_px[static]"), value(m, "moving_ball_error_px[dynamic]"));
}

TEST(DynamicReflection, WrongCamerasPutTheBallElsewhere) {
  Demo d("dynamic_reflection", {"--view", "variants"});
  const ts::Measurements m = d.measure();
  const double right = value(m, "moving_ball_error_px[dynamic]");
  EXPECT_GT(value(m, "moving_ball_error_px[face_flipped]"), 2 * right);
  EXPECT_GT(value(m, "moving_ball_error_px[fov_60]"), 2 * right);
}

TEST(DynamicReflection, ASphereReadsEveryFaceAFlatMirrorFewer) {
  Demo d("dynamic_reflection", {"--view", "faces"});
  const ts::Measurements m = d.measure();
  EXPECT_EQ(value(m, "faces_read[sphere]"), 6);
  EXPECT_LT(value(m, "faces_read[flat_mirror]"), value(m, "faces_read[sphere]"));
  EXPECT_GE(value(m, "faces_read[flat_mirror]"), 1);
  EXPECT_GE(value(m, "faces_read[torus]"), value(m, "faces_read[flat_mirror]"));
}

// Measured (llvmpipe, 256 x 256): rendered mirrored 19 px wrong, the cube map 8671, of 1498 ball pixels traced;
// 892 texels over 36224 pixels (40.6 a texel).  Asserted: the planar pass within a twentieth of the ball (its
// outline's rasterization), the cube map off by more than the ball itself (it shows it near and large).
TEST(DynamicReflection, APlanarMirrorRenderedMirroredIsExactTheCubeMapIsNot) {
  Demo d("dynamic_reflection", {"--view", "planar"});
  const ts::Measurements m = d.measure();
  const double ball = value(m, "flat_mirror_ball_px");
  EXPECT_GT(ball, 100);
  EXPECT_LT(20 * value(m, "flat_mirror_error_px[planar]"), ball);
  EXPECT_GT(value(m, "flat_mirror_error_px[cube_map]"), ball);
  const double pixels = value(m, "flat_mirror_pixels"), texels = value(m, "flat_mirror_texels_read");
  EXPECT_GT(texels, 0);
  EXPECT_GT(pixels, 10 * texels);  // magnified: many pixels a texel
  EXPECT_DOUBLE_EQ(value(m, "flat_mirror_magnification"), pixels / texels);
}

// The cube pass drawn with the ball in red on black, its faces stacked t = 0 first: each texel (face, i, j)
// holds the world in direction cubeDir(face, s, t) (the spec's table, common/core/env_maps.hpp).  A texel whose
// direction is inside the ball's cone by more than a texel's angle must be red, one outside it by as much black.
// The flipped variant breaks this on its face: the probe sees it.
int texelsAgainstTheTable(int variant) {
  constexpr int kFace = 64;
  constexpr double kTime = 1.5;
  const ts::Image img = ts::test::renderer().renderOffscreen(
      dynref::cubeFrame(kFace, dynref::ballCentre(kTime), variant, dynref::kMask));
  const glm::dvec3 c = dynref::ballCentre(kTime);
  const double cone = std::asin(dynref::kBallRadius / glm::length(c)) * 180.0 / dynref::kPi;
  const double texel = 90.0 / kFace * 1.5;  // a texel's angle at a face's centre, with room for its diagonal
  int wrong = 0, inside = 0;
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < kFace; ++j)
      for (int i = 0; i < kFace; ++i) {
        const glm::dvec3 d = ts::envmaps::cubeDir(f, (i + 0.5) / kFace, (j + 0.5) / kFace);
        const double a = ts::envmaps::angleDeg(d, c);
        const bool red = img.at(i, f * kFace + j).r > 127;
        if (a < cone - texel) ++inside, wrong += !red;
        if (a > cone + texel) wrong += red;
      }
  EXPECT_GT(inside, 20);
  return wrong;
}
TEST(DynamicReflection, CubePassFacesFollowTheSpecsTable) {
  EXPECT_EQ(texelsAgainstTheTable(dynref::kRight), 0);
  EXPECT_GT(texelsAgainstTheTable(dynref::kFaceFlipped), 20);
  EXPECT_GT(texelsAgainstTheTable(dynref::kFov60), 20);
}

// The demo's cube pass copied into the cube map's faces on the GPU (glCopyTexSubImage2D, the projection not
// y-negated) holds the texels the y-negated pass reads back stacked: the same faces, the same way up.  The mask
// passes, which every measurement reads, are identical; the coloured ones within a level.  Faces left out of the
// pass are left alone.
TEST(DynamicReflection, TheFacesCopiedOnTheGpuAreTheFacesReadBack) {
  constexpr int kFace = 64;
  ts::Renderer& r = ts::test::renderer();
  const glm::dvec3 ball = dynref::ballCentre(1.5);
  for (int content : {dynref::kColours, dynref::kMask}) {
    const ts::Image read = r.renderOffscreen(dynref::cubeFrame(kFace, ball, dynref::kRight, content));
    const GLuint cube = dynref::makeCubeMap(kFace);
    dynref::renderIntoCube(r, dynref::cubeFrame(kFace, ball, dynref::kRight, content, dynref::kBallRadius, true), cube);
    const ts::Image copied = dynref::readCubeMap(cube, kFace);
    int differ = 0, most = 0;
    for (size_t k = 0; k < read.pixels.size(); ++k) {
      const int d = std::abs(int(copied.pixels[k]) - int(read.pixels[k]));
      differ += d > 0, most = std::max(most, d);
    }
    std::printf("content %d: %d of %zu bytes differ, by at most %d\n", content, differ, read.pixels.size(), most);
    if (content == dynref::kMask) {
      EXPECT_EQ(differ, 0);  // what every measurement reads: the same texels
    } else {
      // The sky's (s, t, r) interpolated over the mirrored triangle rounds the other way at some texels, by one
      // level: how many is the rasterizer's (64-texel faces: 57 of 98304 bytes on llvmpipe, 5140 on softpipe).
      EXPECT_LE(most, 1);
    }
    // Only +Y (bit 2) drawn again, over a mask pass: the other faces keep what they held.
    dynref::renderIntoCube(
        r, dynref::cubeFrame(kFace, ball, dynref::kRight, dynref::kMask, dynref::kBallRadius, true, 1u << 2), cube);
    const ts::Image partly = dynref::readCubeMap(cube, kFace);
    glDeleteTextures(1, &cube);
    const size_t faceBytes = size_t(kFace) * kFace * 4;
    for (int f = 0; f < 6; ++f)
      if (f != 2)
        EXPECT_TRUE(std::equal(partly.pixels.begin() + f * faceBytes, partly.pixels.begin() + (f + 1) * faceBytes,
                               copied.pixels.begin() + f * faceBytes))
            << "face " << f;
  }
}

// The mirrors' pictures are GL's, and each comes with the Frames the sidecar nests so that the CPU reference
// recomputes it: the eye pass, and the cube pass whose render (y negated) is the six faces stacked; the flat
// mirror's pass with the mirrored pass nested in it.  Rendered, each
// Frame is what GL drew (within a level): the faces the GPU copied, texel for texel, and the mirror's picture.
// A cube pass one step of time later is not (the control).
TEST(DynamicReflection, TheMirrorsPicturesAreTheFramesTheSidecarNests) {
  for (const char* view : {"scene", "variants", "planar"}) {
    SCOPED_TRACE(view);
    const ts::Measurements m = Demo("dynamic_reflection", {"--view", view}).measure();
    int checked = 0;
    for (const ts::Measurement& x : m)
      if (x.name.rfind("pass_frame_mismatch_px[", 0) == 0) {
        EXPECT_EQ(x.value, 0) << x.name;
        ++checked;
      }
    // The sphere's mirrors: an eye pass and a cube pass each (scene 2, variants 4, planar 1); the planar view's
    // flat mirror rendered mirrored and through a cube map, one each.
    const int expected = std::string(view) == "scene" ? 4 : std::string(view) == "variants" ? 8 : 4;
    EXPECT_EQ(checked, expected);
  }
  // The control: the cube pass's Frame a second later does not pass for this frame's faces.
  EXPECT_GT(value(Demo("dynamic_reflection", {}).measure(), "pass_frame_control_px[faces_a_second_later]"), 0);
}
}  // namespace
