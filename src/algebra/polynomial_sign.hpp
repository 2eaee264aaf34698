// The exact sign of an integer polynomial at a rational, in integers: one piece of code for the
// algebraic reals' bisection (algebraic_real.hpp) and the margin's root intervals (src/margin/).
#pragma once

#include <vector>

#include "relpos/numbers.hpp"

namespace relpos::detail {

/// Sign of p(x) for an integer polynomial p (index = power; empty: 0) and a rational x = a/b: the
/// sign of the homogenised value sum p_i a^i b^(n-i) = b^n p(x) (b > 0), computed in integers.
inline int sign_of_value(const std::vector<Integer>& p, const Rational& x) {
  if (p.empty()) return 0;
  const Integer a = x.numerator(), b = x.denominator();
  Integer v = p.back(), bpow(1);
  for (std::size_t k = p.size() - 1; k-- > 0;) {
    bpow *= b;
    v = v * a + p[k] * bpow;
  }
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

}  // namespace relpos::detail
