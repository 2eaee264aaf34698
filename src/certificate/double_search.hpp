// The crossing certificate's search in doubles (math.md §8): bisection on lambda for e(x(lambda)) = 0
// along the curve of stationary points, a search only -- every candidate it proposes is checked
// exactly by the caller -- with the exact dyadic arithmetic its candidates need.
#pragma once

#include <gmp.h>

#include <array>
#include <functional>
#include <optional>
#include <utility>

#include "anysize/exact.hpp"
#include "certificate/curve.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::certificate {

/// Tight enclosures of a point's coordinates (forms::tight_interval).
using Enclosure3 = std::array<std::pair<double, double>, 3>;
/// A bracket of lambda from the double search (good end first: e(x) <= 0 there in doubles).
using DoubleBracket = std::optional<std::pair<double, double>>;
/// What a search does with a candidate point: the point, and its enclosure when the search has one
/// (a point of doubles), else null.
using Consider = std::function<void(const V3&, const std::optional<Enclosure3>*)>;

/// The enclosure of a rational point; nullopt beyond the double range.
std::optional<Enclosure3> enclosure(const V3& x);
/// The same for a point of finite doubles: the points themselves (-0 taken as 0, as the rational it
/// converts to).
Enclosure3 enclosure(const double x[3]);

/// out = a - b 2^-shift in lowest terms (out distinct from a and b). The points of the double
/// search and their pulls are dyadic: then by shifts and one subtraction, where mpq_sub takes gcds.
void difference(mpq_ptr out, mpq_srcptr a, mpq_srcptr b, mp_bitcnt_t shift);

/// The centre -M^{-1} m solved in doubles (Cramer's rule), as exact rationals (the doubles
/// themselves into `doubles`); nullopt when it is not finite. An approximation: the caller checks it.
std::optional<V3> approximate_centre(const DoubleMatrix4& e, double doubles[3]);

/// The curve search of crossing_points in doubles on the matrices em, pm: bisection on lambda for
/// e(x(lambda)) = 0, lambda > 0 for the inside point (while `inside` is empty) and lambda in
/// (lambda_s, 0) for the outside one (while `outside` is empty); the point found, and the same point
/// pulled towards `centre` (exact rationals), go to `consider`, which sets `inside` and `outside`.
/// Each bisection's last bracket goes to brackets[0] (inside) and brackets[1] (outside): a start
/// for the exact search when the point itself is beyond doubles.
void double_curve_search(const DoubleMatrix4& em, const DoubleMatrix4& pm, const anysize::LambdaS& lambda_s,
                         const V3& centre, const std::optional<V3>& inside, const std::optional<V3>& outside,
                         const Consider& consider, DoubleBracket (&brackets)[2]);

}  // namespace relpos::detail::certificate
