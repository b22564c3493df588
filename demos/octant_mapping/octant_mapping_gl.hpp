// demos/octant_mapping/octant_mapping_gl.hpp — the octant as a mesh, and the 32 x 32
// raster rendered by OpenGL with each texture filter: what GL_NEAREST (one
// sample per pixel centre), trilinear and anisotropic filtering make of
// Rogers' grid, read back as intensities for the comparison with the exact
// area integral (octant_mapping_math.hpp).
//
// What the GL does: common/gl/render.cpp draws the mesh as one
// glBegin(GL_TRIANGLES), glTexCoord4f(u, w, 0, 1) + glVertex3f(x, y, z) per
// vertex, under glOrtho(-1, 1, -1, 1, -3, 3) and the view Rx(35°) Ry(-45°) as
// the modelview, into a 32 x 32 framebuffer object: x' = Px/16 - 1 exactly.
// The texture is ts::lineGrid(64, 4) (black lines on white, GL_CLAMP_TO_EDGE),
// with GL_NEAREST, or GL_LINEAR_MIPMAP_LINEAR over the book's 2 x 2 mip chain,
// without and with GL_TEXTURE_MAX_ANISOTROPY 16.
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "common/core/mesh.hpp"
#include "common/core/textures.hpp"
#include "common/gl/render.hpp"
#include "octant_mapping_math.hpp"

namespace octant {
// The octant as an n x n grid in (u, w): (s, t) = (u, w), the normal = the point.
inline ts::Mesh mesh(int n) {
  return ts::parametricGrid(
      n, n, false, false,
      [n](int i, int j) {
        const glm::dvec3 p = surfaceUW({double(i) / n, double(j) / n});
        return ts::SurfacePoint{p, p};
      },
      [n](int i, int j) { return glm::dvec2(double(i) / n, double(j) / n); });
}
constexpr int kMeasureMesh = 64;  // a vertex at every texel corner of the pattern
constexpr int kPictureMesh = 24;  // the 3D view's (its sidecar stays small)

// The pattern as a texture: black (0) on the lines, white (255) elsewhere,
// so a read-back channel c is the intensity 1 - c/255.
inline ts::TextureDesc patternTexture() {
  ts::TextureDesc t = ts::lineGrid(kTexels, kCells);
  t.wrapS = t.wrapT = GL_CLAMP_TO_EDGE;
  t.minFilter = t.magFilter = GL_NEAREST;
  return t;
}

inline glm::mat4 viewMatrix() { return glm::mat4(glm::mat3(view())); }

enum class GlFilter { Nearest, Trilinear, Anisotropic };
inline const char* glFilterName(GlFilter f) {
  return f == GlFilter::Nearest     ? "GL_NEAREST"
         : f == GlFilter::Trilinear ? "GL_LINEAR_MIPMAP_LINEAR"
                                    : "GL_LINEAR_MIPMAP_LINEAR, anisotropy 16";
}

// The raster drawn by GL with one filter: intensity per pixel (pixelIndex),
// NaN where no triangle covers the pixel's centre.
inline std::vector<double> renderRaster(ts::Renderer& r, GlFilter filter) {
  ts::Frame f;
  f.width = f.height = kRaster;
  f.clearColor = glm::vec4(0.0f);  // alpha 0: no surface there (the texture is opaque)
  ts::TextureDesc t = patternTexture();
  if (filter != GlFilter::Nearest) {
    t.mipmaps = true;
    t.minFilter = GL_LINEAR_MIPMAP_LINEAR;
    t.magFilter = GL_LINEAR;
    if (filter == GlFilter::Anisotropic) t.maxAnisotropy = 16.0f;
  }
  const int tex = f.addTexture(t);
  ts::Panel p;
  p.id = "raster_gl";
  p.viewport = {0, 0, kRaster, kRaster};
  p.projection = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -3.0f, 3.0f);
  p.modelview = viewMatrix();
  p.depthTest = true;
  ts::Batch b = ts::meshBatch(mesh(kMeasureMesh), tex);
  b.texEnv = GL_REPLACE;
  p.batches.push_back(b);
  f.panels.push_back(p);
  const ts::Image img = r.renderOffscreen(f);
  std::vector<double> out(size_t(kRaster * kRaster), std::nan(""));
  for (int Py = 0; Py < kRaster; ++Py)
    for (int Px = 0; Px < kRaster; ++Px) {
      const ts::Rgba c = img.at(Px, kRaster - 1 - Py);  // image row 0 is the top, Py = 31
      if (c.a == 255) out[size_t(pixelIndex(Px, Py))] = 1.0 - c.r / 255.0;
    }
  return out;
}
}  // namespace octant
