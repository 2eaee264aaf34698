// The double-precision filters of classify() (static_filter.hpp, semi_static_filter.hpp): every sign
// they certify must be the exact sign of the same quantity, and the semi-static stage must actually
// settle what the static bound cannot. Exact signs come from the same generic formulas on exact
// rationals of the same (power-of-two normalized) matrices.
#include <catch2/catch.hpp>
#include <cfenv>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <relpos/classify.hpp>
#include <relpos/scene.hpp>
#include <tuple>

#include "algebra/filtered.hpp"
#include "algebra/quadric_doubles.hpp"
#include "algebra/rounding.hpp"
#include "algebra/smallness.hpp"
#include "anysize/gap.hpp"
#include "filters/semi_static_filter.hpp"
#include "filters/static_filter.hpp"
#include "scene/certificates.hpp"
#include "scene/demo.hpp"
#include "support/construct.hpp"
#include "support/seed.hpp"

using namespace rt;
using relpos::DecisionSigns;
using relpos::DoubleMatrix4;
using relpos::Ellipsoid;
using relpos::Paraboloid;
using relpos::USign;

namespace {

using relpos::testing::seed_from_env;

/// The 13 signs in a fixed order: f0..f4, g2[0..2], g1[0..1], g0, vertex, graeffe.
std::array<USign, 13> flatten(const DecisionSigns& d) {
  const auto& q = d.quartic;
  return {q.f[0],  q.f[1],  q.f[2],  q.f[3], q.f[4],   q.g2[0],  q.g2[1],
          q.g2[2], q.g1[0], q.g1[1], q.g0,   d.vertex, d.graeffe};
}

/// flatten() as ints: the certain sign, or 2 when uncertain (USigns compare only when certain).
std::array<int, 13> sign_codes(const DecisionSigns& d) {
  std::array<int, 13> out{};
  const auto signs = flatten(d);
  for (std::size_t i = 0; i < 13; ++i)
    out[i] = CGAL::is_certain(signs[i]) ? static_cast<int>(CGAL::get_certain(signs[i])) : 2;
  return out;
}

struct RationalView {
  const relpos::Matrix4& m;
  const Rational& operator()(int i, int j) const { return m(i, j); }
};

/// Exact signs of the 13 quantities (flatten's order) for rational matrices.
std::array<int, 13> exact_signs(const relpos::Matrix4& pm, const relpos::Matrix4& em) {
  const RationalView p{pm}, e{em};
  const auto f = relpos::characteristic_polynomial<Rational>(p, e);
  const auto s = relpos::special_polynomial<Rational>(p, e);
  const relpos::SturmHabicht<Rational> sh(f);
  const relpos::SmallnessQuantities<Rational> sq(f, s);
  const Rational q[13] = {f[0],     f[1],     f[2],     f[3],     f[4],      sh.g2[0],  sh.g2[1],
                          sh.g2[2], sh.g1[0], sh.g1[1], sh.g0[0], sq.vertex, sq.graeffe};
  std::array<int, 13> out{};
  for (int i = 0; i < 13; ++i) out[static_cast<std::size_t>(i)] = sgn(q[i]);
  return out;
}

std::array<int, 13> exact_signs(const DoubleMatrix4& pn, const DoubleMatrix4& en) {
  relpos::Matrix4 p, e;
  for (std::size_t i = 0; i < 16; ++i) {
    p.a[i] = relpos::exact_rational(pn[i]);
    e.a[i] = relpos::exact_rational(en[i]);
  }
  return exact_signs(p, e);
}

struct Tally {
  long quantities = 0, static_certified = 0, semi_certified = 0, wrong = 0;
  long pairs = 0, static_all = 0, semi_all = 0;
  long gaps = 0, gaps_true = 0;  // static gap tests answered (each checked against the exact one), and true
};

/// The exact gap test (math.md §8) on the rational pencil.
std::optional<bool> exact_gap(const DoubleMatrix4& pn, const DoubleMatrix4& en) {
  relpos::Matrix4 pm, em;
  for (std::size_t i = 0; i < 16; ++i) {
    pm.a[i] = relpos::exact_rational(pn[i]);
    em.a[i] = relpos::exact_rational(en[i]);
  }
  const RationalView p{pm}, e{em};
  return relpos::detail::anysize::roots_above_lambda_s(relpos::characteristic_polynomial<Rational>(p, e),
                                                       relpos::special_polynomial<Rational>(p, e));
}

/// Check both filters on one pair of normalized matrices against the exact signs.
void check_pair(const DoubleMatrix4& pn, const DoubleMatrix4& en, Tally& t) {
  const auto exact = exact_signs(pn, en);
  const auto st = flatten(relpos::static_filter_signs_normalized(pn, en));
  const auto ss = flatten(relpos::semi_static_filter_signs_normalized(pn, en));
  // The discriminant route (Disc(f) from the invariants, in g0's place; g2 and g1 uncertain).
  std::optional<bool> gap;
  const auto sd = flatten(relpos::static_filter_discriminant_signs_normalized(
      pn, en, [](const relpos::QuarticSigns&) { return true; }, &gap));
  if (gap) {  // answered only for four distinct negative roots and rho > 1: the exact test answers too
    const std::optional<bool> want = exact_gap(pn, en);
    REQUIRE(want);
    CHECK(*gap == *want);
    t.wrong += *gap != *want;
    ++t.gaps;
    t.gaps_true += *gap;
  }
  // The discriminant route balances and scales f and s to the same doubles as the full pipeline
  // (written separately, in lanes): f's coefficients and the smallness quantities are certified
  // alike whenever the full pipeline got past the scaling of s (it returns nothing when that fails).
  bool st_any = false;
  for (const USign& s : st) st_any = st_any || CGAL::is_certain(s);
  if (st_any)
    for (std::size_t i : {0, 1, 2, 3, 4, 11, 12}) {
      CAPTURE(i);
      CHECK(CGAL::is_certain(sd[i]) == CGAL::is_certain(st[i]));
      if (CGAL::is_certain(sd[i]) && CGAL::is_certain(st[i]))
        CHECK(CGAL::get_certain(sd[i]) == CGAL::get_certain(st[i]));
    }
  bool all_st = true, all_ss = true;
  for (std::size_t i = 0; i < 13; ++i) {
    ++t.quantities;
    for (const auto* s : {&st[i], &ss[i], &sd[i]}) {
      if (!CGAL::is_certain(*s)) continue;
      const int got = static_cast<int>(CGAL::get_certain(*s));
      CAPTURE(i, got, exact[i]);
      CHECK(got == exact[i]);
      CHECK(got != 0);  // a float filter never certifies a zero
      t.wrong += got != exact[i];
    }
    const bool cst = CGAL::is_certain(st[i]), css = CGAL::is_certain(ss[i]);
    t.static_certified += cst;
    t.semi_certified += css;
    all_st = all_st && cst;
    all_ss = all_ss && css;
  }
  ++t.pairs;
  t.static_all += all_st;
  t.semi_all += all_ss;
}

DoubleMatrix4 normalized(const std::optional<DoubleMatrix4>& m) {
  auto n = relpos::detail::power_of_two_normalized(m);
  REQUIRE(n);
  return *n;
}

/// Two random symmetric double matrices with entry exponents spread over up to 60 binades, a
/// quarter of the entries zero, power-of-two normalized; false when one cannot be normalized.
bool random_normalized_pair(Rng& g, DoubleMatrix4& pn, DoubleMatrix4& en) {
  DoubleMatrix4 m[2];
  const int spread = static_cast<int>(g.uniform(0, 4)) * 20;  // entry exponents in [-spread, 0]
  for (auto& x : m)
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) {
        double v = 0;
        if (!g.chance(25))
          v = std::ldexp(static_cast<double>(g.uniform(-(1L << 20), 1L << 20)),
                         static_cast<int>(g.uniform(-spread, 0)));
        x[static_cast<std::size_t>(4 * i + j)] = x[static_cast<std::size_t>(4 * j + i)] = v;
      }
  if (g.chance(30)) m[0][15] = 0;  // det P-like degeneracy patterns
  const auto p = relpos::detail::power_of_two_normalized(m[0]), e = relpos::detail::power_of_two_normalized(m[1]);
  if (!p || !e) return false;
  pn = *p;
  en = *e;
  return true;
}

