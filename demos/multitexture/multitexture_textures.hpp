// demos/multitexture/multitexture_textures.hpp — the multitexture demo's textures
// as named generators, so that a figure's sidecar alone remakes
// them (reference/sidecar_reader.cpp's remakeTexture, through the generator
// registry: multitexture_textures.cpp registers them): the name and params
// of each TextureDesc say how it was made.  Images are indexed as GL uploads
// them: texel (i, j), row j = 0 at t = 0 (the bottom).
#pragma once
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"

namespace ts::multitex {
// ---- the images -------------------------------------------------------------
// The cutout tree, 64 x 64 RGBA: a brown trunk and an elliptical green crown,
// alpha 255; alpha 0 elsewhere, keeping the leaves' green.  Every colour has
// blue <= 40 (the sky behind it has blue 255).
inline const Rgba kSky{100, 150, 255, 255};
bool inTree(double x, double y);
Image treeImage();
// The wall's bricks, 128 x 128: two reds, grey mortar.
Image bricksImage();
// A point light at height 0.3 over the unit square's centre: 0.15 + 0.85 (h/d)^3.
double lightAt(double x, double y);
// The light map, n x n grey (v, v, v, 255): the lighting at the texel centres,
// one byte a texel's worth (what GL_LUMINANCE8 would store; uploaded RGBA).
Image lightMapImage(int n);
// The spot, 32 x 32 grey: bright inside radius 0.3 of its centre, a soft rim,
// 0.2 at its border.
Image spotImage();
// base x lightAt per pixel for a w x w picture of the base (GL_NEAREST:
// texel = pixel * base size / w), rows as a texture (row 0 at the bottom).
Image perPixelLitImage(const Image& base, int w);
// The gloss map, w x h grey: 1 on the left half, 51/255 on the right.
constexpr double kGlossLow = 51.0 / 255.0;
// The light map's point light: its height over the unit square's centre.
constexpr double kLightHeight = 0.3;
Image glossImage(int w, int h);
// A, B, C, D: four 64 x 64 textures with AB + CD <= 1 (no clamping).
constexpr int kAbcdSize = 64;
std::vector<Image> abcdImages();
// The CPU's AB + CD (or (AB + C) D when `framebufferOnly`) for a w x w
// picture, each product rounded to 8 bits as the framebuffer stores it;
// rows as a readback (row 0 at the top).
Image abcdCpuImage(const std::vector<Image>& t, int w, bool framebufferOnly);
// The pear's pictures, 128 x 128: t_d a yellow-green skin with speckles, its
// alpha the gloss t_g (glossy skin 150, dull speckles and a dull band 25);
// the same gloss as grey (g, g, g, 255: what GL_LUMINANCE8 stores); t_r a
// sphere map of a sky and a bright window.
Image pearSkinImage();
Image pearGlossImage();
Image pearSkyImage();

// ---- the generators (name "multitexture_<what>") ----------------------------
// Texture descs without filters or wraps (the caller sets those; the sidecar
// records them beside the params).
TextureDesc treeTexture();               // "multitexture_tree"
TextureDesc bricksTexture();             // "multitexture_bricks"
TextureDesc lightMapTexture(int n);      // "multitexture_light_map", size n
TextureDesc spotTexture();               // "multitexture_spot"
TextureDesc perPixelLitTexture(int w);   // "multitexture_per_pixel_lit": bricks x lighting, w x w
TextureDesc glossTexture(int w, int h);  // "multitexture_gloss"
TextureDesc abcdTexture(int k);          // "multitexture_abcd", texture A..D (k = 0..3)
// "multitexture_abcd_cpu": AB + CD at w x w (what = "sum"), (AB + C) D
// ("framebuffer_only"), or |(AB + C) D - (AB + CD)| x 4 ("error_x4").
TextureDesc abcdCpuTexture(int w, const std::string& what);
TextureDesc pearSkinTexture();   // "multitexture_pear_skin"
TextureDesc pearGlossTexture();  // "multitexture_pear_gloss"
TextureDesc pearSkyTexture();    // "multitexture_pear_sky"
// The generator `name` with `params` (as the sidecar records them); false
// when `name` is not one of these.  Throws ts::Error on a bad param.
bool remake(const std::string& name, const std::vector<std::pair<std::string, std::string>>& params, TextureDesc* out);
}  // namespace ts::multitex
