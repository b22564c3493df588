// tests/oracle/test_texgen.cpp — the CPU reference's glTexGen and clip plane
// (reference/geometry.cpp: texGenCoords, screenTriangle), against the
// OpenGL 2.1 specification's formulas worked out here by hand: OBJECT_LINEAR
// is plane · (x, y, z, 1); EYE_LINEAR is (plane · M⁻¹) · (M_v · (x, y, z, 1))
// with M the modelview when the plane was given and M_v the one drawing.
// And through a sidecar: the tex_gen and clip_plane members round-trip.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "common/core/frame.hpp"
#include "common/core/sidecar.hpp"
#include "reference/geometry.hpp"
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
}
}  // namespace