/// A sphere too large to be small for x^2 + y^2/4 = z (rho > 1), in or near the cup: with four
/// negative roots its position hangs on the gap test of math.md §8.
Ellipsoid large_sphere(Rng& g) {
  const double r = static_cast<double>(g.uniform(64, 768)) / 256;  // 0.25 .. 3
  const double z = r + static_cast<double>(g.uniform(-256, 2560)) / 256;
  const double x = static_cast<double>(g.uniform(-64, 64)) / 256, y = static_cast<double>(g.uniform(-64, 64)) / 256;
  return Ellipsoid::sphere(std::array<double, 3>{x, y, z}, r);
}

/// A sphere tangent to x^2 + y^2/4 = z at its vertex (normal (0, 0, -1)), inside (z = r) or outside
/// (z = -r), moved off tangency by +-2^-k (10 <= k < 60) three times in four, possibly shifted in x.
Ellipsoid near_tangent_sphere(Rng& g) {
  const Rational r = Q(g.uniform(1, 64), 256);
  const int k = static_cast<int>(g.uniform(10, 60));
  Rational z = g.chance(50) ? r : -r;
  if (g.chance(75)) z += (g.chance(50) ? 1 : -1) * pow_q(Q(2), -k);
  const Rational x = g.chance(50) ? Q(0) : Q(g.uniform(-8, 8), 64);
  return Ellipsoid::sphere(V(x, Q(0), z), r);
}

}  // namespace

