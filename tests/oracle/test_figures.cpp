// The oracle applied to every registered figure: the GL render of the
// figure's Frame must be, pixel for pixel, a legal OpenGL result for that
// Frame (reference/verify.hpp), with labels off, with labels on (their boxes
// exempt), and when the Frame is re-read from its own sidecar JSON.  Then,
// when a committed PNG exists in book_figures/, a fuzzy comparison with it
// as the regression backstop.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <stdexcept>

#include "common/core/error.hpp"
#include "common/gl/figure.hpp"
#include "common/core/options.hpp"
#include "common/core/scene.hpp"
#include "common/core/sidecar.hpp"
#include "oracle_support.hpp"
#include <random>

#include "common/app/inspect_view.hpp"
#include "reference/inspect.hpp"
#include "sidecar_exemptions.hpp"
#include "reference/sidecar_reader.hpp"

#ifndef TS_SOURCE_DIR
#define TS_SOURCE_DIR "."
#endif

namespace {
// The committed PNGs are OSMesa renders.  Through EGL (an RGBA8 FBO) a figure
// may differ from OSMesa by as many pixels as the reliability tests' measured
// backend bound allows (its backend_bound row in its demo's facts.tsv:
// pixels that differ at all); 0 for a figure without one (byte-identical).
long backendBoundPixels(const std::string& id) { return ts::test::factValue(TS_SOURCE_DIR, "backend_bound", id, 0); }

struct FigureCase {
  std::string scene;
  ts::FigureSpec spec;
};

std::vector<FigureCase> allFigures() {
  std::vector<FigureCase> out;
  for (const auto& reg : ts::sceneRegistry()) {
    std::unique_ptr<ts::Scene> s = reg.make();
    for (const auto& spec : s->figures()) out.push_back({reg.id, spec});
  }
  return out;
}

// One render per figure for all the checks below (measure() is not free).
struct Renders {
  ts::Rendered withLabels;
  ts::Image plain;
  std::shared_ptr<ref::Reference> reference;  // of the Frame, labels off until `labelled`
  bool labelled = false;
};
Renders& rendersOf(const FigureCase& c) {
  static std::map<std::string, Renders> cache;
  auto it = cache.find(c.spec.id);
  if (it != cache.end()) return it->second;
  std::unique_ptr<ts::Scene> scene = ts::makeScene(c.scene);
  if (!scene) throw std::runtime_error("no scene " + c.scene);
  ts::Options o;
  scene->addOptions(o);
  ts::CommonFlags common;  // a footprint figure's --inspect and --footprints
  o.parse(ts::sceneFlags(c.spec.flags, &common));
  Renders r;
  // As the figure tool draws it: measure, then draw with labels; then once
  // more without labels.
  r.withLabels = ts::renderScene(*scene, ts::test::renderer(), c.spec.width, c.spec.height);
  ts::applyInspect(c.scene, common, ts::test::renderer(), &r.withLabels, false, nullptr);  // as make_figures does
  r.plain = oracle::render(r.withLabels.frame, false);
  ref::RenderOptions ro;
  ro.labels = false;
  r.reference = std::make_shared<ref::Reference>(r.withLabels.frame, ro);
  return cache.emplace(c.spec.id, std::move(r)).first->second;
}

class Figure : public ::testing::TestWithParam<FigureCase> {
 protected:
  void SetUp() override {
    if (oracle::tooSlowForSoftpipe(GetParam().spec.id) &&
        ts::test::rendererString().find("softpipe") != std::string::npos)
      GTEST_SKIP() << GetParam().spec.id
                   << ": its measure() takes minutes on softpipe (too_slow_softpipe in its demo's facts.tsv)";
    if (oracle::softpipeDrawsItWrong(GetParam().spec.id) &&
        ts::test::rendererString().find("softpipe") != std::string::npos)
      GTEST_SKIP() << GetParam().spec.id
                   << ": softpipe draws it against the specification (softpipe_wrong in its demo's facts.tsv; "
                      "docs/platform.md)";
    renders_ = &rendersOf(GetParam());
    rendered_ = &renders_->withLabels;
    plain_ = &renders_->plain;
  }
  // The reference without labels, or with them drawn in (in place: the
  // checks run in that order, and a reference made again is the rare case).
  const ref::Reference& reference(bool labels) {
    Renders& r = *renders_;
    if (!r.reference || (r.labelled && !labels)) {
      ref::RenderOptions ro;
      ro.labels = false;
      r.reference = std::make_shared<ref::Reference>(r.withLabels.frame, ro);
      r.labelled = false;
    }
    if (labels && !r.labelled) r.reference->addLabels(r.withLabels.frame), r.labelled = true;
    return *r.reference;
  }
  Renders* renders_ = nullptr;
  const ts::Rendered* rendered_ = nullptr;
  const ts::Image* plain_ = nullptr;
};

TEST_P(Figure, GLRenderIsALegalResultWithoutLabels) {
  const FigureCase& c = GetParam();
  ref::VerifyOptions o = oracle::options(c.spec.id + ".nolabels", "figures");
  o.render.labels = false;
  ref::VerifyResult r = ref::verifyImage(*plain_, reference(false), o);
  std::printf("[oracle] %s\n", r.summary().c_str());
  RecordProperty("invalid_pixels", std::to_string(r.invalid));
  RecordProperty("checked_pixels", std::to_string(r.checked));
  EXPECT_EQ(r.invalid, 0) << r.summary();
  // The figure must actually be checked, not exempted away (a figure may
  // hold unmodelled parts — other GLSL programs, anisotropic filtering —
  // but most of it must be checked).
  EXPECT_GT(r.checked, r.pixels / 2) << r.summary();
}

// The pixel inspector (--inspect) tells the reference's colour at
// any pixel without drawing the frame.  At 50 random pixels of every figure
// it must be the reference image's pixel (within an 8-bit step: the image
// rounds once more), and GL's pixel there is legal for that reference (the
// test above): so reference_rgba lies within the oracle's tolerance of
// gl_rgba.  Fixed-function figures only (a shader's lookup is not modelled).
TEST_P(Figure, InspectorAgreesWithTheReferenceAtRandomPixels) {
  const FigureCase& c = GetParam();
  ref::RenderOptions ro;
  ro.labels = false;
  ref::Inspector inspector(rendered_->frame, ro);
  std::mt19937 rng(12345);
  int compared = 0, textured = 0;
  for (int k = 0; k < 50; ++k) {
    const int x = int(rng() % unsigned(plain_->width)), y = int(rng() % unsigned(plain_->height));
    const ref::Inspection in = inspector.at(x, y);
    if (in.program) continue;
    // A nested frame's picture (TextureDesc::renderedFrom): the inspector reads
    // the picture GL drew, the reference its own recomputation of that frame
    // (unknown where the frame's pixels are a program's): not comparable here.
    if (in.texture >= 0 && rendered_->frame.textures.at(size_t(in.texture)).renderedFrom) continue;
    // A GL_NEAREST lookup exactly on a texel edge (a panel 300 px wide showing
    // 320 texels puts some pixel centres there): either texel is legal, the
    // oracle checks both sides, and the inspector and the reference image
    // may round the tie apart.
    auto onEdge = [](double c) { return std::isfinite(c) && std::abs(c - std::round(c)) < 1e-4; };
    if (in.textured && in.filter == GL_NEAREST && (onEdge(in.u) || onEdge(in.v))) continue;
    const ts::Rgba want = reference(false).image().at(x, y), got = ref::toRgba(in.pixelRgba);
    EXPECT_LE(std::abs(int(got.r) - want.r) + std::abs(int(got.g) - want.g) + std::abs(int(got.b) - want.b), 3)
        << c.spec.id << " pixel " << x << "," << y << "\n"
        << ref::formatInspection(in);
    ++compared, textured += in.textured;
  }
  std::printf("[inspect] %s: %d of 50 random pixels compared (%d textured)\n", c.spec.id.c_str(), compared, textured);
}

TEST_P(Figure, GLRenderIsALegalResultWithLabelsExempt) {
  const FigureCase& c = GetParam();
  ref::VerifyOptions o = oracle::options(c.spec.id + ".labels", "figures");
  ref::VerifyResult r = ref::verifyImage(rendered_->image, reference(true), o);
  renders_->reference.reset();  // the last check that reads it: its memory back
  std::printf("[oracle] %s\n", r.summary().c_str());
  EXPECT_EQ(r.invalid, 0) << r.summary();
  if (!rendered_->frame.labels.empty()) {
    EXPECT_GT(r.exemptBy[size_t(ref::Exempt::Label)], 0) << r.summary();
  }
}

TEST_P(Figure, SidecarAloneReproducesTheFrame) {
  const FigureCase& c = GetParam();
  ts::SidecarInfo info;
  info.figureId = c.spec.id;
  info.demo = c.scene;
  // A figure marked drawn_from_gl in its demo's facts.tsv shows pictures its measure()
  // made (GL renders read back, CPU images computed from them, named in the
  // sidecar by digest and command; maps of the demo's own code) that no
  // generator remakes: those pixels are exempt, and the rest of the figure is
  // still checked from its JSON alone.
  const bool listed = oracle::drawnFromGlRenders(c.spec.id);
  // Every texture is remade by its generator, or is the render of a nested
  // frame (TextureDesc::renderedFrom) whose own textures are.
  if (!listed) {
    std::vector<const ts::Frame*> frames = {&rendered_->frame};
    for (size_t k = 0; k < frames.size(); ++k)
      for (const auto& t : frames[k]->textures) {
        if (t.renderedFrom) {
          frames.push_back(t.renderedFrom.get());
          continue;
        }
        try {
          ref::remakeTexture(t.name, t.params, TS_SOURCE_DIR);
        } catch (const ts::Error& e) {
          FAIL() << "the sidecar cannot reproduce " << c.spec.id << ": " << e.what();
        }
      }
  }
  ref::SidecarReadOptions ro;
  ro.unknownPictures = listed;
  ref::SidecarScene sc = ref::readSidecar(ts::sidecarJson(rendered_->frame, info), ro);
  if (listed)
    EXPECT_FALSE(sc.unknownPictures.empty())
        << c.spec.id << " is marked drawn_from_gl in its demo's facts.tsv, but its "
        << "sidecar remakes every texture: take the row out";
  // The sidecar alone holds what the picture needs: nothing is copied from
  // the Frame, so a field the writer drops makes this check fail.
  EXPECT_TRUE(sc.missing.empty()) << "the sidecar lacks " << (sc.missing.empty() ? "" : sc.missing.front());
  EXPECT_TRUE(sc.labelGeometryKnown);
  EXPECT_TRUE(sc.fixedStateKnown);
  ref::VerifyOptions o = oracle::options(c.spec.id + ".sidecar", "figures");
  o.render.labels = false;
  o.render.exemptTextures = sc.unknownPictures;
  ref::VerifyResult r = ref::verifyImage(*plain_, sc.frame, o);
  EXPECT_EQ(r.invalid, 0) << r.summary();
  if (listed)
    std::printf("[oracle] %s from its sidecar alone, %zu unknown pictures exempt: %s\n", c.spec.id.c_str(),
                sc.unknownPictures.size(), r.summary().c_str());
  // (With labels, from a sidecar alone: tests/oracle/test_committed.cpp.)
}

TEST_P(Figure, MatchesTheCommittedPngFuzzily) {
  const FigureCase& c = GetParam();
  std::string png = std::string(TS_SOURCE_DIR) + "/book_figures/" + c.spec.id + ".png";
  // Every registered figure is committed: a new figure without its PNG is a
  // gallery that lies, so this fails (scripts/figures.sh writes the files).
  ASSERT_TRUE(std::filesystem::exists(png)) << png << " is not committed: run scripts/figures.sh";
  ref::FuzzyOptions o;
  o.name = c.spec.id + ".committed";
  o.outputDir = oracle::outDir("figures");
  // llvmpipe renders the committed files; another rasterizer (softpipe) may
  // settle edge pixels and filtering rounding differently.
  bool llvmpipe = ts::test::rendererString().find("llvmpipe") != std::string::npos;
  o.maxChannelDiff = !llvmpipe && oracle::shadedPerPixelInGlsl(c.spec.id) ? 4 : 2;
  if (!llvmpipe && oracle::showsTheRasterizersFiltering(c.spec.id))
    GTEST_SKIP() << c.spec.id << " prints this rasterizer's own LOD/anisotropy measurements; the committed PNG is "
                 << "llvmpipe's (rasterizer_specific in its demo's facts.tsv)";
  long pixels = long(rendered_->image.width) * rendered_->image.height;
  o.maxDifferingPixels = llvmpipe ? pixels / 2000 : pixels / 50;
  const char* backend = std::getenv("TS_TEST_BACKEND");
  if (backend && std::string(backend) == "egl")
    o.maxDifferingPixels = std::max(o.maxDifferingPixels, backendBoundPixels(c.spec.id));
  ref::FuzzyResult r = ref::compareWithPng(rendered_->image, png, o);
  std::printf("[oracle] %s\n", r.message.c_str());
  EXPECT_TRUE(r.ok) << r.message;
}

std::string caseName(const ::testing::TestParamInfo<FigureCase>& i) {
  std::string n = i.param.spec.id;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

// TS_FIGURE_SHARD=k/n (tests/oracle/CMakeLists.txt): this process checks
// the figures whose place in the registry is k modulo n, each figure whole
// (rendered once, all its checks), so CTest runs the shards on both cores.
std::vector<FigureCase> figuresOfThisShard() {
  std::vector<FigureCase> all = allFigures();
  const char* e = std::getenv("TS_FIGURE_SHARD");
  if (!e || !*e) return all;
  int k = -1, n = 0;
  char tail = 0;
  if (std::sscanf(e, "%d/%d%c", &k, &n, &tail) != 2 || n < 1 || k < 0 || k >= n) {
    std::fprintf(stderr, "TS_FIGURE_SHARD: '%s' is not k/n with 0 <= k < n\n", e);
    std::exit(2);
  }
  std::vector<FigureCase> mine;
  for (size_t i = 0; i < all.size(); ++i)
    if (int(i % size_t(n)) == k) mine.push_back(all[i]);
  return mine;
}
INSTANTIATE_TEST_SUITE_P(Registered, Figure, ::testing::ValuesIn(figuresOfThisShard()), caseName);

// The registry must hold VI.1's book figure and its variants (the figures the
// oracle was written for); others are checked as they are added.
TEST(FigureList, HasTheQuadDistortionFigures) {
  std::vector<std::string> ids;
  for (const auto& c : allFigures()) ids.push_back(c.spec.id);
  EXPECT_NE(std::find(ids.begin(), ids.end(), "vi1_quad_distortion"), ids.end());
  EXPECT_NE(std::find(ids.begin(), ids.end(), "vi1_quad_variants"), ids.end());
}
}  // namespace

// The DXT1 figures' decode: the sidecar remakes it with dxt1.hpp's
// integer palette, GL decodes with its own rounding of the extension's
// fractions (TextureDesc::texelSlack = 1 level).  Described as the picture
// before compression, the same panel fails: the check sees the compression.
TEST(DxtFigure, TheDecodeFromTheSidecarAndAWrongOne) {
  std::vector<FigureCase> all = allFigures();
  auto it = std::find_if(all.begin(), all.end(), [](const FigureCase& c) { return c.spec.id == "dxt1_blocks"; });
  ASSERT_NE(it, all.end());
  const Renders& rr = rendersOf(*it);
  ts::SidecarInfo info;
  info.figureId = it->spec.id;
  info.demo = it->scene;
  const std::string json = ts::sidecarJson(rr.withLabels.frame, info);
  auto verify = [&](const ts::Frame& f, const std::string& name) {
    ref::VerifyOptions o = oracle::options(name, "figures");
    o.render.labels = false;
    o.writeOnFailure = false;
    return ref::verifyImage(rr.plain, f, o);
  };
  ref::SidecarScene sc = ref::readSidecar(json);
  int decoded = -1;
  for (size_t k = 0; k < sc.frame.textures.size(); ++k)
    for (const auto& [key, v] : sc.frame.textures[k].params)
      if (key == "show" && v == "decoded_gl" && decoded < 0) decoded = int(k);
  ASSERT_GE(decoded, 0) << "no texture of GL's decode in the sidecar";
  EXPECT_EQ(sc.frame.textures[size_t(decoded)].texelSlack, 1.0f);
  const ref::VerifyResult right = verify(sc.frame, "dxt1_blocks.sidecar_decode");
  EXPECT_EQ(right.invalid, 0) << right.summary();
  ts::Frame exact = sc.frame;  // the integer palette taken as GL's
  exact.textures[size_t(decoded)].texelSlack = 0;
  const ref::VerifyResult strict = verify(exact, "dxt1_blocks.no_slack");
  ts::Frame wrong = sc.frame;  // the picture before compression
  std::vector<std::pair<std::string, std::string>> p = wrong.textures[size_t(decoded)].params;
  for (auto& [key, v] : p)
    if (key == "show") v = "original";
  const ts::TextureDesc original = ref::remakeTexture("dxt1_picture", p, TS_SOURCE_DIR);
  wrong.textures[size_t(decoded)].image = original.image;
  wrong.textures[size_t(decoded)].texelSlack = 0;
  const ref::VerifyResult bad = verify(wrong, "dxt1_blocks.uncompressed");
  EXPECT_GT(bad.invalid, 1000) << bad.summary();
  std::printf("[oracle] dxt1_blocks' decode from the sidecar: %ld invalid of %ld; with no rounding freedom %ld; "
              "described as the uncompressed picture %ld\n",
              right.invalid, right.checked, strict.invalid, bad.invalid);
}
