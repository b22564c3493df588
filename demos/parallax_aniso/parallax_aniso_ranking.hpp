// demos/parallax_aniso/parallax_aniso_ranking.hpp — the ranking view (v ranking, --view ranking; the
// figure parallax_ranking): seed 003 says parallax mapping gives the most realistic relief of bump, normal,
// displacement and parallax mapping, and measures nothing.  Here the five methods (parallax_aniso_ranking_gl.hpp)
// draw the same bricks at the same grazing angle under one directional light, and each is held against a
// reference traced on the CPU through the height field:
//
//   for n x n jittered rays per pixel (box filter):  d* = traceFine(uv0, Vp)   (the first hit, fine steps)
//       c += albedo(uv0 + Vp d*) (ka + (1 - ka) max(0, N(uv0 + Vp d*) . L)) / n^2
//
// N is the height field's own normal at the hit (central differences, heightNormal), the same formula the
// normal map stores and bump mapping evaluates at the unshifted point.  The measurements, per method:
// relief_rank_psnr_db[m], relief_rank_ssim[m] (the demo's psnr() and ssim()), relief_rank[m] (1 = the highest
// PSNR), and the displacement grid's spacing and triangles.  Whether the seed's claim holds is read off the
// ranks, never typed: ranking().claimHolds.
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/gl/gl_listing.hpp"
#include "parallax_aniso_math.hpp"
#include "parallax_aniso_ranking_gl.hpp"

