// The limits of bump mapping, and their remedies (seed 001 on bump mapping; Rogers, seed 004, after Blinn).
//
// Bump mapping perturbs the normal and nothing else: the surface stays flat, so the bumps cast no shadows on
// themselves; the normal is taken from the texture's axes, so a sheared or stretched parameterisation tilts it
// wrongly unless the method keeps the axes; and the bumps are texture detail, so far away they alias like any
// texture, while averaging the heights (mipmapping) smooths the bumps away.  Three views, each with its remedy:
//
// The self-shadowing claim (view shadows): on a plane bumped by an analytic height field lit at a low angle,
// plain bump mapping lights every pixel facing the light, also where the displaced surface's own bumps hide it
// (bump_self_shadow_px[none], pixels against a ray march of the displaced heights on the CPU).  Horizon mapping
// stores, per texel, the horizon's elevation in 8 directions; a pixel is dark when the light's elevation is below
// the horizon interpolated at its azimuth: it leaves far fewer such pixels (bump_self_shadow_px[horizon]).
//
// The same on bump_mapping's two-light torus (view torus): the bumps displace the torus along its normal; plain
// bump mapping lights pixels the displaced torus shadows from a light their bumped normal faces
// (bump_self_shadow_torus_px[none], against shadow rays traced on the CPU from the displaced point at each pixel's
// (s, t), read back from GL); a horizon map per texel (8 azimuths in the tangent frame, the near bumps along the
// surface and the ring across the hole), looked up for both lights, leaves far fewer
// (bump_self_shadow_torus_px[horizon]); looked up a quarter turn off, or made of the smooth torus, it leaves many.
// Beside it a polynomial texture map (6 coefficients a texel, fitted to the horizon-shadowed diffuse term over
// light directions): its fit's error (bump_ptm_fit_rms_levels) and each picture's RMS against the traced one.
//
// The representations' claim (view methods): Blinn's formula from the heights, a normal map and an offset-vector
// map (bu, bv along two vectors perpendicular to n, seed 001) each give a normal within a measured angle of the
// displaced surface's (bump_normal_error_deg[*]).  With the parameterisation sheared (dp/ds and dp/dt at theta, keys
// + / -) a method that assumes them orthogonal is off by an angle that grows as theta falls from 90 degrees
// (bump_shear_error_deg[90|75|60|45]), and so is it when the texture is not square on the surface
// (bump_stretch_error_deg[orthogonal]); Blinn's formula carries both.  Shading baked into a texture for a static
// light is exact for that light (0 levels) and off by a measured RMS once the light moves.
//
// The distance claim (view distance): at 1x, 2x, 4x, 8x distance the bumped plane shaded once a pixel aliases (RMS
// against an 8 x 8 supersampled reference grows); mipmapped heights do not alias but lose the bumps' tilt
// (bump_tilt_lost_deg[mipmapped]); Blinn's answer, shading at 4 x 4 the resolution and box-filtering down, is
// close to the reference at every distance (bump_distance_rms_levels[super4x4]).
//
// Keys (each is also a flag, see --help):
//   v      view: shadows | methods | distance | torus
//   e / E  the light's elevation, degrees (shadows)        . / ,  its azimuth, degrees (shadows)
//   + / -  the shear angle theta between dp/ds and dp/dt   d      distance: 1 | 2 | 4 | 8 (distance)
//
// The equations (bump_limits_math.hpp; z = kHeightMax h, texel units, L the light's unit vector):
//   n = normalize(-dz/dx, -dz/dy, 1)                                         the displaced plane's normal
//   H_k(p) = max_s atan((z(p + s d_k) - z(p)) / s),  d_k at k x 45 degrees    the horizon map, k = 0..7
//   lit(p) = elevation(L) > (1 - a) H_k0(p) + a H_k0+1(p),  k0 + a = azimuth(L) / 45 degrees
//   shadowed(p) = exists s: z(p + s L_xy) > z(p) + s tan(elevation(L))       the CPU's ray march, the reference
//   n' = n + bu e1 + bv e2,  e1, e2 perpendicular to n                       the offset-vector map
//   true normal, sheared: (Ps + z_s n) x (Pt + z_t n),  Ps . Pt = cos theta; orthogonal method: (-z_s, -z_t, 1)
//   c = A + (1 - A) max(n . L, 0) lit                                        the shading, grey, A = 0.1 ambient
//   torus (bump_limits_torus.hpp): n' = normalize(N - P_s/|Q_s| T - P_t/|Q_t| B),  c = A + sum_i I_i max(n'.L_i, 0)
//   lit_i, the light's azimuth and elevation taken in (T, B, N); the reference: X = Q + P N, shadowed by light i
//   when X + sigma L_i is inside the displaced torus (rho < r + P(theta, phi)) for some sigma > 0
//
// What the GL does (bump_limits_gl.hpp, passes of measure() read back and shown as pictures):
//   glUseProgram(p);  the fragment shader: central differences of texture2D(heights, st +- step), the normal and
//   offset maps, the horizon maps on units 2 and 3 (GL_LINEAR, GL_REPEAT), the light as uniforms
//   glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, ...) each level, GL_LINEAR_MIPMAP_LINEAR   the mipmapped heights
//   the baked shading: the shader's picture read back and drawn with glTexEnvi(GL_TEXTURE_ENV,
//   GL_TEXTURE_ENV_MODE, GL_REPLACE), GL_NEAREST, one pixel a texel, no shader
// Listings: book_figures/bump_limits_shadows.gl.txt, bump_limits_methods.gl.txt, bump_limits_distance.gl.txt,
// bump_self_shadow_torus.gl.txt.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "bump_limits_views.hpp"
#include "common/core/layout.hpp"
#include "common/core/scene.hpp"

