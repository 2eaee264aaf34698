// The refusals of a matrix of another type than the quadric asked for, in the words of the type's
// name (quadric_kind.cpp): one text for the exact path (from_matrix) and for the filtered type test
// of from_doubles (kind_filter.hpp), which names a refused matrix without classifying it exactly.
#pragma once

#include "relpos/quadric.hpp"

namespace relpos::detail {

/// InputError "not an ellipsoid: the matrix describes <a kind>" (swapped pairs named as such).
[[noreturn]] void refuse_as_ellipsoid(QuadricKind k);
/// InputError "not an elliptic paraboloid: the matrix describes <a kind>".
[[noreturn]] void refuse_as_paraboloid(QuadricKind k);

}  // namespace relpos::detail
