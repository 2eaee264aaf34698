// The method motion.cpp uses at irrational instants (instant_position.hpp: definiteness of the
// pencil at the roots of f listed by the subresultants), exposed (privately) so tests can compare it
// with classify() at rational times.
#pragma once

#include <optional>

#include "relpos/motion.hpp"

namespace relpos {

/// For tests: the position at a rational time decided by the method used at irrational instants
/// (math.md §7), for any size, instead of classify(). nullopt when f(., t) is square-free
/// there (that method then takes the position of the neighbouring intervals).
std::optional<Position> position_by_subresultants(const Ellipsoid& e0, const RigidMotion& motion, const Paraboloid& p,
                                                  const Rational& t);

}  // namespace relpos
