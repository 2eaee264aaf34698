// Every input that is not an ellipsoid / elliptic paraboloid pair gets relpos::InputError with a
// message that names what was found (math.md §1).
#include <pthread.h>

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <relpos/algebraic_real.hpp>
#include <relpos/classify.hpp>
#include <relpos/contact.hpp>
#include <relpos/error.hpp>
#include <relpos/motion.hpp>
#include <relpos/numbers.hpp>
#include <relpos/position.hpp>
#include <relpos/quadric.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "algebra/pair_size.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;
using Catch::Matchers::Contains;
using relpos::Ellipsoid;
using relpos::InputError;
using relpos::Paraboloid;

namespace {

struct Bad {
  const char* equation;
  Matrix4 m;
  const char* name;  ///< what the message must say
};

Matrix4 with_linear(Matrix4 m, int i, const Rational& v) {
  set_sym(m, i, 3, v / 2);
  return m;
}

/// Quadrics that are neither an ellipsoid nor an elliptic paraboloid, with the name of their type.
std::vector<Bad> bad_quadrics() {
  const Rational one(1), zero(0), m1(-1);
  return {
      {"hyperboloid of one sheet x^2+y^2-z^2=1", diag4(one, one, m1, m1), "hyperboloid of one sheet"},
      {"hyperboloid of two sheets x^2+y^2-z^2=-1", diag4(one, one, m1, one), "hyperboloid of two sheets"},
      {"cone x^2+y^2=z^2", diag4(one, one, m1, zero), "cone"},
      {"elliptic cylinder x^2+2y^2=1", diag4(one, Q(2), zero, m1), "elliptic cylinder"},
      {"hyperbolic cylinder x^2-y^2=1", diag4(one, m1, zero, m1), "hyperbolic cylinder"},
      {"parabolic cylinder x^2=z", with_linear(diag4(one, zero, zero, zero), 2, m1), "parabolic cylinder"},
      {"imaginary ellipsoid x^2+y^2+z^2=-1", diag4(one, one, one, one), "imaginary ellipsoid"},
      {"point x^2+y^2+z^2=0", diag4(one, one, one, zero), "point"},
      {"hyperbolic paraboloid x^2-y^2=z", with_linear(diag4(one, m1, zero, zero), 2, m1), "hyperbolic paraboloid"},
      {"imaginary elliptic cylinder x^2+y^2=-1", diag4(one, one, zero, one), "imaginary elliptic cylinder"},
      {"line x^2+y^2=0", diag4(one, one, zero, zero), "line"},
      {"intersecting planes x^2=y^2", diag4(one, m1, zero, zero), "intersecting planes"},
      {"parallel planes x^2=1", diag4(one, zero, zero, m1), "parallel planes"},
      {"imaginary parallel planes x^2=-1", diag4(one, zero, zero, one), "imaginary parallel planes"},
      {"double plane x^2=0", diag4(one, zero, zero, zero), "double plane"},
      {"plane z=0", with_linear(Matrix4{}, 2, one), "plane"},
      {"zero matrix", Matrix4{}, "without quadratic terms"},
  };
}

}  // namespace

TEST_CASE("non-ellipsoids are rejected with their type named", "[errors][quadric]") {
  for (const auto& b : bad_quadrics()) {
    CAPTURE(b.equation);
    CHECK_THROWS_AS(Ellipsoid::from_matrix(b.m), InputError);
    CHECK_THROWS_WITH(Ellipsoid::from_matrix(b.m), Contains(b.name));
    CHECK_THROWS_WITH(Ellipsoid::from_matrix(scaled(b.m, Q(-2))), Contains(b.name));
    CHECK_THROWS_WITH(Ellipsoid::from_matrix(b.m), Contains("not an ellipsoid"));
  }
}

TEST_CASE("non-paraboloids are rejected with their type named", "[errors][quadric]") {
  for (const auto& b : bad_quadrics()) {
    CAPTURE(b.equation);
    CHECK_THROWS_AS(Paraboloid::from_matrix(b.m), InputError);
    CHECK_THROWS_WITH(Paraboloid::from_matrix(b.m), Contains(b.name));
    CHECK_THROWS_WITH(Paraboloid::from_matrix(scaled(b.m, Q(-3))), Contains(b.name));
    CHECK_THROWS_WITH(Paraboloid::from_matrix(b.m), Contains("not an elliptic paraboloid"));
  }
}

TEST_CASE("the type is named after any affine congruence too", "[errors][quadric][random]") {
  const std::uint64_t seed = 0xE770;
  Rng g(seed);
  CAPTURE(seed);
  for (int round = 0; round < 5; ++round)
    for (const auto& b : bad_quadrics()) {
      CAPTURE(round, b.equation);
      const Matrix4 m = scaled(congruence(b.m, random_congruence(g).h), g.nonzero_rational(-5, 5, 3));
      CHECK_THROWS_WITH(Ellipsoid::from_matrix(m), Contains(b.name));
      CHECK_THROWS_WITH(Paraboloid::from_matrix(m), Contains(b.name));
    }
}

