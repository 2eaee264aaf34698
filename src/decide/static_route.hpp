// What run_stages does with the signs of the static filter's discriminant route, for the many-pairs
// decision (many_pairs.cpp), whose lanes compute those signs for blocks of pairs: the route's table
// and its gap step, from classify.cpp, so that a pair decided in lanes gets the verdict
// decide_position returns for it.
#pragma once

#include "relpos/classify.hpp"

namespace relpos::detail {

/// The route's verdicts (decide_from_discriminant's table) by DiscriminantCase and rho_vs_one + 1,
/// stage StaticDouble: run_stages returns table[c][rho + 1] when its rule is not None; a default
/// verdict (rule None) for DiscriminantCase::Undecided.
void static_route_table(Verdict (&table)[4][3]);

/// run_stages's next step for a verdict of that table whose rule is None, given the gap test's answer
/// from the same signs (roots above lambda_s): true, with `v` decided as run_stages returns it, when
/// the verdict waited for that answer (math.md §8); false (go on to the next stage) otherwise.
bool static_route_gap(Verdict& v, bool gap);

}  // namespace relpos::detail
