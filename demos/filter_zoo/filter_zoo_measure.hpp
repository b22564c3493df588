// demos/filter_zoo/filter_zoo_measure.hpp — the filter zoo's measurement passes:
// each method's picture of a scene at a fixed size (384 x 192, whatever the
// window's), and what measure() prints.  Shared by the demo and its tests.
//
//  * GL methods (GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST,
//    trilinear, GL's anisotropic 16x) are GL renders: the scene's outline
//    drawn with projective (s q, t q, 0, q) so that GL's own filter, LOD and
//    derivatives act on the exact homography (filter_zoo_math.hpp: viewFrame), read
//    back through Renderer::renderOffscreen.
//  * The methods GL does not have (ripmap, SAT, the probe line, EWA) and the
//    exact area integral are computed on the CPU, in double precision, from
//    the same texture and mip chain (filter_zoo_math.hpp), and shown as pictures:
//    their results do not depend on the driver, and they count their reads.
//  * The exact reference of a scene does not depend on the method or the
//    bias: it is made once per process for each (scene, pattern, azimuth)
//    and kept (a window's later measurements and make_figures' other figures
//    reuse it).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/gl/render.hpp"
#include "filter_zoo_math.hpp"

namespace zoo {
constexpr int kImageW = 384, kImageH = 192;   // every measured picture (the mipmap demo's slant size)
constexpr double kFarLo = 1.5, kFarHi = 5.0;  // the slanted plane's far field: LOD 1.5 .. 5
inline const std::array<double, 3> kAzimuths = {0.0, 22.5, 45.0};
enum Pattern { kChecker, kGrid };
enum SceneKind { kSlant, kZonePlate, kMagnify };
inline const char* const kSceneKeys[] = {"slant", "zoneplate", "magnify"};
const ts::Rgba kBackground{77, 92, 115, 255};  // off the plane (the mipmap demo's slant clear colour)
inline glm::vec4 backgroundColour() { return {77 / 255.0f, 92 / 255.0f, 115 / 255.0f, 1.0f}; }

// "0", "22.5", "45": an azimuth in a measurement's name.
inline std::string azKey(double az) { return ts::layout::fmt("%g", az); }

// The scene's texture (256 x 256, the book's 2x2 mip chain).
inline ts::TextureDesc sceneTexture(int scene, int pattern) {
  ts::TextureDesc t = scene == kZonePlate ? zonePlate()
                      : pattern == kGrid  ? ts::labelledGrid(kTexels, 8)
                                          : ts::checkerboard(kTexels, 8);
  t.mipmaps = true;
  return t;
}
inline View sceneView(int scene, double azimuthDeg, int w = kImageW, int h = kImageH) {
  return scene == kZonePlate ? zonePlateView(w, h, azimuthDeg)
         : scene == kMagnify ? magnifyView(w, h, azimuthDeg)
                             : slantView(w, h, azimuthDeg);
}
// Where the RMS is taken: the slanted plane's far field, every pixel of the flat scenes.
inline std::vector<char> sceneMask(int scene, const View& v) {
  return scene == kSlant ? farField(v, kFarLo, kFarHi) : farField(v, -1e300, 1e300);
}

// GL's filter for a GL method.
inline void glFilter(ts::TextureDesc& t, int method, float bias) {
  t.lodBias = bias;
  t.maxAnisotropy = 1;
  switch (method) {
    case kNearest: t.minFilter = t.magFilter = GL_NEAREST; break;
    case kLinear: t.minFilter = t.magFilter = GL_LINEAR; break;
    case kNearestMipNearest: t.minFilter = GL_NEAREST_MIPMAP_NEAREST, t.magFilter = GL_NEAREST; break;
    default:  // trilinear, and under GL's anisotropic filter
      t.minFilter = GL_LINEAR_MIPMAP_LINEAR, t.magFilter = GL_LINEAR;
      if (method == kAniso16) t.maxAnisotropy = float(kMaxAniso);
  }
}
inline ts::Image glPicture(ts::Renderer& r, const View& v, ts::TextureDesc tex, int method, double bias) {
  glFilter(tex, method, float(bias));
  return r.renderOffscreen(viewFrame(v, tex, backgroundColour()));
}
// A GL method's picture of a scene (its texture, the measured 384 x 192
// view), made once per process: every figure but the kernels' measures the
// same three azimuths, and a window's first stage draws what its full
// measurement draws again.  The picture is a function of these inputs (the
// same frame to the same rasterizer), so a kept one is the one GL would draw.
// A window that visits many states clears the cache past 64 pictures (19 MB).
inline ts::Image sceneGlPicture(ts::Renderer& r, int scene, int pattern, double az, int method, double bias) {
  static std::mutex lock;
  static std::map<std::string, ts::Image> cache;
  const std::string key = std::string(methodKey(method)) + "/" + kSceneKeys[scene] + "/" + std::to_string(pattern) +
                          "/" + ts::layout::fmt("%.17g", az) + "/" + ts::layout::fmt("%.17g", bias);
  {
    std::lock_guard<std::mutex> g(lock);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
  }
  ts::Image img = glPicture(r, sceneView(scene, az), sceneTexture(scene, pattern), method, bias);
  std::lock_guard<std::mutex> g(lock);
  if (cache.size() >= 64) cache.clear();
  cache.emplace(key, img);
  return img;
}

// The exact reference of (scene, pattern, azimuth), made once per process.
// Two threads share the rows (parallelRows: the horizon's footprints are
// thousands of texels long, and their outlines are what cost).  `linearLight`: the area
// average of the texels' linear-light values, encoded back to sRGB (the
// reference for chains averaged in linear light).
inline std::shared_ptr<const Picture> exactPicture(int scene, int pattern, double azimuthDeg, const Pyramids& p,
                                                   bool linearLight = false) {
  static std::mutex lock;
  static std::map<std::string, std::shared_ptr<const Picture>> cache;
  const std::string key = std::string(kSceneKeys[scene]) + "/" + std::to_string(pattern) + "/" + azKey(azimuthDeg) +
                          (linearLight ? "/linear" : "");
  {
    std::lock_guard<std::mutex> g(lock);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
  }
  const View v = sceneView(scene, azimuthDeg);
  auto out = std::make_shared<Picture>();
  out->image = ts::Image(v.w, v.h, kBackground);
  out->exact.assign(size_t(v.w) * size_t(v.h), glm::dvec4(kBackground.r, kBackground.g, kBackground.b, 255));
  exactAverages(
      linearLight ? p.exactLinear() : p.exact, v, [&](int col, int row) { return v.coversPixel(col, row); },
      [&](int col, int row, glm::dvec4 c) {
        if (linearLight) c = glm::dvec4(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b), 255.0 * c.a);
        out->exact[size_t(row) * size_t(v.w) + size_t(col)] = c;
        out->image.set(col, row, toRgba(c));
      });
  std::lock_guard<std::mutex> g(lock);
  return cache.emplace(key, out).first->second;
}
inline const Pyramids& pyramids(int scene, int pattern) {
  static std::mutex lock;
  static std::map<int, std::unique_ptr<Pyramids>> cache;
  std::lock_guard<std::mutex> g(lock);
  std::unique_ptr<Pyramids>& slot = cache[scene == kZonePlate ? 2 : pattern];
  if (!slot) slot = std::make_unique<Pyramids>(*sceneTexture(scene, pattern).image);
  return *slot;
}

