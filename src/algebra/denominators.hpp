// Denominators of exact rationals, handled without a general gcd where their shape allows: the lcm
// of a range's denominators, an entry scaled by that lcm, and 1 / a^2 in lowest terms.
#pragma once

#include <gmp.h>

#include "relpos/numbers.hpp"

namespace relpos::detail::forms {

/// lcm(l, d) into l (d > 0): a divisibility test first, since most denominators of a matrix or a
/// polynomial are equal or divide one already taken (powers of 2 and 5), and lcm costs a gcd.
inline void fold_lcm(mpz_ptr l, mpz_srcptr d) {
  if (mpz_cmp_ui(d, 1) != 0 && !mpz_divisible_p(l, d)) mpz_lcm(l, l, d);
}

/// The lcm of the denominators of a range of rationals, folded into `l` (one loop for every caller).
template <class It>
void lcm_of_denominators(It first, It last, Integer& l) {
  for (; first != last; ++first) fold_lcm(l.mpz(), mpq_denref(first->mpq()));
}

/// 1 / a^2 for a != 0: the squares of its coprime numerator and denominator, swapped, are already
/// in lowest terms (no gcd, where rational division computes two).
inline Rational inverse_square(const Rational& a) {
  Rational out;  // fresh: its mpq is not shared, so it is written in place
  mpz_mul(mpq_numref(out.mpq()), mpq_denref(a.mpq()), mpq_denref(a.mpq()));
  mpz_mul(mpq_denref(out.mpq()), mpq_numref(a.mpq()), mpq_numref(a.mpq()));
  return out;
}

/// The integer q l, for l a multiple of q's denominator (lcm_of_denominators), written into `out`
/// (a fresh Integer's mpz, or an mpz_t: Gmpz shares its value on copy and mpz() does not unshare).
inline void scaled_numerator(const Rational& q, const Integer& l, mpz_ptr out) {
  mpz_divexact(out, l.mpz(), mpq_denref(q.mpq()));
  mpz_mul(out, out, mpq_numref(q.mpq()));
}

}  // namespace relpos::detail::forms
