// demos/multitexture/mt_frames.hpp — AB + CD as Frames (issue 29): the
// passes GL drew for it described as data, so the figure draws
// them and the CPU reference recomputes them from the sidecar.  Unit 1 and
// GL_COMBINE (Batch::texture1, ts::Combine), the multiplying and adding
// blends (Batch::blendSrc / blendDst); the one-unit path's intermediate
// buffer is a nested frame (TextureDesc::renderedFrom: A, then x B, whose
// render is the texture the last pass adds).  measure() renders these very
// Frames (Renderer::render) and the figure draws them into its panels.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/textures.hpp"
#include "mt_gl.hpp"

namespace mt::frames {
constexpr int kAbcdPixels = 128;

// The square over the unit panel, (s, t) = (x, y): one glBegin pass.
inline ts::Batch square(int texture, const std::string& role) {
  ts::Batch b;
  b.role = role;
  b.texture = texture;
  const glm::vec2 c[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i : {0, 1, 2, 0, 2, 3}) b.vertices.push_back({{c[i], 0.0f}, {c[i], 0.0f, 1.0f}, {1, 1, 1, 1}});
  return b;
}
inline ts::Batch times(ts::Batch b) { return b.blend = true, b.blendSrc = GL_DST_COLOR, b.blendDst = GL_ZERO, b; }
inline ts::Batch plus(ts::Batch b) { return b.blend = true, b.blendSrc = GL_ONE, b.blendDst = GL_ONE, b; }
// Unit 1 = `t` by GL_COMBINE: PREVIOUS x TEXTURE.
inline ts::Batch withUnit1(ts::Batch b, int t) {
  b.texture1 = t, b.texEnv1 = GL_COMBINE;
  b.combine1.rgb = GL_MODULATE, b.combine1.source[0] = GL_PREVIOUS, b.combine1.source[1] = GL_TEXTURE;
  return b;
}

// A, B, C, D as the frame's textures (GL_NEAREST, clamped), their indices.
// Image row j is t = (j + 1/2) / 64, as mt_gl.hpp's upload has it.
inline std::array<int, 4> addTextures(ts::Frame& f, const std::vector<ts::Image>& t) {
  std::array<int, 4> ix{};
  const char* names[4] = {"A", "B", "C", "D"};
  for (size_t k = 0; k < 4; ++k) {
    ts::Image top(t[k].width, t[k].height);  // the Frame's textures have row 0 at t = 1
    for (int j = 0; j < top.height; ++j)
      for (int i = 0; i < top.width; ++i) top.set(i, top.height - 1 - j, t[k].at(i, j));
    ts::TextureDesc d = ts::renderedImageTexture(top, "multitexture", std::string("texture ") + names[k], "multitexture");
    d.minFilter = d.magFilter = GL_NEAREST;
    d.wrapS = d.wrapT = GL_CLAMP_TO_EDGE;
    ix[k] = f.addTexture(d);
  }
  return ix;
}

inline ts::Panel unitPanel(const std::string& id, ts::Rect viewport) {
  ts::Panel p;
  p.id = id;
  p.viewport = viewport;
  p.projection = glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f);
  p.clear = true;
  p.clearColor = {0, 0, 0, 1};
  return p;
}

// The intermediate buffer of the one-unit path: A, then x B.
inline ts::Frame abFrame(const std::vector<ts::Image>& t) {
  ts::Frame f;
  f.width = f.height = kAbcdPixels;
  const std::array<int, 4> ix = addTextures(f, t);
  ts::Panel p = unitPanel("ab", {0, 0, kAbcdPixels, kAbcdPixels});
  p.batches = {square(ix[0], "A"), times(square(ix[1], "x B"))};
  f.panels.push_back(p);
  return f;
}

// Method m's batches into `f` (whose textures they add).  kStored needs
// the intermediate buffer's render `ab` (of abFrame).
inline std::vector<ts::Batch> abcdBatches(ts::Frame& f, const std::vector<ts::Image>& t, int m, const ts::Image& ab) {
  const std::array<int, 4> ix = addTextures(f, t);
  const int A = ix[0], B = ix[1], C = ix[2], D = ix[3];
  if (m == kMultitexture) return {withUnit1(square(A, "A, unit 1: x B"), B), plus(withUnit1(square(C, "+ C, unit 1: x D"), D))};
  if (m == kFramebufferOnly) return {square(A, "A"), times(square(B, "x B")), plus(square(C, "+ C")), times(square(D, "x D"))};
  ts::TextureDesc d = ts::renderedImageTexture(ab, "multitexture", "AB, the intermediate buffer", "multitexture");
  d.minFilter = d.magFilter = GL_NEAREST;
  d.wrapS = d.wrapT = GL_CLAMP_TO_EDGE;
  // A nested frame's texel (x, y) is its picture's pixel (x, y), row 0 the
  // top (TextureDesc::renderedFrom): the readback as it is, so t runs down
  // the picture and the square reads it with t = 1 - y.
  d.image = std::make_shared<const ts::Image>(ab);
  d.renderedFrom = std::make_shared<const ts::Frame>(abFrame(t));
  const int stored = f.addTexture(d);
  ts::Batch add = plus(square(stored, "+ AB (stored)"));
  for (ts::Vertex& v : add.vertices) v.tex.y = 1.0f - v.tex.y;
  return {square(C, "C"), times(square(D, "x D")), add};
}