// Texels read per pixel, over the mask, by a method (the GL ones counted by
// the CPU model of GL's rule; GL's anisotropic filter cannot be counted from
// outside: -1).
inline double texelsPerPixel(int method, const Pyramids& p, const View& v, double bias, const std::vector<char>& mask) {
  if (method == kAniso16) return -1;
  if (method == kExact) return exactTexels(v, mask);
  std::atomic<long> reads{0}, pixels{0};  // integers: the same totals in any order
  parallelRows(v.h, [&](int row) {
    long rowReads = 0, n = 0;
    for (int col = 0; col < v.w; ++col) {
      if (!mask[size_t(row) * size_t(v.w) + size_t(col)]) continue;
      lookup(method, p, v, col + 0.5, v.h - 1 - row + 0.5, bias, &rowReads);
      ++n;
    }
    reads += rowReads, pixels += n;
  });
  return pixels ? double(reads) / double(pixels) : 0;
}

// ---------------------------------------------------------------- magnification, read from GL
// A row of `pixels` pixels across which 256 texels of a texel-index texture
// span s = 0..1 (GL_NEAREST): the texel index each pixel took, decoded.
inline std::vector<int> texelsShown(ts::Renderer& r, int pixels) {
  ts::TextureDesc t = ts::texelIndexTexture(kTexels);
  t.minFilter = t.magFilter = GL_NEAREST;
  ts::Frame f;
  f.width = pixels, f.height = 2;
  ts::Panel p = ts::layout::unitPanel("row", {0, 0, pixels, 2});
  ts::Batch b;
  b.role = "texel_index_row";
  b.texture = f.addTexture(t);
  const float tr = 0.5f / kTexels;  // the first texel row's centre
  for (glm::vec2 c :
       {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 0), glm::vec2(1, 1), glm::vec2(0, 1)})
    b.vertices.push_back({glm::vec3(c, 0.0f), glm::vec4(c.x, tr, 0.0f, 1.0f), glm::vec4(1.0f)});
  p.batches.push_back(b);
  f.panels.push_back(p);
  const ts::Image img = r.renderOffscreen(f);
  std::vector<int> out;
  for (int x = 0; x < pixels; ++x) {
    int i = 0, j = 0;
    ts::decodeTexelIndex(img.at(x, 0), &i, &j);
    out.push_back(i);
  }
  return out;
}

