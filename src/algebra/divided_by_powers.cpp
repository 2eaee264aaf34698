#include "algebra/divided_by_powers.hpp"

#include <algorithm>
#include <stdexcept>

#include "algebra/power_of_five.hpp"

namespace relpos::detail::forms {
namespace {

/// num / rest^k in lowest terms for d = scale^k, num already free of the scale's 2s and 5s: the
/// common factor taken from num and rest^k / common multiplied into den. `g` and `common` are scratch.
///
/// gcd(num, rest^k) = g_1 ... g_j, g_i = gcd(num / (g_1 ... g_(i-1)), rest): each step takes
/// min(v_p(num), v_p(rest)) more of every prime p, so k steps take min(v_p(num), k v_p(rest)).
/// Scale after scale, the caps add up: min(v_p(num), sum_j k_j v_p(rest_j)) in all.
/// With rest = prod b_j^(e_j), the b_j pairwise coprime, the same holds base by base: k e_j gcds
/// with b_j take min(v_p(num), k v_p(rest)) of each prime p of b_j. A one-limb base costs a
/// single-limb remainder and a word gcd per step.
void divide_by_rest_power(mpz_ptr num, mpz_ptr den, const ScalePower& d, mpz_ptr g, mpz_ptr common) {
  mpz_set_ui(common, 1);
  for (const SplitScale::Factor& f : d.scale.factors) {
    const unsigned long steps = d.k * f.power;
    if (mpz_fits_ulong_p(f.base.mpz())) {
      const unsigned long b = mpz_get_ui(f.base.mpz());
      for (unsigned long i = 0; i < steps; ++i) {
        const unsigned long c = mpz_gcd_ui(nullptr, num, b);
        if (c == 1) break;
        mpz_divexact_ui(num, num, c);
        mpz_mul_ui(common, common, c);
      }
      continue;
    }
    for (unsigned long i = 0; i < steps; ++i) {
      mpz_gcd(g, num, f.base.mpz());
      if (mpz_cmp_ui(g, 1) == 0) break;
      mpz_divexact(num, num, g);
      mpz_mul(common, common, g);
    }
  }
  if (mpz_cmp_ui(common, 1) == 0) {
    mpz_mul(den, den, d.scale.rest_power[d.k].mpz());
    return;
  }
  mpz_divexact(g, d.scale.rest_power[d.k].mpz(), common);
  mpz_mul(den, den, g);
}

}  // namespace

void divided_by_powers(mpz_srcptr z, std::initializer_list<ScalePower> divisors, mpq_ptr out) {
  mpz_ptr num = mpq_numref(out);
  mpz_ptr den = mpq_denref(out);
  if (mpz_sgn(z) == 0) {
    mpq_set_ui(out, 0, 1);
    return;
  }
  unsigned long twos = 0, fives = 0;
  bool factors = false;
  for (const ScalePower& d : divisors) {
    twos += d.scale.twos * d.k, fives += d.scale.fives * d.k;
    factors = factors || (d.k > 0 && !d.scale.factors.empty());
    // A split made without its factors (the closed-form evidence's) keeps its rest apart: dividing
    // by it here would drop the rest.
    if (d.k > 0 && d.scale.factors.empty() && mpz_cmp_ui(d.scale.rest.mpz(), 1) != 0)
      throw std::logic_error("divided_by_powers: a split scale without its factors");
  }
  const unsigned long shift = std::min<unsigned long>(mpz_scan1(z, 0), twos);
  mpz_tdiv_q_2exp(num, z, shift);
  if (fives == 0 && !factors) {  // powers of two only (doubles): the denominator is one bit
    mpz_set_ui(den, 0);
    mpz_setbit(den, twos - shift);
    return;
  }
  const unsigned long removed = remove_fives(num, fives);
  set_power_of_five(den, fives - removed);
  mpz_mul_2exp(den, den, twos - shift);
  mpz_t g, common;
  mpz_init(g);
  mpz_init(common);
  for (const ScalePower& d : divisors)
    if (d.k != 0 && !d.scale.factors.empty()) divide_by_rest_power(num, den, d, g, common);
  mpz_clear(g);
  mpz_clear(common);
}

Rational divided_by_powers(mpz_srcptr z, std::initializer_list<ScalePower> divisors) {
  Rational out;  // fresh: its mpq is not shared, so it is written in place
  divided_by_powers(z, divisors, out.mpq());
  return out;
}

}  // namespace relpos::detail::forms
