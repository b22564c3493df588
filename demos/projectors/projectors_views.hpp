// demos/projectors/projectors_views.hpp — the pictures of demos/projectors: an
// object in perspective with its coordinates made one of three ways, the
// texture-space panel of the texels it uses, the slide projector's stage.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "projectors_gl.hpp"
#include "projectors_pose.hpp"

namespace proj::views {
// The batch for `s` with coordinates made by `c`; linear projectors only go
// through glTexGen (the others fall back to GLSL, and the caption says so).
struct Way {
  Projector pr;
  Axis ax;
  Formula f;
  Coords c;
  GLenum texGenMode = GL_OBJECT_LINEAR;
};
inline bool linear(Projector p) { return p == Projector::Planar || p == Projector::Solid; }
inline Coords effective(const Way& w) {
  if (w.pr == Projector::Solid) return Coords::TexGen;  // the 3D texture's s, t, r come from OBJECT_LINEAR planes
  if (w.c == Coords::TexGen && !linear(w.pr)) return Coords::Glsl;
  return w.c;
}
inline ts::Batch batchFor(const Shape& s, const Way& w, int tex, const glm::mat4& planeModelview) {
  switch (effective(w)) {
    case Coords::Cpu: return perVertexBatch(s, w.pr, w.ax, w.f, tex);
    case Coords::TexGen:
      return texGenBatch(s,
                         planarTexGen(w.ax, w.f, w.pr == Projector::Solid ? GL_OBJECT_LINEAR : w.texGenMode,
                                      planeModelview, w.pr == Projector::Solid),
                         tex);
    case Coords::Glsl: return glslBatch(s, w.pr, w.ax, w.f, tex);
  }
  return {};
}
// The viewer's camera: 30° lens, 5 units away, looking a little down.
inline glm::mat4 camera() {
  return glm::translate(glm::mat4(1.0f), {0, 0, -5.2f}) * glm::rotate(glm::mat4(1.0f), glm::radians(20.0f), {1, 0, 0}) *
         glm::rotate(glm::mat4(1.0f), glm::radians(-30.0f), {0, 1, 0});
}
inline ts::Panel objectPanel(const std::string& id, const ts::Rect& vp, const ts::Batch& b, const glm::mat4& model) {
  ts::Panel p;
  p.id = id;
  p.viewport = vp;
  p.projection = glm::perspective(glm::radians(30.0f), float(vp.w) / float(vp.h), 1.0f, 20.0f);
  p.modelview = camera() * model;
  p.depthTest = true;
  p.batches.push_back(b);
  return p;
}
// Texture space: the texture dimmed, the texels the object uses (`used`, grid
// x grid, row j from the bottom: Usage::used of projectors_measure.hpp) in
// amber on top, one quad per run of used texels in a row.
inline ts::Panel usagePanel(const ts::Rect& vp, int tex, const std::vector<unsigned char>* used, int grid) {
  ts::Panel p = ts::layout::texturePanel("texture_space", vp, tex, "texture");
  for (ts::Vertex& v : p.batches[0].vertices) v.color = {0.45f, 0.45f, 0.45f, 1.0f};
  p.batches[0].texEnv = GL_MODULATE;
  if (!used || used->empty()) return p;
  ts::Batch runs;
  runs.role = "used_texels";
  runs.blend = true;
  const glm::vec4 amber(1.0f, 0.7f, 0.2f, 0.55f);
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid;) {
      if (!(*used)[size_t(j) * size_t(grid) + size_t(i)]) {
        ++i;
        continue;
      }
      int e = i;
      while (e < grid && (*used)[size_t(j) * size_t(grid) + size_t(e)]) ++e;
      float x0 = float(i) / grid, x1 = float(e) / grid, y0 = float(j) / grid, y1 = float(j + 1) / grid;
      for (glm::vec2 c : {glm::vec2(x0, y0), {x1, y0}, {x1, y1}, {x0, y0}, {x1, y1}, {x0, y1}})
        runs.vertices.push_back({{c, 0.0f}, {0, 0, 0, 1}, amber});
      i = e;
    }
  p.batches.push_back(runs);
  return p;
}
// The colour of the slide projector's frustum outline.
inline const glm::vec4 kProjectorOutline{1.0f, 0.9f, 0.2f, 1.0f};
// The slide projector's stage from the camera, with the projector's frustum outline.
inline ts::Panel slidePanel(const ts::Rect& vp, int tex, bool clip) {
  const Slide sl = slideSetup();
  ts::Panel p;
  p.id = clip ? "stage_clipped" : "stage";
  p.viewport = vp;
  p.projection = glm::perspective(glm::radians(60.0f), float(vp.w) / float(vp.h), 0.5f, 30.0f);
  p.modelview = glm::mat4(sl.camV);
  p.depthTest = true;
  p.clear = true;
  p.clearColor = {0.12f, 0.12f, 0.16f, 1.0f};
  p.batches.push_back(slideBatch(sl, tex, clip));
  if (clip) {  // what the clip plane removed, untextured (drawn after: GL_LESS keeps the lit part)
    ts::Batch plain = slideBatch(sl, -1, false);
    plain.role = "stage_unlit";
    plain.texGen = ts::TexGen();
    for (ts::Vertex& v : plain.vertices) v.color = {0.3f, 0.3f, 0.34f, 1.0f};
    p.batches.push_back(plain);
  }
  // The frustum: the projector's clip corners at depth 3 (w = 3), back to world.
  const glm::dmat4 inv = glm::inverse(sl.projL * sl.viewL);
  glm::dvec3 apex = glm::dvec3(glm::inverse(sl.viewL)[3]);
  ts::Batch lines;
  lines.role = "projector";
  lines.prim = ts::Prim::Lines;
  lines.lineWidth = 2.0f;
  const glm::vec4& yellow = kProjectorOutline;
  for (glm::dvec2 c : {glm::dvec2(-1, -1), {1, -1}, {1, 1}, {-1, 1}}) {
    glm::dvec4 w = inv * glm::dvec4(c, 0.6, 1.0);
    glm::dvec3 q = glm::dvec3(w) / w.w;
    q = apex + (q - apex) * (2.5 / glm::length(q - apex));
    lines.vertices.push_back({glm::vec3(apex), {0, 0, 0, 1}, yellow});
    lines.vertices.push_back({glm::vec3(q), {0, 0, 0, 1}, yellow});
  }
  p.batches.push_back(lines);
  return p;
}
}  // namespace proj::views
