// Arithmetic on single words: the gcd of two words, which GMP's documented interface computes only
// through an mpz (mpz_gcd_ui).
#pragma once

#include <cstdint>

namespace relpos::detail {

/// gcd(u, v) of two words (gcd(0, v) = v), as std::gcd: the binary algorithm with the difference's
/// trailing zeros removed at once and the smaller and the difference chosen without branches (a
/// third of std::gcd's time on the closed forms' 57-bit rests, whose loop branches on every step).
inline std::uint64_t word_gcd(std::uint64_t u, std::uint64_t v) {
  if (u == 0) return v;
  if (v == 0) return u;
  const int shift = __builtin_ctzll(u | v);
  u >>= __builtin_ctzll(u);
  v >>= __builtin_ctzll(v);
  while (u != v) {  // both odd: their difference is even and non-zero
    const std::uint64_t d = u > v ? u - v : v - u;
    u = u < v ? u : v;
    v = d >> __builtin_ctzll(d);
  }
  return u << shift;
}

}  // namespace relpos::detail
