// demos/texture_costs/texture_costs_measure.hpp — what the texture_costs demo measures: each workload's picture
// and what it shows (the same on every machine), and, in a window only, each workload timed on the student's own
// GL (never in a figure, whose bytes must not depend on the machine's speed).
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/core/image.hpp"
#include "common/core/scene.hpp"
#include "common/gl/cost_workloads.hpp"
#include "common/gl/gl_record.hpp"
#include "common/gl/render.hpp"

namespace ts::costs_demo {
namespace C = ts::costs;
constexpr int kPicture = 256;        // each workload's picture, pixels a side
constexpr int kMinifyTexels = 1024;  // the picture's minified texture (the timing's is kTimedMinifyTexels)
constexpr int kMinifyScale = 16;     // texels of level 0 a pixel, each way
constexpr int kOff = 16;             // "off": a channel more than 16 levels from the prediction (8-bit)
constexpr int kTimedFrame = 512, kTimedMinifyTexels = 2048;

// One workload drawn once into a kPicture^2 target, read back (row 0 the top), with its calls.
struct Run {
  Image image;
  gl::CallList calls;                // the workload made, begun, one frame, ended
  std::vector<gl::Call> frameCalls;  // the frame's alone
  std::map<std::string, double> counters;
};
inline Run run(Renderer& r, const char* what, const std::function<std::unique_ptr<C::Workload>()>& make) {
  Run out;
  out.image = r.offscreen(kPicture, kPicture, what, [&](GLuint) {
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glClearColor(0, 0, 0, 1);  // the frames clear with whatever is set: the same black in a figure and a window
    gl::Recording rec;
    std::unique_ptr<C::Workload> w = make();
    w->begin();
    {
      gl::Recording frame;
      w->frame();
      out.frameCalls = frame.take();
    }
    w->end();
    out.counters = w->counters;
    out.calls = std::make_shared<const std::vector<gl::Call>>(rec.take());
    glPopAttrib();
  });
  return out;
}
inline int channelDiff(const Rgba& a, const Rgba& b) {
  return std::max({std::abs(int(a.r) - int(b.r)), std::abs(int(a.g) - int(b.g)), std::abs(int(a.b) - int(b.b))});
}
inline glm::dvec3 rgb(const Rgba& c) { return {c.r, c.g, c.b}; }
inline int offPixels(const Image& a, const Image& b, int tolerance) {
  int n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) n += channelDiff(a.at(x, y), b.at(x, y)) > tolerance;
  return n;
}
inline int countCalls(const std::vector<gl::Call>& calls, const char* name) {
  return int(
      std::count_if(calls.begin(), calls.end(), [&](const gl::Call& c) { return std::strcmp(c.name, name) == 0; }));
}

