#include "algebra/power_of_five.hpp"

#include <algorithm>
#include <cstdint>

namespace relpos::detail::forms {
namespace {

/// 5^0 .. 5^(filled - 1), filled on demand; entries never move (a fixed array).
struct FivePowers {
  static constexpr unsigned long kSize = 513;
  mpz_t p[kSize];
  unsigned long filled = 0;
  FivePowers(const FivePowers&) = delete;
  FivePowers& operator=(const FivePowers&) = delete;
  FivePowers() = default;
  ~FivePowers() {
    for (unsigned long i = 0; i < filled; ++i) mpz_clear(p[i]);
  }
  /// 5^k for k < kSize.
  mpz_srcptr at(unsigned long k) {
    for (; filled <= k; ++filled) {
      if (filled == 0) {
        mpz_init_set_ui(p[0], 1);
      } else {
        mpz_init(p[filled]);
        mpz_mul_ui(p[filled], p[filled - 1], 5);
      }
    }
    return p[k];
  }
};

mpz_srcptr cached_power_of_five(unsigned long k) {
  thread_local FivePowers powers;
  return k < FivePowers::kSize ? powers.at(k) : nullptr;
}

}  // namespace

void set_power_of_five(mpz_ptr out, unsigned long k) {
  if (const mpz_srcptr p = cached_power_of_five(k))
    mpz_set(out, p);
  else
    mpz_ui_pow_ui(out, 5, k);
}

void times_power_of_five(mpz_ptr out, mpz_srcptr x, unsigned long k) {
  if (k == 0) {
    mpz_set(out, x);
  } else if (const mpz_srcptr p = cached_power_of_five(k)) {
    mpz_mul(out, x, p);
  } else {
    mpz_t t;
    mpz_init(t);
    mpz_ui_pow_ui(t, 5, k);
    mpz_mul(out, x, t);
    mpz_clear(t);
  }
}

unsigned long remove_fives(mpz_ptr x, unsigned long most) {
  unsigned long removed = 0;
  while (removed < most) {
    const unsigned long chunk = std::min<unsigned long>(27, most - removed);
    std::uint64_t p = 1;
    for (unsigned long i = 0; i < chunk; ++i) p *= 5;
    std::uint64_t r = mpz_fdiv_ui(x, p);
    if (r == 0) {
      mpz_divexact_ui(x, x, p);
      removed += chunk;
      continue;
    }
    std::uint64_t q = 1;
    for (; r % 5 == 0; r /= 5) q *= 5, ++removed;
    if (q > 1) mpz_divexact_ui(x, x, q);
    break;
  }
  return removed;
}

}  // namespace relpos::detail::forms
