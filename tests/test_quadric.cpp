// quadric.hpp: exact affine types (quadric_kind.cpp), constructors (quadric.cpp), sign
// normalization, affine invariance of the type; the size limit's primitive form (pair_size.cpp)
// invariant under rescaling; the centre of an ellipsoid and exact 3x3 systems (centre.hpp,
// cramer.hpp). The storage and the constructors from doubles: test_from_doubles.
#include <gmp.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <relpos/error.hpp>
#include <relpos/quadric.hpp>
#include <string>
#include <vector>

#include "algebra/centre.hpp"
#include "algebra/coefficients.hpp"
#include "algebra/cramer.hpp"
#include "algebra/pair_size.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using relpos::classify_quadric;
using relpos::Ellipsoid;
using relpos::Paraboloid;
using relpos::QuadricKind;
using namespace rt;

namespace {

struct KindCase {
  const char* equation;
  Matrix4 m;
  QuadricKind kind;
};

/// One representative of every affine type, written from its textbook equation.
std::vector<KindCase> all_kinds() {
  auto linear = [](Matrix4 m, int i, const Rational& v) {  // add the linear term v x_i
    set_sym(m, i, 3, v / 2);
    return m;
  };
  const Rational one(1), zero(0), m1(-1);
  return {
      {"x^2+y^2+z^2-1", diag4(one, one, one, m1), QuadricKind::Ellipsoid},
      {"x^2+y^2+z^2+1", diag4(one, one, one, one), QuadricKind::ImaginaryEllipsoid},
      {"x^2+y^2+z^2", diag4(one, one, one, zero), QuadricKind::Point},
      {"x^2+y^2-z^2-1", diag4(one, one, m1, m1), QuadricKind::HyperboloidOneSheet},
      {"x^2+y^2-z^2+1", diag4(one, one, m1, one), QuadricKind::HyperboloidTwoSheets},
      {"x^2+y^2-z^2", diag4(one, one, m1, zero), QuadricKind::Cone},
      {"x^2+y^2-z", linear(diag4(one, one, zero, zero), 2, m1), QuadricKind::EllipticParaboloid},
      {"x^2-y^2-z", linear(diag4(one, m1, zero, zero), 2, m1), QuadricKind::HyperbolicParaboloid},
      {"x^2+y^2-1", diag4(one, one, zero, m1), QuadricKind::EllipticCylinder},
      {"x^2+y^2+1", diag4(one, one, zero, one), QuadricKind::ImaginaryEllipticCylinder},
      {"x^2+y^2", diag4(one, one, zero, zero), QuadricKind::Line},
      {"x^2-y^2-1", diag4(one, m1, zero, m1), QuadricKind::HyperbolicCylinder},
      {"x^2-y^2", diag4(one, m1, zero, zero), QuadricKind::IntersectingPlanes},
      {"x^2-z", linear(diag4(one, zero, zero, zero), 2, m1), QuadricKind::ParabolicCylinder},
      {"x^2-1", diag4(one, zero, zero, m1), QuadricKind::ParallelPlanes},
      {"x^2+1", diag4(one, zero, zero, one), QuadricKind::ImaginaryParallelPlanes},
      {"x^2", diag4(one, zero, zero, zero), QuadricKind::DoublePlane},
      {"z", linear(Matrix4{}, 2, one), QuadricKind::NotQuadratic},
      {"0", Matrix4{}, QuadricKind::NotQuadratic},
  };
}

}  // namespace

TEST_CASE("classify_quadric: every affine type from its normal form", "[quadric]") {
  for (const auto& k : all_kinds()) {
    CAPTURE(k.equation);
    CHECK(classify_quadric(k.m) == k.kind);
    CHECK(classify_quadric(scaled(k.m, Rational(-3, 7))) == k.kind);  // the sign of the equation is irrelevant
  }
}

