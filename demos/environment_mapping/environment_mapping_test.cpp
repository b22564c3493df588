// demos/environment_mapping/environment_mapping_test.cpp — demos/environment_mapping:
// each claim checked from GL read-backs, as relations between variants or
// against bounds the geometry gives, never against stored numbers.
//
// Tolerances.  The direction maps are RGBA32F and read back as floats; a
// per-pixel lookup returns the exact r to within the bilinear filter's error
// (a few thousandths of a degree in a face's interior).  Angles: a rotation
// by a moves no direction by more than a; reflecting two lines of sight about
// one normal gives reflections exactly as far apart as the lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "demos/environment_mapping/environment_mapping_studies.hpp"
#include "demos/environment_mapping/environment_mapping_math.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::Demo;
using ts::test::value;

// The measurements of the demo with one object (its table is that object's).
const ts::Measurements& measured(const std::string& object) {
  static std::map<std::string, ts::Measurements> cache;
  if (!cache.count(object)) cache[object] = Demo("environment_mapping", {"--object", object}).measure();
  return cache[object];
}
double v(const std::string& name) {
  for (const char* o : {"torus", "mirror"})
    if (name.find(std::string("/") + o + "/") != std::string::npos) return value(measured(o), name);
  return value(measured("sphere"), name);
}
std::string key(const char* p, const char* o, const char* e) { return std::string(p) + "/" + o + "/" + e; }

// Seed 001: the GL's lookup of (-3.2, 5.1, -8.4) read the face and texel the
// spec's table names (1000 x 1000 faces: within half a texel), and the seed's
// answer is that point mirrored in both axes.
TEST(EnvironmentMapping, SeedCubeExampleReadBack) {
  const envmap::CubeST c = envmap::cubeST(envmap::kSeedDirection);
  EXPECT_EQ(v("seed_cube_face"), c.face);
  EXPECT_EQ(v("seed_cube_readback_face"), c.face);
  EXPECT_NEAR(v("seed_cube_readback_s"), v("seed_cube_gl_s"), 0.5 / 1000 + 1e-9);
  EXPECT_NEAR(v("seed_cube_readback_t"), v("seed_cube_gl_t"), 0.5 / 1000 + 1e-9);
  EXPECT_NEAR(v("seed_cube_seed_s"), 1 - v("seed_cube_gl_s"), 1e-9);
  EXPECT_NEAR(v("seed_cube_seed_t"), 1 - v("seed_cube_gl_t"), 1e-9);
  EXPECT_GT(std::abs(v("seed_cube_readback_s") - v("seed_cube_seed_s")), 0.3);  // the GL does not do the seed's
}

// Per pixel every map returns nearly the exact r; per vertex the
// interpolation costs at least ten times more, on the curved objects.
TEST(EnvironmentMapping, PerPixelBeatsPerVertex) {
  for (const char* o : {"sphere", "torus"})
    for (const char* p : envmap::kParamKeys) {
      SCOPED_TRACE(std::string(p) + " " + o);
      EXPECT_LT(10 * v("error_mean_deg[" + key(p, o, "pixel") + "]"), v("error_mean_deg[" + key(p, o, "vertex") + "]"));
      EXPECT_LT(v("error_mean_deg[" + key(p, o, "pixel") + "]"), 0.1);
    }
}

// Where the errors concentrate: the cube's face edges (bilinear lookups
// clamp at a face's border), the sphere map's rim, the paraboloid's rim (the
// discs meet), lat-long's seam under per-vertex interpolation (a triangle
// across it interpolates s the long way round: errors near 180 degrees).
TEST(EnvironmentMapping, ErrorsConcentrateWhereTheMapsAreWeak) {
  auto region = [](const std::string& k, const char* r) { return v("error_region_deg[" + k + "@" + r + "]"); };
  for (const char* o : {"sphere", "torus"}) {
    SCOPED_TRACE(o);
    EXPECT_GT(region(key("cube", o, "pixel"), "edge"), 3 * region(key("cube", o, "pixel"), "face"));
    for (const char* e : {"pixel", "vertex"}) {
      EXPECT_GT(region(key("sphere", o, e), "rim"), 2 * region(key("sphere", o, e), "centre")) << e;
      EXPECT_GT(region(key("paraboloid", o, e), "rim"), 2 * region(key("paraboloid", o, e), "centre")) << e;
    }
    EXPECT_GT(region(key("latlong", o, "vertex"), "seam"), 5 * region(key("latlong", o, "vertex"), "body"));
    EXPECT_GT(v("error_max_deg[" + key("latlong", o, "vertex") + "]"), 90);
  }
}

