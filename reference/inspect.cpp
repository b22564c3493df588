#include "inspect.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "combine.hpp"
#include "common/core/sidecar.hpp"  // ts::glEnumName

namespace ref {
namespace {
std::string enumName(GLenum e) { return ts::glEnumName(e); }

const char* primName(ts::Prim p) {
  switch (p) {
    case ts::Prim::Triangles: return "GL_TRIANGLES";
    case ts::Prim::Lines: return "GL_LINES";
    case ts::Prim::LineStrip: return "GL_LINE_STRIP";
    case ts::Prim::LineLoop: return "GL_LINE_LOOP";
    case ts::Prim::Points: return "GL_POINTS";
  }
  return "?";
}

// Whether the centre of pixel (x, y) is inside the clipped polygon: the
// reference draws it as the fan (v0, vk, vk+1), each with raster.hpp's rule.
bool covers(const ScreenPoly& P, int x, int y, FillRule rule) {
  for (size_t k = 1; k + 1 < P.v.size(); ++k)
    if (coversCentre(P.v[0], P.v[k], P.v[k + 1], x, y, rule)) return true;
  return false;
}

// The blend render.cpp sets: source alpha, one minus source alpha (on all
// four channels, as Reference computes it), over the 8-bit colour beneath.
Colour blendOver(const Colour& src, ts::Rgba beneath) {
  Colour dst = toColour(beneath), out = src;
  float a = src[3];
  for (size_t k = 0; k < 4; ++k) out[k] = src[k] * a + dst[k] * (1 - a);
  return out;
}

bool inside(const PixelRect& r, int x, int y) { return x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1; }
}  // namespace

Inspector::Inspector(const ts::Frame& frame, const RenderOptions& options)
    : frame_(frame), opts_(options), textures_(frame.textures.size()), textureErrors_(frame.textures.size()) {}

Inspector::~Inspector() = default;

const Texture* Inspector::texture(int index, std::string* why) const {
  if (index < 0 || size_t(index) >= frame_.textures.size()) {
    *why = "texture index " + std::to_string(index) + " is not in the frame";
    return nullptr;
  }
  auto& slot = textures_[size_t(index)];
  std::string& error = textureErrors_[size_t(index)];
  if (!slot && error.empty()) {
    try {
      slot = std::make_unique<Texture>(frame_.textures[size_t(index)]);
    } catch (const std::exception& e) {  // e.g. a live view: GL renders it, the CPU has no texels
      error = e.what();
    }
  }
  *why = error;
  return slot.get();
}

const Volume* Inspector::volume(int index) const {
  if (index < 0 || size_t(index) >= frame_.textures.size()) return nullptr;
  const ts::TextureDesc& d = frame_.textures[size_t(index)];
  if (d.depth <= 1 || !d.image || d.image->height % d.depth != 0) return nullptr;
  std::unique_ptr<Slices>& v = volumes_[index];
  if (!v) {
    // The slices stacked in the image (slice k in rows k h ..), each a plain 2D texture, as Reference makes them.
    v = std::make_unique<Slices>();
    const int w = d.image->width, h = d.image->height / d.depth;
    for (int k = 0; k < d.depth; ++k) {
      ts::TextureDesc sd = d;
      sd.depth = 1, sd.mipmaps = false, sd.mipLevels = nullptr;
      auto img = std::make_shared<ts::Image>(w, h);
      std::copy_n(d.image->pixels.begin() + std::ptrdiff_t(size_t(k) * size_t(w) * size_t(h) * 4),
                  size_t(w) * size_t(h) * 4, img->pixels.begin());
      sd.image = img;
      sd.name += "[slice " + std::to_string(k) + "]";
      v->slices.emplace_back(sd);
    }
    v->volume.textures = &v->slices, v->volume.first = 0, v->volume.depth = d.depth, v->volume.wrapR = d.wrapR;
  }
  return &v->volume;
}

Inspection Inspector::fragment(int x, int y, int pi, int bi, const ScreenPoly& P) const {
  const ts::Panel& p = frame_.panels[size_t(pi)];
  const ts::Batch& b = p.batches[size_t(bi)];
  const double cx = x + 0.5, cy = y + 0.5;  // GL samples attributes at the pixel centre
  Inspection in;
  in.x = x, in.y = y;
  in.what = Inspection::What::Triangle;
  in.panel = pi, in.batch = bi;
  in.panelName = p.id, in.batchRole = b.role;
  in.program = !b.program.empty();
  in.z = P.P[kZ].at(cx, cy);
  in.primary = P.colour(cx, cy);
  in.secondary = P.secondary(cx, cy);
  // Each attribute's plane holds a/w; dividing by the plane of 1/w gives a.
  const double invW = P.P[kW].at(cx, cy);
  in.s = P.P[kS].at(cx, cy) / invW, in.t = P.P[kT].at(cx, cy) / invW;
  in.r = P.P[kR].at(cx, cy) / invW, in.q = P.P[kQ].at(cx, cy) / invW;
  in.sq = in.s / in.q, in.tq = in.t / in.q;  // (with a texture: from the planes below, the same value)

  std::vector<std::string> notes;
  const bool modelledProgram = b.program.empty() || P.bilinear;
  const Texture* tex = nullptr;
  Deriv g;  // d(s/q)/dx, d(s/q)/dy, d(t/q)/dx, d(t/q)/dy
  if (b.texture >= 0) {
    std::string why;
    tex = texture(b.texture, &why);
    if (!tex) notes.push_back(why + ": its texels are unknown here");
  }
  if (!b.program.empty() && !P.bilinear)
    notes.push_back("GLSL program '" + b.program +
                    "': the texture lookup is the shader's. (s,t,r,q) are the interpolated vertex texture "
                    "coordinates it receives, not necessarily what it samples; its filter, LOD and texels are "
                    "not shown. The reference draws the vertex colour here (the verifier exempts these pixels)");
  if (P.bilinear)
    notes.push_back("GLSL program 'bilinear_quad': (s/q, t/q) is the shader's bilinear map of the interpolated "
                    "(s/q, t/q) onto the corners st00, st10, st11, st01 (its uniforms), and the shader's "
                    "texture2D() looks it up with the texture's own filter (shown); its colour is the texel");
  if (b.texture < 0 && b.program.empty())
    notes.push_back(std::string("untextured batch: the colour is the interpolated vertex colour") +
                    (b.colorSum ? " plus the secondary colour" : ""));

  if (tex) {
    const ts::TextureDesc& d = tex->desc();
    in.texture = b.texture, in.textureName = d.name;
    in.width0 = tex->width(0), in.height0 = tex->height(0);
    in.minFilter = d.minFilter, in.magFilter = d.magFilter;
    in.texEnv = P.bilinear ? 0 : b.texEnv;
    const double w0 = in.width0, h0 = in.height0;
    P.coord(cx, cy, &in.sq, &in.tq);  // (the bilinear program's map, if any)
    in.u = in.sq * w0, in.v = in.tq * h0;
    // d(s/q)/dx = ((s/w)_x (q/w) - (s/w) (q/w)_x) / (q/w)^2, and so on
    // (ScreenPoly::deriv), scaled to texels of level 0.
    g = P.deriv(cx, cy);
    in.dudx = g.dsdx * w0, in.dvdx = g.dtdx * h0, in.dudy = g.dsdy * w0, in.dvdy = g.dtdy * h0;
    // The footprint in texture space.
    const double corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (size_t k = 0; k < 4; ++k) {
      double a, c;
      P.coord(x + corner[k][0], y + corner[k][1], &a, &c);
      in.preimage[k] = {a * w0, c * h0};
      const glm::dvec2 ex(in.dudx, in.dvdx), ey(in.dudy, in.dvdy);
      in.parallelogram[k] = glm::dvec2(in.u, in.v) + (corner[k][0] - 0.5) * ex + (corner[k][1] - 0.5) * ey;
    }
    const double Ux = in.dudx, Vx = in.dvdx, Uy = in.dudy, Vy = in.dvdy;
    in.ewaA = Vx * Vx + Vy * Vy;
    in.ewaB = -2 * (Ux * Vx + Uy * Vy);
    in.ewaC = Ux * Ux + Uy * Uy;
    in.ewaF = (Ux * Vy - Uy * Vx) * (Ux * Vy - Uy * Vx);
  }

  Colour texel{};
  in.textured = tex && modelledProgram;
  if (in.textured) {
    const ts::TextureDesc& d = tex->desc();
    // rho both ways (sampler.hpp): Bounded spans max-abs .. GL's exact formula.
    tex->rhoRange(g, LodModel::Bounded, &in.rhoMax, &in.rhoEdge);
    in.lambdaBase = tex->lod(g);  // log2(rhoEdge), as Reference samples
    in.bias = d.lodBias;
    const Footprint fp = tex->footprint(in.sq, in.tq, in.lambdaBase);
    in.lambda = fp.lambda;
    in.magnified = fp.magnified;
    in.filter = fp.filter;
    in.level0 = fp.level0, in.level1 = fp.level1, in.levelWeight = fp.levelWeight;
    in.texels.assign(fp.texels.begin(), fp.texels.begin() + fp.count);
    in.filtered = texel = fp.value();
    if (const Volume* v = volume(b.texture)) {
      // A 3D texture (GL_TEXTURE_3D): read at (s, t, r) through its slices, as Reference does (volume.hpp), its
      // level of detail from a slice's size; the footprint above takes the stacked slices for one 2D image.
      in.filtered = texel = v->sample(in.sq, in.tq, in.r / in.q, v->slice(0).lod(g));
      notes.push_back("3D texture of " + std::to_string(d.depth) +
                      " slices: the colour is read at (s, t, r) through them; the texels listed are of the slices "
                      "stacked as one 2D image");
    }
    if (d.maxAnisotropy > 1.0f)
      notes.push_back("anisotropic filtering (up to " + std::to_string(int(d.maxAnisotropy)) +
                      "x): GL may read more texels along the footprint's long axis; shown is the isotropic filter "
                      "the reference draws (the verifier exempts these pixels)");
    if (!P.bilinear && !texEnvModelled(b.texEnv))
      notes.push_back("texture environment " + enumName(b.texEnv) + " is not modelled: the colour is the texel");
  }
  in.referenceRgba = shadeFragment(b, in.primary, in.secondary, in.textured ? &texel : nullptr);
  // Unit 1 at its own (s, t), over unit 0's result, then the colour sum.
  std::string why1;
  const Texture* tex1 = in.textured && b.texture1 >= 0 && unitEnvModelled(b.texEnv1, b.combine1)
                            ? texture(b.texture1, &why1)
                            : nullptr;
  if (tex1) {
    double s1, t1;  // unit 1's own coordinates (its texture matrix, Vertex::tex1 where Batch::coords1)
    P.coord1(cx, cy, &s1, &t1);
    const Colour texel1 = tex1->sample(s1, t1, tex1->lod(P.deriv1(cx, cy)));
    const Colour prev = texEnv(b.texEnv, in.primary, texel, {b.envColor.r, b.envColor.g, b.envColor.b, b.envColor.a});
    in.referenceRgba = unitEnv(b.texEnv1, b.combine1, prev, texel1, in.primary);
    if (b.colorSum) in.referenceRgba = colourSum(in.referenceRgba, in.secondary);
    notes.push_back(
        "unit 1: texture " + std::to_string(b.texture1) + " '" + tex1->desc().name + "' by " + enumName(b.texEnv1) +
        (b.texEnv1 == GL_COMBINE ? " (" + enumName(b.combine1.rgb) + ")" : std::string()) + " over unit 0's result");
  }
  if (b.alphaTest())
    notes.push_back("alpha test " + enumName(b.alphaFunc) + " " + std::to_string(b.alphaRef) +
                    (alphaPasses(b.alphaFunc, in.referenceRgba[3], b.alphaRef) ? ": passes"
                                                                               : ": fails, the fragment is discarded"));
  if (b.blend && b.blendFactors())
    notes.push_back("blended (" + enumName(b.blendSrc) + ", " + enumName(b.blendDst) + ") with the colour beneath");
  else if (b.blend)
    notes.push_back("blended (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) over the colour beneath: the pixel is "
                    "alpha times this colour plus (1 - alpha) times what was there");
  for (const std::string& n : notes) in.note += (in.note.empty() ? "" : "; ") + n;
  return in;
}

Inspection Inspector::at(int x, int y) const {
  const ts::Frame& f = frame_;
  const bool persp = opts_.interpolation == Interpolation::Perspective;
  // The pixel as the reference image holds it (8-bit), and its depth.
  ts::Rgba pixel = toRgba(clampedColour(f.clearColor));
  float depth = 1.0f;
  auto background = [&](int panel, const std::string& whose) {
    Inspection b;
    b.x = x, b.y = y;
    b.panel = panel;
    if (panel >= 0) b.panelName = f.panels[size_t(panel)].id;
    b.note = "background: no batch covers this pixel (" + whose + ")";
    b.referenceRgba = b.pixelRgba = toColour(pixel);
    return b;
  };
  Inspection top = background(-1, "the frame's clear colour");

  for (size_t pi = 0; pi < f.panels.size(); ++pi) {
    const ts::Panel& p = f.panels[pi];
    if (!inside(scissorRect(p, f.width, f.height), x, y)) continue;
    if (top.what == Inspection::What::Background) top.panel = int(pi), top.panelName = p.id;
    if (p.clear) {
      pixel = toRgba(clampedColour(p.clearColor));
      depth = 1.0f;
      top = background(int(pi), "panel '" + p.id + "' cleared to its colour");
    }
    for (size_t bi = 0; bi < p.batches.size(); ++bi) {
      const ts::Batch& b = p.batches[bi];
      if (b.prim == ts::Prim::Triangles) {
        for (size_t i = 0; i + 2 < b.vertices.size(); i += 3) {
          ScreenPoly P;
          if (!screenTriangle(p, b, i, f.height, persp, &P) || !covers(P, x, y, opts_.fill)) continue;
          // GL_LESS against the depth buffer (window z, as a float like the reference's buffer).
          float z = float(P.P[kZ].at(x + 0.5, y + 0.5));
          if (p.depthTest && !(z < depth)) continue;
          Inspection in = fragment(x, y, int(pi), int(bi), P);
          if (b.alphaTest() && !alphaPasses(b.alphaFunc, in.referenceRgba[3], b.alphaRef)) continue;  // discarded
          if (b.blend && b.blendFactors())  // the batch's own factors
            pixel = toRgba(blendWith(b.blendSrc, b.blendDst, in.referenceRgba, toColour(pixel)));
          else pixel = toRgba(b.blend ? blendOver(in.referenceRgba, pixel) : in.referenceRgba);
          in.pixelRgba = toColour(pixel);
          if (p.depthTest) depth = z;
          top = std::move(in);
        }
        continue;
      }
      // Lines and points: drawn over what is there, untextured, no depth test.
      Inspection in;
      in.x = x, in.y = y;
      in.panel = int(pi), in.batch = int(bi);
      in.panelName = p.id, in.batchRole = b.role;
      bool hit = false;
      glm::vec4 colour(0.0f);
      if (b.prim == ts::Prim::Points) {
        for (const ts::Vertex& v : b.vertices) {
          glm::dvec2 w;
          if (windowPoint(p, v, f.height, &w) && inside(pointSquare(w, b.pointSize), x, y))
            hit = true, colour = v.color;
        }
        in.what = Inspection::What::Point;
        in.note = "point batch (size " + std::to_string(int(b.pointSize)) +
                  "): untextured, a square of the vertex colour drawn over what is beneath";
      } else {
        const double half = lineHalfWidth(b);
        for (const WindowSegment& seg : windowSegments(p, b, f.height)) {
          double u;
          if (segmentDistance(seg, glm::dvec2(x + 0.5, y + 0.5), &u) <= half) {
            hit = true;
            colour = glm::mix(b.vertices[seg.ia].color, b.vertices[seg.ib].color, float(u));
          }
        }
        in.what = Inspection::What::Line;
        char w[32];
        std::snprintf(w, sizeof w, "%g", double(b.lineWidth));
        in.note = std::string("line batch (") + primName(b.prim) + ", width " + w +
                  "): untextured, its vertex colours mixed along the segment, drawn over what is beneath";
      }
      if (!hit) continue;
      in.referenceRgba = {colour.r, colour.g, colour.b, colour.a};
      pixel = toRgba(in.referenceRgba);
      in.pixelRgba = toColour(pixel);
      top = std::move(in);
    }
  }

  // Labels: drawn over the frame after every panel.
  if (opts_.labels && opts_.labelGeometryKnown) {
    for (const ts::Label& l : f.labels) {
      ts::Image one(1, 1, pixel);
      paintLabel(one, l, x, y);
      if (one.at(0, 0) == pixel) {
        if (inside(labelBox(l, 0, true), x, y))
          top.note += (top.note.empty() ? "" : "; ") + std::string("inside the box of label \"") + l.text +
                      "\", which leaves this pixel unchanged";
        continue;
      }
      pixel = one.at(0, 0);
      Inspection in;
      in.x = x, in.y = y;
      in.what = Inspection::What::Label;
      in.batchRole = "label";
      in.note = "label \"" + l.text +
                "\": drawn over the frame after every panel (its background box, then its "
                "glyphs), untextured";
      in.referenceRgba = in.pixelRgba = toColour(pixel);
      top = std::move(in);
    }
  }
  return top;
}

Inspection inspect(const ts::Frame& f, int x, int y, const RenderOptions& options) {
  return Inspector(f, options).at(x, y);
}

namespace {
std::string fmt(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string fmt(const char* format, ...) {
  char buf[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  return buf;
}

std::string bytes(const Colour& c) {
  ts::Rgba b = toRgba(c);
  return fmt("(%d, %d, %d, %d)", b.r, b.g, b.b, b.a);
}

const char* whatName(Inspection::What w) {
  switch (w) {
    case Inspection::What::Background: return "background";
    case Inspection::What::Triangle: return "triangles";
    case Inspection::What::Line: return "lines";
    case Inspection::What::Point: return "points";
    case Inspection::What::Label: return "label";
  }
  return "?";
}
}  // namespace

std::string formatInspection(const Inspection& in) {
  std::string o = fmt("pixel (%d, %d)", in.x, in.y);
  if (in.panel >= 0) o += fmt("  panel %d '%s'", in.panel, in.panelName.c_str());
  if (in.batch >= 0) o += fmt("  batch %d '%s'", in.batch, in.batchRole.c_str());
  o += fmt("  [%s%s%s]\n", whatName(in.what), in.textured ? ", textured" : "", in.program ? ", GLSL program" : "");
  if (!in.note.empty()) o += "note: " + in.note + "\n";
  if (in.what == Inspection::What::Triangle)
    o += fmt("depth z      = %.6f   vertex colour %s\n", in.z, bytes(in.primary).c_str());
  if (in.what == Inspection::What::Triangle && (in.texture >= 0 || in.program)) {
    o += fmt("(s,t,r,q)    = (%.6f, %.6f, %.6f, %.6f)\n", in.s, in.t, in.r, in.q);
    o += fmt("(s/q,t/q)    = (%.6f, %.6f)\n", in.sq, in.tq);
  }
  if (in.texture >= 0) {
    o += fmt("texture %d '%s' %dx%d, min %s, mag %s%s%s\n", in.texture, in.textureName.c_str(), in.width0, in.height0,
             enumName(in.minFilter).c_str(), enumName(in.magFilter).c_str(), in.texEnv ? ", env " : "",
             in.texEnv ? enumName(in.texEnv).c_str() : "");
    o += fmt("(u,v)        = (%.4f, %.4f) texels of level 0\n", in.u, in.v);
    o += fmt("du/dx, dv/dx = (%.6f, %.6f)   du/dy, dv/dy = (%.6f, %.6f)\n", in.dudx, in.dvdx, in.dudy, in.dvdy);
  }
  if (in.textured) {
    o += fmt("rho          = %.6f  max(|(du/dx,dv/dx)|, |(du/dy,dv/dy)|) (GL)\n", in.rhoEdge);
    o += fmt("               %.6f  max(|du/dx|, |dv/dx|, |du/dy|, |dv/dy|)\n", in.rhoMax);
    o += fmt("lambda       = log2(rho) %+.6f  + bias %g = %+.6f  (clamped to [-1000, 1000])\n", in.lambdaBase, in.bias,
             in.lambda);
    if (in.magnified) o += fmt("filter       magnified (lambda <= 0): %s on level 0\n", enumName(in.filter).c_str());
    else if (in.level1 != in.level0)
      o += fmt("filter       minified: %s on levels %d and %d, weight of level %d = %.6f\n",
               enumName(in.filter).c_str(), in.level0, in.level1, in.level1, in.levelWeight);
    else o += fmt("filter       minified: %s on level %d\n", enumName(in.filter).c_str(), in.level0);
    o += "texels       level    i    j   weight    rgba\n";
    for (const InspectTexel& t : in.texels)
      o += fmt("             %5d %4d %4d %8.6f  %s\n", t.level, t.i, t.j, t.weight, bytes(t.rgba).c_str());
    o += "filtered     " + bytes(in.filtered) + "  (sum of weight x rgba)\n";
  }
  o += "reference    " + bytes(in.referenceRgba);
  if (in.textured && in.texEnv) o += "  (" + enumName(in.texEnv) + " with the vertex colour)";
  o += "\n";
  if (toRgba(in.pixelRgba) != toRgba(in.referenceRgba)) o += "pixel        " + bytes(in.pixelRgba) + "\n";
  if (in.texture >= 0) {
    // The footprint, corners in the order (x, y), (x+1, y), (x+1, y+1), (x, y+1).
    o += "footprint in texels of level 0:\n  pixel square ";
    for (const auto& c : in.preimage) o += fmt(" (%.3f, %.3f)", c.x, c.y);
    o += "\n  derivatives  ";
    for (const auto& c : in.parallelogram) o += fmt(" (%.3f, %.3f)", c.x, c.y);
    o += fmt("\n  EWA ellipse   %.6g du^2 %+.6g du dv %+.6g dv^2 = %.6g around (u,v)\n", in.ewaA, in.ewaB, in.ewaC,
             in.ewaF);
  }
  return o;
}

nlohmann::json inspectionJson(const Inspection& in) {
  // NaN (not applicable) as null.
  auto num = [](double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); };
  auto rgba = [](const Colour& c) { return nlohmann::json::array({c[0], c[1], c[2], c[3]}); };
  nlohmann::json j;
  j["pixel"] = {in.x, in.y};
  j["panel"] = in.panel;
  j["batch"] = in.batch;
  j["st"] = {num(in.sq), num(in.tq)};
  j["stq"] = {num(in.s), num(in.t), num(in.r), num(in.q)};
  j["uv"] = {num(in.u), num(in.v)};
  j["derivatives"] = {num(in.dudx), num(in.dvdx), num(in.dudy), num(in.dvdy)};
  j["rho_edge"] = num(in.rhoEdge);
  j["rho_max"] = num(in.rhoMax);
  j["lambda"] = num(in.lambda);
  j["levels"] = in.textured ? nlohmann::json{in.level0, in.level1} : nlohmann::json(nullptr);
  j["level_weight"] = in.textured ? nlohmann::json(in.levelWeight) : nlohmann::json(nullptr);
  j["texels"] = nlohmann::json::array();
  for (const InspectTexel& t : in.texels)
    j["texels"].push_back({{"level", t.level}, {"i", t.i}, {"j", t.j}, {"weight", t.weight}, {"rgba", rgba(t.rgba)}});
  j["reference_rgba"] = rgba(in.referenceRgba);
  return j;
}
}  // namespace ref
