// demos/torus/torus_measure.hpp — the measurement of demos/torus: where the
// texture's centre (1/2, 1/2) is found in a render whose pixels name their
// texels, and the point of the torus mesh a ray through it hits.  Kept out
// of torus.cpp so that file shows the figure first; torus_math.hpp holds
// the answer it is compared with.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "common/core/probe.hpp"
#include "common/gl/render.hpp"
#include "common/core/textures.hpp"
#include "torus_math.hpp"

namespace torus {
// Where the centre was found in one mapping.
struct Found {
  bool visible = false;
  glm::dvec2 screen{-1.0};  // pixels of the kMeasureSize render, top-left origin
  glm::dvec2 nearestPixel{-1.0};
  glm::dvec3 point{0.0};  // the mesh point a ray through `screen` hits
};
constexpr int kMeasureSize = 512;

// Möller–Trumbore: distance along the ray to the triangle, or +inf.
inline double hit(glm::dvec3 o, glm::dvec3 d, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  glm::dvec3 e1 = b - a, e2 = c - a, pv = glm::cross(d, e2);
  double det = glm::dot(e1, pv);
  if (std::abs(det) < 1e-14) return std::numeric_limits<double>::infinity();
  glm::dvec3 tv = o - a;
  double u = glm::dot(tv, pv) / det;
  glm::dvec3 qv = glm::cross(tv, e1);
  double v = glm::dot(d, qv) / det, t = glm::dot(e2, qv) / det;
  if (u < -1e-9 || v < -1e-9 || u + v > 1 + 1e-9 || t <= 0) return std::numeric_limits<double>::infinity();
  return t;
}

// Where (1/2, 1/2) is on the screen and on the torus, from a render with the
// texel-index texture (N = 2048, GL_NEAREST, GL_REPEAT) at a fixed size,
// seen through `projection` and `modelview` (the picture's camera).
inline Found find(ts::Renderer& r, const Params& tp, const glm::mat4& projection, const glm::mat4& modelview) {
  const int N = 2048, S = kMeasureSize;
  const ts::Mesh mesh = torus::mesh(tp);
  ts::Frame mf;
  mf.width = mf.height = S;
  mf.clearColor = glm::vec4(0.0f);  // alpha 0: not the torus (every texel has alpha 255)
  int tex = mf.addTexture(ts::texelIndexTexture(N));
  ts::Panel p;
  p.id = "texel_index";
  p.viewport = {0, 0, S, S};
  p.projection = projection;
  p.modelview = modelview;
  p.depthTest = true;
  ts::Batch b = ts::meshBatch(mesh, tex);
  b.texEnv = GL_REPLACE;
  p.batches.push_back(b);
  mf.panels.push_back(p);
  ts::Image img = r.renderOffscreen(mf);

  // Pixels within 0.02 of the centre in s and t (7.2° of θ and of φ): a
  // neighbourhood of some hundred pixels where s and t are nearly linear in
  // the pixel position.  Fit them and solve s = t = 1/2.
  const double near = 0.02;
  std::vector<ts::probe::Sample> ss, st;
  double best = 1e9;
  Found out;
  glm::dvec2 mean(0.0);
  std::vector<glm::dvec4> px;  // x, y, ds, dt
  for (int y = 0; y < S; ++y)
    for (int x = 0; x < S; ++x) {
      ts::Rgba c = img.at(x, y);
      if (c.a == 0) continue;
      int i = 0, j = 0;
      ts::decodeTexelIndex(c, &i, &j);
      double ds = (i + 0.5) / N - 0.5, dt = (j + 0.5) / N - 0.5;
      ds -= std::round(ds), dt -= std::round(dt);  // GL_REPEAT: 1.5 is 0.5
      double d = std::hypot(ds, dt);
      if (d < best) best = d, out.nearestPixel = {x + 0.5, y + 0.5};
      if (std::abs(ds) < near && std::abs(dt) < near)
        px.push_back({x + 0.5, y + 0.5, ds, dt}), mean += glm::dvec2(x + 0.5, y + 0.5);
    }
  if (px.size() < 12) return out;  // too few pixels show it: hidden (or off screen)
  mean /= double(px.size());
  for (const auto& q : px) {
    ss.push_back({q.x - mean.x, q.y - mean.y, q.z});
    st.push_back({q.x - mean.x, q.y - mean.y, q.w});
  }
  // Quadratics absorb the perspective and the curvature over the
  // neighbourhood; Newton's method from its middle finds s = t = 1/2.
  ts::probe::Fit fs = ts::probe::fit(ss, true), ft = ts::probe::fit(st, true);
  glm::dvec2 d(0.0);
  for (int it = 0; it < 8; ++it) {
    double a = fs.dx(d.x, d.y), b = fs.dy(d.x, d.y), c = ft.dx(d.x, d.y), e = ft.dy(d.x, d.y), det = a * e - b * c;
    if (std::abs(det) < 1e-12) return out;
    double fsv = fs.at(d.x, d.y), ftv = ft.at(d.x, d.y);
    d -= glm::dvec2((e * fsv - b * ftv) / det, (a * ftv - c * fsv) / det);
  }
  out.screen = mean + d;
  // Half hidden (the near rim covers the solution, e.g. at a low tilt): the
  // pixel there shows some other texel, and the point is not what is seen.
  {
    int x = int(std::floor(out.screen.x)), y = int(std::floor(out.screen.y)), i = 0, j = 0;
    if (x < 0 || y < 0 || x >= S || y >= S || img.at(x, y).a == 0) return out;
    ts::decodeTexelIndex(img.at(x, y), &i, &j);
    double ds = (i + 0.5) / N - 0.5, dt = (j + 0.5) / N - 0.5;
    if (std::abs(ds - std::round(ds)) >= near || std::abs(dt - std::round(dt)) >= near) return out;
  }
  // Unproject: the pixel position to normalised device coordinates, the
  // near and far points back to the torus's coordinates; nearest hit.
  glm::dmat4 inv = glm::inverse(glm::dmat4(p.projection) * glm::dmat4(p.modelview));
  glm::dvec2 ndc(2.0 * out.screen.x / S - 1.0, 1.0 - 2.0 * out.screen.y / S);
  glm::dvec4 a = inv * glm::dvec4(ndc, -1.0, 1.0), z = inv * glm::dvec4(ndc, 1.0, 1.0);
  glm::dvec3 o = glm::dvec3(a) / a.w, dir = glm::normalize(glm::dvec3(z) / z.w - o);
  double tBest = std::numeric_limits<double>::infinity();
  std::vector<unsigned> tri = mesh.triangles();
  for (size_t k = 0; k + 2 < tri.size(); k += 3)
    tBest = std::min(tBest,
                     hit(o, dir, mesh.points[tri[k]].pos, mesh.points[tri[k + 1]].pos, mesh.points[tri[k + 2]].pos));
  if (!std::isfinite(tBest)) return out;
  out.point = o + tBest * dir;
  out.visible = true;
  return out;
}
}  // namespace torus
