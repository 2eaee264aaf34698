// The human-readable reports' pieces beside classification_to_text (relpos/io.hpp), defined in
// report_text.cpp: what a position means, the rho comparison, a polynomial and a margin as text.
#pragma once

#include <string>

#include "relpos/io.hpp"

namespace relpos::detail::io {

/// One sentence saying what a position means ("the ellipsoid lies inside the paraboloid ...").
std::string position_meaning(Position p);

/// "<1", "=1", ">1".
std::string rho_vs_one_text(int sign);

/// A polynomial with exact coefficients (index = power) as text: "3*l^4 - 1/2*l^2 + 7".
std::string polynomial_to_text(const Rational* coefficients, int size, const std::string& variable = "l");

/// Three or four lines of text for `relpos classify --margin` (ends with a newline).
std::string margin_to_text(const Margin& m, const relpos::io::RenderOptions& options = {});

}  // namespace relpos::detail::io
