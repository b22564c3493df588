// demos/jitter/jitter_zone.hpp — where aliasing sets in on a zone plate
// (the expected onsets: "about 0.5 cycles/pixel with 1 sample and about 1.5
// with 3 x 3 regular samples" (Buss: supersampling "delays aliasing until the
// texture resolution is about 3x the screen's").  No OpenGL here: the CPU
// model of the demo's sample patterns (jitter::samplePos), read sample by
// sample; jitter_gl.hpp (zonePass, zoneSweepGl) renders the same plate with GL
// and reads the same measure off its 8-bit pixels (the figure
// jitter_zone_plate shows those renders).
//
// The zone plate, band by band: a sinusoid across the pixel columns,
//     s(x) = cos(2 pi f x + phi),   f in cycles per pixel,
// sampled by a pattern's n x n points in each pixel (i, j) and averaged.  Its
// truth is the exact box filter over the pixel (analytic):
//     t_i = (sin(2 pi f (i+1) + phi) - sin(2 pi f i + phi)) / (2 pi f).
// The alias at f is the render's error against that truth, as a fraction of
// the truth:  rho(f) = RMS(render - truth) / RMS(truth), over the pixels and
// the phases 0 and pi/2 (so it does not depend on where the pattern starts).
// The error is what the sample grid adds to the box filter: the samples of
// f and of its alias n*k -/+ f (k = the nearest multiple of the grid's rate n)
// are the same numbers, so the render box-filters the wrong frequency.
//
// For regular n x n samples the ratio is a closed form of f/n alone: the
// render is D_n(f) = sin(pi f) / (n sin(pi f / n)) times the signal, the
// truth sinc(f) = sin(pi f) / (pi f) times it, so rho = x / sin(x) - 1 with
// x = pi f / n: 0 at f = 0, pi/2 - 1 = 0.57 at the grid's Nyquist f = n/2,
// infinite at f = n.  The onset — the lowest f where the alias reaches half
// the signal (rho >= 0.5) — is therefore at f = n x*/pi with x*/sin x* = 1.5:
// 0.477 n cycles/pixel, i.e. just under the grid's Nyquist n/2 — 0.48 for
// 1 sample, 1.43 for 3 x 3.  The measure reads rho from the samples; the
// test compares it with that closed form.
// Jittered samples turn the alias into noise: rho is noise there, its onset is
// reported, and at f = 2.5 (above the 3 x 3 grid's Nyquist) the share of the
// error that neighbouring errors predict (jitter::analyse) says which it is.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "common/core/image.hpp"
#include "common/core/scene.hpp"
#include "jitter_math.hpp"

