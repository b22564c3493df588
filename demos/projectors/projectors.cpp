// Projector functions and texgen — seed 002's wraps along X, Y and Z, as
// printed and corrected; box mapping; OBJECT_LINEAR against EYE_LINEAR; the
// slide projector; a solid 3D texture; the cube's 24 vertices (seeds 001,
// 002; Buss VI.1.2).
//
// The claim: a projector function maps a point p of the object to (s, t).
// Seed 002 prints planar, cylindrical and spherical wraps along each axis:
//   planar    z) tu = s·x − cx ; tv = s·x − cx      (tv must read s·y − cy: as printed s ≡ t)
//   cylinder  tu = su/2π · arctg(x/y) − ou           (arctg has period π: atan2, or half the columns, twice around)
//   sphere    tv = sv/π · arctg(z/|p|) − ov          (reaches ±1/4 only: arcsin)
// Box mapping projects along the normal's largest axis (stretch ≤ √3);
// glTexGen computes linear projectors only (OBJECT_LINEAR: fixed to the
// object; EYE_LINEAR: fixed to the planes' modelview, so a moving object
// swims); the slide projector's eye planes are the rows of B·P_L·V_L.
//
// Keys (each is also a flag, see --help):
//   v  view: object | seed002 | box | swim | slide | cube
//   o  object: cube | cylinder | sphere | torus | bumpy        a  axis X | Y | Z
//   p  projector: planar | cylindrical | spherical | box | solid (3D texture)
//   f  formula: printed (seed 002) | corrected
//   c  coordinates: cpu (glTexCoord per vertex) | texgen (linear only) | glsl (per fragment)
//   g  texgen mode: object (GL_OBJECT_LINEAR) | eye (GL_EYE_LINEAR)
//   m / M  move the object (8 poses)      k  slide: clip the back projection (q < 0)
//
// What the GL does (common/gl/render.cpp from the batch's ts::TexGen):
//   glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR); glTexGenfv(GL_S, GL_OBJECT_PLANE, {½,0,0,½});
//   glEnable(GL_TEXTURE_GEN_S) — and T (R, Q); EYE_LINEAR planes are given under
//   the batch's planeModelview (GL keeps plane·M⁻¹).  The slide adds
//   glClipPlane(GL_CLIP_PLANE0, Q row).  The solid texture is glTexImage3D, 64³.
//   Non-linear projectors run per fragment in projectors_gl.hpp's GLSL.
//   Listings: book_figures/projectors_seed002.gl.txt, projectors_box_vs_planar.gl.txt,
//   projectors_texgen_swim.gl.txt, slide_projector.gl.txt.
//
// Measured from texel-index renders (projectors_measure.hpp): columns/rows used and
// mismatches against the corrected formula per axis, the spherical tv at the
// pole and at 45°, the stretch of box and planar maps, the texel changes of a
// moving point, the slide against the CPU, the 3D texture's seam and pinch,
// the cube's faces.
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/gl/render.hpp"
#include "projectors_gl.hpp"
#include "projectors_math.hpp"
#include "projectors_measure.hpp"
#include "projectors_pose.hpp"
#include "projectors_views.hpp"

