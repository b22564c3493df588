#include "sampler.hpp"

#include <algorithm>
#include <cmath>

#include "common/core/error.hpp"
#include "common/core/textures.hpp"

namespace ref {
Colour toColour(ts::Rgba c) { return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, c.a / 255.0f}; }

ts::Rgba toRgba(const Colour& c) {
  auto q = [](float v) { return uint8_t(std::clamp(std::lround(double(v) * 255.0), 0L, 255L)); };
  return {q(c[0]), q(c[1]), q(c[2]), q(c[3])};
}

double wrapCoordSeed(GLenum mode, double u) {
  switch (mode) {
    case GL_REPEAT: return u - std::floor(u);
    case GL_MIRRORED_REPEAT: {
      // The lab sheet's program, verbatim in spirit:
      //   float fTest = fmod(ceil(u), 2); if (fTest) u = u - floor(u); else u = 1 - (u - floor(u));
      double test = std::fmod(std::ceil(u), 2.0);
      return test != 0.0 ? u - std::floor(u) : 1.0 - (u - std::floor(u));
    }
    case GL_CLAMP_TO_EDGE:
    case GL_CLAMP: return std::clamp(u, 0.0, 1.0);
    case GL_CLAMP_TO_BORDER: return u;
    default: throw ts::Error("reference sampler: unsupported wrap mode " + std::to_string(mode));
  }
}

static int floorMod(int a, int m) {
  int r = a % m;
  return r < 0 ? r + m : r;
}

int wrapTexel(GLenum mode, int i, int size) {
  switch (mode) {
    case GL_REPEAT: return floorMod(i, size);
    case GL_MIRRORED_REPEAT: {
      // (size - 1) - mirror((i mod 2 size) - size), mirror(a) = a >= 0 ? a : -(1 + a)
      int a = floorMod(i, 2 * size) - size;
      int m = a >= 0 ? a : -(1 + a);
      return size - 1 - m;
    }
    case GL_CLAMP_TO_EDGE: return std::clamp(i, 0, size - 1);
    case GL_CLAMP_TO_BORDER:
    case GL_CLAMP: return std::clamp(i, -1, size);
    default: throw ts::Error("reference sampler: unsupported wrap mode " + std::to_string(mode));
  }
}

int wrapTexelNearest(GLenum mode, int i, int size) {
  // GL_CLAMP with GL_NEAREST never reaches the border: s is clamped to
  // [0, 1], u = s size, and at s = 1 (u = size) the last texel is taken.
  return mode == GL_CLAMP ? std::clamp(i, 0, size - 1) : wrapTexel(mode, i, size);
}

bool texEnvModelled(GLenum mode) {
  return mode == GL_REPLACE || mode == GL_MODULATE || mode == GL_DECAL || mode == GL_BLEND || mode == GL_ADD;
}

Colour texEnv(GLenum mode, const Colour& f, const Colour& t, const Colour& c) {
  Colour o{};
  for (size_t k = 0; k < 3; ++k) {
    switch (mode) {
      case GL_REPLACE: o[k] = t[k]; break;
      case GL_MODULATE: o[k] = f[k] * t[k]; break;
      case GL_DECAL: o[k] = f[k] * (1 - t[3]) + t[k] * t[3]; break;
      case GL_BLEND: o[k] = f[k] * (1 - t[k]) + c[k] * t[k]; break;
      case GL_ADD: o[k] = std::min(1.0f, f[k] + t[k]); break;
      default: throw ts::Error("reference sampler: unsupported texture environment " + std::to_string(mode));
    }
  }
  o[3] = mode == GL_REPLACE ? t[3] : mode == GL_DECAL ? f[3] : f[3] * t[3];
  return o;
}

