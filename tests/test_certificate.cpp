// The certificates (classify.hpp): the independent verifier and the JSON form of certificates. Every case is built by
// hand (spheres against z = x^2 + y^2, where the pencil lambda P + E is block diagonal), the true
// certificate must be accepted and tampered variants rejected.
#include <CGAL/Interval_nt.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <optional>
#include <random>
#include <relpos/classify.hpp>
#include <relpos/error.hpp>
#include <relpos/io.hpp>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "algebra/forms.hpp"
#include "anysize/exact.hpp"
#include "certificate/build.hpp"
#include "certificate/verify.hpp"
#include "io/certificate_json.hpp"
#include "io/json_tree.hpp"
#include "io/json_write.hpp"

using relpos::Certificate;
using relpos::Ellipsoid;
using relpos::Matrix4;
using relpos::Paraboloid;
using relpos::Position;
using relpos::QuadraticNumber;
using relpos::Rational;
using relpos::Vector3;
using Kind = relpos::Certificate::Kind;
using relpos::detail::io::Json;

namespace {

Rational rat(long n, long d = 1) { return Rational(n, d); }

/// z = x^2 + y^2 (Paraboloid::standard({0,0,0}, 1, 1)).
Paraboloid cup() { return Paraboloid::standard({rat(0), rat(0), rat(0)}, rat(1), rat(1)); }

Ellipsoid sphere(const Rational& cz, const Rational& r) { return Ellipsoid::sphere({rat(0), rat(0), cz}, r); }

Certificate definite(const Rational& lambda) {
  Certificate c;
  c.kind = Kind::Definite;
  c.lambda = lambda;
  return c;
}

Certificate tangent(const Rational& lambda, const Vector3& x) {
  Certificate c;
  c.kind = Kind::Tangent;
  c.lambda = lambda;
  c.contact = x;
  return c;
}

Certificate crossing(const Vector3& in, const Vector3& out) {
  Certificate c;
  c.kind = Kind::Crossing;
  c.inside = in;
  c.outside = out;
  return c;
}

QuadraticNumber qn(const Rational& a, const Rational& b = Rational(0)) { return {a, b}; }

/// The first lambda = k/8, k = 1..200 (times `sign`) that the verifier accepts for `position`.
std::optional<Rational> scan_lambda(const Ellipsoid& e, const Paraboloid& p, Position position, int sign) {
  for (long k = 1; k <= 200; ++k) {
    const Rational lambda = rat(sign * k, 8);
    if (!relpos::verify_certificate(e, p, position, definite(lambda))) return lambda;
  }
  return std::nullopt;
}

bool accepted(const Ellipsoid& e, const Paraboloid& p, Position position, const Certificate& c) {
  const auto r = relpos::verify_certificate(e, p, position, c);
  if (r) UNSCOPED_INFO("rejected: " << *r);
  return !r;
}

void require_rejected(const Ellipsoid& e, const Paraboloid& p, Position position, const Certificate& c,
                      const std::string& fragment = "") {
  const auto r = relpos::verify_certificate(e, p, position, c);
  REQUIRE(r);
  INFO("reason: " << *r);
  if (!fragment.empty()) CHECK(r->find(fragment) != std::string::npos);
}

/// lambda P + E for the sphere centred (0, 0, cz) of radius^2 r2 and z = x^2 + y^2, and its leading
/// minors: independent of the verifier, for the hand derivations below.
bool pencil_pd(const Rational& cz, const Rational& r2, const Rational& lambda) {
  // diag(1 + l, 1 + l) (+) [[1, -cz - l/2], [-cz - l/2, cz^2 - r2]]
  const Rational off = -cz - lambda / 2;
  return 1 + lambda > 0 && (cz * cz - r2) - off * off > 0;
}

/// The hard tangency: sphere of radius 1 centred (0, 0, 5/4) touching the cup along the circle
/// z = 3/4, x^2 + y^2 = 3/4; lambda_s = -1 (s = (1 + lambda)^2).
Certificate circle_certificate() {
  Certificate c;
  c.kind = Kind::HardTangent;
  c.d = 0;
  c.lambda_q = qn(rat(-1));
  c.centre = {qn(rat(0)), qn(rat(0)), qn(rat(3, 4))};
  c.directions = {{qn(rat(1)), qn(rat(0)), qn(rat(0))}, {qn(rat(0)), qn(rat(1)), qn(rat(0))}};
  c.radius2 = qn(rat(3, 4));
  return c;
}

void require_same(const Certificate& a, const Certificate& b) {
  REQUIRE(a.kind == b.kind);
  switch (a.kind) {
    case Kind::None:
      break;
    case Kind::Definite:
      CHECK(a.lambda == b.lambda);
      break;
    case Kind::Tangent:
      CHECK(a.lambda == b.lambda);
      CHECK(a.contact == b.contact);
      break;
    case Kind::Crossing:
      CHECK(a.inside == b.inside);
      CHECK(a.outside == b.outside);
      break;
    case Kind::HardTangent: {
      CHECK(a.d == b.d);
      CHECK(a.lambda_q.a == b.lambda_q.a);
      CHECK(a.lambda_q.b == b.lambda_q.b);
      for (int i = 0; i < 3; ++i) {
        CHECK(a.centre[i].a == b.centre[i].a);
        CHECK(a.centre[i].b == b.centre[i].b);
      }
      REQUIRE(a.directions.size() == b.directions.size());
      for (std::size_t t = 0; t < a.directions.size(); ++t)
        for (int i = 0; i < 3; ++i) {
          CHECK(a.directions[t][i].a == b.directions[t][i].a);
          CHECK(a.directions[t][i].b == b.directions[t][i].b);
        }
      CHECK(a.radius2.a == b.radius2.a);
      CHECK(a.radius2.b == b.radius2.b);
      break;
    }
  }
}

Certificate round_trip(const Certificate& c) {
  // Through text and the exact parser, as relpos verify reads it.
  return relpos::certificate_from_json(relpos::certificate_json_text(c));
}

}  // namespace

