// demos/sphere_projections/sphere_projections_measure.hpp — the measurement of
// demos/sphere_projections: texture area / surface area per 20° band of
// latitude, from a render whose pixels name their texels, and the pinch at
// the poles.  Kept out of sphere_projections.cpp so that file shows the
// figure first; the analytic values are in sphere_projections_math.hpp.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "common/gl/render.hpp"
#include "common/core/textures.hpp"
#include "sphere_projections_math.hpp"

namespace sphere {
using sphere::kBands;
using sphere::Mapping;

// The measurement pass: 9 panels (one per band) of kPanel pixels, whatever
// the window's size, each showing one band's region (sphere_projections_math.hpp's
// regionBox).  2048 texels around the sphere: a texel is smaller than the
// region's pixels except right at the poles, so a texel index pins every
// pixel's (s, t) — and so its band, column and mesh cell — to < 1 pixel.
constexpr int kPanel = 384, kTexels = 2048;
constexpr double kPinchRadiusPx = 3.0;

// One mapping's numbers at one mesh resolution.
struct Result {
  std::array<double, kBands> analytic{}, mesh{}, render{};
  double spread = 0, pinchLost = 0, poleSpan = 0, frontSpan = 0;
};

// The measurement.  For each band, a panel looks at the band's centre
// face-on (ortho, the sphere turned by rotateX(band centre)); the sphere is
// drawn with a texture whose texels hold their own indices (GL_NEAREST), so
// every pixel says which texel it took.  A region of the texture — the
// band's rows, and the columns with |θ| <= sphere::thetaHalfWidth — has a
// known area; the surface it landed on is the sum, over the pixels that took
// one of its texels, of the pixel's area / |n·v| (n the normal of the mesh
// cell the texel belongs to).  No derivatives: a pixel right at a pole, where
// every s meets, counts like any other.
inline Result measureMapping(ts::Renderer& r, Mapping m, int resolution) {
  Result res;
  const ts::Mesh mesh = sphere::sphereMesh(m, resolution);
  const sphere::MeshRatios mr = sphere::meshRatios(mesh);
  const int stacks = mesh.nv, slices = mesh.nu;

  ts::Frame f;
  f.width = 3 * kPanel;
  f.height = 3 * kPanel;
  f.clearColor = {1.0f, 1.0f, 1.0f, 0.0f};  // alpha 0: no texel
  ts::TextureDesc index = ts::texelIndexTexture(kTexels);
  index.wrapT = GL_CLAMP_TO_EDGE;  // t = 1 at the pole vertex is the last row, not the first
  int tex = f.addTexture(index);
  ts::Batch surface = ts::meshBatch(mesh, tex);
  surface.texEnv = GL_REPLACE;
  for (int b = 0; b < kBands; ++b) {
    ts::Panel p;
    p.id = "band_" + std::to_string(b);
    p.viewport = {(b % 3) * kPanel, (b / 3) * kPanel, kPanel, kPanel};
    glm::vec4 box(sphere::regionBox(b));
    p.projection = glm::ortho(box.x, box.y, box.z, box.w, -2.0f, 2.0f);
    p.modelview = glm::rotate(glm::mat4(1.0f), float(sphere::rad(sphere::bandMid(b))), {1, 0, 0});
    p.depthTest = true;
    p.batches.push_back(surface);
    f.panels.push_back(p);
  }
  ts::Image img = r.renderOffscreen(f);

  // Which texel rows and columns make up each band's region, and its area.
  std::vector<int> rowBand(kTexels);
  for (int j = 0; j < kTexels; ++j)
    rowBand[size_t(j)] = std::clamp(int((sphere::phiFromT(m, (j + 0.5) / kTexels) + 90.0) / sphere::kBandDeg), 0,
                                    kBands - 1);
  auto thetaOf = [](int i) {  // texel column centre, degrees in (-180, 180]
    double th = 360.0 * (i + 0.5) / kTexels;
    return th > 180.0 ? th - 360.0 : th;
  };
  // Mesh cell normals (the cells are planar trapezoids): cross of the diagonals.
  std::vector<glm::dvec3> normal(size_t(slices) * size_t(stacks));
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const auto& P = mesh.points;
      glm::dvec3 d1 = P[size_t(mesh.at(i + 1, j + 1))].pos - P[size_t(mesh.at(i, j))].pos;
      glm::dvec3 d2 = P[size_t(mesh.at(i, j + 1))].pos - P[size_t(mesh.at(i + 1, j))].pos;
      normal[size_t(j) * size_t(slices) + size_t(i)] = glm::normalize(glm::cross(d1, d2));
    }
  const double norm = mr.totalArea / mr.totalTexArea;  // the mesh's whole-sphere mean -> 1
  double lo = 1e300, hi = 0;
  for (int b = 0; b < kBands; ++b) {
    const double halfWidth = sphere::thetaHalfWidth(b), e = sphere::rad(sphere::bandMid(b));
    const glm::dvec3 view(0.0, std::sin(e), std::cos(e));  // toward the camera, model coordinates
    long rows = 0, cols = 0;
    for (int j = 0; j < kTexels; ++j) rows += rowBand[size_t(j)] == b;
    for (int i = 0; i < kTexels; ++i) cols += std::abs(thetaOf(i)) <= halfWidth;
    const double texArea = double(rows) * double(cols) / (double(kTexels) * kTexels);
    const glm::dvec4 box = sphere::regionBox(b);
    const double pixelArea = (box.y - box.x) / kPanel * (box.w - box.z) / kPanel;  // model units
    double surfArea = 0;
    const ts::Rect& vp = f.panels[size_t(b)].viewport;
    for (int y = vp.y; y < vp.y + vp.h; ++y)
      for (int x = vp.x; x < vp.x + vp.w; ++x) {
        ts::Rgba c = img.at(x, y);
        int i = 0, j = 0;
        ts::decodeTexelIndex(c, &i, &j);
        if (c.a != 255 || i >= kTexels || j >= kTexels) continue;
        if (rowBand[size_t(j)] != b || std::abs(thetaOf(i)) > halfWidth) continue;
        double phi = sphere::phiFromT(m, (j + 0.5) / kTexels);
        int ci = std::min(slices - 1, i * slices / kTexels);
        int cj = std::clamp(int((phi + 90.0) / 180.0 * stacks), 0, stacks - 1);
        surfArea += pixelArea / std::abs(glm::dot(normal[size_t(cj) * size_t(slices) + size_t(ci)], view));
      }
    res.analytic[size_t(b)] = sphere::bandRatio(m, sphere::bandLo(b), sphere::bandHi(b));
    res.mesh[size_t(b)] = mr.ratio[size_t(b)];
    res.render[size_t(b)] = surfArea > 0 ? texArea / surfArea * norm : 0.0;
    lo = std::min(lo, res.render[size_t(b)]);
    hi = std::max(hi, res.render[size_t(b)]);
  }
  res.spread = lo > 0 ? hi / lo : 0.0;
  res.pinchLost = mr.pinchLost / mr.totalTexArea;

