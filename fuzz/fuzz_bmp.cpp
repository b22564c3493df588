// libFuzzer target: the 24/32-bit BMP loader.  Any input must decode or throw ts::Error
// naming the input; anything else (a crash, a sanitizer report, another
// exception, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "common/core/error.hpp"
#include "common/core/bmp.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    ts::Image img = ts::decodeBmp(data, size, "input");
    if (img.pixels.size() != size_t(img.width) * size_t(img.height) * 4) std::abort();
  } catch (const ts::Error& e) {
    if (std::string(e.what()).rfind("input: ", 0) != 0) std::abort();
  }
  return 0;
}
