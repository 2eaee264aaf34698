// The pair's size limit (relpos::SizeLimit, quadric.hpp) on the storage of any two quadrics
// (defined in pair_size.cpp): the bits of a matrix's primitive integer form and one check, with one
// message, for the paraboloid's pair and a general pair (detail::io::check_general_pair_size).
#pragma once

#include <cstddef>

#include "relpos/internal/quadric_matrix.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail {

/// Bits of the largest entry of the primitive integer form of m (0 for the zero matrix).
std::size_t normalized_bits(const Matrix4& m);

/// max(normalized_bits(e), normalized_bits(p)): independent of how either matrix was scaled.
std::size_t normalized_pair_bits(const Ellipsoid& e, const Paraboloid& p);

/// InputError when limit.max_bits < kMaxNormalizedBits (the limit is raised, never lowered) or when a
/// primitive integer form has entries beyond limit.max_bits ("numbers too large: ...", naming the
/// limit); returns the bound (exact when it exceeds kMaxNormalizedBits; 0 for matrices known to be
/// within the limit without a computation: doubles, the fast reader's numbers).
std::size_t check_normalized_size(const QuadricMatrix& a, const QuadricMatrix& b, const SizeLimit& limit);
/// The same for one matrix (the other known to be within the limit: the same message for the pair).
std::size_t check_normalized_size(const QuadricMatrix& a, const SizeLimit& limit);
/// check_normalized_size on the pair's two matrices.
std::size_t check_normalized_pair_size(const Ellipsoid& e, const Paraboloid& p, const SizeLimit& limit = {});

}  // namespace relpos::detail
