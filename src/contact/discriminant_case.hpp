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

enum class DiscriminantCase : unsigned char {
  Undecided,    ///< a needed sign is uncertain, Disc(f) = 0, or f0, f4 not certified negative
  NonRealPair,  ///< Disc(f) < 0: two distinct negative roots and a non-real pair
  TwoPositive,  ///< Disc(f) > 0 and V = 2: four distinct real roots, two of them positive
  AllNegative,  ///< Disc(f) > 0 and V = 0: four distinct negative roots
};
std::string to_string(DiscriminantCase c);

/// The case from the signs of f[0..4] and of Disc(f) (q.g0); q.g2 and q.g1 are not read.
DiscriminantCase discriminant_case(const QuarticSigns& q);

/// Whether the answer for this case depends on rho (NonRealPair and AllNegative; TwoPositive is E
/// for any size).
bool discriminant_case_needs_rho(DiscriminantCase c);

/// classify's verdict for the case (position, rule, contact, root counts, sign of Disc(f)), applied
/// through classify's own table; rho_vs_one is read only when the case needs it. nullopt when the
/// case is Undecided or a needed rho is missing. The stage is Stage::DiscriminantFilter. For TwoPositive
/// the fields small / rho_vs_one are not meaningful (rho was not looked at).
std::optional<Verdict> verdict_from_discriminant_case(DiscriminantCase c, std::optional<int> rho_vs_one);

}  // namespace relpos
