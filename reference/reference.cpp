#include "reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/core/error.hpp"
#include "common/core/text.hpp"

namespace ref {
namespace {
// Attribute slots of a screen vertex.
enum : int { kS = 0, kT, kR, kQ, kCr, kCg, kCb, kCa, kSr, kSg, kSb, kW, kZ, kAttributes };

struct ClipVertex {
  glm::dvec4 clip{0.0};
  std::array<double, 11> attr{};  // s, t, r, q, colour rgba, secondary rgb
};

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double u) {
  ClipVertex o;
  o.clip = a.clip + (b.clip - a.clip) * u;
  for (size_t k = 0; k < a.attr.size(); ++k) o.attr[k] = a.attr[k] + (b.attr[k] - a.attr[k]) * u;
  return o;
}

// Sutherland-Hodgman against -w <= z <= w (the near and far planes) and
// w > 0.  GL clips x and y too; here the scissor (= the viewport) does that.
std::vector<ClipVertex> clipPolygon(std::vector<ClipVertex> poly) {
  auto planeDist = [](const glm::dvec4& c, int k) {
    switch (k) {
      case 0: return c.z + c.w;
      case 1: return c.w - c.z;
      default: return c.w - 1e-12;
    }
  };
  for (int k = 0; k < 3 && !poly.empty(); ++k) {
    std::vector<ClipVertex> out;
    for (size_t i = 0; i < poly.size(); ++i) {
      const ClipVertex &a = poly[i], &b = poly[(i + 1) % poly.size()];
      double da = planeDist(a.clip, k), db = planeDist(b.clip, k);
      if (da >= 0) out.push_back(a);
      if ((da >= 0) != (db >= 0)) out.push_back(lerp(a, b, da / (da - db)));
    }
    poly.swap(out);
  }
  return poly;
}

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

}  // namespace

const char* exemptName(Exempt e) {
  switch (e) {
    case Exempt::None: return "none";
    case Exempt::Line: return "line";
    case Exempt::Point: return "point";
    case Exempt::Label: return "label";
    case Exempt::Program: return "program";
    case Exempt::Blend: return "blend";
    case Exempt::Unsupported: return "unsupported";
    case Exempt::Edge: return "edge";
    case Exempt::Count: break;
  }
  return "?";
}

// A clipped triangle in screen space with its attribute planes.
struct Reference::Poly {
  std::vector<ScreenVertex> v;
  Plane P[kAttributes];
  bool bilinear = false;
  glm::dvec2 st00{0.0}, st10{0.0}, st11{0.0}, st01{0.0};
  bool constantDeriv = false;
  double orient = 1;  // +1 / -1: sign making edge distances positive inside

