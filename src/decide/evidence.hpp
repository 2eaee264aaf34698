// The full evidence of a classification (Evidence::Full, math.md §2, §5 and §8): the reported f and
// s, deg f~, the real roots with multiplicities, rho, and the certificate -- read off the pair's one
// home (pair/pair.hpp), where the ladder left what it computed.
#pragma once

#include "pair/pair.hpp"
#include "relpos/classify.hpp"

namespace relpos::detail {

/// A default Classification without a heap allocation per number (its numbers share the thread's
/// default ones until assigned).
Classification blank_classification();

/// Writes the full evidence of the pair, classified as `v`, into `out` (out.verdict is v).
void fill_full_evidence(PairContext& pair, const Verdict& v, Classification& out);

}  // namespace relpos::detail
