// A polynomial over Z as FLINT's fmpz_poly and back: the conversions the root code needs around
// FLINT's discriminant, gcd, factorisation and arithmetic modulo word primes (roots.hpp,
// modular.hpp).
#pragma once

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>

#include <array>
#include <cstddef>

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

}  // namespace relpos::detail
