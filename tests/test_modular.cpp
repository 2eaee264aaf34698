// modular.hpp and word_arithmetic.hpp: arithmetic on machine words. Residues read from the limbs
// against mpz_fdiv_ui; word_gcd against std::gcd; the modular tests against what they certify,
// computed over Z: "coprime" only when Res(f, s) != 0, "no rational root" only when FLINT's
// factorisation has no linear factor, and rational_roots equal to the roots f was built from.
#include <gmp.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "algebra/flint_poly.hpp"
#include "algebra/modular.hpp"
#include "algebra/word_arithmetic.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"
#include "support/seed.hpp"

namespace {

using relpos::Integer;
using relpos::Quadratic;
using relpos::Quartic;
using relpos::Rational;

template <unsigned long long M>
void check_residues(std::mt19937_64& rng) {
  CAPTURE(M);
  // Limbs that stress the reduction: random, all ones, and the modulus and its neighbours.
  const unsigned long special[] = {0UL,
                                   ~0UL,
                                   static_cast<unsigned long>(M - 1),
                                   static_cast<unsigned long>(M),
                                   static_cast<unsigned long>(M + 1),
                                   1UL << 63};
  mpz_t z;
  mpz_init(z);
  for (int k = 0; k < 3000; ++k) {
    mpz_set_ui(z, 0);
    for (int i = 0; i < k % 13; ++i) {
      mpz_mul_2exp(z, z, 64);
      mpz_add_ui(z, z, rng() % 3 == 0 ? special[rng() % 6] : static_cast<unsigned long>(rng()));
    }
    if (k % 3 == 1) mpz_neg(z, z);
    CAPTURE(k);
    REQUIRE(relpos::detail::residue<M>(z) == mpz_fdiv_ui(z, static_cast<unsigned long>(M)));
  }
  mpz_clear(z);
}

}  // namespace

TEST_CASE("residues from the limbs agree with mpz_fdiv_ui", "[roots]") {
  std::mt19937_64 rng(relpos::testing::announced_seed("residues", 20261126));
  check_residues<4294967291ULL>(rng);  // the largest prime below 2^32
  check_residues<111546435ULL>(rng);   // 3 * 5 * ... * 23
  check_residues<2756205443ULL>(rng);  // 29 * ... * 47
  check_residues<907383479ULL>(rng);   // 53 * ... * 71
  check_residues<4132280413ULL>(rng);  // 73 * ... * 97
  check_residues<4294967295ULL>(rng);  // the largest allowed modulus
  check_residues<2ULL>(rng);
  check_residues<3ULL>(rng);
}

TEST_CASE("word_gcd agrees with std::gcd", "[roots]") {
  using relpos::detail::word_gcd;
  std::mt19937_64 rng(relpos::testing::announced_seed("word gcd", 20261126));
  const std::uint64_t top = ~std::uint64_t{0};
  for (const auto& [u, v] : std::vector<std::pair<std::uint64_t, std::uint64_t>>{
           {0, 0}, {0, 7}, {7, 0}, {1, 1}, {12, 18}, {top, top}, {top, 1}, {top - 1, top}, {1ULL << 63, 1ULL << 40}})
    CHECK(word_gcd(u, v) == std::gcd(u, v));
  for (int i = 0; i < 20000; ++i) {
    // Random words with a random common factor (often > 1), shifted by random powers of two.
    const std::uint64_t g = (rng() >> (rng() % 64)) | 1;
    const int bits = 64 - (64 - __builtin_clzll(g));  // room for the cofactors
    const std::uint64_t a = bits > 0 ? rng() >> (64 - bits) : 1, b = bits > 0 ? rng() >> (64 - bits) : 1;
    const std::uint64_t u = (a * g) << (rng() % 4 == 0 ? rng() % 8 : 0), v = b * g;
    CHECK(word_gcd(u, v) == std::gcd(u, v));
    const std::uint64_t x = rng() >> (rng() % 64), y = rng() >> (rng() % 64);
    CHECK(word_gcd(x, y) == std::gcd(x, y));
  }
}

