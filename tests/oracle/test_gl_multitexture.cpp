// The oracle against OpenGL on the multitexturing state (issue 29): the
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

#include <cmath>

#include "oracle_support.hpp"
#include "reference/reference.hpp"

namespace {
ts::TextureDesc cutout(int n, GLenum filter) {
  auto img = std::make_shared<ts::Image>(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double r = std::hypot(i + 0.5 - n / 2.0, j + 0.5 - n / 2.0) / (n / 2.0);
      const uint8_t a = r < 0.55 ? 255 : r < 0.7 ? 160 : r < 0.85 ? 100 : 0;
      img->set(i, j, {uint8_t(30 + (i * 37) % 200), uint8_t(90 + (j * 23) % 160), uint8_t(20 + ((i + j) * 11) % 90), a});
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
      ref::VerifyResult bad = ref::verifyImage(img, wrong, oracle::options(n + "_described_wrong", "multitexture_negative"));
      EXPECT_GT(bad.invalid, 2000) << n << ": " << bad.summary();
      if (func != 0) {
        const ts::Frame off = cutoutFrame(filter, 0, 0.0f);
        ref::VerifyResult bad2 = ref::verifyImage(img, off, oracle::options(n + "_described_off", "multitexture_negative"));
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