  void coordFrom(double a, double b, double* s, double* t) const {
    if (!bilinear) {
      *s = a, *t = b;
      return;
    }
    glm::dvec2 bottom = glm::mix(st00, st10, a), top = glm::mix(st01, st11, a);
    glm::dvec2 st = glm::mix(bottom, top, b);
    *s = st.x, *t = st.y;
  }
  void coord(double x, double y, double* s, double* t) const {
    double q = P[kQ].at(x, y);
    coordFrom(P[kS].at(x, y) / q, P[kT].at(x, y) / q, s, t);
  }
  Deriv deriv(double x, double y) const {
    double q = P[kQ].at(x, y);
    double a = P[kS].at(x, y) / q, b = P[kT].at(x, y) / q;
    // d(N/D) = (dN - (N/D) dD) / D
    double dadx = (P[kS].a - a * P[kQ].a) / q, dady = (P[kS].b - a * P[kQ].b) / q;
    double dbdx = (P[kT].a - b * P[kQ].a) / q, dbdy = (P[kT].b - b * P[kQ].b) / q;
    if (!bilinear) return {dadx, dady, dbdx, dbdy};
    glm::dvec2 dA = (1 - b) * (st10 - st00) + b * (st11 - st01);
    glm::dvec2 dB = glm::mix(st01, st11, a) - glm::mix(st00, st10, a);
    return {dA.x * dadx + dB.x * dbdx, dA.x * dady + dB.x * dbdy, dA.y * dadx + dB.y * dbdx,
            dA.y * dady + dB.y * dbdy};
  }
  Colour colour(double x, double y) const {
    double w = P[kW].at(x, y);
    return {float(clamp01(P[kCr].at(x, y) / w)), float(clamp01(P[kCg].at(x, y) / w)),
            float(clamp01(P[kCb].at(x, y) / w)), float(clamp01(P[kCa].at(x, y) / w))};
  }
  Colour secondary(double x, double y) const {
    double w = P[kW].at(x, y);
    return {float(clamp01(P[kSr].at(x, y) / w)), float(clamp01(P[kSg].at(x, y) / w)),
            float(clamp01(P[kSb].at(x, y) / w)), 0.0f};
  }
  // Edge lines n.x x + n.y y + c, unit normals pointing inside.
  std::vector<std::array<double, 3>> edges;
  void prepareEdges() {
    edges.clear();
    for (size_t i = 0; i < v.size(); ++i) {
      const ScreenVertex &a = v[i], &b = v[(i + 1) % v.size()];
      double ex = b.x - a.x, ey = b.y - a.y, len = std::sqrt(ex * ex + ey * ey);
      if (len == 0) continue;
      double nx = -orient * ey / len, ny = orient * ex / len;
      edges.push_back({nx, ny, -(nx * a.x + ny * a.y)});
    }
  }
  // Smallest signed distance (pixels) from (x, y) to the polygon's edges,
  // positive inside.
  double edgeDistance(double x, double y) const {
    double d = std::numeric_limits<double>::infinity();
    for (const auto& e : edges) d = std::min(d, e[0] * x + e[1] * y + e[2]);
    return d;
  }
};

PixelRect labelBox(const ts::Label& l, int margin, bool known) {
  int scale = known ? std::max(1, l.scale) : ts::text::kMaxScale;
  double w = ts::text::width(l.text, scale), h = ts::text::height(scale), pad = 3.0 * scale;
  double x0, x1;
  if (known) {
    double x = l.align == ts::Align::Left ? l.x : l.align == ts::Align::Center ? l.x - w / 2 : l.x - w;
    x = double(int(x));  // render.cpp truncates
    x0 = x - pad, x1 = x + w + pad;
  } else {
    x0 = l.x - w - pad, x1 = l.x + w + pad;
  }
  double y = double(int(l.y));
  return {int(std::floor(x0)) - margin, int(std::floor(y - pad)) - margin, int(std::ceil(x1)) + margin,
          int(std::ceil(y + h + pad)) + margin};
}

Reference::Reference(const ts::Frame& f, const RenderOptions& o) : opts_(o), width_(f.width), height_(f.height) {
  if (f.width < 1 || f.height < 1) throw ts::Error("reference: empty frame", ts::kExitFailure);
  clear_ = {float(clamp01(f.clearColor.r)), float(clamp01(f.clearColor.g)), float(clamp01(f.clearColor.b)),
            float(clamp01(f.clearColor.a))};
  image_ = ts::Image(f.width, f.height, toRgba(clear_));
  depth_.assign(size_t(f.width) * size_t(f.height), 1.0f);
  head_.assign(size_t(f.width) * size_t(f.height), -1);
  pool_.reserve(size_t(f.width) * size_t(f.height) / 2);
  for (const auto& t : f.textures) textures_.emplace_back(t);
  for (const auto& p : f.panels) drawPanel(p);
  if (opts_.labels) drawLabels(f);
}

Reference Reference::withLabels(const ts::Frame& f, bool geometryKnown) const {
  Reference r = *this;
  r.opts_.labels = true;
  r.opts_.labelGeometryKnown = geometryKnown;
  r.drawLabels(f);
  return r;
}

void Reference::note(const std::string& s) {
  if (std::find(notes_.begin(), notes_.end(), s) == notes_.end()) notes_.push_back(s);
}

