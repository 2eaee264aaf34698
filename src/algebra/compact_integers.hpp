// The compact integer form of a pair, what the exact decisions read (math.md §11): far smaller
// integers than one common lcm of both matrices, with every root of f and s scaled by one positive
// constant.
#pragma once

#include <gmp.h>

#include <array>

#include "relpos/quadric.hpp"

namespace relpos::detail::forms {

/// The smallest integer form the *decisions* need (not the evidence: the roots move). With
/// D = diag(1, 1, 1, t), t the lcm of the denominators of both translation columns, and positive
/// alpha, beta clearing the remaining denominators of D E D and D P D and dividing out each form's
/// content (each matrix's scale is forgotten):
///   det(lambda beta DPD + alpha DED) = t^2 alpha^4 f(beta lambda / alpha),
///   det(lambda beta A + alpha M)     = alpha^3 s(beta lambda / alpha),
/// so every root of f and s is multiplied by the same alpha / beta > 0: signs, multiplicities,
/// common roots and rho are unchanged, with far smaller integers than one common lcm.
/// The two forms are written into the caller's integers (16 distinct mpz each, row-major).
void to_compact_integers(const Matrix4& p, const Matrix4& e, const std::array<mpz_ptr, 16>& pz,
                         const std::array<mpz_ptr, 16>& ez);

}  // namespace relpos::detail::forms
