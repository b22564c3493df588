// Texture atlases (seed 001, "atlases" and "sub-textures through the API"; Buss VI.1.3): many small textures packed
// into one, so that a scene of N objects binds one texture and draws one batch instead of N of each; the price is
// that the atlas's mipmaps average a tile's texels with its neighbours', unless each tile has a gutter.
//
// The claim (view atlas): a floor that repeats ONE tile of a 4 x 4 atlas, trilinear (GL_LINEAR_MIPMAP_LINEAR),
// shows its neighbours' colours at the tile's edges ("mip bleeding") unless the tile's gutter (its own edge texels
// replicated around it) is wide enough for the deepest level k the floor reads: half a level-k texel, 2^(k-1)
// texels, for tiles packed right after their gutters as here (2^k for tiles aligned to level k's boxes).  With that
// gutter the floor is, pixel for pixel, the floor drawn with the tile alone; with none, or one level's less, it is not.
//
// The fair reference.  Not the lone tile with GL_REPEAT (the floor's squares do not wrap round the tile: each
// square's corners carry the tile's (s, t) range) nor with GL_CLAMP_TO_EDGE (a gutter replicates level 0's edge,
// clamping replicates each level's own edge: at level 1 and deeper they differ wherever the tile's last two columns
// do): the reference is the tile's own cell, tile and gutter, as a texture of its own (GL_CLAMP_TO_EDGE, the same
// filter, the same squares).  The atlas then differs from it only by what lies beside the cell: the neighbours.
//
// Keys (each is also a flag, see --help):
//   v  view: atlas | fixes | subimage
//   g  the gutter of the atlas's second row of pictures: enough (what the deepest level needs) | 1 | 2 | ... | 32
//
// The equations.  Level k+1 texel (i, j) = the mean of level k's (2i..2i+1, 2j..2j+1) (the book's 2x2 box, built
// on the CPU), so a level-k texel is the mean of a 2^k x 2^k box of level 0, the boxes starting at multiples of 2^k.
// At the tile's edge x0 the bilinear filter at level k reaches back half a level-k texel, to x0 - 2^(k-1), and
// reads the box that holds it.  That box is the cell's own (gutter, not neighbour) when the cells start on box
// boundaries (the pitch 32 + 2 gutter a multiple of 2^k) and 2^k floor((x0 - 2^(k-1)) / 2^k) >= x0 - gutter; with
// x0 = c pitch + gutter (each tile right after its gutter):
//      gutter(k) = 1 (k = 0: half a texel past the edge),  2^(k-1) (k >= 1),
//      k = the deepest level read = ceil(lambda_max)   (GL_LINEAR_MIPMAP_LINEAR reads floor(lambda), floor(lambda) + 1)
// (A tile aligned to level k, x0 a multiple of 2^k, has its edge on a box boundary and the filter reads the whole box
// left of it: 2^k, the rule usually quoted.)  lambda is read off a level picture: the same floor with a texture
// whose level k is flat, red = 32 k, so that GL's blend of two levels leaves red = 32 lambda; the gutter each level
// needs is measured where lambda <= k, and the test recomputes it from the mip chains alone.  The atlas's levels
// stop at the tile's last, 5 (1 x 1 texel): past it no gutter keeps the tiles apart.
//
// What the GL does, all in common/gl/render.cpp (Renderer::draw of each floor's Frame, texture_atlas_math.hpp):
//   glTexImage2D(GL_TEXTURE_2D, k, GL_RGBA8, W >> k, W >> k, 0, GL_RGBA, GL_UNSIGNED_BYTE, level_k);  k = 0..5,
//                W = the atlas's side: 4 (32 + 2 gutter) up to a power of two, 128 (no gutter) to 512 (gutter 32)
//   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 5);   (fewer for the limited-levels fix)
//   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);  GL_CLAMP_TO_EDGE
//   glBegin(GL_TRIANGLES); glTexCoord4f(s0 + u (s1 - s0), t0 + v (t1 - t0), 0, 1); glVertex3f(...) ... glEnd();
// with (s0, t0, s1, t1) = the tile's texels in the atlas / the atlas's side.  The N objects (texture_atlas_gl.hpp):
//   separate:  for each k: glBindTexture(GL_TEXTURE_2D, tile[k]); glBegin(GL_QUADS); ... glEnd();
//   atlas:     glBindTexture(GL_TEXTURE_2D, atlas); glBegin(GL_QUADS); all N squares ... glEnd();
// The sub-image (view subimage): one tile of a 128 x 128 picture uploaded in place, no copy on the CPU:
//   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
//   glPixelStorei(GL_UNPACK_ROW_LENGTH, 128); glPixelStorei(GL_UNPACK_SKIP_PIXELS, 64);
//   glPixelStorei(GL_UNPACK_SKIP_ROWS, 32);
//   glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 32, 32, GL_RGBA, GL_UNSIGNED_BYTE, picture);
//   glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback);
// Listings: book_figures/texture_atlas.gl.txt, texture_atlas_fixes.gl.txt, texture_atlas_subimage.gl.txt.
// The time of a frame of N objects, N textures against one atlas: tests/bench/bench_atlas.cpp (a benchmark).
//
// Measured (measure(), texture_atlas_views.hpp): every floor rendered offscreen at 256 x 160 and read back; the
// pixels more than 3 levels (kTolerance: three 8-bit interpolation weights) off the reference, for gutters 0, 1,
// 2, 4, 8, 16, 32; the deepest level from the level picture, and the gutter each level needs; the three fixes
// (gutters; (s, t) clamped half a level-k texel in from the tile's edge; a 1-texel gutter with GL_TEXTURE_MAX_LEVEL
// the deepest level it covers), each with its bleed and its cost; the binds and glBegin calls of the N objects,
// counted from the recorded calls; the in-place upload's texels (glGetTexImage) against the tile copied out first,
// and with a wrong row length.
#include <string>
#include <vector>

