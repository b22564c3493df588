// tests/layout/layout_test.cpp — every demo's layout at every window size.
//
// Each registered demo is measured once in each of its states (the default,
// every choice of its `view` option, every book figure's flags) and its
// frame is built at seven sizes from 400x300 to 1080x1920 (wide, tall,
// tiny).  From the frame's own boxes (each label's text extent at its
// scale, common/core/layout.hpp's labelBox) it asserts:
//   - no label leaves the window;
//   - a label that touches a panel lies inside it (no caption half over a
//     picture, none cut at a panel's edge);
//   - no two labels overlap;
//   - no panel leaves the window.
// Nothing is rendered but the measurements: the test reads layouts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "common/app/side_panel.hpp"
#include "common/core/error.hpp"
#include "common/core/layout.hpp"
#include "common/core/text.hpp"
#include "tests/support/scene_test.hpp"

namespace {
using ts::layout::Box;

const std::vector<std::pair<int, int>> kSizes = {{400, 300},  {640, 480},   {700, 1000}, {1024, 768},
                                                 {1280, 720}, {1920, 1080}, {1080, 1920}};

// Flags that make a demo's measurement cheap without changing what its
// layout shows (parallax_aniso: small measured renders, few reference rays).
std::vector<std::string> cheap(const std::string& id) {
  if (id == "parallax_aniso") return {"--res", "80", "--rays", "2", "--time", "0"};
  return {};
}

// States whose text no `view` choice or figure shows: the split screen, a
// longer header, the error pictures, the reference's numbers.
std::vector<std::vector<std::string>> extra(const std::string& id) {
  if (id == "parallax_aniso") return {{"--compare"}, {"--gradients", "x4"}, {"--view", "modes", "--map", "flat"}};
  if (id == "jitter") return {{"--error"}, {"--mode", "reference"}, {"--mode", "one", "--samples", "1"}};
  if (id == "mipmap_popping") return {{"--levels", "texture"}, {"--filter", "anisotropic", "--view", "filmstrip"}};
  return {};
}

// The demo's states: default, each choice of `view`, each figure's flags,
// and the extra states above.
std::vector<std::vector<std::string>> states(const std::string& id) {
  std::vector<std::vector<std::string>> out = {{}};
  ts::test::Demo d(id, {});
  for (const auto& it : d.opts.items())
    if (it.name == "view" && it.kind == ts::Options::Item::Enum)
      for (const auto& c : it.choices)
        if (c != "live") out.push_back({"--view", c});  // live: drawn every frame, at the window's size
  for (const auto& f : d.scene->figures()) out.push_back(ts::sceneFlags(f.flags));
  for (const auto& e : extra(id)) out.push_back(e);
  std::set<std::vector<std::string>> seen;
  std::vector<std::vector<std::string>> unique;
  for (auto& s : out) {
    for (const auto& c : cheap(id)) s.push_back(c);
    if (seen.insert(s).second) unique.push_back(s);
  }
  return unique;
}

std::string str(const Box& b) {
  std::ostringstream o;
  o << "[" << b.x0 << "," << b.y0 << " .. " << b.x1 << "," << b.y1 << "]";
  return o.str();
}

// The problems of one frame, one line each.
std::vector<std::string> problems(const ts::Frame& f) {
  std::vector<std::string> out;
  const Box window{0, 0, float(f.width), float(f.height)};
  std::vector<Box> boxes;
  for (const auto& l : f.labels) boxes.push_back(ts::layout::labelBox(l));
  for (const auto& p : f.panels)
    if (!ts::layout::box(p.viewport).inside(window))
      out.push_back("panel '" + p.id + "' " + str(ts::layout::box(p.viewport)) + " leaves the window");
  for (size_t i = 0; i < f.labels.size(); ++i) {
    const auto& l = f.labels[i];
    const Box& b = boxes[i];
    if (l.text.empty() || b.empty()) continue;
    if (!b.inside(window)) out.push_back("label \"" + l.text + "\" " + str(b) + " leaves the window");
    for (const auto& p : f.panels) {
      Box pb = ts::layout::box(p.viewport);
      // Panels as large as the frame are backgrounds (a plot's canvas).
      if (pb.w() >= f.width && pb.h() >= f.height) continue;
      if (b.overlaps(pb) && !b.inside(pb))
        out.push_back("label \"" + l.text + "\" " + str(b) + " crosses the edge of panel '" + p.id + "' " + str(pb));
    }
    for (size_t j = i + 1; j < f.labels.size(); ++j)
      if (!f.labels[j].text.empty() && b.overlaps(boxes[j]))
        out.push_back("labels \"" + l.text + "\" " + str(b) + " and \"" + f.labels[j].text + "\" " + str(boxes[j]) +
                      " overlap");
  }
  return out;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}

class Layout : public ::testing::TestWithParam<std::string> {};

TEST_P(Layout, NoLabelLeavesItsPanelOrTheWindowOrOverlapsAnother) {
  const std::string id = GetParam();
  int failures = 0;
  for (const auto& flags : states(id)) {
    ts::test::Demo d(id, flags);
    d.measure();
    for (auto [w, h] : kSizes) {
      ts::Frame f = d.scene->build(w, h, d.measured);
      ASSERT_EQ(f.width, w);
      ASSERT_EQ(f.height, h);
      std::vector<std::string> p = problems(f);
      if (p.empty()) continue;
      ++failures;
      std::string all;
      for (size_t k = 0; k < p.size() && k < 6; ++k) all += "\n    " + p[k];
      if (p.size() > 6) all += "\n    ... and " + std::to_string(p.size() - 6) + " more";
      ADD_FAILURE() << id << " " << joined(flags) << " at " << w << "x" << h << ":" << all;
    }
  }
  std::printf("[ layout   ] %s: %d failing layouts\n", id.c_str(), failures);
}

// Views a narrow window once cut with "...": now their captions, titles
// and notes wrap (flowFitting; a GL name after an underscore) and the
// notes take the lines they need, so at 640x480 and 700x1000 no label is
// cut.  (Other views still cut a label at 640x480; they are not listed.)
// The control: "measuring..." placeholders are not cuts.  Emboss's compare
// view also keeps its term's key entry, wider than its cell: wrapped; and
// environment_mapping's keys keep every entry (their bands take the lines).
// Each window size twice: the figure the whole width, and beside the side
// panel (a student's window as it opens: 440x480 of a 640x480 window).
// filter_zoo's ten cells at 440x480 have no even grid with room for
// GL_NEAREST_MIPMAP_NEAREST's two title lines: only that title's row takes
// the second line (flowFitting's rows of their own).
TEST(NarrowWindows, TheseViewsCutNoLabel) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> views = {
      {"filter_zoo", {"--view", "methods"}},
      {"filter_zoo", {}},
      {"environment_mapping", {}},
      {"bump_mapping", {"--view", "all"}},
      {"bump_mapping", {"--view", "compare", "--method", "emboss", "--heights", "bricks"}}};
  for (const auto& [id, flags] : views) {
    ts::test::Demo d(id, flags);
    d.measure();
    std::vector<std::pair<int, int>> sizes;
    for (auto [w, h] : {std::pair{640, 480}, std::pair{700, 1000}, std::pair{1280, 720}})
      sizes.insert(sizes.end(), {{w, h}, {ts::splitWindow(w, true, false).figureW, h}});
    for (auto [w, h] : sizes) {
      const ts::Frame f = d.scene->build(w, h, d.measured);
      size_t labels = 0;
      for (const ts::Label& l : f.labels) {
        labels += !l.text.empty();
        const size_t cut = l.text.find("...");
        EXPECT_TRUE(cut == std::string::npos || l.text == "measuring...")
            << id << " " << joined(flags) << " at " << w << "x" << h << ": \"" << l.text << "\" is cut";
      }
      EXPECT_GT(labels, 5u) << id << " at " << w << "x" << h;
      if (id == "environment_mapping")  // the world's four colours and the heat scale's three, every one
        EXPECT_EQ(f.legend.size(), 7u) << "environment_mapping's keys at " << w << "x" << h;
      if (flags.size() > 3 && flags[3] == "emboss")
        EXPECT_TRUE(std::any_of(f.legend.begin(), f.legend.end(),
                                [](const ts::LegendEntry& e) { return e.meaning.find("within") != std::string::npos; }))
            << "emboss's term key at " << w << "x" << h;
    }
  }
}

