// Rigid motions whose matrices are polynomial in time (math.md "Motion").
//
// The ellipsoid is given in a reference placement E0 (a validated Ellipsoid). At time t it is the
// image of E0 under the rigid map
//
//   x = R(t) (y - p) + p + c(t),
//
// with c(t) a vector of polynomials in t (rational coefficients), p a fixed pivot (the origin, the
// centre of E0, or any point), and R(t) = Q(q(t)) / N(t) the rotation of a polynomial quaternion
// q(t) = (w, x, y, z)(t), not necessarily unit: Q holds quadratic forms in q, N = |q|^2 (the same
// formula as rotation_from_quaternion). Without a quaternion R = I.
//
// "Body frame" input (an ellipsoid centred at the origin, placed by the motion) is pivot = origin;
// "world frame" input (the ellipsoid where it is at the reference time, turned about its own
// centre) is pivot = centre. The placement at t equals E0 exactly when c(t) = 0 and q(t) is a
// multiple of (1, 0, 0, 0).
//
// With T(t) the map above, T^-1 = [[R^T, p - R^T (p + c)], [0, 1]] and
//   N T^-1 = [[Q^T, N p - Q^T (p + c)], [0, N]]
// is polynomial in t, so E(t) = (N T^-1)^T E0 (N T^-1) = N^2 T^-T E0 T^-1 is a polynomial matrix: the
// placed ellipsoid times the positive factor N^2, which changes no sign and no root multiplicity
// relpos looks at (math.md section 1).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "relpos/quadric.hpp"

namespace relpos {

/// A polynomial in time t with exact rational coefficients, index = power of t (low degree first).
/// The empty vector is the zero polynomial.
using TimePolynomial = std::vector<Rational>;

/// p(t), exactly.
Rational evaluate(const TimePolynomial& p, const Rational& t);

/// Where the rotation R(t) is applied.
enum class Pivot {
  Origin,  ///< x = R(t) y + c(t)             (ellipsoid given in its body frame)
  Centre,  ///< about the centre of E0        (ellipsoid given where it is at the reference time)
  Point,   ///< about RigidMotion::pivot_point
};

struct RigidMotion {
  std::array<TimePolynomial, 3> translation;              ///< c(t); empty entries are 0
  std::optional<std::array<TimePolynomial, 4>> rotation;  ///< q(t) = (w, x, y, z); absent: R = I
  Pivot pivot = Pivot::Origin;
  Vector3 pivot_point{};  ///< used when pivot == Pivot::Point

  /// Pure translation by c(t).
  static RigidMotion translating(std::array<TimePolynomial, 3> c);
};

/// 4x4 matrix of polynomials in t, row-major.
using TimeMatrix4 = std::array<TimePolynomial, 16>;

/// Q(q) with R(q) = Q(q) / |q|^2, for any number type with ring operations (row-major 3x3).
template <class NT>
std::array<NT, 9> quaternion_matrix(const NT& w, const NT& x, const NT& y, const NT& z) {
  const NT two(2);
  return {w * w + x * x - y * y - z * z, two * (x * y - w * z),         two * (x * z + w * y),
          two * (x * y + w * z),         w * w - x * x + y * y - z * z, two * (y * z - w * x),
          two * (x * z - w * y),         two * (y * z + w * x),         w * w - x * x - y * y + z * z};
}

/// The centre -M^-1 e of an ellipsoid, exactly.
Vector3 centre_of(const Ellipsoid& e);

/// The pivot point of the motion for this ellipsoid.
Vector3 pivot_of(const Ellipsoid& e0, const RigidMotion& m);

/// E(t) = (N T^-1)^T E0 (N T^-1) as polynomials in t (the placed ellipsoid times N(t)^2 > 0).
TimeMatrix4 moving_ellipsoid_matrix(const Ellipsoid& e0, const RigidMotion& m);

/// The placed ellipsoid at a rational time t (the matrix T^-T E0 T^-1 itself, exactly).
Ellipsoid placed_ellipsoid(const Ellipsoid& e0, const RigidMotion& m, const Rational& t);

/// Checks t0 <= t1 and that q(t) does not vanish on [t0, t1] (the rotation would be undefined
/// there); throws InputError naming the problem.
void validate_motion(const RigidMotion& m, const Rational& t0, const Rational& t1);

}  // namespace relpos
