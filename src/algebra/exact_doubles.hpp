// Doubles and rationals converted exactly from their bits: a double as m 2^k, a double as a
// canonical rational, a dyadic rational truncated to a double, and a rational's tightest enclosure.
#pragma once

#include <gmp.h>

#include <cstdint>
#include <utility>

#include "relpos/numbers.hpp"

namespace relpos::detail::forms {

/// A finite non-zero double as m 2^k with m odd (|m| < 2^53), from its bits (subnormals: exponent
/// field 0, no hidden bit).
struct Dyadic {
  std::int64_t m;
  long k;
};
Dyadic dyadic_of(double x);

/// out = x exactly for a finite double x (as mpq_set_d), from its bits: an odd significand over a
/// power of two is already in lowest terms, so no gcd and each part is sized once.
void set_double(mpq_ptr out, double x);

/// The exponent k of a positive z = 2^k, or -1 when z is not a power of two (a dyadic rational's
/// denominator).
inline long power_of_two_exponent(mpz_srcptr z) {
  const mp_bitcnt_t k = mpz_scan1(z, 0);
  return k + 1 == mpz_sizeinbase(z, 2) ? static_cast<long>(k) : -1;
}

/// mpq_get_d(q) (CGAL::to_double): q truncated towards zero to a double. For a dyadic q in the
/// normal range without mpq_get_d's division (the searches' points and pulls are dyadic).
double truncated_double(const Rational& q);

/// CGAL::to_interval(q), the tightest interval of doubles around q, bit for bit: in the normal
/// range from mpq_get_d (q truncated towards zero) and the next double away from zero, or the point
/// when q is a double (a power-of-two denominator and at most 53 significant bits); else CGAL's
/// (MPFR). Independent of the rounding mode.
std::pair<double, double> tight_interval(const Rational& q);

}  // namespace relpos::detail::forms
