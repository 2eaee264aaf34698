#include "relpos/algebraic_real.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>
#include <gmp.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include "algebra/flint_poly.hpp"
#include "algebra/flint_thread.hpp"
#include "algebra/irreducible.hpp"
#include "algebra/polynomial_sign.hpp"
#include "algebra/polynomial_text.hpp"

namespace relpos {
namespace {

using detail::from_flint;
using detail::sign_of_value;
using detail::to_flint;

int sgn(const Rational& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

/// 2^-n as a fresh rational (never written through a shared representation).
Rational inverse_power_of_two(unsigned long n) {
  Integer d;
  mpz_setbit(d.mpz(), n);
  return Rational(Integer(1), d);
}

std::vector<std::vector<Integer>> flint_factors(const std::vector<Integer>& p) {
  detail::flint_thread_cleanup_at_exit();
  fmpz_poly_t f;
  fmpz_poly_init(f);
  to_flint(f, p);
  fmpz_poly_factor_t fac;
  fmpz_poly_factor_init(fac);
  fmpz_poly_factor(fac, f);
  std::vector<std::vector<Integer>> out;
  for (slong k = 0; k < fac->num; ++k) {
    std::vector<Integer> coeffs = from_flint(fac->p + k);
    if (coeffs.size() < 2) continue;  // a constant (FLINT keeps the content apart anyway)
    if (coeffs.back() < 0)
      for (auto& x : coeffs) x = -x;
    out.push_back(std::move(coeffs));
  }
  fmpz_poly_factor_clear(fac);
  fmpz_poly_clear(f);
  return out;
}

}  // namespace

std::vector<std::vector<Integer>> detail::irreducible_factors(const std::vector<Integer>& coefficients) {
  for (const auto& c : coefficients)
    if (c != 0) return flint_factors(coefficients);
  throw std::invalid_argument("irreducible_factors: the zero polynomial");
}

std::vector<Integer> detail::pseudo_remainder(const std::vector<Integer>& p, const std::vector<Integer>& m) {
  detail::flint_thread_cleanup_at_exit();
  if (m.size() < 2) throw std::invalid_argument("pseudo_remainder: constant divisor");
  fmpz_poly_t a, b, r;
  fmpz_poly_init(a);
  fmpz_poly_init(b);
  fmpz_poly_init(r);
  to_flint(a, p);
  to_flint(b, m);
  std::vector<Integer> out;
  if (!fmpz_poly_is_zero(a)) {
    ulong d = 0;
    fmpz_poly_pseudo_rem(r, &d, a, b);
    out = from_flint(r);
  }
  fmpz_poly_clear(a);
  fmpz_poly_clear(b);
  fmpz_poly_clear(r);
  return out;
}

AlgebraicReal AlgebraicReal::rational(const Rational& q) {
  AlgebraicReal r;
  r.poly_ = {-q.numerator(), q.denominator()};
  r.exact_ = q;
  r.lower_ = r.upper_ = q;
  return r;
}

AlgebraicReal AlgebraicReal::root(std::vector<Integer> coefficients, Rational lower, Rational upper, bool irreducible) {
  while (!coefficients.empty() && coefficients.back() == 0) coefficients.pop_back();
  AlgebraicReal r;
  r.poly_ = std::move(coefficients);
  r.lower_ = std::move(lower);
  r.upper_ = std::move(upper);
  const int sl = r.sign_at(r.lower_), su = r.sign_at(r.upper_);
  if (!(r.lower_ < r.upper_) || sl == 0 || su == 0 || sl == su)
    throw std::invalid_argument("AlgebraicReal::root: the interval does not isolate a sign change");
  if (irreducible) {
    if (r.poly_.size() == 2) return rational(Rational(-r.poly_[0], r.poly_[1]));
    if (r.poly_.back() < 0) {
      for (auto& x : r.poly_) x = -x;
      r.sign_lower_ = -sl;
    } else {
      r.sign_lower_ = sl;
    }
    return r;
  }
  // Keep only the irreducible factor that vanishes at the number: the only factor with a root in
  // (lower, upper) (the product is square-free with exactly one root there), hence the only one
  // that changes sign between the ends. It is the minimal polynomial up to a constant.
  for (auto& g : flint_factors(r.poly_)) {
    if (g.size() < 2) continue;
    const int gl = sign_of_value(g, r.lower_), gu = sign_of_value(g, r.upper_);
    if (gl == 0 || gu == 0 || gl == gu) continue;
    if (g.size() == 2) return rational(Rational(-g[0], g[1]));
    r.poly_ = std::move(g);
    r.sign_lower_ = gl;
    return r;
  }
  throw std::logic_error("AlgebraicReal::root: no irreducible factor changes sign");
}

int AlgebraicReal::sign_at(const Rational& x) const { return sign_of_value(poly_, x); }

void AlgebraicReal::refine(const Rational& width) {
  if (!(width > 0))
    throw std::invalid_argument("AlgebraicReal::refine: the width must be positive, got " + to_string(width));
  if (exact_) return;
  // Bisection on exact signs; a midpoint that is a root makes the number rational.
  while (upper_ - lower_ > width) {
    Rational mid = (lower_ + upper_) / 2;
    const int sm = sign_at(mid);
    if (sm == 0) {
      exact_ = mid;
      lower_ = upper_ = mid;
      return;
    }
    if (sm == sign_lower_)
      lower_ = std::move(mid);
    else
      upper_ = std::move(mid);
  }
}

std::string AlgebraicReal::decimals(int digits) const {
  if (digits < 1) digits = 1;
  if (exact_) return to_decimal(*exact_, digits);
  AlgebraicReal copy = *this;
  for (;;) {
    if (copy.exact_) return to_decimal(*copy.exact_, digits);
    std::string lo = to_decimal(copy.lower_, digits), hi = to_decimal(copy.upper_, digits);
    if (lo == hi) return lo;
    // Halve the width at least ~4 times per round: the loop ends because the number is irrational
    // here, so it is not a rounding boundary, and a small enough interval avoids every boundary.
    copy.refine((copy.upper_ - copy.lower_) / 16);
  }
}

double AlgebraicReal::to_double() const {
  if (exact_) return CGAL::to_double(*exact_);
  AlgebraicReal copy = *this;
  const Rational mag = copy.upper_ > 0 ? copy.upper_ : -copy.lower_;
  // Relative width 2^-60 is far below double precision; absolute floor for numbers near 0.
  Rational w = mag * inverse_power_of_two(60);
  if (w == 0) w = inverse_power_of_two(60);
  copy.refine(w);
  if (copy.exact_) return CGAL::to_double(*copy.exact_);
  return CGAL::to_double((copy.lower_ + copy.upper_) / 2);
}

int AlgebraicReal::compare(const Rational& q) const {
  if (exact_) return sgn(*exact_ - q);
  if (q <= lower_) return 1;
  if (q >= upper_) return -1;
  // q inside the isolating interval: the root is on the side where the sign changes.
  const int sq = sign_at(q);
  if (sq == 0) return 0;              // cannot happen for an irrational root, kept for safety
  return sq == sign_lower_ ? 1 : -1;  // same sign as at lower: the root lies right of q
}

int AlgebraicReal::compare(const AlgebraicReal& other) const {
  if (exact_) return -other.compare(*exact_);
  if (other.exact_) return compare(*other.exact_);
  // Irreducible polynomials with positive leading coefficients: proportional for equal numbers (a
  // caller's irreducible polynomial need not be primitive).
  const auto proportional = [](const std::vector<Integer>& p, const std::vector<Integer>& q) {
    if (p.size() != q.size()) return false;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p[i] * q.back() != q[i] * p.back()) return false;
    return true;
  };
  if (proportional(poly_, other.poly_)) {
    // One irreducible polynomial, and each interval holds exactly one of its roots: the two are the same root when
    // the intersection of the intervals holds a root, i.e. when the polynomial changes sign across
    // it (it has no rational root, so no sign is zero at the ends).
    const Rational& lo = std::max(lower_, other.lower_);
    const Rational& hi = std::min(upper_, other.upper_);
    if (lo < hi && sign_at(lo) != sign_at(hi)) return 0;
  }
  // Different numbers: bisect both until their intervals separate them (this ends, as they differ).
  AlgebraicReal a = *this, b = other;
  for (;;) {
    if (a.exact_ || b.exact_) return a.exact_ ? -b.compare(*a.exact_) : a.compare(*b.exact_);
    if (a.upper_ <= b.lower_) return -1;
    if (b.upper_ <= a.lower_) return 1;
    a.refine((a.upper_ - a.lower_) / 2);
    b.refine((b.upper_ - b.lower_) / 2);
  }
}

std::string polynomial_text(const std::vector<Integer>& c, const std::string& variable) {
  return detail::polynomial_text(c.data(), c.size(), variable);
}

}  // namespace relpos