Box texEnvBox(GLenum mode, const Box& f, const Box& t, const Colour& c) {
  Box o{{2, 2, 2, 2}, {-1, -1, -1, -1}};
  for (int corner = 0; corner < 16; ++corner) {
    Colour fc = f.lo, tc = t.lo;
    // bit 0: Cf (all of R, G, B), bit 1: Ct, bit 2: Af, bit 3: At.  Every
    // channel depends only on its own Cf, Ct and the alphas, so taking the
    // same corner for R, G, B at once still visits each channel's corners.
    for (size_t k = 0; k < 3; ++k) {
      if (corner & 1) fc[k] = f.hi[k];
      if (corner & 2) tc[k] = t.hi[k];
    }
    if (corner & 4) fc[3] = f.hi[3];
    if (corner & 8) tc[3] = t.hi[3];
    Colour v = texEnv(mode, fc, tc, c);
    for (size_t k = 0; k < 4; ++k) o.lo[k] = std::min(o.lo[k], v[k]), o.hi[k] = std::max(o.hi[k], v[k]);
  }
  return o;
}

Colour colourSum(const Colour& c, const Colour& s) {
  return {std::min(1.0f, c[0] + s[0]), std::min(1.0f, c[1] + s[1]), std::min(1.0f, c[2] + s[2]), c[3]};
}

Texture::Texture(const ts::TextureDesc& d) : desc_(d) {
  if (!d.image) throw ts::Error("reference sampler: texture '" + d.name + "' has no image");
  if (d.mipmaps) levels_ = d.mipLevels ? *d.mipLevels : ts::buildMipChain(*d.image, d.linearLightMips);
  else levels_ = {*d.image};
  if (levels_.empty()) throw ts::Error("reference sampler: texture '" + d.name + "' has no levels");
  for (const ts::Image& img : levels_) {
    Box b{{2, 2, 2, 2}, {-1, -1, -1, -1}};
    for (size_t k = 0; k < img.pixels.size(); ++k) {
      float v = img.pixels[k] / 255.0f;
      b.lo[k % 4] = std::min(b.lo[k % 4], v), b.hi[k % 4] = std::max(b.hi[k % 4], v);
    }
    bool border = d.wrapS == GL_CLAMP_TO_BORDER || d.wrapT == GL_CLAMP_TO_BORDER || d.wrapS == GL_CLAMP ||
                  d.wrapT == GL_CLAMP;
    if (border)
      for (int k = 0; k < 4; ++k)
        b.lo[size_t(k)] = std::min(b.lo[size_t(k)], d.border[k]),
        b.hi[size_t(k)] = std::max(b.hi[size_t(k)], d.border[k]);
    ranges_.push_back(b);
  }
}

Box Texture::levelRange(int d) const { return ranges_[size_t(d)]; }

bool Texture::mipmapped() const {
  GLenum f = desc_.minFilter;
  return f == GL_NEAREST_MIPMAP_NEAREST || f == GL_LINEAR_MIPMAP_NEAREST || f == GL_NEAREST_MIPMAP_LINEAR ||
         f == GL_LINEAR_MIPMAP_LINEAR;
}

Colour Texture::texel(int d, int i, int j) const {
  const ts::Image& img = levels_[size_t(d)];
  i = wrapTexel(desc_.wrapS, i, img.width);
  j = wrapTexel(desc_.wrapT, j, img.height);
  if (i < 0 || j < 0 || i >= img.width || j >= img.height)
    return {desc_.border.r, desc_.border.g, desc_.border.b, desc_.border.a};
  return toColour(img.at(i, j));  // image row j is t's row j (row 0 = t = 0)
}

// GL_CLAMP clamps the coordinate itself to [0, 1] before the texel lookup.
static double preClamp(GLenum mode, double s) { return mode == GL_CLAMP ? std::clamp(s, 0.0, 1.0) : s; }

Colour Texture::texelNearest(int d, int i, int j) const {
  const ts::Image& img = levels_[size_t(d)];
  return texel(d, desc_.wrapS == GL_CLAMP ? wrapTexelNearest(GL_CLAMP, i, img.width) : i,
               desc_.wrapT == GL_CLAMP ? wrapTexelNearest(GL_CLAMP, j, img.height) : j);
}

Colour Footprint::value() const {
  double o[4] = {0, 0, 0, 0};
  for (int n = 0; n < count; ++n)
    for (size_t k = 0; k < 4; ++k) o[k] += texels[size_t(n)].weight * texels[size_t(n)].rgba[k];
  return {float(o[0]), float(o[1]), float(o[2]), float(o[3])};
}

