// The oracle against OpenGL on every state it models, beyond the figures:
// wrap modes x magnification filters, the six minification filters on a
// slanted plane, GL_MODULATE with vertex colours, projective (s,t,r,q),
// depth-tested overlaps, panels with their own viewports.  Each GL render
// must have no invalid pixel — and swapping the description's wrap mode for
// its neighbour must make many pixels invalid (the check has teeth for each
// mode, not only for REPEAT vs CLAMP).
#include <gtest/gtest.h>

#include <cstdio>

#include "oracle_support.hpp"

namespace {
const char* name(GLenum e) {
  switch (e) {
    case GL_REPEAT: return "repeat";
    case GL_MIRRORED_REPEAT: return "mirrored";
    case GL_CLAMP_TO_EDGE: return "clamp_edge";
    case GL_CLAMP_TO_BORDER: return "clamp_border";
    case GL_NEAREST: return "nearest";
    case GL_LINEAR: return "linear";
    case GL_NEAREST_MIPMAP_NEAREST: return "nmn";
    case GL_LINEAR_MIPMAP_NEAREST: return "lmn";
    case GL_NEAREST_MIPMAP_LINEAR: return "nml";
    case GL_LINEAR_MIPMAP_LINEAR: return "lml";
  }
  return "other";
}

ts::Frame wrapFrame(GLenum wrap, GLenum filter) {
  ts::Frame f;
  f.width = 240, f.height = 180;
  ts::TextureDesc t = oracle::colourful(8);
  t.wrapS = t.wrapT = wrap;
  t.minFilter = t.magFilter = filter;
  t.border = {1.0f, 0.5f, 0.0f, 1.0f};
  int tex = f.addTexture(t);
  ts::Panel p = oracle::unitPanel(240, 180);
  p.batches.push_back(oracle::quad({0, 0}, {1, 1}, {-1.3f, -0.7f}, {2.2f, 1.9f}, tex));
  f.panels.push_back(p);
  return f;
}

TEST(GLSampling, WrapModesAndMagnificationFilters) {
  const GLenum wraps[] = {GL_REPEAT, GL_MIRRORED_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER};
  for (GLenum filter : {GL_NEAREST, GL_LINEAR})
    for (size_t w = 0; w < 4; ++w) {
      std::string n = std::string("wrap_") + name(wraps[w]) + "_" + name(filter);
      SCOPED_TRACE(n);
      ts::Frame f = wrapFrame(wraps[w], filter);
      ts::Image img = oracle::render(f);
      ref::VerifyResult r = ref::verifyImage(img, f, oracle::options(n, "sampling"));
      EXPECT_EQ(r.invalid, 0) << r.summary();
      EXPECT_GT(r.checked, 240 * 180 * 9 / 10) << r.summary();
      // The neighbouring mode in the list must be rejected.
      ts::Frame other = wrapFrame(wraps[(w + 1) % 4], filter);
      ref::VerifyOptions o = oracle::options(n + "_as_" + name(wraps[(w + 1) % 4]), "sampling_negative");
      ref::VerifyResult bad = ref::verifyImage(img, other, o);
      EXPECT_GT(bad.invalid, bad.checked / 5) << bad.summary();
    }
}

TEST(GLSampling, MinificationFiltersOnASlantedPlane) {
  for (bool linearLight : {false, true})
    for (GLenum filter : {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                          GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR})
      for (GLenum mag : {GL_NEAREST, GL_LINEAR}) {
        std::string n = std::string("plane_") + name(filter) + "_mag_" + name(mag) +
                        (linearLight ? "_linear_light" : "");
        SCOPED_TRACE(n);
        ts::TextureDesc t = ts::checkerboard(128, 8, {200, 60, 40, 255}, {30, 90, 220, 255});
        t.mipmaps = true;
        t.linearLightMips = linearLight;
        t.minFilter = filter;
        t.magFilter = mag;
        ts::Frame f = oracle::slantedPlane(200, 200, t, 4.0f);
        ts::Image img = oracle::render(f);
        ref::VerifyResult r = ref::verifyImage(img, f, oracle::options(n, "sampling"));
        EXPECT_EQ(r.invalid, 0) << r.summary();
        EXPECT_GT(r.textured, 200 * 200 / 3) << r.summary();
      }
}

TEST(GLSampling, LodBiasAndExplicitLevels) {
  for (float bias : {-1.0f, 0.5f, 2.0f}) {
    SCOPED_TRACE(bias);
    ts::TextureDesc t = ts::mipLevelColours(128);
    t.minFilter = GL_LINEAR_MIPMAP_NEAREST;
    t.lodBias = bias;
    ts::Frame f = oracle::slantedPlane(200, 200, t, 6.0f);
    ref::VerifyResult r = ref::verifyImage(oracle::render(f), f,
                                           oracle::options("mip_bias_" + std::to_string(bias), "sampling"));
    EXPECT_EQ(r.invalid, 0) << r.summary();
  }
}

TEST(GLSampling, ModulateWithVertexColours) {
  ts::Frame f;
  f.width = f.height = 160;
  ts::TextureDesc t = ts::checkerboard(32, 4);
  int tex = f.addTexture(t);
  ts::Panel p = oracle::unitPanel(160, 160);
  ts::Batch b = oracle::quad({0.05f, 0.05f}, {0.95f, 0.95f}, {0, 0}, {1.5f, 1.5f}, tex, GL_MODULATE);
  const glm::vec4 cols[] = {{1, 0.2f, 0.2f, 1}, {0.2f, 1, 0.2f, 1}, {0.3f, 0.3f, 1, 1}};
  for (size_t i = 0; i < b.vertices.size(); ++i) b.vertices[i].color = cols[i % 3];
  p.batches.push_back(b);
  f.panels.push_back(p);
  ref::VerifyResult r = ref::verifyImage(oracle::render(f), f, oracle::options("modulate", "sampling"));
  EXPECT_EQ(r.invalid, 0) << r.summary();
  // REPLACE in the description must not pass for the modulated picture.
  ts::Frame g = f;
  g.panels[0].batches[0].texEnv = GL_REPLACE;
  ref::VerifyResult bad = ref::verifyImage(oracle::render(f), g,
                                           oracle::options("modulate_as_replace", "sampling_negative"));
  EXPECT_GT(bad.invalid, bad.textured / 2) << bad.summary();
}

TEST(GLSampling, ProjectiveTextureCoordinates) {
  ts::Frame f;
  f.width = f.height = 180;
  ts::TextureDesc t = ts::checkerboard(64, 8);
  t.minFilter = t.magFilter = GL_NEAREST;
  int tex = f.addTexture(t);
  ts::Panel p = oracle::unitPanel(180, 180);
  ts::Batch b = oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, tex);
  // q = 1 + a + 2 b: a projective map of the square; (s q, t q, 0, q) sent.
  for (auto& v : b.vertices) {
    float q = 1.0f + v.pos.x + 2.0f * v.pos.y;
    v.tex = {v.tex.x * q * 1.3f, v.tex.y * q * 0.9f, 0.0f, q};
  }
  p.batches.push_back(b);
  f.panels.push_back(p);
  ts::Image img = oracle::render(f);
  ref::VerifyResult r = ref::verifyImage(img, f, oracle::options("projective", "sampling"));
  EXPECT_EQ(r.invalid, 0) << r.summary();
}

