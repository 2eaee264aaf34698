// Positions and certificates at the edges of scale and nearness (support/edge_cases.hpp): every pair
// has its position by construction; the answer of classify must be it, and its certificate must pass
// the library's verifier and, independently, a rational check written here (C: the two points in
// both quadrics; E, I: the leading minors of lambda P + E; TE, TI: the contact point on both surfaces
// and in the kernel of lambda P + E).
#include <catch2/catch.hpp>
#include <relpos/classify.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/edge_cases.hpp"
#include "support/scale.hpp"

namespace {

using namespace rt;
using namespace rt::edges;
using relpos::Certificate;
using Kind = relpos::Certificate::Kind;

/// X^T Q X for X = (x, 1).
Rational form(const Matrix4& q, const Vector3& x) {
  Rational acc = q(3, 3);
  for (int i = 0; i < 3; ++i) {
    acc += 2 * q(i, 3) * x[static_cast<std::size_t>(i)];
    for (int j = 0; j < 3; ++j) acc += x[static_cast<std::size_t>(i)] * q(i, j) * x[static_cast<std::size_t>(j)];
  }
  return acc;
}

/// The leading k x k minor, by cofactor expansion on a copy.
Rational leading_minor(const Matrix4& m, int k) {
  if (k == 4) return det4(m);
  Matrix4 padded;  // the k x k block, completed by the identity: same determinant
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) padded(i, j) = (i < k && j < k) ? m(i, j) : Rational(i == j ? 1 : 0);
  return det4(padded);
}

/// The signs relpos normalizes to: E's 3x3 block positive definite, P's of positive trace.
Matrix4 normalized(const Matrix4& m, bool ellipsoid) {
  const bool flip = ellipsoid ? m(0, 0) < 0 : m(0, 0) + m(1, 1) + m(2, 2) < 0;
  return flip ? scaled(m, Rational(-1)) : m;
}

/// The independent check of the certificate; empty when it proves `expected`.
std::string own_check(const Matrix4& e_in, const Matrix4& p_in, Position expected, const Certificate& c) {
  const Matrix4 e = normalized(e_in, true), p = normalized(p_in, false);
  switch (expected) {
    case Position::C: {
      if (c.kind != Kind::Crossing) return "not a crossing certificate";
      if (form(e, c.inside) > 0 || form(p, c.inside) >= 0) return "inside point wrong";
      if (form(e, c.outside) > 0 || form(p, c.outside) <= 0) return "outside point wrong";
      return "";
    }
    case Position::E:
    case Position::I: {
      if (c.kind != Kind::Definite) return "not a definite certificate";
      if ((c.lambda > 0) != (expected == Position::E) || c.lambda == 0) return "lambda of the wrong sign";
      const Matrix4 k = [&] {
        Matrix4 out;
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) out(i, j) = c.lambda * p(i, j) + e(i, j);
        return out;
      }();
      for (int n = 1; n <= 4; ++n)
        if (leading_minor(k, n) <= 0) return "leading minor " + std::to_string(n) + " not positive";
      return "";
    }
    case Position::TE:
    case Position::TI: {
      if (c.kind == Kind::HardTangent) return "";  // irrational lambda_s: the verifier's Q(sqrt d) check
      if (c.kind != Kind::Tangent) return "not a tangent certificate";
      if ((c.lambda > 0) != (expected == Position::TE) || c.lambda == 0) return "lambda of the wrong sign";
      if (form(e, c.contact) != 0 || form(p, c.contact) != 0) return "contact point not on both surfaces";
      for (int i = 0; i < 4; ++i) {
        Rational row(0);
        for (int j = 0; j < 4; ++j) row += (c.lambda * p(i, j) + e(i, j)) * (j < 3 ? c.contact[j] : Rational(1));
        if (row != 0) return "contact point not in the kernel of lambda P + E";
      }
      return "";
    }
  }
  return "unknown position";
}

struct Tally {
  int checked = 0, failed = 0;
  std::ostringstream first;
  void run(const EdgeCase& c) {
    ++checked;
    const relpos::Ellipsoid e = relpos::Ellipsoid::from_matrix(c.e);
    const relpos::Paraboloid p = relpos::Paraboloid::from_matrix(c.p);
    const relpos::Classification got = relpos::classify(e, p);
    std::string why;
    if (got.verdict.position != c.expected)
      why = "position " + relpos::to_string(got.verdict.position) + ", expected " + relpos::to_string(c.expected);
    else if (const auto reason = relpos::verify_certificate(e, p, c.expected, got.certificate))
      why = "verifier: " + *reason;
    else
      why = own_check(c.e, c.p, c.expected, got.certificate);
    if (why.empty()) return;
    if (failed++ < 5) first << c.family << ": " << why << "\n";
  }
};

void check_all(const std::vector<EdgeCase>& cases) {
  Tally t;
  for (const EdgeCase& c : cases) t.run(c);
  INFO(t.first.str());
  CHECK(t.checked == static_cast<int>(cases.size()));
  CHECK(t.failed == 0);
}

