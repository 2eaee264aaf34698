// Properties on thousands of random small configurations: classify() == classify_exact(), the
// algebra every configuration determines (f, s, rho, Disc signs, deg f~, multiplicities at the
// roots of s), invariance under congruences and rescalings, the kernel tangency test, the paper's
// Table 2 where it applies, and the position wherever an independent argument fixes it (centre on
// the axis; a point of the cup inside the ball; a separating tangent plane; the side of the centre).
#include <catch2/catch.hpp>
#include <vector>

#include "support/checks.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"
#include "support/scale.hpp"

using namespace rt;
using relpos::Classification;
using relpos::Ellipsoid;
using relpos::Paraboloid;

namespace {

/// A random sphere / standard paraboloid configuration with small entries, biased towards the
/// degenerate cases: centres on the axis or in a symmetry plane, circular cups, on-axis
/// tangencies, centres on the surface, 2r = a^2.
Config random_small_config(Rng& g) {
  static const Rational ab[] = {Q(1, 2), Q(1), Q(3, 2), Q(2)};
  Config k;
  k.name = "random";
  k.a = ab[g.uniform(0, 3)];
  k.b = g.chance(25) ? k.a : ab[g.uniform(0, 3)];
  k.c = {Q(g.uniform(-8, 8), 4), Q(g.uniform(-8, 8), 4), Q(g.uniform(-8, 8), 4)};
  k.r = Q(g.uniform(1, 12), 8);
  const long kind = g.uniform(0, 99);
  if (kind < 15)
    k.c[0] = 0;
  else if (kind < 30)
    k.c[1] = 0;
  else if (kind < 45)
    k.c[0] = k.c[1] = 0;  // on the axis
  else if (kind < 55) {   // on the axis, tangent at the vertex
    k.c[0] = k.c[1] = 0;
    k.c[2] = g.chance(50) ? k.r : -k.r;
  } else if (kind < 62) {  // centre on the surface
    k.c[2] = paraboloid_value(k.a, k.b, {k.c[0], k.c[1], Rational(0)});
  } else if (kind < 68) {  // 2r = a^2
    k.r = rmin(k.a, k.b) * rmin(k.a, k.b) / 2;
  }
  return k;
}

/// What an independent argument says about the configuration: the truth, or nothing.
struct Oracle {
  bool known = false;
  Position truth = Position::C;  ///< read only when known
  bool centre_inside = false, centre_outside = false;
};

Oracle oracle(const Config& k) {
  Oracle o;
  const Rational side = paraboloid_value(k.a, k.b, k.c);
  o.centre_inside = side < 0;
  o.centre_outside = side > 0;
  if (k.c[0] == 0 && k.c[1] == 0) {
    // On the axis at height z, any size. Below the vertex: E / TE / C by z + r. Above: the squared
    // distance to the surface is min over X = x^2 >= 0 of X + (X/a^2 - z)^2 with a = min(a, b) (the
    // narrower section is nearer), i.e. z^2 for z <= a^2/2 (the vertex) and a^2 z - a^4/4 beyond;
    // the ball is inside (I), touching (TI) or crossing (C) as that exceeds, equals or is below r^2.
    const Rational a2 = rmin(k.a, k.b) * rmin(k.a, k.b), z = k.c[2];
    o.known = true;
    if (z < k.r) {
      o.truth = axis_position(z, k.r);
    } else {
      const Rational d2 = z <= a2 / 2 ? z * z : a2 * z - a2 * a2 / 4;
      o.truth = d2 > k.r * k.r ? Position::I : (d2 == k.r * k.r ? Position::TI : Position::C);
    }
    return o;
  }
  if (crossing_certificate(k)) {
    o.known = true;
    o.truth = Position::C;
  } else if (separation_certificate(k)) {
    o.known = true;
    o.truth = Position::E;
  }
  return o;
}

/// Checks what the oracle knows, plus the side of the centre.
void check_oracle(const Classification& c, const Oracle& o) {
  if (o.centre_outside) CHECK((c.verdict.position != Position::I && c.verdict.position != Position::TI));
  if (o.centre_inside) CHECK((c.verdict.position != Position::E && c.verdict.position != Position::TE));
}

}  // namespace