namespace pax::rank {
// What the ranking renders and traces.
struct Setup {
  Camera cam;                  // the demo's camera (same angle, same bricks)
  Light light;                 // the one directional light
  int rays = 3;                // reference rays per side of each pixel (n x n)
  int gridTexels = 2;          // displacement: texels between vertices
  double refHeightScale = -1;  // the reference traced with this height scale (< 0: the camera's; a control)
  uint32_t seed = 1;
};

// The shaded reference: n x n stratified jittered rays per pixel, a box filter; each traced with traceFine
// and shaded at its hit with the height field's normal.  Row 0 = top.  Rows shared by two threads.  `depth`
// (may be null) gets the rays' mean hit depth, grey: white the top of the relief, black its floor.
inline ts::Image traceShaded(const Setup& s, const Relief& r, ts::Image* depth = nullptr) {
  Camera cam = s.cam;
  if (s.refHeightScale >= 0) cam.heightScale = s.refHeightScale;
  const int n = std::max(1, s.rays);
  ts::Image out(cam.width, cam.height), hitDepth(cam.width, cam.height);
  auto rows = [&](int y0, int step) {
    for (int y = y0; y < cam.height; y += step) {
      // A window shows the rows done; a superseded measurement stops early (measureRanking then throws).
      if (ts::measureCancelled(y0 == 0 ? 0.2 + 0.75 * double(y) / cam.height : -1.0)) return;
      for (int x = 0; x < cam.width; ++x) {
        const int gy = cam.height - 1 - y;  // GL row
        uint32_t key = hash32(s.seed * 0x85ebca6bu ^ hash32(uint32_t(x) ^ hash32(uint32_t(gy) + 0x27d4eb2fu)));
        glm::dvec3 sum(0);
        double dsum = 0;
        for (int b = 0; b < n; ++b)
          for (int a = 0; a < n; ++a) {
            uint32_t k = key + 2u * uint32_t(b * n + a);
            glm::dvec2 p(x + (a + unit(hash32(k))) / n, gy + (b + unit(hash32(k + 1))) / n);
            glm::dvec3 d = cam.ray(p);
            glm::dvec2 uv0 = cam.topUV(d), Vp = cam.parallax(d);
            const double dHit = traceFine(r, uv0, Vp);
            const glm::dvec2 hit = uv0 + Vp * dHit;
            dsum += dHit;
            sum += lambert(glm::dvec3(bilinear(r.albedo[0], hit)), heightNormal(r, hit, cam.heightScale, cam.tile),
                           s.light);
          }
        sum /= double(n * n);
        out.set(x, y, {u8(sum.r), u8(sum.g), u8(sum.b), 255});
        const uint8_t g = u8(255.0 * (1.0 - dsum / double(n * n)));
        hitDepth.set(x, y, {g, g, g, 255});
      }
    }
  };
  std::thread t(rows, 1, 2);
  rows(0, 2);
  t.join();
  if (depth) *depth = std::move(hitDepth);
  return out;
}

// |error| against the reference, the channels' mean x4 on a heat scale: black 0, red 32, yellow 64 levels
// or more (the demo's band-error colours, here over the whole frame).
inline const glm::vec4 kErrNone{30 / 255.0f, 20 / 255.0f, 60 / 255.0f, 1},
    kErr32{220 / 255.0f, 40 / 255.0f, 40 / 255.0f, 1}, kErr64{1.0f, 240 / 255.0f, 80 / 255.0f, 1};
constexpr double kErrorScaleTop = 64.0;  // levels of 255: yellow
inline ts::Image errorMap(const ts::Image& img, const ts::Image& ref) {
  ts::Image out(img.width, img.height);
  for (size_t p = 0; p < size_t(img.width) * size_t(img.height); ++p) {
    double e = 0;
    for (int c = 0; c < 3; ++c) e += std::abs(double(img.pixels[p * 4 + size_t(c)]) - ref.pixels[p * 4 + size_t(c)]);
    double v = std::clamp(e / 3.0 / kErrorScaleTop, 0.0, 1.0);
    glm::dvec3 col = v < 0.5 ? glm::mix(glm::dvec3(kErrNone) * 255.0, glm::dvec3(kErr32) * 255.0, v * 2)
                             : glm::mix(glm::dvec3(kErr32) * 255.0, glm::dvec3(kErr64) * 255.0, v * 2 - 1);
    for (int c = 0; c < 3; ++c) out.pixels[p * 4 + size_t(c)] = u8(col[c]);
    out.pixels[p * 4 + 3] = 255;
  }
  return out;
}

// One measured ranking: the pictures and their numbers.
struct Ranking {
  Setup setup;
  ts::Image reference, referenceDepth;
  ts::Image images[kMethods], errors[kMethods];
  ts::gl::CallList calls[kMethods];  // the GL calls that drew each picture (measureRanking's `record`)
  double psnr[kMethods] = {}, ssim[kMethods] = {};
  int rank[kMethods] = {};  // 1 = closest (highest PSNR)
  size_t gridCells = 0;
  int gridColumns = 0, gridRows = 0;
  // The best of the parallax family (parallax, parallax occlusion) and of all five, by rank.
  int bestParallax() const { return rank[kParallax] < rank[kPom] ? kParallax : kPom; }
  int best() const { return int(std::max_element(psnr, psnr + kMethods) - psnr); }
  // The seed's claim as measured: a parallax method is the closest of the five.
  bool claimHolds() const { return rank[bestParallax()] == 1; }
};

// Ranks by PSNR: 1 + the number of methods strictly closer.
inline void rankByPsnr(Ranking& k) {
  for (int m = 0; m < kMethods; ++m) {
    k.rank[m] = 1;
    for (int o = 0; o < kMethods; ++o)
      if (k.psnr[o] > k.psnr[m]) ++k.rank[m];
  }
}

// Every method drawn by GL and held against the traced reference.  `record`: each picture drawn with its GL
// calls recorded, textures and programs made anew so that the listing shows how (the figure's listing).
inline Ranking measureRanking(ts::Renderer& r, const Relief& rel, const Setup& s, bool record = false) {
  Ranking k;
  k.setup = s;
  RankGL& gl = r.attachment<RankGL>();
  const Grid grid = displacedGrid(rel, s.cam, s.gridTexels);
  k.gridCells = grid.cells();
  k.gridColumns = grid.columns;
  k.gridRows = grid.rows;
  for (int m = 0; m < kMethods; ++m) {
    if (!record) {
      k.images[m] = gl.render(s.cam, rel, s.light, m, &grid);
      continue;
    }
    r.attachment<ReliefGL>().release();
    gl.release();
    k.calls[m] = ts::recordRender(r, [&] { k.images[m] = gl.render(s.cam, rel, s.light, m, &grid); });
  }
  ts::measureProgress(0.2);  // the five passes drawn; in a window, throws if superseded
  k.reference = traceShaded(s, rel, &k.referenceDepth);
  ts::measureProgress(0.95);  // throws if the trace above was stopped early
  for (int m = 0; m < kMethods; ++m) {
    k.psnr[m] = psnr(k.images[m], k.reference, nullptr);
    k.ssim[m] = ssim(k.images[m], k.reference, nullptr);
    k.errors[m] = errorMap(k.images[m], k.reference);
  }
  rankByPsnr(k);
  return k;
}

inline std::string psnrName(int m) { return std::string("relief_rank_psnr_db[") + kMethodKeys[m] + "]"; }
inline std::string ssimName(int m) { return std::string("relief_rank_ssim[") + kMethodKeys[m] + "]"; }
inline std::string rankName(int m) { return std::string("relief_rank[") + kMethodKeys[m] + "]"; }

inline void addMeasurements(ts::Measurements& out, const Ranking& k) {
  for (int m = 0; m < kMethods; ++m) {
    out.push_back({psnrName(m), k.psnr[m],
                   std::string(kMethodLabels[m]) + ": PSNR (dB) against the traced, lit reference, whole frame"});
    out.push_back({ssimName(m), k.ssim[m], std::string(kMethodLabels[m]) + ": SSIM against that reference"});
    out.push_back({rankName(m), double(k.rank[m]), std::string(kMethodLabels[m]) + ": rank by PSNR, 1 = closest"});
  }
  out.push_back({"relief_rank_grid_texels", double(k.setup.gridTexels), "displacement: texels between grid vertices"});
  out.push_back({"relief_rank_grid_triangles", double(2 * k.gridCells), "displacement: triangles drawn"});
  out.push_back({"relief_rank_rays", double(k.setup.rays * k.setup.rays), "reference rays per pixel"});
}

// What the figure shows: the ranking and its pictures as textures.
struct RankShown {
  std::shared_ptr<const Ranking> ranking;
  ts::TextureDesc reference, referenceDepth, images[kMethods], errors[kMethods];
};
inline RankShown rankShownOf(std::shared_ptr<const Ranking> k) {
  auto tex = [](const ts::Image& img, const std::string& what) {
    return ts::renderedImageTexture(img, "parallax_render", what, "parallax_aniso");
  };
  RankShown s;
  s.reference = tex(k->reference, "rank_reference");
  s.referenceDepth = tex(k->referenceDepth, "rank_reference_depth");
  for (int m = 0; m < kMethods; ++m) {
    s.images[m] = tex(k->images[m], std::string("rank_") + kMethodKeys[m]);
    s.images[m].renderedBy = k->calls[m];
    s.errors[m] = tex(k->errors[m], std::string("rank_error_") + kMethodKeys[m]);
  }
  s.ranking = std::move(k);
  return s;
}

// The figure: the reference and the five methods in a row, under them each method's error map (the first
// cell of that row says what the reference is), the legend of the error colours, and the ranking in words.
inline void buildRanking(ts::Frame& f, const ts::Measurements& mm, const RankShown& shown, const std::string& header) {
  namespace L = ts::layout;
  const Ranking& k = *shown.ranking;
  struct Pic {
    const ts::TextureDesc* tex;
    L::Captioned caption;
  };
  // A narrow window (under 900 pixels) keeps six pictures: the reference and each method's error map, the
  // method's rank and numbers over and under it; the figure and wide windows show the renders too.
  const bool compact = f.width < 900;
  std::vector<Pic> pics;
  pics.push_back({&shown.reference,
                  {L::Text("reference, traced"), L::measuredText(mm, "{relief_rank_rays|%.0f} rays per pixel, CPU")}});
  for (int m = 0; m < kMethods; ++m) {
    L::Text title = L::Text(compact ? std::string("|error| ") + kMethodKeys[m] + " #"
                                    : std::string(kMethodLabels[m]) + "  #") +
                    L::measured(mm, rankName(m), "%.0f");
    L::Text note = L::measured(mm, psnrName(m), "%.1f") + L::Text(" dB, SSIM ") + L::measured(mm, ssimName(m), "%.3f");
    pics.push_back({compact ? &shown.errors[m] : &shown.images[m], {title, note}});
  }
  if (!compact) {
    pics.push_back(
        {&shown.referenceDepth, {L::Text("reference: depth of the hit"), L::Text("white top, black floor")}});
    for (int m = 0; m < kMethods; ++m)
      pics.push_back({&shown.errors[m],
                      {L::Text(std::string("|error| ") + kMethodKeys[m]),
                       m == kDisplacement ? L::measuredText(mm, "grid every {relief_rank_grid_texels|%.0f} texels, "
                                                                "{relief_rank_grid_triangles|%.0f} triangles")
                                          : L::Text(std::string(m == kBump || m == kNormalMap ? "unshifted coordinate"
                                                                : m == kParallax              ? "one offset step"
                                                                                              : "the demo's march"))}});
  }
  std::vector<L::Captioned> captions;
  for (const Pic& p : pics) captions.push_back(p.caption);

  // The ranking in words, from the ranks: who is closest, where the parallax methods stand, and so whether
  // the seed's claim holds as measured.
  const int best = k.best(), bp = k.bestParallax();
  std::vector<int> order = {0, 1, 2, 3, 4};
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return k.psnr[a] > k.psnr[b]; });
  L::Text ranking("Ranked by PSNR: ");
  for (int i = 0; i < kMethods; ++i) {
    int m = order[size_t(i)];
    ranking = ranking + L::Text(std::string(i ? ",  " : "") + kMethodKeys[m] + " ") +
              L::measured(mm, psnrName(m), "%.1f");
  }
  ranking = ranking + L::Text(" dB.");
  L::Text verdict =
      k.claimHolds()
          ? L::Text(std::string("Seed 003's claim holds as measured: ") + kMethodLabels[bp] + " is closest (") +
                L::measured(mm, psnrName(bp), "%.1f") + L::Text(" dB).")
          : L::Text(std::string("Seed 003's claim does not hold as measured: ") + kMethodLabels[best] + " (") +
                L::measured(mm, psnrName(best), "%.1f") +
                L::Text(std::string(" dB) is closer than the best parallax method, ") + kMethodLabels[bp] + " (") +
                L::measured(mm, psnrName(bp), "%.1f") + L::Text(" dB, rank ") + L::measured(mm, rankName(bp), "%.0f") +
                L::Text(").");
  // Among the texture-space methods (no new geometry), is a parallax method closer than bump and normal?
  const int texBest = k.psnr[bp] >= std::max(k.psnr[kBump], k.psnr[kNormalMap]) ? bp
                      : k.psnr[kBump] >= k.psnr[kNormalMap]                     ? kBump
                                                                                : kNormalMap;
  L::Text perPixel = L::Text(std::string("Among the per-pixel methods (no new geometry) the closest is ") +
                             kMethodLabels[texBest] + " (") +
                     L::measured(mm, psnrName(texBest), "%.1f") + L::Text(" dB).");
  L::Text scale = L::Text("|error|: the channels' mean against the reference; the scale's top is ") +
                  L::given("error_scale_top_levels", kErrorScaleTop, "%.0f") + L::Text(" levels.");
  std::vector<L::Text> notes = {L::Text(header) + L::Text(".  ") + scale, ranking, verdict, perPixel};
  std::vector<ts::LegendEntry> legend = {{kErrNone, "no error against the reference"},
                                         {kErr32, "|error| half the scale"},
                                         {kErr64, "|error| the scale's top or more"},
                                         {{1, 1, 1, 1}, "hit on the top of the relief"},
                                         {{0, 0, 0, 1}, "on its floor (depth, grey between)"}};
  if (compact) {  // the state is in the side panel; no depth picture
    notes = {scale, ranking, verdict};
    legend.resize(3);
  }
  L::pictureFigure(
      f, captions,
      [&](size_t i, const ts::Rect& r) {
        f.panels.push_back(L::picturePanel(f, "rank_picture_" + std::to_string(i), r, *pics[i].tex));
      },
      // Captions at scale 1 (twelve cells share the frame), six to a row where the width allows.
      legend, notes, {0, float(k.reference.width) / float(k.reference.height), 1, 1, 10, 1, 110}, 4);
}
}  // namespace pax::rank
