// common/app/inspect_view.cpp — see inspect_view.hpp.
#include "common/app/inspect_view.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <nlohmann/json.hpp>

#include "common/core/error.hpp"
#include "common/core/layout.hpp"
#include "common/core/text.hpp"
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

std::vector<Picked> inspectPixels(const Frame& frame, const Image& drawn,
                                  const std::vector<std::array<int, 2>>& pixels) {
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
    kEllipse{1.0f, 0.3f, 0.9f, 1.0f}, kLodSquare{1.0f, 0.85f, 0.2f, 1.0f}, kTexels{1.0f, 0.55f, 0.1f, 1.0f},
    kTexelGrid{0.42f, 0.42f, 0.47f, 1.0f};

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
  auto grow = [&](glm::dvec2 p) {
    u0 = std::min(u0, p.x), u1 = std::max(u1, p.x), v0 = std::min(v0, p.y), v1 = std::max(v1, p.y);
  };
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
    for (double u = std::ceil(cu - halfU); u <= cu + halfU; ++u)
      grid.push_back({float(u), y0}), grid.push_back({float(u), y1});
    for (double v = std::ceil(cv - halfV); v <= cv + halfV; ++v)
      grid.push_back({x0, float(v)}), grid.push_back({x1, float(v)});
    p.batches.push_back(lineSegments(grid, kTexelGrid, 1.0f, "texel_grid"));
  }
  for (Batch& b : footprintBatches(picture, in)) p.batches.push_back(std::move(b));
  return p;
}

// A cell's captions as phrases: above, the pick's number with its lambda,
// and its rho; below, its (u, v), and its levels and texel count; each
// number printed from the pick's measurement (applyInspect) or, the pick's
// number, given.
struct CellCaptions {
  std::vector<L::Text> above, below;
};
CellCaptions cellCaptions(int number, const Measurements& measured) {
  const std::string k = "[" + std::to_string(number) + "]";
  const bool twoLevels = std::any_of(measured.begin(), measured.end(),
                                     [&](const Measurement& x) { return x.name == "inspect_level1" + k; });
  const std::string levels = twoLevels ? "levels {inspect_level0" + k + "|%.0f}+{inspect_level1" + k + "|%.0f}"
                                       : "level {inspect_level0" + k + "|%.0f}";
  return {{L::given("pick number", number, "%.0f") +
               L::measuredText(measured, ": lambda {inspect_lambda" + k + "|%.2f},"),
           L::measuredText(measured, "rho {inspect_rho" + k + "|%.2f}")},
          {L::measuredText(measured, "(u,v) = ({inspect_u" + k + "|%.1f}, {inspect_v" + k + "|%.1f}),"),
           L::measuredText(measured, levels + ", {inspect_texels" + k + "|%.0f} texels")}};
}

// Phrases joined into the lines `width` holds at `scale`: a line breaks
// between phrases, never inside one (a number stays with its name).
std::vector<L::Text> phraseLines(const std::vector<L::Text>& phrases, int scale, float width) {
  std::vector<L::Text> lines;
  for (const L::Text& p : phrases) {
    if (!lines.empty() && text::width(lines.back().text + " " + p.text, scale) <= width)
      lines.back() = lines.back() + L::Text(" ") + p;
    else lines.push_back(p);
  }
  return lines;
}
int captionHeight(const std::vector<L::Text>& phrases, int scale, float width) {
  int h = 0;
  for (const L::Text& t : phraseLines(phrases, scale, width))
    h += L::captionLines(t.text, scale, width) * int(L::lineHeight(scale));
  return h;
}
// The lines from the top of `band` down.
void phraseCaption(Frame& f, L::Box band, const std::vector<L::Text>& phrases, glm::vec4 colour, int scale) {
  for (const L::Text& t : phraseLines(phrases, scale, band.w())) band.y0 = L::caption(f, band, t, colour, scale);
}