namespace {
namespace L = ts::layout;
using namespace bumplim;

class BumpLimits final : public ts::Scene {
 public:
  std::string id() const override { return "bump_limits"; }
  std::string title() const override { return "The limits of bump mapping: shadows, representations, distance"; }
  std::string about() const override {
    return "A plane bumped by an analytic height field.  Shadows: plain bump mapping and horizon mapping (8\n"
           "directions) against the displaced surface's shadows ray-marched on the CPU.  Methods: Blinn's formula,\n"
           "a normal map and an offset-vector map against the exact normal; a sheared parameterisation; shading\n"
           "baked for one light.  Distance: the bumps at 1x-8x unfiltered, mipmapped and 4x4 supersampled against\n"
           "an 8x8 supersampled reference.  Torus: the same self-shadowing on bump_mapping's two-light torus, the\n"
           "displaced torus's shadows traced on the CPU, a horizon map looked up for both lights.";
  }
  std::vector<std::string> claim() const override {
    if (view_ == 1) return {"bump_normal_error_deg*", "bump_shear_error_deg*", "bump_baked*"};
    if (view_ == 2) return {"bump_distance_rms_levels*", "bump_tilt_lost_deg*"};
    if (view_ == 3) return {"bump_self_shadow_torus_px*"};
    return {"bump_self_shadow_px*"};
  }
  void addOptions(ts::Options& o) override {
    o.addEnum("view", &view_, {"shadows", "methods", "distance", "torus"},
              "self-shadowing and horizon maps | normal maps, offset maps, shear, baking | bumps at a distance | "
              "self-shadowing on the two-light torus",
              'v');
    o.addInt("elevation", &elevation_, 5, 60, "the light's elevation above the plane, degrees (shadows)", 'E', 'e', 5);
    o.addInt("azimuth", &azimuth_, 0, 345, "the light's azimuth, degrees from +x (shadows)", '.', ',', 15);
    o.addInt("shear", &shear_, 15, 90, "degrees between dp/ds and dp/dt (methods)", '+', '-', 15);
    o.addEnum("distance", &distance_, {"1", "2", "4", "8"}, "the plane's distance, 1x = 2 pixels a texel (distance)",
              'd');
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"bump_limits_shadows",
         "Bump mapping's limits: self-shadowing (seed 001)",
         "A plane bumped by a height field, lit from 20 degrees above it: plain bump mapping lights every pixel "
         "facing the light; horizon mapping darkens the pixels whose horizon, stored for 8 directions a texel, is "
         "above the light; the displaced surface's shadows ray-marched on the CPU; where horizon mapping differs.",
         {"--view", "shadows"},
         1000,
         460,
         "Shadowed pixels plain bump mapping lights: {bump_self_shadow_px[none]}; horizon mapping: "
         "{bump_self_shadow_px[horizon]}."},
        {"bump_limits_methods",
         "Bump mapping's limits: representations, shear, baking (seed 001)",
         "Blinn's formula, a normal map and an offset-vector map shaded by the same light, each normal measured "
         "against the displaced surface's; shading baked for one light and that light moved; the normal error of a "
         "method that assumes "
         "dp/ds and dp/dt orthogonal when they are not.",
         {"--view", "methods", "--shear", "60"},
         1000,
         640,
         "Normal error: Blinn {bump_normal_error_deg[blinn]}, normal map {bump_normal_error_deg[normalmap]}, offset "
         "map {bump_normal_error_deg[offset]} degrees; orthogonal axes at 45 degrees shear: "
         "{bump_shear_error_deg[45]} degrees."},
        {"bump_limits_distance",
         "Bump mapping's limits: bumps at a distance (Rogers, after Blinn)",
         "The bumped plane at 8x distance (4 texels a pixel): shaded once a pixel it aliases; with mipmapped "
         "heights it is smooth but the bumps' tilt is gone; rendered at 4 x 4 the resolution and box-filtered down "
         "it is close to the 8 x 8 supersampled reference.",
         {"--view", "distance", "--distance", "8"},
         1000,
         480,
         "RMS at 8x: unfiltered {bump_distance_rms_levels[unfiltered][8x]}, mipmapped "
         "{bump_distance_rms_levels[mipmapped][8x]}, 4x4 {bump_distance_rms_levels[super4x4][8x]} levels."},
        {"bump_self_shadow_torus",
         "Bump mapping's limits: self-shadowing on the two-light torus (seed 001)",
         "The bumped torus of bump_mapping under its two lights: plain bump mapping lights pixels the displaced "
         "torus shadows; horizon mapping (8 azimuths a texel, looked up for both lights) darkens them; the displaced "
         "torus's shadows traced on the CPU from each pixel's (s, t); where horizon mapping differs.",
         {"--view", "torus"},
         1000,
         480,
         "Shadowed pixels plain bump mapping lights: {bump_self_shadow_torus_px[none]}; horizon mapping: "
         "{bump_self_shadow_torus_px[horizon]}."}};
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override {
    ts::Measurements out;
    Pictures pic;
    pic.view = view_;
    if (view_ == 0) measureShadows(r, azimuth_, elevation_, out, pic);
    if (view_ == 1) measureMethods(r, shear_, out, pic);
    if (view_ == 2) measureDistance(r, kDistances[distance_], out, pic);
    if (view_ == 3) measureTorus(r, out, pic);
    out.detail = pic;
    return out;
  }