// ---------------------------------------------------------------- the LOD form GL uses
// The level GL's trilinear filter reads, from the mip-level-colours texture,
// on a flat view turned by `azimuthDeg` whose footprint is a square of side
// 2^lambdaEdge texels (GL's formula): the centre's mean colour read back as
// k + f.  The edge form gives lambdaEdge at any turn; the largest-component
// form lambdaEdge - log2(rho_edge / rho_max), 0.5 less at 45 degrees.
inline double glLevelAt(ts::Renderer& r, double azimuthDeg, double lambdaEdge) {
  const View v = flatView(64, 64, azimuthDeg, std::exp2(lambdaEdge), {kTexels / 2.0, kTexels / 2.0});
  ts::TextureDesc t = ts::mipLevelColours(kTexels);
  glFilter(t, kTrilinear, 0);
  const ts::Image img = r.renderOffscreen(viewFrame(v, t, backgroundColour()));
  return ts::lod::levelOfColour(ts::lod::meanOf(img, {16, 16, 32, 32}), kLevels);
}

// ---------------------------------------------------------------- one pixel's footprint
// The supports view's pixel (column, row of the 384 x 192 picture, 0,0 top
// left): what its footprint asks of each method, from the scene's homography.
struct PickedPixel {
  bool on = false;  // the whole pixel centre lies on the surface
  double preimageTexels = 0, satBoxRatio = 0, lambda = 0, texelsPerPixel = 0;
  ProbeLine probe;
};
inline PickedPixel pickedPixel(int scene, double az, int col, int row, double bias) {
  const View v = sceneView(scene, az);
  const double x = col + 0.5, y = kImageH - 1 - row + 0.5;
  PickedPixel p;
  p.on = v.covers(x, y);
  if (!p.on) return p;
  const Jacobian j = v.jacobian(x, y);
  p.preimageTexels = std::abs(ts::signedArea(v.preimage(col, row)));
  p.satBoxRatio = satBoxRatio(j);
  p.lambda = glLambda(j, bias);
  p.texelsPerPixel = ts::lod::rhoExact(j);
  p.probe = probeLine(j, bias);
  return p;
}

