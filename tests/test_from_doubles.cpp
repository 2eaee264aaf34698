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

#include "support/scale.hpp"

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
  for (int k = 0; k < relpos::testing::scaled(3000); ++k) {
    const DoubleMatrix4 a = g.ellipsoid_like(), b = g.paraboloid_like(), c = g.symmetric();
    for (const DoubleMatrix4* m : {&a, &b, &c}) {
      if (agree<Ellipsoid>(*m)) ++accepted_e;
      if (agree<Paraboloid>(*m)) ++accepted_p;
    }
  }
  CHECK(accepted_e > relpos::testing::scaled(1000));
  CHECK(accepted_p > relpos::testing::scaled(1000));
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

namespace {

constexpr int kRoundingModes[] = {FE_TONEAREST, FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};

/// In rounding mode `mode`: from_doubles of m (a Q) against from_matrix, and the one call on the pair
/// (e, p) m is part of against the two steps, which must accept it exactly when from_doubles does.
/// True when m was accepted.
template <class Q>
bool both_doors(const DoubleMatrix4& m, const DoubleMatrix4& e, const DoubleMatrix4& p, int mode) {
  std::fesetround(mode);
  const auto made = agree<Q>(m);
  const bool decided = same_decision(e, p);
  std::fesetround(FE_TONEAREST);
  CHECK(decided == made.has_value());
  return made.has_value();
}

/// What normalize_doubles must give, by another route: the exponent e of the largest |entry| plus
/// one, and every entry times 2^-e, which must be normal (or zero) to be kept; refused when an
/// entry is not finite, the largest is zero or subnormal, or some entry would turn subnormal.
struct Normalized {
  bool ok = false;
  DoubleMatrix4 out{};
  int exponent = 0;
  bool plain = false;
};

Normalized reference_normalized(const DoubleMatrix4& d) {
  Normalized r;
  double mx = 0;
  bool subnormal = false;
  for (double x : d) {
    if (!std::isfinite(x)) return r;
    mx = std::max(mx, std::fabs(x));
    subnormal = subnormal || (x != 0 && std::fpclassify(x) == FP_SUBNORMAL);
  }
  if (!(mx >= std::numeric_limits<double>::min())) return r;
  r.exponent = std::ilogb(mx) + 1;
  for (std::size_t i = 0; i < 16; ++i) {
    if (d[i] != 0 && std::ilogb(d[i]) - r.exponent < std::numeric_limits<double>::min_exponent - 1) return r;
    r.out[i] = std::ldexp(d[i], -r.exponent);  // normal: exact
  }
  r.ok = true;
  r.plain = !subnormal && r.exponent <= 1023;
  return r;
}

}  // namespace

TEST_CASE("the normalization of doubles keeps every entry exactly, in every rounding mode", "[from_doubles]") {
  // Entries over the whole range, and at the edges the normalization tests: the smallest kept one
  // (2^(e - 1022) once the largest is below 2^e), one just below it, and (2 - 2^-52) 2^(e - 1023),
  // whose product rounds up to DBL_MIN (to nearest: a tie, to even).
  Gen g;
  const double dmin = std::numeric_limits<double>::min(), dmax = std::numeric_limits<double>::max();
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  int accepted = 0, refused = 0, plain = 0;
  for (int k = 0; k < 20000; ++k) {
    DoubleMatrix4 d{};
    const int top = g.small(-1060, 1023);  // the largest |entry| is in [2^top, 2^(top + 1))
    const double largest = std::ldexp(g.uniform(1, 2), top);
    const int e = top + 1;
    for (double& x : d) {
      switch (g.small(0, 11)) {
        case 0:
        case 1:
          x = 0;
          break;
        case 2:
          x = std::ldexp(1.0, std::max(e - 1022, -1074));  // the smallest kept (when normal)
          break;
        case 3:
          x = std::nextafter(std::ldexp(1.0, std::max(e - 1022, -1074)), 0.0);  // just below it
          break;
        case 4:
          x = std::nextafter(std::ldexp(2.0, std::max(e - 1023, -1074)), 0.0);  // rounds up to DBL_MIN
          break;
        case 5:
          x = std::ldexp(g.uniform(1, 2), g.small(-1074, top));
          break;
        case 6:
          x = std::ldexp(1.0, g.small(-1074, top));  // a power of two
          break;
        case 7:
          x = g.small(0, 40) == 0 ? (g.coin() ? inf : nan) : g.uniform(-1, 1) * largest;
          break;
        default:
          x = g.uniform(-1, 1) * largest;
      }
      if (g.coin()) x = -x;
    }
    d[static_cast<std::size_t>(g.small(0, 15))] = g.coin() ? largest : -largest;
    if (g.small(0, 200) == 0) d[static_cast<std::size_t>(g.small(0, 15))] = g.coin() ? dmax : dmin;
    const Normalized want = reference_normalized(d);
    for (int mode : kRoundingModes) {
      DoubleMatrix4 out;
      int exponent = 0;
      bool is_plain = false;
      std::fesetround(mode);
      const bool ok = relpos::detail::normalize_doubles(d, out, exponent, is_plain);
      std::fesetround(FE_TONEAREST);
      CAPTURE(k, mode, top);
      REQUIRE(ok == want.ok);
      if (!ok) continue;
      CHECK(exponent == want.exponent);
      CHECK(out == want.out);
      CHECK(is_plain == want.plain);
    }
    (want.ok ? accepted : refused) += 1;
    plain += want.plain;
  }
  CHECK(accepted > 2000);
  CHECK(refused > 2000);
  CHECK(plain > 300);
}

