// The margin s* (math.md §19; include/relpos/margin.hpp): spheres whose s* = (distance from the
// centre to the paraboloid) / r is known in closed form, rational and irrational, inside and outside
// the cup, on standard, rotated and translated paraboloids; an independent numerical distance for
// spheres placed at random; centres on the surface; the hard case; the any-size corpus (s* against 1
// from the position known by construction); affine invariance; forged margins rejected; and the pieces
// of src/margin (the scaled family, the margin polynomial, Descartes' rule, Newton's refinement, the
// irreducibility test) on polynomials known by construction.
//
// The seed of the random parts is printed; RELPOS_SEED=<n> reruns or varies it.
#include <gmp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <relpos/classify.hpp>
#include <relpos/error.hpp>
#include <relpos/io.hpp>
#include <relpos/margin.hpp>
#include <string>
#include <utility>
#include <vector>

#include "algebra/irreducible.hpp"
#include "algebra/polynomial_sign.hpp"
#include "io/batch.hpp"
#include "margin/descartes.hpp"
#include "margin/family.hpp"
#include "margin/polynomial.hpp"
#include "margin/refine.hpp"
#include "support/construct.hpp"
#include "support/edge_cases.hpp"
#include "support/large_cases.hpp"
#include "support/seed.hpp"

using relpos::Certificate;
using relpos::Ellipsoid;
using relpos::Integer;
using relpos::Margin;
using relpos::Matrix4;
using relpos::Paraboloid;
using relpos::Position;
using relpos::Rational;
using relpos::Vector3;
using rt::Q;

namespace {

std::uint64_t run_seed() {
  static const std::uint64_t seed = relpos::testing::announced_seed("test_margin", 20261207ULL);
  return seed;
}

Vector3 point(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }

/// The primitive integer polynomial den t^2 - num (num / den = v > 0 in lowest terms): the minimal
/// polynomial of sqrt(v) when v is not a square.
std::vector<Integer> square_root_polynomial(const Rational& v) { return {-v.numerator(), Integer(0), v.denominator()}; }

/// v as a long double (numerator and denominator each below long double's range here).
long double to_long_double(const Rational& v) {
  long en = 0, ed = 0;
  const long double n = mpz_get_d_2exp(&en, v.numerator().mpz()), d = mpz_get_d_2exp(&ed, v.denominator().mpz());
  return std::ldexp(n / d, static_cast<int>(en - ed));
}

/// Every property a margin of s*^2 = v (known exactly) must have: the enclosure holds s* (compared
/// exactly through squares), its relative width, approx within 1e-9 of sqrt(v) computed independently
/// in long double, the minimal polynomial, and the verifier's acceptance.
void check_irrational(const Margin& m, const Rational& v, const Ellipsoid& e, const Paraboloid& p, int bits) {
  INFO("s*^2 = " << relpos::to_string(v) << ", [" << relpos::to_string(m.lo) << ", " << relpos::to_string(m.hi) << "]");
  REQUIRE(m.lo < m.hi);
  CHECK(m.lo > 0);
  CHECK(m.lo * m.lo < v);
  CHECK(v < m.hi * m.hi);
  Integer scale(1);
  mpz_mul_2exp(scale.mpz(), scale.mpz(), static_cast<mp_bitcnt_t>(bits));
  CHECK((m.hi - m.lo) * Rational(scale) <= m.lo);
  const long double s = std::sqrt(to_long_double(v));
  CHECK(std::fabs(static_cast<long double>(m.approx) - s) <= 1e-9L * s);
  CHECK(std::fabs(static_cast<long double>(m.approx) - s) <= 1e-15L * s);  // the nearest double, in fact
  CHECK(m.polynomial == square_root_polynomial(v));
  CHECK(m.below.kind == Certificate::Kind::Definite);
  CHECK(m.above.kind == Certificate::Kind::Crossing);
  CHECK(m.at.kind == Certificate::Kind::None);
  const std::optional<std::string> why = relpos::verify_margin(e, p, m);
  CHECK_FALSE(why);
  if (why) WARN(*why);
}

/// The same for a rational s* = q: lo = hi = q, its linear polynomial, the tangency certificate.
void check_rational(const Margin& m, const Rational& q, const Ellipsoid& e, const Paraboloid& p) {
  INFO("s* = " << relpos::to_string(q));
  CHECK(m.lo == q);
  CHECK(m.hi == q);
  CHECK(m.polynomial == std::vector<Integer>{-q.numerator(), q.denominator()});
  const Rational error = relpos::exact_rational(m.approx) - q;  // the nearest double: within half an ulp
  Integer ulps(1);
  mpz_mul_2exp(ulps.mpz(), ulps.mpz(), 53);
  CHECK(rt::rabs(error) * Rational(ulps) <= rt::rabs(q));
  CHECK((m.at.kind == Certificate::Kind::Tangent || m.at.kind == Certificate::Kind::HardTangent));
  const std::optional<std::string> why = relpos::verify_margin(e, p, m);
  CHECK_FALSE(why);
  if (why) WARN(*why);
}

/// The sphere and the paraboloid z = x^2/a^2 + y^2/b^2 rotated by q about the origin and moved by t:
/// the same pair up to a rigid motion (s* unchanged).
std::pair<Ellipsoid, Paraboloid> moved(const Vector3& c, const Rational& r, const Rational& a, const Rational& b,
                                       const relpos::Quaternion& q, const Vector3& t) {
  const relpos::Matrix3 rot = relpos::rotation_from_quaternion(q);
  Vector3 c2;
  for (int i = 0; i < 3; ++i) {
    Rational x = t[static_cast<std::size_t>(i)];
    for (int j = 0; j < 3; ++j) x += rot(i, j) * c[static_cast<std::size_t>(j)];
    c2[static_cast<std::size_t>(i)] = x;
  }
  return {Ellipsoid::sphere(c2, r), Paraboloid::standard(t, a, b, q)};
}

// ------------------------------------------------------------------------------------------------
// An independent distance from a point to z = x^2/a^2 + y^2/b^2: the minimum over the surface of
// |X - c|^2 as a function of (x, y), by Newton's method on its gradient in long double from a grid of
// starting points (no relpos code).

long double squared_distance(const long double c[3], long double a, long double b) {
  const long double ia = 1 / (a * a), ib = 1 / (b * b);
  auto value = [&](long double x, long double y) {
    const long double z = x * x * ia + y * y * ib - c[2];
    return (x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]) + z * z;
  };
  long double best = std::numeric_limits<long double>::infinity();
  const long double range = 2 + std::fabs(c[0]) + std::fabs(c[1]) + std::sqrt(std::fabs(c[2])) * (a + b);
  for (int i = -8; i <= 8; ++i)
    for (int j = -8; j <= 8; ++j) {
      long double x = range * i / 8, y = range * j / 8;
      for (int step = 0; step < 100; ++step) {
        const long double g = x * x * ia + y * y * ib - c[2];
        // Gradient and Hessian of (x - cx)^2 + (y - cy)^2 + g^2, halved.
        const long double fx = (x - c[0]) + 2 * g * x * ia, fy = (y - c[1]) + 2 * g * y * ib;
        const long double fxx = 1 + 2 * g * ia + 4 * x * x * ia * ia, fyy = 1 + 2 * g * ib + 4 * y * y * ib * ib;
        const long double fxy = 4 * x * y * ia * ib;
        const long double det = fxx * fyy - fxy * fxy;
        if (det == 0) break;
        const long double dx = (fyy * fx - fxy * fy) / det, dy = (fxx * fy - fxy * fx) / det;
        x -= dx;
        y -= dy;
        if (std::fabs(dx) + std::fabs(dy) < 1e-19L * (1 + std::fabs(x) + std::fabs(y))) break;
      }
      best = std::min(best, value(x, y));
    }
  return best;
}

}  // namespace

