// demos/multitexture/multitexture_frames.hpp — the figures' pictures as Frames: the
// passes described as data, so the figure draws them
// (common/gl/render.cpp) and the CPU reference recomputes them from the
// sidecar, every texture a named generator (common/core/
// multitexture_textures.hpp).  The cutout tree (the alpha test), the cross
// tree, the light maps and the spot (unit 1, its texture matrix), the gloss
// map's passes, AB + CD (GL_COMBINE; the multiplying and adding blends,
// Batch::blendSrc / blendDst; the one-unit path's intermediate buffer a
// nested frame, TextureDesc::renderedFrom: A, then x B, whose render is the
// texture the last pass adds), the pear (unit 1's own coordinates, Batch::
// coords1; GL_MODULATE_ADD_ATI; the second pass added with GL_LEQUAL; the
// figure shows it as a nested frame).  measure() renders these very Frames
// (Renderer::renderOffscreen) and the figure draws them into its panels.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "common/core/frame.hpp"
#include "demos/multitexture/multitexture_textures.hpp"
#include "common/core/textures.hpp"
#include "multitexture_gl.hpp"

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

// A, B, C, D as the frame's textures (GL_NEAREST, clamped), their indices:
// the sidecar's generator multitexture_abcd (texel row j is t = (j + 1/2) / 64).
inline std::array<int, 4> addTextures(ts::Frame& f, const std::vector<ts::Image>&) {
  std::array<int, 4> ix{};
  for (int k = 0; k < 4; ++k) {
    ts::TextureDesc d = ts::multitex::abcdTexture(k);
    d.minFilter = d.magFilter = GL_NEAREST;
    d.wrapS = d.wrapT = GL_CLAMP_TO_EDGE;
    ix[size_t(k)] = f.addTexture(d);
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
  if (m == kMultitexture)
    return {withUnit1(square(A, "A, unit 1: x B"), B), plus(withUnit1(square(C, "+ C, unit 1: x D"), D))};
  if (m == kFramebufferOnly)
    return {square(A, "A"), times(square(B, "x B")), plus(square(C, "+ C")), times(square(D, "x D"))};
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
inline int addTree(ts::Frame& f, const ts::Image&, GLenum mag) {
  ts::TextureDesc d = ts::multitex::treeTexture();  // the sidecar's generator multitexture_tree
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
                          {glm::mix(st.x, st.z, c[i].x), glm::mix(st.y, st.w, c[i].y), 0.0f, 1.0f},
                          colour});
  return b;
}
// The alpha test's reference: a texel is leaf or air, its alpha 1 or 0.
constexpr float kAlphaRef = 0.5f;
// The turn the cross tree is shown at: where its width is least.
constexpr float kCrossTurnDeg = 45.0f;
inline ts::Batch treeState(ts::Batch b, int mode) {
  if (mode == kAlphaTest) b.alphaFunc = GL_GREATER, b.alphaRef = kAlphaRef;
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
  p.batches = {treeState(rect({64, 64, 192, 192}, 0.5f, {0, 0, 1, 1}, addTree(f, tree, GL_NEAREST), glm::vec4(1),
                              "the tree, first"),
                         mode),
               rect({0, 0, 256, 256}, -0.5f, {0, 0, 1, 1}, -1, sky(), "the sky, behind")};
  return p;
}
// The sky, then 16 x 16 texels of the crown's edge magnified 16 times (GL_LINEAR).
inline ts::Panel edgePanel(ts::Frame& f, const ts::Image& tree, int mode, const std::string& id, ts::Rect viewport) {
  ts::Panel p = pixelPanel(id, viewport, false);
  p.batches = {rect({0, 0, 256, 256}, 0, {0, 0, 1, 1}, -1, sky(), "the sky"),
               treeState(rect({0, 0, 256, 256}, 0, {0.0625f, 0.5f, 0.3125f, 0.75f}, addTree(f, tree, GL_LINEAR),
                              glm::vec4(1), "the tree's edge x16"),
                         mode)};
  return p;
}
inline ts::Frame alone(int w, int h, const std::function<ts::Panel(ts::Frame&, ts::Rect)>& panel) {
  ts::Frame f;
  f.width = w, f.height = h;
  f.panels.push_back(panel(f, {0, 0, w, h}));
  return f;
}

