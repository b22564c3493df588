#include "reference.hpp"

#include <algorithm>
#include <cmath>

#include "common/core/error.hpp"
#include "common/core/text.hpp"
#include "combine.hpp"
#include "verify.hpp"

namespace ref {
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
    case Exempt::UnknownPicture: return "unknown picture";
    case Exempt::Count: break;
  }
  return "?";
}

void cubeFaceCoord(int face, const glm::dvec3& r, double* s, double* t) {
  double sc = 0, tc = 0, ma = 1;
  switch (face) {
    case 0: sc = -r.z, tc = -r.y, ma = r.x; break;
    case 1: sc = r.z, tc = -r.y, ma = -r.x; break;
    case 2: sc = r.x, tc = r.z, ma = r.y; break;
    case 3: sc = r.x, tc = -r.z, ma = -r.y; break;
    case 4: sc = r.x, tc = -r.y, ma = r.z; break;
    default: sc = -r.x, tc = -r.y, ma = -r.z; break;
  }
  *s = (sc / ma + 1.0) / 2.0, *t = (tc / ma + 1.0) / 2.0;
}
int cubeFace(const glm::dvec3& r, int* alt) {
  const double a[3] = {std::abs(r.x), std::abs(r.y), std::abs(r.z)};
  int k = a[0] >= a[1] && a[0] >= a[2] ? 0 : a[1] >= a[2] ? 1 : 2;
  int second = -1;
  for (int j = 0; j < 3; ++j)
    if (j != k && (second < 0 || a[j] > a[second])) second = j;
  auto faceOf = [&](int axis) { return 2 * axis + (r[axis] > 0 ? 0 : 1); };
  *alt = a[second] >= a[k] * (1.0 - 1e-4) ? faceOf(second) : -1;
  return faceOf(k);
}
namespace {
// The interpolated direction (s, t, r) at (x, y): the planes hold s/w, t/w,
// r/w, and the common positive factor 1/w does not change a direction.
glm::dvec3 cubeDirection(const ScreenPoly& P, double x, double y) {
  return {P.P[kS].at(x, y), P.P[kT].at(x, y), P.P[kR].at(x, y)};
}
// The derivatives of a face's (s, t) at (x, y), by central differences on
// that face (the LOD GL computes from the face coordinates of a 2x2 quad).
Deriv cubeFaceDeriv(const ScreenPoly& P, int face, double x, double y) {
  double s0, t0, s1, t1, s2, t2, s3, t3;
  cubeFaceCoord(face, cubeDirection(P, x - 0.5, y), &s0, &t0);
  cubeFaceCoord(face, cubeDirection(P, x + 0.5, y), &s1, &t1);
  cubeFaceCoord(face, cubeDirection(P, x, y - 0.5), &s2, &t2);
  cubeFaceCoord(face, cubeDirection(P, x, y + 0.5), &s3, &t3);
  return {s1 - s0, s3 - s2, t1 - t0, t3 - t2};
}
}  // namespace