TEST(GLSampling, DepthTestedOverlapAndPanels) {
  ts::Frame f;
  f.width = 300, f.height = 200;
  f.clearColor = {0.2f, 0.1f, 0.1f, 1.0f};
  int a = f.addTexture(ts::checkerboard(64, 4));
  int b = f.addTexture(ts::checkerboard(64, 8, {250, 200, 0, 255}, {0, 120, 60, 255}));
  for (int k = 0; k < 2; ++k) {
    ts::Panel p;
    p.id = "panel" + std::to_string(k);
    p.viewport = {10 + 150 * k, 20 + 30 * k, 130, 150};
    p.projection = glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f);
    p.depthTest = k == 1;
    p.clear = k == 1;
    p.clearColor = {0.0f, 0.2f, 0.3f, 1.0f};
    ts::Batch near = oracle::quad({0.1f, 0.1f}, {0.7f, 0.8f}, {0, 0}, {1, 1}, a);
    ts::Batch far = oracle::quad({0.3f, 0.25f}, {0.95f, 0.9f}, {0, 0}, {2, 2}, b);
    for (auto& v : near.vertices) v.pos.z = 0.5f;  // glm::ortho: window z smaller = nearer
    for (auto& v : far.vertices) v.pos.z = -0.5f;
    p.batches = {near, far};  // without the depth test the far one is drawn over
    f.panels.push_back(p);
  }
  ts::Image img = oracle::render(f);
  ref::VerifyResult r = ref::verifyImage(img, f, oracle::options("depth_panels", "sampling"));
  EXPECT_EQ(r.invalid, 0) << r.summary();
}
}  // namespace