void Reference::place(int x, int y, const Candidate& c, bool sure, bool depthTest) {
  size_t idx = size_t(y) * size_t(width_) + size_t(x);
  int& h = head_[idx];
  if (h < 0) {  // materialise the clear colour so it can be kept beside c
    Candidate clr;
    clr.colour = clear_;
    pool_.push_back(clr);
    h = int(pool_.size()) - 1;
  }
  if (depthTest && c.kind != Candidate::Kind::Exempt) {
    bool canPass = false, mustPass = true;
    for (int i = h; i >= 0; i = pool_[size_t(i)].next) {
      const Candidate& e = pool_[size_t(i)];
      if (e.kind == Candidate::Kind::Exempt) {
        canPass = true, mustPass = false;
      } else if (c.z < e.z - float(opts_.depthEpsilon)) {
        canPass = true;
      } else if (c.z >= e.z + float(opts_.depthEpsilon)) {
        mustPass = false;
      } else {
        canPass = true, mustPass = false;
      }
    }
    if (!canPass) return;
    if (!mustPass) sure = false;
  }
  Candidate n = c;
  n.next = sure ? -1 : h;
  pool_.push_back(n);
  h = int(pool_.size()) - 1;
}

void Reference::exemptDisc(double cx, double cy, double r, Exempt why, PixelRect clip) {
  Candidate e;
  e.kind = Candidate::Kind::Exempt;
  e.why = why;
  int x0 = std::max(clip.x0, int(std::floor(cx - r))), x1 = std::min(clip.x1, int(std::ceil(cx + r)) + 1);
  int y0 = std::max(clip.y0, int(std::floor(cy - r))), y1 = std::min(clip.y1, int(std::ceil(cy + r)) + 1);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) <= r) place(x, y, e, false, false);
}

void Reference::drawPanel(const ts::Panel& p) {
  // The scissor is the viewport (render.cpp), in image rows.
  PixelRect sc{std::max(0, p.viewport.x), std::max(0, p.viewport.y), std::min(width_, p.viewport.x + p.viewport.w),
               std::min(height_, p.viewport.y + p.viewport.h)};
  if (sc.x0 >= sc.x1 || sc.y0 >= sc.y1) return;
  if (p.clear) {
    Candidate c;
    c.colour = {float(clamp01(p.clearColor.r)), float(clamp01(p.clearColor.g)), float(clamp01(p.clearColor.b)),
                float(clamp01(p.clearColor.a))};
    for (int y = sc.y0; y < sc.y1; ++y)
      for (int x = sc.x0; x < sc.x1; ++x) {
        place(x, y, c, true, false);
        image_.set(x, y, toRgba(c.colour));
        depth_[size_t(y) * size_t(width_) + size_t(x)] = 1.0f;
      }
  }
  for (const ts::Batch& b : p.batches) {
    switch (b.prim) {
      case ts::Prim::Triangles: drawTriangles(p, b, sc); break;
      case ts::Prim::Lines:
      case ts::Prim::LineStrip:
      case ts::Prim::LineLoop:
      case ts::Prim::Points: drawLines(p, b, sc); break;
    }
  }
}

