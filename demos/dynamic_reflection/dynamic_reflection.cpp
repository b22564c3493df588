// Dynamic reflection: a cube map rendered from the mirror's centre every
// frame, against one made once (seed 001 §37-38: Greene's cube map, "render
// the scene 6 times from the centre with a 90° field of view ... even per
// frame"; the lab sheet §2.1; Buss VI.1's texture data made during rendering).
//
// The claim: an environment map is a picture of the world from one point at
// one time.  A ball moves near a mirror sphere; a cube map rendered at time 0
// keeps showing the ball where it was, one rendered this frame shows it where
// it is, up to the parallax between the sphere's centre (where the map is
// made) and its surface (where the reflection happens).  It costs six
// renders a frame, one a face, and each face needs its own camera: a face
// turned upside down or a 60 degree field of view puts the ball elsewhere.
// Which faces a reflector reads depends on its shape: a sphere all six, a
// flat mirror few.  And for a flat mirror the cube map is the wrong tool: its
// reflected directions barely change across it, so a few texels are spread
// over the whole mirror, and a near object is seen from the wrong place;
// rendering the scene mirrored in the mirror's plane is exact
// (dynamic_reflection_planar.hpp).
//
// Keys (each is also a flag, see --help):
//   w  the cube map's cameras: right | face_flipped (+Z upside down) | fov_60 (60 instead of 90 degrees)
//   ] / [  time forward / back (--time)     a  animate the ball (window)     + / -  texels a face's side
//   v  view: scene (dynamic | static | traced | the faces) | variants (right | flipped | fov 60 | traced)
//      | faces (sphere, flat mirror, torus reading a cube map of six flat colours)
//      | planar (the flat mirror rendered mirrored | its cube map | traced | the cube texels it reads)
//
// The equations.  Face f of the cube map holds the world in direction
// cubeDir(f, s, t) (GL spec's face table, dynamic_reflection_math.hpp): its
// camera sits at the sphere's centre, looks along the face's axis with the
// table's right and up, gluPerspective(90, 1, near, far), since tan 45 = 1
// puts the face's edges on the cube's.  The mirror reads the map by
// r = u - 2 (n.u) n (u from the eye to the surface point, n the unit normal):
// GL_REFLECTION_MAP texgen, eye space, turned into the world's by the texture
// matrix.  The traced reference follows each pixel's ray: it meets the
// sphere at P, leaves along r from P (not from the centre), and shows the
// ball if that ray meets it.
//
// What the GL does (dynamic_reflection_views.hpp, dynamic_reflection_gl.hpp): the cube map made once with
//   glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA8, w, w, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL)
// then each frame, into a framebuffer object, per face
//   glViewport(0, f w, w, w); glMatrixMode(GL_PROJECTION); glLoadMatrixf(gluPerspective(90, 1, ...));
//   glMatrixMode(GL_MODELVIEW); glLoadMatrixf(the face's gluLookAt); draw the environment and the ball
// and each face copied on the GPU, no CPU round trip, by
//   glCopyTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, 0, 0, x, y, w, w)
// (read back by glGetTexImage only for the faces picture), and the mirror drawn with
// glTexGeni(GL_S/T/R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP), glEnable(GL_TEXTURE_CUBE_MAP).  The planar
// mirror: the scene drawn with glLoadMatrixf(V R), R = I - 2 n n^T, and glClipPlane(GL_CLIP_PLANE0, -n); then
// the mirror textured with that picture by glTexCoord4f(clip-space (x + w)/2, (y + w)/2, 0, w).  Listings:
// book_figures/dynamic_reflection.gl.txt, dynamic_reflection_variants.gl.txt, dynamic_reflection_faces.gl.txt,
// dynamic_reflection_planar.gl.txt (each picture's passes, then the frame).
//
// Measured (measure()): the mirror sphere drawn at 256 x 256 reading cube maps whose passes draw the ball
// in pure red on black, the pixels that show the ball (red > 1/2) against the traced reference's, counted
// where they disagree: moving_ball_error_px[static | dynamic | face_flipped | fov_60], and [parallax_free]: the
// dynamic map against a trace whose reflected rays leave from the centre, as the map's do (what is left is
// resolution and per-vertex r; what it removes is the parallax);
// cube_map_renders_per_frame counted from the recorded calls (the face-sized glViewport calls of one
// cube pass); faces_read[reflector], the distinct face colours in a render reading the face-ID cube map;
// for the flat mirror with a near ball, flat_mirror_error_px[planar | cube_map] the same way against its trace,
// and flat_mirror_texels_read (distinct texels in a render reading a texel-ID cube map, GL_NEAREST) against
// flat_mirror_pixels, their ratio flat_mirror_magnification.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <tuple>

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/text.hpp"
#include "common/core/textures.hpp"
#include "common/gl/gl_listing.hpp"
#include "common/gl/render.hpp"
#include "dynamic_reflection_gl.hpp"
#include "dynamic_reflection_math.hpp"
#include "dynamic_reflection_planar.hpp"
#include "dynamic_reflection_textures.hpp"
#include "dynamic_reflection_views.hpp"

