#include "algebra/forms.hpp"

#include <gmp.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "algebra/word_arithmetic.hpp"

namespace relpos::forms {
namespace {

using detail::word_gcd;

/// The power of two that brings mx into [1/2, 1) (1 for zero or a non-finite mx), as an interval.
Interval scale_below_one(double mx) {
  int e = 0;
  if (mx > 0 && std::isfinite(mx)) std::frexp(mx, &e);
  return Interval(std::ldexp(1.0, -e));
}

/// A finite non-zero double as m 2^k with m odd (|m| < 2^53), from its bits (subnormals: exponent
/// field 0, no hidden bit).
struct Dyadic {
  std::int64_t m;
  long k;
};
Dyadic dyadic_of(double x) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  const auto field = static_cast<long>((bits >> 52) & 0x7ff);
  const std::uint64_t frac = bits & ((std::uint64_t{1} << 52) - 1);
  auto m = static_cast<std::int64_t>(field == 0 ? frac : frac | (std::uint64_t{1} << 52));
  long k = (field == 0 ? 1 : field) - 1075;
  const int zeros = __builtin_ctzll(static_cast<unsigned long long>(m));  // m != 0
  m /= std::int64_t{1} << zeros;                                          // exact
  k += zeros;
  return {bits >> 63 ? -m : m, k};
}

}  // namespace

MatrixOf<Interval> to_intervals(const DoubleMatrix4& m) {
  double mx = 0;
  for (double x : m) mx = std::max(mx, std::fabs(x));
  const Interval scale = scale_below_one(mx);
  MatrixOf<Interval> out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = Interval(m[i]) * scale;
  return out;
}

MatrixOf<Interval> to_intervals(const detail::EnclosureMatrix4& m) {
  double mx = 0;
  for (std::size_t i = 0; i < 16; ++i) mx = std::max({mx, std::fabs(m.lo[i]), std::fabs(m.hi[i])});
  const Interval scale = scale_below_one(mx);
  MatrixOf<Interval> out;
  for (std::size_t i = 0; i < 16; ++i) out.a[i] = Interval(m.lo[i], m.hi[i]) * scale;
  return out;
}

void set_double(mpq_ptr out, double x) {
  const mpz_ptr num = mpq_numref(out), den = mpq_denref(out);
  mpz_set_ui(den, 1);
  if (x == 0) {
    mpz_set_ui(num, 0);
    return;
  }
  const Dyadic d = dyadic_of(x);
  mpz_set_si(num, static_cast<long>(d.m));
  if (d.k > 0) {
    mpz_mul_2exp(num, num, static_cast<mp_bitcnt_t>(d.k));
  } else if (d.k < 0) {
    mpz_set_ui(den, 0);
    mpz_setbit(den, static_cast<mp_bitcnt_t>(-d.k));
  }
}

namespace {

/// mpq_get_d(x) given den(x) = 2^k (k >= 0) or k = -1: mpz_get_d truncates the numerator towards
/// zero, and the power of two is exact while the result stays normal.
double truncated_double(mpq_srcptr x, long k) {
  if (k >= 0 && k <= 1000) {
    const double t = std::ldexp(mpz_get_d(mpq_numref(x)), -static_cast<int>(k));
    if (std::fabs(t) >= DBL_MIN && std::fabs(t) <= DBL_MAX) return t;
  }
  return mpq_get_d(x);
}

}  // namespace

double truncated_double(const Rational& q) {
  return truncated_double(q.mpq(), power_of_two_exponent(mpq_denref(q.mpq())));
}

std::pair<double, double> tight_interval(const Rational& q) {
  const mpq_srcptr x = q.mpq();
  const mpz_srcptr num = mpq_numref(x);
  const long den_twos = power_of_two_exponent(mpq_denref(x));
  const double t = truncated_double(x, den_twos);
  if (!(std::fabs(t) >= DBL_MIN && std::fabs(t) < DBL_MAX)) return CGAL::to_interval(q);  // 0, subnormal, huge
  // A double itself: a power-of-two denominator and at most 53 significant bits.
  if (den_twos >= 0 && mpz_sizeinbase(num, 2) - mpz_scan1(num, 0) <= 53) return {t, t};
  const double away = std::nextafter(t, t < 0 ? -HUGE_VAL : HUGE_VAL);
  return t < 0 ? std::make_pair(away, t) : std::make_pair(t, away);
}

