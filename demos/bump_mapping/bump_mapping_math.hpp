// demos/bump_mapping/bump_mapping_math.hpp — the heights the bump-mapping demo puts
// on the torus, the normal map it bakes from them, and the image statistics
// its measurements use.  CPU only; shared by the demo and its tests.
//
// A height field h(u, v) in [0, 1] over the unit square, stored texel by
// texel (texel (x, y) has its centre at u = (x + 1/2)/W, v = (y + 1/2)/H,
// y counted from v = 0), repeated rep.x times around the ring (s) and rep.y
// times around the tube (t):  P(s, t) = scale * h(rep.x s, rep.y t), the
// displacement along the torus's unit normal (seed 004's P(u, w)).
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "common/core/dxt1.hpp"
#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "common/core/relief_maps.hpp"

namespace bump {
constexpr double kPi = 3.14159265358979323846;

struct Heights {
  std::string name;
  int w = 0, h = 0;
  std::vector<float> v;  // row y = 0 at v = 0
  glm::vec2 rep{2.0f, 1.0f};
  float at(int x, int y) const {  // wraps: the field repeats
    x = ((x % w) + w) % w, y = ((y % h) + h) % h;
    return v[size_t(y) * size_t(w) + size_t(x)];
  }
};

// Dimples on a 4 x 4 lattice and ridges between their rows: smooth (the
// displaced reference and the derivative methods see the same shapes),
// periodic, so the texture repeats without a seam.
inline Heights procedural(int n = 256) {
  Heights H{"procedural", n, n, std::vector<float>(size_t(n) * size_t(n)), {4.0f, 2.0f}};
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      double u = (x + 0.5) / n * 4.0, v = (y + 0.5) / n * 4.0;
      double du = u - std::floor(u) - 0.5, dv = v - std::floor(v) - 0.5;  // from the nearest dimple centre
      double dimple = std::exp(-(du * du + dv * dv) / (2 * 0.17 * 0.17));
      double dr = std::fabs(v - std::floor(v));  // from the ridge line v = k / 4
      dr = std::min(dr, 1.0 - dr);
      double ridge = std::exp(-dr * dr / (2 * 0.06 * 0.06));
      H.v[size_t(y) * size_t(n) + size_t(x)] = float(std::clamp(0.55 - 0.55 * dimple + 0.45 * ridge, 0.0, 1.0));
    }
  return H;
}

// The parallax demo's bricks (common/core/relief_maps.hpp), 512 x 512.
inline Heights bricks() {
  const int n = ts::relief::kTexSize;
  Heights H{"bricks", n, n, std::vector<float>(size_t(n) * size_t(n)), {4.0f, 2.0f}};
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      double h = 0;
      glm::dvec3 c;
      ts::relief::bricksTexel(x, y, &h, &c);
      H.v[size_t(y) * size_t(n) + size_t(x)] = float(h);
    }
  return H;
}

// A picture's luminance as heights (--texture FILE: white is high), given
// as a texture image (row 0 = v = 0, ts::UserTexture::image()).
inline Heights fromImage(const ts::Image& img) {
  Heights H{"file", img.width, img.height, std::vector<float>(size_t(img.width) * size_t(img.height)), {2.0f, 1.0f}};
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      ts::Rgba c = img.at(x, y);
      H.v[size_t(y) * size_t(img.width) + size_t(x)] = float((0.299 * c.r + 0.587 * c.g + 0.114 * c.b) / 255.0);
    }
  return H;
}

inline uint8_t u8(double v) { return uint8_t(std::clamp(std::lround(v * 255.0), 0L, 255L)); }

// As a grey texture image (a TextureDesc's row 0 is v = 0).
inline ts::Image heightImage(const Heights& H) {
  ts::Image img(H.w, H.h);
  for (int y = 0; y < H.h; ++y)
    for (int x = 0; x < H.w; ++x) {
      uint8_t g = u8(H.at(x, y));
      img.set(x, y, {g, g, g, 255});
    }
  return img;
}

