// The libFuzzer entry point of one target: ISPH_FUZZ_TARGET names its body in FuzzTargets.hpp
// (tests/fuzz/CMakeLists.txt compiles this file once per target).
#include <cstddef>
#include <cstdint>

#include "FuzzTargets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ISPH_FUZZ_TARGET({reinterpret_cast<const char*>(data), size});
  return 0;
}
