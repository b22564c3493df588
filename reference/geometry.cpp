#include "geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ref {
namespace {
struct ClipVertex {
  glm::dvec4 clip{0.0};
  std::array<double, 14> attr{};  // s, t, r, q, colour rgba, secondary rgb, unit 1's s, t, q
};

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double u) {
  ClipVertex o;
  o.clip = a.clip + (b.clip - a.clip) * u;
  for (size_t k = 0; k < a.attr.size(); ++k) o.attr[k] = a.attr[k] + (b.attr[k] - a.attr[k]) * u;
  return o;
}

// Signed distances of a clip-space point to the planes GL clips against
// here: k = 0 near (z >= -w), 1 far (z <= w), 2 w > 0.
double clipDistance(const glm::dvec4& c, int k) {
  switch (k) {
    case 0: return c.z + c.w;
    case 1: return c.w - c.z;
    default: return c.w - 1e-12;
  }
}

// Sutherland-Hodgman against -w <= z <= w (the near and far planes) and
// w > 0.  GL clips x and y too; here the scissor (= the viewport) does that.
std::vector<ClipVertex> clipPolygon(std::vector<ClipVertex> poly) {
  for (int k = 0; k < 3 && !poly.empty(); ++k) {
    std::vector<ClipVertex> out;
    for (size_t i = 0; i < poly.size(); ++i) {
      const ClipVertex &a = poly[i], &b = poly[(i + 1) % poly.size()];
      double da = clipDistance(a.clip, k), db = clipDistance(b.clip, k);
      if (da >= 0) out.push_back(a);
      if ((da >= 0) != (db >= 0)) out.push_back(lerp(a, b, da / (da - db)));
    }
    poly.swap(out);
  }
  return poly;
}

glm::dmat4 modelViewProjection(const ts::Panel& p) { return glm::dmat4(p.projection) * glm::dmat4(p.modelview); }
}  // namespace

PixelRect scissorRect(const ts::Panel& p, int frameWidth, int frameHeight) {
  return {std::max(0, p.viewport.x), std::max(0, p.viewport.y), std::min(frameWidth, p.viewport.x + p.viewport.w),
          std::min(frameHeight, p.viewport.y + p.viewport.h)};
}

WindowTransform::WindowTransform(const ts::Panel& p, int H)
    : vx(p.viewport.x),
      vy(double(H - p.viewport.y - p.viewport.h)),  // render.cpp's glViewport y
      vw(p.viewport.w),
      vh(p.viewport.h),
      frameHeight(H) {}

glm::dvec3 WindowTransform::operator()(const glm::dvec4& clip) const {
  glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  return {vx + (ndc.x + 1.0) * 0.5 * vw, frameHeight - (vy + (ndc.y + 1.0) * 0.5 * vh), (ndc.z + 1.0) * 0.5};
}

glm::dvec3 envTexGen(const glm::dmat4& modelview, GLenum mode, const glm::dvec3& pos, const glm::dvec3& normal) {
  // n' = (M⁻¹)ᵀ n: the normal in eye coordinates, not renormalised (GL_NORMALIZE is off).
  const glm::dvec3 n = glm::transpose(glm::inverse(glm::dmat3(modelview))) * normal;
  if (mode == GL_NORMAL_MAP) return n;
  // u: the unit vector from the eye (the origin) to the vertex.
  const glm::dvec3 u = glm::normalize(glm::dvec3(modelview * glm::dvec4(pos, 1.0)));
  const glm::dvec3 r = u - 2.0 * glm::dot(n, u) * n;
  if (mode == GL_REFLECTION_MAP) return r;
  const double m = 2.0 * std::sqrt(r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0));  // GL_SPHERE_MAP
  return {r.x / m + 0.5, r.y / m + 0.5, 0.0};
}

