#include "algebra/modular.hpp"

#include <flint/fmpz.h>
#include <flint/nmod_poly.h>

#include <type_traits>
#include <utility>

#include "algebra/flint_poly.hpp"
#include "algebra/flint_thread.hpp"

namespace relpos::detail {
namespace {

/// The odd primes below 24, the first group of the small-prime tests below (their product is
/// first_primes_product).
using FirstPrimes = std::integer_sequence<unsigned, 3, 5, 7, 11, 13, 17, 19, 23>;

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

}  // namespace

bool certainly_coprime(const unsigned long* f_residues, const Quadratic<Integer>& sc) {
  unsigned long s_residues[3];
  for (std::size_t i = 0; i < 3; ++i) s_residues[i] = residue<first_primes_product>(sc[i].mpz());
  return resultant_nonzero_modulo_any(FirstPrimes(), f_residues, s_residues);
}

bool no_root_modulo_small_primes(const Quartic<Integer>& f, const unsigned long* first_residues) {
  return no_root_modulo_small_primes(4, [&f, first_residues](long i, auto modulus) {
    constexpr unsigned long long m = decltype(modulus)::value;
    if constexpr (m == first_primes_product)
      return first_residues[i];
    else
      return residue<m>(f[static_cast<std::size_t>(i)].mpz());
  });
}

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

bool certainly_no_rational_root(const fmpz_poly_t f) {
  flint_thread_cleanup_at_exit();
  auto residue_of = [f](long i, auto modulus) {
    return fmpz_fdiv_ui(fmpz_poly_get_coeff_ptr(f, i), static_cast<unsigned long>(decltype(modulus)::value));
  };
  return no_root_modulo_small_primes(fmpz_poly_degree(f), residue_of) || no_root_modulo_word_primes(f);
}

/// A quartic's factorisation is a few microseconds; refining each real root below 1/|lc(f)| to test
/// for a rational value (roots.cpp, rational_value) costs hundreds of microseconds on the long
/// coefficients of near-tangent pairs.
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

}  // namespace relpos::detail
