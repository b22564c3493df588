// tests/figures/fig_gl_listing_test.cpp — the OpenGL listings:
// a listing is the calls that drew the picture, so it changes exactly where
// the state changes, it holds the call a figure is about, and every line of
// every book figure's listing reads back as C with enums the GL headers know.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include "common/gl/figure.hpp"
#include "common/gl/gl_listing.hpp"
#include "tests/support/scene_test.hpp"

namespace {
std::vector<std::string> listingOf(const std::string& demo, const std::vector<std::string>& flags, int w, int h) {
  ts::test::Demo d(demo, flags);
  d.measure();
  ts::Frame f = d.frame(w, h);
  std::vector<std::string> out;
  for (const ts::ListingLine& l : ts::listing(ts::recordPicture(ts::test::renderer(), f))) out.push_back(l.text);
  return out;
}

// Claim: --filter nearest and --filter linear differ in the filter lines and
// nowhere else (the same calls draw the rest of the picture).
TEST(GlListing, FilterChangesExactlyTheFilterLines) {
  auto nearest = listingOf("quad_distortion", {"--filter", "nearest"}, 512, 256);
  auto linear = listingOf("quad_distortion", {"--filter", "linear"}, 512, 256);
  ASSERT_EQ(nearest.size(), linear.size());
  int differ = 0;
  for (size_t k = 0; k < nearest.size(); ++k) {
    if (nearest[k] == linear[k]) continue;
    ++differ;
    bool filterLine = nearest[k].find("GL_TEXTURE_MIN_FILTER") != std::string::npos ||
                      nearest[k].find("GL_TEXTURE_MAG_FILTER") != std::string::npos;
    EXPECT_TRUE(filterLine) << "line " << k << " differs: " << nearest[k] << " / " << linear[k];
    if (filterLine) {
      EXPECT_NE(nearest[k].find("GL_NEAREST"), std::string::npos) << nearest[k];
      EXPECT_NE(linear[k].find("GL_LINEAR"), std::string::npos) << linear[k];
    }
  }
  EXPECT_GE(differ, 2) << "the checkerboard's two filter lines must change";
}

// Claim: Figure VI.2's listing holds the hint the figure is about.
TEST(GlListing, PerspectiveCorrectionSetsTheHint) {
  auto l = listingOf("perspective_correction", {}, 512, 256);
  EXPECT_NE(std::find(l.begin(), l.end(), "glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);"), l.end());
}

// ---- pictures a scene renders itself ----------------------------------------
// The --gl-listing file of a state: what `environment_mapping --gl-listing F`
// writes (renderScene records, glListingFile formats), split into lines.
std::vector<std::string> listingFileOf(const std::string& demo, const std::vector<std::string>& flags, int w, int h) {
  ts::test::Demo d(demo, flags);
  ts::Rendered got = ts::renderScene(*d.scene, ts::test::renderer(), w, h, true);
  std::istringstream text(ts::glListingFile(got, demo));
  std::vector<std::string> out;
  for (std::string l; std::getline(text, l);) out.push_back(l);
  return out;
}
// The lines of the section headed by a comment starting with `heading`, up to the next heading.
std::vector<std::string> section(const std::vector<std::string>& l, const std::string& heading) {
  auto at = std::find_if(l.begin(), l.end(), [&](const std::string& s) { return s.rfind(heading, 0) == 0; });
  std::vector<std::string> out;
  for (auto it = at == l.end() ? at : at + 1; it != l.end() && it->rfind("/* the ", 0) != 0; ++it) out.push_back(*it);
  return out;
}
bool has(const std::vector<std::string>& l, const std::string& part) {
  return std::any_of(l.begin(), l.end(), [&](const std::string& s) { return s.find(part) != std::string::npos; });
}

// Claim: environment mapping's pictures are GL renders of nested frames made
// in measure() and shown as textures; the listing holds the calls that rendered them, under a
// comment naming the panel, before the frame's own: GL_SPHERE_MAP texgen for
// the sphere map per vertex, GL_REFLECTION_MAP texgen on a bound cube map for
// the cube map per vertex, a GLSL program and no texgen per pixel.
TEST(GlListing, EnvironmentMappingListsTheTexgenThatRenderedThePicture) {
  auto sphere = listingFileOf("environment_mapping", {"--param", "sphere", "--eval", "vertex"}, 540, 220);
  auto picture = section(sphere, "/* the picture in panel 'picture'");
  ASSERT_FALSE(picture.empty()) << "no section for panel 'picture'";
  EXPECT_TRUE(has(picture, "glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);"));
  EXPECT_TRUE(has(picture, "glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);"));
  EXPECT_FALSE(has(picture, "GL_REFLECTION_MAP"));
  EXPECT_FALSE(has(section(sphere, "/* the frame, drawn with those pictures"), "glTexGeni"))
      << "the frame only shows the pictures: the texgen is the render's";
  auto heading = [&](const std::vector<std::string>& l, const std::string& h) {
    return std::find_if(l.begin(), l.end(), [&](const std::string& s) { return s.rfind(h, 0) == 0; }) - l.begin();
  };
  EXPECT_LT(heading(sphere, "/* the picture in panel 'picture'"), heading(sphere, "/* the frame, drawn"));
  EXPECT_LT(heading(sphere, "/* the picture in panel 'reference'"), heading(sphere, "/* the frame, drawn"));

  auto cube = listingFileOf("environment_mapping", {"--param", "cube", "--eval", "vertex"}, 540, 220);
  picture = section(cube, "/* the picture in panel 'picture'");
  for (const char* coord : {"GL_S", "GL_T", "GL_R"})
    EXPECT_TRUE(has(picture, std::string("glTexGeni(") + coord + ", GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);"))
        << coord;
  EXPECT_TRUE(has(picture, "glBindTexture(GL_TEXTURE_CUBE_MAP, "));
  EXPECT_TRUE(has(picture, "glTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, ")) << "the map is made in the section";
  // The texture matrix turns eye space into the world's: loaded once the eye
  // turns (at yaw 0, pitch 0 it is the identity, which the frame leaves out).
  EXPECT_FALSE(has(picture, "glMatrixMode(GL_TEXTURE);"));
  auto turned = section(listingFileOf("environment_mapping", {"--param", "cube", "--eval", "vertex", "--yaw", "30"},
                                      540, 220),
                        "/* the picture in panel 'picture'");
  EXPECT_TRUE(has(turned, "glMatrixMode(GL_TEXTURE);"));

  auto perPixel = listingFileOf("environment_mapping", {"--param", "cube", "--eval", "pixel"}, 540, 220);
  picture = section(perPixel, "/* the picture in panel 'picture'");
  EXPECT_FALSE(has(picture, "glTexGeni"));
  EXPECT_TRUE(has(picture, "glShaderSource("));
  EXPECT_TRUE(has(picture, "textureCube(mapCube, r)")) << "the fragment shader's lookup is in the listing";
}

// Claim: the pane's highlight covers the render's lines: from r per pixel to
// r per vertex, the texgen lines are marked changed (yellow in the pane).
TEST(GlListing, TheRenderedPicturesLinesAreMarkedWhenAKeyChangesThem) {
  auto sections = [](const std::vector<std::string>& flags) {
    ts::test::Demo d("environment_mapping", flags);
    ts::Rendered got = ts::renderScene(*d.scene, ts::test::renderer(), 540, 220, true);
    return ts::pictureSections(got.frame, got.calls);
  };
  auto before = sections({"--eval", "pixel"});
  auto after = sections({"--eval", "vertex"});
  bool texgen = false, frameLine = false;
  bool inFrame = false;
  for (const ts::ListingLine& l : ts::listing(after, &before, 3)) {
    inFrame |= l.text.rfind("/* the frame", 0) == 0;
    if (l.changed && l.text == "glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);") texgen = true;
    if (l.changed && inFrame && l.text.find("glTexGen") != std::string::npos) frameLine = true;
  }
  EXPECT_TRUE(texgen);
  EXPECT_FALSE(frameLine);
  // A frame without such pictures lists as before: no section comments.
  auto quad = listingFileOf("quad_distortion", {}, 512, 256);
  EXPECT_FALSE(has(quad, "/* the frame, drawn")) << "a plain frame's listing must not change";
}

// The glBegin ... glEnd blocks of a section, each as its lines.
std::vector<std::vector<std::string>> blocks(const std::vector<std::string>& l) {
  std::vector<std::vector<std::string>> out;
  bool in = false;
  for (const std::string& s : l) {
    if (s.rfind("glBegin(", 0) == 0) out.emplace_back(), in = true;
    if (in) out.back().push_back(s);
    if (s == "glEnd();") in = false;
  }
  return out;
}
std::vector<std::string> linesStarting(const std::vector<std::string>& l, const std::string& prefix) {
  std::vector<std::string> out;
  for (const std::string& s : l)
    if (s.rfind(prefix, 0) == 0) out.push_back(s);
  return out;
}

// Claim: bump mapping's B4 picture is seed 001's three passes, and the
// listing shows them: the heights, then with glBlendFunc(GL_ONE, GL_ONE) the
// same triangles with their texture coordinates shifted toward the light,
// then the diffuse light multiplied in.  B5's is GL_COMBINE's GL_DOT3_RGB of
// the normal map and the vertex colour; R's is a shader on the 1024 x 512
// grid, its vertex list not in the listing.
TEST(GlListing, BumpMappingListsTheEmbossPassesAndTheDot3Combiner) {
  auto emboss = listingFileOf("bump_mapping", {"--method", "emboss"}, 1024, 512);
  auto picture = section(emboss, "/* the picture in panel 'picture_emboss'");
  ASSERT_FALSE(picture.empty()) << "no section for panel 'picture_emboss'";
  EXPECT_TRUE(has(picture, "glBlendFunc(GL_ONE, GL_ONE);"));
  EXPECT_TRUE(has(picture, "glBlendFunc(GL_DST_COLOR, GL_SRC_COLOR);"));
  auto passes = blocks(picture);
  ASSERT_EQ(passes.size(), 3u) << "emboss draws the torus three times";
  auto st0 = linesStarting(passes[0], "glTexCoord2f("), st1 = linesStarting(passes[1], "glTexCoord2f(");
  ASSERT_FALSE(st0.empty());
  ASSERT_EQ(st0.size(), st1.size());
  EXPECT_EQ(linesStarting(passes[0], "glVertex3f("), linesStarting(passes[1], "glVertex3f(")) << "the same triangles";
  for (size_t k = 0; k < st0.size(); ++k) EXPECT_NE(st0[k], st1[k]) << "the second pass's (s, t) are shifted";
  EXPECT_TRUE(linesStarting(passes[2], "glTexCoord2f(").empty()) << "the light pass is untextured";
  EXPECT_FALSE(has(emboss, "GL_DOT3_RGB"));
  EXPECT_FALSE(has(section(emboss, "/* the frame, drawn with those pictures"), "GL_DST_COLOR"))
      << "the frame only shows the picture: the passes are the render's";

  auto dot3 = listingFileOf("bump_mapping", {"--method", "dot3"}, 1024, 512);
  picture = section(dot3, "/* the picture in panel 'picture_dot3'");
  ASSERT_FALSE(picture.empty()) << "no section for panel 'picture_dot3'";
  for (const char* line : {"glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);",
                           "glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB);",
                           "glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);",
                           "glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR);"})
    EXPECT_TRUE(has(picture, line)) << line;
  EXPECT_FALSE(has(picture, "GL_DST_COLOR"));

  auto reference = section(dot3, "/* the picture in panel 'picture_reference'");
  ASSERT_FALSE(reference.empty()) << "no section for panel 'picture_reference'";
  EXPECT_TRUE(has(reference, "glShaderSource("));
  EXPECT_TRUE(has(reference, "glDrawElements(GL_TRIANGLES, " + std::to_string(1024 * 512 * 6) + ", "))
      << "R: two triangles per cell of the 1024 x 512 grid";
  EXPECT_LT(dot3.size(), 2000u) << "vertex lists stay folded";
}

// Claim: parallax_aniso's measured pictures list the program that drew each
// (its source with the mode's #define, glUseProgram) and the filter it set:
// M2 asks for 16x anisotropy, M0 for none.  The live view draws every frame
// and is not recorded.
TEST(GlListing, ParallaxListsTheProgramOfEachMeasuredPicture) {
  const std::vector<std::string> flags = {"--view", "modes", "--map", "bricks", "--res", "80", "--rays", "2"};
  auto l = listingFileOf("parallax_aniso", flags, 1360, 660);
  auto naive = section(l, "/* the picture in panel 'image_naive'");
  auto aniso = section(l, "/* the picture in panel 'image_aniso16'");
  ASSERT_FALSE(naive.empty());
  ASSERT_FALSE(aniso.empty());
  for (const auto* s : {&naive, &aniso}) {
    EXPECT_TRUE(has(*s, "glShaderSource("));
    EXPECT_TRUE(has(*s, "glUseProgram("));
  }
  EXPECT_TRUE(has(naive, "#define MODE 0"));
  EXPECT_TRUE(has(aniso, "#define MODE 2"));
  EXPECT_TRUE(has(naive, "GL_TEXTURE_MAX_ANISOTROPY, 1);"));
  EXPECT_TRUE(has(aniso, "GL_TEXTURE_MAX_ANISOTROPY, 16);"));
  EXPECT_FALSE(has(naive, "GL_TEXTURE_MAX_ANISOTROPY, 16);"));
  EXPECT_EQ(std::count_if(l.begin(), l.end(),
                          [](const std::string& s) { return s.find("was rendered by:") != std::string::npos; }),
            6)
      << "a section per GL mode, M0-M5; the reference is traced on the CPU";

  auto live = listingFileOf("parallax_aniso", {"--view", "live", "--map", "bricks", "--res", "80"}, 320, 240);
  EXPECT_FALSE(has(live, "was rendered by:")) << "the live view is not recorded";
}

// ---- reading a listing back as C -------------------------------------------
// The statements of a listing: comments dropped, string literals kept whole,
// split at the ';' that ends each call.
std::vector<std::string> statements(const std::string& text, std::string* error) {
  std::vector<std::string> out;
  std::string cur;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      size_t end = text.find("*/", i + 2);
      if (end == std::string::npos) return *error = "an unterminated comment", out;
      i = end + 1;
      cur += ' ';
      continue;
    }
    if (c == '"') {
      size_t j = i + 1;
      while (j < text.size() && text[j] != '"') j += text[j] == '\\' ? 2 : 1;
      if (j >= text.size()) return *error = "an unterminated string", out;
      cur += "\"\"";  // the string's contents are not C syntax
      i = j;
      continue;
    }
    if (c == ';') {
      out.push_back(cur);
      cur.clear();
      continue;
    }
    cur += c;
  }
  for (char c : cur)
    if (!std::isspace(static_cast<unsigned char>(c))) return *error = "text after the last ';': " + cur, out;
  return out;
}

