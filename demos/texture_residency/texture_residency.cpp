// Texture residency (seed 001 ¶7-8 and ¶19-21, Buss VI.1.3): how big a texture may be, which of its mip levels a
// surface actually needs at a distance, and a clipmap that holds only the part of a huge texture the eye sees.
//
// The claims, one view each (key v, flag --view):
//   sizes      The implicit corresponder (seed 001 ¶7): a vertex's (s, t) in [0, 1] does not depend on the
//              texture's resolution; the texel coordinates (u, v) = (s w, t h) do.  The same (s, t) lands on
//              the same place of the surface at 64^2, 256^2 and 1024^2 (measured: the marker's position, in
//              pixels, within a 64^2 texel), while (u, v) grows with the size.  How big may w be?  Seed 001
//              ¶8: 2^m x 2^n texels, under a limit each card sets; GL says GL_MAX_TEXTURE_SIZE, and a proxy
//              texture answers for one size: a size that does not fit gets GL_TEXTURE_WIDTH 0, and the
//              program halves it until it fits.  Where it settles is the
//              backend's: llvmpipe takes GL_MAX_TEXTURE_SIZE^2 (16384^2 here), softpipe refuses that (1 GiB of
//              RGBA8) and takes half; so the figure prints neither, the sidecar both.
//   residency  Buss VI.1.3 (in translation): "the textures further away are seen at lower resolution, so only the
//              lower-resolution mipmap versions of them need be kept in the more accessible memory (the cache,
//              the graphics chip): memory is used better by keeping only the mipmap versions needed"; seed
//              001 ¶19: a polygon far from the eye needs only part of its texture loaded.  A unit
//              quad facing the eye at distance d, with a level-colour texture (each level one flat colour) and
//              GL_LINEAR_MIPMAP_LINEAR: the colour read back says which two levels GL blended, and the memory of
//              the levels from the finest read to the 1x1 against the whole chain is what must be resident.
//              Measured: the finest level read grows by one each time d doubles, and at d = 24 the resident
//              part is under 1 % of the chain: the claim holds.
//   clipmap    Tanner's clipmap (seed 001 ¶21): a 16384^2 texture (procedural: a function of the texel, so
//              nothing huge is stored) drawn through a stack of 6 levels of 512^2, each a window centred on the
//              eye, updated toroidally as the eye moves: only the rows and columns that entered a window are
//              uploaded (glTexSubImage2D into their places mod 512), and GL_REPEAT reads the window from there.
//
// Keys (each is also a flag, see --help):
//   v      view: sizes | residency | clipmap
//   . / ,  clipmap: the eye one move on / back (--moves; each move is (37, 21) level-0 texels)
//
// The equations:
//   u = s w, v = t h                                            (the corresponder; marker at s, t = 41/64, 21/64)
//   rho = d texels a pixel, lambda = log2 d                     (the unit quad at d: 256 / d pixels of a 256^2 texture)
//   GL_LINEAR_MIPMAP_LINEAR reads levels floor(lambda), floor(lambda) + 1, weight frac(lambda) of the second
//   resident(k) = sum_{j >= k} (256 / 2^j)^2 / sum_{j >= 0} (256 / 2^j)^2  (about 4^-k; the chain: 4/3 of level 0)
//   window_l(eye) = floor(eye / 2^l) - 256 .. + 512 level-l texels;  texel i of level l stored at i mod 512
//   texels a move = sum_l 512 |dx_l| + (512 - |dx_l|) |dy_l|,  dx_l = the window's move at level l
//   stack = sum_l min(16384 / 2^l, 512)^2 texels  (common/core/texture_memory.hpp's clipmapTexels)
//
// What the GL does:
//   glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
//   glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, w, w, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
//   glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &got);   0: does not fit, halve w
//   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);   the residency quads
//   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 512, 512, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);   each clip level, once
//   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S / _T, GL_REPEAT);
//   glTexSubImage2D(GL_TEXTURE_2D, 0, x mod 512, y mod 512, w, h, GL_RGBA, GL_UNSIGNED_BYTE, strip);  each move
// Listings: book_figures/texture_residency_sizes.gl.txt, texture_residency.gl.txt, texture_clipmap.gl.txt.
// The GL passes: texture_residency_gl.hpp; the equations: texture_residency_math.hpp; measurements and figure
// layouts: texture_residency_views.hpp.
//
// What is exact in the clipmap's check: the virtual texture is defined at every level directly (no box filter
// of 4^l texels), so the reference is that same function sampled on the CPU at the level whose window holds the
// point.  From above (a map of the whole texture at 32 texels a pixel, each point showing the finest level the
// stack holds there) the pixel centres fall on texel centres plus halves, never on a texel's or a window's edge,
// and the stack is GL_NEAREST RGBA8: every pixel must equal its reference texel exactly (tolerance 0).  In
// perspective (the eye 200 texels above the ground) the windows, drawn coarsest first, choose the level by
// distance as Tanner's clipmap does; the CPU casts each pixel's ray to the ground, and every pixel farther than
// 1/64 pixel from a texel's or window's edge must be exact (GL snaps vertices to 1/256 pixel; the rest, about
// one pixel in eight, lie on edges where either side is right).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "texture_residency_views.hpp"

