// The plain data types of the public API that describe polynomials and their roots: coefficient
// arrays of the quartic f and the quadratic s (math.md §2), one certified real root, and the
// root facts the classification table reads (math.md §3 and §6). The algorithms that compute
// them are private (src/algebra/pencil.hpp, src/algebra/roots.hpp).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "relpos/numbers.hpp"

namespace relpos {

/// Coefficients of a polynomial, index = power of lambda.
template <class NT>
using Quartic = std::array<NT, 5>;
template <class NT>
using Quadratic = std::array<NT, 3>;

/// A polynomial over Q, index = power of its variable (low degree first); the empty vector is the
/// zero polynomial. The one type of the motions' polynomials in time and of the exact polynomials
/// in lambda of math.md §8.
using RationalPolynomial = std::vector<Rational>;

/// p(x), exactly (Horner's scheme).
Rational evaluate(const RationalPolynomial& p, const Rational& x);

/// One distinct real root of f with certified information.
struct RealRoot {
  int sign = 0;                   ///< -1 or +1 (0 is never a root)
  int multiplicity_f = 1;         ///< multiplicity as a root of f
  int multiplicity_s = 0;         ///< multiplicity as a root of s (0, 1 or 2)
  std::optional<Rational> exact;  ///< the root itself when it is rational
  Rational lower, upper;          ///< isolating interval: the root is the only root of f in it
  /// The multiplicity rule of math.md §3. It characterises tangency for *small* pairs; for a
  /// pair that is not small a root can be a tangency with a smaller excess (e.g. contact along a
  /// circle), so outside smallness read it only as "multiple in f~".
  bool tangency() const { return multiplicity_f - multiplicity_s >= 2; }
};

/// The facts the classification needs, without isolating any root.
struct RootFacts {
  int real = 0, negative = 0, positive = 0;        ///< distinct real roots of f
  int nonreal = 0;                                 ///< non-real roots of f, with multiplicity
  int nonreal_multiple = 0;                        ///< non-real roots of multiplicity >= 2
  int tangent_negative = 0, tangent_positive = 0;  ///< distinct multiple real roots of f~, by sign
  int sign_disc_f = 0, sign_disc_ftilde = 0;
  int degree_ftilde = 4;
};

}  // namespace relpos