TEST_CASE("margin: rational s* of spheres tangent at a point with a rational normal, inside and outside", "[margin]") {
  // tangent_point: a surface point x0 whose outward normal has rational length, so the point at
  // distance d along it has distance d from the cup (outside: the projection onto the convex solid;
  // inside: d <= min(a, b)^2 / 4, below every radius of curvature). A sphere of radius r there has
  // s* = d / r exactly.
  rt::Rng g(run_seed());
  int cases = 0;
  for (int k = 0; k < 12; ++k) {
    const Rational a = g.positive_rational(5, 3) + Q(1, 2), b = g.positive_rational(5, 3) + Q(1, 2);
    const auto [s, t] = rt::random_st(g, k % 3 == 0);
    const rt::TangentPoint tp = rt::tangent_point(a, b, s, t);
    const Rational d = rt::rmin(a, b) * rt::rmin(a, b) * Q(g.uniform(1, 4), 16);
    for (const int side : {-1, 1}) {
      const Vector3 c = tp.along(side * d);
      for (const Rational& r : {d, d * Q(3, 4), d * Q(5, 3), d / 7}) {
        const Ellipsoid e = Ellipsoid::sphere(c, r);
        const Paraboloid p = Paraboloid::standard(point(Q(0), Q(0), Q(0)), a, b);
        const Margin m = relpos::margin(e, p);
        check_rational(m, d / r, e, p);
        // The certificate at s* is the tangency from the side of the centre.
        if (m.at.kind == Certificate::Kind::Tangent) CHECK((side < 0) == (m.at.lambda < 0));
        ++cases;
      }
    }
  }
  CHECK(cases == 96);
}

