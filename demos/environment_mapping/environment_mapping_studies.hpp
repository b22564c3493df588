// demos/environment_mapping/environment_mapping_studies.hpp — the environment mapping demo's
// measurements beyond the error table: seed 001's cube example read back from
// the GL, a sphere map reused as the eye moves, seed 002's sphere-map formula
// against GL_SPHERE_MAP off the view axis, and the flat mirror that cannot
// reflect a nearby object; and addStudies, which prints them all.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <utility>
#include <vector>

#include "common/core/kept.hpp"
#include "common/core/layout.hpp"
#include "common/gl/gl_listing.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/core/scene.hpp"
#include "environment_mapping_gl.hpp"
#include "environment_mapping_measure.hpp"
#include "environment_mapping_math.hpp"

namespace envmap {
using envmap::dvec3;

// ---- seed 001's worked example -------------------------------------------
// r = (-3.2, 5.1, -8.4): the face and (s, t) from the spec's table, the
// seed's (s, t) (its faces are mirrored in both axes: sc = +r_x, tc = +r_y on
// -Z where the GL has -r_x, -r_y), and what a GL_NEAREST lookup of r in an
// n x n texel-index cube map returned.
inline const dvec3 kSeedDirection{-3.2, 5.1, -8.4};
struct SeedCube {
  envmap::CubeST gl, seed;
  glm::ivec3 readBack{-1};  // (i, j, face) the GL's texel
  int n = 1000;
};
inline SeedCube seedCube(envmap::EnvGL& g) {
  SeedCube c;
  c.gl = envmap::cubeST(kSeedDirection);
  c.seed = envmap::seedCubeST(kSeedDirection);
  c.readBack = g.cubeTexelOf(kSeedDirection, c.n);
  return c;
}

// ---- the camera every pass uses -------------------------------------------
// The eye on +Z at distance 5 looking at the object (at the world's origin),
// a 30° field of view; `yawDeg`/`pitchDeg` orbit it (common/core/orbit_camera.hpp's
// convention: the world turns in front of the eye).
constexpr float kEyeDistance = 5.0f, kFovDeg = 30.0f;
inline glm::mat4 viewMatrix(float yawDeg, float pitchDeg) {
  ts::OrbitCamera c;
  c.yaw = yawDeg, c.pitch = pitchDeg;
  return c.view(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -kEyeDistance)), glm::vec3(0.0f));
}
inline glm::mat4 projectionMatrix(float zoom) {
  ts::OrbitCamera c;
  c.zoom = zoom;
  return c.lens(glm::perspective(glm::radians(kFovDeg), 1.0f, 1.0f, 20.0f));
}

// The lens each object is seen through, as a zoom: the torus (outer radius
// 1.4) is wider than the 30° view at the eye's distance (5 tan 15° = 1.34
// units each side of its centre), so its passes zoom out to 0.8 (1.67 units)
// and its sides stay in the picture; the sphere and the mirror fit at 1.
inline float objectLens(int object) { return object == envmap::kTorus ? 0.8f : 1.0f; }

// ---- view dependence -----------------------------------------------------
// A sphere map made for the eye at yaw 0 read by the sphere from an eye
// turned by each angle (per pixel, so only the stale view is measured): the
// mean direction error against the reference.
inline const std::array<float, 6> kEyeAngles{0, 5, 10, 20, 40, 80};
inline std::vector<double> viewDependence(envmap::EnvGL& g, int faceTexels) {
  std::vector<double> out;
  for (float a : kEyeAngles) {
    envmap::Pass p;
    p.view = viewMatrix(a, 0), p.projection = projectionMatrix(1), p.faceTexels = faceTexels;
    p.sphereView = glm::dmat3(glm::mat3(viewMatrix(0, 0)));
    const envmap::Pixels ref = g.draw(p);
    p.param = envmap::kSphere;
    out.push_back(envmap::errorStats(p.param, g.draw(p), ref, p.eyeRotation()).mean);
  }
  return out;
}

