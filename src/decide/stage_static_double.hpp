// Stage 1 of the ladder (math.md §11): both matrices exact doubles, power-of-two normalized once
// when the quadrics were built; the static filter's signs (filters/static_filter.hpp, its error
// bounds derived beside it). First the discriminant route -- f, Disc(f), smallness and, when it is
// the one open question, the gap test, from the same f and s -- then, only if that cannot decide,
// the whole Sturm-Habicht sequence. Inline: every pair of doubles takes this path, and most end here.
#pragma once

#include <optional>

#include "decide/climb.hpp"
#include "filters/static_filter.hpp"

namespace relpos::detail {

struct StaticDoubleStage {
  static constexpr Stage id = Stage::StaticDouble;

  [[gnu::always_inline]] static Step run(Climb& c) {
    if (!c.use_filter || !c.pair.both_doubles()) return Step::Skipped;
    c.v.stage = Stage::StaticDouble;
    const DoubleMatrix4 *pf = c.pair.p_storage().filter_doubles(), *ef = c.pair.e_storage().filter_doubles();
    c.in_range = pf && ef && c.nearest;
    if (c.in_range) {
      // The fast route first: f, Disc(f) and smallness only. Anything it leaves open is asked
      // again of the whole sequence, from the start.
      std::optional<bool> gap;  // the gap test from the same f and s, when it is the one open question
      const DiscriminantSignBits fast = static_filter_discriminant_bits_normalized(*pf, *ef, &gap);
      if (c.determinants_pending) {
        const unsigned f0_and_f4 = 1u << 0 | 1u << 4;  // f(0) = det E, leading coefficient det P
        if ((fast.negative & f0_and_f4) != f0_and_f4) return Step::Done;
        *c.determinants_pending = false;
      }
      if (decide_from_discriminant(fast, c.v)) {
        if (gap && needs_gap(c.v)) {
          c.v.roots_above_lambda_s = static_cast<signed char>(*gap);
          decide(c.v);
        }
        if (decided(c.v) || finish(c)) return Step::Done;  // the common case without a call
      }
    }
    return whole_sequence(c);
  }

 private:
  /// The whole Sturm-Habicht sequence and smallness with static bounds, when the discriminant route
  /// cannot decide (or nothing when the doubles are out of the filter's range).
  [[gnu::noinline]] static Step whole_sequence(Climb& c) {
    if (c.in_range) {
      c.v = Verdict{};
      c.signs =
          static_filter_signs_normalized(*c.pair.p_storage().filter_doubles(), *c.pair.e_storage().filter_doubles());
    }
    if (c.determinants_pending && *c.determinants_pending) return Step::Done;  // not in range: nothing certified
    return decide_from_signs(c.signs, c.v) && finish(c) ? Step::Done : Step::Open;
  }
};

}  // namespace relpos::detail
