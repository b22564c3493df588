// The oracle against OpenGL on the multitexturing state: the
// alpha test (Batch::alphaFunc) and a batch's own blend factors
// (Batch::blendSrc / blendDst).  A cutout texture (alpha 0 outside a disc,
// 255 inside, a ring of 100 and one of 160 around it) on a quad drawn
// first, in front, then a farther quad with the depth test: with
// glAlphaFunc(GL_GREATER, 0.5) the discarded texels write no depth and the
// farther quad shows through them, without the test it is hidden.  Every
// GL pixel must lie in the reference's legal range (verify.hpp), and the
// frame described without the test (or with the test the other way round)
// must make many pixels invalid.  The blend factors (GL_ONE, GL_ONE adds,
// GL_DST_COLOR, GL_ZERO multiplies) are checked on the reference picture
// (blended pixels are exempt in the candidates): within 2 levels of GL.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>

#include "demos/multitexture/multitexture_frames.hpp"
#include "oracle_support.hpp"
#include "reference/reference.hpp"

namespace {
ts::TextureDesc cutout(int n, GLenum filter) {
  auto img = std::make_shared<ts::Image>(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double r = std::hypot(i + 0.5 - n / 2.0, j + 0.5 - n / 2.0) / (n / 2.0);
      const uint8_t a = r < 0.55 ? 255 : r < 0.7 ? 160 : r < 0.85 ? 100 : 0;
      img->set(i, j,
               {uint8_t(30 + (i * 37) % 200), uint8_t(90 + (j * 23) % 160), uint8_t(20 + ((i + j) * 11) % 90), a});
    }
  ts::TextureDesc t;
  t.name = "oracle_cutout";  // not a sidecar generator: GL tests only
  t.params = {{"size", std::to_string(n)}};
  t.image = img;
  t.minFilter = t.magFilter = filter;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}

// The cutout quad in front (z = 0.5 is nearer under the unit panel's
// ortho), drawn first; then the sky quad behind it (z = -0.5), depth test on.
ts::Frame cutoutFrame(GLenum filter, GLenum func, float ref) {
  ts::Frame f;
  f.width = f.height = 160;
  f.clearColor = {0.05f, 0.05f, 0.05f, 1.0f};
  const int t = f.addTexture(cutout(16, filter));
  ts::Panel p = oracle::unitPanel(160, 160);
  p.depthTest = true;
  ts::Batch tree = oracle::quad({0.1f, 0.1f}, {0.9f, 0.9f}, {0, 0}, {1, 1}, t);
  for (ts::Vertex& v : tree.vertices) v.pos.z = 0.5f;
  tree.alphaFunc = func;
  tree.alphaRef = ref;
  ts::Batch sky = oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, -1);
  for (ts::Vertex& v : sky.vertices) v.pos.z = -0.5f, v.color = {0.45f, 0.65f, 0.9f, 1.0f};
  p.batches = {tree, sky};
  f.panels.push_back(p);
  return f;
}

long skyPixels(const ts::Image& img) {
  long n = 0;
  for (int y = 16; y < 144; ++y)
    for (int x = 16; x < 144; ++x)
      if (img.at(x, y).b >= 220 && img.at(x, y).r >= 105 && img.at(x, y).r <= 125) ++n;
  return n;
}

