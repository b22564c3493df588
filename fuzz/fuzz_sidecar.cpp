// libFuzzer target: the sidecar/scene reader (reference/sidecar_reader.cpp
// and the JSON parser under it).  Any input must give a scene or throw
// ts::Error; other exceptions, crashes and sanitizer reports are bugs.
//
// The reader remakes each texture from its generator's parameters, and the
// generators' cost grows with the square of the size the input asks for (a
// 16384-texel checkerboard is 1 GiB and seconds under ASan) while the reader
// runs the same code for 16 texels as for 16384.  So in this program the
// generators the reader calls are wrapped (the linker's --wrap, see
// fuzz/CMakeLists.txt): a size over kMaxSide texels a side throws ts::Error,
// which the reader reports as it does any generator's error; anything else
// goes to the real generator, its own checks included.  fuzz/run.sh replays
// the book figures' own sidecars with TS_FUZZ_WHOLE_TEXTURES=1, which lifts
// the limit (read once, not per input).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "common/core/error.hpp"
#include "common/core/textures.hpp"
#include "reference/sidecar_reader.hpp"

namespace {
constexpr int kMaxSide = 64;
const bool kWholeTextures = std::getenv("TS_FUZZ_WHOLE_TEXTURES") != nullptr;
void bound(const char* what, int side) {
  if (side > kMaxSide && !kWholeTextures)
    throw ts::Error(std::string("fuzz_sidecar: ") + what + " of " + std::to_string(side) +
                    " texels is over the harness' limit of " + std::to_string(kMaxSide));
}
}  // namespace

// The real generators, and the wrappers the reader's calls are sent to.
ts::TextureDesc realCheckerboard(int, int, ts::Rgba, ts::Rgba) asm("__real__ZN2ts12checkerboardEiiNS_4RgbaES0_");
ts::TextureDesc realTexelIndex(int) asm("__real__ZN2ts17texelIndexTextureEi");
ts::TextureDesc realLabelledGrid(int, int) asm("__real__ZN2ts12labelledGridEii");
ts::TextureDesc realMipLevels(int) asm("__real__ZN2ts15mipLevelColoursEi");
ts::TextureDesc realGradient(int, int, bool) asm("__real__ZN2ts15gradientTextureEiib");

ts::TextureDesc wrapCheckerboard(int, int, ts::Rgba, ts::Rgba) asm("__wrap__ZN2ts12checkerboardEiiNS_4RgbaES0_");
ts::TextureDesc wrapTexelIndex(int) asm("__wrap__ZN2ts17texelIndexTextureEi");
ts::TextureDesc wrapLabelledGrid(int, int) asm("__wrap__ZN2ts12labelledGridEii");
ts::TextureDesc wrapMipLevels(int) asm("__wrap__ZN2ts15mipLevelColoursEi");
ts::TextureDesc wrapGradient(int, int, bool) asm("__wrap__ZN2ts15gradientTextureEiib");

ts::TextureDesc wrapCheckerboard(int size, int checks, ts::Rgba a, ts::Rgba b) {
  bound("checkerboard size", size);
  return realCheckerboard(size, checks, a, b);
}
ts::TextureDesc wrapTexelIndex(int size) {
  bound("texel index size", size);
  return realTexelIndex(size);
}
ts::TextureDesc wrapLabelledGrid(int size, int cells) {
  bound("labelled grid size", size);
  return realLabelledGrid(size, cells);
}
ts::TextureDesc wrapMipLevels(int size) {
  bound("mip level texture size", size);
  return realMipLevels(size);
}
ts::TextureDesc wrapGradient(int width, int height, bool alphaRamp) {
  bound("gradient width", width);
  bound("gradient height", height);
  return realGradient(width, height, alphaRamp);
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    ref::readSidecar(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const ts::Error&) {
  }
  return 0;
}
