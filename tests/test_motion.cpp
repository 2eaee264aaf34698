// motion.hpp, polynomial_motion.hpp, algebraic_real.hpp: positions along polynomial motions
// (math.md §7). Every expected instant is known by construction (see each case); every
// timeline is cross-checked against relpos::classify at dense rational samples, and the method used
// at irrational instants (subresultants) against classify at rational instants.
#include <gmp.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <random>
#include <relpos/classify.hpp>
#include <relpos/error.hpp>
#include <relpos/interrupt.hpp>
#include <relpos/motion.hpp>
#include <string>
#include <thread>
#include <vector>

#include "motion/polynomial_motion.hpp"
#include "motion/subresultant_position.hpp"
#include "support/printers.hpp"
#include "support/scale.hpp"

using relpos::AlgebraicReal;
using relpos::Ellipsoid;
using relpos::FirstContact;
using relpos::Integer;
using relpos::Paraboloid;
using relpos::Position;
using relpos::RigidMotion;
using relpos::Timeline;
using relpos::TimePolynomial;
using relpos::Vector3;

namespace {

using Rational = relpos::Rational;
Rational q(const char* text) { return relpos::parse_rational(text); }

TimePolynomial poly(std::initializer_list<const char*> coefficients) {
  TimePolynomial p;
  for (const char* c : coefficients) p.push_back(q(c));
  return p;
}

Paraboloid standard(const char* a, const char* b) {
  const Rational z(0);
  return Paraboloid::standard({z, z, z}, q(a), q(b));
}

Ellipsoid sphere_at_origin(const char* r) {
  const Rational z(0);
  return Ellipsoid::sphere({z, z, z}, q(r));
}

RigidMotion translation(TimePolynomial x, TimePolynomial y, TimePolynomial z) {
  return RigidMotion::translating({std::move(x), std::move(y), std::move(z)});
}

/// The value of an integer polynomial at sqrt(v) (v rational > 0, not a square) is A + B sqrt(v);
/// it is zero iff A = B = 0. Exact check that a reported polynomial vanishes at sqrt(v).
bool vanishes_at_sqrt(const std::vector<Integer>& p, const Rational& v) {
  Rational a(0), b(0), pw(1);  // pw = v^(i/2) for even i, v^((i-1)/2) for odd i
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (i % 2 == 0) {
      if (i > 0) pw *= v;
      a += Rational(p[i]) * pw;
    } else {
      b += Rational(p[i]) * pw;
    }
  }
  return a == 0 && b == 0;
}

/// decimals(digits) of an instant that should be sqrt(v): correct rounding checked exactly,
/// (D - u/2)^2 < v < (D + u/2)^2 with u one unit of the last digit (D > u/2 here).
void check_sqrt_decimals(const AlgebraicReal& x, const Rational& v, int digits) {
  INFO("instant expected at sqrt(" << relpos::to_string(v) << ")");
  REQUIRE(!x.is_rational());
  CHECK(vanishes_at_sqrt(x.polynomial(), v));
  CHECK(x.lower() * x.lower() < v);
  CHECK(v < x.upper() * x.upper());
  const std::string d = x.decimals(digits);
  INFO("decimals " << d);
  REQUIRE(d.find('e') == std::string::npos);
  const Rational value = relpos::parse_rational(d);
  std::size_t point = d.find('.');
  const long frac = point == std::string::npos ? 0 : static_cast<long>(d.size() - point - 1);
  // Significant digits: all digits of d minus leading zeros (d has no trailing zeros).
  std::string digits_only;
  for (char c : d)
    if (c >= '0' && c <= '9') digits_only += c;
  const std::size_t first = digits_only.find_first_not_of('0');
  CHECK(static_cast<int>(digits_only.size() - first) <= digits);
  // One unit of the digits-th significant digit: 10^(intdigits - digits).
  const long int_digits = static_cast<long>(point == std::string::npos ? d.size() : point);
  const long exponent = int_digits - digits;  // value of the last significant place
  Rational unit(1);
  for (long i = 0; i < (exponent < 0 ? -exponent : exponent); ++i) unit = exponent < 0 ? unit / 10 : unit * 10;
  (void)frac;
  const Rational lo = value - unit / 2, hi = value + unit / 2;
  CHECK(lo > 0);
  CHECK(lo * lo < v);
  CHECK(v < hi * hi);
}

/// sqrt(2) to `digits` significant digits, rounded to nearest, from GMP's integer square root
/// (independent of relpos): floor(2 sqrt(2) 10^(digits-1)), then round half up.
std::string sqrt2_decimals(int digits) {
  mpz_t n, r;
  mpz_init(n);
  mpz_init(r);
  mpz_ui_pow_ui(n, 10, static_cast<unsigned long>(2 * (digits - 1)));
  mpz_mul_ui(n, n, 8);  // (2 sqrt 2 * 10^(digits-1))^2 = 8 * 10^(2(digits-1))
  mpz_sqrt(r, n);       // floor(2x), x = sqrt(2) 10^(digits-1)
  mpz_add_ui(r, r, 1);
  mpz_fdiv_q_ui(r, r, 2);  // floor(x + 1/2) = floor((floor(2x) + 1) / 2)
  char* s = mpz_get_str(nullptr, 10, r);
  std::string digits_str(s);
  void (*freefunc)(void*, size_t);
  mp_get_memory_functions(nullptr, nullptr, &freefunc);
  freefunc(s, std::strlen(s) + 1);
  mpz_clear(n);
  mpz_clear(r);
  std::string out = digits_str.substr(0, 1) + "." + digits_str.substr(1);
  while (out.back() == '0') out.pop_back();
  return out;
}

/// Positions of the timeline's spans, in order.
std::vector<Position> span_positions(const Timeline& tl) {
  std::vector<Position> out;
  for (const auto& s : tl.spans()) out.push_back(s.position);
  return out;
}

/// The instant of the timeline where the position is `pos`, the k-th such (0-based).
const relpos::MotionInstant& instant_with(const Timeline& tl, Position pos, int k = 0) {
  for (const auto& inst : tl.instants)
    if (inst.position == pos && k-- == 0) return inst;
  FAIL("no instant with position " << relpos::to_string(pos));
  return tl.instants.front();
}

/// Dense cross-check: classify at `n` evenly spaced and `n` random rational times; each answer must
/// be the timeline's position there (so no sampled change is missed), and every rational instant
/// and interval sample must agree with classify. Prints its seed.
void check_against_sampling(const Timeline& tl, const Ellipsoid& e0, const RigidMotion& m, const Paraboloid& p, int n,
                            unsigned seed) {
  INFO("sampling seed " << seed);
  std::mt19937 rng(seed);
  std::vector<Rational> ts;
  const Rational span = tl.t1 - tl.t0;
  for (int k = 0; k <= n; ++k) ts.push_back(tl.t0 + span * Rational(k, n));
  std::uniform_int_distribution<int> num(0, 1000000);
  for (int k = 0; k < n; ++k) ts.push_back(tl.t0 + span * Rational(num(rng), 1000000));
  for (const auto& t : ts) {
    const Position want =
        relpos::classify(relpos::detail::placed_ellipsoid(e0, m, t), p, relpos::Evidence::Minimal).verdict.position;
    INFO("t = " << relpos::to_string(t));
    CHECK(tl.position_at(t) == want);
  }
  for (std::size_t i = 0; i < tl.intervals.size(); ++i) {
    CHECK(tl.instants[i].time.compare(tl.intervals[i].sample) < 0);
    CHECK(tl.instants[i + 1].time.compare(tl.intervals[i].sample) > 0);
  }
  for (const auto& inst : tl.instants) {
    CHECK(inst.how.find("inconsistent") == std::string::npos);
    if (!inst.time.is_rational()) continue;
    const auto c = relpos::classify(relpos::detail::placed_ellipsoid(e0, m, *inst.time.exact()), p);
    CHECK(inst.position == c.verdict.position);
  }
}