MatrixOf<Interval> to_intervals(const Matrix4& m) {
  std::array<double, 16> v;
  double mx = 0;
  for (std::size_t i = 0; i < 16; ++i) {
    v[i] = mpq_get_d(m.a[i].mpq());
    mx = std::max(mx, std::fabs(v[i]));
  }
  const Interval scale = scale_below_one(mx);
  MatrixOf<Interval> out;
  for (std::size_t i = 0; i < 16; ++i) {
    const double x = v[i];
    const mpq_srcptr q = m.a[i].mpq();
    if (mpq_sgn(q) == 0) {
      out.a[i] = Interval(0);
      continue;
    }
    const mp_bitcnt_t den_bits = mpz_sizeinbase(mpq_denref(q), 2);
    if (mpz_sizeinbase(mpq_numref(q), 2) <= 53 && mpz_scan1(mpq_denref(q), 0) == den_bits - 1 &&
        std::fabs(x) >= DBL_MIN) {  // a double (53-bit numerator over a power of two): exact
      out.a[i] = Interval(x) * scale;
    } else if (std::fabs(x) >= DBL_MIN && std::isfinite(x)) {
      const double next = std::nextafter(x, x > 0 ? HUGE_VAL : -HUGE_VAL);  // away from zero
      out.a[i] = Interval(std::min(x, next), std::max(x, next)) * scale;
    } else if (std::isfinite(x)) {  // |q| below DBL_MIN
      out.a[i] = Interval(x - DBL_TRUE_MIN, x + DBL_TRUE_MIN) * scale;
    } else {  // beyond the double range: no information
      out.a[i] = Interval::largest();
    }
  }
  return out;
}

namespace {

/// The scratch integers of to_compact_integers, one set per thread: they keep their limbs between
/// calls, so a warm thread converts a pair without malloc (a fresh mpz_t allocates on first write).
struct CompactScratch {
  mpz_t t[3], g, den, l, content, dens[16];
  CompactScratch() {
    for (auto& x : t) mpz_init(x);
    for (auto& x : dens) mpz_init(x);
    for (mpz_ptr x : {g, den, l, content}) mpz_init(x);
  }
  ~CompactScratch() {
    for (auto& x : t) mpz_clear(x);
    for (auto& x : dens) mpz_clear(x);
    for (mpz_ptr x : {g, den, l, content}) mpz_clear(x);
  }
  CompactScratch(const CompactScratch&) = delete;
  CompactScratch& operator=(const CompactScratch&) = delete;
};

}  // namespace

void to_compact_integers(const Matrix4& p, const Matrix4& e, const std::array<mpz_ptr, 16>& pz,
                         const std::array<mpz_ptr, 16>& ez) {
  // On mpz_t throughout, written into the caller's integers: the entries of D M D in lowest terms
  // without rational or Integer temporaries (their allocations were most of the cost on long
  // near-tangent inputs).
  thread_local CompactScratch scratch;
  auto& t = scratch.t;
  auto &g = scratch.g, &den = scratch.den, &l = scratch.l, &content = scratch.content;
  auto& dens = scratch.dens;
  mpz_set_ui(t[0], 1);
  mpz_set_ui(t[1], 1);
  for (const auto* m : {&p, &e})
    for (int i = 0; i < 3; ++i) fold_lcm(t[1], mpq_denref((*m)(i, 3).mpq()));
  mpz_mul(t[2], t[1], t[1]);
  auto form = [&](const Matrix4& m, const std::array<mpz_ptr, 16>& out) {
    // x t^k = (n t^k / g) / (d / g) with g = gcd(d, t^k): lowest terms (each prime divides only one
    // of d / g and t^k / g). The numerators go into `out`, the denominators' lcm into l.
    mpz_set_ui(l, 1);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const std::size_t at = static_cast<std::size_t>(4 * i + j);
        const mpq_srcptr x = m.a[at].mpq();
        const int k = (i == 3) + (j == 3);
        const mpz_ptr n = out[at], d = dens[at];
        if (k == 0 || mpz_cmp_ui(t[1], 1) == 0) {
          mpz_set(n, mpq_numref(x));
          mpz_set(d, mpq_denref(x));
        } else if (mpz_cmp_ui(mpq_denref(x), 1) == 0) {
          mpz_mul(n, mpq_numref(x), t[k]);
          mpz_set_ui(d, 1);
        } else {
          mpz_gcd(g, mpq_denref(x), t[k]);
          mpz_divexact(d, mpq_denref(x), g);
          mpz_divexact(n, t[k], g);
          mpz_mul(n, n, mpq_numref(x));
        }
        fold_lcm(l, d);
      }
    mpz_set_ui(content, 0);
    for (std::size_t i = 0; i < 16; ++i) {
      if (mpz_cmp(l, dens[i]) != 0) {
        mpz_divexact(den, l, dens[i]);
        mpz_mul(out[i], out[i], den);
      }
      if (mpz_cmp_ui(content, 1) != 0) mpz_gcd(content, content, out[i]);  // 1 stays 1
    }
    // Divided by its content (a positive factor): the primitive form, whatever the scale of the
    // input matrix, so that the size limit on normalized forms bounds what the exact stages see.
    if (mpz_cmp_ui(content, 1) > 0)
      for (mpz_ptr x : out) mpz_divexact(x, x, content);
  };
  form(p, pz);
  form(e, ez);
}

