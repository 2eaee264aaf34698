// numbers.hpp: exact parsing, exact doubles, printing and decimal rounding; polynomials.hpp's
// evaluate as a ring homomorphism.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <relpos/error.hpp>
#include <relpos/numbers.hpp>
#include <relpos/polynomials.hpp>
#include <string>
#include <thread>
#include <vector>

#include "algebra/number_limits.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using relpos::exact_rational;
using relpos::InputError;
using relpos::Integer;
using relpos::parse_rational;
using relpos::Rational;
using relpos::to_decimal;
using rt::Q;

namespace {
Rational pow10(int e) {
  Rational r(1);
  for (int i = 0; i < (e < 0 ? -e : e); ++i) r *= 10;
  return e < 0 ? Rational(1) / r : r;
}
}  // namespace

TEST_CASE("parse_rational: integers", "[numbers][parse]") {
  CHECK(parse_rational("0") == Q(0));
  CHECK(parse_rational("7") == Q(7));
  CHECK(parse_rational("-3") == Q(-3));
  CHECK(parse_rational("+12") == Q(12));
  CHECK(parse_rational("-0") == Q(0));
  CHECK(parse_rational("000123") == Q(123));
  // Beyond 64 bits: exact.
  Rational big = parse_rational("123456789012345678901234567890");
  CHECK(big == Rational(Integer("123456789012345678901234567890")));
  CHECK(big + 1 == parse_rational("123456789012345678901234567891"));
}

TEST_CASE("parse_rational: fractions", "[numbers][parse]") {
  CHECK(parse_rational("1/2") == Q(1, 2));
  CHECK(parse_rational("-1/2") == Q(-1, 2));
  CHECK(parse_rational("+3/4") == Q(3, 4));
  CHECK(parse_rational("6/4") == Q(3, 2));  // canonicalized
  CHECK(parse_rational("-10/5") == Q(-2));
  CHECK(parse_rational("0/7") == Q(0));
  CHECK(parse_rational("92281/129600") == Q(92281, 129600));
}

TEST_CASE("parse_rational: decimals and exponents are exact", "[numbers][parse]") {
  CHECK(parse_rational("0.712045") == Q(712045, 1000000));
  CHECK(parse_rational("0.712045") != Rational(0.712045));  // never the nearest double
  CHECK(parse_rational("0.1") == Q(1, 10));
  CHECK(parse_rational("0.1") != Rational(0.1));
  CHECK(parse_rational(".5") == Q(1, 2));
  CHECK(parse_rational("-.5") == Q(-1, 2));
  CHECK(parse_rational("+.25") == Q(1, 4));
  CHECK(parse_rational("5.") == Q(5));
  CHECK(parse_rational("-2.50") == Q(-5, 2));
  CHECK(parse_rational("1.2") == Q(6, 5));
  CHECK(parse_rational("1e3") == Q(1000));
  CHECK(parse_rational("1.5e-7") == Q(15, 100000000));
  CHECK(parse_rational("2E+10") == Q(20000000000L));
  CHECK(parse_rational("-2.5E-1") == Q(-1, 4));
  CHECK(parse_rational("1.25e2") == Q(125));
  CHECK(parse_rational(".5e1") == Q(5));
  CHECK(parse_rational("5.e-1") == Q(1, 2));
  CHECK(parse_rational("0.000001") == Q(1, 1000000));
  CHECK(parse_rational("1e-30") == pow10(-30));
  CHECK(parse_rational("3e30") == 3 * pow10(30));
}

