// The moving matrix of a rigid polynomial motion (math.md §7), shared by the motion module and its tests.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "relpos/motion.hpp"

namespace relpos {

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

/// E(t) = (N T^-1)^T E0 (N T^-1) as polynomials in t (the placed ellipsoid times N(t)^2 > 0).
TimeMatrix4 moving_ellipsoid_matrix(const Ellipsoid& e0, const RigidMotion& m);

namespace detail {

/// The pivot point of the motion for this ellipsoid.
Vector3 pivot_of(const Ellipsoid& e0, const RigidMotion& m);

/// The placed ellipsoid at a rational time t (the matrix T^-T E0 T^-1 itself, exactly).
Ellipsoid placed_ellipsoid(const Ellipsoid& e0, const RigidMotion& m, const Rational& t);

/// Checks t0 <= t1 and that q(t) does not vanish on [t0, t1] (the rotation would be undefined
/// there); throws InputError naming the problem.
void validate_motion(const RigidMotion& m, const Rational& t0, const Rational& t1);

/// "start", "discriminant", ... for the set bits, in that order.
std::vector<std::string> cause_names(unsigned causes);

}  // namespace detail

}  // namespace relpos
