// Ellipsoid/Paraboloid::from_doubles against from_matrix on the exact rationals of the same doubles:
// the same acceptance, the same InputError messages, the same stored matrices and the
// same positions, on random and degenerate matrices (rank-deficient blocks, one-ulp perturbations,
// asymmetry, non-finite entries, extreme exponents).
#include <catch2/catch.hpp>
#include <cfenv>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <relpos/classify.hpp>
#include <relpos/error.hpp>
#include <relpos/io.hpp>
#include <relpos/numbers.hpp>
#include <relpos/quadric.hpp>
#include <string>
#include <tuple>
#include <vector>

using relpos::DoubleMatrix4;
using relpos::Ellipsoid;
using relpos::InputError;
using relpos::Matrix4;
using relpos::Paraboloid;

namespace {

template <class Q>
struct Outcome {
  std::optional<Q> value;
  std::string message;
};

Matrix4 exact(const DoubleMatrix4& d) {
  Matrix4 m;
  for (std::size_t i = 0; i < 16; ++i) m.a[i] = relpos::exact_rational(d[i]);
  return m;
}

template <class Q, class F>
Outcome<Q> attempt(F make) {
  Outcome<Q> out;
  try {
    out.value.emplace(make());
  } catch (const InputError& err) {
    out.message = err.what();
  }
  return out;
}

/// Both constructions agree; returns the from_doubles object when it was accepted.
template <class Q>
std::optional<Q> agree(const DoubleMatrix4& d) {
  const Outcome<Q> fast = attempt<Q>([&] { return Q::from_doubles(d); });
  const Outcome<Q> slow = attempt<Q>([&] { return Q::from_matrix(exact(d)); });
  std::string shown;
  for (double x : d) shown += std::to_string(x) + " (" + std::to_string(std::ilogb(x)) + ") ";
  INFO("matrix: " << shown << "; from_doubles: " << fast.message << "; from_matrix: " << slow.message);
  REQUIRE(fast.value.has_value() == slow.value.has_value());
  CHECK(fast.message == slow.message);
  if (!fast.value) return std::nullopt;
  CHECK(fast.value->matrix() == slow.value->matrix());
  CHECK(fast.value->doubles() == slow.value->doubles());
  const relpos::DoubleMatrix4 *nf = storage_of(*fast.value).filter_doubles(),
                              *ns = storage_of(*slow.value).filter_doubles();
  REQUIRE((nf == nullptr) == (ns == nullptr));
  if (nf) CHECK(*nf == *ns);
  return fast.value;
}

struct Gen {
  std::mt19937_64 rng{20261124};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  int small(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  bool coin() { return small(0, 1) == 1; }

  /// A value of one of several kinds: a small integer, a dyadic, a random double, an extreme one.
  double entry() {
    switch (small(0, 5)) {
      case 0:
        return small(-3, 3);
      case 1:
        return std::ldexp(small(-50, 50), small(-8, 4));
      case 2:
        return uniform(-2, 2);
      case 3:
        return std::ldexp(uniform(-1, 1), small(-600, 600));
      default:
        return uniform(-0.1, 0.1);
    }
  }

  static void set(DoubleMatrix4& m, int i, int j, double v) {
    m[static_cast<std::size_t>(4 * i + j)] = v;
    m[static_cast<std::size_t>(4 * j + i)] = v;
  }

  DoubleMatrix4 symmetric() {
    DoubleMatrix4 m{};
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) set(m, i, j, entry());
    return m;
  }

  /// A sphere or axis-aligned ellipsoid in doubles, sometimes rounded so that it is not one.
  DoubleMatrix4 ellipsoid_like() {
    DoubleMatrix4 m{};
    const double c[3] = {uniform(-1, 1), uniform(-1, 1), uniform(-0.2, 1.5)};
    double e0 = -std::pow(uniform(0.01, 0.5), 2);
    for (int i = 0; i < 3; ++i) {
      const double a = coin() ? 1.0 : uniform(0.5, 4);
      set(m, i, i, a);
      set(m, i, 3, -a * c[i]);
      e0 += a * c[i] * c[i];
    }
    if (coin()) set(m, 0, 1, uniform(-0.3, 0.3));
    m[15] = e0;
    if (small(0, 9) == 0) m[15] = -m[15];  // imaginary or a point
    if (coin())
      for (double& x : m) x = -x;
    return m;
  }

