#include "common/core/mesh.hpp"

#include <algorithm>
#include <cmath>

namespace ts {
std::vector<unsigned> Mesh::triangles() const {
  std::vector<unsigned> t;
  t.reserve(size_t(nu) * size_t(nv) * 6);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      unsigned a = unsigned(at(i, j)), b = unsigned(at(i + 1, j)), c = unsigned(at(i + 1, j + 1)),
               d = unsigned(at(i, j + 1));
      t.insert(t.end(), {a, b, c, a, c, d});
    }
  return t;
}

Mesh parametricGrid(int nu, int nv, bool periodicU, bool periodicV,
                    const std::function<SurfacePoint(int, int)>& surface,
                    const std::function<glm::dvec2(int, int)>& texcoord) {
  Mesh m;
  m.nu = nu;
  m.nv = nv;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      // The wrapped index: the seam column is computed as column 0 was.
      int wi = periodicU ? i % nu : i, wj = periodicV ? j % nv : j;
      m.points.push_back(surface(wi, wj));
      m.st.push_back(texcoord(i, j));
      m.index.push_back({i, j});
    }
  return m;
}

SurfacePoint cylinderPoint(double r, double h, int slices, int stacks, int i, int j, double theta0Deg) {
  double th = degToRad(theta0Deg + 360.0 * i / slices);
  double y = -h / 2 + h * j / stacks;
  return {{r * std::sin(th), y, r * std::cos(th)}, {std::sin(th), 0.0, std::cos(th)}};
}

SurfacePoint spherePoint(double r, int slices, int stacks, int i, int j) {
  double th = degToRad(360.0 * i / slices), ph = degToRad(-90.0 + 180.0 * j / stacks);
  glm::dvec3 n(std::sin(th) * std::cos(ph), std::sin(ph), std::cos(th) * std::cos(ph));
  return {r * n, n};
}

SurfacePoint torusPoint(double R, double r, int nu, int nv, int i, int j) {
  double th = degToRad(360.0 * i / nu), ph = degToRad(360.0 * j / nv);
  glm::dvec3 n(std::cos(ph) * std::sin(th), std::sin(ph), std::cos(ph) * std::cos(th));
  glm::dvec3 c(R * std::sin(th), 0.0, R * std::cos(th));
  return {c + r * n, n};
}

Batch meshBatch(const Mesh& m, int texture, glm::vec4 color, std::string role) {
  Batch b;
  b.role = std::move(role);
  b.texture = texture;
  b.texEnv = GL_MODULATE;
  for (unsigned k : m.triangles())
    b.vertices.push_back(
        {glm::vec3(m.points[k].pos), glm::vec4(float(m.st[k].x), float(m.st[k].y), 0.0f, 1.0f), color});
  return b;
}
Batch litMeshBatch(const Mesh& m, int texture, glm::dvec3 toLight, double ambient, double diffuse, std::string role) {
  Batch b = meshBatch(m, texture, glm::vec4(1.0f), std::move(role));
  glm::dvec3 l = glm::normalize(toLight);
  std::vector<unsigned> tri = m.triangles();
  for (size_t k = 0; k < tri.size(); ++k) {
    float c = float(std::min(1.0, ambient + diffuse * std::max(0.0, glm::dot(m.points[tri[k]].normal, l))));
    b.vertices[k].color = glm::vec4(c, c, c, 1.0f);
  }
  return b;
}
}  // namespace ts
