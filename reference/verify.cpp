#include "verify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "common/core/error.hpp"
#include "combine.hpp"
#include "common/core/test_hooks.hpp"

namespace ref {
namespace {
std::string rgba(ts::Rgba c) {
  return "(" + std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b) + "," + std::to_string(c.a) +
         ")";
}
std::string box(const Box& b) {
  ts::Rgba lo = toRgba(b.lo), hi = toRgba(b.hi);
  if (lo == hi) return rgba(lo);
  return rgba(lo) + ".." + rgba(hi);
}
bool inside(ts::Rgba c, const Box& b, int tol) {
  const int v[4] = {c.r, c.g, c.b, c.a};
  for (size_t k = 0; k < 4; ++k) {
    long lo = std::lround(double(b.lo[k]) * 255.0) - tol, hi = std::lround(double(b.hi[k]) * 255.0) + tol;
    if (v[k] < lo || v[k] > hi) return false;
  }
  return true;
}
Box widen(const Colour& c, double e) {
  Box b;
  for (size_t k = 0; k < 4; ++k) b.lo[k] = float(std::max(0.0, c[k] - e)), b.hi[k] = float(std::min(1.0, c[k] + e));
  return b;
}
std::string writeImage(const std::string& dir, const std::string& stem, const char* kind, const ts::Image& img,
                       std::vector<std::string>* files) {
  std::string path = dir + "/" + stem + "." + kind + ".png";
  try {
    ts::writePng(path, img);
    files->push_back(path);
  } catch (const ts::Error& e) {
    files->push_back(std::string("(not written: ") + e.what() + ")");
  }
  return path;
}
}  // namespace