TEST_CASE("paraboloid and ellipsoid swapped", "[errors][quadric]") {
  const Matrix4 p = paraboloid_matrix(Q(1), Q(2));
  const Matrix4 e = sphere_matrix({Q(0), Q(0), Q(1)}, Q(1, 2));
  CHECK_THROWS_AS(Ellipsoid::from_matrix(p), InputError);
  CHECK_THROWS_WITH(Ellipsoid::from_matrix(p), Contains("swapped") && Contains("elliptic paraboloid"));
  CHECK_THROWS_AS(Paraboloid::from_matrix(e), InputError);
  CHECK_THROWS_WITH(Paraboloid::from_matrix(e), Contains("swapped") && Contains("ellipsoid"));
  // Also through the coefficient constructors and after congruences.
  relpos::Coefficients10 pc{Q(1), Q(1, 4), Q(0), Q(0), Q(0), Q(0), Q(0), Q(0), Q(-1), Q(0)};
  CHECK_THROWS_WITH(Ellipsoid::from_coefficients(pc), Contains("swapped"));
  Rng g(0xE771);
  for (int i = 0; i < 10; ++i) {
    const Matrix4 h = random_congruence(g).h;
    CHECK_THROWS_WITH(Ellipsoid::from_matrix(congruence(p, h)), Contains("swapped"));
    CHECK_THROWS_WITH(Paraboloid::from_matrix(congruence(e, h)), Contains("swapped"));
  }
}

TEST_CASE("rank-deficient matrices are rejected", "[errors][quadric][random]") {
  // B^T D B with D = diag(d1, d2, d3, 0) has rank <= 3 whatever B: never an ellipsoid (det = 0)
  // nor an elliptic paraboloid (det != 0 required).
  Rng g(0xE772);
  for (int i = 0; i < 40; ++i) {
    Matrix4 b;
    for (auto& v : b.a) v = g.rational(-4, 4, 2);
    const Matrix4 d = diag4(g.rational(-3, 3, 1), g.rational(-3, 3, 1), g.rational(-3, 3, 1), Q(0));
    const Matrix4 m = congruence(d, b);
    CAPTURE(i);
    REQUIRE(det4(m) == 0);
    CHECK_THROWS_AS(Ellipsoid::from_matrix(m), InputError);
    CHECK_THROWS_AS(Paraboloid::from_matrix(m), InputError);
  }
}

TEST_CASE("non-symmetric matrices are rejected", "[errors][quadric]") {
  Matrix4 e = sphere_matrix({Q(0), Q(0), Q(0)}, Q(1));
  e(0, 1) = Q(1, 3);  // e(1, 0) stays 0
  CHECK_THROWS_AS(Ellipsoid::from_matrix(e), InputError);
  CHECK_THROWS_WITH(Ellipsoid::from_matrix(e), Contains("not symmetric"));
  CHECK_THROWS_WITH(relpos::classify_quadric(e), Contains("not symmetric"));
  Matrix4 p = paraboloid_matrix(Q(1), Q(1));
  p(3, 2) = Q(1, 2);  // p(2, 3) = -1/2
  CHECK_THROWS_AS(Paraboloid::from_matrix(p), InputError);
  CHECK_THROWS_WITH(Paraboloid::from_matrix(p), Contains("not symmetric"));
}

TEST_CASE("non-finite doubles and malformed number text", "[errors][numbers]") {
  CHECK_THROWS_AS(relpos::exact_rational(std::numeric_limits<double>::quiet_NaN()), InputError);
  CHECK_THROWS_AS(relpos::exact_rational(std::numeric_limits<double>::infinity()), InputError);
  CHECK_THROWS_AS(relpos::exact_rational(-std::numeric_limits<double>::infinity()), InputError);
  for (const char* bad : {"1.2.3", "1/0", "", "abc", "1e", "0x10"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(relpos::parse_rational(bad), InputError);
    if (*bad) CHECK_THROWS_WITH(relpos::parse_rational(bad), Contains(bad));
  }
}

TEST_CASE("InputError is the one exception type and an std::invalid_argument", "[errors]") {
  try {
    Ellipsoid::from_matrix(diag4(Q(1), Q(1), Q(-1), Q(-1)));
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("hyperboloid of one sheet") != std::string::npos);
    CHECK(dynamic_cast<const InputError*>(&e) != nullptr);
  }
}

// ---- API misuse ---------------------------------------------------------------------------------

