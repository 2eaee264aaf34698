#include "certificate/rational_search.hpp"

#include <gmp.h>

namespace relpos::detail::certificate {
namespace {

int sgn(const Rational& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

}  // namespace

long log2_of(const Rational& x) {
  return static_cast<long>(mpz_sizeinbase(mpq_numref(x.mpq()), 2)) -
         static_cast<long>(mpz_sizeinbase(mpq_denref(x.mpq()), 2));
}

Rational floor_to(const Rational& x, long e) {
  Rational scaled;  // fresh: written in place (a copy of x would share x's value)
  if (e >= 0)
    mpq_div_2exp(scaled.mpq(), x.mpq(), static_cast<mp_bitcnt_t>(e));
  else
    mpq_mul_2exp(scaled.mpq(), x.mpq(), static_cast<mp_bitcnt_t>(-e));
  Integer n;
  mpz_fdiv_q(n.mpz(), mpq_numref(scaled.mpq()), mpq_denref(scaled.mpq()));
  return Rational(n) * power_of_two(e);
}

Rational sqrt_below(const Rational& x, unsigned bits) {
  Integer nd = x.numerator() * x.denominator();
  mpz_mul_2exp(nd.mpz(), nd.mpz(), 2 * bits);
  Integer r;
  mpz_sqrt(r.mpz(), nd.mpz());
  Integer den = x.denominator();
  mpz_mul_2exp(den.mpz(), den.mpz(), bits);
  return Rational(r, den);
}

Rational approximate(const anysize::LambdaS& ls, const anysize::QuadraticReal& x, unsigned bits, bool up) {
  if (x.b == 0 || ls.d == 0) return x.a;
  const Rational lo = sqrt_below(Rational(ls.d), bits);
  Rational step(1);
  for (unsigned i = 0; i < bits; ++i) step /= 2;
  const Rational hi = lo + step;
  const bool b_positive = x.b > 0;
  return x.a + x.b * ((up == b_positive) ? hi : lo);
}

std::vector<Rational> rational_roots(const anysize::Poly& q) {
  std::vector<Rational> out;
  if (q.size() == 2) out.push_back(-q[0] / q[1]);
  if (q.size() == 3) {
    const Rational disc = q[1] * q[1] - 4 * q[2] * q[0];
    if (disc < 0) return out;
    Integer nd = disc.numerator() * disc.denominator();
    if (!mpz_perfect_square_p(nd.mpz())) return out;
    Integer r;
    mpz_sqrt(r.mpz(), nd.mpz());
    const Rational root = Rational(r) / Rational(disc.denominator());
    out.push_back((-q[1] - root) / (2 * q[2]));
    out.push_back((-q[1] + root) / (2 * q[2]));
  }
  return out;
}

RootBoxes::RootBoxes(const anysize::Poly& q_in) {
  if (q_in.size() <= 1) return;
  const anysize::Poly q =
      anysize::quotient(q_in, anysize::monic_gcd(q_in, anysize::derivative(q_in)));  // square-free part
  if (q.size() <= 1) return;
  // Cauchy bound, as a power of two.
  Rational bound(1);
  for (std::size_t i = 0; i + 1 < q.size(); ++i) {
    const Rational r = q[i] / q.back();
    bound = std::max(bound, r > 0 ? r + 1 : 1 - r);
  }
  Rational b(1);
  while (b < bound) b *= 2;
  sturm_ = anysize::sturm_sequence(q);
  signs_.resize(sturm_.size());
  boxes_.push_back({-b, b});
}

int RootBoxes::variations(const Rational& x) {
  for (std::size_t i = 0; i < sturm_.size(); ++i) signs_[i] = sgn(evaluate(sturm_[i], x));
  return anysize::variations(signs_);
}

}  // namespace relpos::detail::certificate
