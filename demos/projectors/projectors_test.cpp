// demos/projectors/projectors_test.cpp — demos/projectors: seed 002's wraps
// as printed against corrected, box mapping's stretch, glTexGen OBJECT_LINEAR
// against EYE_LINEAR, the slide projector, the solid texture, the cube.
// Every number the demo prints comes from texel-index renders; here each is
// held against its closed form computed independently (projectors_math.hpp's
// formulas or the trigonometry of the wraps' definitions), with a tolerance from the
// texel size of the render that measured it.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "common/core/frame.hpp"
#include "common/core/scene.hpp"
#include "demos/projectors/projectors_math.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::Demo;
using ts::test::value;
constexpr double kPi = 3.14159265358979323846;

// One measurement of the whole demo (the numbers do not depend on the view).
const ts::Measurements& measured() {
  static Demo demo("projectors", {"--view", "object"});
  static ts::Measurements m = demo.measure();
  return m;
}
double v(const std::string& name) { return value(measured(), name); }

// Seed 002, planar along Z as printed: tv written with x, so every pixel's
// texel has s = t; corrected, only the pixels near x = y do (< 1 %); X and Y
// as printed are already right (0 mismatches).
TEST(Projectors, PlanarZAsPrintedLiesOnTheDiagonal) {
  EXPECT_EQ(v("planar_z_diagonal_share"), 1.0);
  EXPECT_LT(v("planar_z_diagonal_share_corrected"), 0.01);
  EXPECT_GT(v("planar_z_mismatch_share"), 0.95);
  EXPECT_EQ(v("planar_x_mismatch_share"), 0.0);
  EXPECT_EQ(v("planar_y_mismatch_share"), 0.0);
  EXPECT_EQ(v("planar_z_corrected_columns"), 1.0);
  EXPECT_EQ(v("planar_z_corrected_rows"), 1.0);
}

// Cylindrical as printed: arctg's period π gives tu in ±0.25 — half the
// columns (64 of 128) along every axis; p and -p read one column; half the
// pixels differ from atan2 (the half with b < 0, where they differ by 1/2).
TEST(Projectors, CylindricalAsPrintedUsesHalfTheColumns) {
  for (const char* a : {"x", "y", "z"}) {
    const std::string k = std::string("cylindrical_") + a;
    EXPECT_NEAR(v(k + "_printed_columns"), 0.5, 1.0 / 128) << a;
    EXPECT_EQ(v(k + "_corrected_columns"), 1.0) << a;
    EXPECT_NEAR(v(k + "_mismatch_share"), 0.5, 0.02) << a;
  }
  EXPECT_EQ(v("cylindrical_opposite_collide"), 1.0);
  EXPECT_EQ(v("cylindrical_opposite_collide_corrected"), 0.0);
}

// Spherical as printed: arctg(x/|p|) reaches π/4 only, so tv − 1/2 is
// atan(1)/π = 0.25 at the pole and atan(sin 45°)/π = 0.1959 at 45°
// (arcsin: 0.5 and 0.25), and only half the rows are used.  Read from a
// 2048-row texel-index render: within one row (1/2048) plus the pixel's
// offset from the point (< 0.002 there).
TEST(Projectors, SphericalAsPrintedReachesAQuarter) {
  const double tol = 1.0 / 2048 + 0.002;
  EXPECT_NEAR(v("spherical_pole_tv"), std::atan(1.0) / kPi, tol);
  EXPECT_NEAR(v("spherical_45_tv"), std::atan(std::sin(kPi / 4)) / kPi, tol);
  EXPECT_NEAR(v("spherical_45_tv"), 0.1959, tol);
  EXPECT_NEAR(v("spherical_pole_tv_corrected"), 0.5, tol);
  EXPECT_NEAR(v("spherical_45_tv_corrected"), 0.25, tol);
  for (const char* a : {"x", "y", "z"}) {
    EXPECT_NEAR(v(std::string("spherical_") + a + "_printed_rows"), 0.5, 2.0 / 128) << a;
    EXPECT_EQ(v(std::string("spherical_") + a + "_corrected_rows"), 1.0) << a;
  }
}

// Corrected cylindrical along Y is Buss's Eq. VI.1: per fragment it reads
// the very texels of cylinder_seam's per-vertex mapping (winding tracked);
// computed per vertex by atan2, the Fig. VI.4 seam comes back on one patch.
// Per fragment with implicit derivatives the cut draws a line of a coarse
// mip level (λ more than 1 above the analytic); textureGrad with cut-free
// derivatives draws none.
TEST(Projectors, CorrectedCylindricalIsBussEqVI1AndItsSeam) {
  EXPECT_EQ(v("cylinder_buss_mismatches"), 0.0);
  EXPECT_EQ(v("cylinder_buss_far"), 0.0);
  EXPECT_GT(v("cylinder_pervertex_seam_pixels"), 0.0);
  EXPECT_EQ(v("cylinder_pervertex_reversed_patches"), 1.0);
  EXPECT_GT(v("lambda_line_implicit"), 0.0);
  EXPECT_EQ(v("lambda_line_grad"), 0.0);
}