namespace {
namespace R = ts::residency;

class TextureResidency final : public ts::Scene {
 public:
  std::string id() const override { return "texture_residency"; }
  std::string title() const override {
    return "Texture residency: the size rules, the mip levels a distance needs, a working clipmap";
  }
  std::string about() const override {
    return "Views: sizes (GL_MAX_TEXTURE_SIZE, a proxy texture's answer, the same (s, t) at 64^2, 256^2 and 1024^2),\n"
           "residency (a level-colour texture on quads at five distances: the levels GL reads, and the memory they\n"
           "need against the whole chain), clipmap (a 16384^2 procedural texture through 6 levels of 512^2 updated\n"
           "toroidally by glTexSubImage2D: pixels off the CPU's answer, texels uploaded a move, memory).";
  }
  std::vector<std::string> claim() const override {
    if (view_ == 1) return {"finest_level_read*", "resident_fraction*"};
    if (view_ == 2) return {"clipmap_mismatch_px*", "clipmap_texels_uploaded*"};
    return {"marker_offset_px*", "proxy_width*"};
  }
  void addOptions(ts::Options& o) override {
    o.addEnum("view", &view_, {"sizes", "residency", "clipmap"},
              "the size rules | the mip levels read at five distances | a working clipmap", 'v');
    o.addInt("moves", &moves_, 1, 400, "clipmap: moves of the eye from its start (each (37, 21) level-0 texels)", '.',
             ',', 1);
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"texture_residency_sizes",
         "Texture residency: the size rules (seed 001)",
         "One marker texture at 64^2, 256^2 and 1024^2 on the same quad: the same (s, t) lands on the same place, "
         "while its texel coordinates (u, v) = (s w, t h) grow with the size.  A proxy texture tells whether a size "
         "fits (GL_TEXTURE_WIDTH 0 when it does not), and the program halves it until it does.",
         {"--view", "sizes"},
         1024,
         520,
         "The marker lies {marker_offset_px[1024]} px from its 64^2 place at 1024^2; a proxy twice "
         "GL_MAX_TEXTURE_SIZE wide reads width {proxy_width[2max]}, and the program halves it until it fits."},
        {"texture_residency",
         "Texture residency: the mip levels a distance needs (Buss VI.1.3)",
         "A level-colour texture (each mip level one flat colour) on a unit quad at five distances, "
         "GL_LINEAR_MIPMAP_LINEAR: the colour says which two levels GL read.  Only the levels from the finest read "
         "down to the 1x1 need be resident.",
         {"--view", "residency"},
         1100,
         460,
         "At d = 24 GL reads level {finest_level_read[24]} and finer levels never: {resident_fraction[24]} of the "
         "chain need be resident."},
        {"texture_clipmap",
         "Texture residency: a working clipmap (seed 001, Tanner)",
         "A 16384^2 procedural texture seen through a stack of six 512^2 levels, each a window centred on the eye, "
         "updated toroidally by glTexSubImage2D as the eye moves: the view from above and in perspective, and each "
         "level's storage with the strips the last move uploaded.",
         {"--view", "clipmap"},
         1100,
         840,
         "{clipmap_mismatch_px} pixels differ from the CPU's answer ({clipmap_mismatch_px[stale]} without the last "
         "update; {clipmap_flight_mismatch_px} in perspective); a move uploads {clipmap_texels_uploaded[move]} texels "
         "against {clipmap_texels_uploaded[reload]} for a reload."}};
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override {
    ts::Measurements out;
    R::Detail d;
    if (view_ == 0) R::measureSizes(r, out, d);
    else if (view_ == 1) R::measureResidency(r, out);
    else R::measureClipmap(r, out, d, moves_);
    out.detail = d;
    return out;
  }