// One cell in `area`: the texture around pick `in` (number `number`), in
// texels of level 0 (u right, v up: t = 0 is the texture's row 0), with the
// footprint drawn over it, between its captions (cellCaptions), each given
// the lines it needs at the cell's width.  Returns whether the cell draws
// level 0's texel grid.
bool addCell(Frame& f, const Frame& picture, const ref::Inspection& in, int number, const Measurements& measured,
             const Rect& area, int scale) {
  const CellCaptions c = cellCaptions(number, measured);
  const float width = float(area.w);
  const int above = captionHeight(c.above, scale, width), below = captionHeight(c.below, scale, width);
  const Rect view{area.x, area.y + above, area.w, std::max(1, area.h - above - below - 2)};
  f.panels.push_back(cellPanel(f, picture, in, number, view));
  phraseCaption(f, {float(area.x), float(area.y), float(area.x + area.w), float(view.y)}, c.above, L::kAmber, scale);
  phraseCaption(f, {float(area.x), float(view.y + view.h + 2), float(area.x + area.w), float(area.y + area.h)}, c.below,
                L::kWhite, scale);
  const Panel& p = f.panels.back();
  return std::any_of(p.batches.begin(), p.batches.end(), [](const Batch& b) { return b.role == "texel_grid"; });
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
  loop({{float(in.u) - hs, float(in.v) - hs},
        {float(in.u) + hs, float(in.v) - hs},
        {float(in.u) + hs, float(in.v) + hs},
        {float(in.u) - hs, float(in.v) + hs}},
       kLodSquare, 1.0f, "lod_square");
  // The EWA ellipse is the image of the unit circle of screen space under
  // the Jacobian [du/dx du/dy; dv/dx dv/dy]: A du^2 + B du dv + C dv^2 = F.
  std::vector<glm::vec2> pts;
  for (int k = 0; k < 64; ++k) {
    const double a = 2 * M_PI * k / 64, cx = std::cos(a), cy = std::sin(a);
    pts.push_back({float(in.u + in.dudx * cx + in.dudy * cy), float(in.v + in.dvdx * cx + in.dvdy * cy)});
  }
  loop(pts, kEllipse, 1.0f, "ewa_ellipse");
  pts.clear();
  for (const glm::dvec2& c : in.preimage) pts.push_back(glm::vec2(c));
  loop(pts, kPreimage, 2.0f, "preimage");
  // The parallelogram is the preimage's first-order approximation and lies
  // almost on it for a pixel: drawn thinner and after it, so both show.
  pts.clear();
  for (const glm::dvec2& c : in.parallelogram) pts.push_back(glm::vec2(c));
  loop(pts, kParallelogram, 1.0f, "derivative_parallelogram");
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
      const glm::dmat3 uv2pos = st2pos * glm::dmat3(glm::dvec3(1.0 / in.width0, 0, 0),
                                                    glm::dvec3(0, 1.0 / in.height0, 0), glm::dvec3(0, 0, 1));
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

namespace {
// The panel the picture shows: the one holding the most picks (the first
// such on a tie), -1 when no pick lies in a panel.
int pickedPanel(const std::vector<Picked>& picks, size_t panels) {
  std::vector<int> count(panels, 0);
  for (const Picked& p : picks)
    if (p.in.panel >= 0 && size_t(p.in.panel) < panels) ++count[size_t(p.in.panel)];
  int best = -1;
  for (size_t k = 0; k < panels; ++k)
    if (count[k] > 0 && (best < 0 || count[k] > count[size_t(best)])) best = int(k);
  return best;
}

// Panel `src` of `picture` drawn again at `at`, showing the part `part` of
// its viewport (frame pixels, the size of `at`): its projection is narrowed
// so that each pixel of `part` lands on one pixel of `at` at the same place
// in the panel, so every pixel centre gets the same (s, t), derivatives and
// levels as in the picture inspected.  Its textures and programs are copied
// into `f`.  The picture is the panel's own geometry, never a cut-out of the
// rendered figure: no caption of the figure is in it.
Panel reframed(Frame& f, const Frame& picture, const Panel& src, const Rect& part, const Rect& at) {
  Panel p = src;
  p.viewport = at;
  const Rect& v = src.viewport;
  // Normalised device coordinates of the panel -> those of the part.
  const float sx = float(v.w) / float(part.w), sy = float(v.h) / float(part.h);
  glm::mat4 narrow(1.0f);
  narrow[0][0] = sx, narrow[1][1] = sy;
  narrow[3][0] = sx - 1 - 2 * float(part.x - v.x) / float(part.w);
  narrow[3][1] = 1 - sy - 2 * float(v.y - part.y) / float(part.h);
  p.projection = narrow * src.projection;
  std::vector<int> copied(picture.textures.size(), -1);
  auto texture = [&](int t) {
    if (t < 0 || size_t(t) >= picture.textures.size()) return t;
    if (copied[size_t(t)] < 0) copied[size_t(t)] = f.addTexture(picture.textures[size_t(t)]);
    return copied[size_t(t)];
  };
  for (Batch& b : p.batches) {
    b.texture = texture(b.texture), b.texture1 = texture(b.texture1);
    if (b.program.empty()) continue;
    const bool have = std::any_of(f.programs.begin(), f.programs.end(),
                                  [&](const auto& q) { return q.first == b.program; });
    if (!have)
      for (const auto& q : picture.programs)
        if (q.first == b.program) f.programs.push_back(q);
  }
  return p;
}

// Whether segment a-b meets box `r` (Liang-Barsky).
bool crosses(glm::vec2 a, glm::vec2 b, const L::Box& r) {
  float t0 = 0, t1 = 1;
  const glm::vec2 d = b - a;
  const float p[4] = {-d.x, d.x, -d.y, d.y}, q[4] = {a.x - r.x0, r.x1 - a.x, a.y - r.y0, r.y1 - a.y};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0) return false;
      continue;
    }
    const float t = q[k] / p[k];
    if (p[k] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}
// Whether segments a-b and c-d cross (touching ends do not count).
bool crosses(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d) {
  auto side = [](glm::vec2 o, glm::vec2 p, glm::vec2 q) {
    return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x);
  };
  const float d1 = side(c, d, a), d2 = side(c, d, b), d3 = side(a, b, c), d4 = side(a, b, d);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}
