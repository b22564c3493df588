// tests/proofread/proofread_test.cpp — every figure the suite renders, read
// from its sidecar as a proofreader would (proofread.hpp): no text cut or
// overlapping, no number without its source, no meaningful colour without a
// key.  The figures are the quick level's one regeneration (the
// figures_render fixture's folder, TS_FIGURES_DIR); the checks read the
// sidecars only, so they hold the code's output, not the committed gallery.
// Each check is also shown failing on a figure spoilt on purpose.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/sidecar.hpp"
#include "common/core/text.hpp"
#include "tests/proofread/proofread.hpp"

namespace {
namespace fs = std::filesystem;
using ts::proofread::Json;

// Figures whose meaningful colours still have no legend entries: the check
// runs on them too and this list must be exactly the figures it fails on,
// so it can only shrink.
const std::set<std::string> kLegendPending = {};

fs::path figuresDir() {
  const char* d = std::getenv("TS_FIGURES_DIR");
  return d ? fs::path(d) : fs::path("build/tests/figures_first");
}

std::vector<fs::path> sidecars() {
  std::vector<fs::path> out;
  if (!fs::is_directory(figuresDir())) return out;
  for (const auto& e : fs::directory_iterator(figuresDir()))
    if (e.path().extension() == ".json") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

Json read(const fs::path& p) {
  std::ifstream in(p);
  return Json::parse(in);
}

std::string lines(const std::vector<std::string>& v, size_t most = 1000) {
  std::string s;
  for (size_t k = 0; k < v.size() && k < most; ++k) s += "\n    " + v[k];
  if (v.size() > most) s += "\n    ... and " + std::to_string(v.size() - most) + " more";
  return s;
}

TEST(Proofread, TheFiguresAreThere) {
  ASSERT_GE(sidecars().size(), 50u) << "no figures in " << figuresDir() << " (the figures_render fixture)";
}

TEST(Proofread, NoTextIsCutOrOverlaps) {
  for (const fs::path& p : sidecars()) {
    const auto problems = ts::proofread::textProblems(read(p));
    EXPECT_TRUE(problems.empty()) << p.stem().string() << ":" << lines(problems);
  }
}

TEST(Proofread, EveryNumberHasItsSource) {
  for (const fs::path& p : sidecars()) {
    const auto problems = ts::proofread::numberProblems(read(p));
    EXPECT_TRUE(problems.empty()) << p.stem().string() << ":" << lines(problems);
  }
}

TEST(Proofread, TextIsReadableInPrint) {
  for (const fs::path& p : sidecars()) {
    const Json d = read(p);
    const auto problems = ts::proofread::sizeProblems(d);
    EXPECT_TRUE(problems.empty()) << p.stem().string() << ":" << lines(problems, 5);
    EXPECT_GE(ts::proofread::smallestCapitals(d), 11.0) << p.stem().string();
  }
}

TEST(Proofread, EveryMeaningfulColourIsNamed) {
  for (const fs::path& p : sidecars()) {
    const std::string id = p.stem().string();
    const auto problems = ts::proofread::colourProblems(read(p));
    if (kLegendPending.count(id))
      EXPECT_FALSE(problems.empty()) << id << " names its colours now: take it off kLegendPending";
    else EXPECT_TRUE(problems.empty()) << id << ":" << lines(problems);
  }
}

// ------------------------------------------------ each check, failing
// A figure made the way the demos make theirs (the layout kit, the sidecar
// writer): a picture panel, a caption printing a measurement, a red outline
// named by a legend.  It reads clean; each spoiling below makes it fail.
Json madeFigure() {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(400, 300);
  f.panels.push_back(L::unitPanel("picture", {20, 40, 200, 150}));
  f.panels.back().batches.push_back(ts::lineLoop({{0.2f, 0.2f}, {0.8f, 0.2f}, {0.8f, 0.8f}, {0.2f, 0.8f}},
                                                 {1.0f, 0.2f, 0.2f, 1.0f}, 2.0f, "highlight"));
  ts::Measurements m;
  m.push_back({"ball_pixels", 2022, "pixels that show the ball"});
  m.push_back({"error_deg", 9.904975, "mean error"});
  L::caption(f, {20, 200, 380, 230}, L::measuredText(m, "the ball: {ball_pixels|%.0f} px, {error_deg|%.1f} deg off"),
             L::kAmber, 1, ts::Align::Left);
  L::caption(f, {20, 6, 380, 30}, "a map " + L::given("map size", 256, "%g") + " texels wide", L::kWhite, 1);
  L::legend(f, {20, 240, 390, 290}, {{{1.0f, 0.2f, 0.2f, 1.0f}, "red: where the ball is"}}, 1);
  ts::SidecarInfo info;
  info.figureId = "made";
  info.measurements = m;
  return Json::parse(ts::sidecarJson(f, info));
}

TEST(ProofreadFails, NotOnTheFigureAsMade) {
  const Json d = madeFigure();
  EXPECT_TRUE(ts::proofread::textProblems(d).empty()) << lines(ts::proofread::textProblems(d));
  EXPECT_TRUE(ts::proofread::numberProblems(d).empty()) << lines(ts::proofread::numberProblems(d));
  EXPECT_TRUE(ts::proofread::colourProblems(d).empty()) << lines(ts::proofread::colourProblems(d));
}

Json& labelSaying(Json& d, const std::string& part) {
  for (Json& l : d["labels"])
    if (l.at("text").get<std::string>().find(part) != std::string::npos) return l;
  throw std::runtime_error("no label says " + part);
}

TEST(ProofreadFails, OnALabelMovedOutsideItsPanel) {
  Json d = madeFigure();
  Json& l = labelSaying(d, "the ball");
  l["x"] = 150, l["y"] = 180;  // half over the picture's lower edge
  EXPECT_FALSE(ts::proofread::textProblems(d).empty());
  l["x"] = 380;  // off the image's right side
  EXPECT_FALSE(ts::proofread::textProblems(d).empty());
}

TEST(ProofreadFails, OnOverlappingOrCutText) {
  Json d = madeFigure();
  Json copy = labelSaying(d, "the ball");
  copy["x"] = copy.at("x").get<float>() + 10;
  d["labels"].push_back(copy);
  EXPECT_FALSE(ts::proofread::textProblems(d).empty()) << "two labels overlap";
  Json e = madeFigure();
  labelSaying(e, "the ball")["text"] = "the ball: 2022 px, 9.9...";
  EXPECT_FALSE(ts::proofread::textProblems(e).empty()) << "a caption cut short";
}

TEST(ProofreadFails, OnANumberChangedInALabel) {
  Json d = madeFigure();
  labelSaying(d, "the ball")["text"] = "the ball: 3161 px, 9.9 deg off";  // as if measured on another image
  EXPECT_FALSE(ts::proofread::numberProblems(d).empty());
  Json e = madeFigure();
  e["measurements"]["ball_pixels"] = 3161;  // the sidecar disagrees with what the label printed
  EXPECT_FALSE(ts::proofread::numberProblems(e).empty());
}

TEST(ProofreadFails, OnATypedNumber) {
  Json d = madeFigure();
  Json l = labelSaying(d, "a map");
  l["text"] = "a near ball, 3161 px";
  l.erase("given");
  l["y"] = 260;
  d["labels"].push_back(l);
  EXPECT_FALSE(ts::proofread::numberProblems(d).empty());
  labelSaying(d, "a map").erase("given");  // 256 said without saying what it is
  EXPECT_FALSE(ts::proofread::numberProblems(d).empty());
}

TEST(ProofreadFails, OnAMeaningfulColourWithoutALegend) {
  Json d = madeFigure();
  d.erase("legend");
  EXPECT_FALSE(ts::proofread::colourProblems(d).empty()) << "the red outline, unnamed";
  Json e = madeFigure();
  labelSaying(e, "red: where")["text"] = "x";
  EXPECT_FALSE(ts::proofread::colourProblems(e).empty()) << "a legend entry not drawn";
}

TEST(ProofreadFails, OnTextBelowTheSize) {
  Json d = madeFigure();
  EXPECT_TRUE(ts::proofread::sizeProblems(d).empty()) << lines(ts::proofread::sizeProblems(d));
  EXPECT_GE(ts::proofread::smallestCapitals(d), 11.0);
  // A sidecar written with ProggyClean at 13 px, the suite's font before: 8 px capitals.
  d["labels"][0]["capital_px"] = 8;
  EXPECT_LT(ts::proofread::smallestCapitals(d), 11.0);
  EXPECT_FALSE(ts::proofread::sizeProblems(d).empty()) << "8 px capitals, and not what the font draws";
  // The font's own capitals at scale 1, held to a larger size.
  Json e = madeFigure();
  EXPECT_FALSE(ts::proofread::sizeProblems(e, ts::text::capitalHeight(1) + 1).empty());
}
}  // namespace
