// The end every stage shares (climb.hpp): the verdict from the root counts, and the gap test of
// math.md §8 when the counts leave it open -- a ladder of its own, through the one filter idiom
// (algebra/filtered.hpp): semi-static doubles, intervals, exact integers.
#include "anysize/gap.hpp"

#include <algorithm>
#include <stdexcept>

#include "algebra/filtered.hpp"
#include "algebra/pencil.hpp"
#include "decide/climb.hpp"
#include "filters/semi_static_filter.hpp"

namespace relpos::detail {

bool finish(Climb& c) {
  if (decided(c.v)) return true;
  if (!needs_gap(c.v)) return false;
  settle_gap(c, c.use_filter);
  return decided(c.v);
}

void settle_gap(Climb& c, bool use_filter) {
  const PairContext& pair = c.pair;
  const DoubleMatrix4 *pf = pair.p_storage().filter_doubles(), *ef = pair.e_storage().filter_doubles();
  const Settled<bool> gap = settle(
      [&] {
        const std::optional<bool> g = anysize::roots_above_lambda_s(pair.compact().f(), pair.compact().s());
        if (!g) throw std::logic_error("relpos: the exact gap test left a sign uncertain");
        return *g;
      },
      level<Rounding::Nearest>([&]() -> std::optional<bool> {
        if (!use_filter || !pf || !ef) return std::nullopt;
        return semi_static_roots_above_lambda_s(*pf, *ef);
      }),
      level<Rounding::Upward>([&]() -> std::optional<bool> {
        if (!use_filter) return std::nullopt;
        using forms::Interval;
        const IntervalEntries& x = pair.intervals();
        return anysize::roots_above_lambda_s(characteristic_polynomial<Interval>(x.p, x.e),
                                             special_polynomial<Interval>(x.p, x.e));
      }));
  static constexpr Stage kBy[] = {Stage::SemiStaticDouble, Stage::Interval, Stage::ExactSigns};
  c.v.roots_above_lambda_s = static_cast<signed char>(gap.value);
  c.v.stage = std::max(c.v.stage, kBy[gap.by]);
  decide(c.v);
}

}  // namespace relpos::detail