TEST(GLAlphaTest, CutoutInFrontOfAFartherQuad) {
  for (GLenum filter : {GL_NEAREST, GL_LINEAR}) {
    const std::string fn = filter == GL_NEAREST ? "nearest" : "linear";
    long sky[3] = {0, 0, 0};
    int k = 0;
    for (auto [func, ref] : {std::pair<GLenum, float>{0, 0.0f}, {GL_GREATER, 0.5f}, {GL_LESS, 0.5f}}) {
      const std::string n = "alpha_" + fn + "_" + (func == 0 ? "off" : func == GL_GREATER ? "greater" : "less");
      const ts::Frame f = cutoutFrame(filter, func, ref);
      const ts::Image img = oracle::render(f);
      sky[k++] = skyPixels(img);
      ref::VerifyResult r = ref::verifyImage(img, f, oracle::options(n, "multitexture"));
      EXPECT_TRUE(r.ok()) << r.summary();
      EXPECT_GT(r.checked, 160L * 160L * 9 / 10) << n;
      std::printf("%s: %ld invalid of %ld checked (%ld sky pixels inside the tree's quad)\n", n.c_str(), r.invalid,
                  r.checked, sky[k - 1]);
      // The same picture described with the test off, or the other way round: wrong.
      const ts::Frame wrong = cutoutFrame(filter, func == GL_GREATER ? GLenum(GL_LESS) : GLenum(GL_GREATER), 0.5f);
      ref::VerifyResult bad = ref::verifyImage(img, wrong,
                                               oracle::options(n + "_described_wrong", "multitexture_negative"));
      EXPECT_GT(bad.invalid, 2000) << n << ": " << bad.summary();
      if (func != 0) {
        const ts::Frame off = cutoutFrame(filter, 0, 0.0f);
        ref::VerifyResult bad2 = ref::verifyImage(img, off,
                                                  oracle::options(n + "_described_off", "multitexture_negative"));
        EXPECT_GT(bad2.invalid, 2000) << n << ": " << bad2.summary();
      }
    }
    // Without the test the tree's transparent texels hide the sky; with
    // GL_GREATER 0.5 the sky shows where alpha <= 0.5; GL_LESS shows it
    // under the opaque middle and the 160 ring.
    EXPECT_EQ(sky[0], 0) << fn;
    EXPECT_GT(sky[1], 4000) << fn;
    EXPECT_GT(sky[2], 2000) << fn;
  }
}

// A colourful quad, then a second one over it blended with the batch's factors.
ts::Frame blendFrame(GLenum src, GLenum dst) {
  ts::Frame f;
  f.width = f.height = 128;
  const int t = f.addTexture(oracle::colourful(8));
  f.textures[size_t(t)].minFilter = f.textures[size_t(t)].magFilter = GL_NEAREST;
  ts::Panel p = oracle::unitPanel(128, 128);
  ts::Batch base = oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, t);
  ts::Batch over = oracle::quad({0, 0}, {1, 1}, {1, 1}, {0, 0}, t, GL_MODULATE);
  for (ts::Vertex& v : over.vertices) v.color = {0.5f, 0.7f, 0.9f, 0.3f};
  over.blend = true;
  over.blendSrc = src, over.blendDst = dst;
  p.batches = {base, over};
  f.panels.push_back(p);
  return f;
}

TEST(GLBlendFactors, AddAndMultiplyAgainstTheReferencePicture) {
  for (auto [src, dst] : {std::pair<GLenum, GLenum>{GL_ONE, GL_ONE}, {GL_DST_COLOR, GL_ZERO}}) {
    const std::string n = src == GL_ONE ? "blend_add" : "blend_multiply";
    const ts::Frame f = blendFrame(src, dst);
    const ts::Image img = oracle::render(f);
    ref::VerifyOptions vo = oracle::options(n, "multitexture");
    vo.render.labels = false;
    const ref::Reference reference(f, vo.render);
    ref::FuzzyOptions fo;
    fo.maxChannelDiff = 2;  // 8-bit products: GL may round, the reference does not
    fo.name = n;
    fo.outputDir = vo.outputDir;
    const ref::FuzzyResult r = ref::compareFuzzy(img, reference.image(), fo);
    EXPECT_TRUE(r.ok) << n << ": " << r.message;
    std::printf("%s: max channel difference %d, %ld pixels beyond 2\n", n.c_str(), r.maxDiff, r.differing);
    // Described with FixedState's factors (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA): far off.
    const ref::Reference plain(blendFrame(0, 0), vo.render);
    fo.writeOnFailure = false;
    const ref::FuzzyResult bad = ref::compareFuzzy(img, plain.image(), fo);
    EXPECT_GT(bad.differing, 128L * 128L / 2) << n;
  }
}
}  // namespace