// The interpolation quad on the CPU (cost_workloads.cpp: vertices (+-1, +-1) at w = 1 below, 8 above; s = x w / 16,
// t = w / 16 at each vertex; split along the diagonal from (-1, -1) to (1, 1)).  At the pixel centre (x, y) in
// normalised device coordinates:
//   hyperbolic (smooth)      1/w, s/w, t/w affine in the screen: 1/w = 1 - 7/16 (y + 1), s/w = x / 16,
//                            t/w = 1/16, so s = x w / 16, t = w / 16: the floor's true coordinates;
//   screen-linear (noperspective) s, t affine in each triangle: t = (1 + 3.5 (y + 1)) / 16 in both, s =
//                            (x + 3.5 y + 3.5) / 16 below the diagonal (x > y), (8 x - 3.5 y + 3.5) / 16 above it.
inline glm::dvec2 quadST(double x, double y, bool hyperbolic) {
  if (hyperbolic) {
    const double w = 1.0 / (1.0 - 7.0 / 16.0 * (y + 1.0));
    return {x * w / 16.0, w / 16.0};
  }
  return {(x > y ? x + 3.5 * y + 3.5 : 8.0 * x - 3.5 * y + 3.5) / 16.0, (1.0 + 3.5 * (y + 1.0)) / 16.0};
}
// GL_LINEAR with GL_REPEAT on the workload's 256^2 checker (texel centres at (i + 1/2) / 256).
inline glm::dvec3 bilinearRepeat(const std::vector<uint8_t>& px, int n, glm::dvec2 st) {
  const double u = st.x * n - 0.5, v = st.y * n - 0.5;
  const double fu = std::floor(u), fv = std::floor(v);
  const double a = u - fu, b = v - fv;
  auto T = [&](double i, double j) {
    const int x = int(((long long)(i) % n + n) % n), y = int(((long long)(j) % n + n) % n);
    const uint8_t* p = &px[(size_t(y) * n + size_t(x)) * 4];
    return glm::dvec3(p[0], p[1], p[2]);
  };
  return (1 - a) * (1 - b) * T(fu, fv) + a * (1 - b) * T(fu + 1, fv) + (1 - a) * b * T(fu, fv + 1) +
         a * b * T(fu + 1, fv + 1);
}
// The quad's picture as either interpolation predicts it (row 0 the top, as read back).
inline Image predictedQuad(bool hyperbolic) {
  const std::vector<uint8_t> tex = C::checker(256, 16, {230, 230, 230}, {40, 40, 160});
  Image img(kPicture, kPicture);
  for (int row = 0; row < kPicture; ++row)
    for (int x = 0; x < kPicture; ++x) {
      const double nx = (x + 0.5) / kPicture * 2 - 1, ny = 1 - (row + 0.5) / kPicture * 2;
      const glm::dvec3 c = bilinearRepeat(tex, 256, quadST(nx, ny, hyperbolic));
      img.set(x, row, {uint8_t(std::lround(c.r)), uint8_t(std::lround(c.g)), uint8_t(std::lround(c.b)), 255});
    }
  return img;
}
// The spread of a picture around its own mean colour, RMS over pixels and channels, in 8-bit levels: what a
// texture minified 16x looks like where it should be one flat colour (its average), i.e. the aliasing.
inline double rmsAroundMean(const Image& img, glm::dvec3* meanOut = nullptr) {
  glm::dvec3 mean(0);
  const double n = double(img.width) * img.height;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) mean += rgb(img.at(x, y)) / n;
  double s = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const glm::dvec3 d = rgb(img.at(x, y)) - mean;
      s += glm::dot(d, d);
    }
  if (meanOut) *meanOut = mean;
  return std::sqrt(s / (3 * n));
}
inline glm::dvec3 textureMean(const std::vector<uint8_t>& px) {
  glm::dvec3 m(0);
  const double n = double(px.size() / 4);
  for (size_t k = 0; k < px.size(); k += 4) m += glm::dvec3(px[k], px[k + 1], px[k + 2]) / n;
  return m;
}

// The pictures, in the order the figure shows them.
enum Pic { kSmooth, kNoPerspective, kBumpQuad, kGrid, kSorted, kUnsorted, kMipmapped, kUnmipmapped, kPictures };
inline const char* const kPictureKeys[] = {"smooth", "noperspective", "bump_quad", "displaced_grid",
                                           "sorted", "unsorted",      "mipmapped", "unmipmapped"};
struct Pictures {
  std::vector<Run> runs;  // one per Pic
  Run batched;            // sorted_batched: the same picture again
};

