// demos/projectors/projectors_measure.hpp — the measurements of demos/projectors,
// every one read from a render with a texture whose texels hold their own
// indices (GL_NEAREST): each pixel says which texel it took.  The formulas of
// projectors_math.hpp are never evaluated here except where a number is compared
// against them (the slide projector's CPU check) — the numbers come from GL.
#pragma once
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "common/core/scene.hpp"
#include "common/core/textures.hpp"
#include "common/gl/render.hpp"
#include "projectors_gl.hpp"
#include "projectors_math.hpp"
#include "projectors_pose.hpp"

namespace proj {
// The texel (i, j) a pixel took, or (-1, -1) where no object is.
struct Texels {
  int w = 0, h = 0;
  std::vector<glm::ivec2> at;
  glm::ivec2 operator()(int x, int y) const { return at[size_t(y) * size_t(w) + size_t(x)]; }
};
inline Texels decode(const ts::Image& img) {
  Texels t;
  t.w = img.width;
  t.h = img.height;
  t.at.assign(size_t(t.w) * size_t(t.h), glm::ivec2(-1));
  for (int y = 0; y < t.h; ++y)
    for (int x = 0; x < t.w; ++x) {
      ts::Rgba c = img.at(x, y);
      if (c.a != 255) continue;
      int i = 0, j = 0;
      ts::decodeTexelIndex(c, &i, &j);
      t.at[size_t(y) * size_t(t.w) + size_t(x)] = {i, j};
    }
  return t;
}
inline ts::Frame indexFrame(int w, int h) {
  ts::Frame f;
  f.width = w;
  f.height = h;
  f.clearColor = {0, 0, 0, 0};  // alpha 0: no texel
  return f;
}

// --- 1. Seed 002 as printed against corrected --------------------------------
// The unit sphere from its six axis directions (3 x 2 panels of kView px),
// coordinates per fragment, a kGrid x kGrid texel-index texture (GL_REPEAT).
constexpr int kView = 256, kGrid = 128;
const glm::dvec3 kSix[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
inline Texels sixViews(ts::Renderer& r, const Shape& s, Projector pr, Axis ax, Formula f, Coords c, int grid) {
  ts::Frame fr = indexFrame(3 * kView, 2 * kView);
  fr.programs.push_back({kProgramName, projectorProgram()});
  int tex = fr.addTexture(ts::texelIndexTexture(grid));
  const bool linear = pr == Projector::Planar || pr == Projector::Solid;
  for (int k = 0; k < 6; ++k) {
    ts::Panel p = orthoPanel("view_" + std::to_string(k), {(k % 3) * kView, (k / 3) * kView, kView, kView},
                             faceOn(kSix[k]));
    if (c == Coords::Cpu) p.batches.push_back(perVertexBatch(s, pr, ax, f, tex));
    else if (c == Coords::TexGen && linear)
      p.batches.push_back(texGenBatch(s, planarTexGen(ax, f, GL_OBJECT_LINEAR, glm::mat4(1.0f)), tex));
    else p.batches.push_back(glslBatch(s, pr, ax, f, tex));
    fr.panels.push_back(p);
  }
  return decode(r.renderOffscreen(fr));
}
struct Usage {
  double columns = 0, rows = 0, diagonal = 0;
  long pixels = 0;
  std::vector<unsigned char> used;  // grid x grid, row j from the bottom
};
inline Usage usage(const Texels& t, int grid) {
  Usage u;
  u.used.assign(size_t(grid) * size_t(grid), 0);
  std::vector<char> col(size_t(grid), 0), row(size_t(grid), 0);
  long diag = 0;
  for (const glm::ivec2& v : t.at) {
    if (v.x < 0 || v.x >= grid || v.y >= grid) continue;
    ++u.pixels;
    col[size_t(v.x)] = row[size_t(v.y)] = 1;
    u.used[size_t(v.y) * size_t(grid) + size_t(v.x)] = 1;
    diag += v.x == v.y;
  }
  u.columns = double(std::count(col.begin(), col.end(), 1)) / grid;
  u.rows = double(std::count(row.begin(), row.end(), 1)) / grid;
  u.diagonal = u.pixels ? double(diag) / double(u.pixels) : 0.0;
  return u;
}
// Pixels (of the object in both) whose texel differs, as a share.
inline double mismatchShare(const Texels& a, const Texels& b, long* count = nullptr) {
  long n = 0, d = 0;
  for (size_t k = 0; k < a.at.size(); ++k) {
    if (a.at[k].x < 0 || b.at[k].x < 0) continue;
    ++n;
    d += a.at[k] != b.at[k];
  }
  if (count) *count = d;
  return n ? double(d) / double(n) : 0.0;
}

// The texel read at one model point of the unit sphere, seen face-on from its
// own direction in a (2m+1)-pixel ortho panel: the point is the centre pixel.
inline glm::ivec2 texelAt(ts::Renderer& r, const Shape& s, Projector pr, Axis ax, Formula f, glm::dvec3 point,
                          int grid) {
  const int n = 257;
  ts::Frame fr = indexFrame(n, n);
  fr.programs.push_back({kProgramName, projectorProgram()});
  ts::TextureDesc idx = ts::texelIndexTexture(grid);
  idx.wrapT = GL_CLAMP_TO_EDGE;  // tv = 1 at the pole is the last row
  int tex = fr.addTexture(idx);
  ts::Panel p = orthoPanel("point", {0, 0, n, n}, faceOn(point));
  p.batches.push_back(glslBatch(s, pr, ax, f, tex));
  fr.panels.push_back(p);
  Texels t = decode(r.renderOffscreen(fr));
  return t(n / 2, n / 2);
}

// --- 2. Corrected cylindrical against Buss's Eq. VI.1, and its seam -----------
// The cylinder (r 1, y from -1 to 1, 48 slices) from the back, where atan2's
// cut lies (θ = 180°), ortho, kView px; its mesh carries cylinder_seam's
// mapping (s = θ/360 with the winding tracked, t = (y + 1)/2) per vertex.
struct SeamResult {
  long perFragmentMismatch = 0, perFragmentFar = 0, perVertexFar = 0;
  int reversedPatches = 0;
  long lambdaImplicit = 0, lambdaGrad = 0;
};
inline SeamResult seamMeasure(ts::Renderer& r) {
  const int slices = 48, grid = 256;
  // θ from -3.75° (half a slice): the cut at 180° runs through the middle of a patch.
  const ts::Mesh mesh = ts::parametricGrid(
      slices, 8, true, false, [](int i, int j) { return ts::cylinderPoint(1.0, 2.0, 48, 8, i, j, -3.75); },
      [](int i, int j) { return glm::dvec2((i - 0.5) / 48.0, j / 8.0); });
  const Shape cyl = fromMesh(mesh);
  // Turned 0.47° off the back: the cut (x = 0) falls one pixel right of the
  // centre, between the pixel centres of one 2x2 quad (128 | 129), not on a
  // quad's edge, where no quad would straddle it.
  const glm::mat4 back = faceOn({std::sin(kPi * 0.47 / 180), 0, -std::cos(kPi * 0.47 / 180)});
  ts::Frame fr = indexFrame(3 * kView, kView);
  fr.programs.push_back({kProgramName, projectorProgram()});
  ts::TextureDesc idx = ts::texelIndexTexture(grid);
  idx.wrapT = GL_CLAMP_TO_EDGE;
  int tex = fr.addTexture(idx);
  ts::Batch buss = perVertexBatch(cyl, Projector::Cylindrical, Axis::Y, Formula::Corrected, tex, true);
  ts::Batch frag = glslBatch(cyl, Projector::Cylindrical, Axis::Y, Formula::Corrected, tex);
  ts::Batch vert = perVertexBatch(cyl, Projector::Cylindrical, Axis::Y, Formula::Corrected, tex);
  const ts::Batch* bs[3] = {&buss, &frag, &vert};
  for (int k = 0; k < 3; ++k) {
    ts::Panel p = orthoPanel("cyl_" + std::to_string(k), {k * kView, 0, kView, kView}, back);
    p.batches.push_back(*bs[k]);
    fr.panels.push_back(p);
  }
  Texels t = decode(r.renderOffscreen(fr));
  SeamResult res;
  std::set<int> patches;
  auto far = [&](glm::ivec2 a, glm::ivec2 b) {  // more than 1 texel apart, around the circle in s
    int di = std::abs(a.x - b.x);
    di = std::min(di, grid - di);
    return di > 1 || std::abs(a.y - b.y) > 1;
  };
  for (int y = 0; y < kView; ++y)
    for (int x = 0; x < kView; ++x) {
      glm::ivec2 a = t(x, y), f = t(x + kView, y), v = t(x + 2 * kView, y);
      if (a.x < 0 || f.x < 0 || v.x < 0) continue;
      res.perFragmentMismatch += a != f;
      res.perFragmentFar += far(a, f);
      if (far(a, v)) {
        ++res.perVertexFar;
        patches.insert(int(std::floor((a.x + 0.5) / grid * slices + 0.5)) % slices);  // its patch (Buss's s)
      }
    }
  res.reversedPatches = int(patches.size());
  // λ: the level of a coloured mip chain (GL_NEAREST_MIPMAP_NEAREST) against
  // the analytic one, λ = log2(N · max(|ds/dx|, |dt/dy|)) with, on the
  // cylinder seen along -z, ds/dx = px / (2π cos φ) (φ = asin of the view x)
  // and dt/dy = px / 2.  Pixels with |φ| < 60°: counted where the level is
  // more than 1 above.
  const int n = 256;
  ts::Frame lf = indexFrame(2 * kView, kView);
  lf.programs.push_back({kProgramName, projectorProgram()});
  int lt = lf.addTexture(ts::mipLevelColours(n));
  for (int k = 0; k < 2; ++k) {
    ts::Panel p = orthoPanel(k ? "grad" : "implicit", {k * kView, 0, kView, kView}, back);
    p.batches.push_back(glslBatch(cyl, Projector::Cylindrical, Axis::Y, Formula::Corrected, lt, k == 1));
    lf.panels.push_back(p);
  }
  ts::Image li = r.renderOffscreen(lf);
  const double px = 2.0 * kHalf / kView;
  for (int k = 0; k < 2; ++k)
    for (int y = 0; y < kView; ++y)
      for (int x = 0; x < kView; ++x) {
        double vx = -kHalf + (x + 0.5) * px, vy = kHalf - (y + 0.5) * px;
        if (std::abs(vx) > std::sin(kPi / 3) || std::abs(vy) > 0.95) continue;
        double phi = std::asin(vx);
        double rho = n * std::max(px / (2 * kPi * std::cos(phi)), px / 2);
        ts::Rgba c = li.at(k * kView + x, y);
        int level = -1;
        for (int l = 0; l < 9 && level < 0; ++l) {
          ts::Rgba w = ts::mipLevelColour(l);
          if (c.r == w.r && c.g == w.g && c.b == w.b) level = l;
        }
        if (level < 0) continue;
        if (level > std::log2(rho) + 1) (k ? res.lambdaGrad : res.lambdaImplicit) += 1;
      }
  return res;
}

// --- 3. Stretch: surface area per texture area, from the texel Jacobian -----
// The unit sphere face-on from `d` (ortho, kStretchPx); at each pixel the
// sphere's point and normal come from the pixel's position (ray and sphere),
// the texture Jacobian from the texels read ±kStep pixels away.  Stretch =
// (surface area / texture area) · s², 1 where the surface faces the axis.
constexpr int kStretchPx = 512, kStretchGrid = 4096, kStep = 4;
struct StretchSample {
  glm::dvec3 n;
  double stretch;
};
inline std::vector<StretchSample> stretchSamples(ts::Renderer& r, const Shape& s, Projector pr, Axis ax, glm::dvec3 d) {
  ts::Frame fr = indexFrame(kStretchPx, kStretchPx);
  fr.programs.push_back({kProgramName, projectorProgram()});
  ts::TextureDesc idx = ts::texelIndexTexture(kStretchGrid);
  int tex = fr.addTexture(idx);
  glm::mat4 mv = faceOn(d);
  ts::Panel p = orthoPanel("stretch", {0, 0, kStretchPx, kStretchPx}, mv);
  p.batches.push_back(glslBatch(s, pr, ax, Formula::Corrected, tex));
  fr.panels.push_back(p);
  Texels t = decode(r.renderOffscreen(fr));
  r.forgetTexture(idx);  // 64 MB: do not keep it
  const glm::dmat3 toModel = glm::transpose(glm::dmat3(glm::mat3(mv)));
  const double px = 2.0 * kHalf / kStretchPx;
  auto normalAt = [&](int x, int y, glm::dvec3* n) {
    double vx = -kHalf + (x + 0.5) * px, vy = kHalf - (y + 0.5) * px, z2 = 1 - vx * vx - vy * vy;
    if (z2 < 0.09) return false;  // keep to |n·v| >= 0.3
    *n = toModel * glm::dvec3(vx, vy, std::sqrt(z2));
    return true;
  };
  std::vector<StretchSample> out;
  for (int y = kStep; y < kStretchPx - kStep; ++y)
    for (int x = kStep; x < kStretchPx - kStep; ++x) {
      glm::dvec3 n, nb;
      if (!normalAt(x, y, &n)) continue;
      glm::ivec2 c[4] = {t(x + kStep, y), t(x - kStep, y), t(x, y - kStep), t(x, y + kStep)};  // right left up down
      const int pos[4][2] = {{x + kStep, y}, {x - kStep, y}, {x, y - kStep}, {x, y + kStep}};
      bool ok = t(x, y).x >= 0;
      for (int k = 0; k < 4 && ok; ++k) {
        ok = c[k].x >= 0 && normalAt(pos[k][0], pos[k][1], &nb);
        if (ok && pr == Projector::Box) ok = boxAxis(nb) == boxAxis(n);  // one face of the box
      }
      if (!ok) continue;
      // Texture coordinates per pixel (x right, y up), in texture units.
      glm::dvec2 dx = glm::dvec2(c[0] - c[1]) / (2.0 * kStep * kStretchGrid);
      glm::dvec2 dy = glm::dvec2(c[2] - c[3]) / (2.0 * kStep * kStretchGrid);
      double texArea = std::abs(dx.x * dy.y - dx.y * dy.x);
      if (texArea <= 0) continue;
      double nz = glm::dot(n, glm::dvec3(glm::transpose(glm::dmat3(glm::mat3(mv)))[2]));
      double surface = 1.0 / nz;  // per pixel², in pixel² units
      double texPerPx2 = texArea / (px * px);
      out.push_back({n, surface * kS * kS / texPerPx2});
    }
  return out;
}

// --- 4. OBJECT_LINEAR against EYE_LINEAR: one surface point as the object moves
// through the poses of projectors_pose.hpp.
constexpr int kSwimGrid = 32, kSwimPx = 256;
// The surface point: texel (20, 19)'s centre on the cube's +Z face.
inline glm::dvec3 swimPoint() { return {2.0 * (20.5 / kSwimGrid) - 1.0, 2.0 * (19.5 / kSwimGrid) - 1.0, 1.0}; }
inline ts::Frame swimFrame(GLenum mode, int texture, const Shape& cube, ts::Frame fr) {
  for (int k = 0; k < kPoses; ++k) {
    ts::Panel p = orthoPanel("pose_" + std::to_string(k), {(k % 4) * kSwimPx, (k / 4) * kSwimPx, kSwimPx, kSwimPx},
                             pose(k));
    // Eye planes given once, under pose 0's modelview: where the object was.
    p.batches.push_back(texGenBatch(cube, planarTexGen(Axis::Z, Formula::Corrected, mode, pose(0)), texture));
    fr.panels.push_back(p);
  }
  return fr;
}
inline int swimChanges(ts::Renderer& r, GLenum mode) {
  ts::Frame fr = indexFrame(4 * kSwimPx, 2 * kSwimPx);
  int tex = fr.addTexture(ts::texelIndexTexture(kSwimGrid));
  fr = swimFrame(mode, tex, shape(Object::Cube), fr);
  Texels t = decode(r.renderOffscreen(fr));
  int changes = 0;
  glm::ivec2 first(-2);
  for (int k = 0; k < kPoses; ++k) {
    const ts::Panel& p = fr.panels[size_t(k)];
    glm::vec2 px = ts::panelToPixels(p, p.projection * p.modelview * glm::vec4(glm::vec3(swimPoint()), 1.0f));
    glm::ivec2 v = t(int(px.x), int(px.y));
    if (k == 0) first = v;
    else changes += v != first;
  }
  return changes;
}

// --- 5. The slide projector ---------------------------------------------------
// The stage of projectors_pose.hpp from the camera: each pixel's texel against
// the CPU's (s/q, t/q) from the same planes, and the pixels behind the
// projector (q < 0) that show the slide.
constexpr int kSlidePx = 512, kSlideGrid = 64;
struct SlideResult {
  long mismatches = 0, checked = 0, back = 0;
};
inline SlideResult slideMeasure(ts::Renderer& r, bool clip) {
  const Slide sl = slideSetup();
  ts::Frame fr = indexFrame(kSlidePx, kSlidePx);
  ts::TextureDesc slide = ts::texelIndexTexture(kSlideGrid);
  slide.wrapS = slide.wrapT = GL_CLAMP_TO_BORDER;  // border (0,0,0,0): outside the slide = no texel
  int tex = fr.addTexture(slide);
  ts::Panel p;
  p.id = "stage";
  p.viewport = {0, 0, kSlidePx, kSlidePx};
  p.projection = glm::mat4(sl.camP);
  p.modelview = glm::mat4(sl.camV);
  p.depthTest = true;
  p.batches.push_back(slideBatch(sl, tex, clip));
  fr.panels.push_back(p);
  Texels t = decode(r.renderOffscreen(fr));
  const auto planes = slidePlanes(sl.projL, sl.viewL);
  const glm::dmat4 inv = glm::inverse(sl.camP * sl.camV);
  const glm::dvec3 eye = glm::dvec3(glm::inverse(sl.camV)[3]);
  SlideResult res;
  for (int y = 0; y < kSlidePx; ++y)
    for (int x = 0; x < kSlidePx; ++x) {
      // The pixel centre's ray, hitting the floor (y = 0) or the wall (z = -3).
      glm::dvec4 far = inv * glm::dvec4(2 * (x + 0.5) / kSlidePx - 1, 1 - 2 * (y + 0.5) / kSlidePx, 1, 1);
      glm::dvec3 dir = glm::dvec3(far) / far.w - eye;
      double best = 1e30;
      glm::dvec3 hit(0.0);
      double tf = -eye.y / dir.y, tw = (-3 - eye.z) / dir.z;
      glm::dvec3 pf = eye + tf * dir, pw = eye + tw * dir;
      if (tf > 0 && std::abs(pf.x) <= 4 && pf.z >= -3 && pf.z <= 4) best = tf, hit = pf;
      if (tw > 0 && tw < best && std::abs(pw.x) <= 4 && pw.y >= 0 && pw.y <= 4) best = tw, hit = pw;
      if (best == 1e30) continue;
      glm::dvec4 c = slideCoords(planes, hit);
      glm::ivec2 got = t(x, y);
      if (c.w < 0) {  // behind the projector
        res.back += got.x >= 0;
        continue;
      }
      glm::dvec2 st(c.x / c.w, c.y / c.w);
      if (c.w < 1e-6) continue;
      glm::dvec2 g = st * double(kSlideGrid);
      // A pixel centre within 1/1000 texel of a texel edge may round either way.
      glm::dvec2 fr2 = g - glm::floor(g);
      if (std::min({fr2.x, 1 - fr2.x, fr2.y, 1 - fr2.y}) < 1e-3) continue;
      ++res.checked;
      bool inside = st.x >= 0 && st.x < 1 && st.y >= 0 && st.y < 1;
      glm::ivec2 want = inside ? glm::ivec2(glm::floor(g)) : glm::ivec2(-1);
      res.mismatches += got != want;
    }
  return res;
}

// --- 6. A solid 3D texture against the sphere's Eq. VI.2 ---------------------
// Discontinuities (neighbouring pixels whose texels are more than 2 apart in
// any index) in the view of the seam (+Z), and the share of the texture's
// s columns met within 3 px of the north pole (view from +Y).
struct SolidResult {
  long seam = 0;
  double poleShare = 0;
};
inline SolidResult solidOrLatLong(ts::Renderer& r, bool solid) {
  const Shape sphere = fromMesh(sphereMesh(64));
  ts::Frame fr = indexFrame(2 * kView, kView);
  ts::TextureDesc t2 = ts::texelIndexTexture(kSolid);
  t2.wrapT = GL_CLAMP_TO_EDGE;
  int tex = fr.addTexture(solid ? solidIndexTexture() : t2);
  const glm::dvec3 dirs[2] = {{0, 0, 1}, {0, 1, 0}};
  for (int k = 0; k < 2; ++k) {
    ts::Panel p = orthoPanel(k ? "pole" : "seam", {k * kView, 0, kView, kView}, faceOn(dirs[k]));
    if (solid)
      p.batches.push_back(
          texGenBatch(sphere, planarTexGen(Axis::Z, Formula::Corrected, GL_OBJECT_LINEAR, glm::mat4(1.0f), true), tex));
    else p.batches.push_back(perVertexBatch(sphere, Projector::Planar, Axis::Z, Formula::Corrected, tex, true));
    fr.panels.push_back(p);
  }
  ts::Image img = r.renderOffscreen(fr);
  auto idx = [&](int x, int y) {  // (i, j, k), -1 where no object
    ts::Rgba c = img.at(x, y);
    if (c.a != 255) return glm::ivec3(-1);
    if (solid) return glm::ivec3(c.r / 4, c.g / 4, c.b / 4);
    int i = 0, j = 0;
    ts::decodeTexelIndex(c, &i, &j);
    return glm::ivec3(i, j, 0);
  };
  SolidResult res;
  const double px = 2.0 * kHalf / kView;
  for (int y = 0; y + 1 < kView; ++y)
    for (int x = 0; x + 1 < kView; ++x) {
      double vx = -kHalf + (x + 0.5) * px, vy = kHalf - (y + 0.5) * px;
      if (vx * vx + vy * vy > 0.8) continue;  // away from the silhouette
      glm::ivec3 a = idx(x, y), b = idx(x + 1, y), c = idx(x, y + 1);
      if (a.x < 0 || b.x < 0 || c.x < 0) continue;
      glm::ivec3 db = glm::abs(a - b), dc = glm::abs(a - c);
      res.seam += std::max({db.x, db.y, db.z, dc.x, dc.y, dc.z}) > 2;
    }
  std::set<int> cols;
  for (int y = kView / 2 - 4; y <= kView / 2 + 4; ++y)
    for (int x = kView + kView / 2 - 4; x <= kView + kView / 2 + 4; ++x) {
      if (std::hypot(x + 0.5 - (kView + kView / 2.0), y + 0.5 - kView / 2.0) > 3.0) continue;
      glm::ivec3 v = idx(x, y);
      if (v.x >= 0) cols.insert(v.x);
    }
  res.poleShare = double(cols.size()) / kSolid;
  return res;
}

// --- 7. The cube's faces face-on: corners and the Jacobian's sign -----------
struct CubeResult {
  int good = 0, smeared = 0, mirrored = 0, other = 0;
};
inline CubeResult cubeFaces(ts::Renderer& r, bool shared8) {
  const int grid = 64;
  std::vector<CubeVertex> q = shared8 ? cube8() : cube24();
  ts::Frame fr = indexFrame(6 * kView, kView);
  int tex = fr.addTexture(ts::texelIndexTexture(grid));
  const Shape cube = cubeShape(shared8);
  for (int f = 0; f < 6; ++f) {
    glm::dvec3 n = q[size_t(4 * f)].normal, u = q[size_t(4 * f + 1)].pos - q[size_t(4 * f)].pos;
    glm::dvec3 w = glm::cross(n, glm::normalize(u));
    glm::dmat4 rot(1.0);  // rows u, w, n: the face's u across, w up, n toward the viewer
    glm::dvec3 un = glm::normalize(u);
    for (int c = 0; c < 3; ++c) rot[c][0] = un[c], rot[c][1] = w[c], rot[c][2] = n[c];
    ts::Panel p = orthoPanel("face_" + std::to_string(f), {f * kView, 0, kView, kView}, glm::mat4(rot));
    p.projection = glm::ortho(-1.2f, 1.2f, -1.2f, 1.2f, -3.0f, 3.0f);
    p.batches.push_back(perVertexBatch(cube, Projector::Planar, Axis::Z, Formula::Corrected, tex, true));
    fr.panels.push_back(p);
  }
  Texels t = decode(r.renderOffscreen(fr));
  CubeResult res;
  for (int f = 0; f < 6; ++f) {
    const ts::Panel& p = fr.panels[size_t(f)];
    auto read = [&](glm::dvec3 m) {
      glm::vec2 px = ts::panelToPixels(p, p.projection * p.modelview * glm::vec4(glm::vec3(m), 1.0f));
      glm::ivec2 v = t(int(px.x), int(px.y));
      return glm::dvec2((v.x + 0.5) / grid, (v.y + 0.5) / grid);
    };
    // The four corners (inset to 85 %), counter-clockwise on the screen.
    glm::dvec3 c = q[size_t(4 * f)].normal;
    std::vector<glm::ivec2> corner;
    for (int k = 0; k < 4; ++k) {
      glm::dvec3 m = c + 0.85 * (q[size_t(4 * f + k)].pos - c);
      glm::dvec2 st = read(m);
      corner.push_back({st.x > 0.5, st.y > 0.5});
    }
    const glm::ivec2 unit[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    bool rotation = false;
    for (int sh = 0; sh < 4; ++sh) {
      bool all = true;
      for (int k = 0; k < 4; ++k) all = all && corner[size_t(k)] == unit[(k + sh) % 4];
      rotation = rotation || all;
    }
    // The Jacobian of (s, t) against screen (x right, y up), from 0.3-face steps.
    glm::dvec3 a = q[size_t(4 * f)].pos - c, b = q[size_t(4 * f + 1)].pos - c;  // corner directions
    glm::dvec3 ex = glm::normalize(b - a), ey = glm::cross(c, ex);
    glm::dvec2 ds = read(c + 0.3 * ex) - read(c - 0.3 * ex), dt = read(c + 0.3 * ey) - read(c - 0.3 * ey);
    double det = ds.x * dt.y - ds.y * dt.x;
    if (rotation && det > 0.05) ++res.good;
    else if (std::abs(det) <= 0.05) ++res.smeared;
    else if (det < 0) ++res.mirrored;
    else ++res.other;
  }
  return res;
}

// --- Everything above, as the demo prints it (state-independent) -------------
inline const char* const kAxisName[] = {"x", "y", "z"};
inline const char* const kProjName[] = {"planar", "cylindrical", "spherical", "box", "solid"};
inline ts::Measurements measureAll(ts::Renderer& r) {
  const char* const* kAxis = kAxisName;
  const char* const* kProj = kProjName;
  ts::Measurements out;
  const Shape sphere = shape(Object::Sphere);
  // 1. Seed 002 as printed against corrected, per projector and axis.
  for (int p = 0; p < 3; ++p)
    for (int a = 0; a < 3; ++a) {
      Texels tp = sixViews(r, sphere, Projector(p), Axis(a), Formula::Printed, Coords::Glsl, kGrid);
      Texels tc = sixViews(r, sphere, Projector(p), Axis(a), Formula::Corrected, Coords::Glsl, kGrid);
      ts::measureProgress(0.05 * (3 * p + a));
      Usage up = usage(tp, kGrid), uc = usage(tc, kGrid);
      std::string k = std::string(kProj[p]) + "_" + kAxis[a];
      out.push_back(
          {k + "_printed_columns", up.columns, "share of texture columns used, as printed (sphere, 6 views)"});
      out.push_back({k + "_printed_rows", up.rows, "share of texture rows used, as printed"});
      out.push_back({k + "_corrected_columns", uc.columns, "the same, corrected"});
      out.push_back({k + "_corrected_rows", uc.rows, "the same, corrected"});
      out.push_back({k + "_mismatch_share", mismatchShare(tp, tc), "pixels whose texel differs, printed vs corrected"});
      if (p == 0 && a == 2) {
        out.push_back(
            {"planar_z_diagonal_share", up.diagonal, "pixels with s = t (same texel column and row), as printed"});
        out.push_back({"planar_z_diagonal_share_corrected", uc.diagonal, "the same, corrected"});
      }
    }
  ts::measureProgress(0.5);
  // The spherical tv (minus ov) at the pole and at 45 deg latitude about Z.
  const int fine = 2048;
  auto tv = [&](Formula fo, glm::dvec3 pt) {
    return (texelAt(r, sphere, Projector::Spherical, Axis::Z, fo, pt, fine).y + 0.5) / fine - 0.5;
  };
  const double s45 = std::sqrt(0.5);
  out.push_back({"spherical_pole_tv", tv(Formula::Printed, {0, 0, 1}), "tv - 1/2 at the pole, as printed (arctg)"});
  out.push_back({"spherical_45_tv", tv(Formula::Printed, {0, s45, s45}), "tv - 1/2 at 45 deg latitude, as printed"});
  out.push_back({"spherical_pole_tv_corrected", tv(Formula::Corrected, {0, 0, 1}), "at the pole, arcsin"});
  out.push_back({"spherical_45_tv_corrected", tv(Formula::Corrected, {0, s45, s45}), "at 45 deg, arcsin"});
  // Opposite points across Z, (1,1,0)/sqrt2 and (-1,-1,0)/sqrt2: the same texel as printed?
  auto same = [&](Formula fo) {
    // The column only (tu): 1001 columns, so tu = 0.125 is no column edge.
    return double(texelAt(r, sphere, Projector::Cylindrical, Axis::Z, fo, {s45, s45, 0}, 1001).x ==
                  texelAt(r, sphere, Projector::Cylindrical, Axis::Z, fo, {-s45, -s45, 0}, 1001).x);
  };
  out.push_back({"cylindrical_opposite_collide", same(Formula::Printed), "1 if p and -p read one column, as printed"});
  out.push_back({"cylindrical_opposite_collide_corrected", same(Formula::Corrected), "the same, atan2"});
  ts::measureProgress(0.55);
  // 2. Corrected cylindrical = Buss's Eq. VI.1; the seam per vertex; the λ line.
  SeamResult seam = seamMeasure(r);
  out.push_back({"cylinder_buss_mismatches", double(seam.perFragmentMismatch),
                 "pixels, corrected cylindrical along Y per fragment vs Eq. VI.1 per vertex (any texel)"});
  out.push_back({"cylinder_buss_far", double(seam.perFragmentFar), "the same, more than 1 texel apart"});
  out.push_back({"cylinder_pervertex_seam_pixels", double(seam.perVertexFar),
                 "pixels > 1 texel off Eq. VI.1 with atan2 per vertex (Fig. VI.4's seam)"});
  out.push_back({"cylinder_pervertex_reversed_patches", double(seam.reversedPatches), "patches those pixels lie on"});
  out.push_back({"lambda_line_implicit", double(seam.lambdaImplicit),
                 "pixels whose mip level is > 1 above the analytic lambda, texture() per fragment"});
  out.push_back({"lambda_line_grad", double(seam.lambdaGrad), "the same with textureGrad (cut-free derivatives)"});
  ts::measureProgress(0.6);
  // 3. Stretch.
  const Shape fineSphere = fromMesh(sphereMesh(256));
  double worst = 0, sum = 0;
  long n = 0;
  for (const StretchSample& s : stretchSamples(r, fineSphere, Projector::Box, Axis::Z, {1, 1, 1}))
    worst = std::max(worst, s.stretch);
  for (const StretchSample& s : stretchSamples(r, fineSphere, Projector::Planar, Axis::Z,
                                               {std::sin(kPi * 80 / 180), 0, std::cos(kPi * 80 / 180)}))
    if (std::abs(std::acos(std::abs(s.n.z)) * 180 / kPi - 80) < 0.5) sum += s.stretch, ++n;
  out.push_back({"box_worst_stretch", worst, "largest surface/texture area ratio of box mapping (sqrt 3 = 1.732)"});
  out.push_back({"planar_stretch_80", n ? sum / double(n) : 0.0, "planar along Z, mean ratio at 79.5..80.5 deg"});
  ts::measureProgress(0.75);
  // 4. OBJECT_LINEAR against EYE_LINEAR.
  out.push_back(
      {"swim_changes_object_linear", double(swimChanges(r, GL_OBJECT_LINEAR)), "texel changes of one point, 7 moves"});
  out.push_back({"swim_changes_eye_linear", double(swimChanges(r, GL_EYE_LINEAR)), "the same with EYE_LINEAR"});
  // 5. The slide projector.
  SlideResult s0 = slideMeasure(r, false), s1 = slideMeasure(r, true);
  out.push_back(
      {"slide_mismatches", double(s0.mismatches + s1.mismatches), "texels differing from the CPU's (s/q, t/q)"});
  out.push_back({"slide_checked", double(s0.checked), "pixels checked (q > 0)"});
  out.push_back({"slide_back_pixels_nofix", double(s0.back), "pixels with q < 0 that show the slide, no fix"});
  out.push_back({"slide_back_pixels_clip", double(s1.back), "the same with the clip plane q >= 0"});
  ts::measureProgress(0.85);
  // 6. The solid texture against Eq. VI.2.
  SolidResult solid = solidOrLatLong(r, true), ll = solidOrLatLong(r, false);
  out.push_back({"solid3d_seam_pixels", double(solid.seam), "texel jumps > 2 between neighbours, 3D texture"});
  out.push_back({"latlong_seam_pixels", double(ll.seam), "the same, Eq. VI.2 (sphere_projections)"});
  out.push_back({"solid3d_pole_s_share", solid.poleShare, "share of s columns within 3 px of the pole, 3D"});
  out.push_back({"latlong_pole_s_share", ll.poleShare, "the same, Eq. VI.2: the pinch"});
  // 7. The cube.
  CubeResult c24 = cubeFaces(r, false), c8 = cubeFaces(r, true);
  out.push_back({"cube24_good_faces", double(c24.good), "faces reading the unit square, not mirrored (of 6)"});
  out.push_back({"cube8_good_faces", double(c8.good), "the same with 8 shared vertices"});
  out.push_back({"cube8_smeared_faces", double(c8.smeared), "faces with a zero Jacobian (s or t constant)"});
  out.push_back({"cube8_mirrored_faces", double(c8.mirrored), "faces with a negative Jacobian"});
  return out;
}
}  // namespace proj
