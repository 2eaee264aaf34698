#include "algebra/double_sign.hpp"

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "algebra/rounding.hpp"

namespace relpos::detail {
namespace {

int sgn(const Integer& z) { return z > 0 ? 1 : (z < 0 ? -1 : 0); }

/// m 2^e, as std::ldexp(m, e) (exact, or one rounding into the subnormal range), by a
/// multiplication when 2^e is a normal double.
double times_power_of_two(double m, long e) {
  if (e < -1022 || e > 1023) return std::ldexp(m, static_cast<int>(std::clamp(e, -4000L, 4000L)));
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double p = 0;
  std::memcpy(&p, &bits, sizeof p);
  return m * p;
}

/// Sign of h(x) = h[0] + ... + h[n] x^n for a finite double x (a dyadic rational m 2^e), exactly:
/// the sign of sum h_i m^i 2^(e i), homogenised to integers.
int sign_at_double(const Integer* h, int n, double x) {
  if (x == 0) return sgn(h[0]);
  int e = 0;
  const double frac = std::frexp(x, &e);                        // x = frac 2^e, frac in [1/2, 1)
  const auto m = static_cast<long long>(std::ldexp(frac, 53));  // exact
  e -= 53;                                                      // x = m 2^e
  // The thread's two temporaries, their limbs kept from call to call (the values run to a few
  // hundred bits: no allocation once grown).
  thread_local struct Scratch {
    mpz_t v, t;
    Scratch() {
      mpz_init(v);
      mpz_init(t);
    }
    ~Scratch() {
      mpz_clear(v);
      mpz_clear(t);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
  } scratch;
  const mpz_ptr v = scratch.v, t = scratch.t;
  // Horner on m with powers of two: e >= 0: v = v m 2^e + h_i; e < 0: v = v m + h_i 2^(-e (n - i)).
  mpz_set(v, h[n].mpz());
  for (int i = n - 1; i >= 0; --i) {
    mpz_mul_si(v, v, static_cast<long>(m));
    if (e >= 0) {
      mpz_mul_2exp(v, v, static_cast<mp_bitcnt_t>(e));
      mpz_add(v, v, h[i].mpz());
    } else {
      mpz_mul_2exp(t, h[i].mpz(), static_cast<mp_bitcnt_t>(-e) * static_cast<mp_bitcnt_t>(n - i));
      mpz_add(v, v, t);
    }
  }
  return mpz_sgn(v);
}

}  // namespace

double scaled_doubles(const Integer* h, int n, double* c, long* top_out) {
  // h_i = m_i 2^(e_i) with 1/2 <= |m_i| < 1 (m_i truncated to 53 bits): e_i is h_i's bit length.
  double m[5];
  long e[5], top = 0;
  for (int i = 0; i <= n; ++i) {
    m[i] = mpz_get_d_2exp(&e[i], h[i].mpz());
    top = std::max(top, e[i]);
  }
  for (int i = 0; i <= n; ++i) c[i] = times_power_of_two(m[i], std::max<long>(e[i] - top, -2000));
  if (top_out != nullptr) *top_out = top;
  double bound = 0;
  for (int i = 0; i < n; ++i) bound = std::max(bound, std::fabs(c[i] / c[n]));
  bound = 2 * (1 + bound);
  return std::isfinite(bound) && bound <= 1e300 ? bound : 0;
}

DoubleSign::DoubleSign(const Integer* h, int n) : h_(h), n_(n) {
  bound_ = scaled_doubles(h, n, c_, &top_);
  for (int i = 0; i <= n; ++i)
    if (h[i] != 0 && !(std::fabs(c_[i]) >= 0x1p-900)) relative_ = false;
}

/// The parts of h_i 2^-top below c_i's 53 bits, to 53 bits more: with r_i = h_i - (h_i's leading 53
/// bits) (truncated towards zero, as mpz_get_d_2exp truncates), lo_i = r_i 2^-top truncated, so
/// |lo_i| < 2^-52 |c_i| and |h_i 2^-top - c_i - lo_i| < 2^-105 |c_i|. False when some lo_i would
/// leave the normal range (then no compensated evaluation).
bool DoubleSign::split() {
  thread_local struct Remainder {
    mpz_t r;
    Remainder() { mpz_init(r); }
    ~Remainder() { mpz_clear(r); }
    Remainder(const Remainder&) = delete;
    Remainder& operator=(const Remainder&) = delete;
  } scratch;
  for (int i = 0; i <= n_; ++i) {
    lo_[i] = 0;
    const long bits = h_[i] == 0 ? 0 : static_cast<long>(mpz_sizeinbase(h_[i].mpz(), 2));
    if (bits <= 53) continue;  // c_i is exact
    mpz_tdiv_r_2exp(scratch.r, h_[i].mpz(), static_cast<mp_bitcnt_t>(bits - 53));
    if (mpz_sgn(scratch.r) == 0) continue;
    long ex = 0;
    const double m = mpz_get_d_2exp(&ex, scratch.r);
    if (ex - top_ < -1000) return false;
    lo_[i] = times_power_of_two(m, ex - top_);
  }
  return true;
}

int DoubleSign::compensated(double x, double mag) {
  if (split_ == 0) split_ = split() ? 1 : -1;
  if (split_ < 0) return 0;
  // Error-free transformations: s_(i+1) x = p + pi exactly (FMA), p + c_i = s_i + sigma exactly
  // (Knuth's TwoSum), so with q_i = pi_i + sigma_i + lo_i (q_n = lo_n)
  //   sum (c_i + lo_i) x^i = s_0 + sum q_i x^i   exactly,
  // and e is q(x) by Horner.
  double s = c_[n_], e = lo_[n_], slack = 0x1p-1000;
  const double ax = std::fabs(x);
  for (int i = n_ - 1; i >= 0; --i) {
    const double p = s * x, pi = std::fma(s, x, -p);
    const double t = p + c_[i], z = t - p, sigma = (p - (t - z)) + (c_[i] - z);
    s = t;
    e = e * x + ((pi + sigma) + lo_[i]);
    if (ax > 1) slack *= ax;
  }
  // The error (math.md §11; u = 2^-53, gamma_k = k u / (1 - k u), p~ = sum |c_i| |x|^i):
  // - sum (|pi_i| + |sigma_i|) |x|^i <= gamma_2n p~ (Graillat, Langlois, Louvet, "Algorithms for
  //   accurate, validated and fast polynomial evaluation", 2009, the compensated Horner scheme), and
  //   |lo_i| <= 2^-52 |c_i|; e passes each q_i x^i through at most 2n + 1 roundings:
  //   |e - q(x)| <= gamma_(2n+1) (gamma_2n + 2^-52) p~ < 2^-99 p~ for n <= 4;
  // - the low parts miss h_i 2^-top by < 2^-105 |c_i|: < 2^-105 p~ at x;
  // - an operation below the normal range (where the transformations may lose their exactness)
  //   adds < 2^-1074, times at most |x|^n later on: within slack = 2^-1000 max(1, |x|)^n;
  // - mag (all terms positive) is p~ within (1 + u)^2n, and fl(s + e) is s + e within u |fl(s + e)|.
  // With B = 2^-96 mag + slack, four times the sum of the above, |fl(s + e)| > 2 B fixes the sign.
  const double bound = 0x1p-96 * mag + slack, v = s + e;
  if (v > 2 * bound) return 1;
  if (v < -2 * bound) return -1;
  return 0;
}

int DoubleSign::operator()(double x) {
  if (const int s = filtered(x)) return s;
  return sign_at_double(h_, n_, x);
}

int DoubleSign::filtered(double x) {
  // The double Horner value when it exceeds its error bound (each c_i is h_i 2^-top truncated,
  // relative error < 2^-52, plus at most 8 roundings: 2^-48 times the magnitude covers both with
  // room, in any rounding mode). Only when no coefficient was flushed towards 0.
  if (relative_) {
    double v = c_[n_], mag = std::fabs(c_[n_]);
    for (int i = n_ - 1; i >= 0; --i) {
      v = v * x + c_[i];
      mag = mag * std::fabs(x) + std::fabs(c_[i]);
    }
    const double error = 0x1p-48 * mag;
    if (std::isfinite(mag) && mag >= 0x1p-900) {
      if (v > error) return 1;
      if (v < -error) return -1;
      // No overflow in the compensated evaluation: with |x| >= 1 every partial value is below about
      // mag, with |x| < 1 below the largest |c_i| < 1. Its error-free transformations need rounding
      // to nearest, tested at each call (two additions): the object may outlive a rounding mode.
      if (mag < 0x1p1000 && rounding_to_nearest()) return compensated(x, mag);
    }
  }
  return 0;
}

}  // namespace relpos::detail