namespace {
using namespace proj;
using ts::layout::fmt;
using ts::layout::kWhite;
const char* const* const kAxis = kAxisName;  // "x", "y", "z" (projectors_measure.hpp, the measurement names)
const char* const* const kProj = kProjName;  // "planar" ... "solid"
const char* const kFormula[] = {"printed", "corrected"};
const char* const kCoordsName[] = {"cpu", "texgen", "glsl"};
constexpr int kUsageGrid = 64;
enum View { kObject, kSeed, kBox, kSwim, kSlide, kCube };

class Projectors final : public ts::Scene {
 public:
  std::string id() const override { return "projectors"; }
  std::string title() const override { return "Projector functions and texgen (seeds 001, 002; Buss VI.1.2)"; }
  std::string about() const override {
    return "Seed 002's planar, cylindrical and spherical wraps along X, Y, Z as printed and corrected; box mapping;\n"
           "glTexGen OBJECT_LINEAR against EYE_LINEAR; the slide projector (eye planes = rows of B P_L V_L); a 3D\n"
           "texture; a cube with 24 against 8 vertices.  Every number is read from renders with a texel-index texture.";
  }
  std::vector<std::string> claim() const override { return {"planar_z_diagonal_share", "spherical_pole_tv"}; }
  void addOptions(ts::Options& o) override {
    o.addEnum("view", &view_, {"object", "seed002", "box", "swim", "slide", "cube"}, "what to show", 'v');
    o.addEnum("object", &object_, {"cube", "cylinder", "sphere", "torus", "bumpy"}, "the object", 'o');
    o.addEnum("axis", &axis_, {"x", "y", "z"}, "the projector's axis", 'a');
    o.addEnum("projector", &proj_, {"planar", "cylindrical", "spherical", "box", "solid"}, "the projector function",
              'p');
    o.addEnum("formula", &formula_, {"printed", "corrected"}, "seed 002 as printed, or corrected", 'f');
    o.addEnum("coords", &coords_, {"cpu", "texgen", "glsl"},
              "glTexCoord per vertex | glTexGen (linear projectors) | per fragment in GLSL", 'c');
    o.addEnum("texgen", &texgen_, {"object", "eye"}, "glTexGen mode: GL_OBJECT_LINEAR | GL_EYE_LINEAR", 'g');
    o.addInt("pose", &pose_, 0, kPoses - 1, "object motion: pose 0..7 (eye planes stay at pose 0)", 'm', 'M');
    o.addBool("clip", &clip_, "slide projector: clip plane q >= 0 against the back projection", 'k');
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {{"projectors_seed002",
             "Seed 002 (lab sheet, lines 83-165)",
             "Seed 002's wraps on a sphere, as printed (left of each pair, "
             "amber) and corrected (right), along X, Y and Z: planar "
             "along Z as printed puts every point on the texture's diagonal; the cylindrical arctg shows the texture "
             "twice around; the spherical arctg uses half the rows.",
             {"--view", "seed002"},
             1024,
             640,
             "As printed, planar Z puts {planar_z_diagonal_share} of the pixels on the diagonal; cylindrical uses "
             "{cylindrical_z_printed_columns} of the columns; spherical tv at the pole is {spherical_pole_tv} (arcsin: "
             "{spherical_pole_tv_corrected})."},
            {"projectors_box_vs_planar",
             "Seed 001 (box mapping)",
             "The sphere seen along (1,1,1): box mapping (left) projects each part along its normal's largest axis; "
             "one planar projection along Z (right) stretches without bound toward its rim.",
             {"--view", "box"},
             1024,
             512,
             "Box mapping stretches at most {box_worst_stretch} (sqrt 3 = 1.732); one planar projection "
             "{planar_stretch_80} at 80 deg (1/cos 80 = 5.76)."},
            {"projectors_texgen_swim",
             "Seed 001 (glTexGen)",
             "A cube at pose 0 (left) and pose 7 (right) with planar texgen "
             "along Z: GL_OBJECT_LINEAR (top) keeps the texture on the "
             "cube; GL_EYE_LINEAR (bottom), planes given at pose 0, leaves it behind: the texture swims.",
             {"--view", "swim"},
             1024,
             512,
             "One surface point changes texel {swim_changes_object_linear} times over 7 moves with OBJECT_LINEAR, "
             "{swim_changes_eye_linear} times with EYE_LINEAR."},
            {"slide_projector",
             "Seed 001 (q: projective texturing)",
             "A slide thrown on a floor and a wall by EYE_LINEAR planes = rows of B P_L V_L. Left: the wall behind the "
             "projector shows the back projection (q < 0). Right: a clip plane q >= 0 removes it.",
             {"--view", "slide"},
             1024,
             512,
             "{slide_mismatches} mismatches against the CPU in {slide_checked} pixels; back-projection pixels "
             "{slide_back_pixels_nofix} without a fix, {slide_back_pixels_clip} with the clip plane."}};
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;

 private:
  views::Way way() const {
    return {Projector(proj_), Axis(axis_), Formula(formula_), Coords(coords_),
            GLenum(texgen_ ? GL_EYE_LINEAR : GL_OBJECT_LINEAR)};
  }
  using Key = std::tuple<int, int, int, int, int, int>;
  Key key() const { return {object_, proj_, axis_, formula_, coords_, texgen_}; }
  struct Detail {
    std::map<Key, Usage> usage;
  };
  void objectView(ts::Frame& f, int w, int h, const ts::Measurements& m) const;
  void gridView(ts::Frame& f, int w, int h) const;
  void pairView(ts::Frame& f, int w, int h, const ts::Measurements& m) const;

  int view_ = kObject, object_ = int(Object::Sphere), axis_ = 2, proj_ = 0, formula_ = 0, coords_ = 2, texgen_ = 0,
      pose_ = 0;
  bool clip_ = false;
  ts::Measurements fixed_;  // the state-independent numbers, measured once
  Detail detail_;
};

ts::TextureDesc picture() { return ts::labelledGrid(512, 8); }

void Projectors::objectView(ts::Frame& f, int w, int h, const ts::Measurements& m) const {
  const views::Way wy = way();
  int tex = f.addTexture(wy.pr == Projector::Solid ? solidRingsTexture() : picture());
  int grid = f.addTexture(picture());
  const bool tall = h > w * 5 / 4;  // a tall window: the texture space below the object
  const int side = tall ? std::min(w - 16, (h - 90) / 2) : std::min(w / 2 - 12, h - 60);
  ts::Rect left{8, 40, side, side}, right{w / 2 + 4, 40, side, side};
  if (tall) left = {(w - side) / 2, 40, side, side}, right = {(w - side) / 2, 48 + side, side, side};
  // EYE_LINEAR planes given where pose 0 was: camera and pose 0 in force.
  const ts::Batch b = views::batchFor(shape(Object(object_)), wy, tex, views::camera() * pose(0));
  f.panels.push_back(views::objectPanel("object", left, b, pose(pose_)));
  const Detail* d = m.detailAs<Detail>();
  const Usage* u = nullptr;
  if (d && d->usage.count(key())) u = &d->usage.at(key());
  f.panels.push_back(views::usagePanel(right, grid, u ? &u->used : nullptr, kUsageGrid));
  const int sc = ts::layout::scaleFor(left, 2);
  std::string what = std::string(kProj[proj_]) + " along " + kAxis[axis_] + ", " + kFormula[formula_] + ", coords " +
                     kCoordsName[int(views::effective(wy))] +
                     (views::effective(wy) == Coords::TexGen ? (texgen_ ? " EYE_LINEAR" : " OBJECT_LINEAR") : "");
  ts::layout::caption(f, {8, 4, float(w) - 8, 36}, what, ts::layout::kAmber, sc);
  if (u)
    ts::layout::caption(f, {float(right.x), float(right.y + right.h + 2), float(w) - 8, float(right.y + right.h + 20)},
                        "texels used: columns " + fmt("%.2f", u->columns) + ", rows " + fmt("%.2f", u->rows) +
                            ", on the diagonal " + fmt("%.2f", u->diagonal),
                        kWhite, 1);
}

// seed002: rows planar / cylindrical / spherical; columns X, Y, Z, each printed | corrected.
void Projectors::gridView(ts::Frame& f, int w, int h) const {
  int tex = f.addTexture(picture());
  const Shape s = fromMesh(sphereMesh(24));  // per fragment: a coarse mesh keeps the sidecar small
  const int cw = (w - 16) / 6, ch = (h - 40) / 3, side = std::min(cw, ch - 18);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 6; ++c) {
      Axis ax = Axis(c / 2);
      Formula fo = Formula(c % 2);
      ts::Rect vp{8 + c * cw + (cw - side) / 2, 36 + r * ch + 16, side, side};
      ts::Panel p = views::objectPanel(std::string(kProj[r]) + "_" + kAxis[c / 2] + "_" + kFormula[c % 2], vp,
                                       glslBatch(s, Projector(r), ax, fo, tex), glm::mat4(1.0f));
      f.panels.push_back(p);
      ts::layout::caption(f, {float(vp.x), float(vp.y - 16), float(vp.x + vp.w), float(vp.y)},
                          std::string(kProj[r]) + " " + kAxis[c / 2] + " " + kFormula[c % 2],
                          fo == Formula::Printed ? ts::layout::kAmber : kWhite, 1);
    }
  ts::layout::caption(f, {8, 4, float(w) - 8, 30}, "seed 002 as printed (amber) and corrected, along X, Y, Z", kWhite,
                      2);
}

// box | swim | slide | cube: two or four pictures side by side.
void Projectors::pairView(ts::Frame& f, int w, int h, const ts::Measurements& measured) const {
  namespace Lk = ts::layout;
  int tex = f.addTexture(picture());
  // Side by side, or one above the other in a tall window; a caption band above each.
  const bool tall = h > w * 5 / 4;
  // A band under each picture: box | planar print their measured stretch there, the slide
  // its back-projection pixels (the claim's numbers, under what they measure).
  const bool under = view_ == kBox || view_ == kSlide;
  auto layoutAt = [&](int band, ts::Rect* l, ts::Rect* r) {
    // The slide's stage has a key under the pictures: the projector's outline.
    const int keyH = view_ == kSlide ? int(Lk::lineHeight(1)) + 4 : 0;
    const int side = std::max(1, tall ? std::min(w - 16, (h - 90 - keyH - 2 * band) / 2)
                                      : std::min(w / 2 - 16, h - 50 - keyH - band));
    *l = {w / 4 - side / 2, 36, side, side}, *r = {3 * w / 4 - side / 2, 36, side, side};
    if (tall) *l = {(w - side) / 2, 36, side, side}, *r = {(w - side) / 2, 36 + side + band + 40, side, side};
  };
  // The band's text at the scale the pictures ask for without it, as the titles: the numbers
  // are the figure's point, not small print.
  ts::Rect L, R;
  layoutAt(0, &L, &R);
  const int underScale = Lk::scaleFor(L, 2);
  if (under) layoutAt(int(Lk::lineHeight(underScale)) + 4, &L, &R);
  const int side = L.w;
  std::string a, b;
  if (view_ == kBox) {
    const Shape s = shape(Object::Sphere);
    glm::mat4 m = glm::inverse(views::camera()) * glm::translate(glm::mat4(1.0f), {0, 0, -5.2f}) *
                  faceOn({1, 1, 1});  // (1,1,1) toward the viewer
    f.panels.push_back(views::objectPanel("box", L, glslBatch(s, Projector::Box, Axis::Z, Formula::Corrected, tex), m));
    f.panels.push_back(
        views::objectPanel("planar_z", R, glslBatch(s, Projector::Planar, Axis::Z, Formula::Corrected, tex), m));
    a = "box mapping: stretch <= sqrt 3", b = "planar along Z: 1/cos to the rim";
    // What the stretch measured on each comes to, against its closed form.
    const Lk::Text sqrt3 = Lk::given("sqrt 3", std::sqrt(3.0), "%.2f"),
                   at = Lk::given("angle from the projector's axis, deg", 80.0, "%g"),
                   secant = Lk::given("1/cos 80 deg", 1.0 / std::cos(glm::radians(80.0)), "%.2f");
    const Lk::Text under[2] = {"worst: " + Lk::measured(measured, "box_worst_stretch", "%.2f") + " (sqrt 3 = " + sqrt3 +
                                   ")",
                               "at " + at + " deg: " + Lk::measured(measured, "planar_stretch_80", "%.2f") +
                                   " (1/cos = " + secant + ")"};
    const ts::Rect* pics[2] = {&L, &R};
    for (int k = 0; k < 2; ++k) {  // as wide as the picture's half of the window (its row when tall)
      const ts::Rect& p = *pics[k];
      const float y = float(p.y + p.h + 2), x0 = tall ? 8.0f : float(k * w / 2 + 8),
                  x1 = tall ? float(w - 8) : x0 + float(w / 2 - 16);
      Lk::caption(f, {x0, y, x1, y + Lk::lineHeight(underScale)}, under[k], Lk::kAmber, underScale);
    }
  } else if (view_ == kSwim) {
    const Shape cube = shape(Object::Cube);
    const int q = side / 2 - 4;
    for (int k = 0; k < 4; ++k) {  // in L pose 0, in R pose 7; OBJECT_LINEAR above EYE_LINEAR
      GLenum mode = k < 2 ? GL_OBJECT_LINEAR : GL_EYE_LINEAR;
      int ps = k % 2 ? kPoses - 1 : 0;
      const ts::Rect& cell = k % 2 ? R : L;
      ts::Rect vp{cell.x + (side - q) / 2, cell.y + (k / 2) * (q + 8), q, q};
      f.panels.push_back(views::objectPanel(
          std::string(k < 2 ? "object_linear_" : "eye_linear_") + std::to_string(ps), vp,
          texGenBatch(cube, planarTexGen(Axis::Z, Formula::Corrected, mode, views::camera() * pose(0)), tex),
          pose(ps)));
    }
    a = "pose 0: OBJECT / EYE_LINEAR", b = "pose 7: EYE_LINEAR swims";
  } else if (view_ == kSlide) {
    ts::TextureDesc slide = picture();
    slide.wrapS = slide.wrapT = GL_CLAMP_TO_BORDER;
    slide.border = {0.3f, 0.3f, 0.34f, 1.0f};  // the unlit stage
    int st = f.addTexture(slide);
    // Left the state's --clip, right the other (k swaps them).
    f.panels.push_back(views::slidePanel(L, st, clip_));
    f.panels.push_back(views::slidePanel(R, st, !clip_));
    a = "no fix: the back projection (q < 0)", b = "clip plane q >= 0";
    if (clip_) std::swap(a, b);
    // The back projection the render shows, counted in the measurement's render of each stage.
    const Lk::Text px = " of " + Lk::given("the check's render, px across", kSlidePx, "%g") + "x" +
                        Lk::given("the check's render, px down", kSlidePx, "%g") + " px";
    const Lk::Text back[2] = {"q < 0 shown: " + Lk::measured(measured, "slide_back_pixels_nofix", "%.0f") + px,
                              "q < 0 shown: " + Lk::measured(measured, "slide_back_pixels_clip", "%.0f") + px};
    const ts::Rect* pics[2] = {&L, &R};
    for (int k = 0; k < 2; ++k) {
      const ts::Rect& p = *pics[k];
      const float y = float(p.y + p.h + 2), x0 = tall ? 8.0f : float(k * w / 2 + 8),
                  x1 = tall ? float(w - 8) : x0 + float(w / 2 - 16);
      Lk::caption(f, {x0, y, x1, y + Lk::lineHeight(underScale)}, back[clip_ ? 1 - k : k], Lk::kAmber, underScale);
    }
    const float y = float(R.y + R.h) + Lk::lineHeight(underScale) + 6;
    ts::layout::legend(f, {float(std::min(L.x, R.x)), y, float(w) - 8, y + ts::layout::lineHeight(1)},
                       {{views::kProjectorOutline, "the projector: its frustum's edges"}}, 1);
  } else {
    f.panels.push_back(views::objectPanel("cube24", L,
                                          perVertexBatch(shape(Object::Cube, false), Projector::Planar, Axis::Z,
                                                         Formula::Corrected, tex, true),
                                          pose(pose_)));
    f.panels.push_back(views::objectPanel("cube8", R,
                                          perVertexBatch(shape(Object::Cube, true), Projector::Planar, Axis::Z,
                                                         Formula::Corrected, tex, true),
                                          pose(pose_)));
    a = "24 vertices: each face its own (s,t)", b = "8 shared vertices: smeared and mirrored faces";
  }
  const int sc = under ? underScale : ts::layout::scaleFor(L, 2);
  if (tall) {
    ts::layout::caption(f, {8, 4, float(w) - 8, 34}, a, ts::layout::kAmber, sc);
    ts::layout::caption(f, {8, float(R.y - 36), float(w) - 8, float(R.y - 4)}, b, ts::layout::kAmber, sc);
  } else {
    ts::layout::caption(f, {8, 4, float(w / 2) - 4, 34}, a, ts::layout::kAmber, sc);
    ts::layout::caption(f, {float(w / 2) + 4, 4, float(w) - 8, 34}, b, ts::layout::kAmber, sc);
  }
}

ts::Frame Projectors::build(int width, int height, const ts::Measurements& measured) const {
  ts::Frame f = ts::layout::blankFrame(width, height);
  f.programs.push_back({kProgramName, projectorProgram()});
  if (view_ == kObject) objectView(f, width, height, measured);
  else if (view_ == kSeed) gridView(f, width, height);
  else pairView(f, width, height, measured);
  return f;
}

ts::Measurements Projectors::measure(ts::Renderer& r) {
  auto stateUsage = [&] {  // the texels the current state reads: the usage panel's picture
    if (detail_.usage.count(key())) return;
    views::Way w = way();
    detail_.usage[key()] = usage(sixViews(r, shape(Object(object_)), w.pr, w.ax, w.f, views::effective(w), kUsageGrid),
                                 kUsageGrid);
  };
  // A window's first measurement: the usage panel at once (ts::measureStage),
  // the state-independent numbers after it.
  if (fixed_.empty() && ts::measureStaged()) {
    stateUsage();
    ts::Measurements first;
    first.detail = detail_;
    ts::measureStage(std::move(first));
  }
  if (fixed_.empty()) {  // state-independent: once per process (make_figures' figures each have a scene)
    static std::mutex lock;
    static ts::Measurements kept;
    std::lock_guard<std::mutex> g(lock);
    if (kept.empty()) kept = measureAll(r);
    fixed_ = kept;
  }
  ts::Measurements out = fixed_;
  stateUsage();
  const Usage& u = detail_.usage[key()];
  out.push_back({"state_columns", u.columns, "share of columns the current object uses"});
  out.push_back({"state_rows", u.rows, "share of rows the current object uses"});
  out.detail = detail_;
  return out;
}
}  // namespace

TS_REGISTER_SCENE(Projectors);