namespace {
using namespace dynref;
enum View { kSceneView, kVariantsView, kFacesView, kPlanarView };
constexpr int kMeasureSize = 256;  // the measurement's pictures, pixels a side

// The pictures measure() made, for build().
struct Found {
  ts::TextureDesc dynamicPic, staticPic, reference, faces;
  ts::TextureDesc variantPics[kVariants];
  ts::TextureDesc reflectorPics[kReflectors];
  ts::TextureDesc planarPic, flatCubePic, flatReference, texelIds;  // the planar view's
};

// A picture GL drew in measure() (or the CPU traced), shown as a texture; its calls go to the listing.
ts::TextureDesc picture(const ts::Image& img, const std::string& what, ts::gl::CallList gl = nullptr) {
  ts::TextureDesc t = ts::renderedImageTexture(img, "dynamic_reflection_render", what, "dynamic_reflection");
  t.renderedBy = std::move(gl);
  return t;
}
// The six faces laid out to be looked at: +X -X +Y over -Y +Z -Z, each with t down as GL stores it.
ts::Image unwrapped(const ts::Image& stacked) {
  const int w = stacked.width;
  ts::Image out(3 * w, 2 * w);
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < w; ++y)
      for (int x = 0; x < w; ++x) out.set((f % 3) * w + x, (f / 3) * w + y, stacked.at(x, f * w + y));
  return out;
}

class DynamicReflection final : public ts::Scene {
 public:
  std::string id() const override { return "dynamic_reflection"; }
  std::string title() const override { return "Dynamic reflection: a cube map rendered every frame"; }
  std::string about() const override {
    return "A mirror sphere reflecting a moving ball through a cube map rendered from its centre, six 90-degree\n"
           "renders a frame, against a map made once and a CPU ray-traced reference.  Measured: the pixels where\n"
           "the ball's reflection disagrees with the traced one (static map, dynamic map, a face flipped, a 60-degree\n"
           "field of view), the renders a frame, and the faces a sphere, a flat mirror and a torus read.";
  }
  int defaultWidth() const override { return 1200; }
  int defaultHeight() const override { return 420; }
  std::vector<std::string> claim() const override {
    return {"moving_ball_error_px[static]", "moving_ball_error_px[dynamic]"};
  }
  void addOptions(ts::Options& o) override {
    o.addEnum("variant", &variant_, {"right", "face_flipped", "fov_60"},
              "the cube map's cameras: right, the +Z face upside down, or a 60-degree field of view", 'w');
    o.addFloat("time", &time_, 0.0f, 4.0f, "the ball's time: it goes round the sphere 30 degrees a unit", ']', '[',
               0.25f);
    o.addEnum("view", &view_, {"scene", "variants", "faces", "planar"},
              "scene: dynamic | static | traced | faces; variants: the cameras; faces: the faces each reflector reads; "
              "planar: a flat mirror rendered mirrored against the cube map's",
              'v');
    o.addBool("animate", &animate_, "move the ball (window)", 'a');
    o.addInt("face", &face_, 16, 512, "texels along a cube face's side", '+', '-', 16);
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {{"dynamic_reflection",
             "Dynamic cube map (seed 001)",
             "A mirror sphere and a ball moving round it. A cube map made at time 0 still shows the ball where it was; "
             "one rendered this frame from the sphere's centre (six 90-degree renders) shows it where it is, up to "
             "the parallax between the centre and the surface; the traced reference follows each ray from the "
             "surface.",
             {},
             1200,
             420,
             "The ball's reflection is wrong in {moving_ball_error_px[static]} pixels with the map of time 0, "
             "{moving_ball_error_px[dynamic]} with the map rendered this frame ({cube_map_renders_per_frame} renders "
             "a frame)."},
            {"dynamic_reflection_variants",
             "Dynamic cube map: wrong cameras (seed 001)",
             "The cube map rendered this frame with the right cameras, with the +Z face upside down (every side face "
             "given up = +Y), and with a 60-degree field of view instead of 90: the ball lands elsewhere.",
             {"--view", "variants"},
             1200,
             420,
             "Pixels wrong: right cameras {moving_ball_error_px[dynamic]}, +Z flipped "
             "{moving_ball_error_px[face_flipped]}, 60-degree field of view {moving_ball_error_px[fov_60]}."},
            {"dynamic_reflection_faces",
             "Dynamic cube map: the faces each reflector reads (lab sheet)",
             "A sphere, a flat mirror and a torus reading a cube map whose faces are six flat colours: the sphere "
             "reads every face, the flat mirror few, so rendering only the faces read saves renders.",
             {"--view", "faces"},
             1200,
             420,
             "Faces read: sphere {faces_read[sphere]}, flat mirror {faces_read[flat_mirror]}, torus "
             "{faces_read[torus]}."},
            {"dynamic_reflection_planar",
             "Planar reflection by rendering (seed 001, lab sheet)",
             "A flat mirror with a small ball in front of it: the scene rendered mirrored in the mirror's plane "
             "(reflection matrix, clip plane) and mapped back onto the mirror, against the cube map rendered at the "
             "mirror's centre; the cube map's texels read, each texel its own colour, show how few there are.",
             {"--view", "planar"},
             1200,
             420,
             "Ball pixels wrong: rendered mirrored {flat_mirror_error_px[planar]}, cube map "
             "{flat_mirror_error_px[cube_map]}; the cube map's {flat_mirror_texels_read} texels cover "
             "{flat_mirror_pixels} pixels ({flat_mirror_magnification} pixels a texel)."}};
  }
  // The animation steps the `time` option itself, a quarter unit every 1.5 s, a few of measure()'s frames
  // (below).  The first kHoldFrames frames after the key are left still, so the state printed for the key is the
  // picture's however long a frame takes (a busy machine's frames can each take longer than a step).
  void update(double seconds) override {
    if (!animate_) {
      animFrames_ = 0, animClock_ = 0;
      return;
    }
    if (++animFrames_ < kHoldFrames) return;
    animClock_ += seconds;
    if (animClock_ < kAnimStepSeconds) return;
    animClock_ = 0;
    time_ = float(std::fmod(time_ + 0.25, 4.0));
  }
  bool animating() const override { return animate_; }
  // The pictures are measure()'s renders, and the window measures again only after a key: while the ball
  // moves, measure() runs every frame (about half a second each), as a live view's does.
  bool live() const override { return animate_; }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override;

