// Any size (math.md §8): a corpus of pairs whose position is known by construction
// (support/large_cases.hpp), judged by an independent exact second method (support/secular.hpp), by dense
// sampling (a check of the constructions themselves), and finally by relpos::classify / classify_exact.
//
// The seed of the random parts is printed; RELPOS_SEED=<n> reruns or varies it.
// Tags: [secular] [sampling] are fast; [anysize] runs the classifier and includes the 2000 random
// pairs ([random], a few seconds in Release).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <relpos/classify.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/construct.hpp"
#include "support/large_cases.hpp"
#include "support/printers.hpp"
#include "support/scale.hpp"
#include "support/secular.hpp"
#include "support/seed.hpp"

using relpos::Ellipsoid;
using relpos::Matrix4;
using relpos::Paraboloid;
using relpos::Position;
using relpos::Rational;
using relpos::Vector3;
using relpos::testing::LargeCase;
using rt::form_value;
using rt::Q;

namespace {

std::uint64_t any_size_seed() {
  static const std::uint64_t seed = relpos::testing::announced_seed("test_any_size", 20250111ULL);
  return seed;
}

/// The base cases and, for each, one copy under a rigid motion and one under a general affine congruence.
const std::vector<LargeCase>& corpus() {
  static const std::vector<LargeCase> all = [] {
    std::vector<LargeCase> out = relpos::testing::large_cases();
    const std::size_t n = out.size();
    rt::Rng g(any_size_seed());
    for (std::size_t i = 0; i < n; ++i) {
      // Under AddressSanitizer one copy per case, rigid and affine in turn (support/scale.hpp).
      if (relpos::testing::kSanitizerShare == 1 || i % 2 == 0)
        out.push_back(relpos::testing::transformed_copy(out[i], g, true));
      if (relpos::testing::kSanitizerShare == 1 || i % 2 == 1)
        out.push_back(relpos::testing::transformed_copy(out[i], g, false));
    }
    return out;
  }();
  return all;
}

/// The second method's position (nullopt when it failed: the reason is returned).
std::string secular_or_error(const LargeCase& c, std::optional<Position>& got, bool* hard = nullptr) {
  try {
    const auto s = relpos::testing::secular_extreme_signs(c.e, c.p, hard);
    got = relpos::testing::position_from_extreme_signs(s.first, s.second);
    return {};
  } catch (const std::exception& ex) {
    got = std::nullopt;
    return ex.what();
  }
}

// ---- sampling in long double --------------------------------------------------------------------

struct SampleResult {
  long double min_p, max_p, tol;
};

/// p = X^T P X (sign-normalized P) at n random points of the solid ellipsoid: half on its surface (where the
/// maximum of the convex p is), half inside.
SampleResult sample(const LargeCase& c, std::mt19937_64& gen, int n) {
  const Matrix4 &em = c.e.matrix(), &pm = c.p.matrix();
  // Centre c = -M^-1 e exactly (Cramer), kappa = e^T M^-1 e - e0.
  rt::Matrix3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = em(i, j);
  const Vector3 centre = rt::solve3(m, {-em(0, 3), -em(1, 3), -em(2, 3)});
  const Rational kappa = -form_value(em, centre);  // X^T E X at the centre = -kappa
  REQUIRE(kappa > 0);
  long double M[3][3], L[3][3] = {}, P[4][4], ctr[3];
  for (int i = 0; i < 3; ++i) {
    ctr[i] = static_cast<long double>(CGAL::to_double(centre[static_cast<std::size_t>(i)]));
    for (int j = 0; j < 3; ++j) M[i][j] = static_cast<long double>(CGAL::to_double(em(i, j)));
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) P[i][j] = static_cast<long double>(CGAL::to_double(pm(i, j)));
  // Cholesky M = L L^T.
  for (int j = 0; j < 3; ++j) {
    long double s = M[j][j];
    for (int k = 0; k < j; ++k) s -= L[j][k] * L[j][k];
    L[j][j] = std::sqrt(s);
    for (int i = j + 1; i < 3; ++i) {
      long double t = M[i][j];
      for (int k = 0; k < j; ++k) t -= L[i][k] * L[j][k];
      L[i][j] = t / L[j][j];
    }
  }
  const long double rk = std::sqrt(static_cast<long double>(CGAL::to_double(kappa)));
  std::normal_distribution<long double> normal(0, 1);
  std::uniform_real_distribution<long double> unif(0, 1);
  SampleResult out{INFINITY, -INFINITY, 0};
  for (int s = 0; s < n; ++s) {
    long double u[3], len = 0;
    for (auto& v : u) {
      v = normal(gen);
      len += v * v;
    }
    len = std::sqrt(len);
    const long double rad = (s % 2 == 0) ? 1 : std::cbrt(unif(gen));
    for (auto& v : u) v *= rk * rad / len;
    // Solve L^T y = u (back substitution); x = centre + y.
    long double y[3];
    for (int i = 2; i >= 0; --i) {
      long double t = u[i];
      for (int k = i + 1; k < 3; ++k) t -= L[k][i] * y[k];
      y[i] = t / L[i][i];
    }
    const long double X[4] = {ctr[0] + y[0], ctr[1] + y[1], ctr[2] + y[2], 1};
    long double p = 0, mag = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        p += X[i] * P[i][j] * X[j];
        mag += std::fabs(X[i] * P[i][j] * X[j]);
      }
    out.min_p = std::min(out.min_p, p);
    out.max_p = std::max(out.max_p, p);
    out.tol = std::max(out.tol, 1e-12L * mag);
  }
  return out;
}

}  // namespace

