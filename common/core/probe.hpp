// common/core/probe.hpp — checking pictures the way conformance suites do:
// probe the interiors of regions whose correct colour is known, with a
// tolerance derived from the channel's bits, and fit the measured data to
// the model a figure claims.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"

namespace ts::probe {
// Tolerance for a colour compared after an n-bit framebuffer: `ulps` steps of
// 1/(2^bits - 1) expressed in 8-bit units (piglit's convention: one step of
// the channel's precision, plus rounding).
int tolerance(int bits = 8, double ulps = 1.0);

struct Result {
  long checked = 0, failed = 0;
  int firstX = -1, firstY = -1;
  Rgba firstGot, firstWant;
  bool ok() const { return failed == 0 && checked > 0; }
  std::string describe() const;  // "3 of 400 pixels differ; first at (12,5): got ..., want ..."
};
bool close(Rgba a, Rgba b, int tol);
// Every pixel of r (clipped to the image) against one colour.
Result rect(const Image& img, Rect r, Rgba want, int tol);
// Pixel-by-pixel comparison of two images of the same size.
Result images(const Image& got, const Image& want, int tol);
// Number of pixels whose largest channel difference exceeds tol.
long countDiffering(const Image& a, const Image& b, int tol);

// Least squares fit of z = c0 + c1 x + c2 y + c3 x^2 + c4 x y + c5 y^2
// (quadratic = false: only the first three terms).  Returns the coefficients
// and the RMS residual.
struct Fit {
  std::array<double, 6> c{};
  double rms = 0;
  long samples = 0;
  double at(double x, double y) const {
    return c[0] + c[1] * x + c[2] * y + c[3] * x * x + c[4] * x * y + c[5] * y * y;
  }
  double dx(double x, double y) const { return c[1] + 2 * c[3] * x + c[4] * y; }
  double dy(double x, double y) const { return c[2] + c[4] * x + 2 * c[5] * y; }
};
struct Sample {
  double x, y, z;
};
Fit fit(const std::vector<Sample>& s, bool quadratic);
}  // namespace ts::probe