// ---- the second texture unit --------------------------------------------
namespace {
// n x n texels of one hue, varying per texel, alpha varying too.
ts::TextureDesc tinted(int n, glm::vec3 hue, GLenum filter, int seed) {
  auto img = std::make_shared<ts::Image>(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int v = 90 + (i * 37 + j * 53 + seed * 29) % 160;
      img->set(i, j,
               {uint8_t(hue.r * v), uint8_t(hue.g * v), uint8_t(hue.b * v),
                uint8_t(60 + (i * 11 + j * 29 + seed) % 190)});
    }
  ts::TextureDesc t;
  t.name = "oracle_tinted";  // not a sidecar generator: GL tests only
  t.params = {{"size", std::to_string(n)}, {"seed", std::to_string(seed)}};
  t.image = img;
  t.minFilter = t.magFilter = filter;
  return t;
}

// One quad over the frame: unit 0 texture 0 (env0), unit 1 texture 1
// (env1 / combine); vertex colours differ per corner.
ts::Frame twoUnitFrame(GLenum filter, GLenum env0, GLenum env1, ts::Combine combine, bool unit1 = true) {
  ts::Frame f;
  f.width = f.height = 128;
  const int a = f.addTexture(tinted(16, {1.0f, 0.8f, 0.5f}, filter, 1));
  const int b = f.addTexture(tinted(8, {0.6f, 0.9f, 1.0f}, filter, 2));
  ts::Panel p = oracle::unitPanel(128, 128);
  ts::Batch q = oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, a, env0);
  const glm::vec4 corner[6] = {{0.9f, 0.5f, 0.3f, 1}, {0.4f, 0.9f, 0.6f, 0.8f}, {0.7f, 0.6f, 1.0f, 0.5f},
                               {0.9f, 0.5f, 0.3f, 1}, {0.7f, 0.6f, 1.0f, 0.5f}, {1.0f, 1.0f, 0.9f, 0.9f}};
  for (size_t k = 0; k < 6; ++k) q.vertices[k].color = corner[k];
  if (unit1) q.texture1 = b, q.texEnv1 = env1, q.combine1 = combine;
  p.batches = {q};
  f.panels.push_back(p);
  return f;
}

ts::Combine combineOf(GLenum rgb, GLenum s0, GLenum s1, GLenum s2 = GL_CONSTANT, GLenum op2 = GL_SRC_ALPHA) {
  ts::Combine c;
  c.rgb = rgb;
  c.source[0] = s0, c.source[1] = s1, c.source[2] = s2;
  c.operand[2] = op2;
  return c;
}
}  // namespace

