// The certificate of each kind (include/relpos/position.hpp, math.md §8), each in its own file,
// read off the pair's one home (pair/pair.hpp); build.cpp dispatches on the position.
#pragma once

#include "pair/pair.hpp"
#include "relpos/position.hpp"

namespace relpos::detail::certificate {

/// E, I (definite.cpp): lambda with lambda P + E positive definite.
void definite(const detail::PairContext& pr, Position position, Certificate& c);
/// TE, TI (tangent.cpp): the rational double root lambda* of f and the contact point x(lambda*),
/// or the hard case's contact set.
void tangent(const detail::PairContext& pr, Position position, Certificate& c);
/// The hard case (hard_case.cpp, math.md §8): the contact set x^ + {w in ker(lambda_s A + M):
/// w^T M w = -e(x^)} over Q(sqrt d); false when the linear system is inconsistent (not the hard case).
bool hard_case(const detail::PairContext& pr, Certificate& c);
/// C (crossing.cpp): two points of the solid ellipsoid with p < 0 and p > 0.
void crossing_points(const detail::PairContext& pr, Certificate& c);

}  // namespace relpos::detail::certificate