TEST_CASE("classify_quadric: the same type at every scale (decided on the primitive integer form)", "[quadric]") {
  Rational big(1);
  for (int i = 0; i < 300; ++i) big *= 10;
  for (const auto& k : all_kinds()) {
    CAPTURE(k.equation);
    // Integer forms with a common factor (6, 10^300: each entry, its mirror too, divided once) and
    // rational ones (10^-300, 7/10^300): the type of each is that of the normal form.
    for (const Rational& s : {Rational(6), big, Rational(1) / big, Rational(-7) / big, -big * Rational(5, 3)})
      CHECK(classify_quadric(scaled(k.m, s)) == k.kind);
  }
}

TEST_CASE("classify_quadric: the type is invariant under random affine congruences", "[quadric][random]") {
  const std::uint64_t seed = 0x51C0FFEE;
  Rng g(seed);
  CAPTURE(seed);
  for (int round = 0; round < 12; ++round)
    for (const auto& k : all_kinds()) {
      Congruence h = random_congruence(g);
      CAPTURE(round, k.equation);
      CHECK(classify_quadric(scaled(congruence(k.m, h.h), g.nonzero_rational(-5, 5, 3))) == k.kind);
    }
}

TEST_CASE("from_matrix (filtered shape test) accepts exactly the ellipsoids and paraboloids", "[quadric][random]") {
  // The interval filter decides most matrices; the exact inertia the rest. Every type, random
  // congruences and scales of either sign, and near-degenerate ones (the constant term moved by
  // +-10^-30, which turns a point, a cone or a cylinder into a neighbouring type).
  Rng g(0xF17E2ED);
  const Rational tiny(Integer(1), Integer("1000000000000000000000000000000"));
  int ellipsoids = 0, paraboloids = 0;
  for (int round = 0; round < 10; ++round)
    for (const auto& k : all_kinds())
      for (int nudge = -1; nudge <= 1; ++nudge) {
        Matrix4 m = scaled(congruence(k.m, random_congruence(g).h), g.nonzero_rational(-5, 5, 3));
        m(3, 3) += nudge * tiny;
        CAPTURE(round, k.equation, nudge);
        const QuadricKind kind = classify_quadric(m);
        if (kind == QuadricKind::Ellipsoid) {
          ++ellipsoids;
          const Ellipsoid e = Ellipsoid::from_matrix(m);
          CHECK(e.matrix() == (m(0, 0) > 0 ? m : scaled(m, Rational(-1))));
        } else {
          CHECK_THROWS_AS(Ellipsoid::from_matrix(m), relpos::InputError);
        }
        if (kind == QuadricKind::EllipticParaboloid) {
          ++paraboloids;
          const Paraboloid q = Paraboloid::from_matrix(m);
          CHECK(q.matrix() == (m(0, 0) + m(1, 1) + m(2, 2) > 0 ? m : scaled(m, Rational(-1))));
        } else {
          CHECK_THROWS_AS(Paraboloid::from_matrix(m), relpos::InputError);
        }
      }
  CHECK(ellipsoids >= 20);
  CHECK(paraboloids >= 20);
}

TEST_CASE("to_string(QuadricKind): the names the error messages use", "[quadric]") {
  CHECK(relpos::to_string(QuadricKind::Ellipsoid) == "ellipsoid");
  CHECK(relpos::to_string(QuadricKind::EllipticParaboloid) == "elliptic paraboloid");
  CHECK(relpos::to_string(QuadricKind::HyperboloidOneSheet) == "hyperboloid of one sheet");
  CHECK(relpos::to_string(QuadricKind::HyperboloidTwoSheets) == "hyperboloid of two sheets");
  CHECK(relpos::to_string(QuadricKind::HyperbolicParaboloid) == "hyperbolic paraboloid");
  // Every kind has a distinct, non-empty name.
  std::vector<std::string> names;
  for (const auto& k : all_kinds()) names.push_back(relpos::to_string(k.kind));
  names.pop_back();  // NotQuadratic appears twice in all_kinds()
  for (std::size_t i = 0; i < names.size(); ++i) {
    CHECK(!names[i].empty());
    for (std::size_t j = i + 1; j < names.size(); ++j) CHECK(names[i] != names[j]);
  }
}