// One statement: name(arguments) where name is a GL function of the suite,
// parentheses and braces balance, and every GL_ identifier is an enum.
std::string checkCall(const std::string& raw) {
  std::string s = raw;
  s.erase(0, s.find_first_not_of(" \n\t"));
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  static const std::set<std::string> functions = {
#define TS_GL_NAME(name) #name,
      TS_GL_FUNCTIONS(TS_GL_NAME)
#undef TS_GL_NAME
  };
  size_t open = s.find('(');
  if (open == std::string::npos || s.back() != ')') return "not a call";
  std::string name = s.substr(0, open);
  if (!functions.count(name)) return "unknown function " + name;
  int depth = 0;
  for (char c : s) {
    depth += (c == '(' || c == '{' || c == '[') - (c == ')' || c == '}' || c == ']');
    if (depth < 0) return "unbalanced";
  }
  if (depth != 0) return "unbalanced";
  for (size_t i = open; i < s.size(); ++i) {
    if (s.compare(i, 3, "GL_") != 0 ||
        (i > 0 && (std::isalnum(static_cast<unsigned char>(s[i - 1])) || s[i - 1] == '_')))
      continue;
    size_t j = i;
    while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
    std::string id = s.substr(i, j - i);
    if (id != "GLfloat" && id != "GLuint" && id != "GLchar" && !ts::gl::enumValue(id, nullptr))
      return "unknown enum " + id;
    i = j;
  }
  // The rest: numbers, type names of compound literals, NULL, NAN/INFINITY.
  for (size_t i = open + 1; i + 1 < s.size(); ++i) {
    char c = s[i];
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      size_t j = i;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_' || s[j] == '+' ||
                              ((s[j] == '-') && j > 0 && s[j - 1] == 'e')))
        ++j;
      std::string id = s.substr(i, j - i);
      bool ok = id.rfind("GL_", 0) == 0 || id == "GLfloat" || id == "GLdouble" || id == "GLuint" || id == "GLchar" ||
                id == "const" || id == "NULL" || id == "NAN" || id == "INFINITY";
      bool exponent = i > open + 1 && std::isdigit(static_cast<unsigned char>(s[i - 1])) && c == 'e';
      if (!ok && !exponent) return "unexpected word " + id;
      i = j - 1;
    }
  }
  return "";
}

