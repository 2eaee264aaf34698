// Narrowing an isolating interval of a simple real root to a relative width 2^-bits: Newton's method
// in MPFR proposes, exact signs decide (math.md §19). The numerics never decide anything: a proposal
// becomes the interval only when the polynomial's exact signs at its two rational ends differ, and
// a failed proposal falls back to bisection.
#pragma once

#include <vector>

#include "margin/descartes.hpp"
#include "relpos/numbers.hpp"

namespace relpos::detail {

/// Shrinks r, an open interval of positive rationals holding exactly one root of f, a simple one,
/// with a sign change of f at its ends, until r.hi - r.lo <= 2^-bits r.lo (or r.lo == r.hi, the root
/// itself). bits >= 1. `start`: an approximation of the root to start Newton's method from (else the
/// midpoint of r).
void refine_root(const std::vector<Integer>& f, RootInterval& r, long bits, const long double* start = nullptr);

}  // namespace relpos::detail
