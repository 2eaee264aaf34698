// The one matrix view the generic formulas read (m(i, j), row-major), over any number type, and the
// views of a matrix of doubles (converted, or read in place).
#pragma once

#include <array>
#include <cstddef>

#include "relpos/quadric.hpp"

namespace relpos::detail::forms {

/// Matrix view with entries converted to NT, for the generic pencil code (m(i, j), row-major).
template <class NT>
struct MatrixOf {
  std::array<NT, 16> a;
  const NT& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

/// The entries of a matrix of exact doubles in NT (exact conversions).
template <class NT>
MatrixOf<NT> converted(const DoubleMatrix4& m) {
  MatrixOf<NT> out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = NT(m[i]);
  return out;
}

/// A DoubleMatrix4 read in place (no copy): the static filter's hot path.
struct DoubleView {
  const DoubleMatrix4& a;
  const double& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

/// The 16 entries' integers (row-major) of a matrix of fresh Integers (their values not shared) or
/// PooledIntegers, for the functions that write a form in place.
template <class NT>
std::array<mpz_ptr, 16> entries(MatrixOf<NT>& m) {
  std::array<mpz_ptr, 16> out;
  for (std::size_t i = 0; i < 16; ++i) out[i] = m.a[i].mpz();
  return out;
}

}  // namespace relpos::detail::forms
