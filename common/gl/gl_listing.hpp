// common/gl/gl_listing.hpp — the recorded GL calls of a picture as a listing a
// student reads: Nate Robins' command pane, generated from the calls made.
//
// A listing keeps every call that sets state or draws (texture creation and
// parameters, texture environment, hints, enables, matrices, programs and
// their sources), and shortens each glBegin ... glEnd to its first vertices,
// a "... N more vertices" comment and glEnd.  Queries (glGet*, glFinish) are
// left out: they draw nothing.  Object names are numbered in order of
// creation (texture 1, 2, ...), so two listings of one state are identical
// and a changed line is a changed call, not a new name.  Every line is a C
// statement or a C comment.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/gl/gl_record.hpp"

namespace ts {
class Renderer;

// The calls that draw `frame` (labels included) into the renderer's target:
// the picture's calls only (measurement passes are never recorded).
std::vector<gl::Call> recordPicture(Renderer& r, const Frame& frame);

// A picture a scene renders itself in measure() and shows as a texture (an
// environment-mapped object, a parallax pass): runs `draw` with its GL calls
// recorded, on the calling thread (the window's measurement worker records on
// its own context), after dropping the renderer's cached textures and
// programs so that the calls show how each is made.  Drop the scene's own
// caches (an attachment's maps) before, for the same reason.  Put the result
// in the TextureDesc that shows the picture (renderedBy), through the
// Measurements' detail: build() stays free of GL.
gl::CallList recordRender(Renderer& r, const std::function<void()>& draw);

// Object names renumbered in order of creation, per kind (textures;
// programs and shaders together; framebuffers; renderbuffers), in every call
// that names them.
std::vector<gl::Call> numberObjects(const std::vector<gl::Call>& calls);

struct ListingLine {
  std::string text;
  bool changed = false;  // not in the listing it is compared with
  bool picked = false;   // sets the texture state of the pixel the inspect mode picked
};

// The listing of `calls`.  `previous` (may be null): the listing before the
// last change; lines whose call was not made then are marked changed, and a
// shortened glBegin ... glEnd keeps its changed vertices too (up to 64: a
// whole new mesh folds like an unchanged one).  `keepVertices`:
// vertices shown at the start of each glBegin (all when negative).
std::vector<ListingLine> listing(const std::vector<gl::Call>& calls, const std::vector<gl::Call>* previous = nullptr,
                                 int keepVertices = 3);

// A part of a listing: a comment saying what the calls made, then the calls.
struct CallSection {
  std::string heading;  // the comment's text, "" = none
  gl::CallList calls;
};
// A picture's listing in order: the render of every texture the frame shows
// that a scene rendered itself (TextureDesc::renderedBy), each headed by the
// panels that show it, then the frame's own calls (headed only after such
// renders: a frame with none lists as before).
std::vector<CallSection> pictureSections(const Frame& frame, std::vector<gl::Call> frameCalls);
// The listing of sections, as listing() above.  Object names are numbered
// per section: each render is a program of its own (in a window it ran on
// the measurement worker's context), and a change in one section leaves the
// names of the others as they were.
// `picked` (may be null): per call of the last section (the frame's own
// calls), whether it sets the picked pixel's texture state (batchTextureCalls).
std::vector<ListingLine> listing(const std::vector<CallSection>& sections, const std::vector<CallSection>* previous,
                                 int keepVertices = 3, const std::vector<bool>* picked = nullptr);
// The calls of a frame's recording (recordPicture) that set the texture
// state of its batch number `ordinal` (counted over all panels in order, as
// the renderer draws them: one glBegin each): its glBegin; back to the glEnd
// before it, the texture's enable, binding, parameters and environment, the
// texture matrix and the program with its uniforms; and, when its texture was
// made for an earlier batch, the binding and glTexImage2D calls that made it.
std::vector<bool> batchTextureCalls(const std::vector<gl::Call>& calls, int ordinal);
// The listing as a file: a header comment, then one line per entry.
std::string listingText(const std::vector<ListingLine>& lines, const std::string& header);
}  // namespace ts
