// textures/make_textures — writes the image assets the suite makes into
// textures/, so that a student can open them in any image viewer or feed them
// back with --texture:
//   bricks_albedo.png, bricks_height.png   the parallax demo's bricks with deep
//                                         mortar (height: white = top, 512x512)
//   step_albedo.png, step_height.png       its synthetic step/ridge map
//   checkerboard_256_8.png                 the book's checkerboard (8x8 checks)
//   labelled_grid_512_8.png                the orientation grid A1..H8
// The demos make the same texels in code (common/core/relief_maps.hpp,
// common/core/textures.hpp); these files are their output, not their input.
//
//   make_textures DIR           write the files into DIR
//   make_textures --check DIR   exit 1 if any file in DIR differs from what
//                               the code makes now (a CTest test runs this)
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/image.hpp"
#include "common/core/textures.hpp"
#include "common/core/relief_maps.hpp"

namespace {
// In memory a texture's row 0 is t = 0 (GL's order); in a file the top row
// is t = 1, as in any picture and as --texture reads it (fileTexture).  So
// each is flipped on the way out: labelled_grid_512_8.png reads the right
// way up in an image viewer, and --texture with it shows A1 at the bottom
// left, exactly as the built-in grid does.
ts::Image asPicture(ts::Image texels) {
  texels.flipVertical();
  return texels;
}

std::vector<std::pair<std::string, ts::Image>> assets() {
  std::vector<std::pair<std::string, ts::Image>> out;
  for (const char* map : {"bricks", "step"}) {
    ts::relief::Relief r = ts::relief::makeRelief(map);
    out.push_back({std::string(map) + "_albedo.png", asPicture(r.albedo[0])});
    out.push_back({std::string(map) + "_height.png", asPicture(r.height[0])});
  }
  out.push_back({"checkerboard_256_8.png", asPicture(*ts::checkerboard(256, 8).image)});
  out.push_back({"labelled_grid_512_8.png", asPicture(*ts::labelledGrid(512, 8).image)});
  return out;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}
}  // namespace

int main(int argc, char** argv) {
  try {
    bool check = argc == 3 && std::string(argv[1]) == "--check";
    if (!(argc == 2 || check) || std::string(argv[1]) == "--help") {
      std::fprintf(stderr, "usage: make_textures [--check] DIR\n");
      return ts::kExitUsage;
    }
    std::string dir = argv[argc - 1];
    int differ = 0;
    for (const auto& [name, img] : assets()) {
      std::string path = dir + "/" + name;
      if (check) {
        std::vector<uint8_t> want = ts::encodePng(img);
        if (readAll(path) != std::string(want.begin(), want.end())) {
          std::printf("%s differs from what the code makes (run make_textures %s)\n", path.c_str(), dir.c_str());
          ++differ;
        }
      } else {
        ts::writePng(path, img);
        std::printf("%s\n", path.c_str());
      }
    }
    return differ ? ts::kExitFailure : ts::kExitOk;
  } catch (const ts::Error& e) {
    std::fprintf(stderr, "make_textures: %s\n", e.what());
    return e.exit_code;
  }
}