 private:
  ts::Frame buildSizes(ts::Frame& f, const ts::Measurements& m) const;
  ts::Frame buildResidency(ts::Frame& f, const ts::Measurements& m) const;
  ts::Frame buildClipmap(ts::Frame& f, const ts::Measurements& m) const;
  int view_ = 0;
  int moves_ = R::kMoves;
};

ts::Frame TextureResidency::build(int width, int height, const ts::Measurements& measured) const {
  ts::Frame f = ts::layout::blankFrame(width, height);
  // Right after the key v the window still holds the previous view's measurements: draw this view as not yet
  // measured ("(measuring)") rather than print numbers it does not have.
  static const char* const kMeasuredBy[] = {"marker_px_x[64]", "levels_read[1.5]", "clipmap_mismatch_px"};
  bool mine = measured.empty();
  for (const ts::Measurement& x : measured) mine = mine || x.name == kMeasuredBy[view_];
  const ts::Measurements none;
  const ts::Measurements& m = mine ? measured : none;
  if (view_ == 0) return buildSizes(f, m);
  if (view_ == 1) return buildResidency(f, m);
  return buildClipmap(f, m);
}

// ---- the size rules: the three sizes side by side, (u, v) under each, the proxy's answers below -----------------
ts::Frame TextureResidency::buildSizes(ts::Frame& f, const ts::Measurements& m) const {
  namespace L = ts::layout;
  const R::Detail* d = m.detailAs<R::Detail>();
  const ts::Rgba mc = R::kMarkerColour;
  const std::vector<ts::LegendEntry> legend = {
      {{mc.r / 255.0f, mc.g / 255.0f, mc.b / 255.0f, 1.0f}, "the marker: the same (s, t) square at every size"}};
  const std::vector<std::pair<L::Text, glm::vec4>> notes = {
      {L::measuredText(m, "The same (s, t) at every size: the marker lies at most {marker_offset_px[1024]|%.1f} px "
                          "from its 64^2 place (a 64^2 texel is ") +
           L::given("pixels a 64^2 texel covers in the 256 px render", R::kSizePanelPx / 64.0, "%.0f") +
           " px); (u, v) = (s w, t h) grows with the size.",
       L::kAmber},
      {L::measuredText(m,
                       "glTexImage2D(GL_PROXY_TEXTURE_2D, ...) of 1024^2: GL_TEXTURE_WIDTH {proxy_width[1024]|%.0f}; "
                       "of twice GL_MAX_TEXTURE_SIZE: {proxy_width[2max]|%.0f}, so the program halves it until "
                       "it fits."),
       L::kAmber},
      {"GL_MAX_TEXTURE_SIZE and the size that fits are the backend's own (sidecar: max_texture_size, "
       "proxy_settled_size).",
       L::kWhite}};
  // The captions first: the bands take the lines they need at this width (a narrow window wraps them).
  std::vector<L::Text> titles;
  std::vector<std::vector<L::Text>> unders;
  std::vector<L::Stack> above, below;
  for (const int size : R::kSizes) {
    const std::string key = "[" + std::to_string(size) + "]";
    titles.push_back(L::given("texture side, texels", size, "%.0f") + " x " +
                     L::given("texture side, texels", size, "%.0f") + " texels");
    unders.push_back({"(s, t) = (" + L::given("the marker's s", R::kMarkerS, "%.4f") + ", " +
                          L::given("the marker's t", R::kMarkerT, "%.4f") + ") -> (u, v) = (" +
                          L::given("u = s w, texels", R::kMarkerS * size, "%.0f") + ", " +
                          L::given("v = t h, texels", R::kMarkerT * size, "%.0f") + ") texels;",
                      L::measuredText(m, "marker at (" + std::string("{marker_px_x" + key + "|%.1f}, {marker_px_y" +
                                                                     key + "|%.1f}) px of 256"))});
    above.push_back({titles.back().text});
    below.emplace_back();
    for (const L::Text& t : unders.back()) below.back().push_back(t.text);
  }
  const float width = float(f.width - 16);
  std::vector<L::Text> noteTexts;
  for (const auto& n : notes) noteTexts.push_back(n.first);
  const float band = L::columnHeight(noteTexts, 1, width) + 8;
  const float key = L::lineHeight(1) * float(L::legendLines(legend, 1, width)) + 4;
  L::FlowSpec spec;
  spec.n = int(R::kSizes.size()), spec.linesAbove = 1, spec.linesBelow = 2, spec.gap = 16, spec.maxScale = 2;
  const std::vector<L::Cell> cells = L::flowFitting({8, 8, float(f.width - 8), float(f.height) - 8 - band - key}, spec,
                                                    above, below);
  L::legend(f, {8, float(f.height) - band - key, float(f.width - 8), float(f.height) - band}, legend, 1);
  for (size_t k = 0; k < cells.size(); ++k) {
    const int size = R::kSizes[k];
    // A whole multiple of 64 pixels a side: every edge between colours (the checks, the marker: 64ths) then falls
    // between pixels, never through a pixel's centre where GL_NEAREST's tie could go either way.
    // (A window too small for 64 pixels takes the cell as it is: a tie or two rather than text overlapped.)
    const int fit = std::min(cells[k].picture.w, cells[k].picture.h), side = fit >= 64 ? fit / 64 * 64 : fit;
    f.panels.push_back(R::sizePanel(f, "size_" + std::to_string(size), L::centred(cells[k].picture, side, side), size));
    // The size queries' calls go into the listing with the first panel's texture.
    if (k == 0 && d) f.textures[size_t(f.panels.back().batches[0].texture)].renderedBy = d->sizeCalls;
    L::caption(f, cells[k].above, titles[k], L::kWhite, cells[k].scale);
    L::phrases(f, cells[k].below, unders[k], L::kAmber, cells[k].scale);
  }
  L::Column column(f, {8, float(f.height) - band, float(f.width - 8), float(f.height - 4)});
  for (const auto& [text, colour] : notes) column.add(text, colour, 1);
  return f;
}