/// The first contact read off the timeline must be first_contact's answer.
void check_first_contact_consistent(const Timeline& tl, const FirstContact& fc) {
  if (tl.instants.front().position != Position::E) {
    CHECK(fc.kind == FirstContact::Kind::NotExteriorAtStart);
    CHECK(fc.position == tl.instants.front().position);
    return;
  }
  for (std::size_t i = 1; i < tl.instants.size(); ++i) {
    REQUIRE(tl.intervals[i - 1].position == Position::E);
    if (tl.instants[i].position != Position::E) {
      REQUIRE(fc.kind == FirstContact::Kind::Contact);
      CHECK(fc.position == tl.instants[i].position);
      CHECK(fc.time->decimals(40) == tl.instants[i].time.decimals(40));
      return;
    }
  }
  CHECK(fc.kind == FirstContact::Kind::None);
}

/// Every instant of the timeline is a limit of both neighbouring positions; smallness everywhere as
/// expected (a translation never changes it), when given.
void check_closure_and_size(const Timeline& tl, std::optional<bool> expect_small) {
  auto in_closure = [](Position at, Position n) {
    switch (n) {
      case Position::E:
        return at == Position::E || at == Position::TE;
      case Position::I:
        return at == Position::I || at == Position::TI;
      case Position::C:
        return at == Position::C || at == Position::TE || at == Position::TI;
      default:
        return at == n;
    }
  };
  for (std::size_t i = 0; i < tl.instants.size(); ++i) {
    const auto& inst = tl.instants[i];
    INFO("instant " << i << " ~ " << inst.time.decimals(12) << ": " << inst.how);
    if (i > 0) CHECK(in_closure(inst.position, tl.intervals[i - 1].position));
    if (i < tl.intervals.size()) CHECK(in_closure(inst.position, tl.intervals[i].position));
    if (expect_small) CHECK(inst.small == *expect_small);
  }
  if (expect_small)
    for (const auto& iv : tl.intervals) CHECK(iv.small == *expect_small);
}

/// The irrational instants of the timeline that change nothing (same position as both neighbours).
int quiet_irrational_instants(const Timeline& tl) {
  int n = 0;
  for (std::size_t i = 1; i + 1 < tl.instants.size(); ++i)
    if (!tl.instants[i].time.is_rational() && tl.instants[i].position == tl.intervals[i - 1].position &&
        tl.instants[i].position == tl.intervals[i].position)
      ++n;
  return n;
}

}  // namespace

// ------------------------------------------------------------------------------------------------

TEST_CASE("AlgebraicReal: sqrt(2), rationals, exact comparison and correct rounding", "[motion][algebraic]") {
  const auto r2 = AlgebraicReal::root({Integer(-2), Integer(0), Integer(1)}, Rational(1), Rational(2));
  CHECK(!r2.is_rational());
  CHECK(r2.decimals(30) == sqrt2_decimals(30));
  CHECK(r2.decimals(1) == "1");
  CHECK(r2.decimals(2) == "1.4");
  CHECK(r2.decimals(100) == sqrt2_decimals(100));
  CHECK(r2.compare(q("1.4142")) == 1);
  CHECK(r2.compare(q("1.4143")) == -1);
  CHECK(r2.to_double() == Approx(1.4142135623730951).epsilon(1e-15));
  check_sqrt_decimals(r2, Rational(2), 45);
  auto copy = r2;
  copy.refine(q("1/1000000"));
  CHECK(copy.upper() - copy.lower() <= q("1/1000000"));
  CHECK(copy.decimals(30) == r2.decimals(30));

  const auto third = AlgebraicReal::rational(q("1/3"));
  CHECK(third.is_rational());
  CHECK(third.decimals(5) == "0.33333");
  CHECK(third.compare(q("1/3")) == 0);
  CHECK(third.polynomial() == std::vector<Integer>{Integer(-1), Integer(3)});
  // A bisection midpoint that is the root makes it rational: 1/2 is the root of 2t - 1 in (0, 1).
  auto half = AlgebraicReal::root({Integer(-1), Integer(2)}, Rational(0), Rational(1));
  half.refine(q("1/4"));
  CHECK(half.is_rational());
  CHECK(*half.exact() == q("1/2"));
  // Rounding near a boundary: 0.5 + 10^-20 * sqrt(2)... here the root of t^2 - t - 1 (golden ratio).
  const auto phi = AlgebraicReal::root({Integer(-1), Integer(-1), Integer(1)}, Rational(1), Rational(2));
  CHECK(phi.decimals(20) == "1.6180339887498948482");
  CHECK_THROWS_AS(AlgebraicReal::root({Integer(-2), Integer(0), Integer(1)}, Rational(2), Rational(3)),
                  std::invalid_argument);
  CHECK(relpos::polynomial_text({Integer(-2), Integer(0), Integer(1)}) == "t^2 - 2");
}

TEST_CASE("AlgebraicReal: exact comparison of two algebraic reals", "[motion][algebraic]") {
  const std::vector<Integer> two{Integer(-2), Integer(0), Integer(1)};  // t^2 - 2
  const auto a = AlgebraicReal::root(two, Rational(1), Rational(2));
  // The same number from other isolating intervals, overlapping a's or not, and from a multiple of
  // its polynomial given as irreducible (not primitive): equal, whichever side compares.
  const auto b = AlgebraicReal::root(two, q("1414/1000"), q("3"));
  auto c = AlgebraicReal::root({Integer(-6), Integer(0), Integer(3)}, q("7/5"), q("3/2"), /*irreducible=*/true);
  c.refine(q("1/1000000"));
  const std::vector<const AlgebraicReal*> same{&a, &b, &c};
  for (const AlgebraicReal* x : same)
    for (const AlgebraicReal* y : same) CHECK(x->compare(*y) == 0);
  // Its conjugate, another root of the same polynomial, and numbers of other polynomials nearby.
  const auto minus = AlgebraicReal::root(two, Rational(-2), Rational(-1));
  CHECK(a.compare(minus) == 1);
  CHECK(minus.compare(a) == -1);
  const auto r3 = AlgebraicReal::root({Integer(-3), Integer(0), Integer(1)}, Rational(1), Rational(2));  // sqrt 3
  CHECK(a.compare(r3) == -1);
  CHECK(r3.compare(b) == 1);
  // (t^2 - 2)(10^12 t - 1414213562373) has roots 1.414213562373 and sqrt 2, 10^-13 apart: the
  // irreducible factors differ, the intervals are bisected until they separate the numbers.
  const auto near = AlgebraicReal::rational(q("1414213562373/1000000000000"));
  const auto root_near = AlgebraicReal::root({Integer(-1414213562373), Integer(1000000000000)}, q("1"), q("2"));
  CHECK(a.compare(near) == 1);
  CHECK(near.compare(a) == -1);
  CHECK(root_near.compare(near) == 0);
  // sqrt(2 + 10^-20), 3.5 10^-21 above sqrt 2: another irreducible polynomial of the same degree.
  const auto close =
      AlgebraicReal::root({-q("200000000000000000001").numerator(), Integer(0), q("100000000000000000000").numerator()},
                          Rational(1), Rational(2));
  CHECK(a.compare(close) == -1);
  CHECK(close.compare(b) == 1);
  const auto phi = AlgebraicReal::root({Integer(-1), Integer(-1), Integer(1)}, Rational(1), Rational(2));
  CHECK(a.compare(phi) == -1);
  CHECK(phi.compare(a) == 1);
  CHECK(phi.compare(AlgebraicReal::rational(q("1618/1000"))) == 1);
}

