// sturm.hpp, sturm_habicht_quartic.hpp, small_factor.hpp and smallness.hpp: root counts from the
// Sturm-Habicht signs on quartics with known roots, the identity g0 = Disc(f) (against the 16-term
// formula and a^6 prod (ri - rj)^2), the sequence beside a known discriminant equal to the full one,
// the counts of a square-free factor of degree <= 2 against the roots it was built from, and the
// smallness test rho <= 1 on the paper's closed forms, invariant under positive rescalings.
#include <catch2/catch.hpp>
#include <vector>

#include "algebra/small_factor.hpp"
#include "algebra/smallness.hpp"
#include "algebra/sturm.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;

TEST_CASE("Sturm-Habicht root counts on quartics with known roots", "[sturm]") {
  struct Known {
    std::array<Rational, 4> roots;
    int real, negative, positive;
  };
  const std::vector<Known> known = {
      {{Q(-1), Q(-2), Q(-3), Q(-4)}, 4, 4, 0},
      {{Q(-1), Q(-2), Q(3), Q(5)}, 4, 2, 2},
      {{Q(1, 3), Q(2), Q(-7, 2), Q(9)}, 4, 1, 3},
      {{Q(1), Q(2), Q(3), Q(4)}, 4, 0, 4},
  };
  for (const auto& k : known)
    for (int lead : {1, -3}) {
      const Quartic<Rational> f = quartic_from_roots(Q(lead), k.roots);
      relpos::SturmHabicht<Rational> sh(f);
      auto c = relpos::count_roots(f, sh);
      REQUIRE(c.has_value());
      CHECK(c->real == k.real);
      CHECK(c->negative == k.negative);
      CHECK(c->positive == k.positive);
      CHECK(sh.discriminant() > 0);
    }
  // Non-real roots: (l^2 + 1)(l + 1)(l - 2): 2 real; (l^2 + 1)(l^2 + 4): none;
  // (l^2 - 2l + 5)(l + 3)(l + 5/2): 2 real negative.
  auto times = [](const std::array<Rational, 3>& p, const std::array<Rational, 3>& q) {
    Quartic<Rational> f{};
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) f[i + j] += p[i] * q[j];
    return f;
  };
  struct KnownPoly {
    Quartic<Rational> f;
    int real, negative, positive, disc_sign;
  };
  const std::vector<KnownPoly> polys = {
      {times({Q(1), Q(0), Q(1)}, {Q(-2), Q(-1), Q(1)}), 2, 1, 1, -1},
      {times({Q(1), Q(0), Q(1)}, {Q(4), Q(0), Q(1)}), 0, 0, 0, 1},
      {times({Q(5), Q(-2), Q(1)}, {Q(15, 2), Q(11, 2), Q(1)}), 2, 2, 0, -1},
  };
  for (const auto& k : polys) {
    relpos::SturmHabicht<Rational> sh(k.f);
    auto c = relpos::count_roots(k.f, sh);
    REQUIRE(c.has_value());
    CHECK(c->real == k.real);
    CHECK(c->negative == k.negative);
    CHECK(c->positive == k.positive);
    CHECK(sgn(sh.discriminant()) == k.disc_sign);
  }
  // A double root makes the sequence defective (Disc = 0): no answer, the caller goes exact.
  const Quartic<Rational> dbl = quartic_from_roots(Q(1), {Q(-1), Q(-1), Q(2), Q(3)});
  relpos::SturmHabicht<Rational> sh(dbl);
  CHECK(sh.discriminant() == 0);
  CHECK_FALSE(relpos::count_roots(dbl, sh).has_value());
}

TEST_CASE("the Sturm-Habicht g0 is the discriminant of f", "[sturm][random]") {
  Rng g(8080);
  for (int i = 0; i < 200; ++i) {
    Quartic<Rational> f{g.nonzero_rational(-9, 9, 3), g.rational(-9, 9, 3), g.rational(-9, 9, 3), g.rational(-9, 9, 3),
                        g.nonzero_rational(-9, 9, 3)};
    relpos::SturmHabicht<Rational> sh(f);
    CHECK(sh.discriminant() == quartic_discriminant(f));
  }
  // And the 16-term formula itself: Disc = a^6 prod (ri - rj)^2.
  const std::array<Rational, 4> r{Q(-1), Q(2), Q(1, 2), Q(5)};
  Rational prod(1);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j) prod *= (r[i] - r[j]) * (r[i] - r[j]);
  CHECK(quartic_discriminant(quartic_from_roots(Q(3), r)) == pow_q(Q(3), 6) * prod);
}

