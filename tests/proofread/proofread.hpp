// tests/proofread/proofread.hpp — a figure read as a proofreader reads it,
// from its sidecar alone: the problems a reader would find, one line each.
//
//   text      every label lies whole inside the image; a label that touches
//             a panel lies inside it (no caption half over a picture, none
//             cut at a panel's edge); no two labels overlap; a label cut
//             with "..." is a cut caption.
//   numbers   every number a label prints is accounted for: a measurement
//             the label names (Label::printed), whose value formatted as
//             recorded gives the very text in the label; or a value the
//             label names as given (an axis tick, a parameter); or a value
//             the sidecar holds (a measurement, the state, the size, a
//             texture's parameters) at the printed precision.  Integers up
//             to 16 (a panel's number, a 2x2 kernel) need no account.
//   colours   every colour that carries meaning, the colour of a mark (an
//             untextured line or point that is not grey) or of text that is
//             neither the caption white, the measurement amber nor grey, is
//             named in the figure's legend, and every legend entry is drawn.
//   size      every label's capitals, as recorded in the sidecar (capital_px)
//             and as the font draws them at its scale, are at least a size:
//             11 px, readable once a 1280-1500 px figure is printed at a
//             page's width.
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ts::proofread {
using Json = nlohmann::json;
std::vector<std::string> textProblems(const Json& sidecar);
std::vector<std::string> numberProblems(const Json& sidecar);
std::vector<std::string> colourProblems(const Json& sidecar);
// The capital height, in pixels, of the smallest text the figure prints.
double smallestCapitals(const Json& sidecar);
std::vector<std::string> sizeProblems(const Json& sidecar, double minCapitals = 11.0);
}  // namespace ts::proofread