// How coarse the world is where the sphere reads it: the sphere map's rim
// texels are long and thin, lat-long's polar texels thin (all as long as a
// row is high, 180/h degrees), a cube face's centre texels larger than those
// at its edges.
TEST(EnvironmentMapping, TexelShapeWhereTheObjectReads) {
  auto ext = [](const std::string& k) { return v("texel_extent_deg[" + k + "]"); };
  auto asp = [](const std::string& k) { return v("texel_aspect[" + k + "]"); };
  EXPECT_GT(ext("sphere@rim"), 2 * ext("sphere@centre"));
  EXPECT_GT(asp("sphere@rim"), 2 * asp("sphere@centre"));
  EXPECT_GT(asp("latlong@pole"), 3 * asp("latlong@body"));
  const double rowDeg = 180.0 / envmap::mapSize(envmap::kLatLong, 64).h;
  for (const char* r : {"body", "pole", "seam"})
    EXPECT_NEAR(ext(std::string("latlong@") + r), rowDeg, 0.01 * rowDeg) << r;
  EXPECT_GT(ext("cube@face"), ext("cube@edge"));
}

// A sphere map made at yaw 0 and read from an eye turned by a: the error
// grows with a and never exceeds it (a rotation by a moves a direction by at
// most a), and is more than half of it.
TEST(EnvironmentMapping, StaleSphereMapErrorFollowsTheEye) {
  double last = -1;
  for (float a : envmap::kEyeAngles) {
    const double e = v("sphere_stale_error_deg[" + ts::layout::fmt("%.0f", a) + "]");
    EXPECT_GT(e, last) << a;
    EXPECT_LE(e, a + 0.1) << a;
    if (a > 0) EXPECT_GE(e, 0.5 * a) << a;
    last = e;
  }
}

// Seed 002's u = N_x/2 + 1/2 against GL_SPHERE_MAP: per pixel the two
// directions are as far apart as the pixel's line of sight is from the axis.
TEST(EnvironmentMapping, SeedSphereMapDriftsOffAxis) {
  for (size_t b = 0; b + 1 < envmap::kAxisBins.size(); ++b) {
    const std::string k = ts::layout::fmt("%g", envmap::kAxisBins[b]) + "-" +
                          ts::layout::fmt("%g", envmap::kAxisBins[b + 1]);
    SCOPED_TRACE(k);
    EXPECT_GE(v("seed_sphere_vs_gl_deg[" + k + "]"), envmap::kAxisBins[b] - 0.1);
    EXPECT_LE(v("seed_sphere_vs_gl_deg[" + k + "]"), envmap::kAxisBins[b + 1] + 0.1);
  }
}

// Seed 002's cube map R = 2 N_z N - I is the reflection where N.I = N_z: on
// the axis it agrees with r to the filter's noise, and it drifts further in
// every band further out.
TEST(EnvironmentMapping, SeedCubeFormulaDriftsOffAxis) {
  double last = -1;
  for (size_t b = 0; b + 1 < envmap::kAxisBins.size(); ++b) {
    const std::string k = ts::layout::fmt("%g", envmap::kAxisBins[b]) + "-" +
                          ts::layout::fmt("%g", envmap::kAxisBins[b + 1]);
    const double e = v("seed_cube_r_vs_gl_deg[" + k + "]");
    EXPECT_GT(e, last) << k;
    if (b == 0) EXPECT_LT(e, 0.05);
    last = e;
  }
  EXPECT_GT(last, 1.0);
}

// Texels per steradian, as printed: the analytic and numeric ratios agree,
// and order the maps: lat-long worst, then the cube, the paraboloid, the
// sphere map's (even) last.
TEST(EnvironmentMapping, SolidAngleUniformity) {
  for (const char* p : envmap::kParamKeys)
    EXPECT_NEAR(v(std::string("texel_solid_angle_ratio_numeric[") + p + "]") /
                    v(std::string("texel_solid_angle_ratio[") + p + "]"),
                1.0, 0.02)
        << p;
  EXPECT_GT(v("texel_solid_angle_ratio[latlong]"), v("texel_solid_angle_ratio[cube]"));
  EXPECT_GT(v("texel_solid_angle_ratio[cube]"), v("texel_solid_angle_ratio[paraboloid]"));
  EXPECT_GT(v("texel_solid_angle_ratio[paraboloid]"), v("texel_solid_angle_ratio[sphere]"));
}

