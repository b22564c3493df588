// Unit tests of the JSON reader and of the sidecar round trip: a Frame
// written by ts::sidecarJson and read back by ref::readSidecar is the same
// Frame (textures re-made from name and params, texel for texel).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "common/core/error.hpp"
#include "common/core/sidecar.hpp"
#include "common/core/textures.hpp"
#include "reference/reference.hpp"
#include "reference/sidecar_reader.hpp"
#include "reference/verify.hpp"

#ifndef TS_ORACLE_OUT_DIR
#define TS_ORACLE_OUT_DIR "oracle_failures"
#endif

namespace {
// The file is read with nlohmann-json: what the suite adds is that its errors
// become one line naming the place, and that wrong types are named.
TEST(Sidecar, MalformedJsonIsOneLineNamingThePlace) {
  auto message = [](const std::string& text) {
    try {
      ref::readSidecar(text);
    } catch (const ts::Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::string m = message("{\n  \"size\": [1, 2,]\n}");
  EXPECT_EQ(m.rfind("json: ", 0), 0u) << m;
  EXPECT_NE(m.find("line 2"), std::string::npos) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  EXPECT_NE(message("[1, 2]").find("document: expected an object"), std::string::npos);
  EXPECT_NE(message("{\"size\": \"big\"}").find("size: expected [width, height]"), std::string::npos);
  EXPECT_NE(message("{\"size\": [1e300, 2]}").find("size: expected a number in 1..16384"), std::string::npos);
  EXPECT_NE(message("{\"size\": [1, true]}").find("expected a number, found boolean"), std::string::npos);
  // Deep nesting is refused or read, never a crash (the parser is not recursive).
  EXPECT_NE(message(std::string(100000, '[')), "no error");
}

ts::Frame sampleFrame() {
  ts::Frame f;
  f.width = 320, f.height = 200;
  f.clearColor = {0.1f, 0.2f, 0.3f, 1.0f};
  f.perspectiveHint = GL_FASTEST;
  ts::TextureDesc c = ts::checkerboard(64, 4, {1, 2, 3, 255}, {250, 240, 230, 128});
  c.wrapS = GL_MIRRORED_REPEAT;
  c.wrapT = GL_CLAMP_TO_BORDER;
  c.border = {0.25f, 0.5f, 0.75f, 1.0f};
  c.minFilter = GL_LINEAR_MIPMAP_NEAREST;
  c.magFilter = GL_NEAREST;
  c.mipmaps = true;
  c.lodBias = -0.75f;
  c.maxAnisotropy = 4.0f;
  f.addTexture(c);
  ts::TextureDesc m = ts::mipLevelColours(32);  // explicit levels
  f.addTexture(m);
  ts::TextureDesc g = ts::labelledGrid(64, 4);
  g.mipmaps = true;
  g.linearLightMips = true;
  f.addTexture(g);
  f.addTexture(ts::texelIndexTexture(16));
  f.programs.push_back({"bilinear_quad", {"demos/quad_distortion/quad_distortion.cpp", "vs", "fs"}});
  ts::Panel p;
  p.id = "left";
  p.viewport = {3, 5, 150, 120};
  p.depthTest = true;
  p.projection = glm::perspective(0.7f, 1.25f, 0.1f, 30.0f);
  p.modelview = glm::lookAt(glm::vec3(0.3f, 1.1f, 2.7f), glm::vec3(0), glm::vec3(0, 1, 0));
  ts::Batch b;
  b.role = "surface";
  b.texture = 0;
  b.texEnv = GL_MODULATE;
  b.vertices = {{{0.1f, 0.2f, 0.3f}, {0.5f, 0.25f, 0.0f, 1.0f}, {1, 0.5f, 0.25f, 1}},
                {{1.0f / 3, -2.0f / 7, 1e-7f}, {3.5f, -1.25f, 0.5f, 2.0f}, {0, 1, 0, 0.5f}},
                {{-5, 6, -7}, {0.1f, 0.9f, 0, 1}, {1, 1, 1, 1}}};
  p.batches.push_back(b);
  ts::Batch q = b;
  q.program = "bilinear_quad";
  q.texture = 1;
  q.texEnv = GL_REPLACE;
  q.uniforms = {{"st00_st10", {0, 0, 1, 0}}, {"st11_st01", {0.75f, 0.75f, 0, 1}}};
  p.batches.push_back(q);
  p.batches.push_back(ts::lineLoop({{0, 0}, {1, 0}, {0.5f, 1}}, {0.9f, 0.1f, 0.1f, 1}, 3.0f, "outline"));
  ts::Batch s = ts::lineSegments({{0, 0}, {1, 1}}, {1, 1, 1, 1}, 1.5f, "diag");
  s.prim = ts::Prim::LineStrip;
  s.blend = true;
  p.batches.push_back(s);
  f.panels.push_back(p);
  ts::Panel r;
  r.id = "right";
  r.viewport = {160, 0, 160, 200};
  ts::Batch l = ts::lineSegments({{0, 0}, {1, 1}}, {1, 1, 1, 1}, 2.0f, "segments");
  r.batches.push_back(l);
  f.panels.push_back(r);
  f.labels.push_back({12.5f, 7.0f, "a \"quoted\" label\\", {1, 1, 1, 1}, 2, ts::Align::Center});
  return f;
}

void expectSameImage(const ts::Image& a, const ts::Image& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_TRUE(a.pixels == b.pixels);
}

TEST(Sidecar, RoundTripOfAFrame) {
  ts::Frame f = sampleFrame();
  ts::SidecarInfo info;
  info.figureId = "x";
  info.demo = "demo";
  info.state = {{"view", "book"}};
  ref::SidecarScene sc = ref::readSidecar(ts::sidecarJson(f, info));
  const ts::Frame& g = sc.frame;
  EXPECT_EQ(sc.figure, "x");
  EXPECT_EQ(sc.demo, "demo");
  ASSERT_EQ(sc.state.size(), 1u);
  EXPECT_EQ(g.width, f.width);
  EXPECT_EQ(g.height, f.height);
  EXPECT_EQ(g.clearColor, f.clearColor);
  EXPECT_EQ(g.perspectiveHint, GLenum(GL_FASTEST));
  ASSERT_EQ(g.textures.size(), f.textures.size());
  for (size_t i = 0; i < f.textures.size(); ++i) {
    SCOPED_TRACE(f.textures[i].name);
    const ts::TextureDesc &a = f.textures[i], &b = g.textures[i];
    EXPECT_EQ(a.key(), b.key());
    EXPECT_EQ(a.minFilter, b.minFilter);
    EXPECT_EQ(a.magFilter, b.magFilter);
    EXPECT_EQ(a.wrapS, b.wrapS);
    EXPECT_EQ(a.wrapT, b.wrapT);
    EXPECT_EQ(a.border, b.border);
    EXPECT_EQ(a.lodBias, b.lodBias);
    EXPECT_EQ(a.maxAnisotropy, b.maxAnisotropy);
    EXPECT_EQ(a.mipmaps, b.mipmaps);
    EXPECT_EQ(a.linearLightMips, b.linearLightMips);
    EXPECT_EQ(bool(a.mipLevels), bool(b.mipLevels));
    expectSameImage(*a.image, *b.image);  // texel for texel
    if (a.mipLevels)
      for (size_t k = 0; k < a.mipLevels->size(); ++k) expectSameImage((*a.mipLevels)[k], (*b.mipLevels)[k]);
  }
  ASSERT_EQ(g.programs.size(), 1u);
  EXPECT_EQ(g.programs[0].first, "bilinear_quad");
  EXPECT_EQ(g.programs[0].second.file, f.programs[0].second.file);
  ASSERT_EQ(g.panels.size(), f.panels.size());
  for (size_t pi = 0; pi < f.panels.size(); ++pi) {
    const ts::Panel &a = f.panels[pi], &b = g.panels[pi];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.viewport.x, b.viewport.x);
    EXPECT_EQ(a.viewport.y, b.viewport.y);
    EXPECT_EQ(a.viewport.w, b.viewport.w);
    EXPECT_EQ(a.viewport.h, b.viewport.h);
    EXPECT_EQ(a.depthTest, b.depthTest);
    EXPECT_EQ(a.projection, b.projection);  // 9 significant digits: floats come back exactly
    EXPECT_EQ(a.modelview, b.modelview);
    ASSERT_EQ(a.batches.size(), b.batches.size());
    for (size_t bi = 0; bi < a.batches.size(); ++bi) {
      const ts::Batch &x = a.batches[bi], &y = b.batches[bi];
      EXPECT_EQ(x.role, y.role);
      EXPECT_EQ(x.prim, y.prim);
      EXPECT_EQ(x.texture, y.texture);
      EXPECT_EQ(x.texEnv, y.texEnv);
      EXPECT_EQ(x.program, y.program);
      EXPECT_EQ(x.lineWidth, y.lineWidth);
      EXPECT_EQ(x.blend, y.blend);
      ASSERT_EQ(x.uniforms.size(), y.uniforms.size());
      for (size_t u = 0; u < x.uniforms.size(); ++u) {
        EXPECT_EQ(x.uniforms[u].name, y.uniforms[u].name);
        EXPECT_EQ(x.uniforms[u].value, y.uniforms[u].value);
      }
      ASSERT_EQ(x.vertices.size(), y.vertices.size());
      for (size_t v = 0; v < x.vertices.size(); ++v) {
        EXPECT_EQ(x.vertices[v].pos, y.vertices[v].pos);
        EXPECT_EQ(x.vertices[v].tex, y.vertices[v].tex);
        EXPECT_EQ(x.vertices[v].color, y.vertices[v].color);
      }
    }
  }
  ASSERT_EQ(g.labels.size(), 1u);
  EXPECT_EQ(g.labels[0].text, f.labels[0].text);
  EXPECT_EQ(g.labels[0].x, f.labels[0].x);
  EXPECT_EQ(g.labels[0].y, f.labels[0].y);
  EXPECT_EQ(g.labels[0].scale, f.labels[0].scale);
  EXPECT_EQ(g.labels[0].align, f.labels[0].align);
  EXPECT_EQ(g.labels[0].color, f.labels[0].color);
  EXPECT_EQ(g.labels[0].background, f.labels[0].background);
  for (size_t pi = 0; pi < f.panels.size(); ++pi) {
    EXPECT_EQ(g.panels[pi].clear, f.panels[pi].clear);
    EXPECT_EQ(g.panels[pi].clearColor, f.panels[pi].clearColor);
  }
}

TEST(Sidecar, HoldsEverythingAndSaysWhatIsMissing) {
  // The writer records every label's geometry and look, each panel's clear,
  // point sizes and the fixed state: the reader finds nothing missing.
  ts::SidecarInfo info;
  info.renderer = "llvmpipe | 4.5";
  ref::SidecarScene sc = ref::readSidecar(ts::sidecarJson(sampleFrame(), info));
  EXPECT_TRUE(sc.labelGeometryKnown);
  EXPECT_TRUE(sc.fixedStateKnown);
  EXPECT_TRUE(sc.missing.empty()) << sc.missing.front();
  EXPECT_EQ(sc.renderer, "llvmpipe | 4.5");
  // A file without them (an older sidecar) is read, and each gap is named.
  std::string old = ts::sidecarJson(sampleFrame(), {});
  size_t at = old.find("\"fixed_state\"");
  ASSERT_NE(at, std::string::npos);
  old.erase(at, old.find('\n', at) + 1 - at);
  for (const char* key : {", \"scale\": ", ", \"align\": "}) {
    size_t k = old.find(key);
    ASSERT_NE(k, std::string::npos) << key;
    old.erase(k, old.find(',', k + 2) - k);
  }
  ref::SidecarScene gaps = ref::readSidecar(old);
  EXPECT_FALSE(gaps.labelGeometryKnown);
  EXPECT_FALSE(gaps.fixedStateKnown);
  std::string all;
  for (const std::string& m : gaps.missing) all += m + " ";
  EXPECT_NE(all.find("fixed_state"), std::string::npos) << all;
  EXPECT_NE(all.find("labels[0].scale"), std::string::npos) << all;
  EXPECT_NE(all.find("labels[0].align"), std::string::npos) << all;
  // And a fixed state the reference does not model is refused, by name.
  std::string lit = ts::sidecarJson(sampleFrame(), {});
  lit.replace(lit.find("\"lighting\": false"), 18, "\"lighting\": true");
  EXPECT_THROW(ref::readSidecar(lit), ts::Error);
}

// Claim: a figure that shows a picture no generator remakes (a GL render its
// measure() read back, named by digest) is still checked from its sidecar
// alone, except exactly the pixels that read that picture.  Read strictly the
// sidecar is refused; read with SidecarReadOptions::unknownPictures the
// picture is a placeholder whose pixels are exempt, and a wrong pixel
// anywhere else is still found.
TEST(Sidecar, UnknownPicturesAreExemptAndNothingElse) {
  ts::Frame f;
  f.width = 64, f.height = 32;
  ts::TextureDesc pic;
  pic.name = "some_demo_render";
  pic.params = {{"image", "a GL render"}, {"digest", "0123456789abcdef"}};
  pic.image = std::make_shared<ts::Image>(8, 8, ts::Rgba{20, 200, 90, 255});
  pic.minFilter = pic.magFilter = GL_NEAREST;
  f.addTexture(pic);
  ts::Panel p;
  p.id = "all";
  p.viewport = {0, 0, 64, 32};
  const auto quad = [](float x0, float x1) {
    std::vector<ts::Vertex> v;
    for (int k : {0, 1, 2, 0, 2, 3}) {
      ts::Vertex q;
      q.pos = {k == 1 || k == 2 ? x1 : x0, k >= 2 ? 1.0f : -1.0f, 0.0f};
      q.tex = {k == 1 || k == 2 ? 1.0f : 0.0f, k >= 2 ? 1.0f : 0.0f, 0.0f, 1.0f};
      q.color = {0.8f, 0.1f, 0.1f, 1.0f};
      v.push_back(q);
    }
    return v;
  };
  ts::Batch shown;  // the picture on the left half
  shown.role = "picture";
  shown.texture = 0;
  shown.texEnv = GL_REPLACE;
  shown.vertices = quad(-1.0f, 0.0f);
  ts::Batch flat;  // a flat quad on the right half
  flat.role = "flat";
  flat.vertices = quad(0.0f, 1.0f);
  p.batches = {shown, flat};
  f.panels.push_back(p);
  ref::RenderOptions ro;
  ro.labels = false;
  const ts::Image truth = ref::Reference(f, ro).image();
  const std::string json = ts::sidecarJson(f, {});

  EXPECT_THROW(ref::readSidecar(json), ts::Error);  // strict: no generator
  ref::SidecarReadOptions lenient;
  lenient.unknownPictures = true;
  const ref::SidecarScene sc = ref::readSidecar(json, lenient);
  ASSERT_EQ(sc.unknownPictures, std::vector<int>{0});
  ref::VerifyOptions o;
  o.outputDir = std::string(TS_ORACLE_OUT_DIR) + "/unknown_pictures";  // the failures shown on purpose below
  o.render.labels = false;
  o.render.exemptTextures = sc.unknownPictures;
  ref::VerifyResult r = ref::verifyImage(truth, sc.frame, o);
  EXPECT_EQ(r.invalid, 0) << r.summary();
  EXPECT_GE(r.exemptBy[size_t(ref::Exempt::UnknownPicture)], 28 * 32) << r.summary();  // the left half, edges aside
  EXPECT_GE(r.checked, 28 * 32) << r.summary();                                        // the right half is checked
  // Without the exemption the placeholder's grey is not the picture: invalid.
  ref::VerifyOptions strict = o;
  strict.render.exemptTextures.clear();
  EXPECT_GT(ref::verifyImage(truth, sc.frame, strict).invalid, 28 * 32);
  // A wrong pixel in the picture is not seen; one in the flat half is.
  ts::Image wrong = truth;
  wrong.set(10, 16, {0, 0, 255, 255});
  EXPECT_EQ(ref::verifyImage(wrong, sc.frame, o).invalid, 0);
  wrong.set(50, 16, {0, 0, 255, 255});
  EXPECT_EQ(ref::verifyImage(wrong, sc.frame, o).invalid, 1);
  // Only an unknown generator is let through: a known one with bad params is
  // still refused, read leniently or not.
  ts::Frame bad = f;
  bad.textures[0].name = "checkerboard";
  bad.textures[0].params = {{"size", "64"}};
  EXPECT_THROW(ref::readSidecar(ts::sidecarJson(bad, {}), lenient), ts::Error);
  // A nested frame showing the picture is itself an unknown picture.
  ts::Frame outer;
  outer.width = 64, outer.height = 32;
  ts::TextureDesc nested;
  nested.name = "a_pass";
  nested.image = std::make_shared<ts::Image>(ref::Reference(f, ro).image());
  nested.renderedFrom = std::make_shared<const ts::Frame>(f);
  outer.addTexture(nested);
  outer.panels.push_back(p);
  outer.panels[0].batches = {shown};
  EXPECT_THROW(ref::readSidecar(ts::sidecarJson(outer, {})), ts::Error);
  EXPECT_EQ(ref::readSidecar(ts::sidecarJson(outer, {}), lenient).unknownPictures, std::vector<int>{0});
}

TEST(Sidecar, UnknownTextureNameIsAClearError) {
  ts::Frame f = sampleFrame();
  f.textures[0].name = "marble";
  try {
    ref::readSidecar(ts::sidecarJson(f, {}));
    FAIL() << "no error";
  } catch (const ts::Error& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("textures[0]"), std::string::npos) << m;
    EXPECT_NE(m.find("unknown texture generator 'marble'"), std::string::npos) << m;
  }
  EXPECT_THROW(ref::remakeTexture("checkerboard", {{"size", "64"}}), ts::Error);  // params missing
  EXPECT_THROW(ref::glEnumFromName("GL_NOT_A_MODE"), ts::Error);
  EXPECT_EQ(ref::glEnumFromName("0x2901"), GLenum(GL_REPEAT));
}
}  // namespace

