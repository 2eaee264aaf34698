// The case generator's random numbers: SplitMix64 (Steele, Lea and Flood 2014), written out so that
// a seed gives the same cases on every platform and compiler (std::mt19937's distributions do not).
// Each case draws from its own stream, keyed on (seed, family, index): a case does not change when
// other families, other epsilons or a larger --n are asked for.
#pragma once

#include <cstdint>
#include <string_view>

#include "relpos/numbers.hpp"

namespace relpos::detail::oracle {

class Random {
 public:
  explicit Random(std::uint64_t state) : state_(state) {}
  /// The stream of case `index` of `family` under `seed`.
  Random(std::uint64_t seed, std::string_view family, std::uint64_t index) : state_(seed) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a of the family's name
    for (const char c : family) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    state_ = mix(mix(seed ^ h) ^ index);
  }

  std::uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ull;
    return mix(state_);
  }
  /// An integer in [lo, hi] (hi - lo < 2^32: the bias of the modulo is below 2^-32).
  long integer(long lo, long hi) { return lo + static_cast<long>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }
  /// A fraction p/q in [lo, hi] with q in [1, max_den] (lo, hi integers or fractions of small height).
  Rational fraction(const Rational& lo, const Rational& hi, long max_den) {
    const long q = integer(1, max_den);
    const Rational a = lo * q, b = hi * q;  // p in [ceil(a), floor(b)]
    const Integer pl = ceil_of(a), ph = floor_of(b);
    if (ph < pl) return lo;
    const long span = CGAL::to_double(ph - pl) > 4e9 ? 4000000000L : static_cast<long>(CGAL::to_double(ph - pl));
    return Rational(pl + Integer(integer(0, span)), Integer(q));
  }

 private:
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  static Integer floor_of(const Rational& x) {
    Integer f;
    mpz_fdiv_q(f.mpz(), mpq_numref(x.mpq()), mpq_denref(x.mpq()));
    return f;
  }
  static Integer ceil_of(const Rational& x) {
    Integer c;
    mpz_cdiv_q(c.mpz(), mpq_numref(x.mpq()), mpq_denref(x.mpq()));
    return c;
  }
  std::uint64_t state_;
};

}  // namespace relpos::detail::oracle
