#include "algebra/between.hpp"

#include <gmp.h>

#include <stdexcept>

namespace relpos::detail {
namespace {

/// The tests compare integers (cross-multiplied, denominators positive): no rational is
/// canonicalized until the answer.
Rational fewest_bits(const Rational& lo, const Rational& hi) {
  const Rational mid = (lo + hi) / 2;
  Integer scaled, a, b;
  for (unsigned bits = 0; bits <= 2048; bits += 4) {
    mpz_mul_2exp(a.mpz(), mpq_numref(mid.mpq()), bits);  // scaled = floor(mid 2^bits)
    mpz_fdiv_q(scaled.mpz(), a.mpz(), mpq_denref(mid.mpq()));
    mpz_mul_2exp(a.mpz(), mpq_numref(lo.mpq()), bits);  // lo < scaled / 2^bits
    mpz_mul(b.mpz(), scaled.mpz(), mpq_denref(lo.mpq()));
    if (mpz_cmp(a.mpz(), b.mpz()) >= 0) continue;
    mpz_mul(a.mpz(), scaled.mpz(), mpq_denref(hi.mpq()));  // scaled / 2^bits < hi
    mpz_mul_2exp(b.mpz(), mpq_numref(hi.mpq()), bits);
    if (mpz_cmp(a.mpz(), b.mpz()) >= 0) continue;
    Integer den(1);
    mpz_mul_2exp(den.mpz(), den.mpz(), bits);
    return Rational(scaled, den);
  }
  return mid;
}

Integer floor_of(const Rational& q) {
  Integer r;
  mpz_fdiv_q(r.mpz(), q.numerator().mpz(), q.denominator().mpz());
  return r;
}

Rational simplest(const Rational& x, const std::optional<Rational>& y) {
  if (y && x < 0 && *y > 0) return Rational(0);
  if (y && *y <= 0) return -simplest(-*y, Rational(-x));
  const Integer n = floor_of(x);  // x >= 0 here
  const Rational next(n + 1);
  if (!y || next < *y) return next;
  // (x, y) lies in [n, n + 1]: recurse on the reciprocals of the fractional parts.
  const Rational lo = Rational(1) / (*y - Rational(n));
  std::optional<Rational> hi;
  if (x > Rational(n)) hi = Rational(1) / (x - Rational(n));
  return Rational(n) + Rational(1) / simplest(lo, hi);
}

}  // namespace

Rational rational_inside(const Rational& lo, const std::optional<Rational>& hi, Shortest shortest) {
  if (shortest == Shortest::Denominator) return simplest(lo, hi);
  if (!hi) throw std::logic_error("relpos internal error: the fewest-bits rational needs a bounded interval");
  return fewest_bits(lo, *hi);
}

}  // namespace relpos::detail
