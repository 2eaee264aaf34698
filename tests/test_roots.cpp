// roots.hpp's fast paths against what they stand for: the residues read from the limbs against
// mpz_fdiv_ui, and the isolation of simple_root_structure (roots approximated in doubles, bracket
// pairs interleaved, intervals certified by exact signs; modular tests on machine words for
// coprimality and rational roots) against roots known by construction, with exact comparisons, on random
// quartics: products of two quadratics (far, close, huge and tiny roots, non-real pairs, repeated
// factors), and a rational root shared with s times an irreducible cubic.
#include <gmp.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <functional>
#include <numeric>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "algebra/roots.hpp"
#include "algebra/word_arithmetic.hpp"
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

/// A real root known by construction: `below(t)` says t < root exactly; `exact` when rational.
struct KnownRoot {
  std::function<bool(const Rational&)> below;
  std::optional<Rational> exact;
  int sign = 0;
};

/// a x^2 + b x + c, a > 0.
struct Quad {
  Integer a, b, c;
  Integer disc() const { return b * b - 4 * a * c; }
};

bool is_square(const Integer& d) { return d >= 0 && mpz_perfect_square_p(d.mpz()); }

/// The two real roots (-b -+ sqrt(D)) / (2a) of q (D > 0, not a square): t < root iff
/// w = 2 a t + b < -+ sqrt(D), decided on w's sign and w^2 against D.
void add_roots(const Quad& q, std::vector<KnownRoot>& out) {
  const Integer d = q.disc();
  if (d <= 0) return;
  for (int s : {-1, 1}) {
    KnownRoot r;
    r.below = [q, d, s](const Rational& t) {
      const Rational w = Rational(2 * q.a) * t + Rational(q.b);
      return s > 0 ? (w < 0 || w * w < Rational(d)) : (w < 0 && w * w > Rational(d));
    };
    // The sign of the root: the sign of -b + s sqrt(D), i.e. of s unless b^2 > D with the sign of -b.
    const int sign_b = q.b > 0 ? 1 : (q.b < 0 ? -1 : 0);
    r.sign = (q.b * q.b > d && sign_b != 0) ? -sign_b : s;
    out.push_back(std::move(r));
  }
}

Quartic<Integer> product(const Quad& p, const Quad& q) {
  return {p.c * q.c, p.b * q.c + p.c * q.b, p.a * q.c + p.b * q.b + p.c * q.a, p.a * q.b + p.b * q.a, p.a * q.a};
}

/// A quadratic with integer coefficients, c != 0 and a discriminant that is not a square: real
/// roots when `real`, else a non-real pair.
Quad random_quad(std::mt19937_64& rng, bool real) {
  std::uniform_int_distribution<int> ua(1, 20), ubc(-60, 60);
  for (;;) {
    Quad q{Integer(ua(rng)), Integer(ubc(rng)), Integer(ubc(rng))};
    const Integer d = q.disc();
    if (q.c != 0 && (real ? d > 0 : d < 0) && !is_square(d)) return q;
  }
}

/// q(x - 2^-k) 2^(2k): the roots moved right by 2^-k.
Quad shifted(const Quad& q, unsigned k) {
  const Integer n = Integer(1) << k;
  return {q.a * n * n, q.b * n * n - 2 * q.a * n, q.a - q.b * n + q.c * n * n};
}

/// The roots multiplied by t = num / den > 0: q(x / t) t^2 den^2.
Quad scaled(const Quad& q, const Integer& num, const Integer& den) {
  return {q.a * den * den, q.b * num * den, q.c * num * num};
}

