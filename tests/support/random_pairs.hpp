// Random ellipsoid and paraboloid matrices whose entries are all doubles: family (a) of relpos_bench
// (doc/performance.md), also drawn by contact_bench and test_contact. One draw order, so a seed
// gives the same pairs everywhere. Also the axis paraboloid z = a x^2 + b y^2 of the benchmarks.
//
//   ellipsoid  E = [[M, -Mc], [-c^T M, c^T M c - k]], M = L L^T + 0.05 I, L in [-1, 1]^9,
//              c in [-2, 2]^3, k in [k_min, 2] (computed in doubles, then read exactly)
//   paraboloid alpha x^2 + beta y^2 + 2 u alpha x + 2 v beta y - z + w, alpha, beta in [0.3, 2],
//              u, v in [-1, 1], w in [-2, 2]
#pragma once

#include <random>
#include <relpos/numbers.hpp>
#include <relpos/quadric.hpp>

namespace rt {

/// The matrix of the paraboloid z = a x^2 + b y^2 (vertex at the origin, axis z), a, b > 0.
inline relpos::Matrix4 axis_paraboloid(const relpos::Rational& a, const relpos::Rational& b) {
  relpos::Matrix4 P;
  P(0, 0) = a;
  P(1, 1) = b;
  P(2, 3) = P(3, 2) = relpos::Rational(-1, 2);
  return P;
}

/// A random ellipsoid matrix (draws L, c, k in that order); the caller validates it.
inline relpos::Matrix4 random_double_ellipsoid_matrix(std::mt19937_64& rng, double k_min) {
  std::uniform_real_distribution<double> u11(-1, 1), uc(-2, 2), uk(k_min, 2);
  double L[3][3], M[3][3], c[3], Mc[3];
  for (auto& r : L)
    for (auto& x : r) x = u11(rng);
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      M[i][j] = 0;
      for (int k = 0; k < 3; ++k) M[i][j] += L[i][k] * L[j][k];
      if (i == j) M[i][j] += 0.05;
      M[j][i] = M[i][j];  // exact symmetry
    }
  for (double& x : c) x = uc(rng);
  const double k = uk(rng);
  double cMc = 0;
  for (int i = 0; i < 3; ++i) {
    Mc[i] = 0;
    for (int j = 0; j < 3; ++j) Mc[i] += M[i][j] * c[j];
    cMc += c[i] * Mc[i];
  }
  relpos::Matrix4 E;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) E(i, j) = relpos::Rational(M[i][j]);
    E(i, 3) = E(3, i) = relpos::Rational(-Mc[i]);
  }
  E(3, 3) = relpos::Rational(cMc - k);
  return E;
}

/// A random paraboloid matrix (draws alpha, beta, u, v, w in that order).
inline relpos::Matrix4 random_double_paraboloid_matrix(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u11(-1, 1), uc(-2, 2), uab(0.3, 2);
  const double alpha = uab(rng), beta = uab(rng), uu = u11(rng), vv = u11(rng), w = uc(rng);
  relpos::Matrix4 P;
  P(0, 0) = relpos::Rational(alpha);
  P(1, 1) = relpos::Rational(beta);
  P(0, 3) = P(3, 0) = relpos::Rational(uu * alpha);
  P(1, 3) = P(3, 1) = relpos::Rational(vv * beta);
  P(2, 3) = P(3, 2) = relpos::Rational(-0.5);
  P(3, 3) = relpos::Rational(w);
  return P;
}

}  // namespace rt
