// Stage 1' of classify(): the decision signs in double arithmetic once more, now with an error
// bound computed from the actual magnitudes of the operands (CGAL's "semi-static" filters,
// Shewchuk's error bound from the permanent) instead of the a-priori bound of stage 1.
//
// Stage 1's bound is derived for the worst entries in [-1, 1], so it fails when a decision quantity
// is small *relative to that worst case* although far from zero relative to its own terms -- e.g. a
// small ellipsoid deep inside the cup, where the quartic's roots cluster around the special roots
// of s and Disc(f) is tiny in absolute terms. The same generic formulas evaluated on RunningBound
// (running_bound.hpp: value, magnitude program, operation count; round-to-nearest, no contraction)
// certify most of these at about twice the cost of stage 1, without the rounding-mode switch and
// the four-products-per-multiplication of interval arithmetic (stage 2).
#pragma once

#include <optional>

#include "filters/static_filter.hpp"
#include "relpos/quadric.hpp"

namespace relpos {

/// Certified signs of every decision quantity (as static_filter_signs) for matrices normalized by
/// power_of_two_normalized() (storage_of(quadric).filter_doubles(), quadric.hpp).
/// Uncertain where the running bound does not separate a value from zero. Requires the rounding
/// mode to be round-to-nearest (the caller checks it).
DecisionSigns semi_static_filter_signs_normalized(const DoubleMatrix4& p, const DoubleMatrix4& e);

/// The same for rational matrices (entries that are not doubles): each entry enters as a double
/// enclosure (RunningBound::enclosing), with the count tracked per pair. About ten times cheaper than
/// the interval stage, which converts every entry with CGAL::to_interval and switches the rounding mode.
DecisionSigns semi_static_filter_signs(const Matrix4& p, const Matrix4& e);

/// The same from stored enclosures (a quadric read from decimal text, io's fast reader).
DecisionSigns semi_static_filter_signs(const detail::EnclosureMatrix4& p, const detail::EnclosureMatrix4& e);

/// Only what the discriminant route reads (as static_filter_discriminant_signs_normalized, with
/// smallness): the signs of f's coefficients, of Disc(f) from the invariants, vertex and graeffe,
/// from stored enclosures; g2 and g1 stay uncertain.
DecisionSigns semi_static_filter_discriminant_signs(const detail::EnclosureMatrix4& p,
                                                    const detail::EnclosureMatrix4& e);

/// The gap test of math.md §8 (anysize/gap.hpp) on RunningBoundLanes from power-of-two
/// normalized matrices: true (a root of f above lambda_s), false, or nullopt when uncertain.
std::optional<bool> semi_static_roots_above_lambda_s(const DoubleMatrix4& p, const DoubleMatrix4& e);

/// The signs for the ellipsoid e (normalized exact doubles, as filter_doubles()) moved by d (exact
/// doubles; the centre moves by +d) against p, without forming the moved ellipsoid: its entries
/// e - M d and e0 - 2 e.d + d^T M d are evaluated with their error carried along, then the same
/// quantities as above. For trackers and moving bodies: a frame costs a few hundred nanoseconds
/// instead of constructing an Ellipsoid. Uncertain when a bound does not separate or d is out of range.
DecisionSigns semi_static_filter_signs_translated(const DoubleMatrix4& p, const DoubleMatrix4& e,
                                                  const std::array<double, 3>& d);

/// The same for rational matrices (entries enter as double enclosures; counts tracked per call).
DecisionSigns semi_static_filter_signs_translated(const Matrix4& p, const Matrix4& e, const std::array<double, 3>& d);

}  // namespace relpos
