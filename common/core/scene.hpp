// common/core/scene.hpp — what a demo implements.  One Scene subclass per demo,
// in demos/<name>/<name>.cpp (its math, GL and measurement in headers beside
// it); figures() lists the book figures it renders, each a set of flags.
// Everything else (flags, windows, offscreen contexts, PNG, sidecars, the
// figure gallery) is shared.
#pragma once
#include <any>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/options.hpp"

namespace ts {
class Renderer;

// The numbers a figure exists to show, e.g. {"kink_deg", 18.43, "..."}.
struct Measurement {
  std::string name;
  double value = 0;
  std::string meaning;
};
// What measure() found: the numbers (printed, written to the sidecar,
// asserted by the tests) and, in `detail`, whatever else the demo's pictures
// show of it (a value per variant, a plot's points) as the demo's own type.
// build() is handed it: a picture is a function of the options and of this,
// never of what a measurement left behind in the scene.  Empty = not
// measured yet (the window draws before its first measurement ends).
struct Measurements : std::vector<Measurement> {
  using std::vector<Measurement>::vector;
  std::any detail;
  // A stage of a measurement still running (measureStage below): its CPU
  // pictures are coarse and its numbers may be missing.  build() marks what
  // is coarse (layout::refiningTag); figures never see a stage.
  bool refining = false;
  template <class T>
  const T* detailAs() const {
    return std::any_cast<T>(&detail);
  }
};
std::string formatMeasurements(const Measurements& m);

// A long measure() says how far it is, between its passes: fraction 0..1.
// In a window the measurement runs on a worker (measure_worker.hpp) and the
// window shows "measuring NN%"; when a newer key or closing the window
// supersedes it, this throws MeasureCancelled (let it pass: the worker
// catches it and the scene stays usable).  Elsewhere (--png, figures, the
// window's live views) it does nothing.
struct MeasureCancelled {};
void measureProgress(double fraction);
// The same for loops that must not throw (threads a measurement starts
// itself, which then stop early): reports `fraction` if >= 0 (from the
// measuring thread) and returns true when the measurement is superseded.
bool measureCancelled(double fraction = -1);
// A picture delivered in stages.  In a window the figure should be complete
// at once: what GL draws is drawn at once, and a picture only the CPU can
// compute (an exact integral, a traced reference) first comes coarse (a
// quarter of the resolution, a few rays), then refined in place.  A long
// measure() asks measureStaged() (true only on the window's worker) and,
// if so, hands the window a first stage (`partial.refining` is set for it)
// before it computes the full pictures; the window shows that stage, marked
// as refining, until the full result replaces it.  Elsewhere (--png,
// make_figures, the tests) measureStaged() is false, so figures are made
// exactly as before, and measureStage does nothing.  Throws
// MeasureCancelled as measureProgress does.
bool measureStaged();
void measureStage(Measurements partial);

// A registered book figure: a state of a demo (its flags) at a size.
struct FigureSpec {
  std::string id;          // file name in book_figures/, e.g. "vi1_quad_distortion"
  std::string bookNumber;  // "Figure VI.1"
  std::string caption;
  std::vector<std::string> flags;  // demo options that set the state
  int width = 1024, height = 512;
  // The claim in one line for the gallery's contents, measurement names in
  // braces standing for their values: "the lines kink by {kink_deg[affine_tl_br]} deg".
  std::string claim;
};

class Scene {
 public:
  virtual ~Scene() = default;
  virtual std::string id() const = 0;     // "quad_distortion" (= folder and program name)
  virtual std::string title() const = 0;  // "Figure VI.1 — quadrilateral distortion"
  virtual std::string about() const = 0;  // a paragraph for --help: the claim
  virtual int defaultWidth() const { return 1024; }
  virtual int defaultHeight() const { return 512; }
  // Binds the demo's state to flags and keys.  Called once, before parsing.
  virtual void addOptions(Options& o) = 0;
  // The picture of the current state at a size, showing what `measured`
  // found (empty before the first measurement).  Pure description: no GL,
  // no state but the options and `measured`.
  virtual Frame build(int width, int height, const Measurements& measured) const = 0;
  // Measures the figure's claim in the current state.  May render extra
  // passes with `r` into the current target (the caller redraws after).
  virtual Measurements measure(Renderer& r) = 0;
  virtual std::vector<FigureSpec> figures() const { return {}; }
  // The names of the one or two measurements that prove the figure (its
  // claim), shown first in the window's side panel; a name ending in '*' is
  // a prefix ("kink_deg*": every variant's).  Default: the first two.
  virtual std::vector<std::string> claim() const { return {}; }
  // An accumulation buffer (the Red Book's jitter method).  OSMesa and GLX
  // windows give one when asked; EGL contexts have none, so a scene must
  // check Context::hasAccumBuffer() and fall back (e.g. averaging in an FBO).
  virtual bool wantsAccumBuffer() const { return false; }
  // Window only: called each frame with the elapsed seconds (animations).
  virtual void update(double /*seconds*/) {}
  // Window only: an animation whose update() changes the state now and then
  // (not every frame) needs frames while nothing else happens: the window
  // then wakes about 20 times a second instead of waiting for an event.
  virtual bool animating() const { return false; }
  // Window only: a click at frame pixel (x, y) (top-left origin) on the
  // figure of a width x height window, outside the inspect mode: the options
  // it sets, as (name, value) pairs the window applies as flags would (so
  // F12's command carries them), e.g. {"pixel", "21,15"} for a raster pixel.
  // Default: none (a click does nothing).
  virtual std::vector<std::pair<std::string, std::string>> click(int /*x*/, int /*y*/, int /*width*/,
                                                                 int /*height*/) const {
    return {};
  }
  // A live view: measure() draws the picture itself with GL (into a texture
  // the frame names through TextureDesc::glTexture), so the window calls it
  // every frame, not only after a key.  Default: no.
  virtual bool live() const { return false; }
  // Files to write beside a figure besides its PNG and sidecar, made by the
  // last measure(): (suffix, contents), e.g. {".csv", table}.  make_figures
  // writes each as <out>/<figure id><suffix>.  Default: none.
  virtual std::vector<std::pair<std::string, std::string>> figureFiles() const { return {}; }
};

// Registry filled by TS_REGISTER_SCENE in each demo's file.
using SceneFactory = std::function<std::unique_ptr<Scene>()>;
struct RegisteredScene {
  std::string id;
  SceneFactory make;
};
std::vector<RegisteredScene>& sceneRegistry();
bool registerScene(const std::string& id, SceneFactory make);
std::unique_ptr<Scene> makeScene(const std::string& id);  // nullptr if unknown

// Runs a demo program (defined in common/app/demo_main.cpp, the app layer):
// flags, --help, --png, or the window.  Returns the exit
// status; every user error becomes one line on stderr.
int runDemo(const std::string& id, int argc, char** argv);
}  // namespace ts

#define TS_REGISTER_SCENE(Class)                                                   \
  static const bool ts_registered_##Class = ::ts::registerScene(Class().id(), [] { \
    return std::unique_ptr<::ts::Scene>(new Class());                              \
  })