void Reference::drawTriangles(const ts::Panel& p, const ts::Batch& b, PixelRect sc) {
  const glm::dmat4 mvp = glm::dmat4(p.projection) * glm::dmat4(p.modelview);
  const double H = height_;
  const double glY = double(height_ - p.viewport.y - p.viewport.h);  // render.cpp's glViewport y
  const bool persp = opts_.interpolation == Interpolation::Perspective;

  // What the batch's fragments are.
  Candidate proto;
  proto.kind = Candidate::Kind::Flat;
  const Texture* tex = nullptr;
  bool bilinear = false;
  glm::dvec4 u0(0.0), u1(0.0);
  if (!b.program.empty()) {
    if (b.program == "bilinear_quad" && b.texture >= 0) {
      bilinear = true;
      for (const auto& u : b.uniforms) {
        if (u.name == "st00_st10") u0 = glm::dvec4(u.value);
        if (u.name == "st11_st01") u1 = glm::dvec4(u.value);
      }
    } else {
      proto.kind = Candidate::Kind::Exempt;
      proto.why = Exempt::Program;
      note("program '" + b.program + "' is not modelled: its pixels are exempt");
    }
  }
  if (proto.kind != Candidate::Kind::Exempt && b.texture >= 0) {
    tex = &textures_.at(size_t(b.texture));
    proto.kind = Candidate::Kind::Textured;
    proto.texture = b.texture;
    if (!bilinear) {
      proto.env = b.texEnv;
      proto.envColour = {b.envColor.r, b.envColor.g, b.envColor.b, b.envColor.a};
      if (b.texEnv == GL_MODULATE) proto.modulate = true;
      else if (!texEnvModelled(b.texEnv)) {
        proto.kind = Candidate::Kind::Exempt;
        proto.why = Exempt::Unsupported;
        note("texture environment " + std::to_string(b.texEnv) + " is not modelled: its pixels are exempt");
      }
    }
    if (tex->desc().maxAnisotropy > 1.0f) {
      proto.kind = Candidate::Kind::Exempt;
      proto.why = Exempt::Unsupported;
      note("anisotropic filtering is not modelled: its pixels are exempt");
    }
  }
  proto.colorSum = b.colorSum;
  if (b.blend && proto.kind != Candidate::Kind::Exempt) {
    proto.kind = Candidate::Kind::Exempt;
    proto.why = Exempt::Blend;
  }
  const bool needLod = tex && (tex->mipmapped() || tex->desc().minFilter != tex->desc().magFilter);

  for (size_t i = 0; i + 2 < b.vertices.size(); i += 3) {
    std::vector<ClipVertex> tri(3);
    for (int k = 0; k < 3; ++k) {
      const ts::Vertex& vx = b.vertices[i + size_t(k)];
      tri[size_t(k)].clip = mvp * glm::dvec4(glm::dvec3(vx.pos), 1.0);
      // The texture matrix acts on (s,t,r,q) per vertex, before clipping and
      // interpolation, as GL's vertex stage does.
      const glm::dvec4 st = glm::dmat4(b.textureMatrix) * glm::dvec4(vx.tex);
      tri[size_t(k)].attr = {st.x, st.y, st.z, st.w, vx.color.r, vx.color.g, vx.color.b, vx.color.a,
                             vx.secondary.r, vx.secondary.g, vx.secondary.b};
    }
    std::vector<ClipVertex> poly = clipPolygon(tri);
    if (poly.size() < 3) continue;
    Poly P;
    P.bilinear = bilinear;
    P.st00 = {u0.x, u0.y}, P.st10 = {u0.z, u0.w}, P.st11 = {u1.x, u1.y}, P.st01 = {u1.z, u1.w};
    for (const ClipVertex& c : poly) {
      ScreenVertex s;
      double w = c.clip.w;
      glm::dvec3 ndc = glm::dvec3(c.clip) / w;
      s.x = p.viewport.x + (ndc.x + 1.0) * 0.5 * p.viewport.w;
      s.y = H - (glY + (ndc.y + 1.0) * 0.5 * p.viewport.h);
      double k = persp ? 1.0 / w : 1.0;
      for (int a = 0; a < kW; ++a) s.a[size_t(a)] = c.attr[size_t(a)] * k;
      s.a[kW] = k;
      s.a[kZ] = (ndc.z + 1.0) * 0.5;
      P.v.push_back(s);
    }
    // Signed area: orientation, and skip degenerate triangles.
    double area = 0;
    for (size_t k = 0; k < P.v.size(); ++k) {
      const ScreenVertex &a = P.v[k], &c = P.v[(k + 1) % P.v.size()];
      area += a.x * c.y - c.x * a.y;
    }
    if (!(std::abs(area) > 1e-9)) continue;
    P.orient = area > 0 ? 1.0 : -1.0;
    P.prepareEdges();
    // Planes from the first three vertices that span an area.
    bool ok = false;
    for (size_t k = 2; k < P.v.size() && !ok; ++k) {
      for (int a = 0; a < kAttributes; ++a) P.P[a] = planeThrough(P.v[0], P.v[1], P.v[k], a, &ok);
    }
    if (!ok) continue;
    P.constantDeriv = !bilinear && P.P[kQ].a == 0 && P.P[kQ].b == 0;

    // The LOD interval and the texels-per-pixel at a pixel centre.
    auto lodAt = [&](double x, double y, float* lo, float* hi, float* rho) {
      // Scale factors first, one log2 at the end.
      double l = 1e300, h = 0;
      auto add = [&](const Deriv& g) {
        double a, c;
        tex->rhoRange(g, opts_.lodModel, &a, &c);
        l = std::min(l, a), h = std::max(h, c);
      };
      auto lg = [](double r) { return r > 0 ? std::log2(r) : -1000.0; };
      Deriv g0 = P.deriv(x, y);
      double e0 = tex->lod(g0);
      *rho = float(std::exp2(std::max(-30.0, e0)));
      if (!needLod) {
        *lo = *hi = float(e0);
        return;
      }
      add(g0);
      if (!P.constantDeriv) {
        // An LOD per 2x2 quad may come from any quad holding this pixel and
        // be taken at any of its corners: the finite differences of all four
        // quads from each corner (besides the analytic LOD at the centre).
        double S[4][4], T[4][4];
        for (int j = 0; j < 4; ++j)
          for (int i = 0; i < 4; ++i) P.coord(x + i - 1, y + j - 1, &S[j][i], &T[j][i]);
        // S[j][i] is pixel (x - 1 + i, y - 1 + j); quads start at i, j in {0, 1}.
        for (int qy = 0; qy < 2; ++qy)
          for (int qx = 0; qx < 2; ++qx)
            for (int cy = 0; cy < 2; ++cy)
              for (int cx = 0; cx < 2; ++cx) {
                int bi = qx + cx, bj = qy + cy, oi = qx + 1 - cx, oj = qy + 1 - cy;
                double sgx = oi > bi ? 1 : -1, sgy = oj > bj ? 1 : -1;
                add({(S[bj][oi] - S[bj][bi]) * sgx, (S[oj][bi] - S[bj][bi]) * sgy, (T[bj][oi] - T[bj][bi]) * sgx,
                     (T[oj][bi] - T[bj][bi]) * sgy});
              }
      }
      *lo = float(lg(l) - opts_.lodMargin);
      *hi = float(lg(h) + opts_.lodMargin);
    };
    float constLo = 0, constHi = 0, constRho = 0;
    if (tex && P.constantDeriv) lodAt(P.v[0].x, P.v[0].y, &constLo, &constHi, &constRho);

    auto candidateAt = [&](double x, double y) {
      Candidate c = proto;
      c.z = float(P.P[kZ].at(x, y));
      c.colour = P.colour(x, y);
      if (c.colorSum) c.secondary = P.secondary(x, y);
      if (c.kind == Candidate::Kind::Textured) {
        P.coord(x, y, &c.s, &c.t);
        if (P.constantDeriv) c.lodLo = constLo, c.lodHi = constHi, c.rho = constRho;
        else lodAt(x, y, &c.lodLo, &c.lodHi, &c.rho);
      }
      return c;
    };

    // 1. The reference picture: the scanline rasterizer over the polygon's
    // fan, each centre textured at its exact coordinate and LOD.
    auto emit = [&](int x, int y, const double* a) {
      size_t idx = size_t(y) * size_t(width_) + size_t(x);
      float z = float(a[kZ]);
      if (p.depthTest && !(z < depth_[idx])) return;
      Colour out;
      Colour col{float(clamp01(a[kCr] / a[kW])), float(clamp01(a[kCg] / a[kW])), float(clamp01(a[kCb] / a[kW])),
                 float(clamp01(a[kCa] / a[kW]))};
      if (tex) {
        double s, t;
        P.coordFrom(a[kS] / a[kQ], a[kT] / a[kQ], &s, &t);
        Colour texel = tex->sample(s, t, tex->lod(P.deriv(x + 0.5, y + 0.5)));
        out = bilinear ? texel : texEnv(b.texEnv, col, texel, proto.envColour);
      } else {
        out = col;
      }
      if (b.colorSum)
        out = colourSum(out, {float(clamp01(a[kSr] / a[kW])), float(clamp01(a[kSg] / a[kW])),
                              float(clamp01(a[kSb] / a[kW])), 0.0f});
      if (b.blend) {
        Colour dst = toColour(image_.at(x, y));
        float al = out[3];
        for (size_t k = 0; k < 4; ++k) out[k] = out[k] * al + dst[k] * (1 - al);
      }
      image_.set(x, y, toRgba(out));
      if (p.depthTest) depth_[idx] = z;
    };
    for (size_t k = 1; k + 1 < P.v.size(); ++k) scanTriangle(P.v[0], P.v[k], P.v[k + 1], kAttributes, sc, opts_.fill, emit);

    // 2. The candidates: sure inside, either way within the edge band.
    double minx = 1e300, maxx = -1e300, miny = 1e300, maxy = -1e300;
    for (const auto& s : P.v) minx = std::min(minx, s.x), maxx = std::max(maxx, s.x), miny = std::min(miny, s.y), maxy = std::max(maxy, s.y);
    const double band = opts_.edgeBand;
    int x0 = std::max(sc.x0, int(std::floor(std::max(minx - band - 1, -1e9)))),
        x1 = std::min(sc.x1, int(std::ceil(std::min(maxx + band + 1, 1e9)))),
        y0 = std::max(sc.y0, int(std::floor(std::max(miny - band - 1, -1e9)))),
        y1 = std::min(sc.y1, int(std::ceil(std::min(maxy + band + 1, 1e9))));
    Candidate edgeExempt;
    edgeExempt.kind = Candidate::Kind::Exempt;
    edgeExempt.why = Exempt::Edge;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        double cx = x + 0.5, cy = y + 0.5;
        double d = P.edgeDistance(cx, cy);
        if (d < -band) continue;
        bool sure = d > band;
        if (!sure && opts_.edges == EdgePolicy::Exempt) {
          place(x, y, edgeExempt, false, false);
          continue;
        }
        place(x, y, candidateAt(cx, cy), sure, p.depthTest);
      }
  }
}

