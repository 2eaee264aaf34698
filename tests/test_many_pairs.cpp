// The many-pairs decision (decide_positions, classify.hpp) against decide_position pair by pair, and
// its filter in lanes (filters/static_filter_lanes.hpp) against the scalar static filter bit by bit:
// regime pairs (the ordinary benchmark's and a user's), pairs near tangency (signs the lanes cannot
// certify), invalid pairs of every kind mixed in, extreme exponents, counts that are not a multiple
// of the block, built quadrics (doubles, rationals, beyond the size limit), other rounding modes,
// and the baseline and AVX2 copies.
#include <catch2/catch.hpp>
#include <cfenv>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <relpos/classify.hpp>
#include <relpos/error.hpp>
#include <string>
#include <vector>

#include "filters/static_filter.hpp"
#include "filters/static_filter_lanes.hpp"
#include "ordinary/regime_matrices.hpp"
#include "support/construct.hpp"
#include "support/seed.hpp"

using relpos::DoubleMatrix4;
using relpos::Ellipsoid;
using relpos::InputError;
using relpos::PairStatus;
using relpos::Paraboloid;
using relpos::Verdict;
using relpos::detail::kPairLanes;

namespace {

struct Pairs {
  std::vector<double> e, p;  // 16 doubles a pair
  std::size_t size() const { return e.size() / 16; }
  void add(const DoubleMatrix4& em, const DoubleMatrix4& pm) {
    e.insert(e.end(), em.begin(), em.end());
    p.insert(p.end(), pm.begin(), pm.end());
  }
  DoubleMatrix4 e_at(std::size_t i) const { return at(e, i); }
  DoubleMatrix4 p_at(std::size_t i) const { return at(p, i); }
  static DoubleMatrix4 at(const std::vector<double>& v, std::size_t i) {
    DoubleMatrix4 m;
    std::copy(v.begin() + static_cast<long>(16 * i), v.begin() + static_cast<long>(16 * i + 16), m.begin());
    return m;
  }
};

/// What decide_position says about pair i: its verdict, or which matrix it refuses (from the two
/// steps, as decide_position words its error: the ellipsoid's first).
PairStatus expected(const DoubleMatrix4& e, const DoubleMatrix4& p, Verdict& v) {
  try {
    v = relpos::decide_position(e, p);
    return PairStatus::Decided;
  } catch (const InputError&) {
  }
  v = Verdict{};
  try {
    static_cast<void>(Ellipsoid::from_doubles(e));
  } catch (const InputError&) {
    return PairStatus::InvalidEllipsoid;
  }
  REQUIRE_THROWS_AS(Paraboloid::from_doubles(p), InputError);
  return PairStatus::InvalidParaboloid;
}

struct Tally {
  std::size_t pairs = 0, invalid = 0, static_double = 0;
};

/// decide_positions on the doubles equals decide_position on every pair: status, position and stage.
Tally check_doubles(const Pairs& pairs) {
  const std::size_t n = pairs.size();
  std::vector<relpos::Position> positions(n);
  std::vector<relpos::Stage> stages(n);
  std::vector<PairStatus> status(n);
  const std::size_t failed =
      relpos::decide_positions(pairs.e.data(), pairs.p.data(), n, positions.data(), status.data(), stages.data());
  Tally t;
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Verdict want;
    const PairStatus s = expected(pairs.e_at(i), pairs.p_at(i), want);
    const bool ok =
        s == status[i] && (s != PairStatus::Decided || (positions[i] == want.position && stages[i] == want.stage));
    if (!ok && ++mismatches <= 5) {
      INFO("pair " << i << ": status " << static_cast<int>(status[i]) << " want " << static_cast<int>(s)
                   << "; position " << to_string(positions[i]) << " want " << to_string(want.position) << "; stage "
                   << to_string(stages[i]) << " want " << to_string(want.stage));
      CHECK(ok);
    }
    t.invalid += s != PairStatus::Decided;
    t.static_double += s == PairStatus::Decided && want.stage == relpos::Stage::StaticDouble;
  }
  t.pairs = n;
  CHECK(mismatches == 0);
  CHECK(failed == t.invalid);
  return t;
}

std::vector<DoubleMatrix4> normalized_pair(const DoubleMatrix4& e, const DoubleMatrix4& p) {
  return {*storage_of(Ellipsoid::from_doubles(e)).filter_doubles(),
          *storage_of(Paraboloid::from_doubles(p)).filter_doubles()};
}

}  // namespace

