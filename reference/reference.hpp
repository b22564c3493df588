// reference/reference.hpp — a Frame drawn on the CPU, without OpenGL, the
// way a conformant OpenGL implementation draws it (common/gl/render.cpp's
// state: per-panel viewport and scissor, the panel's matrices, glBegin with
// one glTexCoord4f/glColor4f per glVertex3f, the fixed-function texture
// environments GL_REPLACE, GL_MODULATE, GL_DECAL, GL_BLEND, GL_ADD with the
// environment colour, the texture matrix applied to each vertex's (s,t,r,q)
// before interpolation, GL_COLOR_SUM with the secondary colour, or the
// "bilinear_quad" program of demos/quad_distortion; a second
// texture unit with GL_COMBINE (combine.hpp), the alpha test, and a batch's
// own blend factors).
//
// It produces two things:
//   * image(): the reference picture — each covered pixel centre (scanline
//     rasterizer, raster.hpp) textured at its exact coordinate and LOD;
//   * for every pixel, the list of fragments that may legally end up there
//     (the "candidates"): normally one; near a triangle's boundary (within
//     RenderOptions::edgeBand pixels) both the triangle and whatever was
//     under it; under lines, points, labels, blended or unsupported batches
//     an exempt marker.  verify.hpp turns candidates into legal colour ranges.
//
// Vertex processing: clip = projection * modelview * (pos, 1); clipped to
// -w <= z <= w; window x = vx + (ndc.x + 1) vw / 2, GL window
// y = (H - vy - vh) + (ndc.y + 1) vh / 2 (the panel's top-left viewport made
// bottom-left exactly as render.cpp does), image y = H - GL y.
// Interpolation: Perspective (hyperbolic: a/w and 1/w screen-linear) — what
// GL does whatever GL_PERSPECTIVE_CORRECTION_HINT says — or Affine
// (screen-linear a), the "without" of Figure VI.2.  Texture coordinates are
// then divided by q.
#pragma once
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "geometry.hpp"
#include "raster.hpp"
#include "sampler.hpp"
#include "volume.hpp"

