// classify() without the pair size limit, for pairs the library builds itself from a checked input
// (the placed ellipsoid of a motion at a rational sample time, whose entries grow with the time's
// size): the limit guards what a caller hands in, not what the exact algorithms derive from it.
#pragma once

#include "relpos/classify.hpp"

namespace relpos::detail {

Classification classify_unchecked(const Ellipsoid& e, const Paraboloid& p, Evidence evidence);

}  // namespace relpos::detail
