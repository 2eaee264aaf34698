// The many-pairs decision (classify.hpp) for the library's own callers: on pairs chosen by index, for
// callers that hold their pairs elsewhere (a scene's bodies that its early-outs left open), and with
// a given copy of the lanes (tests and benchmarks).
#pragma once

#include <cstddef>

#include "filters/static_filter.hpp"
#include "relpos/classify.hpp"

namespace relpos::detail {

/// verdicts[k] = decide_position(bodies[index[k]], p) for k < n (decide_positions on these pairs;
/// InputError as decide_position throws it, for a pair beyond the size limit).
void decide_positions_at(const Ellipsoid* bodies, const std::size_t* index, std::size_t n, const Paraboloid& p,
                         Verdict* verdicts);

/// decide_positions on doubles with the given copy of the lanes (static_filter_lanes_copy; requires
/// static_filter_lanes_copy_runs(copy)), for tests and benchmarks of each copy.
std::size_t decide_positions_copy(FilterCopy copy, const double* e, const double* p, std::size_t n, Position* positions,
                                  PairStatus* status, Stage* stages);

}  // namespace relpos::detail
