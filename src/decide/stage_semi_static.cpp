// Stage 1' of the ladder (math.md §11): the same formulas in doubles with error bounds from the
// operands' magnitudes (filters/semi_static_filter.hpp): on the normalized doubles after stage 1,
// or for entries that are not doubles on double enclosures of them -- the stored ones of a quadric
// read from decimal text (the discriminant route first, as stage 1), else of the rationals.
#include "decide/climb.hpp"
#include "filters/semi_static_filter.hpp"

namespace relpos::detail {

Step SemiStaticDoubleStage::run(Climb& c) {
  if (!c.use_filter) return Step::Skipped;
  const PairContext& pair = c.pair;
  if (pair.both_doubles()) {
    if (!c.in_range) return Step::Skipped;
    c.v.stage = Stage::SemiStaticDouble;
    merge_certain(c.signs, semi_static_filter_signs_normalized(*pair.p_storage().filter_doubles(),
                                                               *pair.e_storage().filter_doubles()));
    return decide_from_signs(c.signs, c.v) && finish(c) ? Step::Done : Step::Open;
  }
  if (!c.nearest) return Step::Skipped;
  c.v.stage = Stage::SemiStaticDouble;
  if (pair.any_enclosure()) {
    const Enclosures& x = pair.enclosures();
    // The discriminant route first, as for doubles; then the whole sequence from the start.
    if (decide_from_discriminant(semi_static_filter_discriminant_signs(x.p, x.e), c.v) && finish(c)) return Step::Done;
    c.v = Verdict{};
    c.v.stage = Stage::SemiStaticDouble;
    c.signs = semi_static_filter_signs(x.p, x.e);
  } else {
    c.signs = semi_static_filter_signs(pair.paraboloid().matrix(), pair.ellipsoid().matrix());
  }
  return decide_from_signs(c.signs, c.v) && finish(c) ? Step::Done : Step::Open;
}

}  // namespace relpos::detail
