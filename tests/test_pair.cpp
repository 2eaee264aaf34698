// The pair's one home (src/pair/): every value it builds on first use against an independent
// computation of the same quantity -- the generic formulas on the rational matrices, the definitions
// of the integer forms, the scaled roots of the compact form, lambda_s as a root of s -- for pairs of
// doubles, of rationals and read from decimal text; each value built once; and the per-thread scratch
// (algebra/recycled.hpp) never showing in a result.
#include <catch2/catch.hpp>
#include <random>
#include <relpos/classify.hpp>
#include <string>
#include <vector>

#include "algebra/pencil.hpp"
#include "io/fast_quadric.hpp"
#include "pair/pair.hpp"
#include "support/construct.hpp"
#include "support/random_pairs.hpp"
#include "support/seed.hpp"

using relpos::Ellipsoid;
using relpos::Matrix4;
using relpos::Paraboloid;
using relpos::Quadratic;
using relpos::Quartic;
using relpos::Rational;
using relpos::detail::PairContext;
using rt::form_value;
using rt::Q;
using rt::sgn;

namespace {

struct PairCase {
  std::string name;
  Ellipsoid e;
  Paraboloid p;
};

/// Pairs of every input form: doubles (rotated and axis-aligned), rationals, decimal text (a sphere
/// and an axis paraboloid, the closed forms; matrices), at several scales.
std::vector<PairCase> cases(std::uint64_t seed) {
  std::vector<PairCase> out;
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 40; ++i) {
    const Matrix4 em = rt::random_double_ellipsoid_matrix(rng, 0.05);
    const Paraboloid p = Paraboloid::from_matrix(rt::axis_paraboloid(Q(3, 4), Q(5, 4)));
    out.push_back({"doubles " + std::to_string(i), Ellipsoid::from_matrix(em), p});
  }
  rt::Rng g(seed);
  for (int i = 0; i < 30; ++i) {
    const Rational a = g.positive_rational(9, 7), b = g.positive_rational(9, 7), r = g.positive_rational(5, 11);
    const rt::Vector3 c{g.rational(-3, 3, 13), g.rational(-3, 3, 17), g.rational(-2, 6, 19)};
    const rt::Congruence h = rt::random_congruence(g);
    out.push_back({"rationals " + std::to_string(i),
                   Ellipsoid::from_matrix(rt::congruence(rt::sphere_matrix(c, r), h.h)),
                   Paraboloid::from_matrix(rt::congruence(rt::paraboloid_matrix(a, b), h.h))});
  }
  const char* spheres[] = {R"({"sphere":{"center":[0.1,-0.25,0.5],"radius":0.3}})",
                           R"({"sphere":{"center":[0,0,1.25],"radius":0.5}})",
                           R"({"sphere":{"center":[3e-7,1.5e-7,2e-6],"radius":1e-7}})",
                           R"([[2,0.5,0,-1],[0.5,3,0.25,0],[0,0.25,1,-0.5],[-1,0,-0.5,-0.75]])"};
  const char* cups[] = {R"({"vertex":[0,0,0],"a":1.2,"b":1.5})", R"({"vertex":[0,0,-0.5],"a":0.7,"b":0.7})",
                        R"([[1,0,0,0],[0,2,0,0],[0,0,0,-0.5],[0,0,-0.5,0.125]])"};
  for (const char* es : spheres)
    for (const char* ps : cups)
      out.push_back({std::string("text ") + es + " " + ps, *relpos::detail::io::fast_ellipsoid(es, false),
                     *relpos::detail::io::fast_paraboloid(ps, false)});
  return out;
}

/// The generic formulas on the rational matrices: f = det(lambda P + E), s = det(lambda A + M).
Quartic<Rational> f_of(const PairCase& k) {
  return relpos::characteristic_polynomial<Rational>(k.p.matrix(), k.e.matrix());
}
Quadratic<Rational> s_of(const PairCase& k) { return relpos::special_polynomial<Rational>(k.p.matrix(), k.e.matrix()); }

