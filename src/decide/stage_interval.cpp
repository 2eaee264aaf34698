// Stage 2 of the ladder (math.md §11): the same formulas on CGAL's Interval_nt, the entries enclosed
// without rational temporaries (from the doubles, the stored enclosures, else mpq_get_d), only while
// Disc(f) is within reach of intervals: near a multiple root its value sits orders of magnitude
// inside the semi-static bound, and every decision needs its sign.
#include "algebra/filtered.hpp"
#include "algebra/pencil.hpp"
#include "algebra/smallness.hpp"
#include "decide/climb.hpp"

namespace relpos::detail {

Step IntervalStage::run(Climb& c) {
  if (!c.use_filter || c.signs.disc_hopeless) return Step::Skipped;
  c.v.stage = Stage::Interval;
  using forms::Interval;
  // Interval_nt<false> needs rounding towards +inf, kept through the gap test finish() may run.
  const std::optional<bool> done = approximate<Rounding::Upward>([&]() -> std::optional<bool> {
    const IntervalEntries& x = c.pair.intervals();
    const Quartic<Interval> f = characteristic_polynomial<Interval>(x.p, x.e);
    const Quadratic<Interval> s = special_polynomial<Interval>(x.p, x.e);
    const SturmHabicht<Interval> sh(f);
    const SmallnessQuantities<Interval> q(f, s);
    merge_certain(c.signs, DecisionSigns{signs_of(f, sh), sign_of(q.vertex), sign_of(q.graeffe)});
    if (decide_from_signs(c.signs, c.v) && finish(c)) return true;
    return std::nullopt;
  });
  return done ? Step::Done : Step::Open;
}

}  // namespace relpos::detail
