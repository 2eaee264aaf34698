#include "algebra/centre.hpp"

#include "algebra/cramer.hpp"
#include "algebra/forms.hpp"

namespace relpos::detail {

std::optional<Vector3> solve_integer_system(const Integer (&k)[3][4]) {
  const std::array<Integer, 4> d = cramer(k);
  if (d[0] == 0) return std::nullopt;
  return Vector3{Rational(d[1], d[0]), Rational(d[2], d[0]), Rational(d[3], d[0])};
}

std::optional<Vector3> centre_of(const Matrix4& q) {
  Integer l;
  const forms::MatrixOf<Integer> z = forms::integer_form(q, l);
  Integer k[3][4];  // [M | -m] times l
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) k[i][j] = j == 3 ? -z(i, j) : z(i, j);
  return solve_integer_system(k);
}

}  // namespace relpos::detail
