#include "algebra/roots.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Polynomial.h>
#include <CGAL/Polynomial_traits_d.h>
#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>
#include <flint/nmod_poly.h>
#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "algebra/flint_thread.hpp"
#include "algebra/forms.hpp"
#include "algebra/rounding.hpp"
#include "algebra/small_factor.hpp"
#include "algebra/sturm_habicht_quartic.hpp"

namespace relpos {
namespace {

using Poly = CGAL::Polynomial<Integer>;
using AK = CGAL::Algebraic_kernel_d_1<Integer>;
using Root = AK::Algebraic_real_1;

template <std::size_t N>
Poly make_poly(const std::array<Integer, N>& c) {
  return Poly(c.begin(), c.end());
}

int sgn(const Integer& z) { return z > 0 ? 1 : (z < 0 ? -1 : 0); }

Rational evaluate(const Quartic<Integer>& f, const Rational& x) {
  Rational v(0);
  for (int i = 4; i >= 0; --i) v = v * x + Rational(f[static_cast<std::size_t>(i)]);
  return v;
}

/// The root itself if it is rational. A rational root p/q (lowest terms) of an integer polynomial has
/// q | lc(f), so root * lc(f) is an integer: refine the isolating interval below width 1/|lc(f)|,
/// take the only candidate m/lc(f) in it and test f(m/lc(f)) = 0 exactly.
std::optional<Rational> rational_value(const AK& ak, const Root& root, const Quartic<Integer>& f) {
  Integer lc = f[4] < 0 ? Integer(-f[4]) : f[4];
  const int bits = static_cast<int>(mpz_sizeinbase(lc.mpz(), 2)) + 4;
  auto iv = ak.approximate_absolute_1_object()(root, bits);
  const Rational scaled = (iv.first + iv.second) / 2 * Rational(lc);
  Integer m;  // nearest integer to scaled
  const Rational shifted = scaled + Rational(1, 2);
  mpz_fdiv_q(m.mpz(), shifted.numerator().mpz(), shifted.denominator().mpz());
  const Rational candidate(m, lc);
  if (candidate < iv.first || candidate > iv.second) return std::nullopt;
  if (evaluate(f, candidate) != 0) return std::nullopt;
  return candidate;
}

}  // namespace

int RootStructure::negative() const {
  return static_cast<int>(
      std::count_if(real_roots.begin(), real_roots.end(), [](const RealRoot& r) { return r.sign < 0; }));
}
int RootStructure::positive() const {
  return static_cast<int>(
      std::count_if(real_roots.begin(), real_roots.end(), [](const RealRoot& r) { return r.sign > 0; }));
}

int sign_of_discriminant(const std::vector<Integer>& c) {
  detail::flint_thread_cleanup_at_exit();
  Poly g(c.begin(), c.end());
  const int n = g.degree();
  if (n < 1) return 0;
  if (n == 1) return 1;
  // Res(g, g') = (-1)^(n(n-1)/2) lc(g) Disc(g)
  Integer res = CGAL::resultant(g, CGAL::differentiate(g));
  int s = sgn(res) * sgn(g.lcoeff());
  if ((n * (n - 1) / 2) % 2) s = -s;
  return s;
}

namespace {

/// An fmpz_poly of a polynomial over Z (RAII).
struct FlintPoly {
  fmpz_poly_t p;
  template <std::size_t N>
  explicit FlintPoly(const std::array<Integer, N>& c) {
    fmpz_poly_init2(p, static_cast<slong>(N));
    fmpz_t z;
    fmpz_init(z);
    for (std::size_t i = 0; i < N; ++i) {
      fmpz_set_mpz(z, c[i].mpz());
      fmpz_poly_set_coeff_fmpz(p, static_cast<slong>(i), z);
    }
    fmpz_clear(z);
  }
  ~FlintPoly() { fmpz_poly_clear(p); }
  FlintPoly(const FlintPoly&) = delete;
  FlintPoly& operator=(const FlintPoly&) = delete;
};

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

/// Polynomial value in doubles (coefficients c[0..N]). The degree is a template parameter so
/// that every loop below unrolls; the operations and their order are those of the written loops.
template <int N>
double horner(const double* c, double x) {
  double v = c[N];
  for (int i = N - 1; i >= 0; --i) v = v * x + c[i];
  return v;
}

/// The safeguarded Newton iteration for a root of c in [lo, hi] where c changes sign (flo: the value
/// at lo), started at the midpoint.
struct Bracket {
  double x = 0, lo = 0, hi = 0;
  double half_step = 0;  // half the last step (at first half the bracket), computed as the step's test reads it
  bool flo_negative = false;
  int steps = 0;
  static Bracket of(double lo, double hi, double flo) {
    return {lo + (hi - lo) / 2, lo, hi, (hi - lo) / 2, flo < 0, 0};
  }
};

/// One step for c of degree N (a template parameter: the loops unroll): Newton steps kept inside the
/// shrinking bracket, bisection when a step leaves it or does not halve the bracket (safeguarded
/// Newton), until the bracket or the step is below 2^-50 of the root, or after 2100 steps. A handful
/// of steps instead of the ~70 of plain bisection; the result is only an approximation, certified
/// afterwards by exact signs. False when done, the root in b.x. Always inlined: a call per step
/// would cost about as much as the step.
template <int N>
[[gnu::always_inline]] inline bool newton_step(const double* c, Bracket& b) {
  const double x = b.x;
  double fx = c[N], dfx = 0;  // value and derivative by Horner
  for (int i = N - 1; i >= 0; --i) {
    dfx = dfx * x + fx;
    fx = fx * x + c[i];
  }
  if (fx == 0) return false;
  if ((fx < 0) == b.flo_negative)
    b.lo = x;
  else
    b.hi = x;
  const double tol = 0x1p-50 * std::max(std::fabs(b.lo), std::fabs(b.hi));
  if (!(b.hi - b.lo > tol)) return false;
  double next = x - fx / dfx;
  const bool inside = next > b.lo && next < b.hi;
  if (!inside || !(std::fabs(next - x) < b.half_step)) next = b.lo + (b.hi - b.lo) / 2;  // bisect
  const double step = std::fabs(next - x);
  b.half_step = step / 2;
  if (!(next > b.lo && next < b.hi)) return false;  // the bracket cannot shrink further
  b.x = next;
  return !(inside && step <= tol) && ++b.steps < 2100;  // a Newton step this small: converged
}

/// A root of c (degree N) in a bracket.
template <int N>
double bracketed_root(const double* c, Bracket b) {
  while (newton_step<N>(c, b)) {
  }
  return b.x;
}

/// The roots in two brackets, their steps interleaved: each step touches only its own bracket, so
/// the iterates are those of bracketed_root, while the two chains of dependent floating-point
/// operations (Horner, division) overlap in the processor (an iteration is bound by their latency).
/// The brackets are local copies: their state stays in registers.
template <int N>
void bracketed_roots(const double* c, Bracket a, Bracket b, double& root_a, double& root_b) {
  bool more_a = true, more_b = true;
  while (more_a && more_b) {
    more_a = newton_step<N>(c, a);
    more_b = newton_step<N>(c, b);
  }
  while (more_a) more_a = newton_step<N>(c, a);
  while (more_b) more_b = newton_step<N>(c, b);
  root_a = a.x;
  root_b = b.x;
}

/// Approximate real roots of c (degree N <= 4, c[N] != 0) in (-bound, bound), increasing, into
/// out[0..count): the roots of the derivative split the line into monotone pieces, each with at most
/// one sign change. The brackets are solved in pairs from the outside in (the two outer ones, far
/// from the roots of the derivative, take the most steps, and about as many). Fixed arrays (no
/// allocation): a few hundred nanoseconds.
template <int N>
int approximate_real_roots(const double* c, double bound, double* out) {
  if constexpr (N == 1) {
    out[0] = -c[0] / c[1];
    return 1;
  } else {
    double d[N], inner[N], cuts[N + 2];
    for (int i = 1; i <= N; ++i) d[i - 1] = i * c[i];
    const int m = approximate_real_roots<N - 1>(d, bound, inner);
    int cut_count = 0;
    cuts[cut_count++] = -bound;
    for (int k = 0; k < m; ++k)
      if (inner[k] > cuts[cut_count - 1] && inner[k] < bound) cuts[cut_count++] = inner[k];
    cuts[cut_count++] = bound;
    Bracket brackets[N];
    int count = 0, bracket_count = 0, at[N];  // at: where each bracket's root goes in out
    double b = horner<N>(c, cuts[0]);
    for (int k = 0; k + 1 < cut_count; ++k) {
      const double a = b;  // the value at each cut computed once
      b = horner<N>(c, cuts[k + 1]);
      if (a == 0) {
        // The last entry, when a bracket's root still to come, lies below its bracket's upper cut,
        // itself below cuts[k]: NaN (unequal to everything) says the same.
        if (count == 0 || out[count - 1] != cuts[k]) out[count++] = cuts[k];
      } else if ((a < 0) != (b < 0) && b != 0) {
        brackets[bracket_count] = Bracket::of(cuts[k], cuts[k + 1], a);
        at[bracket_count++] = count;
        out[count++] = std::numeric_limits<double>::quiet_NaN();
      }
    }
    int first = 0, last = bracket_count - 1;
    for (; first < last; ++first, --last)
      bracketed_roots<N>(c, brackets[first], brackets[last], out[at[first]], out[at[last]]);
    if (first == last) out[at[first]] = bracketed_root<N>(c, brackets[first]);
    return count;
  }
}

/// The same for a degree n in 1..4 known at run time.
int approximate_real_roots(const double* c, int n, double bound, double* out) {
  switch (n) {
    case 1:
      return approximate_real_roots<1>(c, bound, out);
    case 2:
      return approximate_real_roots<2>(c, bound, out);
    case 3:
      return approximate_real_roots<3>(c, bound, out);
    case 4:
      return approximate_real_roots<4>(c, bound, out);
    default:
      throw std::logic_error("approximate_real_roots: degree outside 1..4");
  }
}

/// The odd primes below 24, the first group of the small-prime tests below, and their product
/// (below 2^32): f's residues modulo it serve both the coprimality and the rational-root test.
using FirstPrimes = std::integer_sequence<unsigned, 3, 5, 7, 11, 13, 17, 19, 23>;
constexpr unsigned long long first_primes_product = 3ULL * 5 * 7 * 11 * 13 * 17 * 19 * 23;  // 111546435

/// Whether Res(f, s) mod q != 0 for a prime q (a compile-time constant below 24) not dividing
/// either leading coefficient (then Res(f, s) mod q = Res(f mod q, s mod q)), for a quartic f and a
/// quadratic s given by their residues modulo a multiple of q. By the pseudo-remainder
/// r = r1 x + r0 of s2^3 f modulo s: Res(f, s) is a non-zero multiple of the product of r over the
/// two roots of s, r0^2 s2 - r0 r1 s1 + r1^2 s0 (over s2). A few dozen word operations.
template <unsigned Q>
bool resultant_nonzero_modulo(const unsigned long* f_residues, const unsigned long* s_residues) {
  auto mul = [](unsigned a, unsigned b) { return a * b % Q; };
  auto sub = [](unsigned a, unsigned b) { return (a + Q - b) % Q; };
  unsigned f[5];
  for (int i = 0; i < 5; ++i) f[i] = static_cast<unsigned>(f_residues[i] % Q);
  const unsigned s2 = static_cast<unsigned>(s_residues[2] % Q), s1 = static_cast<unsigned>(s_residues[1] % Q),
                 s0 = static_cast<unsigned>(s_residues[0] % Q);
  if (f[4] == 0 || s2 == 0) return false;
  for (int k = 4; k >= 2; --k) {  // f <- s2 f - f_k x^(k-2) s: degree k - 1
    for (int i = 0; i < k; ++i) f[i] = mul(f[i], s2);
    f[k - 1] = sub(f[k - 1], mul(f[k], s1));
    f[k - 2] = sub(f[k - 2], mul(f[k], s0));
  }
  const unsigned r1 = f[1], r0 = f[0];
  return (sub(mul(mul(r0, r0), s2), mul(mul(r0, r1), s1)) + mul(mul(r1, r1), s0)) % Q != 0;
}

template <unsigned... Q>
bool resultant_nonzero_modulo_any(std::integer_sequence<unsigned, Q...>, const unsigned long* f_residues,
                                  const unsigned long* s_residues) {
  return (resultant_nonzero_modulo<Q>(f_residues, s_residues) || ...);
}

/// True when Res(f, s) != 0 is shown modulo one of the FirstPrimes (f_residues: f's coefficients
/// modulo first_primes_product), usually the first one; false when each of them divides Res(f, s)
/// or a leading coefficient (then the caller computes the gcd over the integers: the same answer,
/// only slower).
bool certainly_coprime(const unsigned long* f_residues, const Quadratic<Integer>& sc) {
  unsigned long s_residues[3];
  for (std::size_t i = 0; i < 3; ++i) s_residues[i] = detail::residue<first_primes_product>(sc[i].mpz());
  return resultant_nonzero_modulo_any(FirstPrimes(), f_residues, s_residues);
}

/// Whether p does not divide lc(f) and f has no root modulo p, p a compile-time constant below 100:
/// Horner on the residues below p without any reduction (every value is below 2 p^5: 32 bits up to
/// p = 47, else 64), one remainder by the constant per point, no early exit (a loop the compiler
/// unrolls or vectorises).
template <unsigned P>
bool no_root_modulo(const unsigned long* residue, long deg) {
  static_assert(P < 100);
  using Word = std::conditional_t<(P <= 47), unsigned, unsigned long long>;
  Word c[5] = {0, 0, 0, 0, 0};  // zero above deg: the same values
  for (long i = 0; i <= deg; ++i) c[i] = static_cast<Word>(residue[i] % P);
  if (c[deg] == 0) return false;  // p divides lc(f): a rational root need not reduce
  bool root = false;
  for (Word x = 0; x < P; ++x) {
    Word v = 0;
    for (int i = 4; i >= 0; --i) v = v * x + c[i];
    root |= v % P == 0;
  }
  return !root;
}

/// no_root_modulo for the primes P..., from the residues of f's coefficients modulo their product
/// (below 2^32).
template <unsigned... P, class ResidueOf>
bool no_root_modulo_any(std::integer_sequence<unsigned, P...>, long deg, ResidueOf residue_of) {
  constexpr unsigned long long product = (1ULL * ... * P);
  unsigned long r[5] = {0, 0, 0, 0, 0};
  for (long i = 0; i <= deg; ++i) r[i] = residue_of(i, std::integral_constant<unsigned long long, product>());
  return (no_root_modulo<P>(r, deg) || ...);
}

/// True when f (degree deg in 1..4) has no root modulo one of the odd primes below 100 not
/// dividing lc(f), every residue tried by Horner on machine words: most irreducible quartics (and
/// products of irreducible quadratics) have no root modulo one of them, usually one of the first
/// few. residue_of(i, std::integral_constant<unsigned long long, M>) is f_i mod M in [0, M); the
/// primes go in four groups, each group's residues asked for only when the groups before it do not
/// settle it.
template <class ResidueOf>
bool no_root_modulo_small_primes(long deg, ResidueOf residue_of) {
  if (deg < 1 || deg > 4) return false;
  return no_root_modulo_any(FirstPrimes(), deg, residue_of) ||
         no_root_modulo_any(std::integer_sequence<unsigned, 29, 31, 37, 41, 43, 47>(), deg, residue_of) ||
         no_root_modulo_any(std::integer_sequence<unsigned, 53, 59, 61, 67, 71>(), deg, residue_of) ||
         no_root_modulo_any(std::integer_sequence<unsigned, 73, 79, 83, 89, 97>(), deg, residue_of);
}

/// The small-prime test on integer coefficients (no FLINT polynomial), degree 4, with f's residues
/// modulo first_primes_product already computed.
bool no_root_modulo_small_primes(const Quartic<Integer>& f, const unsigned long* first_residues) {
  return no_root_modulo_small_primes(4, [&f, first_residues](long i, auto modulus) {
    constexpr unsigned long long m = decltype(modulus)::value;
    if constexpr (m == first_primes_product)
      return first_residues[i];
    else
      return detail::residue<m>(f[static_cast<std::size_t>(i)].mpz());
  });
}

/// The word-sized primes' part of certainly_no_rational_root (FLINT's arithmetic modulo p).
bool no_root_modulo_word_primes(const fmpz_poly_t f) {
  static const mp_limb_t primes[] = {1000003, 1000033, 1000037, 1000039, 1000081, 1000099, 1000117, 1000121,
                                     1000133, 1000151, 1000159, 1000171, 1000183, 1000187, 1000193, 1000199};
  bool found = false;
  for (mp_limb_t p : primes) {
    nmod_poly_t fp, x, r;
    nmod_poly_init(fp, p);
    fmpz_poly_get_nmod_poly(fp, f);
    if (nmod_poly_degree(fp) != fmpz_poly_degree(f)) {
      nmod_poly_clear(fp);
      continue;
    }
    nmod_poly_init(x, p);
    nmod_poly_init(r, p);
    nmod_poly_set_coeff_ui(x, 1, 1);
    nmod_poly_powmod_ui_binexp(r, x, p, fp);  // x^p mod f
    nmod_poly_sub(r, r, x);
    nmod_poly_gcd(r, r, fp);
    found = nmod_poly_degree(r) == 0;
    nmod_poly_clear(fp);
    nmod_poly_clear(x);
    nmod_poly_clear(r);
    if (found) return true;
  }
  return false;
}

/// True when f certainly has no rational root: for some prime p not dividing lc(f), f has no root
/// in F_p (gcd(x^p - x, f mod p) = 1). A rational root a/b has b | lc(f), so it would reduce to one.
bool certainly_no_rational_root(const fmpz_poly_t f) {
  detail::flint_thread_cleanup_at_exit();
  // Small primes first, then word-sized ones by FLINT.
  auto residue_of = [f](long i, auto modulus) {
    return fmpz_fdiv_ui(fmpz_poly_get_coeff_ptr(f, i), static_cast<unsigned long>(decltype(modulus)::value));
  };
  return no_root_modulo_small_primes(fmpz_poly_degree(f), residue_of) || no_root_modulo_word_primes(f);
}

/// The rational roots of f, from its linear factors over Z (FLINT's factorisation; a quartic's is a
/// few microseconds), after the modular test that usually shows there are none. Refining each real
/// root below 1/|lc(f)| to test for a rational value (rational_value) costs hundreds of microseconds
/// on the long coefficients of near-tangent pairs.
std::vector<Rational> rational_roots(const Quartic<Integer>& fc) {
  std::vector<Rational> out;
  const FlintPoly f(fc);
  if (certainly_no_rational_root(f.p)) return out;
  fmpz_poly_factor_t fac;
  fmpz_poly_factor_init(fac);
  fmpz_poly_factor(fac, f.p);
  for (slong i = 0; i < fac->num; ++i) {
    const fmpz_poly_struct* h = fac->p + i;
    if (fmpz_poly_degree(h) != 1) continue;
    Integer num, den;  // fresh: written through mpz()
    fmpz_get_mpz(num.mpz(), fmpz_poly_get_coeff_ptr(h, 0));
    fmpz_get_mpz(den.mpz(), fmpz_poly_get_coeff_ptr(h, 1));
    out.push_back(Rational(-num, den));
  }
  fmpz_poly_factor_clear(fac);
  return out;
}

}  // namespace

namespace {

/// m 2^e, as std::ldexp(m, e) (exact, or one rounding into the subnormal range), by a
/// multiplication when 2^e is a normal double.
double times_power_of_two(double m, long e) {
  if (e < -1022 || e > 1023) return std::ldexp(m, static_cast<int>(std::clamp(e, -4000L, 4000L)));
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double p = 0;
  std::memcpy(&p, &bits, sizeof p);
  return m * p;
}

/// h's coefficients as doubles, all divided by one power of two 2^top (the roots do not move), into c;
/// returns the Cauchy bound 2 (1 + max |c_i / c_n|) on the roots, or 0 when it is not a finite double.
double scaled_doubles(const Integer* h, int n, double* c, long* top_out = nullptr) {
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

}  // namespace

namespace detail {

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

}  // namespace detail

namespace {

/// The real roots of h (integer coefficients h[0..n], n <= 4, square-free, no rational root, h(0) != 0),
/// `expected` of them: approximated in doubles, each certified by exact opposite signs of h at the
/// (dyadic) ends of disjoint intervals, as many as there are real roots, so each isolates exactly
/// one (simple, irrational) root. False when the doubles do not separate them.
bool certified_real_roots(const Integer* h, int n, std::size_t expected, std::vector<RealRoot>& out) {
  detail::DoubleSign sign_at(h, n);
  const double* c = sign_at.coefficients();
  const double bound = sign_at.root_bound();
  if (bound == 0) return false;  // roots beyond the double range: no fast path
  double roots[4];
  const std::size_t count = static_cast<std::size_t>(approximate_real_roots(c, n, bound, roots));
  if (count != expected) return false;
  double prev_hi = -HUGE_VAL;
  out.reserve(out.size() + count);
  for (std::size_t k = 0; k < count; ++k) {
    const double r = roots[k];
    if (r == 0 || !std::isfinite(r)) return false;
    bool ok = false;
    for (int widen = 0; widen < 4 && !ok; ++widen) {
      static constexpr double relative[4] = {0x1p-44, 0x1p-34, 0x1p-24, 0x1p-14};  // 2^(-44 + 10 widen)
      const double delta = std::fabs(r) * relative[widen];
      const double lo = r - delta, hi = r + delta;
      if (!(lo > prev_hi) || (lo < 0) != (r < 0) || (hi < 0) != (r < 0)) break;
      if (k + 1 < count && !(hi < roots[k + 1])) break;
      const int sl = sign_at(lo), sh = sign_at(hi);
      if (sl != 0 && sh != 0 && sl != sh) {
        RealRoot& root = out.emplace_back();  // fresh bounds: written in place
        root.sign = r < 0 ? -1 : 1;
        forms::set_double(root.lower.mpq(), lo);
        forms::set_double(root.upper.mpq(), hi);
        prev_hi = hi;
        ok = true;
      }
    }
    if (!ok) return false;
  }
  return true;
}

/// The coefficients of a FLINT polynomial (degree <= 4) as Integers.
int integer_coefficients(const fmpz_poly_t p, std::array<Integer, 5>& out) {
  const slong n = fmpz_poly_degree(p);
  for (slong i = 0; i <= n; ++i) fmpz_get_mpz(out[i].mpz(), fmpz_poly_get_coeff_ptr(p, i));
  return static_cast<int>(n);
}

/// The real roots of h as certified_real_roots(), when two of them are closer than doubles resolve
/// (near a tangency, two roots of f~ about sqrt(delta) apart): h is moved exactly to a critical point
/// c = M 2^e (a double approximation of a root of h', M an integer, 2^e its last place), as
///   Q(z) = 2^(-e n) h((M + z) 2^e)   (integer coefficients; a FLINT Taylor shift),
/// whose roots z = (x - c) / 2^e put the cluster at O(1) with a separation doubles resolve; Q's roots
/// are certified as h's were (Q has h's signs at corresponding points, a positive factor) and mapped
/// back exactly. Each critical point is tried in turn.
bool zoomed_real_roots(const Integer* h, int n, std::size_t expected, std::vector<RealRoot>& out) {
  if (n < 2) return false;
  double c[5], d[4], critical[4];
  const double bound = scaled_doubles(h, n, c);
  if (bound == 0) return false;
  for (int i = 1; i <= n; ++i) d[i - 1] = i * c[i];
  const int m = approximate_real_roots(d, n - 1, bound, critical);
  fmpz_poly_t p, q;
  fmpz_poly_init(p);
  fmpz_poly_init(q);
  fmpz_t shift, coeff;
  fmpz_init(shift);
  fmpz_init(coeff);
  bool ok = false;
  for (int k = 0; k < m && !ok; ++k) {
    const double x = critical[k];
    if (x == 0 || !std::isfinite(x)) continue;
    const int e = std::ilogb(x) - 52;  // x = M 2^e with |M| < 2^53
    if (e >= 0) continue;
    fmpz_set_si(shift, static_cast<slong>(std::ldexp(x, -e)));
    for (int i = 0; i <= n; ++i) {  // P(y) = sum h_i 2^(-e (n - i)) y^i, then Q(z) = P(M + z)
      fmpz_set_mpz(coeff, h[i].mpz());
      fmpz_mul_2exp(coeff, coeff, static_cast<ulong>(-e) * static_cast<ulong>(n - i));
      fmpz_poly_set_coeff_fmpz(p, i, coeff);
    }
    fmpz_poly_taylor_shift(q, p, shift);
    std::array<Integer, 5> qc;
    integer_coefficients(q, qc);
    std::vector<RealRoot> zs;
    if (qc[0] == 0 || !certified_real_roots(qc.data(), n, expected, zs)) continue;
    const Rational centre(x), unit(std::ldexp(1.0, e));
    ok = true;
    for (RealRoot& r : zs) {
      r.lower = centre + r.lower * unit;
      r.upper = centre + r.upper * unit;
      const int sl = CGAL::sign(r.lower), su = CGAL::sign(r.upper);
      if (sl == 0 || sl != su) ok = false;
      r.sign = sl;
    }
    if (ok) out.insert(out.end(), zs.begin(), zs.end());
  }
  fmpz_clear(shift);
  fmpz_clear(coeff);
  fmpz_poly_clear(p);
  fmpz_poly_clear(q);
  return ok;
}

}  // namespace

std::optional<RootStructure> simple_root_structure(const Quartic<Integer>& fc, const Quadratic<Integer>& sc,
                                                   int sign_disc_f) {
  detail::flint_thread_cleanup_at_exit();
  if (fc[4] == 0 || fc[0] == 0 || sc[2] == 0) return std::nullopt;
  // FLINT's polynomials only when a test on words does not settle it (the usual pair needs none).
  std::optional<FlintPoly> f_flint, s_flint;
  auto f = [&]() -> const FlintPoly& {
    if (!f_flint) f_flint.emplace(fc);
    return *f_flint;
  };
  fmpz_t z;
  fmpz_init(z);
  int disc = sign_disc_f;
  if (disc == 0) {
    fmpz_poly_discriminant(z, f().p);
    disc = fmpz_sgn(z);
  }
  if (disc == 0) {
    fmpz_clear(z);
    return std::nullopt;
  }
  // f is square-free. Its common roots with s (special roots: every sphere has one) are divided
  // out when they are rational: g = gcd(f, s) of degree 1, or 2 with a square discriminant. Each is
  // a simple root of f, and the cofactor h = f / g (= f~ up to a constant) is coprime to s.
  std::vector<RealRoot> common;
  std::optional<std::array<Integer, 5>> hc;  // h's coefficients when a common factor is divided out
  const Integer* hp = fc.data();             // h's coefficients: f's own when f and s are coprime
  int n = 4, disc_h = disc;
  bool ok = true;
  unsigned long f_residues[5];  // f modulo first_primes_product: for both modular tests
  for (std::size_t i = 0; i < 5; ++i) f_residues[i] = detail::residue<first_primes_product>(fc[i].mpz());
  if (!certainly_coprime(f_residues, sc)) {
    fmpz_poly_t g, h;
    fmpz_poly_init(g);
    fmpz_poly_init(h);
    s_flint.emplace(sc);
    fmpz_poly_gcd(g, f().p, s_flint->p);
    const slong dg = fmpz_poly_degree(g);
    ok = dg <= 2 && fmpz_poly_divides(h, f().p, g) && fmpz_poly_degree(h) >= 2;
    if (ok && dg >= 1) {
      std::array<Integer, 5> gc;
      integer_coefficients(g, gc);
      auto add = [&](const Rational& x) {
        RealRoot r;
        r.exact = x;
        r.lower = r.upper = x;
        r.sign = CGAL::sign(x) < 0 ? -1 : 1;
        r.multiplicity_s = (2 * sc[2] * x + sc[1] == 0) ? 2 : 1;  // 2 when s is a square
        common.push_back(std::move(r));
      };
      if (dg == 1) {
        add(Rational(-gc[0], gc[1]));
      } else {
        Integer d = gc[1] * gc[1] - 4 * gc[2] * gc[0], root;  // root: fresh, written through mpz()
        ok = d > 0 && mpz_perfect_square_p(d.mpz());
        if (ok) {
          mpz_sqrt(root.mpz(), d.mpz());
          const Integer den = 2 * gc[2];
          add(Rational(-gc[1] - root, den));
          add(Rational(-gc[1] + root, den));
          if (common[1].exact < common[0].exact) std::swap(common[0], common[1]);
        }
      }
      fmpz_poly_discriminant(z, h);
      disc_h = fmpz_sgn(z);
      ok = ok && disc_h != 0 && certainly_no_rational_root(h);  // f(0) != 0: no root of g is 0
      n = integer_coefficients(h, hc.emplace());
      hp = hc->data();
    } else if (ok) {  // gcd 1 after all
      ok = no_root_modulo_small_primes(fc, f_residues) || no_root_modulo_word_primes(f().p);
    }
    fmpz_poly_clear(g);
    fmpz_poly_clear(h);
  } else {
    ok = no_root_modulo_small_primes(fc, f_residues) || no_root_modulo_word_primes(f().p);
  }
  fmpz_clear(z);
  if (!ok) return std::nullopt;
  // Square-free h of degree n: n real roots when Disc(h) > 0 (for n = 4 also none: then the doubles
  // find none, and the general path decides), else 1 for a cubic, n - 2 otherwise.
  const std::size_t expected = static_cast<std::size_t>(disc_h > 0 ? n : (n == 3 ? 1 : n - 2));
  RootStructure rs;
  if (!certified_real_roots(hp, n, expected, rs.real_roots)) {
    rs.real_roots.clear();
    if (!zoomed_real_roots(hp, n, expected, rs.real_roots)) return std::nullopt;
  }
  for (RealRoot& r : common) {  // the rational roots between the certified intervals (never inside one)
    auto at = rs.real_roots.begin();
    while (at != rs.real_roots.end() && at->upper < *r.exact) ++at;
    if (at != rs.real_roots.end() && at->lower <= *r.exact) return std::nullopt;
    rs.real_roots.insert(at, std::move(r));
  }
  rs.degree_ftilde = n;
  rs.sign_disc_f = disc;
  rs.sign_disc_ftilde = disc_h;
  rs.nonreal = 4 - static_cast<int>(rs.real_roots.size());
  return rs;
}

RootStructure exact_root_structure(const Quartic<Integer>& fc, const Quadratic<Integer>& sc, int sign_disc_f) {
  if (auto fast = simple_root_structure(fc, sc, sign_disc_f)) return std::move(*fast);
  const Poly f = make_poly(fc), s = make_poly(sc);
  const Poly g = CGAL::gcd(f, s);
  const Poly ft = CGAL::integral_division_up_to_constant_factor(f, g);

  RootStructure rs;
  rs.degree_ftilde = ft.degree();
  rs.sign_disc_f = sign_of_discriminant(std::vector<Integer>(fc.begin(), fc.end()));
  {
    std::vector<Integer> c;
    for (int i = 0; i <= ft.degree(); ++i) c.push_back(ft[i]);
    rs.sign_disc_ftilde = sign_of_discriminant(c);
  }

  AK ak;
  std::vector<std::pair<Root, AK::Multiplicity_type>> roots;
  ak.solve_1_object()(f, std::back_inserter(roots));  // distinct real roots, increasing, with multiplicity
  const Poly ds = CGAL::differentiate(s);
  int real_with_mult = 0;
  long bits = 64;
  for (const auto& [root, mult] : roots) {
    RealRoot r;
    r.sign = static_cast<int>(ak.sign_at_1_object()(Poly(CGAL::shift(Poly(Integer(1)), 1)), root));
    r.multiplicity_f = static_cast<int>(mult);
    if (s.degree() >= 0 && ak.is_zero_at_1_object()(s, root))
      r.multiplicity_s = ak.is_zero_at_1_object()(ds, root) ? 2 : 1;
    real_with_mult += r.multiplicity_f;
    rs.real_roots.push_back(std::move(r));
  }
  // Isolating intervals: refine until the intervals of neighbouring roots are disjoint.
  for (;; bits *= 2) {
    for (std::size_t i = 0; i < roots.size(); ++i) {
      auto iv = ak.approximate_absolute_1_object()(roots[i].first, static_cast<int>(bits));
      rs.real_roots[i].lower = iv.first;
      rs.real_roots[i].upper = iv.second;
    }
    bool disjoint = true;
    for (std::size_t i = 1; i < roots.size(); ++i)
      if (!(rs.real_roots[i - 1].upper < rs.real_roots[i].lower)) disjoint = false;
    if (disjoint || bits > 4096) break;
  }
  // The exact value of each rational root: the one rational root of f in its isolating interval.
  const std::vector<Rational> rational = rational_roots(fc);
  for (std::size_t i = 0; i < roots.size(); ++i) {
    RealRoot& r = rs.real_roots[i];
    const bool isolated = (i == 0 || rs.real_roots[i - 1].upper < r.lower) &&
                          (i + 1 == roots.size() || r.upper < rs.real_roots[i + 1].lower);
    if (!isolated) {  // intervals still overlapping (never seen): test this root on its own
      r.exact = rational_value(ak, roots[i].first, fc);
      continue;
    }
    for (const Rational& q : rational)
      if (r.lower <= q && q <= r.upper) r.exact = q;
  }
  rs.nonreal = 4 - real_with_mult;
  // Non-real roots of multiplicity >= 2: look at the square-free factors of multiplicity >= 2.
  std::vector<std::pair<Poly, int>> factors;
  CGAL::square_free_factorize(f, std::back_inserter(factors));
  for (const auto& [h, m] : factors) {
    if (m < 2) continue;
    std::vector<std::pair<Root, AK::Multiplicity_type>> hr;
    ak.solve_1_object()(h, std::back_inserter(hr));
    rs.nonreal_multiple += (h.degree() - static_cast<int>(hr.size())) * m;
  }
  return rs;
}

namespace {

using detail::SmallCount;

/// Distinct real roots of a square-free integer polynomial of degree 1 or 2, by sign.
SmallCount count_small(const Poly& h) {
  const int d = h.degree();
  if (d == 1) return detail::count_small(1, 1, 0, sgn(h[1]), sgn(h[0]));
  return detail::count_small(d, sgn(Integer(h[1] * h[1] - 4 * h[2] * h[0])), sgn(h[2]), sgn(h[1]), sgn(h[0]));
}

}  // namespace

namespace {

/// The rational square root of q >= 0, if q is a square in Q.
std::optional<Rational> rational_sqrt(const Rational& q) {
  if (q < 0) return std::nullopt;
  if (!mpz_perfect_square_p(q.numerator().mpz()) || !mpz_perfect_square_p(q.denominator().mpz())) return std::nullopt;
  Integer n, d;
  mpz_sqrt(n.mpz(), q.numerator().mpz());
  mpz_sqrt(d.mpz(), q.denominator().mpz());
  return Rational(n, d);
}

/// Multiplicity (0, 1 or 2) of x as a root of the quadratic s (s2 = det M > 0).
int multiplicity_in(const Quadratic<Rational>& s, const Rational& x) {
  if (!CGAL::is_zero((s[2] * x + s[1]) * x + s[0])) return 0;
  return CGAL::is_zero(2 * s[2] * x + s[1]) ? 2 : 1;
}

}  // namespace

std::optional<RootFacts> subresultant_root_facts(const Quartic<Integer>& f, const Quadratic<Integer>& s) {
  Integer g2[3], g1[2], g0[1];
  detail::sturm_habicht_quartic(f[0], f[1], f[2], f[3], f[4], g2, g1, g0);
  return subresultant_root_facts(f, s, g2, g1, g0[0]);
}

std::optional<RootFacts> subresultant_root_facts(const Quartic<Integer>& f, const Quadratic<Integer>& s,
                                                 const Integer g2[3], const Integer g1[2], const Integer& disc) {
  if (CGAL::is_zero(f[4]) || CGAL::is_zero(f[0])) return std::nullopt;
  if (!CGAL::is_zero(disc)) return std::nullopt;  // square-free: not this function's case
  // Subresultant theorem: deg gcd(f, f') is the first j whose principal coefficient is non-zero
  // (g0 = Disc(f), then g1[0], then g2[0]), and the gcd is StHa_j. Every multiple root of f is a
  // root of it, with multiplicity one less.
  const Quartic<Rational> fq{Rational(f[0]), Rational(f[1]), Rational(f[2]), Rational(f[3]), Rational(f[4])};
  const Quadratic<Rational> sq{Rational(s[0]), Rational(s[1]), Rational(s[2])};
  struct Root {
    Rational x;
    int mult;
  };
  std::vector<Root> roots;         // the multiple roots, with their multiplicity in f
  std::array<Rational, 3> rest{};  // f / prod (l - x)^mult, degree rest_degree (square-free)
  int rest_degree = 0;
  if (!CGAL::is_zero(g1[0])) {  // gcd linear: one double root, the other two simple
    roots.push_back({Rational(-g1[1], g1[0]), 2});
  } else if (!CGAL::is_zero(g2[0])) {  // gcd = g2, quadratic
    const Rational a(g2[0]), b(g2[1]), c(g2[2]);
    const Rational disc_g2 = b * b - 4 * a * c;
    if (CGAL::is_zero(disc_g2)) {  // gcd = (l - r)^2: a triple root and a simple one
      roots.push_back({-b / (2 * a), 3});
    } else {  // two double roots, rational only if disc is a square
      const auto w = rational_sqrt(disc_g2);
      if (!w) return std::nullopt;  // irrational or non-real double roots: the general path
      roots.push_back({(-b - *w) / (2 * a), 2});
      roots.push_back({(-b + *w) / (2 * a), 2});
    }
  } else {  // gcd cubic: a quadruple root
    roots.push_back({-fq[3] / (4 * fq[4]), 4});
  }
  // Divide the multiple roots out (synthetic division over Q); every remainder must vanish.
  std::array<Rational, 5> c = fq;
  int deg = 4;
  for (const Root& r : roots)
    for (int k = 0; k < r.mult; ++k) {
      std::array<Rational, 5> q{};
      Rational carry(0);
      for (int i = deg; i >= 1; --i) {
        carry = c[static_cast<std::size_t>(i)] + carry * r.x;
        q[static_cast<std::size_t>(i - 1)] = carry;
      }
      if (!CGAL::is_zero(c[0] + carry * r.x)) return std::nullopt;  // cannot happen (theorem above)
      c = q;
      --deg;
    }
  rest_degree = deg;
  for (int i = 0; i <= deg; ++i) rest[static_cast<std::size_t>(i)] = c[static_cast<std::size_t>(i)];

  RootFacts r;
  int gcd_degree = 0;               // deg gcd(f, s)
  Quadratic<Rational> s_rest = sq;  // s with its roots among the multiple roots divided out
  int s_rest_degree = 2;
  bool tangent = false;
  for (const Root& x : roots) {
    const int ms = multiplicity_in(sq, x.x);
    const int sign = CGAL::sign(x.x);
    (sign < 0 ? r.negative : r.positive) += 1;
    if (x.mult - ms >= 2) {  // math.md §3: mult_f - mult_s >= 2
      (sign < 0 ? r.tangent_negative : r.tangent_positive) += 1;
      tangent = true;
    }
    gcd_degree += std::min(x.mult, ms);
    for (int k = 0; k < ms; ++k) {  // s_rest /= (l - x)
      const Rational q1 = s_rest[2], q0 = s_rest[1] + q1 * x.x;
      s_rest = {q0, q1, Rational(0)};
      --s_rest_degree;
    }
  }
  // The square-free cofactor (degree <= 2, none of its roots is a multiple root of f).
  int sign_disc_rest = 1;
  if (rest_degree == 2) sign_disc_rest = CGAL::sign(rest[1] * rest[1] - 4 * rest[2] * rest[0]);
  if (rest_degree >= 1) {
    const SmallCount hc = detail::count_small(rest_degree, sign_disc_rest, rest_degree == 2 ? CGAL::sign(rest[2]) : 0,
                                              CGAL::sign(rest[1]), CGAL::sign(rest[0]));
    r.negative += hc.negative;
    r.positive += hc.positive;
  }
  r.real = r.negative + r.positive;
  r.nonreal = (rest_degree == 2 && sign_disc_rest < 0) ? 2 : 0;
  r.nonreal_multiple = 0;  // every multiple root here is rational
  r.sign_disc_f = 0;
  // f~ keeps f's non-real roots (s has real roots only); it is square-free unless tangent.
  r.sign_disc_ftilde = tangent ? 0 : ((r.nonreal / 2) % 2 ? -1 : 1);
  // Roots the cofactor shares with what is left of s (both square-free, degree <= 2).
  int shared = 0;
  if (rest_degree >= 1 && s_rest_degree >= 1) {
    if (s_rest_degree == 1) {
      const Rational m = -s_rest[0] / s_rest[1];
      Rational v(0);
      for (int i = rest_degree; i >= 0; --i) v = v * m + rest[static_cast<std::size_t>(i)];
      shared = CGAL::is_zero(v) ? 1 : 0;
    } else if (rest_degree == 1) {
      const Rational m = -rest[0] / rest[1];
      shared = CGAL::is_zero((s_rest[2] * m + s_rest[1]) * m + s_rest[0]) ? 1 : 0;
    } else {  // two quadratics: Res = 0 iff a common root; proportional iff both
      const Rational u = rest[2] * s_rest[0] - rest[0] * s_rest[2], v = rest[2] * s_rest[1] - rest[1] * s_rest[2],
                     w = rest[1] * s_rest[0] - rest[0] * s_rest[1];
      if (CGAL::is_zero(u * u - v * w)) shared = (CGAL::is_zero(u) && CGAL::is_zero(v)) ? 2 : 1;
    }
  }
  r.degree_ftilde = 4 - gcd_degree - shared;
  return r;
}

std::optional<RootFacts> exact_root_facts(const Quartic<Integer>& fc, const Quadratic<Integer>& sc) {
  if (auto r = subresultant_root_facts(fc, sc)) return r;  // rational multiple roots, without gcds
  return exact_root_facts_by_factorisation(fc, sc);
}

std::optional<RootFacts> exact_root_facts_by_factorisation(const Quartic<Integer>& fc, const Quadratic<Integer>& sc) {
  const Poly f = make_poly(fc), s = make_poly(sc);
  std::vector<std::pair<Poly, int>> factors;
  CGAL::square_free_factorize(f, std::back_inserter(factors));
  RootFacts r;
  bool multiple = false;
  for (const auto& [h, m] : factors) {
    if (h.degree() > 2) return std::nullopt;  // square-free quartic: not this function's case
    if (h.degree() < 1) continue;
    multiple = multiple || m >= 2;
    const SmallCount c = count_small(h);
    r.negative += c.negative;
    r.positive += c.positive;
    const int nonreal = h.degree() - c.negative - c.positive;
    r.nonreal += nonreal * m;
    if (m >= 2) r.nonreal_multiple += nonreal * m;
  }
  if (!multiple) return std::nullopt;
  r.real = r.negative + r.positive;
  r.sign_disc_f = 0;
  const Poly ft = CGAL::integral_division_up_to_constant_factor(f, CGAL::gcd(f, s));
  r.degree_ftilde = ft.degree();
  std::vector<std::pair<Poly, int>> tfactors;
  CGAL::square_free_factorize(ft, std::back_inserter(tfactors));
  bool ft_multiple = false;
  for (const auto& [h, m] : tfactors) {
    if (m < 2 || h.degree() < 1) continue;
    ft_multiple = true;
    const SmallCount c = count_small(h);  // deg h <= 2 because m >= 2 and deg f~ <= 4
    r.tangent_negative += c.negative;
    r.tangent_positive += c.positive;
  }
  // For a square-free real polynomial, sign Disc = (-1)^(number of non-real conjugate pairs); f~
  // keeps f's non-real roots (s has only real roots).
  r.sign_disc_ftilde = ft_multiple ? 0 : ((r.nonreal / 2) % 2 ? -1 : 1);
  return r;
}

std::vector<std::string> real_root_decimals(const Quartic<Integer>& fc, int digits) {
  const Poly f = make_poly(fc);
  AK ak;
  std::vector<std::pair<Root, AK::Multiplicity_type>> roots;
  ak.solve_1_object()(f, std::back_inserter(roots));
  std::vector<std::string> out;
  const int bits = static_cast<int>(digits * 3.33) + 8;
  for (const auto& r : roots) {
    auto iv = ak.approximate_relative_1_object()(r.first, bits);
    Rational mid = (iv.first + iv.second) / 2;
    out.push_back(to_decimal(mid, digits));
  }
  return out;
}

Rational evaluate(const RationalPolynomial& p, const Rational& x) {
  Rational acc(0);
  for (std::size_t i = p.size(); i-- > 0;) acc = acc * x + p[i];
  return acc;
}

}  // namespace relpos
