// The exact stage of a general pair (math.md §17): the real roots of f and D isolated and compared
// exactly (CGAL's univariate algebraic kernel), the facts of math.md §16 read off them, and, for the
// evidence, the numbers the certificate is built from.
#pragma once

#include <optional>
#include <vector>

#include "general/decision.hpp"
#include "general/integer_pencil.hpp"
#include "relpos/general_classify.hpp"

namespace relpos::detail::general {

/// The facts of math.md §16 from the exact roots.
PencilFacts exact_facts(const IntegerPencil& p, bool ellipsoid);

/// The exact numbers behind a decided position, in the multiplier s of the integer pencil
/// (t = s * p.scale).
struct ExactEvidence {
  PencilFacts facts;
  QuadricVerdict verdict;
  std::vector<PencilRoot> roots;  ///< distinct real roots of f and D, increasing (in s)
  /// E, I, O: a short rational s inside the side's interval with f(s) > 0 (then Qz + s Ez is definite).
  std::optional<Rational> definite;
  /// TE, TI, TO at a root inside the side's interval: that double root, rational (math.md §18).
  std::optional<Rational> tangent;
  /// TE, TI, TO at the end of the interval: the end s* = a + b sqrt(d), a root of D of degree <= 2
  /// (math.md §18: never a cubic irrational).
  std::optional<QuadraticNumber> endpoint;
  Integer d;
};

/// Everything above for a pair (the facts, the verdict, the roots and the certificate's numbers).
ExactEvidence exact_evidence(const IntegerPencil& p, bool ellipsoid);

}  // namespace relpos::detail::general