// ---------------------------------------------------------------- what measure() found
struct Row {
  double azimuth = 0;
  std::array<ts::TextureDesc, kMethodCount> pictures;
  std::array<double, kMethodCount> rms{}, reads{};
  // Where GL_NEAREST_MIPMAP_NEAREST's picture differs from GL_NEAREST's:
  // pixels in the RMS's mask, and the lowest exact LOD of any pixel (+inf: none).
  long nmnDiffersInMask = 0;
  double nmnDiffersFromLod = HUGE_VAL;
};
struct KernelRow {
  int kernel = 0;
  bool linear = false;
  ts::TextureDesc picture;
  double rms = 0, top = 0;
};
struct BiasRow {
  double bias = 0, rms = 0, flicker = 0;
};
struct Result {
  std::string renderer;
  int scene = kSlant;
  std::vector<Row> rows;  // the slanted plane: 0, 22.5, 45 (and the current azimuth when another); else the current
  int current = 0;        // the row of the current azimuth
  std::vector<KernelRow> kernels;  // the kernels view
  std::vector<BiasRow> bias;       // the bias view
  double flickerExact = 0;
  TexelCounts mag300, mag512, mag200;
  double lodGl0 = 0, lodGl45 = 0;
  long pixels = 0;  // in the mask
};

inline ts::TextureDesc pictureTexture(const ts::Image& img, const std::string& what, int scene, double az) {
  return ts::renderedImageTexture(img, "filter_zoo_render", what, "filter_zoo",
                                  {{"scene", kSceneKeys[scene]}, {"azimuth", azKey(az)}});
}

// A CPU method's picture of (scene, pattern, azimuth, bias) and its mean
// texels read over the mask, made once per process (they do not depend on
// the GL: a window's later measurements and the other figures reuse them).
struct CpuResult {
  ts::Image image;
  double reads = 0;
};
inline std::shared_ptr<const CpuResult> cpuResult(int method, int scene, int pattern, double az, double bias) {
  static std::mutex lock;
  static std::map<std::string, std::shared_ptr<const CpuResult>> cache;
  const std::string key = std::string(methodKey(method)) + "/" + kSceneKeys[scene] + "/" + std::to_string(pattern) +
                          "/" + azKey(az) + "/" + ts::layout::fmt("%g", bias);
  {
    std::lock_guard<std::mutex> g(lock);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
  }
  const Pyramids& p = pyramids(scene, pattern);
  const View v = sceneView(scene, az);
  const std::vector<char> mask = sceneMask(scene, v);
  auto out = std::make_shared<CpuResult>();
  if (byGL(method)) {  // the GL draws the picture; the CPU model of its rule counts the reads
    out->reads = texelsPerPixel(method, p, v, bias, mask);
  } else if (method == kExact) {
    out->image = exactPicture(scene, pattern, az, p)->image;
    out->reads = exactTexels(v, mask);
  } else {
    Picture pic = cpuPicture(method, p, v, bias, mask, kBackground);
    out->image = std::move(pic.image);
    out->reads = pic.meanReads;
  }
  std::lock_guard<std::mutex> g(lock);
  return cache.emplace(key, out).first->second;
}

// The CPU's share of measureRow(..., counts = true) at one azimuth, made and
// kept (exactPicture, cpuResult; no GL): a window's measurement starts it on
// threads of their own while its first stage is drawn.
inline void cpuRowWork(int scene, int pattern, double az, double bias) {
  exactPicture(scene, pattern, az, pyramids(scene, pattern));
  for (int m = 0; m < kMethodCount; ++m) cpuResult(m, scene, pattern, az, bias);
}