TEST_CASE("the double stages see each of the four rounding modes", "[filters]") {
  // The double filters run only to nearest; every other mode must be told apart (the interval
  // stage takes over).
  const int modes[4] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
  bool nearest[4];
  for (int i = 0; i < 4; ++i) {
    REQUIRE(std::fesetround(modes[i]) == 0);
    nearest[i] = relpos::detail::rounding_to_nearest();
  }
  std::fesetround(FE_TONEAREST);
  CHECK(nearest[0]);
  CHECK_FALSE(nearest[1]);
  CHECK_FALSE(nearest[2]);
  CHECK_FALSE(nearest[3]);
}

TEST_CASE("double filters: every certified sign is the exact sign (demo scene bodies)", "[filters][random]") {
  const Paraboloid p = Paraboloid::standard({Q(0), Q(0), Q(0)}, Q(1), Q(2));
  relpos::DemoSceneGenerator gen(seed_from_env(4242), Q(1), Q(2), 0.2);
  Tally t;
  for (int i = 0; i < 3000; ++i) {
    const Ellipsoid e = gen.next().ellipsoid();
    if (!storage_of(e).filter_doubles()) continue;
    check_pair(*storage_of(p).filter_doubles(), *storage_of(e).filter_doubles(), t);
  }
  std::cout << "[filters] demo bodies: " << t.pairs << " pairs; all 13 signs certified by the static filter on "
            << t.static_all << ", by the semi-static filter on " << t.semi_all << "\n";
  CHECK(t.wrong == 0);
  // The semi-static stage exists to settle what the static bound cannot (small bodies far from
  // the wall): it must certify every sign on clearly more pairs than the static filter.
  CHECK(t.semi_all > t.static_all);
  CHECK(t.semi_all * 100 >= t.pairs * 95);
}

TEST_CASE("double filters: every certified sign is the exact sign (random matrices, wide exponents, zeros)",
          "[filters][random]") {
  Rng g(seed_from_env(99));
  std::cout << "[filters] seed " << g.seed << "\n";
  Tally t;
  for (int n = 0; n < 1500; ++n) {
    DoubleMatrix4 pn, en;
    if (random_normalized_pair(g, pn, en)) check_pair(pn, en, t);
  }
  std::cout << "[filters] random matrices: " << t.pairs << " pairs, " << t.quantities << " signs; certified "
            << t.static_certified << " static, " << t.semi_certified << " semi-static\n";
  CHECK(t.wrong == 0);
  // Entries below 2^-60 of the largest are refused by the semi-static guards (no-underflow
  // argument), so the wide-spread classes leave some signs to the interval stage.
  CHECK(t.semi_certified > t.static_certified);
  CHECK(t.semi_certified * 10 >= t.quantities * 7);
}

