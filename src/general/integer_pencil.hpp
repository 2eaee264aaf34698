// The exact pencil of a pair on integers (math.md §17): each matrix replaced by its own primitive
// integer form (times the lcm of its denominators, divided by the gcd of the results), so that a
// pair whose two matrices were scaled very differently costs what the unscaled pair costs. With
// Qz = alpha Q and Ez = beta E (alpha, beta > 0),
//   det(Qz + s Ez) = alpha^4 f(s beta / alpha),   det(Bz + s Mz) = alpha^3 D(s beta / alpha),
// so the roots in s are those in t divided by the positive constant scale = beta / alpha: every sign,
// order and multiplicity is kept, and a multiplier s of the integer pencil is t = s * scale.
#pragma once

#include <array>

#include "general/pencil.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::general {

/// A 4x4 integer matrix, row-major, read as m(i, j) by the generic pencil code.
struct IntegerMatrix {
  std::array<Integer, 16> a;
  const Integer& operator()(int i, int j) const { return a[static_cast<std::size_t>(4 * i + j)]; }
};

/// The primitive integer form of m and the factor: form = factor * m, factor > 0 rational.
IntegerMatrix primitive_form(const Matrix4& m, Rational& factor);

struct IntegerPencil {
  IntegerMatrix e, q;  ///< Ez = beta E, Qz = alpha Q
  Rational scale;      ///< beta / alpha: t = s * scale
  Quartic<Integer> f;  ///< det(Qz + s Ez)
  Cubic<Integer> d;    ///< det(Bz + s Mz)
};

IntegerPencil integer_pencil(const Matrix4& e, const Matrix4& q);

}  // namespace relpos::detail::general
