// The verifier's own Q(sqrt d) arithmetic, shared with the JSON form of certificates and the tests.
#pragma once

#include "relpos/position.hpp"

namespace relpos {

/// The exact sign (-1, 0, 1) of x.a + x.b sqrt(d), d >= 0.
int quadratic_sign(const QuadraticNumber& x, const Integer& d);

}  // namespace relpos
