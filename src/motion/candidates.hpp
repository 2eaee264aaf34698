// The candidate instants of a motion: the real zeros in [t0, t1] of the event polynomials
// (moving_pencil.hpp), each with its minimal polynomial (an irreducible factor over Z, FLINT) and
// its exact value when that is linear; a rational strictly between two of them (the samples of the
// open intervals); and the exact sign of a polynomial in t at one of them (instant_sign.cpp).
#pragma once

#include <CGAL/Algebraic_kernel_d_1.h>

#include <optional>
#include <vector>

#include "motion/instant_position.hpp"
#include "relpos/algebraic_real.hpp"
#include "relpos/numbers.hpp"

namespace relpos::detail {

using AK = CGAL::Algebraic_kernel_d_1<Integer>;
using Alg = AK::Algebraic_real_1;

/// A candidate instant: a real zero of an event polynomial, with its causes (kCause... bits).
struct Candidate {
  Alg t;
  unsigned causes = 0;
  std::optional<Rational> exact;
  PolyZ minimal;
  std::vector<Integer> minimal_coefficients;
  /// The public exact form (minimal polynomial + isolating interval), built on first use; its
  /// interval is refined by fast bisection on exact integer signs when a sign needs precision.
  mutable std::optional<AlgebraicReal> instant;
};

/// A candidate at t with the given cause, exact value (when rational) and minimal polynomial.
Candidate make_candidate(const Alg& t, unsigned cause, std::optional<Rational> exact, std::vector<Integer> minimal);

/// The public exact form of an instant: rational, or minimal polynomial + isolating interval whose
/// ends show a strict sign change (CGAL's interval refined until they do).
AlgebraicReal& instant_of(const Candidate& z);

/// Merge the real zeros of p in [lo, hi] into the sorted list `out` (exact comparisons; a zero
/// shared by several polynomials is kept once with all its causes).
void add_zeros(const AK& ak, const PolyZ& p, unsigned cause, const Rational& lo, const Rational& hi,
               std::vector<Candidate>& out);

/// A rational strictly between two algebraic reals a < b: the one of smallest denominator between
/// their isolating intervals, refined until disjoint (a motion's interval sample).
Rational rational_between(const Alg& a, const Alg& b);

/// The exact sign of p(t*) at a candidate instant t*.
int sign_at(const AK& ak, const PolyZ& p, const Candidate& z);

}  // namespace relpos::detail