/// Checks an isolation of f's real roots against the known distinct ones (in any order):
/// increasing disjoint intervals, each holding exactly one known root (exact ones reported
/// exactly), with its sign; every known root in one interval.
void check_against_known(const relpos::RootStructure& rs, const std::vector<KnownRoot>& known, int nonreal) {
  REQUIRE(rs.real_roots.size() == known.size());
  std::vector<int> hits(known.size(), 0);
  for (std::size_t i = 0; i < rs.real_roots.size(); ++i) {
    const relpos::RealRoot& r = rs.real_roots[i];
    CAPTURE(i, relpos::to_string(r.lower), relpos::to_string(r.upper));
    if (i > 0) CHECK(rs.real_roots[i - 1].upper < r.lower);
    int inside = 0;
    for (std::size_t k = 0; k < known.size(); ++k) {
      const KnownRoot& w = known[k];
      bool in = false;
      if (r.exact) {
        in = w.exact && *w.exact == *r.exact;
      } else {
        in = !w.exact && r.lower < r.upper && w.below(r.lower) && !w.below(r.upper);
      }
      if (in) {
        ++inside;
        ++hits[k];
        CHECK(r.sign == w.sign);
      }
    }
    CHECK(inside == 1);
  }
  for (int h : hits) CHECK(h == 1);
  CHECK(rs.nonreal == nonreal);
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

TEST_CASE("simple_root_structure against roots known by construction", "[roots]") {
  std::mt19937_64 rng(relpos::testing::announced_seed("known roots", 20261127));
  std::uniform_int_distribution<int> small(-9, 9);
  int fast = 0;
  for (int iteration = 0; iteration < 3000; ++iteration) {
    CAPTURE(iteration);
    const int kind = iteration % 7;
    std::string detail;  // the case, for a failure's message
    std::vector<KnownRoot> known;
    Quartic<Integer> f;
    // s: two rational roots (det M > 0), never a root of f unless made so.
    int u = small(rng), v = small(rng);
    if (u == 0) u = 1;
    if (v == 0) v = -2;
    Quadratic<Integer> s{Integer(u * v), Integer(u + v), Integer(1)};
    bool must_be_fast = true, shared = false;
    if (kind <= 2) {  // 4, 2 or 0 real roots
      const Quad p = random_quad(rng, kind <= 1), q = random_quad(rng, kind == 0);
      if (p.a * q.b == q.a * p.b && p.a * q.c == q.a * p.c) continue;  // the same roots: another kind
      f = product(p, q);
      add_roots(p, known);
      add_roots(q, known);
      must_be_fast = kind <= 1;  // no real root at all: left to the general path
    } else if (kind == 3) {      // two pairs of close roots, 2^-k apart, k up to 60 (beyond doubles)
      const Quad p = random_quad(rng, true);
      const unsigned k = 1 + static_cast<unsigned>(rng() % 60);
      const Quad q = shifted(p, k);
      f = product(p, q);
      add_roots(p, known);
      add_roots(q, known);
      must_be_fast = k <= 16;
      detail = "2^-" + std::to_string(k) + " apart";
    } else if (kind == 4) {  // huge or tiny roots: scaled up or down by up to 40 factors of 2 or 10
      const Quad p = random_quad(rng, true), q = random_quad(rng, rng() % 2 == 0);
      const unsigned e = static_cast<unsigned>(rng() % 41);
      Integer factor(1), num(1), den(1);
      for (unsigned i = 0; i < e; ++i) factor *= rng() % 2 ? 2 : 10;
      (rng() % 2 ? num : den) = factor;
      detail = "scaled by " + relpos::to_string(Rational(num, den));
      // Huge roots put the cuts of the root approximation (at the Cauchy bound, about |root|^4)
      // beyond the double range: the general path then.
      must_be_fast = mpz_sizeinbase(num.mpz(), 2) <= 40;
      const Quad ps = scaled(p, num, den), qs = scaled(q, num, den);
      f = product(ps, qs);
      add_roots(ps, known);
      add_roots(qs, known);
    } else if (kind == 5) {  // a rational root, shared with s or not, times x^3 - m (m not a cube)
      const int m = 2 + static_cast<int>(rng() % 60);
      Integer cube_root;
      if (mpz_root(cube_root.mpz(), Integer(m).mpz(), 3) != 0) continue;
      // f = (x - r)(x^3 - m) with r = -u a root of s, or r = 10 (s's roots are in -9..9): then the
      // fast path must see the rational root and leave f to the general path.
      shared = iteration % 2 == 1;
      const Integer r(shared ? -u : 10), mm(m);
      f = {r * mm, -mm, Integer(0), -r, Integer(1)};
      KnownRoot rational;
      rational.exact = Rational(r);
      rational.below = [r](const Rational& t) { return t < Rational(r); };
      rational.sign = r > 0 ? 1 : -1;
      KnownRoot cubic;
      cubic.below = [mm](const Rational& t) { return t * t * t < Rational(mm); };
      cubic.sign = 1;
      known = {rational, cubic};
      must_be_fast = shared;
    } else {  // a repeated factor (Disc(f) = 0): not the fast path's case, the general path's
      const Quad p = random_quad(rng, rng() % 2 == 0);
      f = product(p, p);
      const auto rs = relpos::exact_root_structure(f, s);
      CHECK_FALSE(relpos::simple_root_structure(f, s).has_value());
      std::vector<KnownRoot> twice;
      add_roots(p, twice);
      CHECK(rs.sign_disc_f == 0);
      check_against_known(rs, twice, twice.empty() ? 4 : 0);  // distinct roots, each of multiplicity 2
      for (const auto& r : rs.real_roots) CHECK(r.multiplicity_f == 2);
      continue;
    }
    // Big content: the same roots, other doubles.
    if (iteration % 5 == 0)
      for (Integer& c : f) c *= Integer(3) << 200;
    CAPTURE(detail);
    const auto rs = relpos::simple_root_structure(f, s);
    if (must_be_fast) CHECK(rs.has_value());
    if (kind == 5 && !shared) CHECK_FALSE(rs.has_value());  // a rational root not shared with s
    if (rs) {
      ++fast;
      check_against_known(*rs, known, 4 - static_cast<int>(known.size()));
      CHECK(rs->degree_ftilde == (kind == 5 ? 3 : 4));
      CHECK(rs->sign_disc_f == ((rs->nonreal / 2) % 2 ? -1 : 1));  // square-free: (-1)^(pairs)
    }
    // Fast or general, the same facts.
    check_against_known(relpos::exact_root_structure(f, s), known, 4 - static_cast<int>(known.size()));
  }
  CHECK(fast >= 1500);  // most cases went the fast way (about 1900 with this seed)
}
