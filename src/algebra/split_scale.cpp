#include "algebra/split_scale.hpp"

#include <gmp.h>

#include <algorithm>
#include <utility>

#include "algebra/power_of_five.hpp"

namespace relpos::detail::forms {
namespace {

/// rest^k for k = 0..4 and the rest as its one factor (a scale whose rest is not 1).
void with_rest_powers(SplitScale& out) {
  out.rest_power.reserve(5);
  out.rest_power.emplace_back(1);
  for (std::size_t k = 1; k < 5; ++k) out.rest_power.push_back(out.rest_power[k - 1] * out.rest);
  out.factors.push_back({out.rest, 1});
}

/// Factor refinement of the rests' bases: two bases with a common factor c become b / c, b' / c and
/// c, until they are pairwise coprime. Every rest stays a product of bases; the product of the bases
/// decreases. `g` is scratch.
std::vector<Integer> coprime_base(const std::vector<SplitScale::Factor>& rests, mpz_ptr g) {
  std::vector<Integer> base;
  base.reserve(rests.size() + 2);
  for (const SplitScale::Factor& x : rests) {
    base.emplace_back();
    mpz_set(base.back().mpz(), x.base.mpz());
  }
  for (bool split = true; split;) {
    split = false;
    for (std::size_t i = 0; i < base.size() && !split; ++i)
      for (std::size_t j = i + 1; j < base.size() && !split; ++j) {
        mpz_gcd(g, base[i].mpz(), base[j].mpz());
        if (mpz_cmp_ui(g, 1) == 0) continue;
        Integer bi, bj, c;  // fresh: written through mpz()
        mpz_divexact(bi.mpz(), base[i].mpz(), g);
        mpz_divexact(bj.mpz(), base[j].mpz(), g);
        mpz_set(c.mpz(), g);
        std::vector<Integer> next;
        for (std::size_t k = 0; k < base.size(); ++k)
          if (k != i && k != j) next.push_back(base[k]);
        for (const Integer* x : {&bi, &bj, &c}) {
          bool dup = mpz_cmp_ui(x->mpz(), 1) == 0;
          for (const Integer& y : next) dup = dup || mpz_cmp(x->mpz(), y.mpz()) == 0;
          if (!dup) next.push_back(*x);
        }
        base = std::move(next);
        split = true;
      }
  }
  return base;
}

/// The rest of `out` as a coprime base of the distinct rests of its denominators (each a root to the
/// power 1 or 2), with the lcm's powers; `out.factors` stays {rest} unless their product is the rest.
void factor_rests(const std::vector<SplitScale::Factor>& rests, SplitScale& out) {
  mpz_t r, g;
  mpz_init(g);
  // One rest, or two coprime ones (a standard paraboloid's mantissas): the rest is their product,
  // already a coprime base.
  if (rests.size() == 1 ||
      (rests.size() == 2 && (mpz_gcd(g, rests[0].base.mpz(), rests[1].base.mpz()), mpz_cmp_ui(g, 1) == 0))) {
    out.factors = rests;
    mpz_clear(g);
    return;
  }
  mpz_init(r);
  const std::vector<Integer> base = coprime_base(rests, g);
  // The exponent of each base in the lcm: the largest in any rest. The product must be the rest.
  std::vector<unsigned long> power(base.size(), 0);
  bool exact = true;
  for (const SplitScale::Factor& x : rests) {
    mpz_set(r, x.base.mpz());
    for (std::size_t j = 0; j < base.size(); ++j) {
      unsigned long e = 0;
      while (mpz_divisible_p(r, base[j].mpz())) mpz_divexact(r, r, base[j].mpz()), ++e;
      power[j] = std::max(power[j], e * x.power);
    }
    exact = exact && mpz_cmp_ui(r, 1) == 0;
  }
  mpz_set_ui(g, 1);
  for (std::size_t j = 0; j < base.size(); ++j) {
    mpz_pow_ui(r, base[j].mpz(), power[j]);
    mpz_mul(g, g, r);
  }
  if (exact && mpz_cmp(g, out.rest.mpz()) == 0) {
    out.factors.clear();
    out.factors.reserve(base.size());
    for (std::size_t j = 0; j < base.size(); ++j) out.factors.push_back({base[j], power[j]});
  }
  mpz_clear(r);
  mpz_clear(g);
}

}  // namespace

SplitScale split_scale(const Integer& scale) {
  SplitScale out;
  out.twos = mpz_scan1(scale.mpz(), 0);
  const mpz_ptr rest = out.rest.mpz();  // fresh: written in place
  mpz_tdiv_q_2exp(rest, scale.mpz(), out.twos);
  out.fives = remove_fives(rest, ~0UL);
  if (mpz_cmp_ui(rest, 1) == 0) return out;  // doubles and decimal text: nothing to divide by
  with_rest_powers(out);
  return out;
}

SplitScale split_scale(const Integer& scale, const Matrix4& m) {
  SplitScale out = split_scale(scale);
  if (out.factors.empty()) return out;
  // The distinct rests of the denominators (2s and 5s removed), each a root to the power 1 or 2.
  std::vector<SplitScale::Factor> rests;
  rests.reserve(4);  // a standard paraboloid has two or three
  mpz_t r;
  mpz_init(r);
  for (const Rational& q : m.a) {
    const mpz_srcptr d = mpq_denref(q.mpq());
    if (mpz_cmp_ui(d, 1) == 0) continue;
    mpz_tdiv_q_2exp(r, d, mpz_scan1(d, 0));
    remove_fives(r, ~0UL);
    if (mpz_cmp_ui(r, 1) == 0) continue;
    unsigned long power = 1;
    if (mpz_perfect_square_p(r)) {
      mpz_sqrt(r, r);
      power = 2;
    }
    bool seen = false;
    for (const SplitScale::Factor& x : rests) seen = seen || (x.power == power && mpz_cmp(x.base.mpz(), r) == 0);
    if (seen) continue;
    rests.emplace_back();
    mpz_set(rests.back().base.mpz(), r);  // a fresh Integer: written through mpz()
    rests.back().power = power;
  }
  mpz_clear(r);
  factor_rests(rests, out);
  return out;
}

SplitScale split_scale(unsigned long twos, unsigned long fives, const Integer& rest,
                       const std::vector<SplitScale::Factor>& rests) {
  SplitScale out;
  out.twos = twos;
  out.fives = fives;
  if (mpz_cmp_ui(rest.mpz(), 1) == 0) return out;
  mpz_set(out.rest.mpz(), rest.mpz());  // a fresh Integer: written through mpz()
  with_rest_powers(out);
  factor_rests(rests, out);
  return out;
}

}  // namespace relpos::detail::forms