// The tangent-space normal map (B3), baked once from the same heights:
// n = normalize(-dP/dx, -dP/dy, 1) with the slopes in world units, taken
// with central differences over one texel.  A texture has one texel size,
// the torus does not: a texel spans 2 pi (R + r cos phi) / (rep.x W) along
// the ring, so the map is baked for the ring's mean circle (phi = +-90
// degrees, radius R): its slopes along the ring are (R + r cos phi) / R
// times the true ones, 1.4x too steep on the outer equator and 0.6x too
// flat on the inner one (one source of B3's normal error at the same
// (s,t), 1.3 degrees against Blinn's 0.5; its 8-bit texels are another).
// `wrap` takes the differences across the texture's edges from the other
// side (the field repeats); without it they are one-sided there, the seam.
inline ts::Image normalMap(const Heights& H, double R, double r, double scale, bool wrap = true) {
  ts::Image img(H.w, H.h);
  const double texelS = 2 * kPi * R / (H.rep.x * H.w), texelT = 2 * kPi * r / (H.rep.y * H.h);
  for (int y = 0; y < H.h; ++y)
    for (int x = 0; x < H.w; ++x) {
      int x0 = x - 1, x1 = x + 1, y0 = y - 1, y1 = y + 1;
      if (!wrap) x0 = std::max(x0, 0), x1 = std::min(x1, H.w - 1), y0 = std::max(y0, 0), y1 = std::min(y1, H.h - 1);
      double dx = scale * (H.at(x1, y) - H.at(x0, y)) / ((x1 - x0) * texelS);
      double dy = scale * (H.at(x, y1) - H.at(x, y0)) / ((y1 - y0) * texelT);
      glm::dvec3 n = glm::normalize(glm::dvec3(-dx, -dy, 1.0));
      img.set(x, y, {u8(0.5 + 0.5 * n.x), u8(0.5 + 0.5 * n.y), u8(0.5 + 0.5 * n.z), 255});
    }
  return img;
}

// The textures the passes bind: the heights (or 1 - h, emboss's second
// pass) as grey, and the normal map; `key` names the source for the cache.
// `mip`: with the book's 2x2-average mip chain, trilinear.
inline void withMipmaps(ts::TextureDesc& t, bool mip) {
  if (!mip) return;
  t.mipmaps = true;
  t.minFilter = GL_LINEAR_MIPMAP_LINEAR;
  t.params.push_back({"mipmaps", "2x2 average"});
}
inline ts::TextureDesc heightTexture(const Heights& H, const std::string& key, bool inverted = false,
                                     bool mip = false) {
  ts::Image img = heightImage(H);
  if (inverted)
    for (size_t k = 0; k < img.pixels.size(); ++k)
      if (k % 4 != 3) img.pixels[k] = uint8_t(255 - img.pixels[k]);
  ts::TextureDesc t;
  t.name = inverted ? "bump_heights_inverted" : "bump_heights";
  t.params = {{"source", key}};
  t.image = std::make_shared<const ts::Image>(std::move(img));
  t.minFilter = t.magFilter = GL_LINEAR;
  withMipmaps(t, mip);
  return t;
}
// `dxt1`: the map compressed and decoded by common/core/dxt1.hpp (GL's own
// decode of those blocks is within 1 level, texture_compression measures it).
inline ts::TextureDesc normalTexture(const Heights& H, const std::string& key, double scale, bool mip = false,
                                     bool wrap = true, bool dxt1 = false) {
  ts::TextureDesc t;
  t.name = "bump_normal_map";
  char sc[32];
  std::snprintf(sc, sizeof sc, "%.4f", scale);
  t.params = {{"source", key},
              {"height_scale", sc},
              {"baked_for", "R = 1, r = 0.4"},
              {"edge_slopes", wrap ? "wrapped" : "one-sided"}};
  t.image = std::make_shared<const ts::Image>(normalMap(H, 1.0, 0.4, scale, wrap));
  if (dxt1) {
    t.params.push_back({"compressed", "DXT1"});
    t.image = std::make_shared<const ts::Image>(
        ts::dxt1::decode(ts::dxt1::encode(*t.image), t.image->width, t.image->height));
  }
  t.minFilter = t.magFilter = GL_LINEAR;
  withMipmaps(t, mip);
  return t;
}

// A normal render on black kept small: a bit per pixel for "covered" (not
// black) and the covered pixels' red, green and blue, a third of the RGBA
// image where the torus covers two fifths of it.  Exact: every pixel of such
// a render is opaque (a render that is not is kept whole).
struct PackedNormals {
  int width = 0, height = 0;
  std::vector<uint8_t> covered, rgb;       // bits, row by row; 3 bytes per covered pixel
  std::shared_ptr<const ts::Image> whole;  // a render with a pixel not opaque, as it is

