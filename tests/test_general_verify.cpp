// The independent verifier of general certificates (src/general/verify.cpp; math.md §18): every
// certificate of the constructed pairs is accepted, on the stored matrices and on negated ones
// (normalized by the verifier itself), and every tampered one -- a multiplier moved or of the wrong
// sign, a contact point or a crossing point moved, a contact set shrunk, a ratio changed, a
// certificate offered for another position -- is rejected with a reason.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "general/decision.hpp"
#include "relpos/general_classify.hpp"
#include "support/general_cases.hpp"

using namespace relpos;
using namespace relpos::testing;

namespace {

using K = QuadricCertificate::Kind;

/// Tampered copies of a certificate, each of which must be refused for the pair's position.
std::vector<std::pair<std::string, QuadricCertificate>> tampered(const QuadricCertificate& c) {
  std::vector<std::pair<std::string, QuadricCertificate>> out;
  auto add = [&](const std::string& what, auto change) {
    QuadricCertificate t = c;
    change(t);
    out.emplace_back(what, t);
  };
  const Rational tiny(1, 1000000);
  switch (c.kind) {
    case K::Definite:
      add("t negated", [](QuadricCertificate& t) { t.t = -t.t; });
      add("t zero", [](QuadricCertificate& t) { t.t = Rational(0); });
      add("t far", [](QuadricCertificate& t) { t.t *= Rational(1000000); });
      break;
    case K::Tangent:
      add("contact moved", [&](QuadricCertificate& t) { t.contact[0] += tiny; });
      add("t moved", [&](QuadricCertificate& t) { t.t += tiny; });
      add("t negated", [](QuadricCertificate& t) { t.t = -t.t; });
      break;
    case K::HardTangent:
      add("radius2 changed", [&](QuadricCertificate& t) { t.radius2.a += tiny; });
      add("centre moved", [&](QuadricCertificate& t) { t.centre[0].a += tiny; });
      add("t moved", [&](QuadricCertificate& t) { t.t_q.a += tiny; });
      if (!c.directions.empty()) {
        add("a direction dropped", [](QuadricCertificate& t) { t.directions.pop_back(); });
        add("a direction bent", [&](QuadricCertificate& t) {
          // Along a component every direction lacks (within the kernel a direction may move freely).
          std::size_t j = 0;
          auto zero_everywhere = [&](std::size_t col) {
            for (const QuadraticVector3& w : t.directions)
              if (w[col].a != 0 || w[col].b != 0) return false;
            return true;
          };
          while (j < 2 && !zero_everywhere(j)) ++j;
          t.directions[0][j].a += tiny;
        });
      }
      break;
    case K::Crossing:
      add("points swapped", [](QuadricCertificate& t) { std::swap(t.inside, t.outside); });
      add("inside point far away", [](QuadricCertificate& t) { t.inside[0] += Rational(1000); });
      if (c.beyond) {
        add("no point beyond", [](QuadricCertificate& t) { t.beyond.reset(); });
        add("beyond = inside", [](QuadricCertificate& t) { t.beyond = t.inside; });
      }
      break;
    case K::Equal:
      add("ratio changed", [&](QuadricCertificate& t) { t.ratio += tiny; });
      add("ratio negated", [](QuadricCertificate& t) { t.ratio = -t.ratio; });
      break;
    case K::None:
      break;
  }
  add("no certificate", [](QuadricCertificate& t) { t.kind = K::None; });
  return out;
}

}  // namespace

TEST_CASE("general verifier: genuine certificates pass, tampered ones are refused with a reason", "[general]") {
  int refused = 0;
  for (const GeneralCase& k : constructed_cases()) {
    INFO(k.name);
    const Ellipsoid e = Ellipsoid::from_matrix(k.e);
    const QuadricClassification c = classify(e, k.q);
    REQUIRE(c.verdict.position == k.expected);
    CHECK(verify_certificate(e, k.q, k.expected, c.certificate).value_or("verified") == "verified");
    // The verifier normalizes raw matrices itself: E negated, Q negated where its type is normalized.
    const Matrix4 qm = sign_as_given(k.q.type()) ? k.q.matrix() : scaled_matrix(k.q.matrix(), Rational(-1));
    CHECK(verify_certificate(scaled_matrix(e.matrix(), Rational(-1)), qm, k.expected, c.certificate)
              .value_or("verified") == "verified");
    for (const auto& [what, t] : tampered(c.certificate)) {
      INFO(what);
      const auto reason = verify_certificate(e, k.q, k.expected, t);
      CHECK(reason.has_value());
      if (reason) CHECK(!reason->empty());
      ++refused;
    }
    // The same evidence does not prove another position.
    for (QuadricPosition other : detail::general::kAllQuadricPositions)
      if (other != k.expected) CHECK(verify_certificate(e, k.q, other, c.certificate).has_value());
  }
  CHECK(refused > 200);
}
