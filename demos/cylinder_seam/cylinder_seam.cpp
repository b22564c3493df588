// Figures VI.3 and VI.4, Exercise VI.1 — a label wrapped on a cylinder, and
// the patch across the seam.
//
// The claim (Buss, VI.1.2): Eq. VI.1, s = θ/360 and t = (y + h/2)/h, wraps a
// texture around the side of a cylinder like a label on a can; its left and
// right edges meet on the front line x = 0, z = r (Exercise VI.1: s = θ/360 +
// 1/2 puts them at the back).  A patch across that line with θ = -36° at x, w
// and +36° at y, z gets s = 0.9 and s = 0.1 if each vertex's s is reduced to
// [0, 1): it shows the long region 0.1..0.9 of the texture, backwards.  The
// fix: GL_REPEAT and s = 0.9 -> 1.1 (track the winding number).  Shared
// vertices keep bit-identical positions (computed from the wrapped column).
//
// Left: texture space — the label, the region the seam patch should show
// (green, 0.9..1.1 drawn wrapping) and the one it shows (red).  Right: the
// cylinder from the front, the seam patch x, y, z, w outlined in orange.
//
// Keys (each is also a flag, see --help):
//   c  coordinates: wrong (reduced to [0,1) per vertex) | right (winding tracked)
//   b  seam: front (Eq. VI.1, the book) | back (Exercise VI.1) | mine (your
//      exercises/vi1_back_seam.cpp, built by scripts/exercise.sh: drawn with
//      your s, and the panel shows the exercise's checks, pass or FAIL)
//   + / -  slices (patches around the cylinder)      [ / ]  turn the cylinder
//   p  outline the seam patch and its regions         v  view: book | compare
//
// What the GL does: each cylinder is one glBegin(GL_TRIANGLES) sent by
// common/gl/render.cpp: Renderer::draw, glTexCoord4f(s, t, 0, 1) + glVertex3f
// per vertex, s from cylinder_seam_math.hpp's sOf: across the book's seam patch
// 0.9 and 0.1 reduced, 0.9 and 1.1 tracked.  glTexParameteri(GL_TEXTURE_2D,
// GL_TEXTURE_WRAP_S, GL_REPEAT), made by Renderer::texture, reads 1.1 as
// 0.1: the fix.  Listings: book_figures/vi3_cylinder.gl.txt and
// vi4_seam_patch.gl.txt (its two cylinders' first vertices: s = 0.9, 0.1 and
// s = 0.9, 1.1).
//
// Measured: the cylinder is drawn once more, each patch head-on in its own
// orthographic panel, with a texture whose texels hold their own indices;
// along each patch the s it shows is read from the pixels and fitted: the
// span of s across the patch and its direction (the sign of ds/dx).
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "common/gl/render.hpp"
#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/core/student_code.hpp"
#include "common/core/user_texture.hpp"
#include "cylinder_seam_math.hpp"
#include "cylinder_seam_measure.hpp"  // the patches drawn head-on and read back
#include "cylinder_seam_views.hpp"    // the texture-space view: the seam patch's regions

namespace {
using cylinder::Coords;
using cylinder::Seam;

const char* const kCoordNames[] = {"wrong", "right"};
using ts::layout::kWhite;
using cylinder::views::kPatch;
const glm::vec4& kMeasured = ts::layout::kAmber;
const glm::vec4 kFailed{1.0f, 0.4f, 0.35f, 1.0f};

// 10 x 10 labelled cells, 64 texels each: the book's s = 0.1 and 0.9 fall on
// cell edges, so the seam patch shows whole columns (J|A right, I..B wrong).
ts::TextureDesc label() { return ts::labelledGrid(640, 10); }

using ts::layout::fmt;

class CylinderSeam final : public ts::Scene {
 public:
  std::string id() const override { return "cylinder_seam"; }
  std::string title() const override { return "Figures VI.3, VI.4 - a label on a cylinder and its seam"; }
  std::string about() const override {
    return "A labelled texture wrapped on a cylinder by s = theta/360, t = (y + h/2)/h (Eq. VI.1).  The patch across\n"
           "the seam (theta = -36 to +36 degrees) shows 0.8 of the texture backwards when each vertex's s is reduced\n"
           "to [0,1), and the intended 0.2 with s = 0.9 -> 1.1 and GL_REPEAT.  Prints the span and direction of s\n"
           "measured across the patches from a render whose pixels name their texels.";
  }
  std::vector<std::string> claim() const override {
    if (seam_ == kMine) return {"exercise_checks_passed", "seam_patch_span_s*"};
    return {"seam_patch_span_s*", "seam_patch_direction*"};
  }

