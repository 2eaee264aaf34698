// divided_by_powers.hpp: z / (scale_1^k_1 scale_2^k_2 ...) in lowest terms from the scales' splits,
// against rational division, canonical form for canonical form: scales of doubles (2^a), decimal
// text (2^a 5^b) and rationals (another factor, shared with z to various powers), one scale or two
// sharing primes; and a split made without its factors is refused rather than dropping its rest.
#include <gmp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "algebra/divided_by_powers.hpp"
#include "algebra/split_scale.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;

TEST_CASE("divided_by_power: z / scale^k in lowest terms, as rational division gives it", "[divided_by_powers]") {
  // Scales of the three kinds the reports meet: doubles (2^a), decimal text (2^a 5^b) and rationals
  // (another factor, shared with z to various powers); z zero, negative, and with many fives.
  rt::Rng g(4242);
  const long rests[] = {1, 3, 7, 9, 21, 1000003, 3 * 3 * 11};
  for (int trial = 0; trial < 2000; ++trial) {
    // Every 4th scale without fives: with rest 1 (every 7th), a double's power of two alone.
    const auto a = static_cast<unsigned long>(g.uniform(0, 40)), b = static_cast<unsigned long>(g.uniform(0, 40));
    Integer scale = Integer(rests[trial % 7]);
    for (unsigned long i = 0; i < a; ++i) scale *= Integer(2);
    for (unsigned long i = 0; i < (trial % 4 == 0 ? 0 : b); ++i) scale *= Integer(5);
    Integer z(static_cast<long>(g.uniform(-1000000, 1000000)));
    const auto extra = g.uniform(0, 6);
    for (long i = 0; i < extra; ++i) z *= Integer(trial % 3 == 0 ? 5 : trial % 3 == 1 ? 2 : rests[trial % 7]);
    if (trial % 5 == 0) z *= scale * scale;  // common factors beyond one power of the scale
    const relpos::detail::forms::SplitScale split = relpos::detail::forms::split_scale(scale);
    for (unsigned long k = 0; k <= 4; ++k) {
      Rational expected(z);
      for (unsigned long i = 0; i < k; ++i) expected /= Rational(scale);
      const Rational got = relpos::detail::forms::divided_by_power(z, split, k);
      CAPTURE(relpos::to_string(z), relpos::to_string(scale), k);
      CHECK(got == expected);
      CHECK(mpz_cmp(mpq_numref(got.mpq()), mpq_numref(expected.mpq())) == 0);  // canonical
      CHECK(mpz_cmp(mpq_denref(got.mpq()), mpq_denref(expected.mpq())) == 0);
    }
  }
}

TEST_CASE("divided_by_powers: two scales with shared prime factors, as rational division gives it",
          "[divided_by_powers]") {
  // The reported f_i = g_i / (lp^i le^(4-i)): the two matrices' scales may share any prime.
  rt::Rng g(777);
  const long parts[] = {1, 2, 3, 5, 6, 10, 12, 15, 49, 1000003};
  for (int trial = 0; trial < 1500; ++trial) {
    Integer a(1), b(1);
    for (int i = 0; i < 4; ++i) {
      a *= Integer(parts[g.uniform(0, 9)]);
      b *= Integer(parts[g.uniform(0, 9)]);
    }
    Integer z(static_cast<long>(g.uniform(-100000, 100000)));
    for (long i = g.uniform(0, 4); i > 0; --i) z *= Integer(parts[g.uniform(0, 9)]);
    if (trial % 4 == 0) z *= a * a * b;
    const relpos::detail::forms::SplitScale sa = relpos::detail::forms::split_scale(a),
                                            sb = relpos::detail::forms::split_scale(b);
    for (unsigned long i = 0; i <= 4; ++i) {
      Rational expected(z);
      for (unsigned long k = 0; k < i; ++k) expected /= Rational(a);
      for (unsigned long k = i; k < 4; ++k) expected /= Rational(b);
      const Rational got = relpos::detail::forms::divided_by_powers(z, {{sa, i}, {sb, 4 - i}});
      CAPTURE(relpos::to_string(z), relpos::to_string(a), relpos::to_string(b), i);
      CHECK(mpz_cmp(mpq_numref(got.mpq()), mpq_numref(expected.mpq())) == 0);  // same canonical form
      CHECK(mpz_cmp(mpq_denref(got.mpq()), mpq_denref(expected.mpq())) == 0);
    }
  }
}

TEST_CASE("divided_by_powers refuses a split scale without its factors", "[divided_by_powers]") {
  // The closed forms' splits carry their rest apart (no factors): dividing by one would drop it.
  relpos::detail::forms::SplitScale s;
  s.twos = 3;
  s.rest = Integer(7);
  CHECK_THROWS_AS(relpos::detail::forms::divided_by_power(Integer(49), s, 1), std::logic_error);
  CHECK(relpos::detail::forms::divided_by_power(Integer(49), s, 0) == Rational(49));  // k = 0: nothing divided
  s.rest = Integer(1);
  CHECK(relpos::detail::forms::divided_by_power(Integer(12), s, 2) == Rational(Integer(12), Integer(64)));
}
