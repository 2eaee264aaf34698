// The discriminant decision of the contact module (doc/contact.md), private to the library.
#pragma once

#include <optional>
#include <string>

#include "algebra/sturm.hpp"
#include "relpos/classify.hpp"

namespace relpos {

// ------------------------------------------------------------------------------------------------
// The discriminant decision, written once, generic over where the signs come from (static filter,
// intervals, exact integers).
// ------------------------------------------------------------------------------------------------

// DiscriminantCase and discriminant_case() are in algebra/sturm.hpp (the classifier's fast route
// reads them too).
std::string to_string(DiscriminantCase c);

/// classify's verdict for the case (position, rule, contact, root counts, sign of Disc(f)), applied
/// through classify's own table; rho_vs_one is read only when the case needs it. nullopt when the
/// case is Undecided or a needed rho is missing. The stage is Stage::DiscriminantFilter. For TwoPositive
/// the fields small / rho_vs_one are not meaningful (rho was not looked at).
std::optional<Verdict> verdict_from_discriminant_case(DiscriminantCase c, std::optional<int> rho_vs_one);

namespace detail {

struct DiscriminantVerdict {
  /// Position, rule, contact identical to decide_position(); stage: Stage::DiscriminantFilter, or the
  /// stage of decide_position() when the test declined.
  Verdict verdict;
  bool rho_known = true;  ///< false when verdict.small / rho_vs_one were not computed (answer E)
};

/// The discriminant test on exact-double inputs (static filter), falling back to decide_position().
/// `limit`: the pair size limit of that fallback (quadric.hpp).
DiscriminantVerdict decide_by_discriminant(const Ellipsoid& e, const Paraboloid& p, const SizeLimit& limit = {});

}  // namespace detail

}  // namespace relpos