  void addOptions(ts::Options& o) override {
    o.addEnum("coords", &coords_, {kCoordNames[0], kCoordNames[1]},
              "s per vertex: wrong = theta/360 reduced to [0,1); right = winding tracked (0.9 -> 1.1), GL_REPEAT", 'c');
    o.addEnum(
        "seam", &seam_, {"front", "back", "mine"},
        "where the texture edges meet: front (Eq. VI.1) | back (Exercise VI.1) | mine (exercises/vi1_back_seam.cpp)",
        'b');
    // 3 patches at least (a triangle prism); beyond 36 the seam patch is a sliver.
    o.addInt("slices", &slices_, 3, 36, "patches around the cylinder (the book's patch: 5, 72 degrees wide)", '+', '-');
    o.addFloat("turn", &turn_, -180.0f, 180.0f, "turn the cylinder (degrees; 180 shows the back)", ']', '[', 30.0f);
    o.addBool("patch", &patch_, "outline the seam patch x,y,z,w and its regions in texture space", 'p');
    o.addEnum("view", &view_, {"book", "compare"}, "book: texture | cylinder; compare: texture | wrong | right", 'v');
    picture_.addOption(o, "the labelled grid");
    camera_.addOptions(o);
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"vi3_cylinder",
         "Figure VI.3",
         "A texture map (left) wrapped around the side of a cylinder by Eq. VI.1 (right): its left and right edges "
         "meet on the front line x = 0, z = r, where column J meets column A.",
         {"--coords", "right", "--slices", "24", "--patch=off"},
         1024,
         512,
         "Wrapped by Eq. VI.1 with the winding tracked, {reversed_patches[right]} patches show the texture "
         "backwards; the seam patch shows {seam_patch_span_s[right]} of s, one slice of 24."},
        {"vi4_seam_patch",
         "Figure VI.4",
         "The patch x, y, z, w across the seam (theta = -36 deg at x, w; +36 deg at y, z). Left: the intended region "
         "0.9..1.1 (green, wrapping) and the region 0.1..0.9 that s = 0.9 and 0.1 select (red). Middle: s reduced "
         "to [0,1) shows 0.8 of the texture backwards. Right: s = 0.9 -> 1.1 with GL_REPEAT.",
         {"--view", "compare", "--slices", "5", "--seam", "front"},
         1280,
         456,
         "s = 0.9 and 0.1 make the seam patch show {seam_patch_span_s[wrong]} of the texture backwards; s = 0.9 -> "
         "1.1 with GL_REPEAT shows the {seam_patch_span_s[right]} intended."},
    };
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;