TEST(GLSecondUnit, CombineModesAgainstTheReference) {
  struct Case {
    const char* name;
    GLenum env0, env1;
    ts::Combine combine;
  };
  const Case cases[] = {
      {"ab_combine_modulate", GL_REPLACE, GL_COMBINE, combineOf(GL_MODULATE, GL_PREVIOUS, GL_TEXTURE)},
      {"light_map_modulate", GL_REPLACE, GL_MODULATE, {}},
      {"combine_add", GL_MODULATE, GL_COMBINE, combineOf(GL_ADD, GL_TEXTURE, GL_PREVIOUS)},
      {"modulate_add_ati", GL_MODULATE, GL_COMBINE,
       combineOf(GL_MODULATE_ADD_ATI, GL_TEXTURE, GL_PREVIOUS, GL_PREVIOUS, GL_SRC_ALPHA)},
      {"interpolate_primary", GL_REPLACE, GL_COMBINE,
       combineOf(GL_INTERPOLATE, GL_TEXTURE, GL_PREVIOUS, GL_PRIMARY_COLOR, GL_SRC_COLOR)},
  };
  for (GLenum filter : {GL_NEAREST, GL_LINEAR})
    for (const Case& c : cases) {
      const std::string n = std::string(c.name) + (filter == GL_NEAREST ? "_nearest" : "_linear");
      const ts::Frame f = twoUnitFrame(filter, c.env0, c.env1, c.combine);
      const ts::Image img = oracle::render(f);
      ref::VerifyResult r = ref::verifyImage(img, f, oracle::options(n, "multitexture"));
      EXPECT_TRUE(r.ok()) << r.summary();
      EXPECT_EQ(r.checked, 128L * 128L) << n;
      std::printf("%s: %ld invalid of %ld checked (%ld textured)\n", n.c_str(), r.invalid, r.checked, r.textured);
      // Described without unit 1, or with another function: wrong.
      ref::VerifyResult bad = ref::verifyImage(img, twoUnitFrame(filter, c.env0, c.env1, c.combine, false),
                                               oracle::options(n + "_no_unit1", "multitexture_negative"));
      EXPECT_GT(bad.invalid, 128L * 128L / 2) << n << ": " << bad.summary();
      ts::Combine other = c.combine;
      other.rgb = c.combine.rgb == GL_ADD ? GLenum(GL_MODULATE) : GLenum(GL_ADD);
      ref::VerifyResult bad2 = ref::verifyImage(img, twoUnitFrame(filter, c.env0, GL_COMBINE, other),
                                                oracle::options(n + "_other_function", "multitexture_negative"));
      EXPECT_GT(bad2.invalid, 128L * 128L / 2) << n << ": " << bad2.summary();
    }
}

// AB + CD: the two-unit pass (A x B), then C x D added (GL_ONE, GL_ONE).
// The added pass is exempt in the candidates: the reference picture must
// be within 2 levels of GL's everywhere, and the AB + CD of the texels.
TEST(GLSecondUnit, ABPlusCDInTwoPasses) {
  ts::Frame f;
  f.width = f.height = 128;
  int t[4];
  for (int k = 0; k < 4; ++k)
    t[k] = f.addTexture(tinted(16, {0.5f + 0.1f * k, 0.9f - 0.1f * k, 0.6f}, GL_NEAREST, 3 + k));
  ts::Panel p = oracle::unitPanel(128, 128);
  const ts::Combine ab = combineOf(GL_MODULATE, GL_PREVIOUS, GL_TEXTURE);
  ts::Batch first = oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, t[0]);
  first.texture1 = t[1], first.texEnv1 = GL_COMBINE, first.combine1 = ab;
  ts::Batch second = oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, t[2]);
  second.texture1 = t[3], second.texEnv1 = GL_COMBINE, second.combine1 = ab;
  second.blend = true, second.blendSrc = GL_ONE, second.blendDst = GL_ONE;
  p.batches = {first, second};
  f.panels.push_back(p);
  const ts::Image img = oracle::render(f);
  ref::VerifyOptions vo = oracle::options("ab_plus_cd", "multitexture");
  const ref::Reference reference(f, vo.render);
  ref::FuzzyOptions fo;
  fo.maxChannelDiff = 2;
  fo.name = "ab_plus_cd";
  fo.outputDir = vo.outputDir;
  const ref::FuzzyResult r = ref::compareFuzzy(img, reference.image(), fo);
  EXPECT_TRUE(r.ok) << r.message;
  std::printf("ab_plus_cd: max channel difference %d\n", r.maxDiff);
  // Pixel (x, y) shows texel (x / 8, 15 - y / 8) of each: AB + CD per channel.
  int worst = 0;
  for (int y = 4; y < 128; y += 8)
    for (int x = 4; x < 128; x += 8) {
      const int i = x / 8, j = 15 - y / 8;
      auto channels = [](ts::Rgba c) { return glm::dvec3(c.r, c.g, c.b) / 255.0; };
      const glm::dvec3 g = channels(img.at(x, y)) * 255.0;
      auto v = [&](int k) { return channels(f.textures[size_t(t[k])].image->at(i, j)); };
      const glm::dvec3 want = glm::min(glm::dvec3(1.0), v(0) * v(1) + v(2) * v(3)) * 255.0;
      for (int ch = 0; ch < 3; ++ch) {
        worst = std::max(worst, int(std::lround(std::abs(g[ch] - want[ch]))));
      }
    }
  EXPECT_LE(worst, 2);
}

