// demos/environment_mapping/environment_mapping_views.hpp — the figures' pictures of the
// mirror object as ts::Frames, so that each picture panel shows the render
// of a nested frame (TextureDesc::renderedFrom), which the sidecar writes and
// the CPU reference recomputes before it checks the figure.
//
// A picture pass is the object's triangles (glNormal3f + glVertex3f) under
// the figure's projection and view, the map an "environment_map" texture
// (common/core/env_maps.hpp: 8 bits a channel, GL_LINEAR, the generator the
// reference remakes from the sidecar's parameters):
//   cube map, r per vertex    glTexGen GL_REFLECTION_MAP on s, t, r, the
//                             texture matrix turning eye space into the
//                             world's: fixed function, recomputed exactly
//   sphere map, r per vertex  glTexGen GL_SPHERE_MAP on s, t: fixed function,
//                             recomputed exactly
//   the rest                  environment_mapping_gl.hpp's GLSL (r per vertex or per pixel;
//                             the normal sent as (s, t, r)): a batch with a
//                             program, its pixels exempt in the reference
//   the reference             r per pixel in GLSL, read from a cube map of
//                             kReferenceFace texels a side (0.35 degrees a
//                             texel at a face's centre, against the picture's
//                             1.4 at 64)
// The measurements do not read these: they draw float maps into float
// targets (EnvGL::draw) and compare directions.
#pragma once
#include <glm/gtc/type_ptr.hpp>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "common/core/env_maps.hpp"
#include "common/core/frame.hpp"
#include "common/gl/gl_listing.hpp"
#include "common/gl/render.hpp"
#include "environment_mapping_gl.hpp"
#include "environment_mapping_measure.hpp"

