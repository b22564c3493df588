// tests/unit/inspect_pick_test.cpp — what the window's inspect mode draws and
// marks for a picked pixel, on the test context:
//   - the footprint in the demo's own texture-space view lands on the texels
//     the pixel reads (common/app/inspect_view.hpp, footprintInTextureViews);
//   - the GL pane's cyan marks are the calls that set the picked batch's
//     texture state, and only those (common/gl/gl_listing.hpp, batchTextureCalls).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "common/app/inspect_view.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/gl/gl_listing.hpp"
#include "reference/inspect.hpp"
#include "tests/support/gl_test.hpp"

namespace {
const ts::Panel* panelNamed(const ts::Frame& f, const std::string& id) {
  for (const ts::Panel& p : f.panels)
    if (p.id == id) return &p;
  return nullptr;
}
const ts::Batch* batchNamed(const ts::Panel& p, const std::string& role) {
  for (const ts::Batch& b : p.batches)
    if (b.role == role) return &b;
  return nullptr;
}

// Claim: a pixel picked in quad_distortion's screen-space view gets its
// footprint drawn in the texture-space view, where (s, t) is the panel's own
// coordinate (its texture quad has pos = tex): every corner of the drawn
// preimage is the inspector's preimage corner (u, v) / 256; the picked view
// itself gets nothing; a pick in the texture-space view (no other view shows
// that texture flat) is drawn in no view.
TEST(InspectPick, FootprintLandsOnItsTexelsInTheTextureSpaceView) {
  auto scene = ts::makeScene("quad_distortion");
  ASSERT_TRUE(scene);
  ts::Options opts;
  scene->addOptions(opts);
  const ts::Frame f = scene->build(1024, 560, {});
  const ts::Panel* screen = panelNamed(f, "screen_space");
  const ts::Panel* texture = panelNamed(f, "texture_space");
  ASSERT_TRUE(screen && texture);
  const ts::Batch* quad = batchNamed(*texture, "texture");
  ASSERT_TRUE(quad);
  for (const ts::Vertex& v : quad->vertices) ASSERT_EQ(glm::vec2(v.pos), glm::vec2(v.tex)) << "the test's premise";
  const ref::Inspector inspector(f);
  // The screen-space panel's centre (frame rows count from the top).
  const ref::Inspection in = inspector.at(screen->viewport.x + screen->viewport.w / 2,
                                          screen->viewport.y + screen->viewport.h / 2);
  ASSERT_TRUE(in.textured) << in.note;
  ts::Frame over;
  ASSERT_TRUE(ts::footprintInTextureViews(f, in, &over));
  ASSERT_EQ(over.panels.size(), 1u);
  EXPECT_EQ(over.panels[0].id, "texture_space_footprint");
  EXPECT_EQ(over.panels[0].viewport.x, texture->viewport.x);
  EXPECT_EQ(over.panels[0].viewport.w, texture->viewport.w);
  const ts::Batch* preimage = batchNamed(over.panels[0], "preimage");
  ASSERT_TRUE(preimage);
  ASSERT_EQ(preimage->vertices.size(), 4u);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(preimage->vertices[k].pos.x, in.preimage[k].x / 256.0, 1e-5) << k;
    EXPECT_NEAR(preimage->vertices[k].pos.y, in.preimage[k].y / 256.0, 1e-5) << k;
  }
  // The texels read: outlines one texel wide, at the texels' corners.
  const ts::Batch* texel = batchNamed(over.panels[0], "texel_read");
  ASSERT_TRUE(texel);
  EXPECT_NEAR(texel->vertices[1].pos.x - texel->vertices[0].pos.x, std::exp2(in.texels[0].level) / 256.0, 1e-6);
  // A pick in the texture-space view, at (s, t) = (1/4, 1/4),
  // away from the lines drawn over it: drawn in no other view.
  const ref::Inspection own = inspector.at(texture->viewport.x + texture->viewport.w / 4,
                                           texture->viewport.y + texture->viewport.h * 3 / 4);
  ASSERT_TRUE(own.textured) << own.note;
  EXPECT_FALSE(ts::footprintInTextureViews(f, own, &over));
  // The side panel's cell: a frame of the cell's size, the footprint in it.
  const ts::Frame cell = ts::footprintCell(f, in, 256, 256);
  ASSERT_EQ(cell.panels.size(), 1u);
  EXPECT_TRUE(batchNamed(cell.panels[0], "ewa_ellipse"));
}

