// The filtered type test of a matrix of doubles (src/algebra/kind_filter.hpp): whenever it answers,
// its answer is classify_quadric's, on every type it can name under random congruences and scales,
// on rounded rotated paraboloids (rank 2 lost) and rounded far ellipsoids (definiteness lost), with
// one-ulp perturbations; it declines singular blocks, zero leading minors, non-symmetric and
// non-finite matrices. And from_doubles refuses with the exact path's message.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <relpos/error.hpp>
#include <relpos/quadric.hpp>

#include "algebra/kind_filter.hpp"
#include "support/seed.hpp"

using namespace relpos;

namespace {

Matrix4 exact(const DoubleMatrix4& d) {
  Matrix4 m;
  for (std::size_t k = 0; k < 16; ++k) m.a[k] = exact_rational(d[k]);
  return m;
}

/// H^T diag(s) H in doubles for a random H: a symmetric matrix of the inertia of diag(s), rounded.
DoubleMatrix4 congruent(const std::array<double, 4>& s, std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  double h[4][4];
  for (auto& row : h)
    for (double& x : row) x = u(rng);
  for (int i = 0; i < 3; ++i) h[i][3] = 0;  // keep the affine structure: the last column (0, 0, 0, 1)
  h[3][3] = 1;
  for (int j = 0; j < 3; ++j) h[3][j] = scale * u(rng);  // a translation
  DoubleMatrix4 m{};
  for (int i = 0; i < 4; ++i)
    for (int j = i; j < 4; ++j) {
      double v = 0;
      for (int k = 0; k < 4; ++k) v += h[k][i] * s[static_cast<std::size_t>(k)] * h[k][j];
      m[static_cast<std::size_t>(4 * i + j)] = m[static_cast<std::size_t>(4 * j + i)] = v;
    }
  return m;
}

}  // namespace

TEST_CASE("certified_kind answers only with classify_quadric's type", "[kind_filter]") {
  std::mt19937_64 rng(testing::announced_seed("kind_filter", 5));
  const std::array<double, 4> signatures[] = {{1, 1, 1, -1},   {1, 1, 1, 1},     {1, 1, -1, 1}, {1, 1, -1, -1},
                                              {-1, -1, -1, 1}, {1, 1, 0, -1},    {1, 0, 0, -1}, {1, 1, -1, 0},
                                              {1, 1, 1, 0},    {1e-17, 1, 1, -1}};
  int answered = 0;
  for (int round = 0; round < 400; ++round)
    for (const auto& s : signatures) {
      DoubleMatrix4 m = congruent(s, rng, round % 2 ? 1 : 1e6);
      if (round % 3 == 0) m[15] = std::nextafter(m[15], 1e300);  // one ulp
      const std::optional<QuadricKind> k = detail::shape_filter::certified_kind(m);
      if (!k) continue;
      ++answered;
      CHECK(*k == classify_quadric(exact(m)));
    }
  CHECK(answered > 2000);
  // Declined: a zero leading entry, a singular block, asymmetry, a NaN.
  CHECK(!detail::shape_filter::certified_kind({0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1}));
  CHECK(!detail::shape_filter::certified_kind({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0}));
  CHECK(!detail::shape_filter::certified_kind({1, 1e-300, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1}));
  CHECK(!detail::shape_filter::certified_kind({NAN, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1}));
}

TEST_CASE("from_doubles refuses a rounded rotated paraboloid with the exact path's message", "[kind_filter]") {
  // The paraboloid of a = 1, b = 2 rotated by the quaternion (1, 2, 3, 4), its matrix rounded: the
  // block keeps no exact zero eigenvalue, so the doubles describe an ellipsoid or a hyperboloid.
  const Matrix4 exact_p = Paraboloid::standard({Rational(0), Rational(0), Rational(0)}, Rational(1), Rational(2),
                                               {Rational(1), Rational(2), Rational(3), Rational(4)})
                              .matrix();
  DoubleMatrix4 d;
  for (std::size_t k = 0; k < 16; ++k) d[k] = CGAL::to_double(exact_p.a[k]);
  std::string fast, slow;
  try {
    Paraboloid::from_doubles(d);
  } catch (const InputError& e) {
    fast = e.what();
  }
  try {
    Paraboloid::from_matrix(exact(d));
  } catch (const InputError& e) {
    slow = e.what();
  }
  REQUIRE(!slow.empty());
  CHECK(fast == slow);
  CHECK(detail::shape_filter::certified_kind(d).has_value());
}
