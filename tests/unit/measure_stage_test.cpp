// tests/unit/measure_stage_test.cpp — a picture delivered in stages
// (common/core/scene.hpp, ts::measureStage): only a run that takes stages
// (the window's measurement worker) gets them, marked as refining, with the
// demo's detail intact; elsewhere (--png, make_figures) nothing is handed
// over, so figures are made as before; a superseded run stops there.
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include "common/core/measure_run.hpp"
#include "common/core/scene.hpp"

namespace {
struct StagedRun {
  std::atomic<uint64_t> latest{1};
  std::atomic<bool> quit{false};
  std::atomic<double> progress{0};
  ts::MeasureRun run{&latest, &quit, 1, &progress, {}};
  std::vector<ts::Measurements> got;
  explicit StagedRun(bool takesStages) {
    if (takesStages) run.stage = [this](ts::Measurements&& m) { got.push_back(std::move(m)); };
    ts::setMeasureRun(&run);
  }
  ~StagedRun() { ts::setMeasureRun(nullptr); }
};
ts::Measurements stage() {
  ts::Measurements m;
  m.detail = std::string("coarse pictures");
  return m;
}
}  // namespace

TEST(MeasureStage, NoRunTakesNone) {
  EXPECT_FALSE(ts::measureStaged());
  ts::measureStage(stage());  // does nothing, throws nothing
}

TEST(MeasureStage, TheWindowsRunGetsTheStageMarkedRefining) {
  StagedRun r(true);
  EXPECT_TRUE(ts::measureStaged());
  ts::measureStage(stage());
  ASSERT_EQ(r.got.size(), 1u);
  EXPECT_TRUE(r.got[0].refining);
  ASSERT_NE(r.got[0].detailAs<std::string>(), nullptr);
  EXPECT_EQ(*r.got[0].detailAs<std::string>(), "coarse pictures");
}

// The control: a run without a stage callback (as --png's none) is not staged.
TEST(MeasureStage, ARunThatTakesNoStagesIsNotStaged) {
  StagedRun r(false);
  EXPECT_FALSE(ts::measureStaged());
  ts::measureStage(stage());
  EXPECT_TRUE(r.got.empty());
}

TEST(MeasureStage, ASupersededRunStopsAtItsStage) {
  StagedRun r(true);
  r.latest.store(2);  // a newer key
  EXPECT_THROW(ts::measureStage(stage()), ts::MeasureCancelled);
  EXPECT_TRUE(r.got.empty());
}