 private:
  // The student's s (--seam mine), as measure() got it from the checker.
  struct Detail {
    std::map<int, double> spans;  // coords -> signed span of the seam patch
    ts::student::Table mine;
  };
  cylinder::Params params(Coords c, const Detail* d = nullptr) const {
    cylinder::Params p;
    p.slices = slices_;
    p.coords = c;
    p.seam = seam_ == kMine ? Seam::Front : Seam(seam_);
    if (seam_ == kMine && d && d->mine.ok()) p.sOfTheta = [d](double th) { return d->mine.at({th})[0]; };
    return p;
  }
  std::vector<Coords> shownCoords() const {
    if (seam_ == kMine) return {Coords::Right};  // yours, as you wrote it
    return view_ == 0 ? std::vector<Coords>{Coords(coords_)} : std::vector<Coords>{Coords::Wrong, Coords::Right};
  }
  static constexpr int kMine = 2;
  void addTextureView(ts::Frame& f, const ts::Rect& vp, int tex, int scale, const Detail* d) const;
  void addCylinder(ts::Frame& f, const ts::Rect& vp, Coords c, int tex, int scale, const Detail* d) const;
  glm::mat4 view() const {
    // Eye 7.5 radii away (mild perspective), 12° above: the front is seen nearly head-on and the
    // top rim shows it is a cylinder.  `turn` brings θ = turn to the front.
    glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -7.5f));
    m = glm::rotate(m, glm::radians(12.0f), glm::vec3(1, 0, 0));
    return glm::rotate(m, glm::radians(-turn_), glm::vec3(0, 1, 0));
  }

  int coords_ = int(Coords::Wrong), seam_ = int(Seam::Front), slices_ = 5, view_ = 0;
  float turn_ = 0.0f;
  ts::UserTexture picture_;  // --texture FILE
  ts::OrbitCamera camera_;   // --yaw --pitch --zoom: the mouse
  bool patch_ = true;
  // The coordinates whose region the texture view marks.
  Coords textureCoords() const { return view_ == 1 && seam_ != kMine ? Coords::Wrong : Coords(coords_); }
};

void CylinderSeam::addTextureView(ts::Frame& f, const ts::Rect& vp, int tex, int scale, const Detail* d) const {
  ts::Panel p = ts::layout::texturePanel("texture_space", vp, tex, "texture");
  // The seam patch's intended region (green) and the one the shown
  // coordinates select (cylinder_seam_views.hpp).  The compare view shows the
  // wrong way here (the right one is the green region itself).
  if (patch_ && (seam_ != kMine || (d && d->mine.ok())))
    cylinder::views::markSeamPatch(f, p, params(Coords::Right, d), params(textureCoords(), d), scale);
  f.panels.push_back(p);
}

void CylinderSeam::addCylinder(ts::Frame& f, const ts::Rect& vp, Coords c, int tex, int scale, const Detail* d) const {
  cylinder::Params cp = params(c, d);
  ts::Panel p;
  p.id = std::string("cylinder_") + kCoordNames[int(c)];
  p.viewport = vp;
  p.projection = glm::perspective(glm::radians(24.0f), float(vp.w) / float(vp.h), 2.0f, 12.0f);
  p.modelview = view();
  camera_.apply(p);
  p.depthTest = true;
  // Light from the upper left in front, fixed to the viewer: expressed in the
  // cylinder's own coordinates by undoing the turn.
  glm::dvec3 toLight = glm::dvec3(glm::inverse(glm::mat3(p.modelview)) * glm::vec3(-0.4f, 0.5f, 1.0f));
  // The mesh's (s, t) (cylinder::sOf, tOf) become glTexCoord4f(s, t, 0, 1) in Renderer::draw.
  p.batches.push_back(ts::litMeshBatch(cylinder::mesh(cp), tex, toLight, 0.45, 0.55, "cylinder"));
  if (patch_) {
    // The seam patch's outline, 1% outside the surface so the depth test
    // keeps it in front of its own patch but behind the rest of the cylinder.
    const int k = cylinder::seamPatch(cp);
    double ta = cylinder::thetaDeg(cp.slices, k), tb = cylinder::thetaDeg(cp.slices, k + 1);
    const double R = cp.r * 1.01, hh = cp.h / 2;
    glm::dvec3 corner[4] = {cylinder::point(R, ta, -hh), cylinder::point(R, tb, -hh), cylinder::point(R, tb, hh),
                            cylinder::point(R, ta, hh)};
    ts::Batch outline = ts::lineLoop({}, kPatch, 3.0f, "seam_patch");
    for (const auto& q : corner) outline.vertices.push_back({glm::vec3(q), {0, 0, 0, 1}, kPatch});
    p.batches.push_back(outline);
    // x, y, z, w where the patch faces the viewer.
    const char* names[4] = {"x", "y", "z", "w"};
    glm::mat4 mvp = p.projection * p.modelview;
    for (int i = 0; i < 4; ++i) {
      glm::vec3 n = glm::mat3(p.modelview) * glm::vec3(corner[i].x, 0.0, corner[i].z);
      if (n.z <= 0.05f) continue;
      glm::vec2 q = ts::panelToPixels(p, mvp * glm::vec4(glm::vec3(corner[i]), 1.0f));
      float dx = (i == 0 || i == 3 ? -1.0f : 1.0f) * 6.0f * float(scale);
      float dy = i < 2 ? 2.0f * float(scale) : -ts::text::height(scale) - 2.0f * float(scale);
      ts::layout::placeFree(f,
                            {q.x + dx, q.y + dy, names[i], kPatch, scale,
                             i == 0 || i == 3 ? ts::Align::Right : ts::Align::Left},
                            ts::layout::box(vp));
    }
  }
  f.panels.push_back(p);
}

