// Stage 1b of the ladder (math.md §10): the float stages left Disc(f) uncertain (or certified it 0)
// on exact-double input. If f has rational multiple roots, exhibit them on machine integers
// (filters/multiple_roots.hpp): that certifies Disc(f) = 0 and gives every root fact without GMP.
// rho comes from the signs certified so far, or exactly from the same machine integers. Nothing is
// certified when there is no such witness or a number overflows.
#include "decide/climb.hpp"
#include "filters/multiple_roots.hpp"

namespace relpos::detail {
namespace {

bool decide_from_witness(const DoubleMatrix4& p, const DoubleMatrix4& e, const DecisionSigns& d, Verdict& v) {
  const auto mp = machine_pencil(p, e);
  if (!mp) return false;
  const auto facts = rational_multiple_root_facts(mp->f, mp->s);
  if (!facts) return false;
  auto rho = compare_rho_with_one(d.vertex, d.graeffe);
  if (!rho) rho = compare_rho_with_one(mp->f, mp->s);  // CheckedInt: uncertain only on overflow
  if (!rho) return false;
  decide_from_facts(*facts, *rho, v);
  return true;
}

}  // namespace

Step MultipleRootWitnessStage::run(Climb& c) {
  if (!c.use_filter || !c.pair.both_doubles()) return Step::Skipped;
  const std::optional<int> disc = certain(c.signs.quartic.g0);
  if (disc && *disc != 0) return Step::Skipped;
  c.v.stage = Stage::MultipleRootWitness;
  return decide_from_witness(*c.pair.paraboloid().doubles(), *c.pair.ellipsoid().doubles(), c.signs, c.v) &&
                 decided(c.v)
             ? Step::Done
             : Step::Open;
}

}  // namespace relpos::detail
