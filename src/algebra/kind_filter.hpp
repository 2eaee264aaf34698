// The affine type of a quadric given as 16 doubles, as a filtered predicate: classify_quadric's
// answer (quadric.hpp) without its rationals, for the matrices the shape tests of from_doubles
// refuse, so that a refusal costs a few microseconds instead of an exact classification (~100 us;
// doc/oracle.md, "Refused matrices"). The inertia of Q3 comes from the signs of its leading
// principal minors d1, d2, d3 (Jacobi: as many negative eigenvalues as sign changes in 1, d1, d2,
// d3, when none is zero), and with Q3 non-singular Q is congruent to diag(Q3, det Q / det Q3), so
// the sign of det Q settles the rest. Each sign is certified by interval arithmetic, else computed
// exactly on integers (the doubles are integers times one power of two).
#pragma once

#include <optional>

#include "relpos/quadric.hpp"

namespace relpos::detail::shape_filter {

/// classify_quadric(d) when d is symmetric, finite, and its leading minors d1, d2, d3 and det d are
/// non-zero (then the type is one of ellipsoid, imaginary ellipsoid, hyperboloid of one or two
/// sheets); nullopt otherwise (the exact path decides).
std::optional<QuadricKind> certified_kind(const DoubleMatrix4& d);

}  // namespace relpos::detail::shape_filter