TEST_CASE("motion: an Interrupt stops first_contact and timeline, cancelled or past its budget",
          "[motion][interrupt]") {
  // The sphere rising through the vertex of z = x^2 + y^2 / 4 (first contact at sqrt 2).
  const Paraboloid p = standard("1", "2");
  const Ellipsoid e0 = sphere_at_origin("1/4");
  const RigidMotion m = translation(poly({}), poly({}), poly({"-9/4", "0", "1"}));
  relpos::Interrupt never;
  CHECK(relpos::first_contact(e0, m, p, q("0"), q("2"), &never).kind == FirstContact::Kind::Contact);
  relpos::Interrupt cancelled;
  cancelled.cancel();
  try {
    (void)relpos::timeline(e0, m, p, q("0"), q("2"), &cancelled);
    FAIL("not stopped");
  } catch (const relpos::Interrupted& err) {
    CHECK(!err.budget());
  }
  CHECK_THROWS_AS(relpos::first_contact(e0, m, p, q("0"), q("2"), &cancelled), relpos::Interrupted);
  const relpos::Interrupt spent(std::chrono::steady_clock::duration::zero());
  try {
    (void)relpos::timeline(e0, m, p, q("0"), q("2"), &spent);
    FAIL("not stopped");
  } catch (const relpos::Interrupted& err) {
    CHECK(err.budget());
  }
  // Cancelled from another thread while it runs: a motion of degree 12 that takes seconds stops.
  RigidMotion slow = translation(poly({"0", "1/3"}), poly({}), poly({"-1/2", "0", "1"}));
  slow.rotation = std::array<TimePolynomial, 4>{poly({"1", "0", "0", "0", "0", "0", "0", "0", "0", "0", "0", "0", "1"}),
                                                poly({"0", "1"}), poly({"0", "0", "1"}), poly({"0", "0", "0", "1"})};
  const Ellipsoid body = Ellipsoid::from_axes({q("0"), q("0"), q("1")}, {q("1/4"), q("1/5"), q("1/7")},
                                              relpos::Quaternion{q("1"), q("0"), q("0"), q("0")});
  relpos::Interrupt later;
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    later.cancel();
  });
  CHECK_THROWS_AS(relpos::timeline(body, slow, p, q("0"), q("1"), &later), relpos::Interrupted);
  canceller.join();
}

TEST_CASE("polynomial motion: E(t) is N^2 times the placed ellipsoid; pivots; validation", "[motion][polynomial]") {
  const Ellipsoid e0 = Ellipsoid::from_axes({q("1"), q("-2"), q("1/3")}, {q("1/2"), q("1"), q("1/4")},
                                            relpos::Quaternion{q("1"), q("2"), q("0"), q("-1")});
  RigidMotion m;
  m.translation = {poly({"1", "2"}), poly({"0", "0", "-1/3"}), poly({"5/7"})};
  m.rotation = std::array<TimePolynomial, 4>{poly({"1", "1"}), poly({"0", "2"}), poly({"-1", "0", "1"}), poly({"3"})};
  for (auto pivot : {relpos::Pivot::Origin, relpos::Pivot::Centre}) {
    m.pivot = pivot;
    const auto em = relpos::moving_ellipsoid_matrix(e0, m);
    for (const char* tt : {"0", "1/2", "-3", "7/5"}) {
      const Rational t = q(tt);
      const Ellipsoid placed = relpos::detail::placed_ellipsoid(e0, m, t);
      Rational n(0);
      for (const auto& c : *m.rotation) n += relpos::evaluate(c, t) * relpos::evaluate(c, t);
      for (std::size_t i = 0; i < 16; ++i) CHECK(relpos::evaluate(em[i], t) == placed.matrix().a[i] * n * n);
      // The placed ellipsoid is the image of e0: centre R (c0 - p) + p + c(t).
      const auto r = relpos::rotation_from_quaternion(
          {relpos::evaluate((*m.rotation)[0], t), relpos::evaluate((*m.rotation)[1], t),
           relpos::evaluate((*m.rotation)[2], t), relpos::evaluate((*m.rotation)[3], t)});
      const auto c0 = relpos::centre_of(e0), pv = relpos::detail::pivot_of(e0, m), c1 = relpos::centre_of(placed);
      for (int i = 0; i < 3; ++i) {
        Rational x = pv[static_cast<std::size_t>(i)] + relpos::evaluate(m.translation[static_cast<std::size_t>(i)], t);
        for (int j = 0; j < 3; ++j) x += r(i, j) * (c0[static_cast<std::size_t>(j)] - pv[static_cast<std::size_t>(j)]);
        CHECK(c1[static_cast<std::size_t>(i)] == x);
      }
    }
  }
  // quaternion_matrix is rotation_from_quaternion times |q|^2.
  const auto qm = relpos::quaternion_matrix<Rational>(q("1"), q("2"), q("-3"), q("1/2"));
  const auto rq = relpos::rotation_from_quaternion({q("1"), q("2"), q("-3"), q("1/2")});
  for (int i = 0; i < 9; ++i) CHECK(qm[static_cast<std::size_t>(i)] == rq.a[static_cast<std::size_t>(i)] * q("57/4"));

  RigidMotion bad;
  bad.rotation = std::array<TimePolynomial, 4>{poly({"-1", "1"}), poly({"1", "-1"}), poly({}), poly({"2", "-2"})};
  CHECK_THROWS_AS(relpos::detail::validate_motion(bad, q("0"), q("2")), relpos::InputError);  // q(1) = 0
  CHECK_NOTHROW(relpos::detail::validate_motion(bad, q("3/2"), q("2")));
  CHECK_THROWS_AS(relpos::detail::validate_motion(bad, q("2"), q("1")), relpos::InputError);
  RigidMotion zero;
  zero.rotation = std::array<TimePolynomial, 4>{};
  CHECK_THROWS_AS(relpos::detail::validate_motion(zero, q("0"), q("1")), relpos::InputError);
  CHECK_THROWS_AS(relpos::timeline(e0, bad, standard("1", "2"), q("0"), q("2")), relpos::InputError);
}

