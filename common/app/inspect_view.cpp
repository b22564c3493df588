// common/app/inspect_view.cpp — see inspect_view.hpp.
#include "common/app/inspect_view.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "common/core/error.hpp"
#include "common/core/layout.hpp"
#include "common/core/textures.hpp"
#include "common/gl/figure.hpp"
#include "common/gl/gl_listing.hpp"
#include "common/gl/render.hpp"

namespace ts {
namespace L = layout;

void checkPixels(const std::vector<std::array<int, 2>>& pixels, int w, int h) {
  for (const auto& p : pixels)
    if (p[0] < 0 || p[1] < 0 || p[0] >= w || p[1] >= h)
      throw Error("--inspect " + std::to_string(p[0]) + "," + std::to_string(p[1]) + ": outside the " +
                  std::to_string(w) + "x" + std::to_string(h) + " image (X 0.." + std::to_string(w - 1) + ", Y 0.." +
                  std::to_string(h - 1) + ", 0,0 = top left)");
}

std::vector<Picked> inspectPixels(const Frame& frame, const Image& drawn, const std::vector<std::array<int, 2>>& pixels) {
  ref::Inspector inspector(frame);  // each texture's levels made once for all the pixels
  std::vector<Picked> out;
  for (const auto& p : pixels) out.push_back({inspector.at(p[0], p[1]), drawn.at(p[0], p[1])});
  return out;
}

std::string inspectCard(const Picked& p) {
  const Rgba ref = ref::toRgba(p.in.pixelRgba);
  char line[200];
  std::snprintf(line, sizeof line,
                "GL drew       (%3d, %3d, %3d, %3d)\nreference     (%3d, %3d, %3d, %3d)\ndifference    (%+4d, %+4d, "
                "%+4d, %+4d) 8-bit steps\n",
                p.gl.r, p.gl.g, p.gl.b, p.gl.a, ref.r, ref.g, ref.b, ref.a, int(p.gl.r) - ref.r, int(p.gl.g) - ref.g,
                int(p.gl.b) - ref.b, int(p.gl.a) - ref.a);
  return ref::formatInspection(p.in) + line;
}

std::string inspectJson(const Picked& p) {
  nlohmann::json j = ref::inspectionJson(p.in);
  j["gl_rgba"] = {p.gl.r / 255.0, p.gl.g / 255.0, p.gl.b / 255.0, p.gl.a / 255.0};
  return j.dump();
}

namespace {
const glm::vec4 kPreimage{1.0f, 1.0f, 1.0f, 1.0f}, kParallelogram{0.2f, 0.9f, 1.0f, 1.0f},
    kEllipse{1.0f, 0.3f, 0.9f, 1.0f}, kLodSquare{1.0f, 0.85f, 0.2f, 1.0f}, kTexels{1.0f, 0.55f, 0.1f, 1.0f};

bool usable(const ref::Inspection& in) { return in.textured && in.texture >= 0 && std::isfinite(in.u); }

// Where a texel read lies in level 0's texels (its lower-left corner): (i, j)
// are after wrapping, so under GL_REPEAT the copy nearest the footprint.
glm::dvec2 texelCorner(const ref::Inspection& in, const Frame& picture, const ref::InspectTexel& t) {
  const double size = std::exp2(t.level);
  glm::dvec2 a(t.i * size, t.j * size);
  const TextureDesc& d = picture.textures[size_t(in.texture)];
  if (d.wrapS == GL_REPEAT) a.x += std::round((in.u - a.x) / in.width0) * in.width0;
  if (d.wrapT == GL_REPEAT) a.y += std::round((in.v - a.y) / in.height0) * in.height0;
  return a;
}

// The region a footprint cell shows: the footprint's bounding box (preimage,
// ellipse, texels read, the 2^lambda square), at least 4 texels, with a
// margin; centre and extent in texels of level 0.
void cellRegion(const Frame& picture, const ref::Inspection& in, double* cu, double* cv, double* extent) {
  const double side = std::exp2(std::max(0.0, in.lambda));
  double u0 = in.u - side / 2, u1 = in.u + side / 2, v0 = in.v - side / 2, v1 = in.v + side / 2;
  auto grow = [&](glm::dvec2 p) { u0 = std::min(u0, p.x), u1 = std::max(u1, p.x), v0 = std::min(v0, p.y), v1 = std::max(v1, p.y); };
  for (const glm::dvec2& p : in.preimage) grow(p);
  for (const glm::dvec2& p : in.parallelogram) grow(p);
  const double eu = std::hypot(in.dudx, in.dudy), ev = std::hypot(in.dvdx, in.dvdy);  // the ellipse's half extents
  grow({in.u - eu, in.v - ev}), grow({in.u + eu, in.v + ev});
  for (const ref::InspectTexel& t : in.texels) {
    const glm::dvec2 a = texelCorner(in, picture, t);
    grow(a), grow(a + std::exp2(t.level));
  }
  *extent = std::max({u1 - u0, v1 - v0, 4.0}) * 1.25, *cu = (u0 + u1) / 2, *cv = (v0 + v1) / 2;
}

// The cell's panel in `view`: level 0 texel by texel around the footprint
// (GL_NEAREST, the texture's own wrap modes), its texel grid when the texels
// are large enough to see, then the footprint (footprintBatches).
Panel cellPanel(Frame& f, const Frame& picture, const ref::Inspection& in, int number, const Rect& view) {
  double cu = 0, cv = 0, extent = 0;
  cellRegion(picture, in, &cu, &cv, &extent);
  const double aspect = double(view.w) / double(view.h);
  const double halfU = extent / 2 * std::max(1.0, aspect), halfV = extent / 2 * std::max(1.0, 1.0 / aspect);
  Panel p;
  p.id = "footprint_" + std::to_string(number);
  p.viewport = view;
  p.projection = glm::ortho(float(cu - halfU), float(cu + halfU), float(cv - halfV), float(cv + halfV), -1.0f, 1.0f);
  // Level 0 texel by texel: the quad's (s, t) = (u / w0, v / h0), the texture's own wrap modes.
  TextureDesc tex = picture.textures[size_t(in.texture)];
  tex.minFilter = tex.magFilter = GL_NEAREST;
  tex.mipmaps = false, tex.mipLevels = nullptr, tex.lodBias = 0, tex.maxAnisotropy = 1;
  Batch quad;
  quad.role = "texture";
  quad.texture = f.addTexture(tex);
  const float x0 = float(cu - halfU), x1 = float(cu + halfU), y0 = float(cv - halfV), y1 = float(cv + halfV);
  const float w0 = float(in.width0), h0 = float(in.height0);
  for (glm::vec2 c : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y0), glm::vec2(x1, y1),
                      glm::vec2(x0, y1)})
    quad.vertices.push_back({glm::vec3(c, 0.0f), glm::vec4(c.x / w0, c.y / h0, 0.0f, 1.0f), glm::vec4(1.0f)});
  p.batches.push_back(quad);
  if (halfU <= 48 && halfV <= 48) {  // the texel grid of level 0, faint
    std::vector<glm::vec2> grid;
    for (double u = std::ceil(cu - halfU); u <= cu + halfU; ++u) grid.push_back({float(u), y0}), grid.push_back({float(u), y1});
    for (double v = std::ceil(cv - halfV); v <= cv + halfV; ++v) grid.push_back({x0, float(v)}), grid.push_back({x1, float(v)});
    p.batches.push_back(lineSegments(grid, glm::vec4(0.42f, 0.42f, 0.47f, 1.0f), 1.0f, "texel_grid"));
  }
  for (Batch& b : footprintBatches(picture, in)) p.batches.push_back(std::move(b));
  return p;
}

