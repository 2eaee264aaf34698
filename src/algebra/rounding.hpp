// Is the FPU in round-to-nearest (the default)? The double filters' error analysis assumes it; a
// caller inside an upward-rounding block (CGAL interval code) gets the interval stage instead.
#pragma once

#include <cfenv>
#if defined(__SSE2_MATH__)
#include <xmmintrin.h>
#endif

namespace relpos::detail {

/// One stmxcsr on x86-64 (SSE arithmetic), else fegetround.
inline bool rounding_to_nearest() {
#if defined(__SSE2_MATH__)
  return (_mm_getcsr() & 0x6000u) == 0;  // MXCSR.RC, bits 13-14: 00 = to nearest
#else
  return std::fegetround() == FE_TONEAREST;
#endif
}

}  // namespace relpos::detail