// The one-unit path: A, x B rendered first (a nested frame, the
// intermediate buffer), then C, x D, + that picture; and the framebuffer
// alone: A, x B, + C, x D.  The blended candidates (GL_DST_COLOR, GL_ZERO;
// GL_ONE, GL_ONE) are checked: every GL pixel legal.
TEST(GLSecondUnit, BlendedPassesAndAnIntermediateBuffer) {
  auto textures = [](ts::Frame& f, int* t) {
    for (int k = 0; k < 4; ++k)
      t[k] = f.addTexture(tinted(16, {0.5f + 0.1f * k, 0.9f - 0.1f * k, 0.6f}, GL_NEAREST, 3 + k));
  };
  auto blended = [](ts::Batch b, GLenum s, GLenum d) { return b.blend = true, b.blendSrc = s, b.blendDst = d, b; };
  ts::Frame inner;
  inner.width = inner.height = 128;
  int ti[4];
  textures(inner, ti);
  ts::Panel pi = oracle::unitPanel(128, 128);
  pi.clear = true, pi.clearColor = {0, 0, 0, 1};
  pi.batches = {oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, ti[0]),
                blended(oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, ti[1]), GL_DST_COLOR, GL_ZERO),
                blended(oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, ti[2]), GL_ONE, GL_ONE),
                blended(oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, ti[3]), GL_DST_COLOR, GL_ZERO)};
  inner.panels.push_back(pi);
  const ts::Image fbOnly = oracle::render(inner);
  ref::VerifyResult r0 = ref::verifyImage(fbOnly, inner, oracle::options("framebuffer_only", "multitexture"));
  EXPECT_TRUE(r0.ok()) << r0.summary();
  std::printf("framebuffer_only: %s\n", r0.summary().c_str());
  inner.panels[0].batches.resize(2);  // A x B: the intermediate buffer
  const ts::Image ab = oracle::render(inner);
  ts::Frame f;
  f.width = 240, f.height = 180;
  int t[4];
  textures(f, t);
  ts::TextureDesc stored = oracle::colourful(1);
  stored.name = "oracle_ab", stored.image = std::make_shared<ts::Image>(ab);
  stored.minFilter = stored.magFilter = GL_NEAREST;
  stored.wrapS = stored.wrapT = GL_CLAMP_TO_EDGE;
  stored.renderedFrom = std::make_shared<const ts::Frame>(inner);
  const int s = f.addTexture(stored);
  ts::Panel p = oracle::unitPanel(160, 160);
  p.viewport = {50, 12, 160, 160};
  p.clear = true, p.clearColor = {0, 0, 0, 1};
  p.batches = {oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, t[2]),
               blended(oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, t[3]), GL_DST_COLOR, GL_ZERO),
               blended(oracle::quad({0, 0}, {1, 1}, {0, 0}, {1, 1}, s), GL_ONE, GL_ONE)};
  f.panels.push_back(p);
  const ts::Image img = oracle::render(f);
  ref::VerifyResult r = ref::verifyImage(img, f, oracle::options("stored_ab", "multitexture"));
  EXPECT_TRUE(r.ok()) << r.summary();
  std::printf("stored_ab: %s\n", r.summary().c_str());
}