// One cell: the texture around pick `in`, in texels of level 0 (u right,
// v up: t = 0 is the texture's row 0), with the footprint drawn over it.
void addCell(Frame& f, const Frame& picture, const ref::Inspection& in, int number, const Rect& area, int scale) {
  const int line = int(L::lineHeight(scale));
  const Rect view{area.x, area.y + line, area.w, std::max(1, area.h - 3 * line)};
  f.panels.push_back(cellPanel(f, picture, in, number, view));
  L::caption(f, {float(area.x), float(area.y), float(area.x + area.w), float(area.y + line)},
             std::to_string(number) + ": lambda " + L::fmt("%.2f", in.lambda) + ", rho " + L::fmt("%.2f", in.rhoEdge),
             L::kAmber, scale);
  L::caption(f, {float(area.x), float(view.y + view.h + 2), float(area.x + area.w), float(area.y + area.h)},
             "(u,v) = (" + L::fmt("%.1f", in.u) + ", " + L::fmt("%.1f", in.v) + "), level " +
                 std::to_string(in.level0) + (in.level1 != in.level0 ? "+" + std::to_string(in.level1) : "") + ", " +
                 std::to_string(in.texels.size()) + " texels",
             L::kWhite, scale);
}

// The affine map from a batch's (s, t) to its object coordinates, when one
// map fits every vertex (a texture drawn flat: a texture-space view), with
// q = 1 throughout.
bool flatTextureMap(const Batch& b, glm::dmat3* st2pos) {
  if (b.prim != Prim::Triangles || b.vertices.size() < 3) return false;
  const Vertex &a = b.vertices[0], &c1 = b.vertices[1], &c2 = b.vertices[2];
  const glm::dvec2 s0(a.tex), s1(c1.tex), s2(c2.tex), p0(a.pos), p1(c1.pos), p2(c2.pos);
  const glm::dmat2 S(s1 - s0, s2 - s0), P(p1 - p0, p2 - p0);
  if (std::abs(glm::determinant(S)) < 1e-12) return false;
  const glm::dmat2 M = P * glm::inverse(S);
  const glm::dvec2 off = p0 - M * s0;
  for (const Vertex& v : b.vertices) {
    if (v.tex.w != 1.0f || v.pos.z != 0.0f) return false;
    const glm::dvec2 want = M * glm::dvec2(v.tex) + off;
    if (glm::length(want - glm::dvec2(v.pos)) > 1e-4 * (1 + glm::length(glm::dvec2(v.pos)))) return false;
  }
  *st2pos = glm::dmat3(glm::dvec3(M[0], 0), glm::dvec3(M[1], 0), glm::dvec3(off, 1));
  return true;
}
}  // namespace