// ---- residency: the quad at each distance, the levels its colour says GL read, the memory they need ---------------
ts::Frame TextureResidency::buildResidency(ts::Frame& f, const ts::Measurements& m) const {
  namespace L = ts::layout;
  std::vector<ts::LegendEntry> legend;
  for (int l = 0; l < 6; ++l) legend.push_back({R::levelColour(l), "level " + std::to_string(l)});
  const ts::Measurement* far = nullptr;
  for (const ts::Measurement& x : m)
    if (x.name == "resident_fraction[24]") far = &x;
  const std::vector<std::pair<L::Text, glm::vec4>> notes = {
      {"Levels k + (k + 1), f: GL_LINEAR_MIPMAP_LINEAR's two levels and the second's weight, decoded from the "
       "colour; resident = the levels from the finest read down to the 1x1, over the whole chain (" +
           L::measuredText(m, "{chain_over_level0|%.3f}") + " of level 0).",
       L::kWhite},
      {std::string("Buss VI.1.3: a distant texture needs only its lower-resolution levels in fast memory.  ") +
           (far && far->value < 0.01 ? "Measured: it holds, " : "Measured: ") +
           "at d = " + L::given("distance", R::kDistances.back(), "%.0f") +
           L::measuredText(m, " only {resident_fraction[24]|%.4f} of the chain need be resident."),
       L::kAmber}};
  // The captions first: the bands take the lines they need at this width (a narrow window wraps them).
  std::vector<std::pair<L::Text, L::Text>> titles;
  std::vector<std::vector<L::Text>> unders;
  std::vector<L::Stack> above, below;
  for (const double d : R::kDistances) {
    const std::string n = "[" + R::distanceKey(d) + "]";
    titles.push_back({"d = " + L::given("distance", d, "%.1f"),
                      "lambda = log2 d = " + L::given("lambda = log2 d", R::lambdaAt(d), "%.2f")});
    unders.push_back({L::measuredText(m, "reads levels {finest_level_read" + n + "|%.0f} + {second_level_read" + n +
                                             "|%.0f}, f {blend_weight" + n + "|%.2f}:"),
                      L::measuredText(m, "{resident_fraction" + n + "|%.4f} of the chain resident")});
    above.push_back({titles.back().first.text, titles.back().second.text});
    below.push_back({unders.back()[0].text, unders.back()[1].text});
  }
  const float width = float(f.width - 16);
  std::vector<L::Text> noteTexts;
  for (const auto& n : notes) noteTexts.push_back(n.first);
  const float band = L::columnHeight(noteTexts, 1, width) + 8;
  const float key = L::lineHeight(1) * float(L::legendLines(legend, 1, width)) + 4;
  L::FlowSpec spec;
  spec.n = int(R::kDistances.size()), spec.linesAbove = 2, spec.linesBelow = 2, spec.gap = 12, spec.maxScale = 1;
  const std::vector<L::Cell> cells = L::flowFitting({8, 8, float(f.width - 8), float(f.height) - 8 - band - key}, spec,
                                                    above, below);
  const int tex = f.addTexture(R::levelTexture());
  for (size_t k = 0; k < cells.size(); ++k) {
    const double d = R::kDistances[k];
    // The measured panel's size (192 px) when the cell has room: then the picture is the measurement's.
    const int side = std::min({R::kDistancePanelPx, cells[k].picture.w, cells[k].picture.h});
    f.panels.push_back(
        R::distancePanel("distance_" + std::to_string(k), L::centred(cells[k].picture, side, side), tex, d));
    // The distance's lines over lambda's (at the figure's size, the two halves of a two-line band).
    const L::Box& b = cells[k].above;
    const auto [upper, lower] = L::stackApart(b, cells[k].scale, titles[k].second.text);
    L::caption(f, upper, titles[k].first, L::kWhite, cells[k].scale);
    L::caption(f, lower, titles[k].second, L::kWhite, cells[k].scale);
    L::phrases(f, cells[k].below, unders[k], L::kAmber, cells[k].scale);
  }
  L::legend(f, {8, float(f.height) - band - key, float(f.width - 8), float(f.height) - band}, legend, 1);
  L::Column column(f, {8, float(f.height) - band, float(f.width - 8), float(f.height - 4)});
  for (const auto& [text, colour] : notes) column.add(text, colour, 1);
  return f;
}