namespace ref {
enum class Interpolation { Perspective, Affine };
// Pixels near a triangle's boundary: checked against both sides (Union) or
// not checked (Exempt).
enum class EdgePolicy { Union, Exempt };

struct RenderOptions {
  Interpolation interpolation = Interpolation::Perspective;
  FillRule fill = FillRule::GLTopLeft;  // llvmpipe's, measured
  bool labels = true;                   // the image has labels: draw them, exempt their boxes
  bool labelGeometryKnown = true;       // false (a sidecar without label scale/align): exempt wide boxes
  double edgeBand = 1.0;                // pixels
  EdgePolicy edges = EdgePolicy::Union;
  double lineMargin = 1.0;  // exempt this many pixels beyond a line's or point's footprint
  LodModel lodModel = LodModel::Bounded;
  double lodMargin = 0.1;      // levels added on both sides of the LOD interval
  double depthEpsilon = 1e-5;  // window z closer than this: either fragment may win
  // Textures of the frame (indices) whose texels are not known: pictures a
  // sidecar cannot remake (SidecarScene::unknownPictures).  A batch that
  // reads one, on either unit, is exempt (Exempt::UnknownPicture).  The top
  // frame's only: a nested frame is drawn without them.
  std::vector<int> exemptTextures;
};

enum class Exempt : uint8_t { None, Line, Point, Label, Program, Blend, Unsupported, Edge, UnknownPicture, Count };
const char* exemptName(Exempt e);

struct Candidate {
  enum class Kind : uint8_t { Flat, Textured, Exempt };
  Kind kind = Kind::Flat;
  Exempt why = Exempt::None;
  bool modulate = false;       // GL_MODULATE: texture times colour
  GLenum env = GL_REPLACE;     // the texture environment (sampler.hpp's texEnv)
  bool colorSum = false;       // GL_COLOR_SUM: `secondary` added after texturing
  Colour envColour{};          // GL_TEXTURE_ENV_COLOR
  Colour secondary{};          // the fragment's secondary colour (alpha unused)
  int texture = -1;            // index into Reference::textures()
  int next = -1;               // the next candidate of the same pixel
  Colour colour{};             // flat colour, or the fragment's primary colour
  double s = 0, t = 0;         // texture coordinate after the division by q
  float lodLo = 0, lodHi = 0;  // lambda_base interval (without bias), margin included
  float rho = 0;               // texels per pixel (for position jitter)
  float z = 1;
  // A 3D texture (volume.hpp): Reference::volume(volume) samples it at
  // (s, t, r); `texture` is then its first slice.  -1: a 2D texture.
  int volume = -1;
  double r = 0;
  // A nested frame's picture, or a remade picture GL may round
  // its own way (TextureDesc::texelSlack, a DXT1 decode): how far GL's
  // texels may lie from the reference's, added to both ends of the legal ranges.
  float slack = 0;
  // Unit 1 (Batch::texture1): its texture (index into
  // Reference::textures(), -1 = off), read at (s, t) like unit 0, its LOD
  // interval and texels per pixel, and its environment over unit 0's result.
  int texture1 = -1;
  double s1 = 0, t1 = 0;  // unit 1's (s, t): Batch::textureMatrix1 (affine) x (s, t)
  float lodLo1 = 0, lodHi1 = 0, rho1 = 0;
  GLenum env1 = GL_MODULATE;
  ts::Combine combine1;
  // A fragment blended with a batch's own factors (Batch::blendSrc
  // / blendDst): its colour is blend(this fragment, what the
  // pixel held), `below` the first candidate of what it held (-1: the clear
  // colour); verify.cpp combines the two legal sets.
  bool blended = false;
  GLenum blendSrc = GL_ONE, blendDst = GL_ZERO;
  int below = -1;
  // Batch::depthWrite: false, its z hides nothing drawn later (glDepthMask(GL_FALSE)); what it was
  // drawn over (`below`, for a blended one) still does.
  bool writesDepth = true;
};

class Reference {
 public:
  Reference(const ts::Frame& frame, const RenderOptions& options = {});
  int width() const { return width_; }
  int height() const { return height_; }
  const ts::Image& image() const { return image_; }
  const RenderOptions& options() const { return opts_; }
  // The first candidate of pixel (x, y) (top-left origin), -1 = only the
  // frame's clear colour; follow Candidate::next.
  int head(int x, int y) const { return head_[size_t(y) * size_t(width_) + size_t(x)]; }
  const Candidate& candidate(int i) const { return pool_[size_t(i)]; }
  const Colour& clearColour() const { return clear_; }
  const std::vector<Texture>& textures() const { return textures_; }
  // The 3D textures a candidate's `volume` indexes (their slices are textures()).
  Volume volume(int i) const {
    Volume v = volumes_[size_t(i)];
    v.textures = &textures_;
    return v;
  }
  // Draws the frame's labels, exempt, into a reference made with
  // RenderOptions::labels off (for an image rendered with labels): in place,
  // as a copy of a whole figure's candidates costs more than the check.
  void addLabels(const ts::Frame& frame, bool geometryKnown = true);
  // Notes about what could not be modelled (unsupported programs etc.).
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  void drawPanel(const ts::Panel& p);
  void drawTriangles(const ts::Panel& p, const ts::Batch& b, PixelRect scissor);
  void drawLines(const ts::Panel& p, const ts::Batch& b, PixelRect scissor);
  void drawLabels(const ts::Frame& f);
  // Cube maps: each cube texture's six faces as 2D textures
  // appended to textures_, the first one's index in cubeFirstFace_ (-1: not
  // a cube); a fragment's face and (s, t) per GL 2.1 table 3.21.
  void addCubeFaces(const ts::Frame& f);
  bool cubeCandidate(const ScreenPoly& P, double x, double y, int firstFace, bool alternative, Candidate* c) const;
  Colour cubeSample(const ScreenPoly& P, double x, double y, int firstFace) const;
  std::vector<int> cubeFirstFace_;
  // 3D textures: each one's slices as 2D textures appended to textures_;
  // volumeOf_[frame texture] indexes volumes_ (-1: not 3D).
  void addVolumes(const ts::Frame& f);
  std::vector<Volume> volumes_;
  std::vector<int> volumeOf_;
  // Nested frames (TextureDesc::renderedFrom): the texture recomputed from
  // its frame, and how wide each texel's legal range is there (-1: unknown).
  struct NestedTexels {
    int w = 0, h = 0;
    std::vector<float> width;
    float tolerance = 0;
  };
  ts::TextureDesc nestedTexture(const ts::TextureDesc& t, size_t index);
  // The slack of a fragment at (s, t) of texture `texture` (0: not nested,
  // -1: it reads an unknown texel).
  float nestedSlack(int texture, double s, double t, double rho) const;
  std::vector<NestedTexels> nested_;
  // The alpha test: 1 when candidate c's alpha surely passes
  // batch b's test, 0 when it surely fails (the fragment is discarded: no
  // candidate), -1 when its legal alpha range straddles the reference value
  // (the fragment may or may not be there).
  int alphaVerdict(const ts::Batch& b, const Candidate& c) const;
  // depthFunc: GL_LESS, or GL_LEQUAL (a second pass over the same geometry passes where z is equal).
  void place(int x, int y, const Candidate& c, bool sure, bool depthTest, GLenum depthFunc = GL_LESS);
  void exemptDisc(double x, double y, double r, Exempt why, PixelRect clip);
  void note(const std::string& s);