std::string failureDir(const std::string& requested) {
  std::string dir = requested;
  if (dir.empty()) {
    dir = ts::test_hooks::oracleOutDir();
    if (dir.empty()) dir = "oracle_failures";
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  return dir;
}

namespace {
// What a blended candidate's `below` holds, computed once per pixel: the
// legal colours from candidate `below` on, widened by half a step (GL
// stored them in 8 bits), or why they are exempt.  A mesh's second pass
// (GL_ONE, GL_ONE) over its first stacks many layers near shared vertices
// and edges, each blended candidate's `below` a chain holding the blended
// ones before it: followed afresh every time, the work grows with the
// number of paths through the layers; kept here by candidate index, it
// grows with the chain's length.  A pure function of the index within one
// Reference, so what is legal does not change.
struct BelowMemo {
  std::vector<std::pair<int, size_t>> index;  // candidate -> slot
  std::vector<std::vector<Box>> boxes;
  std::vector<Exempt> why;
  size_t used = 0;
  void clear() { index.clear(), used = 0; }
};
// The legal colours of a pixel from candidate h on (a blended
// candidate's `below`), as legalAt.
void legalFrom(const Reference& r, int h, const VerifyOptions& o, std::vector<Box>* outp, Exempt* why, BelowMemo* memo);

// src * srcFactor + dst * dstFactor per channel over boxes: multilinear in
// the colours, so the extremes lie on the corners (alpha: the framebuffer's).
Box blendBox(GLenum sf, GLenum df, const Box& s, const Box& d) {
  // Factors of 1, 0 or a colour in [0, 1] (adding, multiplying): the blend
  // rises with every input, so the low corner and the high corner bound it.
  auto rising = [](GLenum f) { return f == GL_ONE || f == GL_ZERO || f == GL_SRC_COLOR || f == GL_DST_COLOR; };
  if (rising(sf) && rising(df)) return {blendWith(sf, df, s.lo, d.lo), blendWith(sf, df, s.hi, d.hi)};
  Box o{{2, 2, 2, 2}, {-1, -1, -1, -1}};
  for (int corner = 0; corner < 16; ++corner) {
    Colour sc = s.lo, dc = d.lo;
    for (size_t k = 0; k < 3; ++k) {
      if (corner & 1) sc[k] = s.hi[k];
      if (corner & 2) dc[k] = d.hi[k];
    }
    if (corner & 4) sc[3] = s.hi[3];
    if (corner & 8) dc[3] = d.hi[3];
    const Colour v = blendWith(sf, df, sc, dc);
    for (size_t k = 0; k < 4; ++k) o.lo[k] = std::min(o.lo[k], v[k]), o.hi[k] = std::max(o.hi[k], v[k]);
  }
  return o;
}
}  // namespace

void legalAt(const Reference& r, int x, int y, const VerifyOptions& o, std::vector<Box>* outp, Exempt* why) {
  thread_local BelowMemo memo;  // one pixel's: candidate indices are the pixel's own
  memo.clear();
  legalFrom(r, r.head(x, y), o, outp, why, &memo);
}

namespace {
// The legal colours beneath a blended candidate: what the pixel held from
// candidate `below` on, GL's 8-bit storage of it (half a step either way);
// *why != None: exempt.  Memoised per pixel (BelowMemo).
const std::vector<Box>& legalBelow(const Reference& r, int below, const VerifyOptions& o, Exempt* why,
                                   BelowMemo* memo) {
  for (const auto& [c, slot] : memo->index)
    if (c == below) return *why = memo->why[slot], memo->boxes[slot];
  std::vector<Box> held;
  Exempt heldWhy;
  legalFrom(r, below, o, &held, &heldWhy, memo);
  for (Box& d : held)  // GL stored what the pixel held in 8 bits: half a step either way
    for (size_t k = 0; k < 3; ++k)
      d.lo[k] = std::max(0.0f, d.lo[k] - 0.5f / 255), d.hi[k] = std::min(1.0f, d.hi[k] + 0.5f / 255);
  const size_t slot = memo->used++;  // slots are reused across pixels (their vectors keep their capacity)
  if (memo->boxes.size() <= slot) memo->boxes.emplace_back(), memo->why.emplace_back();
  memo->boxes[slot] = std::move(held), memo->why[slot] = heldWhy;
  memo->index.push_back({below, slot});
  *why = heldWhy;
  return memo->boxes[slot];
}

void legalFrom(const Reference& r, int h, const VerifyOptions& o, std::vector<Box>* outp, Exempt* why,
               BelowMemo* memo) {
  std::vector<Box>& out = *outp;
  out.clear();
  *why = Exempt::None;
  if (h < 0) {
    out.push_back(widen(r.clearColour(), 0.0));
    return;
  }
  for (int i = h; i >= 0; i = r.candidate(i).next) {
    const Candidate& c = r.candidate(i);
    const size_t start = out.size();  // this candidate's boxes begin here
    switch (c.kind) {
      case Candidate::Kind::Exempt:
        *why = c.why;
        out.clear();
        return;
      case Candidate::Kind::Flat: {
        Box b = widen(c.colour, o.colourEps);
        if (c.colorSum) {
          Box sec = widen(c.secondary, o.colourEps);
          b.lo = colourSum(b.lo, sec.lo), b.hi = colourSum(b.hi, sec.hi);
        }
        out.push_back(b);
        break;
      }
      case Candidate::Kind::Textured: {
        const Texture& t = r.textures()[size_t(c.texture)];
        double jitter = o.positionEpsPixels * double(c.rho);
        size_t first = out.size();
        if (c.volume >= 0)  // a 3D texture (volume.hpp); r's jitter in slices is taken as s and t's in texels
          r.volume(c.volume).legal(c.s, c.t, c.r, c.lodLo, c.lodHi, o.nearestEpsTexels + jitter,
                                   o.linearEpsTexels + jitter, &out);
        else t.legal(c.s, c.t, c.lodLo, c.lodHi, o.nearestEpsTexels + jitter, o.linearEpsTexels + jitter, &out);
        if (c.slack > 0)  // a nested frame's picture, or TextureDesc::texelSlack
          for (size_t k = first; k < out.size(); ++k)
            for (size_t ch = 0; ch < 4; ++ch) out[k].lo[ch] -= c.slack, out[k].hi[ch] += c.slack;
        if (c.env != GL_REPLACE) {  // the environment's table over the boxes (exact for GL_MODULATE as before)
          Box col = widen(c.colour, o.colourEps);
          for (size_t k = first; k < out.size(); ++k) out[k] = texEnvBox(c.env, col, out[k], c.envColour);
        }
        if (c.texture1 >= 0) {  // unit 1's texels over unit 0's result (combine.hpp)
          std::vector<Box> texels1;
          const double j1 = o.positionEpsPixels * double(c.rho1);
          r.textures()[size_t(c.texture1)].legal(c.s1, c.t1, c.lodLo1, c.lodHi1, o.nearestEpsTexels + j1,
                                                 o.linearEpsTexels + j1, &texels1);
          const Box primary = widen(c.colour, o.colourEps);
          const std::vector<Box> unit0(out.begin() + std::ptrdiff_t(first), out.end());
          out.resize(first);
          for (const Box& p : unit0)
            for (const Box& t1 : texels1) out.push_back(unitEnvBox(c.env1, c.combine1, p, t1, primary));
        }
        if (c.colorSum) {  // monotone in both: the sum of the boxes' ends
          Box sec = widen(c.secondary, o.colourEps);
          for (size_t k = first; k < out.size(); ++k)
            out[k].lo = colourSum(out[k].lo, sec.lo), out[k].hi = colourSum(out[k].hi, sec.hi);
        }
        break;
      }
    }
    if (c.blended && c.blendSrc == GL_ONE && c.blendDst == GL_ZERO) {
      // The colour as drawn, the pixel's alpha kept: what it held is not
      // followed (its chain may be deep, a mesh's layers), the alpha left free.
      for (size_t k = start; k < out.size(); ++k) out[k].lo[3] = 0.0f, out[k].hi[3] = 1.0f;
    } else if (c.blended) {  // this fragment's boxes blended over what the pixel held
      Exempt belowWhy;
      const std::vector<Box>& below = legalBelow(r, c.below, o, &belowWhy, memo);  // valid until the next legalBelow
      if (belowWhy != Exempt::None) {
        *why = belowWhy;
        out.clear();
        return;
      }
      const std::vector<Box> src(out.begin() + std::ptrdiff_t(start), out.end());
      out.resize(start);
      if (src.size() * below.size() <= 16) {
        for (const Box& s : src)
          for (const Box& d : below) out.push_back(blendBox(c.blendSrc, c.blendDst, s, d));
      } else {  // many layers of alternatives: the blend of their hulls (looser, still legal: the corners of both)
        auto hullOf = [](const std::vector<Box>& v) {
          Box u{{2, 2, 2, 2}, {-1, -1, -1, -1}};
          for (const Box& b : v)
            for (size_t k = 0; k < 4; ++k) u.lo[k] = std::min(u.lo[k], b.lo[k]), u.hi[k] = std::max(u.hi[k], b.hi[k]);
          return u;
        };
        out.push_back(blendBox(c.blendSrc, c.blendDst, hullOf(src), hullOf(below)));
      }
    }
  }
}
}  // namespace

VerifyResult verifyImage(const ts::Image& got, const ts::Frame& frame, const VerifyOptions& o) {
  Reference r(frame, o.render);
  return verifyImage(got, r, o);
}

VerifyResult verifyImage(const ts::Image& got, const Reference& r, const VerifyOptions& o) {
  VerifyResult res;
  res.name = o.name;
  res.maxInvalid = o.maxInvalid;
  res.notes = r.notes();
  res.reference = r.image();
  if (got.width != r.width() || got.height != r.height()) {
    res.invalid = 1;
    res.checked = 1;
    res.notes.push_back("image is " + std::to_string(got.width) + "x" + std::to_string(got.height) + ", the frame " +
                        std::to_string(r.width()) + "x" + std::to_string(r.height()));
    return res;
  }
  res.mask = ts::Image(got.width, got.height, {0, 0, 0, 255});
  std::vector<Box> legal;
  legal.reserve(16);
  for (int y = 0; y < got.height; ++y)
    for (int x = 0; x < got.width; ++x) {
      ++res.pixels;
      Exempt why;
      legalAt(r, x, y, o, &legal, &why);
      if (why != Exempt::None) {
        ++res.exempt;
        ++res.exemptBy[size_t(why)];
        res.mask.set(x, y, {0, 0, 110, 255});
        continue;
      }
      ++res.checked;
      bool edge = r.head(x, y) >= 0 && r.candidate(r.head(x, y)).next >= 0;
      if (edge) ++res.edges;
      for (int i = r.head(x, y); i >= 0; i = r.candidate(i).next)
        if (r.candidate(i).kind == Candidate::Kind::Textured) {
          ++res.textured;
          break;
        }
      {
        float lo[4] = {2, 2, 2, 2}, hi[4] = {-1, -1, -1, -1};
        for (const Box& b : legal)
          for (size_t k = 0; k < 4; ++k) lo[k] = std::min(lo[k], b.lo[k]), hi[k] = std::max(hi[k], b.hi[k]);
        bool narrow = true;
        for (size_t k = 0; k < 4; ++k) narrow = narrow && (hi[k] - lo[k]) * 255.0f <= 2.0f;
        res.pinned += narrow;
      }
      ts::Rgba c = got.at(x, y);
      bool ok = false;
      for (const Box& b : legal)
        if (inside(c, b, o.tolerance)) {
          ok = true;
          break;
        }
      if (ok) {
        if (edge) res.mask.set(x, y, {60, 60, 60, 255});
        continue;
      }
      if (res.invalid++ == 0) res.firstX = x, res.firstY = y, res.firstGot = c, res.firstLegal = legal;
      res.mask.set(x, y, {255, 0, 0, 255});
    }
  if (!res.ok() && o.writeOnFailure) {
    std::string dir = failureDir(o.outputDir);
    writeImage(dir, o.name, "rendered", got, &res.files);
    writeImage(dir, o.name, "reference", res.reference, &res.files);
    writeImage(dir, o.name, "errors", res.mask, &res.files);
  }
  return res;
}

std::string VerifyResult::summary() const {
  std::string s = name + ": " + std::to_string(invalid) + " of " + std::to_string(checked) + " checked pixels invalid";
  if (invalid > 0 && firstX >= 0) {
    s += " (first at (" + std::to_string(firstX) + "," + std::to_string(firstY) + "): got " + rgba(firstGot) +
         ", legal ";
    for (size_t i = 0; i < firstLegal.size() && i < 4; ++i) s += (i ? " | " : "") + box(firstLegal[i]);
    if (firstLegal.size() > 4) s += " | ...";
    s += ")";
  }
  s += "; " + std::to_string(textured) + " textured, " + std::to_string(pinned) + " pinned to +-1 step; " +
       std::to_string(edges) + " edge pixels checked against both sides; " + std::to_string(exempt) + " exempt";
  if (exempt) {
    std::string by;
    for (size_t k = 1; k < exemptBy.size(); ++k)
      if (exemptBy[k])
        by += (by.empty() ? "" : ", ") + std::string(exemptName(Exempt(k))) + " " + std::to_string(exemptBy[k]);
    s += " (" + by + ")";
  }
  for (const auto& n : notes) s += "; note: " + n;
  if (!files.empty()) {
    s += "; images:";
    for (const auto& f : files) s += " " + f;
  }
  return s;
}

FuzzyResult compareFuzzy(const ts::Image& got, const ts::Image& want, const FuzzyOptions& o) {
  FuzzyResult r;
  if (got.width != want.width || got.height != want.height) {
    r.message = o.name + ": size " + std::to_string(got.width) + "x" + std::to_string(got.height) + " vs " +
                std::to_string(want.width) + "x" + std::to_string(want.height);
    return r;
  }
  ts::Image diff(got.width, got.height, {0, 0, 0, 255});
  for (int y = 0; y < got.height; ++y)
    for (int x = 0; x < got.width; ++x) {
      ts::Rgba a = got.at(x, y), b = want.at(x, y);
      int d = std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
      r.maxDiff = std::max(r.maxDiff, d);
      if (d > o.maxChannelDiff) {
        if (r.differing++ == 0) r.firstX = x, r.firstY = y;
        diff.set(x, y, {255, 0, 0, 255});
      } else if (d > 0) {
        diff.set(x, y, {90, 90, 0, 255});
      }
    }
  r.ok = r.differing <= o.maxDifferingPixels;
  r.message = o.name + ": " + std::to_string(r.differing) + " pixels differ by more than " +
              std::to_string(o.maxChannelDiff) + " (allowed " + std::to_string(o.maxDifferingPixels) +
              "), largest channel difference " + std::to_string(r.maxDiff);
  if (r.firstX >= 0)
    r.message += ", first at (" + std::to_string(r.firstX) + "," + std::to_string(r.firstY) + "): got " +
                 rgba(got.at(r.firstX, r.firstY)) + ", committed " + rgba(want.at(r.firstX, r.firstY));
  if (!r.ok && o.writeOnFailure) {
    std::string dir = failureDir(o.outputDir);
    writeImage(dir, o.name, "rendered", got, &r.files);
    writeImage(dir, o.name, "committed", want, &r.files);
    writeImage(dir, o.name, "diff", diff, &r.files);
    r.message += "; images:";
    for (const auto& f : r.files) r.message += " " + f;
  }
  return r;
}

FuzzyResult compareWithPng(const ts::Image& got, const std::string& pngPath, const FuzzyOptions& o) {
  return compareFuzzy(got, ts::readPng(pngPath), o);
}
}  // namespace ref
