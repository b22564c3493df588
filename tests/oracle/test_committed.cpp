// The committed figures, checked without OpenGL: every book_figures/<id>.png
// must be a legal OpenGL result for the Frame its sidecar <id>.json
// describes (read by ref::readSidecar, textures re-made from their names).
// The sidecar does not record label scale and alignment, so wide boxes
// around labels are exempt.  Skipped, visibly, while no figure is committed.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "common/core/image.hpp"
#include "reference/sidecar_reader.hpp"
#include "reference/verify.hpp"
#include "sidecar_exemptions.hpp"

#ifndef TS_SOURCE_DIR
#define TS_SOURCE_DIR "."
#endif
#ifndef TS_ORACLE_OUT_DIR
#define TS_ORACLE_OUT_DIR "oracle_failures"
#endif

namespace {
TEST(CommittedFigures, EachPngIsLegalForItsSidecar) {
  namespace fs = std::filesystem;
  fs::path dir = fs::path(TS_SOURCE_DIR) / "book_figures";
  int checked = 0, exempt = 0;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.path().extension() != ".json") continue;
      fs::path png = e.path();
      png.replace_extension(".png");
      if (!fs::exists(png)) continue;
      SCOPED_TRACE(e.path().string());
      // A figure whose panels include pictures its measure() made (GL renders,
      // CPU images from them: drawn_from_gl in its demo's facts.tsv) is read with those
      // pictures as placeholders and their pixels exempt; the rest is checked.
      const bool listed = oracle::drawnFromGlRenders(e.path().stem().string());
      ref::SidecarReadOptions ro;
      ro.unknownPictures = listed;
      ref::SidecarScene sc = ref::readSidecarFile(e.path().string(), TS_SOURCE_DIR, ro);
      ref::VerifyOptions o;
      o.name = e.path().stem().string() + ".committed";
      o.outputDir = std::string(TS_ORACLE_OUT_DIR) + "/committed";
      o.render.labelGeometryKnown = sc.labelGeometryKnown;
      o.render.exemptTextures = sc.unknownPictures;
      ref::VerifyResult r = ref::verifyImage(ts::readPng(png.string()), sc.frame, o);
      std::printf("[oracle] %s\n", r.summary().c_str());
      EXPECT_EQ(r.invalid, 0) << r.summary();
      if (listed) {
        EXPECT_FALSE(sc.unknownPictures.empty())
            << "marked drawn_from_gl in its demo's facts.tsv, but every texture is remade";
        ++exempt;
      } else {
        // Plots are mostly lines and labels (exempt); a quarter of the pixels is
        // still a real check, and a figure the oracle cannot read at all fails.
        EXPECT_GT(r.checked, r.pixels / 4) << r.summary();
      }
      ++checked;
    }
  EXPECT_LE(exempt, int(oracle::figuresDrawnFromGlRenders().size()));
  if (checked == 0) GTEST_SKIP() << "no PNG with a sidecar in " << dir.string() << " (scripts/figures.sh makes them)";
}
}  // namespace

namespace {
// Claim: book figures are opaque.  Blending (seam patches, label boxes) must
// not blend into the framebuffer's alpha: a viewer would show the page
// through a figure (a half-transparent seam patch blended into alpha would
// leave tens of thousands of pixels at alpha 192).
TEST(CommittedFigures, AreOpaque) {
  namespace fs = std::filesystem;
  fs::path dir = fs::path(TS_SOURCE_DIR) / "book_figures";
  int figures = 0;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.path().extension() != ".png") continue;
      ts::Image img = ts::readPng(e.path().string());
      long translucent = 0;
      for (size_t i = 3; i < img.pixels.size(); i += 4) translucent += img.pixels[i] != 255;
      EXPECT_EQ(translucent, 0) << e.path().filename().string() << ": pixels with alpha below 255";
      ++figures;
    }
  if (figures == 0) GTEST_SKIP() << "no PNG in " << dir.string();
}
}  // namespace