namespace {

/// Divides x (non-zero) by its factors 5, at most `most` of them, and returns how many: 27 at a
/// time, by x mod 5^27 (< 2^63) in one single-limb pass; when that is not zero, its own valuation
/// is x's (r = x + k 5^27). No mpz temporaries, unlike mpz_remove.
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

}  // namespace

namespace {

/// rest^k for k = 0..4 and the rest as its one factor (a scale whose rest is not 1).
void with_rest_powers(SplitScale& out) {
  out.rest_power.reserve(5);
  out.rest_power.emplace_back(1);
  for (std::size_t k = 1; k < 5; ++k) out.rest_power.push_back(out.rest_power[k - 1] * out.rest);
  out.factors.push_back({out.rest, 1});
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
  // Factor refinement: two bases with a common factor c become b / c, b' / c and c, until they are
  // pairwise coprime. Every rest stays a product of bases; the product of the bases decreases.
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
  // gcd(num, rest^k) = g_1 ... g_j, g_i = gcd(num / (g_1 ... g_(i-1)), rest): each step takes
  // min(v_p(num), v_p(rest)) more of every prime p, so k steps take min(v_p(num), k v_p(rest)).
  // Scale after scale, the caps add up: min(v_p(num), sum_j k_j v_p(rest_j)) in all.
  // With rest = prod b_j^(e_j), the b_j pairwise coprime, the same holds base by base: k e_j gcds
  // with b_j take min(v_p(num), k v_p(rest)) of each prime p of b_j. A one-limb base costs a
  // single-limb remainder and a word gcd per step.
  mpz_t g, common;
  mpz_init(g);
  mpz_init(common);
  for (const ScalePower& d : divisors) {
    if (d.k == 0 || d.scale.factors.empty()) continue;
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
      continue;
    }
    mpz_divexact(g, d.scale.rest_power[d.k].mpz(), common);
    mpz_mul(den, den, g);
  }
  mpz_clear(g);
  mpz_clear(common);
}

Rational divided_by_powers(mpz_srcptr z, std::initializer_list<ScalePower> divisors) {
  Rational out;  // fresh: its mpq is not shared, so it is written in place
  divided_by_powers(z, divisors, out.mpq());
  return out;
}

MatrixOf<Integer> integer_form(const Matrix4& m, Integer& l) {
  MatrixOf<Integer> out;  // fresh entries: written through mpz()
  // Dyadic entries (exact doubles): the lcm is the largest power of two, the entries shifts.
  mp_bitcnt_t top = 0;
  bool dyadic = true;
  for (const Rational& q : m.a) {
    const mpz_srcptr d = mpq_denref(q.mpq());
    const mp_bitcnt_t k = mpz_scan1(d, 0);
    if (k + 1 != mpz_sizeinbase(d, 2)) {
      dyadic = false;
      break;
    }
    top = std::max(top, k);
  }
  Integer lcm(1);  // fresh: written through mpz()
  if (dyadic) {
    mpz_mul_2exp(lcm.mpz(), lcm.mpz(), top);
    for (std::size_t i = 0; i < 16; ++i)
      mpz_mul_2exp(out.a[i].mpz(), mpq_numref(m.a[i].mpq()), top - mpz_scan1(mpq_denref(m.a[i].mpq()), 0));
  } else {
    lcm_of_denominators(m.a.begin(), m.a.end(), lcm);
    // Most entries share their denominator with the previous one, or have the lcm itself.
    Integer q;  // fresh: written through mpz()
    mpz_srcptr last = nullptr;
    for (std::size_t i = 0; i < 16; ++i) {
      const mpz_srcptr d = mpq_denref(m.a[i].mpq());
      if (mpz_cmp(d, lcm.mpz()) == 0) {
        mpz_set(out.a[i].mpz(), mpq_numref(m.a[i].mpq()));
        continue;
      }
      if (!last || mpz_cmp(d, last) != 0) {
        mpz_divexact(q.mpz(), lcm.mpz(), d);
        last = d;
      }
      mpz_mul(out.a[i].mpz(), q.mpz(), mpq_numref(m.a[i].mpq()));
    }
  }
  l = lcm;
  return out;
}