// The registry is filled by static initialisers in other objects: read it
// when the tests are listed, not when this file's statics are made.
std::vector<std::string> ids() {
  std::vector<std::string> out;
  for (const auto& r : ts::sceneRegistry()) out.push_back(r.id);
  std::sort(out.begin(), out.end());
  return out;
}
INSTANTIATE_TEST_SUITE_P(Demos, Layout, ::testing::ValuesIn(ids()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

// Text scales with its pictures, not the window (common/core/layout.hpp): in
// views whose pictures grow with the window, a 1920x1080 frame has text
// above scale 1, a 400x300 frame none, and no label is larger than the
// largest picture asks for (layout::scaleFor).  Before the views used the
// kit, jitter's and parallax_aniso's stayed at 1 at every size.
TEST(TextScale, GrowsWithThePicturesNotBeyond) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> views = {
      {"jitter", {"--view", "mode"}},           {"jitter", {"--view", "plot"}},
      {"parallax_aniso", {"--view", "single"}}, {"parallax_aniso", {"--view", "single", "--compare"}},
      {"mipmap_popping", {"--view", "slant"}},  {"mipmap_popping", {"--view", "plot"}}};
  for (const auto& [id, flags] : views) {
    std::vector<std::string> all = flags;
    for (const auto& c : cheap(id)) all.push_back(c);
    ts::test::Demo d(id, all);
    d.measure();
    auto largest = [](const ts::Frame& f, int* labelScale, int* pictureScale) {
      *labelScale = 0, *pictureScale = 1;
      for (const auto& l : f.labels) *labelScale = std::max(*labelScale, l.scale);
      for (const auto& p : f.panels)
        if (p.viewport.w < f.width || p.viewport.h < f.height)  // not a background
          *pictureScale = std::max(*pictureScale, ts::layout::scaleFor(p.viewport));
    };
    int big = 0, bigPicture = 0, small = 0, smallPicture = 0;
    largest(d.scene->build(1920, 1080, d.measured), &big, &bigPicture);
    largest(d.scene->build(400, 300, d.measured), &small, &smallPicture);
    EXPECT_GE(big, 2) << id << " " << joined(flags) << ": text at 1920x1080";
    EXPECT_LE(big, bigPicture) << id << " " << joined(flags) << ": text larger than its pictures ask for";
    EXPECT_EQ(small, 1) << id << " " << joined(flags) << ": text at 400x300";
  }
}

// A layout test that cannot fail is no test: the checks find a caption
// pushed over a panel's edge, one outside the window, and two on top of
// each other.
TEST(LayoutCheck, FindsWhatItLooksFor) {
  ts::Frame f;
  f.width = 200;
  f.height = 100;
  ts::Panel p;
  p.id = "picture";
  p.viewport = {10, 10, 80, 80};
  f.panels.push_back(p);
  f.labels.push_back({20, 20, "inside", glm::vec4(1), 1, ts::Align::Left});
  EXPECT_TRUE(problems(f).empty()) << joined(problems(f));
  f.labels.push_back({85, 40, "across", glm::vec4(1), 1, ts::Align::Left});
  EXPECT_EQ(problems(f).size(), 1u);
  f.labels.back() = {195, 40, "outside", glm::vec4(1), 1, ts::Align::Left};
  EXPECT_EQ(problems(f).size(), 1u);
  f.labels.back() = {25, 25, "onto", glm::vec4(1), 1, ts::Align::Left};
  EXPECT_EQ(problems(f).size(), 1u);
}

// The kit's small pieces the demos share: a picture centred in a cell keeps
// its size, lies inside the cell with margins at most a pixel apart; a band
// cut in halves is covered exactly by two equal, disjoint halves; a unit
// panel maps (0, 0) and (1, 1) to its viewport's bottom-left and top-right.
TEST(LayoutKit, CentredHalvesAndUnitPanel) {
  const ts::Rect cell{10, 20, 101, 60};
  const ts::Rect r = ts::layout::centred(cell, 40, 25);
  EXPECT_EQ(r.w, 40);
  EXPECT_EQ(r.h, 25);
  EXPECT_TRUE(ts::layout::box(r).inside(ts::layout::box(cell)));
  EXPECT_LE(std::abs((r.x - cell.x) - (cell.x + cell.w - r.x - r.w)), 1);
  EXPECT_LE(std::abs((r.y - cell.y) - (cell.y + cell.h - r.y - r.h)), 1);
  const Box band{3.5f, 7.25f, 90.0f, 41.75f};
  const auto [top, bottom] = ts::layout::halves(band);
  EXPECT_EQ(top.y0, band.y0);
  EXPECT_EQ(top.y1, bottom.y0);
  EXPECT_EQ(bottom.y1, band.y1);
  EXPECT_FLOAT_EQ(top.h(), bottom.h());
  EXPECT_EQ(top.x0, band.x0);
  EXPECT_EQ(bottom.x1, band.x1);
  EXPECT_FALSE(top.overlaps(bottom));
  const ts::Panel p = ts::layout::unitPanel("unit", {30, 40, 100, 50});
  const glm::vec2 lo = ts::panelToPixels(p, p.projection * glm::vec4(0, 0, 0, 1));
  const glm::vec2 hi = ts::panelToPixels(p, p.projection * glm::vec4(1, 1, 0, 1));
  EXPECT_NEAR(lo.x, 30.0f, 1e-4f);
  EXPECT_NEAR(lo.y, 90.0f, 1e-4f);
  EXPECT_NEAR(hi.x, 130.0f, 1e-4f);
  EXPECT_NEAR(hi.y, 40.0f, 1e-4f);
  EXPECT_TRUE(p.batches.empty());
}
}  // namespace