// One scene at one azimuth: every method's picture, its RMS against the exact
// integral over the mask and its texels read.
inline Row measureRow(ts::Renderer& r, int scene, int pattern, double az, double bias, bool counts) {
  Row row;
  row.azimuth = az;
  const Pyramids& p = pyramids(scene, pattern);
  const View v = sceneView(scene, az);
  const std::vector<char> mask = sceneMask(scene, v);
  const std::shared_ptr<const Picture> exact = exactPicture(scene, pattern, az, p);
  std::array<ts::Image, kMethodCount> imgs;
  for (int m = 0; m < kMethodCount; ++m) {
    ts::Image& img = imgs[size_t(m)];
    std::shared_ptr<const CpuResult> cpu;
    if (!byGL(m) || counts) cpu = cpuResult(m, scene, pattern, az, bias);
    if (byGL(m)) img = sceneGlPicture(r, scene, pattern, az, m, bias);
    else img = cpu->image;
    row.rms[size_t(m)] = m == kExact ? 0.0 : rmsAgainst(img, exact->exact, mask);
    row.reads[size_t(m)] = counts ? cpu->reads : 0;
    row.pictures[size_t(m)] = pictureTexture(img, methodKey(m), scene, az);
  }
  const ts::Image &nearest = imgs[kNearest], &nmn = imgs[kNearestMipNearest];
  for (int y = 0; y < v.h; ++y)
    for (int x = 0; x < v.w; ++x) {
      if (nearest.at(x, y) == nmn.at(x, y) || !v.coversPixel(x, y)) continue;
      row.nmnDiffersInMask += mask[size_t(y) * size_t(v.w) + size_t(x)];
      row.nmnDiffersFromLod = std::min(row.nmnDiffersFromLod,
                                       std::log2(ts::lod::rhoExact(v.jacobian(x + 0.5, v.h - 1 - y + 0.5))));
    }
  return row;
}

// The window's first stage of a row (ts::measureStage): GL's pictures as
// measured, the CPU methods' at a quarter of the resolution (coarsePicture,
// a sixteenth of the work), shown with GL_NEAREST and tagged "refining"; no
// RMS or reads yet (NaN).  Never in a figure.  The CPU's pictures come
// first; `beforeGl` (may be null) is called before GL's (llvmpipe draws the
// anisotropic filter's in about 0.1 s, the others in a millisecond or two).
inline Row coarseRow(ts::Renderer& r, int scene, int pattern, double az, double bias,
                     const std::function<void()>& beforeGl = nullptr) {
  Row row;
  row.azimuth = az;
  const View v = sceneView(scene, az);
  for (int m = 0; m < kMethodCount; ++m) {
    row.rms[size_t(m)] = row.reads[size_t(m)] = std::nan("");
    if (byGL(m)) continue;
    ts::measureProgress(0.02 + 0.08 * m / kMethodCount);
    ts::TextureDesc& t = row.pictures[size_t(m)];
    t = pictureTexture(coarsePicture(m, pyramids(scene, pattern), v, bias, 4, kBackground), methodKey(m), scene, az);
    t.minFilter = t.magFilter = GL_NEAREST;
    t.params.push_back({"stage", "coarse"});
  }
  if (beforeGl) beforeGl();
  for (int m = 0; m < kMethodCount; ++m)
    if (byGL(m))
      row.pictures[size_t(m)] = pictureTexture(sceneGlPicture(r, scene, pattern, az, m, bias), methodKey(m), scene, az);
  return row;
}

