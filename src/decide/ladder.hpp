// The ladder (math.md §11): the stages of stages.hpp run in order, each only while a needed sign is
// uncertain, every sign certified by one kept by the next. The list is unrolled at compile time, so
// the stage on every pair's path (stage_static_double.hpp) is inlined into its caller and the others
// are one call each.
#pragma once

#include <algorithm>

#include "decide/climb.hpp"
#include "decide/counters.hpp"
#include "decide/stage_static_double.hpp"

namespace relpos::detail {

/// The stages of `list` in order until one settles the pair; each counted by `counters`.
template <class Counters, class... S>
[[gnu::always_inline]] inline const Verdict& climb(Climb& c, const Counters& counters, StageList<S...>) {
  static_cast<void>(((counters.record(S::id, S::run(c)) == Step::Done) || ...));
  return c.v;
}

/// The classifier's ladder (the library's counters when built with RELPOS_STAGE_COUNTERS).
[[gnu::always_inline]] inline const Verdict& climb(Climb& c) {
  if constexpr (kLibraryCountsStages) return climb(c, CountInto{library_stage_counts()}, ClassifierLadder{});
  return climb(c, NoCounters{}, ClassifierLadder{});
}

/// The ladder's stages are kClassifierStages, in order (one list for the API, one for the code).
template <class... S>
constexpr bool same_stages(StageList<S...>) {
  constexpr Stage ids[] = {S::id...};
  if (sizeof...(S) != kClassifierStages.size()) return false;
  for (std::size_t i = 0; i < sizeof...(S); ++i)
    if (ids[i] != kClassifierStages[i]) return false;
  return true;
}
static_assert(same_stages(ClassifierLadder{}), "the ladder runs kClassifierStages, in order");

}  // namespace relpos::detail
