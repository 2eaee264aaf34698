// The general Quadric (include/relpos/general_quadric.hpp; math.md §14): the geometric forms and
// their types, the sign normalization (more positive than negative eigenvalues in B, the sign as
// given on a tie), the refusal of degenerate and imaginary quadrics naming what they are, and the
// solids {q <= 0} at points known to be inside or outside.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "general/decision.hpp"
#include "relpos/error.hpp"
#include "relpos/general_quadric.hpp"
#include "support/construct.hpp"
#include "support/general_cases.hpp"
#include "support/seed.hpp"

using namespace relpos;
using namespace relpos::testing;
using rt::form_value;

namespace {

/// (positive, negative) eigenvalues of B, the test's own: the three real roots of the characteristic
/// polynomial by the trigonometric formula in long double (these matrices are small and well
/// conditioned), an eigenvalue below 1e-9 of the largest counted as zero.
std::pair<int, int> inertia_of(const Matrix4& q) {
  long double b[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b[i][j] = static_cast<long double>(CGAL::to_double(q(i, j)));
  const long double tr = b[0][0] + b[1][1] + b[2][2];
  const long double mean = tr / 3;
  long double s[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s[i][j] = b[i][j] - (i == j ? mean : 0);
  long double p2 = 0;
  for (auto& row : s)
    for (long double x : row) p2 += x * x;
  const long double p = std::sqrt(p2 / 6);
  std::array<long double, 3> ev{mean, mean, mean};
  if (p > 0) {
    long double m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = s[i][j] / p;
    const long double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                            m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    const long double phi = std::acos(std::max(-1.0L, std::min(1.0L, det / 2))) / 3;
    const long double pi = 3.14159265358979323846264338327950288L;
    ev = {mean + 2 * p * std::cos(phi), mean + 2 * p * std::cos(phi + 2 * pi / 3),
          mean + 2 * p * std::cos(phi + 4 * pi / 3)};
  }
  long double top = 0;
  for (long double x : ev) top = std::max(top, std::fabs(x));
  int positive = 0, negative = 0;
  for (long double x : ev) {
    if (x > top * 1e-9L) ++positive;
    if (x < -top * 1e-9L) ++negative;
  }
  return {positive, negative};
}

struct Form {
  const char* name;
  Quadric q;
  QuadricType type;
  std::vector<Vector3> inside, outside;
};

std::vector<Form> all_forms() {
  const Rational one(1), two(2), h(1, 2);
  const Vector3 c{Rational(1), Rational(-2), Rational(3)};
  const Quaternion rot{Rational(1), Rational(2), Rational(-1), Rational(3)};
  const Matrix3 r = rotation_from_quaternion(rot);
  // A point c + R u for local coordinates u.
  auto at = [&](const Vector3& u) {
    Vector3 x;
    for (int i = 0; i < 3; ++i) {
      Rational s = c[static_cast<std::size_t>(i)];
      for (int j = 0; j < 3; ++j) s += r(i, j) * u[static_cast<std::size_t>(j)];
      x[static_cast<std::size_t>(i)] = s;
    }
    return x;
  };
  const Vector3 axis_far{0, 0, 5}, side_far{5, 0, 0}, centre{0, 0, 0}, below{0, 0, -1}, y_far{0, 5, 0};
  return {
      {"sphere", Quadric::sphere(c, two), QuadricType::Ellipsoid, {c}, {at(side_far)}},
      {"ellipsoid", Quadric::ellipsoid(c, {one, two, h}, rot), QuadricType::Ellipsoid, {c}, {at(side_far)}},
      {"hyperboloid of one sheet",
       Quadric::hyperboloid_one_sheet(c, {one, two, h}, rot),
       QuadricType::HyperboloidOneSheet,
       {c, at(axis_far)},
       {at(side_far)}},
      {"hyperboloid of two sheets",
       Quadric::hyperboloid_two_sheets(c, {one, two, h}, rot),
       QuadricType::HyperboloidTwoSheets,
       {at(axis_far), at({0, 0, -5})},
       {c, at(side_far)}},
      {"cone", Quadric::cone(c, one, two, rot), QuadricType::Cone, {at(axis_far), at({0, 0, -5})}, {at(side_far)}},
      {"elliptic paraboloid",
       Quadric::elliptic_paraboloid(c, one, two, rot),
       QuadricType::EllipticParaboloid,
       {at(axis_far)},
       {at(below), at(side_far)}},
      {"hyperbolic paraboloid",
       Quadric::hyperbolic_paraboloid(c, one, two, rot),
       QuadricType::HyperbolicParaboloid,
       {at(axis_far), at(y_far)},
       {at(below), at(side_far)}},
      {"elliptic cylinder",
       Quadric::elliptic_cylinder(c, one, two, rot),
       QuadricType::EllipticCylinder,
       {c, at(axis_far)},
       {at(side_far)}},
      {"hyperbolic cylinder",
       Quadric::hyperbolic_cylinder(c, one, two, rot),
       QuadricType::HyperbolicCylinder,
       {c, at(y_far), at(axis_far)},
       {at(side_far)}},
      {"parabolic cylinder",
       Quadric::parabolic_cylinder(c, one, rot),
       QuadricType::ParabolicCylinder,
       {at(axis_far), at({0, 9, 5})},
       {at(below), at(side_far)}},
      {"slab",
       Quadric::slab({1, 2, 2}, Rational(-3), Rational(6)),
       QuadricType::Slab,
       {{0, 0, 0}, {0, 1, 1}},
       {{0, 0, 4}, {0, 0, -2}}},
      {"half-space",
       Quadric::half_space({1, 2, 2}, Rational(3)),
       QuadricType::HalfSpace,
       {{0, 0, 0}, {-9, 0, 0}},
       {{0, 0, 2}}},
  };
}

}  // namespace

TEST_CASE("general quadric: every form has its type, its solid, and survives from_matrix", "[general]") {
  for (const Form& f : all_forms()) {
    INFO(f.name);
    CHECK(f.q.type() == f.type);
    for (const Vector3& x : f.inside) CHECK(form_value(f.q.matrix(), x) < 0);
    for (const Vector3& x : f.outside) CHECK(form_value(f.q.matrix(), x) > 0);
    const Quadric again = Quadric::from_matrix(f.q.matrix());
    CHECK(again.type() == f.type);
    CHECK(again.matrix() == f.q.matrix());
    // A negated matrix: normalized back, unless the type keeps the sign as given (then the solid is
    // the complement's closure, and the inside points are outside).
    const Quadric negated = Quadric::from_matrix(scaled_matrix(f.q.matrix(), Rational(-3)));
    CHECK(negated.type() == f.type);
    if (sign_as_given(f.type)) {
      for (const Vector3& x : f.inside) CHECK(form_value(negated.matrix(), x) > 0);
    } else {
      CHECK(negated.matrix() == scaled_matrix(f.q.matrix(), Rational(3)));
    }
    const auto [p, n] = inertia_of(f.q.matrix());
    CHECK(p >= n);
    // The same from doubles (every entry of these matrices is a double or not: compared on rationals).
    if (const auto d = f.q.doubles()) CHECK(Quadric::from_doubles(*d).matrix() == f.q.matrix());
  }
}

TEST_CASE("general quadric: types and normalization under random congruences and scalings", "[general]") {
  std::mt19937_64 rng(announced_seed("general quadric congruences", 14));
  std::uniform_int_distribution<int> sd(1, 9);
  for (const Form& f : all_forms())
    for (int round = 0; round < 8; ++round) {
      INFO(f.name << " round " << round);
      const AffineMap m = random_map(rng, round % 2 == 1);
      const Quadric mapped = Quadric::from_map(f.q, m.l, m.t);
      CHECK(mapped.type() == f.type);
      const Rational s(sd(rng) * (round % 3 == 0 ? -1 : 1), sd(rng));
      const Quadric q = Quadric::from_matrix(scaled_matrix(mapped.matrix(), s));
      CHECK(q.type() == f.type);
      const auto [p, n] = inertia_of(q.matrix());
      CHECK(p >= n);
      // Points mapped along: inside stays inside (the sign flips with s only where it is kept).
      const bool flipped = s < 0 && sign_as_given(f.type);
      for (const Vector3& u : f.inside) {
        Vector3 x;
        for (int i = 0; i < 3; ++i) {
          Rational acc = m.t[static_cast<std::size_t>(i)];
          for (int j = 0; j < 3; ++j) acc += m.l(i, j) * u[static_cast<std::size_t>(j)];
          x[static_cast<std::size_t>(i)] = acc;
        }
        CHECK(CGAL::sign(form_value(q.matrix(), x)) == (flipped ? 1 : -1));
      }
    }
}

TEST_CASE("general quadric: degenerate and imaginary quadrics are refused, naming what they are", "[general]") {
  auto diag = [](int a, int b, int c, int d) {
    Matrix4 m;
    m(0, 0) = Rational(a);
    m(1, 1) = Rational(b);
    m(2, 2) = Rational(c);
    m(3, 3) = Rational(d);
    return m;
  };
  Matrix4 plane_only;  // z = 0 twice: no linear part
  plane_only(2, 2) = Rational(1);
  Matrix4 constant;
  constant(3, 3) = Rational(5);
  Matrix4 not_symmetric = diag(1, 1, 1, -1);
  not_symmetric(0, 1) = Rational(1);
  const std::vector<std::pair<Matrix4, std::string>> refused{
      {diag(1, 1, 1, 1), "imaginary ellipsoid"},
      {diag(1, 1, 1, 0), "single point"},
      {diag(1, 1, 0, 1), "imaginary elliptic cylinder"},
      {diag(1, 1, 0, 0), "line"},
      {diag(1, -1, 0, 0), "intersecting planes"},
      {diag(1, 0, 0, 1), "imaginary parallel planes"},
      {plane_only, "double plane"},
      {constant, "no quadratic and no linear part"},
      {not_symmetric, "not symmetric"},
  };
  for (const auto& [m, what] : refused) {
    INFO(what);
    try {
      static_cast<void>(Quadric::from_matrix(m));
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find(what) != std::string::npos);
    }
  }
  CHECK_THROWS_AS(Quadric::sphere({0, 0, 0}, Rational(-1)), InputError);
  CHECK_THROWS_AS(Quadric::cone({0, 0, 0}, Rational(0), Rational(1)), InputError);
  CHECK_THROWS_AS(Quadric::half_space({0, 0, 0}, Rational(1)), InputError);
  CHECK_THROWS_AS(Quadric::slab({0, 0, 1}, Rational(1), Rational(1)), InputError);
  CHECK_THROWS_AS(Quadric::from_map(Quadric::sphere({0, 0, 0}, Rational(1)), Matrix3{}, {0, 0, 0}), InputError);
}

TEST_CASE("general quadric: an Ellipsoid and a Paraboloid as quadrics", "[general]") {
  const Ellipsoid e = Ellipsoid::from_axes(Vector3{1, 2, 3}, Vector3{1, 2, 3}, Quaternion{1, 1, 0, 0});
  const Paraboloid p = Paraboloid::standard(Vector3{0, 1, 0}, Rational(1), Rational(2), Quaternion{1, 0, 1, 0});
  CHECK(Quadric::of(e).type() == QuadricType::Ellipsoid);
  CHECK(Quadric::of(e).matrix() == e.matrix());
  CHECK(Quadric::of(p).type() == QuadricType::EllipticParaboloid);
  CHECK(Quadric::of(p).matrix() == p.matrix());
  CHECK(Quadric::from_matrix(p.matrix()).matrix() == p.matrix());
  for (QuadricType t : detail::general::kAllQuadricTypes) CHECK(!to_string(t).empty());
}