TEST_CASE("margin: irrational s* of spheres on a normal of irrational length, inside and outside", "[margin]") {
  // x0 = (x, y, x^2/a^2 + y^2/b^2), n = (2x/a^2, 2y/b^2, -1) (outward), c = x0 + t n: the distance is
  // |t| |n| (outside: t > 0, any t; inside: |t| |n| <= min(a, b)^2 / 4), so s*^2 = t^2 |n|^2 / r^2,
  // irrational when that is not a square.
  rt::Rng g(run_seed() + 1);
  int irrational = 0;
  for (int k = 0; k < 24; ++k) {
    const Rational a = g.positive_rational(5, 3) + Q(1, 2), b = g.positive_rational(5, 3) + Q(1, 2);
    const Rational x = g.rational(-3, 3, 2), y = g.rational(-3, 3, 2);
    const Vector3 x0 = point(x, y, x * x / (a * a) + y * y / (b * b));
    const Vector3 n = point(2 * x / (a * a), 2 * y / (b * b), Q(-1));
    const Rational n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const bool inside = k % 2 == 1;
    // Inside: |t|^2 |n|^2 <= (min(a,b)^2 / 4)^2, with |n| >= 1: |t| = min(a,b)^2 / (4 ceil(|n|)).
    Rational t = g.positive_rational(3, 4);
    if (inside) {
      Rational bound = rt::rmin(a, b) * rt::rmin(a, b) / 4;
      Integer ceil_n(1);
      while (Rational(ceil_n * ceil_n) < n2) ceil_n += 1;
      t = -(bound / Rational(ceil_n)) * Q(g.uniform(1, 4), 4);
    }
    const Vector3 c = point(x0[0] + t * n[0], x0[1] + t * n[1], x0[2] + t * n[2]);
    const Rational r = g.positive_rational(5, 7);
    const Rational v = t * t * n2 / (r * r);
    const Ellipsoid e = Ellipsoid::sphere(c, r);
    const Paraboloid p = Paraboloid::standard(point(Q(0), Q(0), Q(0)), a, b);
    const Margin m = relpos::margin(e, p);
    if (mpz_perfect_square_p(v.numerator().mpz()) && mpz_perfect_square_p(v.denominator().mpz())) continue;
    ++irrational;
    check_irrational(m, v, e, p, relpos::kDefaultMarginBits);
    CHECK((inside ? m.below.lambda < 0 : m.below.lambda > 0));  // I below s* inside the cup, E outside
  }
  CHECK(irrational >= 18);
}

TEST_CASE("margin: the same spheres on rotated and translated paraboloids give the same margin", "[margin]") {
  rt::Rng g(run_seed() + 2);
  for (int k = 0; k < 10; ++k) {
    const Rational a = g.positive_rational(5, 3) + Q(1, 2), b = g.positive_rational(5, 3) + Q(1, 2);
    const Rational x = g.rational(-3, 3, 2), y = g.rational(-3, 3, 2);
    const Vector3 c = point(x + g.rational(-2, 2, 3), y + g.rational(-2, 2, 3), g.rational(-2, 6, 3));
    const Rational r = g.positive_rational(4, 5);
    const Margin m0 = relpos::margin(Ellipsoid::sphere(c, r), Paraboloid::standard(point(Q(0), Q(0), Q(0)), a, b));
    const auto [e, p] = moved(c, r, a, b, rt::random_quaternion(g),
                              point(g.rational(-9, 9, 4), g.rational(-9, 9, 4), g.rational(-9, 9, 4)));
    const Margin m = relpos::margin(e, p);
    CHECK(m.lo == m0.lo);
    CHECK(m.hi == m0.hi);
    CHECK(m.polynomial == m0.polynomial);
    CHECK(m.approx == m0.approx);
    CHECK_FALSE(relpos::verify_margin(e, p, m));
  }
}

TEST_CASE("margin: spheres placed at random against an independent numerical distance", "[margin]") {
  // s* = d / r with d^2 the minimum of |X - c|^2 over the surface, found by Newton's method in long double
  // from a grid of starts (no relpos code): approx within 1e-9, the enclosure within its width.
  rt::Rng g(run_seed() + 3);
  for (int k = 0; k < 30; ++k) {
    const Rational a = g.positive_rational(5, 3) + Q(1, 2), b = g.positive_rational(5, 3) + Q(1, 2);
    const Vector3 c = point(g.rational(-6, 6, 4), g.rational(-6, 6, 4), g.rational(-4, 12, 4));
    const Rational r = g.positive_rational(6, 7);
    const Ellipsoid e = Ellipsoid::sphere(c, r);
    const Paraboloid p = Paraboloid::standard(point(Q(0), Q(0), Q(0)), a, b);
    const Margin m = relpos::margin(e, p);
    const long double cl[3] = {to_long_double(c[0]), to_long_double(c[1]), to_long_double(c[2])};
    const long double s = std::sqrt(squared_distance(cl, to_long_double(a), to_long_double(b))) / to_long_double(r);
    INFO("centre " << relpos::to_string(c[0]) << ", " << relpos::to_string(c[1]) << ", " << relpos::to_string(c[2])
                   << ", r " << relpos::to_string(r) << ": s* ~ " << static_cast<double>(s));
    CHECK(std::fabs(static_cast<long double>(m.approx) - s) <= 1e-9L * s);
    CHECK(to_long_double(m.lo) <= s * (1 + 1e-15L));
    CHECK(s <= to_long_double(m.hi) * (1 + 1e-15L));
    CHECK_FALSE(relpos::verify_margin(e, p, m));
  }
}

TEST_CASE("margin: centres on the paraboloid have s* = 0", "[margin]") {
  rt::Rng g(run_seed() + 4);
  for (int k = 0; k < 6; ++k) {
    const Rational a = g.positive_rational(5, 3) + Q(1, 2), b = g.positive_rational(5, 3) + Q(1, 2);
    const Rational x = g.rational(-3, 3, 2), y = g.rational(-3, 3, 2);
    const Vector3 c = point(x, y, x * x / (a * a) + y * y / (b * b));
    const auto [e, p] = moved(c, g.positive_rational(4, 3), a, b, rt::random_quaternion(g), point(Q(1), Q(-2), Q(3)));
    const Margin m = relpos::margin(e, p);
    CHECK(m.lo == 0);
    CHECK(m.hi == 0);
    CHECK(m.approx == 0);
    CHECK(m.polynomial == std::vector<Integer>{Integer(0), Integer(1)});
    CHECK_FALSE(relpos::verify_margin(e, p, m));
    CHECK(relpos::classify(e, p).verdict.position == Position::C);
  }
}

