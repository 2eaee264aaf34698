// The pieces the regime generators share (benchmarks/ordinary/ordinary_bench.cpp,
// benchmarks/regime_bench.cpp, benchmarks/lanes_bench.cpp and tests/test_many_pairs.cpp): an
// ellipsoid's 4x4 matrix in doubles from its 3x3 block and centre, a rotated block from a quaternion
// and semi-axes, and two distributions of pairs: the ordinary benchmark's (ordinary_pair) and pairs
// as a user's float code writes them (user_pair). Public headers only: ordinary_bench is built
// against the installed package.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
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

/// The paper's regime in doubles (ordinary_bench's pairs): the paraboloid z = x^2/a^2 + y^2/b^2 (a, b
/// in [0.5, 2]) and a sphere (half the pairs) or a randomly rotated ellipsoid with semi-axes in
/// [0.1, 0.45] min(a, b)^2, centred within 0.5 a, 0.5 b of the axis at -2.7 to 5.3 largest semi-axes
/// above the surface. Every entry is the double the formulas round to.
inline void ordinary_pair(std::mt19937_64& rng, relpos::DoubleMatrix4& e, relpos::DoubleMatrix4& p) {
  std::uniform_real_distribution<double> uab(0.5, 2), usize(0.1, 0.45), uxy(-0.5, 0.5), uh(-2.7, 5.3), u11(-1, 1),
      u01(0, 1);
  e.fill(0);
  p.fill(0);
  const double a = uab(rng), b = uab(rng), scale = std::min(a, b) * std::min(a, b);
  set(p, 0, 0, 1 / (a * a));
  set(p, 1, 1, 1 / (b * b));
  set(p, 2, 3, -0.5);
  const double x = uxy(rng) * a, y = uxy(rng) * b;
  const double size = usize(rng) * scale;  // the largest semi-axis
  const double c[3] = {x, y, x * x / (a * a) + y * y / (b * b) + uh(rng) * size};
  double m[3][3] = {};
  if (rng() % 2) {
    const double rad = size;
    for (int i = 0; i < 3; ++i) m[i][i] = 1 / (rad * rad);
  } else {
    double q[4];
    for (double& v : q) v = u11(rng);
    const double ax[3] = {size, size * (0.3 + 0.7 * u01(rng)), size * (0.3 + 0.7 * u01(rng))};
    rotated_block(q, ax, m);
  }
  ellipsoid_matrix(m, c, e);
}

/// A sphere and a standard paraboloid as a user's float code writes them: the paraboloid
/// (x - vx)^2/a^2 + (y - vy)^2/b^2 = z - vz with its vertex anywhere in [-2, 2]^3 and a, b in [0.5, 2],
/// the sphere |X - c| = r with r in [0.02, 0.3] min(a, b)^2, centred within 0.5 a, 0.5 b of the axis
/// at -2.4 to 5 radii above the surface (about I 49 %, C 35 %, E 16 %), each matrix unscaled (a
/// sphere's block the identity). Every entry is the double its formula rounds to. The translation
/// terms make f's coefficients differences of larger numbers than at the origin, so the static
/// filter settles fewer of these pairs (about 94 %; 99 % with the vertex within 1 of the origin).
inline void user_pair(std::mt19937_64& rng, relpos::DoubleMatrix4& e, relpos::DoubleMatrix4& p) {
  std::uniform_real_distribution<double> uv(-2, 2), uab(0.5, 2), ur(0.02, 0.3), uxy(-0.5, 0.5), uh(-2.4, 5);
  e.fill(0);
  p.fill(0);
  const double v[3] = {uv(rng), uv(rng), uv(rng)};
  const double a = uab(rng), b = uab(rng), ia = 1 / (a * a), ib = 1 / (b * b);
  set(p, 0, 0, ia);
  set(p, 1, 1, ib);
  set(p, 0, 3, -v[0] * ia);
  set(p, 1, 3, -v[1] * ib);
  set(p, 2, 3, -0.5);
  p[15] = v[0] * v[0] * ia + v[1] * v[1] * ib + v[2];
  const double r = ur(rng) * std::min(a, b) * std::min(a, b);
  const double x = uxy(rng) * a, y = uxy(rng) * b;  // relative to the vertex
  const double c[3] = {v[0] + x, v[1] + y, v[2] + x * x * ia + y * y * ib + uh(rng) * r};
  double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  ellipsoid_matrix(m, c, e);
  e[15] = c[0] * c[0] + c[1] * c[1] + c[2] * c[2] - r * r;  // the sphere's constant, as a user writes it
}

}  // namespace regime
