// exact_doubles.hpp: doubles and rationals converted from their bits, against GMP and CGAL: a
// double as m 2^k (m odd), set_double as mpq_set_d, truncated_double as mpq_get_d, tight_interval
// as CGAL::to_interval, bit for bit, over the whole exponent range.
#include <CGAL/Gmpq.h>
#include <gmp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "algebra/exact_doubles.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;

TEST_CASE("dyadic_of: a double as m 2^k with m odd", "[exact_doubles]") {
  rt::Rng g(5);
  std::mt19937_64 bits(6);
  for (int trial = 0; trial < 20000; ++trial) {
    const double x = trial == 0 ? std::numeric_limits<double>::denorm_min()
                                : std::ldexp(std::uniform_real_distribution<double>(-1, 1)(bits),
                                             static_cast<int>(g.uniform(-1080, 1024)));
    if (!std::isfinite(x) || x == 0) continue;
    const relpos::detail::forms::Dyadic d = relpos::detail::forms::dyadic_of(x);
    CAPTURE(x);
    CHECK(d.m % 2 != 0);
    CHECK(std::ldexp(static_cast<double>(d.m), static_cast<int>(d.k)) == x);  // exact: |m| < 2^53
  }
}

TEST_CASE("set_double writes the canonical rational mpq_set_d writes", "[exact_doubles]") {
  // Zero, integers, dyadic fractions, subnormals and the extremes, of either sign, into values
  // that held something else before (the caller's fresh or reused rationals).
  rt::Rng g(27);
  std::mt19937_64 bits(8);
  const double special[] = {0.0,
                            -0.0,
                            1.0,
                            -3.0,
                            0.5,
                            std::numeric_limits<double>::denorm_min(),
                            -std::numeric_limits<double>::min(),
                            std::numeric_limits<double>::max(),
                            0x1p52,
                            0x1.8p-1074};
  for (int trial = 0; trial < 20000; ++trial) {
    const double x = trial < 10 ? special[trial]
                                : std::ldexp(std::uniform_real_distribution<double>(-1, 1)(bits),
                                             static_cast<int>(g.uniform(-1080, 1024)));
    if (!std::isfinite(x)) continue;
    Rational got(Integer(g.uniform(-99, 99)), Integer(g.uniform(1, 99))), want;
    relpos::detail::forms::set_double(got.mpq(), x);
    mpq_set_d(want.mpq(), x);
    CAPTURE(x);
    CHECK(mpz_cmp(mpq_numref(got.mpq()), mpq_numref(want.mpq())) == 0);
    CHECK(mpz_cmp(mpq_denref(got.mpq()), mpq_denref(want.mpq())) == 0);
  }
}

TEST_CASE("truncated_double is mpq_get_d, dyadic or not", "[exact_doubles]") {
  rt::Rng g(17);
  std::mt19937_64 bits(18);
  for (int trial = 0; trial < 20000; ++trial) {
    const double d =
        std::ldexp(std::uniform_real_distribution<double>(-1, 1)(bits), static_cast<int>(g.uniform(-1100, 1100)));
    Rational q = Rational(std::isfinite(d) ? d : 1.0);
    if (trial % 3 == 1) q += Rational(Integer(1), Integer(1) << 300);  // dyadic, more than 53 bits
    if (trial % 3 == 2) q *= Rational(Integer(g.uniform(1, 1000)), Integer(g.uniform(1, 999)) * 2 + 1);
    CAPTURE(relpos::to_string(q));
    CHECK(relpos::detail::forms::truncated_double(q) == mpq_get_d(q.mpq()));
  }
}

TEST_CASE("tight_interval equals CGAL::to_interval bit for bit", "[exact_doubles]") {
  // Doubles (exact: a point), dyadics with more than 53 bits, general rationals, subnormal and
  // huge values (CGAL's own path), of either sign.
  rt::Rng g(314);
  std::mt19937_64 bits(15);
  for (int trial = 0; trial < 20000; ++trial) {
    Rational q;
    const double d =
        std::ldexp(std::uniform_real_distribution<double>(-1, 1)(bits), static_cast<int>(g.uniform(-1100, 1100)));
    switch (trial % 4) {
      case 0:
        q = Rational(std::isfinite(d) ? d : 1.0);
        break;
      case 1:
        q = Rational(std::isfinite(d) ? d : 1.0) + Rational(Integer(1), Integer(1) << 200);
        break;
      case 2:
        q = Rational(Integer(g.uniform(-(1L << 60), 1L << 60)), Integer(g.uniform(1, 1L << 60)));
        break;
      default:
        q = Rational(Integer(g.uniform(1, 1000)), Integer(3)) * Rational(std::isfinite(d) && d != 0 ? d : 1.0);
    }
    CAPTURE(relpos::to_string(q));
    const std::pair<double, double> got = relpos::detail::forms::tight_interval(q), want = CGAL::to_interval(q);
    CHECK(got.first == want.first);
    CHECK(got.second == want.second);
  }
}
