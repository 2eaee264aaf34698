// The two polynomials of an ellipsoid E = [[M, m], [m^T, m0]] against any quadric
// Q = [[B, b], [b^T, b0]], in the t-form of math.md §15:
//   f(t) = det(Q + t E)   a quartic, leading coefficient det E < 0, f(0) = det Q;
//   D(t) = det(B + t M)   a cubic, leading coefficient det M > 0, D(0) = det B.
// Written once, generic over the number type (ring operations only), like src/algebra/pencil.hpp,
// whose quartic this reuses: f is characteristic_polynomial with E in the place of P and Q in the
// place of E.
#pragma once

#include <array>

#include "algebra/pencil.hpp"

namespace relpos::detail::general {

template <class NT>
using Cubic = std::array<NT, 4>;

/// f(t) = det(Q + t E) for 4x4 matrices read as m(i, j).
template <class NT, class M>
Quartic<NT> pencil_quartic(const M& e, const M& q) {
  return characteristic_polynomial<NT>(e, q);
}

/// D(t) = det(B + t M), B and M the leading 3x3 blocks of Q and E: expansion along the first row,
/// each 2x2 minor of rows 1 and 2 a quadratic in t.
template <class NT, class M>
Cubic<NT> pencil_cubic(const M& e, const M& q) {
  Cubic<NT> d{NT(0), NT(0), NT(0), NT(0)};
  for (int j = 0; j < 3; ++j) {
    const int c0 = j == 0 ? 1 : 0, c1 = j == 2 ? 1 : 2;
    const Quadratic<NT> m = detail::linear_minor2<NT>(q, e, 1, 2, c0, c1);
    const NT &x0 = q(0, j), &x1 = e(0, j);  // entry (0, j) = x0 + t x1
    const Cubic<NT> t{x0 * m[0], x0 * m[1] + x1 * m[0], x0 * m[2] + x1 * m[1], x1 * m[2]};
    for (int i = 0; i < 4; ++i) d[i] = (j == 1) ? d[i] - t[i] : d[i] + t[i];
  }
  return d;
}

}  // namespace relpos::detail::general
