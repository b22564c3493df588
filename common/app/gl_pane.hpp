// common/app/gl_pane.hpp — the window's GL pane (key `l`): the OpenGL calls that
// drew the current picture, beside it, never over it (the figure is laid
// out in the rest of the window).  The anchor is Nate Robins' texture tutor,
// whose command pane shows glTexCoord2f and glTexParameteri with their live
// values.  The calls are recorded (common/gl/gl_record.hpp), so what the pane
// shows is what drew the picture; lines a key press changed stay highlighted
// for a few seconds (press `f` in quad_distortion: GL_TEXTURE_MAG_FILTER
// turns from GL_NEAREST to GL_LINEAR).
#pragma once
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/gl/gl_listing.hpp"

namespace ts {
class Renderer;

// The pane's width in a window `windowWidth` pixels wide: the figure gets
// the rest, from x = 0.  The window tests use it to find the figure's box.
int glPaneWidth(int windowWidth);

class GlPane {
 public:
  static constexpr double kHighlightSeconds = 4.0;
  bool visible = false;
  // A key (or a drag) changed the state at `now`: what the next recordings
  // draw differently from the listing before it is marked yellow, for
  // kHighlightSeconds after the marks first appear, across every recording
  // in between (the measurement's pictures arriving, a resize).
  void keyPressed(double now);
  // Draws `f` with its calls recorded and keeps their listing, its lines
  // compared with the listing before the last key while the marks last
  // (changed lines are printed to stdout, for tests and logs).  `result`:
  // this picture carries a new measurement (the marks wait for it, however
  // long the measurement takes).
  void record(Renderer& r, const Frame& f, double now, bool print, bool result);
  // Until when the marks of the last key show (or, before its pictures are
  // recorded, would): the window keeps drawing until then, so they fade.
  double marksUntil() const { return (markedSinceKey_ ? changedAt_ : keyAt_) + kHighlightSeconds; }
  // The inspect mode picked a pixel of batch `ordinal` (counted over the
  // frame's panels in drawing order; -1: none): the calls that set its
  // texture state are marked (cyan) from the next recording on, printed to
  // stdout with it, and scrolled to.
  void pick(int ordinal);
  int pickedOrdinal() const { return pick_; }
  // The pane as a Dear ImGui window at (x, 0), w x h pixels.
  void draw(int x, int w, int h, double now);

 private:
  std::vector<CallSection> calls_;     // the last recording
  std::vector<CallSection> baseline_;  // the recording before the last key
  std::vector<ListingLine> lines_;
  double keyAt_ = -1e9, changedAt_ = -1e9;
  bool awaitingResult_ = false, markedSinceKey_ = false;
  int firstChanged_ = -1;
  bool scroll_ = false;
  int pick_ = -1, firstPicked_ = -1;
  bool pickNew_ = false, scrollPick_ = false;
};
}  // namespace ts
