// demos/cylinder_seam/cylinder_seam_measure.hpp — the measurement of
// demos/cylinder_seam: each patch of the cylinder drawn head-on with a
// texture whose texels hold their own indices, and the s it shows read back
// from the pixels and fitted across the patch.  Kept out of
// cylinder_seam.cpp so that file shows the figure first.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/probe.hpp"
#include "common/gl/render.hpp"
#include "common/core/textures.hpp"
#include "cylinder_seam_math.hpp"

namespace cylinder {
struct PatchResult {
  double span = 0;      // signed Δs from left edge to right edge
  double texelErr = 0;  // largest distance (texels) from the assigned s
};

// Each patch is drawn head-on in its own W x H panel: turned by -θ_mid about
// y so it faces +z, and an orthographic projection that maps its chord onto
// exactly the panel's width (left edge = column k, right edge = column k+1).
// Then screen x is linear in s, every pixel centre lies inside the patch,
// and the s a pixel shows is (texel index + 1/2) / N.
inline std::vector<PatchResult> measurePatches(ts::Renderer& r, const cylinder::Params& cp) {
  // 2048 texels: s is read to 1/2048 per pixel; 256 px across a patch make
  // the fitted span good to far better than a texel; 32 rows are plenty (s
  // does not depend on y).  The frame's size depends only on the slices.
  const int N = 2048, W = 256, H = 32;
  const ts::Mesh mesh = cylinder::mesh(cp);
  ts::Frame mf;
  mf.width = W;
  mf.height = H * cp.slices;
  int tex = mf.addTexture(ts::texelIndexTexture(N));  // GL_NEAREST, GL_REPEAT
  ts::Batch all = ts::meshBatch(mesh, tex);
  all.texEnv = GL_REPLACE;
  const double half = 180.0 / cp.slices, chord = cp.r * std::sin(ts::degToRad(half));
  for (int k = 0; k < cp.slices; ++k) {
    ts::Panel p;
    p.id = "patch_" + std::to_string(k);
    p.viewport = {0, k * H, W, H};
    p.projection = glm::ortho(float(-chord), float(chord), float(-cp.h / 2), float(cp.h / 2), float(-2 * cp.r),
                              float(2 * cp.r));
    p.modelview = glm::rotate(glm::mat4(1.0f), float(-ts::degToRad(cylinder::thetaDeg(cp.slices, k) + half)),
                              glm::vec3(0, 1, 0));
    ts::Batch b = all;  // only column k's cells: 6 vertices per cell, row-major in j
    b.vertices.clear();
    for (int j = 0; j < cp.stacks; ++j)
      for (int v = 0; v < 6; ++v) b.vertices.push_back(all.vertices[size_t((j * cp.slices + k) * 6 + v)]);
    p.batches.push_back(b);
    mf.panels.push_back(p);
  }
  ts::Image img = r.renderOffscreen(mf);

  std::vector<PatchResult> out;
  for (int k = 0; k < cp.slices; ++k) {
    const double sa = cylinder::sOf(cp, k), sb = cylinder::sOf(cp, k + 1);
    std::vector<ts::probe::Sample> samples;
    PatchResult pr;
    for (int y = k * H; y < (k + 1) * H; ++y) {
      double prev = 0, unwrapped = 0;
      for (int x = 0; x < W; ++x) {
        int i = 0, j = 0;
        ts::decodeTexelIndex(img.at(x, y), &i, &j);
        double s = (i + 0.5) / N;
        // Unwrap along the row: neighbouring pixels differ by far less than
        // half the texture, so a jump of more than 1/2 is a wrap (GL_REPEAT).
        unwrapped = x == 0 ? s : unwrapped + (s - prev) - std::round(s - prev);
        prev = s;
        double u = (x + 0.5) / W;
        samples.push_back({u, (y - k * H + 0.5) / H, unwrapped});
        // Against the assignment, interpolated linearly across the patch.
        double want = sa + u * (sb - sa), d = (unwrapped - want) - std::round(unwrapped - want);
        pr.texelErr = std::max(pr.texelErr, std::abs(d) * N);
      }
    }
    ts::probe::Fit fit = ts::probe::fit(samples, false);  // s = c0 + c1 u + c2 v: c1 is the span
    pr.span = fit.c[1];
    out.push_back(pr);
  }
  return out;
}
}  // namespace cylinder
