// General pairs of known position (tests/support/general_cases.hpp) under rational affine
// congruences, scalings and sign flips: decide_position, decide_position_exact and classify give
// the constructed position, the trust-region oracle (tests/support/trs_oracle.hpp) agrees, every
// certificate passes the verifier and a check of the test's own.
#include <catch2/catch.hpp>
#include <random>
#include <set>
#include <vector>

#include "general/decision.hpp"
#include "relpos/classify.hpp"
#include "relpos/general_classify.hpp"
#include "support/construct.hpp"
#include "support/general_cases.hpp"
#include "support/seed.hpp"
#include "support/trs_oracle.hpp"

using namespace relpos;
using namespace relpos::testing;
using rt::form_value;

namespace {

/// Determinant of a square matrix (Laplace along the first row), the test's own.
Rational det(const std::vector<std::vector<Rational>>& m) {
  const std::size_t n = m.size();
  if (n == 1) return m[0][0];
  Rational total(0);
  for (std::size_t k = 0; k < n; ++k) {
    std::vector<std::vector<Rational>> sub;
    for (std::size_t i = 1; i < n; ++i) {
      std::vector<Rational> row;
      for (std::size_t j = 0; j < n; ++j)
        if (j != k) row.push_back(m[i][j]);
      sub.push_back(row);
    }
    const Rational term = m[0][k] * det(sub);
    total += k % 2 == 0 ? term : Rational(-term);
  }
  return total;
}

/// The leading n x n minor of a row-major 4x4 matrix.
Rational leading_minor(const std::array<Rational, 16>& m, int n) {
  std::vector<std::vector<Rational>> sub(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) sub[static_cast<std::size_t>(i)].push_back(m[static_cast<std::size_t>(4 * i + j)]);
  return det(sub);
}

/// The test's own check of a certificate (beyond the library's verifier): definite members by their
/// leading minors, tangency points on both surfaces and in the kernel of Q + t E, crossing points in
/// both quadrics, the hard case's contact set sampled in high precision.
void check_certificate(const Matrix4& e, const Matrix4& q, QuadricPosition p, const QuadricCertificate& c) {
  using K = QuadricCertificate::Kind;
  std::array<Rational, 16> k;
  auto pencil = [&](const Rational& t) {
    for (std::size_t i = 0; i < 16; ++i) k[i] = q.a[i] + t * e.a[i];
  };
  switch (c.kind) {
    case K::Definite: {
      pencil(c.t);
      const int sign = p == QuadricPosition::I ? -1 : 1;
      CHECK(CGAL::sign(c.t) == (p == QuadricPosition::E ? 1 : -1));
      for (int n = 1; n <= 4; ++n) CHECK(CGAL::sign(leading_minor(k, n)) == (sign > 0 || n % 2 == 0 ? 1 : -1));
      break;
    }
    case K::Tangent: {
      CHECK(form_value(e, c.contact) == 0);
      CHECK(form_value(q, c.contact) == 0);
      pencil(c.t);
      const std::array<Rational, 4> x{c.contact[0], c.contact[1], c.contact[2], Rational(1)};
      for (int i = 0; i < 4; ++i) {
        Rational s(0);
        for (int j = 0; j < 4; ++j) s += k[static_cast<std::size_t>(4 * i + j)] * x[static_cast<std::size_t>(j)];
        CHECK(s == 0);
      }
      break;
    }
    case K::HardTangent: {
      // A point of the contact set in MPFR: centre + sigma w1 with w1^T M w1 sigma^2 = radius2.
      auto value = [&](const QuadraticNumber& x) { return big(x.a) + big(x.b) * sqrt(big(Rational(c.d))); };
      std::array<Big, 3> point;
      for (std::size_t i = 0; i < 3; ++i) point[i] = value(c.centre[i]);
      const Big r2 = value(c.radius2);
      if (!c.directions.empty()) {
        std::array<Big, 3> w;
        for (std::size_t i = 0; i < 3; ++i) w[i] = value(c.directions[0][i]);
        Big wmw = 0;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            wmw += w[static_cast<std::size_t>(i)] * big(e(i, j)) * w[static_cast<std::size_t>(j)];
        const Big sigma = sqrt(r2 / wmw);
        for (std::size_t i = 0; i < 3; ++i) point[i] += sigma * w[i];
      } else {
        CHECK(abs(r2) < Big("1e-100"));
      }
      auto at = [&](const Matrix4& m) {
        const std::array<Big, 4> v{point[0], point[1], point[2], Big(1)};
        Big s = 0;
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j)
            s += v[static_cast<std::size_t>(i)] * big(m(i, j)) * v[static_cast<std::size_t>(j)];
        return s;
      };
      CHECK(abs(at(e)) < Big("1e-100"));
      CHECK(abs(at(q)) < Big("1e-100"));
      break;
    }
    case K::Crossing:
      CHECK(form_value(e, c.inside) <= 0);
      CHECK(form_value(q, c.inside) < 0);
      CHECK(form_value(e, c.outside) <= 0);
      CHECK(form_value(q, c.outside) > 0);
      if (c.beyond) {
        CHECK(form_value(q, *c.beyond) <= 0);
        CHECK(form_value(e, *c.beyond) > 0);
      }
      break;
    case K::Equal:
      CHECK(c.ratio > 0);
      for (std::size_t i = 0; i < 16; ++i) CHECK(q.a[i] == c.ratio * e.a[i]);
      break;
    case K::None:
      FAIL("no certificate");
  }
}