std::vector<Batch> footprintBatches(const Frame& picture, const ref::Inspection& in) {
  std::vector<Batch> out;
  auto loop = [&](const std::vector<glm::vec2>& pts, glm::vec4 colour, float width, const char* role) {
    out.push_back(lineLoop(pts, colour, width, role));
  };
  for (const ref::InspectTexel& t : in.texels) {  // the texels read, at their level's size
    const glm::dvec2 corner = texelCorner(in, picture, t);
    const float size = float(std::exp2(t.level)), a = float(corner.x), b = float(corner.y);
    loop({{a, b}, {a + size, b}, {a + size, b + size}, {a, b + size}}, kTexels, 2.0f, "texel_read");
  }
  const float hs = float(std::exp2(std::max(0.0, in.lambda)) / 2);
  loop({{float(in.u) - hs, float(in.v) - hs}, {float(in.u) + hs, float(in.v) - hs}, {float(in.u) + hs, float(in.v) + hs},
        {float(in.u) - hs, float(in.v) + hs}},
       kLodSquare, 1.0f, "lod_square");
  std::vector<glm::vec2> pts;
  for (const glm::dvec2& c : in.parallelogram) pts.push_back(glm::vec2(c));
  loop(pts, kParallelogram, 1.0f, "derivative_parallelogram");
  // The EWA ellipse is the image of the unit circle of screen space under
  // the Jacobian [du/dx du/dy; dv/dx dv/dy]: A du^2 + B du dv + C dv^2 = F.
  pts.clear();
  for (int k = 0; k < 64; ++k) {
    const double a = 2 * M_PI * k / 64, cx = std::cos(a), cy = std::sin(a);
    pts.push_back({float(in.u + in.dudx * cx + in.dudy * cy), float(in.v + in.dvdx * cx + in.dvdy * cy)});
  }
  loop(pts, kEllipse, 1.0f, "ewa_ellipse");
  pts.clear();
  for (const glm::dvec2& c : in.preimage) pts.push_back(glm::vec2(c));
  loop(pts, kPreimage, 2.0f, "preimage");
  return out;
}

Frame footprintCell(const Frame& picture, const ref::Inspection& in, int w, int h) {
  Frame f = L::blankFrame(w, h);
  if (usable(in)) f.panels.push_back(cellPanel(f, picture, in, 1, {0, 0, w, h}));
  return f;
}

