// Exact pieces of math.md §8 that the sign ladder does not cover: the decision when f has
// multiple roots (f is not square-free), and the arithmetic of lambda_s, the root of s nearest 0, a
// rational or a quadratic irrational. Small dense polynomials over Q (degree <= 4): these paths run
// only for exact tangencies, special roots and certificates, never on the filtered path.
#pragma once

#include <gmp.h>

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "algebra/pencil.hpp"
#include "relpos/numbers.hpp"
#include "relpos/polynomials.hpp"

namespace relpos::detail::anysize {

/// Polynomial over Q, index = power; no trailing zeros (the zero polynomial is empty). Evaluated by
/// relpos::evaluate (relpos/polynomials.hpp).
using Poly = RationalPolynomial;

Poly trimmed(Poly p);
Poly derivative(const Poly& p);
Poly remainder(const Poly& a, const Poly& b);
Poly quotient(const Poly& a, const Poly& b);  ///< exact division expected
Poly monic_gcd(Poly a, Poly b);
/// The Sturm sequence of a square-free p: p, p', then the negated remainders.
std::vector<Poly> sturm_sequence(const Poly& p);
/// Sign changes of a sequence of signs, zeros dropped: evaluated on a Sturm sequence at a < b, the
/// difference counts the distinct real roots in (a, b].
int variations(const std::vector<int>& signs);
/// Square-free decomposition (Yun): factors[k] is the product of the irreducible factors of
/// multiplicity k + 1, monic; constant factors dropped.
std::vector<Poly> square_free_decomposition(const Poly& p);

/// An element a + b sqrt(d) of Q(sqrt d), d a non-negative integer fixed by the context.
struct QuadraticReal {
  Rational a, b;
};

/// lambda_s and the field it lives in: lambda_s = a + b sqrt(d), with b = 0 and d = 0 when lambda_s
/// is rational (Disc(s) a perfect square, e.g. a circular paraboloid or axis-aligned bodies).
class LambdaS {
 public:
  Integer d;
  double lo = -HUGE_VAL, hi = HUGE_VAL;  ///< a certified enclosure lo <= lambda_s <= hi (compare's filter)
  /// a + b sqrt(d). An irrational lambda_s's a = -s1 / (2 s2) is reduced on first use: most
  /// certificates read only the enclosure, and reducing a is a gcd of s1's and s2's long numerators.
  const QuadraticReal& value() const {
    if (pending_) settle();
    return value_;
  }
  bool rational() const { return value_.b == 0; }  // b is never pending
  /// Exact sign of x + y sqrt(d).
  int sign(const QuadraticReal& x) const;
  QuadraticReal add(const QuadraticReal& x, const QuadraticReal& y) const;
  QuadraticReal sub(const QuadraticReal& x, const QuadraticReal& y) const;
  QuadraticReal mul(const QuadraticReal& x, const QuadraticReal& y) const;
  QuadraticReal div(const QuadraticReal& x, const QuadraticReal& y) const;  ///< y != 0
  /// p(lambda_s) in Q(sqrt d).
  QuadraticReal at(const Poly& p) const;
  /// sign(q - lambda_s) for rational q.
  int compare(const Rational& q) const;

 private:
  friend LambdaS lambda_s_of(const Poly& s, const Rational& disc);
  friend LambdaS rational_lambda_s(const Rational& value);
  /// A copy of the thread's default LambdaS, its numbers sharing that one's values (no heap
  /// allocation): a number is assigned a fresh one before it is written in place.
  static LambdaS blank();
  void settle() const;
  mutable QuadraticReal value_;
  struct Pending {
    Rational num, den;  ///< a = -num / den (den = 2 s2 > 0), not yet reduced
  };
  mutable std::optional<Pending> pending_;
};

/// forms::tight_interval(n / d) for d > 0, bit for bit, without reducing the fraction (no gcd).
std::pair<double, double> tight_interval_of_quotient(mpz_srcptr n, mpz_srcptr d);

/// lambda_s from s = s0 + s1 l + s2 l^2 (two negative roots, s2 > 0).
LambdaS lambda_s_of(const Poly& s);
/// The same from Disc(s) = s1^2 - 4 s2 s0, known to the caller (a rational: canonical).
LambdaS lambda_s_of(const Poly& s, const Rational& disc);
/// lambda_s known to the caller to be the rational `value` (Disc(s) a square).
LambdaS rational_lambda_s(const Rational& value);

/// The five rules of math.md §8 as exact facts of f = det(l P + E) and s = det(l A + M):
/// 1 E: a root of odd multiplicity in (0, oo);  2 TE: any other root in (0, oo);
/// 3 I: a root of odd multiplicity in (lambda_s, 0);  4 TI: f~ = f / gcd(f, s) has a root in
/// [lambda_s, 0);  5 C otherwise. `rule` is 1..5; `hard` says that rule 4 was met only at lambda_s
/// (the hard case: contact along two points or a conic).
struct AnySizeFacts {
  int rule = 5;
  bool hard = false;
  int odd_positive = 0, even_positive = 0;  ///< distinct roots in (0, oo) by parity of multiplicity
  int odd_gap = 0, even_gap = 0;            ///< distinct roots in (lambda_s, 0)
  int multiplicity_at_lambda_s = 0;         ///< mult_f(lambda_s)
  int multiplicity_s = 1;                   ///< mult_s(lambda_s): 2 when s is a square
};

/// Exact facts for any f (square-free or not), from its square-free decomposition and Sturm
/// sequences evaluated at lambda_s, 0 and oo.
AnySizeFacts any_size_facts(const Poly& f, const Poly& s);

template <class Z>
Poly to_poly(const Z* c, std::size_t n) {
  Poly p;
  p.reserve(n);
  for (std::size_t i = 0; i < n; ++i) p.push_back(Rational(c[i]));
  return trimmed(std::move(p));
}

}  // namespace relpos::detail::anysize
