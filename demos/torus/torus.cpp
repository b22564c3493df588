// Figure VI.6, Exercise VI.2 — a checkerboard on a torus, and where the
// texture's centre lands.
//
// The claim (Buss, VI.1.2): the torus p(θ, φ) = ((R + r cos φ) sin θ, r sin φ,
// (R + r cos φ) cos θ) takes the texture by s = θ/360, t = φ/360.  Exercise
// VI.2: the texture's centre (s, t) = (1/2, 1/2) then lands at θ = φ = 180°,
// the point (0, 0, -(R - r)) on the inner wall of the hole at the back; with
// s = θ/360 + 1/2, t = φ/360 + 1/2 it lands at the front, (0, 0, R + r) on
// the positive z axis.
//
// Left: the texture with its centre marked.  Right: the torus tilted towards
// the viewer (from above, as in the book) so the hole's far wall shows; a
// red cross on the surface and a label mark where (1/2, 1/2) is.
//
// Keys (each is also a flag, see --help):
//   c  mapping: book (s = θ/360, t = φ/360) | front (both + 1/2, the exercise)
//      | mine (your exercises/vi2_torus_front.cpp, built by scripts/exercise.sh:
//      drawn with your (s, t); the panel shows the exercise's checks)
//   g  texture: checker (the book's) | grid (labelled cells; the centre is
//      where D4, E4, D5, E5 meet)
//   m  the centre marker            v  view: single | compare (both mappings)
//   . / ,  tilt towards the viewer   ] / [  turn about the torus's axis
//
// What the GL does: each torus is one glBegin(GL_TRIANGLES) sent by
// common/gl/render.cpp: Renderer::draw, glTexCoord4f(s, t, 0, 1) + glVertex3f
// per vertex, (s, t) from common/core/torus.cpp: ts::torusMesh, (i/nu, j/nv)
// plus torus_math.hpp's offset, (1/2, 1/2) for front;
// glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S/T, GL_REPEAT), made by
// Renderer::texture, reads s, t in [1/2, 3/2) as the texture shifted.
// Listings: book_figures/vi6_torus.gl.txt and vi6_torus_centre.gl.txt (its
// front torus starts at glTexCoord4f(0.5, 0.5, 0, 1)).
//
// Measured: the torus is drawn once more with a texture whose texels hold
// their own indices; the pixels whose texel is near (1/2, 1/2) are fitted to
// find where on the screen the centre is, a ray through that point is cast
// against the mesh, and the 3D point it hits is compared with the answer.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "common/core/error.hpp"
#include "common/gl/render.hpp"
#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/core/user_texture.hpp"
#include "torus_math.hpp"     // the exercise's answer; the torus itself is common/core/torus.hpp
#include "torus_measure.hpp"  // the centre found in a texel-index render, and the ray to the mesh
#include "torus_views.hpp"    // the centre's marks
#include "common/core/student_code.hpp"

namespace {
using torus::Mapping;

const char* const kMappingNames[] = {"book", "front", "mine"};
const Mapping kMine = Mapping(2);  // exercises/vi2_torus_front.cpp: the student's (s, t)
using ts::layout::kWhite;
const glm::vec4& kMeasured = ts::layout::kAmber;
const glm::vec4 kFailed{1.0f, 0.4f, 0.35f, 1.0f};

using ts::layout::fmt;

using torus::Found;  // where the centre was found in one mapping (the measurement)
using torus::kMeasureSize;

class Torus final : public ts::Scene {
 public:
  std::string id() const override { return "torus"; }
  std::string title() const override { return "Figure VI.6 - a checkerboard on a torus and its centre"; }
  std::string about() const override {
    return "A checkerboard on a torus by s = theta/360, t = phi/360.  Exercise VI.2: the texture centre (1/2, 1/2)\n"
           "lands at theta = phi = 180 deg, (0, 0, -(R - r)) inside the hole at the back; adding 1/2 to s and t moves\n"
           "it to (0, 0, R + r) at the front.  Prints where the centre is found in a render whose pixels name their\n"
           "texels: its screen position, the 3D point there, and its distance from the answer.";
  }
  std::vector<std::string> claim() const override {
    if (Mapping(mapping_) == kMine) return {"exercise_checks_passed", "centre_distance_to_answer*"};
    return {"centre_3d_z*", "centre_distance_to_answer*"};
  }

