// Building the certificate of an answer (include/relpos/position.hpp, math.md §8): the
// dual multiplier lambda of the trust-region duality for E, I, TE, TI; lambda_s and the contact set
// in the hard case; two witness points for C. Runs on exact rationals after the position is known,
// reading what the pair's one home (pair/pair.hpp) already holds.
#pragma once

#include "pair/pair.hpp"
#include "relpos/position.hpp"

namespace relpos::detail::certificate {

/// The certificate of `position` for the pair (which must be the pair's position), written into `out`,
/// a default-constructed certificate (a caller's member: one certificate's two dozen exact numbers are
/// not allocated twice). Never Kind::None: a certificate that cannot be built throws std::logic_error
/// (an internal error, doc/certificates.md).
void build(const detail::PairContext& pair, Position position, Certificate& out);

/// The same for a pair alone.
Certificate build(const Ellipsoid& e, const Paraboloid& p, Position position);

}  // namespace relpos::detail::certificate
