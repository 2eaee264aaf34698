// The certificates of TE and TI (math.md §8): the double root lambda* of f is rational, lambda* P + E
// is semidefinite and (x(lambda*), 1) spans its kernel, so x(lambda*) is a common point of the two
// surfaces; when no rational double root gives one, TI is the hard case (hard_case.cpp).
#include "certificate/curve.hpp"
#include "certificate/kinds.hpp"
#include "certificate/rational_search.hpp"

namespace relpos::detail::certificate {

void tangent(const detail::PairContext& pr, Position position, Certificate& c) {
  const anysize::Poly& f = pr.f_poly();
  const anysize::Poly g = anysize::monic_gcd(f, anysize::derivative(f));
  const anysize::Poly q = anysize::quotient(g, anysize::monic_gcd(g, anysize::derivative(g)));
  for (const Rational& l : rational_roots(q)) {
    const bool ok = position == Position::TE ? l > 0 : l < 0 && pr.lambda_s().compare(l) > 0;
    if (!ok) continue;
    const auto x = x_of(pr, l);
    if (!x || e_at(pr, *x) != 0 || p_at(pr, *x) != 0) continue;
    c.kind = Certificate::Kind::Tangent;
    c.lambda = l;
    c.contact = *x;
    return;
  }
  // The hard case's contact set exists whenever its linear system is consistent; only the
  // semidefiniteness at lambda_s makes it a tangency, which the verifier's check decides (rare).
  if (position == Position::TI && hard_case(pr, c) && !verify_certificate(pr.ellipsoid(), pr.paraboloid(), position, c))
    return;
  throw internal_error("no contact point for a pair classified " + to_string(position));
}

}  // namespace relpos::detail::certificate
