// The classification (math.md §3, §6 and §8), written once for every stage: from root facts, or
// from the certified signs of the decision quantities, to a Verdict. The hot path reads tables
// generated at start-up from this one decision (decide_from_signs, decide_from_discriminant).
#pragma once

#include "algebra/smallness.hpp"
#include "algebra/sturm.hpp"
#include "filters/static_filter.hpp"
#include "relpos/classify.hpp"

namespace relpos::detail {

/// The table itself: reads the root facts of v and its rho comparison; writes position and rule.
/// Leaves rule None (the position undecided) when the facts do not suffice: a pair that is not
/// small with four real negative roots needs roots_above_lambda_s (math.md §8), and a multiple root
/// outside the proven small-pair table needs the exact facts of math.md §8 (decide_any_size).
void decide(Verdict& v);

inline bool decided(const Verdict& v) { return v.rule != Rule::None; }

/// A square-free f with four real negative roots and a pair that is not small: the position depends
/// on where two roots lie against lambda_s (anysize/gap.hpp).
inline bool needs_gap(const Verdict& v) {
  return !decided(v) && !v.small && v.sign_disc_f != 0 && v.tangent_negative + v.tangent_positive == 0 &&
         v.nonreal_roots == 0 && v.positive_roots == 0 && v.roots_above_lambda_s < 0;
}

/// Section 8 from exact facts of f and s (integer coefficients; any common positive scaling of the
/// roots): the five rules in order. Every valid pair gets one of the five positions.
void decide_any_size(const Quartic<Integer>& f, const Quadratic<Integer>& s, Verdict& v);

/// Decision from certified signs when Disc(f) != 0 (then f and f~ are square-free). False when a
/// needed sign is uncertain, Disc(f) = 0 or the Sturm-Habicht sequence is defective. The common
/// case (every sign certain and non-zero) is one lookup in a table generated from decide().
bool decide_from_signs(const DecisionSigns& d, Verdict& v);

/// Decision from exact root facts (Disc(f) = 0 or a defective sequence) and the rho comparison.
void decide_from_facts(const RootFacts& x, int rho_vs_one, Verdict& v);

/// Keep every sign one filter certified: a sign certain in `more` replaces an uncertain one in `d`
/// (two certified signs of the same quantity never disagree).
void merge_certain(DecisionSigns& d, const DecisionSigns& more);

/// The 3 cases x 3 outcomes of rho of the fast route, generated once from decide_from_facts.
struct CaseTable {
  Verdict v[4][3];
  CaseTable();
};

/// The fast route (math.md §8): with Disc(f) != 0 the signs of f's coefficients and of Disc(f) give
/// every root count (discriminant_case), so the Sturm-Habicht g2 and g1 are not needed; rho is
/// always compared (the answer reports smallness). False when the case or rho is uncertain
/// (rho: 2). Always inlined: on every pair's path, where a call and its frame cost as much as the lookup.
[[gnu::always_inline]] inline bool decide_from_discriminant(DiscriminantCase c, int rho, Verdict& v) {
  static const CaseTable table;
  if (c == DiscriminantCase::Undecided || rho == 2) return false;
  const Stage stage = v.stage;
  v = table.v[static_cast<int>(c)][rho + 1];
  v.stage = stage;
  return true;
}

/// The same from a filter's signs.
inline bool decide_from_discriminant(const DecisionSigns& d, Verdict& v) {
  return decide_from_discriminant(discriminant_case(d.quartic), compare_rho_with_one(d.vertex, d.graeffe).value_or(2),
                                  v);
}
[[gnu::always_inline]] inline bool decide_from_discriminant(const DiscriminantSignBits& d, Verdict& v) {
  return decide_from_discriminant(d.discriminant_case(), d.rho_vs_one(), v);
}

/// Number of rules, None included (tables indexed by Rule take their size from here).
inline constexpr std::size_t kRuleCount = static_cast<std::size_t>(Rule::NoRootInGap) + 1;

/// The classification table itself (math.md §3 and §6), applied to exact root facts and the
/// comparison of rho with 1: the one written decision, for callers that obtain the facts another
/// way (the contact-only discriminant test). Stage is left at its default. nullopt when the facts do
/// not decide (a pair that is not small needs the exact facts of math.md §8 -- the gap test
/// against lambda_s or the five rules -- which decide_position computes).
std::optional<Verdict> decide_from_root_facts(const RootFacts& facts, int rho_vs_one);

}  // namespace relpos::detail