/// The ratio of two polynomials that are positive multiples of each other (nullopt when they are not).
template <class A, class B>
std::optional<Rational> positive_ratio(const A& x, const B& y) {
  std::optional<Rational> k;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Rational xi(x[i]), yi(y[i]);
    if ((xi == 0) != (yi == 0)) return std::nullopt;
    if (yi == 0) continue;
    const Rational r = xi / yi;
    if (r <= 0 || (k && *k != r)) return std::nullopt;
    k = r;
  }
  return k;
}

}  // namespace

TEST_CASE("pair: the evidence's f, s, S^4 f, S^3 s and lambda_s are those of the matrices", "[pair]") {
  for (const PairCase& k : cases(relpos::testing::announced_seed("test_pair", 20260301))) {
    INFO(k.name);
    const PairContext pair(k.e, k.p);
    const Quartic<Rational> f = f_of(k);
    const Quadratic<Rational> s = s_of(k);
    CHECK(pair.evidence().f == f);
    CHECK(pair.evidence().s == s);
    // S^4 f and S^3 s: integer multiples by S^4 and S^3 of one positive S.
    const std::optional<Rational> kf = positive_ratio(pair.f_multiple(), f);
    const std::optional<Rational> ks = positive_ratio(pair.s_multiple(), s);
    REQUIRE(kf);
    REQUIRE(ks);
    CHECK(*kf * *kf * *kf == *ks * *ks * *ks * *ks);  // S^12 both ways
    // lambda_s: a root of s, the one nearest 0 (s2 > 0 and both roots negative, math.md §8).
    const relpos::detail::anysize::LambdaS& ls = pair.lambda_s();
    const relpos::detail::anysize::QuadraticReal at = ls.at(relpos::detail::anysize::to_poly(s.data(), 3));
    CHECK(at.a == 0);
    CHECK(at.b == 0);
    const Rational mean = -s[1] / (2 * s[2]);  // (lambda_s + lambda_s2) / 2
    CHECK(ls.compare(mean) <= 0);              // the mean of the roots is at most lambda_s
    CHECK(ls.compare(Rational(0)) > 0);        // lambda_s < 0
    // Built once: the same object on every call.
    CHECK(&pair.evidence() == &pair.evidence());
    CHECK(&pair.f_poly() == &pair.f_poly());
  }
}

TEST_CASE("pair: the compact pencil's roots are those of f and s times one positive constant", "[pair]") {
  for (const PairCase& k : cases(relpos::testing::seed_from_env(20260301))) {
    INFO(k.name);
    const PairContext pair(k.e, k.p);
    const Quartic<Rational> f = f_of(k);
    const Quadratic<Rational> s = s_of(k);
    // compact f_i = t f_i c^i and compact s_i = u s_i c^i for positive t, u, c (math.md §11).
    const auto& cf = pair.compact().f();
    const auto& cs = pair.compact().s();
    REQUIRE(f[0] != 0);
    REQUIRE(s[0] != 0);
    const Rational t = Rational(cf[0].to_integer()) / f[0], u = Rational(cs[0].to_integer()) / s[0];
    CHECK(t > 0);
    CHECK(u > 0);
    // s1 = tr(adj(M) A) > 0 (M definite, A semidefinite and not 0): c from it.
    REQUIRE(s[1] > 0);
    const Rational c = Rational(cs[1].to_integer()) / (u * s[1]);
    CHECK(c > 0);
    for (std::size_t i = 0; i < 5; ++i) CHECK(Rational(cf[i].to_integer()) == t * f[i] * rt::pow_q(c, int(i)));
    for (std::size_t i = 0; i < 3; ++i) CHECK(Rational(cs[i].to_integer()) == u * s[i] * rt::pow_q(c, int(i)));
    CHECK(&pair.compact() == &pair.compact());
  }
}

