// common/window.hpp — the GLFW window backend with the on-screen overlay.
#pragma once
#include "options.hpp"
#include "scene.hpp"

namespace ts {
// Opens a compatibility-profile window, runs the scene until Esc/q (or
// --frames N), shows the state, keys and measurement in a Dear ImGui overlay
// (never in --png figures).  No display: throws ts::Error (exit status 2).
int runWindow(Scene& scene, Options& opts, const CommonFlags& flags, int width, int height);
}  // namespace ts
