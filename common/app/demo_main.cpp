// common/app/demo_main.cpp — runDemo(), which every demo's main() calls
// (common/app/demo_entry.cpp): the same flags, the same errors, the same three
// ways to run (window, OSMesa, EGL).
#include <cstdio>
#include <iostream>

#include "common/gl/context.hpp"
#include "common/core/child_process.hpp"
#include "common/core/error.hpp"
#include "common/gl/export_c.hpp"
#include "common/gl/figure.hpp"
#include "common/gl/render.hpp"
#include "common/core/scene.hpp"
#include "common/core/sidecar.hpp"
#include "common/app/inspect_view.hpp"
#include "common/app/window.hpp"

namespace ts {
// --png, --json and --gl-listing: one offscreen render of the state.
static int renderOffscreen(Scene& scene, Options& opts, const CommonFlags& f, Backend b, int w, int h) {
  if (!f.png.empty()) checkWritable(f.png);
  if (!f.json.empty()) checkWritable(f.json);
  if (!f.glListing.empty()) checkWritable(f.glListing);
  if (!f.exportC.empty()) checkExportWritable(f.exportC);
  ContextOptions co;
  co.width = w;
  co.height = h;
  co.verbose = true;
  co.accumBuffer = scene.wantsAccumBuffer();
  auto ctx = createOffscreenContext(b, co);
  Renderer r(*ctx);
  const bool record = !f.glListing.empty() || !f.exportC.empty();
  Rendered out = renderScene(scene, r, w, h, record);
  // --inspect: what the reference computes inside those pixels, beside GL's colour.
  std::string cards;
  const std::vector<std::string> inspected = applyInspect(scene.id(), f, r, &out, record, &cards);
  // The program is made before anything is written: a state that cannot be
  // exported leaves no file at all.
  ExportedProgram program;
  if (!f.exportC.empty()) {
    ExportInfo info;
    info.demo = scene.id();
    info.title = scene.title();
    info.about = scene.about();
    info.state = stateCommand(scene.id(), w, h, opts.stateFlags());
    info.width = w;
    info.height = h;
    nameExport(f.exportC, &info);
    program = exportC(out.calls, out.frame, info);
  }
  if (!f.png.empty()) writePng(f.png, out.image);
  if (!f.glListing.empty())
    writeFileAtomic(f.glListing, glListingFile(out, stateCommand(scene.id(), w, h, opts.stateFlags())));
  if (!f.exportC.empty()) writeExport(f.exportC, program);
  if (!f.json.empty()) {
    SidecarInfo info;
    info.demo = scene.id();
    info.figureId = f.png;
    info.caption = scene.title();
    info.command = figureCommand(scene.id(), f.png, w, h, opts.stateFlags());
    info.state = opts.state();
    info.measurements = out.measurements;
    info.renderer = gl::rendererString() + " | " + gl::versionString();
    info.inspect = inspected;
    writeFileAtomic(f.json, sidecarJson(out.frame, info));
  }
  if (!f.quiet) {
    std::printf("%s | %s\n%s", scene.title().c_str(), ctx->describe().c_str(),
                formatMeasurements(out.measurements).c_str());
  }
  if (!cards.empty()) std::printf("\n%s", cards.c_str());
  // r goes before ctx: its GL objects with it (RAII).
  return kExitOk;
}

int runDemo(const std::string& id, int argc, char** argv) {
  useUtf8Console();
  try {
    auto scene = makeScene(id);
    if (!scene) throw Error("no scene named '" + id + "' is registered", kExitFailure);
    Options opts;
    scene->addOptions(opts);
    opts.captureDefaults();  // Backspace in the window comes back here
    CommonFlags f;
    std::vector<std::string> rest = parseCommonFlags(argc, argv, &f);
    setQuietNotes(f.quiet);
    opts.parse(rest);
    if (f.help) {
      std::printf("%s\n\n%s\n\nusage: %s [flags]\n\ncommon flags:\n%s\n%s flags (each key works in the window):\n%s",
                  scene->title().c_str(), scene->about().c_str(), id.c_str(), commonFlagsHelp().c_str(), id.c_str(),
                  opts.helpText().c_str());
      std::printf("\nwindow keys: %s  h: overlay on/off  l: the OpenGL calls beside the picture\n"
                  "  ?/F1: help card  F12: save PNG + sidecar and print the command  Backspace: reset every option\n"
                  "  i (I where the demo takes i): inspect mode, click a pixel: its loupe and what happens inside it\n"
                  "  =: as +  arrows: turn/tilt where the demo has them  esc/q: quit\n",
                  opts.keysText().c_str());
      return kExitOk;
    }
    Backend b = parseBackend(f.backend);
    int w = f.width ? f.width : scene->defaultWidth();
    int h = f.height ? f.height : scene->defaultHeight();
    if (!f.png.empty() || !f.glListing.empty() || !f.exportC.empty()) {
      if (b == Backend::Window)
        throw Error("--png, --gl-listing and --export-c render offscreen: use --backend osmesa, egl, hidden or auto");
      if (!f.screenshot.empty() || f.frames)
        throw Error("--screenshot and --frames are for the window, not --png, --gl-listing or --export-c");
      checkPixels(f.inspect, w, h);  // before anything is rendered or written
      return renderOffscreen(*scene, opts, f, b, w, h);
    }
    if (f.footprints) throw Error("--footprints draws a PNG: add --png FILE and --inspect X,Y");
    if (!f.json.empty()) throw Error("--json needs --png FILE");
    if (b == Backend::OSMesa || b == Backend::EGL || b == Backend::Hidden)
      throw Error(std::string("backend ") + backendName(b) + " is offscreen: add --png FILE");
    checkPixels(f.inspect, w, h);  // --inspect X,Y in the window: opens with it picked
    // A screenshot that cannot be written is said before the window opens.
    if (!f.screenshot.empty()) checkWritable(f.screenshot);
    return runWindow(*scene, opts, f, w, h);
  } catch (const Error& e) {
    std::fprintf(stderr, "%s: %s\n", id.c_str(), e.what());
    return e.exit_code;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", id.c_str(), e.what());
    return kExitFailure;
  }
}
}  // namespace ts