TEST_CASE("rational first contact: a sphere moving horizontally through the wall of z = x^2 + y^2",
          "[motion][translation]") {
  // The point (2/3, 0, 4/9) of z = x^2 has outward unit normal (4/5, 0, -3/5) (|(4/3, 0, -1)| = 5/3);
  // the sphere of radius 1/4 touching it from outside is centred at (2/3 + 1/5, 0, 4/9 - 3/20) =
  // (13/15, 0, 53/180). Moving along x = 2 - t it touches at t = 2 - 13/15 = 17/15, passes the axis
  // at t = 2 (inside: the distance from (0, 0, 53/180) to the cup is 53/180 > 1/4) and leaves by
  // symmetry at t = 2 + 13/15 = 43/15.
  const Paraboloid p = standard("1", "1");
  const Ellipsoid e0 = sphere_at_origin("1/4");
  const RigidMotion m = translation(poly({"2", "-1"}), poly({}), poly({"53/180"}));
  const FirstContact fc = relpos::first_contact(e0, m, p, q("0"), q("4"));
  REQUIRE(fc.kind == FirstContact::Kind::Contact);
  CHECK(fc.start_position == Position::E);
  REQUIRE(fc.time->is_rational());
  CHECK(*fc.time->exact() == q("17/15"));
  CHECK(fc.position == Position::TE);
  CHECK(fc.time->decimals(12) == "1.13333333333");

  const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("4"));
  CHECK(!tl.discriminant_identically_zero);
  CHECK(span_positions(tl) == std::vector<Position>{Position::E, Position::TE, Position::C, Position::TI, Position::I,
                                                    Position::TI, Position::C, Position::TE, Position::E});
  CHECK(*instant_with(tl, Position::TE, 0).time.exact() == q("17/15"));
  CHECK(*instant_with(tl, Position::TE, 1).time.exact() == q("43/15"));
  // Inner tangency: the roots of 4665600 t^4 - 37324800 t^3 + 111865680 t^2 - 148864320 t + 74214671
  // (the factor of Disc f, derived independently with sympy), symmetric about t = 2.
  CHECK(instant_with(tl, Position::TI, 0).time.decimals(20) == "1.8459066100636815526");
  CHECK(instant_with(tl, Position::TI, 1).time.decimals(20) == "2.1540933899363184474");
  // t = 2: the centre is on the axis; -1 is a double root of f and of s (special root), no change.
  bool saw_two = false;
  for (const auto& inst : tl.instants)
    if (inst.time.is_rational() && *inst.time.exact() == 2) {
      saw_two = true;
      CHECK(inst.position == Position::I);
      CHECK((inst.causes & relpos::kCauseDiscriminant));
    }
  CHECK(saw_two);
  // A translation keeps det E and M, hence s and rho: no smallness instant, and the same exact rho
  // (here 4 r^2 / a^4 = 1/4) wherever classify() looks.
  for (const auto& inst : tl.instants) CHECK(!(inst.causes & relpos::kCauseSmallness));
  for (const char* t : {"0", "1", "17/15", "2", "7/2"}) {
    const auto c = relpos::classify(relpos::detail::placed_ellipsoid(e0, m, q(t)), p);
    REQUIRE(c.rho.has_value());
    CHECK(*c.rho == q("1/4"));
  }
  const auto changes = tl.changes();
  REQUIRE(changes.size() == 4);
  CHECK(*changes[0].before == Position::E);
  CHECK(changes[0].at == Position::TE);
  CHECK(*changes[0].after == Position::C);
  check_against_sampling(tl, e0, m, p, 80, 11);
  check_first_contact_consistent(tl, fc);
  // The subresultant method agrees with classify at the rational instants where f is not square-free.
  for (const char* t : {"17/15", "2", "43/15"})
    CHECK(relpos::position_by_subresultants(e0, m, p, q(t)) ==
          relpos::classify(relpos::detail::placed_ellipsoid(e0, m, q(t)), p).verdict.position);
}

TEST_CASE("first contact at sqrt(2): a sphere rising along the axis of z = x^2 + y^2/4", "[motion][irrational]") {
  // Centre (0, 0, t^2 - 9/4), radius 1/4: the top touches the vertex when t^2 - 9/4 = -1/4, t = sqrt(2)
  // (TE); the bottom reaches the vertex from inside when t^2 - 9/4 = 1/4, t = sqrt(5/2) (TI, the
  // sphere is small: 2r = 1/2 <= a^2 = 1). In between -1 = -a^2 and -4 = -b^2 become double roots
  // of f (the paper's special roots, z = r^2/a^2 + a^2/4 = 5/16 and r^2/b^2 + b^2/4 = 65/64) at
  // t = sqrt(41)/4 and sqrt(209)/8: Disc f = 0 there, but nothing touches.
  const Paraboloid p = standard("1", "2");
  const Ellipsoid e0 = sphere_at_origin("1/4");
  const RigidMotion m = translation(poly({}), poly({}), poly({"-9/4", "0", "1"}));
  const FirstContact fc = relpos::first_contact(e0, m, p, q("0"), q("2"));
  REQUIRE(fc.kind == FirstContact::Kind::Contact);
  CHECK(fc.position == Position::TE);
  const AlgebraicReal& t = *fc.time;
  CHECK(t.lower() * t.lower() < 2);
  CHECK(2 < t.upper() * t.upper());
  CHECK(vanishes_at_sqrt(t.polynomial(), Rational(2)));
  CHECK(t.polynomial() == std::vector<Integer>{Integer(-2), Integer(0), Integer(1)});  // minimal polynomial
  CHECK(t.decimals(30) == sqrt2_decimals(30));
  check_sqrt_decimals(t, Rational(2), 60);

  const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("2"));
  CHECK(span_positions(tl) == std::vector<Position>{Position::E, Position::TE, Position::C, Position::TI, Position::I});
  check_sqrt_decimals(instant_with(tl, Position::TE).time, Rational(2), 30);
  check_sqrt_decimals(instant_with(tl, Position::TI).time, q("5/2"), 30);
  // The special instants: position I on both sides and at the instant.
  check_sqrt_decimals(instant_with(tl, Position::I, 0).time, q("41/16"), 25);
  check_sqrt_decimals(instant_with(tl, Position::I, 1).time, q("209/64"), 25);
  CHECK(tl.instants.size() == 6);  // t0, sqrt 2, sqrt(5/2), sqrt(41)/4, sqrt(209)/8, t1
  check_against_sampling(tl, e0, m, p, 80, 12);
  check_first_contact_consistent(tl, fc);
}

/// E, then TE at the single instant sqrt(2), then E again: one change, a graze.
void check_grazes_at_sqrt2(const Timeline& tl) {
  CHECK(span_positions(tl) == std::vector<Position>{Position::E, Position::TE, Position::E});
  const auto changes = tl.changes();
  REQUIRE(changes.size() == 1);
  CHECK(*changes[0].before == Position::E);
  CHECK(changes[0].at == Position::TE);
  CHECK(*changes[0].after == Position::E);
  check_sqrt_decimals(changes[0].time, Rational(2), 30);
}

