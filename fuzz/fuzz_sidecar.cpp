// libFuzzer target: the sidecar/scene reader (reference/sidecar_reader.cpp
// and the JSON parser under it).  Any input must give a scene or throw
// ts::Error; other exceptions, crashes and sanitizer reports are bugs.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.hpp"
#include "reference/sidecar_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    ref::readSidecar(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const ts::Error&) {
  }
  return 0;
}
