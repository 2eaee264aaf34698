// Approximate real roots of an integer polynomial in long double (Durand-Kerner, then Newton on the
// real ones): proposals only (math.md §19). Every use checks what a proposal leads to with exact
// signs; a poor proposal costs time, never correctness.
#pragma once

#include <optional>
#include <vector>

#include "relpos/numbers.hpp"

namespace relpos::detail {

/// Approximations of the real roots of p (degree 1..16, index = power), in increasing order; empty
/// when the iteration does not settle or a coefficient is beyond long double range. Roots of
/// clusters or of high multiplicity may be missed or duplicated.
std::vector<long double> approximate_real_roots(const std::vector<Integer>& p);

/// A dyadic rational within a few ulps of x (its leading 53 bits and the next ones, each a double);
/// nullopt when x is not finite or beyond the range of doubles.
std::optional<Rational> rational_near(long double x);

}  // namespace relpos::detail