  explicit PackedNormals(const ts::Image& img) : width(img.width), height(img.height) {
    const size_t n = size_t(img.width) * size_t(img.height);
    for (size_t k = 0; k < n; ++k)
      if (img.pixels[4 * k + 3] != 255) {
        whole = std::make_shared<const ts::Image>(img);
        return;
      }
    covered.assign((n + 7) / 8, 0);
    for (size_t k = 0; k < n; ++k) {
      const uint8_t* p = &img.pixels[4 * k];
      if ((p[0] | p[1] | p[2]) == 0) continue;
      covered[k / 8] |= uint8_t(1u << (k % 8));
      rgb.insert(rgb.end(), p, p + 3);
    }
  }
  ts::Image image() const {
    if (whole) return *whole;
    ts::Image img(width, height);  // opaque black
    const size_t n = size_t(width) * size_t(height);
    for (size_t k = 0, j = 0; k < n; ++k)
      if (covered[k / 8] & (1u << (k % 8))) {
        std::copy(&rgb[j], &rgb[j] + 3, &img.pixels[4 * k]);
        j += 3;
      }
    return img;
  }
};

// ---- image statistics ---------------------------------------------------
// Pixels of a normal render (colour = 0.5 + 0.5 n, background black) that
// show the surface.
inline bool covered(const ts::Image& normals, int x, int y) {
  ts::Rgba c = normals.at(x, y);
  return c.r + c.g + c.b > 0;
}
inline glm::dvec3 normalAt(const ts::Image& normals, int x, int y) {
  ts::Rgba c = normals.at(x, y);
  return glm::normalize(glm::dvec3(c.r, c.g, c.b) / 255.0 * 2.0 - 1.0);
}
inline double angleDeg(glm::dvec3 a, glm::dvec3 b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * 180.0 / kPi;
}

// The outline: pixels covered by one normal render and not the other,
// divided by the length of `smooth`'s outline (its covered pixels with an
// uncovered 4-neighbour): the mean distance between the outlines, pixels.
inline double outlineDeviationPx(const ts::Image& a, const ts::Image& smooth) {
  long differ = 0, edge = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const bool cs = covered(smooth, x, y);
      differ += covered(a, x, y) != cs;
      if (cs && (x == 0 || y == 0 || x + 1 == a.width || y + 1 == a.height || !covered(smooth, x - 1, y) ||
                 !covered(smooth, x + 1, y) || !covered(smooth, x, y - 1) || !covered(smooth, x, y + 1)))
        ++edge;
    }
  return edge ? double(differ) / double(edge) : 0.0;
}

// The seam where the texture repeats (and where s wraps, at theta = 0): the
// mean angle between the normal-map texels on either side of the edge
// x = W-1 | x = 0, and the mean between all other neighbouring columns.
// Baked without `wrap` the slopes at the edge are one-sided.
inline glm::dvec2 seamJumpDeg(const ts::Image& normalMap) {
  auto n = [&](int x, int y) {
    ts::Rgba c = normalMap.at(x, y);
    return glm::normalize(glm::dvec3(c.r, c.g, c.b) / 255.0 * 2.0 - 1.0);
  };
  glm::dvec2 sum(0.0);
  for (int y = 0; y < normalMap.height; ++y)
    for (int x = 0; x < normalMap.width; ++x)
      (x + 1 == normalMap.width ? sum.x : sum.y) += angleDeg(n(x, y), n((x + 1) % normalMap.width, y));
  return {sum.x / normalMap.height, sum.y / (double(normalMap.height) * (normalMap.width - 1))};
}

// A method's render against the reference's, over the pixels both cover
// (a 2-pixel margin in from either outline, so that the silhouettes, which
// differ by design, are measured apart).
struct Compare {
  double psnr = 0, mad = 0, normalDeg = 0;
  double screenNormalDeg = 0;  // the demo's captions: normalDeg in the same pixel, when normalDeg is at the same (s,t)
  long pixels = 0;
};
inline Compare compare(const ts::Image& shaded, const ts::Image& normals, const ts::Image& refShaded,
                       const ts::Image& refNormals) {
  Compare c;
  double se = 0, ae = 0, deg = 0;
  const int m = 2;
  for (int y = m; y < shaded.height - m; ++y)
    for (int x = m; x < shaded.width - m; ++x) {
      bool inside = true;
      for (int dy = -m; dy <= m && inside; dy += m)
        for (int dx = -m; dx <= m && inside; dx += m)
          inside = covered(normals, x + dx, y + dy) && covered(refNormals, x + dx, y + dy);
      if (!inside) continue;
      ts::Rgba a = shaded.at(x, y), b = refShaded.at(x, y);
      for (int k = 0; k < 3; ++k) {
        double d = double((&a.r)[k]) - double((&b.r)[k]);
        se += d * d, ae += std::fabs(d);
      }
      deg += angleDeg(normalAt(normals, x, y), normalAt(refNormals, x, y));
      ++c.pixels;
    }
  if (c.pixels == 0) return c;
  double mse = se / (3.0 * double(c.pixels));
  c.psnr = mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 99.0;
  c.mad = ae / (3.0 * double(c.pixels));
  c.normalDeg = deg / double(c.pixels);
  return c;
}

