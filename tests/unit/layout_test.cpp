// tests/unit/layout_test.cpp — common/core/layout: flowFitting with keys
// under the cells' titles (a legend per cell, at scale 1).  A key that fits
// one line at the cells' width leaves the layout flow()'s with one line for
// it (the figures' sizes); a narrow window gives the band the lines the key
// wraps to, so that legend() draws every entry instead of leaving some out.
// And caption(): a GL name wider than the line breaks after an underscore.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/layout.hpp"
#include "common/core/text.hpp"

namespace {
namespace L = ts::layout;

const std::vector<ts::LegendEntry> kKey = {{{1.0f, 0.5f, 0.5f, 1.0f}, "n to the right (+x)"},
                                           {{0.5f, 1.0f, 0.5f, 1.0f}, "n up (+y)"},
                                           {{0.5f, 0.5f, 1.0f, 1.0f}, "n to the eye (+z)"}};

L::FlowSpec twoCells() {
  L::FlowSpec spec;
  spec.n = 2, spec.linesAbove = 2, spec.linesBelow = 2;
  return spec;
}

// Every entry the band's legend() draws (ts::Frame::legend).
size_t drawn(const L::Box& band) {
  ts::Frame f = L::blankFrame(1, 1);
  L::legend(f, band, kKey, 1);
  return f.legend.size();
}

TEST(FlowFitting, AKeyThatFitsKeepsFlowsLayout) {
  const L::Box area{6, 6, 1018, 626};
  const std::vector<L::Stack> above = {{"B1 Blinn, normals"}, {"R displaced, normals"}}, below = {{""}, {""}};
  const std::vector<L::Cell> keyed = L::flowFitting(area, twoCells(), above, below, {kKey, {}});
  const std::vector<L::Cell> plain = L::flow(area, twoCells());
  ASSERT_EQ(keyed.size(), plain.size());
  for (size_t k = 0; k < keyed.size(); ++k) {
    EXPECT_EQ(keyed[k].picture.x, plain[k].picture.x);
    EXPECT_EQ(keyed[k].picture.y, plain[k].picture.y);
    EXPECT_EQ(keyed[k].picture.w, plain[k].picture.w);
    EXPECT_EQ(keyed[k].above.y0, plain[k].above.y0);
    EXPECT_EQ(keyed[k].above.y1, plain[k].above.y1);
  }
  EXPECT_EQ(L::legendLines(kKey, 1, keyed[0].above.w()), 1);
  EXPECT_EQ(drawn(L::keyApart(keyed[0].above, keyed[0].scale, 1).second), kKey.size());
}

TEST(FlowFitting, ANarrowWindowWrapsTheKeyInsteadOfLeavingEntriesOut) {
  const L::Box area{6, 6, 634, 474};  // 640 x 480
  const std::vector<L::Stack> above = {{"B1 Blinn, normals"}, {"R displaced, normals"}}, below = {{""}, {""}};
  const std::vector<L::Cell> cells = L::flowFitting(area, twoCells(), above, below, {kKey, {}});
  ASSERT_EQ(cells.size(), 2u);
  const int lines = L::legendLines(kKey, 1, cells[0].above.w());
  ASSERT_GT(lines, 1) << "the key should need two lines at this width for the test to mean anything";
  EXPECT_EQ(drawn(L::keyApart(cells[0].above, cells[0].scale, lines).second), kKey.size());
  // The control: the one line flow() would have given the key leaves entries out.
  const std::vector<L::Cell> plain = L::flow(area, twoCells());
  EXPECT_LT(drawn(L::lastLineApart(plain[0].above, plain[0].scale).second), kKey.size());
}
// Ten cells in two columns, one title two lines at the cells' width, in an
// area with no even grid of two-line titles (filter_zoo's methods beside
// its panel): only that title's row takes the second line.  Every band is
// as deep as its own cell's lines, the rows do not overlap, and the control,
// an even grid of two-line title bands, has no room for a picture in cells
// that wide (only in narrower ones, which an arrangement of wide cells beats).
TEST(FlowFitting, WithNoRoomForAnEvenGridEachRowTakesItsOwnLines) {
  const std::string longTitle = "GL_NEAREST_MIPMAP_NEAREST";
  L::FlowSpec spec;
  spec.n = 10, spec.aspect = 2.5f, spec.gap = 8, spec.minCellWidth = 150;
  std::vector<L::Stack> above(10, {"trilinear"}), below(10, {"RMS 12.34"});
  above[3] = {longTitle};
  const float line = L::lineHeight(1), width = 432;
  // Height for ten rows' worth of lines and a few pixels of picture each, not for five rows of three lines.
  const L::Box area{4, 4, 4 + width, 4 + 11 * line + 4 * 8 + 5 * 6};
  ASSERT_GT(ts::text::width(longTitle, 1), (width - 8) / 2 - 1) << "the title must wrap in two columns";
  L::FlowSpec even = spec;
  even.linesAbove = 2;
  const std::vector<L::Cell> control = L::flow(area, even);
  EXPECT_TRUE(control.front().picture.h <= 1 || control.front().above.w() < spec.minCellWidth)
      << "the control: an even grid of two-line titles in cells wide enough should have no room here";
  const std::vector<L::Cell> cells = L::flowFitting(area, spec, above, below);
  ASSERT_EQ(cells.size(), 10u);
  EXPECT_GT(cells[0].picture.h, 1);
  for (size_t k = 0; k < cells.size(); ++k) {
    const int lines = int(std::lround(cells[k].above.h() / line));
    const bool longRow = k / 2 == 1;
    EXPECT_EQ(lines, longRow ? 2 : 1) << "cell " << k;
    EXPECT_EQ(int(std::lround(cells[k].below.h() / line)), 1) << "cell " << k;
    if (k >= 2) EXPECT_GE(cells[k].above.y0, cells[k - 2].below.y1) << "cell " << k << " overlaps the row above";
    EXPECT_LE(cells[k].below.y1, area.y1 + 0.5f) << "cell " << k;
  }
}
// Six cells, three a row, one note four lines longer than the others
// (bump_mapping's emboss in a 640x480 window): its row takes those lines and
// the other row does not, so the pictures are larger than an even grid's,
// which gives every row the long note's lines (the control).
TEST(FlowFitting, ALongNoteCostsOnlyItsOwnRowTheLines) {
  const std::string shortNote = "PSNR 23.6 dB", longNote = "PSNR 24.4 dB; contrast 0.006 with the light within 10 deg "
                                                           "of the normal, 0.039 beyond 60 deg, and more words besides";
  L::FlowSpec spec;
  spec.n = 6, spec.aspect = 1.0f, spec.gap = 8;
  std::vector<L::Stack> above(6, {"B1 Blinn"}), below(6, {shortNote});
  below[3] = {longNote};
  const L::Box area{4, 4, 436, 420};
  const std::vector<L::Cell> cells = L::flowFitting(area, spec, above, below);
  ASSERT_EQ(cells.size(), 6u);
  const int longLines = int(std::lround(cells[3].below.h() / L::lineHeight(cells[3].scale)));
  ASSERT_GT(longLines, 2) << "the long note must wrap for the test to mean anything";
  EXPECT_LT(cells[0].below.h(), cells[3].below.h()) << "the first row took the long note's lines";
  for (size_t k = 1; k < cells.size(); ++k) EXPECT_EQ(cells[k].picture.w, cells[0].picture.w) << "cell " << k;
  // The control: the same cells with every note as long, an even grid.
  const std::vector<L::Cell> even = L::flowFitting(area, spec, above, std::vector<L::Stack>(6, {longNote}));
  EXPECT_GT(cells[0].picture.h, even[0].picture.h) << "rows of their own should give larger pictures";
}
// A GL name wider than its cell (filter_zoo's GL_NEAREST_MIPMAP_NEAREST in
// a 640x480 window) wraps after an underscore instead of being cut with
// "...": every line within the band, the text whole, the words after it
// going on from its last part.  The control: a band wide enough holds it on
// one line.
TEST(Caption, AGLNameTooWideForALineBreaksAfterAnUnderscore) {
  const std::string name = "GL_NEAREST_MIPMAP_NEAREST", text = name + " and trilinear";
  const float width = float(ts::text::width("GL_NEAREST_MIPMAP_", 1)) + 4;
  ASSERT_GT(ts::text::width(name, 1), width);
  ts::Frame f = L::blankFrame(1, 1);
  L::caption(f, {0, 0, width, 5 * L::lineHeight(1)}, text, {1, 1, 1, 1}, 1, ts::Align::Left);
  ASSERT_GE(f.labels.size(), 2u);
  std::string joined;
  for (const ts::Label& l : f.labels) {
    EXPECT_LE(ts::text::width(l.text, 1), width) << l.text;
    EXPECT_EQ(l.text.find("..."), std::string::npos) << l.text;
    joined += (joined.empty() || joined.back() == '_' ? "" : " ") + l.text;
  }
  EXPECT_EQ(joined, text);
  EXPECT_EQ(f.labels[0].text, "GL_NEAREST_MIPMAP_");
  EXPECT_EQ(f.labels[1].text.rfind("NEAREST", 0), 0u) << "the words after it go on from its last part";
  ts::Frame wide = L::blankFrame(1, 1);
  L::caption(wide, {0, 0, 1000, 5 * L::lineHeight(1)}, text, {1, 1, 1, 1}, 1, ts::Align::Left);
  ASSERT_EQ(wide.labels.size(), 1u);
  EXPECT_EQ(wide.labels[0].text, text);
}
// A key entry wider than its band (bump_mapping's emboss term in a 640x480
// window: "light 1 within 10 deg of the normal" over a third of it) is
// drawn with its meaning wrapped beside its swatch, every line within the
// band, on as many lines as legendLines() counts; the entries after it go
// on below it.  The control: a band one line deep has no room for it, and
// leaves it out rather than cut it.
TEST(Legend, AnEntryWiderThanItsBandWrapsBesideItsSwatch) {
  const std::vector<ts::LegendEntry> key = {{{0.2f, 0.8f, 1.0f, 1.0f}, "light 1 within 10 deg of the normal"},
                                            {{1.0f, 0.5f, 0.5f, 1.0f}, "+x"}};
  const float width = ts::text::width("light 1 within 10 deg", 1);
  const int lines = L::legendLines(key, 1, width);
  ASSERT_GE(lines, 3);  // the long entry's two or more, then the short one's
  ts::Frame f = L::blankFrame(1, 1);
  const L::Box band{0, 0, width, float(lines) * L::lineHeight(1)};
  L::legend(f, band, key, 1);
  ASSERT_EQ(f.legend.size(), 2u);
  std::string meaning;
  float lowest = 0;
  for (const ts::Label& l : f.labels) {
    EXPECT_TRUE(L::labelBox(l).inside(band)) << l.text;
    EXPECT_EQ(l.text.find("..."), std::string::npos) << l.text;
    if (l.text != "+x") meaning += (meaning.empty() ? "" : " ") + l.text;
    else lowest = l.y;
  }
  EXPECT_EQ(meaning, key[0].meaning);
  EXPECT_NEAR(lowest, float(lines - 1) * L::lineHeight(1), 0.5f) << "the short entry on the last line";
  ts::Frame shallow = L::blankFrame(1, 1);
  L::legend(shallow, {0, 0, width, L::lineHeight(1)}, key, 1);
  EXPECT_TRUE(shallow.legend.empty());
  EXPECT_TRUE(shallow.labels.empty());
}
}  // namespace
