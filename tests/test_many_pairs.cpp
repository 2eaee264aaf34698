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
#include <optional>
#include <random>
#include <relpos/classify.hpp>
#include <relpos/error.hpp>
#include <string>
#include <vector>

#include "decide/many_pairs.hpp"
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

using relpos::detail::FilterCopy;

/// The copies of the lanes this build and CPU run (the library's chooses one when it is loaded).
std::vector<FilterCopy> running_copies() {
  std::vector<FilterCopy> copies;
  for (const FilterCopy copy : {FilterCopy::baseline, FilterCopy::avx2, FilterCopy::avx512})
    if (relpos::detail::static_filter_lanes_copy_runs(copy)) copies.push_back(copy);
  return copies;
}

/// decide_positions on the doubles (the loaded copy, or `copy`) equals decide_position on every pair:
/// status, position and stage.
Tally check_doubles(const Pairs& pairs, std::optional<FilterCopy> copy = std::nullopt) {
  const std::size_t n = pairs.size();
  std::vector<relpos::Position> positions(n);
  std::vector<relpos::Stage> stages(n);
  std::vector<PairStatus> status(n);
  const std::size_t failed =
      copy
          ? relpos::detail::decide_positions_copy(*copy, pairs.e.data(), pairs.p.data(), n, positions.data(),
                                                  status.data(), stages.data())
          : relpos::decide_positions(pairs.e.data(), pairs.p.data(), n, positions.data(), status.data(), stages.data());
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
    for (const FilterCopy copy : running_copies()) check_doubles(*pairs, copy);  // each copy, not only the loaded one
    const Tally t = check_doubles(*pairs);
    std::cout << "[many] " << (pairs == &ordinary ? "ordinary" : "user") << " regime: " << t.pairs << " pairs, "
              << t.static_double << " decided by the static stage\n";
    CHECK(t.invalid == 0);
    CHECK(t.static_double * 10 > t.pairs * 8);  // the regime is the static filter's
  }
}

namespace {
void near_tangent_pair(std::mt19937_64& rng, DoubleMatrix4& e, DoubleMatrix4& p);
void rotated_pair(std::mt19937_64& rng, DoubleMatrix4& e, DoubleMatrix4& p);
}  // namespace

TEST_CASE("the lanes compute the scalar static route's signs", "[many]") {
  // Lane by lane, on the normalized doubles of valid quadrics: the bits and the gap answer of
  // static_filter_discriminant_bits_normalized, for both copies; on the raw doubles: the same, or
  // nothing where a lane could not take its pair (rarely, on this regime).
  const std::vector<FilterCopy> copies = running_copies();
  if (copies.size() < 3) WARN("only " << copies.size() << " of the filter's copies run on this build and CPU");
  std::mt19937_64 rng(relpos::testing::seed_from_env(34));
  std::size_t lanes = 0, taken_raw = 0, axis_lanes = 0, axis_taken = 0, gaps = 0, differ = 0;
  for (int block = 0; block < 600; ++block) {
    std::vector<DoubleMatrix4> raw_e(kPairLanes), raw_p(kPairLanes), en(kPairLanes), pn(kPairLanes);
    bool rotated[kPairLanes] = {};
    relpos::detail::PairBlock raw{}, normalized{};
    for (int l = 0; l < kPairLanes; ++l) {
      const std::size_t u = static_cast<std::size_t>(l);
      // Blocks of one kind (each kind of known zeros in the pencil: spheres and axis-aligned
      // paraboloids, with the vertex on the axis or not; none) and mixed ones.
      switch (block % 4 == 3 ? l % 4 : block % 4) {
        case 0:
          regime::user_pair(rng, raw_e[u], raw_p[u]);
          break;
        case 1:
          regime::ordinary_pair(rng, raw_e[u], raw_p[u]);
          break;
        case 2:
          rotated_pair(rng, raw_e[u], raw_p[u]);
          rotated[l] = true;
          break;
        default:
          near_tangent_pair(rng, raw_e[u], raw_p[u]);
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
        axis_lanes += !rotated[l];
        axis_taken += !rotated[l] && raw_taken;
        gaps += want_gap >= 0;
      }
    }
  }
  std::cout << "[many] lanes: " << lanes << " lanes compared, " << taken_raw << " taken from raw doubles, " << gaps
            << " with the gap test answered\n";
  CHECK(differ == 0);
  // From raw doubles, a paraboloid in no axis' direction needs det Q3 = 0 exactly (floating-point
  // expansions): the scalar path's.
  CHECK(axis_taken * 100 > axis_lanes * 95);
  CHECK(gaps > 0);
}

namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

/// A sphere of radius r tangent to z = x^2/a^2 + y^2/b^2 at its vertex, inside or outside, moved off
/// tangency by r 2^-k (10 <= k < 50) along the axis (or not moved at all): signs at the edge of the
/// static bounds, the pairs the lanes leave to the scalar ladder.
void near_tangent_pair(std::mt19937_64& rng, DoubleMatrix4& e, DoubleMatrix4& p) {
  e.fill(0);
  p.fill(0);
  const double a = uniform(rng, 0.5, 2), b = uniform(rng, 0.5, 2), r = uniform(rng, 0.01, 0.2) * std::min(a * a, b * b);
  regime::set(p, 0, 0, 1 / (a * a));
  regime::set(p, 1, 1, 1 / (b * b));
  regime::set(p, 2, 3, -0.5);
  const int k = static_cast<int>(uniform(rng, 10, 50));
  const double z = (rng() % 2 ? r : -r) + (rng() % 4 ? std::ldexp(rng() % 2 ? r : -r, -k) : 0.0);
  const double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, c[3] = {0, 0, z};
  regime::ellipsoid_matrix(m, c, e);
  e[15] = z * z - r * r;
}

/// A paraboloid in no axis' direction (no zero entries to leave out), exact in doubles: A = alpha u u^T
/// + beta v v^T for small integer vectors u, v and powers of two alpha, beta (rank 2 exactly), the
/// linear term along w = u x v; and a sphere near its cup, along w.
void rotated_pair(std::mt19937_64& rng, DoubleMatrix4& e, DoubleMatrix4& p) {
  auto small = [&] { return static_cast<double>(static_cast<int>(rng() % 7) - 3); };
  double u[3], v[3], w[3];
  do {
    for (int i = 0; i < 3; ++i) u[i] = small(), v[i] = small();
    w[0] = u[1] * v[2] - u[2] * v[1], w[1] = u[2] * v[0] - u[0] * v[2], w[2] = u[0] * v[1] - u[1] * v[0];
  } while (w[0] == 0 || w[1] == 0 || w[2] == 0);  // in no coordinate plane: no zero entries
  const double alpha = std::ldexp(1.0, static_cast<int>(rng() % 5) - 2),
               beta = std::ldexp(1.0, static_cast<int>(rng() % 5) - 2);
  p.fill(0);
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) regime::set(p, i, j, alpha * u[i] * u[j] + beta * v[i] * v[j]);
    regime::set(p, i, 3, -0.5 * w[i]);  // x^T A x - w.x: inside the cup is along +w
  }
  const double ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2], r = uniform(rng, 0.05, 0.3);
  const double t = uniform(rng, -1, 3) * r / std::sqrt(ww), m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const double c[3] = {t * w[0] + uniform(rng, -0.1, 0.1), t * w[1], t * w[2]};
  regime::ellipsoid_matrix(m, c, e);
  e[15] = c[0] * c[0] + c[1] * c[1] + c[2] * c[2] - r * r;
}

DoubleMatrix4 negated(DoubleMatrix4 m) {
  for (double& x : m) x = -x;
  return m;
}

}  // namespace