// Nested frames: the texture's frame recomputed by a Reference
// of its own (the same options but a narrower edge band), its picture the
// texture's image.  Each texel keeps how wide the union of that frame's pixel's legal colour
// ranges is (GL's pixel lies in it, give or take the verifier's
// tolerance); where that frame's pixel is exempt (a line, a label, an
// unmodelled program) or wider than kNestedKnownSteps (a silhouette: the
// object on one side, the background on the other) the texel is unknown.
// An outer fragment reading an unknown texel is exempt (Exempt::Edge: an
// edge of the nested picture); one reading known texels gets their widest
// range plus the tolerance as its slack (Candidate::slack, verify.cpp).  An
// edge between two triangles of one textured surface stays known: both
// sides agree.
ts::TextureDesc Reference::nestedTexture(const ts::TextureDesc& t, size_t index) {
  constexpr float kNestedKnownSteps = 24.0f;
  // The edge band of the nested frame: GL snaps window coordinates to at
  // least GL_SUBPIXEL_BITS = 4 bits (the specification's minimum), so a
  // pixel centre more than 1/8 pixel inside a triangle is covered by it on
  // any conformant rasterizer.  The outer frame's 1-pixel band would leave
  // the background legal beside every edge between two triangles of one
  // surface, and the picture unknown along all of them.
  RenderOptions innerOptions = opts_;
  innerOptions.exemptTextures.clear();  // indices into the outer frame's textures
  innerOptions.edgeBand = std::min(opts_.edgeBand, 0.125);
  const Reference inner(*t.renderedFrom, innerOptions);
  for (const std::string& n : inner.notes()) note("the frame of texture '" + t.name + "': " + n);
  ts::TextureDesc d = t;
  d.image = std::make_shared<ts::Image>(inner.image());
  NestedTexels known;
  known.w = inner.width(), known.h = inner.height();
  known.width.assign(size_t(known.w) * size_t(known.h), -1.0f);
  VerifyOptions vo;
  vo.render = innerOptions;
  known.tolerance = float(vo.tolerance) / 255.0f;
  std::vector<Box> boxes;
  for (int y = 0; y < known.h; ++y)
    for (int x = 0; x < known.w; ++x) {
      Exempt why;
      legalAt(inner, x, y, vo, &boxes, &why);
      if (why != Exempt::None || boxes.empty()) continue;
      float width = 0;
      for (size_t k = 0; k < 4; ++k) {
        float lo = 2, hi = -1;
        for (const Box& b : boxes) lo = std::min(lo, b.lo[k]), hi = std::max(hi, b.hi[k]);
        width = std::max(width, hi - lo);
      }
      // Texel (x, y) is pixel (x, y): the texture's image is the frame's
      // picture as Renderer::render returns it (row 0 the top).
      if (width * 255.0f <= kNestedKnownSteps) known.width[size_t(y) * size_t(known.w) + size_t(x)] = width;
    }
  nested_.resize(std::max(nested_.size(), index + 1));
  nested_[index] = std::move(known);
  return d;
}

float Reference::nestedSlack(int texture, double s, double t, double rho) const {
  if (size_t(texture) >= nested_.size() || nested_[size_t(texture)].width.empty()) return 0.0f;
  const NestedTexels& n = nested_[size_t(texture)];
  const ts::TextureDesc& d = textures_[size_t(texture)].desc();
  // The texels GL_NEAREST and GL_LINEAR read for a coordinate within eps
  // texels of (s, t): the verifier's jitter (1/128 texel plus 1/128 pixel),
  // with room to spare; a mip-mapped texture's coarser levels average the
  // texels within rho of it.
  const double eps = 1.0 / 32 + rho / 32 + (textures_[size_t(texture)].mipmapped() ? rho : 0.0);
  const double u = s * n.w, v = t * n.h;
  float widest = 0;
  for (int j = int(std::floor(v - 0.5 - eps)); j <= int(std::floor(v + 0.5 + eps)); ++j)
    for (int i = int(std::floor(u - 0.5 - eps)); i <= int(std::floor(u + 0.5 + eps)); ++i) {
      const int wi = wrapTexel(d.wrapS == GL_CLAMP ? GL_CLAMP_TO_EDGE : d.wrapS, i, n.w);
      const int wj = wrapTexel(d.wrapT == GL_CLAMP ? GL_CLAMP_TO_EDGE : d.wrapT, j, n.h);
      if (wi < 0 || wj < 0 || wi >= n.w || wj >= n.h) continue;  // the border colour: known
      const float w = n.width[size_t(wj) * size_t(n.w) + size_t(wi)];
      if (w < 0) return -1.0f;
      widest = std::max(widest, w);
    }
  return widest + n.tolerance;
}

namespace {
// The `count` w x h pictures stacked in a texture's image (a cube map's
// faces, a 3D texture's slices) as plain 2D textures, named "[<what> k]".
void addStacked(const ts::TextureDesc& d, int w, int h, int count, const char* what, std::vector<Texture>* out) {
  for (int k = 0; k < count; ++k) {
    ts::TextureDesc sd = d;
    sd.cube = false, sd.depth = 1;
    sd.mipmaps = false;
    sd.mipLevels = nullptr;
    auto img = std::make_shared<ts::Image>(w, h);
    std::copy_n(d.image->pixels.begin() + std::ptrdiff_t(size_t(k) * size_t(w) * size_t(h) * 4),
                size_t(w) * size_t(h) * 4, img->pixels.begin());
    sd.image = img;
    sd.name += "[" + std::string(what) + " " + std::to_string(k) + "]";
    out->emplace_back(sd);
  }
}
}  // namespace

