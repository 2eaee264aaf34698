// The two float decisions ordinary_bench measures relpos against, written here in plain doubles (no
// relpos code, no certification: what a user's float pipeline would be). Both read the 32 doubles
// of a pair, P and E row-major, and return a position or nullopt when their rule does not decide.
//
//   minimal_float_decision  the cheapest decision: the characteristic quartic f(λ) = det(λP + E)
//                           (math.md §2), the sign of its discriminant, and a sign rule:
//                             Disc(f) < 0  -> C  (two real roots and a non-real pair: contact)
//                             Disc(f) > 0  -> sign changes of (f4, f3, f2, f1, f0), read as the
//                                             number of positive roots (Descartes' rule, exact when
//                                             all four roots are real): 2 -> E, 0 -> I, 4 -> nullopt
//                             Disc(f) = 0  -> tangent: TE if a sign change, else TI
//                           It assumes that Disc(f) > 0 means four real roots and that the ellipsoid
//                           is small; it is wrong where either fails.
//   paper_float_decision    the paper's decision (math.md §3-§5): f, the Sturm-Habicht sequence of
//                           f counting real, negative and positive roots, s(λ) = det(λA + M) and the
//                           smallness test ρ ≤ 1, then the table of math.md §3 (nullopt for a body
//                           that is not small unless the table's any-size rows decide, or where a
//                           sign the table needs is zero).
#pragma once

#include <array>
#include <optional>

#include "relpos/position.hpp"

namespace ordinary {

using Matrix = std::array<double, 16>;

/// Coefficients of f(λ) = det(λP + E), index = power of λ.
std::array<double, 5> characteristic_quartic(const Matrix& p, const Matrix& e);

std::optional<relpos::Position> minimal_float_decision(const Matrix& p, const Matrix& e);
std::optional<relpos::Position> paper_float_decision(const Matrix& p, const Matrix& e);

}  // namespace ordinary
