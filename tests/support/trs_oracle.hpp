// An independent second method for general pairs (doc/testing.md): the minimum of a quadratic form
// over a solid ellipsoid computed as a trust-region subproblem in MPFR (Boost.Multiprecision), by the
// textbook route -- the ellipsoid mapped to the unit ball (Cholesky), the form's 3x3 block
// diagonalised (Jacobi rotations), the secular equation sum g_i^2 / (lambda_i + mu)^2 = 1 solved by
// bisection, the hard case taken when the secular function stays below 1 at -lambda_min. It shares
// no code and no formula with the classifier (no pencil determinant, no root of f or D, no S-lemma
// sign rule): it computes min q, max q over E and, for an ellipsoid Q, max e over Q as numbers,
// and the position follows from their signs.
#pragma once

#include <mpfr.h>

#include <array>
#include <boost/multiprecision/mpfr.hpp>
#include <optional>
#include <utility>

#include "relpos/general_position.hpp"

namespace relpos::testing {

using Big =
    boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<150>, boost::multiprecision::et_off>;

inline Big big(const Rational& q) {
  Big x;
  mpfr_set_q(x.backend().data(), q.mpq(), MPFR_RNDN);
  return x;
}

/// min of g = X^T G X over the solid ellipsoid {X^T K X <= 0} (K: 3x3 block positive definite, det K < 0).
inline Big minimum_over_ellipsoid(const Matrix4& k, const Matrix4& g) {
  using std::array;
  array<array<Big, 3>, 3> m, b;
  array<Big, 3> km, gb;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      m[i][j] = big(k(i, j));
      b[i][j] = big(g(i, j));
    }
    km[i] = big(k(i, 3));
    gb[i] = big(g(i, 3));
  }
  // Centre c = -M^-1 m by Gaussian elimination, level kappa = -k(c) > 0.
  array<array<Big, 4>, 3> aug;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) aug[i][j] = m[i][j];
    aug[i][3] = -km[i];
  }
  for (int c = 0; c < 3; ++c) {
    for (int r = c + 1; r < 3; ++r) {
      const Big f = aug[r][c] / aug[c][c];
      for (int j = c; j < 4; ++j) aug[r][j] -= f * aug[c][j];
    }
  }
  array<Big, 3> centre;
  for (int r = 2; r >= 0; --r) {
    Big s = aug[r][3];
    for (int j = r + 1; j < 3; ++j) s -= aug[r][j] * centre[j];
    centre[r] = s / aug[r][r];
  }
  auto form = [](const Matrix4& q, const array<Big, 3>& x) {
    const array<Big, 4> v{x[0], x[1], x[2], Big(1)};
    Big s = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) s += v[i] * big(q(i, j)) * v[j];
    return s;
  };
  const Big kappa = -form(k, centre);
  // Cholesky M = R R^T (R lower); the ellipsoid is {c + L u : |u| <= 1} with L = sqrt(kappa) R^-T.
  array<array<Big, 3>, 3> r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j <= i; ++j) {
      Big s = m[i][j];
      for (int p = 0; p < j; ++p) s -= r[i][p] * r[j][p];
      r[i][j] = i == j ? sqrt(s) : s / r[j][j];
    }
  // R^-T: solve R^T X = I (upper triangular).
  array<array<Big, 3>, 3> rit{};
  for (int col = 0; col < 3; ++col)
    for (int i = 2; i >= 0; --i) {
      Big s = i == col ? Big(1) : Big(0);
      for (int p = i + 1; p < 3; ++p) s -= r[p][i] * rit[p][col];
      rit[i][col] = s / r[i][i];
    }
  const Big root_kappa = sqrt(kappa);
  array<array<Big, 3>, 3> l;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) l[i][j] = root_kappa * rit[i][j];
  // h(u) = u^T A u + 2 a^T u + alpha with A = L^T B L, a = L^T (B c + b), alpha = g(c).
  array<array<Big, 3>, 3> a{};
  array<Big, 3> av{}, grad{};
  for (int i = 0; i < 3; ++i) {
    grad[i] = gb[i];
    for (int j = 0; j < 3; ++j) grad[i] += b[i][j] * centre[j];
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Big s = 0;
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) s += l[p][i] * b[p][q] * l[q][j];
      a[i][j] = s;
    }
    for (int p = 0; p < 3; ++p) av[i] += l[p][i] * grad[p];
  }
  const Big alpha = form(g, centre);
  // Jacobi eigen-decomposition A = V diag(lambda) V^T.
  array<array<Big, 3>, 3> v{};
  for (int i = 0; i < 3; ++i) v[i][i] = 1;
  for (int sweep = 0; sweep < 60; ++sweep) {
    Big off = 0, norm = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        norm += a[i][j] * a[i][j];
        if (i != j) off += a[i][j] * a[i][j];
      }
    if (off <= norm * Big("1e-280")) break;
    for (int p = 0; p < 3; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0) continue;
        const Big theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const Big t = (theta >= 0 ? Big(1) : Big(-1)) / (abs(theta) + sqrt(theta * theta + 1));
        const Big c = 1 / sqrt(t * t + 1), s = t * c;
        for (int kk = 0; kk < 3; ++kk) {  // A <- J^T A J
          const Big akp = a[kk][p], akq = a[kk][q];
          a[kk][p] = c * akp - s * akq;
          a[kk][q] = s * akp + c * akq;
        }
        for (int kk = 0; kk < 3; ++kk) {
          const Big apk = a[p][kk], aqk = a[q][kk];
          a[p][kk] = c * apk - s * aqk;
          a[q][kk] = s * apk + c * aqk;
        }
        for (int kk = 0; kk < 3; ++kk) {
          const Big vkp = v[kk][p], vkq = v[kk][q];
          v[kk][p] = c * vkp - s * vkq;
          v[kk][q] = s * vkp + c * vkq;
        }
      }
  }
  array<Big, 3> lambda, gv;
  for (int i = 0; i < 3; ++i) {
    lambda[i] = a[i][i];
    gv[i] = 0;
    for (int p = 0; p < 3; ++p) gv[i] += v[p][i] * av[p];
  }
  Big lmin = lambda[0];
  for (const Big& x : lambda) lmin = x < lmin ? x : lmin;
  Big scale = abs(alpha) + 1;
  for (int i = 0; i < 3; ++i) scale += abs(lambda[i]) + abs(gv[i]);
  const Big tiny = scale * Big("1e-120");
  // Interior minimum: A positive definite with its unconstrained minimiser inside the ball.
  if (lmin > tiny) {
    Big norm2 = 0, value = alpha;
    for (int i = 0; i < 3; ++i) {
      norm2 += gv[i] * gv[i] / (lambda[i] * lambda[i]);
      value -= gv[i] * gv[i] / lambda[i];
    }
    if (norm2 <= 1) return value;
  }
  // Boundary: psi(mu) = sum g_i^2 / (lambda_i + mu)^2 = 1 on mu > max(0, -lambda_min).
  const Big mu_lo = lmin < 0 ? Big(-lmin) : Big(0);
  auto psi = [&](const Big& mu) {
    Big s = 0;
    for (int i = 0; i < 3; ++i) s += gv[i] * gv[i] / ((lambda[i] + mu) * (lambda[i] + mu));
    return s;
  };
  auto value_at =
      [&](const Big& mu) {  // alpha - mu - sum g_i^2 / (lambda_i + mu), terms with lambda_i + mu = 0 dropped
        Big s = alpha - mu;
        for (int i = 0; i < 3; ++i)
          if (abs(lambda[i] + mu) > tiny) s -= gv[i] * gv[i] / (lambda[i] + mu);
        return s;
      };
  Big eps = tiny;
  if (psi(mu_lo + eps) <= 1) return value_at(mu_lo);  // the hard case
  Big lo = mu_lo + eps, hi = mu_lo + 1;
  while (psi(hi) > 1) hi = hi * 2 + 1;
  for (int it = 0; it < 520; ++it) {
    const Big mid = (lo + hi) / 2;
    (psi(mid) > 1 ? lo : hi) = mid;
  }
  return value_at((lo + hi) / 2);
}

