// The doubles a float code holds for a pair given by parameters: the parameters rounded to the
// nearest doubles, and the 4x4 matrices a float program computes from them in plain double
// arithmetic (doc/oracle.md, "The three truths": the formulas, in this order).
#pragma once

#include <array>

#include "oracle/families.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::oracle {

struct DoubleParameters {
  std::array<double, 3> centre, axes;
  std::array<double, 4> e_rotation;
  std::array<double, 3> vertex;
  double a, b;
  std::array<double, 4> p_rotation;
};

/// Every parameter rounded to the nearest double.
DoubleParameters nearest_parameters(const Parameters& p);

/// The exact values of the doubles (what relpos reads for them: nothing rounded again).
Parameters exact_parameters(const DoubleParameters& d);

/// What a float code computes, in double, rounding after every operation (no fused multiply-add):
///   R = R(q) / |q|^2 entry by entry, M = (R D) R^T with D = diag(1/axes^2) (two matrix products,
///   sums in index order: M need not be exactly symmetric), E = [[M, -M c], [-(M c)^T, c^T (M c) - 1]];
///   A = (R diag(1/a^2, 1/b^2, 0)) R^T, r = R's third column, u = -(A v) - r/2,
///   P = [[A, u], [u^T, v^T (A v) + r.v]].
DoubleMatrix4 ellipsoid_matrix(const DoubleParameters& d);
DoubleMatrix4 paraboloid_matrix(const DoubleParameters& d);

/// The matrix with its lower triangle replaced by its upper one (the opt-in reading of a nearly
/// symmetric matrix, doc/oracle.md).
DoubleMatrix4 upper_triangle(const DoubleMatrix4& m);

}  // namespace relpos::detail::oracle
