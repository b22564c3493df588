// common/core/mesh.hpp — the parametric surfaces of Buss VI.1.2 (cylinder, sphere,
// torus) as triangle meshes with normals and texture coordinates.
//
// Two lessons are built in:
//  * Positions and normals are computed from the *wrapped* grid index
//    (i mod nu), by the same expression every time, so a vertex shared by
//    neighbouring patches — including the seam column, which exists twice
//    (i = 0 and i = nu) — has bit-identical coordinates: no round-off cracks
//    (Buss III.3.2).  sin(2*pi) is not sin(0) in floating point; index 0 is.
//  * Texture coordinates are computed from the *unwrapped* index, so the seam
//    column i = nu can carry s = 1 (or 1.1 ...): the winding number is
//    tracked, and GL_REPEAT does the rest (Figure VI.4's fix).
#pragma once
#include <glm/glm.hpp>

#include <functional>
#include <vector>

#include "common/core/frame.hpp"

namespace ts {
struct SurfacePoint {
  glm::dvec3 pos{0.0};
  glm::dvec3 normal{0.0, 0.0, 1.0};
};

struct Mesh {
  int nu = 0, nv = 0;                // grid cells along u and v
  std::vector<SurfacePoint> points;  // (nu+1) x (nv+1), row-major in v
  std::vector<glm::dvec2> st;        // texture coordinate per grid vertex
  std::vector<glm::ivec2> index;     // the (i, j) of each grid vertex
  int at(int i, int j) const { return j * (nu + 1) + i; }
  // Two triangles per cell, counter-clockwise seen from outside.
  std::vector<unsigned> triangles() const;
};

// A grid over (i, j) in [0, nu] x [0, nv].  `surface(i mod nu, j mod nv)` for
// periodic directions (else the index itself) gives the point; `texcoord(i,
// j)` gets the unwrapped index.
Mesh parametricGrid(int nu, int nv, bool periodicU, bool periodicV,
                    const std::function<SurfacePoint(int i, int j)>& surface,
                    const std::function<glm::dvec2(int i, int j)>& texcoord);

// Angles in degrees, as in the book.
inline double degToRad(double d) { return d * 3.14159265358979323846 / 180.0; }

// p(θ, y) = (r sin θ, y, r cos θ), θ = 360 i / slices + theta0Deg, y from -h/2 to h/2.
SurfacePoint cylinderPoint(double r, double h, int slices, int stacks, int i, int j, double theta0Deg = 0);
// p(θ, φ) = (r sin θ cos φ, r sin φ, r cos θ cos φ), θ = 360 i / slices, φ = -90 + 180 j / stacks.
SurfacePoint spherePoint(double r, int slices, int stacks, int i, int j);
// p(θ, φ) = ((R + r cos φ) sin θ, r sin φ, (R + r cos φ) cos θ), θ = 360 i / nu, φ = 360 j / nv.
SurfacePoint torusPoint(double R, double r, int nu, int nv, int i, int j);

// A mesh as a fixed-function batch of triangles (texture coordinates (s,t,0,1)).
Batch meshBatch(const Mesh& m, int texture, glm::vec4 color = glm::vec4(1.0f), std::string role = "surface");
// The same, shaded: each vertex colour is ambient + diffuse * max(0, n . l)
// for a directional light `toLight` given in the mesh's own (model)
// coordinates, combined with the texture by GL_MODULATE.  Computed on the CPU
// so the sidecar holds the exact colours and no GL lighting state is needed.
Batch litMeshBatch(const Mesh& m, int texture, glm::dvec3 toLight, double ambient = 0.35, double diffuse = 0.65,
                   std::string role = "surface");
}  // namespace ts