TEST_CASE("margin: the hard case, spheres on the axis of a circular paraboloid", "[margin]") {
  // z = x^2 + y^2, centre (0, 0, h): for h >= 1/2 the nearest points form the circle z = h - 1/2, at
  // distance^2 h - 1/4; below, the vertex at distance h (support/large_cases.hpp, family 1).
  const Paraboloid p = Paraboloid::standard(point(Q(0), Q(0), Q(0)), Q(1), Q(1));
  // TI along a circle at s* = 1 (the sphere x^2 + y^2 + (z - 1)^2 <= 3/4: irrational radius, a matrix).
  Matrix4 m3;
  m3(0, 0) = m3(1, 1) = m3(2, 2) = Q(1);
  m3(2, 3) = m3(3, 2) = Q(-1);
  m3(3, 3) = Q(1, 4);
  const Ellipsoid touching = Ellipsoid::from_matrix(m3);
  const Margin one = relpos::margin(touching, p);
  check_rational(one, Q(1), touching, p);
  CHECK(one.at.kind == Certificate::Kind::HardTangent);
  for (const auto& [h, r] : std::vector<std::pair<Rational, Rational>>{
           {Q(1), Q(1)}, {Q(1), Q(1, 2)}, {Q(3), Q(2)}, {Q(7, 4), Q(1, 3)}, {Q(5, 8), Q(9, 10)}}) {
    const Ellipsoid e = Ellipsoid::sphere(point(Q(0), Q(0), h), r);
    const Rational v = (h - Q(1, 4)) / (r * r);
    const Margin m = relpos::margin(e, p);
    if (mpz_perfect_square_p(v.numerator().mpz()) && mpz_perfect_square_p(v.denominator().mpz())) {
      Integer num, den;
      mpz_sqrt(num.mpz(), v.numerator().mpz());
      mpz_sqrt(den.mpz(), v.denominator().mpz());
      check_rational(m, Rational(num, den), e, p);
    } else {
      check_irrational(m, v, e, p, relpos::kDefaultMarginBits);
    }
  }
  // Below h = 1/2 the vertex is nearest: s* = h / r.
  const Ellipsoid low = Ellipsoid::sphere(point(Q(0), Q(0), Q(1, 4)), Q(1, 8));
  check_rational(relpos::margin(low, p), Q(2), low, p);
}

TEST_CASE("margin: s* against 1 matches the position known by construction on the any-size corpus", "[margin]") {
  // I and E: s* > 1; TI and TE: s* = 1 exactly; C: s* < 1 (bodies that are not small, irrational
  // lambda_s, 1e-30 from tangencies, under rigid motions and affine congruences).
  std::vector<relpos::testing::LargeCase> cases = relpos::testing::large_cases();
  rt::Rng g(run_seed() + 5);
  const std::size_t base = cases.size();
  for (std::size_t i = 0; i < base; i += 7) cases.push_back(relpos::testing::transformed_copy(cases[i], g, i % 2 == 0));
  int checked = 0;
  for (const auto& c : cases) {
    INFO(c.name);
    const Margin m = relpos::margin(c.e, c.p);
    const int against_one = m.value().compare(Q(1));
    switch (c.expected) {
      case Position::I:
      case Position::E:
        CHECK(against_one > 0);
        break;
      case Position::TI:
      case Position::TE:
        CHECK(m.lo == 1);
        CHECK(m.hi == 1);
        break;
      case Position::C:
        CHECK(against_one < 0);
        break;
    }
    const std::optional<std::string> why = relpos::verify_margin(c.e, c.p, m);
    CHECK_FALSE(why);
    ++checked;
  }
  CHECK(checked > 100);
}

TEST_CASE("margin: s* against 1 at the edges of scale and nearness", "[margin]") {
  // support/edge_cases.hpp: spheres 1e-3 ... 1e-100 from contact, bodies of size 1e-15 ... 1e-40 on
  // the surface (C: s* < 1, tiny) and far away, the sphere resting in the cup moved by 1e-5 ... 2^-130,
  // spheres touching along a circle, under similarities of scale 1e-30 ... 1e30 and affine maps.
  using namespace rt::edges;
  rt::Rng g(2101);
  std::vector<EdgeCase> cases;
  for (const EdgeCase& c : spheres_near_contact(g)) {
    cases.push_back(c);
    cases.push_back(similar(g, c, pow10(-30), pow10(-24), "scaled by 1e-30"));
    cases.push_back(affine(g, c, pow10(30), pow10(30), "affine, scaled by 1e30"));
  }
  for (int k = 15; k <= 40; k += 5)
    for (const EdgeCase& c : tiny_on_surface(g, k)) {
      cases.push_back(c);
      cases.push_back(similar(g, c, Q(1), pow10(6), "translated by 1e6"));
    }
  for (const Rational& eps : {pow10(-5), pow10(-20), pow10(-100), pow2(-130)})
    for (const EdgeCase& c : sphere_in_cup(eps)) {
      cases.push_back(c);
      cases.push_back(affine(g, c, pow10(20), pow10(30), "affine, translated by 1e30"));
    }
  for (const Rational& d : nearness()) {
    const Rational a = Q(g.uniform(1, 3)), h = a * a * Q(g.uniform(3, 6), 4);
    for (const EdgeCase& c : sphere_on_circle(a, h, d)) {
      cases.push_back(c);
      cases.push_back(similar(g, c, pow10(-30), pow10(-24), "moved"));
    }
  }
  for (const EdgeCase& c : cases) {
    INFO(c.family);
    const Ellipsoid e = Ellipsoid::from_matrix(c.e);
    const Paraboloid p = Paraboloid::from_matrix(c.p);
    const Margin m = relpos::margin(e, p);
    const int against_one = m.value().compare(Q(1));
    if (c.expected == Position::I || c.expected == Position::E) CHECK(against_one > 0);
    if (c.expected == Position::TI || c.expected == Position::TE) CHECK(against_one == 0);
    if (c.expected == Position::C) CHECK(against_one < 0);
    CHECK_FALSE(relpos::verify_margin(e, p, m));
  }
  CHECK(cases.size() > 150);
}