TEST_CASE("matrix_from_coefficients halves the cross and linear terms", "[quadric]") {
  // 2x^2 + 3y^2 + 5z^2 + 4xy - 6xz + 8yz + 10x - 12y + 14z - 7
  relpos::Coefficients10 c{Q(2), Q(3), Q(5), Q(4), Q(-6), Q(8), Q(10), Q(-12), Q(14), Q(-7)};
  Matrix4 m = relpos::detail::matrix_from_coefficients(c);
  Matrix4 want = diag4(Q(2), Q(3), Q(5), Q(-7));
  set_sym(want, 0, 1, Q(2));
  set_sym(want, 0, 2, Q(-3));
  set_sym(want, 1, 2, Q(4));
  set_sym(want, 0, 3, Q(5));
  set_sym(want, 1, 3, Q(-6));
  set_sym(want, 2, 3, Q(7));
  CHECK(m == want);
}

TEST_CASE("rotation_from_quaternion: exact rotations", "[quadric]") {
  Rng g(4242);
  for (int i = 0; i < 50; ++i) {
    Quaternion q = random_quaternion(g, 5);
    Matrix3 r = relpos::rotation_from_quaternion(q);
    // R^T R = I and det R = 1, exactly.
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        Rational s(0);
        for (int k = 0; k < 3; ++k) s += r(k, a) * r(k, b);
        CHECK(s == Rational(a == b ? 1 : 0));
      }
    CHECK(det3(r) == 1);
    // Same as the formula written out in the test support; the scale of q is irrelevant.
    Matrix3 mine = rotation(q);
    Quaternion q3{3 * q[0], 3 * q[1], 3 * q[2], 3 * q[3]};
    Matrix3 r3 = relpos::rotation_from_quaternion(q3);
    for (std::size_t k = 0; k < 9; ++k) {
      CHECK(r.a[k] == mine.a[k]);
      CHECK(r.a[k] == r3.a[k]);
    }
  }
  // A quarter turn about z: (cos 45, 0, 0, sin 45) ~ (1, 0, 0, 1) maps x to y.
  Matrix3 r = relpos::rotation_from_quaternion({Q(1), Q(0), Q(0), Q(1)});
  CHECK(r(0, 0) == 0);
  CHECK(r(1, 0) == 1);
  CHECK(r(0, 1) == -1);
  CHECK(r(2, 2) == 1);
  CHECK_THROWS_AS(relpos::rotation_from_quaternion({Q(0), Q(0), Q(0), Q(0)}), relpos::InputError);
}