L::Box grown(const L::Box& b, float by) { return {b.x0 - by, b.y0 - by, b.x1 + by, b.y1 + by}; }

// The picks' numbers beside their rings (frame pixels, `rings` their boxes),
// inside `within`: each at the free place nearest its ring, right of it
// first, never over another label, ring or leader, and either on the
// picture or off it, never across its edge; a number that cannot sit beside
// its ring gets a leader line to it (returned as segments).  Placed with
// layout::placeFree, so the frame's other labels are respected too.
std::vector<glm::vec2> numberPicks(Frame& f, const std::vector<L::Box>& rings, const std::vector<int>& numbers,
                                   L::Box within, L::Box picture, int scale) {
  std::vector<glm::vec2> leaders;
  std::vector<L::Box> placed;
  const float step = 3.0f * float(scale), ringGap = 2.0f * float(scale);
  for (size_t k = 0; k < rings.size(); ++k) {
    Label l;
    l.text = std::to_string(numbers[k]), l.color = L::kAmber, l.scale = scale, l.background = {0, 0, 0, 0.6f};
    l.given = {{"pick number", double(numbers[k])}};
    const L::Box at0 = L::labelBox(l);  // at (0, 0): its offsets from the label's point
    const float bw = at0.w(), bh = at0.h();
    const L::Box& ring = rings[k];
    const glm::vec2 c((ring.x0 + ring.x1) / 2, (ring.y0 + ring.y1) / 2);
    struct Candidate {
      float cost;
      L::Box box;
    };
    std::vector<Candidate> candidates;
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i <= 80; ++i)
        for (int j = -80; j <= 80; ++j) {
          const float x0 = side == 0 ? ring.x1 + ringGap + float(i) * step : ring.x0 - ringGap - bw - float(i) * step;
          const float y0 = std::round(c.y - bh / 2 + float(j) * step);
          // Near first, to the right before the left.
          candidates.push_back({float(i + std::abs(j)) * step + (side ? 2 * step : 0),
                                {std::round(x0), y0, std::round(x0) + bw, y0 + bh}});
        }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });
    for (const Candidate& cand : candidates) {
      const L::Box& b = cand.box;
      if (!b.inside(within) || (b.overlaps(picture) && !b.inside(picture))) continue;
      if (std::any_of(rings.begin(), rings.end(), [&](const L::Box& r) { return grown(r, 1).overlaps(b); })) continue;
      if (std::any_of(placed.begin(), placed.end(), [&](const L::Box& o) { return o.overlaps(b); })) continue;
      bool hitsLeader = false;
      for (size_t s = 0; s + 1 < leaders.size(); s += 2)
        hitsLeader = hitsLeader || crosses(leaders[s], leaders[s + 1], b);
      if (hitsLeader) continue;
      // The leader: from the ring's edge to the nearest point of the label,
      // when the label does not touch the ring.
      const glm::vec2 q(std::clamp(c.x, b.x0, b.x1), std::clamp(c.y, b.y0, b.y1));
      const float reach = std::max(std::abs(q.x - c.x) - (ring.x1 - ring.x0) / 2,
                                   std::abs(q.y - c.y) - (ring.y1 - ring.y0) / 2);
      glm::vec2 from = c;
      bool leader = reach > ringGap + 1;
      if (leader) {
        from = c + (q - c) * ((ring.x1 - ring.x0) / 2 / std::max(std::abs(q.x - c.x), std::abs(q.y - c.y)));
        bool blocked = false;
        // Rings that overlap this one (picks a few pixels apart) are left
        // by any leader: only the others block it.
        for (size_t r = 0; r < rings.size(); ++r)
          blocked = blocked || (r != k && !rings[r].overlaps(ring) && crosses(from, q, grown(rings[r], 1)));
        for (const L::Box& o : placed) blocked = blocked || crosses(from, q, o);
        for (size_t s = 0; s + 1 < leaders.size(); s += 2)
          blocked = blocked || crosses(from, q, leaders[s], leaders[s + 1]);
        if (blocked) continue;
      }
      Label at = l;
      at.x = b.x0 - at0.x0, at.y = b.y0 - at0.y0;
      if (!L::placeFree(f, at, within)) continue;
      placed.push_back(b);
      if (leader) leaders.push_back(from), leaders.push_back(q);
      break;
    }
  }
  return leaders;
}

