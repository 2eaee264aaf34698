// 2^k as an exact rational, for any integer k: the dyadic scales of the certificates' searches and
// of the margin's refinements.
#pragma once

#include "relpos/numbers.hpp"

namespace relpos::detail {

/// 2^k (k may be negative).
Rational power_of_two(long k);

}  // namespace relpos::detail