// The cross tree at `degrees`, a little from above (15 degrees), textured and
// alpha-tested, over the sky, depth test on: a panel of the unit square.
inline ts::Panel crossTreePanel(ts::Frame& f, float degrees, const std::string& id, ts::Rect viewport) {
  ts::Panel p = unitPanel(id, viewport);
  p.projection = glm::ortho(-0.7f, 0.7f, -0.7f, 0.7f, -2.0f, 2.0f);
  p.modelview = glm::rotate(glm::rotate(glm::mat4(1.0f), glm::radians(15.0f), glm::vec3(1, 0, 0)),
                            glm::radians(degrees), glm::vec3(0, 1, 0));
  p.depthTest = true;
  p.clearColor = sky();
  ts::Batch b = treeState(square(addTree(f, {}, GL_NEAREST), "the cross tree: two quads"), kAlphaTest);
  b.vertices.clear();
  const glm::vec2 c[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int q = 0; q < 2; ++q)
    for (int i : {0, 1, 2, 0, 2, 3}) {
      const float a = c[i].x - 0.5f, y = c[i].y - 0.5f;
      b.vertices.push_back({q ? glm::vec3(0, y, a) : glm::vec3(a, y, 0), {c[i], 0.0f, 1.0f}, glm::vec4(1)});
    }
  p.batches = {b};
  return p;
}