// The key in `band`; returns the height it takes.  `draw` false: only measures.
float drawKey(Frame& f, L::Box band, const std::vector<LegendEntry>& entries, int scale, bool draw = true) {
  Frame scratch = L::blankFrame(f.width, f.height);
  return L::legend(draw ? f : scratch, band, entries, scale) - band.y0;
}

// The cells' grid for n cells in `area`: the number of columns that gives
// the largest square view (a cell `cellW` wide keeps captionH(cellW) pixels
// for its captions).
int cellColumns(int n, const Rect& area, const std::function<int(int cellW)>& captionH) {
  int best = 1, bestSide = -1;
  for (int cols = 1; cols <= n; ++cols) {
    const int rows = (n + cols - 1) / cols;
    const int side = std::min(area.w / cols - 6, area.h / rows - 6 - captionH(area.w / cols - 6));
    if (side > bestSide) best = cols, bestSide = side;
  }
  return best;
}
}  // namespace

Frame footprintFrame(const Frame& picture, const std::vector<Picked>& picks, const Measurements& measured, int w,
                     int h) {
  Frame f = L::blankFrame(w, h);
  f.perspectiveHint = picture.perspectiveHint;
  const int scale = std::max(1, std::min(w, h) / 500), line = int(L::lineHeight(scale)), margin = 4;
  // Room above and below the picture for a pick's number (text on its dark box).
  const int tagRoom = int(std::ceil(text::height(scale))) + 6 * scale + 2;
  std::vector<const Picked*> cells;
  for (const Picked& p : picks)
    if (usable(p.in)) cells.push_back(&p);
  const int n = int(cells.size());
  // The key: every entry it may hold (the ring only when a pick is ringed,
  // the grid only when a cell draws it); its room is measured by laying it
  // out on a scratch frame.
  const std::string kRingMeaning = "pixel picked (ring, its number)", kGridMeaning = "texel grid";
  std::vector<LegendEntry> entries = {{L::kAmber, kRingMeaning},
                                      {kPreimage, "preimage of the pixel square"},
                                      {kParallelogram, "derivatives' parallelogram"},
                                      {kEllipse, "EWA ellipse"},
                                      {kLodSquare, "a texel of level lambda"},
                                      {kTexels, "texels read"},
                                      {kTexelGrid, kGridMeaning}};
  auto keyHeight = [&](int width) {
    return int(std::ceil(drawKey(f, {0, 0, float(width), float(h)}, entries, scale, false)));
  };
  const L::Text cellsTitle = n ? L::Text("the texture's level ") + L::given("the level the cells show", 0, "%.0f") +
                                     L::Text(" around each footprint, in its texels (u right, v up)")
                               : L::Text("no picked pixel is textured");
  // The picture: the picks' panel at its own pixels (reframed), whole when
  // there is room, else the part around the picks; beside the cells (left)
  // or above them, whichever shows more of it.  A band of half a line above
  // and below it holds numbers that do not fit on it.
  const int pi = pickedPanel(picks, picture.panels.size());
  // The panel's own marks keep the meaning the inspected figure's legend
  // gives their colours.
  if (pi >= 0)
    for (const Batch& b : picture.panels[size_t(pi)].batches)
      for (const LegendEntry& e : picture.legend)
        if (b.texture < 0 && !b.vertices.empty() && b.vertices[0].color == e.color &&
            std::none_of(entries.begin(), entries.end(), [&](const LegendEntry& c) { return c.color == e.color; }))
          entries.push_back(e);
  Rect panel{0, 0, 0, 0};
  if (pi >= 0) {
    const Rect& v = picture.panels[size_t(pi)].viewport;
    const int x0 = std::max(0, v.x), y0 = std::max(0, v.y);
    panel = {x0, y0, std::max(0, std::min(picture.width, v.x + v.w) - x0),
             std::max(0, std::min(picture.height, v.y + v.h) - y0)};
  }
  const bool one = std::count_if(picks.begin(), picks.end(), [&](const Picked& p) { return p.in.panel == pi; }) == 1;
  const std::string whole = one ? "the pixel's panel, drawn again pixel for pixel"
                                : "the pixels' panel, drawn again pixel for pixel",
                    partOf = one ? "the pixel's part of its panel, drawn again pixel for pixel"
                                 : "the pixels' part of their panel, drawn again pixel for pixel";
  auto captionH = [&](int width) { return L::captionLines(partOf, scale, float(width)) * line; };
  const int leftRoomW = w * 45 / 100 - 2 * margin, leftRoomH = h - captionH(leftRoomW) - 2 * tagRoom - 2 * margin;
  const int topRoomW = w - 2 * margin, topRoomH = h * 2 / 5 - captionH(topRoomW) - 2 * tagRoom - margin;
  auto shown = [&](int rw, int rh) { return double(std::min(panel.w, rw)) * double(std::min(panel.h, rh)); };
  const bool above = pi >= 0 && shown(topRoomW, topRoomH) > shown(leftRoomW, leftRoomH);
  const int cropW = std::min(panel.w, above ? topRoomW : leftRoomW),
            cropH = std::min(panel.h, above ? topRoomH : leftRoomH);
  // The zone of the picture and the picks' numbers (under the picture's
  // caption), the key's band, the cells' title and the cells.
  Rect zone, cellArea;
  L::Box key, title;
  if (above) {
    zone = {margin, captionH(topRoomW) + margin / 2, w - 2 * margin, cropH + 2 * tagRoom};
    const float y = float(zone.y + zone.h + margin);
    title = {float(margin), y, float(w - margin),
             y + float(L::captionLines(cellsTitle.text, scale, float(w - 2 * margin)) * line)};
    key = {float(margin), title.y1, float(w - margin), title.y1 + float(keyHeight(w - 2 * margin))};
    cellArea = {margin, int(key.y1) + margin, w - 2 * margin, h - int(key.y1) - 2 * margin};
  } else {
    const int leftW = pi >= 0 ? std::min(leftRoomW, std::max(cropW + 2 * line, w / 5)) : w / 5;
    zone = {margin, captionH(leftW) + margin / 2, leftW, cropH + 2 * tagRoom};
    const int x0 = zone.x + zone.w + 2 * margin, rightW = w - x0 - margin;
    title = {float(x0), float(margin) / 2, float(w - margin),
             float(margin) / 2 + float(L::captionLines(cellsTitle.text, scale, float(rightW)) * line)};
    // The key under the picture when it fits there, else over the cells.
    if (zone.y + zone.h + margin + keyHeight(leftW) <= h - margin) {
      key = {float(margin), float(zone.y + zone.h + margin), float(margin + leftW), float(h - margin)};
      cellArea = {x0, int(title.y1) + margin, rightW, h - int(title.y1) - 2 * margin};
    } else {
      key = {float(x0), title.y1, float(w - margin), title.y1 + float(keyHeight(rightW))};
      cellArea = {x0, int(key.y1) + margin, rightW, h - int(key.y1) - 2 * margin};
    }
  }
  bool anyRing = false;
  if (pi >= 0) {
    // The part of the panel around the picks in it, clamped to the panel.
    double bx0 = panel.x + panel.w, by0 = panel.y + panel.h, bx1 = panel.x, by1 = panel.y;
    for (const Picked& p : picks)
      if (p.in.panel == pi)
        bx0 = std::min(bx0, double(p.in.x)), by0 = std::min(by0, double(p.in.y)), bx1 = std::max(bx1, p.in.x + 1.0),
        by1 = std::max(by1, p.in.y + 1.0);
    const int px = std::clamp(int(std::lround((bx0 + bx1 - cropW) / 2)), panel.x, panel.x + panel.w - cropW);
    const int py = std::clamp(int(std::lround((by0 + by1 - cropH) / 2)), panel.y, panel.y + panel.h - cropH);
    const Rect part{px, py, cropW, cropH};
    // Moved by whole 2 x 2 blocks of window pixels: a rasterizer takes the
    // derivatives (and so lambda) per 2 x 2 quad, so the same pixels must
    // fall in the same quads (window rows count from the bottom).
    Rect at{zone.x + (zone.w - cropW) / 2, zone.y + tagRoom, cropW, cropH};
    if ((at.x - part.x) % 2) ++at.x;
    if ((at.y - part.y + picture.height - h) % 2) ++at.y;
    f.panels.push_back(reframed(f, picture, picture.panels[size_t(pi)], part, at));
    L::caption(f, {float(zone.x), 2, float(zone.x + zone.w), float(zone.y)},
               cropW == panel.w && cropH == panel.h ? whole : partOf, L::kWhite, scale);
    // Rings round the picks in the part shown, numbered (frame pixels).
    Panel marks;
    marks.id = "picks";
    marks.viewport = zone;
    marks.projection = glm::ortho(float(zone.x), float(zone.x + zone.w), float(zone.y + zone.h), float(zone.y), -1.0f,
                                  1.0f);
    std::vector<const Picked*> ringed;
    for (const Picked& p : picks)
      if (p.in.panel == pi && part.contains(p.in.x, p.in.y)) ringed.push_back(&p);
    // A ring's half side: 4 pixels, less when picks lie closer (down to 2,
    // drawn thinner), so that neighbouring rings do not overlap.
    int r = 4;
    for (const Picked* a : ringed)
      for (const Picked* b : ringed)
        if (a != b) r = std::min(r, (std::max(std::abs(a->in.x - b->in.x), std::abs(a->in.y - b->in.y)) - 1) / 2);
    r = std::max(r, 2);
    std::vector<L::Box> rings;
    std::vector<int> numbers;
    for (const Picked* p : ringed) {
      const float cx = float(at.x + p->in.x - part.x) + 0.5f, cy = float(at.y + p->in.y - part.y) + 0.5f, q = float(r);
      marks.batches.push_back(lineLoop({{cx - q, cy - q}, {cx + q, cy - q}, {cx + q, cy + q}, {cx - q, cy + q}},
                                       L::kAmber, r >= 3 ? 2.0f : 1.0f, "pick"));
      rings.push_back({cx - q - 1, cy - q - 1, cx + q + 1, cy + q + 1});
      numbers.push_back(int(p - picks.data()) + 1);
    }
    anyRing = !rings.empty();
    const std::vector<glm::vec2> leaders = numberPicks(f, rings, numbers, L::box(zone), L::box(at), scale);
    if (!leaders.empty()) marks.batches.push_back(lineSegments(leaders, L::kAmber, 1.0f, "pick_leader"));
    f.panels.push_back(marks);
  } else {
    L::caption(f, {float(zone.x), 2, float(zone.x + zone.w), float(zone.y)}, "no picked pixel lies in a panel",
               L::kWhite, scale);
  }
  // The cells: the texture around each textured pick's footprint.
  L::caption(f, title, cellsTitle, L::kWhite, scale, Align::Left);
  if (n == 0) return f;
  auto cellCaptionH = [&](int cellW) {
    int most = 0;
    for (const Picked* p : cells) {
      const CellCaptions c = cellCaptions(int(p - picks.data()) + 1, measured);
      most = std::max(most, captionHeight(c.above, scale, float(cellW)) + captionHeight(c.below, scale, float(cellW)));
    }
    return most;
  };
  const int cols = cellColumns(n, cellArea, cellCaptionH), rows = (n + cols - 1) / cols;
  const int cellW = cellArea.w / cols, cellH = cellArea.h / rows;
  bool grid = false;
  for (int c = 0; c < n; ++c) {
    const Rect area{cellArea.x + (c % cols) * cellW, cellArea.y + (c / cols) * cellH, cellW - 6, cellH - 4};
    grid = addCell(f, picture, cells[size_t(c)]->in, int(cells[size_t(c)] - picks.data()) + 1, measured, area, scale) ||
           grid;
  }
  // The key names the colours drawn, and only those.
  auto drop = [&](const std::string& meaning) {
    entries.erase(std::remove_if(entries.begin(), entries.end(),
                                 [&](const LegendEntry& e) { return e.meaning == meaning; }),
                  entries.end());
  };
  if (!anyRing) drop(kRingMeaning);
  if (!grid) drop(kGridMeaning);
  drawKey(f, key, entries, scale);
  return f;
}

