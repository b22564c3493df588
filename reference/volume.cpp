#include "volume.hpp"

#include <algorithm>
#include <cmath>

namespace ref {
Colour Volume::border() const {
  const glm::vec4 b = slice(0).desc().border;
  return {b.r, b.g, b.b, b.a};
}

Colour Volume::sample(double s, double t, double r, double lambdaBase) const {
  if (filter() == GL_NEAREST) {
    const int k = wrapTexelNearest(wrapR, int(std::floor(r * depth)), depth);
    return k < 0 || k >= depth ? border() : slice(k).sample(s, t, lambdaBase);
  }
  const double u = r * depth - 0.5, k0 = std::floor(u), beta = u - k0;
  auto at = [&](int k) {
    k = wrapTexel(wrapR, k, depth);
    return k < 0 || k >= depth ? border() : slice(k).sample(s, t, lambdaBase);
  };
  const Colour a = at(int(k0)), b = at(int(k0) + 1);
  Colour out{};
  for (size_t c = 0; c < 4; ++c) out[c] = float((1 - beta) * a[c] + beta * b[c]);
  return out;
}

void Volume::legal(double s, double t, double r, double lodLo, double lodHi, double epsN, double epsL,
                   Boxes* out) const {
  auto sliceBoxes = [&](int k, GLenum wrapped, Boxes* into) {
    const int w = wrapped == GL_NEAREST ? wrapTexelNearest(wrapR, k, depth) : wrapTexel(wrapR, k, depth);
    if (w < 0 || w >= depth) into->push_back(Box::point(border()));
    else slice(w).legal(s, t, lodLo, lodHi, epsN, epsL, into);
  };
  if (filter() == GL_NEAREST) {
    // Every slice a coordinate within epsN slices of r * depth falls in.
    const double u = r * depth;
    for (int k = int(std::floor(u - epsN)); k <= int(std::floor(u + epsN)); ++k) sliceBoxes(k, GL_NEAREST, out);
    return;
  }
  // GL_LINEAR: for each pair of slices the jittered u may fall between, the
  // blend of their bilinear boxes over the weights it may take.
  const double u = r * depth - 0.5;
  for (int k0 = int(std::floor(u - epsL)); k0 <= int(std::floor(u + epsL)); ++k0) {
    const double f0 = std::clamp(u - epsL - k0, 0.0, 1.0), f1 = std::clamp(u + epsL - k0, 0.0, 1.0);
    Boxes a, b;
    sliceBoxes(k0, GL_LINEAR, &a);
    sliceBoxes(k0 + 1, GL_LINEAR, &b);
    blendBoxes(a, b, f0, f1, out);
  }
}
}  // namespace ref