  /// z = a x^2 + b y^2 after a rotation with rational (dyadic) entries, so the 3x3 block is exactly
  /// of rank 2 in doubles; sometimes one entry is moved by one ulp (then it is of rank 3).
  DoubleMatrix4 paraboloid_like() {
    DoubleMatrix4 m{};
    // u, v integer vectors: A = alpha u u^T + beta v v^T, exact in doubles for small integers.
    const int u[3] = {small(-3, 3), small(-3, 3), small(-3, 3)};
    const int v[3] = {small(-3, 3), small(-3, 3), small(-3, 3)};
    const double alpha = std::ldexp(1.0, small(-4, 4)), beta = std::ldexp(small(1, 7), small(-4, 4));
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) set(m, i, j, alpha * u[i] * u[j] + beta * v[i] * v[j]);
    for (int i = 0; i < 3; ++i) set(m, i, 3, coin() ? entry() : uniform(-1, 1));
    m[15] = coin() ? 0.0 : entry();
    if (small(0, 4) == 0) {
      const int k = small(0, 2);
      m[static_cast<std::size_t>(5 * k)] = std::nextafter(m[static_cast<std::size_t>(5 * k)], 10.0);
    }
    if (coin())
      for (double& x : m) x = -x;
    if (small(0, 3) == 0) {  // a common power-of-two scale, sometimes extreme
      const int s = small(-900, 900);
      for (double& x : m) x = std::ldexp(x, s);
    }
    return m;
  }

  /// The paper's regime: z = x^2/a^2 + y^2/b^2 and a small sphere near the cup, all doubles.
  std::pair<DoubleMatrix4, DoubleMatrix4> regime_pair() {
    DoubleMatrix4 p{}, e{};
    set(p, 0, 0, 1 / std::pow(uniform(0.5, 2), 2));
    set(p, 1, 1, 1 / std::pow(uniform(0.5, 2), 2));
    set(p, 2, 3, -0.5);
    const double c[3] = {uniform(-0.5, 0.5), uniform(-0.5, 0.5), uniform(-0.1, 0.6)};
    const double r = uniform(0.01, 0.4);
    double e0 = -r * r;
    for (int i = 0; i < 3; ++i) {
      set(e, i, i, 1.0);
      set(e, i, 3, -c[i]);
      e0 += c[i] * c[i];
    }
    e[15] = e0;
    return {e, p};
  }
};

}  // namespace

TEST_CASE("from_doubles accepts and rejects exactly as from_matrix", "[from_doubles]") {
  Gen g;
  int accepted_e = 0, accepted_p = 0;
  for (int k = 0; k < 3000; ++k) {
    const DoubleMatrix4 a = g.ellipsoid_like(), b = g.paraboloid_like(), c = g.symmetric();
    for (const DoubleMatrix4* m : {&a, &b, &c}) {
      if (agree<Ellipsoid>(*m)) ++accepted_e;
      if (agree<Paraboloid>(*m)) ++accepted_p;
    }
  }
  CHECK(accepted_e > 1000);
  CHECK(accepted_p > 1000);
}

TEST_CASE("from_doubles on degenerate and malformed matrices", "[from_doubles]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  std::vector<DoubleMatrix4> cases;
  cases.push_back({});                                                       // zero
  cases.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1});        // unit sphere
  cases.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0});   // z = x^2 + y^2
  cases.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0});         // a point
  cases.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});         // imaginary
  cases.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1});        // cylinder
  cases.push_back({1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0});  // saddle
  cases.push_back({1, 1e-300, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1});   // asymmetric by a hair
  cases.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, nan});
  cases.push_back({inf, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0});
  cases.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, std::ldexp(1.0, -1074), -0.5, 0, 0, -0.5, 0});  // subnormal
  cases.push_back({std::ldexp(1.0, 1000), 0, 0, 0, 0, std::ldexp(1.0, 1000), 0, 0, 0, 0, std::ldexp(1.0, 1000), 0, 0, 0,
                   0, -std::ldexp(1.0, 1020)});                             // overflowing determinant
  cases.push_back({1, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, -0.5, 0, 0, -0.5, 0});  // rank-2 block, not axis-aligned
  for (const auto& m : cases) {
    agree<Ellipsoid>(m);
    agree<Paraboloid>(m);
  }
  // A NaN is refused with exact_rational's message, from either door.
  CHECK_THROWS_WITH(Ellipsoid::from_doubles(cases[8]), Catch::Matchers::Contains("not a finite number"));
}