// The flat mirror: a near ball appears in it; a map made at the mirror's
// centre (ball included) would show it at the right pixels and at many more
// (it is seen from 1.6 units, not from the mirrored eye), the direction it
// would have to be read at is degrees away from r.
TEST(EnvironmentMapping, FlatMirrorCannotReflectWhatIsNear) {
  EXPECT_GT(v("mirror_ball_pixels"), 100);
  EXPECT_GT(v("mirror_ball_pixels_centre_map"), 2 * v("mirror_ball_pixels"));
  EXPECT_GT(v("mirror_ball_error_mean_deg"), 1);
  // On the flat mirror per-vertex interpolation is nearly harmless for the
  // maps without a seam across it: r is almost linear over a plane.
  EXPECT_LT(v("error_mean_deg[" + key("cube", "mirror", "vertex") + "]"),
            v("error_mean_deg[" + key("cube", "sphere", "vertex") + "]") / 10);
}

// The fixed-function texgen computes what the shaders and environment_mapping_math.hpp say
// it does: on the flat mirror (r nearly linear across each triangle) the
// GL's GL_REFLECTION_MAP (through the texture matrix into the world) and
// GL_SPHERE_MAP per vertex land within a tenth of a degree of the GLSL
// reference, for every pixel on average and for the worst.
// Also from an orbited eye, where the view's rotation is not the identity
// (the texture matrix must turn eye space into the world's).
TEST(EnvironmentMapping, TexgenIsTheFormula) {
  const ts::Measurements orbited =
      Demo("environment_mapping", {"--object", "mirror", "--yaw", "30", "--pitch", "-20"}).measure();
  for (const char* p : {"cube", "sphere"}) {
    EXPECT_LT(v("error_mean_deg[" + key(p, "mirror", "vertex") + "]"), 0.1) << p;
    EXPECT_LT(v("error_max_deg[" + key(p, "mirror", "vertex") + "]"), 0.2) << p;
    EXPECT_LT(value(orbited, "error_mean_deg[" + key(p, "mirror", "vertex") + "]"), 0.1) << p;
    EXPECT_LT(value(orbited, "error_max_deg[" + key(p, "mirror", "vertex") + "]"), 0.2) << p;
  }
}

// The flat mirror's figure prints the near ball's pixels of the picture it
// shows: as many pixels of its reference picture are painted red as the
// caption prints, and the caption prints them as that measurement (its
// sidecar holds the same number); no caption is cut.
TEST(EnvironmentMapping, FlatMirrorPrintsItsOwnPicturesCount) {
  Demo d("environment_mapping", {"--object", "mirror", "--param", "latlong", "--eval", "vertex", "--render", "160"});
  const ts::Measurements m = d.measure();
  const ts::Frame f = d.frame(1080, 440);
  const ts::Image& ref = *f.textures.at(size_t(ts::test::panelOf(f, "reference").batches.front().texture)).image;
  int red = 0;
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) {
      const ts::Rgba c = ref.at(x, y);
      red += c.r == 230 && c.g == 40 && c.b == 40;
    }
  EXPECT_EQ(red, value(m, "mirror_ball_pixels[shown]"));
  EXPECT_GT(value(m, "mirror_ball_pixels_centre_map[shown]"), 2 * value(m, "mirror_ball_pixels[shown]"));
  EXPECT_LE(value(m, "mirror_ball_pixels_both[shown]"), value(m, "mirror_ball_pixels[shown]"));
  std::map<std::string, std::string> printed;  // measurement -> the text a label shows for it
  for (const ts::Label& l : f.labels) {
    EXPECT_EQ(l.text.find("..."), std::string::npos) << l.text;
    for (const ts::Label::Printed& p : l.printed) printed[p.name] = p.text;
  }
  for (const char* name :
       {"mirror_ball_pixels[shown]", "mirror_ball_pixels_centre_map[shown]", "error_mean_deg[shown]"}) {
    ASSERT_TRUE(printed.count(name)) << name;
    EXPECT_EQ(printed[name],
              ts::layout::measured(m, name, name == std::string("error_mean_deg[shown]") ? "%.2f" : "%.0f").text);
  }
  bool keyed = false;
  for (const ts::LegendEntry& e : f.legend)
    keyed |= e.color.r > 0.85f && e.color.g < 0.2f && e.meaning.find("ball") != std::string::npos;
  EXPECT_TRUE(keyed) << "the red ball has a key";
}

