// Is the FPU in round-to-nearest (the default)? The double filters' error analysis assumes it; a
// caller inside an upward-rounding block (CGAL interval code) gets the interval stage instead.
#pragma once

#include <cfenv>

namespace relpos::detail {

/// With b a little over half an ulp of 1, 1 + b rounds away from 1 to nearest and upwards only, and
/// -1 - b to nearest and downwards only: both do only to nearest. Two additions are cheaper than
/// reading the control register (stmxcsr stalls the pipeline on x86-64); the asm keeps the compiler
/// from folding them (it must not anyway under -frounding-math).
inline bool rounding_to_nearest() {
#if defined(__SSE2_MATH__) && defined(__GNUC__)
  double one = 1.0, b = 0x1.0000000000001p-53;
  __asm__("" : "+x"(one), "+x"(b));
  return (one + b) - one == 0x1p-52 && (-one - b) + one == -0x1p-52;
#else
  return std::fegetround() == FE_TONEAREST;
#endif
}

}  // namespace relpos::detail