namespace {
// Triangles whose edges run exactly through pixel centres (a 64x64 frame so
// the pixel projection is exact in float): who owns a centre on an edge is
// then decided by the fill rule alone.  llvmpipe follows the top-left rule in
// GL's window coordinates (y up) — FillRule::GLTopLeft — exactly; softpipe
// follows neither convention, which is one reason the verifier checks pixels
// near edges against both sides.
ts::Frame centreEdgeFrame() {
  ts::Frame f;
  f.width = f.height = 64;
  ts::Panel p;
  p.id = "pixels";
  p.viewport = {0, 0, 64, 64};
  p.projection = glm::ortho(0.0f, 64.0f, 64.0f, 0.0f, -1.0f, 1.0f);  // pixels, y down
  ts::Batch b;
  b.role = "flat";
  auto v = [&](float x, float y, glm::vec4 c) {
    ts::Vertex x0;
    x0.pos = {x, y, 0};
    x0.color = c;
    b.vertices.push_back(x0);
  };
  const glm::vec4 red{1, 0, 0, 1}, green{0, 1, 0, 1}, blue{0, 0, 1, 1};
  v(10.5f, 5.5f, red), v(30.5f, 5.5f, red), v(30.5f, 25.5f, red);  // a square split along its diagonal
  v(10.5f, 5.5f, green), v(30.5f, 25.5f, green), v(10.5f, 25.5f, green);
  v(40.5f, 30.5f, red), v(60.5f, 30.5f, red), v(50.5f, 40.5f, red);  // flat top, then flat bottom
  v(40.5f, 45.5f, green), v(50.5f, 40.5f, green), v(60.5f, 45.5f, green);
  v(5.5f, 40.5f, blue), v(25.5f, 50.5f, blue), v(8.5f, 60.5f, blue);  // slanted edges only
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}

TEST(GLRasterization, FillRuleOfTheReferenceIsLlvmpipes) {
  if (ts::test::rendererString().find("llvmpipe") == std::string::npos)
    GTEST_SKIP() << "the exact fill rule is llvmpipe's; " << ts::test::rendererString()
                 << " differs (edges are checked both ways)";
  ts::Frame f = centreEdgeFrame();
  ts::Image img = oracle::render(f);
  ref::RenderOptions o;
  EXPECT_EQ(ts::probe::countDiffering(img, ref::Reference(f, o).image(), 0), 0);
  o.fill = ref::FillRule::ImageTopLeft;  // the other convention differs on the horizontal edges
  EXPECT_GT(ts::probe::countDiffering(img, ref::Reference(f, o).image(), 0), 20);
  ref::VerifyResult r = ref::verifyImage(img, f, oracle::options("fill_rule", "sampling"));
  EXPECT_EQ(r.invalid, 0) << r.summary();
}

TEST(GLRasterization, CentreEdgesAreLegalOnEveryRasterizer) {
  ts::Frame f = centreEdgeFrame();
  ref::VerifyResult r = ref::verifyImage(oracle::render(f), f, oracle::options("centre_edges", "sampling"));
  EXPECT_EQ(r.invalid, 0) << r.summary();
}
}  // namespace

