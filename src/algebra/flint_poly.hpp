// A polynomial over Z as FLINT's fmpz_poly and back: the conversions the root code needs around
// FLINT's discriminant, gcd, factorisation and arithmetic modulo word primes (roots.hpp,
// modular.hpp), the algebraic reals and the margin's isolation (any degree, as std::vector).
#pragma once

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>

#include <array>
#include <cstddef>
#include <vector>

#include "relpos/numbers.hpp"

namespace relpos::detail {

/// An fmpz_poly of a polynomial over Z given by its coefficients c[0..N-1] (RAII).
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

/// The coefficients of a FLINT polynomial of degree <= 4 as Integers (out[0..deg]); returns deg.
inline int integer_coefficients(const fmpz_poly_t p, std::array<Integer, 5>& out) {
  const slong n = fmpz_poly_degree(p);
  for (slong i = 0; i <= n; ++i) fmpz_get_mpz(out[static_cast<std::size_t>(i)].mpz(), fmpz_poly_get_coeff_ptr(p, i));
  return static_cast<int>(n);
}

/// The polynomial with coefficients p (index = power) written into FLINT's `out` (fresh or zero).
inline void to_flint(fmpz_poly_struct* out, const std::vector<Integer>& p) {
  fmpz_t c;
  fmpz_init(c);
  for (std::size_t i = 0; i < p.size(); ++i) {
    fmpz_set_mpz(c, p[i].mpz());
    fmpz_poly_set_coeff_fmpz(out, static_cast<slong>(i), c);
  }
  fmpz_clear(c);
}

/// The coefficients of a FLINT polynomial (index = power; empty for the zero polynomial).
inline std::vector<Integer> from_flint(const fmpz_poly_t p) {
  std::vector<Integer> out;
  fmpz_t c;
  fmpz_init(c);
  for (slong i = 0; i <= fmpz_poly_degree(p); ++i) {
    fmpz_poly_get_coeff_fmpz(c, p, i);
    Integer z;  // fresh object: written through its mpz_t
    fmpz_get_mpz(z.mpz(), c);
    out.push_back(z);
  }
  fmpz_clear(c);
  return out;
}

}  // namespace relpos::detail