  // The pinch: the s values of the pixels within 3 px of a point, as a
  // fraction of the circle — both poles (band panels 8 and 0) and the front
  // (θ = 0, φ = 0, the centre of the equator's panel).
  auto span = [&](int b, glm::vec3 point) {
    const ts::Panel& p = f.panels[size_t(b)];
    glm::vec2 c = ts::panelToPixels(p, p.projection * p.modelview * glm::vec4(point, 1.0f));
    std::vector<double> s;
    for (int y = int(c.y) - 4; y <= int(c.y) + 4; ++y)
      for (int x = int(c.x) - 4; x <= int(c.x) + 4; ++x) {
        if (std::hypot(x + 0.5 - c.x, y + 0.5 - c.y) > kPinchRadiusPx) continue;
        ts::Rgba px = img.at(x, y);
        int i = 0, j = 0;
        ts::decodeTexelIndex(px, &i, &j);
        if (px.a == 255 && i < kTexels) s.push_back((i + 0.5) / kTexels);
      }
    return sphere::circularSpan(s);
  };
  res.poleSpan = std::min(span(kBands - 1, {0, 1, 0}), span(0, {0, -1, 0}));
  res.frontSpan = span(kBands / 2, {0, 0, 1});
  return res;
}
}  // namespace sphere