// Unit 1's texture matrix (Batch::textureMatrix1): the light map moved over
// the wall (the multitexture demo's spot) is (s, t) -> M1 (s, t) on unit 1
// only, unit 0 untouched.  A rotation as well as the scale and translation,
// so the cross terms count; clamped (the spot's map) and repeated.  Every
// GL pixel in the reference's legal range, none exempt; described without
// the matrix, most pixels are invalid.
TEST(GLSecondUnit, TextureMatrixOnUnitOne) {
  const glm::mat4 m1 = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 0)) *
                       glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0, 0, 1)) *
                       glm::scale(glm::mat4(1.0f), glm::vec3(1.6f, 1.6f, 1)) *
                       glm::translate(glm::mat4(1.0f), glm::vec3(-0.3f, -0.6f, 0));
  for (GLenum filter : {GL_NEAREST, GL_LINEAR})
    for (GLenum wrap : {GL_CLAMP_TO_EDGE, GL_REPEAT}) {
      const std::string n = std::string("unit1_texture_matrix") + (filter == GL_NEAREST ? "_nearest" : "_linear") +
                            (wrap == GL_REPEAT ? "_repeat" : "_clamp");
      auto frame = [&](const glm::mat4& unit0, const glm::mat4& unit1) {
        ts::Frame f = twoUnitFrame(filter, GL_REPLACE, GL_MODULATE, {});
        f.textures[1].wrapS = f.textures[1].wrapT = wrap;
        f.panels[0].batches[0].textureMatrix = unit0;
        f.panels[0].batches[0].textureMatrix1 = unit1;
        return f;
      };
      const ts::Frame f = frame(glm::mat4(1.0f), m1);
      const ts::Image img = oracle::render(f);
      ref::VerifyResult r = ref::verifyImage(img, f, oracle::options(n, "multitexture"));
      EXPECT_TRUE(r.ok()) << r.summary();
      EXPECT_EQ(r.checked, 128L * 128L) << n;
      EXPECT_EQ(r.textured, 128L * 128L) << n << ": modelled, not exempt";
      std::printf("%s: %ld invalid of %ld checked (%ld textured)\n", n.c_str(), r.invalid, r.checked, r.textured);
      ref::VerifyResult bad = ref::verifyImage(img, frame(glm::mat4(1.0f), glm::mat4(1.0f)),
                                               oracle::options(n + "_no_matrix", "multitexture_negative"));
      EXPECT_GT(bad.invalid, 128L * 128L / 2) << n << ": " << bad.summary();
    }
}