// ---- seed 002's formulas against the GL's ----------------------------------
// Per pixel on the sphere: the direction a map returns for seed 002's formula
// against the one it returns for the GL's, binned by the angle between the
// pixel's line of sight and the view axis.
//   sphere map: u = N_x/2 + 1/2, v = N_y/2 + 1/2 against GL_SPHERE_MAP's (s,t).
//     On the axis they agree (I = (0,0,-1) there, and then s = r_x/m + 1/2 =
//     N_x/2 + 1/2); elsewhere the seed ignores where the eye is, and the
//     two reflections are as far apart as the two lines of sight.
//   cube map: R = 2 N_z N - I against r = 2 (N.I) N - I (I to the eye): equal
//     where N.I = N_z, on the axis; apart elsewhere.
inline const std::array<double, 6> kAxisBins{0, 0.5, 2, 5, 8, 12};
struct SeedVsGl {
  std::array<double, 5> meanDeg{}, maxDeg{};
  std::array<int, 5> pixels{};
};
inline SeedVsGl seedVsGl(envmap::EnvGL& g, int faceTexels, int glParam, int seedParam) {
  envmap::Pass p;
  p.view = viewMatrix(0, 0), p.projection = projectionMatrix(1), p.faceTexels = faceTexels;
  p.sphereView = glm::dmat3(glm::mat3(p.view));
  p.param = glParam;
  const envmap::Pixels gl = g.draw(p);
  p.param = seedParam;
  const envmap::Pixels seed = g.draw(p);
  const glm::mat4 inv = glm::inverse(p.projection);
  SeedVsGl s;
  for (int y = 0; y < gl.h; ++y)
    for (int x = 0; x < gl.w; ++x) {
      if (gl.at(x, y).a < 0.5f || seed.at(x, y).a < 0.5f) continue;
      const glm::vec4 q = inv * glm::vec4(2 * (x + 0.5f) / gl.w - 1, 2 * (y + 0.5f) / gl.h - 1, -1, 1);
      const double off = envmap::angleDeg(glm::dvec3(q) / double(q.w), dvec3(0, 0, -1));
      const double e = envmap::angleDeg(gl.direction(x, y), seed.direction(x, y));
      for (size_t b = 0; b + 1 < kAxisBins.size(); ++b)
        if (off >= kAxisBins[b] && off < kAxisBins[b + 1]) {
          s.meanDeg[b] += e, s.maxDeg[b] = std::max(s.maxDeg[b], e), ++s.pixels[b];
        }
    }
  for (size_t b = 0; b < s.pixels.size(); ++b)
    if (s.pixels[b]) s.meanDeg[b] /= s.pixels[b];
  return s;
}