TEST_CASE("grazing paths: E -> TE at one instant -> E", "[motion][grazing]") {
  // A sphere of radius 1/4 moving in the plane z = -1/4 below the vertex of z = x^2 + y^2/4 lies in
  // z <= 0; it meets the paraboloid (z >= 0) only when its top (x, 0, 0) is the vertex: x = 0.
  const Paraboloid p = standard("1", "2");
  const Ellipsoid e0 = sphere_at_origin("1/4");
  SECTION("at a rational instant") {
    const RigidMotion m = translation(poly({"-1", "1"}), poly({}), poly({"-1/4"}));
    const FirstContact fc = relpos::first_contact(e0, m, p, q("0"), q("2"));
    REQUIRE(fc.kind == FirstContact::Kind::Contact);
    CHECK(*fc.time->exact() == 1);
    CHECK(fc.position == Position::TE);
    const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("2"));
    CHECK(span_positions(tl) == std::vector<Position>{Position::E, Position::TE, Position::E});
    check_against_sampling(tl, e0, m, p, 60, 13);
    CHECK(relpos::position_by_subresultants(e0, m, p, q("1")) == Position::TE);
  }
  SECTION("at sqrt(2)") {
    const RigidMotion m = translation(poly({"-2", "0", "1"}), poly({}), poly({"-1/4"}));
    const FirstContact fc = relpos::first_contact(e0, m, p, q("0"), q("2"));
    REQUIRE(fc.kind == FirstContact::Kind::Contact);
    CHECK(fc.position == Position::TE);
    CHECK(fc.time->decimals(30) == sqrt2_decimals(30));
    const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("2"));
    check_grazes_at_sqrt2(tl);
    // Disc f has other real zeros on [0, 2] (roots of f merging away from contact): E on both sides.
    CHECK(tl.instants.size() > 3);
    check_against_sampling(tl, e0, m, p, 60, 14);
    check_first_contact_consistent(tl, fc);
  }
}

TEST_CASE("C -> TI at one instant -> C: a sphere sliding through the inner tangency at the vertex",
          "[motion][grazing]") {
  // Centre (t^2 - 2, 0, 1/4), radius 1/4: at t = sqrt(2) it is on the axis, tangent from inside at
  // the vertex (2r = 1/2 <= a^2); moved sideways its bottom point (x, 0, 0) is outside the cup, so
  // it crosses on both sides. (Neighbours C | C do not imply C at the instant.)
  for (const char* b : {"2", "1"}) {
    INFO("paraboloid x^2 + y^2/b^2, b = " << b);
    const Paraboloid p = standard("1", b);
    const Ellipsoid e0 = sphere_at_origin("1/4");
    const RigidMotion m = translation(poly({"-2", "0", "1"}), poly({}), poly({"1/4"}));
    const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("2"));
    const auto& ti = instant_with(tl, Position::TI);
    check_sqrt_decimals(ti.time, Rational(2), 30);
    const auto spans = span_positions(tl);
    REQUIRE(spans.size() == 7);
    CHECK(spans == std::vector<Position>{Position::E, Position::TE, Position::C, Position::TI, Position::C,
                                         Position::TE, Position::E});
    check_against_sampling(tl, e0, m, p, 60, 15);
    // The same configuration at a rational instant (centre on the axis at t = 1 of x = t - 1).
    const RigidMotion lin = translation(poly({"-1", "1"}), poly({}), poly({"1/4"}));
    CHECK(relpos::position_by_subresultants(e0, lin, p, q("1")) == Position::TI);
    CHECK(relpos::classify(relpos::detail::placed_ellipsoid(e0, lin, q("1")), p).verdict.position == Position::TI);
  }
}

TEST_CASE("axis of a circular paraboloid: Disc f = 0 for every t, contact still found", "[motion][axis]") {
  // z = x^2 + y^2, sphere of radius 1/4 on the axis: -1 = -a^2 is a double root of f and of s at
  // every t (f = -(l + 1)^2 (4 l^2 + 4(4 z + 1) l + 1) / 16 up to scaling), so Disc f vanishes
  // identically; the square-free part of f carries the events. TE when the top reaches the vertex
  // (z = -1/4), TI when the bottom does (z = 1/4).
  const Paraboloid p = standard("1", "1");
  SECTION("rational instants") {
    const Ellipsoid e0 = sphere_at_origin("1/4");
    const RigidMotion m = translation(poly({}), poly({}), poly({"-5/4", "1"}));
    const FirstContact fc = relpos::first_contact(e0, m, p, q("0"), q("3"));
    REQUIRE(fc.kind == FirstContact::Kind::Contact);
    CHECK(*fc.time->exact() == 1);
    CHECK(fc.position == Position::TE);
    const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("3"));
    CHECK(tl.discriminant_identically_zero);
    CHECK(span_positions(tl) ==
          std::vector<Position>{Position::E, Position::TE, Position::C, Position::TI, Position::I});
    CHECK(*instant_with(tl, Position::TI).time.exact() == q("3/2"));
    check_against_sampling(tl, e0, m, p, 60, 16);
    // f is never square-free here: the subresultant method answers at every time; compare with classify.
    for (int k = 0; k <= 30; ++k) {
      const Rational t = Rational(k, 10);
      INFO("t = " << relpos::to_string(t));
      CHECK(relpos::position_by_subresultants(e0, m, p, t) ==
            relpos::classify(relpos::detail::placed_ellipsoid(e0, m, t), p).verdict.position);
    }
  }
  SECTION("irrational instants") {
    const Ellipsoid e0 = sphere_at_origin("1/4");
    const RigidMotion m = translation(poly({}), poly({}), poly({"-9/4", "0", "1"}));
    const FirstContact fc = relpos::first_contact(e0, m, p, q("0"), q("2"));
    REQUIRE(fc.kind == FirstContact::Kind::Contact);
    CHECK(fc.time->decimals(30) == sqrt2_decimals(30));
    const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("2"));
    CHECK(tl.discriminant_identically_zero);
    CHECK(span_positions(tl) ==
          std::vector<Position>{Position::E, Position::TE, Position::C, Position::TI, Position::I});
    check_sqrt_decimals(instant_with(tl, Position::TI).time, q("5/2"), 30);
    check_against_sampling(tl, e0, m, p, 60, 17);
    check_first_contact_consistent(tl, fc);
  }
  SECTION("r = a^2/2: a quadruple root of f at the inner tangency") {
    // Radius 1/2 (rho = 1, still small): f = -(l + 1)^2 (l^2 + 2(2z - 1) l + 1)/4 is -(l + 1)^4/4
    // at z = 1/2 (a tangency: multiplicity 4 in f, 2 in s). Centre z = t^2 - 3/2: TE at t = 1
    // (z = -1/2), TI at t = sqrt(2).
    const Ellipsoid e0 = sphere_at_origin("1/2");
    const RigidMotion m = translation(poly({}), poly({}), poly({"-3/2", "0", "1"}));
    const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("2"));
    CHECK(span_positions(tl) ==
          std::vector<Position>{Position::E, Position::TE, Position::C, Position::TI, Position::I});
    CHECK(*instant_with(tl, Position::TE).time.exact() == 1);
    check_sqrt_decimals(instant_with(tl, Position::TI).time, Rational(2), 30);
    check_against_sampling(tl, e0, m, p, 40, 18);
    const RigidMotion lin = translation(poly({}), poly({}), poly({"-1", "1"}));  // z = 1/2 at t = 3/2
    CHECK(relpos::position_by_subresultants(e0, lin, p, q("3/2")) == Position::TI);
    CHECK(relpos::classify(relpos::detail::placed_ellipsoid(e0, lin, q("3/2")), p).verdict.position == Position::TI);
  }
}

