// The motion module's parts (moving_pencil.hpp, candidates.hpp): the pencil over Z[t] specialised at
// a rational time is the placed pair's pencil up to positive factors (f, s, Disc f and the smallness
// quantities, against pencil.hpp on the placed matrices); the candidate instants are the real zeros
// of the event polynomials, merged exactly; the sign at an algebraic instant satisfies
// sign (r + m q)(t*) = sign r(t*) for m the minimal polynomial of t*, with sign r(t*) known in closed
// form; a sample between two instants is the rational of smallest denominator there.
#include <gmp.h>

#include <catch2/catch.hpp>
#include <optional>
#include <random>
#include <relpos/motion.hpp>
#include <vector>

#include "algebra/pencil.hpp"
#include "algebra/smallness.hpp"
#include "algebra/sturm.hpp"
#include "motion/candidates.hpp"
#include "motion/moving_pencil.hpp"
#include "motion/polynomial_motion.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;
using relpos::detail::PolyZ;

namespace {

/// p(t) for a polynomial over Z at a rational t (Horner in rationals).
Rational value_at(const PolyZ& p, const Rational& t) {
  if (CGAL::is_zero(p)) return Rational(0);
  Rational v(0);
  for (int i = p.degree(); i >= 0; --i) v = v * t + Rational(p[i]);
  return v;
}

/// Whether a_i = c r^i b_i for all i with constants c > 0 and r > 0 (r given): a positive multiple
/// of b with its variable scaled by r.
template <std::size_t N>
bool scaled_multiple(const std::array<Rational, N>& a, const std::array<Rational, N>& b, const Rational& r) {
  if (b[0] == 0 || !(r > 0)) return false;
  const Rational c = a[0] / b[0];
  Rational power(1);
  for (std::size_t i = 0; i < N; ++i, power *= r)
    if (a[i] != c * power * b[i]) return false;
  return c > 0;
}

relpos::TimePolynomial random_poly(Rng& g, int degree) {
  relpos::TimePolynomial p;
  for (int i = 0; i <= degree; ++i) p.push_back(g.rational(-4, 4, 3));
  return p;
}

/// PolyZ from small integer coefficients, constant term first.
PolyZ z_poly(std::initializer_list<long> c) {
  std::vector<Integer> v;
  for (long x : c) v.push_back(Integer(x));
  return PolyZ(v.begin(), v.end());
}

}  // namespace

TEST_CASE("the moving pencil at a rational time is the placed pair's pencil up to positive factors", "[motion]") {
  Rng g(7001);
  int checked = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const relpos::Ellipsoid e0 = relpos::Ellipsoid::from_axes(
        {g.rational(-2, 2, 3), g.rational(-2, 2, 3), g.rational(-2, 2, 3)},
        {g.positive_rational(3, 2), g.positive_rational(3, 2), g.positive_rational(3, 2)}, random_quaternion(g));
    const relpos::Paraboloid p = relpos::Paraboloid::standard({Q(0), Q(0), Q(0)}, g.positive_rational(3, 2),
                                                              g.positive_rational(3, 2), random_quaternion(g, 2));
    relpos::RigidMotion m = relpos::RigidMotion::translating({random_poly(g, 2), random_poly(g, 1), random_poly(g, 2)});
    if (trial % 2 == 0) {  // a rotation q(t) = (1, a t, b t, 0): never zero
      m.rotation = std::array<relpos::TimePolynomial, 4>{
          relpos::TimePolynomial{Q(1)}, {Q(0), g.rational(-2, 2, 1)}, {Q(0), g.rational(-2, 2, 1)}, {}};
      m.pivot = trial % 4 == 0 ? relpos::Pivot::Centre : relpos::Pivot::Origin;
    }
    const relpos::detail::MovingPencil mp(e0, m, p);
    for (int k = 0; k < 6; ++k) {
      const Rational t = g.rational(-3, 3, 4);
      const relpos::Ellipsoid placed = relpos::detail::placed_ellipsoid(e0, m, t);
      const Quartic<Rational> f = relpos::characteristic_polynomial<Rational>(p.matrix(), placed.matrix());
      const Quadratic<Rational> s = relpos::special_polynomial<Rational>(p.matrix(), placed.matrix());
      Quartic<Rational> ft;
      Quadratic<Rational> st;
      for (std::size_t i = 0; i < 5; ++i) ft[i] = value_at(mp.f[i], t);
      for (std::size_t i = 0; i < 3; ++i) st[i] = value_at(mp.s[i], t);
      CAPTURE(trial, relpos::to_string(t));
      // P and E(t) are scaled by different positive factors a and b(t) (integer forms, N(t)^2), so
      // f_t(l) = b^4 f(a l / b): the variable scaled by r = a / b, read off the linear coefficients.
      REQUIRE(f[1] != 0);
      const Rational r = (ft[1] * f[0]) / (ft[0] * f[1]);
      CHECK(scaled_multiple(ft, f, r));
      CHECK(scaled_multiple(st, s, r));
      // The decision quantities: positive multiples, so the same signs as on the placed pair.
      CHECK(sgn(value_at(mp.disc, t)) == sgn(quartic_discriminant(f)));
      const relpos::SmallnessQuantities<Rational> q(f, s);
      CHECK(sgn(value_at(mp.vertex, t)) == sgn(q.vertex));
      CHECK(sgn(value_at(mp.graeffe, t)) == sgn(q.graeffe));
      ++checked;
    }
  }
  CHECK(checked == 72);
}