// ---- the flat mirror and a nearby ball ----------------------------------
// An environment map is the world seen from one point, the object's centre
// O: it holds directions only, as if everything were infinitely far.  A ball
// near the mirror (centre kBall, radius kBallRadius: on the reflection of the
// line of sight through the mirror's centre at the default view, 1.6 units
// out, r0 = (0, 0.940, 0.342) for the 35° lean) is seen in a true mirror
// from each mirror point P along r; a map made at O (even one that has the
// ball in it) shows what is along r from O.  Per mirror pixel of the
// reference read-back: P from the pixel's line of sight and the mirror's
// plane, r read back; the ball's pixels in the true mirror and in the map,
// and for the true ones the angle between r and the direction from O to the
// ball point the mirror shows there (what the map would have to be read at).
inline const dvec3 kBall{0.25, 1.5, 0.55};
constexpr double kBallRadius = 0.35;
inline bool hitsBall(dvec3 from, dvec3 dir, dvec3* hit) {
  const dvec3 oc = from - kBall;
  const double b = glm::dot(oc, dir), c = glm::dot(oc, oc) - kBallRadius * kBallRadius, disc = b * b - c;
  if (disc < 0) return false;
  const double t = -b - std::sqrt(disc);
  if (t <= 0) return false;
  if (hit) *hit = from + t * dir;
  return true;
}
struct Mirror {
  int truePixels = 0, mapPixels = 0, both = 0;
  double meanDeg = 0, maxDeg = 0;
  std::vector<char> trueMask;  // per read-back pixel (GL order): the ball in the true mirror
};
inline Mirror mirrorNear(const envmap::Pixels& ref, const glm::mat4& projection, const glm::mat4& view,
                         const glm::mat4& model) {
  Mirror m;
  m.trueMask.assign(size_t(ref.w) * size_t(ref.h), 0);
  const glm::dmat4 toWorld = glm::inverse(glm::dmat4(view)), invP = glm::inverse(glm::dmat4(projection));
  const dvec3 eye(toWorld * glm::dvec4(0, 0, 0, 1));
  const double a = envmap::rad(envmap::kMirrorTiltDeg);
  const dvec3 n = glm::normalize(glm::dmat3(glm::dmat4(model)) * dvec3(0, std::sin(a), std::cos(a))), o(0.0);
  for (int y = 0; y < ref.h; ++y)
    for (int x = 0; x < ref.w; ++x) {
      if (ref.at(x, y).a < 0.5f) continue;
      const glm::dvec4 q = invP * glm::dvec4(2 * (x + 0.5) / ref.w - 1, 2 * (y + 0.5) / ref.h - 1, -1, 1);
      const dvec3 d = glm::normalize(glm::dmat3(toWorld) * (dvec3(q) / q.w));
      const dvec3 P = eye + (glm::dot(o - eye, n) / glm::dot(d, n)) * d, r = ref.direction(x, y);
      dvec3 hit;
      const bool truly = hitsBall(P, r, &hit), inMap = hitsBall(o, r, nullptr);
      m.truePixels += truly, m.mapPixels += inMap, m.both += truly && inMap;
      if (truly) {
        m.trueMask[size_t(y) * size_t(ref.w) + size_t(x)] = 1;
        const double e = envmap::angleDeg(r, hit - o);
        m.meanDeg += e, m.maxDeg = std::max(m.maxDeg, e);
      }
    }
  if (m.truePixels) m.meanDeg /= m.truePixels;
  return m;
}

// envmap::uniformity (pure arithmetic: 36 cells of two spherical triangles a
// texel) made once per process for each (parameterization, face size):
// every figure prints the same four, and it was a fifth of the demo's time.
inline envmap::Uniformity keptUniformity(envmap::Param p, int face) {
  static ts::Kept<std::pair<int, int>, envmap::Uniformity> kept(4 * envmap::kParams);
  return kept.get({int(p), face}, [&] { return envmap::uniformity(p, face); });
}

