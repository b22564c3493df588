// common/app/window_frame.cpp — the frame loop's steps: wait, measure, draw the figure, present.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "common/app/window_parts.hpp"
#include "common/core/error.hpp"

namespace ts::window_parts {
// Until Esc, q or the window's close button.
bool FrameLoop::running() const { return !glfwWindowShouldClose(win) && !input.quit; }

// Polls the events, or sleeps until one comes while nothing needs a frame.
constexpr double kActiveFrame = 1.0 / 30, kAloneFrame = 0.2;  // seconds between frames while measuring
void FrameLoop::waitForEvents() {
  // Idle is idle: with nothing animating, no key waiting and no test
  // counting frames, wait for an event instead of drawing again (while a
  // changed line of the GL pane is highlighted, wake to fade it).
  // While a measurement runs (and nothing else asks for frames) the loop
  // draws frames for the progress: about 30 a second for 2 s after the
  // student's last key or mouse action, so that what they did shows at
  // once and the progress runs smoothly, and 5 a second in a window left
  // alone (the start, a long measurement): a frame of a large window costs
  // llvmpipe 10-20 ms of the two cores the worker needs, so 30 a second
  // took about a third of them (the start's complete picture came 0.04-0.09 s
  // later).  Any event, and a stage or the result (the worker posts one),
  // wakes the loop at once either way.  --frames (tests) counts those
  // frames too.
  // A --keys key may wait for an event (TS_TEST_KEY_WHEN) or a time
  // (TS_TEST_KEY_INTERVAL_MS): the loop then waits instead of spinning.
  bool keyReady = !input.keys.empty() && testLog.keyDue(measuring, worker->progress(), measuredOnce);
  double keyWait = input.keys.empty() ? 0.0 : testLog.untilKey();
  busy = dirty || redraw || scene.live() || keyReady || !input.dropped.empty() ||
         (flags.frames && !measuring && input.keys.empty());
  const double measuringFrame = aloneWhileMeasuring() ? kAloneFrame : kActiveFrame;
  if (busy) glfwPollEvents();
  else if (keyWait > 0) glfwWaitEventsTimeout(measuring ? std::min(keyWait, measuringFrame) : keyWait);
  else if (measuring || !input.keys.empty())  // the progress moves; the worker wakes us when done
    glfwWaitEventsTimeout(measuring ? measuringFrame : kActiveFrame);
  else if (scene.animating()) glfwWaitEventsTimeout(0.05);           // an animation that steps now and then
  else if (pane.visible && glfwGetTime() < pane.marksUntil() + 0.1)  // the marks fade on time
    glfwWaitEventsTimeout(0.25);
  else glfwWaitEvents();
  redraw = false;
}

bool FrameLoop::aloneWhileMeasuring() const { return measuring && glfwGetTime() - lastAction >= 2.0; }

// The scene's clock (animations) and the frames per second.
void FrameLoop::advanceClock() {
  now = glfwGetTime();
  std::string stateBefore = opts.stateText();
  scene.update(now - last);
  if (opts.stateText() != stateBefore) redraw = true;  // an animation moved: keep drawing
  last = now;
  // Frames per second over the last half second of frames drawn.
  if (now - fpsSince >= 0.5) {
    fps = double(frame - fpsFrame) / (now - fpsSince);
    fpsSince = now;
    fpsFrame = frame;
  }
}

// Takes the window's size now; false while it is minimised.
bool FrameLoop::updateSize() {
  ctx.sync();
  return ctx.width() >= 1 && ctx.height() >= 1;
}

// The side panel and the GL pane dock right of the figure, which is laid
// out in the rest of the window: nothing covers it.
void FrameLoop::layOut() {
  split = splitWindow(ctx.width(), input.overlay, pane.visible);
  renderer.setPictureSize(split.figureW, ctx.height());  // a live view draws at the figure's size
}

// Measures a changed state: here (a live view, or a worker without a
// context) or by a request to the worker.
void FrameLoop::startMeasuring() {
  if (worker->failed() && !measureHere) {  // no context for the worker: measure here, as before
    note("note: measuring in the window's thread (" + worker->failure() + ")");
    measureHere = true;
    dirty |= measuring;
    measuring = false;
  }
  int figureW = split.figureW;
  // The numbers belong to the picture at its size (as --png at that size
  // measures them): a resized figure is measured again.
  if (!scene.live() && measuredW && (figureW != measuredW || ctx.height() != measuredH)) dirty = true;
  if (scene.live() || (dirty && measureHere)) {
    if (measuring) worker->cancel(), measuring = false;  // a live view measures every frame itself
    m = scene.measure(renderer);
    measuredOnce = true;
    measuredW = figureW, measuredH = ctx.height();
    if (dirty) {
      std::printf("%s\n%s", opts.stateText().c_str(), formatMeasurements(m).c_str());
      std::fflush(stdout);
    }
    dirty = false;
  } else if (dirty) {
    worker->request(opts.stateFlags(), figureW, ctx.height());  // measured at the figure's size, as --png
    measuredW = figureW, measuredH = ctx.height();
    measuring = true;
    dirty = false;
  }
}

// Takes the worker's numbers once they are in, and prints them; a stage of
// a measurement still running (coarse CPU pictures) is shown, not printed.
void FrameLoop::collectMeasurement() {
  MeasureWorker::Result res;
  if (scene.live() || !worker->take(&res)) return;
  if (!res.error.empty()) throw Error(res.error, res.errorCode);  // as if measured here
  if (res.stage) {  // a first, coarse stage (ts::measureStage): shown, the request still runs
    m = std::move(res.measured);
    testLog.line("stage");
    redraw = true;
    return;
  }
  m = std::move(res.measured);
  measuredOnce = true;
  testLog.line("result");
  if (pane.visible) record = resultIn = true;  // the picture with the new numbers: its calls again
  measuring = worker->busy();
  std::printf("%s\n%s", res.stateText.c_str(), formatMeasurements(m).c_str());
  std::fflush(stdout);
}

// Draws the figure, recording its GL calls when the GL pane needs a new
// listing, and counts the frame.
Frame FrameLoop::drawPicture() {
  int figureW = split.figureW;
  Frame f = scene.build(figureW, ctx.height(), m);
  if (pane.visible && (record || figureW != recordedW || ctx.height() != recordedH)) {
    pane.record(renderer, f, now, true, resultIn);  // draws the picture, recording its calls
    record = resultIn = false;
    recordedW = figureW;
    recordedH = ctx.height();
  } else {
    renderer.draw(f);
  }
  ++frame;
  if (measuredOnce) ++counted;
  return f;
}

// The inspect mode's card, again when the pick, the state or its numbers
// changed (read from the figure just drawn, before the overlay).
void FrameLoop::inspectPixel(const Frame& f) {
  const std::string state = opts.stateText() + "|" + std::to_string(f.width) + "x" + std::to_string(f.height) + "|" +
                            std::to_string(m.size()) + (measuring ? "|measuring" : "");
  const bool inspected = inspect.update(renderer, f, state != inspectedState);
  inspectedState = state;
  // The GL pane marks the picked batch's texture calls: listed again on every
  // pick (the same batch's too: the marks are printed again), and when the
  // mode is turned off (-1: none).
  if (inspected || inspect.batchOrdinal() != pane.pickedOrdinal())
    pane.pick(inspect.batchOrdinal()), record = redraw = pane.visible;
}

// --frames N (tests): the last frame shows the measurement of the last
// state.  TS_TEST_RESIZE (tests): at what would be the last frame, keep
// that frame as <screenshot>.WxH.png, resize to the next size and go on.
bool FrameLoop::isLastFrame() {
  bool lastFrame = flags.frames && counted >= flags.frames && input.keys.empty() && !measuring && !dirty &&
                   !savePending;
  if (lastFrame && resizing && !flags.screenshot.empty())
    writePng(test_hooks::sizedName(flags.screenshot, ctx.width(), ctx.height()), ctx.readPixels());
  if (lastFrame && !resizes.empty()) {
    glfwSetWindowSize(win, resizes.front().first, resizes.front().second);
    resizes.erase(resizes.begin());
    counted = 0;
    return false;
  }
  return lastFrame;
}

// Shows the frame, and logs it for the test hooks.
void FrameLoop::present() {
  gl::check("drawing the window");
  glfwSwapBuffers(win);
  char progress[64];
  std::snprintf(progress, sizeof progress, "%d %.3f", measuring ? 1 : 0, measuring ? worker->progress() : 1.0);
  if (framePixels) std::snprintf(progress + std::strlen(progress), 24, " %016llx", (unsigned long long)pixelHash);
  testLog.line("frame", progress);
  test_hooks::frameDrawn();
}
}  // namespace ts::window_parts
