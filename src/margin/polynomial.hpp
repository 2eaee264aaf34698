// The pencil of the scaled family and the margin polynomial (math.md §19): an integer polynomial in
// u = t^2 of which s*^2 is a root, s* the factor by which the ellipsoid scaled about its centre first
// touches the paraboloid.
#pragma once

#include <vector>

#include "margin/family.hpp"
#include "relpos/numbers.hpp"
#include "relpos/polynomials.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail {

/// The two polynomials of the family's point ellipsoid E0, on integers: with E0z = alpha E0 and
/// Pz = beta P (alpha, beta > 0, the lcms of the denominators) and m = alpha l / beta,
///   f(m) = det(m Pz + E0z) = alpha^4 f0(l),  s(m) = det(m Az + Mz) = alpha^3 s0(l),
/// where f0(l) = det(l P + E0) and s0(l) = det(l A + M). The pair scaled by q has
/// det(l P + E_q) = f0(l) - q^2 k s0(l) (math.md §19) = (f(m) - q^2 (alpha k) s(m)) / alpha^4.
struct PointPencil {
  Quartic<Integer> f;
  Quadratic<Integer> s;
  Integer alpha, beta;
  Rational k;  ///< the family's level: -e(centre)

  /// f(m) - v (alpha k) s(m): a positive multiple of det(l P + E_q) for q^2 = v, in m.
  Quartic<Rational> scaled(const Rational& v) const;
  /// l = beta m / alpha.
  Rational lambda_of(const Rational& m) const { return m * Rational(beta, alpha); }
};
PointPencil point_pencil(const ScaledFamily& family, const Matrix4& p);

/// The margin polynomial in u = t^2: Pi(u) = Disc_m(H) * Res_m(g*, H) (the second factor only when g
/// has degree >= 1), where g = gcd(f, s), g* its square-free part and H(m, u) a positive multiple of
/// f / g - u alpha k s / g (math.md §19): s*^2 is a root. Primitive, positive leading coefficient,
/// never zero; index = power of u.
std::vector<Integer> margin_polynomial(const PointPencil& pencil);

/// p(t^2) from p(u): the margin polynomial in t, of which s* is a root.
std::vector<Integer> in_square(const std::vector<Integer>& p);

}  // namespace relpos::detail