// GL_NEAREST: the texel holding (u, v) = (s w, t h), i = floor(u), j = floor(v).
void Texture::addNearest(int d, double s, double t, double weight, Footprint* out) const {
  double u = preClamp(desc_.wrapS, s) * width(d), v = preClamp(desc_.wrapT, t) * height(d);
  int i = wrapTexelNearest(desc_.wrapS, int(std::floor(u)), width(d));
  int j = wrapTexelNearest(desc_.wrapT, int(std::floor(v)), height(d));
  out->texels[size_t(out->count++)] = {d, i, j, weight, texel(d, i, j)};
}

// GL_LINEAR: the 2x2 texels whose centres surround (u, v); with
// i0 = floor(u - 1/2), a = frac(u - 1/2) (and j0, b likewise) the weights are
// (1-a)(1-b), a(1-b), (1-a)b, ab.
void Texture::addLinear(int d, double s, double t, double weight, Footprint* out) const {
  double u = preClamp(desc_.wrapS, s) * width(d) - 0.5, v = preClamp(desc_.wrapT, t) * height(d) - 0.5;
  int i0 = int(std::floor(u)), j0 = int(std::floor(v));
  double a = u - i0, b = v - j0;
  const double w[4] = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
  for (int k = 0; k < 4; ++k) {
    int i = wrapTexel(desc_.wrapS, i0 + (k & 1), width(d)), j = wrapTexel(desc_.wrapT, j0 + (k >> 1), height(d));
    out->texels[size_t(out->count++)] = {d, i, j, weight * w[k], texel(d, i, j)};
  }
}

Colour Texture::nearest(int d, double s, double t) const {
  Footprint f;
  addNearest(d, s, t, 1.0, &f);
  return f.value();
}

Colour Texture::linear(int d, double s, double t) const {
  Footprint f;
  addLinear(d, s, t, 1.0, &f);
  return f.value();
}

// The filter a mipmapped min filter applies within a level.
static GLenum filterWithinLevel(GLenum minFilter) {
  return minFilter == GL_NEAREST_MIPMAP_NEAREST || minFilter == GL_NEAREST_MIPMAP_LINEAR ? GL_NEAREST : GL_LINEAR;
}

// *_MIPMAP_NEAREST: the level nearest lambda (GL: d = ceil(lambda + 1/2) - 1
// for lambda > 1/2, else 0), at most the last level q.
static int nearestLevel(double lambda, int q) {
  return std::min(q, lambda <= 0.5 ? 0 : int(std::ceil(lambda + 0.5)) - 1);
}

double Texture::lod(const Deriv& g) const {
  double lo, hi;
  lodRange(g, LodModel::Exact, &lo, &hi);
  return lo;
}

void Texture::rhoRange(const Deriv& g, LodModel m, double* lo, double* hi) const {
  double w = width(0), h = height(0);
  double ux = g.dsdx * w, uy = g.dsdy * w, vx = g.dtdx * h, vy = g.dtdy * h;
  double exact = std::sqrt(std::max(ux * ux + vx * vx, uy * uy + vy * vy));
  double mu = std::max(std::abs(ux), std::abs(uy)), mv = std::max(std::abs(vx), std::abs(vy));
  *lo = *hi = exact;
  if (m == LodModel::Bounded) *lo = std::max(mu, mv);
  if (m == LodModel::Spec) *lo = std::max(mu, mv), *hi = mu + mv;
}

void Texture::lodRange(const Deriv& g, LodModel m, double* lo, double* hi) const {
  double rlo, rhi;
  rhoRange(g, m, &rlo, &rhi);
  auto lg = [](double r) { return r > 0 ? std::log2(r) : -1000.0; };
  *lo = lg(rlo);
  *hi = lg(rhi);
}