// Unit 1's own coordinates (Batch::coords1, Vertex::tex1: the pear's sphere
// map beside its skin's (u, v)), and a second pass over the same geometry
// through glDepthFunc(GL_LEQUAL) (Batch::depthFunc), added (GL_ONE, GL_ONE).
// Unit 1's (s, t) here run against unit 0's (rotated, stretched, with q != 1
// at one corner), so reading unit 0's would be far off.  Every GL pixel in
// the reference's legal range; described with unit 0's coordinates on unit
// 1, most pixels are invalid; the second pass described with GL_LESS (which
// fails on equal depth) leaves the reference's picture without it, far from GL's.
TEST(GLSecondUnit, OwnCoordinatesAndASecondPassThroughLequal) {
  for (GLenum filter : {GL_NEAREST, GL_LINEAR}) {
    const std::string n = std::string("unit1_own_coords") + (filter == GL_NEAREST ? "_nearest" : "_linear");
    auto frame = [&](bool own) {
      ts::Frame f = twoUnitFrame(filter, GL_REPLACE, GL_MODULATE, {});
      ts::Batch& b = f.panels[0].batches[0];
      b.coords1 = own;
      for (ts::Vertex& v : b.vertices) {
        const glm::vec2 st(v.tex.x, v.tex.y);
        const float q = st.x > 0.5f && st.y > 0.5f ? 1.5f : 1.0f;
        v.tex1 = glm::vec4(q * (2.0f * st.y - 0.3f * st.x), q * (1.7f - 1.4f * st.x), 0.0f, q);
      }
      return f;
    };
    const ts::Frame f = frame(true);
    const ts::Image img = oracle::render(f);
    ref::VerifyResult r = ref::verifyImage(img, f, oracle::options(n, "multitexture"));
    EXPECT_TRUE(r.ok()) << r.summary();
    EXPECT_EQ(r.textured, 128L * 128L) << n << ": modelled, not exempt";
    std::printf("%s: %ld invalid of %ld checked (%ld textured)\n", n.c_str(), r.invalid, r.checked, r.textured);
    ref::VerifyResult bad = ref::verifyImage(img, frame(false),
                                             oracle::options(n + "_unit0_coords", "multitexture_negative"));
    EXPECT_GT(bad.invalid, 128L * 128L / 2) << n << ": " << bad.summary();
  }
  // Two passes over one quad, depth test on: the first writes depth, the
  // second (z equal) adds through GL_LEQUAL.
  auto twoPasses = [](GLenum secondFunc) {
    ts::Frame f = twoUnitFrame(GL_NEAREST, GL_MODULATE, GL_MODULATE, {}, false);
    ts::Panel& p = f.panels[0];
    p.depthTest = true, p.clear = true, p.clearColor = {0, 0, 0, 1};
    for (ts::Vertex& v : p.batches[0].vertices) v.pos.z = 0.25f, v.color = glm::vec4(glm::vec3(v.color) * 0.5f, 1.0f);
    ts::Batch second = p.batches[0];
    second.texture = 1;
    second.blend = true, second.blendSrc = GL_ONE, second.blendDst = GL_ONE;
    second.depthFunc = secondFunc;
    p.batches.push_back(second);
    return f;
  };
  // On the reference picture (the candidates allow either verdict where
  // depths are equal within their epsilon): within 2 levels of GL (8-bit
  // sums), and far from it when the second pass is described with GL_LESS.
  const ts::Frame f = twoPasses(GL_LEQUAL);
  const ts::Image img = oracle::render(f);
  ref::VerifyOptions vo = oracle::options("second_pass_lequal", "multitexture");
  vo.render.labels = false;
  ref::FuzzyOptions fo;
  fo.maxChannelDiff = 2;
  fo.name = "second_pass_lequal";
  fo.outputDir = vo.outputDir;
  const ref::FuzzyResult r = ref::compareFuzzy(img, ref::Reference(f, vo.render).image(), fo);
  EXPECT_TRUE(r.ok) << r.message;
  std::printf("second_pass_lequal: max channel difference %d, %ld pixels beyond 2\n", r.maxDiff, r.differing);
  ref::VerifyResult legal = ref::verifyImage(img, f, vo);
  EXPECT_TRUE(legal.ok()) << legal.summary();
  fo.writeOnFailure = false;
  const ref::FuzzyResult bad = ref::compareFuzzy(img, ref::Reference(twoPasses(GL_LESS), vo.render).image(), fo);
  EXPECT_GT(bad.differing, 128L * 128L / 2) << "described with GL_LESS";
}

