// Building the certificate of an answer (include/relpos/position.hpp, math.md §8): the
// dual multiplier lambda of the trust-region duality for E, I, TE, TI; lambda_s and the contact set
// in the hard case; two witness points for C. Runs on exact rationals after the position is known.
#pragma once

#include "algebra/forms.hpp"
#include "anysize/exact.hpp"
#include "filters/pooled_integer.hpp"
#include "relpos/polynomials.hpp"
#include "relpos/position.hpp"

namespace relpos::certificate {

/// The integer forms Ez = le E and Pz = lp P of a pair (forms::integer_form), with their scales.
struct IntegerForms {
  forms::MatrixOf<Integer> ez, pz;
  Integer le, lp;
};

/// The certificate of `position` for the pair (which must be the pair's position). Never Kind::None:
/// a certificate that cannot be built throws std::logic_error (an internal error, doc/certificates.md).
Certificate build(const Ellipsoid& e, const Paraboloid& p, Position position);

/// What the caller already knows about the pair, reused instead of recomputed: f = det(lambda P + E)
/// and s = det(lambda A + M) of the sign-normalized matrices, and isolating intervals of the distinct
/// real roots of f (increasing). Between two consecutive isolating intervals f keeps one sign, so
/// a rational there with f > 0 in the right domain is the multiplier of E and I at once.
struct Known {
  const Quartic<Rational>* f = nullptr;
  const Quadratic<Rational>* s = nullptr;
  const std::vector<RealRoot>* roots = nullptr;
  const anysize::LambdaS* lambda_s = nullptr;    ///< lambda_s of *s (set only with f and s)
  const IntegerForms* forms = nullptr;           ///< the integer forms of E and P, with their scales
  const Quartic<Integer>* f_multiple = nullptr;  ///< a positive integer multiple of f, for exact signs
  /// The caller's integer forms of E and P in pooled integers (positive multiples of E and P): the
  /// exact signs of e and p at candidate points without recomputing.
  const forms::MatrixOf<PooledInteger>* ez_pooled = nullptr;
  const forms::MatrixOf<PooledInteger>* pz_pooled = nullptr;
  /// Their scales when they are the integer forms with their scales (ez_pooled = le E): then `forms`
  /// is copied from them on first use (most certificates of C read only the signs).
  const Integer* le_pooled = nullptr;
  const Integer* lp_pooled = nullptr;
};
Certificate build(const Ellipsoid& e, const Paraboloid& p, Position position, const Known& known);
/// The same written into `out`, a default-constructed certificate (a caller's member: one
/// certificate's two dozen exact numbers are not allocated twice).
void build(const Ellipsoid& e, const Paraboloid& p, Position position, const Known& known, Certificate& out);

}  // namespace relpos::certificate