  void addOptions(ts::Options& o) override {
    o.addEnum("mapping", &mapping_, {kMappingNames[0], kMappingNames[1], kMappingNames[2]},
              "book: s = theta/360, t = phi/360; front: s = theta/360 + 1/2, t = phi/360 + 1/2 (Exercise VI.2); "
              "mine: exercises/vi2_torus_front.cpp",
              'c');
    o.addEnum("pattern", &texture_, {"checker", "grid"}, "checker (Figure VI.6) or labelled grid (shows the centre)",
              'g');
    picture_.addOption(o, "the pattern");
    camera_.addOptions(o);
    o.addBool("marker", &marker_, "mark the texture centre (1/2, 1/2) on the torus", 'm');
    o.addEnum("view", &view_, {"single", "compare"}, "single: texture | torus; compare: texture | book | front", 'v');
    // 0 = edge-on (the hole's far wall is hidden by the front of the ring),
    // 90 = straight down the axis.  The book's figure: about 35, well above
    // the 16.1° from which the book's centre can be seen
    // (torus::minTiltToSeeBookCentre).
    o.addFloat("tilt", &tilt_, 0.0f, 90.0f, "tilt towards the viewer, degrees (the hole's far wall shows above ~16)",
               '.', ',', 5.0f);
    o.addFloat("turn", &turn_, -180.0f, 180.0f, "turn about the torus's axis, degrees", ']', '[', 30.0f);
    o.addText("radii", &radiiText_, "major and minor radius \"R,r\" with 0 < r < R <= 10",
              [](const std::string& v) { parseRadii(v); });
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"vi6_torus",
         "Figure VI.6",
         "A checkerboard texture map (left) applied to a torus by s = theta/360, t = phi/360 (right), the torus "
         "tilted towards the viewer; the red cross marks where the texture's centre lands.",
         {"--mapping", "book", "--pattern", "checker", "--marker=on"},
         1024,
         512,
         "With s = theta/360, t = phi/360 the texture's centre lands at z = {centre_3d_z[book]} = -(R - r), on the "
         "far inner wall of the hole."},
        {"vi6_torus_centre",
         "Exercise VI.2",
         "Where the texture's centre (1/2, 1/2) lands. Middle: s = theta/360, t = phi/360 put it at theta = phi = 180 "
         "deg, (0, 0, -(R - r)), on the far inner wall of the hole. Right: s = theta/360 + 1/2, t = phi/360 + 1/2 "
         "put it at the front, (0, 0, R + r).",
         {"--view", "compare", "--pattern", "grid"},
         1280,
         520,
         "Adding 1/2 to s and t moves the texture's centre from z = {centre_3d_z[book]} to z = {centre_3d_z[front]} "
         "= R + r, the front."},
    };
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;

  static glm::dvec2 parseRadii(const std::string& text) {
    std::istringstream in(text);
    double R = 0, r = 0;
    char comma = 0;
    std::string rest;
    if (!(in >> R >> comma >> r) || comma != ',' || (in >> rest) || !std::isfinite(R) || !std::isfinite(r) ||
        !(r > 0) || !(r < R) || R > 10)
      throw ts::Error("--radii: '" + text + "' is not \"R,r\" with 0 < r < R <= 10");
    return {R, r};
  }

 private:
  struct Detail {
    std::map<int, Found> founds;  // mapping -> where the centre was found
    ts::student::Table mine;      // the student's (s, t) at the grid's angles (--mapping mine)
  };
  // Mine: the answer is the exercise's (the front), the (s, t) the student's.
  torus::Params params(Mapping m, const Detail* d = nullptr) const {
    glm::dvec2 rr = parseRadii(radiiText_);
    torus::Params p;
    p.R = rr.x;
    p.r = rr.y;
    p.mapping = m == kMine ? Mapping::Front : m;
    if (m == kMine && d && d->mine.ok())
      p.stOfAngles = [d](double th, double ph) {
        const std::vector<double>& st = d->mine.at({th, ph});
        return glm::dvec2(st[0], st[1]);
      };
    return p;
  }
  std::vector<Mapping> shownMappings() const {
    return view_ == 0 ? std::vector<Mapping>{Mapping(mapping_)} : std::vector<Mapping>{Mapping::Book, Mapping::Front};
  }
  // The camera, the same for the picture and the measurement.  Eye at
  // 5.2 / 1.4 (R + r) from the centre, 35° field: the whole ring fits with a
  // margin at any tilt and turn (straight down, the near rim is 0.4 closer).
  glm::mat4 projection() const { return glm::perspective(glm::radians(35.0f), 1.0f, 0.5f, 20.0f); }
  glm::mat4 modelview(const torus::Params& p) const {
    float d = float(torus::eyeDistance(p));
    glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -d));
    m = glm::rotate(m, glm::radians(tilt_), glm::vec3(1, 0, 0));  // the eye goes up: (0, sin, cos) -> +z
    return glm::rotate(m, glm::radians(-turn_), glm::vec3(0, 1, 0));
  }
  ts::TextureDesc picture() const {
    return picture_.orDefault(texture_ == 0 ? ts::checkerboard(256, 16) : ts::labelledGrid(512, 8));
  }
  // found: what measure() found for this mapping (null before it has).
  void addTorus(ts::Frame& f, const ts::Rect& vp, Mapping m, int tex, int scale, const Detail* d) const;
  void addTexture(ts::Frame& f, const ts::Rect& vp, int tex, int scale) const;

  int mapping_ = int(Mapping::Book), texture_ = 0, view_ = 0;
  bool marker_ = true;
  float tilt_ = 35.0f, turn_ = 0.0f;
  ts::UserTexture picture_;  // --texture FILE
  ts::OrbitCamera camera_;   // --yaw --pitch --zoom: the mouse
  std::string radiiText_ = "1,0.4";
};

