// demos/projectors/projectors_pose.hpp — where things stand in demos/projectors:
// the rotation that shows a model direction face-on and the ortho panel around
// the unit object, the object's poses as it moves, and the slide projector's
// set-up (its lens and place, the camera's, and the stage it lights).  Both
// the measurements (projectors_measure.hpp) and the pictures
// (projectors_views.hpp) draw from here, so the pictures show what is measured.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>

#include "common/core/frame.hpp"
#include "projectors_gl.hpp"
#include "projectors_math.hpp"

namespace proj {
// A rotation taking model direction `d` to the viewer (+z), `up` kept upright.
inline glm::mat4 faceOn(glm::dvec3 d, glm::dvec3 up = {0, 1, 0}) {
  d = glm::normalize(d);
  if (std::abs(glm::dot(d, glm::normalize(up))) > 0.99) up = {0, 0, d.z > 0 ? -1 : 1};
  if (std::abs(glm::dot(d, glm::normalize(up))) > 0.99) up = {1, 0, 0};
  glm::dvec3 x = glm::normalize(glm::cross(up, d)), y = glm::cross(d, x);
  glm::dmat4 r(1.0);
  for (int c = 0; c < 3; ++c) {
    r[c][0] = x[c];
    r[c][1] = y[c];
    r[c][2] = d[c];
  }
  return glm::mat4(r);
}
constexpr float kHalf = 1.05f;  // the ortho views show [-1.05, 1.05]²
inline ts::Panel orthoPanel(const std::string& id, ts::Rect vp, glm::mat4 modelview) {
  ts::Panel p;
  p.id = id;
  p.viewport = vp;
  p.projection = glm::ortho(-kHalf, kHalf, -kHalf, kHalf, -3.0f, 3.0f);
  p.modelview = modelview;
  p.depthTest = true;
  return p;
}
// The object's poses as it moves (the swim measurement, the window's m / M):
// pose 0 is where the eye planes are given.
constexpr int kPoses = 8;
inline glm::mat4 pose(int k) {
  return glm::translate(glm::mat4(1.0f), {0.04f * k, -0.03f * k, 0.0f}) *
         glm::rotate(glm::mat4(1.0f), glm::radians(5.0f * k), {0.3f, 1.0f, 0.0f}) *
         glm::scale(glm::mat4(1.0f), glm::vec3(0.8f));
}
// The slide projector's set-up: a floor (y = 0) and a back wall (z = -3) seen
// from the front; the projector at (0, 1.5, -1) aims forward and down.  Behind
// it q < 0, and the wall sits in the mirrored cone: the back projection.
struct Slide {
  glm::dmat4 projL, viewL, camP, camV;
};
inline Slide slideSetup() {
  return {glm::perspective(glm::radians(40.0), 1.0, 0.5, 20.0),
          glm::lookAt(glm::dvec3(0, 1.5, -1), glm::dvec3(0, 0, 2.5), glm::dvec3(0, 1, 0)),
          glm::perspective(glm::radians(60.0), 1.0, 0.5, 30.0),
          glm::lookAt(glm::dvec3(0, 6, 6), glm::dvec3(0, 0.8, -1), glm::dvec3(0, 1, 0))};
}
// The floor and the wall as one tessellated batch (world = object coordinates).
inline Shape slideStage() {
  Shape s;
  auto quad = [&](glm::dvec3 o, glm::dvec3 u, glm::dvec3 v, int n) {
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        glm::dvec3 a = o + u * (double(i) / n) + v * (double(j) / n), b = a + u / double(n), c = b + v / double(n),
                   d = a + v / double(n);
        for (glm::dvec3 p : {a, b, c, a, c, d}) s.push_back({p, glm::cross(u, v), {0, 0}});
      }
  };
  quad({-4, 0, 4}, {8, 0, 0}, {0, 0, -7}, 16);  // floor, z from 4 to -3
  quad({-4, 0, -3}, {8, 0, 0}, {0, 4, 0}, 8);   // back wall, facing +z
  return s;
}
inline ts::Batch slideBatch(const Slide& sl, int texture, bool clip) {
  auto planes = slidePlanes(sl.projL, sl.viewL);
  ts::TexGen g;
  g.mode = GL_EYE_LINEAR;
  g.coords = ts::TexGen::S | ts::TexGen::T | ts::TexGen::R | ts::TexGen::Q;
  for (int k = 0; k < 4; ++k) g.planes[k] = glm::vec4(planes[size_t(k)]);
  g.planeModelview = glm::mat4(sl.camV);  // given with the camera's view in force: world-fixed planes
  ts::Batch b = texGenBatch(slideStage(), g, texture);
  b.role = "stage";
  if (clip) {  // the fix: keep q >= 0 (the Q plane, world = object coordinates here)
    b.clip = true;
    b.clipPlane = glm::vec4(planes[3]);
    b.clipModelview = glm::mat4(
        sl.camV);  // given under the camera's view, the stage panel's modelview: a world-fixed plane
  }
  return b;
}
}  // namespace proj
