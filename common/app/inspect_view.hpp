// common/app/inspect_view.hpp — looking inside pixels of a drawn picture.
//
// The CPU reference's inspector (reference/inspect.hpp) says, for one pixel
// of a Frame, what covers it, the interpolated (s,t,r,q), the derivatives,
// rho, lambda, the mip levels and the texels the filter reads with their
// weights.  Here it meets the picture GL drew:
//   --inspect X,Y       the card printed, the "inspect" list in the sidecar
//                       (inspectPixels, inspectCard, inspectJson);
//   --footprints        the PNG becomes the footprint figure: the picture
//                       with the picked pixels ringed and numbered, and for
//                       each one the texture around its footprint
//                       (footprintFrame);
// and the window's inspect mode (key i) shows the same card for the pixel
// under a click.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "common/core/options.hpp"
#include "common/core/scene.hpp"
#include "reference/inspect.hpp"

namespace ts {
class Renderer;
struct Rendered;

struct Picked {
  ref::Inspection in;
  Rgba gl{0, 0, 0, 0};  // the pixel GL drew (the PNG's)
};

// Refuses a pixel outside w x h with one line (exit status 2), before
// anything is rendered or written.
void checkPixels(const std::vector<std::array<int, 2>>& pixels, int w, int h);
// Each pixel of `frame` inspected, beside the pixel of `drawn` (GL's picture of it).
std::vector<Picked> inspectPixels(const Frame& frame, const Image& drawn,
                                  const std::vector<std::array<int, 2>>& pixels);
// The card: the reference's (ref::formatInspection) and GL's colour beside
// the reference's, with their difference in 8-bit steps.
std::string inspectCard(const Picked& p);
// The sidecar's object: ref::inspectionJson plus "gl_rgba" (0..1).
std::string inspectJson(const Picked& p);

// The footprint figure, w x h.  The picture: the panel most picks lie in,
// drawn again from its own data pixel for pixel, in the same 2 x 2 quads
// (the part around the picks when the whole does not fit), so it shows the
// colours GL drew at the picks and none of the figure's captions;
// each pick in it ringed and numbered, a number that has no room beside its
// ring moved away with a leader line.  It goes beside the cells or above
// them, whichever shows more of it.  The cells: one per textured pick,
// level 0 of its texture around the footprint, texel by texel (GL_NEAREST),
// with the preimage of the pixel square, the parallelogram of the
// derivatives, the EWA ellipse (the image of a one-pixel circle), the
// square of side 2^lambda texels a mip level's texel covers and the texels
// the filter reads; under "n: lambda ..., rho ..." and over its (u, v),
// levels and texel count, printed from the pick's measurements in
// `measured` (applyInspect's inspect_*[n]).  A legend names each colour
// drawn.
Frame footprintFrame(const Frame& picture, const std::vector<Picked>& picks, const Measurements& measured, int w,
                     int h);

// The footprint of one inspected pixel as line batches in texels of level 0
// (u right, v up): the texels read (orange), the square of side 2^lambda
// (yellow), the EWA ellipse (magenta), the preimage of the pixel square
// (white) and, thinner over it, the derivative parallelogram (cyan).  The
// footprint figure's cells and the window's inspect mode draw the same
// batches.
std::vector<Batch> footprintBatches(const Frame& picture, const ref::Inspection& in);
// One cell of the footprint figure alone, w x h, without captions: level 0
// around the footprint with the footprint over it (the window's side panel
// shows it when no view of the figure shows the pixel's texture).  A blank
// frame when the pixel is not textured.
Frame footprintCell(const Frame& picture, const ref::Inspection& in, int w, int h);
// The footprint drawn in the demo's own texture-space views: every panel
// (other than the picked pixel's) with a batch of role "texture" that draws
// the pixel's texture flat (one affine map from (s, t) to the view) gets the
// footprint's batches mapped into it.  `over`: a frame of those panels
// alone, to draw over the figure without clearing it.  False when no view
// shows the texture (or the pixel is not textured).
bool footprintInTextureViews(const Frame& picture, const ref::Inspection& in, Frame* over);

// --inspect and --footprints applied to a rendered state (renderScene's
// result): checks the pixels, inspects them, adds each textured pick's
// numbers to the measurements (inspect_lambda[n], inspect_rho[n],
// inspect_anisotropy[n], inspect_u[n], inspect_v[n], inspect_level0[n],
// inspect_level1[n] when two levels blend, inspect_texels[n]; n from 1),
// and with --footprints draws the footprint figure in place of the picture
// (its calls recorded again when `record`).  Returns the sidecar's objects;
// the cards go to `cards`.
std::vector<std::string> applyInspect(const std::string& demo, const CommonFlags& f, Renderer& r, Rendered* got,
                                      bool record, std::string* cards);
}  // namespace ts
