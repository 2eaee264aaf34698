// Facts about integer polynomials read modulo small primes, on machine words: a residue of a GMP
// integer from its limbs, Res(f, s) != 0 (f and s coprime), no root of f in F_p (no rational
// root), and from these the rational roots of a quartic. Each test answers "certainly" or "cannot
// tell"; a "cannot tell" sends the caller to the computation over Z (the same answer, only slower),
// so the tests only save work (roots.hpp's fast path uses them).
#pragma once

#include <flint/fmpz_poly.h>
#include <gmp.h>

#include <vector>

#include "algebra/pencil.hpp"
#include "relpos/numbers.hpp"

namespace relpos::detail {

/// The residue of z modulo a compile-time constant M < 2^32, in [0, M) (mpz_fdiv_ui's value), from
/// its limbs by Horner in base 2^GMP_NUMB_BITS: every product stays below 2^64 and every remainder
/// is by a constant (a multiplication), without mpz_fdiv_ui's set-up for a run-time divisor.
template <unsigned long long M>
unsigned long residue(mpz_srcptr z) {
  static_assert(M > 1 && M < (1ULL << 32) && GMP_NAIL_BITS == 0 && GMP_NUMB_BITS <= 64);
  constexpr unsigned long long base = (static_cast<unsigned long long>(GMP_NUMB_MAX) % M + 1) % M;  // 2^bits mod M
  const mp_limb_t* limbs = mpz_limbs_read(z);
  unsigned long long r = 0;
  for (mp_size_t i = static_cast<mp_size_t>(mpz_size(z)); i-- > 0;)
    r = (r * base + static_cast<unsigned long long>(limbs[i]) % M) % M;  // < M^2 + M <= 2^64
  return static_cast<unsigned long>(mpz_sgn(z) < 0 && r != 0 ? M - r : r);
}

/// The product of the odd primes below 24 (below 2^32): f's residues modulo it serve both the
/// coprimality and the rational-root test.
constexpr unsigned long long first_primes_product = 3ULL * 5 * 7 * 11 * 13 * 17 * 19 * 23;  // 111546435

/// True when Res(f, s) != 0 is shown modulo one of the odd primes below 24 (f_residues[0..4]: f's
/// coefficients modulo first_primes_product), usually the first one; false when each of them
/// divides Res(f, s) or a leading coefficient.
bool certainly_coprime(const unsigned long* f_residues, const Quadratic<Integer>& s);

/// True when the quartic f has no root modulo one of the odd primes below 100 not dividing lc(f)
/// (first_residues[0..4]: f's coefficients modulo first_primes_product), hence no rational root.
bool no_root_modulo_small_primes(const Quartic<Integer>& f, const unsigned long* first_residues);

/// The same for 16 word-sized primes near 10^6 (FLINT's arithmetic modulo p: gcd(x^p - x, f mod p)).
bool no_root_modulo_word_primes(const fmpz_poly_t f);

/// True when f (degree 1..4) certainly has no rational root: for some prime p not dividing lc(f),
/// f has no root in F_p (a rational root a/b has b | lc(f), so it would reduce to one). Small primes
/// first, then word-sized ones.
bool certainly_no_rational_root(const fmpz_poly_t f);

/// The rational roots of f, from its linear factors over Z (FLINT's factorisation), after the
/// modular test that usually shows there are none.
std::vector<Rational> rational_roots(const Quartic<Integer>& f);

}  // namespace relpos::detail