// ---- the clipmap: the view with the windows outlined, the six levels' storage, the numbers -----------------------
ts::Frame TextureResidency::buildClipmap(ts::Frame& f, const ts::Measurements& m) const {
  namespace L = ts::layout;
  const R::Detail* d = m.detailAs<R::Detail>();
  if (!d || d->clipView.width == 0) {
    L::caption(f, {8, 8, float(f.width - 8), float(f.height - 8)}, "rendering ...", L::kWhite, 2);
    return f;
  }
  std::vector<ts::LegendEntry> legend;
  for (int l = 0; l < R::kClipLevels; ++l)
    legend.push_back({R::levelColour(l), "level " + std::to_string(l) + "'s window"});
  legend.push_back({R::kExposedColour, "uploaded by the last move (whitened)"});
  legend.push_back({R::kSeamColour, "the toroidal seam: the window's first row and column"});
  legend.push_back({{R::kSky.r / 255.0f, R::kSky.g / 255.0f, R::kSky.b / 255.0f, 1.0f}, "beyond every window"});
  const std::vector<L::Text> notes = {
      L::measuredText(m, "Pixels off the procedural texture sampled on the CPU at the stack's level: "
                         "{clipmap_mismatch_px|%.0f} (tolerance 0, GL_NEAREST); with the last move's uploads left "
                         "out: {clipmap_mismatch_px[stale]|%.0f}."),
      L::measuredText(m, "In perspective: {clipmap_flight_mismatch_px|%.0f} pixels off the CPU's rays, of those "
                         "farther than 1/") +
          L::given("the edge margin, 1/n pixel", R::kEdgeMarginInv, "%.0f") +
          L::measuredText(m, " pixel from a texel's or window's edge; {clipmap_flight_ambiguous_px|%.0f} nearer, "
                             "where either side is right."),
      L::measuredText(m, "glTexSubImage2D texels a move ({clipmap_step_x|%.0f}, {clipmap_step_y|%.0f} level-0 "
                         "texels): {clipmap_texels_uploaded[move]|%.0f} (the equation: "
                         "{clipmap_texels_uploaded[predicted]|%.0f}); a reload of every window: "
                         "{clipmap_texels_uploaded[reload]|%.0f}."),
      L::measuredText(m, "Memory: the stack {clipmap_stack_texels|%.0f} texels, the whole ") +
          L::given("the virtual texture's side, texels", R::kVirtual, "%.0f") +
          L::measuredText(m, "^2 chain {clipmap_chain_texels|%.0f}: {clipmap_saving|%.1f} times less (") +
          L::given("texture_compression's clipmap side, texels", 65536, "%.0f") + "^2 with " +
          L::given("clip side, texels", R::kClip, "%.0f") +
          L::measuredText(m, "^2 levels: {clipmap_saving[65536/512]|%.0f} times).")};
  // The bands take the lines their text needs at this width (a narrow window wraps them), at most half the height
  // between them: a narrow window keeps its pictures, and the notes that no longer fit are left out (the side
  // panel lists every number).
  const float key = std::min(float(f.height) * 0.25f,
                             L::lineHeight(1) * float(L::legendLines(legend, 1, float(f.width - 16))) + 8);
  const float band = std::min(float(f.height) * 0.5f - key, L::columnHeight(notes, 1, float(f.width - 16)) + 8);
  const float bottom = float(f.height) - 8 - band - key, middle = 8 + (bottom - 8) * 0.6f;
  const float split = float(f.width) * 0.36f;
  auto picture = [&](const ts::Image& img, const std::string& id, const std::string& what, const ts::Rect& r,
                     const ts::gl::CallList& calls) {
    ts::TextureDesc t = ts::renderedImageTexture(img, "texture_residency_render", what, "texture_residency");
    t.minFilter = t.magFilter = GL_LINEAR;
    t.renderedBy = calls;
    f.panels.push_back(L::picturePanel(f, id, r, t));
  };
  // Above: the map (left) and the flight (right); below: the six levels' storage.
  // Each group's captions wrap in a narrow window (flowFitting) rather than being cut.
  const L::Text viewTitle = "from above: " + L::given("the virtual texture's side, texels", R::kVirtual, "%.0f") +
                            "^2 at " + L::given("texels a pixel", R::kTexelsPerPixel, "%.0f") + " texels a pixel";
  const std::string viewNote = "each level's window outlined in its colour";
  const std::vector<L::Cell> view = L::flowFitting({8, 8, split, middle}, {1, 1.0f, 1, 1, 8, 1, 0}, {{viewTitle.text}},
                                                   {{viewNote}});
  picture(d->clipView, "view", "the clipmap's view", view[0].picture, d->clipCalls);
  L::caption(f, view[0].above, viewTitle, L::kWhite, view[0].scale);
  L::caption(f, view[0].below, viewNote, L::kWhite, view[0].scale);
  const L::Text flightTitle = "the same stack in perspective, the eye " +
                              L::given("the eye's height, level-0 texels", R::kFlightHeight, "%.0f") +
                              " texels above the ground";
  const L::Text flightNote =
      L::measuredText(m, "{clipmap_flight_mismatch_px|%.0f} pixels off the CPU's rays to the ground; the edges "
                         "between levels in the finer one's colour");
  const std::vector<L::Cell> flight = L::flowFitting({split + 12, 8, float(f.width - 8), middle},
                                                     {1, float(R::kFlightW) / R::kFlightH, 1, 1, 8, 1, 0},
                                                     {{flightTitle.text}}, {{flightNote.text}});
  picture(d->flight, "flight", "the clipmap in perspective", flight[0].picture, nullptr);
  L::caption(f, flight[0].above, flightTitle, L::kWhite, flight[0].scale);
  L::caption(f, flight[0].below, flightNote, L::kAmber, flight[0].scale);
  std::vector<L::Text> levelTitles, levelNotes;
  std::vector<L::Stack> levelAbove, levelBelow;
  for (int l = 0; l < R::kClipLevels; ++l) {
    levelTitles.push_back("level " + L::given("level", l, "%.0f") + ", of " +
                          L::given("level side", R::kVirtual >> l, "%.0f") + "^2");
    levelNotes.push_back(
        L::measuredText(m, "last move: {clipmap_level_texels_uploaded[" + std::to_string(l) + "]|%.0f} texels"));
    levelAbove.push_back({levelTitles.back().text}), levelBelow.push_back({levelNotes.back().text});
  }
  const std::vector<L::Cell> levels = L::flowFitting({8, middle + 4, float(f.width - 8), bottom},
                                                     {R::kClipLevels, 1.0f, 1, 1, 8, 1, 0}, levelAbove, levelBelow);
  for (int l = 0; l < R::kClipLevels && l < int(levels.size()); ++l) {
    const L::Cell& c = levels[size_t(l)];
    picture(d->clipLevels[l], "level_" + std::to_string(l), "clip level " + std::to_string(l), c.picture, nullptr);
    L::caption(f, c.above, levelTitles[size_t(l)], L::kWhite, c.scale);
    L::caption(f, c.below, levelNotes[size_t(l)], L::kAmber, c.scale);
  }
  L::legend(f, {8, bottom + 8, float(f.width - 8), bottom + 8 + key}, legend, 1);
  L::Column column(f, {8, float(f.height) - band, float(f.width - 8), float(f.height - 4)});
  for (const L::Text& t : notes) column.add(t, L::kAmber, 1);
  return f;
}
}  // namespace

TS_REGISTER_SCENE(TextureResidency);
