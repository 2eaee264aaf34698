// The limits of relpos::parse_rational (numbers.hpp; doc/cli.md, "Limits"): how long a number and
// how large its decimal exponent may be.
#pragma once

#include <cstddef>

namespace relpos::detail {

/// Limits enforced by the parser (a clear error instead of a hang on hostile input).
inline constexpr std::size_t kMaxNumberChars = 10000;  ///< characters in one number
inline constexpr long kMaxDecimalExponent = 4000;      ///< |e| in "1.5e-7"-style exponents

}  // namespace relpos::detail
