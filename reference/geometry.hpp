// reference/geometry.hpp — a batch's primitives after GL's vertex stage, as
// common/gl/render.cpp has OpenGL draw them: what the reference renderer
// (reference.hpp) and the pixel inspector (inspect.hpp) both start from.
//
// A triangle: clip = projection * modelview * (pos, 1), the texture matrix
// applied to (s,t,r,q), clipped to -w <= z <= w (and w > 0), then the
// viewport transform to window coordinates in the image's orientation
// (x right, y down), and the attribute planes: every attribute a divided by
// w (hyperbolic interpolation) is linear in screen space, a/w = A x + B y + C
// (raster.hpp's Plane), and so is 1/w.  A line or a point: the same
// transform, clipped to the near and far planes.
#pragma once
#include <array>
#include <vector>

#include "common/core/frame.hpp"
#include "raster.hpp"
#include "sampler.hpp"

namespace ref {
// Attribute slots of a screen vertex: (s,t,r,q), the primary colour, the
// secondary colour, all divided by w, then 1/w and the window depth z.
// Unit 1's (s, t, q) (Vertex::tex1 or unit 0's as sent, times
// Batch::textureMatrix1) follow the secondary colour.
enum AttributeSlot : int { kS = 0, kT, kR, kQ, kCr, kCg, kCb, kCa, kSr, kSg, kSb, kS1, kT1, kQ1, kW, kZ, kAttributes };

inline double clamp01(double v) { return v < 0 ? 0 : v > 1 ? 1 : v; }
// A clear colour as the colour buffer holds it: each channel clamped to [0, 1].
inline Colour clampedColour(const glm::vec4& c) {
  return {float(clamp01(c.r)), float(clamp01(c.g)), float(clamp01(c.b)), float(clamp01(c.a))};
}

// The scissor render.cpp sets (= the panel's viewport), clipped to the frame,
// in image pixels.
PixelRect scissorRect(const ts::Panel& p, int frameWidth, int frameHeight);

// The viewport transform of a panel: clip coordinates to window x, y (image
// pixels, y down) and depth z in [0, 1].
struct WindowTransform {
  WindowTransform(const ts::Panel& p, int frameHeight);
  glm::dvec3 operator()(const glm::dvec4& clip) const;
  double vx, vy, vw, vh;  // the viewport, GL's bottom-left origin
  double frameHeight;
};

// demos/quad_distortion's "bilinear_quad" program: the one GLSL program the
// reference models (its fragment shader maps (s/q, t/q) bilinearly to the
// corners st00, st10, st11, st01 given as uniforms, then looks the texture up).
bool isBilinearQuad(const ts::Batch& b);
// A vertex's (s, t, r, q) as GL's vertex stage makes them: the batch's
// glTexGen (OBJECT_LINEAR from the object position, EYE_LINEAR from the eye
// position with the planes given under planeModelview) replaces the
// coordinates it generates; the others are glTexCoord4f's.
// glTexGen's environment-mapping modes (GL 2.1 §2.11.4) at a vertex of
// object position `pos` and normal `normal` under `modelview`: with n' the
// eye-space normal (M⁻¹)ᵀ n, u the unit vector from the eye to the vertex
// and r = u - 2 (n'·u) n', GL_NORMAL_MAP gives n', GL_REFLECTION_MAP r,
// GL_SPHERE_MAP (r_x/m + 1/2, r_y/m + 1/2, 0) with m = 2 sqrt(r_x² + r_y² +
// (r_z + 1)²).
glm::dvec3 envTexGen(const glm::dmat4& modelview, GLenum mode, const glm::dvec3& pos, const glm::dvec3& normal);
glm::dvec4 texGenCoords(const ts::Panel& p, const ts::Batch& b, const ts::Vertex& v);

// A clipped triangle (a convex polygon of 3 to 5 vertices) in screen space
// with its attribute planes.
struct ScreenPoly {
  std::vector<ScreenVertex> v;
  Plane P[kAttributes];
  bool bilinear = false;  // the "bilinear_quad" program
  glm::dvec2 st00{0.0}, st10{0.0}, st11{0.0}, st01{0.0};
  bool constantDeriv = false;  // q/w constant: the derivatives are the same everywhere
  double orient = 1;           // +1 / -1: sign making edge distances positive inside

  // The texture coordinate from the interpolated (a, b) = (s/q, t/q): itself,
  // or the bilinear program's map.
  void coordFrom(double a, double b, double* s, double* t) const;
  // The texture coordinate at (x, y): (s/w) / (q/w) from the planes.
  void coord(double x, double y, double* s, double* t) const;
  // Its derivatives along x and y, in closed form.
  Deriv deriv(double x, double y) const;
  // Unit 1's (s/q, t/q) at (x, y) and their derivatives.
  void coord1(double x, double y, double* s, double* t) const;
  Deriv deriv1(double x, double y) const;
  // The interpolated primary and secondary colours (alpha 0), clamped to [0, 1].
  Colour colour(double x, double y) const;
  Colour secondary(double x, double y) const;
  // Edge lines n.x x + n.y y + c, unit normals pointing inside.
  std::vector<std::array<double, 3>> edges;
  void prepareEdges();
  // Smallest signed distance (pixels) from (x, y) to the polygon's edges,
  // positive inside.
  double edgeDistance(double x, double y) const;
};

// Triangle (b.vertices[first], [first + 1], [first + 2]) after vertex
// processing.  False if it is clipped away or has no area.  `perspective`
// false: attributes are interpolated linearly in screen space (the "without"
// of Figure VI.2) instead of hyperbolically.
bool screenTriangle(const ts::Panel& p, const ts::Batch& b, size_t first, int frameHeight, bool perspective,
                    ScreenPoly* out);

// The colour of a fragment of batch b from its interpolated colours and,
// when textured, its filtered texel: the texture environment (or, for the
// bilinear program, the texel itself), then the colour sum when on.
Colour shadeFragment(const ts::Batch& b, const Colour& primary, const Colour& secondary, const Colour* texel);

// A line segment of a line batch in window coordinates (image pixels),
// clipped to the near and far planes; ia, ib: its vertices in the batch.
struct WindowSegment {
  glm::dvec2 a{0.0}, c{0.0};
  size_t ia = 0, ib = 0;
};
std::vector<WindowSegment> windowSegments(const ts::Panel& p, const ts::Batch& b, int frameHeight);
// Distance from q to the segment, and the parameter u in [0, 1] of its
// nearest point (the reference colours the line by mixing the vertex
// colours with it).
double segmentDistance(const WindowSegment& s, glm::dvec2 q, double* u);
// Half the width of a line as the reference draws it (at least half a pixel).
double lineHalfWidth(const ts::Batch& b);
// A point vertex in window coordinates; false if clipped by the near or far plane.
bool windowPoint(const ts::Panel& p, const ts::Vertex& v, int frameHeight, glm::dvec2* out);
// The pixels of a square point of the given size centred at `w`.
PixelRect pointSquare(glm::dvec2 w, double size);
}  // namespace ref