TEST_CASE("Q(sqrt d) signs are exact", "[certificate]") {
  using relpos::Integer;
  using relpos::quadratic_sign;
  CHECK(quadratic_sign(qn(rat(1), rat(-1)), Integer(2)) == -1);  // 1 - sqrt 2
  CHECK(quadratic_sign(qn(rat(3), rat(-2)), Integer(2)) == 1);   // 3 - 2 sqrt 2 = 0.17...
  CHECK(quadratic_sign(qn(rat(-3), rat(2)), Integer(2)) == -1);
  CHECK(quadratic_sign(qn(rat(0), rat(0)), Integer(5)) == 0);
  CHECK(quadratic_sign(qn(rat(2), rat(-1)), Integer(4)) == 0);  // 2 - sqrt 4
  CHECK(quadratic_sign(qn(rat(0), rat(-1, 3)), Integer(7)) == -1);
  CHECK(quadratic_sign(qn(rat(-5), rat(0)), Integer(7)) == -1);
  CHECK(quadratic_sign(qn(rat(1), rat(1)), Integer(3)) == 1);
  CHECK(quadratic_sign(qn(rat(-1), rat(5)), Integer(0)) == -1);  // d = 0: sqrt d = 0
  // 99/70 is just above sqrt 2, 140/99 just below.
  CHECK(quadratic_sign(qn(rat(99, 70), rat(-1)), Integer(2)) == 1);
  CHECK(quadratic_sign(qn(rat(140, 99), rat(-1)), Integer(2)) == -1);
}

TEST_CASE("E: unit sphere at (0,0,-3) below the cup", "[certificate]") {
  const Ellipsoid e = sphere(rat(-3), rat(1));
  const Paraboloid p = cup();
  const auto lambda = scan_lambda(e, p, Position::E, 1);
  REQUIRE(lambda);
  CHECK(pencil_pd(rat(-3), rat(1), *lambda));            // hand formula agrees
  CHECK(accepted(e, p, Position::E, definite(rat(2))));  // 1 + 2 > 0, 8 - 4 > 0
  require_rejected(e, p, Position::E, definite(rat(0)), "must be > 0");
  require_rejected(e, p, Position::E, definite(rat(-1, 2)), "must be > 0");
  require_rejected(e, p, Position::E, definite(rat(1000)), "not positive definite");
  require_rejected(e, p, Position::I, definite(*lambda), "must be < 0");
  // Wrong kinds and positions.
  require_rejected(e, p, Position::TE, definite(*lambda), "cannot prove");
  require_rejected(e, p, Position::E, Certificate{}, "cannot prove");
  // The raw-matrix overload normalizes signs by negation.
  Matrix4 em = e.matrix(), pm = p.matrix();
  for (auto& x : em.a) x = -x;
  for (auto& x : pm.a) x = -x;
  CHECK(!relpos::verify_certificate(em, pm, Position::E, definite(*lambda)));
  // Not an ellipsoid / paraboloid.
  Matrix4 bad = e.matrix();
  bad(0, 0) = -1;
  CHECK(relpos::verify_certificate(bad, p.matrix(), Position::E, definite(*lambda)));
  Matrix4 asym = e.matrix();
  asym(0, 1) = 1;
  CHECK(relpos::verify_certificate(asym, p.matrix(), Position::E, definite(*lambda)));
  CHECK(relpos::verify_certificate(e.matrix(), e.matrix(), Position::E, definite(*lambda)));
}

TEST_CASE("I: sphere of radius 1/10 at (0,0,1) inside the cup", "[certificate]") {
  const Ellipsoid e = sphere(rat(1), rat(1, 10));
  const Paraboloid p = cup();
  const auto lambda = scan_lambda(e, p, Position::I, -1);
  REQUIRE(lambda);
  CHECK(pencil_pd(rat(1), rat(1, 100), *lambda));
  CHECK(accepted(e, p, Position::I, definite(rat(-1, 2))));
  require_rejected(e, p, Position::I, definite(rat(1, 2)), "must be < 0");
  require_rejected(e, p, Position::E, definite(rat(1, 2)));
  require_rejected(e, p, Position::I, definite(rat(-2)), "not positive definite");  // 1 + lambda < 0
  require_rejected(e, p, Position::E, definite(*lambda), "must be > 0");
}

