// The oracle must reject wrong images.  Each case renders a deliberately
// wrong picture with GL — a wrong wrap mode, the other diagonal, affine
// instead of hyperbolic interpolation (and the reverse), a mip level off —
// verifies it against the right description, and asserts that a large share
// of the pixels is invalid.  Each also has its positive control: the same
// render verified against its true description has no invalid pixel (so
// the rejection is the mistake's doing, not the oracle's noise).
#include <gtest/gtest.h>

#include <cstdio>

#include "common/core/options.hpp"
#include "common/core/scene.hpp"
#include "oracle_support.hpp"

namespace {
// Failure images of expected failures go to their own folder.
ref::VerifyOptions negative(const std::string& name) { return oracle::options(name, "negative"); }

void report(const ref::VerifyResult& r) { std::printf("[oracle] %s\n", r.summary().c_str()); }

// --- wrong wrap mode -------------------------------------------------------
ts::Frame wrapFrame(GLenum wrap) {
  ts::Frame f;
  f.width = f.height = 200;
  ts::TextureDesc t = ts::checkerboard(64, 4, {200, 40, 40, 255}, {40, 60, 210, 255});
  t.wrapS = t.wrapT = wrap;
  int tex = f.addTexture(t);
  ts::Panel p = oracle::unitPanel(200, 200);
  // Coordinates well outside [0, 1]: where REPEAT and CLAMP part ways.
  p.batches.push_back(oracle::quad({0, 0}, {1, 1}, {-0.7f, -0.45f}, {2.35f, 1.8f}, tex));
  f.panels.push_back(p);
  return f;
}

TEST(Negative, WrongWrapModeIsRejected) {
  ts::Image clamped = oracle::render(wrapFrame(GL_CLAMP_TO_EDGE));
  ts::Frame says = wrapFrame(GL_REPEAT);
  ref::VerifyResult r = ref::verifyImage(clamped, says, negative("wrap_clamp_as_repeat"));
  report(r);
  EXPECT_GT(r.invalid, r.textured / 3) << r.summary();
  // Control: the REPEAT render is legal for the REPEAT description.
  ref::VerifyResult ok = ref::verifyImage(oracle::render(says), says, negative("wrap_repeat_control"));
  EXPECT_EQ(ok.invalid, 0) << ok.summary();
}

// --- a coordinate off by 1/8 texel ------------------------------------------
// The finest mistake: bilinear magnification of a texture whose neighbouring
// texels differ by tens of levels, the description's (s, t) shifted by an
// eighth of a texel (the oracle allows 1/32 texel of jitter).
TEST(Negative, EighthTexelOffsetIsRejected) {
  auto frame = [](float shift) {
    ts::Frame f;
    f.width = f.height = 200;
    ts::TextureDesc t = oracle::colourful(8);
    t.minFilter = t.magFilter = GL_LINEAR;
    int tex = f.addTexture(t);
    ts::Panel p = oracle::unitPanel(200, 200);
    float d = shift / 8.0f;
    p.batches.push_back(oracle::quad({0, 0}, {1, 1}, {0.1f + d, 0.05f + d}, {0.9f + d, 0.95f + d}, tex));
    f.panels.push_back(p);
    return f;
  };
  ts::Image img = oracle::render(frame(0.0f));
  ref::VerifyResult r = ref::verifyImage(img, frame(0.125f), negative("eighth_texel_offset"));
  report(r);
  EXPECT_GT(r.invalid, r.textured / 2) << r.summary();
  ref::VerifyResult ok = ref::verifyImage(img, frame(0.0f), negative("eighth_texel_control"));
  EXPECT_EQ(ok.invalid, 0) << ok.summary();
}

// --- wrong diagonal (Figure VI.1) ------------------------------------------
ts::Frame quadFigure(const std::string& diagonal, int w, int h) {
  std::unique_ptr<ts::Scene> s = ts::makeScene("quad_distortion");
  ts::Options o;
  s->addOptions(o);
  o.parse({"--view", "book", "--diagonal", diagonal, "--interp", "affine"});
  return s->build(w, h, {});  // the picture before any measurement: labels without numbers
}

TEST(Negative, WrongDiagonalIsRejected) {
  const int w = 1024, h = 560;  // the book figure's size
  ts::Frame tlbr = quadFigure("tl-br", w, h), bltr = quadFigure("bl-tr", w, h);
  ts::Image img = oracle::render(tlbr);
  ref::VerifyOptions o = negative("vi1_tlbr_as_bltr");
  o.render.labels = false;
  ref::VerifyResult r = ref::verifyImage(img, bltr, o);
  report(r);
  // The two splits agree along the square's border and in a band around the
  // shared half of the diagonals; elsewhere in the right panel they differ.
  const ts::Panel* sq = bltr.panel("screen_space");
  ASSERT_TRUE(sq);
  long square = long(sq->viewport.w) * sq->viewport.h;
  EXPECT_GT(r.invalid, square / 10) << r.summary();
  // The invalid pixels lie in the rendered square, but for the left panel's
  // orange curve (the image of the diagonal in texture space, which differs
  // between the two splits and is exempt only where the description has it).
  long inSquare = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (r.mask.at(x, y) == ts::Rgba{255, 0, 0, 255}) inSquare += sq->viewport.contains(x, y);
  EXPECT_GT(inSquare, r.invalid * 95 / 100) << r.summary();
  o.name = "vi1_tlbr_control";
  ref::VerifyResult ok = ref::verifyImage(img, tlbr, o);
  EXPECT_EQ(ok.invalid, 0) << ok.summary();
}

// --- affine instead of perspective (Figure VI.2's two halves) ---------------
ts::TextureDesc planeTexture() {
  ts::TextureDesc t = ts::checkerboard(256, 16);
  t.mipmaps = true;
  t.minFilter = GL_LINEAR_MIPMAP_LINEAR;
  t.magFilter = GL_LINEAR;
  return t;
}

// The same plane with every vertex projected on the CPU and sent with w = 1:
// GL then interpolates (s, t) linearly in screen space — the "without
// hyperbolic interpolation" picture (GL_PERSPECTIVE_CORRECTION_HINT is
// ignored by Mesa, docs/platform.md).
ts::Frame preProjected(const ts::Frame& f) {
  ts::Frame g = f;
  for (ts::Panel& p : g.panels) {
    glm::mat4 mvp = p.projection * p.modelview;
    for (ts::Batch& b : p.batches)
      for (ts::Vertex& v : b.vertices) {
        glm::vec4 c = mvp * glm::vec4(v.pos, 1.0f);
        v.pos = glm::vec3(c) / c.w;
      }
    p.projection = p.modelview = glm::mat4(1.0f);
  }
  return g;
}

TEST(Negative, AffineReferenceRejectsThePerspectiveRender) {
  ts::Frame f = oracle::slantedPlane(256, 256, planeTexture());
  ts::Image persp = oracle::render(f);
  ref::VerifyOptions o = negative("plane_perspective_as_affine");
  o.render.interpolation = ref::Interpolation::Affine;
  ref::VerifyResult r = ref::verifyImage(persp, f, o);
  report(r);
  EXPECT_GT(r.invalid, r.textured / 2) << r.summary();
  o.render.interpolation = ref::Interpolation::Perspective;
  o.name = "plane_perspective_control";
  ref::VerifyResult ok = ref::verifyImage(persp, f, o);
  report(ok);
  EXPECT_EQ(ok.invalid, 0) << ok.summary();
}

TEST(Negative, PerspectiveReferenceRejectsTheAffineRender) {
  ts::Frame f = oracle::slantedPlane(256, 256, planeTexture());
  ts::Image affine = oracle::render(preProjected(f));
  ref::VerifyResult r = ref::verifyImage(affine, f, negative("plane_affine_as_perspective"));
  report(r);
  EXPECT_GT(r.invalid, r.textured / 2) << r.summary();
  ref::VerifyOptions o = negative("plane_affine_control");
  o.render.interpolation = ref::Interpolation::Affine;
  ref::VerifyResult ok = ref::verifyImage(affine, f, o);
  report(ok);
  EXPECT_EQ(ok.invalid, 0) << ok.summary();
}

// --- one mip level off -------------------------------------------------------
ts::Frame mipFrame(float bias, GLenum minFilter) {
  ts::TextureDesc t = ts::mipLevelColours(256);
  t.lodBias = bias;
  t.minFilter = minFilter;
  return oracle::slantedPlane(256, 256, t, 3.0f);
}

TEST(Negative, OneMipLevelOffIsRejected) {
  for (GLenum filter : {GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_LINEAR}) {
    SCOPED_TRACE(filter == GL_NEAREST_MIPMAP_NEAREST ? "GL_NEAREST_MIPMAP_NEAREST" : "GL_LINEAR_MIPMAP_LINEAR");
    std::string tag = filter == GL_NEAREST_MIPMAP_NEAREST ? "nmn" : "lml";
    ts::Frame says = mipFrame(0.0f, filter);
    ts::Image biased = oracle::render(mipFrame(1.0f, filter));
    ref::VerifyResult r = ref::verifyImage(biased, says, negative("mip_bias1_as_bias0_" + tag));
    report(r);
    // Only pixels whose exact LOD is within the margin of a level boundary
    // may legally take the next level; the rest must be rejected.
    EXPECT_GT(r.invalid, r.textured / 2) << r.summary();
    ref::VerifyResult ok = ref::verifyImage(oracle::render(says), says, negative("mip_control_" + tag));
    report(ok);
    EXPECT_EQ(ok.invalid, 0) << ok.summary();
  }
}
}  // namespace
