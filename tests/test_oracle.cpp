// The oracle for float code (src/oracle/, doc/oracle.md): the doubles nearest rationals against the C
// library's correctly rounded reader, the families' positions by construction against relpos (exact,
// with verified certificates) and their s* against the scaled pair's tangency, reproducibility, the
// float code's matrices on exact inputs, the tolerance decided from hand-written sphere margins whose
// s* is known in closed form, and the judge's counts on hand-written answers.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <relpos/classify.hpp>
#include <relpos/error.hpp>
#include <relpos/io.hpp>
#include <relpos/margin.hpp>
#include <relpos/numbers.hpp>
#include <string>
#include <vector>

#include "oracle/cases.hpp"
#include "oracle/judge.hpp"
#include "oracle/nearest.hpp"
#include "oracle/tolerance.hpp"
#include "support/seed.hpp"

using namespace relpos;
using namespace relpos::detail::oracle;

namespace {

Rational q(long n, long d = 1) { return Rational(Integer(n), Integer(d)); }

Ellipsoid ellipsoid_of(const Parameters& p) { return Ellipsoid::from_axes(p.centre, p.axes, p.e_rotation); }
Paraboloid paraboloid_of(const Parameters& p) { return Paraboloid::standard(p.vertex, p.a, p.b, p.p_rotation); }

nlohmann::ordered_json margin_json(const Rational& lo, const Rational& hi, const std::vector<long>& poly) {
  nlohmann::ordered_json j{{"approx", 0}, {"lo", to_string(lo)}, {"hi", to_string(hi)}};
  for (long c : poly) j["polynomial"].push_back(std::to_string(c));
  return j;
}

}  // namespace

TEST_CASE("nearest_double rounds like the C library's correctly rounded reader, ties to even", "[oracle]") {
  std::mt19937_64 rng(testing::announced_seed("nearest_double", 7));
  for (int i = 0; i < 3000; ++i) {
    char text[64];
    const long long m = static_cast<long long>(rng() % 2000000000000000000ULL) - 1000000000000000000LL;
    std::snprintf(text, sizeof text, "%lld.%llde%d", m, static_cast<unsigned long long>(rng() % 1000000),
                  static_cast<int>(rng() % 610) - 340);  // down to subnormals
    CHECK(nearest_double(parse_rational(text)) == std::strtod(text, nullptr));
  }
  // Midpoints: 2^53 + 1 rounds down to the even 2^53, 2^53 + 3 up to 2^53 + 4.
  const Rational two53 = exact_rational(9007199254740992.0);
  CHECK(nearest_double(two53 + 1) == 9007199254740992.0);
  CHECK(nearest_double(two53 + 3) == 9007199254740996.0);
  CHECK(nearest_double(q(1, 3)) == 1.0 / 3.0);
  CHECK(nearest_double(-q(2, 3)) == -2.0 / 3.0);
  CHECK(exact_text(0.5) == "1/2");
  CHECK_THROWS_AS(nearest_double(exact_rational(1e308) * 10), InputError);
}

TEST_CASE("every family's position by construction is relpos's, certified, and s* makes the scaled pair touch",
          "[oracle]") {
  const std::uint64_t seed = testing::announced_seed("oracle families", 3);
  for (const Family& f : families()) {
    for (const char* e : {"1/10", "1e-9", "0"}) {
      for (std::uint64_t i = 0; i < 6; ++i) {
        INFO(f.name << " eps " << e << " case " << i);
        const Construction c = construct(f, parse_rational(e), seed, i);
        const Ellipsoid el = ellipsoid_of(c.exact);
        const Paraboloid pa = paraboloid_of(c.exact);
        const Classification answer = classify(el, pa, Evidence::Full);
        CHECK(!verify_certificate(el, pa, answer.verdict.position, answer.certificate));
        if (!c.position) {  // the random family: no construction
          CHECK(c.side.empty());
          continue;
        }
        CHECK(answer.verdict.position == *c.position);
        REQUIRE(c.s_star);
        const bool inside_only = std::string(f.name) == "special" || std::string(f.name) == "circular";
        const bool closer = (inside_only ? i : i / 2) % 2 == 1;
        const Rational eps = parse_rational(e);
        CHECK(*c.s_star == (f.uses_eps ? (closer ? 1 - eps : 1 + eps) : Rational(1)));
        CHECK(c.side == (inside_only || i % 2 == 0 ? "inside" : "outside"));
        Parameters touching = c.exact;
        for (Rational& a : touching.axes) a *= *c.s_star;
        const Position at = decide_position(ellipsoid_of(touching), paraboloid_of(touching)).position;
        CHECK(at == (c.side == "inside" ? Position::TI : Position::TE));
      }
    }
  }
}