TEST_CASE("TE: unit sphere at (0,0,-1) touching the vertex from outside", "[certificate]") {
  const Ellipsoid e = sphere(rat(-1), rat(1));
  const Paraboloid p = cup();
  // det(lambda P + E) = -(1 + lambda)^2 (1 - lambda/2)^2: the double root lambda = 2.
  const Certificate good = tangent(rat(2), {rat(0), rat(0), rat(0)});
  CHECK(accepted(e, p, Position::TE, good));
  require_rejected(e, p, Position::TE, tangent(rat(2), {rat(0), rat(0), rat(1, 1000)}), "not on the");
  require_rejected(e, p, Position::TE, tangent(rat(2), {rat(1, 1000), rat(0), rat(0)}), "not on the");
  require_rejected(e, p, Position::TE, tangent(rat(3), {rat(0), rat(0), rat(0)}), "not positive semidefinite");
  require_rejected(e, p, Position::TE, tangent(rat(-1), {rat(0), rat(0), rat(0)}), "must be > 0");
  require_rejected(e, p, Position::TI, good, "must be < 0");
  require_rejected(e, p, Position::E, good, "cannot prove");
  // A Definite certificate cannot exist (the pencil is singular at 2) and the verifier agrees.
  CHECK(relpos::verify_certificate(e, p, Position::E, definite(rat(2))));
}

TEST_CASE("TI: sphere of radius 1/4 at (0,0,1/4) touching the vertex from inside", "[certificate]") {
  const Ellipsoid e = sphere(rat(1, 4), rat(1, 4));
  const Paraboloid p = cup();
  // lambda P + E = diag(1 + l, 1 + l) (+) [[1, -1/4 - l/2], [-1/4 - l/2, 0]]: PSD only at l = -1/2.
  const Certificate good = tangent(rat(-1, 2), {rat(0), rat(0), rat(0)});
  CHECK(accepted(e, p, Position::TI, good));
  require_rejected(e, p, Position::TI, tangent(rat(-1, 2), {rat(0), rat(0), rat(1, 2)}), "not on the paraboloid");
  require_rejected(e, p, Position::TI, tangent(rat(-1, 2), {rat(1, 2), rat(0), rat(1, 4)}), "not on the ellipsoid");
  require_rejected(e, p, Position::TI, tangent(rat(-3, 5), {rat(0), rat(0), rat(0)}), "not positive semidefinite");
  require_rejected(e, p, Position::TE, good, "must be > 0");
}

TEST_CASE("TI, hard case: unit sphere at (0,0,5/4) touching along a circle", "[certificate]") {
  const Ellipsoid e = sphere(rat(5, 4), rat(1));
  const Paraboloid p = cup();
  const Certificate good = circle_certificate();
  CHECK(accepted(e, p, Position::TI, good));
  // lambda_s = -1 written as -1 + 0 sqrt 2 (d need not be 0 when b = 0).
  Certificate d2 = good;
  d2.d = 2;
  CHECK(accepted(e, p, Position::TI, d2));
  // The directions in another basis of the kernel.
  Certificate basis = good;
  basis.directions = {{qn(rat(1)), qn(rat(1)), qn(rat(0))}, {qn(rat(1)), qn(rat(-2)), qn(rat(0))}};
  CHECK(accepted(e, p, Position::TI, basis));
  // A direction with an irrational part that cancels: (sqrt 4 - 2, 1, 0) = (0, 1, 0).
  Certificate cancel = good;
  cancel.d = 4;
  cancel.directions[1] = {qn(rat(-2), rat(1)), qn(rat(1)), qn(rat(0))};
  CHECK(accepted(e, p, Position::TI, cancel));

  SECTION("tampered") {
    Certificate c = good;
    c.radius2 = qn(rat(1));
    require_rejected(e, p, Position::TI, c, "radius2");
    c = good;
    c.lambda_q = qn(rat(-999, 1000));
    require_rejected(e, p, Position::TI, c, "not positive semidefinite");
    c = good;
    c.lambda_q = qn(rat(-1001, 1000));
    require_rejected(e, p, Position::TI, c, "not positive semidefinite");
    c = good;
    c.d = 2;
    c.lambda_q = qn(rat(-1), rat(1, 1000000));  // -1 + sqrt(2)/10^6
    require_rejected(e, p, Position::TI, c, "not positive semidefinite");
    c = good;
    c.centre[2] = qn(rat(1, 2));
    require_rejected(e, p, Position::TI, c, "K (centre, 1)");
    c = good;
    c.centre[0] = qn(rat(1, 10));  // still in K's kernel, but not the centre of the circle
    require_rejected(e, p, Position::TI, c, "conjugate");
    c = good;
    c.directions[1] = {qn(rat(0)), qn(rat(1)), qn(rat(1))};
    require_rejected(e, p, Position::TI, c, "kernel");
    c = good;
    c.directions[1] = {qn(rat(2)), qn(rat(0)), qn(rat(0))};
    require_rejected(e, p, Position::TI, c, "dependent");
    c = good;
    c.directions[1] = {qn(rat(0)), qn(rat(0)), qn(rat(0))};
    require_rejected(e, p, Position::TI, c, "zero");
    c = good;
    c.directions.pop_back();  // the kernel has dimension 2: one direction describes two points only
    require_rejected(e, p, Position::TI, c, "dimension 2");
    c.directions.clear();
    require_rejected(e, p, Position::TI, c, "no direction");
    c = good;
    c.directions.push_back(good.directions[0]);
    c.directions.push_back(good.directions[1]);
    require_rejected(e, p, Position::TI, c, "more than 3");
    c = good;
    c.d = -2;
    require_rejected(e, p, Position::TI, c, "d = -2");
    require_rejected(e, p, Position::TE, good, "cannot prove");
    require_rejected(e, p, Position::C, good, "cannot prove");
  }

  SECTION("a single contact point (radius2 = 0): TI at the vertex as a hard certificate") {
    // The sphere of radius 1/2 at (0, 0, 1/2) osculates the vertex: lambda_s = -1 is also the
    // double root, K = diag(0, 0) (+) [[1, -1/2 + 1/2 = 0], [0, 0]], centre (0, 0, 0), radius2 0.
    const Ellipsoid osc = sphere(rat(1, 2), rat(1, 2));
    Certificate c;
    c.kind = Kind::HardTangent;
    c.d = 0;
    c.lambda_q = qn(rat(-1));
    c.centre = {qn(rat(0)), qn(rat(0)), qn(rat(0))};
    c.radius2 = qn(rat(0));
    CHECK(accepted(osc, p, Position::TI, c));
    c.directions = good.directions;  // the full kernel is fine too
    CHECK(accepted(osc, p, Position::TI, c));
    CHECK(accepted(osc, p, Position::TI, tangent(rat(-1), {rat(0), rat(0), rat(0)})));
    c.radius2 = qn(rat(1, 4));
    require_rejected(osc, p, Position::TI, c, "radius2");
  }
}