// A transparent layer drawn with the depth writes off (Batch::depthWrite,
// glDepthMask(GL_FALSE)): a red half-transparent quad near the eye, then an
// opaque green one behind it.  Without depth writes the green quad is drawn
// (it is tested against the clear depth only), with them it is hidden.  GL's
// picture is legal for the frame as described, and most of the overlap is
// invalid for the same frame described with depth writes on.
TEST(GLDepthWrite, ALayerWithoutDepthWritesHidesNothingDrawnAfter) {
  auto frame = [](bool writes) {
    ts::Frame f;
    f.width = f.height = 64;
    f.clearColor = {0, 0, 0, 1};
    ts::Panel p;
    p.id = "layers";
    p.viewport = {0, 0, 64, 64};
    p.depthTest = true;
    auto quad = [](float x0, float x1, float z, glm::vec4 colour) {
      ts::Batch b;
      b.role = "layer";
      for (int c : {0, 1, 2, 0, 2, 3})
        b.vertices.push_back({{c == 1 || c == 2 ? x1 : x0, c >= 2 ? 0.8f : -0.8f, z}, {0, 0, 0, 1}, colour});
      return b;
    };
    ts::Batch red = quad(-0.8f, 0.4f, -0.5f, {1, 0, 0, 0.5f});
    red.blend = true, red.blendSrc = GL_SRC_ALPHA, red.blendDst = GL_ONE_MINUS_SRC_ALPHA;
    red.depthWrite = writes;
    p.batches = {red, quad(-0.4f, 0.8f, 0.5f, {0, 1, 0, 1})};
    f.panels.push_back(p);
    return f;
  };
  const ts::Frame f = frame(false);
  const ts::Image img = oracle::render(f);
  const ts::Rgba overlap = img.at(32, 32);  // in both quads: the green one, drawn over the red
  EXPECT_EQ(overlap.g, 255);
  EXPECT_EQ(overlap.r, 0);
  ref::VerifyResult r = ref::verifyImage(img, f, oracle::options("depth_write_off", "multitexture"));
  EXPECT_TRUE(r.ok()) << r.summary();
  ref::VerifyResult bad = ref::verifyImage(img, frame(true),
                                           oracle::options("depth_write_on", "multitexture_negative"));
  EXPECT_GT(bad.invalid, 20L * 40L) << "described with the depth writes on: " << bad.summary();
}

// The pear of the gloss_map figure (demos/multitexture multitexture_frames.hpp
// pearPanel): a lathe mesh, front and back faces, the depth test on with
// GL_LEQUAL, unit 1 on its own coordinates; in one pass (GL_MODULATE_ADD_ATI:
// t_r x PREVIOUS's alpha + PREVIOUS) and in two (the second added, GL_ONE,
// GL_ONE, over the first's layers).  Every GL pixel in the reference's legal
// range, the mesh textured, not exempt; described wrong (unit 1 GL_MODULATE
// instead of A.C + B; the second pass not added), most of the pear is invalid.
TEST(GLSecondUnit, ThePearInOnePassAndInTwo) {
  constexpr int w = 192;
  auto pear = [&](int method, const std::function<void(ts::Panel&)>& wrong) {
    return mt::frames::alone(w, w, [&](ts::Frame& f, ts::Rect v) {
      ts::Panel p = mt::frames::pearPanel(f, method, "pear", v);
      if (wrong) wrong(p);
      return p;
    });
  };
  for (int m : {mt::kCombine3, mt::kTwoPasses}) {
    const std::string n = m == mt::kCombine3 ? "pear_combine3" : "pear_two_passes";
    const ts::Frame f = pear(m, nullptr);
    const ts::Image img = oracle::render(f);
    const ref::VerifyResult r = ref::verifyImage(img, f, oracle::options(n, "multitexture"));
    EXPECT_EQ(r.invalid, 0) << r.summary();
    EXPECT_EQ(r.checked, long(w) * w) << r.summary();
    // The pear covers about a fifth of the square (its silhouette: 2 x the
    // integral of pearProfile's radius over its 1.6 of height, in the 2 x 2 view).
    EXPECT_GT(r.textured, long(w) * w / 6) << r.summary();
    std::printf("%s: %ld invalid of %ld checked (%ld textured, %ld edge)\n", n.c_str(), r.invalid, r.checked,
                r.textured, r.edges);
    const ts::Frame bad = pear(m, [&](ts::Panel& p) {
      if (m == mt::kCombine3) p.batches[0].combine1.rgb = GL_MODULATE;
      else p.batches[1].blendSrc = GL_ONE, p.batches[1].blendDst = GL_ZERO;
    });
    const ref::VerifyResult b = ref::verifyImage(img, bad,
                                                 oracle::options(n + "_described_wrong", "multitexture_negative"));
    EXPECT_GT(b.invalid, r.textured / 2) << n << ": " << b.summary();
    std::printf("%s described wrong: %ld invalid\n", n.c_str(), b.invalid);
  }
}
