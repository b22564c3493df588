// reference/sidecar_reader.hpp — the sidecar JSON (common/core/sidecar.cpp) read
// back into a ts::Frame, so a figure can be recomputed from the file alone.
//
// Textures are re-made from their name and params with the generators of
// common/core/textures.cpp ("checkerboard", "line_grid", "texel_index", "labelled_grid",
// "mip_level_colours", and "file" from its path); filters, wraps, border, LOD
// bias and the kind of mip chain come from the file.  An unknown texture name
// throws ts::Error "sidecar: texture 0: unknown generator 'x' ...".
//
// A texture entry with "cube": true is a cube map (the generator's image
// holds the six faces stacked, "height" is a face's); with "depth" a 3D
// texture (slices stacked, "height" a slice's, "wrap_r"); with
// "rendered_from" the picture of that nested frame (read like the document's
// own keys, at most 4 deep), which the reference recomputes: no generator.
// Batches' "tex_gen" may be GL_SPHERE_MAP, GL_REFLECTION_MAP or
// GL_NORMAL_MAP (no planes), their vertices then carrying "normal".
//
// What the sidecar does not record (as of this writing) is left at the
// Frame's defaults and flagged in `missing`: a panel's own clear colour,
// points' size, and the labels' scale, alignment, colour and background.
// Keys for them are read when present ("clear", "clear_color", "point_size",
// "scale", "align", "color", "background"), so the writer can add them.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "common/core/frame.hpp"

namespace ref {
struct SidecarScene {
  ts::Frame frame;
  std::string figure, bookNumber, caption, demo, command;
  std::vector<std::pair<std::string, std::string>> state;
  // True when every label carried its scale and alignment (its box is then
  // exact); false: a verifier should exempt a conservative box around labels.
  bool labelGeometryKnown = true;
  std::vector<std::string> missing;  // keys the file lacked, e.g. "labels[0].scale"
  std::string renderer;              // the context that drew the figure ("" when not recorded)
  bool fixedStateKnown = false;      // the file says what blending, depth test, shading it used
  // Read with SidecarReadOptions::unknownPictures: the textures of the frame
  // (indices into frame.textures) whose generator the reference lacks, read
  // as grey placeholders of their recorded size.
  std::vector<int> unknownPictures;
};

// Some figures show pictures a demo made itself: a GL render read back, a CPU
// image computed from one (the sidecar names these by digest and by the
// command that makes them), or a map made by the demo's own code.  The
// reference has no generator for them.  Read strictly (the default), such a
// texture fails the read.  With unknownPictures, a texture of the top frame
// that no generator remakes (or a nested frame that shows one) becomes a
// grey placeholder of its recorded size, listed in
// SidecarScene::unknownPictures, so that a verifier exempts exactly the
// pixels that read it (RenderOptions::exemptTextures) and checks the rest of
// the figure from the JSON alone.  The figures allowed this are marked
// drawn_from_gl in their demo's facts file (demos/<name>/facts.tsv).
struct SidecarReadOptions {
  bool unknownPictures = false;
};

SidecarScene readSidecar(const std::string& jsonText, const SidecarReadOptions& options = {});
// Reads a file; "file" textures with relative paths are resolved against
// `baseDir` (default: the current directory).
SidecarScene readSidecarFile(const std::string& path, const std::string& baseDir = "",
                             const SidecarReadOptions& options = {});

// The texture a sidecar entry describes (generator + params only; filters,
// wraps and mip settings are not applied).  Throws ts::Error for unknown
// names or missing/invalid params.
ts::TextureDesc remakeTexture(const std::string& name, const std::vector<std::pair<std::string, std::string>>& params,
                              const std::string& baseDir = "");
// "GL_LINEAR" -> GL_LINEAR; also "0x2601".  Throws ts::Error for unknown names.
GLenum glEnumFromName(const std::string& name);
}  // namespace ref