  RenderOptions opts_;
  int width_ = 0, height_ = 0;
  ts::Image image_;
  std::vector<float> depth_;  // reference depth buffer (window z)
  std::vector<int> head_;
  std::vector<Candidate> pool_;
  std::vector<Texture> textures_;
  Colour clear_{};
  std::vector<std::string> notes_;
};

// Cube maps, GL 2.1 §3.8.6 table 3.21: the face of direction r
// is its major axis, +X -X +Y -Y +Z -Z = 0..5; *alt is the face of the next
// largest component when it is within a relative 1e-4 of the largest (where
// GL's float arithmetic may pick either), else -1.  On face f, (s, t) =
// ((sc/|ma| + 1)/2, (tc/|ma| + 1)/2), sc, tc and ma from the table:
//   +X: -r_z, -r_y, r_x   -X: r_z, -r_y, -r_x   +Y: r_x, r_z, r_y
//   -Y: r_x, -r_z, -r_y   +Z: r_x, -r_y, r_z    -Z: -r_x, -r_y, -r_z
int cubeFace(const glm::dvec3& r, int* alt);

// The alpha test and blend factors (Batch::alphaFunc, blendSrc/
// blendDst): does `alpha` pass glAlphaFunc(func, ref) (ref clamped to
// [0, 1]); the colour src * srcFactor + dst * dstFactor per channel,
// clamped, alpha the framebuffer's (FixedState's alpha factors).
bool alphaPasses(GLenum func, float alpha, float ref);
Colour blendWith(GLenum srcFactor, GLenum dstFactor, const Colour& src, const Colour& dst);
void cubeFaceCoord(int face, const glm::dvec3& r, double* s, double* t);

// The image rectangle a label covers as render.cpp draws it (text plus
// background padding), in pixels [x0, x1) x [y0, y1), with `margin` around.
PixelRect labelBox(const ts::Label& l, int margin, bool geometryKnown);
// Draws a label as render.cpp does (background box, then the text) into
// `img`, whose pixel (0, 0) is pixel (ox, oy) of the frame: the whole
// frame's image, or a part of it.
void paintLabel(ts::Image& img, const ts::Label& l, int ox, int oy);
}  // namespace ref
