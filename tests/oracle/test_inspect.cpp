// Unit tests of the per-pixel inspector (reference/inspect.hpp, no GL): the
// closed forms on frames whose answer is known (a 4x magnified quad, a plane
// receding in depth, a quad turned 45 degrees), the texel list against the
// sampler, the inspector against the whole reference image, the cards of
// the background, untextured batches, lines and labels, and the one-pixel
// coverage test against the scanline rasterizer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <random>
#include <set>

#include "reference/inspect.hpp"
#include "reference/reference.hpp"

namespace {
using ref::Inspection;
using ref::toRgba;

// A texture of random texels (every texel differs from its neighbours, so a
// wrong texel or weight shows in the colour).
ts::TextureDesc noise(int size, GLenum minFilter, GLenum magFilter, unsigned seed = 7) {
  auto img = std::make_shared<ts::Image>(size, size);
  std::mt19937 rng(seed);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      img->set(i, j, {uint8_t(rng()), uint8_t(rng()), uint8_t(rng()), uint8_t(128 + rng() % 128)});
  ts::TextureDesc t;
  t.name = "inspect_noise";
  t.params = {{"size", std::to_string(size)}, {"seed", std::to_string(seed)}};
  t.image = img;
  t.minFilter = minFilter, t.magFilter = magFilter;
  t.mipmaps = minFilter != GL_NEAREST && minFilter != GL_LINEAR;
  return t;
}

ts::Vertex vert(glm::vec3 pos, glm::vec2 st, glm::vec4 colour = glm::vec4(1.0f)) {
  ts::Vertex v;
  v.pos = pos;
  v.tex = {st.x, st.y, 0.0f, 1.0f};
  v.color = colour;
  return v;
}

// The quad p00 p10 p11 p01 with texture coordinates t00 .. t01, as two triangles.
void addQuad(ts::Batch& b, const std::array<glm::vec3, 4>& p, const std::array<glm::vec2, 4>& t,
             const std::array<glm::vec4, 4>& c = {glm::vec4(1.0f), glm::vec4(1.0f), glm::vec4(1.0f), glm::vec4(1.0f)}) {
  for (int k : {0, 1, 2, 0, 2, 3}) b.vertices.push_back(vert(p[size_t(k)], t[size_t(k)], c[size_t(k)]));
}

ts::Panel orthoPanel(int w, int h, float lo = 0.0f, float hi = 1.0f) {
  ts::Panel p;
  p.id = "p";
  p.viewport = {0, 0, w, h};
  p.projection = glm::ortho(lo, hi, lo, hi, -1.0f, 1.0f);
  return p;
}

// A screen-aligned quad filling a 64x64 frame with a 16x16 texture: 4 pixels a texel.
ts::Frame magnified(GLenum minFilter, GLenum magFilter) {
  ts::Frame f;
  f.width = f.height = 64;
  int tex = f.addTexture(noise(16, minFilter, magFilter));
  ts::Panel p = orthoPanel(64, 64);
  ts::Batch b;
  b.role = "surface";
  b.texture = tex;
  addQuad(b, {glm::vec3(0, 0, 0), {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {glm::vec2(0, 0), {1, 0}, {1, 1}, {0, 1}});
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}

// Figure VI.2's situation built by hand: a floor y = -1 from z = -1 to z = -60
// seen in perspective, its texture repeated 4 x 30 times.
ts::Frame receding(GLenum minFilter = GL_LINEAR_MIPMAP_LINEAR, GLenum env = GL_REPLACE) {
  ts::Frame f;
  f.width = f.height = 96;
  f.clearColor = {0.1f, 0.2f, 0.3f, 1.0f};
  int tex = f.addTexture(noise(32, minFilter, GL_LINEAR));
  f.textures[size_t(tex)].wrapS = f.textures[size_t(tex)].wrapT = GL_REPEAT;
  ts::Panel p;
  p.id = "floor";
  p.viewport = {0, 0, 96, 96};
  p.projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.5f, 100.0f);
  p.depthTest = true;
  ts::Batch b;
  b.role = "floor";
  b.texture = tex;
  b.texEnv = env;
  addQuad(b, {glm::vec3(-4, -1, -1), {4, -1, -1}, {4, -1, -60}, {-4, -1, -60}},
          {glm::vec2(0, 0), {4, 0}, {4, 30}, {0, 30}},
          {glm::vec4(1, 0.5, 0.25, 1), {0.25, 1, 0.5, 1}, {0.5, 0.25, 1, 1}, {1, 1, 1, 1}});
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}

// A 16x16 texture on a square turned 45 degrees in the screen.
ts::Frame turned(GLenum minFilter = GL_LINEAR) {
  ts::Frame f;
  f.width = f.height = 128;
  int tex = f.addTexture(noise(16, minFilter, GL_LINEAR));
  ts::Panel p = orthoPanel(128, 128, -1.0f, 1.0f);
  p.modelview = glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(0, 0, 1));
  ts::Batch b;
  b.role = "turned";
  b.texture = tex;
  addQuad(b, {glm::vec3(-0.6, -0.6, 0), {0.6, -0.6, 0}, {0.6, 0.6, 0}, {-0.6, 0.6, 0}},
          {glm::vec2(0, 0), {1, 0}, {1, 1}, {0, 1}});
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}

// Two panels and most of the state a Frame can hold: a texture matrix, the
// environments GL_DECAL / GL_BLEND / GL_MODULATE, the colour sum, LOD bias,
// clamping, depth-tested triangles crossing each other, an untextured one, a
// blended one, lines, points and a label.
ts::Frame busy() {
  ts::Frame f;
  f.width = 160, f.height = 96;
  int a = f.addTexture(noise(32, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, 3));
  int c = f.addTexture(noise(16, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, 5));
  f.textures[size_t(c)].wrapS = GL_CLAMP_TO_EDGE, f.textures[size_t(c)].wrapT = GL_MIRRORED_REPEAT;
  f.textures[size_t(c)].lodBias = 0.75f;

  ts::Panel left = orthoPanel(80, 96, -1.0f, 1.0f);
  left.id = "left";
  left.clear = true;
  left.clearColor = {0.9f, 0.9f, 0.8f, 1.0f};
  left.modelview = glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0, 0, 1));
  ts::Batch q;
  q.role = "env_blend";
  q.texture = a;
  q.texEnv = GL_BLEND;
  q.envColor = {0.2f, 0.8f, 0.4f, 1.0f};
  q.textureMatrix = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, -0.2f, 0)), glm::vec3(2.5f, 1.5f, 1));
  addQuad(q, {glm::vec3(-0.8, -0.7, 0), {0.7, -0.8, 0}, {0.8, 0.7, 0}, {-0.7, 0.8, 0}},
          {glm::vec2(0, 0), {1, 0}, {1, 1}, {0, 1}}, {glm::vec4(1, 0, 0, 1), {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 0, 1}});
  q.colorSum = true;
  for (auto& v : q.vertices) v.secondary = {0.1f, 0.05f, 0.2f};
  left.batches.push_back(q);
  ts::Batch glass;  // blended, untextured
  glass.role = "glass";
  glass.blend = true;
  glass.vertices = {vert({-0.9f, -0.2f, 0}, {0, 0}, {0.2f, 0.4f, 1.0f, 0.5f}),
                    vert({0.9f, -0.1f, 0}, {0, 0}, {1, 1, 1, 0.3f}),
                    vert({0.0f, 0.9f, 0}, {0, 0}, {1, 0.2f, 0.2f, 0.8f})};
  left.batches.push_back(glass);
  left.batches.push_back(ts::lineLoop({{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}}, {0, 0, 0, 1}, 2.0f, "outline"));
  ts::Batch dots;
  dots.role = "dots";
  dots.prim = ts::Prim::Points;
  dots.pointSize = 3;
  dots.vertices = {vert({0.1f, 0.1f, 0}, {0, 0}, {1, 0, 1, 1}), vert({-0.3f, 0.4f, 0}, {0, 0}, {0, 1, 1, 1})};
  left.batches.push_back(dots);
  f.panels.push_back(left);

  ts::Panel right;
  right.id = "right";
  right.viewport = {80, 0, 80, 96};
  right.projection = glm::perspective(glm::radians(50.0f), 80.0f / 96.0f, 0.5f, 20.0f);
  right.depthTest = true;
  right.clear = true;
  ts::Batch tilted;
  tilted.role = "tilted";
  tilted.texture = c;
  tilted.texEnv = GL_MODULATE;
  addQuad(tilted, {glm::vec3(-1.5, -1.2, -2.5), {1.5, -1.2, -2.5}, {1.5, 1.2, -6.5}, {-1.5, 1.2, -6.5}},
          {glm::vec2(-0.3, -0.2), {1.3, -0.2}, {1.3, 2.5}, {-0.3, 2.5}},
          {glm::vec4(1, 1, 1, 1), {1, 0.6, 0.6, 1}, {0.6, 1, 0.6, 1}, {0.6, 0.6, 1, 1}});
  right.batches.push_back(tilted);
  ts::Batch crossing;  // cuts through the tilted quad in depth
  crossing.role = "crossing";
  crossing.texture = a;
  crossing.texEnv = GL_DECAL;
  addQuad(crossing, {glm::vec3(-1.0, -0.8, -6.0), {1.0, -0.8, -2.0}, {1.0, 0.6, -2.0}, {-1.0, 0.6, -6.0}},
          {glm::vec2(0, 0), {3, 0}, {3, 2}, {0, 2}});
  right.batches.push_back(crossing);
  ts::Batch flat;
  flat.role = "flat";
  flat.vertices = {vert({-0.8f, 0.5f, -3.0f}, {0, 0}, {1, 0.5f, 0, 1}),
                   vert({-0.2f, 0.9f, -3.0f}, {0, 0}, {0, 0.5f, 1, 1}),
                   vert({-0.9f, 1.0f, -3.0f}, {0, 0}, {0.5f, 1, 0.5f, 1})};
  right.batches.push_back(flat);
  f.panels.push_back(right);

  ts::Label l;
  l.x = 90, l.y = 70;
  l.text = "label";
  l.color = {1, 1, 1, 1};
  l.background = {0, 0, 0, 0.6f};
  f.labels.push_back(l);
  return f;
}

