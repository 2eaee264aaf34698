// Exact signs of a polynomial over Q at rationals, on a positive integer multiple of it (math.md §8,
// the certificates' searches): sum z_k n^k d^(deg - k) for x = n / d, d > 0 -- integer products only,
// where a rational Horner scheme canonicalizes at every step -- and the Newton step of the exact
// searches on the same integers.
#pragma once

#include <flint/fmpz_poly.h>

#include <cstddef>
#include <optional>
#include <vector>

#include "anysize/exact.hpp"
#include "relpos/numbers.hpp"

namespace relpos::detail {

/// A positive integer multiple of a polynomial (the same signs), coefficients z[0..deg].
class IntegerPoly {
 public:
  IntegerPoly() = default;
  /// From integer coefficients z[0..n) (a positive multiple of the polynomial: the same signs).
  IntegerPoly(const Integer* z, std::size_t n);
  /// q times the lcm of its denominators.
  explicit IntegerPoly(const anysize::Poly& q);
  /// From a FLINT polynomial's coefficients, kept as they are.
  explicit IntegerPoly(const fmpz_poly_t q);

  /// The exact sign at x.
  int sign(const Rational& x) const;
  /// The Newton step t - q(t)/q'(t) from t = n/d rounded down to a multiple of 2^e, on integers
  /// (one division, no canonicalization); nullopt where q' vanishes.
  std::optional<Rational> newton_floor(const Rational& t, long e) const;
  /// The integer coefficients into a FLINT polynomial.
  void to_flint(fmpz_poly_t out) const;

  std::size_t degree() const { return z_.empty() ? 0 : z_.size() - 1; }
  const Integer* data() const { return z_.data(); }
  std::size_t bits() const { return bits_; }  ///< the largest coefficient's bit length

 private:
  std::vector<Integer> z_;
  std::size_t bits_ = 0;
};

}  // namespace relpos::detail
