// libFuzzer entry point of the "batch_line" harness; the checks live in harnesses.hpp (doc/testing.md).
#include <cstdio>
#include <cstdlib>

#include "harnesses.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    relpos_fuzz::check_batch_line(data, size);
  } catch (const relpos_fuzz::Defect& d) {
    std::fprintf(stderr, "relpos fuzz defect (batch_line): %s\n", d.what());
    std::abort();
  }
  return 0;  // any other exception escapes and is reported by libFuzzer as a crash
}
