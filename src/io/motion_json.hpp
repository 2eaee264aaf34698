// The polynomials of a rigid motion read from exact JSON trees, as `relpos motion` and the Python
// package take them (doc/cli.md, "relpos motion"), within the limits of doc/cli.md ("Limits").
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/json_tree.hpp"
#include "relpos/numbers.hpp"

namespace relpos::detail::io {

/// Limits on the polynomials of a rigid motion (doc/cli.md, Limits): the event polynomials' degree
/// and coefficient sizes grow with these, and the cost with them.
inline constexpr std::size_t kMaxMotionDegree = 12;
inline constexpr std::size_t kMaxMotionCoefficientBits = 512;

/// The `count` polynomials in t of a rigid motion's translation (3) or quaternion (4): a JSON array
/// of `count` entries, each an array of exact coefficients (lowest degree first) or one number (a
/// constant); trailing zeros dropped. Throws InputError naming the field (`role`[i][k]) on a
/// non-number or beyond the limits above.
std::vector<std::vector<Rational>> motion_polynomials(const Json& value, std::size_t count, const std::string& role);

}  // namespace relpos::detail::io
