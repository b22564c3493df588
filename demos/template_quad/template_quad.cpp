// The template demo: one textured quad, magnified, and the magnification
// filter that fills the pixels between its texels.  Copy this folder to start
// a demo (README, "Adding a demo").
//
// The claim (Red Book, "Filtering"; GL 2.1 section 3.8.8): when a texel
// covers many pixels, GL_TEXTURE_MAG_FILTER decides what the pixels between
// texel centres show.  At a texel's centre both filters give the texel's own
// colour.  Between two centres GL_NEAREST shows exactly the two texels'
// colours, a hard edge; GL_LINEAR shows a ramp, one colour per pixel.
//
// Keys (each is also a flag, see --help):
//   f  GL_TEXTURE_MAG_FILTER: GL_NEAREST | GL_LINEAR
//
// The equations, for a w x h texture T and texture coordinates (s, t):
// u = s w, v = t h.
//   GL_NEAREST  C = T[floor(u), floor(v)]
//   GL_LINEAR   i0 = floor(u - 1/2), a = frac(u - 1/2) (j0, b the same of v),
//               C = (1-a)(1-b) T[i0,j0] + a(1-b) T[i0+1,j0] + (1-a)b T[i0,j0+1] + ab T[i0+1,j0+1]
// On the row through texel centres (b = 0) GL_LINEAR is (1-a) T[i0] + a T[i0+1]:
// as many colours across an edge as pixels between the two centres.
//
// What the GL does, all in common/gl/render.cpp: Renderer::texture makes
//   glGenTextures(1, &tex); glBindTexture(GL_TEXTURE_2D, tex);
//   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
//   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST or GL_LINEAR);
//   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S / _T, GL_CLAMP_TO_EDGE);
// and Renderer::draw sends the quad as glBegin(GL_TRIANGLES) of six
// glTexCoord4f(s, t, 0, 1) + glVertex3f.  Listing: book_figures/template_quad.gl.txt.
//
// Measured (measure()): the quad rendered offscreen at 15 pixels a texel, so
// that a pixel centre falls on every texel centre, with each filter: the
// largest difference (8-bit steps) between a texel-centre pixel and its
// texel's colour, and the distinct colours on the row from one texel's
// centre to the next one's.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <string>
#include <tuple>

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/gl/render.hpp"

namespace {
constexpr int kTexels = 8;           // the texture is kTexels x kTexels, one check a texel
constexpr int kPixelsPerTexel = 15;  // odd: the measurement's pixel centres fall on texel centres
const char* const kFilterNames[] = {"nearest", "linear"};
const char* const kFilterGL[] = {"GL_NEAREST", "GL_LINEAR"};

// The texture: an 8 x 8 checkerboard of two colours far apart in every
// channel, so a blend of them is a colour of its own.
ts::TextureDesc quadTexture(int filter) {
  ts::TextureDesc t = ts::checkerboard(kTexels, kTexels, {40, 70, 160, 255}, {240, 190, 80, 255});
  t.magFilter = filter == 1 ? GL_LINEAR : GL_NEAREST;
  t.minFilter = GL_NEAREST;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}

// The quad over the whole panel, (s, t) from 0 to 1 (ts::layout::unitPanel: x, y from 0 to 1).
ts::Panel quadPanel(const std::string& id, const ts::Rect& viewport, int texture) {
  ts::Panel p = ts::layout::unitPanel(id, viewport);
  ts::Batch b;
  b.role = "surface";
  b.texture = texture;
  for (int k : {0, 1, 2, 0, 2, 3}) {
    const glm::vec2 c(k == 1 || k == 2, k >= 2);
    b.vertices.push_back({{c, 0.0f}, {c, 0.0f, 1.0f}, {1, 1, 1, 1}});
  }
  p.batches.push_back(b);
  return p;
}

class TemplateQuad final : public ts::Scene {
 public:
  std::string id() const override { return "template_quad"; }
  std::string title() const override { return "The template: a textured quad and its magnification filter"; }
  std::string about() const override {
    return "An 8x8 checkerboard magnified on a quad, with GL_TEXTURE_MAG_FILTER GL_NEAREST or GL_LINEAR.  Measured:\n"
           "the colour at every texel centre against the texel's, and the colours between two centres (GL_NEAREST:\n"
           "the two texels'; GL_LINEAR: a ramp, one colour a pixel).";
  }
  std::vector<std::string> claim() const override { return {"edge_colours[nearest]", "edge_colours[linear]"}; }
  void addOptions(ts::Options& o) override {
    o.addEnum("filter", &filter_, {"nearest", "linear"}, "GL_TEXTURE_MAG_FILTER of the quad's texture", 'f');
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"template_quad",
         "Template (magnification filter)",
         "An 8x8 checkerboard on a quad, each texel magnified to many pixels, with GL_TEXTURE_MAG_FILTER GL_LINEAR: "
         "between two texel centres the colour ramps from one texel to the other; GL_NEAREST (key f) keeps "
         "each texel's colour up to the edge.",
         {"--filter", "linear"},
         640,
         560,
         "Across a texel edge GL_NEAREST shows {edge_colours[nearest]} colours, GL_LINEAR "
         "{edge_colours[linear]}; texel centres are {centre_error[linear]} steps from their texel."}};
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;