TEST_CASE("static gap test: large spheres in the cup, against the exact gap test", "[filters][random]") {
  // Spheres too large to be small (rho > 1) with four negative roots: the position hangs on the gap
  // test of math.md §8 (I when two roots lie above lambda_s, C otherwise); both outcomes occur.
  Rng g(seed_from_env(17));
  const Paraboloid p = Paraboloid::standard({Q(0), Q(0), Q(0)}, Q(1), Q(2));
  Tally t;
  for (int n = 0; n < 1500; ++n) {
    const Ellipsoid e = large_sphere(g);
    if (!storage_of(e).filter_doubles()) continue;
    check_pair(*storage_of(p).filter_doubles(), *storage_of(e).filter_doubles(), t);
  }
  std::cout << "[filters] large spheres: " << t.pairs << " pairs, static gap test answered on " << t.gaps << " ("
            << t.gaps_true << " with roots above lambda_s)\n";
  CHECK(t.wrong == 0);
  CHECK(t.gaps >= 100);
  CHECK(t.gaps_true > 0);
  CHECK(t.gaps_true < t.gaps);
}

TEST_CASE("double filters on near-tangent and exactly tangent double inputs", "[filters][random]") {
  // Spheres tangent to x^2 + y^2/4 = z at dyadic points with dyadic normals, moved by +-2^-k along
  // the normal: exact zeros (k = infinity) must never be certified, near-zeros only correctly.
  Rng g(seed_from_env(7));
  const Paraboloid p = Paraboloid::standard({Q(0), Q(0), Q(0)}, Q(1), Q(2));
  Tally t;
  for (int n = 0; n < 400; ++n) {
    const Ellipsoid e = near_tangent_sphere(g);
    if (!storage_of(e).filter_doubles()) continue;
    check_pair(*storage_of(p).filter_doubles(), normalized(e.doubles()), t);
  }
  CHECK(t.wrong == 0);
  CHECK(t.pairs > 300);
}