#include "common/core/frame.hpp"

#include "common/core/layout.hpp"
#include "common/core/scene.hpp"
#include "common/gl/render.hpp"
#include "demos/texture_atlas/texture_atlas_textures.hpp"
#include "texture_atlas_views.hpp"

namespace {
namespace A = ts::atlas;
const char* const kGutterChoices[] = {"enough", "1", "2", "4", "8", "16", "32"};

class TextureAtlas final : public ts::Scene {
 public:
  std::string id() const override { return "texture_atlas"; }
  std::string title() const override { return "Texture atlases: mip bleeding, its fixes, sub-images through the API"; }
  std::string about() const override {
    return "Sixteen tiles packed in one atlas; a receding floor repeats one of them, trilinear.  Measured: the\n"
           "floor's pixels off the same floor drawn with the tile's cell alone, for gutters 0 to 32 (bleeding stops\n"
           "at half a level-k texel of gutter, k the deepest level read, from a level picture); the fixes (gutters,\n"
           "clamped coordinates, GL_TEXTURE_MAX_LEVEL) with their costs; binds and draw calls of N objects, N\n"
           "textures against one atlas.\n"
           "View subimage: one tile uploaded in place with GL_UNPACK_ROW_LENGTH / SKIP_PIXELS / SKIP_ROWS, read back.";
  }
  std::vector<std::string> claim() const override {
    if (view_ == 1) return {"fix_bleed_px*"};
    if (view_ == 2) return {"subimage_mismatches", "subimage_mismatches[wrong_row_length]"};
    return {"atlas_bleed_px[gutter=0]", "atlas_bleed_px[gutter=enough]"};
  }
  void addOptions(ts::Options& o) override {
    o.addEnum("view", &view_, {"atlas", "fixes", "subimage"},
              "mip bleeding and the gutter it needs | the three fixes side by side | a tile uploaded in place "
              "(GL_UNPACK_ROW_LENGTH)",
              'v');
    o.addEnum("gutter", &gutter_,
              {kGutterChoices[0], kGutterChoices[1], kGutterChoices[2], kGutterChoices[3], kGutterChoices[4],
               kGutterChoices[5], kGutterChoices[6]},
              "view atlas: the gutter, texels, of the second row's atlas (enough: what the deepest level read needs)",
              'g');
  }
  std::vector<ts::FigureSpec> figures() const override {
    return {
        {"texture_atlas",
         "Texture atlas: mip bleeding (seed 001; Buss VI.1.3)",
         "A floor repeating one tile of a 4 x 4 atlas, trilinear, against the same floor drawn with the tile's cell "
         "alone: with no gutter the neighbours' texels bleed into the tile's edges; with a gutter of half a level-k "
         "texel, k the deepest level the floor reads (the level picture), nothing does; the table: each level's need.",
         {"--view", "atlas"},
         1100,
         660,
         "With no gutter {atlas_bleed_px[gutter=0]} floor pixels show the neighbours; with a gutter of "
         "{atlas_gutter_needed} texels (level {atlas_deepest_level}) {atlas_bleed_px[gutter=enough]}, with half "
         "that {atlas_bleed_px[gutter=short]}.  N = {atlas_objects} objects: {atlas_binds[separate]} binds and "
         "{atlas_draws[separate]} draws, or {atlas_binds[atlas]} and {atlas_draws[atlas]} from the atlas."},
        {"texture_atlas_fixes",
         "Texture atlas: three fixes for mip bleeding (seed 001)",
         "The same floor with three fixes, each against the tile alone drawn the same way, and what each costs: a "
         "gutter (texels of the atlas), coordinates clamped in from the tile's edge (its border never shown), "
         "GL_TEXTURE_MAX_LEVEL at the last level a 1-texel gutter covers (the far floor under-filtered: aliasing).",
         {"--view", "fixes"},
         1100,
         640,
         "Bleed: gutter {atlas_bleed_px[gutter=enough]}, clamped {fix_bleed_px[clamp]}, levels limited "
         "{fix_bleed_px[max_level]} pixels; costs: the tiles fill {atlas_tile_share[gutter=enough]} of the atlas, "
         "{fix_cost_px[clamp]} and {fix_cost_px[max_level]} pixels changed."},
        {"texture_atlas_subimage",
         "Texture atlas: a sub-image through the API (seed 001)",
         "One tile of a larger picture uploaded with glTexSubImage2D straight from the picture's memory "
         "(GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS), read back with glGetTexImage: the "
         "tile copied out first gives the same texels; a row length one pixel short shears it.",
         {"--view", "subimage"},
         1000,
         440,
         "{subimage_mismatches} texels differ from the tile copied out on the CPU; with a row length of "
         "{subimage_row_length} - 1, {subimage_mismatches[wrong_row_length]} do."}};
  }
  ts::Frame build(int width, int height, const ts::Measurements& measured) const override;
  ts::Measurements measure(ts::Renderer& r) override {
    ts::Measurements out;
    out.detail = A::measureAtlas(r, out);
    return out;
  }

