// The oracle against OpenGL on glTexGen's environment-mapping modes: a
// sphere of glNormal3f + glVertex3f under GL_SPHERE_MAP texgen on a
// 2D texture, and under GL_REFLECTION_MAP / GL_NORMAL_MAP texgen on a cube
// map (six faces of distinct texels, GL_NEAREST and GL_LINEAR), with a
// texture matrix turning eye space.  The CPU reference computes (s, t[, r])
// per vertex by the specification's formulas (reference/geometry.cpp:
// envTexGen), interpolates them, and for the cube picks the face and its
// (s, t) per fragment (reference.cpp: cubeFace, cubeFaceCoord).  Every GL
// pixel must lie in the reference's legal range (tolerances from the
// channel bits, verify.hpp) — and a description that is wrong in one
// respect (normals of another length, two cube faces swapped, the texture matrix
// left out) must make many pixels invalid.
#include <gtest/gtest.h>

#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "common/core/env_maps.hpp"
#include "common/core/mesh.hpp"
#include "oracle_support.hpp"
#include "reference/reference.hpp"
#include "tests/support/scene_test.hpp"

namespace {
// A sphere of radius 1 (24 x 12 quads), each vertex with its normal, in a
// panel looking at it from 3 units away, turned so no axis faces the eye.
ts::Frame sphereFrame(int texture, const ts::TextureDesc& t, GLenum mode, unsigned coords, float normalScale = 1.0f) {
  ts::Frame f;
  f.width = f.height = 200;
  f.clearColor = {0.1f, 0.1f, 0.1f, 1.0f};
  f.textures.push_back(t);
  ts::Panel p;
  p.id = "p";
  p.viewport = {0, 0, 200, 200};
  p.projection = glm::perspective(glm::radians(45.0f), 1.0f, 0.5f, 10.0f);
  p.modelview = glm::rotate(glm::rotate(glm::translate(glm::mat4(1.0f), {0, 0, -3.2f}), 0.4f, glm::vec3(1, 0, 0)), 0.7f,
                            glm::vec3(0, 1, 0));
  p.depthTest = true;
  ts::Batch b;
  b.role = "surface";
  b.texture = texture;
  b.texGen.mode = mode;
  b.texGen.coords = coords;
  auto noTex = [](int, int) { return glm::dvec2(0.0); };
  const ts::Mesh m = ts::parametricGrid(
      24, 12, true, false, [](int i, int j) { return ts::spherePoint(1.0, 24, 12, i, j); }, noTex);
  for (unsigned i : m.triangles()) {
    ts::Vertex v;
    v.pos = glm::vec3(m.points[i].pos);
    v.normal = normalScale * glm::vec3(m.points[i].normal);
    b.vertices.push_back(v);
  }
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}

// Six faces of `n` x `n` texels, each face its own hue, each texel distinct.
ts::TextureDesc cubeTexture(int n, GLenum filter, bool swapX = false) {
  auto img = std::make_shared<ts::Image>(n, 6 * n);
  const uint8_t hue[6][3] = {{230, 40, 40},  {40, 200, 60},  {50, 70, 230},
                             {230, 210, 40}, {40, 220, 220}, {220, 50, 220}};
  for (int face = 0; face < 6; ++face) {
    const int src = swapX && face < 2 ? 1 - face : face;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        img->set(i, face * n + j,
                 {uint8_t(hue[src][0] * (4 + (i % 4)) / 7), uint8_t(hue[src][1] * (4 + (j % 4)) / 7),
                  uint8_t(hue[src][2] * (3 + ((i + j) % 5)) / 7), 255});
  }
  ts::TextureDesc t;
  t.name = std::string("oracle_cube") + (swapX ? "_swapped" : "");  // not a sidecar generator: GL tests only
  t.params = {{"size", std::to_string(n)}};
  t.image = img;
  t.cube = true;
  t.minFilter = t.magFilter = filter;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  return t;
}

TEST(GLEnvironmentTexGen, SphereMapOnA2DTexture) {
  for (GLenum filter : {GL_NEAREST, GL_LINEAR})
    for (float scale : {1.0f, 0.8f}) {  // 0.8: GL_NORMALIZE is off, GL uses the normal as given
      const std::string n = std::string("sphere_map_") + (filter == GL_NEAREST ? "nearest" : "linear") +
                            (scale == 1.0f ? "" : "_short_normals");
      SCOPED_TRACE(n);
      ts::TextureDesc t = oracle::colourful(16);
      t.minFilter = t.magFilter = filter;
      t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
      const ts::Frame f = sphereFrame(0, t, GL_SPHERE_MAP, ts::TexGen::S | ts::TexGen::T, scale);
      const ts::Image img = oracle::render(f);
      ref::VerifyResult r = ref::verifyImage(img, f, oracle::options(n, "envmap"));
      std::printf("%s\n", r.summary().c_str());
      EXPECT_EQ(r.invalid, 0) << r.summary();
      EXPECT_GT(r.textured, 200 * 200 / 4) << r.summary();
      // The other normal length in the description: r = u - 2 (n.u) n changes
      // (flipping n would not: r is even in n), and the check must see it.
      const ts::Frame wrong = sphereFrame(0, t, GL_SPHERE_MAP, ts::TexGen::S | ts::TexGen::T,
                                          scale == 1.0f ? 0.8f : 1.0f);
      ref::VerifyResult bad = ref::verifyImage(img, wrong, oracle::options(n + "_other_length", "envmap_negative"));
      EXPECT_GT(bad.invalid, bad.textured / 4) << bad.summary();
    }
}

TEST(GLEnvironmentTexGen, ReflectionMapOnACubeMap) {
  for (GLenum filter : {GL_NEAREST, GL_LINEAR}) {
    const std::string n = std::string("reflection_map_") + (filter == GL_NEAREST ? "nearest" : "linear");
    SCOPED_TRACE(n);
    const unsigned str = ts::TexGen::S | ts::TexGen::T | ts::TexGen::R;
    ts::Frame f = sphereFrame(0, cubeTexture(8, filter), GL_REFLECTION_MAP, str);
    // The texture matrix turns the eye-space r (as EnvGL turns it into the world's).
    f.panels[0].batches[0].textureMatrix = glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(0.3f, 1.0f, 0.2f));
    const ts::Image img = oracle::render(f);
    ref::VerifyResult r = ref::verifyImage(img, f, oracle::options(n, "envmap"));
    std::printf("%s\n", r.summary().c_str());
    EXPECT_EQ(r.invalid, 0) << r.summary();
    EXPECT_GT(r.textured, 200 * 200 / 4) << r.summary();
    // +X and -X swapped in the description: the pixels that read them fail.
    ts::Frame swapped = f;
    swapped.textures[0] = cubeTexture(8, filter, true);
    ref::VerifyResult bad = ref::verifyImage(img, swapped, oracle::options(n + "_swapped", "envmap_negative"));
    std::printf("%s\n", bad.summary().c_str());
    EXPECT_GT(bad.invalid, 500) << bad.summary();
    // Without the texture matrix.
    ts::Frame plain = f;
    plain.panels[0].batches[0].textureMatrix = glm::mat4(1.0f);
    ref::VerifyResult bad2 = ref::verifyImage(img, plain, oracle::options(n + "_no_matrix", "envmap_negative"));
    EXPECT_GT(bad2.invalid, bad2.textured / 4) << bad2.summary();
  }
}

