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
  void update(Renderer& r, const Frame& f, bool changed);
  // The panel's part: the loupe and the card.
  void drawPanel(float width);
  // " --inspect X,Y" for F12's command, or "".
  std::string flag() const;

 private:
  char key_ = 'i';
  bool active_ = false, picked_ = false, stale_ = false;
  int x_ = 0, y_ = 0;
  std::string card_;
  GLuint loupe_ = 0;  // Renderer::attachment<Loupe>'s texture
};
}  // namespace ts
