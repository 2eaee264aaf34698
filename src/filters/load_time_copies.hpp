// Copies of a hot filter, one chosen when the library is loaded: on x86-64 (ELF, GCC) a function is
// compiled for the baseline ISA and for AVX2 (the many-pairs filter also for AVX-512) and an ifunc
// resolver picks one at relocation (the call then costs what any call into the library costs). Only
// the encoding changes, not the arithmetic: the same IEEE double operations in the same order (no
// FMA: contraction is off), so every copy returns the same bits, and the tests run each one this
// CPU can. Elsewhere (Clang, other platforms) only the baseline copy is built. Used by the static
// filter (static_filter.cpp) and its many-pairs form (static_filter_lanes.cpp).
#pragma once

#if defined(__x86_64__) && defined(__ELF__) && defined(__GNUC__) && !defined(__clang__)
#define RELPOS_AVX2_COPY 1
#else
#define RELPOS_AVX2_COPY 0
#endif

#if RELPOS_AVX2_COPY
namespace relpos::detail {
namespace {

// Called by the ifunc resolvers, which run while the loader relocates, before any constructor
// (hence the explicit init) and before a sanitizer's runtime has mapped its shadow memory: it must not
// be instrumented (an instrumented load of the CPU model faults there). Internal linkage: each
// resolver calls its own file's copy directly, never through a relocation not yet applied.
[[gnu::no_sanitize_address, gnu::no_sanitize_undefined, gnu::no_instrument_function]] inline bool cpu_has_avx2() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
}
[[gnu::no_sanitize_address, gnu::no_sanitize_undefined, gnu::no_instrument_function]] inline bool cpu_has_avx512f() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f");
}

}  // namespace
}  // namespace relpos::detail
#endif
