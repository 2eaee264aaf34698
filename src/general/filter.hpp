// The certified double filter of a general pair (math.md §17): f = det(Q + t E) and D = det(B + t M)
// in doubles with running error bounds, the extreme roots of D bracketed by certified signs
// (Budan–Fourier, exact for the real-rooted D), and the real roots of f / t^k counted in the
// multipliers' intervals by its Sturm–Habicht sequence at the brackets' ends. Every sign it reads is
// certified; when one is not, it answers nothing and the exact stage decides.
#pragma once

#include <optional>

#include "relpos/general_classify.hpp"

namespace relpos::detail::general {

/// What the filter can certify, or nullopt. Stage Filter.
std::optional<QuadricVerdict> filtered_decision(const Ellipsoid& e, const Quadric& q);

/// The structure the type fixes (math.md §17): f = t^k f^ and D = t^j D^ with f^(0), D^(0) != 0 (k is
/// a lower bound for a cone, whose f^(0) vanishes when its apex is on E), and the numbers of positive
/// and negative roots of D^ (Sylvester's law of inertia: the signs of B's eigenvalues, negated).
struct Structure {
  int k, j, positive, negative;
  bool ellipsoid;
};
Structure structure_of(QuadricType type);

}  // namespace relpos::detail::general
