// Stage 4 of the ladder (math.md §11): Disc(f) = 0 or a defective Sturm-Habicht sequence. Rational
// multiple roots are read off the subresultants stage 3 computed; otherwise exact gcd and square-free
// factorisation, or, for a square-free f, its isolated roots. Multiple roots of a pair that is not
// small get the exact facts of math.md §8: every pair is settled here.
#include "algebra/root_facts.hpp"
#include "algebra/roots.hpp"
#include "algebra/smallness.hpp"
#include "decide/climb.hpp"

namespace relpos::detail {
namespace {

/// The root facts of f (integer coefficients fi, si; sh: the Sturm-Habicht sequence of the same f).
RootFacts exact_facts(const Quartic<Integer>& fi, const Quadratic<Integer>& si, const SturmHabicht<PooledInteger>& sh) {
  const Integer g2[3] = {sh.g2[0].to_integer(), sh.g2[1].to_integer(), sh.g2[2].to_integer()};
  const Integer g1[2] = {sh.g1[0].to_integer(), sh.g1[1].to_integer()};
  std::optional<RootFacts> facts = subresultant_root_facts(fi, si, g2, g1, sh.g0[0].to_integer());
  if (!facts) facts = exact_root_facts_by_factorisation(fi, si);
  if (facts) return *facts;  // closed forms on the degree <= 2 square-free factors
  // Square-free f with a defective sequence: isolate the roots.
  RootFacts x;
  const RootStructure rs = exact_root_structure(fi, si);  // counts only: the roots are scaled
  x.real = static_cast<int>(rs.real_roots.size());
  x.negative = rs.negative();
  x.positive = rs.positive();
  x.nonreal = rs.nonreal;
  x.nonreal_multiple = rs.nonreal_multiple;
  for (const auto& r : rs.real_roots)
    if (r.tangency()) ++(r.sign < 0 ? x.tangent_negative : x.tangent_positive);
  x.sign_disc_f = rs.sign_disc_f;
  x.sign_disc_ftilde = rs.sign_disc_ftilde;
  return x;
}

}  // namespace

Step ExactRootsStage::run(Climb& c) {
  const CompactPencil& x = c.pair.compact();
  c.v.stage = Stage::ExactRoots;
  const Quartic<Integer> fi = x.f_integer();
  const Quadratic<Integer> si = x.s_integer();
  decide_from_facts(exact_facts(fi, si, x.sturm_habicht()), *compare_rho_with_one(x.f(), x.s()), c.v);  // exact
  if (!decided(c.v) && needs_gap(c.v)) settle_gap(c, false);
  if (!decided(c.v)) decide_any_size(fi, si, c.v);  // math.md §8: every pair gets an answer
  return Step::Done;
}

}  // namespace relpos::detail
