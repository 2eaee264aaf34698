// decimal_recipe.hpp and closed_evidence.hpp: what is computed from the numbers a quadric was read
// from, on recipes made here directly (the reader of text is tested in test_fast_reader.cpp), against
// the library's constructors and rational arithmetic:
//   - exact_matrix is the matrix of the constructor the general reader calls (Ellipsoid::sphere,
//     Paraboloid::standard), or the numbers with their orientation, for decimals and for doubles;
//   - write_integer_form writes integer_form(exact_matrix) and split_scale(l, exact_matrix), factor
//     for factor (off the axis: a coprime base of the same rest), and only the parts asked for;
//   - truncated_doubles is truncated_double of each exact entry, for every recipe of decimals;
//   - sphere_standard_evidence gives f, s, lambda_s and rho in lowest terms, and S^4 f, S^3 s.
#include <gmp.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <string>

#include "algebra/closed_evidence.hpp"
#include "algebra/decimal_recipe.hpp"
#include "algebra/exact_doubles.hpp"
#include "algebra/integer_form.hpp"
#include "algebra/pencil.hpp"
#include "algebra/split_scale.hpp"
#include "support/printers.hpp"

namespace {

using relpos::Integer;
using relpos::Rational;
using relpos::detail::Decimal;
using relpos::detail::DecimalRecipe;

/// (-1)^neg m 10^e with m's trailing zeros moved into e: the reader's one identity of a value.
Decimal decimal(std::uint64_t m, int e, bool neg) {
  while (m != 0 && m % 10 == 0) m /= 10, ++e;
  return m == 0 ? Decimal{} : Decimal{m, e, neg};
}

Rational value(const Decimal& x) {
  Integer m;  // fresh: written through mpz() (m may exceed a long)
  mpz_set_ui(m.mpz(), x.m);
  Rational q{m};
  Integer ten(1);
  for (int k = 0; k < (x.e < 0 ? -x.e : x.e); ++k) ten *= Integer(10);
  q = x.e < 0 ? q / Rational(ten) : q * Rational(ten);
  return x.neg ? -q : q;
}

/// A decimal of up to 19 digits, sometimes made of small primes (common factors with others).
Decimal random_decimal(std::mt19937_64& rng, bool positive) {
  const std::uint64_t primes[] = {2, 3, 5, 7, 11, 13, 9, 343, 1000003};
  std::uint64_t m = 1 + rng() % 9;
  if (rng() % 2) {
    for (int k = static_cast<int>(rng() % 7); k > 0; --k) {
      const std::uint64_t p = primes[rng() % 9];
      if (m > 100000000000000000ULL / p) break;
      m *= p;
    }
  } else {
    m = 1 + rng() % 9999999999999999999ULL;
  }
  if (!positive && rng() % 5 == 0) return Decimal{};
  return decimal(m, -static_cast<int>(rng() % 25), !positive && rng() % 2 == 0);
}

DecimalRecipe sphere_recipe(std::mt19937_64& rng) {
  DecimalRecipe r;
  r.form = DecimalRecipe::Form::Sphere;
  r.n = {random_decimal(rng, false), random_decimal(rng, false), random_decimal(rng, false), random_decimal(rng, true)};
  return r;
}

DecimalRecipe standard_recipe(std::mt19937_64& rng, bool on_axis) {
  DecimalRecipe r;
  r.form = DecimalRecipe::Form::Standard;
  const Decimal zero{};
  r.n = {on_axis ? zero : random_decimal(rng, false), on_axis ? zero : random_decimal(rng, false),
         random_decimal(rng, false), random_decimal(rng, true), random_decimal(rng, true)};
  return r;
}

/// The constructor's matrix for the recipe's form (the general reader's quadric).
relpos::Matrix4 constructed(const DecimalRecipe& r) {
  const auto q = [&](std::size_t k) { return value(r.n[k]); };
  if (r.form == DecimalRecipe::Form::Sphere) return relpos::Ellipsoid::sphere({q(0), q(1), q(2)}, q(3)).matrix();
  return relpos::Paraboloid::standard({q(0), q(1), q(2)}, q(3), q(4)).matrix();
}

/// The same split; with `same_factors` false, a's factors only a coprime base of the rest (what
/// divided_by_powers reads), not necessarily b's.
void require_same_split(const relpos::detail::forms::SplitScale& a, const relpos::detail::forms::SplitScale& b,
                        bool same_factors = true) {
  REQUIRE(a.twos == b.twos);
  REQUIRE(a.fives == b.fives);
  REQUIRE(a.rest == b.rest);
  REQUIRE(a.rest_power.size() == b.rest_power.size());
  for (std::size_t k = 0; k < a.rest_power.size(); ++k) REQUIRE(a.rest_power[k] == b.rest_power[k]);
  if (!same_factors) {
    Integer product(1);
    for (std::size_t k = 0; k < a.factors.size(); ++k) {
      for (unsigned long i = 0; i < a.factors[k].power; ++i) product *= a.factors[k].base;
      for (std::size_t j = 0; j < k; ++j) {
        Integer g;  // fresh: written through mpz()
        mpz_gcd(g.mpz(), a.factors[k].base.mpz(), a.factors[j].base.mpz());
        REQUIRE(g == 1);
      }
    }
    REQUIRE((a.factors.empty() ? a.rest == 1 : product == a.rest));
    return;
  }
  REQUIRE(a.factors.size() == b.factors.size());
  for (std::size_t k = 0; k < a.factors.size(); ++k) {
    REQUIRE(a.factors[k].base == b.factors[k].base);
    REQUIRE(a.factors[k].power == b.factors[k].power);
  }
}

/// write_integer_form against the matrix's integer form and split; with the parts not asked for
/// left alone.
void check_integer_form(const DecimalRecipe& r) {
  const relpos::Matrix4 m = relpos::detail::exact_matrix(r);
  relpos::detail::forms::MatrixOf<Integer> form, untouched;
  Integer l, l2, l_only, unused;
  relpos::detail::forms::SplitScale s, split_only, exponents;
  REQUIRE(relpos::detail::write_integer_form(r, {relpos::detail::forms::entries(form), l, s}));
  const relpos::detail::forms::MatrixOf<Integer> want = relpos::detail::forms::integer_form(m, l2);
  REQUIRE(l == l2);
  for (std::size_t k = 0; k < 16; ++k) REQUIRE(form.a[k] == want.a[k]);
  // Off the axis the factors may be coarser than split_scale's (recipe_integer_form.cpp).
  const bool on_axis = r.form != DecimalRecipe::Form::Standard || (r.n[0].m == 0 && r.n[1].m == 0);
  require_same_split(s, relpos::detail::forms::split_scale(l2, m), on_axis);
  REQUIRE(relpos::detail::write_integer_form(
      r, {relpos::detail::forms::entries(untouched), l_only, split_only, false, false}));
  CHECK(l_only == l);
  CHECK(split_only.rest == s.rest);
  CHECK(split_only.twos == s.twos);
  REQUIRE(relpos::detail::write_integer_form(
      r, {relpos::detail::forms::entries(untouched), unused, exponents, false, false, false}));
  CHECK(exponents.twos == s.twos);
  CHECK(exponents.fives == s.fives);
  for (const Integer& x : untouched.a) CHECK(x == 0);
}

}  // namespace