 private:
  int view_ = 0, elevation_ = 20, azimuth_ = 30, shear_ = 60, distance_ = 3;
};

ts::Frame BumpLimits::build(int width, int height, const ts::Measurements& measured) const {
  ts::Frame f = L::blankFrame(width, height);
  const Pictures* p = measured.detailAs<Pictures>();
  if (!p || p->view != view_ || p->shown.empty()) {  // the view's measurement is still to come
    L::caption(f, {8, 8, float(width - 8), float(height - 8)}, "rendering ...", L::kWhite, 2);
    return f;
  }
  auto M = [&](const std::string& t) { return L::measuredText(measured, t); };
  auto G = [](const std::string& what, double v) { return L::given(what, v, "%.0f"); };
  const auto& s = p->shown;
  if (view_ == 0) {
    const L::Text light = "light " + G("the light's elevation, degrees", elevation_) + " deg up, azimuth " +
                          G("the light's azimuth, degrees", azimuth_) + " deg";
    pictureRow(f,
               {{&s[0], "plain bump mapping", M("{bump_self_shadow_px[none]|%.0f} shadowed px lit")},
                {&s[1], "horizon mapping, " + G("directions of the horizon map", kDirections) + " directions",
                 M("{bump_self_shadow_px[horizon]|%.0f} shadowed px lit")},
                {&s[2], "ray-marched shadows (CPU)", M("{bump_shadowed_px|%.0f} px in shadow")},
                {&s[3], "horizon map against the ray march",
                 M("{bump_self_shadow_px[horizon]|%.0f} red, {bump_self_shadow_px[horizon_extra]|%.0f} blue")}},
               {{kMissed, "in the ray march's shadow, lit by horizon mapping"},
                {kExtra, "darkened by horizon mapping, lit in the ray march"},
                {kLitBoth, "lit in both"},
                {kDarkBoth, "dark in both (shadowed, or facing away)"}},
               {light +
                    M(": of {bump_shadowed_px|%.0f} pixels the displaced surface shadows, plain bump mapping lights "
                      "{bump_self_shadow_px[none]|%.0f}, horizon mapping {bump_self_shadow_px[horizon]|%.0f} "
                      "(and darkens {bump_self_shadow_px[horizon_extra]|%.0f} more)."),
                M("Control: the horizon looked up a quarter turn from the light lights "
                  "{bump_self_shadow_px[horizon_wrong_azimuth]|%.0f} of the shadowed pixels.")});
  } else if (view_ == 3) {
    pictureRow(f,
               {{&s[0], "plain bump mapping", M("{bump_self_shadow_torus_px[none]|%.0f} shadowed px lit")},
                {&s[1], "horizon map, " + G("directions of the horizon map", kDirections) + " azimuths",
                 M("{bump_self_shadow_torus_px[horizon]|%.0f} shadowed px lit")},
                {&s[2], "traced (CPU)", M("{bump_torus_shadowed_px|%.0f} px shadowed")},
                {&s[3], "horizon map vs trace",
                 M("{bump_self_shadow_torus_px[horizon]|%.0f} red, {bump_self_shadow_torus_px[horizon_extra]|%.0f} "
                   "blue")},
                {&s[4], "polynomial texture map", M("RMS {bump_shadow_torus_rms_levels[ptm]|%.1f} levels")}},
               {{kMissed, "shadowed in the trace, lit by the horizon map"},
                {kExtra, "darkened by the horizon map, lit in the trace"},
                {kLitBoth, "lit in both"},
                {kDarkBoth, "dark in both"}},
               {M("Of {bump_torus_shadowed_px|%.0f} torus pixels the displaced torus shadows, plain bump mapping "
                  "lights {bump_self_shadow_torus_px[none]|%.0f} from the shadowing light, the horizon map "
                  "{bump_self_shadow_torus_px[horizon]|%.0f} (and darkens "
                  "{bump_self_shadow_torus_px[horizon_extra]|%.0f} more)."),
                M("Controls: the horizon a quarter turn off the light "
                  "{bump_self_shadow_torus_px[horizon_wrong_azimuth]|%.0f}; the smooth torus's horizon "
                  "{bump_self_shadow_torus_px[horizon_smooth]|%.0f}."),
                M("RMS against the trace: plain {bump_shadow_torus_rms_levels[none]|%.1f}, horizon "
                  "{bump_shadow_torus_rms_levels[horizon]|%.1f}, PTM {bump_shadow_torus_rms_levels[ptm]|%.1f} levels; "
                  "the PTM's fit {bump_ptm_fit_rms_levels|%.1f} ({bump_ptm_fit_rms_levels[unshadowed]|%.1f} "
                  "unshadowed).")});
  } else if (view_ == 1) {
    L::Text table = "orthogonal-axes method's normal error against shear: ";
    for (double th : kThetas) {
      char k[64];
      std::snprintf(k, sizeof k, "{bump_shear_error_deg[%.0f]|%%.2f}", th);
      table = table + G("a shear angle of the table, degrees", th) + " deg " + M(k) + (th > 45 ? ", " : " degrees.");
    }
    const ts::plot::Spec plot = shearPlot(measured, shear_);
    pictureRow(f,
               {{&s[0], "Blinn (heights)", M("{bump_normal_error_deg[blinn]|%.2f} deg off")},
                {&s[1], "normal map", M("{bump_normal_error_deg[normalmap]|%.2f} deg off")},
                {&s[2], "offset-vector map (bu, bv)", M("{bump_normal_error_deg[offset]|%.2f} deg off")},
                {&s[3], "baked for the light", M("{bump_baked_error_levels[same_light]|%.0f} levels off for it")},
                {&s[4], M("the light moved {bump_baked_light_moved_deg|%.0f} deg"),
                 M("baked is {bump_baked_rms_levels[moved]|%.1f} levels RMS off")}},
               {},
               {M("Mean normal error against the displaced surface (8-bit read-back floor "
                  "{bump_normal_error_deg[readback]|%.2f} deg).  "),
                table,
                "At the keys' shear " + G("the shear angle, degrees", shear_) +
                    M(" deg: orthogonal axes {bump_shear_error_deg[shown]|%.2f} deg, Blinn's formula "
                      "{bump_shear_error_deg[blinn_shown]|%.2f} deg.  Not square (|dp/dt| = {bump_stretch_aspect|%.0f} "
                      "|dp/ds|): orthogonal unit axes {bump_stretch_error_deg[orthogonal]|%.2f} deg, Blinn's "
                      "{bump_stretch_error_deg[blinn]|%.2f} deg.")},
               &plot);
  } else {
    auto sq = [&](const std::string& what, int n) { return G(what, n) + " x " + G(what, n); };
    auto row = [&](const L::Text& what, const char* key) {
      L::Text t = what + ": ";
      for (int d : kDistances) {
        char k[96];
        std::snprintf(k, sizeof k, "{%s[%dx]|%%.1f}", key, d);
        t = t + G("a distance of the table", d) + "x " + M(k) + (d < 8 ? ", " : "");
      }
      return t;
    };
    const int d = kDistances[distance_];
    char k[160];
    auto K = [&](const char* templ) {
      std::snprintf(k, sizeof k, templ, d, d);
      return M(k);
    };
    pictureRow(f,
               {{&s[0], "unfiltered, one sample a pixel", K("RMS {bump_distance_rms_levels[unfiltered][%dx]|%%.1f}")},
                {&s[1], "mipmapped heights",
                 K("RMS {bump_distance_rms_levels[mipmapped][%dx]|%%.1f}, "
                   "tilt lost {bump_tilt_lost_deg[mipmapped][%dx]|%%.1f} deg")},
                {&s[2], sq("samples a pixel, a side, of Blinn's answer", kSuper) + " supersampled, box filter",
                 K("RMS {bump_distance_rms_levels[super4x4][%dx]|%%.1f}")},
                {&s[3], sq("samples a pixel, a side, of the reference", kReferenceSuper) + " supersampled reference",
                 K("mean tilt {bump_tilt_deg[reference][%dx]|%%.1f} deg")}},
               {},
               {"At " + G("the distance shown", d) + "x (" + L::given("texels a pixel", d / 2.0, "%.1f") +
                    " texels a pixel).  RMS levels against the reference, by distance:",
                row("unfiltered", "bump_distance_rms_levels[unfiltered]"),
                row("mipmapped", "bump_distance_rms_levels[mipmapped]"),
                row(sq("samples a pixel, a side, of Blinn's answer", kSuper) + " supersampled",
                    "bump_distance_rms_levels[super4x4]"),
                row("tilt lost by mipmapped heights, deg", "bump_tilt_lost_deg[mipmapped]")});
  }
  return f;
}
}  // namespace

TS_REGISTER_SCENE(BumpLimits);