// The torus fits its pictures: in the comparison every picture's outermost
// rows and columns are background, so no side of the torus is cut.
TEST(EnvironmentMapping, CompareTorusShowsTheWholeTorus) {
  Demo d("environment_mapping",
         {"--view", "compare", "--object", "torus", "--eval", "vertex", "--tilt", "30", "--render", "96"});
  d.measure();
  const ts::Frame f = d.frame(1280, 360);
  const ts::Rgba bg = envmap::toRgba(envmap::kBackground);
  std::vector<std::string> ids(envmap::kParamKeys, envmap::kParamKeys + 4);
  ids.push_back("reference");
  for (const std::string& id : ids) {
    const ts::Image& img = *f.textures.at(size_t(ts::test::panelOf(f, id).batches.front().texture)).image;
    int covered = 0;
    auto at = [&](int x, int y) {
      const ts::Rgba c = img.at(x, y);
      covered += std::abs(c.r - bg.r) > 2 || std::abs(c.g - bg.g) > 2 || std::abs(c.b - bg.b) > 2;
    };
    for (int k = 0; k < img.width; ++k) at(k, 0), at(k, img.height - 1);
    for (int k = 0; k < img.height; ++k) at(0, k), at(img.width - 1, k);
    EXPECT_EQ(covered, 0) << id << ": the torus reaches the picture's edge";
  }
}

// Lat-long's seam per vertex, as computed and with the sources' +1 rule (a triangle whose corners' s differ by
// more than 1/2 adds 1 to the smaller, GL_REPEAT): the rule mends the seam, where the mean error falls more than
// tenfold (measured: 26.9 to 1.47 deg, 18x, on the figure's torus), but not the poles, where longitude means
// nothing and the error stays (measured: 15.0 to 13.3 deg, 9x the mended seam's).  The corners' (s, t) are
// computed on the CPU (the rule needs a triangle's three); as computed they must give the vertex shader's
// error in the same region against the same reference (float against double: 26.8961 against 26.8950).
TEST(EnvironmentMapping, PlusOneRuleMendsTheSeamNotThePoles) {
  glm::vec2 corners[3] = {{0.97f, 0.3f}, {0.02f, 0.3f}, {0.96f, 0.4f}};
  envmap::plusOneRule(corners);
  EXPECT_FLOAT_EQ(corners[0].x, 0.97f);
  EXPECT_FLOAT_EQ(corners[1].x, 1.02f);
  EXPECT_FLOAT_EQ(corners[2].x, 0.96f);

  Demo d("environment_mapping", {"--view", "seam", "--object", "torus", "--param", "latlong", "--eval", "vertex",
                                 "--tilt", "30", "--render", "96"});
  const ts::Measurements m = d.measure();
  const double seamNone = value(m, "latlong_seam_error_deg[none]"),
               seamFixed = value(m, "latlong_seam_error_deg[plus_one]"),
               poleNone = value(m, "latlong_pole_error_deg[none]"),
               poleFixed = value(m, "latlong_pole_error_deg[plus_one]");
  EXPECT_NEAR(seamNone, value(m, "error_region_deg[latlong/torus/vertex@seam]"), 0.01 * seamNone);
  EXPECT_NEAR(poleNone, value(m, "error_region_deg[latlong/torus/vertex@pole]"), 0.01 * poleNone);
  EXPECT_GT(seamNone, 10 * seamFixed) << "the +1 rule mends the seam";
  EXPECT_GT(poleFixed, 0.5 * poleNone) << "the rule does not mend the poles";
  EXPECT_GT(poleFixed, 5 * seamFixed) << "the poles' error stays well above the mended seam's";

  // The figure's labels print these four numbers from the measurement.
  const ts::Frame f = d.frame(1280, 440);
  std::set<std::string> printed;
  for (const ts::Label& l : f.labels)
    for (const ts::Label::Printed& p : l.printed) {
      EXPECT_EQ(ts::layout::measured(m, p.name, p.format.c_str()).text, p.text) << p.name;
      printed.insert(p.name);
    }
  for (const char* name : {"latlong_seam_error_deg[none]", "latlong_seam_error_deg[plus_one]",
                           "latlong_pole_error_deg[none]", "latlong_pole_error_deg[plus_one]"})
    EXPECT_TRUE(printed.count(name)) << name;

  // The key (u) draws the shown lat-long per vertex with the rule: its seam error is the rule's.
  Demo fixed("environment_mapping", {"--seam", "plus_one", "--object", "torus", "--param", "latlong", "--eval",
                                     "vertex", "--tilt", "30", "--render", "96"});
  const ts::Measurements mf = fixed.measure();
  EXPECT_NEAR(value(mf, "error_region_deg[latlong/torus/vertex@seam]"), value(mf, "latlong_seam_error_deg[plus_one]"),
              1e-9);
}

