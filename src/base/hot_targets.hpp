// RELPOS_HOT_TARGETS: a hot function compiled twice on x86-64 (ELF, GCC), for AVX2 and for the
// baseline, one of the two chosen when the library is loaded (target_clones: an ifunc). Only the
// encoding changes -- three operands and unaligned memory operands, about a sixth fewer instructions
// on decide_position's path -- not the arithmetic: the same IEEE double operations in the same order
// (AVX2 brings no FMA, and contraction is off), so every value, error bound and sign is the same
// double on either path. GCC only: Clang refuses target_clones on a function that is also flatten.
#pragma once

#if defined(__x86_64__) && defined(__ELF__) && defined(__GNUC__) && !defined(__clang__)
#define RELPOS_HOT_TARGETS __attribute__((target_clones("avx2", "default")))
#else
#define RELPOS_HOT_TARGETS
#endif