TEST_CASE("margin: affine congruences and rescalings leave the margin unchanged", "[margin]") {
  // s* is affine-invariant (the scaled family commutes with affine maps), and the margin polynomial
  // changes by a constant factor only, so the whole margin is the same.
  rt::Rng g(run_seed() + 6);
  for (int k = 0; k < 12; ++k) {
    const Rational a = g.positive_rational(5, 3) + Q(1, 2), b = g.positive_rational(5, 3) + Q(1, 2);
    const Vector3 c = point(g.rational(-4, 4, 3), g.rational(-4, 4, 3), g.rational(-2, 8, 3));
    const Matrix4 e0 = rt::sphere_matrix(c, g.positive_rational(4, 5)), p0 = rt::paraboloid_matrix(a, b);
    const Ellipsoid e = Ellipsoid::from_matrix(e0);
    const Paraboloid p = Paraboloid::from_matrix(p0);
    const Margin m0 = relpos::margin(e, p);
    const rt::Transformed t = rt::transform(e0, p0, g, /*rigid=*/false, /*rescale=*/true);
    const Ellipsoid e2 = Ellipsoid::from_matrix(t.e);
    const Paraboloid p2 = Paraboloid::from_matrix(t.p);
    const Margin m = relpos::margin(e2, p2);
    CHECK(m.lo == m0.lo);
    CHECK(m.hi == m0.hi);
    CHECK(m.polynomial == m0.polynomial);
    CHECK(m.approx == m0.approx);
    CHECK_FALSE(relpos::verify_margin(e2, p2, m));
    // An ellipsoid under its own scaling: the factor's reciprocal.
    const Margin half = relpos::margin(relpos::detail::scaled_about_centre(e, Q(1, 2)), p);
    CHECK(half.value().compare(m0.lo * 2) >= 0);
    CHECK(half.value().compare(m0.hi * 2) <= 0);
  }
}

TEST_CASE("verify_margin: forged margins are rejected", "[margin]") {
  const Paraboloid p = Paraboloid::standard(point(Q(0), Q(0), Q(0)), Q(6, 5), Q(3, 2));
  const Ellipsoid e = Ellipsoid::sphere(point(Q(1, 2), Q(1, 3), Q(2)), Q(1, 5));
  const Margin good = relpos::margin(e, p);
  REQUIRE_FALSE(relpos::verify_margin(e, p, good));
  REQUIRE(good.lo < good.hi);
  const Rational width = good.hi - good.lo;
  auto rejected = [&](const Margin& m, const char* what) {
    INFO(what);
    const std::optional<std::string> why = relpos::verify_margin(e, p, m);
    CHECK(why);
    if (why) INFO(*why);
  };
  Margin m = good;
  m.lo = good.hi + width;  // the enclosure moved above s*, certificates kept
  m.hi = good.hi + 2 * width;
  rejected(m, "enclosure above s*");
  m = good;
  m.lo = good.lo - 2 * width;  // below s*
  m.hi = good.lo - width;
  rejected(m, "enclosure below s*");
  relpos::AlgebraicReal s = good.value();  // hi moved across s*: lo < hi < s*
  s.refine(width / 1024);
  REQUIRE(s.lower() > good.lo);
  m = good;
  m.hi = s.lower();
  rejected(m, "hi below s*");
  m = good;
  m.lo = s.upper();  // lo moved across s*: s* < lo < hi
  rejected(m, "lo above s*");
  m = good;
  m.lo = good.hi;  // lo == hi: a rational claim
  rejected(m, "a rational claim of an irrational s*");
  m = good;
  m.polynomial[0] += 1;  // polynomial changed
  rejected(m, "polynomial changed");
  m = good;
  for (auto& x : m.polynomial) x *= 2;  // not primitive
  rejected(m, "polynomial not primitive");
  m = good;
  m.polynomial.insert(m.polynomial.begin(), Integer(0));  // times t: reducible, still a sign change
  rejected(m, "polynomial times t");
  m = good;
  std::swap(m.below, m.above);  // certificates swapped
  rejected(m, "certificates swapped");
  m = good;
  m.below.lambda = -m.below.lambda;  // tampered multiplier
  rejected(m, "below tampered");
  m = good;
  m.above.inside = m.above.outside;  // tampered witness
  rejected(m, "above tampered");
  m = good;
  m.approx = CGAL::to_double(good.hi) * (1 + 1e-12);  // approximation outside
  rejected(m, "approx outside");
  m = good;
  m.approx = std::numeric_limits<double>::quiet_NaN();
  rejected(m, "approx NaN");
  m = good;
  m.at = m.below;  // an extra certificate
  rejected(m, "an extra certificate");
  // A rational margin moved, and a zero margin claimed for a centre off the surface.
  const Ellipsoid ti = Ellipsoid::sphere(point(Q(0), Q(0), Q(1, 4)), Q(1, 8));
  const Paraboloid cup = Paraboloid::standard(point(Q(0), Q(0), Q(0)), Q(1), Q(1));
  const Margin two = relpos::margin(ti, cup);
  REQUIRE_FALSE(relpos::verify_margin(ti, cup, two));
  Margin bad = two;
  bad.lo = bad.hi = Q(9, 4);
  bad.polynomial = {Integer(-9), Integer(4)};
  CHECK(relpos::verify_margin(ti, cup, bad));
  bad = two;
  bad.lo = bad.hi = Q(0);
  bad.polynomial = {Integer(0), Integer(1)};
  bad.at = Certificate{};
  bad.approx = 0;
  CHECK(relpos::verify_margin(ti, cup, bad));
}