TEST(Inspect, MagnifiedFourTimesHasLambdaMinusTwo) {
  for (GLenum filter : {GLenum(GL_LINEAR_MIPMAP_LINEAR), GLenum(GL_NEAREST)}) {
    ts::Frame f = magnified(filter, filter == GL_NEAREST ? GL_NEAREST : GL_LINEAR);
    const int x = 13, y = 41;
    Inspection in = ref::inspect(f, x, y);
    ASSERT_EQ(in.what, Inspection::What::Triangle);
    EXPECT_TRUE(in.textured);
    EXPECT_EQ(in.panel, 0);
    EXPECT_EQ(in.batch, 0);
    EXPECT_EQ(in.batchRole, "surface");
    // 16 texels over 64 pixels: rho = 1/4, lambda = log2(1/4) = -2, exactly.
    EXPECT_EQ(in.lambda, -2.0);
    EXPECT_EQ(in.rhoEdge, 0.25);
    EXPECT_EQ(in.rhoMax, 0.25);
    EXPECT_TRUE(in.magnified);
    // s grows with x; t grows upwards (GL window y up), image y down.
    EXPECT_NEAR(in.s, (x + 0.5) / 64.0, 1e-14);
    EXPECT_NEAR(in.t, 1.0 - (y + 0.5) / 64.0, 1e-14);
    EXPECT_NEAR(in.q, 1.0, 1e-14);
    EXPECT_NEAR(in.u, (x + 0.5) / 4.0, 1e-12);
    EXPECT_NEAR(in.v, 16.0 - (y + 0.5) / 4.0, 1e-12);
    EXPECT_NEAR(in.dudx, 0.25, 1e-14);
    EXPECT_NEAR(in.dvdy, -0.25, 1e-14);
    EXPECT_NEAR(in.dvdx, 0.0, 1e-14);
    EXPECT_NEAR(in.dudy, 0.0, 1e-14);
    if (filter == GL_NEAREST) {
      ASSERT_EQ(in.texels.size(), 1u);
      EXPECT_EQ(in.texels[0].i, int(std::floor(in.u)));
      EXPECT_EQ(in.texels[0].j, int(std::floor(in.v)));
      EXPECT_EQ(in.texels[0].weight, 1.0);
    } else {
      EXPECT_EQ(in.texels.size(), 4u);  // magnified: GL_LINEAR on level 0
      EXPECT_EQ(in.filter, GLenum(GL_LINEAR));
    }
    // The preimage of the pixel square is a 1/4-texel square; the
    // parallelogram is the same square; the EWA ellipse is a circle of
    // radius 1/4: (1/16) du^2 + (1/16) dv^2 = (1/16)^2.
    EXPECT_NEAR(in.preimage[0].x, x / 4.0, 1e-12);
    EXPECT_NEAR(in.preimage[2].y, 16.0 - (y + 1) / 4.0, 1e-12);
    for (size_t k = 0; k < 4; ++k) {
      EXPECT_NEAR(in.parallelogram[k].x, in.preimage[k].x, 1e-12);
      EXPECT_NEAR(in.parallelogram[k].y, in.preimage[k].y, 1e-12);
    }
    EXPECT_NEAR(in.ewaA, 1.0 / 16, 1e-14);
    EXPECT_NEAR(in.ewaB, 0.0, 1e-14);
    EXPECT_NEAR(in.ewaC, 1.0 / 16, 1e-14);
    EXPECT_NEAR(in.ewaF, 1.0 / 256, 1e-14);
  }
}