void Reference::addCubeFaces(const ts::Frame& f) {
  cubeFirstFace_.assign(f.textures.size(), -1);
  for (size_t i = 0; i < f.textures.size(); ++i) {
    // A nested frame's faces are the reference's own render of that frame (textures_[i]), not GL's picture.
    const ts::TextureDesc d = f.textures[i].renderedFrom ? textures_[i].desc() : f.textures[i];
    if (!d.cube || !d.image || d.image->height != 6 * d.image->width) continue;
    const int w = d.image->width;
    cubeFirstFace_[i] = int(textures_.size());
    addStacked(d, w, w, 6, "face", &textures_);
    // And the nested frame's known texels, face by face: face k is rows k w .. k w + w - 1 of its picture.
    if (i < nested_.size() && !nested_[i].width.empty()) {
      nested_.resize(textures_.size());
      for (int k = 0; k < 6; ++k) {
        NestedTexels& n = nested_[size_t(cubeFirstFace_[i] + k)];
        n.w = n.h = w, n.tolerance = nested_[i].tolerance;
        const auto first = nested_[i].width.begin() + std::ptrdiff_t(size_t(k) * size_t(w) * size_t(w));
        n.width.assign(first, first + std::ptrdiff_t(size_t(w) * size_t(w)));
      }
    }
  }
}

void Reference::addVolumes(const ts::Frame& f) {
  volumeOf_.assign(f.textures.size(), -1);
  for (size_t i = 0; i < f.textures.size(); ++i) {
    const ts::TextureDesc& d = f.textures[i];
    if (d.depth <= 1 || !d.image || d.image->height % d.depth != 0) continue;
    Volume v;
    v.first = int(textures_.size()), v.depth = d.depth, v.wrapR = d.wrapR;
    addStacked(d, d.image->width, d.image->height / d.depth, d.depth, "slice", &textures_);
    volumeOf_[i] = int(volumes_.size());
    volumes_.push_back(v);
  }
}

bool Reference::cubeCandidate(const ScreenPoly& P, double x, double y, int firstFace, bool alternative,
                              Candidate* c) const {
  int alt = -1;
  int face = cubeFace(cubeDirection(P, x, y), &alt);
  if (alternative) {
    if (alt < 0) return false;
    face = alt;
  }
  const Texture& tex = textures_[size_t(firstFace + face)];
  cubeFaceCoord(face, cubeDirection(P, x, y), &c->s, &c->t);
  c->texture = firstFace + face;
  const Deriv g = cubeFaceDeriv(P, face, x, y);
  const double e0 = tex.lod(g);
  c->rho = float(std::exp2(std::max(-30.0, e0)));
  double lo = e0, hi = e0;
  if (tex.mipmapped() || tex.desc().minFilter != tex.desc().magFilter) {
    tex.lodRange(g, opts_.lodModel, &lo, &hi);
    lo -= opts_.lodMargin, hi += opts_.lodMargin;
  }
  c->lodLo = float(lo), c->lodHi = float(hi);
  return true;
}

Colour Reference::cubeSample(const ScreenPoly& P, double x, double y, int firstFace) const {
  int alt = -1;
  const int face = cubeFace(cubeDirection(P, x, y), &alt);
  double s, t;
  cubeFaceCoord(face, cubeDirection(P, x, y), &s, &t);
  const Texture& tex = textures_[size_t(firstFace + face)];
  return tex.sample(s, t, tex.lod(cubeFaceDeriv(P, face, x, y)));
}

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
  clear_ = clampedColour(f.clearColor);
  image_ = ts::Image(f.width, f.height, toRgba(clear_));
  depth_.assign(size_t(f.width) * size_t(f.height), 1.0f);
  head_.assign(size_t(f.width) * size_t(f.height), -1);
  // Most covered pixels hold two candidates (the clear colour and a fragment),
  // edges, overlaps and labels more: reserved up front (address space only,
  // pages are touched as they fill), so the pool is not copied as it grows.
  pool_.reserve(size_t(f.width) * size_t(f.height) * 5 / 2);
  for (size_t i = 0; i < f.textures.size(); ++i)
    textures_.emplace_back(f.textures[i].renderedFrom ? nestedTexture(f.textures[i], i) : f.textures[i]);
  addCubeFaces(f);
  addVolumes(f);
  for (const auto& p : f.panels) drawPanel(p);
  if (opts_.labels) drawLabels(f);
}

void Reference::addLabels(const ts::Frame& f, bool geometryKnown) {
  if (opts_.labels) throw ts::Error("reference: the labels are drawn already", ts::kExitFailure);
  opts_.labels = true;
  opts_.labelGeometryKnown = geometryKnown;
  drawLabels(f);
}

