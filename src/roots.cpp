#include "relpos/roots.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>
#include <gmp.h>

#include <algorithm>
#include <utility>

#include "relpos/detail/small_factor.hpp"

namespace relpos {
namespace {

using Poly = CGAL::Polynomial<Integer>;
using AK = CGAL::Algebraic_kernel_d_1<Integer>;
using Root = AK::Algebraic_real_1;

template <std::size_t N>
Poly make_poly(const std::array<Integer, N>& c) {
  return Poly(c.begin(), c.end());
}

int sgn(const Integer& z) { return z > 0 ? 1 : (z < 0 ? -1 : 0); }

Rational evaluate(const Quartic<Integer>& f, const Rational& x) {
  Rational v(0);
  for (int i = 4; i >= 0; --i) v = v * x + Rational(f[static_cast<std::size_t>(i)]);
  return v;
}

/// The root itself if it is rational. A rational root p/q (lowest terms) of an integer polynomial has
/// q | lc(f), so root * lc(f) is an integer: refine the isolating interval below width 1/|lc(f)|,
/// take the only candidate m/lc(f) in it and test f(m/lc(f)) = 0 exactly.
std::optional<Rational> rational_value(const AK& ak, const Root& root, const Quartic<Integer>& f) {
  Integer lc = f[4] < 0 ? Integer(-f[4]) : f[4];
  const int bits = static_cast<int>(mpz_sizeinbase(lc.mpz(), 2)) + 4;
  auto iv = ak.approximate_absolute_1_object()(root, bits);
  const Rational scaled = (iv.first + iv.second) / 2 * Rational(lc);
  Integer m;  // nearest integer to scaled
  const Rational shifted = scaled + Rational(1, 2);
  mpz_fdiv_q(m.mpz(), shifted.numerator().mpz(), shifted.denominator().mpz());
  const Rational candidate(m, lc);
  if (candidate < iv.first || candidate > iv.second) return std::nullopt;
  if (evaluate(f, candidate) != 0) return std::nullopt;
  return candidate;
}

}  // namespace

int RootStructure::negative() const {
  return static_cast<int>(
      std::count_if(real_roots.begin(), real_roots.end(), [](const RealRoot& r) { return r.sign < 0; }));
}
int RootStructure::positive() const {
  return static_cast<int>(
      std::count_if(real_roots.begin(), real_roots.end(), [](const RealRoot& r) { return r.sign > 0; }));
}

int sign_of_discriminant(const std::vector<Integer>& c) {
  Poly g(c.begin(), c.end());
  const int n = g.degree();
  if (n < 1) return 0;
  if (n == 1) return 1;
  // Res(g, g') = (-1)^(n(n-1)/2) lc(g) Disc(g)
  Integer res = CGAL::resultant(g, CGAL::differentiate(g));
  int s = sgn(res) * sgn(g.lcoeff());
  if ((n * (n - 1) / 2) % 2) s = -s;
  return s;
}

RootStructure exact_root_structure(const Quartic<Integer>& fc, const Quadratic<Integer>& sc) {
  const Poly f = make_poly(fc), s = make_poly(sc);
  const Poly g = CGAL::gcd(f, s);
  const Poly ft = CGAL::integral_division_up_to_constant_factor(f, g);

  RootStructure rs;
  rs.degree_ftilde = ft.degree();
  rs.sign_disc_f = sign_of_discriminant(std::vector<Integer>(fc.begin(), fc.end()));
  {
    std::vector<Integer> c;
    for (int i = 0; i <= ft.degree(); ++i) c.push_back(ft[i]);
    rs.sign_disc_ftilde = sign_of_discriminant(c);
  }

  AK ak;
  std::vector<std::pair<Root, AK::Multiplicity_type>> roots;
  ak.solve_1_object()(f, std::back_inserter(roots));  // distinct real roots, increasing, with multiplicity
  const Poly ds = CGAL::differentiate(s);
  int real_with_mult = 0;
  long bits = 64;
  for (const auto& [root, mult] : roots) {
    RealRoot r;
    r.sign = static_cast<int>(ak.sign_at_1_object()(Poly(CGAL::shift(Poly(Integer(1)), 1)), root));
    r.multiplicity_f = static_cast<int>(mult);
    if (s.degree() >= 0 && ak.is_zero_at_1_object()(s, root))
      r.multiplicity_s = ak.is_zero_at_1_object()(ds, root) ? 2 : 1;
    r.exact = rational_value(ak, root, fc);
    real_with_mult += r.multiplicity_f;
    rs.real_roots.push_back(std::move(r));
  }
  // Isolating intervals: refine until the intervals of neighbouring roots are disjoint.
  for (;; bits *= 2) {
    for (std::size_t i = 0; i < roots.size(); ++i) {
      auto iv = ak.approximate_absolute_1_object()(roots[i].first, static_cast<int>(bits));
      rs.real_roots[i].lower = iv.first;
      rs.real_roots[i].upper = iv.second;
    }
    bool disjoint = true;
    for (std::size_t i = 1; i < roots.size(); ++i)
      if (!(rs.real_roots[i - 1].upper < rs.real_roots[i].lower)) disjoint = false;
    if (disjoint || bits > 4096) break;
  }
  rs.nonreal = 4 - real_with_mult;
  // Non-real roots of multiplicity >= 2: look at the square-free factors of multiplicity >= 2.
  std::vector<std::pair<Poly, int>> factors;
  CGAL::square_free_factorize(f, std::back_inserter(factors));
  for (const auto& [h, m] : factors) {
    if (m < 2) continue;
    std::vector<std::pair<Root, AK::Multiplicity_type>> hr;
    ak.solve_1_object()(h, std::back_inserter(hr));
    rs.nonreal_multiple += (h.degree() - static_cast<int>(hr.size())) * m;
  }
  return rs;
}

namespace {

using detail::SmallCount;

/// Distinct real roots of a square-free integer polynomial of degree 1 or 2, by sign.
SmallCount count_small(const Poly& h) {
  const int d = h.degree();
  if (d == 1) return detail::count_small(1, 1, 0, sgn(h[1]), sgn(h[0]));
  return detail::count_small(d, sgn(Integer(h[1] * h[1] - 4 * h[2] * h[0])), sgn(h[2]), sgn(h[1]), sgn(h[0]));
}

}  // namespace

std::optional<RootFacts> exact_root_facts(const Quartic<Integer>& fc, const Quadratic<Integer>& sc) {
  const Poly f = make_poly(fc), s = make_poly(sc);
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

std::vector<std::string> real_root_decimals(const Quartic<Integer>& fc, int digits) {
  const Poly f = make_poly(fc);
  AK ak;
  std::vector<std::pair<Root, AK::Multiplicity_type>> roots;
  ak.solve_1_object()(f, std::back_inserter(roots));
  std::vector<std::string> out;
  const int bits = static_cast<int>(digits * 3.33) + 8;
  for (const auto& r : roots) {
    auto iv = ak.approximate_relative_1_object()(r.first, bits);
    Rational mid = (iv.first + iv.second) / 2;
    out.push_back(to_decimal(mid, digits));
  }
  return out;
}

}  // namespace relpos
