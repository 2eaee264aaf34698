// The doubles a float code holds: the double nearest an exact rational (what a float program reads
// for a parameter known exactly), and the exact text of a double (what reproduces it exactly).
#pragma once

#include <string>

#include "relpos/numbers.hpp"

namespace relpos::detail::oracle {

/// The double nearest q, ties to the even significand (IEEE round to nearest, as a correctly
/// rounding decimal reader gives it). Throws InputError beyond the largest finite double.
double nearest_double(const Rational& q);

/// The exact value of a finite double as the shortest exact text: "3", "-7/2", "5404319552844595/18014398509481984".
std::string exact_text(double x);

}  // namespace relpos::detail::oracle
