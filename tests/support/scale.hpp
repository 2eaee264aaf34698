// How many random cases a test draws. Under AddressSanitizer (scripts/sanitize.sh) the instrumented
// exact arithmetic runs about eight times slower, so the sanitizer build draws a quarter of them: the
// same families and code paths, fewer repetitions (doc/testing.md, "Time in CI"). RELPOS_SEED still
// varies the draw.
#pragma once

namespace relpos::testing {

#if defined(RELPOS_TEST_SHARE)  // to run the sanitizer's share in an ordinary build: -DRELPOS_TEST_SHARE=4
inline constexpr int kSanitizerShare = RELPOS_TEST_SHARE;
#elif defined(__SANITIZE_ADDRESS__)
inline constexpr int kSanitizerShare = 4;
#else
inline constexpr int kSanitizerShare = 1;
#endif

/// n cases in an ordinary build, n / 4 (at least one) under AddressSanitizer.
constexpr int scaled(int n) { return n / kSanitizerShare > 0 ? n / kSanitizerShare : 1; }

}  // namespace relpos::testing
