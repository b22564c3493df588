// common/core/sidecar.hpp — the JSON written beside every figure: every number
// needed to recompute the image without OpenGL (size, matrices, textures and
// how they were made, per-vertex positions and (s,t,r,q), filters, wraps),
// plus the demo state that produced it and what it measured.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/scene.hpp"

namespace ts {
struct SidecarInfo {
  std::string figureId, bookNumber, caption, demo, command;
  std::vector<std::pair<std::string, std::string>> state;
  Measurements measurements;
  std::string renderer;  // GL_RENDERER and GL_VERSION of the context that drew it ("" = not written)
  // --inspect: one JSON object per pixel looked inside (reference/inspect.hpp's
  // fields and the PNG's gl_rgba); written as the "inspect" list when given.
  std::vector<std::string> inspect;
};
// Deterministic: fixed key order, floats with 9 significant digits, no
// renderer strings or times (the file must not change between machines).
std::string sidecarJson(const Frame& frame, const SidecarInfo& info);
std::string glEnumName(GLenum e);
}  // namespace ts