TEST_CASE("from_doubles gives the same positions as from_matrix", "[from_doubles]") {
  Gen g;
  int exact_checked = 0;
  for (int k = 0; k < 4000; ++k) {
    const auto [ed, pd] = g.regime_pair();
    const auto e = agree<Ellipsoid>(ed);
    const auto p = agree<Paraboloid>(pd);
    REQUIRE(e);
    REQUIRE(p);
    const Ellipsoid es = Ellipsoid::from_matrix(exact(ed));
    const Paraboloid ps = Paraboloid::from_matrix(exact(pd));
    const relpos::Verdict fast = relpos::decide_position(*e, *p);
    const relpos::Verdict slow = relpos::decide_position(es, ps);
    CHECK(fast.position == slow.position);
    CHECK(fast.rule == slow.rule);
    if (k % 40 == 0) {
      CHECK(relpos::classify_exact(*e, *p, relpos::Evidence::Minimal).verdict.position == slow.position);
      ++exact_checked;
    }
  }
  CHECK(exact_checked == 100);
}

TEST_CASE("full evidence from doubles is the full evidence of the exact matrices", "[from_doubles]") {
  // The evidence reads a quadric made from doubles through its doubles (integer forms from the
  // bits, the certificate's matrices only when it needs them): every byte of the report must be
  // the one of the same pair given as exact rationals.
  Gen g;
  for (int k = 0; k < 300; ++k) {
    const auto [ed, pd] = g.regime_pair();
    const Ellipsoid e = Ellipsoid::from_doubles(ed);
    const Paraboloid p = Paraboloid::from_doubles(pd);
    const Ellipsoid es = Ellipsoid::from_matrix(exact(ed));
    const Paraboloid ps = Paraboloid::from_matrix(exact(pd));
    const std::string fast = relpos::io::classification_json_text(relpos::classify(e, p, relpos::Evidence::Full));
    const std::string slow = relpos::io::classification_json_text(relpos::classify(es, ps, relpos::Evidence::Full));
    CAPTURE(k);
    CHECK(fast == slow);
  }
}

TEST_CASE("A quadric from doubles is shared safely and copies keep their matrix", "[from_doubles]") {
  const Paraboloid p = Paraboloid::from_doubles({1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0});
  const Paraboloid copy = p;  // before materialization
  const Matrix4& m = p.matrix();
  CHECK(&m == &p.matrix());  // built once
  CHECK(copy.matrix() == m);
  CHECK(m(1, 1) == relpos::Rational(2));
  const Ellipsoid e = Ellipsoid::from_doubles({-1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0.5, 0, 0, 0.5, 0});
  CHECK(e.matrix()(0, 0) == relpos::Rational(1));  // sign-normalized
}

TEST_CASE("from_doubles at the edge of its filters and under upward rounding", "[from_doubles]") {
  // Ellipsoids whose det E is within a few ulps of zero (a point, imaginary, or barely real): the
  // static and semi-static signs are uncertain there, so the interval and exact stages decide; and
  // the same matrices with the FPU rounding upwards (the semi-static stage is skipped).
  Gen g;
  int accepted = 0, rejected = 0;
  for (int k = 0; k < 600; ++k) {
    DoubleMatrix4 m{};
    const double c[3] = {g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-1, 1)};
    double e0 = 0;
    for (int i = 0; i < 3; ++i) {
      Gen::set(m, i, i, 1.0);
      Gen::set(m, i, 3, -c[i]);
      e0 += c[i] * c[i];
    }
    for (int step = g.small(0, 4); step > 0; --step) e0 = std::nextafter(e0, g.coin() ? 10.0 : -10.0);
    m[15] = e0;
    const bool upward = k % 3 == 0;
    if (upward) std::fesetround(FE_UPWARD);
    const auto e = agree<Ellipsoid>(m);
    const auto p = agree<Paraboloid>(g.paraboloid_like());
    if (upward) std::fesetround(FE_TONEAREST);
    (e ? accepted : rejected) += 1;
    (void)p;
  }
  CHECK(accepted > 0);
  CHECK(rejected > 0);
}