ts::Batch triangle(int texture) {
  ts::Batch b;
  b.role = texture >= 0 ? "textured" : "plain";
  b.texture = texture;
  for (glm::vec2 p : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1)})
    b.vertices.push_back({glm::vec3(p, 0.0f), glm::vec4(p, 0.0f, 1.0f), glm::vec4(1.0f)});
  return b;
}
std::vector<std::string> markedCalls(const std::vector<ts::gl::Call>& calls, int ordinal) {
  const std::vector<bool> m = ts::batchTextureCalls(calls, ordinal);
  EXPECT_EQ(m.size(), calls.size());
  std::vector<std::string> out;
  for (size_t k = 0; k < calls.size(); ++k)
    if (m[k]) out.push_back(std::to_string(k) + " " + ts::gl::formatCall(calls[k]));
  return out;
}
int count(const std::vector<std::string>& lines, const char* text) {
  int n = 0;
  for (const std::string& l : lines) n += l.find(text) != std::string::npos;
  return n;
}

// Claim: for three batches (textured, untextured, textured with the same
// texture, made for the first), batch 2's marks are its own glBegin (the
// third), its enable, binding, parameters and environment, and the
// glGenTextures/glTexImage2D that made its texture for batch 0; batch 1's
// are its glDisable(GL_TEXTURE_2D) and glBegin, with no texture image; a
// batch that does not exist marks nothing.
TEST(InspectPick, PaneMarksThePickedBatchsTextureCalls) {
  ts::Frame f;
  f.width = f.height = 64;
  f.textures.push_back(ts::checkerboard(16, 4));
  ts::Panel p;
  p.id = "only";
  p.viewport = {0, 0, 64, 64};
  p.batches = {triangle(0), triangle(-1), triangle(0)};
  f.panels.push_back(p);
  const std::vector<ts::gl::Call> calls = ts::recordPicture(ts::test::renderer(), f);
  std::vector<size_t> begins;
  for (size_t k = 0; k < calls.size(); ++k)
    if (std::strcmp(calls[k].name, "glBegin") == 0) begins.push_back(k);
  ASSERT_GE(begins.size(), 3u);

  const std::vector<std::string> b2 = markedCalls(calls, 2);
  EXPECT_EQ(count(b2, "glBegin("), 1);
  EXPECT_TRUE(ts::batchTextureCalls(calls, 2)[begins[2]]);
  EXPECT_FALSE(ts::batchTextureCalls(calls, 2)[begins[0]]);
  EXPECT_EQ(count(b2, "glTexImage2D("), 1) << "the image made for batch 0";
  EXPECT_EQ(count(b2, "glGenTextures("), 1);
  EXPECT_GE(count(b2, "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER"), 1);
  EXPECT_EQ(count(b2, "glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE"), 1);
  EXPECT_EQ(count(b2, "glEnable(GL_TEXTURE_2D)"), 1);
  EXPECT_EQ(count(b2, "glLineWidth"), 0);
  EXPECT_EQ(count(b2, "glViewport"), 0);
  // Nothing of batch 2 lies before batch 1's glEnd but the making of the texture.
  for (const std::string& l : b2) {
    const size_t at = size_t(std::stoul(l));
    if (at < begins[1])
      EXPECT_TRUE(l.find("glTexImage2D") != std::string::npos || l.find("glGenTextures") != std::string::npos ||
                  l.find("glBindTexture") != std::string::npos || l.find("glPixelStorei") != std::string::npos ||
                  l.find("GL_TEXTURE_MAX_LEVEL") != std::string::npos)
          << l;
  }

  const std::vector<std::string> b1 = markedCalls(calls, 1);
  EXPECT_EQ(count(b1, "glBegin("), 1);
  EXPECT_TRUE(ts::batchTextureCalls(calls, 1)[begins[1]]);
  EXPECT_EQ(count(b1, "glDisable(GL_TEXTURE_2D)"), 1);
  EXPECT_EQ(count(b1, "glTexImage2D("), 0);

  EXPECT_TRUE(markedCalls(calls, 7).empty());
  EXPECT_TRUE(markedCalls(calls, -1).empty());
}
}  // namespace
