// The oracle's exemptions, read from the demos' facts files
// (demos/<name>/facts.tsv; docs/facts.md explains each kind) in the source
// tree at run time:
//   drawn_from_gl        figures whose panels include pictures that OpenGL
//                        itself rendered in the demo's measure(): their
//                        sidecar cannot remake every texture, so those
//                        pixels are exempt and the rest is checked from the
//                        JSON alone (test_figures.cpp, test_committed.cpp);
//   too_slow_softpipe    figures whose measure() takes minutes on softpipe:
//                        skipped there, visibly;
//   rasterizer_specific  figures of the rasterizer's own filtering: compared
//                        with the committed (llvmpipe) PNGs on llvmpipe only;
//   glsl_specular        per-pixel GLSL specular: compared within 4 levels;
//   softpipe_wrong       figures softpipe draws against the specification (a
//                        bug of softpipe's, in docs/platform.md with its check):
//                        skipped there, visibly.
// Every other figure must be reproducible from its JSON alone, to the last
// pixel; a new figure that is not fails the oracle tests until it is made
// reproducible or its demo's facts file marks it with its reason, and a
// marked figure whose sidecar remakes every texture fails until its row is
// taken out.
#pragma once
#include <algorithm>
#include <string>
#include <vector>

#include "tests/support/facts.hpp"

#ifndef TS_SOURCE_DIR
#define TS_SOURCE_DIR "."
#endif

namespace oracle {
inline bool hasFact(const std::string& kind, const std::string& id) {
  const std::vector<std::string> keys = ts::test::factKeys(TS_SOURCE_DIR, kind);
  return std::find(keys.begin(), keys.end(), id) != keys.end();
}

inline std::vector<std::string> figuresDrawnFromGlRenders() {
  return ts::test::factKeys(TS_SOURCE_DIR, "drawn_from_gl");
}
inline bool drawnFromGlRenders(const std::string& id) { return hasFact("drawn_from_gl", id); }
inline bool tooSlowForSoftpipe(const std::string& id) { return hasFact("too_slow_softpipe", id); }
inline bool showsTheRasterizersFiltering(const std::string& id) { return hasFact("rasterizer_specific", id); }
inline bool shadedPerPixelInGlsl(const std::string& id) { return hasFact("glsl_specular", id); }
inline bool softpipeDrawsItWrong(const std::string& id) { return hasFact("softpipe_wrong", id); }
}  // namespace oracle