 private:
  void measurePlanar(ts::Renderer& r, ts::Measurements& out, Found& found) const;
  float time_ = 1.5f;
  static constexpr double kAnimStepSeconds = 1.5;
  static constexpr int kHoldFrames = 8;  // more than the frames a window test takes after a key (3)
  int variant_ = kRight, view_ = kSceneView, face_ = 128, animFrames_ = 0;
  double animClock_ = 0;
  bool animate_ = false;
};

// The ball's pixels in a measurement render (red over half) against the traced ones: the disagreements.
int ballError(const ts::Image& img, double time, bool fromCentre = false) {
  int wrong = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const Seen s = trace(x, y, img.width, time, nullptr, fromCentre);
      if (s == kOff) continue;
      wrong += (img.at(x, y).r > 127) != (s == kBall);
    }
  return wrong;
}

ts::Measurements DynamicReflection::measure(ts::Renderer& r) {
  ts::Measurements out;
  Found found;
  const double t = time_;
  // "Ball or not": the cube passes draw the ball red on black; the sphere reads each map.
  auto maskError = [&](double mapTime, int variant, bool fromCentre = false) {
    const GLuint cube = makeCubeMap(face_);
    renderIntoCube(r, cubeFrame(face_, ballCentre(mapTime), variant, kMask, kBallRadius, true), cube);
    const ts::Image eye = r.renderOffscreen(
        eyeFrame(kMeasureSize, cubeMapTexture(cube, "mask"), kSphere, false, ballCentre(t)));
    glDeleteTextures(1, &cube);
    return ballError(eye, t, fromCentre);
  };
  out.push_back({"moving_ball_error_px[static]", double(maskError(0.0, kRight)),
                 "pixels of the mirror sphere (256 x 256 picture) where the ball's reflection through a cube map "
                 "made at time 0 disagrees with the traced reference"});
  out.push_back({"moving_ball_error_px[dynamic]", double(maskError(t, kRight)),
                 "the same with the cube map rendered this frame"});
  out.push_back({"moving_ball_error_px[parallax_free]", double(maskError(t, kRight, true)),
                 "the map rendered this frame against a reference whose reflected rays leave from the sphere's "
                 "centre, as the map's do: what is left of the dynamic error without the parallax"});
  ts::measureProgress(0.3);
  out.push_back({"moving_ball_error_px[face_flipped]", double(maskError(t, kFaceFlipped)),
                 "the same, the map rendered this frame with the +Z face's camera upside down"});
  out.push_back({"moving_ball_error_px[fov_60]", double(maskError(t, kFov60)),
                 "the same, the map rendered this frame with a 60-degree field of view per face"});
  int ballPx = 0;
  for (int y = 0; y < kMeasureSize; ++y)
    for (int x = 0; x < kMeasureSize; ++x) ballPx += trace(x, y, kMeasureSize, t) == kBall;
  out.push_back({"ball_reflection_px", double(ballPx), "pixels of the traced reference showing the ball"});
  ts::measureProgress(0.5);

  // The pictures: the cube pass in colour, its calls recorded (the renders a frame are counted from them).
  // The cube map it draws into is the caller's to delete (eyePicture does).
  auto colourCube = [&](double mapTime, int variant, ts::gl::CallList* gl) {
    GLuint cube = 0;
    const ts::gl::CallList calls = ts::recordRender(r, [&] {
      cube = makeCubeMap(face_);
      renderIntoCube(r, cubeFrame(face_, ballCentre(mapTime), variant, kColours, kBallRadius, true), cube);
    });
    if (gl) *gl = calls;
    return cube;
  };
  // The mirror's picture, GL's, with the Frames that describe it (nested frames the CPU reference recomputes):
  // the eye pass reading the cube map, and the cube pass whose render is that map's six faces stacked.  Each is
  // checked here against what GL drew (pass_frame_mismatch_px).
  auto mismatch = [](const ts::Image& a, const ts::Image& b) {  // pixels more than a level apart
    int n = 0;
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) {
        const ts::Rgba p = a.at(x, y), q = b.at(x, y);
        n += std::abs(p.r - q.r) > 1 || std::abs(p.g - q.g) > 1 || std::abs(p.b - q.b) > 1;
      }
    return n;
  };
  auto eyePicture = [&](GLuint cube, const std::string& what, ts::gl::CallList cubeGL, double mapTime, int variant) {
    ts::Image img;
    const ts::gl::CallList eyeGL = ts::recordRender(r, [&] {
      img = r.renderOffscreen(eyeFrame(kMeasureSize, cubeMapTexture(cube, what), kSphere, true, ballCentre(t)));
    });
    ts::TextureDesc faces;
    faces.name = "dynamic_reflection_cube_pass";
    faces.params = {{"pass", what}};
    faces.cube = true;
    faces.image = std::make_shared<const ts::Image>(readCubeMap(cube, face_));
    faces.renderedFrom = std::make_shared<const ts::Frame>(
        cubeFrame(face_, ballCentre(mapTime), variant, kColours, kBallRadius, false));
    faces.minFilter = faces.magFilter = GL_LINEAR;
    faces.wrapS = faces.wrapT = GL_CLAMP_TO_EDGE;
    glDeleteTextures(1, &cube);
    const ts::Frame eye = eyeFrame(kMeasureSize, faces, kSphere, true, ballCentre(t));
    out.push_back({"pass_frame_mismatch_px[" + what + "_eye]", double(mismatch(r.renderOffscreen(eye), img)),
                   "pixels where the Frame describing the " + what +
                       " mirror's eye pass (the sidecar's nested "
                       "frame, the faces uploaded from GL's) renders more than a level off the pass's own picture"});
    out.push_back({"pass_frame_mismatch_px[" + what + "_faces]",
                   double(mismatch(r.renderOffscreen(*faces.renderedFrom), *faces.image)),
                   "texels where the Frame describing the " + what +
                       " cube pass (y negated: its picture is the six "
                       "faces stacked) renders more than a level off the faces GL copied on the GPU"});
    std::vector<ts::gl::Call> calls = cubeGL ? *cubeGL : std::vector<ts::gl::Call>{};
    calls.insert(calls.end(), eyeGL->begin(), eyeGL->end());
    ts::TextureDesc shown = ts::nestedPictureTexture(img, eye, "dynamic_reflection_pass", what);
    shown.minFilter = shown.magFilter = GL_NEAREST;  // as the traced picture beside it
    shown.renderedBy = std::make_shared<const std::vector<ts::gl::Call>>(std::move(calls));
    return shown;
  };
  ts::gl::CallList dynGL;
  const GLuint dynCubeMap = colourCube(t, variant_, &dynGL);
  const ts::Image dynCube = readCubeMap(dynCubeMap, face_);  // the faces picture needs its texels
  int renders = 0;
  for (const ts::gl::Call& c : *dynGL)
    if (std::string(c.name) == "glViewport" && c.args.size() == 4 && c.args[2].i == face_ && c.args[3].i == face_)
      ++renders;
  out.push_back({"cube_map_renders_per_frame", double(renders),
                 "face-sized glViewport calls recorded in one dynamic cube-map pass: one render a face"});
  found.dynamicPic = eyePicture(dynCubeMap, "dynamic", dynGL, t, variant_);
  found.faces = picture(unwrapped(dynCube), "faces");
  out.push_back(
      {"pass_frame_control_px[faces_a_second_later]",
       double(mismatch(r.renderOffscreen(cubeFrame(face_, ballCentre(t + 1), variant_, kColours, kBallRadius, false)),
                       dynCube)),
       "texels where the cube pass's Frame a second later (the ball moved on) renders more than a level off "
       "this frame's faces (a control that must find some)"});
  if (view_ == kSceneView) {
    ts::gl::CallList staticGL;
    found.staticPic = eyePicture(colourCube(0.0, kRight, &staticGL), "static", staticGL, 0.0, kRight);
  }
  if (view_ == kVariantsView)
    for (int v = 0; v < kVariants; ++v) {
      ts::gl::CallList gl;
      found.variantPics[v] = eyePicture(colourCube(t, v, &gl), kVariantKeys[v], gl, t, v);
    }
  // The traced reference in colour: the world in r, or the ball; off the sphere the background.
  ts::Image ref(kMeasureSize, kMeasureSize);
  for (int y = 0; y < kMeasureSize; ++y)
    for (int x = 0; x < kMeasureSize; ++x) {
      glm::dvec3 rr;
      const Seen s = trace(x, y, kMeasureSize, t, &rr);
      ref.set(x, y,
              s == kOff    ? ts::envmaps::toRgba(ts::envmaps::kBackground)
              : s == kBall ? ts::envmaps::toRgba(glm::dvec3(kBallColour))
                           : ts::envmaps::toRgba(ts::envmaps::worldColour(rr)));
    }
  found.reference = picture(ref, "traced reference");
  ts::measureProgress(0.7);

  // Which faces each reflector reads: drawn with the face-ID cube map (GL_NEAREST), its colours counted.
  for (int k = 0; k < kReflectors; ++k) {
    ts::Image img;
    const ts::gl::CallList gl = ts::recordRender(r, [&] {
      img = r.renderOffscreen(eyeFrame(kMeasureSize, faceIdCube(), k, false, ballCentre(t)));
    });
    std::set<int> faces;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        for (int f = 0; f < 6; ++f) {
          const ts::Rgba p = img.at(x, y), c = kFaceIds[f];
          if (p.r == c.r && p.g == c.g && p.b == c.b) faces.insert(f);
        }
    out.push_back({std::string("faces_read[") + kReflectorKeys[k] + "]", double(faces.size()),
                   "distinct face colours in a 256 x 256 render of this reflector reading the face-ID cube map"});
    found.reflectorPics[k] = picture(img, std::string("face ids ") + kReflectorKeys[k], gl);
  }
  ts::measureProgress(0.85);
  measurePlanar(r, out, found);
  out.detail = found;
  return out;
}