TEST_CASE("static filter: the baseline and the AVX2 copy return the same bits as the public path",
          "[filters][random]") {
  // Only one copy runs in the library (chosen at load time); a defect in the other would go unseen.
  // Both must give the same positive and negative bits and the same gap answer, equal to what the
  // library's dispatched function and the unpacked signs route give. Pairs: random wide-exponent
  // matrices, large spheres (the gap test open) and spheres within 2^-k of tangency (signs at the
  // edge of their bounds).
  using relpos::detail::FilterCopy;
  REQUIRE(relpos::detail::static_filter_copy_runs(FilterCopy::baseline));
  const bool avx2 = relpos::detail::static_filter_copy_runs(FilterCopy::avx2);
  if (!avx2) WARN("the AVX2 copy is not built or this CPU lacks AVX2: only the baseline copy is compared");
  Rng g(seed_from_env(23));
  const DoubleMatrix4 cup = *storage_of(Paraboloid::standard({Q(0), Q(0), Q(0)}, Q(1), Q(2))).filter_doubles();
  long pairs = 0, gaps = 0, uncertain = 0, differ = 0;
  auto compare = [&](const DoubleMatrix4& pn, const DoubleMatrix4& en) {
    std::optional<bool> gap_public, gap_signs, gap_copy[2];
    const auto want = relpos::static_filter_discriminant_bits_normalized(pn, en, &gap_public);
    const auto signs = sign_codes(relpos::static_filter_discriminant_signs_normalized(
        pn, en, [](const relpos::QuarticSigns&) { return true; }, &gap_signs));
    CHECK(sign_codes(want.signs()) == signs);
    CHECK(gap_public == gap_signs);
    for (const FilterCopy copy : {FilterCopy::baseline, FilterCopy::avx2}) {
      if (copy == FilterCopy::avx2 && !avx2) continue;
      auto& gap = gap_copy[copy == FilterCopy::avx2];
      const auto got = relpos::detail::static_filter_discriminant_bits_copy(copy, pn, en, &gap);
      CAPTURE(static_cast<int>(copy), want.positive, want.negative, got.positive, got.negative);
      CHECK(got.positive == want.positive);
      CHECK(got.negative == want.negative);
      CHECK(gap == gap_public);
      differ += got.positive != want.positive || got.negative != want.negative || gap != gap_public;
    }
    ++pairs;
    gaps += gap_public.has_value();
    uncertain += (want.positive | want.negative) != 0xffu;
  };
  for (int n = 0; n < 2000; ++n) {
    DoubleMatrix4 pn, en;
    if (random_normalized_pair(g, pn, en)) compare(pn, en);
    for (const Ellipsoid& e : {large_sphere(g), near_tangent_sphere(g)})
      if (storage_of(e).filter_doubles()) compare(cup, *storage_of(e).filter_doubles());
  }
  std::cout << "[filters] filter copies" << (avx2 ? " (baseline, AVX2)" : " (baseline only)") << ": " << pairs
            << " pairs, " << gaps << " with the gap test answered, " << uncertain << " with a sign uncertain\n";
  CHECK(differ == 0);
  // The comparison covers each kind of answer: gap tests answered, signs left uncertain, all certain.
  CHECK(pairs >= 4000);
  CHECK(gaps >= 100);
  CHECK(uncertain >= 100);
  CHECK(uncertain < pairs);
}

TEST_CASE("semi-static filter on rational entries: every certified sign is the exact sign", "[filters][random]") {
  // Rational spheres near tangency (the demo scene's wall bodies) and random rational matrices with
  // large denominators: entries enter as double enclosures.
  Rng g(seed_from_env(31));
  const Paraboloid p = Paraboloid::standard({Q(0), Q(0), Q(0)}, Q(1), Q(2));
  long certified = 0, quantities = 0, wrong = 0, pairs = 0;
  auto check = [&](const relpos::Matrix4& pm, const relpos::Matrix4& em) {
    // Exact signs of the same quantities on the rational matrices themselves.
    const auto q = exact_signs(pm, em);
    const auto got = flatten(relpos::semi_static_filter_signs(pm, em));
    // The discriminant route from enclosures of the same rationals.
    auto enclosure = [](const relpos::Matrix4& m) {
      relpos::detail::EnclosureMatrix4 x;
      for (std::size_t i = 0; i < 16; ++i) std::tie(x.lo[i], x.hi[i]) = CGAL::to_interval(m.a[i]);
      return x;
    };
    const auto disc = flatten(relpos::semi_static_filter_discriminant_signs(enclosure(pm), enclosure(em)));
    for (std::size_t i = 0; i < 13; ++i) {
      ++quantities;
      for (const auto* sign : {&got[i], &disc[i]}) {
        if (!CGAL::is_certain(*sign)) continue;
        ++certified;
        const int x = static_cast<int>(CGAL::get_certain(*sign));
        CAPTURE(i, x);
        CHECK(x == q[i]);
        wrong += x != q[i];
      }
    }
    ++pairs;
  };
  relpos::DemoSceneGenerator gen(seed_from_env(5), Q(1), Q(2), 0.9);
  for (int n = 0; n < 4000 && pairs < 300; ++n) {
    const Ellipsoid e = gen.next().ellipsoid();
    if (!e.doubles()) check(p.matrix(), e.matrix());
  }
  for (int n = 0; n < 300; ++n) {
    relpos::Matrix4 m[2];
    for (auto& x : m)
      for (int i = 0; i < 4; ++i)
        for (int j = i; j < 4; ++j) {
          const Rational v = g.chance(20) ? Q(0) : Q(g.uniform(-(1L << 40), 1L << 40), g.uniform(1, 1L << 30));
          x(i, j) = v;
          x(j, i) = v;
        }
    check(m[0], m[1]);
  }
  std::cout << "[filters] rational entries: " << pairs << " pairs, " << certified << " of " << quantities
            << " signs certified\n";
  CHECK(wrong == 0);
  CHECK(pairs >= 500);
  CHECK(certified * 10 >= quantities * 8);
}

