// demos/texture_residency/texture_residency_math.hpp — the demo's equations as plain math (no GL): the
// implicit corresponder u = s w, v = t h at three sizes; the levels a facing surface at distance d reads and
// the memory of those levels against the whole chain; the clipmap's procedural 16384^2 texture, its
// per-level windows, the strips a move exposes (uploaded toroidally) and the picture the stack must give.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "common/core/image.hpp"
#include "common/core/texture_memory.hpp"

namespace ts::residency {
// ---- the size rules (view sizes) -------------------------------------------------------------------------------
constexpr std::array<int, 3> kSizes = {64, 256, 1024};
// The marker: the square s in [40/64, 42/64), t in [20/64, 22/64) of every size, whole texels at each (64ths).
constexpr int kMarkerI64 = 40, kMarkerJ64 = 20, kMarkerSide64 = 2;
constexpr double kMarkerS = (kMarkerI64 + kMarkerSide64 / 2.0) / 64, kMarkerT = (kMarkerJ64 + kMarkerSide64 / 2.0) / 64;
constexpr int kSizePanelPx = 256;  // the measurement draws each size on a 256 x 256 quad
inline bool inMarker(int size, int i, int j) {
  const int i64 = i * 64 / size, j64 = j * 64 / size;  // the 64th of the texture the texel lies in
  return i64 >= kMarkerI64 && i64 < kMarkerI64 + kMarkerSide64 && j64 >= kMarkerJ64 && j64 < kMarkerJ64 + kMarkerSide64;
}
inline const Rgba kMarkerColour{250, 40, 40, 255};

// ---- residency by distance (view residency) --------------------------------------------------------------------
constexpr int kLevelTexels = 256, kLevels = 9;  // the level-colour texture: 256^2, levels 0..8
constexpr std::array<double, 5> kDistances = {1.5, 3, 6, 12, 24};
constexpr int kDistancePanelPx = 192;  // each distance's panel, square
constexpr double kTanHalfFov = 0.375;  // so the unit quad at d = 1 is 256 px: 1 texel a pixel
// The quad (side 1 at distance d, facing) spans 192 / (2 d 0.375) = 256 / d pixels: rho = d texels a pixel.
inline double quadPixels(double d) { return kDistancePanelPx / (2 * d * kTanHalfFov); }
inline double lambdaAt(double d) { return std::log2(kLevelTexels / quadPixels(d)); }
// Texels of levels k .. the 1 x 1 of a size x size chain.
inline uint64_t texelsFrom(int k, int size = kLevelTexels) {
  uint64_t n = 0;
  for (int s = size >> k; s >= 1; s /= 2) n += uint64_t(s) * uint64_t(s);
  return n;
}
inline double residentFraction(int finest, int size = kLevelTexels) {
  return double(texelsFrom(finest, size)) / double(chainTexels(uint64_t(size)));
}

// ---- the clipmap (view clipmap) ---------------------------------------------------------------------------------
constexpr int kVirtual = 16384;  // the virtual texture: 16384^2 texels at level 0, periodic
constexpr int kClip = 512;       // each clipped level's texture: 512^2, toroidal
constexpr int kClipLevels = 6;   // levels 0..5 are clipped (16384 >> 5 = 512: level 5 is whole)
constexpr int kViewPx = 512;     // the view: 512^2 pixels over the whole 16384^2, centred on the eye
constexpr int kTexelsPerPixel = kVirtual / kViewPx;  // 32
struct Eye {
  int x = 0, y = 0;  // level-0 texels
};
// The eye's path: a start and equal steps (level-0 texels a step); the figure shows it after kMoves of them.
constexpr Eye kEyeStart{4100, 8700};  // on a coast: land and water ahead
constexpr int kMoves = 8, kStepX = 37, kStepY = 21;
inline Eye eyeAfter(int moves) { return {kEyeStart.x + moves * kStepX, kEyeStart.y + moves * kStepY}; }

inline int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
inline int mod(int a, int b) { return ((a % b) + b) % b; }
// Level l's window: level-l texels [origin, origin + 512) in x and y, centred on the eye.
inline Eye windowOrigin(const Eye& e, int l) {
  return {floorDiv(e.x, 1 << l) - kClip / 2, floorDiv(e.y, 1 << l) - kClip / 2};
}

namespace detail {
inline uint32_t hash3(uint32_t a, uint32_t b, uint32_t c) {
  uint32_t h = a * 73856093u ^ b * 19349663u ^ c * 83492791u;
  h ^= h >> 15, h *= 0x2c1b3c6du, h ^= h >> 12, h *= 0x297a2d39u, h ^= h >> 15;
  return h;
}
}  // namespace detail
// The virtual texture, defined at every level directly (integer arithmetic only, the same on every platform):
// level l's texel (i, j) is value noise (a lattice every 1024 level-0 texels, 16 x 16 lattice points round
// the period) at the texel's centre, ((2i + 1) 2^l / 2, (2j + 1) 2^l / 2) in level-0 texels, shaded into
// land colours, plus a grain of its own (a hash of l, i, j) so that no texel equals its neighbours.
inline Rgba virtualTexel(int l, int i, int j) {
  const int period = kVirtual >> l;
  i = mod(i, period), j = mod(j, period);
  const int64_t x2 = int64_t(2 * i + 1) << l, y2 = int64_t(2 * j + 1) << l;  // doubled level-0 coordinates
  constexpr int64_t kCell = 2048, kLattice = 16;                             // 1024 texels, doubled
  const int64_t cx = x2 / kCell, cy = y2 / kCell, fx = x2 % kCell, fy = y2 % kCell;
  auto h = [](int64_t a, int64_t b) {
    return int64_t(detail::hash3(uint32_t(a % kLattice), uint32_t(b % kLattice), 7u) & 255u);
  };
  const int64_t v = (h(cx, cy) * (kCell - fx) * (kCell - fy) + h(cx + 1, cy) * fx * (kCell - fy) +
                     h(cx, cy + 1) * (kCell - fx) * fy + h(cx + 1, cy + 1) * fx * fy) /
                    (kCell * kCell);  // 0..255
  const int grain = int(detail::hash3(uint32_t(i), uint32_t(j), uint32_t(l) + 101u) % 13u);
  const bool water = v < 90;
  const int r = water ? 30 + int(v) / 4 : 70 + int(v) / 2, g = water ? 60 + int(v) / 3 : 150 - int(v) / 5,
            b = water ? 120 + int(v) / 2 : 40 + int(v) / 6;
  return {uint8_t(r + grain), uint8_t(g + grain), uint8_t(b + grain), 255};
}

// A rectangle of level-l texels in the virtual (unwrapped) coordinates.
struct TexelRect {
  int x = 0, y = 0, w = 0, h = 0;
  long long texels() const { return (long long)w * h; }
};
// What a move from `from` to `to` exposes of level l's window: the columns that entered (full height of the
// new window), then the rows that entered outside those columns.  Their texels are exactly the new window's
// texels that the old one lacked; a move of a whole window or more exposes all of it.
inline std::vector<TexelRect> exposed(const Eye& from, const Eye& to, int l) {
  const Eye a = windowOrigin(from, l), b = windowOrigin(to, l);
  const int dx = b.x - a.x, dy = b.y - a.y;
  if (std::abs(dx) >= kClip || std::abs(dy) >= kClip) return {{b.x, b.y, kClip, kClip}};
  std::vector<TexelRect> out;
  if (dx != 0) out.push_back({dx > 0 ? a.x + kClip : b.x, b.y, std::abs(dx), kClip});
  if (dy != 0)
    out.push_back({dx > 0 ? b.x : b.x + std::abs(dx), dy > 0 ? a.y + kClip : b.y, kClip - std::abs(dx), std::abs(dy)});
  return out;
}
// The texels a move uploads over the whole stack (the equation the recorded calls are held to).
inline long long exposedTexels(const Eye& from, const Eye& to) {
  long long n = 0;
  for (int l = 0; l < kClipLevels; ++l)
    for (const TexelRect& r : exposed(from, to, l)) n += r.texels();
  return n;
}
// A virtual rectangle cut where the toroidal storage wraps: up to four pieces, each as (storage x, storage y,
// virtual x, virtual y, w, h).
struct Piece {
  int sx, sy, vx, vy, w, h;
};
inline std::vector<Piece> toroidalPieces(const TexelRect& r) {
  std::vector<Piece> out;
  for (int y = r.y; y < r.y + r.h;) {
    const int sy = mod(y, kClip), h = std::min(r.y + r.h - y, kClip - sy);
    for (int x = r.x; x < r.x + r.w;) {
      const int sx = mod(x, kClip), w = std::min(r.x + r.w - x, kClip - sx);
      out.push_back({sx, sy, x, y, w, h});
      x += w;
    }
    y += h;
  }
  return out;
}

// The view: pixel (px, py) (py up from the bottom) covers level-0 texels from O + 32 (px, py), O = eye - 8192 +
// 1/2; its centre, O + 32 p + 16, is a whole texel plus a half, so it never lies on a texel's edge at any level
// (those are whole multiples of 2^l) nor on a window's edge: GL_NEAREST has no ties, and the answer is exact.
inline double viewOriginX(const Eye& e) { return e.x - kVirtual / 2 + 0.5; }
inline double viewOriginY(const Eye& e) { return e.y - kVirtual / 2 + 0.5; }
// The finest level whose window holds the level-0 point (x, y), and that level's texel there: what the stack
// drawn coarsest first shows at the point.  Outside every window (a pixel at the view's edge) the coarsest level,
// whose window is its whole period, still holds the texel.
inline int levelAt(const Eye& e, double x, double y) {
  for (int l = 0; l < kClipLevels; ++l) {
    const Eye w = windowOrigin(e, l);
    const double s = double(1 << l);
    if (x >= w.x * s && x < (w.x + kClip) * s && y >= w.y * s && y < (w.y + kClip) * s) return l;
  }
  return kClipLevels - 1;
}
// The picture the stack must give at eye e (row 0 the top, as a readback), and each pixel's level.
inline Image referenceView(const Eye& e, std::vector<int>* levels = nullptr) {
  Image img(kViewPx, kViewPx);
  if (levels) levels->assign(size_t(kViewPx) * kViewPx, 0);
  for (int py = 0; py < kViewPx; ++py)
    for (int px = 0; px < kViewPx; ++px) {
      const double x = viewOriginX(e) + kTexelsPerPixel * (px + 0.5), y = viewOriginY(e) + kTexelsPerPixel * (py + 0.5);
      const int l = levelAt(e, x, y);
      const double s = double(1 << l);
      img.set(px, kViewPx - 1 - py, virtualTexel(l, int(std::floor(x / s)), int(std::floor(y / s))));
      if (levels) (*levels)[size_t(kViewPx - 1 - py) * kViewPx + size_t(px)] = l;
    }
  return img;
}
inline long long differingPixels(const Image& a, const Image& b) {
  long long n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) n += a.at(x, y) != b.at(x, y);
  return n;
}

