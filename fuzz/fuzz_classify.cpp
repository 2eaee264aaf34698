// libFuzzer entry point of the "classify" harness; the checks live in harnesses.hpp (doc/testing.md).
#include <cstdio>
#include <cstdlib>

#include "harnesses.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    relpos_fuzz::check_classify(data, size);
  } catch (const relpos_fuzz::Defect& d) {
    std::fprintf(stderr, "relpos fuzz defect (classify): %s\n", d.what());
    std::abort();
  }
  return 0;  // any other exception escapes and is reported by libFuzzer as a crash
}