/// Every path and every check on one pair of expected position.
void check_pair(const std::string& name, const Ellipsoid& e, const Quadric& q, QuadricPosition expected,
                bool hard = false) {
  INFO(name);
  const QuadricVerdict v = decide_position(e, q), x = decide_position_exact(e, q);
  CHECK(to_string(v.position) == to_string(expected));
  CHECK(to_string(x.position) == to_string(expected));
  CHECK(v.type == q.type());
  const QuadricClassification c = classify(e, q);
  CHECK(to_string(c.verdict.position) == to_string(expected));
  const auto problem = verify_certificate(e, q, c.verdict.position, c.certificate);
  CHECK(problem.value_or("verified") == "verified");
  check_certificate(e.matrix(), q.matrix(), c.verdict.position, c.certificate);
  // A tangency at the end of an interval (the hard case) is reported as such, with its contact set.
  const bool tangent = contact_of(expected) == Contact::Touching && expected != QuadricPosition::EQ;
  if (tangent) {
    const bool endpoint = c.verdict.rule == QuadricRule::EndpointLo || c.verdict.rule == QuadricRule::EndpointHi ||
                          c.verdict.rule == QuadricRule::EndpointInner;
    CHECK(endpoint == hard);
    CHECK((c.certificate.kind == QuadricCertificate::Kind::HardTangent) == hard);
  }
  const OracleAnswer o = oracle_position(e.matrix(), q.matrix(), q.type() == QuadricType::Ellipsoid);
  CHECK(to_string(o.position) == to_string(expected));
}

}  // namespace

TEST_CASE("general pairs of known position, as constructed", "[general]") {
  for (const GeneralCase& k : constructed_cases())
    check_pair(k.name, Ellipsoid::from_matrix(k.e), k.q, k.expected, k.hard);
}

TEST_CASE("general pairs of known position under affine congruences, scalings and sign flips", "[general]") {
  std::mt19937_64 rng(announced_seed("general congruences", 20261201));
  std::uniform_int_distribution<int> sd(1, 9);
  for (const GeneralCase& k : constructed_cases()) {
    for (int round = 0; round < 3; ++round) {
      const AffineMap m = random_map(rng, round == 2);
      const Quadric qe = Quadric::from_map(Quadric::from_matrix(k.e), m.l, m.t);
      const Quadric qq = Quadric::from_map(k.q, m.l, m.t);
      // Scalings of each matrix, negative for E (normalized back) and for Q (normalized back unless
      // its type keeps the sign as given: then the solid is the complement's closure).
      const bool flip = round == 1;
      const Matrix4 em = scaled_matrix(qe.matrix(), Rational(-sd(rng), sd(rng)));
      const Matrix4 qm = scaled_matrix(qq.matrix(), Rational(flip ? -sd(rng) : sd(rng), sd(rng)));
      const Quadric q2 = Quadric::from_matrix(qm);
      CHECK(q2.type() == k.q.type());
      const QuadricPosition expected = flip && sign_as_given(k.q.type()) ? mirrored(k.expected) : k.expected;
      check_pair(k.name + " (mapped, round " + std::to_string(round) + ")", Ellipsoid::from_matrix(em), q2, expected,
                 k.hard);
    }
  }
}

TEST_CASE("general pairs: every type and every position its geometry allows is constructed", "[general]") {
  std::set<std::pair<QuadricType, QuadricPosition>> seen;
  std::set<QuadricType> hard_seen;
  for (const GeneralCase& k : constructed_cases()) {
    seen.insert({k.q.type(), k.expected});
    if (k.hard) hard_seen.insert(k.q.type());
  }
  for (QuadricType t : detail::general::kAllQuadricTypes)
    for (QuadricPosition p :
         {QuadricPosition::I, QuadricPosition::TI, QuadricPosition::C, QuadricPosition::TE, QuadricPosition::E}) {
      INFO(to_string(t) << " " << to_string(p));
      CHECK(seen.count({t, p}) == 1);
    }
  for (QuadricPosition p : {QuadricPosition::O, QuadricPosition::TO, QuadricPosition::EQ})
    CHECK(seen.count({QuadricType::Ellipsoid, p}) == 1);
}

TEST_CASE("general pairs: an elliptic paraboloid gives the paraboloid classifier's position", "[general]") {
  // The general rule with D = det(B + t M) reduces to math.md §8 for a paraboloid (t_lo = 0, t_hi the
  // smallest root of D): the two classifiers, sharing no decision code, agree on random pairs.
  std::mt19937_64 rng(announced_seed("general vs paraboloid", 7));
  std::uniform_int_distribution<int> c(-64, 64), a(8, 64), qd(-3, 3);
  int positions[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < 400; ++i) {
    const Paraboloid p = Paraboloid::standard(
        {Rational(c(rng), 32), Rational(c(rng), 32), Rational(c(rng), 32)}, Rational(a(rng), 32), Rational(a(rng), 32),
        {Rational(1 + (i % 3)), Rational(qd(rng)), Rational(qd(rng)), Rational(qd(rng))});
    const Ellipsoid e =
        Ellipsoid::from_axes({Rational(c(rng), 32), Rational(c(rng), 32), Rational(c(rng), 16)},
                             {Rational(a(rng), 64), Rational(a(rng), 64), Rational(a(rng), 64)},
                             Quaternion{Rational(1), Rational(qd(rng)), Rational(qd(rng)), Rational(qd(rng))});
    const Position old = decide_position(e, p).position;
    const QuadricVerdict v = decide_position(e, Quadric::of(p));
    CHECK(to_string(v.position) == to_string(old));
    ++positions[static_cast<int>(old)];
  }
  CHECK(positions[static_cast<int>(Position::I)] > 0);
  CHECK(positions[static_cast<int>(Position::C)] > 0);
  CHECK(positions[static_cast<int>(Position::E)] > 0);
}
