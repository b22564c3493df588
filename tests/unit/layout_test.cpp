// tests/unit/layout_test.cpp — common/core/layout: flowFitting with keys
// under the cells' titles (a legend per cell, at scale 1).  A key that fits
// one line at the cells' width leaves the layout flow()'s with one line for
// it (the figures' sizes); a narrow window gives the band the lines the key
// wraps to, so that legend() draws every entry instead of leaving some out.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/layout.hpp"

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
}  // namespace
