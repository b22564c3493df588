// Figure VI.1 — a quadrilateral region of a checkerboard drawn on a square.
//
// The claim (Buss, VI.1.1): a quad is drawn as two triangles and each one
// interpolates (s, t) linearly, so when the (s, t) corners do not form a
// parallelogram the two triangles map the texture differently and the
// checker lines bend along the diagonal.  The bend depends on which diagonal
// splits the quad, and vanishes with bilinear interpolation over the quad or
// with projective texture coordinates (s, t, r, q).
//
// Left: texture space — the whole checkerboard, the region in red, the image
// of the screen diagonal in orange.  Right: screen space — the square.
//
// Keys (each is also a flag, see --help):
//   d  which diagonal splits the square (tl-br as in the book, or bl-tr)
//   i  interpolation: affine triangles | bilinear (GLSL) | projective (s,t,r,q)
//   e  draw the triangle edges
//   v  view: the book's figure | the four variants side by side
//   f  texture filter nearest | linear      + / -  checks per side
//
// What the GL does: common/gl/render.cpp: Renderer::draw sends the square as
// one glBegin(GL_TRIANGLES) of six glTexCoord4f(s, t, 0, 1) + glVertex3f
// (addSquare below), and GL interpolates (s, t) linearly in each triangle.
// Projective: glTexCoord4f(s·q, t·q, 0, q) from quad_distortion_math.hpp's homography,
// divided by q per pixel.  Bilinear: a GLSL program, texture2D(tex,
// mix(bottom, top, ab.y)), the corners sent by glUniform4f.  Listings:
// book_figures/vi1_quad_distortion.gl.txt, vi1_quad_variants.gl.txt.
//
// Measured: the kink — the angle between the checker lines on the two sides
// of the diagonal, fitted from a render that shows which texel each pixel
// took — next to the angle the math predicts.
#include <cmath>
#include <map>

#include "common/core/layout.hpp"
#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "common/core/user_texture.hpp"
#include "quad_distortion_math.hpp"
#include "quad_distortion_measure.hpp"  // the kink fitted from a texel-index render
#include "quad_distortion_views.hpp"    // the texture-space view and the corner labels

namespace {
using quad::Diagonal;

enum Interp { kAffine, kBilinear, kProjective };
const char* const kInterpNames[] = {"affine", "bilinear", "projective"};
const char* const kDiagNames[] = {"tl-br", "bl-tr"};

// Bilinear is beyond fixed function: the vertices carry the square's (a, b) (affine, so exact per
// triangle), the shader blends the corners' (s, t) by them.  GLSL 1.20: softpipe runs it too.
const char* const kBilinearVS = R"(#version 120
void main() {
  gl_TexCoord[0] = gl_MultiTexCoord0;   // (a, b) in [0,1]^2
  gl_Position = ftransform();
})";
const char* const kBilinearFS = R"(#version 120
uniform sampler2D tex;
uniform vec4 st00_st10;  // (s,t) at corner (0,0) and (1,0)
uniform vec4 st11_st01;  // (s,t) at corner (1,1) and (0,1)
void main() {
  vec2 ab = gl_TexCoord[0].xy;
  vec2 bottom = mix(st00_st10.xy, st00_st10.zw, ab.x);   // along b = 0
  vec2 top    = mix(st11_st01.zw, st11_st01.xy, ab.x);   // along b = 1
  gl_FragColor = texture2D(tex, mix(bottom, top, ab.y));
})";