 private:
  void buildAtlas(ts::Frame& f, const ts::Measurements& m, const A::Pictures& p) const;
  void buildFixes(ts::Frame& f, const ts::Measurements& m, const A::Pictures& p) const;
  void buildSubimage(ts::Frame& f, const ts::Measurements& m, const A::Pictures& p) const;
  int view_ = 0, gutter_ = 0;
};

ts::Frame TextureAtlas::build(int width, int height, const ts::Measurements& measured) const {
  namespace L = ts::layout;
  ts::Frame f = L::blankFrame(width, height);
  const A::Pictures* p = measured.detailAs<A::Pictures>();
  if (!p) {
    L::caption(f, {8, 8, float(width - 8), float(height - 8)}, "rendering ...", L::kWhite, 2);
    return f;
  }
  if (view_ == 0) buildAtlas(f, measured, *p);
  else if (view_ == 1) buildFixes(f, measured, *p);
  else buildSubimage(f, measured, *p);
  return f;
}

// The bleed: the atlas with no gutter and with the chosen one, each against its cell alone, and the level picture.
void TextureAtlas::buildAtlas(ts::Frame& f, const ts::Measurements& measured, const A::Pictures& p) const {
  namespace L = ts::layout;
  auto M = [&](const std::string& templ) { return L::measuredText(measured, templ); };
  const int shown = gutter_ == 0 ? p.gutters[p.enoughIndex] : std::stoi(kGutterChoices[gutter_]);
  size_t i = 0;
  while (i + 1 < p.gutters.size() && p.gutters[i] != shown) ++i;
  const std::string g = std::to_string(p.gutters[i]);
  const L::Text gText = L::given("the second row's gutter, texels", p.gutters[i], "%.0f");
  std::vector<A::Picture> ps = {
      {A::floorPicture(p.atlasFloors[0], A::atlasFloor(0), "the atlas floor, gutter 0"),
       "atlas, no gutter",
       M("{atlas_bleed_px[gutter=0]|%.0f} px bleed"),
       {}},
      {A::floorPicture(p.cellFloors[0], A::cellFloor(0), "the tile alone"),
       "the tile alone (reference)",
       "GL_CLAMP_TO_EDGE, same filter",
       {}},
      {A::drawnPicture(A::bleedMap(p.atlasFloors[0], p.cellFloors[0]), "bleed, gutter 0", nullptr),
       "atlas - tile alone, no gutter",
       M("{atlas_bleed_px[gutter=0]|%.0f} px red"),
       {}},
      {A::floorPicture(p.atlasFloors[i], A::atlasFloor(p.gutters[i]), "the atlas floor, gutter " + g),
       "atlas, gutter " + gText,
       M("{atlas_bleed_px[gutter=" + g + "]|%.0f} px bleed"),
       {}},
      {A::drawnPicture(A::bleedMap(p.atlasFloors[i], p.cellFloors[i]), "bleed, gutter " + g, nullptr),
       "atlas - its cell alone, gutter " + gText,
       M("{atlas_bleed_px[gutter=" + g + "]|%.0f} px red"),
       {}},
      {A::floorPicture(p.levels, A::levelFloor(), "the level picture"),
       "the level read (LOD)",
       M("LOD up to {atlas_lod_max|%.2f}: level {atlas_deepest_level|%.0f}"),
       {}}};
  std::vector<ts::LegendEntry> legend = {
      {A::kBleed, "more than " + std::to_string(A::kTolerance) + " levels off the reference"}};
  const std::vector<ts::Image> levels = A::levelImages(A::kTile);
  for (int k = 0; k <= p.deepest && k < int(levels.size()); ++k)
    legend.push_back({A::colour(levels[size_t(k)].at(0, 0)), "level " + std::to_string(k)});
  // The table: each level's gutter, the equation's and the one measured (the narrowest with no bleeding where the
  // LOD is at most that level).
  L::Text table = "Gutter each level needs, texels (equation / measured):";
  for (int k = 0; k <= p.deepest; ++k)
    table = table + "  level " + L::given("mip level", k, "%.0f") + ": " +
            L::given("the equation's gutter for the level, texels", A::gutterForLevel(k), "%.0f") + " / " +
            M("{atlas_gutter_needed[level=" + std::to_string(k) + "]|%.0f}") + (k < p.deepest ? ";" : ".");
  std::vector<L::Text> lines = {table};
  lines.push_back(M("With the gutter the deepest level needs, {atlas_gutter_needed|%.0f} texels: "
                    "{atlas_bleed_px[gutter=enough]|%.0f} px bleed; one level short, {atlas_gutter_short|%.0f} texels: "
                    "{atlas_bleed_px[gutter=short]|%.0f} px; none: {atlas_bleed_px[gutter=0]|%.0f} px."));
  lines.push_back(
      M("N = {atlas_objects|%.0f} objects, each its own texture: {atlas_binds[separate]|%.0f} glBindTexture and "
        "{atlas_draws[separate]|%.0f} glBegin; from the atlas: {atlas_binds[atlas]|%.0f} and "
        "{atlas_draws[atlas]|%.0f}; the two pictures differ in {atlas_objects_mismatches|%.0f} pixels."));
  A::pictureGrid(f, ps, float(A::kFloorW) / float(A::kFloorH), legend, lines);
}

// The three fixes, each beside what it costs.
void TextureAtlas::buildFixes(ts::Frame& f, const ts::Measurements& measured, const A::Pictures& p) const {
  namespace L = ts::layout;
  auto M = [&](const std::string& templ) { return L::measuredText(measured, templ); };
  const size_t e = p.enoughIndex;
  const int enough = p.gutters[e];
  const L::Text gText = L::measured(measured, "atlas_gutter_needed", "%.0f");
  std::vector<A::Picture> ps = {
      {A::floorPicture(p.atlasFloors[e], A::atlasFloor(enough), "the atlas floor, gutter enough"),
       "1. a gutter of " + gText + " texels",
       M("{atlas_bleed_px[gutter=enough]|%.0f} px bleed"),
       {}},
      {A::drawnPicture(A::bleedMap(p.atlasFloors[e], p.cellFloors[e]), "bleed, gutter enough", nullptr),
       "its bleed",
       M("cost: tiles fill {atlas_tile_share[gutter=enough]|%.2f} of the atlas"),
       {}},
      {A::floorPicture(p.clampAtlas, A::atlasFloor(0, p.inset), "the atlas floor, clamped"),
       "2. no gutter, (s, t) clamped in",
       M("{fix_bleed_px[clamp]|%.0f} px bleed"),
       {}},
      {A::drawnPicture(A::bleedMap(p.clampCell, p.cellFloors[0]), "clamped against whole", nullptr),
       "its cost: the tile's border lost",
       M("{fix_cost_px[clamp]|%.0f} px changed"),
       {}},
      {A::floorPicture(p.limitAtlas, A::atlasFloor(p.limitGutter, 0, p.limitLevel), "the atlas floor, levels limited"),
       M("3. GL_TEXTURE_MAX_LEVEL {fix_max_level|%.0f}, gutter {fix_gutter[max_level]|%.0f}"),
       M("{fix_bleed_px[max_level]|%.0f} px bleed"),
       {}},
      {A::drawnPicture(A::bleedMap(p.limitCell, p.cellFloors[1]), "levels limited against all levels", nullptr),
       "its cost: aliasing",
       M("{fix_cost_px[max_level]|%.0f} px changed"),
       {}}};
  const std::vector<ts::LegendEntry> legend = {{A::kBleed, "more than " + std::to_string(A::kTolerance) +
                                                               " levels off the reference (bleed) or the whole, "
                                                               "mipmapped tile (cost)"}};
  const std::vector<L::Text> lines = {
      M("1. Gutter: the tiles fill {atlas_tile_share[gutter=enough]|%.2f} of the atlas's texels against "
        "{atlas_tile_share[gutter=0]|%.2f} with none (the texture grows to the next power of two)."),
      M("2. Clamped: (s, t) stop {fix_inset_texels[clamp]|%.0f} texels of level 0 in from each edge, half a texel of "
        "level {atlas_deepest_level|%.0f}: the filter never leaves the tile, but only the tile's middle is shown "
        "(when that level's texel is the whole tile, nothing of its pattern is left)."),
      M("3. Levels limited: a gutter of {fix_gutter[max_level]|%.0f} covers levels 0 to {fix_max_level|%.0f} (the "
        "table); with every level it bleeds {fix_bleed_px[max_level_full_chain]|%.0f} px, with those alone "
        "{fix_bleed_px[max_level]|%.0f}, but the far floor is under-filtered: {fix_cost_px[max_level]|%.0f} px "
        "change.")};
  A::pictureGrid(f, ps, float(A::kFloorW) / float(A::kFloorH), legend, lines);
}

// The sub-image: the picture with the tile marked, the tile uploaded in place, copied out, and with a wrong row length.
void TextureAtlas::buildSubimage(ts::Frame& f, const ts::Measurements& measured, const A::Pictures& p) const {
  namespace L = ts::layout;
  auto M = [&](const std::string& templ) { return L::measuredText(measured, templ); };
  const float n = float(p.rowLength);
  const float x0 = float(p.skipPixels) / n, y0 = float(p.skipRows) / n, x1 = x0 + A::kTile / n, y1 = y0 + A::kTile / n;
  // Texels read back (row 0 = t = 0) shown upright: drawnPicture takes a picture with row 0 at the top.
  auto upright = [](ts::Image img) {
    img.flipVertical();
    return img;
  };
  std::vector<A::Picture> ps = {{A::sourceTexture(),
                                 "the picture, " + L::given("picture side, pixels", p.rowLength, "%.0f") + " x " +
                                     L::given("picture side, pixels", p.rowLength, "%.0f"),
                                 "yellow: the tile read",
                                 {ts::lineLoop({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, A::kOutline, 2.0f, "tile")}},
                                {A::drawnPicture(upright(p.subTexels), "uploaded in place", p.subCalls),
                                 "glTexSubImage2D in place",
                                 M("{subimage_mismatches|%.0f} texels off the copy"),
                                 {}},
                                {A::drawnPicture(upright(p.copiedTexels), "copied out, uploaded whole", p.copiedCalls),
                                 "copied out on the CPU",
                                 M("{subimage_bytes|%.0f} bytes either way"),
                                 {}},
                                {A::drawnPicture(upright(p.wrongTexels), "row length one short", p.wrongCalls),
                                 "GL_UNPACK_ROW_LENGTH " + L::given("the wrong row length", p.wrongRowLength, "%.0f"),
                                 M("{subimage_mismatches[wrong_row_length]|%.0f} texels off"),
                                 {}}};
  const std::vector<ts::LegendEntry> legend = {{A::kOutline, "the tile the upload reads"}};
  const std::vector<L::Text> lines = {
      M("glPixelStorei(GL_UNPACK_ROW_LENGTH, {subimage_row_length|%.0f}); GL_UNPACK_SKIP_PIXELS "
        "{subimage_skip_pixels|%.0f}; GL_UNPACK_SKIP_ROWS {subimage_skip_rows|%.0f}; glTexSubImage2D of the whole "
        "picture's pointer reads the tile, no copy on the CPU."),
      M("Read back with glGetTexImage: {subimage_mismatches|%.0f} texels differ from the tile copied out first, "
        "{subimage_mismatches[cpu]|%.0f} from the CPU's copy; with a row length one pixel short every row starts one "
        "texel further left: {subimage_mismatches[wrong_row_length]|%.0f} differ.")};
  A::pictureGrid(f, ps, 1.0f, legend, lines);
}
}  // namespace

TS_REGISTER_SCENE(TextureAtlas);
