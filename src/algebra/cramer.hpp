// 3x3 determinants and Cramer's rule, written once for every number type the library uses
// (exact rationals and integers, doubles, intervals, error-bound magnitudes).
#pragma once

#include <array>

namespace relpos::detail {

/// The determinant of the 3x3 matrix read through a(i, j), 0 <= i, j < 3, expanded along the first
/// row. The order of the operations is fixed, so a floating-point type always gets the same value.
template <class T, class At>
T det3(const At& a) {
  return a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)) - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0)) +
         a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0));
}

/// Cramer's rule for [K | r] (3x4, the right-hand side in column 3): the determinant of K, then
/// those of K with column 0, 1 and 2 replaced by r. The solution is {n0 / d, n1 / d, n2 / d}.
template <class T>
std::array<T, 4> cramer(const T (&k)[3][4]) {
  auto det = [&](int c0, int c1, int c2) {
    const int c[3] = {c0, c1, c2};
    return det3<T>([&](int i, int j) -> const T& { return k[i][c[j]]; });
  };
  return {det(0, 1, 2), det(3, 1, 2), det(0, 3, 2), det(0, 1, 3)};
}

}  // namespace relpos::detail