TEST(Inspect, LambdaRisesWithDepthAlongTheCentreColumn) {
  ts::Frame f = receding();
  ref::Inspector inspector(f);
  std::vector<std::pair<double, double>> zLambda;  // (depth, lambda) down the column
  for (int y = 0; y < f.height; ++y) {
    Inspection in = inspector.at(f.width / 2, y);
    if (in.what != Inspection::What::Triangle) continue;
    ASSERT_TRUE(in.textured);
    zLambda.push_back({in.z, in.lambda});
  }
  ASSERT_GT(zLambda.size(), 30u);
  std::sort(zLambda.begin(), zLambda.end());
  for (size_t k = 1; k < zLambda.size(); ++k) {
    EXPECT_LT(zLambda[k - 1].first, zLambda[k].first);
    EXPECT_LT(zLambda[k - 1].second, zLambda[k].second) << "at depth " << zLambda[k].first;
  }
  // Far away the floor is minified (several levels), near it is magnified.
  EXPECT_GT(zLambda.back().second, 2.0);
  EXPECT_LT(zLambda.front().second, 0.0);
}

TEST(Inspect, FortyFiveDegreesSeparatesTheTwoRhos) {
  // Turned by 45 degrees, (du/dx, dv/dx) = k (cos 45, -sin 45): its length k
  // is sqrt(2) times its largest component, so log2(rhoEdge / rhoMax) = 1/2.
  ts::Frame f = turned();
  ref::Inspector inspector(f);
  int checked = 0;
  for (int y = 40; y < 90; y += 7)
    for (int x = 40; x < 90; x += 9) {
      Inspection in = inspector.at(x, y);
      ASSERT_EQ(in.what, Inspection::What::Triangle) << x << "," << y;
      EXPECT_NEAR(std::log2(in.rhoEdge / in.rhoMax), 0.5, 1e-9);
      EXPECT_NEAR(in.lambda, std::log2(in.rhoEdge), 1e-12);
      ++checked;
    }
  EXPECT_GT(checked, 20);
}