void Texture::levelValues(GLenum filter, int d, double s, double t, double epsN, double epsL, Boxes* out) const {
  const double w = width(d), h = height(d);
  const double u = preClamp(desc_.wrapS, s) * w, v = preClamp(desc_.wrapT, t) * h;
  // A jitter of several texels: any texel of the level may be picked.
  const double e = filter == GL_NEAREST ? epsN : epsL;
  if (e > 4.0) {
    out->push_back(levelRange(d));
    return;
  }
  if (filter == GL_NEAREST) {
    if (epsN >= 0.5) {  // more than two texels per axis: their range
      Box b{{2, 2, 2, 2}, {-1, -1, -1, -1}};
      for (int j = int(std::floor(v - epsN)); j <= int(std::floor(v + epsN)); ++j)
        for (int i = int(std::floor(u - epsN)); i <= int(std::floor(u + epsN)); ++i) {
          Colour c = texelNearest(d, i, j);
          for (size_t k = 0; k < 4; ++k) b.lo[k] = std::min(b.lo[k], c[k]), b.hi[k] = std::max(b.hi[k], c[k]);
        }
      out->push_back(b);
      return;
    }
    int is[2] = {int(std::floor(u - epsN)), int(std::floor(u + epsN))};
    int js[2] = {int(std::floor(v - epsN)), int(std::floor(v + epsN))};
    size_t first = out->size();
    for (int a = 0; a < (is[0] == is[1] ? 1 : 2); ++a)
      for (int b = 0; b < (js[0] == js[1] ? 1 : 2); ++b) {
        Colour c = texelNearest(d, is[a], js[b]);
        bool dup = false;
        for (size_t k = first; k < out->size() && !dup; ++k) dup = (*out)[k].lo == c;
        if (!dup) out->push_back(Box::point(c));
      }
    return;
  }
  // GL_LINEAR: the bilinear function is bilinear between texel centres, so
  // over the jitter square its extremes lie on the corners and on the
  // centre lines crossing it.
  // (At most 16 stops per axis: the jitter is at most 4 texels here.)
  auto stops = [](double x, double e, double* o) {
    int n = 0;
    o[n++] = x - e;
    if (e > 0) {
      for (double k = std::floor(x - e - 0.5) + 1.5; k < x + e && n < 15; k += 1.0) o[n++] = k;
      o[n++] = x + e;
    }
    return n;
  };
  double us[16], vs[16];
  int nu = stops(u, epsL, us), nv = stops(v, epsL, vs);
  Box b{{2, 2, 2, 2}, {-1, -1, -1, -1}};
  // Common case: the jitter square inside one 2x2 footprint — fetch it once.
  int i0 = int(std::floor(us[0] - 0.5)), j0 = int(std::floor(vs[0] - 0.5));
  if (i0 == int(std::floor(us[nu - 1] - 0.5)) && j0 == int(std::floor(vs[nv - 1] - 0.5))) {
    const Colour c00 = texel(d, i0, j0), c10 = texel(d, i0 + 1, j0), c01 = texel(d, i0, j0 + 1),
                 c11 = texel(d, i0 + 1, j0 + 1);
    for (int a = 0; a < nu; ++a)
      for (int c = 0; c < nv; ++c) {
        double fa = us[a] - 0.5 - i0, fb = vs[c] - 0.5 - j0;
        for (size_t k = 0; k < 4; ++k) {
          float x = float((1 - fa) * (1 - fb) * c00[k] + fa * (1 - fb) * c10[k] + (1 - fa) * fb * c01[k] +
                          fa * fb * c11[k]);
          b.lo[k] = std::min(b.lo[k], x), b.hi[k] = std::max(b.hi[k], x);
        }
      }
    out->push_back(b);
    return;
  }
  for (int a = 0; a < nu; ++a)
    for (int c = 0; c < nv; ++c) {
      Colour col = linear(d, us[a] / w, vs[c] / h);
      // linear() re-applies GL_CLAMP's pre-clamp; harmless, u is already clamped.
      for (size_t k = 0; k < 4; ++k) b.lo[k] = std::min(b.lo[k], col[k]), b.hi[k] = std::max(b.hi[k], col[k]);
    }
  out->push_back(b);
}

