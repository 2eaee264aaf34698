// z / (scale_1^k_1 scale_2^k_2 ...) in lowest terms, the scales split (split_scale.hpp): the
// reduction of the full evidence's g_i / (lp^i le^(4-i)) without a general gcd of long numbers.
#pragma once

#include <gmp.h>

#include <initializer_list>

#include "algebra/split_scale.hpp"
#include "relpos/numbers.hpp"

namespace relpos::detail::forms {

/// One divisor of divided_by_powers: scale^k, k <= 4.
struct ScalePower {
  const SplitScale& scale;
  unsigned long k;
};

/// z / (scale_1^k_1 scale_2^k_2 ...) in lowest terms without a gcd of the long numbers: the twos
/// by a bit scan, the fives by single-limb remainders, and the common factor with each rest^k as
/// at most k e gcds with each factor b^e of rest, usually one that is 1 (a general gcd per
/// coefficient of the reported f and s costs a tenth to a sixth of a decimal batch line's full
/// evidence).
Rational divided_by_powers(mpz_srcptr z, std::initializer_list<ScalePower> divisors);
/// The same written into `out` (e.g. a fresh Rational's unshared mpq): no temporary Rational.
void divided_by_powers(mpz_srcptr z, std::initializer_list<ScalePower> divisors, mpq_ptr out);
inline Rational divided_by_powers(const Integer& z, std::initializer_list<ScalePower> divisors) {
  return divided_by_powers(z.mpz(), divisors);
}
inline Rational divided_by_power(const Integer& z, const SplitScale& scale, unsigned long k) {
  return divided_by_powers(z, {{scale, k}});
}

}  // namespace relpos::detail::forms