// Item 8: each kernel's chain (sRGB values, linear light) under GL's trilinear
// filter on the slanted plane at `az`: far-field RMS against the exact
// integral made the same way (of the sRGB values, or of the linear-light
// values encoded back), and the 1 x 1 level.
inline std::vector<KernelRow> measureKernels(ts::Renderer& r, int pattern, double az, double bias) {
  std::vector<KernelRow> out;
  const Pyramids& p = pyramids(kSlant, pattern);
  const View v = sceneView(kSlant, az);
  const std::vector<char> mask = sceneMask(kSlant, v);
  const std::shared_ptr<const Picture> exact = exactPicture(kSlant, pattern, az, p),
                                       exactLinear = exactPicture(kSlant, pattern, az, p, true);
  for (int k = 0; k < kKernelCount; ++k)
    for (bool lin : {false, true}) {
      ts::measureProgress(0.6 + 0.3 * (2 * k + lin) / (2.0 * kKernelCount));
      ts::TextureDesc t = sceneTexture(kSlant, pattern);
      auto chain = std::make_shared<std::vector<ts::Image>>(kernelChain(*t.image, k, lin));
      t.mipLevels = chain;
      t.params.push_back({"mip_kernel", std::string(kernelKey(k)) + (lin ? " in linear light" : " in sRGB values")});
      KernelRow row;
      row.kernel = k, row.linear = lin;
      const ts::Image img = glPicture(r, v, t, kTrilinear, bias);
      row.rms = rmsAgainst(img, (lin ? exactLinear : exact)->exact, mask);
      row.top = topValue(*chain);
      row.picture = pictureTexture(img, std::string("trilinear_") + kernelKey(k) + (lin ? "_linear" : "_srgb"), kSlant,
                                   az);
      out.push_back(row);
    }
  return out;
}

// Item 9: GL's trilinear filter with LOD bias -1 .. +1 on the slanted plane
// at `az`: the far field's RMS against the exact integral, and its flicker:
// the plane moves away 1/8 texel a frame for 8 frames, and the flicker is
// the RMS of a frame's change over the far field (the exact picture's own
// change is printed beside it: what the motion itself changes).
inline std::vector<BiasRow> measureBias(ts::Renderer& r, int pattern, double az, double* flickerExact) {
  std::vector<BiasRow> out;
  const Pyramids& p = pyramids(kSlant, pattern);
  const ts::TextureDesc tex = sceneTexture(kSlant, pattern);
  constexpr int kFrames = 8;
  constexpr double kStep = 1.0 / 8;  // texels a frame, along the plane's depth
  std::vector<View> views;
  for (int k = 0; k < kFrames; ++k) {
    View v = sceneView(kSlant, az);
    glm::dmat3 shift(1.0);
    const double a = glm::radians(az);
    shift[2][0] = -std::sin(a) * kStep * k, shift[2][1] = std::cos(a) * kStep * k;  // along the turned t axis
    v.H = shift * v.H;
    views.push_back(v);
  }
  const std::vector<char> mask = sceneMask(kSlant, views[0]);
  std::vector<Picture> exact;
  for (const View& v : views)
    exact.push_back(cpuPicture(kExact, p, v, 0, mask, kBackground, true));  // the far field only
  auto change = [&](const ts::Image& a, const ts::Image& b) {
    double sum = 0;
    long n = 0;
    for (int row = 0; row < a.height; ++row)
      for (int col = 0; col < a.width; ++col) {
        if (!mask[size_t(row) * size_t(a.width) + size_t(col)]) continue;
        const ts::Rgba x = a.at(col, row), y = b.at(col, row);
        const double dr = y.r - x.r, dg = y.g - x.g, db = y.b - x.b;
        sum += dr * dr + dg * dg + db * db, n += 3;
      }
    return n ? std::sqrt(sum / double(n)) : 0.0;
  };
  *flickerExact = 0;
  for (int k = 1; k < kFrames; ++k)
    *flickerExact += change(exact[size_t(k) - 1].image, exact[size_t(k)].image) / (kFrames - 1);
  for (double b = -1.0; b <= 1.0 + 1e-9; b += 0.5) {
    ts::measureProgress(0.6 + 0.3 * (b + 1) / 2);
    BiasRow row;
    row.bias = b;
    std::vector<ts::Image> frames;
    for (const View& v : views) frames.push_back(glPicture(r, v, tex, kTrilinear, b));
    row.rms = rmsAgainst(frames[0], exact[0].exact, mask);
    for (int k = 1; k < kFrames; ++k) row.flicker += change(frames[size_t(k) - 1], frames[size_t(k)]) / (kFrames - 1);
    out.push_back(row);
  }
  return out;
}
}  // namespace zoo