ts::Frame CylinderSeam::build(int width, int height, const ts::Measurements& measured) const {
  ts::Frame f = ts::layout::blankFrame(width, height);
  ts::TextureDesc t = label();
  t.wrapS = GL_REPEAT;
  t = picture_.orDefault(t);  // the fix needs it (and the wrong way does not care)
  int tex = f.addTexture(t);
  const std::vector<Coords> shown = shownCoords();
  const Detail* d = measured.detailAs<Detail>();
  // The texture square, then the cylinders, in a row (or a column when the
  // window is tall); titles above, the seam's rule and the measurement below.
  namespace L = ts::layout;
  L::FlowSpec spec;
  spec.n = 1 + int(shown.size());
  spec.aspect = 1.1f;  // the cylinder's framing (24 degrees high) needs this width
  spec.linesAbove = 1;
  spec.linesBelow = 1;
  spec.gap = 12;
  // The key of the seam patch's colours, under the pictures when they are
  // drawn: the flow's text scale, then the flow again over the rest.
  const bool marked = patch_ && (seam_ != kMine || (d && d->mine.ok()));
  std::vector<ts::LegendEntry> key;
  if (marked) {
    key.push_back({cylinder::views::kIntended, "intended region of the seam patch"});
    if (textureCoords() == Coords::Wrong) key.push_back({cylinder::views::kActual, "region its s values select"});
    key.push_back({kPatch, "seam patch x y z w, the way s runs"});
  }
  const L::Box all{6, 6, float(width) - 6, float(height) - 6};
  const int keyScale = L::flow(all, spec)[0].scale;
  float keyW = 0;
  for (const ts::LegendEntry& e : key)
    keyW += ts::text::height(keyScale) + 4.0f * float(keyScale) + ts::text::width(e.meaning, keyScale) +
            8.0f * float(keyScale);
  const float keyH = key.empty() ? 0.0f : L::lineHeight(keyScale) * std::ceil(keyW / all.w());
  std::vector<L::Cell> cells = L::flow({all.x0, all.y0, all.x1, all.y1 - keyH}, spec);
  if (!key.empty()) {  // right under the captions (the flow centres the cells in its area)
    float y = 0;
    for (const L::Cell& c : cells) y = std::max(y, c.below.y1);
    const float x0 = std::max(all.x0, (float(width) - keyW) / 2);
    L::legend(f, {x0, y, all.x1, y + keyH}, key, keyScale);
  }
  const L::Cell& tc = cells[0];
  const int scale = tc.scale, names = int(L::lineHeight(scale));  // room for x, y, z, w above and below the square
  const int side = std::max(1, std::min(tc.picture.w, tc.picture.h - 2 * names));
  addTextureView(f, L::centred(tc.picture, side, side), tex, scale, d);
  L::caption(f, tc.above, "texture space", kWhite, scale);
  const char* rule[] = {"seam at the front: s = theta/360", "seam at the back: s = theta/360 + 1/2",
                        "s = your cylinderS(theta)"};
  L::caption(f, tc.below, rule[seam_], kWhite, scale);
  for (size_t c = 0; c < shown.size(); ++c) {
    const L::Cell& cell = cells[c + 1];
    if (seam_ == kMine && !(d && d->mine.ok())) {  // not done yet, or it failed: say so, draw nothing
      L::caption(f, L::box(cell.picture), d ? d->mine.failure : "asking the exercise checker for your s ...", kFailed,
                 cell.scale);
      continue;
    }
    addCylinder(f, cell.picture, shown[c], tex, cell.scale, d);
    L::caption(f, cell.above,
               seam_ == kMine              ? ts::student::summary(measured)
               : shown[c] == Coords::Wrong ? "s reduced to [0,1): wrong"
                                           : "s winding tracked: right",
               kWhite, cell.scale);
    if (d && d->spans.count(int(shown[c]))) {
      double span = d->spans.at(int(shown[c]));
      const std::string n = std::string("[") + kCoordNames[int(shown[c])] + "]";
      L::caption(f, cell.below,
                 "seam patch: " + L::measured(measured, "seam_patch_span_s" + n, "%.2f") + " of s, " +
                     (span < 0 ? "reversed" : "forwards"),
                 kMeasured, cell.scale);
    }
  }
  return f;
}