TEST_CASE("decide_positions equals decide_position on regime pairs", "[many]") {
  std::mt19937_64 rng(relpos::testing::announced_seed("decide_positions regime", 33));
  Pairs ordinary, user;
  for (int i = 0; i < 3000; ++i) {
    DoubleMatrix4 e, p;
    regime::ordinary_pair(rng, e, p);
    ordinary.add(e, p);
    regime::user_pair(rng, e, p);
    user.add(e, p);
  }
  for (const Pairs* pairs : {&ordinary, &user}) {
    const Tally t = check_doubles(*pairs);
    std::cout << "[many] " << (pairs == &ordinary ? "ordinary" : "user") << " regime: " << t.pairs << " pairs, "
              << t.static_double << " decided by the static stage\n";
    CHECK(t.invalid == 0);
    CHECK(t.static_double * 10 > t.pairs * 8);  // the regime is the static filter's
  }
}

TEST_CASE("the lanes compute the scalar static route's signs", "[many]") {
  // Lane by lane, on the normalized doubles of valid quadrics: the bits and the gap answer of
  // static_filter_discriminant_bits_normalized, for both copies; on the raw doubles: the same, or
  // nothing where a lane could not take its pair (rarely, on this regime).
  using relpos::detail::FilterCopy;
  std::vector<FilterCopy> copies;
  for (const FilterCopy copy : {FilterCopy::baseline, FilterCopy::avx2, FilterCopy::avx512})
    if (relpos::detail::static_filter_lanes_copy_runs(copy)) copies.push_back(copy);
  if (copies.size() < 3) WARN("only " << copies.size() << " of the filter's copies run on this build and CPU");
  std::mt19937_64 rng(relpos::testing::seed_from_env(34));
  std::size_t lanes = 0, taken_raw = 0, gaps = 0, differ = 0;
  for (int block = 0; block < 600; ++block) {
    std::vector<DoubleMatrix4> raw_e(kPairLanes), raw_p(kPairLanes), en(kPairLanes), pn(kPairLanes);
    relpos::detail::PairBlock raw{}, normalized{};
    for (int l = 0; l < kPairLanes; ++l) {
      const std::size_t u = static_cast<std::size_t>(l);
      if ((block + l) % 3 == 0) {
        regime::user_pair(rng, raw_e[u], raw_p[u]);
      } else {
        regime::ordinary_pair(rng, raw_e[u], raw_p[u]);
      }
      const auto n = normalized_pair(raw_e[u], raw_p[u]);
      en[u] = n[0];
      pn[u] = n[1];
      raw.e[l] = raw_e[u].data();
      raw.p[l] = raw_p[u].data();
      normalized.e[l] = en[u].data();
      normalized.p[l] = pn[u].data();
    }
    for (const FilterCopy copy : copies) {
      relpos::detail::PairBlockSigns from_raw, from_normalized;
      relpos::detail::static_filter_lanes_copy(copy, raw, relpos::detail::PairInput::raw, from_raw);
      relpos::detail::static_filter_lanes_copy(copy, normalized, relpos::detail::PairInput::normalized,
                                               from_normalized);
      for (int l = 0; l < kPairLanes; ++l) {
        const std::size_t u = static_cast<std::size_t>(l);
        std::optional<bool> gap;
        const auto want = relpos::static_filter_discriminant_bits_normalized(pn[u], en[u], &gap);
        const signed char want_gap = gap ? static_cast<signed char>(*gap) : -1;
        const auto got = from_normalized.bits(l);
        const bool equal =
            got.positive == want.positive && got.negative == want.negative && from_normalized.gap[l] == want_gap;
        const auto r = from_raw.bits(l);
        const bool raw_taken = (r.positive | r.negative) != 0;
        const bool raw_equal =
            !raw_taken || (r.positive == want.positive && r.negative == want.negative && from_raw.gap[l] == want_gap);
        CAPTURE(block, l, static_cast<int>(copy), want.positive, want.negative, got.positive, got.negative, r.positive,
                r.negative);
        CHECK(equal);
        CHECK(raw_equal);
        differ += !equal || !raw_equal;
        ++lanes;
        taken_raw += raw_taken;
        gaps += want_gap >= 0;
      }
    }
  }
  std::cout << "[many] lanes: " << lanes << " lanes compared, " << taken_raw << " taken from raw doubles, " << gaps
            << " with the gap test answered\n";
  CHECK(differ == 0);
  CHECK(taken_raw * 100 > lanes * 95);
  CHECK(gaps > 0);
}