class QuadDistortion final : public ts::Scene {
 public:
  std::string id() const override { return "quad_distortion"; }
  std::string title() const override { return "Figure VI.1 - quadrilateral distortion"; }
  std::string about() const override {
    return "A non-parallelogram region of a checkerboard, chosen by (s,t) at the corners of a square, drawn on\n"
           "that square as two triangles: each triangle's map is affine, so checker lines bend at the diagonal.\n"
           "Prints the bend measured from the render and the bend the math predicts.";
  }
  std::vector<std::string> claim() const override { return {"kink_deg*"}; }
  void addOptions(ts::Options& o) override {
    o.addEnum("diagonal", &diagonal_, {kDiagNames[0], kDiagNames[1]},
              "which diagonal splits the square (the book: tl-br)", 'd');
    o.addEnum("interp", &interp_, {kInterpNames[0], kInterpNames[1], kInterpNames[2]},
              "affine triangles, bilinear over the quad (GLSL), or projective (s,t,r,q)", 'i');
    o.addBool("edges", &edges_, "draw the two triangles' edges", 'e');
    o.addEnum("view", &view_, {"book", "compare"}, "book: texture | square; compare: four variants", 'v');
    o.addEnum("filter", &filter_, {"nearest", "linear"}, "texture magnification filter", 'f');
    o.addInt("checks", &checks_, 2, 32, "checks along each side of the texture", '+', '-');
    picture_.addOption(o, "the checkerboard");
    o.addText("corners", &cornersText_, "(s,t) at the square's corners (0,0) (1,0) (1,1) (0,1): \"s,t s,t s,t s,t\"",
              [](const std::string& v) { quad::parseCorners(v); });
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"vi1_quad_distortion",
         "Figure VI.1",
         "The texture with the region chosen by the (s,t) corners (left) and that region drawn on a square as two "
         "linearly mapped triangles (right): the checker lines bend along the diagonal.",
         {"--view", "book", "--diagonal", "tl-br", "--interp", "affine"},
         1024,
         560,
         "Two linearly mapped triangles bend the checker lines by {kink_deg[affine_tl_br]} deg along the diagonal."},
        {"vi1_quad_variants",
         "Figure VI.1 (variants)",
         "The same region four ways: split along either diagonal (the kink moves and changes), bilinear "
         "interpolation of (s,t) over the quad, and projective (s,t,r,q) coordinates (no kink).",
         {"--view", "compare", "--edges"},
         1280,
         376,
         "Split along the other diagonal the kink changes ({kink_deg[affine_tl_br]} -> {kink_deg[affine_bl_tr]} "
         "deg); bilinear and projective (s,t,r,q) remove it ({kink_deg[bilinear]}, {kink_deg[projective]} deg)."},
    };
  }
  ts::Measurements measure(ts::Renderer& r) override;
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;

  // Public for the tests: the texel-index render of one variant.
  struct Variant {
    Diagonal diagonal;
    Interp interp;
  };
  quad::Corners corners() const { return quad::parseCorners(cornersText_); }
  // The variants the view shows: the current one (book), or both diagonals and then the two fixes (compare).
  std::vector<Variant> shown() const {
    if (view_ == 0) return {{Diagonal(diagonal_), Interp(interp_)}};
    return {{Diagonal::TopLeftBottomRight, kAffine},
            {Diagonal::BottomLeftTopRight, kAffine},
            {Diagonal(diagonal_), kBilinear},
            {Diagonal(diagonal_), kProjective}};
  }

 private:
  // The square with `interp` applied, as batches in a unit-square panel.
  void addSquare(ts::Frame& f, ts::Panel& p, Variant v, int texture, bool edges) const;
  ts::TextureDesc checker() const {
    ts::TextureDesc t = ts::checkerboard(256, checks_);
    t.minFilter = t.magFilter = filter_ == 0 ? GL_NEAREST : GL_LINEAR;
    return picture_.orDefault(t);
  }
  double measureKink(ts::Renderer& r, Variant v, double* texelError);
  // The bend the math predicts: closed form for the affine split, the same
  // angle measured on the analytic map for the others (smooth: about 0).
  double predicted(Variant v) const {
    const quad::Corners st = corners();
    if (v.interp == kAffine) return quad::predictedKinkDeg(st, v.diagonal);
    return quad::kinkAcrossDiagonalDeg([&](glm::dvec2 p) { return analytic(st, v, p); }, v.diagonal);
  }
  // The corners come parsed (corners()) by the caller: this runs once a pixel.
  static glm::dvec2 analytic(const quad::Corners& st, Variant v, glm::dvec2 p) {
    if (v.interp == kBilinear) return quad::bilinear(st, p);
    if (v.interp == kProjective) return quad::projective(quad::homography(st), p);
    return quad::split(st, v.diagonal).at(p, v.diagonal)(p);
  }

  int diagonal_ = 0, interp_ = kAffine, view_ = 0, filter_ = 1, checks_ = 8;
  bool edges_ = false;
  std::string cornersText_ = "0,0 1,0 0.75,0.75 0,1";  // the book's labels
  ts::UserTexture picture_;                            // --texture FILE
  using Kinks = std::map<std::string, double>;         // variant name -> measured kink: measure()'s detail
};

std::string variantName(const QuadDistortion::Variant& v) {
  return v.interp == kAffine ? std::string("affine ") + kDiagNames[int(v.diagonal)] : kInterpNames[v.interp];
}
// The key of a variant's measurements: its name with spaces and dashes made '_' (kink_deg[affine_tl_br]).
std::string variantKey(const QuadDistortion::Variant& v) {
  std::string key = variantName(v);
  for (char& c : key)
    if (c == ' ' || c == '-') c = '_';
  return "[" + key + "]";
}

