// classify(): positions known by construction (never by running the code). Every case states why
// its answer is what it is; check_all() (support/checks.hpp) then asserts the position and all the
// evidence the construction determines, and cross-checks classify_exact(), Evidence::Minimal, the
// kernel tangency test and the paper's Table 2.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "support/checks.hpp"
#include "support/construct.hpp"
#include "support/oracles.hpp"
#include "support/printers.hpp"
#include "support/scale.hpp"
#include "support/secular.hpp"

using namespace rt;
using relpos::Classification;
using relpos::Ellipsoid;
using relpos::Paraboloid;
using relpos::Stage;
using relpos::testing::secular_position;

namespace {

/// The root of c.roots at x, a known root of f: the one whose isolating interval holds x.
const relpos::RealRoot& root_at(const Classification& c, const Rational& x) {
  for (const auto& r : c.roots)
    if (r.lower <= x && x <= r.upper) {
      if (r.exact) CHECK(*r.exact == x);
      return r;
    }
  FAIL("no root " << relpos::to_string(x) << " among the " << c.roots.size() << " listed");
  return c.roots.front();
}

Config config(const char* name, const Rational& a, const Rational& b, const Vector3& c, const Rational& r, Position p) {
  return Config{name, a, b, c, r, p};
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// 1-2. Each position around an exact tangency (rational-normal points), then transformed
// ---------------------------------------------------------------------------------------------

TEST_CASE("tangency at (1,1,2) on z = x^2 + y^2: |n| = |(2,2,-1)| = 3", "[classify][tangency]") {
  // Gradient of x^2 + y^2 - z at (1,1,2) is (2,2,-1), of length 3: the unit outer normal is (2,2,-1)/3.
  const Rational one(1);
  const Vector3 x0{Q(1), Q(1), Q(2)};
  auto at = [&](const Rational& d) {  // x0 + d (2,2,-1)/3
    return V(x0[0] + d * Q(2, 3), x0[1] + d * Q(2, 3), x0[2] - d * Q(1, 3));
  };
  const Rational r(3, 8);  // <= a^2/2 = 1/2: small, and inside the rolling radius
  // TI: centre (1,1,2) - (3/8)(2,2,-1)/3 = (3/4, 3/4, 17/8).
  CHECK(at(-r)[0] == Q(3, 4));
  CHECK(at(-r)[2] == Q(17, 8));
  std::vector<Config> cases = {
      config("TI", one, one, at(-r), r, Position::TI),
      config("TE", one, one, at(r), r, Position::TE),
      config("TE, large sphere (not small)", one, one, at(Q(5)), Q(5), Position::TE),
      config("I (smaller concentric)", one, one, at(-r), Q(1, 4), Position::I),
      config("E (smaller concentric)", one, one, at(r), Q(1, 4), Position::E),
      config("E (pushed out)", one, one, at(Q(1, 2)), r, Position::E),
      config("C (larger concentric)", one, one, at(-r), Q(1, 2), Position::C),
      config("C (centre across x0)", one, one, at(Q(1, 8)), r, Position::C),
      config("C (centre on the surface)", one, one, x0, r, Position::C),
  };
  for (const auto& k : cases) {
    const Classification c = check_config(k);
    if (k.expected == Position::TI || k.expected == Position::TE) {
      // The tangency is a double root; on this circular cup f~ = f / (l + 1), because -a^2 = -1 is
      // a double root of s and (off the axis) a simple root of f.
      CHECK(c.verdict.sign_disc_f == 0);
      CHECK(c.degree_ftilde == 3);
      CHECK((c.verdict.stage == Stage::ExactRoots || c.verdict.stage == Stage::MultipleRootWitness));
    }
  }
}

TEST_CASE("each position in general position, standard frame", "[classify][tangency]") {
  // a != b, tangency points off both symmetry planes (s, t != 0).
  struct Pick {
    Rational a, b, s, t;
  };
  const std::vector<Pick> picks = {
      {Q(6, 5), Q(3, 2), Q(1, 3), Q(-1, 2)},
      {Q(2), Q(1), Q(-3, 4), Q(1, 4)},
      {Q(1, 2), Q(3, 4), Q(2), Q(1)},
  };
  for (const auto& pk : picks) {
    const TangentPoint tp = tangent_point(pk.a, pk.b, pk.s, pk.t);
    // The construction itself: x0 on the surface and |n| = m.
    REQUIRE(paraboloid_value(pk.a, pk.b, tp.x0) == 0);
    REQUIRE(tp.n[0] * tp.n[0] + tp.n[1] * tp.n[1] + 1 == tp.m * tp.m);
    REQUIRE(tp.n[0] == 2 * tp.x0[0] / (pk.a * pk.a));
    REQUIRE(tp.n[1] == 2 * tp.x0[1] / (pk.b * pk.b));
    const Rational r = rmin(pk.a, pk.b) * rmin(pk.a, pk.b) / 5;
    for (const Config& k : tangency_family(tp, r, 3)) {
      Expect x = expect_from(k);
      // Generic, moderate entries: the interval filter decides everything but the tangencies.
      x.expect_filter_stage = k.expected != Position::TI && k.expected != Position::TE;
      check_all(Ellipsoid::from_matrix(k.e()), Paraboloid::from_matrix(k.p()), x);
    }
  }
}

TEST_CASE("each position after random affine congruences, rescalings and sign flips", "[classify][tangency][random]") {
  const std::uint64_t seed = 0x5EED0001;
  Rng g(seed);
  CAPTURE(seed);
  int per_position[5] = {0, 0, 0, 0, 0};
  for (int round = 0; round < 30; ++round) {
    const Rational a = Q(g.uniform(2, 8), 4), b = Q(g.uniform(2, 8), 4);
    const auto [s, t] = random_st(g, false);
    const TangentPoint tp = tangent_point(a, b, s, t);
    const Rational r = random_tangent_radius(g, a, b);
    const long j = g.uniform(1, 7);
    CAPTURE(round);
    for (const Config& k : tangency_family(tp, r, j)) {
      check_config_transformed(k, g);
      ++per_position[static_cast<int>(k.expected)];
    }
  }
  // Several hundred cases, every position well represented.
  for (int n : per_position) CHECK(n >= 30);
}

TEST_CASE("tangencies at vertices and symmetry planes survive congruences", "[classify][tangency][random]") {
  const std::uint64_t seed = 0x5EED0002;
  Rng g(seed);
  CAPTURE(seed);
  for (int round = 0; round < 10; ++round) {
    const Rational a = Q(g.uniform(2, 8), 4), b = Q(g.uniform(2, 8), 4);
    const auto [s, t] = random_st(g, true);
    const Rational s2 = round % 3 == 0 ? Rational(0) : s, t2 = round % 3 == 1 ? Rational(0) : t;
    if (s2 * s2 + t2 * t2 == 1) continue;
    const TangentPoint tp = tangent_point(a, b, s2, t2);
    const Rational r = random_tangent_radius(g, a, b);
    CAPTURE(round);
    for (const Config& k : tangency_family(tp, r, g.uniform(1, 7))) {
      check_config(k);
      check_config_transformed(k, g, round % 2 == 0);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// 3. The paper's Remark example, exact z_c
// ---------------------------------------------------------------------------------------------

TEST_CASE("the paper's Remark example: I with -a^2 a double root of f and a root of s", "[classify][paper]") {
  const Rational a(6, 5), b(3, 2), r(1, 4), yc(1, 2);
  // z_c = y_c^2/(b^2 - a^2) + r^2/a^2 + a^2/4 makes -a^2 a double root (math.md §3).
  const Rational zc = yc * yc / (b * b - a * a) + r * r / (a * a) + a * a / 4;
  REQUIRE(zc == Q(92281, 129600));
  const Config k = config("Remark", a, b, V(Q(0), yc, zc), r, Position::I);
  const auto f = paper_f(a, b, k.c, r);
  REQUIRE(multiplicity(f, -a * a) == 2);
  REQUIRE(multiplicity(paper_s(a, b), -a * a) == 1);

  const Classification c = check_config(k);
  CHECK(c.verdict.position == Position::I);
  CHECK(c.verdict.small);
  CHECK(c.verdict.sign_disc_f == 0);
  CHECK(c.verdict.sign_disc_ftilde == 1);
  CHECK(c.degree_ftilde == 3);
  CHECK((c.verdict.stage == Stage::ExactRoots || c.verdict.stage == Stage::MultipleRootWitness));
  REQUIRE(c.roots.size() == 3);  // -3.548..., -36/25 (double), -0.110...
  CHECK(c.verdict.nonreal_roots == 0);
  // The simple roots are those of q = 5184 l^2 + 18964 l + 2025 (f = c (25 l + 36)^2 q), one on
  // each side of -36/25; their isolating intervals bracket a sign change of q.
  const Quadratic<Rational> q{Q(2025), Q(18964), Q(5184)};
  CHECK(c.roots[0].multiplicity_f == 1);
  CHECK(c.roots[0].upper < Q(-36, 25));
  CHECK(sgn(eval(q, c.roots[0].lower)) * sgn(eval(q, c.roots[0].upper)) <= 0);
  REQUIRE(c.roots[1].exact.has_value());
  CHECK(*c.roots[1].exact == Q(-36, 25));
  CHECK(c.roots[1].multiplicity_f == 2);
  CHECK(c.roots[1].multiplicity_s == 1);
  CHECK_FALSE(c.roots[1].tangency());
  CHECK(c.roots[2].multiplicity_f == 1);
  CHECK(c.roots[2].lower > Q(-36, 25));
  CHECK(c.roots[2].upper < 0);
  CHECK(sgn(eval(q, c.roots[2].lower)) * sgn(eval(q, c.roots[2].upper)) <= 0);
  // rho = 4 r^2 / a^4 = (1/4) / (1296/625) = 625/5184.
  REQUIRE(c.rho.has_value());
  CHECK(*c.rho == Q(625, 5184));
  // Table 2 alone would call this TI (Disc(f) = 0, all c_i > 0): the Remark is why f~ exists.
  CHECK(table2(c.f) == Position::TI);

  Rng g(0x5EED0003);
  for (int i = 0; i < 12; ++i) {
    const Classification ct = check_config_transformed(k, g);
    CHECK(ct.verdict.position == Position::I);
  }
}

// ---------------------------------------------------------------------------------------------
// 4. Centre on the axis, a != b
// ---------------------------------------------------------------------------------------------

TEST_CASE("centre on the axis: I, TI, C, TE, E by the height", "[classify][axis]") {
  // f = -(l + a^2)(l + b^2)(l^2 + 4 z l + 4 r^2) / (4 a^2 b^2): the quadratic factor has a double
  // root exactly when z = +-r, negative roots when z > r, non-real when |z| < r, positive when z < -r.
  const Rational r(1, 4);
  for (const auto& ab : {std::pair<Rational, Rational>{Q(1), Q(2)}, {Q(2), Q(1)}, {Q(3, 2), Q(5, 4)}}) {
    const Rational a = ab.first, b = ab.second;
    for (const Rational& z : {Q(3), Q(1), Q(1, 3), r, Q(1, 8), Q(0), Q(-1, 8), -r, Q(-1, 3), Q(-2)}) {
      const Config k = config("axis", a, b, V(Q(0), Q(0), z), r, axis_position(z, r));
      const auto f = paper_f(a, b, k.c, r);
      REQUIRE(multiplicity(f, -a * a) == 1);
      REQUIRE(multiplicity(f, -b * b) == 1);
      const Classification c = check_config(k);
      // gcd(f, s) = s: f~ is the quadratic factor.
      CHECK(c.degree_ftilde == 2);
      CHECK(c.verdict.sign_disc_ftilde == sgn(z * z - r * r));
      if (z == r || z == -r) {
        const auto& t = root_at(c, -2 * z);  // the double root -2z of l^2 + 4 z l + 4 z^2
        CHECK(t.multiplicity_f == 2);
        CHECK(t.tangency());
      }
    }
  }
  Rng g(0x5EED0004);
  for (const Rational& z : {Q(1), Q(1, 4), Q(0), Q(-1, 4), Q(-1)}) {
    const Config k = config("axis, transformed", Q(1), Q(2), V(Q(0), Q(0), z), r, axis_position(z, r));
    for (int i = 0; i < 4; ++i) check_config_transformed(k, g);
  }
}

// ---------------------------------------------------------------------------------------------
// 5-6. Special roots: circular paraboloids and the triple -a^2
// ---------------------------------------------------------------------------------------------

TEST_CASE("circular paraboloid: -a^2 has multiplicity 1, 2, 3 or 4 in f", "[classify][special]") {
  // For a = b, s = (1 + l/a^2)^2 and (worked out from eq. (4))
  //   f = -(l + a^2) g(l) / (4 a^4),  g = l^3 + (a^2 + 4 z) l^2 + 4 (a^2 z + r^2 - d^2) l + 4 a^2 r^2,
  // d^2 = x^2 + y^2, with g(-a^2) = 4 a^2 d^2. So:
  //   off the axis: mult_f(-a^2) = 1 (and mult_s = 2);
  //   on the axis:  f = -(l + a^2)^2 (l^2 + 4 z l + 4 r^2) / (4 a^4): multiplicity 2, 3 when also
  //                 a^4 - 4 z a^2 + 4 r^2 = 0 (z = a^2/4 + r^2/a^2), 4 when z = r = a^2/2.
  const Rational a(1), a2 = a * a;
  SECTION("off the axis: multiplicity 1, I") {
    // The I sphere of a tangency family at an off-axis rational-normal point.
    const TangentPoint tp = tangent_point(a, a, Q(1, 2), Q(1, 3));
    const Config k = tangency_family(tp, Q(1, 4), 4)[2];  // I: TI centre, smaller radius
    REQUIRE(k.expected == Position::I);
    REQUIRE(k.c[0] * k.c[0] + k.c[1] * k.c[1] != 0);
    const Classification c = check_config(k);
    const auto& t = root_at(c, -a2);
    CHECK(t.multiplicity_f == 1);
    CHECK(t.multiplicity_s == 2);
    CHECK_FALSE(t.tangency());
    CHECK(c.degree_ftilde == 3);
  }
  SECTION("on the axis, generic height: multiplicity 2, I") {
    const Config k = config("circular axis", a, a, V(Q(0), Q(0), Q(1)), Q(1, 4), Position::I);
    const Classification c = check_config(k);
    const auto& t = root_at(c, -a2);
    CHECK(t.multiplicity_f == 2);
    CHECK(t.multiplicity_s == 2);
    CHECK_FALSE(t.tangency());
    CHECK(c.degree_ftilde == 2);
    CHECK(c.verdict.sign_disc_f == 0);  // Disc(f) = 0 with nothing touching
    CHECK(c.verdict.sign_disc_ftilde == 1);
  }
  SECTION("on the axis, z = a^2/4 + r^2/a^2: multiplicity 3, I") {
    const Rational r(1, 4), z = a2 / 4 + r * r / a2;  // 5/16 > r: interior (axis rule)
    REQUIRE(z > r);
    const Config k = config("circular axis, triple", a, a, V(Q(0), Q(0), z), r, Position::I);
    const Classification c = check_config(k);
    const auto& t = root_at(c, -a2);
    CHECK(t.multiplicity_f == 3);
    CHECK(t.multiplicity_s == 2);
    CHECK_FALSE(t.tangency());
    // The fourth root: l^2 + (5/4) l + 1/4 = (l + 1)(l + 1/4).
    CHECK(root_at(c, Q(-1, 4)).multiplicity_f == 1);
    CHECK(c.degree_ftilde == 2);
  }
  SECTION("on the axis, z = r = a^2/2: multiplicity 4, TI (rho = 1)") {
    for (const Rational& aa : {Q(1), Q(2), Q(3, 5)}) {
      const Rational h = aa * aa / 2;
      const Config k = config("circular axis, quadruple", aa, aa, V(Q(0), Q(0), h), h, Position::TI);
      const Classification c = check_config(k);
      REQUIRE(c.roots.size() == 1);
      CHECK(*c.roots[0].exact == -aa * aa);
      CHECK(c.roots[0].multiplicity_f == 4);
      CHECK(c.roots[0].multiplicity_s == 2);
      CHECK(c.roots[0].tangency());
      CHECK(c.verdict.rho_vs_one == 0);
      CHECK(c.verdict.small);
    }
  }
  SECTION("on the axis, z = r != a^2/2: TI at -2r, -a^2 double but not a tangency") {
    const Config k = config("circular axis, TI", a, a, V(Q(0), Q(0), Q(1, 4)), Q(1, 4), Position::TI);
    const Classification c = check_config(k);
    CHECK(root_at(c, -a2).multiplicity_f == 2);
    CHECK_FALSE(root_at(c, -a2).tangency());
    CHECK(root_at(c, Q(-1, 2)).multiplicity_f == 2);
    CHECK(root_at(c, Q(-1, 2)).tangency());
  }
  SECTION("all of them under congruences") {
    Rng g(0x5EED0005);
    const std::vector<Config> ks = {
        config("circular axis", a, a, V(Q(0), Q(0), Q(1)), Q(1, 4), Position::I),
        config("circular axis, triple", a, a, V(Q(0), Q(0), Q(5, 16)), Q(1, 4), Position::I),
        config("circular axis, quadruple", a, a, V(Q(0), Q(0), Q(1, 2)), Q(1, 2), Position::TI),
        config("circular axis, C", a, a, V(Q(0), Q(0), Q(1, 8)), Q(1, 4), Position::C),
        config("circular axis, TE", a, a, V(Q(0), Q(0), Q(-1, 4)), Q(1, 4), Position::TE),
    };
    for (const auto& k : ks)
      for (int i = 0; i < 4; ++i) check_config_transformed(k, g);
  }
}

TEST_CASE("a != b: triple -a^2 at centre (0,0,a^2/2), r = a^2/2 is TI with rho = 1", "[classify][special]") {
  // f = -(l + a^2)^3 (l + b^2) / (4 a^2 b^2): mult_f(-a^2) - mult_s(-a^2) = 3 - 1 = 2: tangency.
  struct AB {
    Rational a, b;
  };
  Rng g(0x5EED0006);
  for (const auto& ab : {AB{Q(1), Q(2)}, AB{Q(3, 2), Q(5, 2)}, AB{Q(2, 3), Q(3, 4)}}) {
    const Rational h = ab.a * ab.a / 2;
    const Config k = config("triple", ab.a, ab.b, V(Q(0), Q(0), h), h, Position::TI);
    const Classification c = check_config(k);
    const auto& t = root_at(c, -ab.a * ab.a);
    CHECK(t.multiplicity_f == 3);
    CHECK(t.multiplicity_s == 1);
    CHECK(t.tangency());
    CHECK(root_at(c, -ab.b * ab.b).multiplicity_f == 1);
    CHECK(c.verdict.small);
    CHECK(c.verdict.rho_vs_one == 0);
    REQUIRE(c.rho.has_value());
    CHECK(*c.rho == 1);
    for (int i = 0; i < 4; ++i) check_config_transformed(k, g);
  }
}

// ---------------------------------------------------------------------------------------------
// 7. -b^2 double in C and in E: Disc(f) = 0 without tangency; Table 2 is wrong here
// ---------------------------------------------------------------------------------------------

TEST_CASE("-b^2 double root with the centre crossing or outside (math.md §3)", "[classify][special][table2]") {
  // y_c = 0 and z_c = x_c^2/(a^2 - b^2) + r^2/b^2 + b^2/4 make -b^2 a double root of f.
  const Rational a(1), b(2), r(1, 4);
  auto zc = [&](const Rational& xc) { return xc * xc / (a * a - b * b) + r * r / (b * b) + b * b / 4; };
  REQUIRE(zc(Q(1)) == Q(131, 192));
  REQUIRE(zc(Q(6, 5)) == Q(857, 1600));

  SECTION("centre (1, 0, 131/192): C, certified by a point of the cup inside the ball") {
    const Config k = config("-b^2 double, C", a, b, V(Q(1), Q(0), Q(131, 192)), r, Position::C);
    // (9/10, 0, 81/100) lies on the paraboloid at squared distance < r^2 from the centre.
    const Vector3 p{Q(9, 10), Q(0), Q(81, 100)};
    REQUIRE(paraboloid_value(a, b, p) == 0);
    REQUIRE(dist2(p, k.c) < r * r);
    REQUIRE(crossing_certificate(k));
    const Classification c = check_config(k);
    CHECK(c.verdict.position == Position::C);
    CHECK(c.verdict.sign_disc_f == 0);
    CHECK(c.verdict.sign_disc_ftilde == -1);
    CHECK(c.degree_ftilde == 3);
    const auto& t = root_at(c, Q(-4));
    CHECK(t.multiplicity_f == 2);
    CHECK(t.multiplicity_s == 1);
    CHECK_FALSE(t.tangency());
    CHECK(c.verdict.nonreal_roots == 2);
    // The paper's Table 2 (Disc = 0 and c_1 < 0) would say TE: documented counterexample.
    CHECK(table2(c.f) == Position::TE);
    CHECK(table2(c.f) != c.verdict.position);
  }
  SECTION("centre (6/5, 0, 857/1600): E, certified by a separating tangent plane") {
    const Config k = config("-b^2 double, E", a, b, V(Q(6, 5), Q(0), Q(857, 1600)), r, Position::E);
    // Tangent plane at (6/5, 0, 36/25): normal (12/5, 0, -1), |n| = 13/5; the centre is at
    // distance (1447/1600)/(13/5) > 1/4 on the outer side.
    const Vector3 n{Q(12, 5), Q(0), Q(-1)};
    const Rational val = n[0] * (k.c[0] - Q(6, 5)) + n[2] * (k.c[2] - Q(36, 25));
    REQUIRE(val == Q(1447, 1600));
    REQUIRE(val * val > r * r * Q(169, 25));
    REQUIRE(separation_certificate(k));
    const Classification c = check_config(k);
    CHECK(c.verdict.position == Position::E);
    CHECK(c.verdict.sign_disc_f == 0);
    CHECK(c.verdict.sign_disc_ftilde == 1);
    CHECK(c.verdict.positive_roots == 2);
    const auto& t = root_at(c, Q(-4));
    CHECK(t.multiplicity_f == 2);
    CHECK(t.multiplicity_s == 1);
    CHECK_FALSE(t.tangency());
    CHECK(table2(c.f) == Position::TE);  // wrong again
  }
  SECTION("both under congruences") {
    Rng g(0x5EED0007);
    for (int i = 0; i < 6; ++i) {
      check_config_transformed(config("-b^2 double, C", a, b, V(Q(1), Q(0), Q(131, 192)), r, Position::C), g);
      check_config_transformed(config("-b^2 double, E", a, b, V(Q(6, 5), Q(0), Q(857, 1600)), r, Position::E), g);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// 8. The smallness boundary 2r = a^2
// ---------------------------------------------------------------------------------------------

TEST_CASE("2r = a^2 exactly: rho == 1, small", "[classify][smallness]") {
  const Rational a(1), b(2), r(1, 2);
  // On the axis above a^2/2: distance^2 to the cup is a^2 z - a^4/4 = 19/4 > r^2: interior.
  const Config inside = config("rho = 1, axis", a, b, V(Q(0), Q(0), Q(5)), r, Position::I);
  const Classification c = check_config(inside);
  CHECK(c.verdict.small);
  CHECK(c.verdict.rho_vs_one == 0);
  REQUIRE(c.rho.has_value());
  CHECK(*c.rho == 1);
  // Around an off-axis rational-normal point, with r = a^2/2 the smallest radius of curvature
  // (Blaschke's rolling theorem keeps the TI ball inside).
  const TangentPoint tp = tangent_point(a, b, Q(1, 2), Q(-1, 3));
  check_config(config("rho = 1, TI off-axis", a, b, tp.along(-r), r, Position::TI));
  check_config(config("rho = 1, TE off-axis", a, b, tp.along(r), r, Position::TE));
  check_config(config("rho = 1, C", a, b, tp.along(-r / 2), r, Position::C));
  check_config(config("rho = 1, E", a, b, tp.along(2 * r), r, Position::E));
  // Just beyond: not small, and still the true position (math.md §8).
  const Config beyond = config("rho > 1, axis", a, b, V(Q(0), Q(0), Q(5)), r + Q(1, 1000), Position::I);
  const Classification cb = check_config(beyond);
  CHECK_FALSE(cb.verdict.small);
  CHECK(cb.verdict.rho_vs_one == 1);
  CHECK(cb.verdict.position == Position::I);
  CHECK(cb.verdict.position ==
        secular_position(Ellipsoid::from_matrix(beyond.e()), Paraboloid::from_matrix(beyond.p())));
  Rng g(0x5EED0008);
  for (int i = 0; i < 6; ++i) {
    const Classification ct = check_config_transformed(inside, g);
    CHECK(ct.verdict.rho_vs_one == 0);
  }
}

// ---------------------------------------------------------------------------------------------
// 10. Double-precision inputs are exact dyadic rationals
// ---------------------------------------------------------------------------------------------

TEST_CASE("double inputs: dyadic centres on the axis give exact tangencies", "[classify][double]") {
  using relpos::exact_rational;
  // Paraboloid x^2 + y^2/4 - z (a = 1, b = 2) and spheres, every entry given as a double.
  auto par = [&] {
    Matrix4 p = diag4(exact_rational(1.0), exact_rational(0.25), exact_rational(0.0), exact_rational(0.0));
    set_sym(p, 2, 3, exact_rational(-0.5));
    return p;
  };
  auto sph = [&](double z, double r) {
    Matrix4 e = diag4(exact_rational(1.0), exact_rational(1.0), exact_rational(1.0), exact_rational(z * z - r * r));
    set_sym(e, 2, 3, exact_rational(-z));
    return e;
  };
  struct D {
    double z, r;
    Position want;
  };
  // z * z - r * r is exact in double for these dyadics.
  for (const D& d : {D{0.25, 0.25, Position::TI}, D{0.125, 0.125, Position::TI}, D{0.5, 0.125, Position::I},
                     D{0.0625, 0.125, Position::C}, D{-0.125, 0.125, Position::TE}, D{-0.5, 0.125, Position::E},
                     D{-0.375, 0.375, Position::TE}}) {
    CAPTURE(d.z, d.r);
    REQUIRE(axis_position(Rational(d.z), Rational(d.r)) == d.want);
    const Matrix4 e = sph(d.z, d.r);
    REQUIRE(e == sphere_matrix(V(Q(0), Q(0), Rational(d.z)), Rational(d.r)));
    const Config k = config("double axis", Q(1), Q(2), V(Q(0), Q(0), Rational(d.z)), Rational(d.r), d.want);
    const Classification c = check_all(Ellipsoid::from_matrix(e), Paraboloid::from_matrix(par()), expect_from(k));
    CHECK(c.verdict.position == d.want);
  }
  // A double 0.1 is not 1/10: with z = 0.1 (double) and r = 0.1 (double) the sphere is exactly
  // tangent; with z = 1/10 and r = double(0.1) > 1/10 it crosses; the other way round it is inside.
  const Rational z_double(0.1), tenth = relpos::parse_rational("0.1");
  REQUIRE(z_double > tenth);
  check_config(config("double 0.1 both", Q(1), Q(2), V(Q(0), Q(0), z_double), z_double, Position::TI));
  check_config(config("decimal z, double r", Q(1), Q(2), V(Q(0), Q(0), tenth), z_double, Position::C));
  check_config(config("double z, decimal r", Q(1), Q(2), V(Q(0), Q(0), z_double), tenth, Position::I));
  check_config(config("decimal both", Q(1), Q(2), V(Q(0), Q(0), tenth), tenth, Position::TI));
  // Off-axis tangency with dyadic data: the (1,1,2) point on z = x^2 + y^2 with r = 3/8 = 0.375.
  const Rational r(0.375);
  check_config(config("dyadic TI", Q(1), Q(1), V(Rational(0.75), Rational(0.75), Rational(2.125)), r, Position::TI));
}

// ---------------------------------------------------------------------------------------------
// 12. Not-small pairs (math.md §6)
// ---------------------------------------------------------------------------------------------

TEST_CASE("not small: every position is decided (math.md §8)", "[classify][smallness]") {
  const Rational one(1), r(2);  // 2r = 4 > a^2 = 1
  SECTION("centre (0,0,3): crossing, although the root pattern alone cannot tell") {
    // f = -(l + 1)^2 (l^2 + 12 l + 16) / 4: all roots real and negative, so neither a non-real
    // root (contact) nor two positive roots (separation) is available; math.md §8 decides C.
    const Classification c = check_config(config("big, (0,0,3)", one, one, V(Q(0), Q(0), Q(3)), r, Position::C));
    CHECK_FALSE(c.verdict.small);
    CHECK(c.verdict.rho_vs_one == 1);
    CHECK(*c.rho == 16);
    CHECK(c.verdict.position == Position::C);
  }
  SECTION("centre (0,0,-3): E; (0,0,-2): TE") {
    const Classification e = check_config(config("big, (0,0,-3)", one, one, V(Q(0), Q(0), Q(-3)), r, Position::E));
    CHECK(e.verdict.position == Position::E);
    CHECK_FALSE(e.verdict.small);
    // f = -(l - 4)^2 (l + 1)^2 / 4: -1 is shared with s (not a tangency), 4 is the tangency.
    const Classification t = check_config(config("big, (0,0,-2)", one, one, V(Q(0), Q(0), Q(-2)), r, Position::TE));
    CHECK(t.verdict.position == Position::TE);
    CHECK(root_at(t, Q(4)).multiplicity_f == 2);
    CHECK(root_at(t, Q(4)).tangency());
    CHECK(root_at(t, Q(-1)).multiplicity_f == 2);
    CHECK_FALSE(root_at(t, Q(-1)).tangency());
  }
  SECTION("centre (0,0,0): non-real roots, so the surfaces meet") {
    // f = -(l + 1)^2 (l^2 + 16) / 4.
    const Classification c = check_config(config("big, (0,0,0)", one, one, V(Q(0), Q(0), Q(0)), r, Position::C));
    CHECK(c.verdict.position == Position::C);
    CHECK(c.verdict.nonreal_roots == 2);
  }
  SECTION("a root of s carrying a tangential contact point of crossing surfaces") {
    // a = 1, b = 1/2, centre (0, 0, 5/4), r = 1 (2r > b^2): f = -(l + 1)^2 (l + 4)(4 l + 1) / 4
    // (eq. (4)), so -a^2 = -1 is a double root of f and a simple root of s: mult_f - mult_s = 1.
    // Yet in the section y = 0 the circle touches the parabola z = x^2 at x^2 = 3/4, z = 3/4
    // (the nearest points: distance^2 = a^2 z - a^4/4 = 1 = r^2), where the two surfaces have a
    // common tangent plane, while in the narrower section x = 0 the parabola z = 4 y^2 comes within
    // distance^2 = b^2 z - b^4/4 = 19/64 < r^2 of the centre: the surfaces cross. Beyond
    // smallness, then, the kernel test sees a genuine tangential contact point that the
    // multiplicity rule does not call a tangency; the pair is crossing, and reported C (math.md §8).
    const Config k = config("big, touching section", one, Q(1, 2), V(Q(0), Q(0), Q(5, 4)), one, Position::C);
    const auto f = paper_f(k.a, k.b, k.c, k.r);
    REQUIRE(multiplicity(f, Q(-1)) == 2);
    REQUIRE(multiplicity(f, Q(-4)) == 1);
    REQUIRE(multiplicity(f, Q(-1, 4)) == 1);
    const Classification c = check_config(k);
    CHECK(c.verdict.position == Position::C);
    CHECK(c.verdict.position == secular_position(Ellipsoid::from_matrix(k.e()), Paraboloid::from_matrix(k.p())));
    CHECK_FALSE(c.verdict.small);
    CHECK(relpos::detail::oracle::kernel_has_common_point(Ellipsoid::from_matrix(k.e()), Paraboloid::from_matrix(k.p()),
                                                          Q(-1)));
    CHECK(root_at(c, Q(-1)).multiplicity_s == 1);
  }
  SECTION("a big sphere resting inside on the axis touches along a circle: never called TI") {
    // r = 2 > a^2/2, centre (0,0,2): the quadratic factor is (l + 4)^2, a 'TI' root pattern.
    const Config k = config("big, (0,0,2)", one, one, V(Q(0), Q(0), Q(2)), r, Position::C);
    const Classification c = check_config(k);
    CHECK(c.verdict.position == Position::C);
    CHECK(c.verdict.position == secular_position(Ellipsoid::from_matrix(k.e()), Paraboloid::from_matrix(k.p())));
  }
}

// ---------------------------------------------------------------------------------------------
// Hard inputs for the interval filter: near-tangencies, extreme magnitudes, far translations
// ---------------------------------------------------------------------------------------------

TEST_CASE("near-tangencies: perturbations of 10^-k around exact tangencies", "[classify][tangency][filter]") {
  const TangentPoint tp = tangent_point(Q(6, 5), Q(3, 2), Q(1, 3), Q(-1, 2));
  const Rational r(1, 5);
  for (int k : {6, 12, 20, 40, 80}) {
    Rational eps(1);
    for (int i = 0; i < k; ++i) eps /= 10;
    CAPTURE(k);
    // Same constructions as tangency_family, with the radius or the centre moved by eps.
    check_config(config("I, radius - eps", tp.a, tp.b, tp.along(-r), r - eps, Position::I));
    check_config(config("C, radius + eps (TI centre)", tp.a, tp.b, tp.along(-r), r + eps, Position::C));
    check_config(config("E, radius - eps", tp.a, tp.b, tp.along(r), r - eps, Position::E));
    check_config(config("C, radius + eps (TE centre)", tp.a, tp.b, tp.along(r), r + eps, Position::C));
    check_config(config("E, pushed out by eps", tp.a, tp.b, tp.along(r + eps), r, Position::E));
    check_config(config("I, pushed in by eps", tp.a, tp.b, tp.along(-r - eps), r, Position::I));
    // On the axis too: z = r +- eps.
    check_config(config("axis I", Q(1), Q(2), V(Q(0), Q(0), r + eps), r, Position::I));
    check_config(config("axis C", Q(1), Q(2), V(Q(0), Q(0), r - eps), r, Position::C));
    check_config(config("axis C below", Q(1), Q(2), V(Q(0), Q(0), -r + eps), r, Position::C));
    check_config(config("axis E", Q(1), Q(2), V(Q(0), Q(0), -r - eps), r, Position::E));
    // And the smallness boundary: 2r = a^2 +- eps.
    const Config lo = config("rho just below 1", Q(1), Q(2), V(Q(0), Q(0), Q(5)), Q(1, 2) - eps, Position::I);
    const Config hi = config("rho just above 1", Q(1), Q(2), V(Q(0), Q(0), Q(5)), Q(1, 2) + eps, Position::I);
    CHECK(check_config(lo).verdict.rho_vs_one == -1);
    CHECK(check_config(hi).verdict.rho_vs_one == 1);
  }
}

TEST_CASE("extreme magnitudes: rescaling E and P by huge or tiny factors changes nothing", "[classify][filter]") {
  // Q -> k Q for k = 10^e and 2^e, far beyond the double range: the answer is scale-free.
  const TangentPoint tp = tangent_point(Q(1), Q(3, 2), Q(1, 2), Q(1, 3));
  const std::vector<Config> family = tangency_family(tp, Q(1, 5), 3);
  auto power = [](long base, int e) {
    Rational p(1);
    for (int i = 0; i < (e < 0 ? -e : e); ++i) p *= base;
    return e < 0 ? Rational(1) / p : p;
  };
  const std::vector<std::pair<Rational, Rational>> factors = {
      {power(10, 300), Rational(1)},    {Rational(1), power(10, -300)}, {power(10, 400), power(10, -400)},
      {power(2, 1100), power(2, 1100)}, {power(2, -1100), Rational(1)}, {power(10, -350), power(10, 350)},
      {power(10, 20), power(10, -20)},
  };
  // Under AddressSanitizer each factor takes every fourth member of the family, a different fourth
  // for each factor (support/scale.hpp).
  const int share = relpos::testing::kSanitizerShare;
  for (std::size_t f = 0; f < factors.size(); ++f) {
    const auto& [ke, kp] = factors[f];
    for (std::size_t i = 0; i < family.size(); ++i) {
      if (static_cast<int>((i + f) % static_cast<std::size_t>(share)) != 0) continue;
      const Config& k = family[i];
      Transformed t;
      t.det_h = 1;
      t.ke = ke;
      t.kp = kp;
      t.e = scaled(k.e(), ke);
      t.p = scaled(k.p(), kp);
      check_all(Ellipsoid::from_matrix(t.e), Paraboloid::from_matrix(t.p), expect_from(k, t));
    }
  }
}

TEST_CASE("far away: the whole scene translated by 10^k", "[classify][filter]") {
  const TangentPoint tp = tangent_point(Q(1), Q(3, 2), Q(1, 2), Q(1, 3));
  const std::vector<Config> family = tangency_family(tp, Q(1, 5), 3);
  for (int e : {8, 17, 30, 320}) {
    Rational big(1);
    for (int i = 0; i < e; ++i) big *= 10;
    CAPTURE(e);
    Transformed t;
    t.det_h = 1;
    t.ke = t.kp = 1;
    const Matrix4 h = affine_matrix(identity3(), V(big, -big / 3, big / 7));
    for (const Config& k : family) {
      t.e = congruence(k.e(), h);
      t.p = congruence(k.p(), h);
      check_all(Ellipsoid::from_matrix(t.e), Paraboloid::from_matrix(t.p), expect_from(k, t));
    }
  }
}

TEST_CASE("very flat and very elongated shapes: affine maps with extreme scalings", "[classify][filter]") {
  const TangentPoint tp = tangent_point(Q(1), Q(3, 2), Q(1, 2), Q(1, 3));
  const std::vector<Config> family = tangency_family(tp, Q(1, 5), 3);
  for (int e : {5, 15, 40}) {
    Rational big(1);
    for (int i = 0; i < e; ++i) big *= 10;
    CAPTURE(e);
    const Matrix3 l = diag3(big, Rational(1) / big, Q(3));
    const Matrix4 h = affine_matrix(mul(rotation({Q(1), Q(2), Q(-1), Q(3)}), l), V(Q(1), Q(2), Q(3)));
    Transformed t;
    t.det_h = det3(mul(rotation({Q(1), Q(2), Q(-1), Q(3)}), l));
    t.ke = t.kp = 1;
    for (const Config& k : family) {
      t.e = congruence(k.e(), h);
      t.p = congruence(k.p(), h);
      check_all(Ellipsoid::from_matrix(t.e), Paraboloid::from_matrix(t.p), expect_from(k, t));
    }
  }
}

TEST_CASE("position and stage names", "[classify]") {
  CHECK(relpos::to_string(Position::I) == "I");
  CHECK(relpos::to_string(Position::TI) == "TI");
  CHECK(relpos::to_string(Position::C) == "C");
  CHECK(relpos::to_string(Position::TE) == "TE");
  CHECK(relpos::to_string(Position::E) == "E");
  for (const Position p : relpos::kAllPositions) CHECK_FALSE(relpos::to_string(p).empty());
  CHECK(relpos::to_string(Stage::Interval) != relpos::to_string(Stage::ExactSigns));
  CHECK(relpos::to_string(Stage::ExactSigns) != relpos::to_string(Stage::ExactRoots));
}