void Reference::note(const std::string& s) {
  if (std::find(notes_.begin(), notes_.end(), s) == notes_.end()) notes_.push_back(s);
}

void Reference::place(int x, int y, const Candidate& c, bool sure, bool depthTest, GLenum depthFunc) {
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
    // The candidates whose z the depth buffer may hold: the pixel's, and beneath one that wrote no depth,
    // what it was drawn over (the depth that stayed).
    std::vector<int> chains = {h};
    for (size_t k = 0; k < chains.size(); ++k)
      for (int i = chains[k]; i >= 0; i = pool_[size_t(i)].next) {
        const Candidate& e = pool_[size_t(i)];
        if (!e.writesDepth && e.kind != Candidate::Kind::Exempt) {
          if (e.below >= 0) chains.push_back(e.below);
          else canPass = true;  // over the clear depth: nothing nearer held
          continue;
        }
        if (e.kind == Candidate::Kind::Exempt) {
          canPass = true, mustPass = false;
        } else if (depthFunc == GL_LEQUAL && c.z == e.z) {  // the same geometry again: GL's depth is the same too
          canPass = true;
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
  // Blended over what is there, or drawn without depth writes over the depth it leaves.
  if ((n.blended || !n.writesDepth) && n.kind != Candidate::Kind::Exempt) n.below = h;
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
  PixelRect sc = scissorRect(p, width_, height_);
  if (sc.x0 >= sc.x1 || sc.y0 >= sc.y1) return;
  if (p.clear) {
    Candidate c;
    c.colour = clampedColour(p.clearColor);
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
  const bool persp = opts_.interpolation == Interpolation::Perspective;

  // What the batch's fragments are.
  Candidate proto;
  proto.kind = Candidate::Kind::Flat;
  const Texture* tex = nullptr;
  const bool bilinear = isBilinearQuad(b);
  if (!b.program.empty()) {
    if (!bilinear) {
      proto.kind = Candidate::Kind::Exempt;
      proto.why = Exempt::Program;
      note("program '" + b.program + "' is not modelled: its pixels are exempt");
    }
  }
  // A picture the sidecar cannot remake (RenderOptions::exemptTextures): its texels are unknown.
  const auto unknownPicture = [&](int t) {
    return t >= 0 &&
           std::find(opts_.exemptTextures.begin(), opts_.exemptTextures.end(), t) != opts_.exemptTextures.end();
  };
  if (proto.kind != Candidate::Kind::Exempt && (unknownPicture(b.texture) || unknownPicture(b.texture1))) {
    proto.kind = Candidate::Kind::Exempt;
    proto.why = Exempt::UnknownPicture;
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
  proto.writesDepth = b.depthWrite;
  // A batch's own blend factors are modelled (Candidate::blended);
  // FixedState's blend is exempt as before.
  if (b.blend && b.blendFactors() && proto.kind != Candidate::Kind::Exempt) {
    proto.blended = true;
    proto.blendSrc = b.blendSrc, proto.blendDst = b.blendDst;
  } else if (b.blend && proto.kind != Candidate::Kind::Exempt) {
    proto.kind = Candidate::Kind::Exempt;
    proto.why = Exempt::Blend;
  }
  // A cube map: its faces are textures cubeFirstFace_ .. + 5; the
  // face and its (s, t) are chosen per fragment from the interpolated (s, t, r).
  const int cubeFirst = tex ? cubeFirstFace_[size_t(b.texture)] : -1;
  if (cubeFirst >= 0) tex = &textures_[size_t(cubeFirst)];
  // A 3D texture: sampled at (s, t, r) through its slices (volume.hpp), the
  // LOD from (s, t) on a slice; modelled with minFilter == magFilter only.
  const int volumeIndex = tex && cubeFirst < 0 ? volumeOf_[size_t(b.texture)] : -1;
  if (volumeIndex >= 0) {
    tex = &textures_[size_t(volumes_[size_t(volumeIndex)].first)];
    if (tex->desc().minFilter != tex->desc().magFilter && proto.kind == Candidate::Kind::Textured) {
      proto.kind = Candidate::Kind::Exempt;
      proto.why = Exempt::Unsupported;
      note("a 3D texture with different min and mag filters is not modelled: its pixels are exempt");
    }
  }
  const bool needLod = tex && (tex->mipmapped() || tex->desc().minFilter != tex->desc().magFilter);
  // Unit 1, a 2D texture read at unit 0's (s, t), modelled when
  // unit 0 is a plain 2D texture without texgen or texture matrix.
  // (A blended batch's candidates are exempt, but its reference picture still has unit 1.)
  const Texture* tex1 = nullptr;
  if (b.texture1 >= 0 && (tex || proto.kind != Candidate::Kind::Exempt)) {
    // Unit 1's coordinates are its own planes (kS1 ..: Vertex::tex1 or unit 0's as sent, times textureMatrix1).
    const bool plain = tex && cubeFirst < 0 && volumeIndex < 0 && !b.texGen.on() &&
                       b.textureMatrix == glm::mat4(1.0f) && b.program.empty() &&
                       cubeFirstFace_[size_t(b.texture1)] < 0 && volumeOf_[size_t(b.texture1)] < 0;
    if (plain && unitEnvModelled(b.texEnv1, b.combine1) && texEnvModelled(b.texEnv)) {
      tex1 = &textures_.at(size_t(b.texture1));
    } else if (proto.kind != Candidate::Kind::Exempt) {
      proto.kind = Candidate::Kind::Exempt;
      proto.why = Exempt::Unsupported;
      note("this second texture unit's state is not modelled: its pixels are exempt");
    }
  }
  const bool needLod1 = tex1 && (tex1->mipmapped() || tex1->desc().minFilter != tex1->desc().magFilter);

  for (size_t i = 0; i + 2 < b.vertices.size(); i += 3) {
    ScreenPoly P;
    if (!screenTriangle(p, b, i, height_, persp, &P)) continue;

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
    if (tex && cubeFirst < 0 && P.constantDeriv) lodAt(P.v[0].x, P.v[0].y, &constLo, &constHi, &constRho);

    // A cube map rendered from a nested frame (its faces the reference's render): a face texel's legal range,
    // or exempt where it lies on an edge of that frame's picture, as for a 2D nested frame below.
    auto cubeSlack = [&](Candidate* c) {
      c->slack = nestedSlack(c->texture, c->s, c->t, c->rho);
      if (c->slack < 0) c->kind = Candidate::Kind::Exempt, c->why = Exempt::Edge, c->slack = 0;
    };
    auto candidateAt = [&](double x, double y) {
      Candidate c = proto;
      c.z = float(P.P[kZ].at(x, y));
      c.colour = P.colour(x, y);
      if (c.colorSum) c.secondary = P.secondary(x, y);
      if (c.kind == Candidate::Kind::Textured && cubeFirst >= 0) {
        cubeCandidate(P, x, y, cubeFirst, false, &c);
        cubeSlack(&c);
      } else if (c.kind == Candidate::Kind::Textured) {
        P.coord(x, y, &c.s, &c.t);
        if (volumeIndex >= 0) {
          c.volume = volumeIndex;
          c.texture = volumes_[size_t(volumeIndex)].first;
          c.r = P.P[kR].at(x, y) / P.P[kQ].at(x, y);
        }
        if (P.constantDeriv) c.lodLo = constLo, c.lodHi = constHi, c.rho = constRho;
        else lodAt(x, y, &c.lodLo, &c.lodHi, &c.rho);
        c.slack = nestedSlack(c.texture, c.s, c.t, c.rho);
        if (c.slack < 0) {  // reads an edge of a nested frame's picture
          c.kind = Candidate::Kind::Exempt;
          c.why = Exempt::Edge;
        } else if (c.texture >= 0) {  // a remade picture GL may round its own way (TextureDesc::texelSlack)
          c.slack = std::max(c.slack, textures_[size_t(c.texture)].desc().texelSlack / 255.0f);
        }
        if (volumeIndex >= 0) {  // the position jitter in r: slices per pixel
          auto rAt = [&](double u, double v) { return P.P[kR].at(u, v) / P.P[kQ].at(u, v); };
          const double slices = std::max(std::abs(rAt(x + 0.5, y) - rAt(x - 0.5, y)),
                                         std::abs(rAt(x, y + 0.5) - rAt(x, y - 0.5))) *
                                volumes_[size_t(volumeIndex)].depth;
          c.rho = std::max(c.rho, float(slices));
        }
      }
      if (tex1 && c.kind == Candidate::Kind::Textured) {  // unit 1 at its own (s, t)
        const Deriv g = P.deriv1(x, y);
        P.coord1(x, y, &c.s1, &c.t1);
        const double e = tex1->lod(g);
        double lo = e, hi = e;
        if (needLod1) {
          tex1->lodRange(g, opts_.lodModel, &lo, &hi);
          lo -= opts_.lodMargin, hi += opts_.lodMargin;
        }
        c.texture1 = b.texture1;
        c.lodLo1 = float(lo), c.lodHi1 = float(hi), c.rho1 = float(std::exp2(std::max(-30.0, e)));
        c.env1 = b.texEnv1;
        c.combine1 = b.combine1;
      }
      return c;
    };

    // 1. The reference picture: the scanline rasterizer over the polygon's
    // fan, each centre textured at its exact coordinate and LOD.
    auto emit = [&](int x, int y, const double* a) {
      size_t idx = size_t(y) * size_t(width_) + size_t(x);
      float z = float(a[kZ]);
      if (p.depthTest && !(b.depthFunc == GL_LEQUAL ? z <= depth_[idx] : z < depth_[idx])) return;
      Colour col{float(clamp01(a[kCr] / a[kW])), float(clamp01(a[kCg] / a[kW])), float(clamp01(a[kCb] / a[kW])),
                 float(clamp01(a[kCa] / a[kW]))};
      Colour sec{float(clamp01(a[kSr] / a[kW])), float(clamp01(a[kSg] / a[kW])), float(clamp01(a[kSb] / a[kW])), 0.0f};
      Colour texel{};
      if (tex && cubeFirst >= 0) {
        texel = cubeSample(P, x + 0.5, y + 0.5, cubeFirst);
      } else if (tex && volumeIndex >= 0) {
        texel = volume(volumeIndex)
                    .sample(a[kS] / a[kQ], a[kT] / a[kQ], a[kR] / a[kQ], tex->lod(P.deriv(x + 0.5, y + 0.5)));
      } else if (tex) {
        double s, t;
        P.coordFrom(a[kS] / a[kQ], a[kT] / a[kQ], &s, &t);
        texel = tex->sample(s, t, tex->lod(P.deriv(x + 0.5, y + 0.5)));
      }
      Colour out = shadeFragment(b, col, sec, tex ? &texel : nullptr);
      if (tex1) {  // unit 1 over unit 0's result, then the colour sum
        const Colour texel1 = tex1->sample(a[kS1] / a[kQ1], a[kT1] / a[kQ1], tex1->lod(P.deriv1(x + 0.5, y + 0.5)));
        const Colour prev = texEnv(b.texEnv, col, texel, {b.envColor.r, b.envColor.g, b.envColor.b, b.envColor.a});
        out = unitEnv(b.texEnv1, b.combine1, prev, texel1, col);
        if (b.colorSum) out = colourSum(out, sec);
      }
      // A fragment failing the alpha test is discarded (no colour,
      // no depth); a batch's own blend factors act on colour, alpha stays.
      if (b.alphaTest() && !alphaPasses(b.alphaFunc, out[3], b.alphaRef)) return;
      if (b.blend && b.blendFactors()) {
        out = blendWith(b.blendSrc, b.blendDst, out, toColour(image_.at(x, y)));
      } else if (b.blend) {
        Colour dst = toColour(image_.at(x, y));
        float al = out[3];
        for (size_t k = 0; k < 4; ++k) out[k] = out[k] * al + dst[k] * (1 - al);
      }
      image_.set(x, y, toRgba(out));
      if (p.depthTest && b.depthWrite) depth_[idx] = z;
    };
    for (size_t k = 1; k + 1 < P.v.size(); ++k)
      scanTriangle(P.v[0], P.v[k], P.v[k + 1], kAttributes, sc, opts_.fill, emit);

    // 2. The candidates: sure inside, either way within the edge band.
    double minx = 1e300, maxx = -1e300, miny = 1e300, maxy = -1e300;
    for (const auto& s : P.v)
      minx = std::min(minx, s.x), maxx = std::max(maxx, s.x), miny = std::min(miny, s.y), maxy = std::max(maxy, s.y);
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
        const Candidate c = candidateAt(cx, cy);
        if (b.alphaTest() && c.kind != Candidate::Kind::Exempt) {  // the alpha test drops what surely fails it
          const int verdict = alphaVerdict(b, c);
          if (verdict == 0) continue;  // discarded: no colour, no depth
          if (verdict < 0) sure = false;
        }
        place(x, y, c, sure, p.depthTest, b.depthFunc ? b.depthFunc : GLenum(GL_LESS));
        // Near a cube's face boundary either face is legal.
        Candidate other = c;
        if (cubeFirst >= 0 && c.kind == Candidate::Kind::Textured &&
            cubeCandidate(P, cx, cy, cubeFirst, true, &other)) {
          cubeSlack(&other);
          place(x, y, other, false, p.depthTest, b.depthFunc ? b.depthFunc : GLenum(GL_LESS));
        }
      }
  }
}

// ---- the alpha test and blend factors ---------------------------------------
bool alphaPasses(GLenum func, float alpha, float ref) {
  ref = std::min(1.0f, std::max(0.0f, ref));
  switch (func) {
    case GL_NEVER: return false;
    case GL_LESS: return alpha < ref;
    case GL_EQUAL: return alpha == ref;
    case GL_LEQUAL: return alpha <= ref;
    case GL_GREATER: return alpha > ref;
    case GL_NOTEQUAL: return alpha != ref;
    case GL_GEQUAL: return alpha >= ref;
    default: return true;  // GL_ALWAYS
  }
}

namespace {
float blendFactor(GLenum f, int k, const Colour& src, const Colour& dst) {
  switch (f) {
    case GL_ZERO: return 0.0f;
    case GL_ONE: return 1.0f;
    case GL_SRC_COLOR: return src[size_t(k)];
    case GL_ONE_MINUS_SRC_COLOR: return 1.0f - src[size_t(k)];
    case GL_DST_COLOR: return dst[size_t(k)];
    case GL_ONE_MINUS_DST_COLOR: return 1.0f - dst[size_t(k)];
    case GL_SRC_ALPHA: return src[3];
    case GL_ONE_MINUS_SRC_ALPHA: return 1.0f - src[3];
    default: return 1.0f;
  }
}
}  // namespace

Colour blendWith(GLenum srcFactor, GLenum dstFactor, const Colour& src, const Colour& dst) {
  Colour out = dst;  // alpha: FixedState's (GL_ZERO, GL_ONE) keeps the framebuffer's
  for (int k = 0; k < 3; ++k)
    out[size_t(k)] = float(clamp01(src[size_t(k)] * blendFactor(srcFactor, k, src, dst) +
                                   dst[size_t(k)] * blendFactor(dstFactor, k, src, dst)));
  return out;
}

int Reference::alphaVerdict(const ts::Batch& b, const Candidate& c) const {
  // The candidate's legal alpha, as verify.cpp's legalAt bounds it with the
  // default VerifyOptions (coordinate jitter, colour epsilon), widened by
  // the tolerance of 8 bits: within that of the reference value GL's
  // comparison may go either way.
  const VerifyOptions vo;
  const double eps = double(vo.tolerance + 1) / 255.0;
  double lo = c.colour[3] - vo.colourEps, hi = c.colour[3] + vo.colourEps;
  if (c.kind == Candidate::Kind::Textured) {
    if (c.volume >= 0 || c.texture1 >= 0) return -1;
    std::vector<Box> boxes;
    const double jitter = vo.positionEpsPixels * double(c.rho);
    textures_[size_t(c.texture)].legal(c.s, c.t, c.lodLo, c.lodHi, vo.nearestEpsTexels + jitter,
                                       vo.linearEpsTexels + jitter, &boxes);
    if (boxes.empty()) return -1;
    Box col;
    for (size_t k = 0; k < 4; ++k)
      col.lo[k] = float(std::max(0.0, double(c.colour[k]) - vo.colourEps)),
      col.hi[k] = float(std::min(1.0, double(c.colour[k]) + vo.colourEps));
    lo = 2, hi = -1;
    for (Box bx : boxes) {
      if (c.env != GL_REPLACE) bx = texEnvBox(c.env, col, bx, c.envColour);
      lo = std::min(lo, double(bx.lo[3]) - c.slack), hi = std::max(hi, double(bx.hi[3]) + c.slack);
    }
  }
  const bool atLo = alphaPasses(b.alphaFunc, float(lo - eps), b.alphaRef),
             atHi = alphaPasses(b.alphaFunc, float(hi + eps), b.alphaRef);
  const bool mid = alphaPasses(b.alphaFunc, float((lo + hi) / 2), b.alphaRef);
  if (b.alphaFunc == GL_EQUAL || b.alphaFunc == GL_NOTEQUAL) return -1;
  if (atLo && atHi && mid) return 1;
  if (!atLo && !atHi && !mid) return 0;
  return -1;
}

void Reference::drawLines(const ts::Panel& p, const ts::Batch& b, PixelRect sc) {
  Candidate ex;
  ex.kind = Candidate::Kind::Exempt;
  if (b.prim == ts::Prim::Points) {
    ex.why = Exempt::Point;
    double r = b.pointSize * 0.5 * std::sqrt(2.0) + opts_.lineMargin;
    for (const auto& v : b.vertices) {
      glm::dvec2 w;
      if (!windowPoint(p, v, height_, &w)) continue;
      exemptDisc(w.x, w.y, r, Exempt::Point, sc);
      // The reference picture: a square point.
      PixelRect sq = pointSquare(w, b.pointSize);
      for (int y = std::max(sc.y0, sq.y0); y < std::min(sc.y1, sq.y1); ++y)
        for (int x = std::max(sc.x0, sq.x0); x < std::min(sc.x1, sq.x1); ++x)
          image_.set(x, y, toRgba({v.color.r, v.color.g, v.color.b, v.color.a}));
    }
    return;
  }
  ex.why = Exempt::Line;
  const double half = lineHalfWidth(b);
  const double r = half * std::sqrt(2.0) + opts_.lineMargin;
  for (const WindowSegment& seg : windowSegments(p, b, height_)) {
    const glm::dvec2 &a = seg.a, &c = seg.c;
    int x0 = std::max(sc.x0, int(std::floor(std::min(a.x, c.x) - r))),
        x1 = std::min(sc.x1, int(std::ceil(std::max(a.x, c.x) + r)) + 1);
    int y0 = std::max(sc.y0, int(std::floor(std::min(a.y, c.y) - r))),
        y1 = std::min(sc.y1, int(std::ceil(std::max(a.y, c.y) + r)) + 1);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        double u;
        double dist = segmentDistance(seg, glm::dvec2(x + 0.5, y + 0.5), &u);
        if (dist > r) continue;
        place(x, y, ex, false, false);
        if (dist <= half) {
          glm::vec4 col = glm::mix(b.vertices[seg.ia].color, b.vertices[seg.ib].color, float(u));
          image_.set(x, y, toRgba({col.r, col.g, col.b, col.a}));
        }
      }
  }
}

void paintLabel(ts::Image& img, const ts::Label& l, int ox, int oy) {
  float w = ts::text::width(l.text, l.scale), h = ts::text::height(l.scale);
  float x = l.align == ts::Align::Left ? l.x : l.align == ts::Align::Center ? l.x - w / 2 : l.x - w;
  x = float(int(x));  // render.cpp truncates
  float y = float(int(l.y));
  if (l.background.a > 0) {
    float pad = 3.0f * float(l.scale);
    for (int py = std::max(oy, int(y - pad)); py < std::min(oy + img.height, int(std::ceil(y + h + pad))); ++py)
      for (int px = std::max(ox, int(x - pad)); px < std::min(ox + img.width, int(std::ceil(x + w + pad))); ++px) {
        Colour d = toColour(img.at(px - ox, py - oy));
        Colour o;
        for (size_t k = 0; k < 4; ++k) o[k] = l.background[int(k)] * l.background.a + d[k] * (1 - l.background.a);
        img.set(px - ox, py - oy, toRgba(o));
      }
  }
  ts::text::draw(img, x - float(ox), y - float(oy), l.text, toRgba({l.color.r, l.color.g, l.color.b, l.color.a}),
                 l.scale);
}

void Reference::drawLabels(const ts::Frame& f) {
  Candidate ex;
  ex.kind = Candidate::Kind::Exempt;
  ex.why = Exempt::Label;
  for (const ts::Label& l : f.labels) {
    PixelRect r = labelBox(l, 2, opts_.labelGeometryKnown);
    for (int y = std::max(0, r.y0); y < std::min(height_, r.y1); ++y)
      for (int x = std::max(0, r.x0); x < std::min(width_, r.x1); ++x) place(x, y, ex, false, false);
    // The reference picture: background box and text as render.cpp draws them.
    if (opts_.labelGeometryKnown) paintLabel(image_, l, 0, 0);
  }
}
}  // namespace ref