// The flat mirror: rendered mirrored against the cube map made at its centre, both against the trace; the
// cube map's texels it reads, counted from a render reading the texel-ID cube map.
void DynamicReflection::measurePlanar(ts::Renderer& r, ts::Measurements& out, Found& found) const {
  const int n = kMeasureSize;
  const glm::dvec3 ball = nearBall();
  auto flatError = [&](const ts::Image& img) {
    int wrong = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Seen s = traceFlat(x, y, n);
        if (s != kOff) wrong += (img.at(x, y).r > 127) != (s == kBall);
      }
    return wrong;
  };
  // The planar mirror's passes, and (with `described`) the Frame of the mirror's pass with the mirrored pass nested
  // in it, as the sidecar holds them.
  auto planar = [&](int content, ts::gl::CallList* gl, ts::Frame* described = nullptr) {
    ts::Image img, mirrored;
    *gl = ts::recordRender(r, [&] {
      mirrored = r.renderOffscreen(mirroredFrame(n, content));
      img = r.renderOffscreen(planarMirrorFrame(n, picture(mirrored, "mirrored pass"), content == kColours));
    });
    if (described) {
      ts::TextureDesc nested = ts::nestedPictureTexture(mirrored, mirroredFrame(n, content), "dynamic_reflection_pass",
                                                        "mirrored pass");
      nested.minFilter = nested.magFilter = GL_NEAREST;  // as the pass read it
      *described = planarMirrorFrame(n, nested, content == kColours);
    }
    return img;
  };
  auto cubeMirror = [&](int content, ts::gl::CallList* gl, ts::Frame* described = nullptr) {
    ts::Image img;
    GLuint cube = 0;
    *gl = ts::recordRender(r, [&] {
      cube = makeCubeMap(face_);
      renderIntoCube(r, cubeFrame(face_, ball, kRight, content, kNearBallRadius, true), cube);
      img = r.renderOffscreen(eyeFrame(n, cubeMapTexture(cube, "flat mirror cube"), kFlatMirror, content == kColours,
                                       ball, kNearBallRadius));
    });
    if (described) {  // the eye pass with the cube pass nested in it (its render the six faces), as for the sphere
      ts::TextureDesc faces;
      faces.name = "dynamic_reflection_cube_pass";
      faces.params = {{"pass", "flat mirror cube"}};
      faces.cube = true;
      faces.image = std::make_shared<const ts::Image>(readCubeMap(cube, face_));
      faces.renderedFrom = std::make_shared<const ts::Frame>(
          cubeFrame(face_, ball, kRight, content, kNearBallRadius, false));
      faces.minFilter = faces.magFilter = GL_LINEAR;
      faces.wrapS = faces.wrapT = GL_CLAMP_TO_EDGE;
      *described = eyeFrame(n, faces, kFlatMirror, content == kColours, ball, kNearBallRadius);
    }
    glDeleteTextures(1, &cube);
    return img;
  };
  ts::gl::CallList gl;
  out.push_back({"flat_mirror_error_px[planar]", double(flatError(planar(kMask, &gl))),
                 "pixels of the flat mirror (256 x 256 picture) where the near ball's reflection, rendered mirrored "
                 "(reflection matrix, clip plane), disagrees with the traced reference"});
  out.push_back({"flat_mirror_error_px[cube_map]", double(flatError(cubeMirror(kMask, &gl))),
                 "the same with a cube map rendered at the mirror's centre this frame"});
  int ballPx = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) ballPx += traceFlat(x, y, n) == kBall;
  out.push_back({"flat_mirror_ball_px", double(ballPx), "pixels of the traced flat mirror showing the near ball"});
  // The texels read: the mirror drawn with the texel-ID cube map, cleared to a colour no texel has.
  ts::Frame ids = eyeFrame(n, texelIdCube(face_), kFlatMirror, false, ball, kNearBallRadius);
  ids.clearColor = {0, 0, 1, 1};
  ts::Image idImg;
  const ts::gl::CallList idGL = ts::recordRender(r, [&] { idImg = r.renderOffscreen(ids); });
  std::set<std::tuple<int, int, int>> texels;
  int pixels = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const ts::Rgba p = idImg.at(x, y);
      if (p.b == 255) continue;
      ++pixels;
      texels.insert({p.r, p.g, p.b});
    }
  out.push_back({"flat_mirror_pixels", double(pixels), "pixels the flat mirror covers (256 x 256 picture)"});
  out.push_back({"flat_mirror_texels_read", double(texels.size()),
                 "distinct cube-map texels the flat mirror reads (texel-ID cube map, GL_NEAREST)"});
  out.push_back({"flat_mirror_magnification", double(pixels) / double(std::max<size_t>(1, texels.size())),
                 "flat_mirror_pixels / flat_mirror_texels_read: pixels a texel read"});
  if (view_ != kPlanarView) return;
  // The two mirrors' pictures with the Frames the sidecar nests, each checked against what GL drew.
  ts::gl::CallList planarGL, cubeGL;
  ts::Frame planarFrame, cubeFrameDescribed;
  const ts::Image planarImg = planar(kColours, &planarGL, &planarFrame);
  const ts::Image cubeImg = cubeMirror(kColours, &cubeGL, &cubeFrameDescribed);
  auto nestedPicture = [&](const ts::Image& img, const ts::Frame& described, const std::string& what,
                           const ts::gl::CallList& gl) {
    int off = 0;
    const ts::Image own = r.renderOffscreen(described);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const ts::Rgba p = own.at(x, y), q = img.at(x, y);
        off += std::abs(p.r - q.r) > 1 || std::abs(p.g - q.g) > 1 || std::abs(p.b - q.b) > 1;
      }
    out.push_back({"pass_frame_mismatch_px[" + what + "]", double(off),
                   "pixels where the Frame describing the " + what +
                       " pass (the sidecar's nested frame) renders more "
                       "than a level off the pass's own picture"});
    ts::TextureDesc t = ts::nestedPictureTexture(img, described, "dynamic_reflection_pass", what);
    t.minFilter = t.magFilter = GL_NEAREST;  // as the traced picture beside it
    t.renderedBy = gl;
    return t;
  };
  found.planarPic = nestedPicture(planarImg, planarFrame, "planar", planarGL);
  found.flatCubePic = nestedPicture(cubeImg, cubeFrameDescribed, "flat_mirror_cube", cubeGL);
  // Shown with a colour of its own per texel (a hash of its ID), so neighbours differ and each texel's
  // patch of pixels shows; off the mirror the page's background.
  ts::Image shownIds(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const ts::Rgba p = idImg.at(x, y);
      uint32_t h = (uint32_t(p.r) * 73856093u) ^ (uint32_t(p.g) * 19349663u) ^ (uint32_t(p.b) * 83492791u);
      h = (h ^ (h >> 13)) * 0x5bd1e995u;
      shownIds.set(x, y,
                   p.b == 255
                       ? ts::envmaps::toRgba(ts::envmaps::kBackground)
                       : ts::Rgba{uint8_t(60 + (h & 0xff) * 195 / 255), uint8_t(60 + ((h >> 8) & 0xff) * 195 / 255),
                                  uint8_t(60 + ((h >> 16) & 0xff) * 195 / 255), 255});
    }
  found.texelIds = picture(shownIds, "texel ids", idGL);
  ts::Image ref(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      glm::dvec3 rr;
      const Seen s = traceFlat(x, y, n, &rr);
      ref.set(x, y,
              s == kOff    ? ts::envmaps::toRgba(ts::envmaps::kBackground)
              : s == kBall ? ts::envmaps::toRgba(glm::dvec3(kBallColour))
                           : ts::envmaps::toRgba(ts::envmaps::worldColour(rr)));
    }
  found.flatReference = picture(ref, "flat mirror traced");
}