TEST_CASE("semi-static filter: entries that are subnormal as doubles are not trusted (review finding)",
          "[filters][regression]") {
  // An ellipsoid whose entries lie near 2^-1000: mpq_get_d of a is subnormal and off by up to 2^-1074
  // (not 2^-52 |v|); the filter once certified det E > 0 and rho > 1 here, and decide_position said
  // "unclassified" where classify_exact says E.
  auto two_to_minus = [](int k) { return Q(1) / pow_q(Q(2), k); };  // pow_q takes k >= 0
  const Rational S = two_to_minus(990);
  const Rational n = two_to_minus(1015) * (Q(1) + two_to_minus(20));
  const Rational a = n * n / S + two_to_minus(1100);
  relpos::Matrix4 E, P;
  for (auto& x : E.a) x = Q(0);
  for (auto& x : P.a) x = Q(0);
  E(0, 0) = a, E(0, 1) = E(1, 0) = n, E(1, 1) = S, E(2, 2) = S, E(3, 3) = -S;
  P(0, 0) = Q(1), P(1, 1) = Q(1, 4), P(2, 3) = P(3, 2) = Q(-1, 2), P(3, 3) = Q(10);
  const auto q = exact_signs(P, E);
  const auto got = flatten(relpos::semi_static_filter_signs(P, E));
  for (std::size_t i = 0; i < 13; ++i)
    if (CGAL::is_certain(got[i])) CHECK(static_cast<int>(CGAL::get_certain(got[i])) == q[i]);
  const Ellipsoid e = Ellipsoid::from_matrix(E);
  const Paraboloid p = Paraboloid::from_matrix(P);
  CHECK(relpos::decide_position(e, p).position ==
        relpos::classify_exact(e, p, relpos::Evidence::Minimal).verdict.position);
  CHECK(relpos::classify_exact(e, p, relpos::Evidence::Minimal).verdict.position == relpos::Position::E);
}

TEST_CASE("translated semi-static filter: every certified sign is the exact sign of the moved body",
          "[filters][random]") {
  // The moved ellipsoid's entries are evaluated with their error carried along (never formed
  // exactly); compare with the exact signs of Ellipsoid::translated, for exact-double and for
  // rational reference bodies, translations over many binary orders (and zeros).
  Rng g(seed_from_env(17));
  std::mt19937_64 rng(g.seed);
  const Paraboloid p = Paraboloid::standard({Q(0), Q(0), Q(0)}, Q(1), Q(2));
  long certified = 0, quantities = 0, wrong = 0;
  for (int n = 0; n < 600; ++n) {
    const Vector3 c{g.rational(-8, 8, n % 2 ? 16 : 7), g.rational(-8, 8, 16), g.rational(-4, 8, 16)};
    const Ellipsoid ref = n % 3 == 0 ? Ellipsoid::sphere(c, Q(g.uniform(1, 32), 64))
                                     : Ellipsoid::from_axes(c, V(Q(1, 4), Q(1, 8), Q(g.uniform(1, 8), 32)),
                                                            relpos::Quaternion{Q(g.uniform(-2, 2)), Q(g.uniform(-2, 2)),
                                                                               Q(g.uniform(-2, 2)), Q(1)});
    std::array<double, 3> d;
    for (double& x : d) {
      const int kind = static_cast<int>(g.uniform(0, 9));
      x = kind == 0
              ? 0.0
              : std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng), static_cast<int>(g.uniform(-30, 3)));
    }
    const Ellipsoid moved =
        ref.translated(V(relpos::exact_rational(d[0]), relpos::exact_rational(d[1]), relpos::exact_rational(d[2])));
    const auto q = exact_signs(p.matrix(), moved.matrix());
    const auto got = flatten(storage_of(ref).filter_doubles()
                                 ? relpos::semi_static_filter_signs_translated(*storage_of(p).filter_doubles(),
                                                                               *storage_of(ref).filter_doubles(), d)
                                 : relpos::semi_static_filter_signs_translated(p.matrix(), ref.matrix(), d));
    for (std::size_t i = 0; i < 13; ++i) {
      ++quantities;
      if (!CGAL::is_certain(got[i])) continue;
      ++certified;
      const int x = static_cast<int>(CGAL::get_certain(got[i]));
      CAPTURE(n, i, x);
      CHECK(x == q[i]);
      wrong += x != q[i];
    }
  }
  std::cout << "[filters] translated: " << certified << " of " << quantities << " signs certified\n";
  CHECK(wrong == 0);
  CHECK(certified * 10 >= quantities * 8);
}