TEST_CASE("C: unit sphere at the origin crossing the cup", "[certificate]") {
  const Ellipsoid e = sphere(rat(0), rat(1));
  const Paraboloid p = cup();
  const Vector3 in{rat(0), rat(0), rat(1, 2)}, out{rat(0), rat(0), rat(-1, 2)};
  CHECK(accepted(e, p, Position::C, crossing(in, out)));
  CHECK(accepted(e, p, Position::C, crossing(in, {rat(0), rat(0), rat(-1)})));  // on the sphere: X^T E X = 0
  require_rejected(e, p, Position::C, crossing(out, in), "not inside the paraboloid");
  require_rejected(e, p, Position::C, crossing(in, in), "not outside the paraboloid");
  require_rejected(e, p, Position::C, crossing({rat(0), rat(0), rat(2)}, out), "not in the solid ellipsoid");
  require_rejected(e, p, Position::C, crossing(in, {rat(0), rat(0), rat(-2)}), "not in the solid ellipsoid");
  require_rejected(e, p, Position::C, crossing(in, {rat(0), rat(0), rat(0)}), "not outside");  // on the paraboloid
  require_rejected(e, p, Position::E, crossing(in, out), "cannot prove");
  require_rejected(e, p, Position::C, definite(rat(1)), "cannot prove");
}

TEST_CASE("a classification's unused numbers stay zero across results", "[certificate]") {
  // Each position writes different members; whatever one result fills must not show up in another's
  // members left at their defaults (results may share their default numbers).
  const Paraboloid p = cup();
  for (int round = 0; round < 2; ++round) {
    const relpos::Classification c = relpos::classify(sphere(rat(0), rat(1)), p);      // C: inside, outside
    const relpos::Classification i = relpos::classify(sphere(rat(1), rat(1, 10)), p);  // I: lambda
    const relpos::Classification t = relpos::classify(sphere(rat(-1), rat(1)), p);     // TE: lambda, contact
    const relpos::Classification h = relpos::classify(sphere(rat(5, 4), rat(1)), p);   // TI: the hard case
    REQUIRE(c.certificate.kind == Kind::Crossing);
    REQUIRE(i.certificate.kind == Kind::Definite);
    REQUIRE(t.certificate.kind == Kind::Tangent);
    REQUIRE(h.certificate.kind == Kind::HardTangent);
    CHECK(i.certificate.lambda != 0);
    CHECK(c.certificate.lambda == 0);
    for (int k = 0; k < 3; ++k) {
      CHECK(i.certificate.inside[k] == 0);
      CHECK(i.certificate.outside[k] == 0);
      CHECK(c.certificate.contact[k] == 0);
      CHECK(t.certificate.inside[k] == 0);
      CHECK(c.certificate.centre[k].a == 0);
      CHECK(c.certificate.centre[k].b == 0);
    }
    CHECK(c.certificate.d == 0);
    CHECK(h.certificate.directions.size() == 2);
    CHECK(c.certificate.directions.empty());
    CHECK(c.certificate.radius2.a == 0);
    CHECK(i.certificate.lambda_q.a == 0);
    CHECK(h.certificate.lambda == 0);
  }
}

