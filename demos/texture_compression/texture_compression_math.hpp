// demos/texture_compression/texture_compression_math.hpp — what the demo measures of a
// DXT1 texture: colours per block, differences, PSNR, normals' angles.  The
// codec itself, written out for reading, is common/core/dxt1.hpp (the
// bump-mapping demo compresses its normal map with it too).
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "common/core/dxt1.hpp"
#include "common/core/image.hpp"

namespace dxt {
using namespace ts::dxt1;

// ---- what the demo measures -------------------------------------------
// The most distinct colours any decoded 4x4 block holds (at most 4).
inline int maxColoursPerBlock(const ts::Image& img) {
  int most = 0;
  for (int by = 0; by < blocksAcross(img.height); ++by)
    for (int bx = 0; bx < blocksAcross(img.width); ++bx) {
      std::set<uint32_t> seen;
      for (int k = 0; k < 16; ++k) {
        if (bx * 4 + k % 4 >= img.width || by * 4 + k / 4 >= img.height) continue;  // padding: not decoded
        const ts::Rgba c = img.at(bx * 4 + k % 4, by * 4 + k / 4);
        seen.insert(uint32_t(c.r) << 16 | uint32_t(c.g) << 8 | c.b);
      }
      most = std::max(most, int(seen.size()));
    }
  return most;
}
// The largest channel difference and the RMS over RGB: common/core/image.hpp.
inline int maxDiff(const ts::Image& a, const ts::Image& b) { return ts::maxChannelDiff(a, b); }
inline double rms(const ts::Image& a, const ts::Image& b) { return ts::rmsRgb(a, b); }
// PSNR = 20 log10(255 / RMS).
inline double psnr(const ts::Image& a, const ts::Image& b) {
  return 20.0 * std::log10(255.0 / std::max(rms(a, b), 1e-9));
}
// A normal map's texel as the unit vector it encodes (n = 2 c / 255 - 1).
inline glm::dvec3 normalOf(ts::Rgba c) { return glm::normalize(glm::dvec3(c.r, c.g, c.b) / 127.5 - 1.0); }
// The mean and largest angle (degrees) between two normal maps' normals.
inline glm::dvec2 normalAngles(const ts::Image& a, const ts::Image& b) {
  double sum = 0, most = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const double d = glm::degrees(
          std::acos(std::clamp(glm::dot(normalOf(a.at(x, y)), normalOf(b.at(x, y))), -1.0, 1.0)));
      sum += d, most = std::max(most, d);
    }
  return {sum / (double(a.width) * a.height), most};
}
// Where the error is: the mean angle over blocks whose own normals all lie
// within 15 degrees of each other (flat but for the bricks' grain: one colour
// line serves them), and over
// the rest (a brick's edge turns the normal inside the block).
struct AnglesByBlock {
  double flat = 0, edge = 0;
  int flatBlocks = 0, edgeBlocks = 0;
};
inline double blockMaxAngle(const ts::Image& a, const ts::Image& b, int bx, int by) {
  double most = 0;
  for (int y = by * 4; y < std::min(by * 4 + 4, a.height); ++y)
    for (int x = bx * 4; x < std::min(bx * 4 + 4, a.width); ++x)
      most = std::max(most, glm::degrees(std::acos(
                                std::clamp(glm::dot(normalOf(a.at(x, y)), normalOf(b.at(x, y))), -1.0, 1.0))));
  return most;
}
inline AnglesByBlock normalAnglesByBlock(const ts::Image& a, const ts::Image& b) {
  AnglesByBlock r;
  double flatSum = 0, edgeSum = 0;
  for (int by = 0; by * 4 < a.height; ++by)
    for (int bx = 0; bx * 4 < a.width; ++bx) {
      const glm::dvec3 first = normalOf(a.at(bx * 4, by * 4));
      double spread = 0, sum = 0;
      int n = 0;
      for (int y = by * 4; y < std::min(by * 4 + 4, a.height); ++y)
        for (int x = bx * 4; x < std::min(bx * 4 + 4, a.width); ++x, ++n) {
          spread = std::max(spread,
                            glm::degrees(std::acos(std::clamp(glm::dot(first, normalOf(a.at(x, y))), -1.0, 1.0))));
          sum += glm::degrees(std::acos(std::clamp(glm::dot(normalOf(a.at(x, y)), normalOf(b.at(x, y))), -1.0, 1.0)));
        }
      if (spread <= 15.0) flatSum += sum / n, ++r.flatBlocks;
      else edgeSum += sum / n, ++r.edgeBlocks;
    }
  r.flat = r.flatBlocks ? flatSum / r.flatBlocks : 0;
  r.edge = r.edgeBlocks ? edgeSum / r.edgeBlocks : 0;
  return r;
}
}  // namespace dxt