TEST_CASE("AlgebraicReal::refine rejects a width that is not positive", "[errors][api]") {
  auto sqrt2 = relpos::AlgebraicReal::root({Integer(-2), Integer(0), Integer(1)}, Rational(1), Rational(2));
  CHECK_THROWS_AS(sqrt2.refine(Rational(0)), std::invalid_argument);
  CHECK_THROWS_AS(sqrt2.refine(Rational(-1)), std::invalid_argument);
  auto half = relpos::AlgebraicReal::rational(Rational(1, 2));
  CHECK_THROWS_AS(half.refine(Rational(0)), std::invalid_argument);
  sqrt2.refine(Rational(1, 1000));  // a positive width still works
  CHECK(sqrt2.upper() - sqrt2.lower() <= Rational(1, 1000));
}

TEST_CASE("An empty Timeline throws instead of crashing", "[errors][api]") {
  const relpos::Timeline empty{};
  CHECK_THROWS_AS(empty.position_at(Rational(0)), InputError);
}

TEST_CASE("Doubles reach the constructors only through exact_rational", "[errors][api]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(Ellipsoid::sphere({0, 0, nan}, 0.25), InputError);
  CHECK_THROWS_AS(Ellipsoid::sphere({0, 0, 1}, inf), InputError);
  CHECK_THROWS_AS(Ellipsoid::sphere({0, 0, 1}, nan), InputError);
  const std::array<double, 3> centre{0, 0, 1}, axes{1, nan, 1};
  const std::array<double, 4> identity{1, 0, 0, 0};
  CHECK_THROWS_AS(Ellipsoid::from_axes(centre, axes, identity), InputError);
  CHECK_THROWS_AS(Paraboloid::standard({0, 0, -inf}, 1.0, 1.0), InputError);
  CHECK_THROWS_AS(Paraboloid::standard({0, 0, 0}, 1.0, 1.0, {1, nan, 0, 0}), InputError);
  // Finite doubles are taken exactly.
  const Ellipsoid s = Ellipsoid::sphere({0, 0, 1.5}, 0.25);
  CHECK(s.matrix()(2, 3) == Rational(-3, 2));
  CHECK(s.matrix()(3, 3) == Rational(9, 4) - Rational(1, 16));
  const Paraboloid p = Paraboloid::standard({0, 0, 0}, 1.0, 2.0);
  CHECK(p.matrix() == Paraboloid::standard({Rational(0), Rational(0), Rational(0)}, Rational(1), Rational(2)).matrix());
}

TEST_CASE("The size limit reads each matrix divided by its own content", "[errors][size]") {
  // Two matrices rescaled independently by 10^1000 and 10^-1000: the common-lcm form is huge, each
  // normalized form is tiny.
  Rational big(1), small(1);
  for (int i = 0; i < 1000; ++i) big *= 10;
  small = Rational(1) / big;
  Matrix4 e = sphere_matrix({Q(0), Q(0), Q(1)}, Q(1, 2)), p;
  p(0, 0) = p(1, 1) = Q(1);
  p(2, 3) = p(3, 2) = Q(-1, 2);
  for (auto& x : e.a) x *= big;
  for (auto& x : p.a) x *= small;
  const Ellipsoid es = Ellipsoid::from_matrix(e);
  const Paraboloid ps = Paraboloid::from_matrix(p);
  CHECK(relpos::detail::normalized_pair_bits(es, ps) <= 8);
  CHECK_NOTHROW(relpos::detail::check_normalized_pair_size(es, ps));
  // A genuinely large entry is refused with a message naming the limit.
  Rational huge(1);
  for (int i = 0; i < 4200; ++i) huge *= 2;
  Matrix4 e2 = sphere_matrix({Q(0), Q(0), Q(1)}, Q(1, 2));
  e2(3, 3) += Rational(1) / huge;
  const Ellipsoid e2s = Ellipsoid::from_matrix(e2);
  CHECK(relpos::detail::normalized_pair_bits(e2s, ps) > relpos::kMaxNormalizedBits);
  CHECK_THROWS_WITH(relpos::detail::check_normalized_pair_size(e2s, ps), Contains("kMaxNormalizedBits"));
  // The library's entry points enforce it themselves (a C++ caller gets the CLI's limit) ...
  CHECK_THROWS_WITH(relpos::classify(e2s, ps), Contains("kMaxNormalizedBits"));
  CHECK_THROWS_WITH(relpos::classify_exact(e2s, ps, relpos::Evidence::Minimal), Contains("kMaxNormalizedBits"));
  CHECK_THROWS_WITH(relpos::decide_position(e2s, ps), Contains("kMaxNormalizedBits"));
  // ... and answer the independently rescaled pair, whose own forms are tiny.
  CHECK(relpos::decide_position(es, ps).position == relpos::classify_exact(es, ps).verdict.position);
}