// ---- light maps and the gloss map as Frames --------------------------------
// The base on unit 0 (GL_NEAREST, repeated): the sidecar's generator
// multitexture_bricks, or the student's picture (--texture: not remade).
inline int addBase(ts::Frame& f, const ts::Image& base, bool user) {
  ts::TextureDesc d = ts::multitex::bricksTexture();
  if (user) {
    ts::Image top = base;  // renderedImageTexture flips: row 0 stays t = 0
    top.flipVertical();
    d = ts::renderedImageTexture(top, "multitexture", "the base picture (--texture)", "multitexture");
  }
  d.minFilter = d.magFilter = GL_NEAREST;
  d.wrapS = d.wrapT = GL_REPEAT;
  return f.addTexture(d);
}
inline int addGrey(ts::Frame& f, ts::TextureDesc d, GLenum filter) {
  d.minFilter = d.magFilter = filter;
  d.wrapS = d.wrapT = GL_CLAMP_TO_EDGE;
  return f.addTexture(d);
}
// c = base (unit 0, GL_REPLACE) x L (unit 1, GL_MODULATE, GL_LINEAR, clamped)
// over the unit square; L the n^2 light map, or (n = 0) the spot at position
// k of kSpotFrames, placed by unit 1's texture matrix:
// (s, t) -> 1.6 ((s, t) - c) + 0.5, c on a circle.
inline glm::vec2 spotCentre(int k, int n) {
  const double a = 6.283185307179586 * k / n;
  return {float(0.5 + 0.28 * std::cos(a)), float(0.5 + 0.28 * std::sin(a))};
}
inline ts::Batch lightMapped(ts::Frame& f, const ts::Image& base, bool user, int n, int k = 0, int frames = 12) {
  ts::Batch b = square(addBase(f, base, user),
                       n ? "the bricks, unit 1: x the light map" : "the bricks, unit 1: x the spot");
  b.texture1 = addGrey(f, n ? ts::multitex::lightMapTexture(n) : ts::multitex::spotTexture(), GL_LINEAR);
  b.texEnv1 = GL_MODULATE;
  if (!n) {
    const glm::vec2 c = spotCentre(k, frames);
    b.textureMatrix1 = glm::translate(glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 0)),
                                                 glm::vec3(1.6f, 1.6f, 1)),
                                      glm::vec3(-c, 0));
  }
  return b;
}
// The gloss-mapped plane, 256 x 128 pixels over [0, 2] x [0, 1], a 64 x 32
// grid lit per vertex (glossLighting), each strip as GL draws it (triangles
// (v_k, v_k+1, v_k+2)).  Pass 1: t_d GL_MODULATE i_diff; pass 2: g
// GL_MODULATE i_spec, added (GL_ONE, GL_ONE).
inline ts::Batch glossGrid(int texture, bool spec, const std::string& role) {
  ts::Batch b;
  b.role = role;
  b.texture = texture, b.texEnv = GL_MODULATE;
  for (int j = 0; j < 32; ++j) {
    std::vector<ts::Vertex> strip;
    for (int i = 0; i <= 64; ++i)
      for (int dj = 1; dj >= 0; --dj) {
        const double x = i / 32.0, y = (j + dj) / 32.0;
        const glm::dvec2 l = glossLighting(x, y);
        const float c = float(spec ? l.y : l.x);
        strip.push_back(
            {{float(x * 128), float(y * 128), 0.0f}, {float(spec ? x / 2 : x), float(y), 0.0f, 1.0f}, {c, c, c, 1.0f}});
      }
    for (size_t k = 0; k + 2 < strip.size(); ++k)
      b.vertices.insert(b.vertices.end(), {strip[k], strip[k + 1], strip[k + 2]});
  }
  return b;
}
enum Gloss { kDiffuseOnly, kGlossed, kSpecularTwice };
inline ts::Panel glossPanel(ts::Frame& f, const ts::Image& base, bool user, int what, const std::string& id,
                            ts::Rect viewport) {
  ts::Panel p = unitPanel(id, viewport);
  p.projection = glm::ortho(0.0f, 256.0f, 0.0f, 128.0f, -1.0f, 1.0f);
  const int g = addGrey(f, ts::multitex::glossTexture(64, 32), GL_NEAREST);
  if (what != kSpecularTwice) p.batches.push_back(glossGrid(addBase(f, base, user), false, "pass 1: t_d x i_diff"));
  if (what != kDiffuseOnly) p.batches.push_back(plus(glossGrid(g, true, "pass 2: + g x i_spec")));
  if (what == kSpecularTwice) p.batches.push_back(plus(glossGrid(g, true, "+ g x i_spec again (x 2)")));
  return p;
}
// ---- the pear: i = t_d x i_diff + t_g t_r -----------------------------------
// A lathe (pearProfile), 48 x 32 quads, seen along -z, orthographic.  Per
// vertex: i_diff (Lambert, a light up-left-front) as the colour; (u, v) for
// the skin; the sphere-map coordinates of the reflected view direction
// (what GL_SPHERE_MAP texgen would give, computed here) for t_r.
struct PearVertex {
  glm::vec3 p;
  glm::vec2 uv, sphere;
  float diffuse;
};
inline PearVertex pearVertex(int i, int j) {
  const double u = i / 48.0, v = j / 32.0, a = 6.283185307179586 * u;
  const glm::dvec2 c = pearProfile(v),
                   d = (pearProfile(std::min(1.0, v + 1e-3)) - pearProfile(std::max(0.0, v - 1e-3)));
  const glm::dvec3 p(c.x * std::sin(a), c.y, c.x * std::cos(a));
  glm::dvec3 n = glm::normalize(glm::dvec3(d.y * std::sin(a), -d.x, d.y * std::cos(a)));
  if (glm::length(d) < 1e-9) n = {0, v < 0.5 ? -1 : 1, 0};
  const glm::dvec3 refl = glm::reflect(glm::dvec3(0, 0, -1), n);
  const double m = 2.0 * std::sqrt(refl.x * refl.x + refl.y * refl.y + (refl.z + 1) * (refl.z + 1));
  const double lambert = std::max(0.0, glm::dot(n, glm::normalize(glm::dvec3(-0.5, 0.6, 0.7))));
  return {glm::vec3(p), glm::vec2(u, v), glm::vec2(refl.x / m + 0.5, refl.y / m + 0.5), float(0.15 + 0.7 * lambert)};
}
// The mesh as one batch, each of the 32 strips as GL draws it (triangles
// (v_k, v_k+1, v_k+2)); unit 0 reads (u, v) (skinFirst) or the sphere map's
// (s, t), unit 1 its own coordinates, the other set (Batch::coords1).
inline ts::Batch pearMesh(int texture, bool skinFirst, const std::string& role) {
  ts::Batch b;
  b.role = role;
  b.texture = texture;
  b.coords1 = true;
  b.depthFunc = GL_LEQUAL;
  for (int j = 0; j < 32; ++j) {
    std::vector<ts::Vertex> strip;
    for (int i = 0; i <= 48; ++i)
      for (int dj = 1; dj >= 0; --dj) {
        const PearVertex q = pearVertex(i, j + dj);
        ts::Vertex v;
        v.pos = q.p;
        v.tex = glm::vec4(skinFirst ? q.uv : q.sphere, 0.0f, 1.0f);
        v.tex1 = glm::vec4(skinFirst ? q.sphere : q.uv, 0.0f, 1.0f);
        v.color = {q.diffuse, q.diffuse, q.diffuse, 1.0f};
        strip.push_back(v);
      }
    for (size_t k = 0; k + 2 < strip.size(); ++k)
      b.vertices.insert(b.vertices.end(), {strip[k], strip[k + 1], strip[k + 2]});
  }
  return b;
}
// The pear's three pictures (GL_LINEAR; the skin and its gloss repeated,
// the sphere map clamped), the sidecar's generators multitexture_pear_*.
inline int addPearTexture(ts::Frame& f, ts::TextureDesc d, GLenum wrap) {
  d.minFilter = d.magFilter = GL_LINEAR;
  d.wrapS = d.wrapT = wrap;
  return f.addTexture(d);
}
// kCombine3: one pass, two units.  Unit 0: t_d GL_MODULATE i_diff (its alpha
//   t_g passes on); unit 1: GL_COMBINE, GL_MODULATE_ADD_ATI: t_r x
//   PREVIOUS's alpha + PREVIOUS.
// kTwoPasses: pass 1 t_d GL_MODULATE i_diff; pass 2 t_r (unit 0, GL_REPLACE)
//   x t_g (unit 1, GL_MODULATE), added (GL_ONE, GL_ONE, depth GL_LEQUAL).
// Over a dark grey, depth test on, z in [-2, 2] (+z nearest).
inline ts::Panel pearPanel(ts::Frame& f, int method, const std::string& id, ts::Rect viewport) {
  ts::Panel p = unitPanel(id, viewport);
  p.projection = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -2.0f, 2.0f);
  p.depthTest = true;
  p.clearColor = {0.12f, 0.12f, 0.14f, 1.0f};
  const int skin = addPearTexture(f, ts::multitex::pearSkinTexture(), GL_REPEAT);
  const int sky = addPearTexture(f, ts::multitex::pearSkyTexture(), GL_CLAMP_TO_EDGE);
  if (method == kCombine3) {
    ts::Batch b = pearMesh(skin, true, "t_d x i_diff, unit 1: + t_r x t_g (GL_MODULATE_ADD_ATI)");
    b.texEnv = GL_MODULATE;
    b.texture1 = sky, b.texEnv1 = GL_COMBINE;
    b.combine1.rgb = GL_MODULATE_ADD_ATI;
    b.combine1.source[0] = GL_TEXTURE, b.combine1.source[1] = GL_PREVIOUS, b.combine1.source[2] = GL_PREVIOUS;
    b.combine1.operand[0] = b.combine1.operand[1] = GL_SRC_COLOR, b.combine1.operand[2] = GL_SRC_ALPHA;
    p.batches = {b};
    return p;
  }
  ts::Batch skinPass = pearMesh(skin, true, "pass 1: t_d x i_diff");
  skinPass.texEnv = GL_MODULATE;
  skinPass.coords1 = false;  // unit 1 off: no second coordinates
  ts::Batch glossPass = plus(pearMesh(sky, false, "pass 2: + t_r x t_g"));
  glossPass.texEnv = GL_REPLACE;
  glossPass.texture1 = addPearTexture(f, ts::multitex::pearGlossTexture(), GL_REPEAT), glossPass.texEnv1 = GL_MODULATE;
  p.batches = {skinPass, glossPass};
  return p;
}
// The two methods side by side (w x w each), kCombine3 on the left only
// where GL_ATI_texture_env_combine3 is there (else the dark grey alone).
inline ts::Frame pearsFrame(int w, bool combine3) {
  ts::Frame f;
  f.width = 2 * w, f.height = w;
  for (int m = kCombine3; m <= kTwoPasses; ++m) {
    const ts::Rect v{m * w, 0, w, w};
    ts::Panel p = pearPanel(f, m, m == kCombine3 ? "pear_combine3" : "pear_two_passes", v);
    if (m == kCombine3 && !combine3) p.batches.clear();
    f.panels.push_back(p);
  }
  return f;
}

// The four textures in quadrants: A B over C D.
inline ts::Panel abcdQuadrants(ts::Frame& f, const std::string& id, ts::Rect viewport) {
  ts::Panel p = unitPanel(id, viewport);
  const std::array<int, 4> ix = addTextures(f, {});
  const char* names[4] = {"A", "B", "C", "D"};
  for (int k = 0; k < 4; ++k) {
    ts::Batch b = square(ix[size_t(k)], names[k]);
    for (ts::Vertex& v : b.vertices) v.pos = {(v.pos.x + float(k % 2)) / 2, (v.pos.y + float(1 - k / 2)) / 2, 0.0f};
    p.batches.push_back(b);
  }
  return p;
}
}  // namespace mt::frames
