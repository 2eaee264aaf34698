// Test oracles: independent checks of the library's answers, kept out of the library.
#pragma once

#include <array>
#include <cstddef>
#include <relpos/numbers.hpp>
#include <relpos/quadric.hpp>
#include <utility>
#include <vector>

namespace relpos::detail::oracle {

/// Independent tangency check (math.md §3): lambda0 a real root of f; true iff the kernel of
/// lambda0 P + E contains a real X != 0 with X^T E X = 0. lambda0 must be rational.
inline bool kernel_has_common_point(const Ellipsoid& e, const Paraboloid& p, const Rational& lambda0) {
  // Kernel of K = lambda0 P + E by exact Gaussian elimination over Q; then decide whether the
  // quadratic form X^T E X vanishes at a real non-zero X of the kernel (an indefinite or degenerate
  // restriction). Returns true iff such an X exists.
  Matrix4 k;
  for (std::size_t i = 0; i < 16; ++i) k.a[i] = lambda0 * p.matrix().a[i] + e.matrix().a[i];
  // Row reduce to find a basis of the null space.
  int row = 0;
  std::array<int, 4> pivot_col{-1, -1, -1, -1};
  std::array<bool, 4> is_pivot{false, false, false, false};
  for (int c = 0; c < 4 && row < 4; ++c) {
    int r = row;
    while (r < 4 && k(r, c) == 0) ++r;
    if (r == 4) continue;
    for (int j = 0; j < 4; ++j) std::swap(k(r, j), k(row, j));
    Rational inv = Rational(1) / k(row, c);
    for (int j = 0; j < 4; ++j) k(row, j) *= inv;
    for (int i = 0; i < 4; ++i) {
      if (i == row || k(i, c) == 0) continue;
      Rational factor = k(i, c);
      for (int j = 0; j < 4; ++j) k(i, j) -= factor * k(row, j);
    }
    pivot_col[static_cast<std::size_t>(row)] = c;
    is_pivot[static_cast<std::size_t>(c)] = true;
    ++row;
  }
  std::vector<std::array<Rational, 4>> basis;
  for (int free = 0; free < 4; ++free) {
    if (is_pivot[static_cast<std::size_t>(free)]) continue;
    std::array<Rational, 4> v{};
    v[static_cast<std::size_t>(free)] = Rational(1);
    for (int r = 0; r < row; ++r) v[static_cast<std::size_t>(pivot_col[static_cast<std::size_t>(r)])] = -k(r, free);
    basis.push_back(v);
  }
  if (basis.empty()) return false;
  // Gram matrix G of E restricted to the kernel; a real non-zero X with X^T E X = 0 exists iff G is
  // not definite.
  const std::size_t n = basis.size();
  std::vector<Rational> g(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      Rational acc(0);
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          acc += basis[i][static_cast<std::size_t>(a)] * e.matrix()(a, b) * basis[j][static_cast<std::size_t>(b)];
      g[i * n + j] = acc;
    }
  // Definite iff all leading principal minors alternate properly (Sylvester); n <= 3 in practice.
  auto minor = [&](std::size_t m) {
    if (m == 1) return g[0];
    if (m == 2) return g[0] * g[n + 1] - g[1] * g[n];
    return g[0] * (g[n + 1] * g[2 * n + 2] - g[n + 2] * g[2 * n + 1]) -
           g[1] * (g[n] * g[2 * n + 2] - g[n + 2] * g[2 * n]) + g[2] * (g[n] * g[2 * n + 1] - g[n + 1] * g[2 * n]);
  };
  if (n > 3) return true;  // E restricted to all of R^4 is indefinite (ellipsoid has real points)
  bool pos_def = true, neg_def = true;
  for (std::size_t m = 1; m <= n; ++m) {
    Rational d = minor(m);
    if (!(d > 0)) pos_def = false;
    if (!((m % 2 == 1) ? d < 0 : d > 0)) neg_def = false;
  }
  return !(pos_def || neg_def);
}

}  // namespace relpos::detail::oracle