void blendBoxes(const Boxes& a, const Boxes& b, double f0, double f1, Boxes* out) {
  for (const Box& x : a)
    for (const Box& y : b) {
      Box r;
      for (size_t k = 0; k < 4; ++k) {
        double l0 = (1 - f0) * x.lo[k] + f0 * y.lo[k], l1 = (1 - f1) * x.lo[k] + f1 * y.lo[k];
        double h0 = (1 - f0) * x.hi[k] + f0 * y.hi[k], h1 = (1 - f1) * x.hi[k] + f1 * y.hi[k];
        r.lo[k] = float(std::min(l0, l1));
        r.hi[k] = float(std::max(h0, h1));
      }
      out->push_back(r);
    }
}

void Texture::legal(double s, double t, double lodLo, double lodHi, double epsN, double epsL, Boxes* out) const {
  const double bias = desc_.lodBias;
  double lo = std::clamp(lodLo + bias, -1000.0, 1000.0), hi = std::clamp(lodHi + bias, -1000.0, 1000.0);
  if (hi < lo) std::swap(lo, hi);
  const int q = levels() - 1;
  // Magnified where lambda <= 0 (c = 0): level 0 with the mag filter.
  if (lo <= 0) levelValues(desc_.magFilter, 0, s, t, epsN, epsL, out);
  if (hi <= 0) return;
  lo = std::max(lo, 0.0);
  GLenum f = desc_.minFilter;
  if (f == GL_NEAREST || f == GL_LINEAR) {
    levelValues(f, 0, s, t, epsN, epsL, out);
    return;
  }
  GLenum within = filterWithinLevel(f);
  if (f == GL_NEAREST_MIPMAP_NEAREST || f == GL_LINEAR_MIPMAP_NEAREST) {
    for (int d = nearestLevel(lo, q); d <= nearestLevel(hi, q); ++d) levelValues(within, d, s, t, epsN, epsL, out);
    return;
  }
  // *_MIPMAP_LINEAR: between floor(lambda) and the next level, weight frac.
  if (lo >= q) {
    levelValues(within, q, s, t, epsN, epsL, out);
    return;
  }
  for (int k = int(std::floor(lo)); k <= int(std::floor(hi)) && k < q; ++k) {
    double a = std::max(lo, double(k)), b = std::min(hi, double(k + 1));
    if (b < a) continue;
    Boxes b1, b2;
    levelValues(within, k, s, t, epsN, epsL, &b1);
    levelValues(within, k + 1, s, t, epsN, epsL, &b2);
    blendBoxes(b1, b2, a - k, b - k, out);
  }
  if (hi >= q) levelValues(within, q, s, t, epsN, epsL, out);
}

Footprint Texture::footprint(double s, double t, double lambdaBase) const {
  Footprint f;
  f.lambda = std::clamp(lambdaBase + double(desc_.lodBias), -1000.0, 1000.0);
  const int q = levels() - 1;  // the last level (GL: q = min(p, TEXTURE_MAX_LEVEL))
  const GLenum minF = desc_.minFilter;
  if (f.lambda <= 0) {  // magnification (GL's c = 0): level 0, mag filter
    f.magnified = true;
    f.filter = desc_.magFilter;
  } else if (minF == GL_NEAREST || minF == GL_LINEAR) {  // minified, no mipmaps: level 0
    f.filter = minF;
  } else if (minF == GL_NEAREST_MIPMAP_NEAREST || minF == GL_LINEAR_MIPMAP_NEAREST) {
    f.filter = filterWithinLevel(minF);
    f.level0 = f.level1 = nearestLevel(f.lambda, q);
  } else {  // *_MIPMAP_LINEAR: levels floor(lambda) and the next, weight frac(lambda)
    f.filter = filterWithinLevel(minF);
    if (f.lambda >= q) {
      f.level0 = f.level1 = q;
    } else {
      f.level0 = int(std::floor(f.lambda));
      f.level1 = f.level0 + 1;
      f.levelWeight = f.lambda - f.level0;
    }
  }
  auto add = [&](int d, double weight) {
    if (f.filter == GL_NEAREST) addNearest(d, s, t, weight, &f);
    else addLinear(d, s, t, weight, &f);
  };
  add(f.level0, 1.0 - f.levelWeight);
  if (f.level1 != f.level0) add(f.level1, f.levelWeight);
  return f;
}
}  // namespace ref