TEST_CASE("parse_rational: malformed text throws InputError naming the text", "[numbers][parse][errors]") {
  using Catch::Matchers::Contains;
  for (const char* bad :
       {"1.2.3", "1/0",   "",      "   ",  "abc",   "1e",  "0x10", "1/2/3", "--1",  "+-1",      "1e+",  ".",
        "e5",    "1 2",   "1/",    "/2",   "1.5/2", "nan", "NaN",  "inf",   "-inf", "Infinity", "1,5",  "1e1.5",
        "½",     "1/0.5", "0x1p3", "1ee2", "12a",   " 1",  "1 ",   "\t42",  "1/-2", "1/+2",     "-1/-2"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(parse_rational(bad), InputError);
  }
  CHECK_THROWS_WITH(parse_rational("1.2.3"), Contains("1.2.3"));
  CHECK_THROWS_WITH(parse_rational("abc"), Contains("abc"));
  CHECK_THROWS_WITH(parse_rational("0x10"), Contains("0x10"));
  CHECK_THROWS_WITH(parse_rational("1/0"), Contains("1/0"));
  // InputError is an std::invalid_argument.
  CHECK_THROWS_AS(parse_rational("abc"), std::invalid_argument);
}

TEST_CASE("parse_rational: hostile sizes give a clear error, not a hang", "[numbers][parse][errors]") {
  CHECK_THROWS_AS(parse_rational("1e999999999"), InputError);
  CHECK_THROWS_AS(parse_rational("1e-999999999"), InputError);
  CHECK_THROWS_AS(parse_rational("1e4001"), InputError);  // beyond kMaxDecimalExponent
  CHECK(parse_rational("1e4000") == pow10(4000));         // at the limit
  CHECK_THROWS_AS(parse_rational(std::string(relpos::detail::kMaxNumberChars + 1, '7')), InputError);
  CHECK(parse_rational(std::string(relpos::detail::kMaxNumberChars, '0')) == 0);
}

TEST_CASE("exact_rational: a double is exactly its dyadic value", "[numbers][double]") {
  CHECK(exact_rational(0.5) == Q(1, 2));
  CHECK(exact_rational(0.125) == Q(1, 8));
  CHECK(exact_rational(-3.0) == Q(-3));
  CHECK(exact_rational(0.0) == Q(0));
  CHECK(exact_rational(-0.0) == Q(0));
  CHECK(exact_rational(0.1) == Rational(0.1));
  CHECK(exact_rational(0.1) != Q(1, 10));
  // 0.1 = 3602879701896397 / 2^55 exactly.
  Rational two55(1);
  for (int i = 0; i < 55; ++i) two55 *= 2;
  CHECK(exact_rational(0.1) == Rational(Integer(3602879701896397L)) / two55);
  CHECK(exact_rational(0.712045) == Rational(0.712045));
  CHECK(exact_rational(0.712045) != Q(712045, 1000000));
  // Extremes are still exact (subnormal, largest).
  const double tiny = std::numeric_limits<double>::denorm_min();
  Rational two1074(1);
  for (int i = 0; i < 1074; ++i) two1074 *= 2;
  CHECK(exact_rational(tiny) == Rational(1) / two1074);
  CHECK(exact_rational(std::numeric_limits<double>::max()) > pow10(308));
  CHECK(exact_rational(1e300) == Rational(1e300));
}

TEST_CASE("exact_rational: non-finite doubles throw", "[numbers][double][errors]") {
  using Catch::Matchers::Contains;
  CHECK_THROWS_AS(exact_rational(std::numeric_limits<double>::quiet_NaN()), InputError);
  CHECK_THROWS_AS(exact_rational(std::numeric_limits<double>::infinity()), InputError);
  CHECK_THROWS_AS(exact_rational(-std::numeric_limits<double>::infinity()), InputError);
  CHECK_THROWS_WITH(exact_rational(std::nan("")), Contains("finite"));
}

TEST_CASE("to_string: shortest exact text", "[numbers][print]") {
  CHECK(relpos::to_string(Q(3)) == "3");
  CHECK(relpos::to_string(Q(-7, 2)) == "-7/2");
  CHECK(relpos::to_string(Q(6, 4)) == "3/2");
  CHECK(relpos::to_string(Q(0)) == "0");
  CHECK(relpos::to_string(Q(-10, 5)) == "-2");
  CHECK(relpos::to_string(Integer(-12345)) == "-12345");
  CHECK(relpos::to_string(Integer(0)) == "0");
  CHECK(relpos::to_string(Integer("98765432109876543210")) == "98765432109876543210");
  // Round trip through the parser.
  rt::Rng g(20240601);
  for (int i = 0; i < 200; ++i) {
    Rational q = g.rational(-1000000, 1000000, 1000000);
    CAPTURE(relpos::to_string(q));
    CHECK(parse_rational(relpos::to_string(q)) == q);
  }
}

TEST_CASE("to_decimal: rounding to significant digits", "[numbers][print]") {
  CHECK(to_decimal(Q(1, 3), 5) == "0.33333");
  CHECK(to_decimal(Q(2, 3), 3) == "0.667");
  CHECK(to_decimal(Q(-2, 3), 3) == "-0.667");
  CHECK(to_decimal(Q(1, 2), 5) == "0.5");  // no trailing zeros
  CHECK(to_decimal(Q(1), 6) == "1");
  CHECK(to_decimal(Q(0), 4) == "0");
  CHECK(to_decimal(Q(1, 8), 2) == "0.13");    // half rounds up
  CHECK(to_decimal(Q(-1, 8), 2) == "-0.13");  // symmetric in the sign
  CHECK(to_decimal(Q(5, 2), 1) == "3");
  CHECK(to_decimal(Q(249, 25), 2) == "10");  // 9.96: rounding carries into a new digit
  CHECK(to_decimal(Q(999, 1000), 2) == "1");
  CHECK(to_decimal(Q(1, 1000), 3) == "0.001");
  CHECK(to_decimal(Q(314159, 100000), 3) == "3.14");
  CHECK(to_decimal(Q(-36, 25), 4) == "-1.44");
  CHECK(to_decimal(Q(12345), 3) == "12300");
  CHECK(to_decimal(Q(22, 7), 10) == "3.142857143");
  CHECK(to_decimal(Q(92281, 129600), 6) == "0.712045");  // the paper's z_c
}

TEST_CASE("to_decimal: very large and very small values round to within half a unit", "[numbers][print]") {
  // Whatever the format (plain or exponent), the text parses back to within half a unit in the
  // last significant digit: |x - q| <= 5 * 10^-digits * |q|.
  rt::Rng g(777);
  for (int i = 0; i < 300; ++i) {
    Rational q = g.nonzero_rational(-99999, 99999, 99999) * pow10(static_cast<int>(g.uniform(-40, 40)));
    const int digits = static_cast<int>(g.uniform(1, 17));
    const std::string s = to_decimal(q, digits);
    CAPTURE(relpos::to_string(q), digits, s);
    Rational x = parse_rational(s);
    CHECK(rt::rabs(x - q) <= 5 * pow10(-digits) * rt::rabs(q));
    CHECK(rt::sgn(x) == rt::sgn(q));
  }
  CHECK(parse_rational(to_decimal(pow10(30), 3)) == pow10(30));
  CHECK(parse_rational(to_decimal(pow10(-10), 3)) == pow10(-10));
}

namespace {

/// Text of a chain of exact operations on growing numbers: limb arrays of many sizes are allocated,
/// grown (realloc) and freed.
std::string gmp_workout(int seed) {
  rt::Rng g(static_cast<unsigned>(seed));
  Rational acc(1);
  std::string out;
  for (int i = 0; i < 60; ++i) {
    const Rational q = g.nonzero_rational(-99999, 99999, 99999);
    acc = i % 3 == 2 ? acc / q + Rational(1, 7) : acc * q - Rational(i);
    if (i % 10 == 9) out += relpos::to_string(acc) + ";";
  }
  Integer big(1);
  for (int i = 1; i < 120; ++i) big *= Integer(1000003 + i);  // past the cached sizes: plain realloc
  return out + relpos::to_string(big);
}

}  // namespace

TEST_CASE("install_gmp_block_cache: the same values, on every thread, with numbers made before it",
          "[numbers][allocator]") {
  std::vector<std::string> expected;
  for (int s = 0; s < 8; ++s) expected.push_back(gmp_workout(s));
  std::vector<Rational> before;  // allocated by the default allocator, freed by the cache
  for (int s = 0; s < 200; ++s) before.push_back(Rational(s + 1, 3) * Rational(1000000007));
  relpos::install_gmp_block_cache();
  relpos::install_gmp_block_cache();  // idempotent
  for (int s = 0; s < 200; ++s) CHECK(before[static_cast<std::size_t>(s)] == Rational(s + 1, 3) * Rational(1000000007));
  before.clear();
  std::vector<std::string> got(32);
  std::vector<Rational> made(32);  // made on the workers, freed on this thread
  std::vector<std::thread> workers;
  for (int t = 0; t < 4; ++t)
    workers.emplace_back([&, t] {
      for (int k = t; k < 32; k += 4) {
        got[static_cast<std::size_t>(k)] = gmp_workout(k % 8);
        made[static_cast<std::size_t>(k)] = Rational(k + 1, 11) * Rational(998244353);
      }
    });
  for (auto& w : workers) w.join();
  for (int k = 0; k < 32; ++k) {
    CHECK(got[static_cast<std::size_t>(k)] == expected[static_cast<std::size_t>(k % 8)]);
    CHECK(made[static_cast<std::size_t>(k)] == Rational(k + 1, 11) * Rational(998244353));
  }
  CHECK(gmp_workout(3) == expected[3]);
}

TEST_CASE("evaluate: a ring homomorphism, p(x) + q(x) = (p + q)(x) and p(x) q(x) = (pq)(x)", "[numbers][polynomials]") {
  rt::Rng g(5772);
  for (int trial = 0; trial < 500; ++trial) {
    relpos::RationalPolynomial p, q;
    for (long i = g.uniform(0, 6); i > 0; --i) p.push_back(g.rational(-20, 20, 9));
    for (long i = g.uniform(0, 6); i > 0; --i) q.push_back(g.rational(-20, 20, 9));
    relpos::RationalPolynomial sum(std::max(p.size(), q.size()), Rational(0));
    relpos::RationalPolynomial product(p.empty() || q.empty() ? 0 : p.size() + q.size() - 1, Rational(0));
    for (std::size_t i = 0; i < p.size(); ++i) sum[i] += p[i];
    for (std::size_t i = 0; i < q.size(); ++i) sum[i] += q[i];
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = 0; j < q.size(); ++j) product[i + j] += p[i] * q[j];
    const Rational x = g.rational(-30, 30, 7);
    CHECK(relpos::evaluate(p, x) + relpos::evaluate(q, x) == relpos::evaluate(sum, x));
    CHECK(relpos::evaluate(p, x) * relpos::evaluate(q, x) == relpos::evaluate(product, x));
    if (!p.empty()) CHECK(relpos::evaluate(p, Rational(0)) == p[0]);
  }
  CHECK(relpos::evaluate({}, Q(3)) == 0);  // the zero polynomial
}