namespace envmap {
constexpr int kReferenceFace = 256;  // the reference picture's cube map: texels a face's side

// True where a picture pass is fixed function (texgen): the reference recomputes it.
inline bool texgenPass(const Pass& p) { return p.perVertex && (p.param == kCube || p.param == kSphere); }

// The picture pass `p` (p.directions is ignored: the world's colours) as a
// frame of p.w x p.h, the background kBackground.
inline ts::Frame passFrame(const Pass& p) {
  ts::Frame f;
  f.width = p.w, f.height = p.h;
  f.clearColor = glm::vec4(glm::vec3(kBackground), 1.0f);
  f.textures.push_back(ts::envmaps::environmentMap(ts::envmaps::Param(mapOf(p.param)), p.faceTexels, p.sphereView));
  ts::Panel panel;
  panel.id = std::string("pass_") + kParamKeys[mapOf(p.param)];
  panel.viewport = {0, 0, p.w, p.h};
  panel.projection = p.projection;
  panel.modelview = p.view * p.model;
  panel.depthTest = true;
  ts::Batch b;
  b.role = "mirror";
  b.texture = 0;
  b.texEnv = GL_REPLACE;
  const glm::mat3 toWorld = glm::transpose(glm::mat3(p.view));
  // A pass with seamRule >= 0 has lat-long's (s, t) computed per triangle corner (latlongCornerST): plain texture
  // coordinates, fixed function, which the reference recomputes exactly; the map's GL_REPEAT wraps s past 1.
  if (texgenPass(p)) {
    b.texGen.mode = p.param == kCube ? GL_REFLECTION_MAP : GL_SPHERE_MAP;
    b.texGen.coords = ts::TexGen::S | ts::TexGen::T | (p.param == kCube ? ts::TexGen::R : 0u);  // sphere: s, t only
    if (p.param == kCube) b.textureMatrix = glm::mat4(toWorld);  // eye-space r -> the world's
  } else if (p.seamRule < 0) {
    b.program = "envmap_frame_p" + std::to_string(p.param) + (p.perVertex ? "_v" : "_f");
    f.programs.push_back(
        {b.program, {kFile, vertexShader(p.param, p.perVertex, true), fragmentShader(p.param, p.perVertex, true)}});
    const glm::mat3 sphereEye(p.view);  // read in this eye's space, as GL_SPHERE_MAP does
    for (int c = 0; c < 3; ++c) {
      b.uniforms.push_back({"toWorld" + std::to_string(c), glm::vec4(toWorld[c], 0.0f)});
      b.uniforms.push_back({"sphereEye" + std::to_string(c), glm::vec4(sphereEye[c], 0.0f)});
    }
  }
  const ts::Mesh m = objectMesh(p.object);
  const std::vector<glm::vec2> st = p.seamRule >= 0 ? latlongCornerST(p, p.seamRule == 1) : std::vector<glm::vec2>{};
  for (unsigned i : m.triangles()) {
    ts::Vertex v;
    v.pos = glm::vec3(m.points[i].pos);
    v.normal = glm::vec3(m.points[i].normal);
    if (!b.program.empty()) v.tex = glm::vec4(v.normal, 1.0f);  // the program's normal
    if (!st.empty()) v.tex = glm::vec4(st[b.vertices.size()], 0.0f, 1.0f);
    b.vertices.push_back(v);
  }
  panel.batches.push_back(b);
  f.panels.push_back(panel);
  return f;
}

// The reference picture: r per pixel (GLSL) through the fine cube map.
inline ts::Frame referenceFrame(Pass p) {
  p.param = kCube, p.perVertex = false, p.faceTexels = kReferenceFace;
  return passFrame(p);
}

// The texture a figure shows: GL's render of `inner` (drawn here, its calls
// recorded for the listings), with the frame it is the render of.  Its image
// is the picture as Renderer::render returns it (row 0 the top); the digest
// keeps the renderer's upload cache apart for different pictures.
inline ts::TextureDesc nestedTexture(ts::Renderer& r, const ts::Frame& inner, const std::string& what) {
  ts::Image img;
  const ts::gl::CallList calls = ts::recordRender(r, [&] { img = r.renderOffscreen(inner); });
  ts::TextureDesc t = ts::nestedPictureTexture(img, inner, "environment_mapping_pass", what);
  t.renderedBy = calls;
  return t;
}
// The map view's panel (ts::layout::texturePanel of ts::envmaps::unwrappedMap:
// one quad, (u, v) = its texture coordinates): the map dimmed, GL_MODULATE by
// kDim, and over it the texels the object reads at full colour, GL_REPLACE,
// one quad per run of lit texels along a row (the quads are in the sidecar,
// so the reference redraws the lit region too).
constexpr float kDim = 0.35f;
inline void lightTheReadTexels(ts::Panel& panel, const LitTexels& lit) {
  ts::Batch& map = panel.batches.back();
  map.texEnv = GL_MODULATE;
  for (ts::Vertex& v : map.vertices) v.color = {kDim, kDim, kDim, 1.0f};
  ts::Batch b = map;
  b.role = "read texels";
  b.texEnv = GL_REPLACE;
  b.vertices.clear();
  for (int y = 0; y < lit.h; ++y)
    for (int x0 = 0; x0 < lit.w;) {
      if (!lit.hit[size_t(y) * size_t(lit.w) + size_t(x0)]) {
        ++x0;
        continue;
      }
      int x1 = x0;
      while (x1 < lit.w && lit.hit[size_t(y) * size_t(lit.w) + size_t(x1)]) ++x1;
      const float u0 = float(x0) / float(lit.w), u1 = float(x1) / float(lit.w);
      const float v0 = 1.0f - float(y + 1) / float(lit.h), v1 = 1.0f - float(y) / float(lit.h);  // row 0 at the top
      const glm::vec2 c[4] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
      for (int i : {0, 1, 2, 0, 2, 3}) b.vertices.push_back({{c[i], 0.0f}, {c[i], 0.0f, 1.0f}, {1, 1, 1, 1}});
      x0 = x1;
    }
  if (!b.vertices.empty()) panel.batches.push_back(b);
}
}  // namespace envmap