TEST_CASE("contact at t0 is a result, not an error", "[motion][start]") {
  const Paraboloid p = standard("1", "2");
  const Ellipsoid e0 = sphere_at_origin("1/4");
  const RigidMotion m = translation(poly({}), poly({}), poly({"-1/4", "1"}));  // top at the vertex at t = 0
  FirstContact fc = relpos::first_contact(e0, m, p, q("0"), q("1"));
  CHECK(fc.kind == FirstContact::Kind::NotExteriorAtStart);
  CHECK(fc.start_position == Position::TE);
  CHECK(fc.position == Position::TE);
  CHECK(*fc.time->exact() == 0);
  fc = relpos::first_contact(e0, m, p, q("1/8"), q("1"));
  CHECK(fc.kind == FirstContact::Kind::NotExteriorAtStart);
  CHECK(fc.start_position == Position::C);
  // A zero-length interval and a path that never touches.
  const Timeline point = relpos::timeline(e0, m, p, q("0"), q("0"));
  REQUIRE(point.instants.size() == 1);
  CHECK(point.intervals.empty());
  CHECK(point.instants[0].position == Position::TE);
  CHECK((point.instants[0].causes & relpos::kCauseStart));
  CHECK((point.instants[0].causes & relpos::kCauseEnd));
  const RigidMotion away = translation(poly({}), poly({}), poly({"-1", "-1"}));
  fc = relpos::first_contact(e0, away, p, q("0"), q("5"));
  CHECK(fc.kind == FirstContact::Kind::None);
  CHECK(!fc.time);
  const Timeline tl = relpos::timeline(e0, away, p, q("0"), q("5"));
  CHECK(span_positions(tl) == std::vector<Position>{Position::E});
  CHECK(tl.changes().empty());
}

TEST_CASE("a rotating ellipsoid touches the vertex when its long axis turns vertical", "[motion][rotation]") {
  // Semi-axes (1/2, 1, 1/4) along x, y, z, centred at (0, 0, -1), turned about the x axis by the
  // angle th with tan(th/2) = q_x/q_w. Its highest point is at height -1 + sqrt(sin^2 th + cos^2 th/16)
  // < 0 unless th = 90 degrees, when the long semi-axis 1 is vertical and the top is the vertex:
  // the only common point (the ellipsoid lies in z <= 0, the paraboloid in z >= 0). So E, TE at
  // the instant th = 90 degrees, E again.
  const Paraboloid p = standard("1", "2");
  const Rational z(0);
  const relpos::Quaternion id{Rational(1), z, z, z};
  const Ellipsoid body = Ellipsoid::from_axes({z, z, z}, {q("1/2"), q("1"), q("1/4")}, id);
  const Ellipsoid world = Ellipsoid::from_axes({z, z, q("-1")}, {q("1/2"), q("1"), q("1/4")}, id);
  SECTION("q(t) = (1, t, 0, 0): th = 90 degrees at t = 1") {
    RigidMotion m = translation(poly({}), poly({}), poly({"-1"}));
    m.rotation = std::array<TimePolynomial, 4>{poly({"1"}), poly({"0", "1"}), poly({}), poly({})};
    const FirstContact fc = relpos::first_contact(body, m, p, q("0"), q("2"));
    REQUIRE(fc.kind == FirstContact::Kind::Contact);
    CHECK(*fc.time->exact() == 1);
    CHECK(fc.position == Position::TE);
    const Timeline tl = relpos::timeline(body, m, p, q("0"), q("2"));
    CHECK(span_positions(tl) == std::vector<Position>{Position::E, Position::TE, Position::E});
    check_against_sampling(tl, body, m, p, 40, 19);
    CHECK(relpos::position_by_subresultants(body, m, p, q("1")) == Position::TE);
  }
  SECTION("q(t) = (1, t^2/2, 0, 0): th = 90 degrees at t = sqrt(2); body and world frames agree") {
    RigidMotion mb = translation(poly({}), poly({}), poly({"-1"}));
    mb.rotation = std::array<TimePolynomial, 4>{poly({"1"}), poly({"0", "0", "1/2"}), poly({}), poly({})};
    RigidMotion mw;
    mw.rotation = mb.rotation;
    mw.pivot = relpos::Pivot::Centre;
    const FirstContact fb = relpos::first_contact(body, mb, p, q("0"), q("2"));
    const FirstContact fw = relpos::first_contact(world, mw, p, q("0"), q("2"));
    REQUIRE(fb.kind == FirstContact::Kind::Contact);
    REQUIRE(fw.kind == FirstContact::Kind::Contact);
    CHECK(fb.position == Position::TE);
    CHECK(fb.time->decimals(30) == sqrt2_decimals(30));
    CHECK(fw.time->decimals(40) == fb.time->decimals(40));
    check_sqrt_decimals(*fb.time, Rational(2), 30);
    const Timeline tl = relpos::timeline(world, mw, p, q("0"), q("2"));
    CHECK(span_positions(tl) == std::vector<Position>{Position::E, Position::TE, Position::E});
    check_against_sampling(tl, world, mw, p, 40, 20);
    check_first_contact_consistent(tl, fw);
  }
}

TEST_CASE("a rotation can change smallness; spans without it are classified too", "[motion][rotation]") {
  // A long thin ellipsoid (semi-axes 1/10, 1/10, 3/4) inside z = x^2 + y^2/4 at height 2, turning
  // about the x axis. Upright, its curvature fits the cup; lying along y its size compared with the
  // cup changes rho; the timeline must report rho's crossings (smallness instants) and agree with
  // classify everywhere.
  const Paraboloid p = standard("1", "2");
  const Rational z(0);
  const relpos::Quaternion id{Rational(1), z, z, z};
  const Ellipsoid e0 = Ellipsoid::from_axes({z, z, z}, {q("1/10"), q("1/10"), q("3/4")}, id);
  RigidMotion m = translation(poly({}), poly({}), poly({"2"}));
  m.rotation = std::array<TimePolynomial, 4>{poly({"1"}), poly({"0", "1"}), poly({}), poly({})};
  const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("3"));
  bool smallness_instant = false, small_interval = false, large_interval = false;
  for (const auto& inst : tl.instants) smallness_instant = smallness_instant || (inst.causes & relpos::kCauseSmallness);
  for (const auto& iv : tl.intervals) (iv.small ? small_interval : large_interval) = true;
  CHECK(smallness_instant);
  CHECK(small_interval);
  CHECK(large_interval);
  // Every interval, small or not, carries classify's position at its sample (math.md §8).
  for (const auto& iv : tl.intervals) {
    INFO("interval sample t = " << relpos::to_string(iv.sample) << (iv.small ? " (small)" : " (not small)"));
    const Position want = relpos::classify(relpos::detail::placed_ellipsoid(e0, m, iv.sample), p).verdict.position;
    CHECK(iv.position == want);
  }
  // Irrational instants, small or not, are decided too (and checked against both neighbours);
  // rational ones are checked by check_against_sampling against classify.
  check_closure_and_size(tl, std::nullopt);
  check_against_sampling(tl, e0, m, p, 40, 21);
}

namespace {

/// Random bodies on random paths through a random paraboloid z = x^2/a^2 + y^2/b^2 (a, b dyadic in
/// [1, 2]): semi-axes axis_offset + a dyadic in [axis_lo, axis_hi], turned by an integer
/// quaternion; a straight path from `start` to `target` (dyadic boxes), parabolic every
/// `parabolic_every`-th path, turning about its centre every `turning_every`-th path.
struct RandomPaths {
  std::mt19937_64 rng;
  int axis_lo, axis_hi, axis_bits;
  Rational axis_offset;
  int start_xy, start_z_lo, start_z_hi, target_xy, target_z_lo, target_z_hi, curve;
  int parabolic_every, turning_every;