// Claim: every registered figure has its listing in book_figures/, and every
// line of it reads back as C: known functions, known enums, balanced.
TEST(GlListing, EveryFigureListingReadsBackAsC) {
  int figures = 0;
  for (const auto& reg : ts::sceneRegistry())
    for (const ts::FigureSpec& spec : reg.make()->figures()) {
      ++figures;
      std::ifstream in("book_figures/" + spec.id + ".gl.txt");
      ASSERT_TRUE(in) << "book_figures/" << spec.id << ".gl.txt is missing (scripts/figures.sh writes it)";
      std::stringstream text;
      text << in.rdbuf();
      std::string error;
      std::vector<std::string> calls = statements(text.str(), &error);
      EXPECT_TRUE(error.empty()) << spec.id << ": " << error;
      EXPECT_GT(calls.size(), 10u) << spec.id;
      int bad = 0;
      for (const std::string& c : calls) {
        std::string why = checkCall(c);
        if (!why.empty() && ++bad <= 3) ADD_FAILURE() << spec.id << ": " << why << " in: " << c.substr(0, 200);
      }
      EXPECT_EQ(bad, 0) << spec.id;
      EXPECT_NE(text.str().find("glBegin("), std::string::npos) << spec.id;
    }
  EXPECT_GT(figures, 0);
}

// The checker itself rejects what is not C with known enums (so the test
// above can fail).
TEST(GlListing, TheReaderRejectsWhatIsNotAListing) {
  EXPECT_EQ(checkCall("glEnable(GL_TEXTURE_2D)"), "");
  EXPECT_NE(checkCall("glEnable(GL_NOT_AN_ENUM)"), "");
  EXPECT_NE(checkCall("glFrobnicate(1)"), "");
  EXPECT_NE(checkCall("glEnable(GL_TEXTURE_2D"), "");
  EXPECT_NE(checkCall("glEnable(0x9999 banana)"), "");
  EXPECT_EQ(checkCall("glLoadMatrixf((const GLfloat[2]){1, -2.5e-05})"), "");
}
}  // namespace
