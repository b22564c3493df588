// reference/verify.hpp — bounded image verification: is every pixel of a
// rendered image one a conformant OpenGL could have produced for this Frame?
//
// The way dEQP's texture verifier works, not a golden image: for each pixel
// the legal results are computed from the analytic interpolation
// (reference.hpp): the texture coordinate, an LOD interval (the pixel's and
// its neighbours' analytic LOD and the quad finite differences, so an
// implementation that picks one LOD per 2x2 quad — llvmpipe — passes; near a
// level boundary both levels are legal), the texels GL_NEAREST may pick when
// the coordinate is within a small epsilon of a texel boundary, the range
// GL_LINEAR spans under a small coordinate jitter, texture environment
// (REPLACE / MODULATE), and then a tolerance from the channel bits
// (ts::probe::tolerance).  Pixels within RenderOptions::edgeBand of a
// triangle's boundary are checked against both sides; pixels under lines,
// points, labels, blended or unmodelled batches are exempt.
// Unit 1 (GL_COMBINE) is applied over unit 0's result; the alpha test drops
// a fragment whose legal alpha surely fails it (one that may fail leaves
// what was beneath legal too); a batch blended with its own factors
// (Batch::blendSrc / blendDst) is checked: its boxes blended
// with the legal colours of what the pixel held (Candidate::below; derived
// once per pixel and candidate, however many blended layers stand on it).
//
// On failure the rendered image, the reference image and an error mask (red:
// invalid; blue: exempt; grey: checked against both sides of an edge) are
// written as PNGs into VerifyOptions::outputDir and named in the summary.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "common/core/frame.hpp"
#include "common/core/image.hpp"
#include "common/core/probe.hpp"
#include "reference.hpp"

namespace ref {
struct VerifyOptions {
  RenderOptions render;
  int tolerance = ts::probe::tolerance(8);  // 8-bit steps allowed beyond the legal range
  double nearestEpsTexels = 1.0 / 128;      // GL_NEAREST: a coordinate this close to a texel edge may go either way
  double linearEpsTexels = 1.0 / 128;       // GL_LINEAR: coordinate jitter (llvmpipe weighs with 8 bits: 1/256)
  double positionEpsPixels = 1.0 / 128;     // plus this many pixels of position error, times texels per pixel
  double colourEps = 1.0 / 255;             // interpolated vertex colours
  long maxInvalid = 0;                      // invalid pixels allowed
  // Where failure images go: "" = $TS_ORACLE_OUT, else ./oracle_failures.
  std::string outputDir;
  std::string name = "oracle";  // file name stem
  bool writeOnFailure = true;
};

struct VerifyResult {
  std::string name;
  long pixels = 0, checked = 0, invalid = 0, exempt = 0, edges = 0;
  long textured = 0;  // checked pixels with a textured fragment among their candidates
  long pinned = 0;    // checked pixels whose legal colours span at most 2 steps per channel
  std::array<long, size_t(Exempt::Count)> exemptBy{};
  int firstX = -1, firstY = -1;
  ts::Rgba firstGot;
  std::vector<Box> firstLegal;
  long maxInvalid = 0;
  std::vector<std::string> files;  // PNGs written on failure
  std::vector<std::string> notes;  // from the reference (unmodelled state)
  ts::Image reference, mask;
  bool ok() const { return invalid <= maxInvalid && checked > 0; }
  std::string summary() const;
};

// Verifies `got` (the Frame rendered by GL, read back top row first) against
// the Frame's legal results.
VerifyResult verifyImage(const ts::Image& got, const ts::Frame& frame, const VerifyOptions& options = {});
VerifyResult verifyImage(const ts::Image& got, const Reference& reference, const VerifyOptions& options = {});
// The legal colour ranges of one pixel (into *out, cleared first; empty =
// exempt, *why says why).
void legalAt(const Reference& reference, int x, int y, const VerifyOptions& options, std::vector<Box>* out,
             Exempt* why);

// Whole-image regression backstop against a committed picture: passes when
// at most `maxDifferingPixels` pixels have a channel differing by more than
// `maxChannelDiff`.
struct FuzzyOptions {
  int maxChannelDiff = 2;
  long maxDifferingPixels = 0;
  std::string outputDir;  // as VerifyOptions::outputDir
  std::string name = "fuzzy";
  bool writeOnFailure = true;
};
struct FuzzyResult {
  bool ok = false;
  long differing = 0;  // pixels beyond maxChannelDiff
  int maxDiff = 0;     // largest channel difference anywhere
  int firstX = -1, firstY = -1;
  std::string message;
  std::vector<std::string> files;
};
FuzzyResult compareFuzzy(const ts::Image& got, const ts::Image& want, const FuzzyOptions& options = {});
// Reads `pngPath` (ts::Error if unreadable) and compares.
FuzzyResult compareWithPng(const ts::Image& got, const std::string& pngPath, const FuzzyOptions& options = {});

// The directory failure images go to, created if needed.
std::string failureDir(const std::string& requested);
}  // namespace ref