// The alpha test, a batch's blend factors and unit 1 with
// GL_COMBINE survive the round trip; a batch without them writes none of
// their keys (so older sidecars stay byte-identical).
TEST(Sidecar, RoundTripOfTheMultitextureState) {
  ts::Frame f;
  f.width = f.height = 16;
  f.addTexture(ts::checkerboard(8, 2, {10, 20, 30, 255}, {200, 210, 220, 0}));
  f.addTexture(ts::checkerboard(4, 1, {90, 80, 70, 255}, {160, 150, 140, 255}));
  ts::Panel p;
  p.id = "p";
  p.viewport = {0, 0, 16, 16};
  ts::Batch b;
  b.role = "tree";
  b.texture = 0;
  b.vertices = {ts::Vertex{}, ts::Vertex{}, ts::Vertex{}};
  ts::Batch plain = b;
  b.alphaFunc = GL_GREATER, b.alphaRef = 0.5f;
  b.blend = true, b.blendSrc = GL_DST_COLOR, b.blendDst = GL_ZERO;
  b.texture1 = 1, b.texEnv1 = GL_COMBINE;
  b.combine1.rgb = GL_MODULATE_ADD_ATI;
  b.combine1.source[0] = GL_TEXTURE, b.combine1.source[1] = GL_PREVIOUS, b.combine1.source[2] = GL_PREVIOUS;
  b.combine1.operand[2] = GL_SRC_ALPHA;
  b.textureMatrix1 = glm::mat4(1.6f, 0.1f, 0, 0, -0.2f, 1.6f, 0, 0, 0, 0, 1, 0, 0.25f, -0.5f, 0, 1);
  b.coords1 = true, b.depthFunc = GL_LEQUAL, b.depthWrite = false;
  for (size_t k = 0; k < b.vertices.size(); ++k) b.vertices[k].tex1 = {0.25f * float(k), 0.5f, 0.0f, 1.0f + float(k)};
  p.batches = {b, plain};
  f.panels.push_back(p);
  const std::string text = ts::sidecarJson(f, {});
  const auto back = ref::readSidecar(text);  // kept: the batches below are references into it
  const ts::Batch& g = back.frame.panels.at(0).batches.at(0);
  EXPECT_EQ(g.alphaFunc, GLenum(GL_GREATER));
  EXPECT_FLOAT_EQ(g.alphaRef, 0.5f);
  EXPECT_EQ(g.blendSrc, GLenum(GL_DST_COLOR));
  EXPECT_EQ(g.blendDst, GLenum(GL_ZERO));
  EXPECT_EQ(g.texture1, 1);
  EXPECT_EQ(g.texEnv1, GLenum(GL_COMBINE));
  EXPECT_EQ(g.combine1.rgb, GLenum(GL_MODULATE_ADD_ATI));
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(g.combine1.source[k], b.combine1.source[k]) << k;
    EXPECT_EQ(g.combine1.operand[k], b.combine1.operand[k]) << k;
  }
  EXPECT_EQ(g.textureMatrix1, b.textureMatrix1);
  EXPECT_TRUE(g.coords1);
  EXPECT_EQ(g.depthFunc, GLenum(GL_LEQUAL));
  EXPECT_FALSE(g.depthWrite);
  for (size_t k = 0; k < b.vertices.size(); ++k) EXPECT_EQ(g.vertices.at(k).tex1, b.vertices[k].tex1) << k;
  const ts::Batch& h = back.frame.panels.at(0).batches.at(1);
  EXPECT_EQ(h.textureMatrix1, glm::mat4(1.0f));
  EXPECT_FALSE(h.coords1);
  EXPECT_EQ(h.depthFunc, GLenum(0));
  EXPECT_TRUE(h.depthWrite);
  EXPECT_FALSE(h.alphaTest());
  EXPECT_FALSE(h.blendFactors());
  EXPECT_EQ(h.texture1, -1);
  // Only the first batch names them ("blend_func" is also the fixed state's).
  auto count = [&](const std::string& key) {
    size_t n = 0;
    for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("\"alpha_test\""), 1u);
  EXPECT_EQ(count("\"unit1\""), 1u);
  EXPECT_EQ(count("\"texture_matrix\""), 1u);  // unit 1's, inside "unit1"
  EXPECT_EQ(count("\"depth_func\""), 2u);      // the batch's, and the fixed state's
  EXPECT_EQ(count("\"tex1\""), 3u);            // the first batch's vertices only
  EXPECT_EQ(count("\"blend_func\""), 2u);
}

