// common/app/window_save.cpp — --screenshot of the last frame, and F12's picture, sidecar and command.
#include <sys/stat.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "common/app/window_parts.hpp"
#include "common/core/sidecar.hpp"
#include "common/gl/figure.hpp"

namespace ts::window_parts {
namespace {
// F12: the window's picture as PNG + sidecar under a name not yet taken
// (<demo>-<n>.png in the working folder), and the command that remakes it.
void saveState(Scene& scene, const Options& opts, const Frame& f, const Image& window,
               const std::vector<std::string>& extra) {
  std::string base;
  for (int n = 1; n < 10000; ++n) {
    base = scene.id() + "-" + std::to_string(n);
    struct stat st;
    if (::stat((base + ".png").c_str(), &st) != 0 && ::stat((base + ".json").c_str(), &st) != 0) break;
  }
  Image picture(f.width, f.height);  // the figure's part of the window (the GL pane takes the rest)
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) picture.set(x, y, window.at(x, y));
  std::vector<std::string> flags = {"--json", base + ".json"};
  for (const std::string& s : opts.stateFlags()) flags.push_back(s);
  for (const std::string& s : extra) flags.push_back(s);  // the inspect mode's pick
  SidecarInfo info;
  info.demo = scene.id();
  info.figureId = base;
  info.caption = scene.title();
  info.command = figureCommand(scene.id(), base + ".png", f.width, f.height, flags);
  info.state = opts.state();
  info.renderer = gl::rendererString() + " | " + gl::versionString();
  writePng(base + ".png", picture);
  writeFileAtomic(base + ".json", sidecarJson(f, info));
  std::printf("saved %s.png and %s.json; remake them with:\n  %s\n", base.c_str(), base.c_str(), info.command.c_str());
  std::fflush(stdout);
}
}  // namespace

// F12 while measuring saves when the numbers are in: the picture, its
// sidecar and the command that remakes them must agree.
void FrameLoop::saveIfAsked(const Frame& f) {
  if (!savePending || measuring) return;
  std::vector<std::string> pick;  // the inspect mode's pick goes into the command
  if (!inspect.flag().empty()) pick = {"--inspect", inspect.flag().substr(11)};
  saveState(scene, opts, f, ctx.readPixels(), pick), savePending = false;
}

// --screenshot on the last frame, called before and after the overlay is
// drawn: the figure alone (it must match --png), unless
// TS_SCREENSHOT_OVERLAY=1 asks for the window as the student sees it.
void FrameLoop::takeScreenshot(bool lastFrame, bool overlayDrawn) {
  if (!overlayDrawn && framePixels) {  // TS_TEST_FRAME_PIXELS: a hash of the figure for the frame log
    std::vector<uint8_t> px(size_t(split.figureW) * size_t(ctx.height()) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, split.figureW, ctx.height(), GL_RGBA, GL_UNSIGNED_BYTE, px.data());
    uint64_t h = 1469598103934665603ull;  // FNV-1a
    for (uint8_t b : px) h = (h ^ b) * 1099511628211ull;
    pixelHash = h;
  }
  if (!lastFrame || flags.screenshot.empty()) return;
  if (test_hooks::screenshotWithOverlay() == overlayDrawn) writePng(flags.screenshot, ctx.readPixels());
}
}  // namespace ts::window_parts