TEST_CASE("semi-static gap test (math.md §8): every certified answer is the exact one", "[filters][random]") {
  // Large spheres and ellipsoids near the cup (most pairs are not small, many need the gap test),
  // and random matrices with wide exponents: whenever the double filter answers, the exact gap test
  // on the same f and s answers the same.
  Rng g(seed_from_env(808));
  std::cout << "[filters] gap seed " << g.seed << "\n";
  auto u = [&g](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g.gen); };
  int answered = 0, pairs = 0;
  for (int n = 0; n < 3000; ++n) {
    DoubleMatrix4 pm{}, em{};
    auto set = [](DoubleMatrix4& m, int i, int j, double v) {
      m[static_cast<std::size_t>(4 * i + j)] = m[static_cast<std::size_t>(4 * j + i)] = v;
    };
    const double a = u(0.5, 2), b = u(0.5, 2);
    set(pm, 0, 0, 1 / (a * a));
    set(pm, 1, 1, 1 / (b * b));
    set(pm, 2, 3, -0.5);
    const double c[3] = {u(-1, 1), u(-1, 1), u(-0.5, 3)};
    const double k[3] = {u(0.1, 4), u(0.1, 4), u(0.1, 4)};
    double e0 = -u(0.05, 4);
    for (int i = 0; i < 3; ++i) {
      set(em, i, i, k[i]);
      set(em, i, 3, -k[i] * c[i]);
      e0 += k[i] * c[i] * c[i];
    }
    em[15] = e0;
    if (n % 3 == 0) set(em, 0, 1, u(-0.05, 0.05));
    const auto pn = relpos::detail::power_of_two_normalized(pm), en = relpos::detail::power_of_two_normalized(em);
    if (!pn || !en) continue;
    ++pairs;
    const auto fast = relpos::semi_static_roots_above_lambda_s(*pn, *en);
    if (!fast) continue;
    relpos::Matrix4 p, e;
    for (std::size_t i = 0; i < 16; ++i) {
      p.a[i] = relpos::exact_rational((*pn)[i]);
      e.a[i] = relpos::exact_rational((*en)[i]);
    }
    const RationalView pv{p}, ev{e};
    const auto f = relpos::characteristic_polynomial<Rational>(pv, ev);
    const auto s = relpos::special_polynomial<Rational>(pv, ev);
    const auto exact =
        relpos::detail::anysize::roots_above_lambda_s(relpos::detail::anysize::GapQuantities<Rational>(f, s),
                                                      [](const Rational& x) { return std::optional<int>(sgn(x)); });
    REQUIRE(exact);
    CHECK(*fast == *exact);
    ++answered;
  }
  std::cout << "[filters] gap: " << pairs << " pairs, answered by the double filter on " << answered << "\n";
  CHECK(answered * 10 >= pairs * 9);
}

