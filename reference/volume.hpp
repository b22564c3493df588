// reference/volume.hpp — 3D textures (TextureDesc::depth > 1, GL_TEXTURE_3D)
// on the CPU, as GL 2.1 §3.8.8 filters them, built on the 2D sampler: the
// volume is kept as its `depth` slices, each a 2D ref::Texture (the slices
// stacked in the desc's image, slice k in rows k*h .. k*h+h-1, r = (k + 1/2)
// / depth at its centre).
//   GL_NEAREST: slice k = floor(r depth) after wrapR, then the slice's
//       GL_NEAREST at (s, t);
//   GL_LINEAR: u = r depth - 1/2, k0 = floor(u), beta = frac(u):
//       (1 - beta) bilinear(slice k0) + beta bilinear(slice k0 + 1), the
//       slices wrapped by wrapR (a slice -1 or depth under GL_CLAMP_TO_BORDER
//       is the border colour): the trilinear filter of the specification.
// No mipmaps (the renderer uploads level 0 only); the reference models
// minFilter == magFilter (then the LOD does not matter).
#pragma once
#include <vector>

#include "sampler.hpp"

namespace ref {
struct Volume {
  const std::vector<Texture>* textures = nullptr;  // the slices are textures first .. first + depth - 1
  int first = 0, depth = 0;
  GLenum wrapR = GL_REPEAT;
  GLenum filter() const { return slice(0).desc().magFilter; }
  const Texture& slice(int k) const { return (*textures)[size_t(first + k)]; }
  Colour border() const;
  // The exact value at (s, t, r).
  Colour sample(double s, double t, double r, double lambdaBase) const;
  // Every value legal for a coordinate within eps texels of (s, t, r) (as
  // Texture::legal, with r's eps in slices), appended to `out`.
  void legal(double s, double t, double r, double lodLo, double lodHi, double epsN, double epsL, Boxes* out) const;
};
}  // namespace ref
