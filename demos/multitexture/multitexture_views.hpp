// demos/multitexture/multitexture_views.hpp — the Frame's panels: each picture is a
// GL render (or the CPU's answer) made by measure(), shown as a texture
// (ts::renderedImageTexture) with the GL calls behind it (renderedBy), a
// title above and a note below; the figure's numbers at the bottom.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/textures.hpp"
#include "multitexture_measure.hpp"

namespace mt::views {
namespace L = ts::layout;

struct Picture {
  ts::Image image;  // a picture made by measure(); empty: a panel the caller draws (or `texture`)
  L::Text title, note;
  ts::gl::CallList calls = nullptr;
  ts::TextureDesc texture;  // a generator's texture shown as it is (the sidecar remakes it)
  Picture(ts::Image i = {}, L::Text t = {}, L::Text n = {}, ts::gl::CallList c = nullptr, ts::TextureDesc d = {})
      : image(std::move(i)), title(std::move(t)), note(std::move(n)), calls(std::move(c)), texture(std::move(d)) {}
};

// Pictures of one aspect in a row (or grid) over the frame above a band of
// `lines` lines for the numbers.
inline void pictures(ts::Frame& f, const std::vector<Picture>& ps, float aspect, const L::Text& numbers,
                     int lines = 2) {
  const float band = L::lineHeight(1) * float(lines) + 8;
  const L::Box area{8, 8, float(f.width - 8), float(f.height) - 8 - band};
  const std::vector<L::Cell> cells = L::flow(area, {int(ps.size()), aspect, 1, 1, 10, 2, 120});
  for (size_t k = 0; k < ps.size() && k < cells.size(); ++k) {
    // Drawn by the caller: an empty unit panel (multitexture_frames.hpp).
    if (ps[k].image.width == 0 && !ps[k].texture.image) {
      f.panels.push_back(frames::unitPanel("picture_" + std::to_string(k), cells[k].picture));
    } else {
      ts::TextureDesc t = ps[k].texture.image
                              ? ps[k].texture
                              : ts::renderedImageTexture(ps[k].image, "multitexture", ps[k].title.text, "multitexture");
      t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
      // GL_LINEAR: a panel's pixel centre can fall on a texel boundary, where GL_NEAREST's tie goes either way.
      t.minFilter = t.magFilter = GL_LINEAR;
      t.renderedBy = ps[k].calls;
      f.panels.push_back(
          L::picturePanel(f, "picture_" + std::to_string(k), cells[k].picture, t));  // a nested frame's upright
      if (t.renderedFrom) {
        // Its alpha is what its passes left (the pear's: the gloss t_g that GL_MODULATE_ADD_ATI reads):
        // drawn (GL_ONE, GL_ZERO), the colour as it is and the figure's own alpha kept, opaque.
        ts::Batch& b = f.panels.back().batches.back();
        b.blend = true, b.blendSrc = GL_ONE, b.blendDst = GL_ZERO;
      }
    }
    L::caption(f, cells[k].above, ps[k].title, L::kWhite, cells[k].scale);
    L::caption(f, cells[k].below, ps[k].note, L::kAmber, cells[k].scale);
  }
  L::caption(f, {8, float(f.height) - band, float(f.width - 8), float(f.height - 4)}, numbers, L::kAmber, 1);
}

}  // namespace mt::views
