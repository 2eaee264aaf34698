// A fast proof of irreducibility over Q, by the degrees of the factors modulo primes (the first
// phase of Zassenhaus's algorithm): a factor of h over Z of degree d reduces modulo a prime p (not
// dividing the leading coefficient) to a product of irreducible factors whose degrees sum to d. So
// when no d strictly between 0 and deg h is a sum of factor degrees modulo every prime tried, h is
// irreducible. Most irreducible polynomials are proven so by two or three primes, at a fraction of
// a full factorisation's cost; when the primes leave it open, the caller factors (FLINT).
#pragma once

#include <vector>

#include "relpos/numbers.hpp"

namespace relpos::detail {

/// True when the degrees of h's factors modulo a few word primes prove h irreducible over Q (h
/// primitive up to sign, degree >= 1; a linear h is irreducible). False: not proven (h may still be
/// irreducible).
bool proven_irreducible(const std::vector<Integer>& h);

}  // namespace relpos::detail