// The mean angle between a bumped normal render and the smooth surface's
// (the same view with no bumps): how far the method tilts the normals.
inline double meanTiltDeg(const ts::Image& normals, const ts::Image& smooth) {
  double sum = 0;
  long n = 0;
  for (int y = 0; y < normals.height; ++y)
    for (int x = 0; x < normals.width; ++x)
      if (covered(normals, x, y) && covered(smooth, x, y))
        sum += angleDeg(normalAt(normals, x, y), normalAt(smooth, x, y)), ++n;
  return n ? sum / double(n) : 0.0;
}

// Does the method tilt the normals the way the true surface does?  Over the
// pixels all three renders cover, the mean sign agreement between the
// method's perturbation (n - n_smooth) and the reference's along the eye's
// x and y: +1 the same way everywhere, -1 the opposite way.  Pixels where
// the reference's perturbation along the axis is under 0.02 are left out.
// `rows` restricts to image rows [rows.x, rows.y) (the near or far side).
inline glm::dvec2 perturbationAgreement(const ts::Image& normals, const ts::Image& ref, const ts::Image& smooth,
                                        glm::ivec2 rows = {0, 1 << 30}) {
  glm::dvec2 sum(0.0), cnt(0.0);
  for (int y = std::max(rows.x, 0); y < std::min(rows.y, normals.height); ++y)
    for (int x = 0; x < normals.width; ++x) {
      if (!covered(normals, x, y) || !covered(ref, x, y) || !covered(smooth, x, y)) continue;
      glm::dvec3 s = normalAt(smooth, x, y), a = normalAt(normals, x, y) - s, b = normalAt(ref, x, y) - s;
      for (int k = 0; k < 2; ++k)
        if (std::fabs(b[k]) > 0.02 && std::fabs(a[k]) > 0.005) sum[k] += (a[k] * b[k] > 0 ? 1.0 : -1.0), cnt[k] += 1;
    }
  return {cnt.x ? sum.x / cnt.x : 0.0, cnt.y ? sum.y / cnt.y : 0.0};
}
// The picture of what perturbationAgreement counts along the eye's x, in
// the rows `bands` (the near and the far side): each pixel it counts
// painted `with` where the method tilts the normal as the reference does,
// `against` where it tilts it the other way; the rest of the surface
// `surface`, the rest `background`.  (with - against) / (with + against)
// over a band's rows is that band's agreement.
inline ts::Image agreementPicture(const ts::Image& normals, const ts::Image& ref, const ts::Image& smooth,
                                  const std::vector<glm::ivec2>& bands, ts::Rgba with, ts::Rgba against,
                                  ts::Rgba surface, ts::Rgba background) {
  ts::Image out(normals.width, normals.height, background);
  for (int y = 0; y < normals.height; ++y)
    for (int x = 0; x < normals.width; ++x) {
      if (!covered(smooth, x, y)) continue;
      out.set(x, y, surface);
      const bool inBand = std::any_of(bands.begin(), bands.end(), [&](glm::ivec2 b) { return y >= b.x && y < b.y; });
      if (!inBand || !covered(normals, x, y) || !covered(ref, x, y)) continue;
      const glm::dvec3 s = normalAt(smooth, x, y), a = normalAt(normals, x, y) - s, b = normalAt(ref, x, y) - s;
      if (std::fabs(b.x) > 0.02 && std::fabs(a.x) > 0.005) out.set(x, y, a.x * b.x > 0 ? with : against);
    }
  return out;
}
// The rows a normal render's surface covers: [first, last + 1).
inline glm::ivec2 coveredRows(const ts::Image& normals) {
  glm::ivec2 r(normals.height, 0);
  for (int y = 0; y < normals.height; ++y)
    for (int x = 0; x < normals.width; ++x)
      if (covered(normals, x, y)) r.x = std::min(r.x, y), r.y = std::max(r.y, y + 1);
  return r;
}
}  // namespace bump