TEST_CASE("a certificate that cannot be built is an internal error, never a null certificate", "[certificate]") {
  // The unit sphere at the origin crosses the cup: no rational double root of f proves a tangency.
  const Ellipsoid e = sphere(rat(0), rat(1));
  const Paraboloid p = cup();
  CHECK_THROWS_AS(relpos::detail::certificate::build(e, p, Position::TE), std::logic_error);
  CHECK_THROWS_WITH(relpos::detail::certificate::build(e, p, Position::TI),
                    Catch::Contains("internal error") && Catch::Contains("classified TI"));
  const Certificate c = relpos::detail::certificate::build(e, p, Position::C);
  CHECK(c.kind == Kind::Crossing);
  CHECK_FALSE(relpos::verify_certificate(e, p, Position::C, c));
}

TEST_CASE("certificates survive JSON exactly", "[certificate]") {
  require_same(round_trip(Certificate{}), Certificate{});
  CHECK(relpos::certificate_json_text(Certificate{}) == "null");
  const Certificate d = definite(rat(-7, 3));
  CHECK(relpos::certificate_json_text(d) == R"({"lambda":"-7/3"})");
  require_same(round_trip(d), d);
  const Certificate t = tangent(rat(2), {rat(1, 3), rat(-2), rat(0)});
  CHECK(relpos::certificate_json_text(t) == R"({"lambda":"2","contact":["1/3","-2","0"]})");
  require_same(round_trip(t), t);
  const Certificate c = crossing({rat(0), rat(0), rat(1, 2)}, {rat(5), rat(-1, 1000000), rat(3)});
  require_same(round_trip(c), c);

  Certificate h = circle_certificate();
  h.d = 35;
  h.lambda_q = qn(rat(-3, 2), rat(1, 7));
  h.centre[0] = qn(rat(0), rat(-1, 2));
  h.radius2 = qn(rat(3, 4), rat(2));
  require_same(round_trip(h), h);
  const Json j = Json::parse(relpos::certificate_json_text(h, 6));
  CHECK(j["lambda"]["d"] == "35");
  CHECK(j["lambda"]["b"] == "1/7");
  const Json& dec = j["contact_set"]["decimal"];
  CHECK(dec["lambda"] == "-0.654846");    // -1.5 + sqrt(35)/7 = -0.6548457...
  CHECK(dec["center"][0] == "-2.95804");  // -sqrt(35)/2 = -2.9580398...
  CHECK(dec["center"][2] == "0.75");
  CHECK(dec["radius2"] == "12.5822");  // 3/4 + 2 sqrt 35 = 12.58215...
  // Numbers may also be JSON numbers (read exactly) and "decimal" is ignored.
  const Certificate n = relpos::certificate_from_json(R"({"lambda": 0.1})");
  CHECK(n.kind == Kind::Definite);
  CHECK(n.lambda == rat(1, 10));
}

TEST_CASE("malformed certificate JSON is an InputError", "[certificate]") {
  const char* bad[] = {
      R"(3)",
      R"("x")",
      R"([])",
      R"({})",
      R"({"lambda": true})",
      R"({"lambda": "1/0"})",
      R"({"lambda": "abc"})",
      R"({"lambda": "1", "extra": 2})",
      R"({"lambda": "1", "contact": ["1", "2"]})",
      R"({"lambda": "1", "contact": ["1", "2", null]})",
      R"({"contact": ["1", "2", "3"]})",
      R"({"inside": ["0", "0", "0"]})",
      R"({"inside": ["0", "0", "0"], "outside": "0"})",
      R"({"lambda": {"a": "-1", "b": "0", "d": "1/2"}, "contact_set": {"center": [{"a": "0", "b": "0"}, {"a": "0", "b": "0"}, {"a": "0", "b": "0"}], "directions": [], "radius2": {"a": "0", "b": "0"}}})",
      R"({"lambda": {"a": "-1", "b": "0", "d": "-3"}, "contact_set": {"center": [{"a": "0", "b": "0"}, {"a": "0", "b": "0"}, {"a": "0", "b": "0"}], "directions": [], "radius2": {"a": "0", "b": "0"}}})",
      R"({"lambda": {"a": "-1", "b": "0", "d": "2"}, "contact_set": {"center": [{"a": "0", "b": "0"}, {"a": "0", "b": "0"}], "directions": [], "radius2": {"a": "0", "b": "0"}}})",
      R"({"lambda": {"a": "-1", "b": "0", "d": "2"}, "contact_set": {"center": [{"a": "0", "b": "0"}, {"a": "0", "b": "0"}, {"a": "0"}], "directions": [], "radius2": {"a": "0", "b": "0"}}})",
      R"({"lambda": {"a": "-1", "b": "0", "d": "2"}, "contact_set": {"center": [{"a": "0", "b": "0"}, {"a": "0", "b": "0"}, {"a": "0", "b": "0"}], "directions": {}, "radius2": {"a": "0", "b": "0"}}})",
      R"({"lambda": {"a": "-1", "b": "0", "d": "2"}, "contact_set": {"center": [{"a": "0", "b": "0"}, {"a": "0", "b": "0"}, {"a": "0", "b": "0"}], "directions": []}})",
      R"({"lambda": "-1", "contact_set": {"center": [{"a": "0", "b": "0"}, {"a": "0", "b": "0"}, {"a": "0", "b": "0"}], "directions": [], "radius2": {"a": "0", "b": "0"}}})",
  };
  for (const char* text : bad) {
    INFO(text);
    CHECK_THROWS_AS(relpos::certificate_from_json(text), relpos::InputError);
  }
}