void integer_form_of(const detail::QuadricMatrix& q, const IntegerFormOut& out) {
  if (const detail::ExactSource* source = q.exact_source(); source && source->integer_form(out)) return;
  const MatrixOf<Integer> form = integer_form(q.matrix(), out.l);
  for (std::size_t i = 0; i < 16; ++i) mpz_set(out.form[i], form.a[i].mpz());
  out.split = split_scale(out.l, q.matrix());
}

namespace {

/// d[i] = m_i 2^k_i with m_i odd (|m_i| < 2^53), or m_i = k_i = 0 for d[i] = 0: the lcm of the
/// denominators is 2^top with top = max(0, -k_i) (returned), and the integer entries are
/// m_i 2^(k_i + top).
long dyadic_entries(const DoubleMatrix4& d, std::int64_t (&m)[16], long (&k)[16]) {
  long top = 0;
  for (std::size_t i = 0; i < 16; ++i) {
    if (d[i] == 0) {
      m[i] = 0;
      k[i] = 0;
      continue;
    }
    const Dyadic x = dyadic_of(d[i]);
    m[i] = x.m;
    k[i] = x.k;
    top = std::max(top, -k[i]);
  }
  return top;
}

}  // namespace

bool small_integer_form(const DoubleMatrix4& d, MatrixOf<std::int64_t>& out, unsigned long& twos) {
  std::int64_t m[16];
  long k[16];
  const long top = dyadic_entries(d, m, k);
  for (std::size_t i = 0; i < 16; ++i) {
    if (m[i] == 0) {
      out.a[i] = 0;
      continue;
    }
    // |m_i| 2^shift < 2^62 iff bit_length(|m_i|) + shift <= 62 (|m_i| < 2^53: no overflow below).
    const long shift = k[i] + top;
    const auto magnitude = static_cast<std::uint64_t>(m[i] < 0 ? -m[i] : m[i]);
    if (64 - __builtin_clzll(magnitude) + shift > 62) return false;
    out.a[i] = m[i] * (std::int64_t{1} << shift);
  }
  twos = static_cast<unsigned long>(top);
  return true;
}

void integer_form(const DoubleMatrix4& d, const std::array<mpz_ptr, 16>& out, Integer& l) {
  std::int64_t m[16];
  long k[16];
  const long top = dyadic_entries(d, m, k);
  for (std::size_t i = 0; i < 16; ++i) {
    mpz_set_si(out[i], static_cast<long>(m[i]));
    if (m[i] != 0) mpz_mul_2exp(out[i], out[i], static_cast<mp_bitcnt_t>(k[i] + top));
  }
  Integer lcm(1);  // fresh: written through mpz()
  mpz_mul_2exp(lcm.mpz(), lcm.mpz(), static_cast<mp_bitcnt_t>(top));
  l = lcm;
}

MatrixOf<Integer> integer_form(const DoubleMatrix4& d, Integer& l) {
  MatrixOf<Integer> out;  // fresh entries: written through mpz()
  integer_form(d, entries(out), l);
  return out;
}

