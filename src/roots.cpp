#include "relpos/roots.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>
#include <gmp.h>

#include <algorithm>
#include <utility>

#include "relpos/detail/small_factor.hpp"
#include "relpos/detail/sturm_habicht_quartic.hpp"

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

std::optional<RootFacts> single_double_root_facts(const Quartic<Integer>& f, const Quadratic<Integer>& s) {
  if (CGAL::is_zero(f[4]) || CGAL::is_zero(f[0])) return std::nullopt;
  Integer g2[3], g1[2], g0[1];
  detail::sturm_habicht_quartic(f[0], f[1], f[2], f[3], f[4], g2, g1, g0);
  // Subresultant theorem: deg gcd(f, f') is the first j with a non-zero principal coefficient
  // (g0 = Disc(f), then g1[0]). Disc(f) = 0 and g1[0] != 0 make gcd(f, f') = StHa_1, linear: f has
  // exactly one multiple root, double and rational, and the other two roots are simple.
  if (!CGAL::is_zero(g0[0]) || CGAL::is_zero(g1[0])) return std::nullopt;
  const Rational l0(-g1[1], g1[0]);
  // h = f / (lambda - l0)^2 by two synthetic divisions over Q; both remainders are zero.
  std::array<Rational, 5> c;
  for (std::size_t i = 0; i < 5; ++i) c[i] = Rational(f[i]);
  std::array<Rational, 3> h;
  for (int pass = 0; pass < 2; ++pass) {
    const int deg = 4 - pass;
    std::array<Rational, 5> q{};
    Rational carry(0);
    for (int i = deg; i >= 1; --i) {
      carry = c[static_cast<std::size_t>(i)] + carry * l0;
      q[static_cast<std::size_t>(i - 1)] = carry;
    }
    if (!CGAL::is_zero(c[0] + carry * l0)) return std::nullopt;  // cannot happen (theorem above)
    c = q;
  }
  for (std::size_t i = 0; i < 3; ++i) h[i] = c[i];
  const Rational s0(s[0]), s1(s[1]), s2(s[2]);
  // Multiplicity of l0 in s (s has degree 2, s2 = det M > 0).
  int ms = 0;
  if (CGAL::is_zero((s2 * l0 + s1) * l0 + s0)) ms = CGAL::is_zero(2 * s2 * l0 + s1) ? 2 : 1;
  const int sign_l0 = CGAL::sign(l0);
  RootFacts r;
  (sign_l0 < 0 ? r.negative : r.positive) += 1;
  const bool tangent = 2 - ms >= 2;  // math.md section 3: mult_f - mult_s >= 2
  if (tangent) (sign_l0 < 0 ? r.tangent_negative : r.tangent_positive) += 1;
  const int sign_disc_h = CGAL::sign(h[1] * h[1] - 4 * h[2] * h[0]);  // != 0: h is square-free
  const SmallCount hc = detail::count_small(2, sign_disc_h, CGAL::sign(h[2]), CGAL::sign(h[1]), CGAL::sign(h[0]));
  r.negative += hc.negative;
  r.positive += hc.positive;
  r.real = r.negative + r.positive;
  r.nonreal = sign_disc_h < 0 ? 2 : 0;
  r.sign_disc_f = 0;
  // f~ keeps the non-real pair (s has real roots only); square-free unless tangent.
  r.sign_disc_ftilde = tangent ? 0 : ((r.nonreal / 2) % 2 ? -1 : 1);
  // deg f~ = 4 - deg gcd(f, s): min(2, ms) at l0, plus the roots h shares with s / (lambda - l0)^ms.
  int shared = 0;
  if (ms == 1) {  // s = s2 (lambda - l0)(lambda - m), m = -s1/s2 - l0
    const Rational m = -s1 / s2 - l0;
    shared = CGAL::is_zero((h[2] * m + h[1]) * m + h[0]) ? 1 : 0;
  } else if (ms == 0) {  // Res(h, s) = 0 iff a common root; proportional iff both
    const Rational u = h[2] * s0 - h[0] * s2, v = h[2] * s1 - h[1] * s2, w = h[1] * s0 - h[0] * s1;
    if (CGAL::is_zero(u * u - v * w)) shared = (CGAL::is_zero(u) && CGAL::is_zero(v)) ? 2 : 1;
  }
  r.degree_ftilde = 4 - std::min(2, ms) - shared;
  return r;
}

std::optional<RootFacts> exact_root_facts(const Quartic<Integer>& fc, const Quadratic<Integer>& sc) {
  if (auto r = single_double_root_facts(fc, sc)) return r;  // the common case, without gcds
  return exact_root_facts_by_factorisation(fc, sc);
}

std::optional<RootFacts> exact_root_facts_by_factorisation(const Quartic<Integer>& fc, const Quadratic<Integer>& sc) {
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