inline Matrix4 negated_matrix(const Matrix4& m) {
  Matrix4 out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = -m.a[i];
  return out;
}

/// The position from the optima (math.md §16), each compared with 0 within `tolerance` relative to
/// the matrices' scale; nullopt when an optimum is within the tolerance but cannot be told apart
/// from 0 by the construction (the caller then relies on the construction alone).
struct OracleAnswer {
  QuadricPosition position;
  Big min_q, max_q, max_e;
};

inline int sign_within(const Big& x, const Big& tolerance) { return x > tolerance ? 1 : (x < -tolerance ? -1 : 0); }

/// The position of E against Q's solid by the trust-region optima; `ellipsoid` when Q is one.
/// Matrices sign-normalized as the library stores them, each scaled near 1 by the caller or not:
/// the tolerance is relative to the largest entry of each.
inline OracleAnswer oracle_position(const Matrix4& e, const Matrix4& q, bool ellipsoid) {
  auto largest = [](const Matrix4& m) {
    Big s = 0;
    for (const Rational& x : m.a) s = abs(big(x)) > s ? abs(big(x)) : s;
    return s;
  };
  const Big tol_q = largest(q) * Big("1e-90"), tol_e = largest(e) * Big("1e-90");
  OracleAnswer out{QuadricPosition::C, minimum_over_ellipsoid(e, q), -minimum_over_ellipsoid(e, negated_matrix(q)),
                   Big(1)};
  if (ellipsoid) out.max_e = -minimum_over_ellipsoid(q, negated_matrix(e));
  const int smin = sign_within(out.min_q, tol_q), smax = sign_within(out.max_q, tol_q);
  const int se = ellipsoid ? sign_within(out.max_e, tol_e) : 1;
  if (smin > 0)
    out.position = QuadricPosition::E;
  else if (smin == 0)
    out.position = QuadricPosition::TE;
  else if (smax < 0)
    out.position = QuadricPosition::I;
  else if (smax == 0)
    out.position = se == 0 ? QuadricPosition::EQ : QuadricPosition::TI;
  else if (se < 0)
    out.position = QuadricPosition::O;
  else if (se == 0)
    out.position = QuadricPosition::TO;
  return out;
}

}  // namespace relpos::testing