// GL_CLAMP (the compatibility profile's clamp, border blended in
// by GL_LINEAR), with pixel centres also exactly at integer s: each column
// of the quad has one constant s, from -2 to 3 in steps of 1/4.
TEST(GLSampling, LegacyClampAndIntegerCoordinates) {
  for (GLenum wrap : {GL_CLAMP, GL_MIRRORED_REPEAT, GL_CLAMP_TO_BORDER, GL_REPEAT, GL_CLAMP_TO_EDGE})
    for (GLenum filter : {GL_NEAREST, GL_LINEAR}) {
      std::string n = std::string("integers_") + std::to_string(wrap) + "_" + name(filter);
      SCOPED_TRACE(n);
      ts::Frame f = wrapFrame(wrap, filter);
      ts::Image img = oracle::render(f);
      ref::VerifyResult r = ref::verifyImage(img, f, oracle::options(n, "sampling"));
      EXPECT_EQ(r.invalid, 0) << r.summary();
      // Columns of constant s: 21 one-pixel-wide quads.
      ts::Frame g;
      g.width = 21, g.height = 8;
      ts::TextureDesc t = oracle::colourful(8);
      t.wrapS = t.wrapT = wrap;
      t.minFilter = t.magFilter = filter;
      t.border = {1.0f, 0.5f, 0.0f, 1.0f};
      int tex = g.addTexture(t);
      ts::Panel p = oracle::unitPanel(21, 8);
      for (int k = 0; k < 21; ++k) {
        float s = -2.0f + 0.25f * float(k);
        p.batches.push_back(oracle::quad({k / 21.0f, 0}, {(k + 1) / 21.0f, 1}, {s, 0.3f}, {s, 0.8f}, tex));
      }
      g.panels.push_back(p);
      ref::VerifyOptions o = oracle::options(n + "_columns", "sampling");
      ref::VerifyResult c = ref::verifyImage(oracle::render(g), g, o);
      EXPECT_EQ(c.invalid, 0) << c.summary();
      EXPECT_GT(c.checked, 21 * 8 / 2) << c.summary();
    }
  // GL_CLAMP with GL_LINEAR is not GL_CLAMP_TO_EDGE (the border shows).
  ts::Frame f = wrapFrame(GL_CLAMP, GL_LINEAR);
  ref::VerifyResult bad = ref::verifyImage(oracle::render(f), wrapFrame(GL_CLAMP_TO_EDGE, GL_LINEAR),
                                           oracle::options("clamp_as_clamp_to_edge", "sampling_negative"));
  EXPECT_GT(bad.invalid, bad.checked / 5) << bad.summary();
}

// The texture environments with vertex colours, an RGBA texture whose alpha
// varies and GL_TEXTURE_ENV_COLOR; each against the reference's table, and
// each told as GL_MODULATE must fail.
TEST(GLSampling, TextureEnvironments) {
  for (GLenum env : {GL_REPLACE, GL_MODULATE, GL_DECAL, GL_BLEND, GL_ADD}) {
    SCOPED_TRACE(env);
    ts::Frame f;
    f.width = f.height = 160;
    ts::TextureDesc t = ts::gradientTexture(8, 8, true);
    t.minFilter = t.magFilter = GL_NEAREST;
    int tex = f.addTexture(t);
    ts::Panel p = oracle::unitPanel(160, 160);
    ts::Batch b = oracle::quad({0.05f, 0.05f}, {0.95f, 0.95f}, {0, 0}, {1, 1}, tex, env);
    const glm::vec4 cols[] = {{0.9f, 0.3f, 0.2f, 1}, {0.2f, 0.8f, 0.4f, 0.6f}, {0.3f, 0.3f, 1, 0.8f}};
    for (size_t i = 0; i < b.vertices.size(); ++i) b.vertices[i].color = cols[i % 3];
    b.envColor = {0.1f, 0.6f, 0.95f, 1.0f};
    p.batches.push_back(b);
    f.panels.push_back(p);
    ts::Image img = oracle::render(f);
    ref::VerifyResult r = ref::verifyImage(img, f, oracle::options("env_" + std::to_string(env), "sampling"));
    EXPECT_EQ(r.invalid, 0) << r.summary();
    EXPECT_GT(r.textured, 160 * 160 / 2) << r.summary();
    if (env == GL_MODULATE) continue;
    ts::Frame g = f;
    g.panels[0].batches[0].texEnv = GL_MODULATE;
    ref::VerifyResult bad = ref::verifyImage(img, g, oracle::options("env_as_modulate", "sampling_negative"));
    EXPECT_GT(bad.invalid, bad.textured / 4) << bad.summary();
  }
}