TEST(GLEnvironmentTexGen, NormalMapOnACubeMap) {
  const ts::Frame f = sphereFrame(0, cubeTexture(8, GL_NEAREST), GL_NORMAL_MAP,
                                  ts::TexGen::S | ts::TexGen::T | ts::TexGen::R);
  const ts::Image img = oracle::render(f);
  ref::VerifyResult r = ref::verifyImage(img, f, oracle::options("normal_map", "envmap"));
  std::printf("%s\n", r.summary().c_str());
  EXPECT_EQ(r.invalid, 0) << r.summary();
  EXPECT_GT(r.textured, 200 * 200 / 4) << r.summary();
  const ts::Frame wrong = sphereFrame(0, cubeTexture(8, GL_NEAREST), GL_REFLECTION_MAP,
                                      ts::TexGen::S | ts::TexGen::T | ts::TexGen::R);
  ref::VerifyResult bad = ref::verifyImage(img, wrong, oracle::options("normal_map_as_reflection", "envmap_negative"));
  EXPECT_GT(bad.invalid, bad.textured / 4) << bad.summary();
}
}  // namespace

// 3D textures (TextureDesc::depth > 1, GL_TEXTURE_3D): a square whose
// (s, t, r) run across the volume and beyond it, r along a diagonal, so
// every pixel's texel (GL_NEAREST) or trilinear blend (GL_LINEAR) depends
// on r; wrapR REPEAT and CLAMP_TO_EDGE.  The reference samples the slices
// (reference/volume.hpp); describing the render with r shifted by one slice
// must fail.
namespace {
ts::TextureDesc volumeTexture(int n, GLenum filter, GLenum wrapR) {
  auto img = std::make_shared<ts::Image>(n, n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        img->set(i, k * n + j,
                 {uint8_t(30 + (i * 53 + k * 29) % 200), uint8_t(20 + (j * 61 + k * 17) % 220),
                  uint8_t(25 + (k * 71 + i * 11 + j * 5) % 210), 255});
  ts::TextureDesc t;
  t.name = "oracle_volume";  // not a sidecar generator: GL tests only
  t.params = {{"size", std::to_string(n)}};
  t.image = img;
  t.depth = n;
  t.minFilter = t.magFilter = filter;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  t.wrapR = wrapR;
  return t;
}
ts::Frame volumeFrame(const ts::TextureDesc& t, float rShift = 0.0f) {
  ts::Frame f;
  f.width = f.height = 160;
  f.addTexture(t);
  ts::Panel p = oracle::unitPanel(160, 160);
  ts::Batch b = oracle::quad({0, 0}, {1, 1}, {-0.1f, -0.1f}, {1.1f, 1.1f}, 0);
  for (ts::Vertex& v : b.vertices) v.tex.z = -0.3f + 1.6f * 0.5f * (v.pos.x + v.pos.y) + rShift;
  p.batches.push_back(b);
  f.panels.push_back(p);
  return f;
}
}  // namespace

TEST(GLVolumeTexture, NearestAndTrilinearInR) {
  for (GLenum filter : {GL_NEAREST, GL_LINEAR})
    for (GLenum wrapR : {GL_REPEAT, GL_CLAMP_TO_EDGE}) {
      const std::string n = std::string("volume_") + (filter == GL_NEAREST ? "nearest" : "linear") +
                            (wrapR == GL_REPEAT ? "_repeat" : "_clamp");
      SCOPED_TRACE(n);
      const ts::Frame f = volumeFrame(volumeTexture(8, filter, wrapR));
      const ts::Image img = oracle::render(f);
      ref::VerifyResult r = ref::verifyImage(img, f, oracle::options(n, "volume"));
      std::printf("%s\n", r.summary().c_str());
      EXPECT_EQ(r.invalid, 0) << r.summary();
      EXPECT_GT(r.textured, 160 * 160 * 9 / 10) << r.summary();
      const ts::Frame shifted = volumeFrame(volumeTexture(8, filter, wrapR), 1.0f / 8);
      ref::VerifyResult bad = ref::verifyImage(img, shifted, oracle::options(n + "_shifted", "volume_negative"));
      EXPECT_GT(bad.invalid, bad.checked / 4) << bad.summary();
    }
}

// Nested frames (TextureDesc::renderedFrom): a panel showing, magnified
// with GL_LINEAR, the picture GL drew of another Frame (the sphere under
// GL_SPHERE_MAP texgen).  The reference recomputes that frame first and
// samples its picture; the texels on its triangles' edges, where GL may
// differ legally, make the outer pixels that read them exempt.  Describing
// the inner frame wrongly (normals of another length) must fail.
namespace {
ts::Frame nestedFrame(const ts::Image& innerPicture, const ts::Frame& inner) {
  ts::Frame f;
  f.width = f.height = 220;
  ts::TextureDesc t;
  t.name = "oracle_nested_render";
  t.image = std::make_shared<ts::Image>(innerPicture);
  t.renderedFrom = std::make_shared<const ts::Frame>(inner);
  t.minFilter = t.magFilter = GL_LINEAR;
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  f.addTexture(t);
  ts::Panel p = oracle::unitPanel(220, 220);
  p.batches.push_back(oracle::quad({0.05f, 0.05f}, {0.95f, 0.95f}, {0, 1}, {1, 0}, 0));  // image row 0 at the top
  f.panels.push_back(p);
  return f;
}
}  // namespace

// The sphere's half facing the eye: with its back half too, every pixel
// near an edge between two front triangles could legally show the back
// (the reference's depth test keeps the clear colour's candidate there,
// and the back is nearer than that), and the nested picture would be
// unknown along every edge.
ts::Frame frontHalf(ts::Frame f) {
  ts::Batch& b = f.panels[0].batches[0];
  std::vector<ts::Vertex> kept;
  const glm::mat4 mv = f.panels[0].modelview;
  for (size_t i = 0; i + 2 < b.vertices.size(); i += 3) {
    const glm::vec3 c = (b.vertices[i].pos + b.vertices[i + 1].pos + b.vertices[i + 2].pos) / 3.0f;
    const glm::vec3 e = glm::vec3(mv * glm::vec4(c, 1.0f)),
                    n = glm::mat3(mv) * c;  // a sphere: the normal is the position
    if (glm::dot(e, n) < 0) kept.insert(kept.end(), b.vertices.begin() + long(i), b.vertices.begin() + long(i) + 3);
  }
  b.vertices = kept;
  return f;
}

TEST(GLNestedFrame, APanelShowingATexgenRender) {
  ts::TextureDesc t = oracle::colourful(16);
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  ts::Frame inner = frontHalf(sphereFrame(0, t, GL_SPHERE_MAP, ts::TexGen::S | ts::TexGen::T));
  inner.width = inner.height = 120;
  inner.panels[0].viewport = {0, 0, 120, 120};
  const ts::Image innerPicture = oracle::render(inner);
  const ts::Frame f = nestedFrame(innerPicture, inner);
  const ts::Image img = oracle::render(f);
  ref::VerifyResult r = ref::verifyImage(img, f, oracle::options("nested_sphere_map", "envmap"));
  std::printf("%s\n", r.summary().c_str());
  EXPECT_EQ(r.invalid, 0) << r.summary();
  EXPECT_GT(r.textured, 220 * 220 / 2) << r.summary();
  ts::Frame wrongInner = frontHalf(sphereFrame(0, t, GL_SPHERE_MAP, ts::TexGen::S | ts::TexGen::T, 0.8f));
  wrongInner.width = wrongInner.height = 120;
  wrongInner.panels[0].viewport = {0, 0, 120, 120};
  ref::VerifyResult bad = ref::verifyImage(img, nestedFrame(innerPicture, wrongInner),
                                           oracle::options("nested_wrong_inner", "envmap_negative"));
  EXPECT_GT(bad.invalid, bad.textured / 4) << bad.summary();
}

// A cube map rendered from a frame (dynamic_reflection's mirror): the
// mirror's picture is a nested frame whose cube map is itself the render of
// a nested frame, the cube pass, its six faces stacked.  The reference
// recomputes the faces, carries their legal ranges through the cube-map
// lookup (texels on the faces' edges unknown), and GL's mirror is legal for
// it; the cube pass told with its +X and -X faces' cameras swapped fails.
TEST(GLNestedFrame, ACubeMapRenderedFromAFrame) {
  ts::test::Demo d("dynamic_reflection", {});
  d.measure();
  const ts::Frame f = d.frame(1200, 420);
  int checked = 0;
  for (const ts::TextureDesc& t : f.textures) {
    if (!t.renderedFrom || t.renderedFrom->textures.empty() || !t.renderedFrom->textures[0].cube) continue;
    ASSERT_TRUE(t.renderedFrom->textures[0].renderedFrom) << "the cube map is the render of the cube pass";
    const std::string n = "nested_cube_" + std::to_string(checked);
    ref::VerifyResult r = ref::verifyImage(*t.image, *t.renderedFrom, oracle::options(n, "envmap"));
    std::printf("%s\n", r.summary().c_str());
    EXPECT_EQ(r.invalid, 0) << r.summary();
    EXPECT_GT(r.textured, r.checked / 4) << r.summary();
    ts::Frame wrong = *t.renderedFrom;
    ts::Frame pass = *wrong.textures[0].renderedFrom;
    std::swap(pass.panels[0].modelview, pass.panels[1].modelview);
    wrong.textures[0].renderedFrom = std::make_shared<const ts::Frame>(pass);
    ref::VerifyResult bad = ref::verifyImage(*t.image, wrong, oracle::options(n + "_swapped", "envmap_negative"));
    std::printf("%s\n", bad.summary().c_str());
    EXPECT_GT(bad.invalid, 500) << bad.summary();
    ++checked;
  }
  EXPECT_EQ(checked, 2) << "the dynamic and the static mirror";
}

// The environment-mapping figures' texgen pictures: the compare
// view's cube-map and sphere-map panels are nested frames (GL_REFLECTION_MAP
// with the texture matrix on an "environment_map" cube, GL_SPHERE_MAP on the
// 2D map), and the picture GL drew of each is a legal result of the frame the
// reference recomputes — most of its pixels checked, none invalid.  The same
// picture against the frame told with another mode (GL_NORMAL_MAP for the
// cube, the map made for an eye turned 40 degrees for the sphere) fails.
TEST(GLNestedFrame, TheEnvironmentMappingFiguresTexgenPictures) {
  ts::test::Demo d("environment_mapping", {"--view", "compare", "--object", "torus", "--eval", "vertex", "--tilt", "30",
                                           "--yaw", "25", "--render", "160"});
  d.measure();
  const ts::Frame f = d.frame(900, 300);
  int checkedPasses = 0;
  for (const ts::TextureDesc& t : f.textures) {
    if (!t.renderedFrom) continue;
    const ts::Batch& b = t.renderedFrom->panels.at(0).batches.at(0);
    if (!b.program.empty()) continue;  // the GLSL passes: exempt, not checked here
    ASSERT_TRUE(b.texGen.mode == GL_REFLECTION_MAP || b.texGen.mode == GL_SPHERE_MAP);
    const std::string n = b.texGen.mode == GL_REFLECTION_MAP ? "env_figure_cube_texgen" : "env_figure_sphere_texgen";
    ref::VerifyResult r = ref::verifyImage(*t.image, *t.renderedFrom, oracle::options(n, "envmap"));
    std::printf("%s\n", r.summary().c_str());
    EXPECT_EQ(r.invalid, 0) << r.summary();
    EXPECT_GT(r.textured, 160 * 160 / 4) << r.summary();  // the torus covers about half the picture
    ts::Frame wrong = *t.renderedFrom;
    ts::Batch& wb = wrong.panels[0].batches[0];
    if (wb.texGen.mode == GL_REFLECTION_MAP) {
      wb.texGen.mode = GL_NORMAL_MAP;
    } else {
      const glm::dmat3 turned(glm::rotate(glm::mat4(1.0f), glm::radians(40.0f), glm::vec3(0, 1, 0)));
      wrong.textures[0] = ts::envmaps::environmentMap(ts::envmaps::kSphere, 64, turned);
    }
    ref::VerifyResult bad = ref::verifyImage(*t.image, wrong, oracle::options(n + "_wrong", "envmap_negative"));
    std::printf("%s\n", bad.summary().c_str());
    EXPECT_GT(bad.invalid, bad.textured / 4) << bad.summary();
    ++checkedPasses;
  }
  EXPECT_EQ(checkedPasses, 2) << "the cube-map and sphere-map texgen pictures";
}