glm::dvec4 texGenCoords(const ts::Panel& p, const ts::Batch& b, const ts::Vertex& v) {
  glm::dvec4 tex(v.tex);
  if (!b.texGen.on()) return tex;
  if (b.texGen.needsNormal()) {  // GL_SPHERE_MAP, GL_REFLECTION_MAP, GL_NORMAL_MAP
    const glm::dvec3 g = envTexGen(glm::dmat4(p.modelview), b.texGen.mode, glm::dvec3(v.pos), glm::dvec3(v.normal));
    for (int k = 0; k < 3; ++k)
      if (b.texGen.coords & (1u << k)) tex[k] = g[k];
    return tex;
  }
  const glm::dvec4 obj(glm::dvec3(v.pos), 1.0);
  const bool eye = b.texGen.mode == GL_EYE_LINEAR;
  // EYE_LINEAR: GL stores plane · M⁻¹ (M the modelview when it was given)
  // and evaluates it at the vertex in eye coordinates.
  const glm::dmat4 toEye = glm::dmat4(p.modelview), planeInv = glm::inverse(glm::dmat4(b.texGen.planeModelview));
  const glm::dvec4 e = toEye * obj;
  for (int k = 0; k < 4; ++k) {
    if (!(b.texGen.coords & (1u << k))) continue;
    const glm::dvec4 plane(b.texGen.planes[k]);
    // A row vector times a matrix: (plane · M⁻¹)_c = Σ_r plane_r M⁻¹[c][r].
    tex[k] = eye ? glm::dot(plane * planeInv, e) : glm::dot(plane, obj);
  }
  return tex;
}

bool isBilinearQuad(const ts::Batch& b) { return b.program == "bilinear_quad" && b.texture >= 0; }

void ScreenPoly::coordFrom(double a, double b, double* s, double* t) const {
  if (!bilinear) {
    *s = a, *t = b;
    return;
  }
  glm::dvec2 bottom = glm::mix(st00, st10, a), top = glm::mix(st01, st11, a);
  glm::dvec2 st = glm::mix(bottom, top, b);
  *s = st.x, *t = st.y;
}

void ScreenPoly::coord(double x, double y, double* s, double* t) const {
  double q = P[kQ].at(x, y);
  coordFrom(P[kS].at(x, y) / q, P[kT].at(x, y) / q, s, t);
}

Deriv ScreenPoly::deriv(double x, double y) const {
  double q = P[kQ].at(x, y);
  double a = P[kS].at(x, y) / q, b = P[kT].at(x, y) / q;
  // d(N/D) = (dN - (N/D) dD) / D
  double dadx = (P[kS].a - a * P[kQ].a) / q, dady = (P[kS].b - a * P[kQ].b) / q;
  double dbdx = (P[kT].a - b * P[kQ].a) / q, dbdy = (P[kT].b - b * P[kQ].b) / q;
  if (!bilinear) return {dadx, dady, dbdx, dbdy};
  glm::dvec2 dA = (1 - b) * (st10 - st00) + b * (st11 - st01);
  glm::dvec2 dB = glm::mix(st01, st11, a) - glm::mix(st00, st10, a);
  return {dA.x * dadx + dB.x * dbdx, dA.x * dady + dB.x * dbdy, dA.y * dadx + dB.y * dbdx, dA.y * dady + dB.y * dbdy};
}

void ScreenPoly::coord1(double x, double y, double* s, double* t) const {
  const double q = P[kQ1].at(x, y);
  *s = P[kS1].at(x, y) / q, *t = P[kT1].at(x, y) / q;
}

Deriv ScreenPoly::deriv1(double x, double y) const {
  const double q = P[kQ1].at(x, y), a = P[kS1].at(x, y) / q, b = P[kT1].at(x, y) / q;
  return {(P[kS1].a - a * P[kQ1].a) / q, (P[kS1].b - a * P[kQ1].b) / q, (P[kT1].a - b * P[kQ1].a) / q,
          (P[kT1].b - b * P[kQ1].b) / q};
}

Colour ScreenPoly::colour(double x, double y) const {
  double w = P[kW].at(x, y);
  return {float(clamp01(P[kCr].at(x, y) / w)), float(clamp01(P[kCg].at(x, y) / w)), float(clamp01(P[kCb].at(x, y) / w)),
          float(clamp01(P[kCa].at(x, y) / w))};
}

Colour ScreenPoly::secondary(double x, double y) const {
  double w = P[kW].at(x, y);
  return {float(clamp01(P[kSr].at(x, y) / w)), float(clamp01(P[kSg].at(x, y) / w)), float(clamp01(P[kSb].at(x, y) / w)),
          0.0f};
}