TEST_CASE("random small configurations: exact algebra, classify == classify_exact, oracles", "[properties][random]") {
  const std::uint64_t seed = 0xC0FFEE42;
  Rng g(seed);
  CAPTURE(seed);
  const int kernel_before = g_kernel_checks, table2_before = g_table2_checks;
  int known = 0, total = 0;
  int seen[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < relpos::testing::scaled(2500); ++i) {
    Config k = random_small_config(g);
    const Oracle o = oracle(k);
    k.expected = o.truth;
    Expect x = expect_from(k);
    x.truth_known = o.known;
    CAPTURE(i, describe(k));
    const bool transformed = g.chance(40);
    Classification c;
    if (transformed) {
      const Transformed t = transform(k.e(), k.p(), g, g.chance(50));
      Expect xt = expect_from(k, t);
      xt.truth_known = o.known;
      c = check_all(Ellipsoid::from_matrix(t.e), Paraboloid::from_matrix(t.p), xt);
    } else {
      c = check_all(Ellipsoid::from_matrix(k.e()), Paraboloid::from_matrix(k.p()), x);
    }
    check_oracle(c, o);
    ++total;
    if (o.known) ++known;
    ++seen[static_cast<int>(c.verdict.position)];
  }
  // The oracles fix a good share of the cases and every position occurs (every pair gets one of the
  // five, math.md §8).
  CHECK(known * 2 > total);
  for (const Position q : {Position::I, Position::TI, Position::C, Position::TE, Position::E})
    CHECK(seen[static_cast<int>(q)] > relpos::testing::scaled(20));
  CHECK(g_kernel_checks - kernel_before > relpos::testing::scaled(100));
  CHECK(g_table2_checks - table2_before > relpos::testing::scaled(500));
}

TEST_CASE("random general ellipsoids: the answer is invariant under congruences and rescalings",
          "[properties][random]") {
  // Metamorphic: whatever the answer, Q -> k H^T Q H (same H) must not change it.
  const std::uint64_t seed = 0xA11CE;
  Rng g(seed);
  CAPTURE(seed);
  for (int i = 0; i < 150; ++i) {
    CAPTURE(i);
    const Vector3 c{g.rational(-6, 6, 2), g.rational(-6, 6, 2), g.rational(-3, 6, 2)};
    const Vector3 axes{g.positive_rational(4, 4), g.positive_rational(4, 4), g.positive_rational(4, 4)};
    const Ellipsoid e = Ellipsoid::from_axes(c, axes, random_quaternion(g));
    const Paraboloid p =
        Paraboloid::standard({g.rational(-2, 2, 2), g.rational(-2, 2, 2), g.rational(-2, 2, 2)},
                             g.positive_rational(4, 2), g.positive_rational(4, 2), random_quaternion(g));
    const Classification c0 = relpos::classify(e, p);
    check_same(c0, relpos::classify_exact(e, p));
    check_kernel(e, p, c0);
    check_table2(c0);
    for (int j = 0; j < 2; ++j) {
      const Transformed t = transform(e.matrix(), p.matrix(), g);
      const Ellipsoid e2 = Ellipsoid::from_matrix(t.e);
      const Paraboloid p2 = Paraboloid::from_matrix(t.p);
      const Classification c1 = relpos::classify(e2, p2);
      CHECK(c1.verdict.position == c0.verdict.position);
      CHECK(c1.verdict.small == c0.verdict.small);
      CHECK(c1.verdict.rho_vs_one == c0.verdict.rho_vs_one);
      CHECK(c1.verdict.sign_disc_f == c0.verdict.sign_disc_f);
      CHECK(c1.verdict.sign_disc_ftilde == c0.verdict.sign_disc_ftilde);
      CHECK(c1.degree_ftilde == c0.degree_ftilde);
      CHECK(c1.verdict.negative_roots == c0.verdict.negative_roots);
      CHECK(c1.verdict.positive_roots == c0.verdict.positive_roots);
      CHECK(c1.verdict.nonreal_roots == c0.verdict.nonreal_roots);
      for (std::size_t k = 0; k < 5; ++k) CHECK(c1.f[k] == transformed_f(c0.f, t)[k]);
      for (std::size_t k = 0; k < 3; ++k) CHECK(c1.s[k] == transformed_s(c0.s, t)[k]);
      CHECK(c1.rho.has_value() == c0.rho.has_value());
      if (c1.rho && c0.rho) CHECK(*c1.rho == *c0.rho);
      REQUIRE(c1.roots.size() == c0.roots.size());
      for (std::size_t k = 0; k < c0.roots.size(); ++k) {
        CHECK(c1.roots[k].multiplicity_f == c0.roots[k].multiplicity_f);
        CHECK(c1.roots[k].multiplicity_s == c0.roots[k].multiplicity_s);
        if (c0.roots[k].exact && c1.roots[k].exact) CHECK(*c1.roots[k].exact == *c0.roots[k].exact * t.root_scale());
      }
    }
  }
}

