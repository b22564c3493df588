#include "common/core/frame.hpp"

namespace ts {
std::string TextureDesc::key() const {
  std::string k = name;
  for (const auto& [n, v] : params) k += ";" + n + "=" + v;
  if (mipmaps) k += linearLightMips ? ";mips=linear" : ";mips=box";
  if (depth > 1) k += ";depth=" + std::to_string(depth);
  if (cube) k += ";cube";
  return k;
}

static Batch lines(Prim prim, const std::vector<glm::vec2>& pts, glm::vec4 color, float width, std::string role) {
  Batch b;
  b.role = std::move(role);
  b.prim = prim;
  b.lineWidth = width;
  for (auto p : pts) b.vertices.push_back({{p, 0.0f}, {0, 0, 0, 1}, color});
  return b;
}
Batch lineLoop(const std::vector<glm::vec2>& pts, glm::vec4 color, float width, std::string role) {
  return lines(Prim::LineLoop, pts, color, width, std::move(role));
}
Batch lineSegments(const std::vector<glm::vec2>& pts, glm::vec4 color, float width, std::string role) {
  return lines(Prim::Lines, pts, color, width, std::move(role));
}

glm::vec2 panelToPixels(const Panel& p, glm::vec4 clip) {
  glm::vec3 ndc = glm::vec3(clip) / clip.w;
  // GL: x_w = x + (ndc.x + 1) w / 2; y is flipped to the PNG's top-left origin.
  return {float(p.viewport.x) + (ndc.x + 1.0f) * 0.5f * float(p.viewport.w),
          float(p.viewport.y) + (1.0f - ndc.y) * 0.5f * float(p.viewport.h)};
}
}  // namespace ts