void ScreenPoly::prepareEdges() {
  edges.clear();
  for (size_t i = 0; i < v.size(); ++i) {
    const ScreenVertex &a = v[i], &b = v[(i + 1) % v.size()];
    double ex = b.x - a.x, ey = b.y - a.y, len = std::sqrt(ex * ex + ey * ey);
    if (len == 0) continue;
    double nx = -orient * ey / len, ny = orient * ex / len;
    edges.push_back({nx, ny, -(nx * a.x + ny * a.y)});
  }
}

double ScreenPoly::edgeDistance(double x, double y) const {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& e : edges) d = std::min(d, e[0] * x + e[1] * y + e[2]);
  return d;
}

bool screenTriangle(const ts::Panel& p, const ts::Batch& b, size_t first, int frameHeight, bool persp,
                    ScreenPoly* out) {
  const glm::dmat4 mvp = modelViewProjection(p);
  const WindowTransform window(p, frameHeight);
  std::vector<ClipVertex> tri(3);
  double userDistance[3] = {0, 0, 0};
  // glClipPlane: GL stores plane · M⁻¹ (M the modelview it was given under)
  // and evaluates it at the vertex in eye coordinates.
  const glm::dvec4 clipEye = b.clip ? glm::dvec4(b.clipPlane) * glm::inverse(glm::dmat4(b.clipModelview))
                                    : glm::dvec4(0.0);
  const glm::dmat4 toEye(p.modelview);
  for (size_t k = 0; k < 3; ++k) {
    const ts::Vertex& vx = b.vertices[first + k];
    tri[k].clip = mvp * glm::dvec4(glm::dvec3(vx.pos), 1.0);
    // glTexGen first (it replaces the coordinates it generates), then the
    // texture matrix acts on (s,t,r,q) per vertex, before clipping and
    // interpolation, as GL's vertex stage does.
    const glm::dvec4 st = glm::dmat4(b.textureMatrix) * texGenCoords(p, b, vx);
    if (b.clip) userDistance[k] = glm::dot(clipEye, toEye * glm::dvec4(glm::dvec3(vx.pos), 1.0));
    // Unit 1: its own coordinates or unit 0's as sent, times its texture matrix.
    const glm::dvec4 u1 = glm::dmat4(b.textureMatrix1) * glm::dvec4(b.coords1 ? vx.tex1 : vx.tex);
    tri[k].attr = {st.x,       st.y,           st.z,           st.w,           vx.color.r, vx.color.g, vx.color.b,
                   vx.color.a, vx.secondary.r, vx.secondary.g, vx.secondary.b, u1.x,       u1.y,       u1.w};
  }
  if (b.clip) {
    // Keep the distance >= 0.  The distance is linear
    // along an edge, so the cut lies where clip space interpolates to 0.
    std::vector<ClipVertex> kept;
    for (size_t i = 0; i < 3; ++i) {
      const size_t j = (i + 1) % 3;
      const double da = userDistance[i], db = userDistance[j];
      if (da >= 0) kept.push_back(tri[i]);
      if ((da >= 0) != (db >= 0)) kept.push_back(lerp(tri[i], tri[j], da / (da - db)));
    }
    tri.swap(kept);
    if (tri.size() < 3) return false;
  }
  std::vector<ClipVertex> poly = clipPolygon(tri);
  if (poly.size() < 3) return false;
  ScreenPoly& P = *out;
  P = ScreenPoly{};
  P.bilinear = isBilinearQuad(b);
  if (P.bilinear) {
    for (const auto& u : b.uniforms) {
      if (u.name == "st00_st10") P.st00 = {u.value.x, u.value.y}, P.st10 = {u.value.z, u.value.w};
      if (u.name == "st11_st01") P.st11 = {u.value.x, u.value.y}, P.st01 = {u.value.z, u.value.w};
    }
  }
  for (const ClipVertex& c : poly) {
    ScreenVertex s;
    glm::dvec3 win = window(c.clip);
    s.x = win.x, s.y = win.y;
    double k = persp ? 1.0 / c.clip.w : 1.0;
    for (int a = 0; a < kW; ++a) s.a[size_t(a)] = c.attr[size_t(a)] * k;
    s.a[kW] = k;
    s.a[kZ] = win.z;
    P.v.push_back(s);
  }
  // Signed area: orientation, and skip degenerate triangles.
  double area = 0;
  for (size_t k = 0; k < P.v.size(); ++k) {
    const ScreenVertex &a = P.v[k], &c = P.v[(k + 1) % P.v.size()];
    area += a.x * c.y - c.x * a.y;
  }
  if (!(std::abs(area) > 1e-9)) return false;
  P.orient = area > 0 ? 1.0 : -1.0;
  P.prepareEdges();
  // Planes from the first three vertices that span an area.
  bool ok = false;
  for (size_t k = 2; k < P.v.size() && !ok; ++k) {
    for (int a = 0; a < kAttributes; ++a) P.P[a] = planeThrough(P.v[0], P.v[1], P.v[k], a, &ok);
  }
  if (!ok) return false;
  P.constantDeriv = !P.bilinear && P.P[kQ].a == 0 && P.P[kQ].b == 0;
  return true;
}