// A variant's title, its field of view a given number.
ts::layout::Text variantTitle(int v) {
  namespace L = ts::layout;
  const L::Text fov = L::given("field of view of a cube map face, degrees", faceFovDeg(v), "%.0f");
  if (v == kFaceFlipped) return "+Z face upside down";
  if (v == kFov60) return fov + " deg per face";
  return "right: " + fov + " deg, spec's table";
}

ts::Frame DynamicReflection::build(int width, int height, const ts::Measurements& measured) const {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(width, height);
  const Found* found = measured.detailAs<Found>();
  // One cell a picture: its panel, title, key (under the title) and the measured note below it.
  struct CellSpec {
    std::string id;
    const ts::TextureDesc* tex;
    L::Text title, note;
    std::vector<ts::LegendEntry> key;
  };
  std::vector<CellSpec> cells;
  auto add = [&](const std::string& id, const ts::TextureDesc* tex, const L::Text& title, const L::Text& note,
                 const std::vector<ts::LegendEntry>& key = {}) {
    cells.push_back({id, found ? tex : nullptr, title, note, key});
  };
  const std::vector<ts::LegendEntry> ballKey = {{kBallColour, "the ball"}};
  // The world's colours encode the direction (common/core/env_maps.hpp): its base colour toward each axis.
  auto toward = [](glm::dvec3 d) { return glm::vec4(glm::vec3(ts::envmaps::directionColour(d)), 1.0f); };
  const std::vector<ts::LegendEntry> worldKey = {{toward({1, 0, 0}), "to +X"},
                                                 {toward({0, 1, 0}), "to +Y"},
                                                 {toward({0, 0, 1}), "to +Z"}};
  auto err = [&](const std::string& k) {
    return L::measuredText(measured, "{moving_ball_error_px[" + k + "]|%.0f} px wrong");
  };
  const Found none;
  const Found& pics = found ? *found : none;
  if (view_ == kFacesView) {
    const char* titles[] = {"sphere", "flat mirror", "torus"};
    for (int k = 0; k < kReflectors; ++k) {
      std::vector<ts::LegendEntry> key;
      for (int face = 3 * k; face < 3 * k + 3 && k < 2; ++face)
        key.push_back({faceIdColour(face), std::string("face ") + ts::envmaps::kFaceNames[face]});
      if (k == 2) key.push_back({{0, 0, 0, 1}, "no reflector"});
      add(std::string("faces_") + kReflectorKeys[k], &pics.reflectorPics[k],
          std::string(titles[k]) + ": a flat colour a face",
          L::measuredText(measured, std::string("faces read: {faces_read[") + kReflectorKeys[k] + "]|%.0f} of ") +
              L::given("faces of a cube map", 6, "%.0f"),
          key);
    }
  } else if (view_ == kPlanarView) {
    add("planar", &pics.planarPic, "rendered mirrored",
        L::measuredText(measured, "{flat_mirror_error_px[planar]|%.0f} px wrong"), ballKey);
    add("cube_map", &pics.flatCubePic, "cube map at its centre",
        L::measuredText(measured, "{flat_mirror_error_px[cube_map]|%.0f} px wrong"), worldKey);
    add("reference", &pics.flatReference, "traced from the surface",
        L::measuredText(measured, "the ball: {flat_mirror_ball_px|%.0f} px"));
    add("texels", &pics.texelIds, "cube texels read",
        L::measuredText(measured, "{flat_mirror_texels_read|%.0f} texels over {flat_mirror_pixels|%.0f} px: "
                                  "{flat_mirror_magnification|%.1f} px a texel"));
  } else if (view_ == kVariantsView) {
    const char* keys[] = {"dynamic", "face_flipped", "fov_60"};
    for (int v = 0; v < kVariants; ++v)
      add(std::string("variant_") + kVariantKeys[v], &pics.variantPics[v], variantTitle(v), err(keys[v]),
          v == 0 ? ballKey : std::vector<ts::LegendEntry>{});
    add("reference", &pics.reference, "traced from the surface",
        L::measuredText(measured, "the ball: {ball_reflection_px|%.0f} px"));
  } else {
    const std::string shownKey = variant_ == kRight ? "dynamic" : kVariantKeys[variant_];
    add("dynamic", &pics.dynamicPic, variant_ == kRight ? L::Text("this frame's cube map") : variantTitle(variant_),
        err(shownKey), ballKey);
    add("static", &pics.staticPic, "cube map of time " + L::given("time the static map was made", 0, "%.0f"),
        err("static"), worldKey);
    add("reference", &pics.reference, "traced from the surface",
        L::measuredText(measured, "the ball: {ball_reflection_px|%.0f} px"));
    add("faces", &pics.faces, "its six faces (t down)",
        L::measuredText(measured, "{cube_map_renders_per_frame|%.0f} renders a frame"));
  }
  L::FlowSpec spec;
  spec.n = int(cells.size()), spec.linesAbove = 2, spec.linesBelow = 2, spec.gap = 10;
  // As wide as the widest title or key needs at the smallest scale: a small window stacks the pictures in
  // rows rather than cut their titles and keys.
  for (const CellSpec& c : cells) {
    float keyWidth = 0;  // layout::legend's: a swatch, 4 px, the meaning, 8 px to the next
    for (const ts::LegendEntry& e : c.key)
      keyWidth += (keyWidth > 0 ? 8 : 0) + ts::text::height(1) + 4 + ts::text::width(e.meaning, 1);
    spec.minCellWidth = std::max({spec.minCellWidth, ts::text::width(c.title.text, 1) + 8, keyWidth});
  }
  const std::vector<L::Cell> flow = L::flow({6, 6, float(width) - 6, float(height) - 6}, spec);
  for (size_t k = 0; k < cells.size(); ++k) {
    const L::Cell& c = flow[k];
    const CellSpec& s = cells[k];
    if (s.tex && s.tex->image) {
      ts::Rect pic = c.picture;
      if (s.tex->image->width != s.tex->image->height)  // the unwrapped faces: 3:2 inside the square cell
        pic = L::centred(c.picture, c.picture.w, c.picture.w * s.tex->image->height / s.tex->image->width);
      f.panels.push_back(L::picturePanel(f, s.id, pic, *s.tex));
    }
    if (s.key.empty()) {
      L::caption(f, c.above, s.title, L::kWhite, c.scale);
    } else {
      L::caption(f, L::halves(c.above).first, s.title, L::kWhite, c.scale);
      L::legend(f, L::halves(c.above).second, s.key, c.scale);
    }
    L::caption(f, c.below, s.note, L::kAmber, c.scale);
  }
  return f;
}
}  // namespace

TS_REGISTER_SCENE(DynamicReflection);
