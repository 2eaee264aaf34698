// The position at one instant t* of a motion where f(., t*) = det(l P + E(t*)) has a multiple
// root, for an ellipsoid of any size (math.md §7, "The position at an instant").
//
// The decision reads the definiteness of the pencil M(l) = l P + E(t*) (the S-lemma facts behind the
// certificates):
//   E  <=> M(l) positive definite for some l > 0;      I  <=> the same for some l < 0;
//   TE <=> not E and M(l) positive semidefinite for some l > 0;  TI likewise with l < 0;  C otherwise.
// The set {l : M(l) > 0} is an open interval (convex, and bounded because P is indefinite) whose ends
// are consecutive distinct real roots of f, and it never contains 0 (E(t*) is indefinite): so E or I
// is a positive-definiteness test at the midpoint of two consecutive roots, and where that set is
// empty the semidefinite set is at most one point, a root of f. At such t* every real root of f lies
// in K(sqrt D), K = Q(t*) (the subresultants of f and df/dl give them: one double root and a
// quadratic cofactor, a triple root, two double roots, or a quadruple root), so every test is the
// sign of U + W sqrt(D) with U, W, D polynomials in t, decided from the signs of U, W and
// U^2 - W^2 D at t*. Neither smallness nor the root lambda_s of s is needed.
#pragma once

#include <CGAL/Polynomial.h>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "algebra/forms.hpp"
#include "relpos/classify.hpp"
#include "relpos/numbers.hpp"

namespace relpos::detail {

using PolyZ = CGAL::Polynomial<Integer>;          // polynomials in t
using PencilZ = CGAL::Polynomial<PolyZ>;          // polynomials in l over Z[t]
using SignAt = std::function<int(const PolyZ&)>;  // the exact sign of a polynomial in t at t*

/// What the decision needs from the moving pencil (all with integer coefficients, positive multiples
/// of the true quantities): P and E(t) (the same scaled matrices f was computed from), f's
/// coefficients, the Sturm-Habicht principal data g2, g1 and Disc f (sturm.hpp).
struct InstantPencil {
  InstantPencil(const forms::MatrixOf<PolyZ>& p, const forms::MatrixOf<PolyZ>& e, const std::array<PolyZ, 5>& f,
                const PolyZ (&g2)[3], const PolyZ (&g1)[2], const PolyZ& disc);

  std::array<PolyZ, 5> f;
  PolyZ g2[3], g1[2], disc;
  /// The 14 principal minors of M(l) of sizes 1 to 3 (polynomials in l), smallest first (the one of
  /// size 4 is f itself).
  std::vector<PencilZ> minors;
  std::array<std::size_t, 3> leading{};  ///< indices in `minors` of the leading minors of sizes 1, 2, 3
};

struct InstantDecision {
  Position position = Position::C;
  int j = 0;  ///< degree of gcd(f, df/dl) at t*
  std::string how;
};

/// The position at t* when f(., t*) has a multiple root; nullopt when f(., t*) is square-free (then
/// the position is open -- E, I or C -- and equals that of both neighbouring intervals). With
/// `known_multiple` the test Disc f(t*) = 0 is skipped (t* is a zero of Disc f). Throws
/// std::logic_error on a root configuration the theory excludes.
std::optional<InstantDecision> decide_at_instant(const InstantPencil& pencil, const SignAt& sign, bool known_multiple);

}  // namespace relpos::detail
