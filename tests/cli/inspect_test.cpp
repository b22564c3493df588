// tests/cli/inspect_test.cpp — --inspect X,Y and --footprints as a user meets
// them: the sidecar's "inspect" objects and their fields,
// the closed form of a magnified texture, gl_rgba as the PNG's own pixel, the
// texel weights, and bad input (one line, exit 2, no file).  The demo runs
// in this process through runDemo, exactly as its main() does.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/image.hpp"
#include "common/core/scene.hpp"

namespace {
std::string tmp(const std::string& name) { return ::testing::TempDir() + "ts_inspect_" + name; }

int run(const std::string& demo, std::vector<std::string> args) {
  args.insert(args.begin(), demo);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  return ts::runDemo(demo, int(argv.size()), argv.data());
}

bool exists(const std::string& path) { return std::ifstream(path).good(); }

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return nlohmann::json::parse(s.str());
}

// quad_distortion's book view at 1024x512 with two picks: a pixel of the
// texture-space panel (the whole 256x256 texture drawn square, magnified or
// minified by 256 / its width) and a background pixel.
struct Inspected {
  nlohmann::json doc;
  ts::Image png;
};
const Inspected& quad() {
  static Inspected got = [] {
    const std::string png = tmp("quad.png"), json = tmp("quad.json");
    std::remove(png.c_str()), std::remove(json.c_str());
    EXPECT_EQ(run("quad_distortion",
                  {"--png", png, "--json", json, "--quiet", "--inspect", "300,200", "--inspect", "10,10"}),
              0);
    return Inspected{readJson(json), ts::readPng(png)};
  }();
  return got;
}

TEST(Inspect, SidecarHasTheFieldsOfEveryPick) {
  const nlohmann::json& ins = quad().doc.at("inspect");
  ASSERT_EQ(ins.size(), 2u);
  for (const char* k : {"pixel", "panel", "batch", "st", "stq", "uv", "derivatives", "rho_edge", "rho_max", "lambda",
                        "levels", "level_weight", "texels", "reference_rgba", "gl_rgba"})
    EXPECT_TRUE(ins[0].contains(k)) << "missing " << k;
  EXPECT_EQ(ins[0]["pixel"], nlohmann::json({300, 200}));
  EXPECT_EQ(ins[0]["stq"].size(), 4u);
  EXPECT_EQ(ins[0]["derivatives"].size(), 4u);
}

TEST(Inspect, GlRgbaIsThePngsPixel) {
  for (const nlohmann::json& o : quad().doc.at("inspect")) {
    const ts::Rgba p = quad().png.at(o["pixel"][0], o["pixel"][1]);
    const uint8_t want[4] = {p.r, p.g, p.b, p.a};
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(o["gl_rgba"][c].get<double>() * 255.0, want[c], 1e-6);
  }
}

// The texture-space panel shows the 256-texel texture across its viewport's
// width: rho = 256 / width exactly (both forms: the map is a scale), lambda
// = log2(rho), and the derivatives are (rho, 0) and (0, -rho) (v runs up,
// y down).
TEST(Inspect, TextureSpacePanelHasTheClosedFormLod) {
  const nlohmann::json& o = quad().doc.at("inspect")[0];
  const nlohmann::json& panel = quad().doc.at("panels")[o["panel"].get<int>()];
  const double width = panel.at("viewport")[2].get<double>(), rho = 256.0 / width;
  EXPECT_NEAR(o["rho_edge"].get<double>(), rho, 1e-9);
  EXPECT_NEAR(o["rho_max"].get<double>(), rho, 1e-9);
  EXPECT_NEAR(o["lambda"].get<double>(), std::log2(rho), 1e-9);
  EXPECT_NEAR(o["derivatives"][0].get<double>(), rho, 1e-9);
  EXPECT_NEAR(o["derivatives"][3].get<double>(), -rho, 1e-9);
  EXPECT_NEAR(o["derivatives"][1].get<double>(), 0.0, 1e-9);
}

// The texels' weights sum to 1, their weighted sum is the filtered colour,
// which (GL_REPLACE, white vertices) is the reference colour, within an
// 8-bit step of GL's.
TEST(Inspect, TexelsReproduceTheReferenceAndGlAgrees) {
  const nlohmann::json& o = quad().doc.at("inspect")[0];
  double sum = 0, rgba[4] = {0, 0, 0, 0};
  for (const nlohmann::json& t : o["texels"]) {
    sum += t["weight"].get<double>();
    for (int c = 0; c < 4; ++c) rgba[c] += t["weight"].get<double>() * t["rgba"][c].get<double>();
  }
  EXPECT_NEAR(sum, 1.0, 1e-9);
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(rgba[c], o["reference_rgba"][c].get<double>(), 1e-6);
    EXPECT_NEAR(o["gl_rgba"][c].get<double>(), o["reference_rgba"][c].get<double>(), 1.0 / 255 + 1e-9);
  }
}

TEST(Inspect, BackgroundPickSaysSo) {
  const nlohmann::json& o = quad().doc.at("inspect")[1];
  EXPECT_EQ(o["batch"], -1);
  EXPECT_TRUE(o["lambda"].is_null());
  EXPECT_TRUE(o["texels"].empty());
}

TEST(Inspect, BadPixelsAreOneLineExit2AndNoFile) {
  const std::string png = tmp("bad.png");
  for (std::vector<std::string> bad : {std::vector<std::string>{"--inspect", "1024,0"},
                                       {"--inspect", "0,512"},
                                       {"--inspect", "5x"},
                                       {"--inspect", "-1,3"},
                                       {"--inspect", "1,2,3"},
                                       {"--footprints"}}) {
    std::remove(png.c_str());
    bad.insert(bad.begin(), {"--png", png, "--quiet"});
    EXPECT_EQ(run("quad_distortion", bad), 2) << bad.back();
    EXPECT_FALSE(exists(png)) << bad.back();
  }
}

// --footprints: a picture of the same size, not the plain one, and the
// picks' lambda as measurements.
TEST(Inspect, FootprintsDrawAnotherPicture) {
  const std::string png = tmp("fp.png"), json = tmp("fp.json");
  ASSERT_EQ(run("quad_distortion", {"--png", png, "--json", json, "--quiet", "--inspect", "300,200", "--footprints"}),
            0);
  const ts::Image fp = ts::readPng(png);
  EXPECT_EQ(fp.width, quad().png.width);
  EXPECT_EQ(fp.height, quad().png.height);
  EXPECT_NE(fp.pixels, quad().png.pixels);
  const nlohmann::json doc = readJson(json);
  EXPECT_NEAR(doc.at("measurements").at("inspect_lambda[1]").get<double>(),
              quad().doc.at("inspect")[0]["lambda"].get<double>(), 1e-6);
}
}  // namespace
