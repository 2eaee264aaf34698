// The static filter's discriminant route in lanes across pairs (math.md §11, "Many pairs at once"):
// kPairLanes pairs per block, one pair per lane of LaneDouble (lane_double.hpp), each lane computing
// the doubles the scalar route (static_filter_discriminant_bits_normalized) computes for its pair,
// bit for bit: the same generic formulas in the same order, the same balancing and scaling, the
// same error bounds (detail::static_filter_bounds()) and the same comparisons. A lane's signs are
// therefore the scalar route's signs, and a pair decided from them gets the verdict decide_position
// gives.
//
// From raw doubles (the many-pairs decision on 32 doubles), a block first does in lanes what
// decide_position(e, p) on doubles does before its pencil: the symmetry test, the normalization by
// a power of two (only where it keeps every entry exactly, as QuadricMatrix's constructor does; the
// largest entry in the top two binades goes to the scalar path, which scales in two steps), the
// shape signs certified by their static bounds (shape_filter.hpp: for the ellipsoid the leading
// minor and det Q3 with the first entry's sign; for the paraboloid a diagonal Q3 by its signs, else
// E2 and the trace by static bounds and det Q3 = 0 by a zero pattern) and the orientation. det E < 0
// and det P < 0 are f(0) and the leading coefficient (math.md §2), certified with the route's signs.
// Whatever a lane cannot certify (a sign only the semi-static bound, intervals or expansions settle,
// an input out of range, an invalid matrix) leaves its bits empty: its pair goes to the scalar ladder.
#pragma once

#include "filters/static_filter.hpp"

namespace relpos::detail {

/// Pairs per block: one AVX-512 register of eight doubles per quantity, or two AVX2 ones (or four
/// SSE2 ones) one after the other.
inline constexpr int kPairLanes = 8;

/// A block's pairs: for each lane the 16 row-major doubles of its ellipsoid and of its paraboloid
/// (any addresses: arrays of matrices, quadrics' stored doubles, one paraboloid for every lane).
struct PairBlock {
  const double* e[kPairLanes];
  const double* p[kPairLanes];
};

/// What the route certified for each lane (DiscriminantSignBits; empty where a lane could not be
/// taken), and the gap test's answer where the signs left only it open (math.md §8): 1 (roots above
/// lambda_s), 0 (none), -1 (not needed, or a sign uncertain).
struct PairBlockSigns {
  unsigned long positive[kPairLanes], negative[kPairLanes];  // DiscriminantSignBits' masks, lane by lane
  /// DiscriminantSignBits::case_index() and rho_index() of each lane, formed in the lanes.
  unsigned long case_index[kPairLanes], rho_index[kPairLanes];
  signed char gap[kPairLanes];
  DiscriminantSignBits bits(int lane) const {
    return {static_cast<unsigned>(positive[lane]), static_cast<unsigned>(negative[lane])};
  }
};

/// What a block's doubles are: the matrices as given (from 32 doubles a pair: validated in lanes,
/// as above) or the normalized, sign-normalized doubles of validated quadrics
/// (storage_of(q).filter_doubles()).
enum class PairInput { raw, normalized };

/// The route on one block, in round to nearest (the caller's test). The copy built for this CPU
/// (load_time_copies.hpp).
void static_filter_lanes(const PairBlock& block, PairInput input, PairBlockSigns& out);

/// True when `copy` of static_filter_lanes() is built and this CPU can run it.
bool static_filter_lanes_copy_runs(FilterCopy copy);
/// static_filter_lanes() computed by `copy`; requires static_filter_lanes_copy_runs(copy). For tests,
/// which run every copy to see they agree.
void static_filter_lanes_copy(FilterCopy copy, const PairBlock& block, PairInput input, PairBlockSigns& out);

}  // namespace relpos::detail
