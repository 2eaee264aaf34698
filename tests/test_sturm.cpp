// sturm.hpp and smallness.hpp: root counts from the Sturm-Habicht signs on quartics with known
// roots, the identity g0 = Disc(f) (against the 16-term formula and a^6 prod (ri - rj)^2), and the
// smallness test rho <= 1 on the paper's closed forms, invariant under positive rescalings.
#include <catch2/catch.hpp>
#include <vector>

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
