// common/gl/figure.hpp — render a scene's current state offscreen and write it
// as PNG + sidecar.  Used by every demo's --png and by the figure tool.
#pragma once
#include <string>

#include "common/core/frame.hpp"
#include "common/gl/gl_record.hpp"
#include "common/core/image.hpp"
#include "common/core/scene.hpp"
#include "common/core/sidecar.hpp"

namespace ts {
class Renderer;
struct Rendered {
  Frame frame;
  Image image;
  Measurements measurements;
  std::vector<gl::Call> calls;  // the picture's GL calls, when asked for
};
// Measures, then draws the figure (without the window overlay) at w x h.
// `record`: also keep the GL calls that draw the picture (not the
// measurement's), for a listing or an exported program.
Rendered renderScene(Scene& scene, Renderer& r, int width, int height, bool record = false);
// The --gl-listing file of a rendered state; `state` names it (stateCommand).
std::string glListingFile(const Rendered& got, const std::string& state);
// "build/bin/quad_distortion --size 1024x512 --filter nearest": a state.
std::string stateCommand(const std::string& demo, int w, int h, const std::vector<std::string>& flags);
// Fails early, with one line naming the path, if `path` cannot be written.
void checkWritable(const std::string& path);
// "build/bin/quad_distortion --png book_figures/x.png --size 1024x512 ..."
std::string figureCommand(const std::string& demo, const std::string& png, int w, int h,
                          const std::vector<std::string>& flags);
}  // namespace ts
