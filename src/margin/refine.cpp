#include "margin/refine.hpp"

#include <mpfr.h>

#include <utility>

#include "algebra/polynomial_sign.hpp"
#include "algebra/power_of_two.hpp"

namespace relpos::detail {
namespace {

/// Whether r is narrow enough.
bool narrow(const RootInterval& r, const Rational& scale) { return r.hi - r.lo <= r.lo * scale; }

/// The exact value of an MPFR number (a dyadic rational).
Rational exact(const mpfr_t x) {
  Rational q;  // fresh: written through its mpq_t
  mpfr_get_q(q.mpq(), x);
  return q;
}

/// Newton's iteration for the root of f in r, at `prec` bits, from `start` when it lies in r, else from
/// the midpoint of r; false when an iterate leaves r or the steps do not settle (then the caller
/// bisects).
bool newton(const std::vector<Integer>& f, const RootInterval& r, mpfr_prec_t prec, const long double* start,
            mpfr_t x) {
  mpfr_t v, d, t, lo, hi;
  mpfr_inits2(prec, v, d, t, lo, hi, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_q(lo, r.lo.mpq(), MPFR_RNDD);
  mpfr_set_q(hi, r.hi.mpq(), MPFR_RNDU);
  if (start) mpfr_set_ld(x, *start, MPFR_RNDN);
  if (!start || mpfr_cmp(x, lo) <= 0 || mpfr_cmp(x, hi) >= 0) {
    mpfr_add(x, lo, hi, MPFR_RNDN);
    mpfr_div_2ui(x, x, 1, MPFR_RNDN);
  }
  bool ok = false;
  for (int step = 0; step < 64; ++step) {
    mpfr_set_z(v, f.back().mpz(), MPFR_RNDN);  // Horner: v = f(x), d = f'(x)
    mpfr_set_ui(d, 0, MPFR_RNDN);
    for (std::size_t k = f.size() - 1; k-- > 0;) {
      mpfr_mul(d, d, x, MPFR_RNDN);
      mpfr_add(d, d, v, MPFR_RNDN);
      mpfr_mul(v, v, x, MPFR_RNDN);
      mpfr_add_z(v, v, f[k].mpz(), MPFR_RNDN);
    }
    if (mpfr_zero_p(d)) break;
    mpfr_div(t, v, d, MPFR_RNDN);
    mpfr_sub(x, x, t, MPFR_RNDN);
    if (mpfr_cmp(x, lo) <= 0 || mpfr_cmp(x, hi) >= 0) break;
    // Settled when the step is below 2^-(prec - 8) x: quadratic convergence has used the precision.
    if (mpfr_zero_p(t) || mpfr_get_exp(t) < mpfr_get_exp(x) - static_cast<mpfr_exp_t>(prec) + 8) {
      ok = true;
      break;
    }
  }
  mpfr_clears(v, d, t, lo, hi, static_cast<mpfr_ptr>(nullptr));
  return ok;
}

}  // namespace

void refine_root(const std::vector<Integer>& f, RootInterval& r, long bits, const long double* start) {
  const Rational scale = power_of_two(-static_cast<long>(bits));
  if (r.lo == r.hi || narrow(r, scale)) return;
  mpfr_t x, y;
  const mpfr_prec_t prec = static_cast<mpfr_prec_t>(bits) + 64;
  mpfr_inits2(prec, x, y, static_cast<mpfr_ptr>(nullptr));
  for (int attempt = 0; attempt < 6 && !narrow(r, scale); ++attempt) {
    if (newton(f, r, prec, attempt == 0 ? start : nullptr, x)) {
      // The proposal x (1 -+ 2^-(bits + 2)): the root lies between them when f's exact signs differ.
      mpfr_div_2ui(y, x, static_cast<unsigned long>(bits) + 2, MPFR_RNDN);
      mpfr_sub(y, x, y, MPFR_RNDN);
      RootInterval t{exact(y), Rational()};
      mpfr_div_2ui(y, x, static_cast<unsigned long>(bits) + 2, MPFR_RNDN);
      mpfr_add(y, x, y, MPFR_RNDN);
      t.hi = exact(y);
      const int sl = sign_of_value(f, t.lo), sh = sign_of_value(f, t.hi);
      if (r.lo < t.lo && t.hi < r.hi && sl != 0 && sh != 0 && sl != sh) {
        r = std::move(t);
        break;
      }
    }
    // A failed proposal (or r.lo = 0): a few halvings bring Newton's method closer to home.
    for (int i = 0; i < 4 && r.lo != r.hi; ++i) bisect(f, r);
  }
  mpfr_clears(x, y, static_cast<mpfr_ptr>(nullptr));
  while (r.lo != r.hi && !narrow(r, scale)) bisect(f, r);  // never reached in practice
}

}  // namespace relpos::detail