// The texel list is the filter: weights sum to 1 and sum(weight x rgba) is
// what the sampler returns; NEAREST reads 1 texel, LINEAR 4, trilinear 8.
TEST(Inspect, TexelListReproducesTheSampler) {
  std::mt19937 rng(11);
  for (GLenum filter :
       {GLenum(GL_NEAREST), GLenum(GL_LINEAR), GLenum(GL_NEAREST_MIPMAP_NEAREST), GLenum(GL_LINEAR_MIPMAP_NEAREST),
        GLenum(GL_NEAREST_MIPMAP_LINEAR), GLenum(GL_LINEAR_MIPMAP_LINEAR)}) {
    ts::Frame f = receding(filter, GL_MODULATE);
    ref::Inspector inspector(f);
    ref::Texture tex(f.textures[0]);
    int seen = 0, minified = 0;
    for (int n = 0; n < 400 && seen < 60; ++n) {
      Inspection in = inspector.at(int(rng() % 96), int(rng() % 96));
      if (!in.textured) continue;
      ++seen;
      double weights = 0;
      double sum[4] = {0, 0, 0, 0};
      for (const ref::InspectTexel& t : in.texels) {
        weights += t.weight;
        for (size_t k = 0; k < 4; ++k) sum[k] += t.weight * t.rgba[k];
        // Each texel is the level's texel at the wrapped (i, j).
        EXPECT_EQ(toRgba(t.rgba), tex.level(t.level).at(t.i, t.j));
      }
      EXPECT_NEAR(weights, 1.0, 1e-12);
      const ref::Colour want = tex.sample(in.sq, in.tq, in.lambdaBase);
      for (size_t k = 0; k < 4; ++k) {
        // Colours are floats: the sum is compared after the sampler's
        // rounding to float (a double sum differs from it by ~1e-8).
        EXPECT_NEAR(double(float(sum[k])), want[k], 1e-9) << "channel " << k;
        EXPECT_NEAR(in.filtered[k], want[k], 1e-9);
        // GL_MODULATE: the reference colour is the vertex colour times the filtered texel.
        EXPECT_NEAR(in.referenceRgba[k], in.primary[k] * want[k], 1e-6);
      }
      const bool nearest = in.filter == GL_NEAREST;
      const bool twoLevels = in.level1 != in.level0;
      EXPECT_EQ(in.texels.size(), size_t((nearest ? 1 : 4) * (twoLevels ? 2 : 1)));
      if (!in.magnified) {
        ++minified;
        EXPECT_EQ(twoLevels, (filter == GL_NEAREST_MIPMAP_LINEAR || filter == GL_LINEAR_MIPMAP_LINEAR) &&
                                 in.lambda < tex.levels() - 1);
      }
    }
    EXPECT_GE(seen, 40);
    EXPECT_GT(minified, 5);
  }
}

