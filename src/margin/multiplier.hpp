// The multiplier of a margin's lower certificate (math.md §19): a rational lambda with lambda P + E_lo
// positive definite, found where r = f0 / s attains s*^2 k. Below s* the pair scaled by lo is I or E,
// and f_lo = f0 - lo^2 k s = s (r - lo^2 k) is positive near the critical point of r whose value is
// s*^2 k > lo^2 k, which is the optimal dual multiplier of the tangency at s*. So rationals converging
// to the critical points of r in the domain (lambda > 0 for E, lambda_s < lambda < 0 for I) meet one
// where f_lo > 0 after about half as many bits as the enclosure has.
#pragma once

#include <optional>

#include "margin/polynomial.hpp"
#include "relpos/numbers.hpp"

namespace relpos::detail {

/// A lambda with lambda > 0 (inside == false) or lambda_s < lambda < 0 (inside) and f0(lambda) -
/// lo^2 k s0(lambda) > 0 (then lambda P + E_lo is positive definite: lambda A + M is, and so is its
/// Schur complement f / s), tried at rationals converging to the critical points of f0 / s0 and, for a
/// centre inside, to lambda_s from above (the hard case, where the supremum of r is its limit at
/// lambda_s), up to about 2 bits + 64 bits; nullopt when none shows it.
std::optional<Rational> below_multiplier(const PointPencil& pencil, const Rational& lo, bool inside, long bits);

}  // namespace relpos::detail
