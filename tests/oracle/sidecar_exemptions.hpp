// Figures whose sidecar cannot remake every texture: their panels are
// pictures that OpenGL itself rendered in the demo's measure() pass (Figure
// VI.7 shows GL's own multi-pass and per-pixel-jitter renders side by side, and
// its zone plate GL's shader renders of the plate;
// the parallax figures show GLSL renders of the filtering modes and errors;
// two environment mapping figures show error pictures made from GL's float read-backs;
// the bump-mapping figures show the displaced reference torus R, drawn from a
// 1024 x 512 grid in a vertex array by its measure(); the DXT1 figures show
// GL's decode of compressed blocks),
// so the sidecar records them by digest and by the command that makes them.
// These figures are still checked from their JSON alone, everywhere but on
// those pictures: read with ref::SidecarReadOptions::unknownPictures, a
// texture no generator remakes is a placeholder and the pixels that read it
// are exempt (Exempt::UnknownPicture), so the nested texgen frames, the
// flat panels, plots and frames around the pictures are verified
// (test_figures.cpp, test_committed.cpp).  Every other figure must be
// reproducible from its JSON alone, to the last pixel; a new figure that is
// not fails the oracle tests until it is made reproducible or listed here
// with its reason, and a listed figure whose sidecar remakes every texture
// fails until it is taken off the list.
#pragma once
#include <algorithm>
#include <array>
#include <string>

namespace oracle {
inline constexpr std::array<const char*, 15> kFiguresDrawnFromGlRenders = {
    "vi7_jitter", "jitter_zone_plate", "parallax_modes", "parallax_error_band", "parallax_step",
    // environment_mapping: its object pictures are nested frames the reference recomputes (texgen) or
    // exempts (GLSL), its maps "environment_map" textures it remakes, the texels read quads in the
    // sidecar (env_compare_torus, env_latlong_map, env_cube_map are all of these); but these two also
    // show a picture its measure() computes from GL's float read-backs, which no generator remakes: the
    // direction error per pixel (both), and env_flat_mirror's reference with the near ball painted in.
    // Their texgen pictures are still checked from the Frame (test_figures.cpp's GL tests, and
    // test_gl_envmap.cpp's TheEnvironmentMappingFiguresTexgenPictures).
    "env_cube_sphere", "env_flat_mirror",
    // bump_mapping: R, emboss and DOT3 are pictures its measure() draws
    "bump_two_lights", "bump_seed002", "bump_normals", "bump_methods", "bump_emboss_overhead",
    // filter_zoo: each method's picture is a GL render (GL's filters) or a CPU
    // computation (ripmap, SAT, probe line, EWA, the exact integral) made by measure()
    "filter_zoo_azimuth", "filter_zoo_supports", "mip_kernels"};

// Figures whose measure() takes minutes on softpipe (the parallax table: twelve
// full-frame GLSL passes and a CPU reference per state).  The oracle checks
// them on llvmpipe; on softpipe they are skipped, visibly, and the parallax
// demo's own tests (tests/figures/fig_parallax_aniso_test.cpp) run there at a
// small size.
inline constexpr std::array<const char*, 3> kFiguresTooSlowForSoftpipe = {"parallax_modes", "parallax_error_band",
                                                                          "parallax_step"};

inline bool tooSlowForSoftpipe(const std::string& id) {
  return std::any_of(kFiguresTooSlowForSoftpipe.begin(), kFiguresTooSlowForSoftpipe.end(),
                     [&](const char* f) { return id == f; });
}

// Figures that show measurements of the rasterizer's own filtering (the LOD it
// picks per quad, its anisotropic filter, the popping measure printed on
// them): another rasterizer legally draws them differently, so the fuzzy
// comparison with the committed (llvmpipe) PNGs applies on llvmpipe only.
// The per-pixel oracle and the mipmap tests still check them everywhere.
inline constexpr std::array<const char*, 7> kFiguresOfTheRasterizersFiltering = {
    "mip_popping_filmstrip", "mip_popping_plot", "mip_anisotropic", "inspect_aniso_footprint",
    // filter_zoo: GL's filters' pictures and errors (the memory plot places them by their RMS)
    "filter_zoo_azimuth", "filter_zoo_memory", "mip_kernels"};

inline bool showsTheRasterizersFiltering(const std::string& id) {
  return std::any_of(kFiguresOfTheRasterizersFiltering.begin(), kFiguresOfTheRasterizersFiltering.end(),
                     [&](const char* f) { return id == f; });
}

// Figures of smooth surfaces shaded per pixel in GLSL with a specular term
// (bump mapping's Phong torus): another rasterizer evaluates the shader with
// other float rounding, and the specular power magnifies it, so the fuzzy
// comparison with the committed (llvmpipe) PNGs allows 4 levels there, not 2.
// Measured on softpipe (Mesa 22.3.6), pixels over 2 / 3 / 4 / 8 levels of
// 573,440: bump_two_lights 15,594 / 7,167 / 3,934 / 1,114; bump_normals
// 20,169 / 7,717 / 3,240 / 907; bump_emboss_overhead 23,493 / 11,078 / 5,937
// / 1,350 (the 2 % bound is 11,468).  The bump tests' relations still hold
// there (fig_bump_mapping runs on softpipe too).
inline constexpr std::array<const char*, 5> kFiguresShadedPerPixelInGlsl = {"bump_two_lights", "bump_seed002",
                                                                            "bump_normals", "bump_methods",
                                                                            "bump_emboss_overhead"};

inline bool shadedPerPixelInGlsl(const std::string& id) {
  return std::any_of(kFiguresShadedPerPixelInGlsl.begin(), kFiguresShadedPerPixelInGlsl.end(),
                     [&](const char* f) { return id == f; });
}

// An array declared longer than its list pads with null pointers: refuse that at compile time.
template <size_t N>
constexpr bool allNamed(const std::array<const char*, N>& a) {
  for (const char* f : a)
    if (!f) return false;
  return true;
}
static_assert(allNamed(kFiguresDrawnFromGlRenders) && allNamed(kFiguresTooSlowForSoftpipe) &&
                  allNamed(kFiguresOfTheRasterizersFiltering) && allNamed(kFiguresShadedPerPixelInGlsl),
              "a list's declared size is larger than its entries");

inline bool drawnFromGlRenders(const std::string& id) {
  return std::any_of(kFiguresDrawnFromGlRenders.begin(), kFiguresDrawnFromGlRenders.end(),
                     [&](const char* f) { return id == f; });
}
}  // namespace oracle