const int kScales[] = {-30, -15, -3, 0, 3, 15, 30};
const int kShifts[] = {0, 6, 15, 30};

}  // namespace

TEST_CASE("spheres near contact at 1e-3 ... 1e-100 under similarities of scale 1e-30 ... 1e30 and affine maps") {
  Rng g(2101);
  std::vector<EdgeCase> cases;
  // One round under AddressSanitizer (support/scale.hpp).
  for (int round = 0; round < (relpos::testing::kSanitizerShare == 1 ? 2 : 1); ++round)
    for (const EdgeCase& c : spheres_near_contact(g)) {
      cases.push_back(c);
      for (int s : kScales) {
        const int shift = kShifts[g.uniform(0, 3)];
        cases.push_back(similar(g, c, pow10(s), pow10(s + shift), "moved (scale 1e" + std::to_string(s) + ")"));
        if (round == 0) cases.push_back(affine(g, c, pow10(s), pow10(shift), "under an affine map"));
      }
    }
  check_all(cases);
}

TEST_CASE("extreme rotated ellipsoids near contact: axes 1e-4 ... 1e3, cups 1e-3 ... 1e3, offsets up to 1e15") {
  Rng g(2102);
  std::vector<EdgeCase> cases;
  const std::vector<std::pair<Vector3, std::pair<Rational, Rational>>> shapes = {
      {{pow10(-4), pow10(-4) * 3, pow10(-4) * 2}, {Q(1), Q(2)}},
      {{pow10(-4), Q(1), pow10(3)}, {Q(1), Q(1)}},
      {{Q(1), Q(2), Q(3)}, {pow10(-3), pow10(-3) * 2}},
      {{pow10(3), pow10(3) * 2, pow10(2)}, {pow10(3), pow10(3) / 2}},
      {{pow10(-2), pow10(2), Q(1)}, {pow10(-3), pow10(3)}},
      {{pow10(3), pow10(-4), pow10(-4) * 5}, {pow10(2), pow10(-1)}}};
  for (const auto& sh : shapes)
    for (const EdgeCase& c : ellipsoids_near_contact(g, sh.first, sh.second.first, sh.second.second)) {
      cases.push_back(c);
      cases.push_back(similar(g, c, Q(1), pow10(static_cast<int>(g.uniform(0, 15))), "translated"));
    }
  check_all(cases);
}

TEST_CASE("bodies of size 1e-15 ... 1e-40 centred on the surface, in place and far away") {
  Rng g(2103);
  std::vector<EdgeCase> cases;
  for (int k = 15; k <= 40; ++k)
    for (const EdgeCase& c : tiny_on_surface(g, k)) {
      cases.push_back(c);
      cases.push_back(similar(g, c, Q(1), pow10(6), "translated by 1e6"));
      cases.push_back(similar(g, c, pow10(30), pow10(30), "scaled by 1e30"));
    }
  check_all(cases);
}

TEST_CASE("the sphere resting in the cup, lowered or raised by 1e-5 ... 1e-100") {
  Rng g(2104);
  std::vector<EdgeCase> cases;
  for (const Rational& eps : {pow10(-5), pow10(-12), pow10(-20), pow10(-40), pow10(-80), pow10(-100), pow2(-130)})
    for (const EdgeCase& c : sphere_in_cup(eps)) {
      cases.push_back(c);
      cases.push_back(similar(g, c, pow10(-3), pow10(6), "scaled by 1e-3, translated by 1e6"));
      cases.push_back(affine(g, c, pow10(20), pow10(30), "under an affine map, translated by 1e30"));
    }
  check_all(cases);
}

TEST_CASE("spheres touching along a circle (the hard case) or 1e-3 ... 1e-100 from it, at scales 1e-30 ... 1e30") {
  Rng g(2106);
  std::vector<EdgeCase> cases;
  for (const Rational& d : nearness()) {
    const Rational a = Q(g.uniform(1, 3)), h = a * a * Q(g.uniform(3, 6), 4);  // h > a^2 / 2
    for (const EdgeCase& c : sphere_on_circle(a, h, d)) {
      cases.push_back(c);
      for (int s : kScales) cases.push_back(similar(g, c, pow10(s), pow10(s + 6), "moved"));
    }
  }
  check_all(cases);
}

TEST_CASE("ordinary pairs around a tangency scaled by 1e-3 and translated by 1e6, or 1e-6 and 1e3") {
  Rng g(2105);
  std::vector<EdgeCase> cases;
  for (int i = 0; i < 40; ++i) {
    const Rational a = Q(g.uniform(1, 4)), b = Q(g.uniform(1, 4));
    const TangentPoint tp = touch_point(g, a, b);
    for (const Config& k : tangency_family(tp, random_tangent_radius(g, a, b), g.uniform(1, 7))) {
      const EdgeCase c{k.name, k.e(), k.p(), k.expected};
      cases.push_back(similar(g, c, pow10(-3), pow10(6), "scaled by 1e-3, translated by 1e6"));
      cases.push_back(similar(g, c, pow10(-6), pow10(3), "scaled by 1e-6, translated by 1e3"));
    }
  }
  check_all(cases);
}