void Torus::addTexture(ts::Frame& f, const ts::Rect& vp, int tex, int scale) const {
  ts::Panel p = ts::layout::texturePanel("texture_space", vp, tex, "texture");
  if (marker_) torus::views::markTextureCentre(f, p, scale);
  f.panels.push_back(p);
}

void Torus::addTorus(ts::Frame& f, const ts::Rect& vp, Mapping m, int tex, int scale, const Detail* d) const {
  torus::Params tp = params(m, d);
  const Found* found = d && d->founds.count(int(m)) ? &d->founds.at(int(m)) : nullptr;
  ts::Panel p;
  p.id = std::string("torus_") + kMappingNames[int(m)];
  p.viewport = vp;
  p.projection = projection();
  p.modelview = modelview(tp);
  camera_.apply(p);
  p.depthTest = true;
  // Light from the upper left in front, fixed to the viewer.
  glm::dvec3 toLight = glm::dvec3(glm::inverse(glm::mat3(p.modelview)) * glm::vec3(-0.4f, 0.6f, 1.0f));
  // The mesh's (s, t) (ts::torusMesh) become glTexCoord4f(s, t, 0, 1) in Renderer::draw.
  p.batches.push_back(ts::litMeshBatch(torus::mesh(tp), tex, toLight, 0.4, 0.6, "torus"));
  if (marker_) torus::views::markTorusCentre(f, p, tp, scale, found && !found->visible);
  f.panels.push_back(p);
}

ts::Frame Torus::build(int width, int height, const ts::Measurements& measured) const {
  ts::Frame f = ts::layout::blankFrame(width, height);
  int tex = f.addTexture(picture());
  const std::vector<Mapping> shown = shownMappings();
  const Detail* d = measured.detailAs<Detail>();
  // The texture, then one square torus panel per mapping, in a row (or a
  // column in a tall window): each with its mapping and the answer above,
  // the measurement below.
  namespace L = ts::layout;
  L::FlowSpec spec;
  spec.n = 1 + int(shown.size());
  spec.linesAbove = 2;
  spec.linesBelow = 1;
  spec.gap = 12;
  std::vector<L::Cell> cells = L::flow({6, 6, float(width) - 6, float(height) - 6}, spec);
  const L::Cell& tc = cells[0];
  const int texSide = std::max(1, tc.picture.w * 3 / 4);  // the texture a little smaller than the tori
  addTexture(f, L::centred(tc.picture, texSide, texSide), tex, tc.scale);
  L::caption(f, L::halves(tc.above).first, "texture", kWhite, tc.scale);
  // The crosses' key, under the texture (that cell has no measurement to show).
  if (marker_) L::legend(f, tc.below, {{torus::views::kMarker, "the texture's centre (1/2, 1/2)"}}, tc.scale);
  for (size_t k = 0; k < shown.size(); ++k) {
    const Mapping m = shown[k];
    const torus::Params tp = params(m, d);
    const L::Cell& c = cells[k + 1];
    const Found* found = d && d->founds.count(int(m)) ? &d->founds.at(int(m)) : nullptr;
    const auto [mapping, centre] = L::halves(c.above);
    if (m == kMine && !(d && d->mine.ok())) {  // not done yet, or it failed: say so, draw nothing
      L::caption(f, L::box(c.picture), d ? d->mine.failure : "asking the exercise checker for your (s, t) ...", kFailed,
                 c.scale);
      continue;
    }
    addTorus(f, c.picture, m, tex, c.scale, d);
    L::caption(f, mapping,
               m == kMine           ? ts::student::summary(measured)
               : m == Mapping::Book ? "s=theta/360, t=phi/360"
                                    : "s=theta/360+1/2, t=phi/360+1/2",
               kWhite, c.scale);
    // Where the texture's centre lands: the z measured on the render (the
    // claim's number), and what the exercise's answer says it should be.
    const std::string n = std::string("[") + kMappingNames[int(m)] + "]";
    // The claim's words too: where on the torus that z is.
    const L::Text should = m == Mapping::Book ? " = -(R - r): the hole's far wall" : " = R + r: the front";
    const bool seen = found && found->visible;
    L::caption(f, centre,
               seen ? "centre lands at z = " + L::measured(measured, "centre_3d_z" + n, "%.2f") + should
                    : "centre at z = " + L::given("z of the exercise's answer", torus::centrePoint(tp).z, "%.2f") +
                          should,
               seen ? kMeasured : kWhite, c.scale);
    if (found)
      L::caption(f, c.below,
                 seen ? "measured: " + L::measured(measured, "centre_distance_to_answer" + n, "%.3f") +
                            " from the answer"
                      : "measured: not visible from here",
                 kMeasured, c.scale);
  }
  return f;
}

