// The method motion.cpp uses at irrational instants, exposed (privately) so tests can compare it
// with classify() at rational times. It stays in motion.cpp, next to the internals it runs on.
#pragma once

#include <optional>

#include "relpos/motion.hpp"

namespace relpos {

/// For tests: the position at a rational time decided by the method used at irrational instants
/// (subresultants of f and df/dl, math.md "Motion") instead of classify(). nullopt when f(., t) is
/// square-free there (that method then takes its root counts from a neighbouring interval).
std::optional<Position> position_by_subresultants(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p,
                                                  const Rational& t);

}  // namespace relpos
