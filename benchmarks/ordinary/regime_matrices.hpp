// The pieces both regime generators share (benchmarks/ordinary/ordinary_bench.cpp and
// benchmarks/regime_bench.cpp, each with its own distribution): an ellipsoid's 4x4 matrix in doubles
// from its 3x3 block and centre, and a rotated block from a quaternion and semi-axes. Public headers
// only: ordinary_bench is built against the installed package.
#pragma once

#include <cmath>
#include <cstddef>
#include <relpos/quadric.hpp>

namespace regime {

/// m(i, j) = m(j, i) = v.
inline void set(relpos::DoubleMatrix4& m, int i, int j, double v) {
  m[static_cast<std::size_t>(4 * i + j)] = v;
  m[static_cast<std::size_t>(4 * j + i)] = v;
}

/// R diag(1/ax^2) R^T for the rotation R of the quaternion q (normalized here).
inline void rotated_block(const double q[4], const double ax[3], double m[3][3]) {
  const double nq = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double w = q[0] / nq, x = q[1] / nq, y = q[2] / nq, z = q[3] / nq;
  const double rot[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j <= i; ++j) {
      m[i][j] = 0;
      for (int k = 0; k < 3; ++k) m[i][j] += rot[i][k] * rot[j][k] / (ax[k] * ax[k]);
      m[j][i] = m[i][j];
    }
}

/// The ellipsoid (X - c)^T m (X - c) = 1 as a 4x4 matrix, every entry the double its formula rounds to.
inline void ellipsoid_matrix(const double m[3][3], const double c[3], relpos::DoubleMatrix4& e) {
  double e0 = -1;
  for (int i = 0; i < 3; ++i) {
    double mc = 0;
    for (int j = 0; j < 3; ++j) {
      set(e, i, j, m[i][j]);
      mc += m[i][j] * c[j];
    }
    set(e, i, 3, -mc);
    e0 += c[i] * mc;
  }
  e[15] = e0;
}

}  // namespace regime