TEST_CASE("the secular polynomial is D^2 e(x(t)) (one case, exact rational t)", "[secular]") {
  using namespace relpos::testing::secular_detail;
  const auto all = relpos::testing::wedged_cases();
  for (const LargeCase* c : {&all.front(), &all.back()}) {
    const auto sp = relpos::testing::secular_polynomials(c->e, c->p);
    const Matrix4 &em = c->e.matrix(), &pm = c->p.matrix();
    for (const Rational& t : {Q(1, 3), Q(2), Q(-5), Q(-1, 7)}) {
      // x(t) = -(A + tM)^-1 (a + t m) by Cramer's rule.
      rt::Matrix3 k;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) k(i, j) = pm(i, j) + t * em(i, j);
      const Rational det = rt::det3(k);
      REQUIRE(det != 0);
      Vector3 rhs;
      for (int i = 0; i < 3; ++i) rhs[static_cast<std::size_t>(i)] = -(pm(i, 3) + t * em(i, 3));
      const Vector3 x = rt::solve3(k, rhs);
      const Field f{Rational(0)};
      const Rational D = f.eval(sp.D, {t, Rational(0)}).u, S = f.eval(sp.S, {t, Rational(0)}).u;
      const Rational F = f.eval(sp.F, {t, Rational(0)}).u;
      CHECK(D == det);
      CHECK(S == D * D * form_value(em, x));
      // R = F / D = p(x) + t e(x).
      CHECK(F / D == form_value(pm, x) + t * form_value(em, x));
    }
  }
}

TEST_CASE("second method gives the constructed answer", "[secular]") {
  const auto& cases = corpus();
  std::map<std::string, int> histogram;
  int failures = 0, hard_cases = 0;
  for (const LargeCase& c : cases) {
    std::optional<Position> got;
    bool hard = false;
    const std::string err = secular_or_error(c, got, &hard);
    if (hard && got != Position::E && got != Position::TE) ++hard_cases;
    INFO(c.name << (err.empty() ? "" : ": " + err));
    CHECK(got == c.expected);
    if (got != c.expected) ++failures;
    ++histogram[relpos::to_string(c.expected)];
  }
  std::ostringstream h;
  for (const auto& kv : histogram) h << " " << kv.first << ":" << kv.second;
  std::cout << "test_any_size: " << cases.size() << " corpus cases (" << relpos::testing::large_cases().size()
            << " base + transformed copies):" << h.str() << "; hard case on the max side: " << hard_cases
            << "; secular failures: " << failures << std::endl;
}

TEST_CASE("sampling agrees with the constructed answer", "[sampling]") {
  std::mt19937_64 gen(any_size_seed());
  const auto base = relpos::testing::large_cases();
  int contact_checks = 0;
  for (const LargeCase& c : base) {
    INFO(c.name << " expected " << relpos::to_string(c.expected));
    const SampleResult sampled = sample(c, gen, 20000);
    INFO("sampled p in [" << static_cast<double>(sampled.min_p) << ", " << static_cast<double>(sampled.max_p)
                          << "], tolerance " << static_cast<double>(sampled.tol));
    SampleResult s = sampled;
    for (const Vector3& w : c.witnesses) {
      REQUIRE(form_value(c.e.matrix(), w) < 0);
      const Rational pw = form_value(c.p.matrix(), w);
      const long double v = static_cast<long double>(CGAL::to_double(pw));
      INFO("witness p = " << relpos::to_decimal(pw, 6));
      CHECK(pw != 0);
      s.min_p = std::min(s.min_p, v);
      s.max_p = std::max(s.max_p, v);
    }
    const Position x = c.expected;
    const bool inside_side = x == Position::TI || c.near < 0;
    if (c.near != 0 || x == Position::TI || x == Position::TE) {
      // Within 1e-30 of a tangency (or tangent): only the non-strict side is visible in long double.
      if (inside_side)
        CHECK(s.max_p <= s.tol);
      else
        CHECK(s.min_p >= -s.tol);
    } else if (x == Position::I) {
      CHECK(s.max_p < 0);
    } else if (x == Position::E) {
      CHECK(s.min_p > 0);
    } else {
      CHECK(s.min_p < 0);
      CHECK(s.max_p > 0);
    }
    // Exact contact points: on both surfaces.
    for (const Vector3& pt : c.contacts) {
      CHECK(form_value(c.e.matrix(), pt) == 0);
      CHECK(form_value(c.p.matrix(), pt) == 0);
      ++contact_checks;
    }
  }
  // math.md §3's C and E examples also have exact certificates (test_classify_constructed).
  std::cout << "test_any_size: sampled " << base.size() << " base cases x 20000 points, " << contact_checks
            << " exact contact points" << std::endl;
}