TEST_CASE("Ellipsoid constructors agree with hand-built matrices", "[quadric]") {
  const Vector3 c{Q(1, 2), Q(-3), Q(7, 4)};
  const Rational r(3, 5);
  Matrix4 want = sphere_matrix(c, r);
  CHECK(Ellipsoid::sphere(c, r).matrix() == want);
  CHECK(Ellipsoid::from_matrix(want).matrix() == want);
  CHECK(Ellipsoid::from_matrix(scaled(want, Q(-5, 2))).matrix() == scaled(want, Q(5, 2)));  // -Q is normalized
  // x^2 + y^2 + z^2 - x + 6y - 7/2 z + ... as coefficients.
  relpos::Coefficients10 co{Q(1), Q(1), Q(1), Q(0), Q(0), Q(0), -2 * c[0], -2 * c[1], -2 * c[2], want(3, 3)};
  CHECK(Ellipsoid::from_coefficients(co).matrix() == want);
  // Semi-axes r, r, r along any rotation: the unit-ball image is the sphere divided by r^2.
  Rng g(99);
  for (int i = 0; i < 10; ++i) {
    Quaternion q = random_quaternion(g);
    CHECK(Ellipsoid::from_axes(c, {r, r, r}, q).matrix() == scaled(want, 1 / (r * r)));
    CHECK(Ellipsoid::from_axes(c, {r, r, r}, rotation(q)).matrix() == scaled(want, 1 / (r * r)));
  }
  CHECK(Ellipsoid::from_map(c, diag3(r, r, -r)).matrix() == scaled(want, 1 / (r * r)));
  // Axis-aligned ellipsoid (x/2)^2 + (y/3)^2 + (z/5)^2 = 1.
  Matrix4 axes = diag4(Q(1, 4), Q(1, 9), Q(1, 25), Q(-1));
  CHECK(Ellipsoid::from_axes({Q(0), Q(0), Q(0)}, {Q(2), Q(3), Q(5)}, Quaternion{Q(1), Q(0), Q(0), Q(0)}).matrix() ==
        axes);
  CHECK(Ellipsoid::from_map({Q(0), Q(0), Q(0)}, diag3(Q(2), Q(3), Q(5))).matrix() == axes);
}

TEST_CASE("sphere and standard paraboloid entries: the rational operations' canonical values", "[quadric][random]") {
  // Decimal-like denominators (2s and 5s) and others, shared or not, of both signs: the constant
  // |c|^2 - r^2 and the entries 1/a^2, 1/b^2 as rational arithmetic gives them, in lowest terms.
  Rng g(4711);
  auto same = [](const Rational& x, const Rational& y) {
    return mpz_cmp(mpq_numref(x.mpq()), mpq_numref(y.mpq())) == 0 &&
           mpz_cmp(mpq_denref(x.mpq()), mpq_denref(y.mpq())) == 0;
  };
  const long dens[] = {1, 2, 5, 10, 1000, 3, 7, 12, 625, 1024, 99991};
  auto number = [&](bool positive) {
    const Rational x(Integer(g.uniform(positive ? 1 : -100000, 100000)), Integer(dens[g.uniform(0, 10)]));
    return x * Rational(Integer(1), Integer(dens[g.uniform(0, 10)]));
  };
  for (int i = 0; i < 500; ++i) {
    const Vector3 c{number(false), number(false), number(false)};
    const Rational r = number(true);
    CAPTURE(relpos::to_string(c[0]), relpos::to_string(c[1]), relpos::to_string(c[2]), relpos::to_string(r));
    CHECK(same(Ellipsoid::sphere(c, r).matrix()(3, 3), c[0] * c[0] + c[1] * c[1] + c[2] * c[2] - r * r));
    const Rational a = number(true), b = number(true);
    const Paraboloid para = Paraboloid::standard({Q(0), Q(0), Q(0)}, a, b);
    const Matrix4& p = para.matrix();
    CHECK(same(p(0, 0), Rational(1) / (a * a)));
    CHECK(same(p(1, 1), Rational(1) / (b * b)));
  }
}

TEST_CASE("Ellipsoid normalization: positive definite block, negative determinant", "[quadric]") {
  Rng g(1234);
  for (int i = 0; i < 40; ++i) {
    Congruence h = random_congruence(g);
    Matrix4 e = scaled(congruence(sphere_matrix({Q(1), Q(2), Q(3)}, Q(1, 2)), h.h), g.nonzero_rational(-9, 9, 4));
    Ellipsoid el = Ellipsoid::from_matrix(e);
    const Matrix4& m = el.matrix();
    CHECK(m(0, 0) > 0);
    CHECK(m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0) > 0);
    CHECK(det4(m) < 0);
    CHECK((m == e || m == scaled(e, Q(-1))));
  }
}

