// reliability_tool — helpers for the reliability tests:
//   reliability_tool corpus DIR   writes the image corpus (corpus_gen.hpp) into
//       DIR: one file per case plus MANIFEST ("name<TAB>ok" or
//       "name<TAB>error<TAB>phrase").  The committed tests/reliability/corpus/
//       is its output; reliability_test fails if the two drift apart.  Files
//       found by fuzzing go to corpus/regressions/ (kept as found).
//   reliability_tool check FILE...   every FILE must decode completely as an
//       image (used after killing a run: no half-written PNG may exist).
//   reliability_tool diff-rgb A B   the same on the red, green and blue
//       channels only; A or B may be a binary PPM (P6), as exported
//       programs write (tests/cli/export_c_test.sh).
//   reliability_tool diff A B   compares two images: prints
//       "<pixels that differ> <largest channel difference>" (exit 0), or fails
//       if either cannot be read or the sizes differ.
//   reliability_tool measurements SIDECAR.json   prints the sidecar's
//       measurements, "name<TAB>value" a line, every digit kept (%.17g), for
//       comparing two runs' numbers in a shell (tests/windows/wine_test.sh).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "common/core/error.hpp"
#include "common/core/image.hpp"
#include "corpus_gen.hpp"

// A binary PPM (P6, maxval 255) as an opaque image; anything else: readImage.
static ts::Image readAny(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw ts::Error("cannot read " + path, 1);
  char magic[3] = {0, 0, 0};
  int w = 0, h = 0, maxval = 0;
  bool ppm = std::fread(magic, 1, 2, f) == 2 && magic[0] == 'P' && magic[1] == '6' &&
             std::fscanf(f, "%d %d %d", &w, &h, &maxval) == 3 && maxval == 255 && w > 0 && h > 0 && w <= 16384 &&
             h <= 16384 && std::fgetc(f) != EOF;
  if (!ppm) {
    std::fclose(f);
    return ts::readImage(path);
  }
  ts::Image img(w, h);
  for (size_t p = 0; p < size_t(w) * size_t(h); ++p) {
    unsigned char rgb[3];
    if (std::fread(rgb, 1, 3, f) != 3) {
      std::fclose(f);
      throw ts::Error(path + ": the PPM ends early", 1);
    }
    for (int c = 0; c < 3; ++c) img.pixels[p * 4 + size_t(c)] = rgb[c];
    img.pixels[p * 4 + 3] = 255;
  }
  std::fclose(f);
  return img;
}

int main(int argc, char** argv) {
  std::string cmd = argc > 1 ? argv[1] : "";
  try {
    if (cmd == "corpus" && argc == 3) {
      std::string dir = argv[2], manifest;
      for (const corpus::Case& c : corpus::makeCases()) {
        ts::writeFileAtomic(dir + "/" + c.name, std::string(c.bytes.begin(), c.bytes.end()));
        manifest += c.name + (c.good ? "\tok\n" : "\terror\t" + c.error + "\n");
      }
      ts::writeFileAtomic(dir + "/MANIFEST", manifest);
      return 0;
    }
    if (cmd == "check" && argc >= 3) {
      for (int i = 2; i < argc; ++i) ts::readImage(argv[i]);
      return 0;
    }
    if ((cmd == "diff" || cmd == "diff-rgb") && argc == 4) {
      bool rgb = cmd == "diff-rgb";
      ts::Image a = rgb ? readAny(argv[2]) : ts::readImage(argv[2]),
                b = rgb ? readAny(argv[3]) : ts::readImage(argv[3]);
      if (a.width != b.width || a.height != b.height)
        throw ts::Error(std::string(argv[2]) + " and " + argv[3] + " differ in size", 1);
      long n = 0;
      int most = 0;
      for (size_t i = 0; i < a.pixels.size(); i += 4) {
        int d = 0;
        for (int k = 0; k < (rgb ? 3 : 4); ++k) d = std::max(d, std::abs(int(a.pixels[i + k]) - int(b.pixels[i + k])));
        if (d) ++n;
        most = std::max(most, d);
      }
      std::printf("%ld %d\n", n, most);
      return 0;
    }
    if (cmd == "measurements" && argc == 3) {
      const std::vector<uint8_t> bytes = ts::readFileBytes(argv[2], size_t(64) << 20);
      const nlohmann::json j = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
      if (j.is_discarded() || !j.is_object()) throw ts::Error(std::string(argv[2]) + ": not a JSON object", 1);
      if (j.contains("measurements") && j["measurements"].is_object())
        for (const auto& [name, v] : j["measurements"].items())
          if (v.is_number()) std::printf("%s\t%.17g\n", name.c_str(), v.get<double>());
      return 0;
    }
  } catch (const ts::Error& e) {
    std::fprintf(stderr, "reliability_tool: %s\n", e.what());
    return e.exit_code;
  }
  std::fprintf(stderr,
               "usage: reliability_tool corpus DIR | check FILE... | diff A B | diff-rgb A B | measurements JSON\n");
  return 2;
}
