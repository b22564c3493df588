// tests/oracle/test_texgen.cpp — the CPU reference's glTexGen and clip plane
// (reference/geometry.cpp: texGenCoords, screenTriangle), against the
// OpenGL 2.1 specification's formulas worked out here by hand: OBJECT_LINEAR
// is plane · (x, y, z, 1); EYE_LINEAR is (plane · M⁻¹) · (M_v · (x, y, z, 1))
// with M the modelview when the plane was given and M_v the one drawing.
// And through a sidecar: the tex_gen and clip_plane members round-trip.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <set>

#include "common/core/error.hpp"
#include "common/core/frame.hpp"
#include "common/core/sidecar.hpp"
#include "common/core/textures.hpp"
#include "reference/geometry.hpp"
#include "reference/reference.hpp"
#include "reference/sidecar_reader.hpp"

namespace {
ts::Batch texGenBatch(GLenum mode, glm::mat4 planeModelview) {
  ts::Batch b;
  b.texGen.mode = mode;
  b.texGen.coords = ts::TexGen::S | ts::TexGen::T | ts::TexGen::Q;
  b.texGen.planes[0] = {0.5f, 0, 0, 0.5f};
  b.texGen.planes[1] = {0, 0.25f, 0.5f, 0.125f};
  b.texGen.planes[3] = {0, 0, -1, 2};
  b.texGen.planeModelview = planeModelview;
  return b;
}

TEST(TexGen, ObjectLinearIsThePlaneAtTheObjectPosition) {
  ts::Panel p;
  p.modelview = glm::translate(glm::mat4(1.0f), {3, -1, -5});  // does not matter for OBJECT_LINEAR
  ts::Batch b = texGenBatch(GL_OBJECT_LINEAR, glm::mat4(1.0f));
  ts::Vertex v;
  v.pos = {0.4f, -0.2f, 0.6f};
  v.tex = {9, 9, 7, 9};
  glm::dvec4 t = ref::texGenCoords(p, b, v);
  EXPECT_NEAR(t.x, 0.5 * 0.4 + 0.5, 1e-7);
  EXPECT_NEAR(t.y, 0.25 * -0.2 + 0.5 * 0.6 + 0.125, 1e-7);
  EXPECT_EQ(t.z, 7.0);  // r not generated: glTexCoord's
  EXPECT_NEAR(t.w, -0.6 + 2, 1e-7);
}

TEST(TexGen, EyeLinearFollowsThePlanesModelviewNotTheObject) {
  // Planes given under M; drawn under the same M: the object's own planes.
  const glm::mat4 M = glm::rotate(glm::translate(glm::mat4(1.0f), {0, 0, -4}), 0.7f, glm::vec3(0, 1, 0));
  ts::Panel p;
  p.modelview = M;
  ts::Vertex v;
  v.pos = {0.3f, 0.1f, -0.7f};
  glm::dvec4 same = ref::texGenCoords(p, texGenBatch(GL_EYE_LINEAR, M), v);
  glm::dvec4 object = ref::texGenCoords(p, texGenBatch(GL_OBJECT_LINEAR, M), v);
  EXPECT_NEAR(same.x, object.x, 1e-6);
  EXPECT_NEAR(same.y, object.y, 1e-6);
  EXPECT_NEAR(same.w, object.w, 1e-6);
  // Planes given under the identity: fixed to the eye, s = 0.5 x_eye + 0.5.
  glm::dvec4 eye = ref::texGenCoords(p, texGenBatch(GL_EYE_LINEAR, glm::mat4(1.0f)), v);
  glm::vec4 e = M * glm::vec4(v.pos, 1.0f);
  EXPECT_NEAR(eye.x, 0.5 * e.x + 0.5, 1e-6);
  EXPECT_NEAR(eye.w, -e.z + 2, 1e-6);
}

TEST(TexGen, SidecarRoundTripsTexGenAndClipPlane) {
  ts::Frame f;
  f.width = 8, f.height = 8;
  ts::Panel p;
  p.id = "p";
  p.viewport = {0, 0, 8, 8};
  ts::Batch b = texGenBatch(GL_EYE_LINEAR, glm::translate(glm::mat4(1.0f), {1, 2, 3}));
  b.clip = true;
  b.clipPlane = {0, 0, -1, 2};
  b.clipModelview = glm::translate(glm::mat4(1.0f), {0, 0, -4});
  b.vertices.push_back({{0, 0, 0}});
  b.vertices.push_back({{1, 0, 0}});
  b.vertices.push_back({{0, 1, 0}});
  p.batches.push_back(b);
  f.panels.push_back(p);
  const std::string json = ts::sidecarJson(f, ts::SidecarInfo{});
  ref::SidecarScene got = ref::readSidecar(json);
  const ts::Batch& r = got.frame.panels.at(0).batches.at(0);
  EXPECT_EQ(r.texGen.mode, GLenum(GL_EYE_LINEAR));
  EXPECT_EQ(r.texGen.coords, b.texGen.coords);
  for (int k : {0, 1, 3}) EXPECT_EQ(r.texGen.planes[k], b.texGen.planes[k]) << k;
  EXPECT_EQ(r.texGen.planeModelview, b.texGen.planeModelview);
  EXPECT_TRUE(r.clip);
  EXPECT_EQ(r.clipPlane, b.clipPlane);
  EXPECT_EQ(r.clipModelview, b.clipModelview);
}
// The environment-mapping modes, by the GL 2.1 §2.11.4 formulas
// worked by hand.  A vertex at eye (1, 0, -1) with normal (0, 0, 1) (the
// modelview a translation, which leaves normals alone): u = (1, 0, -1)/√2,
// n·u = -1/√2, r = u + √2 n = (1/√2, 0, 1/√2).
TEST(TexGen, ReflectionAndSphereMapFromTheEyeSpaceNormal) {
  ts::Panel p;
  p.modelview = glm::translate(glm::mat4(1.0f), {0, 0, -1});
  ts::Batch b;
  b.texGen.coords = ts::TexGen::S | ts::TexGen::T | ts::TexGen::R;
  ts::Vertex v;
  v.pos = {1, 0, 0};
  v.normal = {0, 0, 1};
  v.tex = {9, 9, 9, 1};
  const double h = std::sqrt(0.5);
  b.texGen.mode = GL_REFLECTION_MAP;
  glm::dvec4 t = ref::texGenCoords(p, b, v);
  EXPECT_NEAR(t.x, h, 1e-7);
  EXPECT_NEAR(t.y, 0.0, 1e-7);
  EXPECT_NEAR(t.z, h, 1e-7);
  EXPECT_EQ(t.w, 1.0);
  b.texGen.mode = GL_NORMAL_MAP;
  t = ref::texGenCoords(p, b, v);
  EXPECT_NEAR(t.x, 0.0, 1e-7);
  EXPECT_NEAR(t.z, 1.0, 1e-7);
  // Sphere map: m = 2 sqrt(r_x² + r_y² + (r_z + 1)²), s = r_x/m + 1/2; r untouched.
  b.texGen.mode = GL_SPHERE_MAP;
  b.texGen.coords = ts::TexGen::S | ts::TexGen::T;
  t = ref::texGenCoords(p, b, v);
  const double m = 2.0 * std::sqrt(0.5 + (h + 1) * (h + 1));
  EXPECT_NEAR(t.x, h / m + 0.5, 1e-7);
  EXPECT_NEAR(t.y, 0.5, 1e-7);
  EXPECT_EQ(t.z, 9.0);
  // A normal of length 2 is used as given (GL_NORMALIZE off): n·u = -√2,
  // r = u + 2√2 (0, 0, 2) = (1/√2, 0, -1/√2 + 4√2).
  v.normal = {0, 0, 2};
  b.texGen.mode = GL_REFLECTION_MAP;
  b.texGen.coords = ts::TexGen::S | ts::TexGen::T | ts::TexGen::R;
  t = ref::texGenCoords(p, b, v);
  EXPECT_NEAR(t.z, -h + 8 * h, 1e-7);
}

// The cube-map face table (GL 2.1 table 3.21) at one direction per face.
TEST(TexGen, CubeMapFaceAndCoordinates) {
  struct Case {
    glm::dvec3 r;
    int face;
    double s, t;
  } cases[] = {{{2, 0.4, -1}, 0, (0.5 + 1) / 2, (-0.2 + 1) / 2},  {{-2, 0.4, -1}, 1, (-0.5 + 1) / 2, (-0.2 + 1) / 2},
               {{0.5, 4, 1}, 2, (0.125 + 1) / 2, (0.25 + 1) / 2}, {{0.5, -4, 1}, 3, (0.125 + 1) / 2, (-0.25 + 1) / 2},
               {{0.5, -1, 2}, 4, (0.25 + 1) / 2, (0.5 + 1) / 2},  {{0.5, -1, -2}, 5, (-0.25 + 1) / 2, (0.5 + 1) / 2}};
  for (const Case& c : cases) {
    int alt = 0;
    EXPECT_EQ(ref::cubeFace(c.r, &alt), c.face);
    EXPECT_EQ(alt, -1);
    double s, t;
    ref::cubeFaceCoord(c.face, c.r, &s, &t);
    EXPECT_NEAR(s, c.s, 1e-12) << c.face;
    EXPECT_NEAR(t, c.t, 1e-12) << c.face;
  }
  int alt = -1;
  EXPECT_EQ(ref::cubeFace({1, 1 - 1e-6, 0.2}, &alt), 0);
  EXPECT_EQ(alt, 2);  // a tie within 1e-4: either face is legal
}

// Sphere-map texgen, normals and a cube map through a sidecar; and the
// sidecar of a batch without them carries none of the new keys.
TEST(TexGen, SidecarRoundTripsEnvironmentTexGenAndCubeMaps) {
  ts::Frame f;
  f.width = 8, f.height = 8;
  ts::TextureDesc cube = ts::gradientTexture(4, 24, false);
  cube.cube = true;
  f.addTexture(cube);
  ts::Panel p;
  p.id = "p";
  p.viewport = {0, 0, 8, 8};
  ts::Batch b;
  b.texture = 0;
  b.texGen.mode = GL_REFLECTION_MAP;
  b.texGen.coords = ts::TexGen::S | ts::TexGen::T | ts::TexGen::R;
  for (int k = 0; k < 3; ++k) {
    ts::Vertex v;
    v.pos = {float(k == 1), float(k == 2), 0};
    v.normal = {0.25f * float(k), 0.5f, 1};
    b.vertices.push_back(v);
  }
  p.batches.push_back(b);
  ts::Batch plain = b;
  plain.texGen = ts::TexGen{};
  p.batches.push_back(plain);
  f.panels.push_back(p);
  const std::string json = ts::sidecarJson(f, ts::SidecarInfo{});
  EXPECT_NE(json.find("\"cube\": true"), std::string::npos);
  EXPECT_NE(json.find("\"GL_REFLECTION_MAP\""), std::string::npos);
  ref::SidecarScene got = ref::readSidecar(json);
  ASSERT_EQ(got.frame.textures.size(), 1u);
  EXPECT_TRUE(got.frame.textures[0].cube);
  const ts::Batch& r = got.frame.panels.at(0).batches.at(0);
  EXPECT_EQ(r.texGen.mode, GLenum(GL_REFLECTION_MAP));
  EXPECT_EQ(r.texGen.coords, b.texGen.coords);
  for (size_t k = 0; k < 3; ++k) EXPECT_EQ(r.vertices[k].normal, b.vertices[k].normal) << k;
  // The second batch: no texgen, so no normals written (they read back as GL's default).
  const ts::Batch& q = got.frame.panels.at(0).batches.at(1);
  EXPECT_FALSE(q.texGen.on());
  EXPECT_EQ(q.vertices[1].normal, glm::vec3(0, 0, 1));
  size_t normals = 0;
  for (size_t at = json.find("\"normal\""); at != std::string::npos; at = json.find("\"normal\"", at + 1)) ++normals;
  EXPECT_EQ(normals, 3u);
  // Sphere mapping makes s and t only: a sidecar asking it for r is refused.
  std::string bad = json;
  bad.replace(bad.find("\"GL_REFLECTION_MAP\""), 19, "\"GL_SPHERE_MAP\"");
  EXPECT_THROW(ref::readSidecar(bad), ts::Error);
}
// A 3D texture through a sidecar: depth, a slice's height and wrap_r come
// back (the reader refused depth before); a depth that does not divide the
// remade image is refused.
TEST(TexGen, SidecarRoundTrips3DTextures) {
  ts::Frame f;
  f.width = f.height = 8;
  ts::TextureDesc t = ts::gradientTexture(4, 16, false);
  t.depth = 4;
  t.wrapR = GL_MIRRORED_REPEAT;
  f.addTexture(t);
  const std::string json = ts::sidecarJson(f, ts::SidecarInfo{});
  ref::SidecarScene got = ref::readSidecar(json);
  ASSERT_EQ(got.frame.textures.size(), 1u);
  EXPECT_EQ(got.frame.textures[0].depth, 4);
  EXPECT_EQ(got.frame.textures[0].wrapR, GLenum(GL_MIRRORED_REPEAT));
  std::string bad = json;
  bad.replace(bad.find("\"depth\": 4"), 11, "\"depth\": 3");
  EXPECT_THROW(ref::readSidecar(bad), ts::Error);
}
// A nested frame (TextureDesc::renderedFrom) through a sidecar: the inner
// frame (a sphere-mapped triangle on a generated checkerboard) comes back
// with its texgen, normals and texture, and the reference recomputes the
// same picture from the file as from the frame itself.
TEST(TexGen, SidecarRoundTripsNestedFrames) {
  auto inner = std::make_shared<ts::Frame>();
  inner->width = 24, inner->height = 16;
  inner->addTexture(ts::checkerboard(16, 4, {200, 40, 40, 255}, {30, 30, 200, 255}));
  ts::Panel ip;
  ip.id = "inner";
  ip.viewport = {0, 0, 24, 16};
  ip.modelview = glm::translate(glm::mat4(1.0f), {0, 0, -0.5f});
  ts::Batch b;
  b.texture = 0;
  b.texGen.mode = GL_SPHERE_MAP;
  b.texGen.coords = ts::TexGen::S | ts::TexGen::T;
  const glm::vec3 corners[3] = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  for (const glm::vec3& c : corners) {
    ts::Vertex v;
    v.pos = c;
    v.normal = glm::normalize(glm::vec3(c.x, c.y, 2.0f));
    b.vertices.push_back(v);
  }
  ip.batches.push_back(b);
  inner->panels.push_back(ip);
  ts::Frame f;
  f.width = f.height = 32;
  ts::TextureDesc t;
  t.name = "a_render";
  t.image = std::make_shared<ts::Image>(ref::Reference(*inner).image());
  t.renderedFrom = inner;
  f.addTexture(t);
  ts::Panel p;
  p.id = "outer";
  p.viewport = {0, 0, 32, 32};
  p.projection = glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f);
  ts::Batch q;
  q.texture = 0;
  for (glm::vec2 c :
       {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
    ts::Vertex v;
    v.pos = {c, 0};
    v.tex = {c.x, 1 - c.y, 0, 1};
    q.vertices.push_back(v);
  }
  p.batches.push_back(q);
  f.panels.push_back(p);
  const std::string json = ts::sidecarJson(f, ts::SidecarInfo{});
  EXPECT_NE(json.find("\"rendered_from\""), std::string::npos);
  ref::SidecarScene got = ref::readSidecar(json);
  ASSERT_EQ(got.frame.textures.size(), 1u);
  ASSERT_TRUE(got.frame.textures[0].renderedFrom);
  const ts::Frame& back = *got.frame.textures[0].renderedFrom;
  EXPECT_EQ(back.width, 24);
  EXPECT_EQ(back.panels.at(0).batches.at(0).texGen.mode, GLenum(GL_SPHERE_MAP));
  EXPECT_EQ(back.panels.at(0).batches.at(0).vertices.at(2).normal, b.vertices[2].normal);
  const ts::Image fromFile = ref::Reference(got.frame).image(), fromFrame = ref::Reference(f).image();
  EXPECT_EQ(fromFile.pixels, fromFrame.pixels);
  // The inner picture is not flat: the triangle shows both checks.
  std::set<uint32_t> colours;
  for (size_t k = 0; k + 3 < fromFrame.pixels.size(); k += 4)
    colours.insert(uint32_t(fromFrame.pixels[k]) << 16 | uint32_t(fromFrame.pixels[k + 1]) << 8 |
                   fromFrame.pixels[k + 2]);
  EXPECT_GE(colours.size(), 3u);
  // A nested frame whose size disagrees with the texture's is refused.
  std::string bad = json;
  bad.replace(bad.find("\"width\": 24"), 11, "\"width\": 25");
  EXPECT_THROW(ref::readSidecar(bad), ts::Error);
}
}  // namespace
