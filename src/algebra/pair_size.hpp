// The pair's size limit (relpos::SizeLimit, quadric.hpp): the bits of a matrix's primitive integer
// form and the check every entry point applies (defined in pair_size.cpp).
#pragma once

#include <cstddef>

#include "relpos/quadric.hpp"

namespace relpos::detail {

/// Bits of the largest entry of the primitive integer form of m (0 for the zero matrix).
std::size_t normalized_bits(const Matrix4& m);

/// max(normalized_bits(e), normalized_bits(p)): independent of how either matrix was scaled.
std::size_t normalized_pair_bits(const Ellipsoid& e, const Paraboloid& p);

/// Throws InputError ("numbers too large: ...", naming the limit) when normalized_pair_bits(e, p) >
/// limit.max_bits, and InputError when limit.max_bits < kMaxNormalizedBits (the limit is raised,
/// never lowered). Returns a bound on normalized_pair_bits(e, p) that is exact when it exceeds
/// kMaxNormalizedBits (0 for matrices known to be within it without a computation).
std::size_t check_normalized_pair_size(const Ellipsoid& e, const Paraboloid& p, const SizeLimit& limit = {});

}  // namespace relpos::detail
