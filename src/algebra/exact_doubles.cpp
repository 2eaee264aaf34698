#include "algebra/exact_doubles.hpp"

#include <CGAL/Gmpq.h>

#include <cfloat>
#include <cmath>
#include <cstring>

namespace relpos::detail::forms {

Dyadic dyadic_of(double x) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  const auto field = static_cast<long>((bits >> 52) & 0x7ff);
  const std::uint64_t frac = bits & ((std::uint64_t{1} << 52) - 1);
  auto m = static_cast<std::int64_t>(field == 0 ? frac : frac | (std::uint64_t{1} << 52));
  long k = (field == 0 ? 1 : field) - 1075;
  const int zeros = __builtin_ctzll(static_cast<unsigned long long>(m));  // m != 0
  m /= std::int64_t{1} << zeros;                                          // exact
  k += zeros;
  return {bits >> 63 ? -m : m, k};
}

void set_double(mpq_ptr out, double x) {
  const mpz_ptr num = mpq_numref(out), den = mpq_denref(out);
  mpz_set_ui(den, 1);
  if (x == 0) {
    mpz_set_ui(num, 0);
    return;
  }
  const Dyadic d = dyadic_of(x);
  mpz_set_si(num, static_cast<long>(d.m));
  if (d.k > 0) {
    mpz_mul_2exp(num, num, static_cast<mp_bitcnt_t>(d.k));
  } else if (d.k < 0) {
    mpz_set_ui(den, 0);
    mpz_setbit(den, static_cast<mp_bitcnt_t>(-d.k));
  }
}

namespace {

/// mpq_get_d(x) given den(x) = 2^k (k >= 0) or k = -1: mpz_get_d truncates the numerator towards
/// zero, and the power of two is exact while the result stays normal.
double truncated_double(mpq_srcptr x, long k) {
  if (k >= 0 && k <= 1000) {
    const double t = std::ldexp(mpz_get_d(mpq_numref(x)), -static_cast<int>(k));
    if (std::fabs(t) >= DBL_MIN && std::fabs(t) <= DBL_MAX) return t;
  }
  return mpq_get_d(x);
}

}  // namespace

double truncated_double(const Rational& q) {
  return truncated_double(q.mpq(), power_of_two_exponent(mpq_denref(q.mpq())));
}

std::pair<double, double> tight_interval(const Rational& q) {
  const mpq_srcptr x = q.mpq();
  const mpz_srcptr num = mpq_numref(x);
  const long den_twos = power_of_two_exponent(mpq_denref(x));
  const double t = truncated_double(x, den_twos);
  if (!(std::fabs(t) >= DBL_MIN && std::fabs(t) < DBL_MAX)) return CGAL::to_interval(q);  // 0, subnormal, huge
  // A double itself: a power-of-two denominator and at most 53 significant bits.
  if (den_twos >= 0 && mpz_sizeinbase(num, 2) - mpz_scan1(num, 0) <= 53) return {t, t};
  const double away = std::nextafter(t, t < 0 ? -HUGE_VAL : HUGE_VAL);
  return t < 0 ? std::make_pair(away, t) : std::make_pair(t, away);
}

}  // namespace relpos::detail::forms
