#include "relpos/polynomials.hpp"

namespace relpos {

Rational evaluate(const RationalPolynomial& p, const Rational& x) {
  Rational acc(0);
  for (std::size_t i = p.size(); i-- > 0;) acc = acc * x + p[i];
  return acc;
}

}  // namespace relpos