void Reference::drawLines(const ts::Panel& p, const ts::Batch& b, PixelRect sc) {
  const glm::dmat4 mvp = glm::dmat4(p.projection) * glm::dmat4(p.modelview);
  const double H = height_;
  const double glY = double(height_ - p.viewport.y - p.viewport.h);
  auto toWindow = [&](const glm::dvec4& c) {
    glm::dvec3 ndc = glm::dvec3(c) / c.w;
    return glm::dvec2(p.viewport.x + (ndc.x + 1.0) * 0.5 * p.viewport.w, H - (glY + (ndc.y + 1.0) * 0.5 * p.viewport.h));
  };
  std::vector<std::pair<size_t, size_t>> segs;
  size_t n = b.vertices.size();
  if (b.prim == ts::Prim::Lines)
    for (size_t i = 0; i + 1 < n; i += 2) segs.push_back({i, i + 1});
  if (b.prim == ts::Prim::LineStrip || b.prim == ts::Prim::LineLoop)
    for (size_t i = 0; i + 1 < n; ++i) segs.push_back({i, i + 1});
  if (b.prim == ts::Prim::LineLoop && n > 2) segs.push_back({n - 1, 0});
  Candidate ex;
  ex.kind = Candidate::Kind::Exempt;
  if (b.prim == ts::Prim::Points) {
    ex.why = Exempt::Point;
    double r = b.pointSize * 0.5 * std::sqrt(2.0) + opts_.lineMargin;
    for (const auto& v : b.vertices) {
      glm::dvec4 c = mvp * glm::dvec4(glm::dvec3(v.pos), 1.0);
      if (!(c.w > 0) || c.z < -c.w || c.z > c.w) continue;
      glm::dvec2 w = toWindow(c);
      exemptDisc(w.x, w.y, r, Exempt::Point, sc);
      // The reference picture: a square point.
      double h = b.pointSize * 0.5;
      for (int y = std::max(sc.y0, int(std::floor(w.y - h))); y < std::min(sc.y1, int(std::ceil(w.y + h))); ++y)
        for (int x = std::max(sc.x0, int(std::floor(w.x - h))); x < std::min(sc.x1, int(std::ceil(w.x + h))); ++x)
          image_.set(x, y, toRgba({v.color.r, v.color.g, v.color.b, v.color.a}));
    }
    return;
  }
  ex.why = Exempt::Line;
  const double half = std::max(0.5, double(b.lineWidth) * 0.5);
  const double r = half * std::sqrt(2.0) + opts_.lineMargin;
  for (auto [ia, ib] : segs) {
    const ts::Vertex &va = b.vertices[ia], &vb = b.vertices[ib];
    glm::dvec4 ca = mvp * glm::dvec4(glm::dvec3(va.pos), 1.0), cb = mvp * glm::dvec4(glm::dvec3(vb.pos), 1.0);
    // Clip the segment to the near/far planes.
    double t0 = 0, t1 = 1;
    bool visible = true;
    for (int k = 0; k < 3 && visible; ++k) {
      auto dist = [k](const glm::dvec4& c) { return k == 0 ? c.z + c.w : k == 1 ? c.w - c.z : c.w - 1e-12; };
      double da = dist(ca), db = dist(cb);
      if (da < 0 && db < 0) visible = false;
      else if (da < 0) t0 = std::max(t0, da / (da - db));
      else if (db < 0) t1 = std::min(t1, da / (da - db));
    }
    if (!visible || t0 > t1) continue;
    glm::dvec2 a = toWindow(ca + (cb - ca) * t0), c = toWindow(ca + (cb - ca) * t1);
    glm::dvec2 d = c - a;
    double len2 = glm::dot(d, d);
    int x0 = std::max(sc.x0, int(std::floor(std::min(a.x, c.x) - r))),
        x1 = std::min(sc.x1, int(std::ceil(std::max(a.x, c.x) + r)) + 1);
    int y0 = std::max(sc.y0, int(std::floor(std::min(a.y, c.y) - r))),
        y1 = std::min(sc.y1, int(std::ceil(std::max(a.y, c.y) + r)) + 1);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        glm::dvec2 q(x + 0.5, y + 0.5);
        double u = len2 > 0 ? std::clamp(glm::dot(q - a, d) / len2, 0.0, 1.0) : 0.0;
        double dist = glm::length(q - (a + d * u));
        if (dist > r) continue;
        place(x, y, ex, false, false);
        if (dist <= half) {
          glm::vec4 col = glm::mix(va.color, vb.color, float(u));
          image_.set(x, y, toRgba({col.r, col.g, col.b, col.a}));
        }
      }
  }
}