// The DXT1 pictures' generator: every param is checked, and only
// GL's decode carries the rounding freedom.
TEST(Sidecar, Dxt1PictureGenerator) {
  using P = std::vector<std::pair<std::string, std::string>>;
  const P good = {{"picture", "checker"}, {"three_colour", "0"}, {"show", "decoded_gl"}, {"crop", "8,16,32,32"}};
  const ts::TextureDesc t = ref::remakeTexture("dxt1_picture", good, "");
  ASSERT_TRUE(t.image);
  EXPECT_EQ(t.image->width, 32);
  EXPECT_EQ(t.image->height, 32);
  EXPECT_EQ(t.texelSlack, 1.0f);
  P cpu = good;
  cpu[2].second = "decoded_cpu";
  EXPECT_EQ(ref::remakeTexture("dxt1_picture", cpu, "").texelSlack, 0.0f);
  for (const auto& [key, value] : P{{"picture", "marble"},
                                    {"three_colour", "2"},
                                    {"show", "decoded"},
                                    {"crop", "500,0,32,32"},
                                    {"crop", "0,0,0,4"},
                                    {"crop", "1,2,3"},
                                    {"crop", "1,2,3,4x"}}) {
    P p = good;
    for (auto& kv : p)
      if (kv.first == key) kv.second = value;
    EXPECT_THROW(ref::remakeTexture("dxt1_picture", p, ""), ts::Error) << key << " = " << value;
  }
  EXPECT_THROW(ref::remakeTexture("dxt1_picture", P{{"picture", "photo"}}, ""), ts::Error);  // params missing
}
