#include "algebra/root_facts.hpp"

#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>
#include <gmp.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <utility>
#include <vector>

#include "algebra/small_factor.hpp"
#include "algebra/sturm_habicht_quartic.hpp"

namespace relpos {
namespace {

using Poly = CGAL::Polynomial<Integer>;
using detail::SmallCount;

int sgn(const Integer& z) { return z > 0 ? 1 : (z < 0 ? -1 : 0); }

/// Distinct real roots of a square-free integer polynomial of degree 1 or 2, by sign.
SmallCount count_small(const Poly& h) {
  const int d = h.degree();
  if (d == 1) return detail::count_small(1, 1, 0, sgn(h[1]), sgn(h[0]));
  return detail::count_small(d, sgn(Integer(h[1] * h[1] - 4 * h[2] * h[0])), sgn(h[2]), sgn(h[1]), sgn(h[0]));
}

/// The rational square root of q >= 0, if q is a square in Q.
std::optional<Rational> rational_sqrt(const Rational& q) {
  if (q < 0) return std::nullopt;
  if (!mpz_perfect_square_p(q.numerator().mpz()) || !mpz_perfect_square_p(q.denominator().mpz())) return std::nullopt;
  Integer n, d;
  mpz_sqrt(n.mpz(), q.numerator().mpz());
  mpz_sqrt(d.mpz(), q.denominator().mpz());
  return Rational(n, d);
}

/// Multiplicity (0, 1 or 2) of x as a root of the quadratic s (s2 = det M > 0).
int multiplicity_in(const Quadratic<Rational>& s, const Rational& x) {
  if (!CGAL::is_zero((s[2] * x + s[1]) * x + s[0])) return 0;
  return CGAL::is_zero(2 * s[2] * x + s[1]) ? 2 : 1;
}

/// A multiple root of f with its multiplicity in f.
struct MultipleRoot {
  Rational x;
  int mult;
};

/// The multiple roots of f (Disc(f) = 0) read off gcd(f, f'), the first non-zero subresultant
/// (subresultant theorem: deg gcd is the first j whose principal coefficient is non-zero, g1[0]
/// then g2[0], and the gcd is StHa_j; every multiple root of f is a root of it, with multiplicity
/// one less). False when they are irrational or non-real.
bool multiple_roots(const Quartic<Rational>& fq, const Integer g2[3], const Integer g1[2],
                    std::vector<MultipleRoot>& roots) {
  if (!CGAL::is_zero(g1[0])) {  // gcd linear: one double root, the other two simple
    roots.push_back({Rational(-g1[1], g1[0]), 2});
  } else if (!CGAL::is_zero(g2[0])) {  // gcd = g2, quadratic
    const Rational a(g2[0]), b(g2[1]), c(g2[2]);
    const Rational disc_g2 = b * b - 4 * a * c;
    if (CGAL::is_zero(disc_g2)) {  // gcd = (l - r)^2: a triple root and a simple one
      roots.push_back({-b / (2 * a), 3});
    } else {  // two double roots, rational only if disc is a square
      const auto w = rational_sqrt(disc_g2);
      if (!w) return false;  // irrational or non-real double roots: the general path
      roots.push_back({(-b - *w) / (2 * a), 2});
      roots.push_back({(-b + *w) / (2 * a), 2});
    }
  } else {  // gcd cubic: a quadruple root
    roots.push_back({-fq[3] / (4 * fq[4]), 4});
  }
  return true;
}

/// The square-free cofactor of f (degree <= 2, none of its roots a multiple root of f).
struct Cofactor {
  std::array<Rational, 3> c{};
  int degree = 0;
};

/// f / prod (l - x)^mult by synthetic division over Q; false when a remainder is not 0 (cannot
/// happen: the roots divide f by the theorem above).
bool divide_out(const Quartic<Rational>& fq, const std::vector<MultipleRoot>& roots, Cofactor& rest) {
  std::array<Rational, 5> c = fq;
  int deg = 4;
  for (const MultipleRoot& r : roots)
    for (int k = 0; k < r.mult; ++k) {
      std::array<Rational, 5> q{};
      Rational carry(0);
      for (int i = deg; i >= 1; --i) {
        carry = c[static_cast<std::size_t>(i)] + carry * r.x;
        q[static_cast<std::size_t>(i - 1)] = carry;
      }
      if (!CGAL::is_zero(c[0] + carry * r.x)) return false;
      c = q;
      --deg;
    }
  rest.degree = deg;
  for (int i = 0; i <= deg; ++i) rest.c[static_cast<std::size_t>(i)] = c[static_cast<std::size_t>(i)];
  return true;
}

/// s with the multiple roots of f that are its roots divided out.
struct SRest {
  Quadratic<Rational> c;
  int degree = 2;
};

/// The multiple roots counted into r (by sign, tangent ones apart: math.md §3, mult_f - mult_s >= 2)
/// and divided out of s; returns deg of their part of gcd(f, s) and sets `tangent`.
int count_multiple_roots(const std::vector<MultipleRoot>& roots, const Quadratic<Rational>& sq, RootFacts& r,
                         SRest& s_rest, bool& tangent) {
  int gcd_degree = 0;
  for (const MultipleRoot& x : roots) {
    const int ms = multiplicity_in(sq, x.x);
    const int sign = CGAL::sign(x.x);
    (sign < 0 ? r.negative : r.positive) += 1;
    if (x.mult - ms >= 2) {
      (sign < 0 ? r.tangent_negative : r.tangent_positive) += 1;
      tangent = true;
    }
    gcd_degree += std::min(x.mult, ms);
    for (int k = 0; k < ms; ++k) {  // s_rest /= (l - x)
      const Rational q1 = s_rest.c[2], q0 = s_rest.c[1] + q1 * x.x;
      s_rest.c = {q0, q1, Rational(0)};
      --s_rest.degree;
    }
  }
  return gcd_degree;
}

/// The number of roots the square-free cofactor shares with what is left of s (both square-free,
/// degree <= 2).
int shared_roots(const Cofactor& rest, const SRest& s) {
  if (rest.degree < 1 || s.degree < 1) return 0;
  const std::array<Rational, 3>& h = rest.c;
  const Quadratic<Rational>& q = s.c;
  if (s.degree == 1) {
    const Rational m = -q[0] / q[1];
    Rational v(0);
    for (int i = rest.degree; i >= 0; --i) v = v * m + h[static_cast<std::size_t>(i)];
    return CGAL::is_zero(v) ? 1 : 0;
  }
  if (rest.degree == 1) {
    const Rational m = -h[0] / h[1];
    return CGAL::is_zero((q[2] * m + q[1]) * m + q[0]) ? 1 : 0;
  }
  // Two quadratics: Res = 0 iff a common root; proportional iff both.
  const Rational u = h[2] * q[0] - h[0] * q[2], v = h[2] * q[1] - h[1] * q[2], w = h[1] * q[0] - h[0] * q[1];
  if (!CGAL::is_zero(u * u - v * w)) return 0;
  return (CGAL::is_zero(u) && CGAL::is_zero(v)) ? 2 : 1;
}

/// The facts of the cofactor's roots added to r: its real roots by sign, its non-real pair.
void count_cofactor(const Cofactor& rest, RootFacts& r) {
  int sign_disc_rest = 1;
  if (rest.degree == 2) sign_disc_rest = CGAL::sign(rest.c[1] * rest.c[1] - 4 * rest.c[2] * rest.c[0]);
  if (rest.degree >= 1) {
    const SmallCount hc = detail::count_small(rest.degree, sign_disc_rest, rest.degree == 2 ? CGAL::sign(rest.c[2]) : 0,
                                              CGAL::sign(rest.c[1]), CGAL::sign(rest.c[0]));
    r.negative += hc.negative;
    r.positive += hc.positive;
  }
  r.nonreal = (rest.degree == 2 && sign_disc_rest < 0) ? 2 : 0;
}

}  // namespace

std::optional<RootFacts> subresultant_root_facts(const Quartic<Integer>& f, const Quadratic<Integer>& s) {
  Integer g2[3], g1[2], g0[1];
  detail::sturm_habicht_quartic(f[0], f[1], f[2], f[3], f[4], g2, g1, g0);
  return subresultant_root_facts(f, s, g2, g1, g0[0]);
}

std::optional<RootFacts> subresultant_root_facts(const Quartic<Integer>& f, const Quadratic<Integer>& s,
                                                 const Integer g2[3], const Integer g1[2], const Integer& disc) {
  if (CGAL::is_zero(f[4]) || CGAL::is_zero(f[0])) return std::nullopt;
  if (!CGAL::is_zero(disc)) return std::nullopt;  // square-free: not this function's case
  const Quartic<Rational> fq{Rational(f[0]), Rational(f[1]), Rational(f[2]), Rational(f[3]), Rational(f[4])};
  const Quadratic<Rational> sq{Rational(s[0]), Rational(s[1]), Rational(s[2])};
  std::vector<MultipleRoot> roots;  // the multiple roots, with their multiplicity in f
  Cofactor rest;
  if (!multiple_roots(fq, g2, g1, roots) || !divide_out(fq, roots, rest)) return std::nullopt;
  RootFacts r;
  SRest s_rest{sq};
  bool tangent = false;
  const int gcd_degree = count_multiple_roots(roots, sq, r, s_rest, tangent);  // deg gcd(f, s) so far
  count_cofactor(rest, r);
  r.real = r.negative + r.positive;
  r.nonreal_multiple = 0;  // every multiple root here is rational
  r.sign_disc_f = 0;
  // f~ keeps f's non-real roots (s has real roots only); it is square-free unless tangent.
  r.sign_disc_ftilde = tangent ? 0 : ((r.nonreal / 2) % 2 ? -1 : 1);
  r.degree_ftilde = 4 - gcd_degree - shared_roots(rest, s_rest);
  return r;
}

std::optional<RootFacts> exact_root_facts(const Quartic<Integer>& fc, const Quadratic<Integer>& sc) {
  if (auto r = subresultant_root_facts(fc, sc)) return r;  // rational multiple roots, without gcds
  return exact_root_facts_by_factorisation(fc, sc);
}

std::optional<RootFacts> exact_root_facts_by_factorisation(const Quartic<Integer>& fc, const Quadratic<Integer>& sc) {
  const Poly f(fc.begin(), fc.end()), s(sc.begin(), sc.end());
  std::vector<std::pair<Poly, int>> factors;
  CGAL::square_free_factorize(f, std::back_inserter(factors));
  RootFacts r;
  bool multiple = false;
  for (const auto& [h, m] : factors) {
    if (h.degree() > 2) return std::nullopt;  // square-free quartic: not this function's case
    if (h.degree() < 1) continue;
    multiple = multiple || m >= 2;
    const SmallCount c = count_small(h);
    r.negative += c.negative;
    r.positive += c.positive;
    const int nonreal = h.degree() - c.negative - c.positive;
    r.nonreal += nonreal * m;
    if (m >= 2) r.nonreal_multiple += nonreal * m;
  }
  if (!multiple) return std::nullopt;
  r.real = r.negative + r.positive;
  r.sign_disc_f = 0;
  const Poly ft = CGAL::integral_division_up_to_constant_factor(f, CGAL::gcd(f, s));
  r.degree_ftilde = ft.degree();
  std::vector<std::pair<Poly, int>> tfactors;
  CGAL::square_free_factorize(ft, std::back_inserter(tfactors));
  bool ft_multiple = false;
  for (const auto& [h, m] : tfactors) {
    if (m < 2 || h.degree() < 1) continue;
    ft_multiple = true;
    const SmallCount c = count_small(h);  // deg h <= 2 because m >= 2 and deg f~ <= 4
    r.tangent_negative += c.negative;
    r.tangent_positive += c.positive;
  }
  // For a square-free real polynomial, sign Disc = (-1)^(number of non-real conjugate pairs); f~
  // keeps f's non-real roots (s has only real roots).
  r.sign_disc_ftilde = ft_multiple ? 0 : ((r.nonreal / 2) % 2 ? -1 : 1);
  return r;
}

}  // namespace relpos