// ---- all of the above, as the demo prints them -----------------------------
inline void addStudies(envmap::EnvGL& g, int face, ts::Measurements& out) {
  {  // the flat mirror in the default view, at the measuring size (Pass: 256 x 256; a figure's own picture
     // counts its pixels as mirror_ball_pixels*[shown])
    envmap::Pass ps;
    ps.object = envmap::kMirror, ps.view = viewMatrix(0, 0), ps.projection = projectionMatrix(1);
    const Mirror m = mirrorNear(g.draw(ps), ps.projection, ps.view, ps.model);
    out.push_back({"mirror_ball_pixels", double(m.truePixels),
                   "mirror pixels that show the near ball in a true mirror (the default view, 256 x 256)"});
    out.push_back({"mirror_ball_pixels_centre_map", double(m.mapPixels),
                   "pixels a map made at the mirror's centre, ball included, shows it at"});
    out.push_back(
        {"mirror_ball_pixels_both", double(m.both), "pixels where the true mirror and that map both show it"});
    out.push_back({"mirror_ball_error_mean_deg", m.meanDeg,
                   "mean angle between r and the direction from the centre to the ball point shown"});
    out.push_back({"mirror_ball_error_max_deg", m.maxDeg, "largest such angle, degrees"});
  }
  // Seed 001's cube example: the spec's table, the seed's mirrored faces, the GL.
  const SeedCube c = seedCube(g);
  out.push_back({"seed_cube_face", double(c.gl.face), "face of (-3.2, 5.1, -8.4) by the spec's table (5 = -Z)"});
  out.push_back({"seed_cube_gl_s", c.gl.s, "s by the spec's table"});
  out.push_back({"seed_cube_gl_t", c.gl.t, "t by the spec's table"});
  out.push_back({"seed_cube_seed_s", c.seed.s, "s as seed 001 computes it (sc = +r_x: the face mirrored)"});
  out.push_back({"seed_cube_seed_t", c.seed.t, "t as seed 001 computes it (tc = +r_y)"});
  out.push_back({"seed_cube_readback_face", double(c.readBack.z), "the face the GL's lookup read"});
  out.push_back(
      {"seed_cube_readback_s", (c.readBack.x + 0.5) / c.n, "the GL's texel centre s (1000 x 1000 faces, GL_NEAREST)"});
  out.push_back({"seed_cube_readback_t", (c.readBack.y + 0.5) / c.n, "the GL's texel centre t"});
  // Texels per steradian at equal memory.
  for (int p = 0; p < envmap::kParams; ++p) {
    const envmap::Uniformity u = keptUniformity(envmap::Param(p), face);
    const std::string k = envmap::kParamKeys[p];
    out.push_back(
        {"texel_solid_angle_ratio[" + k + "]", u.analyticRatio(), "largest / smallest texel solid angle, analytic"});
    out.push_back({"texel_solid_angle_ratio_numeric[" + k + "]", u.numericRatio(), "the same by numeric integration"});
    out.push_back({"texel_solid_angle_reldiff[" + k + "]", u.largestRelDiff,
                   "largest |numeric - analytic| / analytic of a texel"});
  }
  ts::measureProgress(0.8);
  const std::vector<double> vd = viewDependence(g, face);
  for (size_t k = 0; k < vd.size(); ++k)
    out.push_back({"sphere_stale_error_deg[" + ts::layout::fmt("%.0f", kEyeAngles[k]) + "]", vd[k],
                   "sphere map made at yaw 0, eye at this yaw: mean error on the sphere, degrees"});
  const SeedVsGl ss = seedVsGl(g, face, envmap::kSphere, envmap::kSeedSphere),
                 sc = seedVsGl(g, face, envmap::kCube, envmap::kSeedCube);
  for (size_t b = 0; b + 1 < kAxisBins.size(); ++b) {
    const std::string k = ts::layout::fmt("%g", kAxisBins[b]) + "-" + ts::layout::fmt("%g", kAxisBins[b + 1]);
    out.push_back({"seed_sphere_vs_gl_deg[" + k + "]", ss.meanDeg[b],
                   "seed 002's (N_x/2 + 1/2) against GL_SPHERE_MAP: mean angle, pixels this far off the view axis"});
    out.push_back({"seed_sphere_vs_gl_max_deg[" + k + "]", ss.maxDeg[b], "the same, largest"});
    out.push_back({"seed_cube_r_vs_gl_deg[" + k + "]", sc.meanDeg[b],
                   "seed 002's R = 2 N_z N - I against r = 2 (N.I) N - I on the cube map: mean angle"});
  }
}

// What the demo's measure() found: the numbers for the captions and the pictures.
struct Found {
  ErrorStats current;                 // the shown state
  std::array<ErrorStats, 4> compare;  // each parameterization, this object and evaluation
  // The pictures of the object: nested frames (environment_mapping_views.hpp),
  // their GL calls recorded (renderedBy); the
  // flat mirror's reference is an image (the near ball is painted on it), as are the error and the map.
  ts::TextureDesc picture, reference;       // object view, map view
  std::array<ts::TextureDesc, 4> pictures;  // compare view
  ts::Image error;
  ts::TextureDesc map;  // the map unwrapped (a generator), and the texels the object reads
  LitTexels lit;
  Mirror mirror;
  double errorScale = 1;  // degrees shown yellow in the error picture
  // seam view: lat-long per vertex without and with the +1 rule, and their errors, both on the scale of the
  // first's (the seam's tear white, the rest of the torus dark: what the rule mends stands out)
  std::array<ts::TextureDesc, 2> seamPictures;
  std::array<ts::Image, 2> seamErrors;
  double seamScale = 1;
};
}  // namespace envmap
