// The pair's size limit on the storage of any two quadrics (src/algebra/pair_size.cpp): one check,
// with one message, for the paraboloid's pair (check_normalized_pair_size, quadric.hpp) and a
// general pair (io::check_general_pair_size).
#pragma once

#include <cstddef>

#include "relpos/internal/quadric_matrix.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail {

/// check_normalized_pair_size on the two matrices' storage: InputError when limit.max_bits <
/// kMaxNormalizedBits or when a primitive integer form has entries beyond it; returns the bound
/// (0 for matrices known to be within the limit without a computation: doubles, the fast reader's
/// numbers).
std::size_t check_normalized_size(const QuadricMatrix& a, const QuadricMatrix& b, const SizeLimit& limit);
/// The same for one matrix (the other known to be within the limit: the same message for the pair).
std::size_t check_normalized_size(const QuadricMatrix& a, const SizeLimit& limit);

}  // namespace relpos::detail
