// common/app/side_panel.hpp — the window's side panel (key `h`): docked beside
// the figure, never over it.  It opens with the claim (the one or two
// numbers that prove the figure, Scene::claim), then the state, then the
// keys; the full list of measurements waits under a collapsed header.
//
// The window is split left to right: the figure from x = 0, then this
// panel, then the GL pane (key `l`).  The figure is built at the width
// left over, so nothing covers it.
#pragma once
#include <functional>
#include <string>

#include "common/core/options.hpp"
#include "common/core/scene.hpp"

namespace ts {
// What the window knows of its measurement when it draws the panel.  A
// measurement may run elsewhere (a worker): `measuring` and `progress`
// (0..1) say so, and `stale` marks the numbers shown as those of an older
// state.
struct PanelStatus {
  double fps = 0;
  bool idle = false;   // nothing animating: drawn only when something changes
  bool paced = false;  // a measurement runs, nobody acting: a few frames a second, the rest the worker's
  bool measuring = false;
  double progress = 0;  // 0..1 while measuring
  bool stale = false;   // the numbers shown are not the current state's
};

// The panel's width in a window `windowWidth` pixels wide (0 when closed).
int sidePanelWidth(int windowWidth);

// Where the parts of a window go: the figure at [0, figureW), the side panel
// at [panelX, panelX + panelW), the GL pane at [paneX, paneX + paneW).
struct WindowSplit {
  int figureW = 1, panelX = 0, panelW = 0, paneX = 0, paneW = 0;
};
WindowSplit splitWindow(int windowWidth, bool panelOpen, bool paneOpen);

// The measurements a claim names, in the claim's order (names not measured
// are left out; an empty claim falls back to the first two measurements).
std::vector<const Measurement*> claimed(const Scene& scene, const Measurements& m);

// The panel as a Dear ImGui window at (x, 0), w x h pixels.
// `extra` (when given) draws more inside the panel, under its title (the
// inspect mode's loupe and card).
void drawSidePanel(const Scene& scene, const Options& opts, const Measurements& m, const PanelStatus& status, int x,
                   int w, int h, const std::function<void()>& extra = nullptr);
}  // namespace ts