TEST_CASE("a quadric from doubles keeps its doubles at the edge of the normalization", "[from_doubles]") {
  // The unit sphere with an entry (2 - 2^-52) 2^-1022 and its mirror: normalized by 2^-1, that entry
  // would round up to DBL_MIN (a tie, to even); the quadric keeps the given doubles in every mode.
  const double x = std::nextafter(2 * std::numeric_limits<double>::min(), 0.0);
  const DoubleMatrix4 sphere{1, 0, 0, x, 0, 1, 0, 0, 0, 0, 1, 0, x, 0, 0, -1};
  const DoubleMatrix4 cup{1, 0, 0, x, 0, 1, 0, 0, 0, 0, 0, -0.5, x, 0, -0.5, 0};
  for (int mode : kRoundingModes) {
    std::fesetround(mode);
    const auto e = agree<Ellipsoid>(sphere);
    const auto p = agree<Paraboloid>(cup);
    std::fesetround(FE_TONEAREST);
    CAPTURE(mode);
    REQUIRE(e);
    REQUIRE(p);
    CHECK(*e->doubles() == sphere);
    CHECK(e->matrix() == exact(sphere));
    CHECK(*p->doubles() == cup);
    CHECK(p->matrix() == exact(cup));
  }
}

TEST_CASE("axis-aligned paraboloids and the shortcuts of a diagonal block, both doors", "[from_doubles]") {
  // A diagonal Q3 is certified by the signs of its entries (rank 2 and semidefinite: one zero, two of
  // one sign; det P = -a b q_z^2). The cases that just miss: two zeros, opposite signs, q_z = 0,
  // and a block one off-diagonal entry away from diagonal; each zero position, each orientation.
  Gen g;
  const DoubleMatrix4 sphere{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -0.5, 0, 0, -0.5, 0.1875};
  int accepted = 0, refused = 0;
  for (int k = 0; k < 4000; ++k) {
    DoubleMatrix4 p{};
    const int z = g.small(0, 2);  // the zero diagonal entry
    for (int i = 0; i < 3; ++i) Gen::set(p, i, i, i == z ? 0.0 : g.uniform(0.25, 4));
    for (int i = 0; i < 3; ++i) Gen::set(p, i, 3, g.coin() ? 0.0 : g.uniform(-1, 1));
    Gen::set(p, z, 3, g.small(0, 5) == 0 ? 0.0 : g.uniform(-1, 1));  // q_z = 0: a cylinder
    p[15] = g.coin() ? 0.0 : g.uniform(-1, 1);
    switch (g.small(0, 7)) {
      case 0:  // opposite signs: a hyperbolic paraboloid or cylinder
        p[static_cast<std::size_t>(5 * ((z + 1) % 3))] *= -1;
        break;
      case 1:  // two zeros: rank 1
        p[static_cast<std::size_t>(5 * ((z + 2) % 3))] = 0;
        break;
      case 2: {  // one off-diagonal entry of Q3 (and its mirror), sometimes tiny
        const int i = g.small(0, 1), j = g.small(i + 1, 2);
        Gen::set(p, i, j, g.coin() ? 1e-300 : g.uniform(-0.5, 0.5));
        break;
      }
      case 3:  // the diagonal entries far apart in magnitude
        p[static_cast<std::size_t>(5 * ((z + 1) % 3))] *= std::ldexp(1.0, g.small(-600, 600));
        break;
      default:
        break;
    }
    if (g.coin())
      for (double& v : p) v = -v;
    (both_doors<Paraboloid>(p, sphere, p, kRoundingModes[k % 4]) ? accepted : refused) += 1;
  }
  CHECK(accepted > 1000);
  CHECK(refused > 1000);
}

