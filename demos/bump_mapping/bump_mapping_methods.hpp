// demos/bump_mapping/bump_mapping_methods.hpp — the demo's methods, one table: each
// method's key (--method's value, the measurements' [key]), its caption,
// the number the shader knows it by, and whether it is drawn without
// shaders.  Every other file names a method by its constant (kBlinn, ...),
// never by a number: the shader's text gets the numbers from this table
// (bump_mapping_gl.hpp: glsl), the fixed-function passes test the constants
// (bump_mapping_ff.hpp), the measurement loops over the table (bump_mapping_measure.hpp).
#pragma once

namespace bump {
// The methods, in the order of --method (and of kMethods below).
enum Method : int { kFlat, kBlinn, kSeed002, kNormalMap, kReference, kEmboss, kDot3, kMethodCount };

struct MethodInfo {
  Method method;       // its place in the table (checked below)
  const char* key;     // --method's value; the measurements' [key]
  const char* title;   // the caption above its picture
  int shaderId;        // the fragment shader's `method` (the torus uniform's w): which normal it computes
  bool fixedFunction;  // B4, B5: no shader, drawn by bump_mapping_ff.hpp and shown as a picture
};

// Shader ids: 0 is the smooth torus's own normal (the shader's last
// branch), so the flat torus and the fixed-function methods (whose torus
// panel only lends its matrices and textures) share it; R's own normal is 9,
// apart from the bump methods' 1-3.
inline constexpr MethodInfo kMethods[kMethodCount] = {
    {kFlat, "flat", "flat (no bumps)", 0, false},
    {kBlinn, "blinn", "B1 Blinn (seed 004)", 1, false},
    {kSeed002, "seed002", "B2 seed 002 literally", 2, false},
    {kNormalMap, "normalmap", "B3 normal map", 3, false},
    {kReference, "reference", "R displaced", 9, false},
    {kEmboss, "emboss", "B4 emboss (seed 001)", 0, true},
    {kDot3, "dot3", "B5 DOT3", 0, true},
};
constexpr bool methodsInOrder() {
  for (int m = 0; m < kMethodCount; ++m)
    if (kMethods[m].method != m) return false;
  return true;
}
static_assert(methodsInOrder(), "kMethods lists the methods in the order of enum Method");
}  // namespace bump
