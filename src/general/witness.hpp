// Crossing witnesses (math.md §18): a rational point of one solid ellipsoid where a quadratic form is
// negative, built from the optimal multiplier of the pencil -- never by sampling.
#pragma once

#include "relpos/quadric.hpp"

namespace relpos::detail::general {

/// A rational point x with k(x) <= 0 and g(x) < 0, where K is a sign-normalized ellipsoid (3x3 block
/// positive definite, det K < 0) and the minimum of g = X^T G X over K's solid is negative (the
/// caller's exact decision says so). The minimiser is approached along the pencil G + s K (the
/// stationary points x(s), or at the end of the interval the kernel of the pencil's 3x3 block, the
/// hard case), in doubles and then in MPFR with doubling precision; each candidate is pulled towards
/// K's centre, rounded to rationals and checked exactly. Throws std::logic_error (internal error)
/// when no point is found within 8192 bits.
Vector3 negative_point(const Matrix4& k, const Matrix4& g);

}  // namespace relpos::detail::general
