// The ellipsoid scaled about its centre (math.md §19). With centre c = -M^-1 m and level
// k = -e(c) > 0 the solid ellipsoid is {x : (x - c)^T M (x - c) <= k}; scaled by q > 0 about c it is
// {x : (x - c)^T M (x - c) <= q^2 k}. Its matrix differs from E in the corner entry only:
//   E_q = E0 - q^2 k e4 e4^T,   E0 = E + k e4 e4^T   (the "point ellipsoid" at c: det E0 = 0),
// so the family is one line in the space of matrices, and the solids are nested (q < q' gives a
// solid inside the other).
#pragma once

#include "algebra/matrix4.hpp"
#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail {

/// The ellipsoids E_q of one ellipsoid E, q >= 0.
struct ScaledFamily {
  Vector3 centre;  ///< c = -M^-1 m
  Rational k;      ///< -e(c) = -det E / det M > 0
  Matrix4 point;   ///< E0 = E + k e4 e4^T
  /// E_q: the matrix of E scaled by q about its centre (a real ellipsoid for q > 0; E_1 = E).
  Matrix4 at(const Rational& q) const { return at_square(q * q); }
  /// The same for q^2 = v > 0 given (q itself may be irrational: the family depends on q^2 only).
  Matrix4 at_square(const Rational& v) const;
};

/// The family of the matrix of a real ellipsoid (M positive definite, det E < 0).
ScaledFamily scaled_family(const Matrix4& e);

/// The largest `bits` margin() accepts (each bit costs the certificates about one bit of length).
inline constexpr int kMaxMarginBits = 1000;

/// The ellipsoid scaled by `factor` > 0 about its centre (InputError otherwise): the matrix with
/// the corner entry e0 + k (1 - factor^2), k = -e(centre) (math.md §19).
Ellipsoid scaled_about_centre(const Ellipsoid& e, const Rational& factor);

}  // namespace relpos::detail