std::vector<std::string> applyInspect(const std::string& /*demo*/, const CommonFlags& flags, Renderer& r, Rendered* got,
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
    got->measurements.push_back(
        {"inspect_lambda" + k, p.in.lambda, "--inspect pick " + k + ": lambda (level of detail)"});
    got->measurements.push_back({"inspect_rho" + k, p.in.rhoEdge, "--inspect pick " + k + ": rho, texels per pixel"});
    got->measurements.push_back(
        {"inspect_u" + k, p.in.u, "--inspect pick " + k + ": u = (s/q) x width, texels of level 0"});
    got->measurements.push_back(
        {"inspect_v" + k, p.in.v, "--inspect pick " + k + ": v = (t/q) x height, texels of level 0"});
    got->measurements.push_back(
        {"inspect_level0" + k, double(p.in.level0), "--inspect pick " + k + ": the mip level read"});
    if (p.in.level1 != p.in.level0)
      got->measurements.push_back({"inspect_level1" + k, double(p.in.level1),
                                   "--inspect pick " + k + ": the second level the filter blends in"});
    got->measurements.push_back({"inspect_texels" + k, double(p.in.texels.size()),
                                 "--inspect pick " + k + ": texels the filter reads, both levels"});
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
    got->frame = footprintFrame(got->frame, picks, got->measurements, got->image.width, got->image.height);
    if (record) got->calls = recordPicture(r, got->frame);
    got->image = r.render(got->frame);
  }
  return objects;
}
}  // namespace ts