TEST_CASE("cases: a seed gives the same lines; a case does not depend on --n or the other families", "[oracle]") {
  CaseOptions a;
  a.families = {"offaxis", "special"};
  a.n = 3;
  a.eps = {"1e-6", "0"};
  a.seed = 11;
  CaseOptions b = a;
  b.families = {"special"};
  b.n = 5;
  const std::vector<Case> ca = make_cases(a), cb = make_cases(b);
  REQUIRE(ca.size() == 12);
  REQUIRE(cb.size() == 10);
  for (const Case& x : ca) {
    CHECK(case_line(x, Form::Exact) == case_line(make_cases(a)[static_cast<std::size_t>(&x - ca.data())], Form::Exact));
    for (const Case& y : cb)
      if (x.id == y.id) CHECK(case_line(x, Form::Exact) == case_line(y, Form::Exact));
  }
  a.seed = 12;
  CHECK(case_line(make_cases(a)[0], Form::Exact) != case_line(ca[0], Form::Exact));
  a.families = {"nothing"};
  CHECK_THROWS_AS(make_cases(a), InputError);
  a.families = {"axis"};
  a.eps = {"1"};
  CHECK_THROWS_AS(make_cases(a), InputError);
}

TEST_CASE("cases carry the certified margins: each verifies and holds the s* the construction knows", "[oracle]") {
  CaseOptions o;
  o.families = {"all"};
  o.n = 2;
  o.eps = {"1e-4", "0"};
  o.seed = 5;
  std::size_t known = 0;
  for (const Case& c : make_cases(o)) {
    INFO(c.id);
    REQUIRE(c.margin);
    REQUIRE(c.double_margin);
    const Ellipsoid e = ellipsoid_of(c.construction.exact);
    const Paraboloid p = paraboloid_of(c.construction.exact);
    CHECK_FALSE(verify_margin(e, p, *c.margin));
    const Parameters d = exact_parameters(c.doubles);
    CHECK_FALSE(verify_margin(ellipsoid_of(d), paraboloid_of(d), *c.double_margin));
    // s* against the position: > 1 for I and E, = 1 for TI and TE, < 1 for C (math.md §19).
    const Position pos = c.exact_position;
    if (pos == Position::C) CHECK(c.margin->hi < 1);
    if (pos == Position::TI || pos == Position::TE) CHECK((c.margin->lo == 1 && c.margin->hi == 1));
    if (pos == Position::I || pos == Position::E) CHECK(c.margin->lo > 1);
    if (c.construction.s_star) {
      ++known;
      CHECK(c.margin->lo <= *c.construction.s_star);
      CHECK(*c.construction.s_star <= c.margin->hi);
    }
    // The line carries them as `relpos batch --margin` writes them.
    const nlohmann::ordered_json line = nlohmann::ordered_json::parse(case_line(c, Form::Exact));
    CHECK(line["meta"]["margin"].dump() == nlohmann::ordered_json::parse(io::margin_json_text(*c.margin)).dump());
  }
  CHECK(known > 0);
}