bool footprintInTextureViews(const Frame& picture, const ref::Inspection& in, Frame* over) {
  *over = L::blankFrame(picture.width, picture.height);
  if (!usable(in)) return false;
  const TextureDesc& shown = picture.textures[size_t(in.texture)];
  const std::vector<Batch> lines = footprintBatches(picture, in);
  for (size_t k = 0; k < picture.panels.size(); ++k) {
    const Panel& p = picture.panels[k];
    if (int(k) == in.panel) continue;  // the picked pixel's own view: never drawn over
    for (const Batch& b : p.batches) {
      glm::dmat3 st2pos;
      // The same texture: made the same way (its filters may differ).
      if (b.role != "texture" || b.texture < 0 || picture.textures[size_t(b.texture)].name != shown.name ||
          picture.textures[size_t(b.texture)].params != shown.params || !flatTextureMap(b, &st2pos))
        continue;
      // (u, v) in texels of level 0 -> (s, t) -> the view's object coordinates.
      const glm::dmat3 uv2pos = st2pos * glm::dmat3(glm::dvec3(1.0 / in.width0, 0, 0), glm::dvec3(0, 1.0 / in.height0, 0),
                                                     glm::dvec3(0, 0, 1));
      Panel o;
      o.id = p.id + "_footprint";
      o.viewport = p.viewport, o.projection = p.projection, o.modelview = p.modelview;
      for (Batch l : lines) {
        for (Vertex& v : l.vertices) v.pos = glm::vec3(glm::vec2(uv2pos * glm::dvec3(glm::dvec2(v.pos), 1.0)), 0.0f);
        o.batches.push_back(std::move(l));
      }
      over->panels.push_back(std::move(o));
      break;
    }
  }
  return !over->panels.empty();
}

Frame footprintFrame(const std::string& demo, const Frame& picture, const Image& drawn, const std::vector<Picked>& picks,
                     int w, int h) {
  Frame f = L::blankFrame(w, h);
  const int scale = std::max(1, std::min(w, h) / 500), line = int(L::lineHeight(scale));
  // Left: the part of the picture around the picks (at least a third of
  // it each way, padded), as large as fits in 45% of the width.
  const int leftW = w * 45 / 100, top = 2 * line;
  double bx0 = drawn.width, by0 = drawn.height, bx1 = 0, by1 = 0;
  for (const Picked& p : picks)
    bx0 = std::min(bx0, double(p.in.x)), by0 = std::min(by0, double(p.in.y)), bx1 = std::max(bx1, p.in.x + 1.0),
    by1 = std::max(by1, p.in.y + 1.0);
  const double areaAspect = double(leftW - 8) / double(h - top - 4);
  double cw = std::max(bx1 - bx0 + drawn.width * 0.2, drawn.width / 3.0), ch = std::max(by1 - by0 + drawn.height * 0.2, drawn.height / 3.0);
  if (cw / ch < areaAspect) cw = ch * areaAspect;
  else ch = cw / areaAspect;
  cw = std::min(cw, double(drawn.width)), ch = std::min(ch, double(drawn.height));
  const double cx0 = std::clamp((bx0 + bx1 - cw) / 2, 0.0, drawn.width - cw), cy0 = std::clamp((by0 + by1 - ch) / 2, 0.0, drawn.height - ch);
  const double k = std::min(double(leftW - 8) / cw, double(h - top - 4) / ch);
  const Rect pic{4, top, std::max(1, int(cw * k)), std::max(1, int(ch * k))};
  // The crop as the quad's (s, t): t = 0 is the image's bottom row.
  const float s0 = float(cx0 / drawn.width), s1 = float((cx0 + cw) / drawn.width);
  const float t0 = float(1 - (cy0 + ch) / drawn.height), t1 = float(1 - cy0 / drawn.height);
  Panel left = L::unitPanel("picture", pic);
  Batch crop;
  crop.role = "image";
  crop.texture = f.addTexture(renderedImageTexture(drawn, "inspect_picture", "the picture inspected", demo));
  for (glm::vec4 c : {glm::vec4(0, 0, s0, t0), glm::vec4(1, 0, s1, t0), glm::vec4(1, 1, s1, t1), glm::vec4(0, 0, s0, t0),
                      glm::vec4(1, 1, s1, t1), glm::vec4(0, 1, s0, t1)})
    crop.vertices.push_back({glm::vec3(c.x, c.y, 0.0f), glm::vec4(c.z, c.w, 0.0f, 1.0f), glm::vec4(1.0f)});
  left.batches.push_back(crop);
  for (size_t n = 0; n < picks.size(); ++n) {  // a ring around each picked pixel, its number beside it
    const float x = float((picks[n].in.x + 0.5 - cx0) / cw), y = 1.0f - float((picks[n].in.y + 0.5 - cy0) / ch);
    const float rx = 4.0f / float(pic.w), ry = 4.0f / float(pic.h);
    left.batches.push_back(lineLoop({{x - rx, y - ry}, {x + rx, y - ry}, {x + rx, y + ry}, {x - rx, y + ry}}, L::kAmber,
                                    2.0f, "pick"));
    Label l;
    l.x = float(pic.x) + x * float(pic.w) + 7, l.y = float(pic.y) + (1 - y) * float(pic.h) - float(line) / 2;
    l.text = std::to_string(n + 1), l.color = L::kAmber, l.scale = scale, l.background = {0, 0, 0, 0.6f};
    f.labels.push_back(l);
  }
  f.panels.push_back(left);
  L::caption(f, {4, 2, float(leftW), float(top - 2)}, "the picture, pixels picked", L::kWhite, scale);
  // Right: a cell per textured pick.
  std::vector<const Picked*> cells;
  for (const Picked& p : picks)
    if (usable(p.in)) cells.push_back(&p);
  const int areaX = leftW + 8, areaW = w - areaX - 4, n = int(cells.size());
  L::caption(f, {float(areaX), 2, float(w - 4), float(top - 2)},
             n ? "level 0 around each footprint: preimage (white), derivatives (cyan), EWA ellipse (magenta), 2^lambda "
                 "(yellow), texels read (orange)"
               : "no picked pixel is textured",
             L::kWhite, scale);
  if (n == 0) return f;
  const int cols = n <= 2 ? n : n <= 4 ? 2 : 3, rows = (n + cols - 1) / cols;
  const int cellW = areaW / cols, cellH = (h - top) / rows;
  for (int c = 0; c < n; ++c) {
    const Rect area{areaX + (c % cols) * cellW, top + (c / cols) * cellH, cellW - 6, cellH - 4};
    addCell(f, picture, cells[size_t(c)]->in, int(cells[size_t(c)] - picks.data()) + 1, area, scale);
  }
  return f;
}