// Box mapping: the worst stretch is 1/|n_axis| <= √3, reached toward
// (1,1,1)/√3 (the measured pixels stop 4 px short of the face edges, so a
// little under); one planar projection: 1/cos 80° = 5.76 at 80°.
TEST(Projectors, BoxMappingStretchesAtMostRootThree) {
  EXPECT_LE(v("box_worst_stretch"), std::sqrt(3.0) * 1.02);
  EXPECT_GE(v("box_worst_stretch"), 1.6);
  EXPECT_NEAR(v("planar_stretch_80"), proj::planarStretch(80), 0.05 * proj::planarStretch(80));
}

// glTexGen: a surface point keeps its texel as the object moves with
// OBJECT_LINEAR; with EYE_LINEAR (planes given at pose 0) it changes.
TEST(Projectors, EyeLinearSwimsObjectLinearDoesNot) {
  EXPECT_EQ(v("swim_changes_object_linear"), 0.0);
  EXPECT_GT(v("swim_changes_eye_linear"), 0.0);
}

// The slide projector: GL's EYE_LINEAR (s/q, t/q) against the CPU's rows of
// B·P_L·V_L at every pixel centre not within 1/1000 texel of a texel edge:
// 0 mismatches; the back projection shows without a fix and not with the
// clip plane q >= 0.
TEST(Projectors, SlideProjectorMatchesTheCpuAndTheClipPlaneRemovesTheBackProjection) {
  EXPECT_EQ(v("slide_mismatches"), 0.0);
  EXPECT_GT(v("slide_checked"), 50000.0);
  EXPECT_GT(v("slide_back_pixels_nofix"), 0.0);
  EXPECT_EQ(v("slide_back_pixels_clip"), 0.0);
}

// The solid texture (GL_TEXTURE_3D, 64³, OBJECT_LINEAR s, t, r): no texel
// jumps and no pinch; Eq. VI.2 has its seam line and pinches at the pole.
TEST(Projectors, SolidTextureHasNoSeamAndNoPinch) {
  EXPECT_EQ(v("solid3d_seam_pixels"), 0.0);
  EXPECT_GT(v("latlong_seam_pixels"), 0.0);
  EXPECT_LT(v("solid3d_pole_s_share"), 4.0 / 64);
  EXPECT_GT(v("latlong_pole_s_share"), 0.25);
}

// Seed 002's Task 2 and Buss's cube: 24 vertices give 6 faces reading the
// unit square, not mirrored; 8 shared vertices ((x+1)/2, (y+1)/2) give one
// (+Z), four smeared (±X, ±Y) and one mirrored (-Z) — as projectors_math.hpp's
// signed areas say.
TEST(Projectors, CubeNeeds24Vertices) {
  EXPECT_EQ(v("cube24_good_faces"), 6.0);
  int good = 0, smeared = 0, mirrored = 0;
  auto c8 = proj::cube8();
  for (int f = 0; f < 6; ++f) {
    double a = proj::faceStArea(c8, f);
    good += a > 0.5, smeared += std::abs(a) < 1e-9, mirrored += a < -0.5;
  }
  EXPECT_EQ(v("cube8_good_faces"), double(good));
  EXPECT_EQ(v("cube8_smeared_faces"), double(smeared));
  EXPECT_EQ(v("cube8_mirrored_faces"), double(mirrored));
}

// The texgen state is in the Frame, so the sidecar can say it: the swim
// figure's batches carry OBJECT_LINEAR and EYE_LINEAR planes, the slide's
// the four rows of B·P_L·V_L and the clip plane (the Q row).
TEST(Projectors, TexGenIsPartOfTheFrame) {
  Demo swim("projectors", {"--view", "swim"});
  ts::Frame f = swim.frame(1024, 512);
  int object = 0, eye = 0;
  for (const auto& p : f.panels)
    for (const auto& b : p.batches) {
      object += b.texGen.mode == GL_OBJECT_LINEAR;
      eye += b.texGen.mode == GL_EYE_LINEAR;
    }
  EXPECT_EQ(object, 2);
  EXPECT_EQ(eye, 2);
  Demo slide("projectors", {"--view", "slide"});
  ts::Frame g = slide.frame(1024, 512);
  const ts::Batch* clipped = nullptr;
  for (const auto& p : g.panels)
    for (const auto& b : p.batches)
      if (b.clip) clipped = &b;
  ASSERT_NE(clipped, nullptr);
  EXPECT_EQ(clipped->texGen.coords, 15u);
  EXPECT_EQ(clipped->clipPlane, clipped->texGen.planes[3]);
  // The same plane in the same space: given under the modelview the Q plane was.
  EXPECT_EQ(clipped->clipModelview, clipped->texGen.planeModelview);
}

// The window's texture-space panel: the state's share of columns, as the
// corrected planar map along Z on the sphere uses all of them.
TEST(Projectors, StateUsage) {
  Demo d("projectors", {"--projector", "planar", "--axis", "z", "--formula", "corrected", "--object", "sphere"});
  ts::Measurements m = d.measure();
  EXPECT_EQ(value(m, "state_columns"), 1.0);
  Demo p("projectors", {"--projector", "cylindrical", "--axis", "y", "--formula", "printed", "--coords", "glsl"});
  EXPECT_NEAR(value(p.measure(), "state_columns"), 0.5, 2.0 / 64);
}
}  // namespace
