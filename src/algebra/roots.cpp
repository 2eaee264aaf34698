#include "algebra/roots.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>
#include <gmp.h>

#include <algorithm>
#include <iterator>
#include <utility>

#include "algebra/flint_thread.hpp"
#include "algebra/modular.hpp"

namespace relpos {
namespace {

using Poly = CGAL::Polynomial<Integer>;
using AK = CGAL::Algebraic_kernel_d_1<Integer>;
using Root = AK::Algebraic_real_1;
using Solutions = std::vector<std::pair<Root, AK::Multiplicity_type>>;

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

/// Isolating intervals of the roots: refined until the intervals of neighbouring roots are disjoint.
void isolate(const AK& ak, const Solutions& roots, std::vector<RealRoot>& out) {
  for (long bits = 64;; bits *= 2) {
    for (std::size_t i = 0; i < roots.size(); ++i) {
      auto iv = ak.approximate_absolute_1_object()(roots[i].first, static_cast<int>(bits));
      out[i].lower = iv.first;
      out[i].upper = iv.second;
    }
    bool disjoint = true;
    for (std::size_t i = 1; i < roots.size(); ++i)
      if (!(out[i - 1].upper < out[i].lower)) disjoint = false;
    if (disjoint || bits > 4096) break;
  }
}

/// The exact value of each rational root: the one rational root of f in its isolating interval.
void set_rational_values(const AK& ak, const Solutions& roots, const Quartic<Integer>& fc, std::vector<RealRoot>& out) {
  const std::vector<Rational> rational = detail::rational_roots(fc);
  for (std::size_t i = 0; i < roots.size(); ++i) {
    RealRoot& r = out[i];
    const bool isolated =
        (i == 0 || out[i - 1].upper < r.lower) && (i + 1 == roots.size() || r.upper < out[i + 1].lower);
    if (!isolated) {  // intervals still overlapping (never seen): test this root on its own
      r.exact = rational_value(ak, roots[i].first, fc);
      continue;
    }
    for (const Rational& q : rational)
      if (r.lower <= q && q <= r.upper) r.exact = q;
  }
}

/// Non-real roots of f of multiplicity >= 2: those of its square-free factors of multiplicity >= 2.
int nonreal_multiple(const AK& ak, const Poly& f) {
  std::vector<std::pair<Poly, int>> factors;
  CGAL::square_free_factorize(f, std::back_inserter(factors));
  int count = 0;
  for (const auto& [h, m] : factors) {
    if (m < 2) continue;
    Solutions hr;
    solve_on_fitting_stack(ak, h, std::back_inserter(hr));
    count += (h.degree() - static_cast<int>(hr.size())) * m;
  }
  return count;
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
  detail::flint_thread_cleanup_at_exit();
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

RootStructure exact_root_structure(const Quartic<Integer>& fc, const Quadratic<Integer>& sc, int sign_disc_f) {
  if (auto fast = simple_root_structure(fc, sc, sign_disc_f)) return std::move(*fast);
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
  Solutions roots;
  solve_on_fitting_stack(ak, f, std::back_inserter(roots));  // distinct real roots, increasing, with multiplicity
  const Poly ds = CGAL::differentiate(s);
  int real_with_mult = 0;
  for (const auto& [root, mult] : roots) {
    RealRoot r;
    r.sign = static_cast<int>(ak.sign_at_1_object()(Poly(CGAL::shift(Poly(Integer(1)), 1)), root));
    r.multiplicity_f = static_cast<int>(mult);
    if (s.degree() >= 0 && ak.is_zero_at_1_object()(s, root))
      r.multiplicity_s = ak.is_zero_at_1_object()(ds, root) ? 2 : 1;
    real_with_mult += r.multiplicity_f;
    rs.real_roots.push_back(std::move(r));
  }
  isolate(ak, roots, rs.real_roots);
  set_rational_values(ak, roots, fc, rs.real_roots);
  rs.nonreal = 4 - real_with_mult;
  rs.nonreal_multiple = nonreal_multiple(ak, f);
  return rs;
}

std::vector<std::string> real_root_decimals(const Quartic<Integer>& fc, int digits) {
  const Poly f = make_poly(fc);
  AK ak;
  Solutions roots;
  solve_on_fitting_stack(ak, f, std::back_inserter(roots));
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
