// split_scale.hpp: a positive scale split as 2^twos 5^fives rest, the rest's powers and a coprime
// base of it, by each of the three ways a caller knows the scale (the scale alone; the scale and the
// matrix whose denominators it is the lcm of; the parts the decimal reader knows). Identities: the
// parts multiply back to the scale, the bases are pairwise coprime with the rest as their product,
// and the three ways agree; z / scale^k reduces along the split as rational division does.
#include <gmp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "algebra/divided_by_powers.hpp"
#include "algebra/integer_form.hpp"
#include "algebra/split_scale.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;

namespace {

/// 2^twos 5^fives rest, and rest prime to 10; rest_power[k] = rest^k; the factors' bases pairwise
/// coprime with rest as the product of base^power (or no factors and no powers for rest 1).
void check_split(const relpos::detail::forms::SplitScale& s, const Integer& scale) {
  Integer back = s.rest;
  for (unsigned long i = 0; i < s.twos; ++i) back *= Integer(2);
  for (unsigned long i = 0; i < s.fives; ++i) back *= Integer(5);
  CHECK(back == scale);
  CHECK(mpz_divisible_ui_p(s.rest.mpz(), 2) == 0);
  CHECK(mpz_divisible_ui_p(s.rest.mpz(), 5) == 0);
  if (s.rest == 1) {
    CHECK(s.rest_power.empty());
    CHECK(s.factors.empty());
    return;
  }
  REQUIRE(s.rest_power.size() == 5);
  Integer power(1);
  for (std::size_t k = 0; k < 5; ++k) {
    CHECK(s.rest_power[k] == power);
    power *= s.rest;
  }
  Integer product(1);
  for (const auto& f : s.factors)
    for (unsigned long k = 0; k < f.power; ++k) product *= f.base;
  CHECK(product == s.rest);
  for (std::size_t i = 0; i < s.factors.size(); ++i)
    for (std::size_t j = i + 1; j < s.factors.size(); ++j) {
      Integer c;
      mpz_gcd(c.mpz(), s.factors[i].base.mpz(), s.factors[j].base.mpz());
      CHECK(c == 1);
    }
}

}  // namespace

TEST_CASE("split_scale: the parts multiply back to the scale, the rest prime to 10", "[split_scale]") {
  // Powers of 2 and 5 alone (doubles, decimal text), with a rest, and rests of many limbs.
  rt::Rng g(101);
  const long rests[] = {1, 3, 7, 9, 21, 1000003, 3 * 3 * 11};
  for (int trial = 0; trial < 2000; ++trial) {
    Integer scale(rests[trial % 7]);
    for (long i = g.uniform(0, 80); i > 0; --i) scale *= Integer(2);
    for (long i = g.uniform(0, 80); i > 0; --i) scale *= Integer(5);
    if (trial % 11 == 0)
      for (int i = 0; i < 6; ++i) scale *= Integer(1000003);  // a rest beyond one limb
    CAPTURE(relpos::to_string(scale));
    const relpos::detail::forms::SplitScale s = relpos::detail::forms::split_scale(scale);
    check_split(s, scale);
    CHECK(s.factors.size() == (s.rest == 1 ? 0u : 1u));  // no matrix: the rest is its one factor
  }
}

