#include "certificate/curve.hpp"

#include "algebra/centre.hpp"

namespace relpos::detail::certificate {

Rational form(const Matrix4& q, const V3& x) {
  Rational acc = q(3, 3);
  for (int i = 0; i < 3; ++i) {
    acc += 2 * q(i, 3) * x[i];
    for (int j = 0; j < 3; ++j) acc += x[i] * q(i, j) * x[j];
  }
  return acc;
}

std::optional<V3> x_of(const PairContext& pr, const Rational& l) {
  const detail::IntegerForms& z = pr.integer_forms();
  const Integer pf = l.numerator() * z.le, ef = l.denominator() * z.lp;
  Integer k[3][4];  // [lambda A + M | -(lambda a + m)], scaled
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      k[i][j] = pf * z.pz(i, j) + ef * z.ez(i, j);
      if (j == 3) k[i][j] = -k[i][j];
    }
  return detail::solve_integer_system(k);
}

std::logic_error internal_error(const std::string& what) {
  return std::logic_error("relpos internal error: " + what + " (please report the input)");
}

}  // namespace relpos::detail::certificate
