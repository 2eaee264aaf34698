// The crossing certificate's exact search (math.md §8): the signs of e and p along the curve
// x(lambda) from two integer polynomials (the secular pair), and the points of the solid with p < 0
// (min side, lambda > 0) and p > 0 (max side, lambda in (lambda_s, 0)) found exactly on it, for what
// the double search (double_search.hpp) did not find.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>

#include "certificate/curve.hpp"
#include "certificate/double_search.hpp"
#include "pair/integer_poly.hpp"

namespace relpos::detail::certificate {

/// The signs of e and p along the curve x(lambda), lambda in (lambda_s, oo), from two polynomials
/// (math.md §8): lambda p + e is f/s at x(lambda), and its derivative in lambda is p(x(lambda))
/// (the envelope theorem), so with s > 0 there
///   p(x(lambda)) s^2 = f' s - f s'   and   e(x(lambda)) s^2 = f s - lambda (f' s - f s').
/// e(x(lambda)) increases on (0, oo) and decreases on (lambda_s, 0) while p(x(lambda)) decreases on
/// both (f/s is concave): the optimisers of p over the solid are x(lambda*) at the root lambda* of
/// the second polynomial, or the limit at lambda_s in the hard case. Only their signs are used, so
/// f and s are taken as positive integer multiples (FLINT's integer products: no rational
/// canonicalisation).
struct Secular {
  detail::IntegerPoly e, p;
  /// The most bisection steps or approximation bits a witness may take before the search is
  /// declared broken: the margin of p at its optimiser and the distance of lambda* to the other
  /// polynomial's roots are algebraic numbers whose size the coefficients bound (root separation),
  /// so a crossing never needs more than a multiple of the coefficient bits.
  std::size_t budget;
  explicit Secular(const PairContext& pr);
};

/// What the exact searches do with a point on the curve (crossing_points' check).
using ConsiderExact = std::function<void(const V3&)>;

/// The exact search for the point with p of sign `want` (-1: min side, lambda > 0; 1: max side,
/// lambda in (lambda_s, 0)) from the double search's last bracket of lambda*, its ends taken exactly
/// and checked (doubles only suggested them). False when the bracket does not hold.
bool refine_from_doubles(const PairContext& pr, const Secular& sec, const DoubleBracket& bracket, int want,
                         std::optional<V3>& found, const ConsiderExact& consider);
/// The point of the solid with p < 0 from the min side, exactly (sets `found` through `consider`).
void min_side_point(const PairContext& pr, const Secular& sec, std::optional<V3>& found, const ConsiderExact& consider);
/// The point of the solid with p > 0 from the max side, exactly, the hard case included.
void max_side_point(const PairContext& pr, const Secular& sec, std::optional<V3>& found, const ConsiderExact& consider);

}  // namespace relpos::detail::certificate
