// A fast proof of irreducibility over Q, by the degrees of the factors modulo primes (the first
// phase of Zassenhaus's algorithm): a factor of h over Z of degree d reduces modulo a prime p (not
// dividing the leading coefficient) to a product of irreducible factors whose degrees sum to d. So
// when no d strictly between 0 and deg h is a sum of factor degrees modulo every prime tried, h is
// irreducible. Most irreducible polynomials are proven so by two or three primes, at a fraction of
// a full factorisation's cost; when the primes leave it open, the caller factors (FLINT): the
// irreducible factors and the pseudo-remainder over Z, defined in algebraic_real.cpp.
#pragma once

#include <vector>

#include "relpos/numbers.hpp"

namespace relpos::detail {

/// True when the degrees of h's factors modulo a few word primes prove h irreducible over Q (h
/// primitive up to sign, degree >= 1; a linear h is irreducible). False: not proven (h may still be
/// irreducible).
bool proven_irreducible(const std::vector<Integer>& h);

/// The distinct irreducible factors over Z of a non-zero integer polynomial (FLINT), each primitive
/// with a positive leading coefficient; constant factors are dropped.
std::vector<std::vector<Integer>> irreducible_factors(const std::vector<Integer>& coefficients);

/// The pseudo-remainder r of p by m (FLINT): lc(m)^k p = q m + r with deg r < deg m. When lc(m) > 0,
/// r(a) has the sign of p(a) at every root a of m (empty vector: r = 0). m must be non-constant.
std::vector<Integer> pseudo_remainder(const std::vector<Integer>& p, const std::vector<Integer>& m);

}  // namespace relpos::detail
