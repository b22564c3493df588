// tests/unit/options_test.cpp — ts::Options (every demo's flags and keys),
// ts::parseSize and ts::parseCommonFlags.  No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/options.hpp"
#include "common/core/orbit_camera.hpp"
#include "common/core/scene.hpp"

namespace {
// A demo-like state with one option of each kind.
struct State {
  bool edges = false;
  int mode = 0;  // "book" | "compare" | "grid"
  int checks = 8;
  float zoom = 1.0f;
  std::string corners = "0,0 1,1";
  void bind(ts::Options& o) {
    o.addBool("edges", &edges, "draw edges", 'e');
    o.addEnum("mode", &mode, {"book", "compare", "grid"}, "layout", 'm');
    o.addInt("checks", &checks, 2, 32, "checks per side", '+', '-', 2);
    o.addFloat("zoom", &zoom, 0.5f, 4.0f, "zoom", 'z', 'x', 0.25f);
    o.addText("corners", &corners, "corners", [](const std::string& v) {
      if (v.find(',') == std::string::npos) throw ts::Error("--corners: '" + v + "' has no comma");
    });
  }
};

// Runs parse and returns the ts::Error message ("" if nothing was thrown).
std::string parseError(ts::Options& o, const std::vector<std::string>& args) {
  try {
    o.parse(args);
  } catch (const ts::Error& e) {
    EXPECT_EQ(e.exit_code, ts::kExitUsage) << e.what();
    return e.what();
  }
  return "";
}

// Claim: a bool option accepts --x, --no-x, --x=on|off (and the synonyms),
// and rejects any other value.
TEST(Options, BoolForms) {
  State s;
  ts::Options o;
  s.bind(o);
  o.parse({"--edges"});
  EXPECT_TRUE(s.edges);
  o.parse({"--no-edges"});
  EXPECT_FALSE(s.edges);
  o.parse({"--edges=on"});
  EXPECT_TRUE(s.edges);
  o.parse({"--edges=off"});
  EXPECT_FALSE(s.edges);
  o.parse({"--edges=yes"});
  EXPECT_TRUE(s.edges);
  o.parse({"--edges=0"});
  EXPECT_FALSE(s.edges);
  EXPECT_NE(parseError(o, {"--edges=maybe"}).find("maybe"), std::string::npos);
  EXPECT_FALSE(s.edges);
}

// Claim: an enum takes one of its choices, as "--x v" or "--x=v"; anything
// else is rejected with a message listing the choices.
TEST(Options, EnumForms) {
  State s;
  ts::Options o;
  s.bind(o);
  o.parse({"--mode", "compare"});
  EXPECT_EQ(s.mode, 1);
  o.parse({"--mode=grid"});
  EXPECT_EQ(s.mode, 2);
  std::string e = parseError(o, {"--mode", "Book"});
  EXPECT_NE(e.find("book, compare, grid"), std::string::npos) << e;
  EXPECT_EQ(s.mode, 2);
}

// Claim: ints must be integers inside [lo, hi]; floats numbers inside
// [lo, hi]; NaN, inf, trailing garbage and out-of-range values are refused
// and leave the value as it was.
TEST(Options, NumbersAndRanges) {
  State s;
  ts::Options o;
  s.bind(o);
  o.parse({"--checks", "32", "--zoom=0.5"});
  EXPECT_EQ(s.checks, 32);
  EXPECT_FLOAT_EQ(s.zoom, 0.5f);
  o.parse({"--checks=2", "--zoom", "4"});
  EXPECT_EQ(s.checks, 2);
  EXPECT_FLOAT_EQ(s.zoom, 4.0f);
  for (const char* bad : {"33", "1", "2.5", "abc", "4x", "", "-8", "1e99"})
    EXPECT_NE(parseError(o, {"--checks", bad}), "") << bad;
  EXPECT_EQ(s.checks, 2);
  for (const char* bad : {"4.01", "0.49", "nan", "inf", "-inf", "1,5", "z"})
    EXPECT_NE(parseError(o, {"--zoom", bad}), "") << bad;
  EXPECT_FLOAT_EQ(s.zoom, 4.0f);
  EXPECT_NE(parseError(o, {"--checks=99"}).find("[2, 32]"), std::string::npos);
}

// Claim: text options go through their validator; a rejected value keeps the
// old one and the validator's message reaches the caller.
TEST(Options, TextIsValidated) {
  State s;
  ts::Options o;
  s.bind(o);
  o.parse({"--corners", "1,2 3,4"});
  EXPECT_EQ(s.corners, "1,2 3,4");
  EXPECT_NE(parseError(o, {"--corners=nocomma"}).find("has no comma"), std::string::npos);
  EXPECT_EQ(s.corners, "1,2 3,4");
}

// Claim: unknown options, positional arguments, a bare "--", --no- on a
// non-bool and a missing value are errors that name the culprit.
TEST(Options, BadArguments) {
  State s;
  ts::Options o;
  s.bind(o);
  EXPECT_NE(parseError(o, {"--nosuch"}).find("unknown option --nosuch"), std::string::npos);
  EXPECT_NE(parseError(o, {"--nosuch=1"}).find("unknown option --nosuch"), std::string::npos);
  EXPECT_NE(parseError(o, {"compare"}).find("unexpected argument 'compare'"), std::string::npos);
  EXPECT_NE(parseError(o, {"--"}), "");
  EXPECT_NE(parseError(o, {"-e"}), "");
  EXPECT_NE(parseError(o, {"--no-mode"}).find("unknown option --no-mode"), std::string::npos);
  EXPECT_NE(parseError(o, {"--mode"}).find("--mode needs a value"), std::string::npos);
  EXPECT_NE(parseError(o, {"--checks"}).find("--checks needs a value"), std::string::npos);
  EXPECT_THROW(o.set("nosuch", "1"), ts::Error);
  EXPECT_TRUE(o.has("zoom"));
  EXPECT_FALSE(o.has("zoo"));
}

// Claim: keys toggle bools, cycle enums (wrapping), step ints and floats by
// their step clamped to [lo, hi], and report whether they changed anything.
TEST(Options, HandleKey) {
  State s;
  ts::Options o;
  s.bind(o);
  EXPECT_TRUE(o.handleKey('e'));
  EXPECT_TRUE(s.edges);
  EXPECT_TRUE(o.handleKey('e'));
  EXPECT_FALSE(s.edges);
  for (int want : {1, 2, 0, 1}) {
    EXPECT_TRUE(o.handleKey('m'));
    EXPECT_EQ(s.mode, want);
  }
  o.parse({"--checks", "28"});
  o.handleKey('+');
  EXPECT_EQ(s.checks, 30);
  o.handleKey('+');
  o.handleKey('+');
  EXPECT_EQ(s.checks, 32);  // clamped at hi
  o.parse({"--checks", "3"});
  o.handleKey('-');
  EXPECT_EQ(s.checks, 2);  // 3 - 2 = 1, clamped at lo
  o.handleKey('z');
  EXPECT_FLOAT_EQ(s.zoom, 1.25f);
  for (int k = 0; k < 10; ++k) o.handleKey('x');
  EXPECT_FLOAT_EQ(s.zoom, 0.5f);
  EXPECT_FALSE(o.handleKey('q'));
  EXPECT_FALSE(o.handleKey(0));
  EXPECT_EQ(o.keysText(), "e: edges  m: mode  +/-: checks  z/x: zoom");
}

// Claim: helpText has one line per option naming its flag, its keys and its
// current value; stateText lists every name=value.
TEST(Options, HelpAndStateText) {
  State s;
  ts::Options o;
  s.bind(o);
  o.parse({"--mode", "grid"});
  std::string h = o.helpText();
  for (const char* want : {"--edges[=on|off]", "--mode book|compare|grid", "--checks [2..32]", "--zoom [0.5..4]",
                           "--corners TEXT", "key +/-", "(now grid)"})
    EXPECT_NE(h.find(want), std::string::npos) << want << " missing from\n" << h;
  EXPECT_EQ(std::count(h.begin(), h.end(), '\n'), 5);
  EXPECT_EQ(o.stateText(), "edges=off mode=grid checks=8 zoom=1 corners=0,0 1,1");
}

// Claim: parse(stateFlags()) on a freshly bound state reproduces the state,
// for every kind of option and both bool values (the sidecar's "command"
// and the window's state rely on it); text with spaces stays one argument.
TEST(Options, StateFlagsRoundTrip) {
  for (bool edges : {false, true}) {
    SCOPED_TRACE(edges ? "edges on" : "edges off");
    State s;
    ts::Options a;
    s.bind(a);
    a.parse({"--mode", "compare", "--checks", "14", "--zoom", "2.75", "--corners", "0.5,0.25 1,1"});
    s.edges = edges;
    State t;
    t.edges = !edges;  // start from the other value so the bool must be set
    ts::Options b;
    t.bind(b);
    ASSERT_NO_THROW(b.parse(a.stateFlags()));
    EXPECT_EQ(b.stateText(), a.stateText());
    EXPECT_EQ(t.edges, edges);
    EXPECT_EQ(t.mode, 1);
    EXPECT_EQ(t.checks, 14);
    EXPECT_FLOAT_EQ(t.zoom, 2.75f);
    EXPECT_EQ(t.corners, "0.5,0.25 1,1");
  }
}

// Claim: an empty text value (an unset file name, which its validator would
// refuse) is left out of stateFlags, so the round trip still parses.
TEST(Options, StateFlagsOmitEmptyText) {
  std::string file;
  ts::Options a;
  a.addText("texture", &file, "", [](const std::string& v) {
    if (v.empty()) throw ts::Error("--texture: empty");
  });
  for (const auto& f : a.stateFlags()) EXPECT_EQ(f.find("texture"), std::string::npos) << f;
  std::string file2 = "";
  ts::Options b;
  b.addText("texture", &file2, "", [](const std::string& v) {
    if (v.empty()) throw ts::Error("--texture: empty");
  });
  EXPECT_NO_THROW(b.parse(a.stateFlags()));
}

// Claim: --help shows FILE for a file option and TEXT for other free text.
TEST(Options, HelpShowsFileForFileOptions) {
  std::string file, corners;
  ts::Options o;
  o.addFile("texture", &file, "a picture", [](const std::string&) {});
  o.addText("corners", &corners, "corners", [](const std::string&) {});
  std::string help = o.helpText();
  EXPECT_NE(help.find("--texture FILE "), std::string::npos) << help;
  EXPECT_NE(help.find("--corners TEXT "), std::string::npos) << help;
  EXPECT_EQ(help.find("--texture TEXT"), std::string::npos) << help;
}

// Claim: adjust (the window's mouse) changes a number option by name within
// its range, and nothing else: no option of that name, a non-number, or no
// change gives false.
TEST(Options, AdjustClampsAndFindsByName) {
  State s;
  ts::Options o;
  s.bind(o);
  EXPECT_TRUE(o.adjust("zoom", [](double v) { return v * 1.5; }));
  EXPECT_FLOAT_EQ(s.zoom, 1.5f);
  EXPECT_TRUE(o.adjust("zoom", [](double v) { return v * 100; }));
  EXPECT_FLOAT_EQ(s.zoom, 4.0f);                                   // clamped to the range
  EXPECT_FALSE(o.adjust("zoom", [](double v) { return v + 1; }));  // already at the top
  EXPECT_TRUE(o.adjust("checks", [](double v) { return v + 2.6; }));
  EXPECT_EQ(s.checks, 11);
  EXPECT_FALSE(o.adjust("yaw", [](double v) { return v + 1; }));
  EXPECT_FALSE(o.adjust("mode", [](double v) { return v + 1; }));
  EXPECT_FALSE(o.adjust("corners", [](double v) { return v + 1; }));
  EXPECT_FALSE(o.adjust("zoom", [](double) { return std::nan(""); }));
  EXPECT_FLOAT_EQ(s.zoom, 4.0f);
}

// Claim: the orbit camera leaves a view untouched at its defaults (the book's
// figures stay byte-identical), turns the model about its centre (which
// stays where it was on screen), and zooms by scaling x and y only.
TEST(OrbitCamera, IdentityAtDefaultsAndTurnsAboutTheCentre) {
  ts::OrbitCamera cam;
  ts::Options o;
  cam.addOptions(o);
  glm::mat4 mv = glm::rotate(glm::translate(glm::mat4(1.0f), {0.3f, -0.2f, -5.0f}), 0.7f, glm::vec3(1, 2, 3));
  glm::mat4 pr = glm::perspective(0.6f, 1.5f, 1.0f, 10.0f);
  EXPECT_TRUE(cam.view(mv, glm::vec3(0.1f, 0.2f, 0.3f)) == mv);
  EXPECT_TRUE(cam.lens(pr) == pr);
  o.parse({"--yaw=90", "--pitch=-30", "--zoom=2"});
  glm::vec3 centre(0.1f, 0.2f, 0.3f);
  glm::mat4 v = cam.view(mv, centre);
  glm::vec4 c0 = mv * glm::vec4(centre, 1), c1 = v * glm::vec4(centre, 1);
  EXPECT_NEAR(glm::length(c0 - c1), 0.0f, 1e-5f);
  glm::vec4 p0 = mv * glm::vec4(1, 0, 0, 1), p1 = v * glm::vec4(1, 0, 0, 1);
  EXPECT_NEAR(glm::length(glm::vec3(p0 - c0)), glm::length(glm::vec3(p1 - c1)), 1e-5f);  // a rotation
  EXPECT_GT(glm::length(p0 - p1), 0.1f);
  glm::mat4 z = cam.lens(pr);
  glm::vec4 q(0.5f, -0.25f, -3.0f, 1.0f), a = pr * q, b = z * q;
  EXPECT_FLOAT_EQ(b.x, 2 * a.x);
  EXPECT_FLOAT_EQ(b.y, 2 * a.y);
  EXPECT_FLOAT_EQ(b.z, a.z);
  EXPECT_FLOAT_EQ(b.w, a.w);
}

// Claim: the same round trip through a real demo's options (Figure VI.1's
// scene; no GL needed to bind or parse).
TEST(Options, SceneStateFlagsRoundTrip) {
  auto s1 = ts::makeScene("quad_distortion"), s2 = ts::makeScene("quad_distortion");
  ASSERT_TRUE(s1 && s2);
  ts::Options a, b;
  s1->addOptions(a);
  s2->addOptions(b);
  a.parse({"--diagonal", "bl-tr", "--interp=projective", "--edges", "--view", "compare", "--filter", "nearest",
           "--checks", "12", "--corners", "0,0 1,0 0.5,0.875 0,1"});
  std::string before = b.stateText();
  ASSERT_NO_THROW(b.parse(a.stateFlags()));
  EXPECT_EQ(b.stateText(), a.stateText());
  EXPECT_NE(b.stateText(), before);
}

// Claim: Figure VI.1's --corners validator refuses what it cannot draw:
// garbage, too few or too many pairs, non-finite or huge values, and three
// corners in a line; it accepts the book's corners.
TEST(Options, QuadDistortionCornersAreValidated) {
  auto scene = ts::makeScene("quad_distortion");
  ASSERT_TRUE(scene);
  ts::Options o;
  scene->addOptions(o);
  EXPECT_EQ(parseError(o, {"--corners", "0,0 1,0 0.75,0.75 0,1"}), "");
  for (const char* bad : {"garbage", "0,0 1,0 1,1", "0,0 1,0 1,1 0,1 2,2", "0,0 1,0 nan,1 0,1", "0,0 1,0 65,1 0,1",
                          "0;0 1;0 1;1 0;1", "0,0 0.5,0 1,0 0,1", ""})
    EXPECT_NE(parseError(o, {"--corners", bad}).find("--corners"), std::string::npos) << "'" << bad << "'";
  // The refused values left the accepted one in place.
  EXPECT_NE(o.stateText().find("corners=0,0 1,0 0.75,0.75 0,1"), std::string::npos) << o.stateText();
}

// Claim: corners that do not form a convex quadrilateral are refused too.
// KNOWN BUG (demos/quad_distortion/quad_distortion_math.hpp, parseCorners): only collinear triples are
// rejected, so a bow-tie ("0,0 1,0 0,1 1,1") or a concave quad ("0,0 1,0 0.2,0.2 0,1") is accepted; the
// homography's q then changes sign inside the square and the projective
// variant is garbage (measured: kink_deg[projective] = 135 deg for the
// bow-tie, texel_error_max[projective] = 1024 for the concave quad), so the
// figure's claim "projective coordinates remove the kink" fails.  Enable
// once parseCorners requires the four turns to have one sign.
TEST(Options, QuadDistortionRefusesNonConvexCorners) {
  auto scene = ts::makeScene("quad_distortion");
  ASSERT_TRUE(scene);
  ts::Options o;
  scene->addOptions(o);
  for (const char* bad : {"0,0 1,0 0,1 1,1", "0,0 1,0 0.2,0.2 0,1"})
    EXPECT_NE(parseError(o, {"--corners", bad}), "") << "'" << bad << "' was accepted";
  // Convex quads of either orientation stay accepted.
  EXPECT_EQ(parseError(o, {"--corners", "0,0 0,1 0.75,0.75 1,0"}), "");
}

// Claim: flags that take no value (--quiet, --help) refuse "=value" rather
// than ignore it.  KNOWN BUG (common/core/options.cpp, parseCommonFlags, the
// "--help" and "--quiet" branches): "--quiet=off" turns quiet ON and
// "--help=no" prints the help.  Enable once they reject an inline value.
TEST(CommonFlags, ValuelessFlagsRefuseAValue) {
  for (const char* flag : {"--quiet=off", "--help=no"}) {
    std::vector<std::string> args{"demo", flag};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    ts::CommonFlags f;
    EXPECT_THROW(ts::parseCommonFlags(int(argv.size()), argv.data(), &f), ts::Error) << flag;
  }
}

// Claim: parseSize accepts "WxH" with 1 <= W, H <= 16384 and nothing else;
// a refused size leaves the outputs untouched.
TEST(ParseSize, GoodAndBad) {
  int w = -1, h = -1;
  ts::parseSize("640x480", &w, &h);
  EXPECT_EQ(w, 640);
  EXPECT_EQ(h, 480);
  ts::parseSize("1x1", &w, &h);
  EXPECT_EQ(w, 1);
  EXPECT_EQ(h, 1);
  ts::parseSize("16384x16384", &w, &h);
  EXPECT_EQ(w, 16384);
  EXPECT_EQ(h, 16384);
  for (const char* bad : {"0x10", "10x0", "-5x5", "5x-5", "16385x10", "10x16385", "abc", "12x", "x12", "x", "",
                          "12x12x12", " 12x12", "12X12", "+5x5", "1.5x2", "99999999x1", "0010x"}) {
    w = h = -1;
    try {
      ts::parseSize(bad, &w, &h);
      ADD_FAILURE() << "'" << bad << "' was accepted as " << w << "x" << h;
    } catch (const ts::Error& e) {
      EXPECT_NE(std::string(e.what()).find("--size"), std::string::npos) << e.what();
      EXPECT_EQ(e.exit_code, ts::kExitUsage);
    }
    EXPECT_EQ(w, -1) << bad;
    EXPECT_EQ(h, -1) << bad;
  }
}

// Claim: parseCommonFlags takes the shared flags (both "--f v" and "--f=v"),
// passes everything else through in order, and refuses a directory as --png.
TEST(CommonFlags, SplitsSharedFromDemoFlags) {
  std::vector<std::string> args{"demo",  "--diagonal", "bl-tr",   "--png=out.png", "--size",
                                "64x32", "--edges",    "--quiet", "--frames",      "3"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  ts::CommonFlags f;
  std::vector<std::string> rest = ts::parseCommonFlags(int(argv.size()), argv.data(), &f);
  EXPECT_EQ(rest, (std::vector<std::string>{"--diagonal", "bl-tr", "--edges"}));
  EXPECT_EQ(f.png, "out.png");
  EXPECT_EQ(f.width, 64);
  EXPECT_EQ(f.height, 32);
  EXPECT_TRUE(f.quiet);
  EXPECT_EQ(f.frames, 3);

  std::vector<std::string> bad{"demo", "--png", "some/dir/"};
  std::vector<char*> bargv;
  for (auto& a : bad) bargv.push_back(a.data());
  ts::CommonFlags g;
  EXPECT_THROW(ts::parseCommonFlags(int(bargv.size()), bargv.data(), &g), ts::Error);
  std::vector<std::string> missing{"demo", "--size"};
  std::vector<char*> margv;
  for (auto& a : missing) margv.push_back(a.data());
  EXPECT_THROW(ts::parseCommonFlags(int(margv.size()), margv.data(), &g), ts::Error);
}
}  // namespace