 private:
  int filter_ = 0;
};

ts::Frame TemplateQuad::build(int width, int height, const ts::Measurements& measured) const {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(width, height);
  L::FlowSpec spec;
  spec.n = 1, spec.linesAbove = 1, spec.linesBelow = 2;
  const L::Cell c = L::flow({6, 6, float(width) - 6, float(height) - 6}, spec)[0];
  f.panels.push_back(quadPanel("quad", c.picture, f.addTexture(quadTexture(filter_))));
  L::caption(f, c.above,
             std::string("glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, ") + kFilterGL[filter_] + ")",
             L::kWhite, c.scale);
  // The numbers printed come from the measurement (measuredText names each), and the one given number says
  // what it is (L::given), so the sidecar holds the source of every number on the figure.
  const std::string shown = kFilterNames[filter_];
  L::caption(f, c.below,
             "measured at " + L::given("pixels a texel in the measurement", kPixelsPerTexel, "%.0f") +
                 " pixels a texel: " +
                 L::measuredText(measured, "{edge_colours[nearest]|%.0f} colours from one texel centre to the next "
                                           "with GL_NEAREST, {edge_colours[linear]|%.0f} with GL_LINEAR; at the "
                                           "centres {centre_error[" +
                                               shown + "]|%.0f} steps (8-bit) from the texel"),
             L::kAmber, c.scale);
  return f;
}

// Both filters, whichever the key chose: the claim is the difference.
ts::Measurements TemplateQuad::measure(ts::Renderer& r) {
  ts::Measurements out;
  for (int filter = 0; filter < 2; ++filter) {
    const int n = kTexels * kPixelsPerTexel;
    ts::Frame f;
    f.width = f.height = n;
    const ts::TextureDesc tex = quadTexture(filter);
    f.panels.push_back(quadPanel("quad", {0, 0, n, n}, f.addTexture(tex)));
    const ts::Image img = r.renderOffscreen(f);  // row 0 at the top
    // Texel (i, j)'s centre (j = 0 at t = 0, the bottom) is pixel (x, y) below, from the top.
    auto centreX = [](int i) { return kPixelsPerTexel * i + kPixelsPerTexel / 2; };
    auto centreY = [&](int j) { return n - 1 - centreX(j); };
    int worst = 0;
    for (int j = 0; j < kTexels; ++j)
      for (int i = 0; i < kTexels; ++i) {
        const ts::Rgba p = img.at(centreX(i), centreY(j)), t = tex.image->at(i, j);
        worst = std::max({worst, std::abs(p.r - t.r), std::abs(p.g - t.g), std::abs(p.b - t.b)});
      }
    // The row through the centres of texels (3, 4) and (4, 4), from one centre to the other.
    std::set<std::tuple<int, int, int>> colours;
    for (int x = centreX(3); x <= centreX(4); ++x) {
      const ts::Rgba p = img.at(x, centreY(4));
      colours.insert({p.r, p.g, p.b});
    }
    const std::string name = kFilterNames[filter];
    out.push_back({"edge_colours[" + name + "]", double(colours.size()),
                   std::string("distinct colours from one texel centre to the next with ") + kFilterGL[filter]});
    out.push_back({"centre_error[" + name + "]", double(worst),
                   "largest difference (8-bit steps) between a texel-centre pixel and its texel's colour"});
  }
  return out;
}
}  // namespace

TS_REGISTER_SCENE(TemplateQuad);
