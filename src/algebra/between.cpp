#include "algebra/between.hpp"

#include <gmp.h>

#include <algorithm>
#include <stdexcept>

namespace relpos::detail {
namespace {

/// The power k of a power-of-two denominator 2^k, or -1.
long two_exponent(mpz_srcptr d) {
  const mp_bitcnt_t k = mpz_scan1(d, 0);
  return k + 1 == mpz_sizeinbase(d, 2) ? static_cast<long>(k) : -1;
}

__extension__ typedef __int128 Word;  // __extension__: a GCC/Clang builtin type under -Wpedantic

/// fewest_bits_dyadic below on 128-bit words, when the numerators are words, the shifts short and
/// |M| < 2^62 (ends that are doubles of close magnitude: the isolating intervals), into `out` (fresh);
/// false otherwise. The same steps: floor shifts are arithmetic shifts, M xor L has GMP's
/// two's-complement meaning (both of one sign there), mpz_scan1 is a count of trailing zeros.
bool fewest_bits_in_words(const Rational& lo, const Rational& hi, long kl, long kh, long k, Rational& out) {
  const mpz_srcptr nl = mpq_numref(lo.mpq()), nh = mpq_numref(hi.mpq());
  const long sl = k - kl, sh = k - 1 - kh;  // L = nl 2^sl, M = nl 2^(sl - 1) + nh 2^sh (sl >= 1)
  if (sl > 60 || sh > 60 || !mpz_fits_slong_p(nl) || !mpz_fits_slong_p(nh)) return false;
  const Word l0 = mpz_get_si(nl), h0 = mpz_get_si(nh), one = 1;
  const Word L = l0 * (one << sl), M = l0 * (one << (sl - 1)) + h0 * (one << sh);
  if (M >= (one << 62) || M <= -(one << 62)) return false;
  long bits = 0;
  if (!(M >= 0 && L < 0)) {
    const Word t = M ^ L;      // > 0: M > L, one sign
    if (t == 0) return false;  // equal ends (callers pass lo < hi): left to the general path
    const auto high = static_cast<unsigned long>(t >> 64), low = static_cast<unsigned long>(t);
    const long h = high != 0 ? 127 - __builtin_clzl(high) : 63 - __builtin_clzl(low);
    bits = std::max(0L, (k - h + 3) / 4 * 4);
  }
  Word num = M;
  if (bits > 2048 || bits >= k) {
    bits = k;
  } else {
    const long s = k - bits;
    num = s >= 127 ? (M < 0 ? -1 : 0) : (M >> s);
  }
  if (num == 0) return true;  // 0/1
  auto v = static_cast<long>(num);
  const unsigned long magnitude = v < 0 ? 0UL - static_cast<unsigned long>(v) : static_cast<unsigned long>(v);
  const long shift = std::min<long>(__builtin_ctzl(magnitude), bits);
  v >>= shift;  // exact
  mpz_set_si(mpq_numref(out.mpq()), v);
  mpz_set_ui(mpq_denref(out.mpq()), 0);
  mpz_setbit(mpq_denref(out.mpq()), static_cast<mp_bitcnt_t>(bits - shift));
  return true;
}

/// fewest_bits for dyadic ends (the usual case: ends of isolating intervals, which are doubles),
/// on shifts only. With mid = M / 2^K and lo = L / 2^K: floor(mid 2^b) = M >> (K - b) for b < K,
/// and mid itself from b = K on. The test scaled / 2^b < hi always holds (scaled / 2^b <= mid).
Rational fewest_bits_dyadic(const Rational& lo, const Rational& hi, long kl, long kh) {
  const long k = std::max(kl, kh) + 1;
  Rational out;  // fresh: written in place, then reduced by its common power of two
  if (fewest_bits_in_words(lo, hi, kl, kh, k, out)) return out;
  mpz_t m, l, t;  // M = mid 2^k, L = lo 2^k and a temporary
  mpz_init(m);
  mpz_init(l);
  mpz_init(t);
  mpz_mul_2exp(m, mpq_numref(lo.mpq()), static_cast<mp_bitcnt_t>(k - 1 - kl));
  mpz_mul_2exp(t, mpq_numref(hi.mpq()), static_cast<mp_bitcnt_t>(k - 1 - kh));
  mpz_add(m, m, t);
  mpz_mul_2exp(l, mpq_numref(lo.mpq()), static_cast<mp_bitcnt_t>(k - kl));
  mpz_ptr num = mpq_numref(out.mpq()), den = mpq_denref(out.mpq());
  // The fewest bits b (a multiple of 4) with lo < floor(mid 2^b) / 2^b, i.e. L < floor(M / 2^s) 2^s
  // for s = k - b. As M > L, that holds iff floor(M / 2^s) != floor(L / 2^s) (two's complement
  // shifts), iff s <= h, the highest bit where M and L differ (any s when their signs differ).
  long bits = 0;
  if (mpz_sgn(m) >= 0 && mpz_sgn(l) < 0) {
    bits = 0;
  } else {
    mpz_xor(t, m, l);  // M != L with equal signs: t > 0
    const long h = static_cast<long>(mpz_sizeinbase(t, 2)) - 1;
    bits = std::max(0L, (k - h + 3) / 4 * 4);
  }
  if (bits > 2048 || bits >= k) {  // mid
    mpz_set(num, m);
    bits = k;
  } else {
    mpz_fdiv_q_2exp(num, m, static_cast<mp_bitcnt_t>(k - bits));
  }
  mpz_clear(m);
  mpz_clear(l);
  mpz_clear(t);
  if (mpz_sgn(num) == 0) return out;  // 0/1
  const long shift = std::min<long>(static_cast<long>(mpz_scan1(num, 0)), bits);
  mpz_tdiv_q_2exp(num, num, static_cast<mp_bitcnt_t>(shift));
  mpz_set_ui(den, 1);
  mpz_mul_2exp(den, den, static_cast<mp_bitcnt_t>(bits - shift));
  return out;
}

/// The tests compare integers (cross-multiplied, denominators positive): no rational is
/// canonicalized until the answer.
Rational fewest_bits(const Rational& lo, const Rational& hi) {
  const long kl = two_exponent(mpq_denref(lo.mpq())), kh = two_exponent(mpq_denref(hi.mpq()));
  if (kl >= 0 && kh >= 0) return fewest_bits_dyadic(lo, hi, kl, kh);
  const Rational mid = (lo + hi) / 2;
  Integer scaled, a, b;
  for (unsigned bits = 0; bits <= 2048; bits += 4) {
    mpz_mul_2exp(a.mpz(), mpq_numref(mid.mpq()), bits);  // scaled = floor(mid 2^bits)
    mpz_fdiv_q(scaled.mpz(), a.mpz(), mpq_denref(mid.mpq()));
    mpz_mul_2exp(a.mpz(), mpq_numref(lo.mpq()), bits);  // lo < scaled / 2^bits
    mpz_mul(b.mpz(), scaled.mpz(), mpq_denref(lo.mpq()));
    if (mpz_cmp(a.mpz(), b.mpz()) >= 0) continue;
    mpz_mul(a.mpz(), scaled.mpz(), mpq_denref(hi.mpq()));  // scaled / 2^bits < hi
    mpz_mul_2exp(b.mpz(), mpq_numref(hi.mpq()), bits);
    if (mpz_cmp(a.mpz(), b.mpz()) >= 0) continue;
    Integer den(1);
    mpz_mul_2exp(den.mpz(), den.mpz(), bits);
    return Rational(scaled, den);
  }
  return mid;
}

Integer floor_of(const Rational& q) {
  Integer r;
  mpz_fdiv_q(r.mpz(), q.numerator().mpz(), q.denominator().mpz());
  return r;
}

Rational simplest(const Rational& x, const std::optional<Rational>& y) {
  if (x < 0 && (!y || *y > 0)) return Rational(0);
  if (y && *y <= 0) return -simplest(-*y, Rational(-x));
  const Integer n = floor_of(x);  // x >= 0 here
  const Rational next(n + 1);
  if (!y || next < *y) return next;
  // (x, y) lies in [n, n + 1]: recurse on the reciprocals of the fractional parts.
  const Rational lo = Rational(1) / (*y - Rational(n));
  std::optional<Rational> hi;
  if (x > Rational(n)) hi = Rational(1) / (x - Rational(n));
  return Rational(n) + Rational(1) / simplest(lo, hi);
}

}  // namespace

Rational rational_inside(const Rational& lo, const std::optional<Rational>& hi, Shortest shortest) {
  if (shortest == Shortest::Denominator) return simplest(lo, hi);
  if (!hi) throw std::logic_error("relpos internal error: the fewest-bits rational needs a bounded interval");
  return fewest_bits(lo, *hi);
}

}  // namespace relpos::detail