TEST_CASE("decide_positions equals decide_position near tangency, on rotated paraboloids and in both orientations",
          "[many]") {
  std::mt19937_64 rng(relpos::testing::seed_from_env(35));
  Pairs near, rotated;
  for (int i = 0; i < 1500; ++i) {
    DoubleMatrix4 e, p;
    near_tangent_pair(rng, e, p);
    near.add(i % 3 ? e : negated(e), i % 5 ? p : negated(p));
    rotated_pair(rng, e, p);
    rotated.add(e, i % 2 ? p : negated(p));
  }
  for (const FilterCopy copy : running_copies()) check_doubles(near, copy), check_doubles(rotated, copy);
  const Tally n = check_doubles(near), r = check_doubles(rotated);
  std::cout << "[many] near tangency: " << n.pairs << " pairs, " << n.static_double
            << " decided by the static stage; rotated paraboloids: " << r.static_double << " of " << r.pairs << "\n";
  CHECK(n.invalid == 0);
  CHECK(r.invalid == 0);
  CHECK(n.static_double < n.pairs);  // some pairs are the scalar ladder's
  CHECK(r.static_double * 10 > r.pairs * 8);
}

TEST_CASE("decide_positions reports every invalid pair as decide_position refuses it", "[many]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const DoubleMatrix4 sphere{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -0.5, 0, 0, -0.5, 0.1875};  // radius 1/4 at z = 1/2
  const DoubleMatrix4 cup{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0};          // z = x^2 + y^2
  const std::vector<DoubleMatrix4> bad = {
      {},                                                                           // zero
      {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0},                             // a point: det E = 0
      {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1},                             // imaginary: det E > 0
      {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1},                            // cylinder: det P = 0
      {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1},                             // imaginary cylinder
      {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0},                      // saddle
      {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1},                           // hyperboloid
      {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0},                       // parabolic cylinder
      {1, 1e-300, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1},                       // not symmetric
      {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.4, 0},                       // not symmetric
      {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, nan},                           // NaN on the diagonal
      {1, nan, 0, 0, nan, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1},                        // NaN off it
      {inf, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0},                     // infinity
      {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, std::ldexp(1.0, -1074), -0.5, 0, 0, -0.5, 0},  // subnormal
  };
  std::mt19937_64 rng(relpos::testing::seed_from_env(36));
  Pairs pairs;
  std::size_t mixed = 0;
  for (int round = 0; round < 6; ++round)
    for (const DoubleMatrix4& m : bad) {
      // Invalid pairs among valid ones, at every position of a block.
      for (int k = static_cast<int>(rng() % kPairLanes); k > 0; --k) {
        DoubleMatrix4 e, p;
        regime::ordinary_pair(rng, e, p);
        pairs.add(e, p);
      }
      pairs.add(m, cup);
      pairs.add(sphere, m);
      pairs.add(m, m);
      pairs.add(negated(m), negated(cup));
      pairs.add(cup, sphere);  // swapped
      mixed += 5;
    }
  for (const FilterCopy copy : running_copies()) check_doubles(pairs, copy);
  const Tally t = check_doubles(pairs);
  std::cout << "[many] invalid pairs: " << t.invalid << " of " << t.pairs << " refused\n";
  CHECK(t.invalid > mixed / 2);
}