TEST_CASE("The size limit can be raised, not lowered, and a raised limit answers as within it", "[errors][size]") {
  // The sphere of radius 1/2 at (0, 0, 1) in z = x^2 + y^2 (I), its constant lowered by 2^-4200:
  // a 4200-bit primitive form, beyond the default, and the same position (an open condition).
  Matrix4 p;
  p(0, 0) = p(1, 1) = Q(1);
  p(2, 3) = p(3, 2) = Q(-1, 2);
  const Paraboloid cup = Paraboloid::from_matrix(p);
  Rational huge(1);
  for (int i = 0; i < 4200; ++i) huge *= 2;
  Matrix4 e = sphere_matrix({Q(0), Q(0), Q(1)}, Q(1, 2));
  e(3, 3) -= Rational(1) / huge;
  const Ellipsoid big = Ellipsoid::from_matrix(e);
  const Ellipsoid plain = Ellipsoid::from_matrix(sphere_matrix({Q(0), Q(0), Q(1)}, Q(1, 2)));
  const std::size_t bits = relpos::detail::normalized_pair_bits(big, cup);
  REQUIRE(bits > relpos::kMaxNormalizedBits);
  CHECK_THROWS_WITH(relpos::classify(big, cup), Contains("beyond the limit of 4096 bits (kMaxNormalizedBits"));
  const relpos::SizeLimit raised{bits};
  CHECK(relpos::detail::check_normalized_pair_size(big, cup, raised) == bits);
  CHECK_THROWS_WITH(relpos::detail::check_normalized_pair_size(big, cup, relpos::SizeLimit{bits - 1}),
                    Contains("beyond the limit of " + std::to_string(bits - 1) + " bits (the limit given"));
  const relpos::Classification c = relpos::classify(big, cup, relpos::Evidence::Full, raised);
  CHECK(c.verdict.position == relpos::classify(plain, cup).verdict.position);
  CHECK(relpos::verify_certificate(big, cup, c.verdict.position, c.certificate) == std::nullopt);
  CHECK(relpos::classify_exact(big, cup, relpos::Evidence::Minimal, raised).verdict.position == c.verdict.position);
  CHECK(relpos::decide_position(big, cup, raised).position == c.verdict.position);
  CHECK(relpos::contact(big, cup, raised).position == c.verdict.position);
  CHECK_THROWS_WITH(relpos::contact(big, cup), Contains("kMaxNormalizedBits"));
  // Lowering is refused, whatever the pair.
  CHECK_THROWS_WITH(relpos::detail::check_normalized_pair_size(plain, cup, relpos::SizeLimit{100}),
                    Contains("it can be raised, not lowered"));
}

TEST_CASE("A pair beyond the default limit is classified on a stack of its own", "[errors][size]") {
  // Roots of f 10^-1200 apart (the sphere at (0, 0, 1) of radius 1/4 in the circular cup has the
  // double root -1 of f; a perturbation of 10^-1200 splits it): CGAL's root isolation recurses
  // about 4000 levels, more than a 256 KiB thread stack holds. The library runs such a pair on a
  // thread whose stack fits it (algebra/large_stack.hpp), whatever the caller's stack.
  Rational tiny(1);
  for (int i = 0; i < 1200; ++i) tiny /= 10;
  Matrix4 p;
  p(0, 0) = p(1, 1) = Q(1);
  p(2, 3) = p(3, 2) = Q(-1, 2);
  const Paraboloid cup = Paraboloid::from_matrix(p);
  const Ellipsoid e =
      Ellipsoid::from_matrix(sphere_matrix({tiny / Q(3), tiny / Q(7), Q(1) + tiny / Q(11)}, Q(1, 4) + tiny / Q(13)));
  const relpos::SizeLimit raised{relpos::detail::normalized_pair_bits(e, cup)};
  REQUIRE(raised.max_bits > relpos::kMaxNormalizedBits);
  struct Job {
    const Ellipsoid* e;
    const Paraboloid* p;
    relpos::SizeLimit limit;
    std::optional<relpos::Position> position;
  } job{&e, &cup, raised, std::nullopt};
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, std::size_t(256) << 10);
  pthread_t thread;
  REQUIRE(pthread_create(
              &thread, &attr,
              [](void* arg) -> void* {
                Job& j = *static_cast<Job*>(arg);
                j.position = relpos::classify(*j.e, *j.p, relpos::Evidence::Full, j.limit).verdict.position;
                return nullptr;
              },
              &job) == 0);
  pthread_join(thread, nullptr);
  pthread_attr_destroy(&attr);
  // Inside the cup (the sphere at height 1 of radius about 1/4 is far from the wall): I.
  CHECK(job.position == relpos::Position::I);
}