// The texture matrix (glMatrixMode(GL_TEXTURE)): rotated, sheared, shifted
// and projective (q row), applied by the reference per vertex; the same
// picture described without it must fail.
TEST(GLSampling, TextureMatrix) {
  glm::mat4 m(1.0f);
  m = glm::translate(m, glm::vec3(0.3f, -0.2f, 0.0f));
  m = glm::rotate(m, glm::radians(35.0f), glm::vec3(0, 0, 1));
  m[1][0] += 0.4f;  // shear
  glm::mat4 projective = m;
  projective[0][3] = 0.5f;  // q = 1 + s/2
  for (const glm::mat4& tm : {m, projective}) {
    ts::Frame f;
    f.width = f.height = 160;
    ts::TextureDesc t = ts::checkerboard(32, 8);
    t.minFilter = t.magFilter = GL_NEAREST;
    t.wrapS = GL_MIRRORED_REPEAT;
    int tex = f.addTexture(t);
    ts::Panel p = oracle::unitPanel(160, 160);
    ts::Batch b = oracle::quad({0, 0}, {1, 1}, {-0.5f, -0.5f}, {1.5f, 1.5f}, tex);
    b.textureMatrix = tm;
    p.batches.push_back(b);
    f.panels.push_back(p);
    ts::Image img = oracle::render(f);
    ref::VerifyResult r = ref::verifyImage(img, f, oracle::options("texture_matrix", "sampling"));
    EXPECT_EQ(r.invalid, 0) << r.summary();
    ts::Frame g = f;
    g.panels[0].batches[0].textureMatrix = glm::mat4(1.0f);
    ref::VerifyResult bad = ref::verifyImage(img, g,
                                             oracle::options("texture_matrix_as_identity", "sampling_negative"));
    EXPECT_GT(bad.invalid, bad.textured / 4) << bad.summary();
  }
}

// GL_COLOR_SUM: the secondary colour added after texturing (what
// GL_SEPARATE_SPECULAR_COLOR does with the specular term).
TEST(GLSampling, ColourSumAfterTexturing) {
  ts::Frame f;
  f.width = f.height = 120;
  ts::TextureDesc t = ts::checkerboard(16, 4, {20, 20, 20, 255}, {120, 60, 30, 255});
  t.minFilter = t.magFilter = GL_NEAREST;
  int tex = f.addTexture(t);
  ts::Panel p = oracle::unitPanel(120, 120);
  ts::Batch b = oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, tex, GL_MODULATE);
  b.colorSum = true;
  for (size_t i = 0; i < b.vertices.size(); ++i) {
    b.vertices[i].color = {0.8f, 0.8f, 0.8f, 1};
    b.vertices[i].secondary = glm::vec3(0.7f * b.vertices[i].pos.x * b.vertices[i].pos.y);
  }
  p.batches.push_back(b);
  f.panels.push_back(p);
  ts::Image img = oracle::render(f);
  ref::VerifyResult r = ref::verifyImage(img, f, oracle::options("color_sum", "sampling"));
  EXPECT_EQ(r.invalid, 0) << r.summary();
  ts::Frame g = f;
  g.panels[0].batches[0].colorSum = false;
  ref::VerifyResult bad = ref::verifyImage(img, g, oracle::options("color_sum_off", "sampling_negative"));
  EXPECT_GT(bad.invalid, bad.textured / 4) << bad.summary();
}