// sample() sums the footprint now; the verifier's legal set (another code
// path) at zero jitter must hold the same single value.
TEST(Inspect, FootprintAgreesWithTheLegalSet) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(-1.5, 2.5), lod(-2.0, 7.0);
  for (GLenum wrap : {GLenum(GL_REPEAT), GLenum(GL_MIRRORED_REPEAT), GLenum(GL_CLAMP_TO_EDGE),
                      GLenum(GL_CLAMP_TO_BORDER), GLenum(GL_CLAMP)})
    for (GLenum filter :
         {GLenum(GL_NEAREST), GLenum(GL_LINEAR), GLenum(GL_NEAREST_MIPMAP_NEAREST), GLenum(GL_LINEAR_MIPMAP_NEAREST),
          GLenum(GL_NEAREST_MIPMAP_LINEAR), GLenum(GL_LINEAR_MIPMAP_LINEAR)}) {
      ts::TextureDesc d = noise(16, filter, filter == GL_NEAREST ? GL_NEAREST : GL_LINEAR);
      d.wrapS = d.wrapT = wrap;
      d.border = {0.25f, 0.5f, 0.75f, 1.0f};
      d.lodBias = 0.5f;
      ref::Texture tex(d);
      for (int n = 0; n < 200; ++n) {
        double s = coord(rng), t = coord(rng), l = lod(rng);
        ref::Boxes legal;
        tex.legal(s, t, l, l, 0.0, 0.0, &legal);
        ASSERT_EQ(legal.size(), 1u);
        ref::Colour got = tex.sample(s, t, l);
        for (size_t k = 0; k < 4; ++k) {
          EXPECT_NEAR(got[k], legal[0].lo[k], 1e-6);
          EXPECT_NEAR(got[k], legal[0].hi[k], 1e-6);
        }
      }
    }
}