TEST_CASE("split_scale along a matrix's denominators: a coprime base of the rest, same reductions", "[split_scale]") {
  // Denominators of the kinds a standard paraboloid with decimal a, b has (squares of mantissas
  // that may share primes, times 2s and 5s) and others (not squares, powers of one another, shared
  // primes): the split rest is a product of pairwise coprime bases, and z / scale^k reduces as
  // rational division does.
  rt::Rng g(31337);
  const long parts[] = {3, 7, 9, 11, 21, 1000003, 99991, 6, 10, 25};
  for (int trial = 0; trial < 1500; ++trial) {
    relpos::Matrix4 m;
    for (std::size_t i = 0; i < 16; ++i) {
      Integer den(1);
      for (long k = g.uniform(0, 3); k > 0; --k) den *= Integer(parts[g.uniform(0, 9)]);
      if (trial % 2 == 0) den *= den;  // squares, as 1/a^2 has
      m.a[i] = g.uniform(0, 3) == 0 ? Rational(0) : Rational(Integer(g.uniform(-50, 50)) * Integer(2), den);
    }
    Integer scale;
    relpos::detail::forms::integer_form(m, scale);
    const relpos::detail::forms::SplitScale split = relpos::detail::forms::split_scale(scale, m);
    const relpos::detail::forms::SplitScale plain = relpos::detail::forms::split_scale(scale);
    CHECK(split.twos == plain.twos);
    CHECK(split.fives == plain.fives);
    Integer product(1);
    for (const auto& f : split.factors)
      for (unsigned long k = 0; k < f.power; ++k) product *= f.base;
    CHECK(product == split.rest);
    for (std::size_t i = 0; i < split.factors.size(); ++i)
      for (std::size_t j = i + 1; j < split.factors.size(); ++j) {
        Integer c;
        mpz_gcd(c.mpz(), split.factors[i].base.mpz(), split.factors[j].base.mpz());
        CHECK(c == 1);
      }
    Integer z(static_cast<long>(g.uniform(-100000, 100000)));
    for (long i = g.uniform(0, 6); i > 0; --i) z *= Integer(parts[g.uniform(0, 9)]);
    if (trial % 3 == 0) z *= scale;
    for (unsigned long k = 0; k <= 4; ++k) {
      Rational expected(z);
      for (unsigned long i = 0; i < k; ++i) expected /= Rational(scale);
      const Rational got = relpos::detail::forms::divided_by_power(z, split, k);
      CAPTURE(relpos::to_string(z), relpos::to_string(scale), k);
      CHECK(mpz_cmp(mpq_numref(got.mpq()), mpq_numref(expected.mpq())) == 0);  // same canonical form
      CHECK(mpz_cmp(mpq_denref(got.mpq()), mpq_denref(expected.mpq())) == 0);
    }
  }
}

TEST_CASE("split_scale from the decimal reader's parts equals the split along the matrix", "[split_scale]") {
  // A standard paraboloid with decimal a and b: 1/a^2 and 1/b^2 have the denominators R_a^2 and R_b^2
  // (R the part of the mantissa prime to 10), and the reader knows the scale as 2^twos 5^fives
  // lcm(R_a^2, R_b^2) with the rests {R_a, R_b} squared: the same split, base for base.
  rt::Rng g(2024);
  const long mantissas[] = {1, 3, 7, 9, 21, 33, 63, 121, 1001, 999983, 4096, 625, 6, 15};
  for (int trial = 0; trial < 1500; ++trial) {
    const Rational a(Integer(mantissas[g.uniform(0, 13)]), Integer(g.chance(50) ? 10 : 1000));
    const Rational b(Integer(mantissas[g.uniform(0, 13)] * (g.chance(30) ? 3 : 1)), Integer(g.chance(50) ? 100 : 1));
    relpos::Matrix4 m;
    m(0, 0) = 1 / (a * a);
    m(1, 1) = 1 / (b * b);
    m(2, 3) = m(3, 2) = Rational(-1, 2);
    m(3, 3) = Rational(Integer(g.uniform(-50, 50)), Integer(g.chance(50) ? 8 : 125));
    Integer scale;
    relpos::detail::forms::integer_form(m, scale);
    const relpos::detail::forms::SplitScale along = relpos::detail::forms::split_scale(scale, m);
    // The reader's parts: the rests of the mantissas (numerators of a and b without 2s and 5s).
    std::vector<relpos::detail::forms::SplitScale::Factor> rests;
    for (const Rational* x : {&a, &b}) {
      Integer r;  // fresh: written through mpz() (a copy would share the numerator's value)
      mpz_set(r.mpz(), x->numerator().mpz());
      mpz_remove(r.mpz(), r.mpz(), Integer(2).mpz());
      mpz_remove(r.mpz(), r.mpz(), Integer(5).mpz());
      bool seen = r == 1;
      for (const auto& f : rests) seen = seen || f.base == r;
      if (!seen) rests.push_back({r, 2});
    }
    const relpos::detail::forms::SplitScale parts =
        relpos::detail::forms::split_scale(along.twos, along.fives, along.rest, rests);
    CAPTURE(relpos::to_string(a), relpos::to_string(b), relpos::to_string(scale));
    check_split(parts, scale);
    CHECK(parts.rest == along.rest);
    REQUIRE(parts.factors.size() == along.factors.size());
    for (std::size_t k = 0; k < parts.factors.size(); ++k) {
      bool found = false;
      for (const auto& f : along.factors)
        found = found || (f.base == parts.factors[k].base && f.power == parts.factors[k].power);
      CHECK(found);
    }
  }
}