TEST_CASE("make_primitive divides by the joint content of the integer coefficients", "[motion]") {
  PolyZ ps[2] = {z_poly({6, -12, 18}), z_poly({-30, 0, 42, 0, 0, 6})};
  relpos::detail::make_primitive(ps, ps + 2);
  CHECK(ps[0] == z_poly({1, -2, 3}));
  CHECK(ps[1] == z_poly({-5, 0, 7, 0, 0, 1}));
  PolyZ zero[1] = {z_poly({0})};
  relpos::detail::make_primitive(zero, zero + 1);  // no content: unchanged
  CHECK(CGAL::is_zero(zero[0]));
}

TEST_CASE("candidate instants: the real zeros of the event polynomials, merged with their causes", "[motion]") {
  relpos::detail::AK ak;
  std::vector<relpos::detail::Candidate> out;
  // (t^2 - 2)(t - 1) and (t - 1)(t + 3) on [-5, 5]: -3, -sqrt 2, 1 (both causes), sqrt 2.
  relpos::detail::add_zeros(ak, z_poly({2, -2, -1, 1}), 1u, Q(-5), Q(5), out);
  relpos::detail::add_zeros(ak, z_poly({-3, 2, 1}), 2u, Q(-5), Q(5), out);
  REQUIRE(out.size() == 4);
  CHECK(out[0].exact == std::optional<Rational>(Q(-3)));
  CHECK(out[0].causes == 2u);
  CHECK(!out[1].exact);
  CHECK(relpos::detail::instant_of(out[1]).compare(Q(-1414, 1000)) < 0);
  CHECK(relpos::detail::instant_of(out[1]).compare(Q(-1415, 1000)) > 0);
  CHECK(out[2].exact == std::optional<Rational>(Q(1)));
  CHECK(out[2].causes == 3u);
  CHECK(out[3].causes == 1u);
  CHECK(out[3].minimal_coefficients == std::vector<Integer>{Integer(-2), Integer(0), Integer(1)});
  // Outside [lo, hi] nothing is added.
  relpos::detail::add_zeros(ak, z_poly({-100, 1}), 4u, Q(-5), Q(5), out);
  CHECK(out.size() == 4);
  // The samples between consecutive instants lie strictly between them.
  for (std::size_t i = 0; i + 1 < out.size(); ++i) {
    const Rational x = relpos::detail::rational_between(out[i].t, out[i + 1].t);
    CHECK(relpos::detail::instant_of(out[i]).compare(x) < 0);
    CHECK(relpos::detail::instant_of(out[i + 1]).compare(x) > 0);
  }
}

TEST_CASE("sign at an algebraic instant: sign (r + m q)(t*) = sign r(t*) for m(t*) = 0", "[motion][random]") {
  // t* = sqrt(k) for k not a square, the positive root of m = t^2 - k; r = a + b t has the sign of
  // a + b sqrt(k), known in closed form (the signs of a and b, and of a^2 - b^2 k when they differ).
  std::mt19937_64 rng(20261128);
  std::uniform_int_distribution<long> small(-40, 40);
  relpos::detail::AK ak;
  int zeros = 0;
  for (long k : {2L, 3L, 5L, 1000003L}) {
    std::vector<relpos::detail::Candidate> cands;
    relpos::detail::add_zeros(ak, z_poly({-k, 0, 1}), 1u, Q(0), Q(k), cands);
    REQUIRE(cands.size() == 1);
    const PolyZ m = z_poly({-k, 0, 1});
    for (int trial = 0; trial < 150; ++trial) {
      const long a = trial % 50 == 0 ? 0 : small(rng), b = trial % 25 == 0 ? 0 : small(rng);
      const int sa = a > 0 ? 1 : (a < 0 ? -1 : 0), sb = b > 0 ? 1 : (b < 0 ? -1 : 0);
      const long d = a * a - b * b * k;
      const int want = sb == 0 ? sa : (sa == 0 || sa == sb ? sb : sa * (d > 0 ? 1 : (d < 0 ? -1 : 0)));
      PolyZ q = z_poly({small(rng), small(rng), small(rng)});
      if (trial % 5 == 0) q = q * q * q;  // large multiples of m
      const PolyZ r = z_poly({a, b});
      CAPTURE(k, a, b);
      CHECK(relpos::detail::sign_at(ak, r + m * q, cands[0]) == want);
      CHECK(relpos::detail::sign_at(ak, m * q, cands[0]) == 0);
      zeros += want == 0;
    }
  }
  CHECK(zeros > 0);  // a = b = 0 comes up
}
