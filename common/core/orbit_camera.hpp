// common/core/orbit_camera.hpp — the mouse's camera in every 3D view.
//
// Three options, --yaw and --pitch (degrees) and --zoom (a factor), are part
// of the demo's state like any other: the window turns them with a left drag
// and the wheel (window_input.cpp finds them by these names), the overlay shows
// them, F12's command and the sidecar carry them, so whatever view a student
// finds is one --png away.  At the defaults (0, 0, 1) nothing is changed, not
// a bit: the book's figures are the figures' own views.
//
//   yaw    turns the model about the eye's vertical axis through its centre
//   pitch  then about the eye's horizontal axis through the same point
//   zoom   scales the projection's x and y (a longer lens): the depth range,
//          and so the near/far clipping, stays the demo's own
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "common/core/frame.hpp"
#include "common/core/options.hpp"

namespace ts {
struct OrbitCamera {
  static constexpr const char* kYaw = "yaw";
  static constexpr const char* kPitch = "pitch";
  static constexpr const char* kZoom = "zoom";
  static constexpr float kMinZoom = 0.25f, kMaxZoom = 8.0f;

  float yaw = 0.0f, pitch = 0.0f, zoom = 1.0f;

  // --yaw, --pitch, --zoom (no keys: the mouse, and the demo's own keys).
  void addOptions(Options& o) {
    o.addFloat(kYaw, &yaw, -180.0f, 180.0f, "orbit: turn about the view's vertical, degrees (left drag)");
    o.addFloat(kPitch, &pitch, -90.0f, 90.0f, "orbit: tilt about the view's horizontal, degrees (left drag)");
    o.addFloat(kZoom, &zoom, kMinZoom, kMaxZoom, "orbit: lens zoom, 1 = the figure's own (mouse wheel)");
  }
  bool isDefault() const { return yaw == 0.0f && pitch == 0.0f && zoom == 1.0f; }

  // `modelview` orbited about `centre` (model coordinates).
  template <typename T, glm::qualifier Q>
  glm::mat<4, 4, T, Q> view(const glm::mat<4, 4, T, Q>& modelview, glm::vec<3, T, Q> centre = {}) const {
    if (yaw == 0.0f && pitch == 0.0f) return modelview;
    using M = glm::mat<4, 4, T, Q>;
    using V = glm::vec<3, T, Q>;
    V c(modelview * glm::vec<4, T, Q>(centre, T(1)));  // the centre in eye space
    M r = glm::rotate(M(T(1)), glm::radians(T(pitch)), V(1, 0, 0)) *
          glm::rotate(M(T(1)), glm::radians(T(yaw)), V(0, 1, 0));
    return glm::translate(M(T(1)), c) * r * glm::translate(M(T(1)), -c) * modelview;
  }
  // `projection` with the zoom applied (x and y scaled about the centre).
  template <typename T, glm::qualifier Q>
  glm::mat<4, 4, T, Q> lens(const glm::mat<4, 4, T, Q>& projection) const {
    if (zoom == 1.0f) return projection;
    using M = glm::mat<4, 4, T, Q>;
    return glm::scale(M(T(1)), glm::vec<3, T, Q>(T(zoom), T(zoom), T(1))) * projection;
  }
  // Both, on a panel whose matrices are set.
  void apply(Panel& p, glm::vec3 centre = glm::vec3(0.0f)) const {
    p.modelview = view(p.modelview, centre);
    p.projection = lens(p.projection);
  }
};
}  // namespace ts