Colour shadeFragment(const ts::Batch& b, const Colour& primary, const Colour& secondary, const Colour* texel) {
  Colour out = primary;
  if (texel) {
    // The bilinear program writes its texel; an environment the table does
    // not hold (the verifier exempts its pixels) is drawn as the texel too.
    bool env = !isBilinearQuad(b) && texEnvModelled(b.texEnv);
    out = env ? texEnv(b.texEnv, primary, *texel, {b.envColor.r, b.envColor.g, b.envColor.b, b.envColor.a}) : *texel;
  }
  return b.colorSum ? colourSum(out, secondary) : out;
}

std::vector<WindowSegment> windowSegments(const ts::Panel& p, const ts::Batch& b, int frameHeight) {
  const glm::dmat4 mvp = modelViewProjection(p);
  const WindowTransform window(p, frameHeight);
  std::vector<std::pair<size_t, size_t>> segs;
  size_t n = b.vertices.size();
  if (b.prim == ts::Prim::Lines)
    for (size_t i = 0; i + 1 < n; i += 2) segs.push_back({i, i + 1});
  if (b.prim == ts::Prim::LineStrip || b.prim == ts::Prim::LineLoop)
    for (size_t i = 0; i + 1 < n; ++i) segs.push_back({i, i + 1});
  if (b.prim == ts::Prim::LineLoop && n > 2) segs.push_back({n - 1, 0});
  std::vector<WindowSegment> out;
  for (auto [ia, ib] : segs) {
    glm::dvec4 ca = mvp * glm::dvec4(glm::dvec3(b.vertices[ia].pos), 1.0);
    glm::dvec4 cb = mvp * glm::dvec4(glm::dvec3(b.vertices[ib].pos), 1.0);
    // Clip the segment to the near/far planes.
    double t0 = 0, t1 = 1;
    bool visible = true;
    for (int k = 0; k < 3 && visible; ++k) {
      double da = clipDistance(ca, k), db = clipDistance(cb, k);
      if (da < 0 && db < 0) visible = false;
      else if (da < 0) t0 = std::max(t0, da / (da - db));
      else if (db < 0) t1 = std::min(t1, da / (da - db));
    }
    if (!visible || t0 > t1) continue;
    WindowSegment s;
    s.a = glm::dvec2(window(ca + (cb - ca) * t0));
    s.c = glm::dvec2(window(ca + (cb - ca) * t1));
    s.ia = ia, s.ib = ib;
    out.push_back(s);
  }
  return out;
}

double segmentDistance(const WindowSegment& s, glm::dvec2 q, double* u) {
  glm::dvec2 d = s.c - s.a;
  double len2 = glm::dot(d, d);
  *u = len2 > 0 ? std::clamp(glm::dot(q - s.a, d) / len2, 0.0, 1.0) : 0.0;
  return glm::length(q - (s.a + d * *u));
}

double lineHalfWidth(const ts::Batch& b) { return std::max(0.5, double(b.lineWidth) * 0.5); }

bool windowPoint(const ts::Panel& p, const ts::Vertex& v, int frameHeight, glm::dvec2* out) {
  glm::dvec4 c = modelViewProjection(p) * glm::dvec4(glm::dvec3(v.pos), 1.0);
  if (!(c.w > 0) || c.z < -c.w || c.z > c.w) return false;
  *out = glm::dvec2(WindowTransform(p, frameHeight)(c));
  return true;
}

PixelRect pointSquare(glm::dvec2 w, double size) {
  double h = size * 0.5;
  return {int(std::floor(w.x - h)), int(std::floor(w.y - h)), int(std::ceil(w.x + h)), int(std::ceil(w.y + h))};
}
}  // namespace ref
