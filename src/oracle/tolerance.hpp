// Judging within a tolerance (doc/oracle.md, "Tolerance"): a float answer is excused when it is the
// position of the pair with the ellipsoid scaled about its centre by some factor in [1 - tau, 1 + tau].
// The scaled ellipsoids are nested, so with s* (the factor at which the scaled ellipsoid first
// touches the paraboloid) the position at factor s > 0 is I (E) below s*, TI (TE) at s* and C above
// it when the centre is inside (outside) the paraboloid, and C for every s when the centre lies on it
// (s* = 0). Everything is decided exactly from the margin's rational enclosure and polynomial.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "relpos/position.hpp"

namespace relpos::detail::oracle {

/// s*, the number alone, as a margin member of an answer line gives it: the only root of
/// `polynomial` (integer coefficients, lowest degree first) in [lo, hi], or lo itself when lo = hi.
/// Not relpos::Margin (margin.hpp), which is margin()'s result with the proof of s* (the
/// certificates at lo and hi, the nearest double): the judge reads the number from a line another
/// run wrote and decides with it, so it keeps neither the proof nor the double.
struct MarginValue {
  Rational lo, hi;
  std::vector<Integer> polynomial;
};

/// The margin of a JSON object {"lo": "p/q", "hi": "p/q", "polynomial": ["c0", ...], ...} (other
/// members, "approx" included, are not read: nothing is decided on them). Throws InputError naming
/// what is wrong: a missing or malformed member, lo > hi, lo < 0, or lo < hi without a change of sign
/// of the polynomial between them (no root to speak of).
MarginValue margin_from_json(const nlohmann::ordered_json& j);

/// The sign of t - s*, exactly: by the enclosure when t lies outside it, else by the sign of the
/// polynomial at t against its sign at lo.
int compare_with(const Rational& t, const MarginValue& m);

/// Where the ellipsoid's centre lies.
enum class CentreSide { Inside, On, Outside };

/// Whether `answer` is the position of the pair scaled by some factor s in [1 - tau, 1 + tau], s > 0.
bool within_tolerance(Position answer, CentreSide side, const MarginValue& m, const Rational& tau);

}  // namespace relpos::detail::oracle