// The shown state's numbers are the table's, and the pictures are there.
TEST(EnvironmentMapping, ShownStateAndPictures) {
  Demo d("environment_mapping", {"--param", "sphere", "--eval", "vertex", "--object", "torus", "--render", "128"});
  ts::Measurements m = d.measure();
  EXPECT_NEAR(value(m, "error_mean_deg[shown]"), value(m, "error_mean_deg[sphere/torus/vertex]"),
              0.35 * value(m, "error_mean_deg[sphere/torus/vertex]"));
  for (const char* view : {"object", "map", "compare", "seam"}) {
    Demo s("environment_mapping", {"--view", view, "--render", "96"});
    s.measure();
    ts::Frame f = s.frame(900, 400);
    EXPECT_GE(f.panels.size(), 2u) << view;
  }
}

// A window's measurement comes in stages (ts::measureStage, only on the
// window's worker): the pictures first, numbers "(measuring)"; then, for
// every view but the map's, its whole picture before the seeds' studies
// (which only the map view's notes print) are measured.  The second stage's
// labels are the result's; the first's, the control, are not.
TEST(Stage, TheObjectViewsSecondStageIsItsWholePicture) {
  Demo staged("environment_mapping", {"--view", "object"});
  const std::vector<ts::Measurements> stages = ts::test::measureInStages(staged);
  ASSERT_EQ(stages.size(), 2u);
  auto texts = [&](const ts::Measurements& m) {
    staged.measured = m;
    std::vector<std::string> t;
    for (const ts::Label& l : staged.frame(1080, 440).labels) t.push_back(l.text);
    return t;
  };
  const ts::Measurements whole = staged.measured;
  EXPECT_EQ(texts(stages[1]), texts(whole));
  EXPECT_LT(stages[1].size(), whole.size());  // the studies follow, in the panel
  EXPECT_NE(texts(stages[0]), texts(whole));
}
}  // namespace

namespace {
// The lat-long and the cube map figures are siblings: the map at the same
// place and height, titles and captions at the same heights and scale, the
// picture beside it in the same place; each prints its claim's numbers
// (texel shape and solid-angle ratio) from their measurements.  The object
// view keys the world's colours by direction.
TEST(EnvironmentMapping, MapFiguresShareTheirLayoutAndPrintTheirClaims) {
  struct Seen {
    ts::Rect map, picture;
    std::vector<std::pair<float, int>> rows;  // each label's y and scale
    std::set<std::string> printed;
  };
  std::map<std::string, Seen> seen;
  for (const char* param : {"latlong", "cube"}) {
    Demo d("environment_mapping", {"--view", "map", "--param", param, "--object", "mirror"});
    d.measure();
    const ts::Frame f = d.frame(1080, 440);
    Seen& s = seen[param];
    for (const ts::Panel& p : f.panels) {
      if (p.id == "map") s.map = p.viewport;
      if (p.id == "picture") s.picture = p.viewport;
    }
    for (const ts::Label& l : f.labels) {
      s.rows.push_back({l.y, l.scale});
      for (const ts::Label::Printed& p : l.printed) {
        EXPECT_EQ(ts::layout::measured(d.measured, p.name, p.format.c_str()).text, p.text) << p.name;
        s.printed.insert(p.name);
      }
    }
    std::sort(s.rows.begin(), s.rows.end());
    s.rows.erase(std::unique(s.rows.begin(), s.rows.end()), s.rows.end());
  }
  const Seen &ll = seen["latlong"], &cube = seen["cube"];
  EXPECT_EQ(ll.map.y, cube.map.y);
  EXPECT_EQ(ll.map.h, cube.map.h);
  EXPECT_GT(ll.map.w, cube.map.w);  // 2:1 against 3:2, as tall
  EXPECT_EQ(ll.picture.x, cube.picture.x);
  EXPECT_EQ(ll.picture.y, cube.picture.y);
  EXPECT_EQ(ll.picture.w, cube.picture.w);
  EXPECT_EQ(ll.rows, cube.rows);
  for (const char* name :
       {"texel_aspect[latlong@pole]", "texel_aspect[latlong@body]", "texel_solid_angle_ratio[latlong]"})
    EXPECT_TRUE(ll.printed.count(name)) << name;
  for (const char* name :
       {"texel_aspect[cube@face]", "texel_solid_angle_ratio[cube]", "texel_solid_angle_ratio[latlong]"})
    EXPECT_TRUE(cube.printed.count(name)) << name;

  Demo d("environment_mapping", {"--eval", "vertex"});
  d.measured = measured("sphere");
  const ts::Frame f = d.frame(1080, 440);
  std::set<std::string> keyed;
  for (const ts::LegendEntry& e : f.legend) keyed.insert(e.meaning);
  for (const char* meaning : {"toward +X", "toward +Y", "toward +Z", "equator, meridian through -Z"})
    EXPECT_TRUE(keyed.count(meaning)) << meaning;
}
}  // namespace