TEST_CASE("pair: the integer forms, signs at points, f's sign and the roots against their definitions", "[pair]") {
  rt::Rng g(relpos::testing::seed_from_env(20260301));
  for (const PairCase& k : cases(relpos::testing::seed_from_env(20260301))) {
    INFO(k.name);
    const PairContext pair(k.e, k.p);
    const relpos::detail::IntegerForms& z = pair.integer_forms();
    for (std::size_t i = 0; i < 16; ++i) {
      CHECK(Rational(z.ez.a[i]) == z.le * k.e.matrix().a[i]);
      CHECK(Rational(z.pz.a[i]) == z.lp * k.p.matrix().a[i]);
    }
    CHECK(z.le > 0);
    CHECK(z.lp > 0);
    const relpos::detail::anysize::Poly fp = relpos::detail::anysize::to_poly(f_of(k).data(), 5);
    for (int t = 0; t < 20; ++t) {
      const rt::Vector3 x{g.rational(-4, 4, 9), g.rational(-4, 4, 9), g.rational(-4, 4, 9)};
      const relpos::detail::PointForm::Point xz(x);
      CHECK(pair.e_point_form().sign(xz) == sgn(form_value(k.e.matrix(), x)));
      CHECK(pair.p_point_form().sign(xz) == sgn(form_value(k.p.matrix(), x)));
      const Rational l = g.rational(-40, 40, 7);
      CHECK(pair.f_sign(l) == sgn(relpos::evaluate(fp, l)));
      const double d = std::ldexp(static_cast<double>(g.uniform(-1000, 1000)), int(g.uniform(-12, 2)));
      CHECK(pair.f_sign(Rational(d)) == sgn(relpos::evaluate(fp, Rational(d))));
    }
    // Each isolating interval holds a sign change of f (or its rational root), in increasing order.
    const auto& roots = pair.roots().real_roots;
    for (std::size_t i = 0; i < roots.size(); ++i) {
      const auto& r = roots[i];
      if (r.exact) {
        CHECK(relpos::evaluate(fp, *r.exact) == 0);
      } else {
        CHECK(r.lower < r.upper);
        if (r.multiplicity_f % 2 == 1)
          CHECK(sgn(relpos::evaluate(fp, r.lower)) * sgn(relpos::evaluate(fp, r.upper)) < 0);
      }
      if (i > 0)
        CHECK((roots[i - 1].exact ? *roots[i - 1].exact : roots[i - 1].upper) <= (r.exact ? *r.exact : r.lower));
    }
  }
}

TEST_CASE("pair: the per-thread scratch never shows in a result", "[pair]") {
  // Results of the full evidence, kept while later pairs reuse the thread's scratch: every number
  // of an earlier result keeps its value (their digits compared before and after).
  const std::vector<PairCase> all = cases(relpos::testing::seed_from_env(20260301));
  std::vector<relpos::Classification> kept;
  std::vector<std::string> before;
  auto digits = [](const relpos::Classification& c) {
    std::string t;
    for (const Rational& x : c.f) t += relpos::to_string(x) + " ";
    for (const Rational& x : c.s) t += relpos::to_string(x) + " ";
    for (const auto& r : c.roots) t += relpos::to_string(r.lower) + " " + relpos::to_string(r.upper) + " ";
    t += relpos::to_string(c.certificate.lambda) + " " + relpos::to_string(c.certificate.inside[0]) + " " +
         relpos::to_string(c.certificate.d);
    return t;
  };
  for (const PairCase& k : all) {
    kept.push_back(relpos::classify(k.e, k.p));
    before.push_back(digits(kept.back()));
  }
  for (const PairCase& k : all) static_cast<void>(relpos::classify(k.e, k.p));
  for (std::size_t i = 0; i < kept.size(); ++i) CHECK(digits(kept[i]) == before[i]);
}
