// A quadric's matrix from the 10 coefficients of its implicit equation (defined in quadric.cpp): the
// one conversion behind every from_coefficients (Ellipsoid, Paraboloid, Quadric).
#pragma once

#include "relpos/quadric.hpp"

namespace relpos::detail {

/// Matrix from the 10 coefficients of the implicit equation (cross terms halved).
Matrix4 matrix_from_coefficients(const Coefficients10& c);

}  // namespace relpos::detail