// Method m alone, 128 x 128: what measure() renders.
inline ts::Frame abcdFrame(const std::vector<ts::Image>& t, int m, const ts::Image& ab) {
  ts::Frame f;
  f.width = f.height = kAbcdPixels;
  ts::Panel p = unitPanel("abcd", {0, 0, kAbcdPixels, kAbcdPixels});
  p.batches = abcdBatches(f, t, m, ab);
  f.panels.push_back(p);
  return f;
}

// ---- the cutout tree (alpha test, blending) as Frames ------------------------
// The tree's hidden-sky and edge passes as data: a panel in
// pixel coordinates of a 256 x 256 picture (x right, y up, z in [-1, 1],
// +1 nearest), the tree a texture (GL_NEAREST, or GL_LINEAR magnified).
inline int addTree(ts::Frame& f, const ts::Image& tree, GLenum mag) {
  ts::Image top(tree.width, tree.height);  // renderedImageTexture flips: row 0 stays t = 0
  for (int j = 0; j < top.height; ++j)
    for (int i = 0; i < top.width; ++i) top.set(i, top.height - 1 - j, tree.at(i, j));
  ts::TextureDesc d = ts::renderedImageTexture(top, "multitexture", "the cutout tree", "multitexture");
  d.minFilter = GL_NEAREST, d.magFilter = mag;
  d.wrapS = d.wrapT = GL_CLAMP_TO_EDGE;
  return f.addTexture(d);
}
inline ts::Batch rect(glm::vec4 xy, float z, glm::vec4 st, int texture, glm::vec4 colour, const std::string& role) {
  ts::Batch b;
  b.role = role;
  b.texture = texture;
  const glm::vec2 c[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i : {0, 1, 2, 0, 2, 3})
    b.vertices.push_back({{glm::mix(xy.x, xy.z, c[i].x), glm::mix(xy.y, xy.w, c[i].y), z},
                          {glm::mix(st.x, st.z, c[i].x), glm::mix(st.y, st.w, c[i].y), 0.0f, 1.0f}, colour});
  return b;
}
inline ts::Batch treeState(ts::Batch b, int mode) {
  if (mode == kAlphaTest) b.alphaFunc = GL_GREATER, b.alphaRef = 0.5f;
  // kBlend: FixedState's GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA.  Otherwise
  // (GL_ONE, GL_ZERO): the colour as drawn, and the framebuffer's alpha
  // kept (FixedState's alpha factors), so the picture stays opaque where
  // the texels are transparent (GL would use glColorMask for that).
  b.blend = true;
  if (mode != kBlend) b.blendSrc = GL_ONE, b.blendDst = GL_ZERO;
  return b;
}
inline ts::Panel pixelPanel(const std::string& id, ts::Rect viewport, bool depth) {
  ts::Panel p = unitPanel(id, viewport);
  p.projection = glm::ortho(0.0f, 256.0f, 0.0f, 256.0f, -1.0f, 1.0f);
  p.depthTest = depth;
  return p;
}
inline glm::vec4 sky() { return glm::vec4(kSky.r, kSky.g, kSky.b, 255) / 255.0f; }
// The tree drawn first, in front (z = 0.5), then the sky behind it (z = -0.5), depth test on.
inline ts::Panel hiddenPanel(ts::Frame& f, const ts::Image& tree, int mode, const std::string& id, ts::Rect viewport) {
  ts::Panel p = pixelPanel(id, viewport, true);
  p.batches = {treeState(rect({64, 64, 192, 192}, 0.5f, {0, 0, 1, 1}, addTree(f, tree, GL_NEAREST), glm::vec4(1), "the tree, first"), mode),
               rect({0, 0, 256, 256}, -0.5f, {0, 0, 1, 1}, -1, sky(), "the sky, behind")};
  return p;
}
// The sky, then 16 x 16 texels of the crown's edge magnified 16 times (GL_LINEAR).
inline ts::Panel edgePanel(ts::Frame& f, const ts::Image& tree, int mode, const std::string& id, ts::Rect viewport) {
  ts::Panel p = pixelPanel(id, viewport, false);
  p.batches = {rect({0, 0, 256, 256}, 0, {0, 0, 1, 1}, -1, sky(), "the sky"),
               treeState(rect({0, 0, 256, 256}, 0, {0.0625f, 0.5f, 0.3125f, 0.75f}, addTree(f, tree, GL_LINEAR), glm::vec4(1),
                              "the tree's edge x16"), mode)};
  return p;
}
inline ts::Frame alone(int w, int h, const std::function<ts::Panel(ts::Frame&, ts::Rect)>& panel) {
  ts::Frame f;
  f.width = w, f.height = h;
  f.panels.push_back(panel(f, {0, 0, w, h}));
  return f;
}
}  // namespace mt::frames
