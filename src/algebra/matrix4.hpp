// Two elementary operations on a quadric's 4x4 matrix that the decision, the certificates and both
// verifiers use: its negation (the solid {q <= 0} of -Q is {q >= 0}, doc/math.md §14) and the value
// of its form at an affine point.
#pragma once

#include <cstddef>

#include "relpos/quadric.hpp"

namespace relpos::detail {

/// -Q.
inline Matrix4 negated(const Matrix4& q) {
  Matrix4 r;
  for (std::size_t i = 0; i < 16; ++i) r.a[i] = -q.a[i];
  return r;
}

/// X^T Q X for X = (x, y, z, 1), exact: q33 + sum_i x_i (2 q_i3 + sum_j q_ij x_j).
inline Rational form_at(const Matrix4& q, const Vector3& x) {
  Rational v = q(3, 3);
  for (int i = 0; i < 3; ++i) {
    Rational row = 2 * q(i, 3);  // the linear term, twice, plus the quadratic row
    for (int j = 0; j < 3; ++j) row += q(i, j) * x[static_cast<std::size_t>(j)];
    v += x[static_cast<std::size_t>(i)] * row;
  }
  return v;
}

}  // namespace relpos::detail