// Each patch is drawn head-on with a texel-index texture and the s it shows
// fitted across it (cylinder_seam_measure.hpp): the seam patch's span and sign.
ts::Measurements CylinderSeam::measure(ts::Renderer& r) {
  ts::Measurements out;
  Detail d;
  if (seam_ == kMine) {  // the student's s at each column (the checker runs it), then the exercise's checks
    std::vector<std::vector<double>> at;
    for (int i = 0; i < slices_; ++i) at.push_back({std::fmod(cylinder::thetaDeg(slices_, i) + 360.0, 360.0)});
    d.mine = ts::student::table("cylinderS", at);
    ts::student::addTo(out, "vi1_back_seam", ts::student::check("vi1_back_seam"));
    if (!d.mine.ok()) return out.detail = d, out;
  }
  const int k = cylinder::seamPatch(params(Coords::Right, &d));
  out.push_back({"seam_patch", double(k), "the patch the texture edges meet in (0 = the front one)"});
  for (Coords c : shownCoords()) {
    std::vector<cylinder::PatchResult> res = cylinder::measurePatches(r, params(c, &d));
    std::string n = std::string("[") + kCoordNames[int(c)] + "]";
    int reversed = 0;
    double err = 0;
    for (const auto& pr : res) reversed += pr.span < 0, err = std::max(err, pr.texelErr);
    d.spans[int(c)] = res[size_t(k)].span;
    out.push_back({"seam_patch_span_s" + n, std::abs(res[size_t(k)].span),
                   "how much of the texture (in s) the seam patch shows"});
    out.push_back(
        {"seam_patch_direction" + n, res[size_t(k)].span < 0 ? -1.0 : 1.0, "sign of ds/dx across it: -1 = backwards"});
    out.push_back(
        {"front_patch_span_s" + n, std::abs(res[0].span), "the same for the patch facing +z (theta -180/n..180/n)"});
    out.push_back({"front_patch_direction" + n, res[0].span < 0 ? -1.0 : 1.0, "sign of ds/dx across the front patch"});
    out.push_back({"reversed_patches" + n, double(reversed), "patches showing the texture backwards"});
    out.push_back(
        {"texel_error_max" + n, err, "largest distance (texels of 2048) between the texel shown and the assigned s"});
  }
  out.detail = d;
  return out;
}
}  // namespace

TS_REGISTER_SCENE(CylinderSeam);