TEST_CASE("the symmetry test on lanes: each mirrored pair, NaN and infinities, both doors", "[from_doubles]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const DoubleMatrix4 sphere{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -0.5, 0, 0, -0.5, 0.1875};
  const DoubleMatrix4 cup{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0};
  for (int mode : kRoundingModes) {
    std::fesetround(mode);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        if (i == j) continue;
        const std::size_t at = static_cast<std::size_t>(4 * i + j);
        for (double v : {0.0, 0.25, nan, inf}) {
          DoubleMatrix4 e = sphere, p = cup;
          // One entry off its mirror: by one ulp (v = 0), by v, or not finite.
          e[at] = v == 0 ? std::nextafter(e[at], 1.0) : (std::isfinite(v) ? e[at] + v : v);
          p[at] = v == 0 ? std::nextafter(p[at], 1.0) : (std::isfinite(v) ? p[at] + v : v);
          CHECK_FALSE(agree<Ellipsoid>(e));
          CHECK_FALSE(agree<Paraboloid>(p));
          CHECK_FALSE(same_decision(e, cup));
          CHECK_FALSE(same_decision(sphere, p));
          if (i < j) {  // the same value in both mirrored places: symmetric (NaN never is)
            Gen::set(e, i, j, e[at]);
            Gen::set(p, i, j, p[at]);
            same_decision(e, cup);
            same_decision(sphere, p);
            agree<Ellipsoid>(e);
            agree<Paraboloid>(p);
          }
        }
      }
    std::fesetround(FE_TONEAREST);
  }
}

TEST_CASE("the ellipsoid's three determinants from shared minors: each at and just off zero, both doors",
          "[from_doubles]") {
  // The ellipsoid test reads its 2x2 leading minor, det Q3 and det Q off one set of 2x2 minors
  // (static bounds, then the magnitudes of the matrix, then intervals, then the exact path). Blocks
  // built to make each one zero up to the rounding of their entries, nudged by a few ulps either
  // way, with general (rotated) blocks, blocks much smaller than the last entry (the magnitudes
  // decide, not the static bounds), both orientations and every rounding mode; from_doubles must
  // agree with from_matrix, and the one call with the two steps.
  Gen g;
  const DoubleMatrix4 paraboloid{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.5, 0, 0, -0.5, 0};
  int accepted = 0, refused = 0;
  for (int k = 0; k < 3000; ++k) {
    // Q3 = L L^T + t I (L 3x3, or of rank 2 for det Q3 near zero), scaled by 2^-s.
    double l[3][3];
    for (auto& row : l)
      for (double& x : row) x = g.uniform(-1, 1);
    const int target = g.small(0, 3);  // 0: the 2x2 minor, 1: det Q3, 2: det Q, 3: none near zero
    if (target == 0)
      for (int i = 0; i < 3; ++i) l[i][1] = l[i][2] = 0, l[i][0] = i < 2 ? l[i][0] : g.uniform(-1, 1);
    if (target == 1)
      for (int i = 0; i < 3; ++i) l[i][2] = 0;
    const double scale = std::ldexp(1.0, -g.small(0, 40));
    double q[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        q[i][j] = 0;
        for (int r = 0; r < 3; ++r) q[i][j] += l[i][r] * l[j][r];
        q[i][j] *= scale;
      }
    // Only the 2x2 minor near zero; with q_22 lowered, det Q3 = q_22 (the minor) takes its sign from the
    // minor's with the orientation's: an indefinite block that only the minor's sign refuses.
    if (target == 0) q[2][2] += (g.coin() ? 1 : -1) * scale * g.uniform(0.5, 1);
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j) q[j][i] = q[i][j];
    // The entry nudged, (1, 1) or (2, 2): by a few ulps (only intervals or the exact path can
    // tell), or by 2^-20 to 2^-48 of itself (the signs in doubles certify it, unless wrong).
    const int at = target == 0 ? 1 : 2;
    if (g.coin())
      for (int step = g.small(-3, 3); step != 0; step += step > 0 ? -1 : 1)
        q[at][at] = std::nextafter(q[at][at], step > 0 ? 10.0 : -10.0);
    else
      q[at][at] *= 1 + (g.coin() ? 1 : -1) * std::ldexp(1.0, -g.small(20, 48));
    DoubleMatrix4 m{};
    const double c[3] = {g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-1, 1)};
    double e0 = 0;
    for (int i = 0; i < 3; ++i) {
      double qc = 0;
      for (int j = 0; j < 3; ++j) {
        Gen::set(m, i, j, q[i][j]);
        qc += q[i][j] * c[j];
      }
      Gen::set(m, i, 3, -qc);
      e0 += c[i] * qc;
    }
    // det Q = det Q3 (q_33 - c^T Q3 c): near zero when q_33 is c^T Q3 c up to a few ulps; otherwise
    // sometimes positive with det Q3 < 0 (an indefinite block that only det Q3's sign refuses).
    e0 = target == 2 ? e0 : e0 + (g.small(0, 3) == 0 ? 1 : -1) * scale * g.uniform(0.01, 1);
    if (target == 2 && g.coin())
      e0 += (g.coin() ? 1 : -1) * std::ldexp(std::fabs(e0), -g.small(20, 48));
    else
      for (int step = target == 2 ? g.small(-3, 3) : 0; step != 0; step += step > 0 ? -1 : 1)
        e0 = std::nextafter(e0, step > 0 ? 10.0 : -10.0);
    m[15] = e0;
    if (g.coin())
      for (double& x : m) x = -x;
    (both_doors<Ellipsoid>(m, m, paraboloid, kRoundingModes[k % 4]) ? accepted : refused) += 1;
  }
  CHECK(accepted > 500);
  CHECK(refused > 500);
}
