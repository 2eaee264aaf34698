// The certificates of E and I (math.md §8): a rational lambda in the domain (lambda > 0 for E,
// lambda in (lambda_s, 0) for I) with f(lambda) > 0 makes lambda P + E positive definite (lambda A + M
// is, and det = f(lambda) > 0). f keeps one sign between consecutive isolating intervals of its real
// roots, so one exact sign per gap finds it; else points converging to the roots of f' do (the
// positive maximum of f over the domain is attained at one).
#include <optional>
#include <vector>

#include "algebra/between.hpp"
#include "certificate/curve.hpp"
#include "certificate/kinds.hpp"
#include "certificate/rational_search.hpp"

namespace relpos::detail::certificate {
namespace {

/// A lambda in the domain with f(lambda) > 0 from the isolating intervals of f's real roots: f has
/// one sign between consecutive intervals, so one exact evaluation per gap decides. `below_domain`
/// (x at or below the domain's lower end) skips the gaps whose every point is outside.
template <class InDomain, class BelowDomain>
std::optional<Rational> lambda_between_roots(const detail::PairContext& pr, InDomain in_domain,
                                             BelowDomain below_domain) {
  const std::vector<RealRoot>& roots = pr.roots().real_roots;
  for (std::size_t i = 0; i + 1 < roots.size(); ++i) {
    const Rational& lo = roots[i].exact ? *roots[i].exact : roots[i].upper;
    const Rational& hi = roots[i + 1].exact ? *roots[i + 1].exact : roots[i + 1].lower;
    if (!(lo < hi) || below_domain(hi)) continue;
    const Rational l = detail::rational_inside(lo, hi, detail::Shortest::Bits);
    if (in_domain(l) && pr.f_sign(l) > 0) return l;
  }
  return std::nullopt;
}

/// lambda with f(lambda) > 0 in the domain, near a root of f' (the positive maximum of f over the
/// domain); its margin, like a crossing's, needs at most a multiple of the coefficient bits.
template <class InDomain>
std::optional<Rational> definite_lambda(const detail::PairContext& pr, InDomain in_domain) {
  return search_near_roots(
      anysize::derivative(pr.f_poly()), [&](const Rational& l) { return in_domain(l) && pr.f_sign(l) > 0; },
      1024 + 16 * pr.fz().bits());
}

}  // namespace

void definite(const detail::PairContext& pr, Position position, Certificate& c) {
  const bool ext = position == Position::E;
  auto positive = [](const Rational& x) { return x > 0; };
  auto not_positive = [](const Rational& x) { return CGAL::sign(x) <= 0; };
  auto in_gap = [&](const Rational& l) { return l < 0 && pr.lambda_s().compare(l) > 0; };
  auto not_above_lambda_s = [&](const Rational& x) { return pr.lambda_s().compare(x) <= 0; };
  std::optional<Rational> l =
      ext ? lambda_between_roots(pr, positive, not_positive) : lambda_between_roots(pr, in_gap, not_above_lambda_s);
  if (!l) l = ext ? definite_lambda(pr, positive) : definite_lambda(pr, in_gap);
  if (!l)
    throw internal_error("no multiplier lambda with lambda P + E definite for a pair classified " +
                         to_string(position));
  c.kind = Certificate::Kind::Definite;
  c.lambda = *l;
}

}  // namespace relpos::detail::certificate