TEST_CASE("the report's JSON text holds the classification's exact values, for every position", "[certificate][io]") {
  // The one writer of reports (src/io/answer_json.cpp): its text is read back member by member and
  // compared with the Classification it renders; dumping the tree read from it gives the same text.
  const std::pair<Ellipsoid, Position> cases[] = {
      {sphere(rat(-3), rat(1)), Position::E},    {sphere(rat(1), rat(1, 10)), Position::I},
      {sphere(rat(-1), rat(1)), Position::TE},   {sphere(rat(1, 4), rat(1, 4)), Position::TI},
      {sphere(rat(5, 4), rat(1)), Position::TI}, {sphere(rat(0), rat(1)), Position::C}};
  for (const auto& [e, expected] : cases) {
    const relpos::Classification c = relpos::classify(e, cup(), relpos::Evidence::Full);
    REQUIRE(c.verdict.position == expected);
    const std::string text = relpos::io::classification_json_text(c);
    CAPTURE(text);
    const Json j = Json::parse(text);
    CHECK(relpos::detail::io::dump_json(j) == text);
    CHECK(j["position"] == relpos::to_string(c.verdict.position));
    CHECK(j["small"] == c.verdict.small);
    CHECK(j["stage"] == relpos::to_string(c.verdict.stage));
    CHECK(j["rule"] == c.rule_text());
    CHECK(j["disc_sign"] == int(c.verdict.sign_disc_f));
    CHECK(j["roots"]["real"] == int(c.verdict.real_roots));
    CHECK(j["degree_ftilde"] == c.degree_ftilde);
    for (std::size_t i = 0; i < 5; ++i) CHECK(j["f"][i] == relpos::to_string(c.f[i]));
    for (std::size_t i = 0; i < 3; ++i) CHECK(j["s"][i] == relpos::to_string(c.s[i]));
    if (c.rho) CHECK(j["rho"] == relpos::to_string(*c.rho));
    if (c.rho) CHECK(j["rho_approx"].get<double>() == c.rho_approx);  // the double itself, round trip
    std::size_t multiple = 0;
    for (const auto& r : c.roots) multiple += r.multiplicity_f >= 2;
    CHECK(j["multiple_roots"].size() == multiple);
    require_same(relpos::detail::io::certificate_from_tree(j["certificate"]), c.certificate);
    CHECK_FALSE(relpos::verify_certificate(e, cup(), c.verdict.position,
                                           relpos::detail::io::certificate_from_tree(j["certificate"])));
  }
}

TEST_CASE("the report writer's rationals are GMP's decimal text at every length", "[io]") {
  // JsonWriter::rational writes the digits itself (json_write.cpp): chunks of 19 digits with their
  // leading zeros under a leading part of up to 20, and GMP's own text beyond 64 limbs. Compared
  // with to_string (mpz_get_str) on integers of 0 to 90 limbs, near powers of ten and chunk edges.
  std::mt19937_64 rng(19);
  const relpos::Integer ten19 = relpos::Integer(10000000000000000000UL);
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    relpos::Integer z(static_cast<unsigned long>(rng()) >> (rng() % 64));
    const int limbs = static_cast<int>(rng() % (trial < 2900 ? 12 : 90));
    for (int i = 0; i < limbs; ++i) z = z * relpos::Integer(static_cast<unsigned long>(rng() | 1));
    switch (trial % 5) {
      case 1:  // a power of ten times z, minus one: runs of nines and zeros across chunks
        for (int i = 0; i < limbs % 4 + 1; ++i) z = z * ten19;
        z = z - 1;
        break;
      case 2:
        z = z * ten19;
        break;
      case 3:
        z = -z;
        break;
      default:
        break;
    }
    const relpos::Rational q = trial % 2 ? relpos::Rational(z) : relpos::Rational(z, z * z + 1);
    std::string text;
    relpos::detail::io::JsonWriter w(text);
    w.rational(q);
    REQUIRE(text == "\"" + relpos::to_string(q) + "\"");
    ++checked;
  }
  REQUIRE(checked == 3000);
}

