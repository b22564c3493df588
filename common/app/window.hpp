// common/app/window.hpp — the GLFW window backend with the on-screen overlay.
#pragma once
#include "common/core/options.hpp"
#include "common/core/scene.hpp"

namespace ts {
// Keys without a character, as they travel through --keys and the window's
// key queue (tests type them with --keys too).
namespace keys {
constexpr char kReset = '\b', kHelp = '\x01', kSave = '\x02', kLeft = '\x03', kRight = '\x04', kUp = '\x05',
               kDown = '\x06';
}
// Opens a compatibility-profile window, runs the scene until Esc/q (or
// --frames N), shows the state, keys and measurement in a Dear ImGui overlay
// (never in --png figures).  No display: throws ts::Error (exit status 2).
int runWindow(Scene& scene, Options& opts, const CommonFlags& flags, int width, int height);
}  // namespace ts