TEST_CASE("margin: bits, the JSON form and the batch member", "[margin]") {
  const Paraboloid p = Paraboloid::standard(point(Q(0), Q(0), Q(0)), Q(1), Q(1));
  const Ellipsoid e = Ellipsoid::sphere(point(Q(1), Q(0), Q(1, 2)), Q(1, 3));
  for (const int bits : {1, 8, 40, 100, 300}) {
    const Margin m = relpos::margin(e, p, bits);
    Integer scale(1);
    mpz_mul_2exp(scale.mpz(), scale.mpz(), static_cast<mp_bitcnt_t>(bits));
    CHECK((m.hi - m.lo) * Rational(scale) <= m.lo);
    CHECK_FALSE(relpos::verify_margin(e, p, m));
    const Margin back = relpos::io::margin_from_json_text(relpos::io::margin_json_text(m));
    CHECK(back.lo == m.lo);
    CHECK(back.hi == m.hi);
    CHECK(back.polynomial == m.polynomial);
    CHECK(back.approx == m.approx);
    CHECK_FALSE(relpos::verify_margin(e, p, back));
  }
  CHECK_THROWS_AS(relpos::margin(e, p, 0), relpos::InputError);
  CHECK_THROWS_AS(relpos::margin(e, p, relpos::detail::kMaxMarginBits + 1), relpos::InputError);
  CHECK_THROWS_AS(relpos::detail::scaled_about_centre(e, Q(0)), relpos::InputError);
  // The batch line's last member, after the certificate; the other members as without --margin.
  const std::string line =
      R"({"id":"x","ellipsoid":{"sphere":{"center":[1,0,0.5],"radius":"1/3"}},"paraboloid":{"vertex":[0,0,0],"a":1,"b":1}})";
  relpos::detail::io::BatchOptions options;
  const std::string plain = relpos::detail::io::answer_batch_line(line, 1, options);
  options.margin_bits = relpos::kDefaultMarginBits;
  const std::string with = relpos::detail::io::answer_batch_line(line, 1, options);
  const std::string member = ",\"margin\":" + relpos::io::margin_json_text(relpos::margin(e, p)) + "}";
  CHECK(with == plain.substr(0, plain.size() - 1) + member);
  CHECK_THROWS_AS(relpos::io::margin_from_json_text(R"({"approx":1,"lo":"1","hi":"1"})"), relpos::InputError);
  CHECK_THROWS_AS(relpos::io::margin_from_json_text(R"({"approx":"x","lo":"1","hi":"1","polynomial":["-1","1"]})"),
                  relpos::InputError);
  CHECK_THROWS_AS(relpos::io::margin_from_json_text(R"({"approx":1,"lo":"1","hi":"1","polynomial":["1/2"]})"),
                  relpos::InputError);
}

