// between.hpp: a short rational inside an open interval, in both senses of short, against the
// definitions computed independently on rationals (the first dyadic of the midpoint's roundings;
// no rational of smaller denominator in the interval, by enumeration).
#include <gmp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <optional>
#include <random>
#include <string>

#include "algebra/between.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;

TEST_CASE("rational_inside, fewest bits: the first dyadic floor(mid 2^b) / 2^b above lo, b = 0, 4, 8, ...", "[forms]") {
  // Ends that are doubles (isolating intervals), one of them an exact rational or both, of either
  // sign, close and far apart: the answer is the definition's, computed here on rationals.
  rt::Rng g(2718);
  std::mt19937_64 bits(11);
  auto reference = [](const Rational& lo, const Rational& hi) {
    const Rational mid = (lo + hi) / 2;
    for (unsigned b = 0; b <= 2048; b += 4) {
      Rational step(1);
      for (unsigned i = 0; i < b; ++i) step /= 2;
      Integer scaled;
      const Rational x = mid / step;
      mpz_fdiv_q(scaled.mpz(), mpq_numref(x.mpq()), mpq_denref(x.mpq()));
      const Rational y = Rational(scaled) * step;
      if (lo < y && y < hi) return y;
    }
    return mid;
  };
  for (int trial = 0; trial < 6000; ++trial) {
    const double a =
        std::ldexp(std::uniform_real_distribution<double>(-1, 1)(bits), static_cast<int>(g.uniform(-60, 60)));
    const double w = std::fabs(a) * std::ldexp(1.0, -static_cast<int>(g.uniform(1, 52)));
    Rational lo(a), hi(a + (w > 0 ? w : 1.0));
    if (trial % 5 == 1) hi = lo + Rational(Integer(1), Integer(g.uniform(3, 1000)) * Integer(2));  // not dyadic
    if (trial % 7 == 2) lo = Rational(Integer(1), Integer(3)) - Rational(Integer(2));
    if (trial % 11 == 3) lo = -hi / 3;                                                               // opposite signs
    if (trial % 13 == 4) hi = lo + Rational(std::ldexp(1.0, static_cast<int>(g.uniform(-70, 70))));  // far apart
    if (trial % 17 == 5) hi = Rational(Integer(g.uniform(-3, 3)));                                   // an integer end
    if (!(lo < hi)) continue;
    const Rational got = relpos::detail::rational_inside(lo, hi, relpos::detail::Shortest::Bits);
    const Rational want = reference(lo, hi);
    CAPTURE(relpos::to_string(lo), relpos::to_string(hi));
    CHECK(lo < got);
    CHECK(got < hi);
    CHECK(mpz_cmp(mpq_numref(got.mpq()), mpq_numref(want.mpq())) == 0);  // the same canonical rational
    CHECK(mpz_cmp(mpq_denref(got.mpq()), mpq_denref(want.mpq())) == 0);
  }
}

TEST_CASE("rational_inside, smallest denominator: no rational of smaller denominator in the interval", "[between]") {
  // The simplest rational of (lo, hi): checked against the definition by enumeration: for every
  // denominator q below the answer's, no integer p has lo < p / q < hi; at the answer's denominator,
  // no p of smaller magnitude does. Ends of either sign, small and large, hi unbounded too.
  rt::Rng g(1618);
  int checked = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Rational lo = g.rational(-3000, 3000, 400);
    std::optional<Rational> hi;
    if (trial % 10 != 0) hi = lo + g.positive_rational(trial % 3 == 0 ? 2000 : 20, 500);
    const Rational x = relpos::detail::rational_inside(lo, hi, relpos::detail::Shortest::Denominator);
    CAPTURE(relpos::to_string(lo), hi ? relpos::to_string(*hi) : std::string("+inf"), relpos::to_string(x));
    REQUIRE(lo < x);
    if (hi) REQUIRE(x < *hi);
    const Integer den = x.denominator();
    REQUIRE(den <= 100000);  // small ends: a small answer
    // The integers p with lo q < p < hi q: from floor(lo q) + 1 up.
    auto first_above = [&lo](const Integer& q) {
      const Rational t = lo * Rational(q);
      Integer f;
      mpz_fdiv_q(f.mpz(), t.numerator().mpz(), t.denominator().mpz());
      return Integer(f + 1);
    };
    auto inside = [&](const Integer& p, const Integer& q) {
      const Rational y(p, q);
      return lo < y && (!hi || y < *hi);
    };
    for (Integer q(1); q < den; q += 1) REQUIRE_FALSE(inside(first_above(q), q));
    // At den, the candidate of smallest magnitude: 0 when the interval holds it, else the one
    // nearest to 0 (from lo up when lo >= 0, from hi down when hi <= 0).
    Integer nearest(0);
    if (lo >= 0) {
      nearest = first_above(den);
    } else if (hi && *hi <= 0) {
      const Rational t = *hi * Rational(den);
      mpz_cdiv_q(nearest.mpz(), t.numerator().mpz(), t.denominator().mpz());
      nearest -= 1;
    }
    CHECK(x.numerator() == nearest);
    ++checked;
  }
  CHECK(checked == 2000);
}