inline Pictures measurePictures(Renderer& r, Measurements& m) {
  Pictures p;
  p.runs.push_back(run(r, "smooth", [&] { return C::interpolation(r, true); }));
  p.runs.push_back(run(r, "noperspective", [&] { return C::interpolation(r, false); }));
  p.runs.push_back(run(r, "bump quad", [&] { return C::detail(r, C::Detail::Bump); }));
  p.runs.push_back(run(r, "displaced grid", [&] { return C::detail(r, C::Detail::Grid); }));
  p.runs.push_back(run(r, "sorted", [&] { return C::switches(r, C::Order::Sorted); }));
  p.runs.push_back(run(r, "unsorted", [&] { return C::switches(r, C::Order::Unsorted); }));
  auto minified = [&](GLint f) { return C::minify(r, f, kMinifyTexels, kMinifyScale, kPicture); };
  p.runs.push_back(run(r, "mipmapped", [&] { return minified(GL_LINEAR_MIPMAP_LINEAR); }));
  p.runs.push_back(run(r, "unmipmapped", [&] { return minified(GL_LINEAR); }));
  p.batched = run(r, "sorted, batched", [&] { return C::switches(r, C::Order::SortedBatched); });
  auto put = [&](const std::string& n, double v, const std::string& what) { m.push_back({n, v, what}); };
  auto img = [&](Pic k) -> const Image& { return p.runs[size_t(k)].image; };

  // 1. Interpolation: each mode against each equation.
  const Image hyperbolic = predictedQuad(true), linear = predictedQuad(false);
  const double all = double(kPicture) * kPicture;
  put("costs_interp_off_share[smooth_vs_hyperbolic]", offPixels(img(kSmooth), hyperbolic, kOff) / all,
      "share of the smooth quad's pixels more than 16 levels off the hyperbolic equation (s = x w / 16, t = w / 16)");
  put("costs_interp_off_share[noperspective_vs_linear]", offPixels(img(kNoPerspective), linear, kOff) / all,
      "share of the noperspective quad's pixels more than 16 levels off the screen-linear equation");
  put("costs_interp_off_share[noperspective_vs_hyperbolic]", offPixels(img(kNoPerspective), hyperbolic, kOff) / all,
      "share of the noperspective quad's pixels off the true (hyperbolic) floor: what the saved division costs");
  put("costs_interp_triangles", p.runs[kSmooth].counters["triangles"], "triangles of the quad");
  // 2. Detail: the same bricks either way.
  put("costs_detail_triangles[bump_quad]", p.runs[kBumpQuad].counters["triangles"], "triangles, the bump-mapped quad");
  put("costs_detail_triangles[displaced_grid]", p.runs[kGrid].counters["triangles"],
      "triangles, the grid with one vertex per height texel");
  put("costs_detail_off_share[bump_vs_grid]", offPixels(img(kBumpQuad), img(kGrid), kOff) / all,
      "share of pixels where the bump-mapped quad and the displaced grid differ by more than 16 levels");
  // 3. Switches: the binds and draws as recorded; the same picture in every order.
  for (auto [k, key] : {std::pair{kSorted, "sorted"}, {kUnsorted, "unsorted"}}) {
    put(std::string("costs_binds[") + key + "]", countCalls(p.runs[size_t(k)].frameCalls, "glBindTexture"),
        "glBindTexture calls in one frame (recorded)");
    put(std::string("costs_draws[") + key + "]", countCalls(p.runs[size_t(k)].frameCalls, "glDrawElements"),
        "glDrawElements calls in one frame (recorded)");
  }
  put("costs_binds[sorted_batched]", countCalls(p.batched.frameCalls, "glBindTexture"),
      "glBindTexture calls, one draw a texture");
  put("costs_draws[sorted_batched]", countCalls(p.batched.frameCalls, "glDrawElements"),
      "glDrawElements calls, one a texture");
  put("costs_switch_off_px[unsorted_vs_sorted]", offPixels(img(kUnsorted), img(kSorted), 0),
      "pixels that differ at all between the unsorted and the sorted frame");
  put("costs_switch_off_px[batched_vs_sorted]", offPixels(p.batched.image, img(kSorted), 0),
      "pixels that differ at all between one draw a texture and one draw a quad");
  // 4. Minification: the flat average colour, or aliasing.
  glm::dvec3 meanMip(0);
  put("costs_minify_rms[mipmapped]", rmsAroundMean(img(kMipmapped), &meanMip),
      "RMS of the 16x minified picture around its mean, levels (flat = the texture's average)");
  put("costs_minify_rms[unmipmapped]", rmsAroundMean(img(kUnmipmapped)), "the same with GL_LINEAR: aliasing");
  const glm::dvec3 want = textureMean(C::checker(kMinifyTexels, 5, {240, 200, 60}, {20, 60, 140}));
  const glm::dvec3 d = glm::abs(meanMip - want);
  put("costs_minify_mean_error[mipmapped]", std::max({d.x, d.y, d.z}),
      "the mipmapped picture's mean against the texture's average colour, levels");
  return p;
}