TEST_CASE("Paraboloid constructors agree with hand-built matrices", "[quadric]") {
  const Rational a(6, 5), b(3, 2);
  const Matrix4 want = paraboloid_matrix(a, b);
  CHECK(Paraboloid::standard({Q(0), Q(0), Q(0)}, a, b).matrix() == want);
  CHECK(Paraboloid::from_matrix(want).matrix() == want);
  CHECK(Paraboloid::from_matrix(scaled(want, Q(-2))).matrix() == scaled(want, Q(2)));
  CHECK(Paraboloid::from_map(diag3(a, b, Q(1)), {Q(0), Q(0), Q(0)}).matrix() == want);
  relpos::Coefficients10 co{1 / (a * a), 1 / (b * b), Q(0), Q(0), Q(0), Q(0), Q(0), Q(0), Q(-1), Q(0)};
  CHECK(Paraboloid::from_coefficients(co).matrix() == want);
  // With a vertex and a rotation: the pull-back by x = R u + v of the standard matrix.
  Rng g(5);
  for (int i = 0; i < 20; ++i) {
    Quaternion q = random_quaternion(g);
    Vector3 v{g.rational(-5, 5, 3), g.rational(-5, 5, 3), g.rational(-5, 5, 3)};
    Matrix4 p = Paraboloid::standard(v, a, b, q).matrix();
    // x^T P x = 0 at the vertex, and at vertex + R (a, 0, 1) (a point of the standard surface).
    Matrix3 r = rotation(q);
    auto value = [&](const Vector3& x) {
      Rational s(0);
      for (int i2 = 0; i2 < 4; ++i2)
        for (int j = 0; j < 4; ++j)
          s += (i2 < 3 ? x[static_cast<std::size_t>(i2)] : Rational(1)) * p(i2, j) *
               (j < 3 ? x[static_cast<std::size_t>(j)] : Rational(1));
      return s;
    };
    CHECK(value(v) == 0);
    Vector3 on{v[0] + r(0, 0) * a + r(0, 2), v[1] + r(1, 0) * a + r(1, 2), v[2] + r(2, 0) * a + r(2, 2)};
    CHECK(value(on) == 0);
    // A point on the axis above the vertex is interior (negative), below is exterior.
    Vector3 in{v[0] + r(0, 2), v[1] + r(1, 2), v[2] + r(2, 2)};
    Vector3 out{v[0] - r(0, 2), v[1] - r(1, 2), v[2] - r(2, 2)};
    CHECK(value(in) < 0);
    CHECK(value(out) > 0);
    CHECK(det4(p) < 0);
    CHECK(p(0, 0) + p(1, 1) + p(2, 2) > 0);
  }
}

TEST_CASE("constructor arguments are validated", "[quadric][errors]") {
  using relpos::InputError;
  const Vector3 c{Q(0), Q(0), Q(0)};
  CHECK_THROWS_AS(Ellipsoid::sphere(c, Q(0)), InputError);
  CHECK_THROWS_AS(Ellipsoid::sphere(c, Q(-1)), InputError);
  CHECK_THROWS_AS(Ellipsoid::from_axes(c, {Q(1), Q(0), Q(1)}, Quaternion{Q(1), Q(0), Q(0), Q(0)}), InputError);
  CHECK_THROWS_AS(Ellipsoid::from_axes(c, {Q(1), Q(-2), Q(1)}, Quaternion{Q(1), Q(0), Q(0), Q(0)}), InputError);
  CHECK_THROWS_AS(Ellipsoid::from_map(c, diag3(Q(1), Q(0), Q(1))), InputError);
  Matrix3 not_orthogonal = identity3();
  not_orthogonal(0, 1) = Q(1, 1000);
  CHECK_THROWS_WITH(Ellipsoid::from_axes(c, {Q(1), Q(1), Q(1)}, not_orthogonal),
                    Catch::Matchers::Contains("orthogonal"));
  CHECK_THROWS_AS(Paraboloid::standard(c, Q(0), Q(1)), InputError);
  CHECK_THROWS_AS(Paraboloid::standard(c, Q(1), Q(-1)), InputError);
  CHECK_THROWS_AS(Paraboloid::standard(c, Q(1), Q(1), {Q(0), Q(0), Q(0), Q(0)}), InputError);
  CHECK_THROWS_AS(Paraboloid::from_map(diag3(Q(1), Q(1), Q(0)), c), InputError);
}

