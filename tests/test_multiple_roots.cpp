// The machine-integer witness of Disc(f) = 0 (multiple_roots.hpp, checked_int.hpp): CheckedInt
// overflow semantics; rational_multiple_root_facts against the GMP exact_root_facts on quartics with
// known factorisations; and the adaptive classifier on exactly degenerate double inputs (tangencies
// and special double roots under random dyadic affine maps) against classify_exact.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <iostream>

#include "algebra/root_facts.hpp"
#include "filters/checked_int.hpp"
#include "filters/multiple_roots.hpp"
#include "filters/static_filter.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"
#include "support/seed.hpp"

using namespace rt;
using relpos::CheckedInt;
using relpos::Classification;
using relpos::Ellipsoid;
using relpos::Paraboloid;
using relpos::RootFacts;
using relpos::Stage;
using relpos::Verdict;

namespace {

using relpos::testing::seed_from_env;

/// Product of integer polynomials (index = power).
std::vector<long long> mul(const std::vector<long long>& a, const std::vector<long long>& b) {
  std::vector<long long> c(a.size() + b.size() - 1, 0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}

void check_same_facts(const RootFacts& fast, const RootFacts& exact) {
  CHECK(fast.real == exact.real);
  CHECK(fast.negative == exact.negative);
  CHECK(fast.positive == exact.positive);
  CHECK(fast.nonreal == exact.nonreal);
  CHECK(fast.nonreal_multiple == exact.nonreal_multiple);
  CHECK(fast.tangent_negative == exact.tangent_negative);
  CHECK(fast.tangent_positive == exact.tangent_positive);
  CHECK(fast.sign_disc_f == exact.sign_disc_f);
  CHECK(fast.sign_disc_ftilde == exact.sign_disc_ftilde);
  if (fast.degree_ftilde >= 0) CHECK(fast.degree_ftilde == exact.degree_ftilde);
}

}  // namespace

TEST_CASE("CheckedInt: exact ring operations, overflow makes the value invalid", "[checked]") {
  const CheckedInt big = CheckedInt::from(CheckedInt::Int{1} << 100);
  CHECK((big * CheckedInt(7)).valid());
  CHECK(!(big * big).valid());                          // 2^200
  CHECK(!((big * big) - big + CheckedInt(1)).valid());  // invalid propagates
  const CheckedInt max = CheckedInt::from(~(CheckedInt::Int{1} << 127));
  CHECK(!(max + CheckedInt(1)).valid());
  CHECK(!(-max - CheckedInt(2)).valid());
  CHECK((max - max).value() == 0);
  CHECK(exact_quotient(CheckedInt(12), CheckedInt(-4)).value() == -3);
  CHECK(!exact_quotient(CheckedInt(13), CheckedInt(4)).valid());
  CHECK(!exact_quotient(CheckedInt(13), CheckedInt(0)).valid());
  const CheckedInt min = -max - CheckedInt(1);
  CHECK(min.valid());
  CHECK(!exact_quotient(min, CheckedInt(-1)).valid());  // -MIN overflows; no trap
  CHECK(exact_quotient(big * CheckedInt(3), big).value() == 3);
  CHECK(relpos::sign_of(CheckedInt(-5)) == CGAL::NEGATIVE);
  CHECK(!CGAL::is_certain(relpos::sign_of(big * big)));
}

TEST_CASE("QuarticSigns default to uncertain, never to a certain zero", "[checked]") {
  relpos::QuarticSigns q;
  CHECK(!CGAL::is_certain(q.g0));
  for (const auto& s : q.f) CHECK(!CGAL::is_certain(s));
  CHECK(!relpos::count_roots(q).has_value());
}

TEST_CASE("rational_multiple_root_facts equals exact_root_facts on known factorisations", "[witness][random]") {
  Rng g(seed_from_env(20261121));
  std::cout << "[witness] seed " << g.seed << " (set RELPOS_SEED to reproduce)\n";
  int found = 0, square_free = 0, subresultant = 0;
  int by_shape[6] = {0, 0, 0, 0, 0, 0};
  for (int iter = 0; iter < 3000; ++iter) {
    // f = lead * (q1 l - p1)^m1 [* (q2 l - p2)^m2] * h, every root non-zero.
    auto linear = [&] {
      long p = 0, q = g.uniform(1, 9);
      while (p == 0) p = g.uniform(-30, 30);
      return std::vector<long long>{-p, q};
    };
    std::vector<long long> f{g.chance(50) ? -1 : 1};
    f[0] *= g.uniform(1, 5);
    std::vector<std::vector<long long>> pieces;
    const int shape = static_cast<int>(g.uniform(0, 5));
    const auto r1 = linear(), r2 = linear();
    std::vector<long long> h{1};
    switch (shape) {
      case 0:  // square-free: no witness may be claimed
        h = mul(mul(r1, r2), mul(linear(), linear()));
        break;
      case 1:  // double root and a quadratic cofactor (real, non-real, or sharing nothing)
        h = mul(mul(r1, r1), std::vector<long long>{g.uniform(1, 20) * (g.chance(50) ? 1 : -1), g.uniform(-20, 20),
                                                    g.uniform(1, 6)});
        break;
      case 2:  // triple root
        h = mul(mul(r1, mul(r1, r1)), linear());
        break;
      case 3:  // quadruple root
        h = mul(mul(r1, r1), mul(r1, r1));
        break;
      case 4:  // two double roots (maybe equal)
        h = mul(mul(r1, r1), mul(r2, r2));
        break;
      default:  // double root and two simple ones
        h = mul(mul(r1, r1), mul(r2, linear()));
        break;
    }
    f = mul(f, h);
    if (f[0] == 0) continue;
    // s: roots chosen among f's roots or random, sometimes a double root (circular paraboloid).
    std::vector<long long> s;
    const int sk = static_cast<int>(g.uniform(0, 3));
    if (sk == 0)
      s = mul(r1, linear());
    else if (sk == 1)
      s = mul(r1, r1);
    else if (sk == 2)
      s = mul(r2, r1);
    else
      s = mul(linear(), linear());
    Quartic<Integer> fz;
    Quartic<CheckedInt> fc;
    for (std::size_t i = 0; i < 5; ++i) {
      fz[i] = Integer(static_cast<long>(f[i]));
      fc[i] = CheckedInt(static_cast<long long>(f[i]));
    }
    Quadratic<Integer> sz;
    Quadratic<CheckedInt> sc;
    for (std::size_t i = 0; i < 3; ++i) {
      sz[i] = Integer(static_cast<long>(s[i]));
      sc[i] = CheckedInt(static_cast<long long>(s[i]));
    }
    CAPTURE(iter, shape, f, s);
    const auto exact = relpos::exact_root_facts_by_factorisation(fz, sz);
    // The subresultant fast path of exact_root_facts (no gcd) must agree with the factorisation
    // wherever it answers, and must answer whenever f has multiple roots: every root built here is
    // rational (double, triple, quadruple, two double roots, and coincidences of the simple ones).
    const auto sub = relpos::subresultant_root_facts(fz, sz);
    CHECK(sub.has_value() == exact.has_value());
    if (sub && exact) {
      check_same_facts(*sub, *exact);
      CHECK(sub->degree_ftilde == exact->degree_ftilde);
      ++subresultant;
      by_shape[shape] += 1;
    }
    const auto fast = relpos::rational_multiple_root_facts(fc, sc);
    if (!exact) {  // square-free f: a witness would be a false certificate
      CHECK(!fast);
      ++square_free;
      continue;
    }
    // Every multiple root here is rational with a small denominator: the witness must be found.
    REQUIRE(fast);
    check_same_facts(*fast, *exact);
    ++found;
  }
  std::cout << "[witness] " << found << " witnesses checked against GMP, " << square_free << " square-free refused\n";
  CHECK(found > 2000);
  CHECK(square_free > 300);
  std::cout << "[witness] subresultant path: " << subresultant << " answered (shapes 1-5: " << by_shape[1] << ", "
            << by_shape[2] << ", " << by_shape[3] << ", " << by_shape[4] << ", " << by_shape[5] << ")\n";
  CHECK(subresultant > 2000);
  for (int k = 1; k <= 5; ++k) CHECK(by_shape[k] > 100);  // every multiple-root shape goes through it
}

namespace {

/// A random affine congruence with dyadic entries (signed permutation of x and y, power-of-two
/// scalings, dyadic translation): it keeps every matrix an exact double, and the position.
Matrix4 dyadic_congruence(Rng& g) {
  Matrix3 l;
  const bool swap = g.chance(50);
  const Rational sx = Rational(g.chance(50) ? 1 : -1) * pow_q(Q(2), static_cast<int>(g.uniform(-2, 2)));
  const Rational sy = Rational(g.chance(50) ? 1 : -1) * pow_q(Q(2), static_cast<int>(g.uniform(-2, 2)));
  l(swap ? 1 : 0, 0) = sx;
  l(swap ? 0 : 1, 1) = sy;
  l(2, 2) = pow_q(Q(2), static_cast<int>(g.uniform(-2, 2)));  // z is the axis: keep its sign
  Vector3 t{Q(g.uniform(-64, 64), 16), Q(g.uniform(-64, 64), 16), Q(g.uniform(-64, 64), 16)};
  return affine_matrix(l, t);
}

struct DyadicCase {
  std::string name;
  Matrix4 e, p;
  Position expected;
};

/// Exactly degenerate configurations with dyadic data and a known answer.
std::vector<DyadicCase> dyadic_cases() {
  std::vector<DyadicCase> out;
  const Rational inv[4] = {Q(1), Q(1, 2), Q(1, 4), Q(2)};
  for (const auto& ia : inv)
    for (const auto& ib : inv) {
      Matrix4 p = diag4(ia, ib, Q(0), Q(0));
      set_sym(p, 2, 3, Q(-1, 2));
      const Rational rmin = Rational(1) / (2 * std::max(ia, ib));  // smallest curvature radius at the vertex
      for (int k : {1, 2, 3}) {
        const Rational r = rmin / Q(1 << k);
        out.push_back({"TI at the vertex", sphere_matrix(V(Q(0), Q(0), r), r), p, Position::TI});
        out.push_back({"TE below the vertex", sphere_matrix(V(Q(0), Q(0), -r), r), p, Position::TE});
      }
      if (ia == ib) {  // circular cup, centre on the axis: -a^2 double in s and in f for every height
        const Rational r = rmin / 4;
        out.push_back({"axis I (special double root)", sphere_matrix(V(Q(0), Q(0), 2 * r), r), p, Position::I});
        out.push_back({"axis C (special double root)", sphere_matrix(V(Q(0), Q(0), r / 2), r), p, Position::C});
        out.push_back({"axis E (special double root)", sphere_matrix(V(Q(0), Q(0), -2 * r), r), p, Position::E});
      }
    }
  // Off the axis of z = x^2 + y^2: points whose normal (-2x, -2y, 1) has rational length m.
  struct Pt {
    Rational x, y, m;
  };
  const Pt pts[5] = {
      {Q(1), Q(1), Q(3)}, {Q(2), Q(4), Q(9)}, {Q(6), Q(6), Q(17)}, {Q(3, 8), Q(0), Q(5, 4)}, {Q(0), Q(3, 8), Q(5, 4)}};
  Matrix4 p = diag4(Q(1), Q(1), Q(0), Q(0));
  set_sym(p, 2, 3, Q(-1, 2));
  for (const Pt& q : pts) {
    const Vector3 x0{q.x, q.y, q.x * q.x + q.y * q.y};
    const Vector3 n{-2 * q.x, -2 * q.y, Q(1)};  // inward
    Rational r = q.m;
    while (r > Q(1, 2)) r = r / 2;  // r = m 2^-k <= 1/2 = a^2/2: small; r / m dyadic
    const Rational t = r / q.m;
    out.push_back({"TI off the axis", sphere_matrix(V(x0[0] + t * n[0], x0[1] + t * n[1], x0[2] + t * n[2]), r), p,
                   Position::TI});
    out.push_back({"TE off the axis", sphere_matrix(V(x0[0] - t * n[0], x0[1] - t * n[1], x0[2] - t * n[2]), r), p,
                   Position::TE});
  }
  // The Remark family with dyadic data is not available (z_c has a factor 1/a^2 b^2 ...); the
  // circular-cup multiplicities 3 and 4 of -a^2 are (a = 1): z = 1/4 + r^2, and z = r = 1/2.
  out.push_back(
      {"-1 triple in f (a = b = 1)", sphere_matrix(V(Q(0), Q(0), Q(1, 4) + Q(1, 64)), Q(1, 8)), p, Position::I});
  out.push_back(
      {"-1 quadruple in f: TI with rho = 1", sphere_matrix(V(Q(0), Q(0), Q(1, 2)), Q(1, 2)), p, Position::TI});
  return out;
}

}  // namespace

TEST_CASE("adaptive == exact on exactly degenerate double inputs; the witness stage settles them",
          "[witness][classify][double][random]") {
  Rng g(seed_from_env(777));
  std::cout << "[witness-classify] seed " << g.seed << "\n";
  const auto cases = dyadic_cases();
  int total = 0, witness = 0, disc_zero = 0;
  for (const auto& c : cases)
    for (int rep = 0; rep < 12; ++rep) {
      const Matrix4 h = rep == 0 ? affine_matrix(identity3(), V(Q(0), Q(0), Q(0))) : dyadic_congruence(g);
      const Rational ke = pow_q(Q(2), static_cast<int>(g.uniform(-3, 3)));
      const Rational kp = pow_q(Q(2), static_cast<int>(g.uniform(-3, 3)));
      const Ellipsoid e = Ellipsoid::from_matrix(scaled(congruence(c.e, h), rep % 3 == 1 ? -ke : ke));
      const Paraboloid p = Paraboloid::from_matrix(scaled(congruence(c.p, h), kp));
      REQUIRE(e.doubles());
      REQUIRE(p.doubles());
      CAPTURE(c.name, rep);
      const Verdict v = relpos::decide_position(e, p);
      const Classification x = relpos::classify_exact(e, p, relpos::Evidence::Minimal);
      CHECK(v.position == c.expected);
      CHECK(x.verdict.position == c.expected);
      CHECK(v.sign_disc_f == x.verdict.sign_disc_f);
      CHECK(v.sign_disc_ftilde == x.verdict.sign_disc_ftilde);
      CHECK(v.real_roots == x.verdict.real_roots);
      CHECK(v.negative_roots == x.verdict.negative_roots);
      CHECK(v.positive_roots == x.verdict.positive_roots);
      CHECK(v.nonreal_roots == x.verdict.nonreal_roots);
      CHECK(v.rho_vs_one == x.verdict.rho_vs_one);
      ++total;
      if (x.verdict.sign_disc_f == 0) {
        ++disc_zero;
        // A zero is never certified by a float filter, only by an exact stage.
        CHECK((v.stage == Stage::MultipleRootWitness || v.stage == Stage::ExactRoots));
      }
      if (v.stage == Stage::MultipleRootWitness) ++witness;
    }
  std::cout << "[witness-classify] " << total << " pairs, " << disc_zero << " with Disc(f) = 0, " << witness
            << " settled by the witness stage\n";
  CHECK(disc_zero == total);             // every case here is degenerate
  CHECK(witness * 10 >= disc_zero * 9);  // the fast path must actually fire
}

TEST_CASE("machine_pencil equals the GMP pencil of the power-of-two scaled matrices", "[witness]") {
  Rng g(seed_from_env(4242));
  auto to_integer = [](const CheckedInt& x) {
    const relpos::Int128 v = x.value();
    const auto hi = static_cast<long>(v >> 64);
    const auto lo = static_cast<unsigned long>(v & ((relpos::Int128{1} << 64) - 1));
    return Integer((Integer(hi) << 64) + Integer(lo));
  };
  for (const auto& c : dyadic_cases()) {
    const Ellipsoid e = Ellipsoid::from_matrix(congruence(c.e, dyadic_congruence(g)));
    const Paraboloid p = Paraboloid::from_matrix(c.p);
    const auto mp = relpos::machine_pencil(*p.doubles(), *e.doubles());
    REQUIRE(mp);
    // Each matrix is scaled by 2^-v, v the least 2-adic valuation of its entries: then f and s
    // must be exactly the GMP pencil of the scaled matrices.
    auto scaled_to_integers = [](const Matrix4& m) {
      long lowest = 1L << 30;
      for (const auto& x : m.a)
        if (x != 0)
          lowest = std::min<long>(lowest, static_cast<long>(mpz_scan1(x.numerator().mpz(), 0)) -
                                              static_cast<long>(mpz_scan1(x.denominator().mpz(), 0)));
      return scaled(m, pow_q(Q(2), static_cast<int>(-lowest)));
    };
    const Matrix4 ps = scaled_to_integers(p.matrix()), es = scaled_to_integers(e.matrix());
    const auto fq = relpos::characteristic_polynomial<Rational>(ps, es);
    const auto sq = relpos::special_polynomial<Rational>(ps, es);
    for (std::size_t i = 0; i < 5; ++i) CHECK(Rational(to_integer(mp->f[i])) == fq[i]);
    for (std::size_t i = 0; i < 3; ++i) CHECK(Rational(to_integer(mp->s[i])) == sq[i]);
  }
}

TEST_CASE("decide_position gives the same answers when called with the FPU rounding upwards", "[classify][rounding]") {
  // The static filter's bounds assume round-to-nearest; inside CGAL interval code (rounding
  // upwards) classify must notice and use the interval stage instead of a wrong static bound.
  Rng g(seed_from_env(99));
  std::vector<std::pair<Ellipsoid, Paraboloid>> pairs;
  for (const auto& c : dyadic_cases()) pairs.emplace_back(Ellipsoid::from_matrix(c.e), Paraboloid::from_matrix(c.p));
  for (int i = 0; i < 200; ++i) {  // generic pairs with exact-double entries
    const Matrix4 h = dyadic_congruence(g);
    const Rational r = Q(g.uniform(1, 16), 16);
    const Vector3 c{Q(g.uniform(-32, 32), 8), Q(g.uniform(-32, 32), 8), Q(g.uniform(-32, 32), 8)};
    pairs.emplace_back(Ellipsoid::from_matrix(congruence(sphere_matrix(c, r), h)),
                       Paraboloid::from_matrix(congruence(paraboloid_matrix(Q(1), Q(2)), h)));
  }
  std::vector<Verdict> nearest;
  for (const auto& [e, p] : pairs) nearest.push_back(relpos::decide_position(e, p));
  std::vector<Verdict> upward;
  {
    CGAL::Protect_FPU_rounding<true> up;  // rounding towards +infinity
    for (const auto& [e, p] : pairs) upward.push_back(relpos::decide_position(e, p));
  }
  int interval = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    CAPTURE(i);
    CHECK(upward[i].position == nearest[i].position);
    CHECK(upward[i].stage != Stage::StaticDouble);
    interval += upward[i].stage == Stage::Interval;
  }
  CHECK(interval > 100);
}
