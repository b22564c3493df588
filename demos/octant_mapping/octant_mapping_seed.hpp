// demos/octant_mapping/octant_mapping_seed.hpp — what seed 004 prints, as it prints
// it, and where it is wrong.  The seed is a machine transliteration of
// Rogers' chapter: p stands for π, q for θ, f for φ ("p/2" is π/2, "7/(16p)"
// was 7π/16).  Each misprint is checked against octant_mapping_math.hpp here, not
// taken on trust: misprints() recomputes the right value and keeps only
// entries that really differ.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "octant_mapping_math.hpp"

namespace octant::seed {
// The first example's table, u = 1/4, as printed: θ only in the first row,
// x, y, z to 2 decimals.
struct PrintedRow {
  const char* w;
  const char* theta;  // "" where the seed leaves it blank
  const char* phi;
  double x, y, z;
};
inline const std::array<PrintedRow, 5>& table() {
  static const std::array<PrintedRow, 5> t = {{{"0", "p/2", "p/2", 0.38, 0.00, 0.92},
                                               {"1/4", "", "7/(16p)", 0.38, 0.20, 0.91},
                                               {"1/2", "", "3/(8p)", 0.35, 0.38, 0.85},
                                               {"3/4", "", "5/(16p)", 0.32, 0.56, 0.77},
                                               {"1", "", "p/4", 0.27, 0.71, 0.65}}};
  return t;
}

// The inverse example's tables, pixel (21, 15)'s corners in the seed's order.
struct PrintedCorner {
  int Px, Py;
  double xv, yv, zv;        // x', y', z' (z' to 3 decimals)
  double x, y, z;           // after the inverse view, 3 decimals
  double phiDeg, thetaDeg;  // 2 decimals
  double u, w;              // 3 decimals
};
inline const std::array<PrintedCorner, 4>& corners() {
  static const std::array<PrintedCorner, 4> c = {{
      {21, 15, 0.3125, -0.0625, 0.948, 0.795, 0.493, 0.341, 60.50, 66.04, 0.734, 0.656},
      {22, 15, 0.3750, -0.0625, 0.925, 0.826, 0.479, 0.296, 61.34, 70.30, 0.781, 0.636},
      {22, 16, 0.3750, 0.0, 0.927, 0.802, 0.532, 0.272, 57.88, 71.28, 0.792, 0.714},
      {21, 16, 0.3125, 0.0, 0.950, 0.771, 0.545, 0.329, 56.99, 66.88, 0.743, 0.734},
  }};
  return c;
}
// The seed's worked answers.
constexpr int kCatmullLevels = 4;                     // subdivisions
constexpr int kCatmullLine = 7, kCatmullTexels = 16;  // 7/16
constexpr int kInverseLine = 5, kInverseTexels = 18;  // 5/18
constexpr int kCatmullPx = 5, kCatmullPy = 9;         // the pixel whose centre the seed's fragment covers
constexpr int kInversePx = 21, kInversePy = 15;
// Catmull's fragment's corners, as printed: phi = 59pi/64 for 31pi/64.
constexpr double kCatmullPhiPrinted = 59 * kPi / 64;

// A misprint the demo flags: what the seed prints, what it should be (both
// as text), and the right value as a number (the gallery's value column).
struct Misprint {
  std::string id;       // measurement name: misprint[<id>]
  std::string where;    // which example, which entry
  std::string printed;  // as printed (and what it would mean)
  std::string correct;  // the right entry
  double value = 0;     // the right value
  // The same in parts, for a figure to print its numbers with their
  // sources: the entry as printed ("\"p/2\" = pi/2") and the number it
  // reads as (NaN: none), and the right entry without its value ("pi/8"),
  // a note after it.
  std::string printedAs{};
  double printedValue = std::nan("");
  std::string correctAs{}, note{};
};

inline std::string f3(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", v);
  return b;
}
inline std::string f2(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

// Entries of the corner tables that differ from the computed value by more
// than one unit of their last printed digit (the seed carries rounded
// values on, e.g. z' = 0.948, which moves some entries by a unit: y at
// (21,15) is 0.4925, printed 0.493), over all 4 x 10 entries.
struct CornerCheck {
  int checked = 0, wrong = 0;
  std::vector<std::string> which;  // "z at (21,15): printed 0.341, computed 0.353"
};
inline CornerCheck checkCorners() {
  CornerCheck cc;
  for (const PrintedCorner& c : corners()) {
    auto b = backOfPixelPoint({double(c.Px), double(c.Py)});
    if (!b) continue;
    const glm::dvec2 uw = b->uw;
    struct E {
      const char* name;
      double printed, computed, unit;
    } es[] = {{"x'", c.xv, b->viewPoint.x, 1e-4},
              {"y'", c.yv, b->viewPoint.y, 1e-4},
              {"z'", c.zv, b->viewPoint.z, 1e-3},
              {"x", c.x, b->point.x, 1e-3},
              {"y", c.y, b->point.y, 1e-3},
              {"z", c.z, b->point.z, 1e-3},
              {"phi", c.phiDeg, b->phi * 180 / kPi, 1e-2},
              {"theta", c.thetaDeg, b->theta * 180 / kPi, 1e-2},
              {"u", c.u, uw.x, 1e-3},
              {"w", c.w, uw.y, 1e-3}};
    for (const E& e : es) {
      ++cc.checked;
      if (std::fabs(e.printed - e.computed) > e.unit + 1e-9) {
        ++cc.wrong;
        cc.which.push_back(std::string(e.name) + " at (" + std::to_string(c.Px) + "," + std::to_string(c.Py) +
                           "): printed " + (e.unit < 5e-3 ? f3(e.printed) : f2(e.printed)) + ", computed " +
                           (e.unit < 5e-3 ? f3(e.computed) : f2(e.computed)));
      }
    }
  }
  return cc;
}
// The table's x, y, z entries that differ from the computed ones by more
// than their 2-decimal rounding allows.
inline int tableXyzWrong() {
  int wrong = 0;
  const auto rows = forwardTable(0.25);
  for (size_t k = 0; k < rows.size(); ++k) {
    const PrintedRow& p = table()[k];
    const double pr[3] = {p.x, p.y, p.z};
    for (int a = 0; a < 3; ++a) wrong += std::fabs(pr[a] - rows[k].xyz[a]) > 5e-3 + 1e-9;
  }
  return wrong;
}

inline std::vector<Misprint> misprints() {
  std::vector<Misprint> out;
  const auto rows = forwardTable(0.25);
  // Example 1: the table.
  out.push_back({"table_theta_w0", "table u = 1/4, row w = 0: theta", "\"p/2\" = pi/2 = " + f3(kPi / 2),
                 "pi/8 = " + f3(rows[0].theta) + " (theta = (pi/2) u)", rows[0].theta, "\"p/2\" = pi/2", kPi / 2,
                 "pi/8", "(theta = (pi/2) u)"});
  const char* phiNames[] = {"", "7pi/16", "3pi/8", "5pi/16"};
  const double phiWrong[] = {0, 7 / (16 * kPi), 3 / (8 * kPi), 5 / (16 * kPi)};
  const char* rowNames[] = {"", "1/4", "1/2", "3/4"};
  for (int k = 1; k <= 3; ++k)
    out.push_back({std::string("table_phi_w") + (k == 1   ? "1/4"
                                                 : k == 2 ? "1/2"
                                                          : "3/4"),
                   std::string("table u = 1/4, row w = ") + rowNames[k] + ": phi",
                   std::string("\"") + table()[size_t(k)].phi + "\" = " + f3(phiWrong[k]),
                   std::string(phiNames[k]) + " = " + f3(rows[size_t(k)].phi), rows[size_t(k)].phi,
                   std::string("\"") + table()[size_t(k)].phi + "\"", phiWrong[k], phiNames[k], ""});
  // Example 2: the fragment's corners.
  const Fragment seedFragment = fragmentAt({0, 0}, 4);
  const double phiLow = seedFragment.phiRange().x;
  out.push_back(
      {"catmull_phi", "Catmull fragment corners (twice): phi",
       "59pi/64 = " + f3(kCatmullPhiPrinted) + " (w = " + f3(uwOf(0, kCatmullPhiPrinted).y) + ", off the patch)",
       "31pi/64 = " + f3(phiLow) + " (w = 1/16)", phiLow});
  // Example 3: the corners' tables.
  const auto first = backOfPixelPoint({21, 15});
  const glm::dvec3 p = first->point;
  const double printedZ = corners()[0].z;
  const double norm2Printed = corners()[0].x * corners()[0].x + corners()[0].y * corners()[0].y + printedZ * printedZ;
  const double norm2Right = corners()[0].x * corners()[0].x + corners()[0].y * corners()[0].y +
                            round3(p.z) * round3(p.z);
  out.push_back({"corner_z_21_15", "inverse example, pixel (21,15)'s first corner: z",
                 "0.341 (x^2 + y^2 + z^2 = " + f3(norm2Printed) + " with the printed x, y)",
                 f3(p.z) + " (x^2 + y^2 + z^2 = " + f3(norm2Right) + ")", p.z});
  const auto second = backOfPixelPoint({22, 15});
  const double phi2 = second->phi * 180 / kPi;
  out.push_back({"corner_phi_22_15", "inverse example, corner (22,15): phi in degrees",
                 "61.34 (w would be " + f3((90 - 61.34) / 45) + ")",
                 f2(phi2) + " (the printed w = 0.636 follows from it)", phi2});
  out.push_back({"sphere_formula", "inverse example: the sphere",
                 "y = cos theta, z = cos theta sin theta (y = " + f3(std::cos(first->theta)) + " at (21,15))",
                 "y = cos phi, z = cos theta sin phi (y = " + f3(p.y) + ")", p.y});
  const glm::dmat3 V = view();
  out.push_back({"view_matrix", "inverse example: the viewing transformation T and T^-1", "announced, not printed",
                 "(x,y,z) = V^T (x',y',z'), V = Rx(35) Ry(-45); V^T's first row: (" + f3(V[0][0]) + ", " + f3(V[0][1]) +
                     ", " + f3(V[0][2]) + ")",
                 glm::determinant(V)});
  return out;
}
}  // namespace octant::seed
