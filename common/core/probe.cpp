#include "common/core/probe.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace ts::probe {
int tolerance(int bits, double ulps) {
  // One step of an n-bit channel in 8-bit units, rounded up, at least 1.
  double step = 255.0 / double((1 << bits) - 1);
  return std::max(1, int(std::ceil(ulps * step)));
}

bool close(Rgba a, Rgba b, int tol) {
  return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol &&
         std::abs(a.a - b.a) <= tol;
}

static std::string rgba(Rgba c) {
  return "(" + std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b) + "," + std::to_string(c.a) +
         ")";
}

std::string Result::describe() const {
  if (checked == 0) return "no pixel was checked";
  if (failed == 0) return std::to_string(checked) + " pixels match";
  return std::to_string(failed) + " of " + std::to_string(checked) + " pixels differ; first at (" +
         std::to_string(firstX) + "," + std::to_string(firstY) + "): got " + rgba(firstGot) + ", want " +
         rgba(firstWant);
}

static void record(Result& r, int x, int y, Rgba got, Rgba want, int tol) {
  ++r.checked;
  if (close(got, want, tol)) return;
  if (r.failed++ == 0) r.firstX = x, r.firstY = y, r.firstGot = got, r.firstWant = want;
}

Result rect(const Image& img, Rect rc, Rgba want, int tol) {
  Result r;
  for (int y = std::max(0, rc.y); y < std::min(img.height, rc.y + rc.h); ++y)
    for (int x = std::max(0, rc.x); x < std::min(img.width, rc.x + rc.w); ++x) record(r, x, y, img.at(x, y), want, tol);
  return r;
}

Result images(const Image& got, const Image& want, int tol) {
  Result r;
  if (got.width != want.width || got.height != want.height) {
    r.checked = 1;
    r.failed = 1;
    return r;
  }
  for (int y = 0; y < got.height; ++y)
    for (int x = 0; x < got.width; ++x) record(r, x, y, got.at(x, y), want.at(x, y), tol);
  return r;
}

long countDiffering(const Image& a, const Image& b, int tol) {
  if (a.width != b.width || a.height != b.height) return long(std::max(a.pixels.size(), b.pixels.size()) / 4);
  long n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) n += !close(a.at(x, y), b.at(x, y), tol);
  return n;
}

Fit fit(const std::vector<Sample>& s, bool quadratic) {
  const int n = quadratic ? 6 : 3;
  double A[6][7] = {};
  for (const Sample& p : s) {
    double row[6] = {1, p.x, p.y, p.x * p.x, p.x * p.y, p.y * p.y};
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) A[i][j] += row[i] * row[j];
      A[i][n] += row[i] * p.z;
    }
  }
  // Gaussian elimination with partial pivoting on the normal equations.
  for (int c = 0; c < n; ++c) {
    int piv = c;
    for (int r = c + 1; r < n; ++r)
      if (std::abs(A[r][c]) > std::abs(A[piv][c])) piv = r;
    for (int k = 0; k <= n; ++k) std::swap(A[c][k], A[piv][k]);
    if (std::abs(A[c][c]) < 1e-300) continue;
    for (int r = 0; r < n; ++r) {
      if (r == c) continue;
      double f = A[r][c] / A[c][c];
      for (int k = c; k <= n; ++k) A[r][k] -= f * A[c][k];
    }
  }
  Fit out;
  for (int i = 0; i < n; ++i) out.c[size_t(i)] = std::abs(A[i][i]) < 1e-300 ? 0 : A[i][n] / A[i][i];
  double ss = 0;
  for (const Sample& p : s) ss += (out.at(p.x, p.y) - p.z) * (out.at(p.x, p.y) - p.z);
  out.samples = long(s.size());
  out.rms = s.empty() ? 0 : std::sqrt(ss / double(s.size()));
  return out;
}
}  // namespace ts::probe
