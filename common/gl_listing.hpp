// common/gl_listing.hpp — the recorded GL calls of a picture as a listing a
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
#include <string>
#include <vector>

#include "frame.hpp"
#include "gl_record.hpp"

namespace ts {
class Renderer;

// The calls that draw `frame` (labels included) into the renderer's target:
// the picture's calls only (measurement passes are never recorded).
std::vector<gl::Call> recordPicture(Renderer& r, const Frame& frame);

// Object names renumbered in order of creation, per kind (textures;
// programs and shaders together), in every call that names them.
std::vector<gl::Call> numberObjects(const std::vector<gl::Call>& calls);

struct ListingLine {
  std::string text;
  bool changed = false;  // not in the listing it is compared with
};

// The listing of `calls`.  `previous` (may be null): the listing before the
// last change; lines whose call was not made then are marked changed, and a
// shortened glBegin ... glEnd keeps its changed vertices too.  `keepVertices`:
// vertices shown at the start of each glBegin (all when negative).
std::vector<ListingLine> listing(const std::vector<gl::Call>& calls, const std::vector<gl::Call>* previous = nullptr,
                                 int keepVertices = 3);
// The listing as a file: a header comment, then one line per entry.
std::string listingText(const std::vector<ListingLine>& lines, const std::string& header);
}  // namespace ts