// The inspector agrees with the whole reference picture.
void expectAgreesWithReference(const ts::Frame& f, int samples, unsigned seed) {
  ref::Reference reference(f);
  ref::Inspector inspector(f);
  std::mt19937 rng(seed);
  int covered = 0;
  for (int n = 0; n < 20000 && covered < samples; ++n) {
    int x = int(rng() % unsigned(f.width)), y = int(rng() % unsigned(f.height));
    Inspection in = inspector.at(x, y);
    if (in.what == Inspection::What::Background) continue;
    ++covered;
    const ts::Rgba want = reference.image().at(x, y);
    const ts::Rgba got = toRgba(in.pixelRgba);
    const int d = std::max(
        {std::abs(got.r - want.r), std::abs(got.g - want.g), std::abs(got.b - want.b), std::abs(got.a - want.a)});
    EXPECT_LE(d, 1) << "pixel " << x << "," << y << "\n" << ref::formatInspection(in);
    // Unless blended, the pixel is the fragment's reference colour.
    const bool blended = in.what == Inspection::What::Triangle &&
                         f.panels[size_t(in.panel)].batches[size_t(in.batch)].blend;
    if (!blended) EXPECT_EQ(toRgba(in.referenceRgba), got);
  }
  EXPECT_EQ(covered, samples);
}

TEST(Inspect, AgreesWithTheReferenceImage) {
  expectAgreesWithReference(receding(GL_LINEAR_MIPMAP_LINEAR, GL_MODULATE), 50, 1);
  expectAgreesWithReference(turned(GL_NEAREST_MIPMAP_LINEAR), 50, 2);
  expectAgreesWithReference(magnified(GL_NEAREST, GL_NEAREST), 50, 3);
  expectAgreesWithReference(busy(), 50, 4);
}

// Every pixel of the busy frame: the same pixels covered, the same colours
// (the edges between triangles, the depth test, blending, lines, points and
// the label included).
TEST(Inspect, AgreesWithTheReferenceImageEverywhere) {
  ts::Frame f = busy();
  ref::Reference reference(f);
  ref::Inspector inspector(f);
  int bad = 0;
  std::set<Inspection::What> seen;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      Inspection in = inspector.at(x, y);
      seen.insert(in.what);
      const ts::Rgba want = reference.image().at(x, y), got = toRgba(in.pixelRgba);
      const int d = std::max(
          {std::abs(got.r - want.r), std::abs(got.g - want.g), std::abs(got.b - want.b), std::abs(got.a - want.a)});
      if (d > 1 && ++bad <= 5) ADD_FAILURE() << "pixel " << x << "," << y << "\n" << ref::formatInspection(in);
    }
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(seen.size(), 5u) << "background, triangles, lines, points and a label";
}

TEST(Inspect, BackgroundAndUntexturedSayWhatTheyAre) {
  ts::Frame f = busy();
  ref::Inspector inspector(f);
  // The right panel's corner: nothing drawn, its clear colour.
  Inspection bg = inspector.at(159, 0);
  EXPECT_EQ(bg.what, Inspection::What::Background);
  EXPECT_FALSE(bg.textured);
  EXPECT_EQ(bg.batch, -1);
  EXPECT_EQ(bg.panelName, "right");
  EXPECT_EQ(bg.note.rfind("background: no batch covers this pixel", 0), 0u) << bg.note;
  EXPECT_TRUE(bg.texels.empty());
  EXPECT_TRUE(std::isnan(bg.lambda));
  nlohmann::json j = ref::inspectionJson(bg);
  EXPECT_EQ(j["batch"], -1);
  EXPECT_TRUE(j["lambda"].is_null());
  // An untextured triangle.
  ts::Frame g;
  g.width = g.height = 32;
  ts::Panel p = orthoPanel(32, 32);
  ts::Batch b;
  b.role = "flat";
  b.vertices = {vert({0, 0, 0}, {0, 0}, {1, 0, 0, 1}), vert({1, 0, 0}, {0, 0}, {1, 0, 0, 1}),
                vert({0, 1, 0}, {0, 0}, {1, 0, 0, 1})};
  p.batches.push_back(b);
  g.panels.push_back(p);
  Inspection flat = ref::inspect(g, 4, 28);
  EXPECT_EQ(flat.what, Inspection::What::Triangle);
  EXPECT_FALSE(flat.textured);
  EXPECT_EQ(flat.batchRole, "flat");
  EXPECT_EQ(flat.note.rfind("untextured batch", 0), 0u) << flat.note;
  EXPECT_TRUE(flat.texels.empty());
  EXPECT_EQ(toRgba(flat.referenceRgba), (ts::Rgba{255, 0, 0, 255}));
  EXPECT_EQ(ref::inspect(g, 30, 1).what, Inspection::What::Background);
}

