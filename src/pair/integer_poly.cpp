#include "pair/integer_poly.hpp"

#include <gmp.h>

#include <algorithm>

#include "algebra/forms.hpp"
#include "filters/pooled_integer.hpp"

namespace relpos::detail {

IntegerPoly::IntegerPoly(const Integer* z, std::size_t n) : z_(z, z + n) {
  while (!z_.empty() && z_.back() == 0) z_.pop_back();
  for (const Integer& c : z_) bits_ = std::max(bits_, mpz_sizeinbase(c.mpz(), 2));
}

IntegerPoly::IntegerPoly(const anysize::Poly& q) {
  Integer l(1);
  forms::lcm_of_denominators(q.begin(), q.end(), l);
  z_.resize(q.size());
  for (std::size_t k = 0; k < q.size(); ++k) {
    forms::scaled_numerator(q[k], l, z_[k].mpz());
    bits_ = std::max(bits_, mpz_sizeinbase(z_[k].mpz(), 2));
  }
}

IntegerPoly::IntegerPoly(const fmpz_poly_t q) : z_(static_cast<std::size_t>(fmpz_poly_length(q))) {
  for (std::size_t k = 0; k < z_.size(); ++k) {
    fmpz_get_mpz(z_[k].mpz(), fmpz_poly_get_coeff_ptr(q, static_cast<slong>(k)));
    bits_ = std::max(bits_, mpz_sizeinbase(z_[k].mpz(), 2));
  }
}

int IntegerPoly::sign(const Rational& x) const {
  if (z_.empty()) return 0;
  PooledInteger acc_, dp_(1), t_;  // no Integer handles: one exact sign per candidate multiplier
  const mpz_ptr acc = acc_.mpz(), dp = dp_.mpz(), t = t_.mpz();
  mpz_set(acc, z_.back().mpz());
  for (std::size_t k = z_.size() - 1; k-- > 0;) {
    mpz_mul(dp, dp, mpq_denref(x.mpq()));
    mpz_mul(acc, acc, mpq_numref(x.mpq()));
    mpz_mul(t, z_[k].mpz(), dp);
    mpz_add(acc, acc, t);
  }
  return mpz_sgn(acc);
}

std::optional<Rational> IntegerPoly::newton_floor(const Rational& t, long e) const {
  if (z_.size() < 2) return std::nullopt;
  const mpz_srcptr n = mpq_numref(t.mpq()), d = mpq_denref(t.mpq());
  // v = d^deg q(t) and s = d^(deg - 1) q'(t) by Horner on the homogenized forms: v <- v n + z_k d^(deg - k)
  // and, differentiating the non-homogeneous step, s <- s n + v (the old v).
  Integer v, s, t1, dp(1);  // fresh objects: Gmpz shares its value on copy, mpz() does not unshare
  mpz_set(v.mpz(), z_.back().mpz());
  for (std::size_t k = z_.size() - 1; k-- > 0;) {
    mpz_mul(s.mpz(), s.mpz(), n);
    mpz_add(s.mpz(), s.mpz(), v.mpz());
    mpz_mul(dp.mpz(), dp.mpz(), d);
    mpz_mul(v.mpz(), v.mpz(), n);
    mpz_mul(t1.mpz(), z_[k].mpz(), dp.mpz());
    mpz_add(v.mpz(), v.mpz(), t1.mpz());
  }
  if (mpz_sgn(s.mpz()) == 0) return std::nullopt;
  // t - v / (s d) = (n s - v) / (s d), then divided by 2^e and floored.
  Integer num, den;
  mpz_mul(num.mpz(), n, s.mpz());
  mpz_sub(num.mpz(), num.mpz(), v.mpz());
  mpz_mul(den.mpz(), s.mpz(), d);
  if (mpz_sgn(den.mpz()) < 0) {
    mpz_neg(den.mpz(), den.mpz());
    mpz_neg(num.mpz(), num.mpz());
  }
  if (e >= 0)
    mpz_mul_2exp(den.mpz(), den.mpz(), static_cast<mp_bitcnt_t>(e));
  else
    mpz_mul_2exp(num.mpz(), num.mpz(), static_cast<mp_bitcnt_t>(-e));
  mpz_fdiv_q(num.mpz(), num.mpz(), den.mpz());
  Rational out(num);
  if (e >= 0)
    mpq_mul_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(e));
  else
    mpq_div_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(-e));
  return out;
}

void IntegerPoly::to_flint(fmpz_poly_t out) const {
  for (std::size_t k = 0; k < z_.size(); ++k) fmpz_poly_set_coeff_mpz(out, static_cast<slong>(k), z_[k].mpz());
}

}  // namespace relpos::detail
