// demos/parallax_aniso/parallax_aniso_measure.hpp — the measurement of every mode against
// the reference: the table the demo prints and writes as CSV, the tests
// regenerate and bound, and the figure shows.
#pragma once
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/gl/gl_listing.hpp"
#include "common/core/layout.hpp"
#include "common/core/probe.hpp"
#include "parallax_aniso_gl.hpp"
#include "parallax_aniso_math.hpp"

namespace pax {
struct Row {
  int mode = 0;
  double psnrAll = 0, ssimAll = 0, psnrAniso = 0, ssimAniso = 0, psnrBand = 0, ssimBand = 0;
  double ms = 0;               // median milliseconds per frame at the measured size
  double lookupsPerPixel = 0;  // texture lookups (calls) per pixel, counted by the shader
  double excludedPerPixel = 0;
  ts::Image image;
  ts::gl::CallList calls;  // the GL calls that rendered `image` (MeasureOptions::record)
};
struct Table {
  Camera cam;
  std::string map, renderer;
  int refRays = 0;
  uint32_t seed = 0;
  double refSeconds = 0;
  Reference reference;
  ts::Image referenceImage;
  std::vector<uint8_t> anisoMask, bandMask;
  size_t anisoPixels = 0, bandPixels = 0;
  std::vector<Row> rows;  // modes 0..5
  // Does the hardware filter use the gradients textureGrad hands it?  Pixels
  // of M1 and of M2 that change when those gradients are 4 times longer
  // (PassOptions::gradScale); -1 = not measured.  Trilinear filtering must
  // change (a coarser level); 0 for M2 means the driver's anisotropic filter
  // took its footprint and level from elsewhere (on llvmpipe: the implicit
  // derivatives of the shifted coordinate, M0's artifact).
  long gradChangeM1 = -1, gradChangeM2 = -1;
  float gradScale = 1;  // the gradients M1/M2 were given (MeasureOptions::gradScale)
  // A window's first stage (MeasureOptions::firstStage): the modes' pictures
  // as GL draws them, the reference traced with few rays; its numbers are not
  // the table's and are not shown.
  bool stage = false;
};

struct MeasureOptions {
  int refRays = 16;  // n x n rays per pixel for the reference
  uint32_t seed = 1;
  int timingRuns = 5;  // 0 = do not time
  bool accel = true;
  float gradScale = 1;             // the gradients M1 and M2 hand their lookup (PassOptions::gradScale)
  ts::Renderer* record = nullptr;  // set: each mode's picture is drawn anew with its GL calls recorded (Row::calls)
  // Only the pictures (Table::stage): no PSNR, SSIM or lookup counts, no
  // gradient test, no progress reported (the full measurement that follows reports it).
  bool firstStage = false;
};

inline Table measureAll(ReliefGL& gl, const Camera& cam, const Relief& rel, const MeasureOptions& o,
                        const std::vector<int>& modes = {kNaive, kTrilinear, kAniso16, kEwa, kEwaVis, kEwaRows}) {
  Table t;
  t.cam = cam;
  t.map = rel.name;
  t.renderer = ts::gl::rendererString();
  t.refRays = o.refRays;
  t.seed = o.seed;
  t.gradScale = o.gradScale;
  auto t0 = std::chrono::steady_clock::now();
  // Progress (a window shows it): the reference about 40 %, the modes the rest.
  const double refShare = 0.4;
  t.stage = o.firstStage;
  auto progress = [&](double f) {
    if (!o.firstStage) ts::measureProgress(f);
  };
  t.reference = renderReference(cam, rel, o.refRays, o.seed, [&](double f) {
    if (!o.firstStage) ts::measureCancelled(refShare * f);
  });
  progress(refShare);
  t.refSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  t.referenceImage = t.reference.image();
  t.anisoMask = anisotropyMask(cam);
  t.bandMask = occlusionMask(t.reference);
  for (uint8_t m : t.anisoMask) t.anisoPixels += m;
  for (uint8_t m : t.bandMask) t.bandPixels += m;
  const ts::Image& ref = t.referenceImage;
  for (int mode : modes) {
    progress(refShare + (1 - refShare) * 0.9 * double(t.rows.size()) / double(modes.size()));
    Row r;
    r.mode = mode;
    PassOptions po;
    po.accel = o.accel;
    po.gradScale = o.gradScale;
    if (o.record) {  // the textures, target and program made again, so that the calls show how
      gl.release();
      r.calls = ts::recordRender(*o.record, [&] { r.image = gl.render(cam, rel, mode, po); });
    } else {
      r.image = gl.render(cam, rel, mode, po);
    }
    if (o.firstStage) {  // no numbers: they would be against the stage's coarse reference
      t.rows.push_back(std::move(r));
      continue;
    }
    r.psnrAll = psnr(r.image, ref, nullptr);
    r.ssimAll = ssim(r.image, ref, nullptr);
    r.psnrAniso = psnr(r.image, ref, &t.anisoMask);
    r.ssimAniso = ssim(r.image, ref, &t.anisoMask);
    r.psnrBand = psnr(r.image, ref, &t.bandMask);
    r.ssimBand = ssim(r.image, ref, &t.bandMask);
    po.count = true;
    ts::Image counts = gl.render(cam, rel, mode, po);
    double f = 0, e = 0;
    for (size_t p = 0; p < size_t(cam.width) * size_t(cam.height); ++p) {
      f += counts.pixels[p * 4] + 256.0 * counts.pixels[p * 4 + 1];
      e += counts.pixels[p * 4 + 2] + 256.0 * counts.pixels[p * 4 + 3];
    }
    r.lookupsPerPixel = f / (double(cam.width) * cam.height);
    r.excludedPerPixel = e / (double(cam.width) * cam.height);
    po.count = false;
    r.ms = o.timingRuns > 0 ? gl.timeMs(cam, rel, mode, o.timingRuns, po) : 0.0;
    t.rows.push_back(std::move(r));
  }
  progress(refShare + (1 - refShare) * 0.9);
  if (o.firstStage) return t;
  for (const Row& r : t.rows)
    if (r.mode == kTrilinear || (r.mode == kAniso16 && ts::gl::hasAnisotropicFiltering())) {
      PassOptions po;
      po.accel = o.accel;
      po.gradScale = o.gradScale * 4;
      long changed = ts::probe::countDiffering(r.image, gl.render(cam, rel, r.mode, po), 0);
      (r.mode == kTrilinear ? t.gradChangeM1 : t.gradChangeM2) = changed;
    }
  return t;
}

// printf of one number; a measure that does not exist (PSNR over an empty
// mask) is NaN and prints as nothing, an empty CSV cell.
inline std::string fmtNum(const char* f, double v) { return std::isnan(v) ? std::string() : ts::layout::fmt(f, v); }

inline std::string optCount(long n) { return n >= 0 ? std::to_string(n) : std::string(); }

inline std::string csv(const Table& t) {
  std::string s =
      "mode,label,psnr_all,ssim_all,psnr_aniso,ssim_aniso,psnr_band,ssim_band,ms_per_frame,lookups_per_pixel,"
      "excluded_per_pixel,width,height,map,elevation_deg,height_scale,reference_rays,seed,aniso_pixels,band_pixels,"
      "m1_m2_gradient_scale,m1_grad_x4_changed_px,m2_grad_x4_changed_px,renderer\n";
  for (const Row& r : t.rows) {
    s += std::string(kModeKeys[r.mode]) + "," + kModeLabels[r.mode] + "," + fmtNum("%.3f", r.psnrAll) + "," +
         fmtNum("%.4f", r.ssimAll) + "," + fmtNum("%.3f", r.psnrAniso) + "," + fmtNum("%.4f", r.ssimAniso) + "," +
         fmtNum("%.3f", r.psnrBand) + "," + fmtNum("%.4f", r.ssimBand) + "," +
         (r.ms > 0 ? fmtNum("%.2f", r.ms) : std::string()) + "," + fmtNum("%.1f", r.lookupsPerPixel) + "," +
         fmtNum("%.2f", r.excludedPerPixel) + "," + std::to_string(t.cam.width) + "," + std::to_string(t.cam.height) +
         "," + t.map + "," + fmtNum("%.1f", t.cam.elevationDeg) + "," + fmtNum("%.3f", t.cam.heightScale) + "," +
         std::to_string(t.refRays) + "x" + std::to_string(t.refRays) + "," + std::to_string(t.seed) + "," +
         std::to_string(t.anisoPixels) + "," + std::to_string(t.bandPixels) + "," + fmtNum("%g", t.gradScale) + "," +
         optCount(t.gradChangeM1) + "," + optCount(t.gradChangeM2) + ",\"" + t.renderer + "\"\n";
  }
  return s;
}

// What the gradient test says (Table::gradChangeM1/M2).
inline std::string gradientFinding(const Table& t) {
  if (t.gradChangeM1 < 0 || t.gradChangeM2 < 0) return "gradients x4: not measured";
  std::string s = "gradients x4 change " + std::to_string(t.gradChangeM1) + " px of M1 and " +
                  std::to_string(t.gradChangeM2) + " px of M2";
  if (t.gradChangeM1 > 0 && t.gradChangeM2 == 0)
    s += " -- this driver's anisotropic filter ignores the gradients textureGrad gives it";
  return s;
}

inline std::string textTable(const Table& t) {
  std::string s = "parallax_aniso: " + t.map + " " + std::to_string(t.cam.width) + "x" + std::to_string(t.cam.height) +
                  ", elevation " + fmtNum("%.1f", t.cam.elevationDeg) + " deg, height scale " +
                  fmtNum("%.3f", t.cam.heightScale) + ", reference " + std::to_string(t.refRays) + "x" +
                  std::to_string(t.refRays) + " rays (" + fmtNum("%.1f", t.refSeconds) + " s on the CPU), renderer " +
                  t.renderer + "\n";
  s += "aniso mask " + std::to_string(t.anisoPixels) + " px, occlusion band " + std::to_string(t.bandPixels) + " px" +
       (t.gradScale != 1 ? ", M1/M2 given their gradients x" + fmtNum("%g", t.gradScale) : std::string()) + "\n";
  s += "mode               PSNR all  SSIM all  PSNR aniso SSIM "
       "aniso PSNR band SSIM band   ms/frame  lookups/px excl/px\n";
  for (const Row& r : t.rows) {
    char line[256];
    std::snprintf(line, sizeof line, "%-18s %8.2f  %8.4f  %9.2f  %9.4f  %9.2f  %8.4f  %9.1f  %10.1f  %6.2f\n",
                  kModeLabels[r.mode], r.psnrAll, r.ssimAll, r.psnrAniso, r.ssimAniso, r.psnrBand, r.ssimBand, r.ms,
                  r.lookupsPerPixel, r.excludedPerPixel);
    s += line;
  }
  s += gradientFinding(t) + "\n";
  return s;
}
}  // namespace pax