void QuadDistortion::addSquare(ts::Frame& f, ts::Panel& p, Variant v, int texture, bool edges) const {
  quad::Corners st = corners();
  const auto& P = quad::squareCorners();
  // Vertex order of the two triangles for each diagonal.
  const int tlbr[6] = {0, 1, 3, 1, 2, 3}, bltr[6] = {0, 1, 2, 0, 2, 3};
  const int* idx = v.diagonal == Diagonal::TopLeftBottomRight ? tlbr : bltr;
  ts::Batch b;
  b.role = "surface";
  b.texture = texture;
  glm::dmat3 H = quad::homography(st);
  for (int k = 0; k < 6; ++k) {
    int i = idx[k];
    ts::Vertex vert;
    vert.pos = glm::vec3(glm::vec2(P[size_t(i)]), 0.0f);
    // vert.tex becomes glTexCoord4f(s, t, 0, 1), (a, b, 0, 1) or (s·q, t·q, 0, q) in Renderer::draw
    switch (v.interp) {
      case kAffine: vert.tex = glm::vec4(glm::vec2(st[size_t(i)]), 0, 1); break;
      case kBilinear: vert.tex = glm::vec4(glm::vec2(P[size_t(i)]), 0, 1); break;  // (a, b); shader maps
      case kProjective: vert.tex = glm::vec4(quad::projectiveTexCoord(H, P[size_t(i)])); break;
    }
    b.vertices.push_back(vert);
  }
  if (v.interp == kBilinear) {
    b.program = "bilinear_quad";
    b.uniforms = {{"st00_st10", glm::vec4(glm::vec2(st[0]), glm::vec2(st[1]))},
                  {"st11_st01", glm::vec4(glm::vec2(st[2]), glm::vec2(st[3]))}};
    bool have = false;
    for (const auto& pr : f.programs) have |= pr.first == "bilinear_quad";
    if (!have)
      f.programs.push_back({"bilinear_quad", {"demos/quad_distortion/quad_distortion.cpp", kBilinearVS, kBilinearFS}});
  }
  p.batches.push_back(b);
  if (edges) {
    glm::vec2 d0 = v.diagonal == Diagonal::TopLeftBottomRight ? glm::vec2(0, 1) : glm::vec2(0, 0);
    glm::vec2 d1 = v.diagonal == Diagonal::TopLeftBottomRight ? glm::vec2(1, 0) : glm::vec2(1, 1);
    p.batches.push_back(ts::lineSegments({d0, d1}, quad::views::kDiagonal, 2.0f, "diagonal"));
    p.batches.push_back(ts::lineLoop({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, quad::views::kDiagonal, 2.0f, "edges"));
  }
}

using ts::layout::fmt;

ts::Frame QuadDistortion::build(int width, int height, const ts::Measurements& measured) const {
  ts::Frame f = ts::layout::blankFrame(width, height);
  int checker = f.addTexture(this->checker());
  const glm::vec4 &white = ts::layout::kWhite, &amber = ts::layout::kAmber;
  Variant current{Diagonal(diagonal_), Interp(interp_)};
  const Kinks none, &kinks = measured.detailAs<Kinks>() ? *measured.detailAs<Kinks>() : none;
  namespace L = ts::layout;
  const float margin = 8;
  const L::Box all{margin, margin, float(width) - margin, float(height) - margin};
  if (view_ == 0) {
    // The book's layout: texture left, square right (one above the other when tall), kink underneath.
    std::string name = variantName(current);
    const bool haveKink = kinks.count(name) > 0;
    const std::string key = variantKey(current);
    const L::Text kink = haveKink
                             ? "kink along the diagonal: " + L::measured(measured, "kink_deg" + key, "%.1f") +
                                   " deg (predicted " + L::measured(measured, "kink_predicted_deg" + key, "%.1f") + ")"
                             : L::Text();
    L::FlowSpec spec;
    spec.n = 2;
    spec.linesAbove = 2;                       // title, top corners
    spec.linesBelow = (haveKink ? 2 : 1) + 1;  // bottom corners (and the kink), the colours' key under the last
    spec.gap = 16;
    std::vector<L::Cell> cells = L::flow(all, spec);
    ts::Panel left = L::unitPanel("texture_space", cells[0].picture),
              right = L::unitPanel("screen_space", cells[1].picture);
    // The texture, the corners' region and the screen diagonal's image (quad_distortion_views.hpp; the affine
    // split's along its first triangle).
    const quad::Corners st = corners();
    const quad::Split sp = quad::split(st, current.diagonal);
    quad::views::addTextureView(left, st, current.diagonal, checker, [&](glm::dvec2 q) {
      return current.interp == kAffine ? sp.first(q) : analytic(st, current, q);
    });
    addSquare(f, right, current, checker, edges_);
    f.panels = {left, right};
    const std::string titles[2] = {"texture space: the region", "screen space: " + name};
    for (int k = 0; k < 2; ++k) {
      const L::Cell& c = cells[size_t(k)];
      L::caption(f, {c.above.x0, c.above.y0, c.above.x1, c.above.y1 - L::lineHeight(c.scale)}, titles[k], white,
                 c.scale);
      quad::views::cornerLabels(f, c, st, k == 1);
    }
    // The kink, then the key of the marks' colours: under the pictures, across the window.
    const L::Cell& c = cells[1];
    const float bottom = std::max(cells[0].below.y1, cells[1].below.y1), line = L::lineHeight(c.scale);
    L::caption(f, {all.x0, bottom - 2 * line, all.x1, bottom - line}, kink, amber, c.scale);
    std::vector<ts::LegendEntry> colours{{quad::views::kRegion, "the region the corners' (s,t) select"},
                                         {quad::views::kDiagonal, edges_ ? "the diagonal (screen), its image (texture)"
                                                                         : "the screen diagonal's image"}};
    L::legend(f, {cells[0].below.x0, bottom - line, all.x1, bottom}, colours, c.scale);
  } else {
    // The four variants: both diagonals, then the two fixes.
    const std::vector<Variant> vs = shown();
    L::FlowSpec spec;
    spec.n = 4;
    spec.gap = 16;
    spec.minCellWidth = ts::text::width("kink 18.4 deg", 1) + 4;
    // The key of the triangles' edges under the pictures (when they are drawn).
    const float keyH = edges_ ? L::lineHeight(1) : 0.0f;
    std::vector<L::Cell> cells = L::flow({all.x0, all.y0, all.x1, all.y1 - keyH}, spec);
    if (edges_) {  // under the last row of pictures
      float under = cells[0].below.y1;
      for (const L::Cell& c : cells) under = std::max(under, c.below.y1);
      L::legend(f, {cells[0].below.x0, under, all.x1, under + keyH},
                {{quad::views::kDiagonal, "the affine variants' triangles: edges and shared diagonal"}}, 1);
    }
    for (int k = 0; k < 4; ++k) {
      const L::Cell& c = cells[size_t(k)];
      ts::Panel p = L::unitPanel("variant_" + std::to_string(k), c.picture);
      addSquare(f, p, vs[size_t(k)], checker, edges_ && vs[size_t(k)].interp == kAffine);
      f.panels.push_back(p);
      std::string name = variantName(vs[size_t(k)]);
      L::caption(f, c.above, name, white, c.scale);
      if (kinks.count(name))
        L::caption(f, c.below, "kink " + L::measured(measured, "kink_deg" + variantKey(vs[size_t(k)]), "%.1f") + " deg",
                   amber, c.scale);
    }
  }
  return f;
}

// The measurement: the square drawn again, full-frame, texel (i, j) holding R = i, G = j
// (GL_NEAREST); the kink fitted from the texels taken either side of the diagonal (quad_distortion_measure.hpp).
double QuadDistortion::measureKink(ts::Renderer& r, Variant v, double* texelError) {
  const int N = 512;  // the same at any figure or window size
  ts::Frame mf;
  mf.width = mf.height = N;
  const int T = 2048;  // 2048 texels across 512 pixels: each pixel's texel is known to 1/4 pixel
  int tex = mf.addTexture(ts::texelIndexTexture(T));
  ts::Panel p = ts::layout::unitPanel("texel_index", {0, 0, N, N});
  addSquare(mf, p, v, tex, false);
  mf.panels.push_back(p);
  ts::Image img = r.renderOffscreen(mf);
  const quad::Corners st = corners();
  return quad::kinkDeg(
      img, T, v.diagonal, [&](glm::dvec2 ab) { return analytic(st, v, ab); }, texelError);
}

ts::Measurements QuadDistortion::measure(ts::Renderer& r) {
  Variant current{Diagonal(diagonal_), Interp(interp_)};
  ts::Measurements out;
  Kinks kinks;
  for (const Variant& v : shown()) {
    double texelError = 0;
    double kink = measureKink(r, v, &texelError);
    std::string name = variantName(v);
    kinks[name] = kink;
    const std::string key = variantKey(v);
    out.push_back({"kink_deg" + key, kink, "measured angle between checker lines across the diagonal"});
    out.push_back({"kink_predicted_deg" + key, predicted(v),
                   "the same angle from the analytic maps (closed form for the affine split)"});
    out.push_back({"texel_error_max" + key, texelError,
                   "largest distance (texels of 2048) between the texel taken and the analytic one"});
  }
  out.push_back({"split_disagreement_texels", quad::splitDisagreement(corners(), current.diagonal) * 256.0,
                 "how far apart the two triangles' maps put one point (256 texels)"});
  out.detail = kinks;
  return out;
}
}  // namespace

TS_REGISTER_SCENE(QuadDistortion);