// ---- the flight: the same stack seen in perspective ---------------------------------------------------------------
// An eye kFlightHeight level-0 texels above the ground at the clipmap's eye, looking ahead (+y) and down.  The
// windows drawn coarsest first as ground quads: the ground at distance r from the eye is shown by the finest
// window that reaches r, whose texels, 2^l level-0 texels wide, cover about as much of the screen there as level 0
// does near the eye: Tanner's choice of level by distance, made by the windows' sizes.
constexpr int kFlightW = 640, kFlightH = 320;
constexpr double kFlightHeight = 200, kFlightAhead = 500, kFlightFovYDeg = 60, kFlightFar = 40000;
inline const Rgba kSky{24, 24, 48, 255};  // the flight's clear colour: beyond every window
constexpr int kEdgeMarginInv = 64;        // pixels within 1/64 pixel of an edge are not held to one texel
struct Camera {
  glm::dmat4 projection, view;
};
inline Camera flightCamera(const Eye& e) {
  const glm::dvec3 eye(e.x + 0.5, e.y + 0.5, kFlightHeight), at(e.x + 0.5, e.y + 0.5 + kFlightAhead, 0);
  return {glm::perspective(glm::radians(kFlightFovYDeg), double(kFlightW) / kFlightH, 1.0, kFlightFar),
          glm::lookAt(eye, at, glm::dvec3(0, 0, 1))};
}
// What the stack shows at the point (px + dx, py + dy) of the flight view (py up from the bottom): the level and
// texel of the ground point there, or level -1 where the ray misses the windows (the sky, kSky).
struct Sample {
  int level = -1, i = 0, j = 0;
  bool operator==(const Sample& o) const { return level == o.level && i == o.i && j == o.j; }
};
inline Sample flightSample(const Eye& e, const Camera& c, double x, double y) {
  const glm::dmat4 inv = glm::inverse(c.projection * c.view);
  const double nx = 2 * x / kFlightW - 1, ny = 2 * y / kFlightH - 1;
  glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
  a /= a.w, b /= b.w;
  if (b.z >= a.z) return {};
  const double t = a.z / (a.z - b.z);
  if (t > 1) return {};
  const double gx = a.x + t * (b.x - a.x), gy = a.y + t * (b.y - a.y);
  for (int l = 0; l < kClipLevels; ++l) {
    const Eye w = windowOrigin(e, l);
    const double s = double(1 << l);
    if (gx >= w.x * s && gx < (w.x + kClip) * s && gy >= w.y * s && gy < (w.y + kClip) * s)
      return {l, int(std::floor(gx / s)), int(std::floor(gy / s))};
  }
  return {};
}
// The flight view the stack must give (row 0 the top); `ambiguous` marks the pixels whose centre lies within
// 1/64 pixel of a texel's or a window's edge (a corner of the square of half-side 1/64 around the centre samples
// otherwise: any edge through the square's inscribed circle separates a corner from the centre).  GL snaps the
// projected vertices to 1/256 pixel (llvmpipe, softpipe) and interpolates in float, so it may take either side
// there; those pixels are not held to one texel, every other must be exact.
inline Image referenceFlight(const Eye& e, std::vector<char>* ambiguous, std::vector<int>* levels = nullptr) {
  const Camera c = flightCamera(e);
  Image img(kFlightW, kFlightH, kSky);
  ambiguous->assign(size_t(kFlightW) * kFlightH, 0);
  if (levels) levels->assign(size_t(kFlightW) * kFlightH, -1);
  constexpr double d = 1.0 / kEdgeMarginInv;
  for (int py = 0; py < kFlightH; ++py)
    for (int px = 0; px < kFlightW; ++px) {
      const double x = px + 0.5, y = py + 0.5;
      const Sample s = flightSample(e, c, x, y);
      bool same = true;
      for (const auto& o : {glm::dvec2(-d, -d), glm::dvec2(d, -d), glm::dvec2(-d, d), glm::dvec2(d, d)})
        same = same && flightSample(e, c, x + o.x, y + o.y) == s;
      const size_t at = size_t(kFlightH - 1 - py) * kFlightW + size_t(px);
      (*ambiguous)[at] = !same;
      if (levels) (*levels)[at] = s.level;
      if (s.level >= 0) img.set(px, kFlightH - 1 - py, virtualTexel(s.level, s.i, s.j));
    }
  return img;
}
// Pixels that differ, outside the ambiguous ones.
inline long long differingPixels(const Image& a, const Image& b, const std::vector<char>& skip) {
  long long n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) n += !skip[size_t(y) * size_t(a.width) + size_t(x)] && a.at(x, y) != b.at(x, y);
  return n;
}
}  // namespace ts::residency