TEST_CASE("semi-static filter: Disc(f) hopeless near a tangency, the ladder goes straight to exact signs",
          "[filters]") {
  // A sphere of radius 1/4 tangent from inside at the vertex (0, 0, -1) of z = x^2 + y^2 / 2 - 1
  // (smallest radius of curvature 1/2), moved by delta along the axis: I into the cup, C out of it
  // (positions by construction). Every decision needs the sign of Disc(f), about delta in relative
  // terms; every entry is far from 0, so the semi-static stage runs on their enclosures.
  relpos::Matrix4 P;
  for (auto& x : P.a) x = Q(0);
  P(0, 0) = Q(1), P(1, 1) = Q(1, 2), P(2, 3) = P(3, 2) = Q(-1, 2), P(3, 3) = Q(-1);
  const Paraboloid p = Paraboloid::from_matrix(P);
  for (int k : {100, 130})
    for (int side : {1, -1}) {
      CAPTURE(k, side);
      const Rational delta = Q(1) / pow_q(Q(2), k);
      const Ellipsoid e = Ellipsoid::sphere({Q(0), Q(0), Q(-3, 4) + side * delta}, Q(1, 4));
      const DecisionSigns d = relpos::semi_static_filter_signs(P, e.matrix());
      CHECK(!CGAL::is_certain(d.quartic.g0));
      CHECK(d.disc_hopeless);
      const relpos::Verdict v = relpos::decide_position(e, p);
      CHECK(v.position == (side > 0 ? relpos::Position::I : relpos::Position::C));
      CHECK(v.stage == relpos::Stage::ExactSigns);
    }
  // Far from any tangency the flag stays down, whether or not every sign is certified.
  const Ellipsoid far = Ellipsoid::sphere({Q(0), Q(0), Q(0)}, Q(1, 3));
  CHECK_FALSE(relpos::semi_static_filter_signs(P, far.matrix()).disc_hopeless);
}

TEST_CASE("filtered.hpp: each approximation under its rounding mode, the exact one only when all are uncertain",
          "[filters]") {
  using relpos::detail::approximate;
  using relpos::detail::filtered;
  using relpos::detail::level;
  using relpos::detail::Rounding;
  using relpos::detail::rounding_to_nearest;
  using relpos::detail::settle;
  // The mode each approximation runs in, read from the control register.
  auto upward = [] { return CGAL::FPU_get_cw() == CGAL_FE_UPWARD; };
  REQUIRE(rounding_to_nearest());
  CHECK(approximate<Rounding::Upward>([&] { return std::optional<bool>(upward()); }) == std::optional<bool>(true));
  CHECK(rounding_to_nearest());  // restored
  CHECK(approximate<Rounding::Nearest>([&] { return std::optional<bool>(upward()); }) == std::optional<bool>(false));
  {
    CGAL::Protect_FPU_rounding<true> up;  // a caller inside an upward block
    CHECK_FALSE(approximate<Rounding::Nearest>([&] { return std::optional<bool>(true); }));  // skipped
    CHECK(approximate<Rounding::ToNearest>([&] { return std::optional<bool>(upward()); }) ==
          std::optional<bool>(false));
    CHECK_FALSE(rounding_to_nearest());  // the caller's mode again
  }
  // The exact computation runs only when the approximation is uncertain.
  int exact_calls = 0;
  auto exact = [&] { return ++exact_calls, 7; };
  CHECK(filtered<Rounding::Nearest>([] { return std::optional<int>(3); }, exact) == 3);
  CHECK(exact_calls == 0);
  CHECK(filtered<Rounding::Nearest>([] { return std::optional<int>(); }, exact) == 7);
  CHECK(exact_calls == 1);
  // settle: the first certain level, in order, and which one; the later levels do not run.
  int later = 0;
  const auto first = settle(exact, level<Rounding::Nearest>([] { return std::optional<int>(); }),
                            level<Rounding::Upward>([] { return std::optional<int>(5); }),
                            level<Rounding::Nearest>([&] { return ++later, std::optional<int>(6); }));
  CHECK(first.value == 5);
  CHECK(first.by == 1);
  CHECK(later == 0);
  const auto none = settle(exact, level<Rounding::Upward>([] { return std::optional<int>(); }));
  CHECK(none.value == 7);
  CHECK(none.by == 1);
  CHECK(exact_calls == 2);
}