namespace {

/// The scratch integers of sphere_standard_evidence, one set per thread: warm limbs, no malloc.
struct ClosedScratch {
  static constexpr std::size_t kCount = 27;
  mpz_t t[kCount];
  ClosedScratch() {
    for (auto& x : t) mpz_init(x);
  }
  ~ClosedScratch() {
    for (auto& x : t) mpz_clear(x);
  }
  ClosedScratch(const ClosedScratch&) = delete;
  ClosedScratch& operator=(const ClosedScratch&) = delete;
};

/// A standard paraboloid's 1/a^2 = 2^p 5^q / R^2, R the part of a's mantissa prime to 10.
struct InverseSquare {
  std::uint64_t rest = 1;
  long p = 0, q = 0;
};
InverseSquare inverse_square_of(const Decimal& a) {
  InverseSquare out;
  std::uint64_t m = a.m;  // a > 0: m != 0
  const int twos = __builtin_ctzll(m);
  m >>= twos;
  long fives = 0;
  for (; m % 5 == 0; m /= 5) ++fives;
  out.rest = m;
  out.p = -2L * (a.e + twos);
  out.q = -2L * (a.e + fives);
  return out;
}

/// out = (-1)^neg m 10^(e - low) (e >= low).
void set_scaled(mpz_ptr out, const Decimal& x, int low) {
  mpz_set_ui(out, x.m);
  if (x.m == 0) return;
  const auto k = static_cast<unsigned long>(x.e - low);
  times_power_of_five(out, out, k);
  mpz_mul_2exp(out, out, k);
  if (x.neg) mpz_neg(out, out);
}

/// One term c 2^u 5^v of a sum (c may be zero).
struct Term {
  mpz_srcptr c;
  long u, v;
};

/// sum = sum of c 2^(u - u0) 5^(v - v0) over the terms, u0 and v0 the smallest exponents: the sum is
/// sum 2^u0 5^v0. `t` is scratch.
void sum_terms(std::initializer_list<Term> terms, mpz_ptr sum, long& u0, long& v0, mpz_ptr t) {
  u0 = v0 = 0;
  bool any = false;
  for (const Term& x : terms) {
    if (mpz_sgn(x.c) == 0) continue;
    u0 = any ? std::min(u0, x.u) : x.u;
    v0 = any ? std::min(v0, x.v) : x.v;
    any = true;
  }
  mpz_set_ui(sum, 0);
  for (const Term& x : terms) {
    if (mpz_sgn(x.c) == 0) continue;
    if (x.u == u0 && x.v == v0) {
      mpz_add(sum, sum, x.c);
      continue;
    }
    times_power_of_five(t, x.c, static_cast<unsigned long>(x.v - v0));
    mpz_mul_2exp(t, t, static_cast<unsigned long>(x.u - u0));
    mpz_add(sum, sum, t);
  }
}

/// The rests R_a and R_b of a and b, their squares and the product of the squares.
struct Rests {
  std::uint64_t a, b;
  mpz_srcptr a2, b2, both;
};

/// Where reduce_all writes S^k times a coefficient: S = 2^twos 5^fives rest, and
/// q[k] = S's rest^k / (R_a^2 R_b^2) for k = 3, 4 (q[0] = rest^4, for a coefficient without R).
struct Multiples {
  unsigned long twos, fives;
  mpz_srcptr q[5];
};

/// A coefficient n 2^e2 5^e5 / (R_a^ja R_b^jb) on its way to lowest terms (R_a, R_b prime to 10;
/// ja, jb in {0, 2}), written into `out` (a fresh mpq) by reduce_all.
struct Pending {
  mpz_ptr n;  // its own integer: overwritten
  long e2 = 0, e5 = 0;
  int ja = 2, jb = 2;
  mpq_ptr out = nullptr;
  mpz_ptr multiple = nullptr;  // S^k times the coefficient, or nullptr
  unsigned long k = 4;
};

/// The pending coefficients in lowest terms. Their factors 2 and 5 go into the exponents; the common
/// factor of n with R_a^ja R_b^jb is found by at most ja gcds with R_a, then jb with R_b, each
/// taking min(v_p(n), v_p(R)) more of every prime p (as in divided_by_powers: the caps add up
/// whether R_a and R_b share primes or not). Those gcds are taken only where one can be more than
/// 1: for each R, g = gcd(prod (n mod R), R) over the coefficients with R in their denominator is
/// one word gcd; gcd(n, R) divides g, so g = 1 clears every n, and else gcd(n, R) = gcd(n mod R, g),
/// a gcd with the short g, is the first step's factor (the residues are taken before any division by
/// a factor of R_a: a divisor of a number prime to R_b is prime to R_b). Each next step's factor
/// divides the previous one: gcd(n / c, R) = gcd(n / c, c) for c = gcd(n, R) (a prime of R dividing
/// n / c divides c with the power it has in R), and gcd(n', R) = gcd(n', c) for a divisor n' of n.
void reduce_all(Pending* p, std::size_t count, const Rests& r, const Multiples& m, mpz_ptr common) {
  constexpr std::size_t kMost = 8;
  std::uint64_t shared[kMost][2] = {};  // gcd(n, R_a), gcd(n, R_b) of the n before any division (0: 1)
  for (std::size_t i = 0; i < count; ++i) {
    if (mpz_sgn(p[i].n) == 0) continue;
    const mp_bitcnt_t twos = mpz_scan1(p[i].n, 0);
    mpz_tdiv_q_2exp(p[i].n, p[i].n, twos);
    p[i].e2 += static_cast<long>(twos);
    p[i].e5 += static_cast<long>(remove_fives(p[i].n, ~0UL));
  }
  for (int side = 0; side < 2; ++side) {
    const std::uint64_t base = side ? r.b : r.a;
    if (base == 1) continue;
    std::uint64_t residue[kMost] = {};
    __extension__ unsigned __int128 product = 1;  // residues below 2^64: no overflow
    auto takes = [&](const Pending& x) {
      return mpz_sgn(x.n) != 0 && mpz_cmpabs_ui(x.n, 1) != 0 && (side ? x.jb : x.ja) > 0;
    };
    for (std::size_t i = 0; i < count; ++i)
      if (takes(p[i])) {
        residue[i] = mpz_fdiv_ui(p[i].n, base);
        product = product * residue[i] % base;
      }
    const std::uint64_t g = word_gcd(static_cast<std::uint64_t>(product), base);  // gcd(0, R) = R
    if (g == 1) continue;
    for (std::size_t i = 0; i < count; ++i)
      if (takes(p[i])) shared[i][side] = word_gcd(residue[i] % g, g);
  }
  for (std::size_t i = 0; i < count; ++i) {
    const Pending& x = p[i];
    const mpz_ptr num = mpq_numref(x.out), den = mpq_denref(x.out);
    if (mpz_sgn(x.n) == 0) {
      mpq_set_ui(x.out, 0, 1);
      if (x.multiple) mpz_set_ui(x.multiple, 0);
      continue;
    }
    if (x.multiple) {
      // S^k n 2^e2 5^e5 / (R_a^ja R_b^jb), n prime to 10: an integer, so both exponents are >= 0.
      const long twos = static_cast<long>(x.k * m.twos) + x.e2, fives = static_cast<long>(x.k * m.fives) + x.e5;
      if (twos < 0 || fives < 0 || x.ja != x.jb)
        throw std::logic_error("relpos internal error: S^k times a closed-form coefficient is not an integer");
      const mpz_srcptr q = m.q[x.ja ? x.k : 0];
      // Sized once (5 < 2^3), not regrown by each product: a caller's integer is fresh.
      mpz_realloc2(x.multiple, mpz_sizeinbase(x.n, 2) + mpz_sizeinbase(q, 2) + 3 * static_cast<unsigned long>(fives) +
                                   static_cast<unsigned long>(twos) + 64);
      mpz_mul(x.multiple, x.n, q);
      times_power_of_five(x.multiple, x.multiple, static_cast<unsigned long>(fives));
      mpz_mul_2exp(x.multiple, x.multiple, static_cast<unsigned long>(twos));
    }
    mpz_set_ui(common, 1);
    for (int side = 0; side < 2; ++side) {
      std::uint64_t c = shared[i][side];  // gcd(n, R) of the undivided n
      if (c <= 1) continue;
      for (int step = 0; step < (side ? x.jb : x.ja); ++step) {
        if (step > 0 || mpz_cmp_ui(common, 1) != 0) c = mpz_gcd_ui(nullptr, x.n, c);
        if (c == 1) break;
        mpz_divexact_ui(x.n, x.n, c);
        mpz_mul_ui(common, common, c);
      }
    }
    const mpz_srcptr rest = x.ja && x.jb ? r.both : x.ja ? r.a2 : x.jb ? r.b2 : nullptr;
    const auto n5 = static_cast<unsigned long>(std::max(0L, x.e5)), n2 = static_cast<unsigned long>(std::max(0L, x.e2)),
               d5 = static_cast<unsigned long>(std::max(0L, -x.e5)),
               d2 = static_cast<unsigned long>(std::max(0L, -x.e2));
    // Each part sized once (5 < 2^3): the caller's rational is fresh.
    mpz_realloc2(num, mpz_sizeinbase(x.n, 2) + 3 * n5 + n2 + 64);
    mpz_realloc2(den, (rest ? mpz_sizeinbase(rest, 2) : 0) + 3 * d5 + d2 + 64);
    times_power_of_five(num, x.n, n5);
    mpz_mul_2exp(num, num, n2);
    set_power_of_five(den, d5);
    mpz_mul_2exp(den, den, d2);
    if (!rest) continue;
    if (mpz_cmp_ui(common, 1) != 0) {
      mpz_divexact(common, rest, common);
      mpz_mul(den, den, common);
    } else {
      mpz_mul(den, den, rest);
    }
  }
}

}  // namespace

