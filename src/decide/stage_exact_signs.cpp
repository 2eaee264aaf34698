// Stage 3 of the ladder (math.md §11): the same signs exactly, on the compact integer form of the
// pair (pair/compact_pencil.hpp). Near a tangency the float stages certified everything but
// Disc(f): then its sign alone, from the invariants; else the whole Sturm-Habicht sequence, which
// stage 4 reads again.
#include "algebra/smallness.hpp"
#include "decide/climb.hpp"

namespace relpos::detail {
namespace {

/// True when a float stage certified every sign the decision reads except Disc(f)'s: the usual state
/// near a tangency, where the exact stage then needs that one sign only.
bool only_disc_uncertain(const DecisionSigns& d) {
  const QuarticSigns& q = d.quartic;
  auto ok = [](const USign& x) { return CGAL::is_certain(x); };
  return !ok(q.g0) && ok(q.f[0]) && ok(q.f[1]) && ok(q.f[2]) && ok(q.f[3]) && ok(q.f[4]) && ok(q.g2[0]) &&
         ok(q.g2[1]) && ok(q.g2[2]) && ok(q.g1[0]) && ok(q.g1[1]) && ok(d.vertex) && ok(d.graeffe);
}

}  // namespace

Step ExactSignsStage::run(Climb& c) {
  const CompactPencil& x = c.pair.compact();
  c.v.stage = Stage::ExactSigns;
  if (c.use_filter && only_disc_uncertain(c.signs)) {
    c.signs.quartic.g0 = sign_of(x.discriminant_times_27());
    // Disc(f) = 0 needs the subresultants below (stage 4).
    if (c.signs.quartic.g0 != CGAL::ZERO && decide_from_signs(c.signs, c.v) && finish(c)) return Step::Done;
  }
  const SturmHabicht<PooledInteger>& sh = x.sturm_habicht();
  const SmallnessQuantities<PooledInteger> sq(x.f(), x.s());
  return decide_from_signs(DecisionSigns{signs_of(x.f(), sh), sign_of(sq.vertex), sign_of(sq.graeffe)}, c.v) &&
                 finish(c)
             ? Step::Done
             : Step::Open;
}

}  // namespace relpos::detail
