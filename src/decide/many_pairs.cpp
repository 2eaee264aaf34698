#include "decide/many_pairs.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "algebra/rounding.hpp"
#include "decide/decision.hpp"
#include "filters/static_filter_lanes.hpp"

namespace relpos {
namespace {

using detail::kPairLanes;

/// Blocks ahead whose pairs are requested while a block is decided: far enough for a line to arrive
/// from memory during the blocks between (a block takes a few hundred ns in the lanes), near enough
/// that the lines are still in L1 when their block comes (doc/performance.md, "Many pairs at once").
constexpr std::size_t kPrefetchBlocks = 2;

/// Every cache line of the `Bytes` bytes at `first` requested for reading, into all levels of the
/// cache: one request a line length apart and one for the last byte (the line a range that does not
/// start on a line's boundary ends in), unrolled. Inlined always: GCC takes a function that only
/// prefetches for one without effects, and drops its calls.
template <std::size_t Bytes>
[[gnu::always_inline]] inline void prefetch_bytes(const double* first) {
  constexpr std::size_t kLine = 64;
  const char* bytes = reinterpret_cast<const char*>(first);
  for (std::size_t k = 0; k < Bytes; k += kLine) __builtin_prefetch(bytes + k, 0, 3);
  __builtin_prefetch(bytes + Bytes - 1, 0, 3);
}

/// Pairs as 32 raw doubles each.
struct RawPairs {
  const double *e, *p;
  static constexpr detail::PairInput kInput = detail::PairInput::raw;
  void lane(std::size_t i, const double*& el, const double*& pl) const {
    el = e + 16 * i;
    pl = p + 16 * i;
  }
  /// The block of pairs from `first` requested from memory: arrays of pairs are read once, in order,
  /// and the lanes' compute and the stream from memory overlap only if the next pairs are on their
  /// way before the lanes need them.
  [[gnu::always_inline]] void prefetch(std::size_t first) const {
    constexpr std::size_t kBytes = 16 * sizeof(double) * kPairLanes;
    prefetch_bytes<kBytes>(e + 16 * first);
    prefetch_bytes<kBytes>(p + 16 * first);
  }
  /// decide_position on the doubles as its two steps (the same verdict, and the same InputError, the
  /// ellipsoid's first; classify.hpp): its one-call form would first repeat the static route, which
  /// the lanes ran already.
  PairStatus scalar(std::size_t i, Verdict& v) const {
    DoubleMatrix4 ed, pd;
    std::copy(e + 16 * i, e + 16 * i + 16, ed.begin());
    std::copy(p + 16 * i, p + 16 * i + 16, pd.begin());
    std::optional<Ellipsoid> ellipsoid;
    try {
      ellipsoid.emplace(Ellipsoid::from_doubles(ed));
    } catch (const InputError&) {
      return PairStatus::InvalidEllipsoid;
    }
    try {
      const Paraboloid paraboloid = Paraboloid::from_doubles(pd);
      v = decide_position(*ellipsoid, paraboloid);
    } catch (const InputError&) {
      return PairStatus::InvalidParaboloid;  // doubles are within the size limit: the shape
    }
    return PairStatus::Decided;
  }
};

/// The normalized doubles the static filter reads, or null (no doubles: the scalar ladder).
template <class Q>
const double* filter_doubles_of(const Q& q) {
  const DoubleMatrix4* d = storage_of(q).filter_doubles();
  return d ? d->data() : nullptr;
}

/// Pairs of built quadrics, the paraboloid shared when `shared`.
struct BuiltPairs {
  const Ellipsoid* e;
  const Paraboloid* p;
  bool shared;
  static constexpr detail::PairInput kInput = detail::PairInput::normalized;
  void lane(std::size_t i, const double*& el, const double*& pl) const {
    el = filter_doubles_of(e[i]);
    pl = filter_doubles_of(p[shared ? 0 : i]);
  }
  /// Nothing requested: the quadrics' doubles are wherever their objects are.
  void prefetch(std::size_t) const {}
  /// decide_position on the quadrics: InputError only for the size limit.
  PairStatus scalar(std::size_t i, Verdict& v) const {
    try {
      v = decide_position(e[i], p[shared ? 0 : i]);
      return PairStatus::Decided;
    } catch (const InputError&) {
      return PairStatus::TooLarge;
    }
  }
};

/// The bodies index[k] against one paraboloid (InputError passed on, as the scene's callers expect).
struct IndexedPairs {
  const Ellipsoid* bodies;
  const std::size_t* index;
  const Paraboloid* p;
  static constexpr detail::PairInput kInput = detail::PairInput::normalized;
  void lane(std::size_t k, const double*& el, const double*& pl) const {
    el = filter_doubles_of(bodies[index[k]]);
    pl = filter_doubles_of(*p);
  }
  /// Nothing requested, as for BuiltPairs.
  void prefetch(std::size_t) const {}
  PairStatus scalar(std::size_t k, Verdict& v) const {
    v = decide_position(bodies[index[k]], *p);
    return PairStatus::Decided;
  }
};

/// What the static stage (stage_static_double.hpp) does with the route's signs, read from the one
/// decision table (decision.hpp: decide_from_discriminant, decide): the verdict of a case and
/// rho_vs_one, and the positions it decides at once indexed for the lanes' bits.
struct RouteTable {
  /// The position the table decides for case c and DiscriminantSignBits::rho_index() r (its rule not
  /// None), -1 where it does not decide at once (an uncertain case or rho, or the gap test to come).
  signed char position[4][16];
  /// The route's own tables (static_filter.hpp): the case of a case_index(), rho_vs_one of a
  /// rho_index() (2: uncertain).
  const std::array<DiscriminantCase, 1 << 12>& cases = detail::discriminant_case_table();
  const std::array<signed char, 16>& rhos = detail::rho_vs_one_table();
  RouteTable() {
    for (int c = 0; c < 4; ++c)
      for (std::size_t r = 0; r < 16; ++r) {
        Verdict v;
        const bool decides = verdict(c, rhos[r], v) && detail::decided(v);
        position[c][r] = decides ? static_cast<signed char>(v.position) : -1;
      }
  }
  /// The route's verdict for case c and rho_vs_one (stage StaticDouble); false when the case or rho is
  /// uncertain.
  static bool verdict(int c, int rho, Verdict& v) {
    v = Verdict{};
    return detail::decide_from_discriminant(static_cast<DiscriminantCase>(c), rho, v);
  }
};

/// Positions (and stages) out, and the status of every pair.
struct PositionsOut {
  Position* positions;
  PairStatus* status;
  Stage* stages;
  void decided(std::size_t i, const Verdict& v) const {
    positions[i] = v.position;
    if (stages) stages[i] = v.stage;
    status[i] = PairStatus::Decided;
  }
  /// A verdict of the route's table that decides (stage StaticDouble, as every verdict of it), by
  /// case and rho_index().
  void route(std::size_t i, const RouteTable& table, int c, unsigned long rho_index) const {
    positions[i] = static_cast<Position>(table.position[c][rho_index]);
    if (stages) stages[i] = Stage::StaticDouble;
    status[i] = PairStatus::Decided;
  }
  void failed(std::size_t i, PairStatus s) const { status[i] = s; }
};

/// Whole verdicts out (the scene's).
struct VerdictsOut {
  Verdict* verdicts;
  void decided(std::size_t i, const Verdict& v) const { verdicts[i] = v; }
  void route(std::size_t i, const RouteTable& table, int c, unsigned long rho_index) const {
    RouteTable::verdict(c, table.rhos[rho_index], verdicts[i]);
  }
  void failed(std::size_t, PairStatus) const {}
};

/// Whether the pairs of the blocks ahead are requested from memory (RawPairs::prefetch) for `copy`
/// of the lanes: for the AVX-512 copy only. It let that copy's compute overlap the stream from
/// memory; the AVX2 copy (two passes of four lanes a block) ran slower with the same requests on the
/// machine of doc/performance.md ("Many pairs at once"), and the baseline copy was not measured.
bool prefetches(detail::FilterCopy copy) { return copy == detail::FilterCopy::avx512; }

/// The filter of the blocks: the copy chosen when the library was loaded, or a given one; and
/// whether that copy prefetches.
struct LoadedCopy {
  /// The loaded copy is the AVX-512 one wherever that one runs (static_filter_lanes' resolver).
  bool prefetch() const {
    static const bool avx512 = detail::static_filter_lanes_copy_runs(detail::FilterCopy::avx512);
    return avx512 && prefetches(detail::FilterCopy::avx512);
  }
  void operator()(const detail::PairBlock& block, detail::PairInput input, detail::PairBlockSigns& out) const {
    detail::static_filter_lanes(block, input, out);
  }
};
struct GivenCopy {
  detail::FilterCopy copy;
  bool prefetch() const { return prefetches(copy); }
  void operator()(const detail::PairBlock& block, detail::PairInput input, detail::PairBlockSigns& out) const {
    detail::static_filter_lanes_copy(copy, block, input, out);
  }
};

/// Lane l of a block (pair i) from the route's signs, as the static stage takes them
/// (stage_static_double.hpp): the table's verdict when it decides; else, when the verdict waits for
/// the gap test only and the lanes have its answer, the verdict with it (math.md §8). False: the pair
/// stays open, for the ladder.
template <class Out>
[[gnu::always_inline]] inline bool decide_lane(const detail::PairBlockSigns& signs, int l, const RouteTable& table,
                                               const Out& out, std::size_t i) {
  const int c = static_cast<int>(table.cases[signs.case_index[l]]);
  if (table.position[c][signs.rho_index[l]] >= 0) {
    out.route(i, table, c, signs.rho_index[l]);
    return true;
  }
  Verdict v;
  if (signs.gap[l] < 0 || !RouteTable::verdict(c, table.rhos[signs.rho_index[l]], v) || !detail::needs_gap(v))
    return false;
  v.roots_above_lambda_s = static_cast<signed char>(signs.gap[l] != 0);
  detail::decide(v);
  if (!detail::decided(v)) return false;
  out.decided(i, v);
  return true;
}

/// The pairs through the lanes (in round to nearest, which their bounds assume; in any other mode
/// decide_position runs its interval stage instead) in blocks of kPairLanes pairs; the pairs whose
/// signs they do not settle through decide_position itself, after the blocks of their chunk (so that
/// neither the lanes' code nor the ladder's evicts the other's from the instruction caches pair by
/// pair; the chunk's pairs are still in the L2 cache then). While a block is decided, the pairs
/// kPrefetchBlocks blocks ahead are requested from memory, where the filter's copy prefetches.
template <class Pairs, class Out, class Filter = LoadedCopy>
std::size_t decide_blocks(const Pairs& pairs, std::size_t n, const Out& out, Filter filter = {}) {
  static const RouteTable table;
  std::size_t failed = 0;
  auto scalar = [&](std::size_t i) {
    Verdict v;
    const PairStatus s = pairs.scalar(i, v);
    if (s == PairStatus::Decided) {
      out.decided(i, v);
    } else {
      out.failed(i, s);
      ++failed;
    }
  };
  if (!detail::rounding_to_nearest()) {
    for (std::size_t i = 0; i < n; ++i) scalar(i);
    return failed;
  }
  constexpr std::size_t kChunk = 1024;
  std::size_t open[kChunk];
  const bool prefetch = filter.prefetch();
  detail::PairBlock block;
  detail::PairBlockSigns signs;
  for (std::size_t chunk = 0; chunk < n; chunk += kChunk) {
    const std::size_t end = std::min(n, chunk + kChunk);
    std::size_t opened = 0;
    for (std::size_t start = chunk; start < end; start += kPairLanes) {
      const int count = static_cast<int>(std::min<std::size_t>(kPairLanes, end - start));
      const std::size_t ahead = start + kPrefetchBlocks * kPairLanes;
      if (prefetch && ahead + kPairLanes <= n) pairs.prefetch(ahead);  // whole blocks only
      for (int l = 0; l < kPairLanes; ++l) {
        if (l < count) {
          pairs.lane(start + static_cast<std::size_t>(l), block.e[l], block.p[l]);
        } else {
          block.e[l] = block.p[l] = nullptr;
        }
      }
      filter(block, Pairs::kInput, signs);
      for (int l = 0; l < count; ++l) {
        const std::size_t i = start + static_cast<std::size_t>(l);
        if (!decide_lane(signs, l, table, out, i)) open[opened++] = i;
      }
    }
    for (std::size_t k = 0; k < opened; ++k) scalar(open[k]);
  }
  return failed;
}

}  // namespace

std::size_t decide_positions(const double* e, const double* p, std::size_t n, Position* positions, PairStatus* status,
                             Stage* stages) {
  return decide_blocks(RawPairs{e, p}, n, PositionsOut{positions, status, stages});
}

std::size_t decide_positions(const Ellipsoid* e, const Paraboloid* p, std::size_t n, Position* positions,
                             PairStatus* status, Stage* stages) {
  return decide_blocks(BuiltPairs{e, p, false}, n, PositionsOut{positions, status, stages});
}

std::size_t decide_positions(const Ellipsoid* e, std::size_t n, const Paraboloid& p, Position* positions,
                             PairStatus* status, Stage* stages) {
  return decide_blocks(BuiltPairs{e, &p, true}, n, PositionsOut{positions, status, stages});
}

std::size_t detail::decide_positions_copy(FilterCopy copy, const double* e, const double* p, std::size_t n,
                                          Position* positions, PairStatus* status, Stage* stages) {
  return decide_blocks(RawPairs{e, p}, n, PositionsOut{positions, status, stages}, GivenCopy{copy});
}

void detail::decide_positions_at(const Ellipsoid* bodies, const std::size_t* index, std::size_t n, const Paraboloid& p,
                                 Verdict* verdicts) {
  decide_blocks(IndexedPairs{bodies, index, &p}, n, VerdictsOut{verdicts});
}

}  // namespace relpos
