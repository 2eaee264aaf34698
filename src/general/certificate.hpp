// The certificate of a general pair's answer (math.md §18), from the exact evidence.
#pragma once

#include "general/exact.hpp"
#include "relpos/general_position.hpp"

namespace relpos::detail::general {

/// The certificate of ev's verdict for the stored (sign-normalized) matrices e and q; `scale` turns
/// the integer pencil's multipliers s into multipliers t = s * scale of Q + t E. Throws
/// std::logic_error (internal error) when the evidence does not yield one (never: every position has
/// its certificate, math.md §18).
QuadricCertificate build_certificate(const Matrix4& e, const Matrix4& q, const ExactEvidence& ev,
                                     const Rational& scale);

}  // namespace relpos::detail::general
