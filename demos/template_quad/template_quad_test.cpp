// demos/template_quad/template_quad_test.cpp — the template demo's claim,
// probed in its own figure's render (never against a stored image): near
// every texel centre the pixel is what the filter's equation gives at that
// pixel's centre (the texel's own colour, or within a pixel of it), and
// between two centres GL_NEAREST shows only the two texels' colours and
// GL_LINEAR a ramp of more.  The demo's measurements must agree with what
// the probes find.
//
// Tolerance.  The read-back pixel is the exact result rounded to 8 bits
// (half a step) and GL_LINEAR's weights are fixed point (llvmpipe: 1/256, up
// to 200/256 of a step for these two colours, 200 steps apart): within 2
// steps of the equation.  GL_NEAREST near a texel centre has no rounding: 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <tuple>

#include <glm/glm.hpp>

#include "common/core/image.hpp"
#include "common/core/textures.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::test::Demo;
using ts::test::value;

constexpr int kTexels = 8;  // the demo's texture: 8 x 8 texels, one check a texel
const ts::TextureDesc kTexture = ts::checkerboard(kTexels, kTexels, {40, 70, 160, 255}, {240, 190, 80, 255});

// The figure's render (labels off) and where its quad is on it (ts::Rect:
// top-left origin, as the image; t runs up).
struct Probe {
  ts::Image img;
  ts::Rect quad;
  // The pixel whose centre is nearest the point (s, t) of the quad.
  ts::Rgba at(double s, double t) const {
    return img.at(quad.x + int(s * quad.w), quad.y + quad.h - 1 - int(t * quad.h));
  }
};
Probe renderFigure(const std::string& filter) {
  Demo d("template_quad", {"--filter", filter});
  d.measure();
  ts::Frame f;
  Probe p{d.render(640, 560, &f), ts::test::panelOf(f, "quad").viewport};
  return p;
}

int stepsApart(ts::Rgba a, glm::dvec3 b) {
  return int(std::ceil(std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) - 1e-9));
}

// The texel (i, j) of the texture, clamped to its edge (GL_CLAMP_TO_EDGE), as doubles.
glm::dvec3 texel(int i, int j) {
  const ts::Rgba c = kTexture.image->at(std::clamp(i, 0, kTexels - 1), std::clamp(j, 0, kTexels - 1));
  return {c.r, c.g, c.b};
}

// The demo's equations (template_quad.cpp's header) at (s, t), u = s w, v = t h.
glm::dvec3 filtered(const std::string& filter, double s, double t) {
  const double u = s * kTexels, v = t * kTexels;
  if (filter == "nearest") return texel(int(std::floor(u)), int(std::floor(v)));
  const int i0 = int(std::floor(u - 0.5)), j0 = int(std::floor(v - 0.5));
  const double a = u - 0.5 - i0, b = v - 0.5 - j0;
  return (1 - a) * (1 - b) * texel(i0, j0) + a * (1 - b) * texel(i0 + 1, j0) + (1 - a) * b * texel(i0, j0 + 1) +
         a * b * texel(i0 + 1, j0 + 1);
}

TEST(TemplateQuad, PixelsNearTexelCentresAreTheFiltersEquation) {
  for (const char* filter : {"nearest", "linear"}) {
    SCOPED_TRACE(filter);
    const Probe p = renderFigure(filter);
    const int tolerance = std::string(filter) == "nearest" ? 0 : 2;
    for (int j = 0; j < kTexels; ++j)
      for (int i = 0; i < kTexels; ++i) {
        // The pixel nearest texel (i, j)'s centre, and its own centre's (s, t).
        const int x = p.quad.x + int((i + 0.5) / kTexels * p.quad.w);
        const int y = p.quad.y + p.quad.h - 1 - int((j + 0.5) / kTexels * p.quad.h);
        const double s = (x + 0.5 - p.quad.x) / p.quad.w, t = (p.quad.y + p.quad.h - y - 0.5) / p.quad.h;
        EXPECT_LE(stepsApart(p.img.at(x, y), filtered(filter, s, t)), tolerance) << "texel " << i << "," << j;
      }
  }
}

// The row through the centres of texels (3, 4) and (4, 4): the colours met
// from one centre to the other, in the figure and in the demo's measurement.
TEST(TemplateQuad, NearestKeepsTwoColoursAcrossAnEdgeAndLinearRamps) {
  Demo d("template_quad", {});
  const ts::Measurements m = d.measure();
  for (const char* filter : {"nearest", "linear"}) {
    SCOPED_TRACE(filter);
    const Probe p = renderFigure(filter);
    const double t = 4.5 / kTexels;
    const int x0 = p.quad.x + int(3.5 / kTexels * p.quad.w), x1 = p.quad.x + int(4.5 / kTexels * p.quad.w);
    std::set<std::tuple<int, int, int>> colours;
    for (int x = x0; x <= x1; ++x) {
      const ts::Rgba c = p.at(double(x - p.quad.x) / p.quad.w, t);
      colours.insert({c.r, c.g, c.b});
    }
    if (std::string(filter) == "nearest") {
      // Exactly texel (3,4)'s and texel (4,4)'s colours, as the texture holds them.
      std::set<std::tuple<int, int, int>> texels;
      for (int i : {3, 4}) texels.insert({int(texel(i, 4).r), int(texel(i, 4).g), int(texel(i, 4).b)});
      EXPECT_EQ(colours, texels);
      EXPECT_EQ(value(m, "edge_colours[nearest]"), double(texels.size()));
    } else {
      // A ramp: more colours than the two texels', about one a pixel.
      EXPECT_GT(colours.size(), size_t(x1 - x0) / 2);
      EXPECT_GT(value(m, "edge_colours[linear]"), 2);
    }
    EXPECT_LE(value(m, std::string("centre_error[") + filter + "]"), 1);
  }
}
}  // namespace