TEST_CASE("margin: s* beyond the double range has approx +infinity, JSON null", "[margin]") {
  // Spheres against z = x^2 + y^2 (known by construction): on the axis below the vertex, centre
  // (0, 0, -h), the vertex is the nearest point, s* = h / r = 2^1025 exactly (E); on the axis above,
  // centre (0, 0, h) with h >= 1/2, the circle z = h - 1/2 is nearest, s*^2 = (h - 1/4) / r^2 (I),
  // here about 2^2300, irrational. Both exceed DBL_MAX < 2^1024: the nearest double is +infinity.
  const Paraboloid cup = Paraboloid::standard(point(Q(0), Q(0), Q(0)), Q(1), Q(1));
  Integer h1(1), h2(1), r2(1);
  mpz_mul_2exp(h1.mpz(), h1.mpz(), 1025);
  mpz_mul_2exp(h2.mpz(), h2.mpz(), 900);
  mpz_mul_2exp(r2.mpz(), r2.mpz(), 700);
  const Ellipsoid below = Ellipsoid::sphere(point(Q(0), Q(0), -Rational(h1)), Q(1));
  const Ellipsoid above = Ellipsoid::sphere(point(Q(0), Q(0), Rational(h2)), Rational(Integer(1), r2));
  const Margin rational = relpos::margin(below, cup);
  CHECK(rational.lo == Rational(h1));
  CHECK(rational.hi == Rational(h1));
  CHECK(rational.polynomial == std::vector<Integer>{-h1, Integer(1)});
  CHECK(rational.at.kind == Certificate::Kind::Tangent);
  const Rational v = (Rational(h2) - Q(1, 4)) * Rational(r2) * Rational(r2);
  const Margin irrational = relpos::margin(above, cup);
  INFO("s*^2 = " << relpos::to_string(v));
  REQUIRE(irrational.lo < irrational.hi);
  CHECK(irrational.lo * irrational.lo < v);
  CHECK(v < irrational.hi * irrational.hi);
  CHECK(irrational.polynomial == square_root_polynomial(v));
  auto beyond = [&](const Ellipsoid& e, const Margin& m) {
    CHECK(m.lo > relpos::exact_rational(std::numeric_limits<double>::max()));
    CHECK(m.approx == std::numeric_limits<double>::infinity());
    CHECK_FALSE(relpos::verify_margin(e, cup, m));
    const std::string text = relpos::io::margin_json_text(m);
    CHECK(text.rfind("{\"approx\":null,", 0) == 0);
    const Margin back = relpos::io::margin_from_json_text(text);
    CHECK(back.approx == std::numeric_limits<double>::infinity());
    CHECK(back.lo == m.lo);
    CHECK(back.hi == m.hi);
    CHECK_FALSE(relpos::verify_margin(e, cup, back));
    Margin forged = m;
    forged.approx = -std::numeric_limits<double>::infinity();
    CHECK(relpos::verify_margin(e, cup, forged));
    forged.approx = 1e300;  // finite, far below s*
    CHECK(relpos::verify_margin(e, cup, forged));
  };
  beyond(below, rational);
  beyond(above, irrational);
  // +infinity (null) claimed for an s* within the double range is rejected.
  const Ellipsoid small = Ellipsoid::sphere(point(Q(0), Q(0), Q(-1)), Q(1, 2));
  const Margin two = relpos::margin(small, cup);
  REQUIRE_FALSE(relpos::verify_margin(small, cup, two));
  Margin forged = relpos::io::margin_from_json_text(relpos::io::margin_json_text(two));
  forged.approx = std::numeric_limits<double>::infinity();
  CHECK(relpos::verify_margin(small, cup, forged));
}

TEST_CASE("margin pieces: the scaled family", "[margin]") {
  rt::Rng g(run_seed() + 7);
  for (int k = 0; k < 10; ++k) {
    const Vector3 c = point(g.rational(-5, 5, 3), g.rational(-5, 5, 3), g.rational(-5, 5, 3));
    const Rational r = g.positive_rational(5, 4), q = g.positive_rational(9, 4);
    const Ellipsoid e = Ellipsoid::sphere(c, r);
    const relpos::detail::ScaledFamily f = relpos::detail::scaled_family(e.matrix());
    CHECK(f.centre == c);
    CHECK(f.k == r * r);
    CHECK(f.at(Q(1)) == e.matrix());
    CHECK(f.at(q) == Ellipsoid::sphere(c, q * r).matrix());
    CHECK(relpos::detail::scaled_about_centre(e, q).matrix() == Ellipsoid::sphere(c, q * r).matrix());
    CHECK(relpos::detail::form_at(e.matrix(), c) == -r * r);
  }
}

TEST_CASE("margin pieces: the margin polynomial vanishes at s*^2", "[margin]") {
  // Constructed s*^2 (the rational and irrational families above): Pi(s*^2) = 0 exactly, and its
  // value at t^2 is Pi in t.
  rt::Rng g(run_seed() + 8);
  for (int k = 0; k < 10; ++k) {
    const Rational a = g.positive_rational(5, 3) + Q(1, 2), b = g.positive_rational(5, 3) + Q(1, 2);
    const Rational x = g.rational(-3, 3, 2), y = g.rational(-3, 3, 2);
    const Vector3 x0 = point(x, y, x * x / (a * a) + y * y / (b * b));
    const Vector3 n = point(2 * x / (a * a), 2 * y / (b * b), Q(-1));
    const Rational t = g.positive_rational(3, 4), r = g.positive_rational(5, 7);
    const Vector3 c = point(x0[0] + t * n[0], x0[1] + t * n[1], x0[2] + t * n[2]);
    const Rational v = t * t * (n[0] * n[0] + n[1] * n[1] + 1) / (r * r);
    const relpos::detail::ScaledFamily f = relpos::detail::scaled_family(Ellipsoid::sphere(c, r).matrix());
    const std::vector<Integer> pi =
        relpos::detail::margin_polynomial(relpos::detail::point_pencil(f, rt::paraboloid_matrix(a, b)));
    CHECK(relpos::detail::sign_of_value(pi, v) == 0);
    const std::vector<Integer> in_t = relpos::detail::in_square(pi);
    REQUIRE(in_t.size() == 2 * pi.size() - 1);
    for (std::size_t i = 0; i < pi.size(); ++i) CHECK(in_t[2 * i] == pi[i]);
    CHECK(pi.back() > 0);
  }
}