std::vector<std::string> applyInspect(const std::string& demo, const CommonFlags& flags, Renderer& r, Rendered* got,
                                      bool record, std::string* cards) {
  std::vector<std::string> objects;
  if (flags.inspect.empty()) {
    if (flags.footprints) throw Error("--footprints needs --inspect X,Y (the pixels whose footprints it draws)");
    return objects;
  }
  checkPixels(flags.inspect, got->image.width, got->image.height);
  const std::vector<Picked> picks = inspectPixels(got->frame, got->image, flags.inspect);
  for (size_t n = 0; n < picks.size(); ++n) {
    const Picked& p = picks[n];
    objects.push_back(inspectJson(p));
    if (cards) *cards += inspectCard(p) + "\n";
    // The numbers a figure's claim can quote, pick by pick (1-based).
    if (!usable(p.in)) continue;
    const std::string k = "[" + std::to_string(n + 1) + "]";
    got->measurements.push_back({"inspect_lambda" + k, p.in.lambda, "--inspect pick " + k + ": lambda (level of detail)"});
    got->measurements.push_back({"inspect_rho" + k, p.in.rhoEdge, "--inspect pick " + k + ": rho, texels per pixel"});
    // The footprint's anisotropy: the ratio of the Jacobian's singular values
    // (the EWA ellipse's axes), from its squared Frobenius norm and determinant.
    const double a = p.in.dudx * p.in.dudx + p.in.dudy * p.in.dudy + p.in.dvdx * p.in.dvdx + p.in.dvdy * p.in.dvdy;
    const double det = std::abs(p.in.dudx * p.in.dvdy - p.in.dudy * p.in.dvdx);
    const double root = std::sqrt(std::max(0.0, a * a - 4 * det * det));
    if (det > 0)
      got->measurements.push_back({"inspect_anisotropy" + k, std::sqrt((a + root) / (a - root)),
                                   "--inspect pick " + k + ": the footprint's long axis over its short one"});
  }
  if (flags.footprints) {
    got->frame = footprintFrame(demo, got->frame, got->image, picks, got->image.width, got->image.height);
    if (record) got->calls = recordPicture(r, got->frame);
    got->image = r.render(got->frame);
  }
  return objects;
}
}  // namespace ts
