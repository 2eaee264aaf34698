#include "decide/evidence.hpp"

#include <gmp.h>
#include <mpfr.h>

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <utility>

#include "certificate/build.hpp"

namespace relpos::detail {
namespace {

/// The double nearest q (ties to even; CGAL's to_double of a Gmpq truncates): rounded once to 53
/// bits by MPFR, which is the double itself unless it is subnormal, then rounded from 40 digits.
double nearest_double(const Rational& q) {
  MPFR_DECL_INIT(x, 53);  // on the stack: no allocation, nothing to clear
  mpfr_set_q(x, q.mpq(), MPFR_RNDN);
  const double d = mpfr_get_d(x, MPFR_RNDN);
  if (d == 0 || std::fabs(d) < DBL_MIN || !std::isfinite(d)) return std::strtod(to_decimal(q, 40).c_str(), nullptr);
  return d;
}

/// A rational rho, with the double nearest it.
void take_rho(const Rational& rho, Classification& out) {
  out.rho = rho;
  out.rho_approx = nearest_double(*out.rho);
}

/// rho = (f0/f4)(s2/s0) / u1^2 with u1 = -lambda_s, the smallest root of s(-u), rational iff Disc(s)
/// is a square. A rational rho comes from the reduced f, s and lambda_s; an irrational one only as a
/// double, from the reduced f and s.
void fill_rho(const EvidencePencil& ev, Classification& out) {
  if (ev.rho) return take_rho(*ev.rho, out);
  const Quartic<Rational>& f = ev.f;
  const Quadratic<Rational>& s = ev.s;
  // k = (f0 s2) / (f4 s0)
  if (ev.lambda_s.rational()) {
    // rho = (f0 / f4) (s2 / s0) / lambda_s^2 from the reduced coefficients and lambda_s: GMP's
    // products of fractions in lowest terms take gcds of their short parts only, where reducing
    // 4 g0 h2^3 / (g4 h0 (R - h1)^2) is one gcd of numbers ten times longer (mostly the scales).
    // s2 / f4 first: both are over powers of lp (h2 / (lp^2 le), g4 / lp^4), so their quotient
    // cancels most of both and the later gcds see short numbers (the order sets their sizes).
    Rational rho;  // fresh: written in place
    const mpq_ptr r = rho.mpq();
    mpq_div(r, s[2].mpq(), f[4].mpq());  // f4 = det P, s0 = det M and lambda_s are not 0
    mpq_mul(r, r, f[0].mpq());
    mpq_div(r, r, s[0].mpq());
    mpq_mul(r, r, forms::inverse_square(ev.lambda_s.value().a).mpq());
    return take_rho(rho, out);
  }
  // k only as a double (CGAL::to_double is mpq_get_d: the exact quotient truncated, whatever
  // fraction represents it), so from the unreduced product of the reduced coefficients: no gcd.
  mpq_t k;  // a fraction of our own (canonical: positive denominator), read by mpq_get_d only
  mpq_init(k);
  const mpz_ptr kn = mpq_numref(k), kd = mpq_denref(k);
  mpz_mul(kn, mpq_numref(f[0].mpq()), mpq_denref(f[4].mpq()));
  mpz_mul(kn, kn, mpq_numref(s[2].mpq()));
  mpz_mul(kn, kn, mpq_denref(s[0].mpq()));
  mpz_mul(kd, mpq_denref(f[0].mpq()), mpq_numref(f[4].mpq()));
  mpz_mul(kd, kd, mpq_denref(s[2].mpq()));
  mpz_mul(kd, kd, mpq_numref(s[0].mpq()));
  if (mpz_sgn(kd) < 0) {  // a positive denominator, as mpq_get_d reads it
    mpz_neg(kn, kn);
    mpz_neg(kd, kd);
  }
  const double k_double = mpq_get_d(k);
  mpq_clear(k);
  const double s2 = forms::truncated_double(s[2]), s1 = forms::truncated_double(s[1]),
               s0 = forms::truncated_double(s[0]);
  const double u1 = (2 * s0) / (s1 + std::sqrt(s1 * s1 - 4 * s2 * s0));  // stable smaller root
  out.rho_approx = k_double / (u1 * u1);
}

}  // namespace

Classification blank_classification() {
  // A copy of the thread's default one, its numbers sharing that one's (a Gmpq copy shares its
  // value; each default Gmpq costs two allocations, and a certificate holds some twenty, most never
  // written). Every number of a result is assigned or swapped in, never written in place.
  thread_local const Classification prototype;
  return prototype;
}

void fill_full_evidence(PairContext& pair, const Verdict& v, Classification& out) {
  // The certificate reads the integer forms for the points of C, TE and TI, not the multipliers of
  // E and I; the verdict's sign of Disc(f) is certified (a positive rescaling of f keeps it).
  pair.expect(v.sign_disc_f, v.position != Position::E && v.position != Position::I);
  const EvidencePencil& ev = pair.evidence();
  out.has_full_evidence = true;
  out.degree_ftilde = pair.roots().degree_ftilde;
  fill_rho(ev, out);
  // The certificate reuses f, s, lambda_s, the isolation, the integer forms and S^4 f.
  certificate::build(pair, v.position, out.certificate);
  RootStructure roots;
  pair.move_evidence(out.f, out.s, roots);
  out.roots = std::move(roots.real_roots);
}

}  // namespace relpos::detail