TEST_CASE("the report writer's integers are their decimal text at the edges of its chunks and limbs", "[io]") {
  // The writer's digits (json_write.cpp) come in chunks of 19 (below 10^19 < 2^64), each as a head
  // of 3 and two words of 8; the quotients are limbs and the text beyond 64 limbs is GMP's. A
  // decimal text read as an Integer must come back as the same text (and as mpz_get_str's):
  // nines and zeros across every such edge, powers of two at limb edges, and random digits.
  const auto written = [](const Rational& x) {
    std::string text;
    relpos::detail::io::JsonWriter w(text);
    w.rational(x);
    return text;
  };
  std::vector<std::string> texts = {"0",
                                    "1",
                                    "9",
                                    "10",
                                    "99999999",
                                    "100000000",
                                    "1000000000000000000",
                                    "9999999999999999999",
                                    "10000000000000000000",
                                    "10000000000000000001",
                                    "18446744073709551615",
                                    "18446744073709551616",
                                    "18446744073709551617",
                                    "99999999999999999999",
                                    "100000000000000000000000000000000000000",
                                    "340282366920938463463374607431768211455",
                                    "340282366920938463463374607431768211456"};
  for (int digits = 1; digits <= 1300; digits += digits < 80 ? 1 : 37) {  // 1300 digits: beyond 64 limbs
    texts.push_back("1" + std::string(digits, '0'));                      // 10^digits
    texts.push_back(std::string(digits, '9'));                            // 10^digits - 1
    texts.push_back("1" + std::string(digits, '0') + "1");                // zeros inside the chunks
  }
  relpos::Integer power(1);
  for (int bits = 0; bits <= 64 * 70; ++bits, power = power * relpos::Integer(2))  // 2^bits and its neighbours
    if (bits % 64 <= 1 || bits % 64 == 63)
      for (const relpos::Integer& z : {power - 1, power, power + 1}) texts.push_back(relpos::to_string(Rational(z)));
  std::mt19937_64 rng(64);
  for (int trial = 0; trial < 2000; ++trial) {  // random digits, with runs of 0 and 9
    std::string t(1, static_cast<char>('1' + rng() % 9));
    const std::size_t length = rng() % (trial < 1900 ? 120 : 1400);
    while (t.size() < length)
      t.append(rng() % 8 + 1, "0987654321"[rng() % 4 == 0 ? 0 : rng() % 3 == 0 ? 1 : rng() % 10]);
    texts.push_back(t);
  }
  for (const std::string& t : texts) {
    CAPTURE(t);
    const relpos::Integer z(t);
    REQUIRE(written(Rational(z)) == "\"" + t + "\"");
    REQUIRE(relpos::to_string(Rational(z)) == t);  // the text is GMP's
    if (z != 0) REQUIRE(written(Rational(-z)) == "\"-" + t + "\"");
    const Rational third(relpos::Integer(3), z * 2 + 1);  // a denominator of the same size
    REQUIRE(written(third) == "\"" + relpos::to_string(third) + "\"");
  }
  // A denominator whose lowest limb is 1 is not 1: 1/(2^64 + 1) keeps its denominator.
  const Rational tiny(relpos::Integer(1), relpos::Integer("18446744073709551617"));
  CHECK(written(tiny) == "\"1/18446744073709551617\"");
  CHECK(written(Rational(-7)) == "\"-7\"");
}

TEST_CASE("tight_interval_of_quotient is tight_interval of the reduced fraction, bit for bit", "[certificate]") {
  // Doubles (a point), dyadics beyond 53 bits, general rationals, subnormal and huge values, of
  // either sign, each written as n / d with a common factor c (even, odd, long) that the function
  // must not need removed.
  std::mt19937_64 bits(2718);
  auto uniform = [&](long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(bits); };
  for (int trial = 0; trial < 20000; ++trial) {
    const double x =
        std::ldexp(std::uniform_real_distribution<double>(-1, 1)(bits), static_cast<int>(uniform(-1100, 1100)));
    const double d = std::isfinite(x) && x != 0 ? x : 0.75;
    Rational value;
    switch (trial % 4) {
      case 0:
        value = Rational(d);
        break;
      case 1:
        value = Rational(d) + Rational(relpos::Integer(1), relpos::Integer(1) << 200);
        break;
      case 2:
        value = Rational(relpos::Integer(uniform(-(1L << 60), 1L << 60)), relpos::Integer(uniform(1, 1L << 60)));
        break;
      default:
        value = Rational(relpos::Integer(uniform(1, 1000)), relpos::Integer(3)) * Rational(d);
    }
    relpos::Integer c(uniform(1, 1L << 40));
    if (trial % 3 == 0) c = c << static_cast<unsigned long>(uniform(0, 90));
    if (trial % 5 == 0) c = c * c * c;
    const relpos::Integer n = value.numerator() * c, den = value.denominator() * c;
    CAPTURE(relpos::to_string(value), relpos::to_string(c));
    const std::pair<double, double> got = relpos::detail::anysize::tight_interval_of_quotient(n.mpz(), den.mpz()),
                                    want = relpos::detail::forms::tight_interval(value);
    CHECK(got.first == want.first);
    CHECK(got.second == want.second);
  }
}