TEST_CASE("decide_positions at extreme exponents, on every count of pairs and in every rounding mode", "[many]") {
  std::mt19937_64 rng(relpos::testing::seed_from_env(37));
  Pairs pairs;
  const double scales[] = {1.0, std::ldexp(1.0, 1000), std::ldexp(1.0, -1000), 1e300, 1e-300, 0x1p-1060};
  for (int i = 0; i < 600; ++i) {
    DoubleMatrix4 e, p;
    regime::ordinary_pair(rng, e, p);
    const double se = scales[rng() % 6], sp = scales[rng() % 6];
    for (double& x : e) x *= se;  // inexact for 1e300: another valid ellipsoid, or an invalid matrix
    for (double& x : p) x *= sp;
    if (i % 7 == 0) e[15] = std::ldexp(1.0, -1070);  // a subnormal entry
    pairs.add(e, p);
  }
  for (const FilterCopy copy : running_copies()) check_doubles(pairs, copy);
  const Tally t = check_doubles(pairs);
  std::cout << "[many] extreme exponents: " << t.invalid << " of " << t.pairs << " refused, " << t.static_double
            << " decided by the static stage\n";
  // Every count, so that blocks end anywhere.
  for (std::size_t n : {0, 1, 2, 7, 8, 9, 15, 17, 23}) {
    Pairs head;
    head.e.assign(pairs.e.begin(), pairs.e.begin() + static_cast<long>(16 * n));
    head.p.assign(pairs.p.begin(), pairs.p.begin() + static_cast<long>(16 * n));
    check_doubles(head);
  }
  // Another rounding mode: the lanes stand aside (their bounds assume rounding to nearest) and every
  // pair is decide_position's in that mode.
  for (int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
    Pairs head;
    head.e.assign(pairs.e.begin(), pairs.e.begin() + 16 * 40);
    head.p.assign(pairs.p.begin(), pairs.p.begin() + 16 * 40);
    std::fesetround(mode);
    check_doubles(head);
    std::fesetround(FE_TONEAREST);
  }
}

TEST_CASE("decide_positions on built quadrics and against one paraboloid", "[many]") {
  std::mt19937_64 rng(relpos::testing::seed_from_env(38));
  std::vector<Ellipsoid> es;
  std::vector<Paraboloid> ps;
  for (int i = 0; i < 700; ++i) {
    DoubleMatrix4 e, p;
    if (i % 3 == 0) {
      near_tangent_pair(rng, e, p);
    } else {
      regime::ordinary_pair(rng, e, p);
    }
    es.push_back(Ellipsoid::from_doubles(e));
    ps.push_back(Paraboloid::from_doubles(p));
  }
  // Quadrics that are not doubles (the lanes pass them by) and a pair beyond the size limit.
  es.push_back(Ellipsoid::sphere({rt::Q(1, 3), rt::Q(0), rt::Q(1, 2)}, rt::Q(1, 5)));
  ps.push_back(Paraboloid::standard({rt::Q(0), rt::Q(0), rt::Q(-1, 7)}, rt::Q(2, 3), rt::Q(3, 2)));
  relpos::Integer huge(1);
  mpz_mul_2exp(huge.mpz(), huge.mpz(), 5000);
  es.push_back(Ellipsoid::sphere({rt::Q(0), rt::Q(0), relpos::Rational(1) + relpos::Rational(huge)}, rt::Q(1)));
  ps.push_back(ps.front());
  const std::size_t n = es.size();
  std::vector<relpos::Position> positions(n), shared_positions(n);
  std::vector<relpos::Stage> stages(n), shared_stages(n);
  std::vector<PairStatus> status(n), shared_status(n);
  const std::size_t failed =
      relpos::decide_positions(es.data(), ps.data(), n, positions.data(), status.data(), stages.data());
  const std::size_t shared_failed = relpos::decide_positions(es.data(), n, ps.front(), shared_positions.data(),
                                                             shared_status.data(), shared_stages.data());
  std::size_t mismatches = 0, too_large = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (int shared = 0; shared < 2; ++shared) {
      const Paraboloid& p = shared ? ps.front() : ps[i];
      const PairStatus got = shared ? shared_status[i] : status[i];
      try {
        const Verdict want = relpos::decide_position(es[i], p);
        const bool ok = got == PairStatus::Decided && (shared ? shared_positions[i] : positions[i]) == want.position &&
                        (shared ? shared_stages[i] : stages[i]) == want.stage;
        mismatches += !ok;
      } catch (const InputError&) {
        mismatches += got != PairStatus::TooLarge;
        too_large += 1;
      }
    }
  }
  CHECK(mismatches == 0);
  CHECK(too_large == 2);
  CHECK(failed == 1);
  CHECK(shared_failed == 1);
}