namespace {

/// Every field of the verdict.
auto fields(const relpos::Verdict& v) {
  return std::make_tuple(v.position, v.stage, v.rule, v.small, v.rho_vs_one, v.sign_disc_f, v.sign_disc_ftilde,
                         v.real_roots, v.negative_roots, v.positive_roots, v.nonreal_roots, v.tangent_negative,
                         v.tangent_positive, v.nonreal_multiple, v.roots_above_lambda_s);
}

/// decide_position on the 32 doubles and the two steps it stands for: the same verdict, or the same
/// InputError. True when the pair was accepted.
bool same_decision(const DoubleMatrix4& e, const DoubleMatrix4& p) {
  std::optional<relpos::Verdict> one, two;
  std::string one_error, two_error;
  try {
    one = relpos::decide_position(e, p);
  } catch (const InputError& err) {
    one_error = err.what();
  }
  try {
    const Ellipsoid ell = Ellipsoid::from_doubles(e);  // the ellipsoid first, as a user writes it
    const Paraboloid par = Paraboloid::from_doubles(p);
    two = relpos::decide_position(ell, par);
  } catch (const InputError& err) {
    two_error = err.what();
  }
  std::string shown;
  for (const DoubleMatrix4* m : {&e, &p})
    for (double x : *m) shown += std::to_string(x) + " ";
  INFO("pair: " << shown << "; one call: " << one_error << "; two steps: " << two_error);
  REQUIRE(one.has_value() == two.has_value());
  CHECK(one_error == two_error);
  if (one) CHECK(fields(*one) == fields(*two));
  return one.has_value();
}

DoubleMatrix4 negated(DoubleMatrix4 m) {
  for (double& x : m) x = -x;
  return m;
}

}  // namespace

TEST_CASE("decide_position on 32 doubles is from_doubles then decide_position", "[from_doubles]") {
  Gen g;
  int accepted = 0;
  SECTION("the regime, in both orientations") {
    for (int k = 0; k < 3000; ++k) {
      const auto [e, p] = g.regime_pair();
      accepted += same_decision(k % 2 ? negated(e) : e, k % 3 ? p : negated(p));
    }
    CHECK(accepted == 3000);
  }
  SECTION("random matrices of every kind, either one in either place") {
    for (int k = 0; k < 3000; ++k) {
      const DoubleMatrix4 a = g.ellipsoid_like(), b = g.paraboloid_like(), c = g.symmetric();
      accepted += same_decision(a, b);
      same_decision(b, a);  // swapped
      same_decision(a, c);
      same_decision(c, b);
    }
    CHECK(accepted > 1000);
  }
  SECTION("degenerate, malformed and non-finite matrices, and det E or det P near zero") {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const DoubleMatrix4 sphere{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -0.5, 0, 0, -0.5, 0.1875};  // radius 1/4 at z = 1/2
    const DoubleMatrix4 cup{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0};          // z = x^2 + y^2
    const std::vector<DoubleMatrix4> bad = {
        {},                                                                           // zero
        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0},                             // a point: det E = 0
        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1},                             // imaginary: det E > 0
        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1},                            // cylinder: det P = 0
        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1},                             // imaginary cylinder
        {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0},                      // saddle
        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1},                           // hyperboloid
        {1, 1e-300, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1},                       // not symmetric
        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.4, 0},                       // not symmetric
        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, nan},                           // NaN
        {inf, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0},                     // infinity
        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, std::ldexp(1.0, -1074), -0.5, 0, 0, -0.5, 0},  // subnormal
        {1, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, -0.5, 0, 0, -0.5, 0},                       // rank-2 block, not axis-aligned
        {std::ldexp(1.0, 1000), 0, 0, 0, 0, std::ldexp(1.0, 1000), 0, 0, 0, 0, std::ldexp(1.0, 1000), 0, 0, 0, 0,
         -std::ldexp(1.0, 1020)},  // overflowing determinant
    };
    for (const DoubleMatrix4& m : bad) {
      same_decision(m, cup);
      same_decision(sphere, m);
      same_decision(m, m);
      same_decision(negated(m), negated(cup));
    }
    CHECK(same_decision(sphere, cup));
    CHECK(same_decision(negated(sphere), negated(cup)));
    // det E within a few ulps of zero (barely real, a point, or imaginary): the pencil's f(0) is
    // uncertain there, and the two steps decide; under upward rounding the double stages stand aside.
    for (int k = 0; k < 600; ++k) {
      DoubleMatrix4 m = sphere;
      for (int step = g.small(0, 4); step > 0; --step) m[15] = std::nextafter(m[15], g.coin() ? 10.0 : -10.0);
      const bool upward = k % 3 == 0;
      if (upward) std::fesetround(FE_UPWARD);
      same_decision(m, cup);
      same_decision(m, g.paraboloid_like());
      if (upward) std::fesetround(FE_TONEAREST);
    }
  }
}
