// Exponent arithmetic on the bits of a double: std::ilogb and std::ldexp are out-of-line libm calls
// that cost as much as a whole filter on the hot paths that use these. Valid for normal numbers;
// callers check ranges.
#pragma once

#include <cstdint>
#include <cstring>

namespace relpos::detail {

/// floor(log2 |x|) for a normal, non-zero x.
inline int exponent_of(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return static_cast<int>((b >> 52) & 0x7ff) - 1023;
}

/// 2^k for -1022 <= k <= 1023.
inline double power_of_two(int k) {
  const std::uint64_t b = static_cast<std::uint64_t>(k + 1023) << 52;
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

}  // namespace relpos::detail
