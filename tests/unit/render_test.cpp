// tests/unit/render_test.cpp — the Frame renderer (common/gl/render.cpp) on the
// test context.  The one unit program that needs GL: it checks the
// conventions every figure test relies on (viewports from the top-left,
// texture row 0 = t = 0, cropping, measurement passes) on tiny frames.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <memory>

#include "common/core/error.hpp"
#include "common/core/frame.hpp"
#include "common/core/probe.hpp"
#include "common/gl/render.hpp"
#include "tests/support/gl_test.hpp"

namespace {
int tol() { return ts::probe::tolerance(8); }
glm::vec4 rgba(ts::Rgba c) { return glm::vec4(c.r, c.g, c.b, c.a) / 255.0f; }

const ts::Rgba kBlack{0, 0, 0, 255}, kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255},
    kWhite{255, 255, 255, 255};

// A unit-square panel (ortho 0..1) at `vp` holding one quad of two triangles
// with (s,t) = (a,b), optionally textured, in `color`.
ts::Panel squarePanel(const std::string& id, ts::Rect vp, int texture, glm::vec4 color) {
  ts::Panel p;
  p.id = id;
  p.viewport = vp;
  p.projection = glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f);
  ts::Batch b;
  b.role = "square";
  b.texture = texture;
  for (glm::vec2 c :
       {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 0), glm::vec2(1, 1), glm::vec2(0, 1)})
    b.vertices.push_back({{c, 0}, {c, 0, 1}, color});
  p.batches.push_back(b);
  return p;
}

// Two panels in a 64x40 frame: a cleared red one at (5,3) 20x10 and a green
// square at (40,25) 16x12 — placed asymmetrically so a flipped y shows.
ts::Frame twoPanels() {
  ts::Frame f;
  f.width = 64;
  f.height = 40;
  f.clearColor = rgba(kBlack);
  ts::Panel red;
  red.id = "red";
  red.viewport = {5, 3, 20, 10};
  red.clear = true;
  red.clearColor = rgba(kRed);
  f.panels.push_back(red);
  f.panels.push_back(squarePanel("green", {40, 25, 16, 12}, -1, rgba(kGreen)));
  return f;
}

// Claim: panel viewports are in image pixels from the top-left, and nothing
// is drawn outside them.
TEST(Render, PanelViewportsAreTopLeftOrigin) {
  ts::Frame f = twoPanels();
  ts::Image img = ts::test::renderer().render(f, false);
  ASSERT_EQ(img.width, 64);
  ASSERT_EQ(img.height, 40);
  ts::probe::Result r = ts::probe::rect(img, {5, 3, 20, 10}, kRed, tol());
  EXPECT_TRUE(r.ok()) << r.describe();
  r = ts::probe::rect(img, {40, 25, 16, 12}, kGreen, tol());
  EXPECT_TRUE(r.ok()) << r.describe();
  long black = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 64; ++x) black += ts::probe::close(img.at(x, y), kBlack, tol());
  EXPECT_EQ(black, 64 * 40 - 20 * 10 - 16 * 12);
}

// Claim: a frame smaller than the target is read back from where GL drew it
// (cropped): the same pixels as on a target of exactly the frame's size; a
// frame larger than the target is an error.
TEST(Render, SmallFrameOnALargeTargetIsCropped) {
  ts::Context& ctx = ts::test::context();
  ts::Frame f = twoPanels();
  ctx.resize(200, 100);
  ts::Image big = ts::test::renderer().render(f, false);
  ctx.resize(64, 40);
  ts::Image exact = ts::test::renderer().render(f, false);
  EXPECT_TRUE(big.pixels == exact.pixels);
  ts::Frame huge = f;
  huge.width = 65;
  EXPECT_THROW(ts::test::renderer().render(huge, false), ts::Error);
  ctx.resize(512, 512);
}

// Claim: texture row 0 is t = 0 (the bottom of the panel) and column 0 is
// s = 0 (the left): a 2x2 texture drawn GL_NEAREST on a square shows texel
// (0,0) at the bottom-left, (1,0) bottom-right, (0,1) top-left, (1,1)
// top-right of the picture.
TEST(Render, TextureRowZeroIsTheBottom) {
  auto img2 = std::make_shared<ts::Image>(2, 2);
  img2->set(0, 0, kRed);
  img2->set(1, 0, kGreen);
  img2->set(0, 1, kBlue);
  img2->set(1, 1, kWhite);
  ts::TextureDesc t;
  t.name = "render_test_2x2";
  t.image = img2;
  t.minFilter = t.magFilter = GL_NEAREST;
  ts::Frame f;
  f.width = f.height = 40;
  int tex = f.addTexture(t);
  f.panels.push_back(squarePanel("square", {4, 4, 32, 32}, tex, glm::vec4(1)));
  ts::Image img = ts::test::renderer().render(f, false);
  struct {
    ts::Rect r;
    ts::Rgba want;
  } quads[] = {{{5, 21, 14, 14}, kRed}, {{21, 21, 14, 14}, kGreen}, {{5, 5, 14, 14}, kBlue}, {{21, 5, 14, 14}, kWhite}};
  for (const auto& q : quads) {
    ts::probe::Result r = ts::probe::rect(img, q.r, q.want, tol());
    EXPECT_TRUE(r.ok()) << r.describe();
  }
}

// Claim: renderOffscreen (the measurement passes) gives the pixels render()
// gives, and leaves the context's own target as it was.
TEST(Render, RenderOffscreenMatchesRenderAndKeepsTheTarget) {
  ts::Frame f = twoPanels();
  ts::Image onTarget = ts::test::renderer().render(f, false);
  ts::Frame other = f;
  other.clearColor = rgba(kBlue);
  ts::Image off = ts::test::renderer().renderOffscreen(other);
  ts::Image again = ts::test::renderer().renderOffscreen(f);
  EXPECT_TRUE(again.pixels == onTarget.pixels);
  EXPECT_TRUE(ts::probe::close(off.at(0, 0), kBlue, tol()));
  // The target still holds the first frame (bottom-left 64x40 of 512x512).
  ts::Image target = ts::test::context().readPixels();
  int dy = target.height - f.height;
  long differ = 0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) differ += !ts::probe::close(target.at(x, y + dy), onTarget.at(x, y), tol());
  EXPECT_EQ(differ, 0);
}

// Claim: panelToPixels maps a panel's normalised device corners to its
// viewport's corners (y down), dividing by w.
TEST(Render, PanelToPixels) {
  ts::Panel p;
  p.viewport = {10, 20, 100, 50};
  glm::vec2 bl = ts::panelToPixels(p, {-1, -1, 0, 1}), tr = ts::panelToPixels(p, {2, 2, 0, 2});
  EXPECT_FLOAT_EQ(bl.x, 10);
  EXPECT_FLOAT_EQ(bl.y, 70);
  EXPECT_FLOAT_EQ(tr.x, 110);
  EXPECT_FLOAT_EQ(tr.y, 20);
}
}  // namespace