// Captions wrap at words and at phrases, never inside a formula: an operator
// word keeps its neighbours on its line ("c3 = (c0+2c1)/3" moves whole to
// the next line rather than leave "c3 =" behind), and phrases() breaks only
// between its phrases, each line keeping the numbers it prints.
TEST(LayoutKit, WrapKeepsFormulasAndPhrasesWhole) {
  namespace L = ts::layout;
  {
    ts::Frame f = L::blankFrame(600, 200);
    const std::string head = "the third colour c3 =";  // where a plain word wrap would break
    const float w = ts::text::width(head, 1) + 2;
    L::caption(f, {0, 0, w, 100}, head + " (c0+2c1)/3 of the block", L::kWhite, 1);
    bool whole = false;
    for (const ts::Label& l : f.labels) {
      whole = whole || l.text.find("c3 = (c0+2c1)/3") != std::string::npos;
      EXPECT_NE(l.text.back(), '=') << l.text;
      EXPECT_NE(l.text.front(), '=') << l.text;
    }
    EXPECT_TRUE(whole);
    EXPECT_EQ(L::captionLines(head + " (c0+2c1)/3 of the block", 1, w), int(f.labels.size()));
  }
  {
    ts::Frame f = L::blankFrame(600, 200);
    const std::string first = "alpha beta gamma,";
    const L::Text second = "delta " + L::given("a parameter", 2.5, "%.1f");
    const float w = ts::text::width(first + " delta 2.5", 1) - 4;  // both do not fit on one line, each does
    const float below = L::phrases(f, {0, 0, w, 100}, {first, second}, L::kWhite, 1);
    ASSERT_EQ(f.labels.size(), 2u);
    EXPECT_EQ(f.labels[0].text, first);
    EXPECT_EQ(f.labels[1].text, "delta 2.5");
    ASSERT_EQ(f.labels[1].given.size(), 1u);
    EXPECT_EQ(f.labels[1].given[0].first, "a parameter");
    EXPECT_GT(f.labels[1].y, f.labels[0].y);
    EXPECT_LE(below, 100.0f);
  }
}

// A measured number before anything is measured (a window's first frames)
// says it is coming; once measured, a name the state lacks is refused, as
// is a format that does not print a double.
TEST(LayoutKit, MeasuredNumbersBeforeAndAfterTheMeasurement) {
  namespace L = ts::layout;
  const ts::Measurements none;
  EXPECT_EQ(L::measured(none, "kink_deg", "%.1f").text, "(measuring)");
  ts::Measurements some;
  some.push_back({"kink_deg", 18.43, "degrees"});
  const L::Text t = L::measured(some, "kink_deg", "%.1f");
  EXPECT_EQ(t.text, "18.4");
  ASSERT_EQ(t.printed.size(), 1u);
  EXPECT_EQ(t.printed[0].name, "kink_deg");
  EXPECT_THROW(L::measured(some, "no_such_number", "%.1f"), ts::Error);
  EXPECT_THROW(L::measured(some, "kink_deg", "%d"), ts::Error);
  EXPECT_THROW(L::given("a width", 512, "%d"), ts::Error);
  EXPECT_EQ(L::given("a width", 512, "%.0f").text, "512");
}