// ---- timed, window only -------------------------------------------------------------------------------------------
// Each variant's frames at kTimedFrame^2, one a window frame in turn (so the window stays responsive even where a
// frame is slow), glFinish after each; the median of kSamples once every variant has them.
struct Timed {
  const char* key;    // cost_ms_per_frame[key]
  const char* label;  // for the panel
  std::function<std::unique_ptr<C::Workload>(Renderer&)> make;
};
inline std::vector<Timed> timedVariants() {
  auto minified = [](GLint f) {
    return [f](Renderer& r) { return C::minify(r, f, kTimedMinifyTexels, kMinifyScale, kTimedFrame); };
  };
  return {{"interpolation/smooth", "hyperbolic", [](Renderer& r) { return C::interpolation(r, true); }},
          {"interpolation/noperspective", "screen-linear", [](Renderer& r) { return C::interpolation(r, false); }},
          {"detail/bump_quad", "bump quad", [](Renderer& r) { return C::detail(r, C::Detail::Bump); }},
          {"detail/parallax_quad", "parallax quad", [](Renderer& r) { return C::detail(r, C::Detail::Parallax); }},
          {"detail/displaced_grid", "displaced grid", [](Renderer& r) { return C::detail(r, C::Detail::Grid); }},
          {"switches/sorted", "sorted", [](Renderer& r) { return C::switches(r, C::Order::Sorted); }},
          {"switches/unsorted", "unsorted", [](Renderer& r) { return C::switches(r, C::Order::Unsorted); }},
          {"minify/mipmapped", "mipmapped", minified(GL_LINEAR_MIPMAP_LINEAR)},
          {"minify/unmipmapped", "unmipmapped", minified(GL_LINEAR)}};
}
// The claims the ratios test, each a ratio of two variants' medians; `above` is what the claim predicts (the
// ratio > 1 when the claim holds).
struct Claim {
  const char* key;
  const char* slow;
  const char* fast;
  const char* text;
};
inline const Claim kClaims[] = {{"interpolation", "interpolation/smooth", "interpolation/noperspective",
                                 "Buss VI.1.1: hyperbolic interpolation costs extra"},
                                {"detail", "detail/displaced_grid", "detail/bump_quad",
                                 "Buss VI.1, seed 001: a texture is cheaper than the same detail as geometry"},
                                {"switches", "switches/unsorted", "switches/sorted",
                                 "seed 001: texture switches cost; group polygons by texture"},
                                {"minify", "minify/unmipmapped", "minify/mipmapped",
                                 "Buss VI.1.3: mipmaps make minified reads cheaper"}};

class Timer final : public Renderer::Attachment {
 public:
  static constexpr size_t kSamples = 9;
  explicit Timer(Renderer& r) : r_(r), variants_(timedVariants()) {}
  ~Timer() override { made_.clear(); }
  bool done() const { return next_ >= variants_.size() * kSamples; }
  // One frame of the next variant, timed.
  void step() {
    if (done()) return;
    const size_t v = next_ % variants_.size();
    ++next_;
    std::unique_ptr<C::Workload>& w = made_[v];
    r_.offscreen(kTimedFrame, kTimedFrame, variants_[v].key, [&](GLuint) {
      glPushAttrib(GL_ALL_ATTRIB_BITS);
      glClearColor(0, 0, 0, 1);
      if (!w) {
        w = variants_[v].make(r_);
        w->begin();
        w->frame();  // warm: programs linked, textures resident
        glFinish();
      } else {
        w->begin();
      }
      const auto t0 = std::chrono::steady_clock::now();
      w->frame();
      glFinish();
      ms_[v].push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      w->end();
      glPopAttrib();
    });
  }
  void report(Measurements& m) const {
    std::map<std::string, double> median;
    for (size_t v = 0; v < variants_.size(); ++v) {
      auto it = ms_.find(v);
      if (it == ms_.end() || it->second.empty()) continue;
      std::vector<double> s = it->second;
      std::sort(s.begin(), s.end());
      median[variants_[v].key] = s[s.size() / 2];
      m.push_back({std::string("cost_ms_per_frame[") + variants_[v].key + "]", s[s.size() / 2],
                   std::string("ms a frame, ") + variants_[v].label + ", " + std::to_string(kTimedFrame) +
                       "^2, median of " + std::to_string(s.size()) + " (glFinish), on this machine's GL"});
    }
    for (const Claim& c : kClaims) {
      if (!median.count(c.slow) || !median.count(c.fast)) continue;
      const double ratio = median[c.slow] / median[c.fast];
      const char* verdict = ratio > 1.1   ? "supported here"
                            : ratio < 0.9 ? "contradicted here"
                                          : "no clear difference here";
      m.push_back(
          {std::string("cost_timed_ratio[") + c.key + "]", ratio,
           std::string(c.text) + ": " + c.slow + " / " + c.fast + ", " + verdict + (done() ? "" : " (still timing)")});
    }
  }

 private:
  Renderer& r_;
  std::vector<Timed> variants_;
  std::map<size_t, std::unique_ptr<C::Workload>> made_;
  std::map<size_t, std::vector<double>> ms_;
  size_t next_ = 0;
};
}  // namespace ts::costs_demo
