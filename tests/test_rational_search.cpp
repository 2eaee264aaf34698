// The certificates' searches over the rationals (src/certificate/rational_search.hpp): refine_root
// converges to the one sign change of its bracket with every good end on the good side, in few rounds
// near a simple root (quadratic convergence), from either orientation, and gives up within its
// budget; search_near_roots reaches every real root; the dyadic tools satisfy their definitions.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "anysize/exact.hpp"
#include "certificate/rational_search.hpp"
#include "pair/integer_poly.hpp"
#include "support/construct.hpp"
#include "support/seed.hpp"

using relpos::Rational;
using relpos::detail::IntegerPoly;
using relpos::detail::anysize::Poly;
using relpos::detail::certificate::floor_to;
using relpos::detail::certificate::log2_of;
using relpos::detail::certificate::power_of_two;
using relpos::detail::certificate::refine_root;
using relpos::detail::certificate::search_near_roots;
using relpos::detail::certificate::sqrt_below;
using rt::Q;
using rt::sgn;

TEST_CASE("refine_root: sqrt(n) to 1000 bits, every good end below it, in O(log bits) rounds", "[search]") {
  rt::Rng g(relpos::testing::announced_seed("test_rational_search", 20260303));
  for (int t = 0; t < 40; ++t) {
    const long n = g.uniform(2, 1000000);
    if (std::sqrt(double(n)) == std::floor(std::sqrt(double(n)))) continue;
    INFO("n = " << n);
    const Poly q{Q(-n), Q(0), Q(1)};  // x^2 - n: one sign change in (0, n)
    const IntegerPoly qz(q);
    const unsigned bits = 1000;
    const Rational eps = power_of_two(-long(bits));
    int calls = 0;
    bool all_good = true;
    auto accept = [&](const Rational& x) {  // within 2^-bits below sqrt(n)
      ++calls;
      all_good = all_good && x * x <= n;
      return (x + eps) * (x + eps) > n;
    };
    REQUIRE(refine_root(qz, Q(0), Q(n), accept, 4096));
    CHECK(all_good);
    CHECK(calls < 80);  // quadratic convergence: about log2(1000) doublings, not 1000 halvings
    // The same from above (good > bad): n - x^2 <= 0 above sqrt(n).
    const IntegerPoly rz(Poly{Q(n), Q(0), Q(-1)});
    calls = 0;
    bool above = true;
    REQUIRE(refine_root(
        rz, Q(n), Q(0),
        [&](const Rational& x) {
          ++calls;
          above = above && x * x >= n;
          return (x - eps) * (x - eps) < n;
        },
        4096));
    CHECK(above);
    CHECK(calls < 80);
  }
}

TEST_CASE("refine_root: a rational root reached exactly or within any width; the budget ends a search", "[search]") {
  rt::Rng g(relpos::testing::seed_from_env(20260303));
  for (int t = 0; t < 40; ++t) {
    const Rational r = g.rational(-100000, 100000, 99991);
    INFO("r = " << relpos::to_string(r));
    // (x - r)(x^2 + 1): one real root, simple.
    const Poly q{-r, Q(1), -r, Q(1)};
    const IntegerPoly qz(q);
    const Rational lo = r - g.positive_rational(50, 3), hi = r + g.positive_rational(50, 3);
    const Rational eps = power_of_two(-300);
    Rational last;
    REQUIRE(refine_root(
        qz, lo, hi,
        [&](const Rational& x) {
          CHECK(relpos::evaluate(q, x) <= 0);
          last = x;
          return r - x < eps;
        },
        2048));
    CHECK(last <= r);
    CHECK(r - last < eps);
    // An accept that never holds: false within the budget (bits below the scale of `bad`).
    int calls = 0;
    CHECK_FALSE(refine_root(
        qz, lo, hi, [&](const Rational&) { return ++calls < 0; }, 64));
    CHECK(calls <= 2 * 64 + 1);
  }
}

TEST_CASE("search_near_roots: a point near each real root of a cubic", "[search]") {
  rt::Rng g(relpos::testing::seed_from_env(20260303));
  for (int t = 0; t < 30; ++t) {
    Rational roots[3] = {g.rational(-50, 50, 7), g.rational(-50, 50, 7), g.rational(-50, 50, 7)};
    if (roots[0] == roots[1] || roots[1] == roots[2] || roots[0] == roots[2]) continue;
    // (x - a)(x - b)(x - c) times 5, expanded.
    const Rational& a = roots[0];
    const Rational& b = roots[1];
    const Rational& c = roots[2];
    const Poly q{-5 * a * b * c, 5 * (a * b + b * c + a * c), -5 * (a + b + c), Q(5)};
    const Rational eps = power_of_two(-60);
    for (const Rational& root : roots) {
      const auto found = search_near_roots(
          q, [&](const Rational& x) { return rt::rabs(x - root) < eps; }, 1024);
      REQUIRE(found);
      CHECK(rt::rabs(*found - root) < eps);
    }
    // A polynomial without real roots: the first box's midpoint only, then nothing is left to refine.
    int offered = 0;
    CHECK_FALSE(search_near_roots(
        Poly{Q(1), Q(0), Q(1)}, [&](const Rational&) { return ++offered < 0; }, 64));
    CHECK(offered <= 1);
  }
}

TEST_CASE("dyadic tools: floor_to, log2_of, sqrt_below against their definitions", "[search]") {
  rt::Rng g(relpos::testing::seed_from_env(20260303));
  for (int t = 0; t < 500; ++t) {
    const Rational x = g.nonzero_rational(-1000000, 1000000, 999983) * power_of_two(g.uniform(-80, 80));
    const long e = g.uniform(-100, 100);
    const Rational f = floor_to(x, e), step = power_of_two(e);
    CHECK(f <= x);
    CHECK(x < f + step);
    const Rational k = f / step;
    CHECK(k.denominator() == 1);
    const long l = log2_of(x);
    const Rational ax = rt::rabs(x);
    CHECK(power_of_two(l - 1) <= ax);
    CHECK(ax < power_of_two(l + 1));
    const unsigned bits = static_cast<unsigned>(g.uniform(1, 120));
    const Rational r = sqrt_below(ax, bits), u = power_of_two(-long(bits));
    CHECK(r * r <= ax);
    CHECK(ax < (r + u) * (r + u));
  }
}
