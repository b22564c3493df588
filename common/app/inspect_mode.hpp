// common/app/inspect_mode.hpp — the window's inspect mode (key i, or I in a
// demo whose options take i): a click on the figure picks a pixel; the side
// panel shows a loupe (32 x 32 pixels around it, 6x, with the pixel grid and
// the picked pixel outlined) and the card of reference/inspect.hpp beside the
// colour GL drew.  The card is printed on stdout too (the window tests read
// it).  --inspect X,Y with the window backend opens with that pixel picked.
#pragma once
#include <string>

#include "common/core/frame.hpp"
#include "common/core/options.hpp"
#include "common/gl/gl.hpp"

namespace ts {
class Renderer;

class InspectMode {
 public:
  // The key: i, unless one of the demo's options takes it (then I).
  InspectMode(const Options& opts, const CommonFlags& flags);
  char key() const { return key_; }
  bool active() const { return active_; }
  void toggle();
  // A click at window pixel (x, y): a pick when active and inside the
  // figure (0 <= x < figureW, 0 <= y < height).
  void click(double x, double y, int figureW, int height);
  // After the figure is drawn (in the back buffer): inspects the pick again
  // when it or the picture changed (`changed`: a new state or measurement).
  // The loupe's texture belongs to the renderer (deleted with it).
  // True when it inspected (a new pick, or the picture changed under it).
  bool update(Renderer& r, const Frame& f, bool changed);
  // The picked pixel's footprint over the figure, in each of the demo's
  // texture-space views that shows its texture (footprintInTextureViews);
  // call after the figure is drawn and read (update).
  void drawFootprint(Renderer& r) const;
  // The panel's part: the loupe, the footprint on level 0 when no view of
  // the figure shows the texture, and the card.
  void drawPanel(float width);
  // The picked pixel's batch, numbered over the frame's panels in drawing
  // order (the GL pane marks its calls); -1: nothing picked, or background.
  int batchOrdinal() const { return active_ && picked_ ? ordinal_ : -1; }
  // " --inspect X,Y" for F12's command, or "".
  std::string flag() const;

 private:
  char key_ = 'i';
  bool active_ = false, picked_ = false, stale_ = false;
  int x_ = 0, y_ = 0;
  std::string card_;
  GLuint loupe_ = 0;  // Renderer::attachment<Loupe>'s texture
  GLuint cell_ = 0;   // Renderer::attachment<Cell>'s: the footprint on level 0, or 0
  Frame over_;        // the footprint in the figure's texture-space views
  bool inViews_ = false;
  int ordinal_ = -1;
};
}  // namespace ts
