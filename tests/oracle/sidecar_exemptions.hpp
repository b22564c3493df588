// Figures whose sidecar cannot remake every texture: their panels are
// pictures that OpenGL itself rendered in the demo's measure() pass (Figure
// VI.7 shows GL's own multi-pass and per-pixel-jitter renders side by side;
// the parallax figures show GLSL renders of the filtering modes and errors),
// so the sidecar records them by digest and by the command that makes them.
// Every other figure must be reproducible from its JSON alone; a new figure
// that is not fails the oracle tests until it is made reproducible or listed
// here with its reason.
#pragma once
#include <algorithm>
#include <array>
#include <string>

namespace oracle {
inline constexpr std::array<const char*, 4> kFiguresDrawnFromGlRenders = {
    "vi7_jitter", "parallax_modes", "parallax_error_band", "parallax_step"};

inline bool drawnFromGlRenders(const std::string& id) {
  return std::any_of(kFiguresDrawnFromGlRenders.begin(), kFiguresDrawnFromGlRenders.end(),
                     [&](const char* f) { return id == f; });
}
}  // namespace oracle
