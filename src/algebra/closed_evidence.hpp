// The full evidence of a decimal sphere and an unrotated standard paraboloid (its vertex anywhere), from
// closed forms on the numbers read (decimal_recipe.hpp): f, s, lambda_s and rho on short integers.
#pragma once

#include "algebra/decimal_recipe.hpp"
#include "relpos/numbers.hpp"
#include "relpos/polynomials.hpp"

namespace relpos::detail::forms {

/// Where sphere_standard_evidence writes: f and s in lowest terms, lambda_s and rho.
/// With the exponents of 2 and 5 in S = lcm(lp, le), the lcm of the two integer forms' scales
/// (their rest is lcm(R_a^2, R_b^2), R the parts of a's and b's mantissas prime to 10), also the
/// common-lcm integer forms S^4 f and S^3 s.
struct ClosedEvidence {
  Quartic<Rational>& f;
  Quadratic<Rational>& s;
  Rational& lambda_s;
  Rational& rho;
  unsigned long s_twos, s_fives;
  Quartic<Integer>& f_multiple;    ///< S^4 f (fresh Integers: written in place)
  Quadratic<Integer>& s_multiple;  ///< S^3 s
};

/// Whether sphere_standard_evidence takes the pair: a sphere and an unrotated standard paraboloid,
/// both of decimal numbers, the vertex anywhere (f and s do not see a common translation, math.md §2).
bool has_closed_evidence(const detail::DecimalRecipe& sphere, const detail::DecimalRecipe& paraboloid);

/// The reported f = det(lambda P + E) and s = det(lambda A + M), lambda_s and rho of a sphere E
/// and a standard paraboloid P (has_closed_evidence), from closed forms (math.md §2, §5). With
/// A = 1/a^2, B = 1/b^2, x and y the centre's less the vertex's, w = vz - z, E's block is the
/// identity and P's is diag(A, B, 0):
///   f0 = -r^2,  f1 = A (x^2 - r^2) + B (y^2 - r^2) + w,  f2 = A B (x^2 + y^2 - r^2) + (A + B) w - 1/4,
///   f3 = A B w - (A + B) / 4,  f4 = -A B / 4,  s = (1 + A lambda)(1 + B lambda),
/// so lambda_s, the root of s nearest 0, is -min(a, b)^2 and rho = (f0 / f4)(s2 / s0) / lambda_s^2
/// = (2 r / min(a, b)^2)^2. Each coefficient is a short integer over 2^i 5^j and the squares of the
/// parts of a's and b's mantissas prime to 10, reduced by a bit scan, single-limb remainders and
/// word gcds with those two parts: the same rationals as the general path (the integer forms'
/// determinants reduced along their scales), without their long integers. S^k times a coefficient
/// n 2^i 5^j / (R_a^2 R_b^2) is n 2^(k s_twos + i) 5^(k s_fives + j) lcm(R_a^2, R_b^2)^(k-1) / g^2,
/// g = gcd(R_a, R_b): products, no division of long integers.
void sphere_standard_evidence(const detail::DecimalRecipe& sphere, const detail::DecimalRecipe& paraboloid,
                              const ClosedEvidence& out);

}  // namespace relpos::detail::forms
