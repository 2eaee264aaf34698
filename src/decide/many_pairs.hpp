// The many-pairs decision on pairs chosen by index, for callers that hold their pairs elsewhere: a
// scene's bodies that its early-outs left open.
#pragma once

#include <cstddef>

#include "relpos/classify.hpp"

namespace relpos::detail {

/// verdicts[k] = decide_position(bodies[index[k]], p) for k < n (decide_positions on these pairs;
/// InputError as decide_position throws it, for a pair beyond the size limit).
void decide_positions_at(const Ellipsoid* bodies, const std::size_t* index, std::size_t n, const Paraboloid& p,
                         Verdict* verdicts);

}  // namespace relpos::detail