namespace {

int count_classifier_failures(const std::vector<LargeCase>& cases, bool exact) {
  int failures = 0, definite = 0;
  std::map<std::string, int> got_hist;
  for (const LargeCase& c : cases) {
    const auto cl = exact ? relpos::classify_exact(c.e, c.p) : relpos::classify(c.e, c.p);
    ++got_hist[relpos::to_string(cl.verdict.position)];
    if (cl.verdict.position == c.expected) {
      // Every answer's certificate verifies with rational arithmetic alone (position.hpp).
      const auto why = relpos::verify_certificate(c.e, c.p, cl.verdict.position, cl.certificate);
      if (why) {
        ++failures;
        UNSCOPED_INFO(c.name << ": certificate of " << relpos::to_string(cl.verdict.position) << " rejected: " << *why);
      }
    }
    if (cl.verdict.position != c.expected) {
      ++definite;
      if (++failures <= 10)
        UNSCOPED_INFO((exact ? "classify_exact: " : "classify: ")
                      << c.name << ": expected " << relpos::to_string(c.expected) << ", got "
                      << relpos::to_string(cl.verdict.position));
    }
  }
  std::ostringstream h;
  for (const auto& kv : got_hist) h << " " << kv.first << ":" << kv.second;
  std::cout << "test_any_size: " << (exact ? "classify_exact" : "classify") << " on " << cases.size()
            << " corpus cases: " << failures << " wrong (" << definite << " definite wrong answers); answers" << h.str()
            << std::endl;
  return failures;
}

}  // namespace

TEST_CASE("classifier gives the constructed answer on any size", "[anysize]") {
  const auto& cases = corpus();
  CHECK(count_classifier_failures(cases, false) == 0);
  CHECK(count_classifier_failures(cases, true) == 0);
}

TEST_CASE("2000 random general pairs", "[anysize][random]") {
  rt::Rng g(any_size_seed() ^ 0xA11517E5ULL);
  CAPTURE(g.seed);
  std::map<std::string, int> histogram;
  int mismatches = 0, errors = 0, definite_mismatches = 0;
  for (int i = 0; i < relpos::testing::scaled(2000); ++i) {
    // In the paraboloid's frame: z = x^2/a^2 + y^2/b^2, a, b in [0.3, 3]; ellipsoid with semi-axes in
    // [0.05, 20], rotated by a small-integer quaternion, centre |x|, |y| <= 5, z in [-5, 20]. Then one random
    // rigid motion (and rescalings / sign flips) of both.
    const Rational a = Q(g.uniform(3, 30), 10), b = Q(g.uniform(3, 30), 10);
    const Vector3 axes{Q(g.uniform(1, 400), 20), Q(g.uniform(1, 400), 20), Q(g.uniform(1, 400), 20)};
    const Vector3 centre{Q(g.uniform(-20, 20), 4), Q(g.uniform(-20, 20), 4), Q(g.uniform(-20, 80), 4)};
    const Ellipsoid e0 = Ellipsoid::from_axes(centre, axes, rt::random_quaternion(g, 3));
    const Matrix4 p0 = rt::paraboloid_matrix(a, b);
    const rt::Transformed t = rt::transform(e0.matrix(), p0, g, true, true);
    const Ellipsoid e = Ellipsoid::from_matrix(t.e);
    const Paraboloid p = Paraboloid::from_matrix(t.p);
    std::optional<Position> sec;  // nullopt: the second method failed
    std::string err;
    try {
      sec = relpos::testing::secular_position(e, p);
    } catch (const std::exception& ex) {
      err = ex.what();
      ++errors;
    }
    const Position cl = relpos::classify(e, p, relpos::Evidence::Minimal).verdict.position;
    ++histogram[sec ? relpos::to_string(*sec) : "error"];
    if (sec && *sec != cl) ++definite_mismatches;
    if (sec != cl || !err.empty()) {
      if (++mismatches <= 10)
        UNSCOPED_INFO("pair " << i << ": a=" << a << " b=" << b << " axes=(" << axes[0] << ", " << axes[1] << ", "
                              << axes[2] << ") centre=(" << centre[0] << ", " << centre[1] << ", " << centre[2]
                              << "): secular " << (sec ? relpos::to_string(*sec) : "error")
                              << (err.empty() ? "" : " (" + err + ")") << ", classify " << relpos::to_string(cl));
    }
  }
  std::ostringstream h;
  for (const auto& kv : histogram) h << " " << kv.first << ":" << kv.second;
  std::cout << "test_any_size: " << relpos::testing::scaled(2000) << " random pairs, secular positions" << h.str()
            << "; disagreements with classify " << mismatches << " (" << definite_mismatches
            << " with a definite classify answer), secular errors " << errors << std::endl;
  CHECK(errors == 0);
  CHECK(definite_mismatches == 0);
  CHECK(mismatches == 0);
}
