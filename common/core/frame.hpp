// common/core/frame.hpp — a demo describes what to draw as data, not GL calls.
//
// A Frame is the whole picture: textures, panels (viewport + matrices +
// batches of vertices), and text labels.  common/gl/render.cpp turns it into
// fixed-function OpenGL (glBegin/glTexCoord4f/glVertex3f) or GLSL, and
// common/core/sidecar.cpp writes the very same data as JSON beside every figure,
// so anyone (the CPU reference rasterizer, a student with a calculator) can
// recompute the image without running OpenGL.
#pragma once
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/core/gl_call.hpp"   // recorded calls as plain data, no GL headers
#include "common/core/gl_enums.hpp"  // GL names only: the plain data never calls GL
#include "common/core/image.hpp"

namespace ts {
struct Frame;  // a texture may be the render of another Frame (TextureDesc::renderedFrom)
struct Vertex {
  glm::vec3 pos{0.0f};
  glm::vec4 tex{0.0f, 0.0f, 0.0f, 1.0f};  // (s, t, r, q): q != 1 for projective maps
  glm::vec4 color{1.0f};
  // The secondary colour (glSecondaryColor3f), added after texturing when the
  // batch's colorSum is on: what GL_SEPARATE_SPECULAR_COLOR does with the
  // specular term, computed on the CPU here so the reference can redo it.
  glm::vec3 secondary{0.0f};
  // --- environment-mapping texgen ---
  // The normal (glNormal3f), object coordinates: sent, and written in the
  // sidecar, only for batches whose texgen reads it (TexGen::needsNormal).
  // GL's initial current normal is (0, 0, 1).
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  // Unit 1's own (s, t, r, q) (glMultiTexCoord4f(GL_TEXTURE1, ...)), read
  // only by batches with Batch::coords1 on (the pear's sphere map
  // beside its skin's (u, v)); written in the sidecar only for those.
  glm::vec4 tex1{0.0f, 0.0f, 0.0f, 1.0f};
};

enum class Prim { Triangles, Lines, LineStrip, LineLoop, Points };

struct TextureDesc {
  std::string name;                                         // "checkerboard"
  std::vector<std::pair<std::string, std::string>> params;  // how it was made
  std::shared_ptr<const Image> image;                       // level 0
  bool mipmaps = false;                                     // levels built on the CPU by the book's 2x2 average
  bool linearLightMips = false;                             // average in linear light instead of sRGB values
  // Explicit levels 0..n (then `mipmaps` must be on); overrides the 2x2 average.
  std::shared_ptr<const std::vector<Image>> mipLevels;
  GLenum minFilter = GL_LINEAR, magFilter = GL_LINEAR;
  GLenum wrapS = GL_REPEAT, wrapT = GL_REPEAT;
  glm::vec4 border{0.0f};
  // > 1: a GL_TEXTURE_3D of image->width x (image->height / depth) x depth,
  // `image` holding the slices r = 0..depth-1 one above the other (slice k
  // in rows k*h .. k*h+h-1), wrapR its third wrap.  No mipmaps.
  int depth = 1;
  GLenum wrapR = GL_REPEAT;
  // --- cube maps ---
  // true: a GL_TEXTURE_CUBE_MAP whose six square faces (w x w, w =
  // image->width) are stacked in `image` in GL's face order +X, -X, +Y, -Y,
  // +Z, -Z (face f in rows f*w .. f*w+w-1, row 0 of a face its t = 0), each
  // uploaded to GL_TEXTURE_CUBE_MAP_POSITIVE_X + f.  No mipmaps.
  bool cube = false;
  // --- nested frames ---
  // The Frame whose render `image` is (a pass a demo drew itself, e.g. a
  // texgen picture): the sidecar writes it as "rendered_from" in the
  // texture's entry, and the CPU reference recomputes that frame first and
  // uses its picture as this texture.  The frame's size is the image's.
  std::shared_ptr<const Frame> renderedFrom;
  float maxAnisotropy = 1.0f;
  float lodBias = 0.0f;
  // 8-bit levels by which each texel of `image` may differ from GL's: 0 for
  // a picture the Frame holds as GL holds it; set by a sidecar generator
  // that remakes a picture the specification lets GL round its own way (a
  // DXT1 decode, demos/texture_compression/texture_compression_textures.hpp).
  // The CPU reference widens the texels' legal range by it.  Not part of the texels: never in key() or the sidecar.
  float texelSlack = 0.0f;
  // A texture the scene drew itself for this frame (a live view, see
  // Scene::live): bound as it is, never uploaded, cached or hashed; `image`
  // stays empty and the parameters above are still applied.
  GLuint glTexture = 0;
  // The GL calls that rendered `image`, when a scene rendered it itself in
  // measure() (recordRender in gl_listing.hpp): the listings and the GL pane
  // print them, under a comment naming the panel, before the frame's own.
  // Not part of the texels: never in key(), the sidecar or an export.
  gl::CallList renderedBy;
  // Identifies the texel contents (name + params), for caching uploads.
  std::string key() const;
};

struct Uniform {
  std::string name;
  glm::vec4 value{0.0f};
};

// glTexGen for a batch's texture coordinates (fixed function only): GL
// computes the coordinates named in `coords` from the vertex position, the
// others come from glTexCoord4f as sent.  OBJECT_LINEAR: s = planes[0] ·
// (x, y, z, 1) in object coordinates.  EYE_LINEAR: the planes are given
// while `planeModelview` is the modelview (GL stores plane · M⁻¹), then
// s = stored plane · (the vertex in eye coordinates): with planeModelview =
// the panel's modelview the planes are object-fixed, with the camera's view
// alone they are world-fixed (the slide projector), with the identity they
// are fixed to the eye (the texture "swims" as the object moves).
//
// The environment-mapping modes read the vertex's normal
// (Vertex::normal) and position in eye coordinates, n' = (M⁻¹)ᵀ n (not
// renormalised: GL_NORMALIZE stays off) and u = the unit vector from the
// eye to the vertex; they take no planes:
//   GL_SPHERE_MAP      (s, t only) r = u - 2 (n'·u) n', m = 2 sqrt(r_x² +
//                      r_y² + (r_z + 1)²), s = r_x/m + 1/2, t = r_y/m + 1/2
//   GL_REFLECTION_MAP  (s, t, r) = r = u - 2 (n'·u) n'
//   GL_NORMAL_MAP      (s, t, r) = n'
struct TexGen {
  GLenum mode = 0;      // 0 = off; GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP, GL_REFLECTION_MAP, GL_NORMAL_MAP
  unsigned coords = 0;  // bit 0 s, bit 1 t, bit 2 r, bit 3 q
  glm::vec4 planes[4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};  // GL's defaults
  glm::mat4 planeModelview{1.0f};
  bool on() const { return mode != 0 && coords != 0; }
  // The modes computed from the normal (no planes).
  bool needsNormal() const {
    return on() && (mode == GL_SPHERE_MAP || mode == GL_REFLECTION_MAP || mode == GL_NORMAL_MAP);
  }
  static constexpr unsigned S = 1, T = 2, R = 4, Q = 8;
};

// GL_COMBINE's colour function of a texture unit: glTexEnvi
// GL_COMBINE_RGB, GL_SOURCEk_RGB, GL_OPERANDk_RGB.  Arg k = source k's
// colour (GL_SRC_COLOR), 1 - it, its alpha (GL_SRC_ALPHA) or 1 - that;
// sources GL_TEXTURE (this unit's texel), GL_PREVIOUS (the unit before's
// result), GL_PRIMARY_COLOR, GL_CONSTANT (the unit's environment colour,
// GL's (0, 0, 0, 0) here).  C = GL_REPLACE a0 | GL_MODULATE a0 a1 |
// GL_ADD a0 + a1 | GL_ADD_SIGNED a0 + a1 - 1/2 | GL_SUBTRACT a0 - a1 |
// GL_INTERPOLATE a0 a2 + a1 (1 - a2) | GL_MODULATE_ADD_ATI a0 a2 + a1
// (GL_ATI_texture_env_combine3), clamped to [0, 1].  Alpha keeps GL's
// defaults: GL_MODULATE of GL_TEXTURE and GL_PREVIOUS alphas.
struct Combine {
  GLenum rgb = GL_MODULATE;
  GLenum source[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};       // GL's defaults
  GLenum operand[3] = {GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};  // GL's defaults
};

struct Program {
  std::string file;  // where the source lives, for error messages ("demos/x/x.cpp")
  std::string vertex, fragment;
};

struct Batch {
  std::string role;  // what it is, for the sidecar: "surface", "outline", ...
  Prim prim = Prim::Triangles;
  std::vector<Vertex> vertices;
  int texture = -1;            // index into Frame::textures, -1 = untextured
  GLenum texEnv = GL_REPLACE;  // fixed-function combine mode
  std::string program;         // "" = fixed function; else a Frame::programs key
  std::vector<Uniform> uniforms;
  float lineWidth = 1.0f;
  float pointSize = 1.0f;
  bool blend = false;
  // glMatrixMode(GL_TEXTURE) + glLoadMatrixf: GL multiplies every vertex's
  // (s,t,r,q) by it before interpolation (render.cpp loads it for the batch
  // and the identity after, so no other batch sees it; the sidecar writes it
  // when it is not the identity and the reference applies it per vertex).
  glm::mat4 textureMatrix{1.0f};
  // GL_TEXTURE_ENV_COLOR (glTexEnvfv): the constant colour GL_BLEND mixes in.
  glm::vec4 envColor{0.0f};
  // GL_COLOR_SUM: add each vertex's secondary colour after texturing.
  bool colorSum = false;
  TexGen texGen;  // glTexGen (off by default)
  // glClipPlane(GL_CLIP_PLANE0): keeps the points where the plane, given
  // while `clipModelview` is the modelview (GL stores plane · M⁻¹, as for
  // EYE_LINEAR planes), is >= 0 at the vertex in eye coordinates.  render.cpp
  // loads clipModelview to give the plane, as it does planeModelview for
  // tex_gen; set to the panel's modelview the plane is in object
  // coordinates.  The sidecar records both, so a reader recomputes the cut.
  bool clip = false;
  glm::vec4 clipPlane{0.0f};
  glm::mat4 clipModelview{1.0f};
  // --- the alpha test and blend factors (multitexturing) ---
  // glEnable(GL_ALPHA_TEST); glAlphaFunc(alphaFunc, alphaRef): a fragment
  // whose alpha (after texturing) fails the comparison is discarded, so it
  // writes neither colour nor depth.  0 = the test off (GL's default).
  GLenum alphaFunc = 0;
  float alphaRef = 0.0f;
  // With `blend` on: glBlendFuncSeparate(blendSrc, blendDst, FixedState's
  // alpha factors) instead of FixedState's colour factors — (GL_ONE,
  // GL_ONE) adds the fragment to the framebuffer, (GL_DST_COLOR, GL_ZERO)
  // multiplies it in.  0, 0 = FixedState's (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA).
  GLenum blendSrc = 0, blendDst = 0;
  // --- a second texture unit (multitexturing) ---
  // Unit 1 textured with Frame::textures[texture1] (2D), reading the
  // (s, t, r, q) unit 0 is sent, or its own (coords1) (glMultiTexCoord4f(
  // GL_TEXTURE1, ...); no texgen on unit 1; its own texture matrix below),
  // combined with unit 0's result by texEnv1:
  // a classic environment (GL_MODULATE: previous x texel, ...) or
  // GL_COMBINE with `combine1`.  -1 = unit 1 off.
  int texture1 = -1;
  GLenum texEnv1 = GL_MODULATE;
  Combine combine1;
  // Unit 1's texture matrix (glActiveTexture(GL_TEXTURE1); glMatrixMode(
  // GL_TEXTURE)): unit 1 reads textureMatrix1 x (s, t, r, q) as sent, e.g.
  // a light map moved over a wall (the reference applies it per vertex too).
  glm::mat4 textureMatrix1{1.0f};
  // true: unit 1 reads each vertex's own coordinates (Vertex::tex1), not unit 0's.
  bool coords1 = false;
  // glDepthFunc for this batch (with the panel's depth test): GL_LEQUAL lets
  // a second pass over the same geometry through (multipass); 0 = FixedState's GL_LESS.
  GLenum depthFunc = 0;
  // glDepthMask: false leaves the depth buffer as it was, so a transparent
  // layer drawn after the opaque ones (back to front) hides nothing drawn
  // after it.  The depth test still applies (the panel's).
  bool depthWrite = true;
  bool alphaTest() const { return alphaFunc != 0; }
  bool blendFactors() const { return blendSrc != 0 || blendDst != 0; }
};

// Viewport in pixels of the frame, origin at the top-left (as in the PNG).
struct Rect {
  int x = 0, y = 0, w = 0, h = 0;
  bool contains(int px, int py) const { return px >= x && py >= y && px < x + w && py < y + h; }
};

struct Panel {
  std::string id;
  Rect viewport;
  glm::mat4 projection{1.0f}, modelview{1.0f};
  bool depthTest = false;
  bool clear = false;
  glm::vec4 clearColor{0.0f};
  std::vector<Batch> batches;
};

enum class Align { Left, Center, Right };

struct Label {
  float x = 0, y = 0;  // pixels, top-left origin; y is the top of the text
  std::string text;
  glm::vec4 color{1.0f};
  int scale = 1;  // multiples of the 13-pixel base font
  Align align = Align::Left;
  glm::vec4 background{0.0f};  // alpha 0 = no box
  // Where the label's numbers come from, written in the sidecar so a check
  // can hold the picture to its own measurements:
  //   printed: each measurement the text prints, as its name, the printf
  //            format and the text that made (layout::measuredText fills it);
  //            the check formats the sidecar's value again and finds it here;
  //   given:   each number it prints that is not measured (an axis tick, a
  //            parameter of the state, a constant of the method), named.
  struct Printed {
    std::string name, format, text;
  };
  std::vector<Printed> printed{};
  std::vector<std::pair<std::string, double>> given{};
};

// A colour that carries meaning in a figure (a mark, a curve, a highlight)
// and what it means: drawn as a key by layout::legend and written in the
// sidecar, so a check can find every meaningful colour named.
struct LegendEntry {
  glm::vec4 color{1.0f};
  std::string meaning;
};

// The fixed state common/gl/render.cpp draws every Frame with, written into the
// sidecar so that a reader knows it without reading the renderer.
struct FixedState {
  static constexpr GLenum blendSrc = GL_SRC_ALPHA, blendDst = GL_ONE_MINUS_SRC_ALPHA;  // colour
  static constexpr GLenum blendSrcAlpha = GL_ZERO, blendDstAlpha = GL_ONE;             // alpha: stays opaque
  static constexpr GLenum depthFunc = GL_LESS;
  static constexpr GLenum shadeModel = GL_SMOOTH;
  static constexpr bool cullFace = false, lighting = false;
};

struct Frame {
  int width = 0, height = 0;
  glm::vec4 clearColor{0.0f, 0.0f, 0.0f, 1.0f};
  // glHint(GL_PERSPECTIVE_CORRECTION_HINT, ...) as the book sets it.  Mesa
  // ignores it (docs/platform.md, "GL_PERSPECTIVE_CORRECTION_HINT"); Figure VI.2 detects that and says so.
  GLenum perspectiveHint = GL_NICEST;
  std::vector<TextureDesc> textures;
  std::vector<std::pair<std::string, Program>> programs;
  std::vector<Panel> panels;
  std::vector<Label> labels;
  std::vector<LegendEntry> legend;

  int addTexture(TextureDesc t) {
    textures.push_back(std::move(t));
    return int(textures.size()) - 1;
  }
  const Panel* panel(const std::string& id) const {
    for (const auto& p : panels)
      if (p.id == id) return &p;
    return nullptr;
  }
};

// Builders for the common shapes.
Batch lineLoop(const std::vector<glm::vec2>& pts, glm::vec4 color, float width, std::string role);
Batch lineSegments(const std::vector<glm::vec2>& pts, glm::vec4 color, float width, std::string role);
// Maps a point of a panel's normalised device coordinates to frame pixels.
glm::vec2 panelToPixels(const Panel& p, glm::vec4 clip);
}  // namespace ts
