// tests/figures/fig_inspect_footprints_test.cpp — the "inside a pixel"
// figures (--inspect X,Y --footprints, common/app/inspect_view.hpp), drawn
// as make_figures draws them, held to what the figure claims to show:
//   * its picture is the picks' panel drawn again pixel for pixel, not a
//     cut-out of the rendered figure: at each ring's centre the figure shows
//     the colour GL drew at that pick, and none of the inspected figure's
//     captions is in it;
//   * no text is cut ("..."), leaves the figure, crosses the edge of a
//     picture or overlaps other text (the picks' numbers included);
//   * the legend names every colour a mark is drawn in, and each colour it
//     names shows in the pictures (outside the legend's own swatches);
//   * every number printed is a measurement, whose value formats to the
//     text printed, or a given number (the pick's).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/app/inspect_view.hpp"
#include "common/core/layout.hpp"
#include "common/core/options.hpp"
#include "common/gl/figure.hpp"
#include "tests/support/gl_test.hpp"

namespace {
namespace L = ts::layout;

struct Drawn {
  ts::Rendered before;  // the inspected picture
  ts::Rendered after;   // the footprint figure
  std::vector<std::array<int, 2>> picks;
};

// The figure `id` of demo `demo`, as make_figures renders it.
const Drawn& figure(const std::string& demo, const std::string& id) {
  static std::map<std::string, Drawn> cache;
  auto it = cache.find(id);
  if (it != cache.end()) return it->second;
  std::unique_ptr<ts::Scene> scene = ts::makeScene(demo);
  ts::Options o;
  scene->addOptions(o);
  for (const ts::FigureSpec& spec : scene->figures()) {
    if (spec.id != id) continue;
    ts::CommonFlags common;
    o.parse(ts::sceneFlags(spec.flags, &common));
    Drawn d;
    d.picks = common.inspect;
    d.before = ts::renderScene(*scene, ts::test::renderer(), spec.width, spec.height);
    d.after = d.before;
    EXPECT_TRUE(common.footprints) << id;
    ts::applyInspect(demo, common, ts::test::renderer(), &d.after, false, nullptr);
    return cache.emplace(id, std::move(d)).first->second;
  }
  throw std::runtime_error(demo + " has no figure " + id);
}

struct Case {
  const char* demo;
  const char* id;
};
class Footprints : public ::testing::TestWithParam<Case> {
 protected:
  const Drawn& d() { return figure(GetParam().demo, GetParam().id); }
};

int maxDiff(ts::Rgba a, ts::Rgba b) {
  return std::max({std::abs(int(a.r) - b.r), std::abs(int(a.g) - b.g), std::abs(int(a.b) - b.b)});
}

TEST_P(Footprints, ThePictureIsThePicksPanelDrawnAgainPixelForPixel) {
  const ts::Frame& f = d().after.frame;
  const ts::Panel* marks = f.panel("picks");
  ASSERT_TRUE(marks);
  std::vector<glm::vec2> centres;
  for (const ts::Batch& b : marks->batches) {
    if (b.role != "pick") continue;
    glm::vec2 c(0.0f);
    for (const ts::Vertex& v : b.vertices) c += glm::vec2(v.pos) / float(b.vertices.size());
    centres.push_back(c);
  }
  // Every pick of these figures lies in one panel: each is ringed.
  ASSERT_EQ(centres.size(), d().picks.size());
  for (size_t k = 0; k < centres.size(); ++k) {
    const auto [x, y] = d().picks[k];
    const ts::Rgba gl = d().before.image.at(x, y), shown = d().after.image.at(int(centres[k].x), int(centres[k].y));
    // The same pixel centre through the same (narrowed) projection, in the
    // same 2 x 2 quad: the same colour, up to float rounding of the matrix
    // product.
    std::printf("[footprints] %s pick %zu at %d,%d: GL drew (%d,%d,%d), the figure shows (%d,%d,%d)\n", GetParam().id,
                k + 1, x, y, gl.r, gl.g, gl.b, shown.r, shown.g, shown.b);
    EXPECT_LE(maxDiff(gl, shown), 2) << "pick " << k + 1 << " at " << x << "," << y;
  }
  // Drawn from the panel's own data: every texture is one the inspected
  // figure's panels read (the cells read level 0 of the same ones), none a
  // picture of the rendered figure, whose captions it would carry.
  for (const ts::TextureDesc& t : f.textures)
    EXPECT_TRUE(std::any_of(d().before.frame.textures.begin(), d().before.frame.textures.end(),
                            [&](const ts::TextureDesc& o) { return o.name == t.name && o.params == t.params; }))
        << "the figure shows a texture the inspected picture does not have: " << t.name;
}

TEST_P(Footprints, NoTextIsCutLeavesCrossesAPictureOrOverlaps) {
  const ts::Frame& f = d().after.frame;
  const L::Box window{0, 0, float(f.width), float(f.height)};
  for (size_t i = 0; i < f.labels.size(); ++i) {
    const ts::Label& l = f.labels[i];
    if (l.text.empty()) continue;
    const L::Box b = L::labelBox(l);
    EXPECT_EQ(l.text.find("..."), std::string::npos) << "cut: " << l.text;
    EXPECT_TRUE(b.inside(window)) << l.text;
    for (const ts::Panel& p : f.panels) {
      if (p.id == "picks") continue;  // the rings' overlay: the zone the numbers are placed in
      const L::Box pb = L::box(p.viewport);
      EXPECT_FALSE(b.overlaps(pb) && !b.inside(pb)) << "\"" << l.text << "\" crosses the edge of " << p.id;
    }
    for (size_t j = i + 1; j < f.labels.size(); ++j)
      if (!f.labels[j].text.empty())
        EXPECT_FALSE(b.overlaps(L::labelBox(f.labels[j]))) << "\"" << l.text << "\" and \"" << f.labels[j].text << "\"";
  }
  // Each ring has its number.
  const ts::Panel* marks = f.panel("picks");
  ASSERT_TRUE(marks);
  int numbered = 0;
  for (const ts::Label& l : f.labels)
    numbered += l.given.size() == 1 && l.given[0].first == "pick number" &&
                l.text == std::to_string(int(l.given[0].second));
  EXPECT_EQ(numbered, int(d().picks.size()));
}

bool sameColour(glm::vec4 a, glm::vec4 b) { return glm::length(a - b) < 1e-4f; }

TEST_P(Footprints, TheLegendNamesTheColoursDrawnAndOnlyThose) {
  const ts::Frame& f = d().after.frame;
  ASSERT_FALSE(f.legend.empty());
  // Every untextured mark's colour is named.
  std::vector<glm::vec4> marks;
  for (const ts::Panel& p : f.panels)
    for (const ts::Batch& b : p.batches)
      if (b.texture < 0 && !b.vertices.empty()) marks.push_back(b.vertices[0].color);
  for (const glm::vec4& c : marks)
    EXPECT_TRUE(
        std::any_of(f.legend.begin(), f.legend.end(), [&](const ts::LegendEntry& e) { return sameColour(e.color, c); }))
        << "a mark drawn in (" << c.r << ", " << c.g << ", " << c.b << ") is not in the legend";
  // Every colour named shows in a picture: a pixel of that colour in a
  // panel other than the legend's own swatches, outside every label's box.
  const ts::Image& img = d().after.image;
  std::vector<L::Box> text;
  for (const ts::Label& l : f.labels) text.push_back(L::labelBox(l));
  for (const ts::LegendEntry& e : f.legend) {
    const ts::Rgba want{uint8_t(std::lround(e.color.r * 255)), uint8_t(std::lround(e.color.g * 255)),
                        uint8_t(std::lround(e.color.b * 255)), 255};
    int found = 0;
    for (const ts::Panel& p : f.panels)
      for (int y = p.viewport.y; p.id != "legend_swatch" && y < p.viewport.y + p.viewport.h; ++y)
        for (int x = p.viewport.x; x < p.viewport.x + p.viewport.w; ++x) {
          const L::Box px{float(x), float(y), float(x + 1), float(y + 1)};
          if (maxDiff(img.at(x, y), want) > 1 ||
              std::any_of(text.begin(), text.end(), [&](const L::Box& b) { return b.overlaps(px); }))
            continue;
          ++found;
        }
    EXPECT_GT(found, 0) << "the legend names \"" << e.meaning << "\", whose colour shows nowhere";
  }
}

TEST_P(Footprints, EveryNumberPrintedIsAMeasurementOrGiven) {
  const ts::Frame& f = d().after.frame;
  const ts::Measurements& m = d().after.measurements;
  int printed = 0;
  for (const ts::Label& l : f.labels) {
    std::string rest = l.text;
    for (const ts::Label::Printed& p : l.printed) {
      auto it = std::find_if(m.begin(), m.end(), [&](const ts::Measurement& x) { return x.name == p.name; });
      ASSERT_NE(it, m.end()) << "\"" << l.text << "\" prints " << p.name << ", which is not measured";
      char b[64];
      std::snprintf(b, sizeof b, p.format.c_str(), it->value);
      EXPECT_EQ(p.text, b) << p.name;
      const size_t at = rest.find(p.text);
      ASSERT_NE(at, std::string::npos) << "\"" << l.text << "\" does not show " << p.text;
      rest.erase(at, p.text.size());
      ++printed;
    }
    for (const auto& [name, value] : l.given) {
      char b[64];
      std::snprintf(b, sizeof b, "%g", value);
      const size_t at = rest.find(b);
      ASSERT_NE(at, std::string::npos) << "\"" << l.text << "\" does not show its " << name;
      rest.erase(at, std::string(b).size());
    }
    EXPECT_EQ(rest.find_first_of("0123456789"), std::string::npos) << "an unsourced number in \"" << l.text << "\"";
  }
  // The cells print lambda, rho, (u, v), the level(s) and the texel count of every pick.
  EXPECT_GE(printed, 6 * int(d().picks.size()));
}

INSTANTIATE_TEST_SUITE_P(Figures, Footprints,
                         ::testing::Values(Case{"perspective_correction", "inspect_vi2_footprints"},
                                           Case{"mipmap_popping", "inspect_aniso_footprint"}),
                         [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.demo); });
}  // namespace