TEST_CASE("decimal recipes: exact matrix, integer form and truncated doubles of spheres and paraboloids",
          "[decimal_recipe]") {
  std::mt19937_64 rng(29);
  for (int trial = 0; trial < 600; ++trial) {
    const DecimalRecipe r = trial % 3 == 0 ? sphere_recipe(rng) : standard_recipe(rng, trial % 3 == 1);
    const relpos::Matrix4 m = relpos::detail::exact_matrix(r);
    INFO(trial);
    REQUIRE(m == constructed(r));
    const bool closed = r.form == DecimalRecipe::Form::Sphere || (r.n[0].m == 0 && r.n[1].m == 0);
    REQUIRE(relpos::detail::has_closed_form(r) == closed);
    relpos::DoubleMatrix4 d;
    REQUIRE(relpos::detail::truncated_doubles(r, d));  // on and off the axis
    for (std::size_t k = 0; k < 16; ++k) REQUIRE(d[k] == relpos::detail::forms::truncated_double(m.a[k]));
    check_integer_form(r);  // on and off the axis: the numbers' form is the constructor matrix's
  }
}

TEST_CASE("decimal recipes: a matrix with either orientation, and numbers that are doubles", "[decimal_recipe]") {
  std::mt19937_64 rng(31);
  for (int trial = 0; trial < 300; ++trial) {
    DecimalRecipe r;
    r.orientation = trial % 2 ? -1 : 1;
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) r.n[4 * i + j] = r.n[4 * j + i] = random_decimal(rng, false);
    const relpos::Matrix4 m = relpos::detail::exact_matrix(r);
    for (std::size_t k = 0; k < 16; ++k) REQUIRE(m.a[k] == (r.orientation < 0 ? -value(r.n[k]) : value(r.n[k])));
    REQUIRE_FALSE(relpos::detail::has_closed_form(r));
    relpos::DoubleMatrix4 d;
    REQUIRE(relpos::detail::truncated_doubles(r, d));
    for (std::size_t k = 0; k < 16; ++k) REQUIRE(d[k] == relpos::detail::forms::truncated_double(m.a[k]));
    check_integer_form(r);
    // The same form over doubles (--numbers double): (-1)^neg m 2^(e - 53), built exactly.
    DecimalRecipe s = sphere_recipe(rng);
    s.doubles = true;
    for (Decimal& x : s.n) {
      const double v = std::ldexp(static_cast<double>(1 + rng() % (1ULL << 52)), -static_cast<int>(rng() % 60));
      x = Decimal{};
      if (v != 0) x.m = static_cast<std::uint64_t>(std::frexp(v, &x.e) * 0x1p53);
    }
    const auto q = [&](std::size_t k) { return Rational(std::ldexp(static_cast<double>(s.n[k].m), s.n[k].e - 53)); };
    REQUIRE(relpos::detail::exact_matrix(s) == relpos::Ellipsoid::sphere({q(0), q(1), q(2)}, q(3)).matrix());
    REQUIRE_FALSE(relpos::detail::has_closed_form(s));
    REQUIRE_FALSE(relpos::detail::truncated_doubles(s, d));
    relpos::detail::forms::MatrixOf<Integer> form;
    Integer l;
    relpos::detail::forms::SplitScale split;
    REQUIRE_FALSE(relpos::detail::write_integer_form(s, {relpos::detail::forms::entries(form), l, split}));
  }
}