TEST_CASE("-a^2 double root in the plane x = 0 (the Remark family), random", "[properties][special][random]") {
  // a != b, x_c = 0, z_c = y_c^2/(b^2 - a^2) + r^2/a^2 + a^2/4: -a^2 is a root of s (simple) and a
  // double root of f, generically; no tangency unless it is a triple root.
  const std::uint64_t seed = 0xBADA55;
  Rng g(seed);
  CAPTURE(seed);
  const int kernel_before = g_kernel_checks;
  int certified = 0;
  for (int i = 0; i < 150; ++i) {
    Config k;
    k.name = "Remark family";
    k.a = Q(g.uniform(2, 8), 4);
    do k.b = Q(g.uniform(2, 8), 4);
    while (k.b == k.a);
    k.r = rmin(k.a, k.b) * rmin(k.a, k.b) * Q(g.uniform(1, 8), 16);
    const Rational yc = Q(g.uniform(-8, 8), 8), a2 = k.a * k.a, b2 = k.b * k.b;
    k.c = {Rational(0), yc, yc * yc / (b2 - a2) + k.r * k.r / a2 + a2 / 4};
    const auto f = paper_f(k.a, k.b, k.c, k.r);
    REQUIRE(multiplicity(f, -a2) >= 2);
    const Oracle o = oracle(k);
    k.expected = o.truth;
    Expect x = expect_from(k);
    x.truth_known = o.known;
    CAPTURE(i, describe(k));
    const Classification c = check_all(Ellipsoid::from_matrix(k.e()), Paraboloid::from_matrix(k.p()), x);
    check_oracle(c, o);
    if (o.known) ++certified;
    for (const auto& r : c.roots)
      if (r.lower <= -a2 && -a2 <= r.upper) {
        CHECK(r.multiplicity_s == 1);
        CHECK(r.tangency() == (multiplicity(f, -a2) >= 3));
      }
  }
  CHECK(certified > 10);
  CHECK(g_kernel_checks - kernel_before >= 150);
}

TEST_CASE("-b^2 double root in the plane y = 0, random: C, E or I without tangency", "[properties][special][random]") {
  // y_c = 0, z_c = x_c^2/(a^2 - b^2) + r^2/b^2 + b^2/4 (math.md §3).
  const std::uint64_t seed = 0xB0B;
  Rng g(seed);
  CAPTURE(seed);
  int certified = 0, crossing_with_zero_disc = 0;
  for (int i = 0; i < relpos::testing::scaled(150); ++i) {
    Config k;
    k.name = "-b^2 family";
    k.a = Q(g.uniform(2, 8), 4);
    do k.b = Q(g.uniform(2, 8), 4);
    while (k.b == k.a);
    k.r = rmin(k.a, k.b) * rmin(k.a, k.b) * Q(g.uniform(1, 8), 16);
    const Rational xc = Q(g.uniform(-12, 12), 8), a2 = k.a * k.a, b2 = k.b * k.b;
    k.c = {xc, Rational(0), xc * xc / (a2 - b2) + k.r * k.r / b2 + b2 / 4};
    const auto f = paper_f(k.a, k.b, k.c, k.r);
    REQUIRE(multiplicity(f, -b2) >= 2);
    const Oracle o = oracle(k);
    k.expected = o.truth;
    Expect x = expect_from(k);
    x.truth_known = o.known;
    CAPTURE(i, describe(k));
    const Classification c = check_all(Ellipsoid::from_matrix(k.e()), Paraboloid::from_matrix(k.p()), x);
    check_oracle(c, o);
    if (o.known) ++certified;
    if (c.verdict.position == Position::C && c.verdict.sign_disc_f == 0) ++crossing_with_zero_disc;
    // A transformed copy: same answer, same algebra up to the known factors.
    const Transformed t = transform(k.e(), k.p(), g);
    Expect xt = expect_from(k, t);
    xt.truth_known = o.known;
    const Classification ct = check_all(Ellipsoid::from_matrix(t.e), Paraboloid::from_matrix(t.p), xt);
    CHECK(ct.verdict.position == c.verdict.position);
  }
  CHECK(certified > relpos::testing::scaled(30));
  CHECK(crossing_with_zero_disc > relpos::testing::scaled(5));
}