TEST_CASE("the float code's matrices of exact dyadic parameters are the exact matrices", "[oracle]") {
  DoubleParameters d{{0.5, -0.25, 1.0}, {0.5, 0.25, 2.0}, {1, 0, 0, 0}, {0.0, 0.0, -1.0}, 2.0, 0.5, {1, 0, 0, 0}};
  const Parameters p = exact_parameters(d);
  const Ellipsoid el = ellipsoid_of(p);
  const Paraboloid pa = paraboloid_of(p);
  const Matrix4& e = el.matrix();
  const Matrix4& m = pa.matrix();
  const DoubleMatrix4 fe = ellipsoid_matrix(d), fp = paraboloid_matrix(d);
  // The library's matrices may be scaled by a positive constant: compare up to the (3, 3)/(2, 3) ratio.
  const Rational ke = exact_rational(fe[0]) / e(0, 0), kp = exact_rational(fp[11]) / m(2, 3);
  for (std::size_t k = 0; k < 16; ++k) {
    CHECK(exact_rational(fe[k]) == ke * e.a[k]);
    CHECK(exact_rational(fp[k]) == kp * m.a[k]);
  }
  const DoubleMatrix4 u = upper_triangle({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
  CHECK(u == DoubleMatrix4{1, 2, 3, 4, 2, 6, 7, 8, 3, 7, 11, 12, 4, 8, 12, 16});
}

TEST_CASE("tolerance: sphere margins with s* in closed form", "[oracle]") {
  // A sphere of radius r centred (0, 0, c) in the cup z = x^2 + y^2 (a = b = 1): with c <= 1/2 the
  // vertex is the nearest point, s* = c / r (rational); above, the nearest points form a circle at
  // distance sqrt(c - 1/4), s*^2 = (c - 1/4) / r^2 (math of doc/oracle.md, "Families").
  const detail::oracle::MarginValue rational =
      margin_from_json(margin_json(q(2, 5), q(2, 5), {-2, 5}));  // c = 1/5, r = 1/2
  CHECK(compare_with(q(2, 5), rational) == 0);
  CHECK(compare_with(q(1, 2), rational) == 1);
  // c = 3/4, r = 1: s*^2 = 1/2, s* = 1/sqrt(2) ~ 0.7071 in [7/10, 71/100], root of 2 x^2 - 1.
  const detail::oracle::MarginValue root = margin_from_json(margin_json(q(7, 10), q(71, 100), {-1, 0, 2}));
  for (const auto& [t, sign] : std::vector<std::pair<Rational, int>>{
           {q(7, 10), -1}, {q(707, 1000), -1}, {q(7072, 10000), 1}, {q(71, 100), 1}, {q(1), 1}, {q(1, 2), -1}})
    CHECK(compare_with(t, root) == sign);
  // tau = 3/10: factors [7/10, 13/10] reach s*: TI, I and C are excused; outside positions never.
  CHECK(within_tolerance(Position::TI, CentreSide::Inside, root, q(3, 10)));
  CHECK(within_tolerance(Position::I, CentreSide::Inside, root, q(3, 10)));     // the factor 7/10 < s*
  CHECK(!within_tolerance(Position::I, CentreSide::Inside, root, q(29, 100)));  // 71/100 > s*: no factor below
  CHECK(within_tolerance(Position::C, CentreSide::Inside, root, q(0)));         // s* < 1: the pair itself crosses
  CHECK(!within_tolerance(Position::TI, CentreSide::Inside, root, q(29, 100)));
  CHECK(!within_tolerance(Position::E, CentreSide::Inside, root, q(1, 2)));
  CHECK(!within_tolerance(Position::TE, CentreSide::Inside, root, q(1, 2)));
  // Outside, s* = 1 + 1/1000: E within any tau, TE from tau = 1/1000 on, C beyond it.
  const detail::oracle::MarginValue out = margin_from_json(margin_json(q(1001, 1000), q(1001, 1000), {-1001, 1000}));
  CHECK(within_tolerance(Position::E, CentreSide::Outside, out, q(0)));
  CHECK(!within_tolerance(Position::TE, CentreSide::Outside, out, q(999, 1000000)));
  CHECK(within_tolerance(Position::TE, CentreSide::Outside, out, q(1, 1000)));
  CHECK(!within_tolerance(Position::C, CentreSide::Outside, out, q(1, 1000)));
  CHECK(within_tolerance(Position::C, CentreSide::Outside, out, q(1001, 1000000)));
  // The centre on the surface: only C.
  const detail::oracle::MarginValue zero = margin_from_json(margin_json(q(0), q(0), {0, 1}));
  CHECK(within_tolerance(Position::C, CentreSide::On, zero, q(0)));
  CHECK(!within_tolerance(Position::TI, CentreSide::On, zero, q(2)));
  // Refused margins.
  CHECK_THROWS_AS(margin_from_json(margin_json(q(8, 10), q(9, 10), {-1, 0, 2})), InputError);  // no root inside
  CHECK_THROWS_AS(margin_from_json(margin_json(q(9, 10), q(8, 10), {-1, 0, 2})), InputError);  // lo > hi
  CHECK_THROWS_AS(margin_from_json(nlohmann::ordered_json{{"approx", 0.7}}), InputError);      // approx alone
}

TEST_CASE("judge: counts of hand-written answers, the tolerance on a sphere, the three truths", "[oracle]") {
  // Three spheres in z = x^2 + y^2: I (c = 1/5, r = 1/10: s* = 2), TI (c = r = 1/5), C (c = 3/4, r = 1:
  // s* = 1/sqrt(2)); each with a hand-written margin.
  const std::string cases =
      R"({"id":"i","ellipsoid":{"sphere":{"center":[0,0,"1/5"],"radius":"1/10"}},"paraboloid":{"vertex":[0,0,0],"a":1,"b":1},"meta":{"family":"s","eps":"1/10","margin":{"lo":"2","hi":"2"}}})"
      "\n"
      R"({"id":"t","ellipsoid":{"sphere":{"center":[0,0,"1/5"],"radius":"1/5"}},"paraboloid":{"vertex":[0,0,0],"a":1,"b":1},"meta":{"family":"s","eps":"0","margin":{"lo":"1","hi":"1"}}})"
      "\n"
      R"({"id":"c","ellipsoid":{"sphere":{"center":[0,0,"3/4"],"radius":1}},"paraboloid":{"vertex":[0,0,0],"a":1,"b":1},"meta":{"family":"r","eps":"1/10","margin":{"lo":"7/10","hi":"71/100","polynomial":["-1","0","2"]}}})"
      "\n"
      R"({"id":"m","ellipsoid":{"sphere":{"center":[0,0,-1],"radius":"1/2"}},"paraboloid":{"vertex":[0,0,0],"a":1,"b":1}})"
      "\n";
  // i: wrong (TI); t: right, then a duplicate; c: undecided; m: missing; and three answers that match
  // no case: not JSON, no id, an unknown id.
  const std::string answers =
      "{\"id\":\"i\",\"position\":\"TI\"}\n{\"id\":\"t\",\"position\":\"TI\",\"x\":1}\n"
      "{\"id\":\"t\",\"position\":\"C\"}\n{\"id\":\"c\",\"position\":null}\nnot json\n{\"position\":\"I\"}\n"
      "{\"id\":\"zz\",\"position\":\"E\"}\n\n";
  JudgeReport r = judge(cases, answers, JudgeOptions{});
  CHECK(r.total.counts.cases == 4);
  CHECK(r.total.counts.right == 1);
  CHECK(r.total.counts.wrong == 1);
  CHECK(r.total.counts.undecided == 1);
  CHECK(r.total.counts.missing == 1);  // m's truth is relpos's (no meta): E
  CHECK(r.malformed == 2);
  CHECK(r.unknown == 1);
  CHECK(r.duplicate == 1);
  CHECK(r.confusion[static_cast<int>(Position::I)][static_cast<int>(Position::TI)] == 1);
  CHECK(r.confusion[static_cast<int>(Position::E)][6] == 1);
  CHECK(r.groups.size() == 4);  // (s, 1/10), (s, 0), (r, 1/10), and m's ("", "")
  REQUIRE(r.misses.size() == 3);
  CHECK(r.misses[0].reproduce.find("relpos classify --ellipsoid '") == 0);
  // With tau = 1: the factor 1/2 makes i touch (s* = 2 is within [0, 2]): excused. c stays undecided.
  JudgeOptions tol;
  tol.tolerance = q(1);
  r = judge(cases, answers, tol);
  CHECK(r.total.counts.excused == 1);
  CHECK(r.total.counts.wrong == 0);
  tol.tolerance = q(49, 100);  // factors [51/100, 149/100] do not reach s* = 2
  CHECK(judge(cases, answers, tol).total.counts.wrong == 1);
  // c answered TI within 3/10 (the factors reach 1/sqrt(2)), not within 29/100.
  const std::string c_ti = "{\"id\":\"c\",\"position\":\"TI\"}\n";
  tol.tolerance = q(3, 10);
  CHECK(judge(cases, c_ti, tol).total.counts.excused == 1);
  tol.tolerance = q(29, 100);
  CHECK(judge(cases, c_ti, tol).total.counts.excused == 0);
  // An answer's own margin comes first; a forged one (no root) is a warning, not an excuse.
  const std::string forged =
      "{\"id\":\"c\",\"position\":\"TI\",\"margin\":{\"lo\":\"8/10\",\"hi\":\"9/10\","
      "\"polynomial\":[\"-1\",\"0\",\"2\"]}}\n";
  tol.tolerance = q(3, 10);
  r = judge(cases, forged, tol);
  CHECK(r.total.counts.excused == 0);
  CHECK(!r.warnings.empty());
  // The double truth of a line read as doubles: 0.25000000000000000000025 is 1/4 as a double.
  const std::string line =
      R"({"id":"d","ellipsoid":{"sphere":{"center":[0,0,0.25000000000000000000025],"radius":0.25}},"paraboloid":{"vertex":[0,0,0],"a":1,"b":1}})";
  JudgeOptions dbl;
  dbl.truth = Truth::Double;
  CHECK(judge(line, "{\"id\":\"d\",\"position\":\"TI\"}", dbl).total.counts.right == 1);
  CHECK(judge(line, "{\"id\":\"d\",\"position\":\"TI\"}", JudgeOptions{}).total.counts.wrong == 1);  // exact: I
  CHECK_THROWS_AS(judge(line + "\n" + line, "", JudgeOptions{}), InputError);  // an id given twice
  // The reports.
  const std::string md = report_markdown(r), csv = report_csv(r), json = report_json(r);
  CHECK(md.find("| all |") != std::string::npos);
  CHECK(csv.rfind("family,eps,cases,", 0) == 0);
  CHECK(nlohmann::json::parse(json)["total"]["cases"] == 4);
}

TEST_CASE("judge: cases of relpos cases, every truth and baseline counted once", "[oracle]") {
  CaseOptions o;
  o.families = {"offaxis", "tiny"};
  o.n = 6;
  o.eps = {"1e-8", "0"};
  std::string cases, right, matrix;
  for (const Case& c : make_cases(o)) {
    cases += case_line(c, Form::Exact) + "\n";
    right += "{\"id\":\"" + c.id + "\",\"position\":\"" + to_string(c.exact_position) + "\"}\n";
    matrix += "{\"id\":\"" + c.id + "\",\"position\":\"" +
              (c.matrix_position ? to_string(*c.matrix_position) : std::string("?")) + "\"}\n";
  }
  JudgeReport r = judge(cases, right, JudgeOptions{});
  CHECK(r.total.counts.right == 24);
  CHECK(r.total.baselines.cases == 24);
  CHECK(r.curves.size() == 3);  // all, offaxis, tiny
  JudgeOptions m;
  m.truth = Truth::Matrix;
  r = judge(cases, matrix, m);
  CHECK(r.total.counts.wrong == 0);
  CHECK(r.total.counts.right + r.total.counts.no_truth == 24);
  CHECK(r.total.counts.undecided == 0);
}
