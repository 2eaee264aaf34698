// Interval enclosures of a quadric's matrix for the interval stage, scaled by a power of two that
// brings the largest entry near 1 (guards interval overflow and underflow; a positive scaling of
// either matrix changes no decision, math.md §1). Call each with the rounding mode towards +inf
// (CGAL::Protect_FPU_rounding).
#pragma once

#include <CGAL/Interval_nt.h>

#include "algebra/matrix_view.hpp"
#include "relpos/quadric.hpp"

namespace relpos::detail::forms {

using Interval = CGAL::Interval_nt<false>;

/// Entries of a matrix of exact doubles: a point interval times a power of two encloses the scaled
/// entry even if the product underflows.
MatrixOf<Interval> to_intervals(const DoubleMatrix4& m);

/// The stored enclosures of a quadric read from text, scaled by 2^k (largest bound near 1).
MatrixOf<Interval> to_intervals(const detail::EnclosureMatrix4& m);

/// Enclosures of the entries of m scaled by 2^k (largest near 1) without rational temporaries
/// (mpq_get_d truncates towards zero, so q lies between v and the next double away from zero).
MatrixOf<Interval> to_intervals(const Matrix4& m);

}  // namespace relpos::detail::forms