namespace jitter::zone {
constexpr double kPi = 3.14159265358979323846;
constexpr double kThreshold = 0.5;  // the onset: alias RMS >= half the true signal's RMS
constexpr double kStep = 0.02;      // the sweep's step, cycles per pixel
constexpr double kMaxF = 3.0;       // the sweep's end (the 3 x 3 grid's sampling rate)
// A band of the plate: so many pixel columns and rows.
constexpr int kBandW = 64, kBandH = 16;
// Frequencies where the box-filtered truth is under this (RMS, the signal's
// amplitude = 1) are skipped: near whole cycles per pixel the box filter
// cancels the signal and both render and truth vanish (0 / 0).
constexpr double kTruthFloor = 0.03;
// The GL render of the plate (jitter_gl.hpp, zonePass): kGlBands bands of
// kGlBandRows rows, kGlWidth columns; band b at (b + 1) kStep cycles/pixel.
constexpr int kGlWidth = 64, kGlBandRows = 2, kGlBands = 150;

// The exact box filter of cos(2 pi f x + phi) over [i, i + 1).
inline double truth(double f, double phi, int i) {
  const double w = 2 * kPi * f;
  return (std::sin(w * (i + 1) + phi) - std::sin(w * i + phi)) / w;
}
// The pattern's n x n samples of pixel (i, j), averaged.
inline double render(Pattern p, int n, uint32_t seed, double f, double phi, int i, int j) {
  double sum = 0;
  for (int k = 0; k < n * n; ++k) sum += std::cos(2 * kPi * f * (i + samplePos(p, n, seed, i, j, k).x) + phi);
  return sum / (n * n);
}
// Error images of the band at f (pixel columns i0 .. i0 + w - 1, rows 0 .. h - 1).
inline std::vector<double> errorBand(Pattern p, int n, uint32_t seed, double f, double phi, int w, int h, int i0 = 0) {
  std::vector<double> e(size_t(w) * size_t(h));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      e[size_t(j) * size_t(w) + size_t(i)] = render(p, n, seed, f, phi, i0 + i, j) - truth(f, phi, i0 + i);
  return e;
}

struct Ratio {
  double rho = 0;    // RMS(render - truth) / RMS(truth)
  double truth = 0;  // RMS(truth)
};
// rho at f, over a band at column offset i0 (bands of the plate at other f
// sit elsewhere: their jitter is the pixels' own), phases 0 and pi/2.
inline Ratio ratio(Pattern p, int n, uint32_t seed, double f, int i0 = 0) {
  double ee = 0, tt = 0;
  for (double phi : {0.0, kPi / 2})
    for (int j = 0; j < kBandH; ++j)
      for (int i = i0; i < i0 + kBandW; ++i) {
        const double t = truth(f, phi, i), d = render(p, n, seed, f, phi, i, j) - t;
        ee += d * d, tt += t * t;
      }
  return {std::sqrt(ee / std::max(tt, 1e-300)), std::sqrt(tt / (2.0 * kBandH * kBandW))};
}

// The sweep f = kStep, 2 kStep, ... kMaxF.
struct Sweep {
  std::vector<double> f, rho;  // skipped frequencies (truth under the floor) are left out
  double onset = -1;           // the lowest f with rho >= kThreshold (-1: none)
};
inline Sweep sweep(Pattern p, int n, uint32_t seed) {
  Sweep s;
  const int steps = int(std::lround(kMaxF / kStep));
  for (int q = 1; q <= steps; ++q) {
    const double f = q * kStep;
    const Ratio r = ratio(p, n, seed, f, q * kBandW);
    if (r.truth < kTruthFloor) continue;
    s.f.push_back(f), s.rho.push_back(r.rho);
    if (s.onset < 0 && r.rho >= kThreshold) s.onset = f;
  }
  return s;
}

// What the zone view draws (measure() keeps it): the GL renders at phase 0
// and their sweeps, for 1 sample, n x n regular and n x n jittered per pixel.
struct Plate {
  std::array<ts::Image, 3> images;
  std::array<Sweep, 3> sweeps;
  int n = 0;
  bool valid = false;
};

// The closed form for regular n x n samples: f with x / sin x = 1 + kThreshold, x = pi f / n.
inline double expectedOnset(int n) {
  double lo = 1e-6, hi = kPi - 1e-6;
  for (int it = 0; it < 100; ++it) {
    const double mid = (lo + hi) / 2;
    (mid / std::sin(mid) - 1 < kThreshold ? lo : hi) = mid;
  }
  return n * lo / kPi;
}

// The share of the error at f that its neighbours' errors predict
// (jitter::analyse: aliasing / rms): ~1 for a coherent alias, small for noise.
inline double predictableShare(Pattern p, int n, uint32_t seed, double f) {
  const int w = 96, h = 64;
  const ErrorStats s = analyse(errorBand(p, n, seed, f, 0.3, w, h), w, h);
  return s.rms > 0 ? s.aliasing / s.rms : 0;
}

// The demo's numbers (jitter.cpp's measure()): the onsets for 1 sample, n x n
// regular and n x n jittered per pixel, and the predictable share at 2.5.
constexpr double kAboveNyquist = 2.5;  // cycles per pixel: above the grid's Nyquist for n <= 4
inline void measure(ts::Measurements& out, int n, uint32_t seed) {
  const std::string nn = std::to_string(n) + "x" + std::to_string(n);
  for (int side : n == 1 ? std::vector<int>{1} : std::vector<int>{1, n})
    out.push_back({"alias_onset_cpp[" + std::to_string(side) + "x" + std::to_string(side) + "]",
                   sweep(Pattern::Regular, side, seed).onset,
                   "zone plate: lowest cycles/pixel where the alias (render - box-filtered truth) reaches half the "
                   "signal, regular samples (CPU model)"});
  out.push_back({"alias_onset_cpp[jitter_pixel_" + nn + "]", sweep(Pattern::JitterPixel, n, seed).onset,
                 "the same, jittered per pixel: its error is noise, not an alias"});
  for (Pattern p : {Pattern::Regular, Pattern::JitterPixel})
    out.push_back({std::string("zone_predictable[") + (p == Pattern::Regular ? "regular_" : "jitter_pixel_") + nn + "]",
                   predictableShare(p, n, seed, kAboveNyquist),
                   "share of the zone plate's error at 2.5 cycles/pixel its neighbours predict (1: a coherent alias)"});
}
}  // namespace jitter::zone
