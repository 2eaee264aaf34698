// Per-stage counters of the ladder (geogram's PredicateStats): how often each stage ran and how
// often a climb ended in it. Compiled into the library only on request (CMake option
// RELPOS_STAGE_COUNTERS); a caller of climb() can always pass its own.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>

#include "decide/stages.hpp"

namespace relpos::detail {

/// Counts per Stage (indexed by Stage), relaxed atomics: several threads may count at once.
struct StageCounts {
  std::array<std::atomic<unsigned long>, kAllStages.size()> ran{}, ended{};
  void clear() {
    for (auto& x : ran) x.store(0, std::memory_order_relaxed);
    for (auto& x : ended) x.store(0, std::memory_order_relaxed);
  }
};

/// No counting: record() is the identity and vanishes from the inlined ladder.
struct NoCounters {
  static constexpr Step record(Stage, Step step) { return step; }
};

/// Counting into `counts`.
struct CountInto {
  StageCounts& counts;
  Step record(Stage stage, Step step) const {
    const auto i = static_cast<std::size_t>(stage);
    if (step != Step::Skipped) counts.ran[i].fetch_add(1, std::memory_order_relaxed);
    if (step == Step::Done) counts.ended[i].fetch_add(1, std::memory_order_relaxed);
    return step;
  }
};

#ifdef RELPOS_STAGE_COUNTERS
inline constexpr bool kLibraryCountsStages = true;
#else
inline constexpr bool kLibraryCountsStages = false;
#endif

/// The counts of every climb of decide_position and classify in this process (zero unless the
/// library was built with RELPOS_STAGE_COUNTERS).
inline StageCounts& library_stage_counts() {
  static StageCounts counts;
  return counts;
}

}  // namespace relpos::detail