TEST_CASE("compare_rho_with_one: rho = 4 r^2 / min(a,b)^4 against 1", "[smallness]") {
  struct Case {
    Rational a, b, r;
    int want;
  };
  const std::vector<Case> cases = {
      {Q(1), Q(2), Q(1, 4), -1},
      {Q(1), Q(2), Q(1, 2), 0},
      {Q(1), Q(2), Q(3, 4), 1},
      {Q(2), Q(1), Q(1, 2), 0},
      {Q(2), Q(1), Q(1, 2) + Q(1, 1000000), 1},
      {Q(2), Q(1), Q(1, 2) - Q(1, 1000000), -1},
      {Q(1), Q(1), Q(1, 2), 0},
      {Q(1), Q(1), Q(2), 1},
      {Q(6, 5), Q(3, 2), Q(1, 4), -1},
      {Q(6, 5), Q(3, 2), Q(18, 25), 0},
      {Q(3, 2), Q(6, 5), Q(18, 25), 0},
  };
  Rng g(11);
  for (const auto& k : cases) {
    CAPTURE(relpos::to_string(k.a), relpos::to_string(k.b), relpos::to_string(k.r));
    for (int rep = 0; rep < 5; ++rep) {
      const Vector3 c{g.rational(-5, 5, 2), g.rational(-5, 5, 2), g.rational(-5, 5, 2)};
      const auto f = paper_f(k.a, k.b, c, k.r);
      const auto s = paper_s(k.a, k.b);
      auto cmp = relpos::compare_rho_with_one(f, s);
      REQUIRE(cmp.has_value());
      CHECK(*cmp == k.want);
      // Independent of positive rescalings of the pencil (lambda -> t lambda, f -> u f, s -> v s).
      const Rational t = g.positive_rational(9, 7), u = g.positive_rational(9, 7), v = g.positive_rational(9, 7);
      Quartic<Rational> f2;
      Quadratic<Rational> s2;
      for (int i = 0; i < 5; ++i) f2[static_cast<std::size_t>(i)] = u * pow_q(t, i) * f[static_cast<std::size_t>(i)];
      for (int i = 0; i < 3; ++i) s2[static_cast<std::size_t>(i)] = v * pow_q(t, i) * s[static_cast<std::size_t>(i)];
      auto cmp2 = relpos::compare_rho_with_one(f2, s2);
      REQUIRE(cmp2.has_value());
      CHECK(*cmp2 == k.want);
    }
  }
}

TEST_CASE("the Sturm-Habicht g2, g1 beside a known discriminant are the full sequence's", "[sturm][random]") {
  // SturmHabicht(f, Disc f) computes only g2 and g1 (the generated second routine of
  // sturm_habicht_quartic.hpp): they must be the first routine's, on integers and rationals.
  Rng g(4242);
  for (int i = 0; i < 300; ++i) {
    const Quartic<Rational> f{g.nonzero_rational(-30, 30, 4), g.rational(-30, 30, 4), g.rational(-30, 30, 4),
                              g.rational(-30, 30, 4), g.nonzero_rational(-30, 30, 4)};
    const relpos::SturmHabicht<Rational> full(f);
    const relpos::SturmHabicht<Rational> given(f, quartic_discriminant(f));
    for (int k = 0; k < 3; ++k) CHECK(given.g2[k] == full.g2[k]);
    for (int k = 0; k < 2; ++k) CHECK(given.g1[k] == full.g1[k]);
    CHECK(given.discriminant() == full.discriminant());
  }
}

TEST_CASE("count_small: the real roots of a square-free factor of degree <= 2, by sign, from signs",
          "[sturm][random]") {
  // Factors built from their roots: a (x - r1)(x - r2) with distinct non-zero rational roots, a
  // quadratic without real roots (x - u)^2 + v, v > 0, and a linear factor; the counts from the
  // coefficients' and the discriminant's signs alone must be the roots built in.
  Rng g(777);
  for (int i = 0; i < 2000; ++i) {
    const Rational a = g.nonzero_rational(-9, 9, 4);
    const int kind = i % 3;
    Rational r1 = g.nonzero_rational(-20, 20, 5), r2 = g.nonzero_rational(-20, 20, 5);
    if (kind == 0 && r1 == r2) continue;
    Rational h2(0), h1, h0;
    int negative = 0, positive = 0;
    if (kind == 0) {  // two real roots
      h2 = a, h1 = -a * (r1 + r2), h0 = a * r1 * r2;
      negative = (r1 < 0) + (r2 < 0), positive = (r1 > 0) + (r2 > 0);
    } else if (kind == 1) {  // a non-real pair
      const Rational v = g.positive_rational(20, 5);
      h2 = a, h1 = -2 * a * r1, h0 = a * (r1 * r1 + v);
    } else {  // linear: a (x - r1)
      h1 = a, h0 = -a * r1;
      (r1 < 0 ? negative : positive) = 1;
    }
    const int degree = kind == 2 ? 1 : 2;
    const relpos::detail::SmallCount c =
        relpos::detail::count_small(degree, sgn(h1 * h1 - 4 * h2 * h0), sgn(h2), sgn(h1), sgn(h0));
    CAPTURE(i, relpos::to_string(h2), relpos::to_string(h1), relpos::to_string(h0));
    CHECK(c.negative == negative);
    CHECK(c.positive == positive);
  }
}
