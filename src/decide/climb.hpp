// One climb of the ladder (ladder.hpp): the state every stage reads and writes -- the pair's one
// home, the signs certified so far, the verdict -- and the finish every stage shares (the gap test
// of math.md §8 when the counts leave it open).
#pragma once

#include "algebra/rounding.hpp"
#include "decide/decision.hpp"
#include "decide/stages.hpp"
#include "pair/pair.hpp"

namespace relpos::detail {

/// The state of one climb: the pair, every sign certified so far (by any stage), the verdict.
struct Climb {
  /// `determinants_pending` (true on entry, or null): a pair validated but for det E < 0 and
  /// det P < 0, which the static stage certifies as f(0) and the leading coefficient (math.md §2);
  /// false once it has, and the climb ends at once (nothing decided) when it has not.
  Climb(const PairContext& pair_, bool use_filter_, bool* determinants_pending_ = nullptr)
      : pair(pair_),
        use_filter(use_filter_),
        nearest(use_filter_ && rounding_to_nearest()),
        determinants_pending(determinants_pending_) {}
  const PairContext& pair;
  const bool use_filter;  ///< false: the exact stages only (classify_exact)
  /// The double stages assume round-to-nearest; a caller inside an upward-rounding block (CGAL
  /// interval code) gets the interval stage instead.
  const bool nearest;
  bool* const determinants_pending;
  bool in_range = false;  ///< both quadrics' normalized doubles usable (static and semi-static stages)
  DecisionSigns signs;    ///< every sign certified so far (uncertain until then)
  Verdict v;
};

/// A stage certified the root counts: finish the decision (the gap test when it is needed). False
/// when the exact facts of math.md §8 are needed (multiple roots outside the small-pair table).
bool finish(Climb& c);

/// The gap test of math.md §8 through its own ladder (algebra/filtered.hpp): semi-static doubles,
/// intervals (with `use_filter`), exact integers (always certain). Records the latest stage used.
void settle_gap(Climb& c, bool use_filter);

}  // namespace relpos::detail