TEST(Inspect, LinesPointsLabelsAndProgramsAreNamed) {
  ts::Frame f = busy();
  ref::Inspector inspector(f);
  int lines = 0, labels = 0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      Inspection in = inspector.at(x, y);
      if (in.what == Inspection::What::Line) {
        ++lines;
        EXPECT_FALSE(in.textured);
        EXPECT_EQ(in.batchRole, "outline");
        EXPECT_NE(in.note.find("line batch"), std::string::npos);
      }
      if (in.what == Inspection::What::Label) {
        ++labels;
        EXPECT_FALSE(in.textured);
        EXPECT_EQ(in.panel, -1);
        EXPECT_NE(in.note.find("label \"label\""), std::string::npos);
      }
    }
  EXPECT_GT(lines, 20);
  EXPECT_GT(labels, 20);
  // A GLSL program the reference does not model: no filter is made up.
  ts::Frame g = magnified(GL_LINEAR, GL_LINEAR);
  g.panels[0].batches[0].program = "mystery";
  Inspection in = ref::inspect(g, 10, 10);
  EXPECT_TRUE(in.program);
  EXPECT_FALSE(in.textured);
  EXPECT_TRUE(in.texels.empty());
  EXPECT_TRUE(std::isnan(in.lambda));
  EXPECT_NE(in.note.find("GLSL program 'mystery': the texture lookup is the shader's"), std::string::npos);
  EXPECT_NEAR(in.s, 10.5 / 64, 1e-12);  // the interpolated attribute it receives
}

TEST(Inspect, CardAndJson) {
  Inspection in = ref::inspect(magnified(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR), 20, 20);
  std::string card = ref::formatInspection(in);
  for (const char* want : {"pixel (20, 20)", "(s,t,r,q)", "(s/q,t/q)", "(u,v)", "du/dx", "rho", "lambda", "magnified",
                           "texels", "reference"})
    EXPECT_NE(card.find(want), std::string::npos) << want << " missing from\n" << card;
  nlohmann::json j = ref::inspectionJson(in);
  std::set<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.insert(it.key());
  EXPECT_EQ(keys, (std::set<std::string>{"pixel", "panel", "batch", "st", "stq", "uv", "derivatives", "rho_edge",
                                         "rho_max", "lambda", "levels", "level_weight", "texels", "reference_rgba"}));
  EXPECT_EQ(j["pixel"], nlohmann::json({20, 20}));
  EXPECT_EQ(j["lambda"].get<double>(), -2.0);
  ASSERT_EQ(j["texels"].size(), 4u);
  EXPECT_EQ(j["texels"][0]["rgba"].size(), 4u);
  EXPECT_EQ(j["derivatives"].size(), 4u);
  EXPECT_EQ(j["stq"].size(), 4u);
}

// The one-pixel coverage test is the scanline rasterizer's, pixel for pixel.
TEST(Inspect, CoversCentreMatchesScanTriangle) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> pos(-2.0, 18.0);
  // Vertices on the pixel grid, on centres and on half-centres too: the ties.
  std::uniform_int_distribution<int> grid(-2, 36);
  for (int n = 0; n < 400; ++n) {
    ref::ScreenVertex v[3];
    for (auto& p : v) {
      if (n % 2) p.x = pos(rng), p.y = pos(rng);
      else p.x = grid(rng) * 0.5, p.y = grid(rng) * 0.5;
    }
    for (ref::FillRule rule : {ref::FillRule::GLTopLeft, ref::FillRule::ImageTopLeft}) {
      std::vector<int> emitted(16 * 16, 0);
      ref::scanTriangle(v[0], v[1], v[2], 0, {0, 0, 16, 16}, rule,
                        [&](int x, int y, const double*) { ++emitted[size_t(y * 16 + x)]; });
      for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
          ASSERT_EQ(ref::coversCentre(v[0], v[1], v[2], x, y, rule), emitted[size_t(y * 16 + x)] == 1)
              << "triangle " << n << " pixel " << x << "," << y;
    }
  }
}
}  // namespace