// The centre is found in a texel-index render with the picture's camera, and
// a ray through it cast against the mesh (torus_measure.hpp).
ts::Measurements Torus::measure(ts::Renderer& r) {
  ts::Measurements out;
  Detail d;
  if (Mapping(mapping_) == kMine) {  // the student's (s, t) at the grid's angles (the checker runs it), then the checks
    const torus::Params g = params(kMine);
    std::vector<std::vector<double>> at;
    for (int i = 0; i < g.nu; ++i)
      for (int j = 0; j < g.nv; ++j) at.push_back({360.0 * i / g.nu, 360.0 * j / g.nv});
    d.mine = ts::student::table("torusST", at);
    ts::student::addTo(out, "vi2_torus_front", ts::student::check("vi2_torus_front"));
    if (!d.mine.ok()) return out.detail = d, out;
  }
  for (Mapping m : shownMappings()) {
    const torus::Params tp = params(m, &d), other = params(m == Mapping::Book ? Mapping::Front : Mapping::Book);
    Found fd = torus::find(r, tp, projection(), modelview(tp));
    d.founds[int(m)] = fd;
    const std::string n = std::string("[") + kMappingNames[int(m)] + "]";
    const glm::dvec3 answer = torus::centrePoint(tp);
    glm::mat4 mvp = projection() * modelview(tp);
    ts::Panel whole;
    whole.viewport = {0, 0, kMeasureSize, kMeasureSize};
    glm::vec2 projected = ts::panelToPixels(whole, mvp * glm::vec4(glm::vec3(answer), 1.0f));
    const double none = -1.0;
    out.push_back({"centre_visible" + n, fd.visible ? 1.0 : 0.0, "1 if the render shows texel (1/2,1/2)"});
    out.push_back({"centre_x_px" + n, fd.screen.x, "where it is, pixels of a 512x512 render (fitted)"});
    out.push_back({"centre_y_px" + n, fd.screen.y, "... (top-left origin)"});
    out.push_back({"centre_screen_error_px" + n, fd.visible ? glm::distance(fd.screen, glm::dvec2(projected)) : none,
                   "from the projection of the exercise's answer"});
    out.push_back({"centre_3d_x" + n, fd.point.x, "the torus point a ray through it hits"});
    out.push_back({"centre_3d_y" + n, fd.point.y, ""});
    out.push_back({"centre_3d_z" + n, fd.point.z, "answer: -(R - r) for book, R + r for front"});
    out.push_back({"centre_distance_to_answer" + n, fd.visible ? glm::distance(fd.point, answer) : none,
                   "from the exercise's answer"});
    out.push_back({"centre_distance_to_other" + n,
                   fd.visible ? glm::distance(fd.point, torus::centrePoint(other)) : none,
                   "from the other mapping's answer (should be far)"});
  }
  out.detail = d;
  return out;
}
}  // namespace

TS_REGISTER_SCENE(Torus);