TEST_CASE("an irrational lambda_s: a reduced on first use, the enclosure as from the reduced a", "[certificate]") {
  // s = s2 (l - r1)(l - r2) + t with two negative roots and an irrational discriminant; its
  // coefficients are dyadic (as from doubles) or general rationals. lambda_s = a + b sqrt(d) with
  // a = -s1 / (2 s2), and [lo, hi] the interval sum of the tight enclosures of a, b and sqrt(d).
  using relpos::detail::anysize::LambdaS;
  using relpos::detail::anysize::QuadraticReal;
  using I = CGAL::Interval_nt<false>;
  std::mt19937_64 bits(1618);
  auto uniform = [&](long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(bits); };
  int irrational = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const bool dyadic = trial % 2 == 0;
    auto coefficient = [&](long lo, long hi) {
      const long den = dyadic ? 1L << uniform(0, 60) : uniform(1, 1L << 40);
      return Rational(relpos::Integer(uniform(lo, hi)), relpos::Integer(den)) * Rational(1L << uniform(0, 20));
    };
    const Rational s2 = coefficient(1, 1L << 50), s1 = coefficient(1, 1L << 50);
    // s0 in (0, s1^2 / (4 s2)): two negative roots.
    const Rational s0 = s1 * s1 / (4 * s2) * rat(uniform(1, 999), 1000);
    const relpos::detail::anysize::Poly s{s0, s1, s2};
    const LambdaS ls = relpos::detail::anysize::lambda_s_of(s);
    if (ls.rational()) continue;
    ++irrational;
    {
      // Between irrational ones, a rational lambda_s = r1 (s = s2 (l - r1)(l - r2), r2 < r1 < 0): the
      // numbers an irrational lambda_s wrote must not show through (each LambdaS starts blank).
      const Rational r1 = -coefficient(1, 1L << 30), r2 = r1 - coefficient(1, 1L << 30);
      const LambdaS rl = relpos::detail::anysize::lambda_s_of({s2 * r1 * r2, -s2 * (r1 + r2), s2});
      CHECK(rl.rational());
      CHECK(rl.d == 0);
      CHECK(rl.value().a == r1);
      CHECK(rl.value().b == 0);
      CHECK(Rational(rl.lo) <= r1);
      CHECK(r1 <= Rational(rl.hi));
    }
    CAPTURE(relpos::to_string(s0), relpos::to_string(s1), relpos::to_string(s2));
    // The enclosure first (before value() reduces a), then the exact value.
    const double lo = ls.lo, hi = ls.hi;
    const QuadraticReal& v = ls.value();
    CHECK(v.a == -s1 / (2 * s2));
    const Rational disc = s1 * s1 - 4 * s2 * s0;
    CHECK(v.b * v.b * Rational(ls.d) == disc / (4 * s2 * s2));  // b sqrt(d) = sqrt(disc) / (2 s2)
    CHECK(ls.sign({v.a - Rational(lo), v.b}) >= 0);
    CHECK(ls.sign({v.a - Rational(hi), v.b}) <= 0);
    CGAL::Protect_FPU_rounding<true> guard;
    const I want = I(relpos::detail::forms::tight_interval(v.a)) +
                   I(relpos::detail::forms::tight_interval(v.b)) * CGAL::sqrt(I(CGAL::to_interval(ls.d)));
    CHECK(lo == want.inf());
    CHECK(hi == want.sup());
  }
  CHECK(irrational > 2000);
}

TEST_CASE("full evidence on a thread does not depend on the calls before it", "[certificate]") {
  // classify keeps per-thread integers between calls (written in place unless a callee kept a
  // copy): each report, certificate included, must be the one a fresh thread gives. Pairs of
  // doubles (spheres and general ellipsoids near a cup, every position) and of exact rationals.
  std::mt19937_64 bits(4242);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(bits); };
  std::vector<std::pair<Ellipsoid, Paraboloid>> pairs;
  for (int k = 0; k < 120; ++k) {
    relpos::DoubleMatrix4 p{}, e{};
    const double a = uniform(0.5, 2), b = uniform(0.5, 2);
    p[0] = 1 / (a * a), p[5] = 1 / (b * b), p[11] = p[14] = -0.5;
    const double c[3] = {uniform(-0.5, 0.5), uniform(-0.5, 0.5), uniform(-0.2, 0.8)}, r = uniform(0.05, 0.4);
    double m[3][3] = {{1 / (r * r), 0, 0}, {0, 1 / (r * r), 0}, {0, 0, 1 / (r * r)}};
    if (k % 2) {  // a general ellipsoid: the sphere's block plus a symmetric perturbation
      for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) m[i][j] = m[j][i] = m[i][j] + uniform(-0.2, 0.2) / (r * r);
    }
    double e0 = -1;
    for (int i = 0; i < 3; ++i) {
      double mc = 0;
      for (int j = 0; j < 3; ++j) {
        e[static_cast<std::size_t>(4 * i + j)] = m[i][j];
        mc += m[i][j] * c[j];
      }
      e[static_cast<std::size_t>(4 * i + 3)] = e[static_cast<std::size_t>(12 + i)] = -mc;
      e0 += mc * c[i];
    }
    e[15] = e0;
    try {
      pairs.emplace_back(Ellipsoid::from_doubles(e), Paraboloid::from_doubles(p));
    } catch (const std::exception&) {  // a perturbed block that is not positive definite
    }
    pairs.emplace_back(sphere(rat(k % 7 - 2, 3), rat(1 + k % 5, 4)), cup());
  }
  std::vector<std::string> sequential;
  for (const auto& [e, p] : pairs)
    sequential.push_back(relpos::io::classification_json_text(relpos::classify(e, p, relpos::Evidence::Full)));
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    std::string alone;
    std::thread([&] {
      alone = relpos::io::classification_json_text(
          relpos::classify(pairs[i].first, pairs[i].second, relpos::Evidence::Full));
    }).join();
    CAPTURE(i);
    CHECK(alone == sequential[i]);
  }
  CHECK(pairs.size() > 200);
}