TEST_CASE("closed forms of a sphere and a standard paraboloid: the general path's f, s, lambda_s and rho",
          "[closed_evidence]") {
  // Mantissas made of a few primes, the radius, the centre and vz often multiples of a's or b's
  // mantissa and a's of b's: the closed forms' reductions then meet the common factors that
  // rational arithmetic cancels (beyond the powers of 2 and 5), and zeros and w = vz - z = 0 occur.
  // Every other vertex is off the axis (its x and y related numbers too, sometimes the centre's).
  // Compared in lowest terms with rational arithmetic on the constructors' matrices.
  std::mt19937_64 rng(41);
  const std::uint64_t primes[] = {2, 3, 5, 7, 11, 13, 9, 343, 1000003};
  auto mantissa = [&] {
    std::uint64_t m = 1 + rng() % 9;
    for (int k = static_cast<int>(rng() % 7); k > 0; --k) {
      const std::uint64_t p = primes[rng() % 9];
      if (m > 100000000000000000ULL / p) break;
      m *= p;
    }
    return m;
  };
  auto number = [&](std::uint64_t m, bool negative) { return decimal(m, -static_cast<int>(rng() % 12), negative); };
  auto same = [](const Rational& got, const Rational& want) {  // the same canonical form
    CHECK(mpz_cmp(mpq_numref(got.mpq()), mpq_numref(want.mpq())) == 0);
    CHECK(mpz_cmp(mpq_denref(got.mpq()), mpq_denref(want.mpq())) == 0);
  };
  for (int trial = 0; trial < 500; ++trial) {
    const std::uint64_t ma = mantissa(), mb = trial % 3 == 0 ? ma * (1 + rng() % 12) : mantissa();
    auto related = [&](bool negative) {  // a multiple of ma or mb, a free mantissa, or zero
      switch (rng() % 5) {
        case 0:
          return number(ma * (1 + rng() % 50), negative);
        case 1:
          return number(mb * (1 + rng() % 50), negative);
        case 2:
          return Decimal{};
        default:
          return number(mantissa(), negative);
      }
    };
    DecimalRecipe e, p;
    e.form = DecimalRecipe::Form::Sphere;
    p.form = DecimalRecipe::Form::Standard;
    const Decimal z = related(rng() % 2 == 0);
    e.n = {related(true), related(false), z, rng() % 3 == 0 ? number(ma, false) : number(mantissa(), false)};
    p.n = {Decimal{}, Decimal{}, trial % 7 == 0 ? z : related(rng() % 2 == 0), number(ma, false), number(mb, false)};
    if (trial % 2 == 1) {
      p.n[0] = trial % 5 == 1 ? e.n[0] : related(rng() % 2 == 0);
      p.n[1] = related(rng() % 2 == 0);
    }
    INFO(trial);
    REQUIRE(relpos::detail::forms::has_closed_evidence(e, p));
    REQUIRE_FALSE(relpos::detail::forms::has_closed_evidence(p, e));
    // S = lcm(lp, le) of the integer forms, its exponents of 2 and 5 from their splits.
    Integer lp, le, lcm;
    relpos::detail::forms::SplitScale p_split, e_split;
    relpos::detail::forms::MatrixOf<Integer> pm, em;
    REQUIRE(relpos::detail::write_integer_form(p, {relpos::detail::forms::entries(pm), lp, p_split}));
    REQUIRE(relpos::detail::write_integer_form(e, {relpos::detail::forms::entries(em), le, e_split}));
    mpz_lcm(lcm.mpz(), lp.mpz(), le.mpz());
    relpos::Quartic<Rational> f;
    relpos::Quadratic<Rational> s;
    Rational lambda_s, rho;
    relpos::Quartic<Integer> f_multiple;
    relpos::Quadratic<Integer> s_multiple;
    relpos::detail::forms::sphere_standard_evidence(e, p,
                                                    {f, s, lambda_s, rho, std::max(p_split.twos, e_split.twos),
                                                     std::max(p_split.fives, e_split.fives), f_multiple, s_multiple});
    const auto want_f = relpos::characteristic_polynomial<Rational>(constructed(p), constructed(e));
    const auto want_s = relpos::special_polynomial<Rational>(constructed(p), constructed(e));
    for (std::size_t k = 0; k < 5; ++k) same(f[k], want_f[k]);
    for (std::size_t k = 0; k < 3; ++k) same(s[k], want_s[k]);
    const Rational cube = Rational(lcm * lcm * lcm), fourth = cube * Rational(lcm);
    for (std::size_t k = 0; k < 5; ++k) CHECK(Rational(f_multiple[k]) == fourth * want_f[k]);
    for (std::size_t k = 0; k < 3; ++k) CHECK(Rational(s_multiple[k]) == cube * want_s[k]);
    // lambda_s: the root of s nearest 0 (s = (1 + A l)(1 + B l): its discriminant is a square).
    const Rational disc = want_s[1] * want_s[1] - 4 * want_s[2] * want_s[0];
    Rational root;
    mpz_sqrt(mpq_numref(root.mpq()), mpq_numref(disc.mpq()));
    mpz_sqrt(mpq_denref(root.mpq()), mpq_denref(disc.mpq()));
    REQUIRE(root * root == disc);
    const Rational want_lambda_s = (root - want_s[1]) / (2 * want_s[2]);
    same(lambda_s, want_lambda_s);
    same(rho, want_f[0] * want_s[2] / (want_f[4] * want_s[0] * want_lambda_s * want_lambda_s));
  }
}