  Rational dyadic(int lo, int hi, int bits) {  // a random multiple of 2^-bits in [lo, hi]
    std::uniform_int_distribution<long> d(static_cast<long>(lo) * (1L << bits), static_cast<long>(hi) * (1L << bits));
    return Rational(d(rng), 1L << bits);
  }
  struct Path {
    Paraboloid p;
    Ellipsoid e0;
    RigidMotion m;
  };
  Path next(int k) {
    std::uniform_int_distribution<int> small(-2, 2);
    const Rational z(0);
    const Paraboloid p = Paraboloid::standard({z, z, z}, dyadic(1, 2, 2), dyadic(1, 2, 2));
    relpos::Quaternion rot{Rational(1), Rational(small(rng)), Rational(small(rng)), Rational(small(rng))};
    auto axis = [&] { return axis_offset + dyadic(axis_lo, axis_hi, axis_bits); };
    const Ellipsoid e0 = Ellipsoid::from_axes({z, z, z}, {axis(), axis(), axis()}, rot);
    RigidMotion m;
    const Vector3 start{dyadic(-start_xy, start_xy, 2), dyadic(-start_xy, start_xy, 2),
                        dyadic(start_z_lo, start_z_hi, 2)};
    const Vector3 target{dyadic(-target_xy, target_xy, 2), dyadic(-target_xy, target_xy, 2),
                         dyadic(target_z_lo, target_z_hi, 2)};
    for (std::size_t i = 0; i < 3; ++i) {
      m.translation[i] = {start[i], target[i] - start[i]};
      if (k % parabolic_every == parabolic_every - 1) m.translation[i].push_back(dyadic(-curve, curve, 1));
    }
    if (k % turning_every == turning_every - 1)
      m.rotation = std::array<TimePolynomial, 4>{poly({"1"}), poly({"0", "1"}), poly({}), poly({})};
    return {p, e0, m};
  }
};

/// The subresultant (instant) method equals classify() at every rational instant; returns the
/// number of irrational instants.
int check_rational_instants(const Timeline& tl, const Ellipsoid& e0, const RigidMotion& m, const Paraboloid& p) {
  int irrational = 0;
  for (const auto& inst : tl.instants) {
    if (!inst.time.is_rational()) {
      ++irrational;
      continue;
    }
    const Rational t = *inst.time.exact();
    const auto sub = relpos::position_by_subresultants(e0, m, p, t);
    if (sub) CHECK(*sub == relpos::classify(relpos::detail::placed_ellipsoid(e0, m, t), p).verdict.position);
  }
  return irrational;
}

}  // namespace

TEST_CASE("random paths: timelines agree with dense classification; both methods agree at rational instants",
          "[motion][random]") {
  // Random ellipsoids (small dyadic semi-axes, integer quaternions) on straight or parabolic paths
  // through a random paraboloid, and a few turning bodies. No answer is known in advance: the
  // timeline must agree with classify() everywhere it is sampled, first_contact with the timeline,
  // and the subresultant method with classify() at every rational instant.
  const std::uint64_t seed = 0x5EED1;
  CAPTURE(seed);
  RandomPaths gen{std::mt19937_64(seed), 0, 1, 3, q("1/8"), 2, -2, 0, 1, 1, 2, 1, 3, 4};
  int rational_instants = 0, irrational_instants = 0;
  for (int k = 0; k < 12; ++k) {
    CAPTURE(k);
    const auto [p, e0, m] = gen.next(k);
    const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("1"));
    check_against_sampling(tl, e0, m, p, 30, static_cast<unsigned>(seed + static_cast<unsigned>(k)));
    check_first_contact_consistent(tl, relpos::first_contact(e0, m, p, q("0"), q("1")));
    const int irrational = check_rational_instants(tl, e0, m, p);
    irrational_instants += irrational;
    rational_instants += static_cast<int>(tl.instants.size()) - irrational;
  }
  CHECK(irrational_instants > 0);
  CHECK(rational_instants >= 24);  // t0 and t1 of each path at least
}

// ------------------------------------------------------------------------------------------------
// Bodies that are not small (math.md §8): every instant is decided, irrational ones included
// (definiteness of l P + E(t*) at the roots of f, instant_position.hpp).

/// A timeline over [0, t1] whose instants respect the closure, that agrees with classify() at 40
/// samples, and whose first contact is TE at sqrt(2), as the timeline says.
void check_touches_first_at_sqrt2(const Timeline& tl, const Ellipsoid& e0, const RigidMotion& m, const Paraboloid& p,
                                  const Rational& t1, unsigned seed) {
  check_closure_and_size(tl, false);
  check_against_sampling(tl, e0, m, p, 40, seed);
  const FirstContact fc = relpos::first_contact(e0, m, p, q("0"), t1);
  REQUIRE(fc.kind == FirstContact::Kind::Contact);
  CHECK(fc.position == Position::TE);
  check_sqrt_decimals(*fc.time, Rational(2), 30);
  check_first_contact_consistent(tl, fc);
}

TEST_CASE("a big sphere on the axis: TE at sqrt(2), inner tangency along a circle or two points at sqrt(17)/2",
          "[motion][irrational][anysize]") {
  // Radius 1 (not small: 2r > a^2 = 1) centred at (0, 0, h), h = t^2 - 3. The top reaches the vertex
  // at h = -1 (t = sqrt 2, TE). Inside the cup the distance from (0, 0, h) to z = x^2 (the section
  // y = 0) is sqrt(h - 1/4) (nearest at x^2 = h - 1/2); for z = x^2 + y^2/4 the section x = 0 is
  // farther (sqrt(4h - 4) for h >= 2, else h^2 + ...), so the sphere becomes tangent from inside at
  // h = 5/4, t = sqrt(17)/2: along a circle for z = x^2 + y^2 (the hard case), at two points for
  // z = x^2 + y^2/4. E before, C between, I after.
  const Ellipsoid e0 = sphere_at_origin("1");
  const RigidMotion m = translation(poly({}), poly({}), poly({"-3", "0", "1"}));
  for (const char* b : {"1", "2"}) {
    INFO("paraboloid x^2 + y^2/b^2, b = " << b);
    const Paraboloid p = standard("1", b);
    const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("3"));
    CHECK(tl.discriminant_identically_zero == (std::string(b) == "1"));
    CHECK(span_positions(tl) ==
          std::vector<Position>{Position::E, Position::TE, Position::C, Position::TI, Position::I});
    check_sqrt_decimals(instant_with(tl, Position::TE).time, Rational(2), 30);
    check_sqrt_decimals(instant_with(tl, Position::TI).time, q("17/4"), 30);
    check_touches_first_at_sqrt2(tl, e0, m, p, q("3"), 31);
    // The same configurations at rational instants (h = t - 3): the instant method agrees with classify.
    const RigidMotion lin = translation(poly({}), poly({}), poly({"-3", "1"}));
    for (const char* t : {"2", "17/4"}) {
      const Position want = relpos::classify(relpos::detail::placed_ellipsoid(e0, lin, q(t)), p).verdict.position;
      CHECK(want == (std::string(t) == "2" ? Position::TE : Position::TI));
      CHECK(relpos::position_by_subresultants(e0, lin, p, q(t)) == want);
    }
  }
}