TEST_CASE("margin pieces: Descartes' rule, isolation and refinement on polynomials with known roots", "[margin]") {
  rt::Rng g(run_seed() + 9);
  for (int k = 0; k < 40; ++k) {
    // prod (d_i t - n_i) over distinct positive and negative rationals, some 2^-60 apart, times an
    // irreducible quadratic t^2 - w (w not a square).
    std::vector<Rational> roots;
    const int count = static_cast<int>(g.uniform(1, 5));
    while (static_cast<int>(roots.size()) < count) {
      Rational r = g.nonzero_rational(-40, 40, 9);
      if (g.chance(20) && !roots.empty()) {
        Integer tiny(1);
        mpz_mul_2exp(tiny.mpz(), tiny.mpz(), 60);
        r = roots.back() + Rational(Integer(1), tiny);
      }
      if (std::find(roots.begin(), roots.end(), r) == roots.end()) roots.push_back(r);
    }
    std::vector<Integer> p{Integer(1)};
    auto times = [&](const std::vector<Integer>& f) {
      std::vector<Integer> out(p.size() + f.size() - 1, Integer(0));
      for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = 0; j < f.size(); ++j) out[i + j] += p[i] * f[j];
      p = out;
    };
    for (const Rational& r : roots) times({-r.numerator(), r.denominator()});
    const long w = 2 * g.uniform(1, 30) + 1;  // odd, and w = 9 etc. are squares: skipped below
    const bool quadratic = !mpz_perfect_square_p(Integer(w).mpz());
    if (quadratic) times({Integer(-w), Integer(0), Integer(1)});
    const std::vector<relpos::detail::RootInterval> found = relpos::detail::positive_roots(p);
    std::vector<Rational> positive;
    for (const Rational& r : roots)
      if (r > 0) positive.push_back(r);
    REQUIRE(found.size() == positive.size() + (quadratic ? 1 : 0));
    for (const auto& iv : found) {
      // Each interval holds exactly one of the known positive roots (or sqrt w).
      int inside = 0;
      for (const Rational& r : positive) inside += (iv.lo == iv.hi ? r == iv.lo : (iv.lo < r && r < iv.hi)) ? 1 : 0;
      if (quadratic && iv.lo != iv.hi && iv.lo * iv.lo < w && w < iv.hi * iv.hi) ++inside;
      CHECK(inside == 1);
      if (iv.lo != iv.hi) CHECK(relpos::detail::descartes_bound(p, iv.lo, iv.hi) == 1);
    }
    if (quadratic) {  // sqrt(w) refined to 2^-100 relative, checked through squares
      const std::vector<Integer> m{Integer(-w), Integer(0), Integer(1)};
      relpos::detail::RootInterval iv{Q(1), Rational(w)};
      relpos::detail::refine_root(m, iv, 100);
      CHECK(iv.lo * iv.lo < w);
      CHECK(w < iv.hi * iv.hi);
      Integer scale(1);
      mpz_mul_2exp(scale.mpz(), scale.mpz(), 100);
      CHECK((iv.hi - iv.lo) * Rational(scale) <= iv.lo);
      CHECK(relpos::detail::isolates(p, m, iv.lo, iv.hi));
    }
    // No positive root below the smallest interval: Descartes' bound 0 there.
    if (!found.empty() && found.front().lo > 0) CHECK(relpos::detail::descartes_bound(p, Q(0), found.front().lo) == 0);
  }
}

TEST_CASE("margin pieces: irreducibility by degrees modulo primes is never claimed for a product", "[margin]") {
  rt::Rng g(run_seed() + 10);
  int proven = 0;
  for (int k = 0; k < 200; ++k) {
    auto random_poly = [&](int degree) {
      std::vector<Integer> f;
      for (int i = 0; i < degree; ++i) f.push_back(Integer(g.uniform(-50, 50)));
      f.push_back(Integer(g.uniform(1, 9)));
      return f;
    };
    const std::vector<Integer> f = random_poly(static_cast<int>(g.uniform(1, 5))),
                               h = random_poly(static_cast<int>(g.uniform(1, 5)));
    std::vector<Integer> fh(f.size() + h.size() - 1, Integer(0));
    for (std::size_t i = 0; i < f.size(); ++i)
      for (std::size_t j = 0; j < h.size(); ++j) fh[i + j] += f[i] * h[j];
    CHECK_FALSE(relpos::detail::proven_irreducible(fh));
    // When claimed for f itself, FLINT's factorisation agrees.
    if (relpos::detail::proven_irreducible(f)) {
      ++proven;
      CHECK(relpos::detail::irreducible_factors(f).size() == 1);
    }
  }
  CHECK(proven > 20);
  // x^5 - x - 1 (Galois group S5) and t^4 + 1 (reducible modulo every prime, irreducible over Q).
  CHECK(relpos::detail::proven_irreducible({Integer(-1), Integer(-1), Integer(0), Integer(0), Integer(0), Integer(1)}));
  CHECK_FALSE(relpos::detail::proven_irreducible({Integer(1), Integer(0), Integer(0), Integer(0), Integer(1)}));
}
