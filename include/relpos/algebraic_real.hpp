// An exact real algebraic number given by a square-free integer polynomial and an isolating
// interval: how relpos reports instants that are roots of polynomials in time (math.md §7),
// such as a first-contact time t* = sqrt(2).
//
// Nothing here is decided in floating point. Refinement bisects the isolating interval on the exact
// sign of the polynomial at rational midpoints, and decimals() stops only when both ends of the
// interval round to the same decimal string, which is then the correctly rounded value of the
// number (rounding to nearest is monotone, so every point of the interval rounds the same way).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "relpos/numbers.hpp"

namespace relpos {

class AlgebraicReal {
 public:
  /// The rational q (its polynomial is den(q) t - num(q)).
  static AlgebraicReal rational(const Rational& q);
  /// The only root of the square-free integer polynomial `coefficients` (index = power of t) in
  /// the open interval (lower, upper), where the polynomial has opposite non-zero signs at the ends.
  /// The polynomial is replaced by its irreducible factor that vanishes there (FLINT), so that
  /// polynomial() is the minimal polynomial and a rational root becomes rational().
  /// Throws std::invalid_argument when the ends do not show a sign change. `irreducible`: the
  /// caller guarantees that the polynomial is already irreducible over Q (no factorisation).
  static AlgebraicReal root(std::vector<Integer> coefficients, Rational lower, Rational upper,
                            bool irreducible = false);

  bool is_rational() const { return exact_.has_value(); }
  /// The value when it is rational (then lower() == upper() == value).
  const std::optional<Rational>& exact() const { return exact_; }
  /// Isolating interval: the number lies in [lower, upper], strictly inside when it is irrational.
  const Rational& lower() const { return lower_; }
  const Rational& upper() const { return upper_; }
  /// Defining polynomial, index = power of t: irreducible over Q, primitive, positive leading
  /// coefficient (the minimal polynomial times an integer); den t - num for a rational.
  const std::vector<Integer>& polynomial() const { return poly_; }

  /// Bisect (exact signs) until upper - lower <= width. No-op for a rational. Throws
  /// std::invalid_argument when width <= 0 (bisection would never end).
  void refine(const Rational& width);
  /// Correctly rounded decimal with `digits` significant digits (round to nearest, ties away from
  /// zero; exact for a rational), in the format of relpos::to_decimal.
  std::string decimals(int digits) const;
  /// Nearest double of the value (for display and float baselines only).
  double to_double() const;
  /// Exact comparison with a rational: -1, 0, +1 for this <, =, > q.
  int compare(const Rational& q) const;
  /// Exact comparison with another algebraic real: -1, 0, +1 for this <, =, > other. Equal
  /// numbers have the same minimal polynomial; two roots of one polynomial are equal when the
  /// intersection of their isolating intervals holds a root, and different numbers are told apart by
  /// bisecting both intervals until they are disjoint.
  int compare(const AlgebraicReal& other) const;

 private:
  AlgebraicReal() = default;
  int sign_at(const Rational& x) const;
  std::vector<Integer> poly_;
  std::optional<Rational> exact_;
  Rational lower_, upper_;
  int sign_lower_ = 0;  ///< sign of the polynomial at lower_ (irrational case)
};

/// Text of an integer polynomial in t, e.g. "t^2 - 2".
std::string polynomial_text(const std::vector<Integer>& coefficients, const std::string& variable = "t");

}  // namespace relpos
