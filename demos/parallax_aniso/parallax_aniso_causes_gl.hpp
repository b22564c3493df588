// demos/parallax_aniso/parallax_aniso_causes_gl.hpp — the causes view's measurement
// and figure: the CPU measurements of seed 003's equations
// (parallax_aniso_causes.hpp) and one GL pass, M3 EWA with the seed's F =
// (Ux Vy + Uy Vx)^2 (ts::ewa::glsl(true): the only change to the shader is
// that line and the ellipse's row span), set beside the corrected M3 of the
// measured table and held to the same reference.
//
// The slip only matters where the footprint is sheared: with the view
// looking straight along +v (azimuth 0) Vx = 0 exactly, so Ux Vy + Uy Vx =
// Ux Vy - Uy Vx and the two renders are the same, byte for byte (the test's
// control); at the figures' azimuth, 12 degrees, they are not.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/probe.hpp"
#include "common/core/textures.hpp"
#include "parallax_aniso_causes.hpp"
#include "parallax_aniso_gl.hpp"
#include "parallax_aniso_measure.hpp"

namespace pax::causes {
struct Result {
  Cpu cpu;
  ts::Image seedF;                        // M3 with the seed's F (the corrected one is the table's M3 row)
  long seedFChanged = 0;                  // pixels where it differs from the corrected M3
  int seedFMaxDiff = 0;                   // the largest difference of a channel there, levels
  double seedFPsnr = 0;                   // against the reference (dB)
  double correctedPsnr = 0;               // the corrected M3's, the same measure
  std::vector<ts::TextureDesc> textures;  // the figure's seven pictures, in order
};

inline ts::TextureDesc picture(const ts::Image& img, const std::string& what) {
  return ts::renderedImageTexture(img, "parallax_render", what, "parallax_aniso");
}

// The seed-F pass at the table's camera and options; `accel` as the table's.
inline ts::Image renderSeedF(ReliefGL& gl, const Camera& cam, const Relief& rel, bool accel) {
  PassOptions po;
  po.accel = accel;
  po.seedF = true;
  return gl.render(cam, rel, kEwa, po);
}

// `record` (may be null): the seed-F pass is drawn anew with its GL calls
// recorded, for the figure's listing (as the table's passes are).
inline std::shared_ptr<const Result> measure(ReliefGL& gl, const Table& t, const Relief& rel, bool accel,
                                             ts::Renderer* record = nullptr) {
  auto r = std::make_shared<Result>();
  r->cpu = measureCpu(t.cam, rel);
  ts::measureProgress(0.95);  // a superseded measurement (measureCpu stopped early) throws here, never cached
  const ts::Image& corrected = t.rows[size_t(kEwa)].image;
  ts::gl::CallList calls;
  if (record) {
    gl.release();
    calls = ts::recordRender(*record, [&] { r->seedF = renderSeedF(gl, t.cam, rel, accel); });
  } else {
    r->seedF = renderSeedF(gl, t.cam, rel, accel);
  }
  r->seedFChanged = ts::probe::countDiffering(r->seedF, corrected, 0);
  r->seedFMaxDiff = maxDiff(r->seedF, corrected);
  r->seedFPsnr = psnr(r->seedF, t.referenceImage, nullptr);
  r->correctedPsnr = psnr(corrected, t.referenceImage, nullptr);
  r->textures = {picture(eq2Picture(r->cpu, r->cpu.eq2Error), "causes_eq2"),
                 picture(eq2Picture(r->cpu, r->cpu.eq2Typo), "causes_eq2_typo"),
                 picture(areaPicture(r->cpu), "causes_area_ratio"),
                 picture(hiddenPicture(r->cpu), "causes_hidden_share"),
                 picture(corrected, "ewa"),
                 picture(r->seedF, "causes_ewa_seed_f"),
                 picture(diffPicture(r->seedF, corrected), "causes_seed_f_diff")};
  r->textures[4].renderedBy = t.rows[size_t(kEwa)].calls;
  r->textures[5].renderedBy = calls;
  return r;
}

inline void addMeasurements(ts::Measurements& m, const Result& r) {
  const Cpu& c = r.cpu;
  m.push_back({"eq2_derivative_error_texels[frame]", c.eq2Frame,
               "Eq. 2 forward differences of the shifted (u,v) vs the analytic derivatives: median |error|, level-0 "
               "texels, whole frame"});
  m.push_back({"eq2_derivative_error_texels[steps]", c.eq2Steps,
               "the same median at the relief's steps (forward neighbours' ray depths > half the relief apart)"});
  m.push_back({"eq2_derivative_error_texels[typo]", c.eq2TypoFrame,
               "the seed's printed Eq. 2 (dv = v(x+1,y) - u(x,y)): median |error|, whole frame"});
  m.push_back({"eq2_step_pixels", double(c.stepPixels), "pixels at steps"});
  m.push_back({"footprint_area_ratio[parallax/plain]", c.areaRatioMedian,
               "Eq. 3, Fig. 3: footprint area from the shifted differences / from the plain ones, median"});
  m.push_back({"footprint_area_ratio[steps]", c.areaRatioStepsMedian, "the same ratio, median at the steps"});
  m.push_back({"footprint_area_ratio[steps_p90]", c.areaRatioStepsP90, "the same ratio, 90th percentile at steps"});
  for (const Bin& b : c.bins) {
    m.push_back({b.name, b.share, "Fig. 4: mean share of hidden texels in the footprint, this size bin"});
    m.push_back({b.name + "_error", b.sampleError, "its standard error (over the sampled pixels)"});
    m.push_back({b.name + "_pixels", double(b.pixels), "sampled pixels in the bin"});
  }
  m.push_back({"double_counted_texels[buffer]", double(c.doubleBuffer),
               "Fig. 6: texels the row walk (M5, with its stop index) counts twice, every 4th pixel each way"});
  m.push_back({"double_counted_texels[no_buffer]", double(c.doubleNoBuffer),
               "the same walk without the stop index (the walk from the right always runs)"});
  m.push_back({"double_counted_texels[seed_walk_no_bound]", double(c.doubleSeedNoBound),
               "the seed's walk (from the right only after a hidden texel), not bounded by the stop index"});
  m.push_back({"row_walk_texels", double(c.walkedTexels), "texels the row walk counts over those pixels"});
  m.push_back({"seed_F_error_px", double(r.seedFChanged), "pixels M3 with the seed's F changes"});
  m.push_back({"seed_F_max_diff_levels", double(r.seedFMaxDiff), "the largest channel difference there, levels"});
  m.push_back({"seed_F_psnr_db", r.seedFPsnr, "M3 with the seed's F: PSNR (dB) vs the reference"});
  m.push_back({"corrected_F_psnr_db", r.correctedPsnr, "M3 with the corrected F: PSNR (dB) vs the reference"});
}

// The figures: the causes (Eq. 2 twice, Fig. 3, Fig. 4 pictured; Fig. 6 in
// the notes) or, with seedF, M3 with either F and their difference; each
// captioned pictures above a legend and the notes.
inline void build(ts::Frame& f, const Result& r, const ts::Measurements& m, const std::string& header, bool seedF) {
  namespace L = ts::layout;
  auto M = [&](const std::string& templ) { return L::measuredText(m, templ); };
  const glm::vec4 black{0, 0, 0, 1}, dark{30 / 255.f, 20 / 255.f, 60 / 255.f, 1},
      red{220 / 255.f, 40 / 255.f, 40 / 255.f, 1}, yellow{1, 240 / 255.f, 80 / 255.f, 1};
  std::vector<L::Captioned> pics;
  std::vector<ts::LegendEntry> legend;
  std::vector<L::Text> notes;
  size_t firstPicture = 0;
  if (seedF) {
    firstPicture = 4;
    pics = {
        {"M3, corrected F", M("{corrected_F_psnr_db|%.3f} dB vs R")},
        {"M3, the seed's F", M("{seed_F_psnr_db|%.3f} dB vs R")},
        {"|seed's F - corrected|",
         M("{seed_F_error_px|%.0f} px differ, by {seed_F_max_diff_levels|%.0f} levels at most")},
    };
    legend = {{black, "equal"}, {dark, "under 1 level"}, {red, "4 levels"}, {yellow, "8 levels or more"}};
    notes = {L::Text(header + "; M3 EWA with Heckbert's F = (Ux Vy - Uy Vx)^2 and with the seed's (Ux Vy + Uy Vx)^2 "
                              "(plus A + C + 1, the unit reconstruction term, in both); R: the traced reference.")};
  } else {
    std::string first, last;  // the smallest and largest footprint bins with sampled pixels
    for (const Bin& b : r.cpu.bins)
      if (b.pixels > 0) last = b.name, first = first.empty() ? b.name : first;
    pics = {
        {"Eq. 2, shifted (u,v)", M("median {eq2_derivative_error_texels[frame]|%.2f} texels, "
                                   "{eq2_derivative_error_texels[steps]|%.1f} at steps")},
        {"Eq. 2 as printed (v - u)", M("median {eq2_derivative_error_texels[typo]|%.0f} texels")},
        {"Fig. 3: area shifted/plain",
         M("median {footprint_area_ratio[parallax/plain]|%.2f}, at steps {footprint_area_ratio[steps]|%.1f}")},
        {"Fig. 4: hidden share", M("{" + first + "|%.3f} (smallest) .. {" + last + "|%.3f} (largest)")},
    };
    legend = {
        {black, "0, none"},
        {dark, "1/16 texel"},
        {red, "1 texel, share 1/2"},
        {yellow, "16+ texels, share 1"},
        {{110 / 255.f, 110 / 255.f, 115 / 255.f, 1}, "area ratio 1"},
        {{40 / 255.f, 80 / 255.f, 1, 1}, "<= 1/4"},
        {{230 / 255.f, 60 / 255.f, 200 / 255.f, 1}, ">= 16"},
    };
    // Fig. 4's bins that hold sampled pixels (a small render has no smallest footprints); their bounds given.
    // A narrow frame (a small window beside its panel) gets the short notes, so that its pictures keep some room.
    const bool narrow = f.width < 900;
    L::Text bins(narrow ? "Fig. 4 share by footprint:" : "Fig. 4, hidden share by footprint (level-0 texels):");
    for (const Bin& b : r.cpu.bins) {
      if (b.pixels == 0) continue;
      const L::Text lo = L::given("footprint_bin_from", b.lo, "%.0f"), hi = L::given("footprint_bin_to", b.hi, "%.0f");
      bins = bins + L::Text(bins.text.back() == ':' ? " " : ", ") +
             (b.lo <= 0     ? L::Text("<=") + hi
              : b.hi > 1e29 ? L::Text(">") + lo
                            : lo + L::Text("..") + hi) +
             M(" {" + b.name + "|%.3f}" + (narrow ? "" : " +- {" + b.name + "_error|%.3f}"));
    }
    if (narrow)
      notes = {L::Text(header + "; steps ") + M("{eq2_step_pixels|%.0f} px."), bins + L::Text("."),
               M("Fig. 6 counted twice: buffer {double_counted_texels[buffer]|%.0f}, none "
                 "{double_counted_texels[no_buffer]|%.0f} of {row_walk_texels|%.0f}, seed's walk "
                 "{double_counted_texels[seed_walk_no_bound]|%.0f}.")};
    else
      notes = {
          L::Text(header + "; Eq. 2 against the analytic derivatives; steps: neighbours' rays end > half the relief "
                           "apart (") +
              M("{eq2_step_pixels|%.0f} px)."),
          bins + L::Text("."),
          M("Fig. 6, texels M5's row walk counts twice: with its buffer (where the left walk stopped) "
            "{double_counted_texels[buffer]|%.0f}, without it {double_counted_texels[no_buffer]|%.0f} of "
            "{row_walk_texels|%.0f}, the seed's walk unbounded {double_counted_texels[seed_walk_no_bound]|%.0f}."),
      };
  }
  L::pictureFigure(
      f, pics,
      [&](size_t k, const ts::Rect& rect) {
        f.panels.push_back(ts::layout::texturePanel("causes_" + std::to_string(firstPicture + k), rect,
                                                    f.addTexture(r.textures[firstPicture + k]), "image"));
      },
      legend, notes, {0, float(r.cpu.width) / float(r.cpu.height), 1, 1, 10, 2, 110}, 1, ts::Align::Left);
}
}  // namespace pax::causes