void sphere_standard_evidence(const DecimalShape& sphere, const DecimalShape& paraboloid, const ClosedEvidence& out) {
  thread_local ClosedScratch scratch;
  auto& t = scratch.t;
  const Decimal &x = sphere.n[0], &y = sphere.n[1], &z = sphere.n[2], &r = sphere.n[3];
  const Decimal& vz = paraboloid.n[2];
  // The sphere's numbers and vz as integers over 10^low: X = x 10^-low, ...
  int low = 0;
  for (const Decimal* d : {&x, &y, &z, &r, &vz})
    if (d->m != 0) low = std::min(low, d->e);
  const mpz_ptr X2 = t[0], Y2 = t[1], R2 = t[2], W = t[3], P1 = t[4], P2 = t[5], Q0 = t[6], sum = t[7], tmp = t[8],
                common = t[9], a2 = t[10], b2 = t[11], both = t[12], ra_w = t[13], rb_w = t[14];
  set_scaled(X2, x, low);
  mpz_mul(X2, X2, X2);
  set_scaled(Y2, y, low);
  mpz_mul(Y2, Y2, Y2);
  set_scaled(R2, r, low);
  mpz_mul(R2, R2, R2);
  set_scaled(W, vz, low);  // w = vz - z = W 10^low
  set_scaled(tmp, z, low);
  mpz_sub(W, W, tmp);
  mpz_sub(P1, X2, R2);  // (x^2 - r^2) 10^(-2 low)
  mpz_sub(P2, Y2, R2);  // (y^2 - r^2) 10^(-2 low)
  mpz_add(Q0, P1, Y2);  // (x^2 + y^2 - r^2) 10^(-2 low)
  // A = 2^pa 5^qa / R_a^2, B = 2^pb 5^qb / R_b^2.
  const InverseSquare A = inverse_square_of(paraboloid.n[0]), B = inverse_square_of(paraboloid.n[1]);
  mpz_set_ui(a2, A.rest);
  mpz_mul(a2, a2, a2);
  mpz_set_ui(b2, B.rest);
  mpz_mul(b2, b2, b2);
  mpz_mul(both, a2, b2);
  const Rests rests{A.rest, B.rest, a2, b2, both};
  const long l1 = low, l2 = 2L * low, pab = A.p + B.p, qab = A.q + B.q;
  // The coefficients' numerators over 2^u 5^v R_a^2 R_b^2 (f1 to f4, s1, s2; A = 2^pa 5^qa R_b^2 /
  // (R_a^2 R_b^2), and so on) or 2^u 5^v (f0 = -r^2), each into its own integer.
  Pending pending[8];
  const mpz_ptr f0 = t[15], f1 = t[16], f2 = t[17], f3 = t[18], f4 = t[19], s1 = t[20], s2 = t[21], rho = t[22];
  auto coefficient = [&](std::size_t k, mpz_ptr n, std::initializer_list<Term> terms, mpq_ptr to) {
    sum_terms(terms, n, pending[k].e2, pending[k].e5, tmp);
    pending[k].n = n;
    pending[k].out = to;
  };
  mpz_neg(f0, R2);
  pending[0] = {f0, l2, l2, 0, 0, out.f[0].mpq(), nullptr, 4};
  mpz_mul(ra_w, a2, P2);  // R_a^2 (y^2 - r^2)
  mpz_mul(rb_w, b2, P1);  // R_b^2 (x^2 - r^2)
  mpz_mul(sum, both, W);  // R_a^2 R_b^2 w
  coefficient(1, f1, {{rb_w, A.p + l2, A.q + l2}, {ra_w, B.p + l2, B.q + l2}, {sum, l1, l1}}, out.f[1].mpq());
  mpz_mul(ra_w, a2, W);  // R_a^2 w
  mpz_mul(rb_w, b2, W);  // R_b^2 w
  mpz_neg(sum, both);    // -R_a^2 R_b^2
  coefficient(2, f2, {{Q0, pab + l2, qab + l2}, {rb_w, A.p + l1, A.q + l1}, {ra_w, B.p + l1, B.q + l1}, {sum, -2, 0}},
              out.f[2].mpq());
  mpz_neg(ra_w, a2);
  mpz_neg(rb_w, b2);
  coefficient(3, f3, {{W, pab + l1, qab + l1}, {rb_w, A.p - 2, A.q}, {ra_w, B.p - 2, B.q}}, out.f[3].mpq());
  mpz_set_si(sum, -1);
  coefficient(4, f4, {{sum, pab - 2, qab}}, out.f[4].mpq());
  mpq_set_ui(out.s[0].mpq(), 1, 1);
  coefficient(5, s1, {{b2, A.p, A.q}, {a2, B.p, B.q}}, out.s[1].mpq());
  mpz_set_ui(sum, 1);
  coefficient(6, s2, {{sum, pab, qab}}, out.s[2].mpq());
  // lambda_s = -min(a, b)^2 = -1 / max(A, B): a <= b compared as integers over 10^min(ea, eb).
  const Decimal &a = paraboloid.n[0], &b = paraboloid.n[1];
  const int e0 = std::min(a.e, b.e);
  set_scaled(P1, a, e0);
  set_scaled(P2, b, e0);
  const bool a_smaller = mpz_cmp(P1, P2) <= 0;
  const InverseSquare& m = a_smaller ? A : B;
  // -R^2 2^-p 5^-q: R is prime to 10, so this is in lowest terms.
  const mpz_ptr ln = mpq_numref(out.lambda_s.mpq()), ld = mpq_denref(out.lambda_s.mpq());
  times_power_of_five(ln, a_smaller ? a2 : b2, static_cast<unsigned long>(std::max(0L, -m.q)));
  mpz_mul_2exp(ln, ln, static_cast<unsigned long>(std::max(0L, -m.p)));
  mpz_neg(ln, ln);
  set_power_of_five(ld, static_cast<unsigned long>(std::max(0L, m.q)));
  mpz_mul_2exp(ld, ld, static_cast<unsigned long>(std::max(0L, m.p)));
  // rho = (2 r / min(a, b)^2)^2: 2 r 2^p 5^q / R^2 reduced, then squared (coprime parts stay coprime).
  mpz_set_ui(rho, r.m);
  pending[7] = {rho, 1L + r.e + m.p, static_cast<long>(r.e) + m.q, a_smaller ? 2 : 0, a_smaller ? 0 : 2, out.rho.mpq()};
  // S^4 f and S^3 s: S's rest is lcm(R_a^2, R_b^2) = (R_a R_b / g)^2; q[k] = rest^(k-1) / g^2.
  const std::uint64_t g = word_gcd(A.rest, B.rest);
  const mpz_ptr rest = t[23], q3 = t[24], q4 = t[25], rest4 = t[26];
  mpz_set_ui(rest, A.rest / g);
  mpz_mul_ui(rest, rest, B.rest);
  mpz_mul(rest, rest, rest);
  mpz_mul(q3, rest, rest);  // rest^2
  mpz_mul(q4, q3, rest);    // rest^3
  mpz_mul(rest4, q4, rest);
  const mpz_ptr s0 = out.s_multiple[0].mpz();  // S^3 s0 = S^3
  times_power_of_five(s0, q4, 3 * out.s_fives);
  mpz_mul_2exp(s0, s0, 3 * out.s_twos);
  for (int i = 0; g > 1 && i < 2; ++i) {  // g divides R_a R_b / g, so g^2 divides rest
    mpz_divexact_ui(q3, q3, g);
    mpz_divexact_ui(q4, q4, g);
  }
  for (std::size_t k = 0; k < 5; ++k) pending[k].multiple = out.f_multiple[k].mpz();
  for (std::size_t k = 5; k < 7; ++k) {
    pending[k].multiple = out.s_multiple[k - 4].mpz();
    pending[k].k = 3;
  }
  const Multiples multiples{out.s_twos, out.s_fives, {rest4, nullptr, nullptr, q3, q4}};
  reduce_all(pending, 8, rests, multiples, common);
  mpz_mul(mpq_numref(out.rho.mpq()), mpq_numref(out.rho.mpq()), mpq_numref(out.rho.mpq()));
  mpz_mul(mpq_denref(out.rho.mpq()), mpq_denref(out.rho.mpq()), mpq_denref(out.rho.mpq()));
}

}  // namespace relpos::forms