TEST_CASE("a big sphere moved sideways touches the wall from outside at sqrt(2)", "[motion][irrational][anysize]") {
  // z = x^2 + y^2: at (3/8, 0, 9/64) the outward unit normal is (3/5, 0, -4/5) (2x = 3/4, |(3/4, -1)| =
  // 5/4). The sphere of radius 1 centred at (3/8, 0, 9/64) + (3/5, 0, -4/5) = (39/40, 0, -211/320)
  // touches the convex cup from outside there and nowhere else. It comes in from the right along x:
  // centre x = 119/40 - t^2, E before t = sqrt 2, TE at sqrt 2, then it pushes into the wall (C).
  const Paraboloid p = standard("1", "1");
  const Ellipsoid e0 = sphere_at_origin("1");
  const RigidMotion m = translation(poly({"119/40", "0", "-1"}), poly({}), poly({"-211/320"}));
  const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("3/2"));
  const auto spans = span_positions(tl);
  REQUIRE(spans.size() >= 3);
  CHECK(std::vector<Position>(spans.begin(), spans.begin() + 3) ==
        std::vector<Position>{Position::E, Position::TE, Position::C});
  check_sqrt_decimals(instant_with(tl, Position::TE).time, Rational(2), 30);
  check_touches_first_at_sqrt2(tl, e0, m, p, q("3/2"), 32);
}

TEST_CASE("a big sphere grazes the vertex: E -> TE at sqrt(2) -> E; discriminant zeros change nothing",
          "[motion][irrational][anysize]") {
  // Radius 2 (not small) centred at (t^2 - 2, 0, -2): the sphere lies in z <= 0 and meets z = 0 only
  // at its top (t^2 - 2, 0, 0), on the paraboloid only when t = sqrt 2. E on both sides.
  const Ellipsoid e0 = sphere_at_origin("2");
  const RigidMotion m = translation(poly({"-2", "0", "1"}), poly({}), poly({"-2"}));
  for (const char* b : {"1", "2"}) {
    INFO("paraboloid x^2 + y^2/b^2, b = " << b);
    const Paraboloid p = standard("1", b);
    const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("2"));
    check_grazes_at_sqrt2(tl);
    check_closure_and_size(tl, false);
    check_against_sampling(tl, e0, m, p, 40, 33);
    const FirstContact fc = relpos::first_contact(e0, m, p, q("0"), q("2"));
    REQUIRE(fc.kind == FirstContact::Kind::Contact);
    CHECK(fc.position == Position::TE);
    check_first_contact_consistent(tl, fc);
  }
}

TEST_CASE("a big sphere crossing the axis: quiet discriminant zeros, two inner tangencies",
          "[motion][irrational][anysize]") {
  // Radius 1 (not small) in z = x^2 + y^2/4, centre (t^2 - 2, 0, z0) moving along x through the axis.
  const Paraboloid p = standard("1", "2");
  const Ellipsoid e0 = sphere_at_origin("1");
  SECTION("below the vertex (z0 = -3/2): E throughout; Disc f vanishes at irrational instants") {
    // The sphere lies in z <= -1/2 < 0: never a common point. At t = sqrt 2 the centre is on the axis.
    const RigidMotion m = translation(poly({"-2", "0", "1"}), poly({}), poly({"-3/2"}));
    const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("3"));
    CHECK(span_positions(tl) == std::vector<Position>{Position::E});
    for (const auto& inst : tl.instants) CHECK(inst.position == Position::E);
    CHECK(quiet_irrational_instants(tl) >= 2);
    bool axis = false;
    for (const auto& inst : tl.instants)
      if (!inst.time.is_rational() && vanishes_at_sqrt(inst.time.polynomial(), Rational(2))) axis = true;
    CHECK(axis);
    check_closure_and_size(tl, false);
    check_against_sampling(tl, e0, m, p, 30, 34);
    CHECK(relpos::first_contact(e0, m, p, q("0"), q("3")).kind == FirstContact::Kind::None);
  }
  SECTION("inside (z0 = 3): C -> TI -> I -> TI -> C -> TE -> E, symmetric about the axis") {
    // Near the axis the sphere is inside (the distance from (0, 0, 3) to the surface exceeds 1); moved
    // sideways it touches from inside at x = -x0 and x = +x0 (t^2 - 2 = -+x0, so t1^2 + t2^2 = 4),
    // crosses the wall, and leaves it tangentially from outside. On the axis (t = sqrt 2) the
    // discriminant vanishes and nothing changes.
    const RigidMotion m = translation(poly({"-2", "0", "1"}), poly({}), poly({"3"}));
    const Timeline tl = relpos::timeline(e0, m, p, q("0"), q("3"));
    CHECK(span_positions(tl) == std::vector<Position>{Position::C, Position::TI, Position::I, Position::TI, Position::C,
                                                      Position::TE, Position::E});
    const AlgebraicReal& t1 = instant_with(tl, Position::TI, 0).time;
    const AlgebraicReal& t2 = instant_with(tl, Position::TI, 1).time;
    REQUIRE(!t1.is_rational());
    REQUIRE(!t2.is_rational());
    const Rational a = relpos::parse_rational(t1.decimals(40)), b = relpos::parse_rational(t2.decimals(40));
    const Rational gap = a * a + b * b - Rational(4);
    CHECK(CGAL::abs(gap) < q("1/1000000000000000000000000000000"));
    CHECK(quiet_irrational_instants(tl) >= 1);
    check_closure_and_size(tl, false);
    check_against_sampling(tl, e0, m, p, 40, 35);
  }
}

TEST_CASE("random motions of bodies that are not small: every instant decided and consistent",
          "[motion][random][anysize]") {
  // Large random ellipsoids (semi-axes in [1, 3]) on straight or parabolic paths through random
  // paraboloids, some turning. No answer is known in advance: no exception (a closure violation
  // throws), every instant lies in the closure of both neighbours, the timeline agrees with classify
  // wherever it is sampled, first_contact with the timeline, and the instant method with classify at
  // the rational instants.
  const std::uint64_t seed = 0xB16B0D1;
  CAPTURE(seed);
  RandomPaths gen{std::mt19937_64(seed), 1, 3, 2, Rational(0), 4, -5, 0, 2, 2, 8, 2, 2, 5};
  int irrational_instants = 0, decided_by_definiteness = 0, not_small = 0;
  for (int k = 0; k < relpos::testing::scaled(40); ++k) {
    CAPTURE(k);
    const auto [p, e0, m] = gen.next(k);
    Timeline tl;
    REQUIRE_NOTHROW(tl = relpos::timeline(e0, m, p, q("0"), q("1")));
    check_closure_and_size(tl, m.rotation ? std::nullopt : std::optional<bool>(tl.instants.front().small));
    check_against_sampling(tl, e0, m, p, 20, static_cast<unsigned>(seed + static_cast<unsigned>(k)));
    check_first_contact_consistent(tl, relpos::first_contact(e0, m, p, q("0"), q("1")));
    irrational_instants += check_rational_instants(tl, e0, m, p);
    for (const auto& inst : tl.instants) {
      if (!inst.small) ++not_small;
      if (!inst.time.is_rational() && inst.how.find("definite") != std::string::npos) ++decided_by_definiteness;
    }
  }
  INFO(irrational_instants << " irrational instants, " << decided_by_definiteness << " by definiteness, " << not_small
                           << " instants not small");
  CHECK(irrational_instants > 0);
  CHECK(decided_by_definiteness > 0);
  CHECK(not_small > 0);
}