TEST_CASE("normalized_bits: the primitive integer form's bits, the same for every rescaling", "[quadric][size]") {
  // Computed here by another route: the matrix times the product of its denominators (not their
  // lcm), divided by the gcd of the resulting integers, which is the same primitive form up to sign.
  Rng g(4096);
  for (int trial = 0; trial < 400; ++trial) {
    Matrix4 m;
    for (auto& x : m.a)
      if (!g.chance(30)) x = g.rational(-1000, 1000, trial % 2 ? 97 : 1024);
    if (trial % 7 == 0) m.a[5] = Rational(Integer(1) << 300, Integer(g.uniform(1, 9)));
    Integer product(1);
    for (const Rational& x : m.a) product *= x.denominator();
    Integer content(0);
    std::array<Integer, 16> z;
    for (std::size_t i = 0; i < 16; ++i) {
      z[i] = m.a[i].numerator() * (product / m.a[i].denominator());
      mpz_gcd(content.mpz(), content.mpz(), z[i].mpz());
    }
    std::size_t want = 0;
    if (content != 0)
      for (const Integer& x : z)
        if (x != 0) want = std::max<std::size_t>(want, mpz_sizeinbase(Integer(x / content).mpz(), 2));
    CAPTURE(trial);
    CHECK(relpos::detail::normalized_bits(m) == want);
    Rational c = g.nonzero_rational(-50, 50, 50);
    if (trial % 3 == 0) c *= Rational(Integer(1) << 2000, Integer(3) << 10);  // far beyond the limit as a common form
    Matrix4 scaled;
    for (std::size_t i = 0; i < 16; ++i) scaled.a[i] = c * m.a[i];
    CHECK(relpos::detail::normalized_bits(scaled) == want);
  }
}

TEST_CASE("centre_of and solve_integer_system: exact solutions, nullopt when singular", "[quadric][random]") {
  // The centre of an ellipsoid built around a known centre is that centre; K x = r holds exactly for
  // the solution of a random integer system (Cramer's rule of cramer.hpp on integers); a singular K
  // gives nullopt.
  Rng g(3003);
  for (int trial = 0; trial < 200; ++trial) {
    const Vector3 c{g.rational(-9, 9, 7), g.rational(-9, 9, 7), g.rational(-9, 9, 7)};
    const Ellipsoid e = Ellipsoid::from_axes(
        c, {g.positive_rational(5, 3), g.positive_rational(5, 3), g.positive_rational(5, 3)}, random_quaternion(g));
    const auto centre = relpos::detail::centre_of(e.matrix());
    REQUIRE(centre.has_value());
    CHECK(*centre == c);
    Integer k[3][4];
    for (auto& row : k)
      for (auto& x : row) x = Integer(g.uniform(-20, 20));
    if (trial % 5 == 0)
      for (int j = 0; j < 4; ++j) k[2][j] = k[0][j] * 3 - k[1][j];  // row 2 = 3 row 0 - row 1: singular
    const Rational det = relpos::detail::det3<Rational>([&](int i, int j) { return Rational(k[i][j]); });
    const auto x = relpos::detail::solve_integer_system(k);
    CHECK(x.has_value() == (det != 0));
    if (!x) continue;
    for (int i = 0; i < 3; ++i)
      CHECK(Rational(k[i][0]) * (*x)[0] + Rational(k[i][1]) * (*x)[1] + Rational(k[i][2]) * (*x)[2] ==
            Rational(k[i][3]));
  }
}
