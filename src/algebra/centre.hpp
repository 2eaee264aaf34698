// The exact solution of a 3x3 system on integers and the centre of an ellipsoid's matrix: Cramer's
// rule (cramer.hpp) on integer determinants, one rational canonicalisation per coordinate.
#pragma once

#include <optional>

#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail {

/// The solution {n1 / d, n2 / d, n3 / d} of [K | r] (3x4, integers, the right-hand side in column
/// 3) by Cramer's rule; nullopt when K is singular.
std::optional<Vector3> solve_integer_system(const Integer (&k)[3][4]);

/// The centre -M^{-1} m of a quadric [[M, m], [m^T, m0]], solved on the matrix times the lcm of its
/// denominators (forms::integer_form); nullopt when M is singular.
std::optional<Vector3> centre_of(const Matrix4& q);

}  // namespace relpos::detail
