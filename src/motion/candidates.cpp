#include "motion/candidates.hpp"

#include <iterator>
#include <stdexcept>
#include <utility>

#include "algebra/between.hpp"
#include "algebra/irreducible.hpp"
#include "base/interrupt.hpp"

namespace relpos::detail {

Candidate make_candidate(const Alg& t, unsigned cause, std::optional<Rational> exact, std::vector<Integer> minimal) {
  return Candidate{t, cause, std::move(exact), PolyZ(minimal.begin(), minimal.end()), std::move(minimal), {}};
}

AlgebraicReal& instant_of(const Candidate& z) {
  if (z.instant) return *z.instant;
  if (z.exact) return z.instant.emplace(AlgebraicReal::rational(*z.exact));
  const PolyZ& p = z.minimal;
  for (int guard = 0; guard < 10000; ++guard) {
    const CGAL::Sign sl = p.sign_at(z.t.low()), sh = p.sign_at(z.t.high());
    if (sl != CGAL::ZERO && sh != CGAL::ZERO && sl != sh)
      return z.instant.emplace(
          AlgebraicReal::root(z.minimal_coefficients, z.t.low(), z.t.high(), /*irreducible=*/true));
    z.t.refine();
  }
  throw std::logic_error("motion: could not isolate an irrational instant with a sign change");
}

/// CGAL's Bound_between needs a big-float interval type; this does not: the isolating intervals are
/// refined until disjoint, then any number strictly between their facing ends will do.
Rational rational_between(const Alg& a, const Alg& b) {
  while (!(a.high() < b.low())) {
    if (a.low() != a.high()) a.refine();
    if (b.low() != b.high()) b.refine();
  }
  // a <= a.high() < b.low() <= b.
  return rational_inside(a.high(), Rational(b.low()), Shortest::Denominator);
}

/// p is split into irreducible factors first: a linear factor gives a rational zero at once, and the
/// others are isolated separately (smaller polynomials make every later sign evaluation at the zero
/// cheaper).
void add_zeros(const AK& ak, const PolyZ& p, unsigned cause, const Rational& lo, const Rational& hi,
               std::vector<Candidate>& out, const Interrupt* interrupt) {
  check(interrupt);
  if (CGAL::is_zero(p) || p.degree() < 1) return;
  std::vector<Integer> coeffs;
  for (int i = 0; i <= p.degree(); ++i) coeffs.push_back(p[i]);
  std::vector<Candidate> zeros;
  for (const auto& g : irreducible_factors(coeffs)) {
    check(interrupt);
    const PolyZ gz(g.begin(), g.end());
    if (g.size() == 2) {
      const Rational x(-g[0], g[1]);
      if (lo <= x && x <= hi) zeros.push_back(make_candidate(Alg(x), cause, x, g));
      continue;
    }
    std::vector<Alg> roots;
    ak.solve_1_object()(gz, true, lo, hi, std::back_inserter(roots));
    for (const Alg& z : roots) zeros.push_back(make_candidate(z, cause, std::nullopt, g));
  }
  const auto cmp = ak.compare_1_object();
  for (Candidate& z : zeros) {
    std::size_t i = 0;
    while (i < out.size() && cmp(out[i].t, z.t) == CGAL::SMALLER) ++i;
    if (i < out.size() && cmp(out[i].t, z.t) == CGAL::EQUAL)
      out[i].causes |= cause;
    else
      out.insert(out.begin() + static_cast<std::ptrdiff_t>(i), std::move(z));
  }
}

}  // namespace relpos::detail