void Reference::drawLabels(const ts::Frame& f) {
  Candidate ex;
  ex.kind = Candidate::Kind::Exempt;
  ex.why = Exempt::Label;
  for (const ts::Label& l : f.labels) {
    PixelRect r = labelBox(l, 2, opts_.labelGeometryKnown);
    for (int y = std::max(0, r.y0); y < std::min(height_, r.y1); ++y)
      for (int x = std::max(0, r.x0); x < std::min(width_, r.x1); ++x) place(x, y, ex, false, false);
    if (!opts_.labelGeometryKnown) continue;
    // The reference picture: background box and text as render.cpp draws them.
    float w = ts::text::width(l.text, l.scale), h = ts::text::height(l.scale);
    float x = l.align == ts::Align::Left ? l.x : l.align == ts::Align::Center ? l.x - w / 2 : l.x - w;
    x = float(int(x));
    float y = float(int(l.y));
    if (l.background.a > 0) {
      float pad = 3.0f * float(l.scale);
      for (int py = std::max(0, int(y - pad)); py < std::min(height_, int(std::ceil(y + h + pad))); ++py)
        for (int px = std::max(0, int(x - pad)); px < std::min(width_, int(std::ceil(x + w + pad))); ++px) {
          Colour d = toColour(image_.at(px, py));
          Colour o;
          for (size_t k = 0; k < 4; ++k) o[k] = l.background[int(k)] * l.background.a + d[k] * (1 - l.background.a);
          image_.set(px, py, toRgba(o));
        }
    }
    ts::text::draw(image_, x, y, l.text, toRgba({l.color.r, l.color.g, l.color.b, l.color.a}), l.scale);
  }
}
}  // namespace ref
