// The exact sign of a polynomial in t at a candidate instant (candidates.hpp, sign_at): interval
// filters first, then an exact zero test modulo the minimal polynomial, then filters of growing
// precision, which end because the value is not zero.
#include <CGAL/Interval_nt.h>
#include <gmp.h>
#include <mpfi.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "algebra/irreducible.hpp"
#include "motion/candidates.hpp"
#include "motion/moving_pencil.hpp"

namespace relpos::detail {
namespace {

std::vector<Integer> coefficients_of(const PolyZ& p) {
  std::vector<Integer> c;
  if (CGAL::is_zero(p)) return c;
  for (int i = 0; i <= p.degree(); ++i) c.push_back(p[i]);
  return c;
}

/// Refine an instant's interval to a width below 2^-bits times max(1, |bounds|).
void refine_to(AlgebraicReal& x, long bits) {
  if (x.is_rational()) return;
  Rational mag = CGAL::abs(x.lower()) > CGAL::abs(x.upper()) ? CGAL::abs(x.lower()) : CGAL::abs(x.upper());
  if (mag < 1) mag = Rational(1);
  Integer d;
  mpz_setbit(d.mpz(), static_cast<mp_bitcnt_t>(bits));
  x.refine(mag / Rational(d));
}

/// The sign of an integer polynomial over an interval in doubles with outward rounding, the
/// coefficients scaled by one power of two into double range (a positive factor): +1 / -1 when the
/// enclosure excludes 0, else 0.
int double_sign_on(const std::vector<Integer>& c, const Rational& lo, const Rational& hi) {
  long top = 0;
  for (const auto& x : c) top = std::max(top, static_cast<long>(mpz_sizeinbase(x.mpz(), 2)));
  using Interval = CGAL::Interval_nt<false>;
  CGAL::Protect_FPU_rounding<true> guard;
  auto coefficient = [&](const Integer& x) {
    if (x == 0) return Interval(0);
    // x = (d + e) 2^k with 0.5 <= |d| < 1 (truncated) and |e| < 2^-53: an exact enclosure.
    long k = 0;
    const double d = mpz_get_d_2exp(&k, x.mpz());
    const long shift = k - top;
    const double tiny = std::ldexp(1.0, -1000);
    if (shift < -1000) return Interval(-tiny, tiny);  // |x 2^-top| < 2^-1000
    const double u = std::ldexp(1.0, -53);
    return Interval(std::ldexp(d - u, static_cast<int>(shift)), std::ldexp(d + u, static_cast<int>(shift)));
  };
  const Interval x(CGAL::to_interval(lo).first, CGAL::to_interval(hi).second);
  Interval v = coefficient(c.back());
  for (std::size_t k = c.size() - 1; k-- > 0;) v = v * x + coefficient(c[k]);
  return v.inf() > 0 ? 1 : (v.sup() < 0 ? -1 : 0);
}

/// The same in MPFI at `prec` bits (outward rounding everywhere).
int mpfi_sign_on(const std::vector<Integer>& c, const Rational& lo, const Rational& hi, mpfr_prec_t prec) {
  mpfi_t x, v;
  mpfi_init2(x, prec);
  mpfi_init2(v, prec);
  mpfi_interv_q(x, lo.mpq(), hi.mpq());
  mpfi_set_z(v, c.back().mpz());
  for (std::size_t k = c.size() - 1; k-- > 0;) {
    mpfi_mul(v, v, x);
    mpfi_add_z(v, v, c[k].mpz());
  }
  const int sg = mpfi_is_strictly_pos(v) ? 1 : (mpfi_is_strictly_neg(v) ? -1 : 0);
  mpfi_clear(x);
  mpfi_clear(v);
  return sg;
}

/// The sign of a non-zero p(t*) (pc: p's coefficients, r: its non-zero remainder modulo the minimal
/// polynomial, of degree >= 1) by MPFI with doubling precision, CGAL's exact Sign_at_1 last.
int nonzero_sign(const AK& ak, const std::vector<Integer>& pc, const std::vector<Integer>& r, const Candidate& z,
                 AlgebraicReal& x) {
  for (long prec = 2048; prec <= (1L << 18); prec *= 2) {
    refine_to(x, prec / 2);
    if (const int sg = mpfi_sign_on(pc, x.lower(), x.upper(), prec)) return sg;
  }
  return static_cast<int>(ak.sign_at_1_object()(PolyZ(r.begin(), r.end()), z.t));
}

}  // namespace

/// 1. Filters: interval evaluation of p over t*'s isolating interval, in doubles (after refining
///    the interval to ~60 bits) and, for large polynomials, in MPFI at 256 and 1024 bits (interval
///    refined to match). A certified non-zero enclosure decides; most signs read are not zero.
/// 2. Exact zero test: p reduced modulo the minimal polynomial m of t* (pseudo-remainder; lc(m) > 0
///    keeps the sign); p(t*) = 0 iff the remainder is 0, since m is irreducible.
/// 3. A non-zero value is then signed by MPFI with doubling precision (this ends, the value not
///    being 0), with CGAL's exact Sign_at_1 as the last resort.
int sign_at(const AK& ak, const PolyZ& p, const Candidate& z) {
  if (CGAL::is_zero(p)) return 0;
  if (p.degree() == 0) return static_cast<int>(CGAL::sign(p[0]));
  if (z.exact) return static_cast<int>(p.sign_at(*z.exact));
  PolyZ q = p;
  make_primitive(&q, &q + 1);  // a positive factor: same sign, smaller numbers
  const std::vector<Integer> pc = coefficients_of(q);
  AlgebraicReal& x = instant_of(z);
  refine_to(x, 60);
  if (x.is_rational()) return static_cast<int>(q.sign_at(*x.exact()));
  if (const int sg = double_sign_on(pc, x.lower(), x.upper())) return sg;
  // Small polynomials: the exact zero test is cheap, do it first. Large ones (the pseudo-remainder
  // grows like lc(m)^(deg p)): try the multi-precision filters first.
  std::size_t bits = 0;
  for (const auto& c : pc) bits = std::max(bits, mpz_sizeinbase(c.mpz(), 2));
  const std::size_t lc_bits = mpz_sizeinbase(z.minimal_coefficients.back().mpz(), 2);
  const bool cheap_remainder = bits + pc.size() * lc_bits < 4096;
  if (!cheap_remainder)
    for (long prec : {256L, 1024L}) {
      refine_to(x, prec / 2);
      if (const int sg = mpfi_sign_on(pc, x.lower(), x.upper(), prec)) return sg;
    }
  std::vector<Integer> r = pseudo_remainder(pc, z.minimal_coefficients);
  while (!r.empty() && r.back() == 0) r.pop_back();
  if (r.empty()) return 0;
  if (r.size() == 1) return static_cast<int>(CGAL::sign(r[0]));
  return nonzero_sign(ak, pc, r, z, x);
}

}  // namespace relpos::detail
