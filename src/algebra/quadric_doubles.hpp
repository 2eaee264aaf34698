// A quadric's matrix as doubles, exactly: the entries when each one is a double, and the power-of-two
// normalization that is the static filter's input range (defined in quadric_matrix.cpp and
// quadric_doubles.cpp).
#pragma once

#include <optional>

#include "relpos/quadric.hpp"

namespace relpos::detail {

/// The entries as doubles if each one is exactly representable, else nullopt.
std::optional<DoubleMatrix4> exact_doubles(const Matrix4& m);

/// m times the power of two that brings its largest entry into [1/2, 1) (exact), or nullopt if a
/// non-zero entry would become subnormal or m is zero or not finite: the input range of the static
/// filter (static_filter.hpp). A positive scaling changes no decision (math.md §1).
std::optional<DoubleMatrix4> power_of_two_normalized(const std::optional<DoubleMatrix4>& m);

}  // namespace relpos::detail
