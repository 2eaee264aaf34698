// Float baselines for an ellipsoid against a general quadric (general_bench; doc/performance.md,
// "General quadrics"): what a float code would write, nothing certified. Compiled in its own
// translation unit without -frounding-math (general_float.cpp), as naive_double.cpp is.
#pragma once

#include <array>

#include "relpos/general_classify.hpp"

namespace bench {

using DoubleMatrix4 = std::array<double, 16>;

/// The float decision of the general pencil (doc/math.md §16 and §17) in plain doubles: the
/// characteristic quartic f(t) = det(Q + tE) with the root 0 of multiplicity 4 - rank Q that Q's type
/// fixes divided out, its Sturm sequence, the extreme roots of D(t) = det(B + tM) by Newton, and the
/// sign rule (E, then I, then O for two ellipsoids, else C). It never reports a tangency.
relpos::QuadricPosition pencil_float(const DoubleMatrix4& e, const DoubleMatrix4& q, relpos::QuadricType type);

/// Wang–Wang–Kim's separation test in doubles (doc/math.md §6, doc/performance.md): the quartic
/// f(t) = det(Q + tE) by cofactor expansion and the number of its distinct positive roots by a Sturm
/// sequence of polynomial remainders; separated when there is one (two, in exact arithmetic). It
/// answers only "separated or not", and only for ellipsoids (and elliptic paraboloids) is that the
/// exact criterion.
bool wwk_separated(const DoubleMatrix4& e, const DoubleMatrix4& q);

}  // namespace bench