namespace {

/// f's coefficients modulo first_primes_product, as the root code computes them.
std::array<unsigned long, 5> first_residues(const Quartic<Integer>& f) {
  std::array<unsigned long, 5> r{};
  for (std::size_t i = 0; i < 5; ++i) r[i] = relpos::detail::residue<relpos::detail::first_primes_product>(f[i].mpz());
  return r;
}

/// The linear factors of f over Z (FLINT's factorisation), as roots -c0/c1: the independent answer.
std::vector<Rational> linear_factor_roots(const Quartic<Integer>& f) {
  const relpos::detail::FlintPoly p(f);
  fmpz_poly_factor_t fac;
  fmpz_poly_factor_init(fac);
  fmpz_poly_factor(fac, p.p);
  std::vector<Rational> out;
  for (slong i = 0; i < fac->num; ++i)
    if (fmpz_poly_degree(fac->p + i) == 1) {
      Integer c0, c1;
      fmpz_get_mpz(c0.mpz(), fmpz_poly_get_coeff_ptr(fac->p + i, 0));
      fmpz_get_mpz(c1.mpz(), fmpz_poly_get_coeff_ptr(fac->p + i, 1));
      out.push_back(Rational(-c0, c1));
    }
  fmpz_poly_factor_clear(fac);
  std::sort(out.begin(), out.end());
  return out;
}

/// (a x + b) times the cubic c (coefficients from the constant term up).
Quartic<Integer> times_linear(const Integer& a, const Integer& b, const std::array<Integer, 4>& c) {
  Quartic<Integer> f{Integer(0), Integer(0), Integer(0), Integer(0), Integer(0)};
  for (std::size_t i = 0; i < 4; ++i) {
    f[i] += b * c[i];
    f[i + 1] += a * c[i];
  }
  return f;
}

}  // namespace

TEST_CASE("certainly_coprime: only when Res(f, s) != 0, and for most coprime pairs", "[modular][random]") {
  std::mt19937_64 rng(relpos::testing::announced_seed("coprime", 20261128));
  std::uniform_int_distribution<long> small(-40, 40);
  int coprime = 0, shown = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    // s = (x - u)(x - v); f = (q x - p) c(x) with p / q = u on odd trials (a common root), else random.
    const long u = small(rng), v = small(rng);
    const Quadratic<Integer> s{Integer(u * v), Integer(-u - v), Integer(1)};
    const std::array<Integer, 4> c{Integer(small(rng) | 1), Integer(small(rng)), Integer(small(rng)),
                                   Integer(1 + rng() % 9)};
    const bool shared = trial % 2 == 1;
    const long q = shared ? 1 + static_cast<long>(rng() % 5) : small(rng) | 1;
    const Quartic<Integer> f = times_linear(Integer(q), Integer(shared ? -u * q : small(rng)), c);
    if (f[4] == 0) continue;
    const relpos::detail::FlintPoly fp(f), sp(s);
    fmpz_t res;
    fmpz_init(res);
    fmpz_poly_resultant(res, fp.p, sp.p);
    const bool nonzero = !fmpz_is_zero(res);
    fmpz_clear(res);
    const auto r = first_residues(f);
    const bool certain = relpos::detail::certainly_coprime(r.data(), s);
    CAPTURE(trial, relpos::to_string(Rational(f[0])), u, v);
    if (shared) CHECK_FALSE(nonzero);
    if (certain) CHECK(nonzero);  // the claim is an identity over Z
    coprime += nonzero;
    shown += certain;
  }
  CHECK(shown * 10 >= coprime * 9);  // the first primes settle nearly every coprime pair
}

TEST_CASE("no rational root modulo primes: only when FLINT's factorisation has no linear factor", "[modular][random]") {
  std::mt19937_64 rng(relpos::testing::announced_seed("rational roots", 20261128));
  std::uniform_int_distribution<long> small(-30, 30);
  int none = 0, shown = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Quartic<Integer> f;
    std::vector<Rational> built;  // the rational roots f is built with
    if (trial % 3 == 0) {         // (q x - p) times a cubic: p / q a root
      const long p = small(rng), q = 1 + static_cast<long>(rng() % 12);
      const std::array<Integer, 4> c{Integer(small(rng) | 1), Integer(small(rng)), Integer(small(rng)),
                                     Integer(1 + rng() % 5)};
      f = times_linear(Integer(q), Integer(-p), c);
      built.push_back(Rational(Integer(p), Integer(q)));
    } else {  // random coefficients, big content on some: usually irreducible
      for (auto& x : f) x = Integer(small(rng));
      if (f[4] == 0) f[4] = 7;
      if (trial % 5 == 1)
        for (auto& x : f) x *= Integer(3) << 100;
    }
    const std::vector<Rational> linear = linear_factor_roots(f);
    const relpos::detail::FlintPoly fp(f);
    const auto r = first_residues(f);
    const bool small_primes = relpos::detail::no_root_modulo_small_primes(f, r.data());
    const bool certain = relpos::detail::certainly_no_rational_root(fp.p);
    CAPTURE(trial);
    if (small_primes) CHECK(certain);  // the word primes only add
    if (certain) CHECK(linear.empty());
    for (const Rational& x : built) CHECK(std::find(linear.begin(), linear.end(), x) != linear.end());
    std::vector<Rational> got = relpos::detail::rational_roots(f);
    std::sort(got.begin(), got.end());
    CHECK(got == linear);  // the same roots as the independent factorisation
    none += linear.empty();
    shown += certain;
  }
  CHECK(shown * 10 >= none * 9);  // most polynomials without rational roots are shown so cheaply
}
