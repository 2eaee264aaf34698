// roots.hpp: the root structure of f, fast path (simple_root_structure: roots approximated in
// doubles, certified by exact signs, after modular tests) and general path (exact_root_structure),
// against roots known by construction with exact comparisons: random quartics (products of two
// quadratics: far, close, huge and tiny roots, non-real pairs, repeated factors; a rational root
// shared with s times an irreducible cubic), hand-made factorisations, the rational roots reported
// exactly, certified decimals, and the sign of the discriminant against the identity
// Disc(pq) = Disc(p) Disc(q) Res(p, q)^2.
#include <gmp.h>

#include <catch2/catch.hpp>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "algebra/large_stack.hpp"
#include "algebra/roots.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"
#include "support/seed.hpp"

namespace {

using relpos::Integer;
using relpos::Quadratic;
using relpos::Quartic;
using relpos::Rational;

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

using namespace rt;

namespace {

Quartic<Integer> to_integer(const Quartic<Rational>& f) {
  // Only for polynomials with integer coefficients.
  Quartic<Integer> out;
  for (std::size_t i = 0; i < 5; ++i) {
    REQUIRE(f[i].denominator() == 1);
    out[i] = f[i].numerator();
  }
  return out;
}

Quadratic<Integer> to_integer(const Quadratic<Rational>& s) {
  Quadratic<Integer> out;
  for (std::size_t i = 0; i < 3; ++i) {
    REQUIRE(s[i].denominator() == 1);
    out[i] = s[i].numerator();
  }
  return out;
}

}  // namespace

TEST_CASE("exact_root_structure on polynomials with known factorizations", "[roots]") {
  using relpos::exact_root_structure;
  SECTION("generic: four simple roots, none shared with s") {
    const auto f = to_integer(quartic_from_roots(Q(-2), {Q(-5), Q(-1), Q(3), Q(7)}));
    const auto s = to_integer(Quadratic<Rational>{Q(6), Q(5), Q(1)});  // (l + 2)(l + 3)
    auto rs = exact_root_structure(f, s);
    REQUIRE(rs.real_roots.size() == 4);
    CHECK(rs.nonreal == 0);
    CHECK(rs.degree_ftilde == 4);
    CHECK(rs.sign_disc_f == 1);
    CHECK(rs.sign_disc_ftilde == 1);
    CHECK(rs.negative() == 2);
    CHECK(rs.positive() == 2);
    const Rational want[4] = {Q(-5), Q(-1), Q(3), Q(7)};
    for (std::size_t i = 0; i < 4; ++i) {
      const auto& r = rs.real_roots[i];
      CHECK(r.multiplicity_f == 1);
      CHECK(r.multiplicity_s == 0);
      CHECK(r.lower <= want[i]);
      CHECK(want[i] <= r.upper);
      CHECK(!r.tangency());
      CHECK(r.sign == sgn(want[i]));
    }
  }
  SECTION("the Section 3 crossing: (l + 4)^2 (48 l^2 - 13 l + 3), s with root -4") {
    // a = 1, b = 2: s = (1 + l)(1 + l/4) ~ (l + 1)(l + 4).
    // expand (l^2 + 8 l + 16)(48 l^2 - 13 l + 3)
    const Rational p[3] = {Q(16), Q(8), Q(1)}, q[3] = {Q(3), Q(-13), Q(48)};
    Quartic<Rational> f{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) f[static_cast<std::size_t>(i + j)] += p[i] * q[j];
    auto rs = exact_root_structure(to_integer(f), to_integer(Quadratic<Rational>{Q(4), Q(5), Q(1)}));
    CHECK(rs.degree_ftilde == 3);
    CHECK(rs.sign_disc_f == 0);
    CHECK(rs.sign_disc_ftilde == -1);  // f~ = (l + 4)(48 l^2 - 13 l + 3): a non-real pair
    CHECK(rs.nonreal == 2);
    CHECK(rs.nonreal_multiple == 0);
    REQUIRE(rs.real_roots.size() == 1);
    CHECK(rs.real_roots[0].multiplicity_f == 2);
    CHECK(rs.real_roots[0].multiplicity_s == 1);
    REQUIRE(rs.real_roots[0].exact.has_value());
    CHECK(*rs.real_roots[0].exact == -4);
    CHECK_FALSE(rs.real_roots[0].tangency());
  }
  SECTION("quadruple root shared with a double root of s: tangency (4 - 2 >= 2)") {
    const auto f = to_integer(quartic_from_roots(Q(-1), {Q(-1), Q(-1), Q(-1), Q(-1)}));
    auto rs = exact_root_structure(f, to_integer(Quadratic<Rational>{Q(1), Q(2), Q(1)}));
    REQUIRE(rs.real_roots.size() == 1);
    CHECK(rs.real_roots[0].multiplicity_f == 4);
    CHECK(rs.real_roots[0].multiplicity_s == 2);
    CHECK(rs.real_roots[0].tangency());
    CHECK(rs.degree_ftilde == 2);
    CHECK(rs.sign_disc_ftilde == 0);
  }
  SECTION("double pair of non-real roots is reported") {
    // (l^2 + 1)^2
    const Quartic<Integer> f{Integer(1), Integer(0), Integer(2), Integer(0), Integer(1)};
    auto rs = exact_root_structure(f, to_integer(Quadratic<Rational>{Q(2), Q(3), Q(1)}));
    CHECK(rs.real_roots.empty());
    CHECK(rs.nonreal == 4);
    CHECK(rs.nonreal_multiple > 0);
    CHECK(rs.sign_disc_f == 0);
  }
  SECTION("irrational simple roots: isolating intervals are disjoint, increasing and bracket a sign change") {
    // (l^2 - 2)(l^2 - 6 l + 7): roots -sqrt2, sqrt2, 3 - sqrt2, 3 + sqrt2.
    Quartic<Rational> f{};
    const Rational p[3] = {Q(-2), Q(0), Q(1)}, q[3] = {Q(7), Q(-6), Q(1)};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) f[static_cast<std::size_t>(i + j)] += p[i] * q[j];
    auto rs = exact_root_structure(to_integer(f), to_integer(Quadratic<Rational>{Q(1), Q(3), Q(1)}));
    REQUIRE(rs.real_roots.size() == 4);
    for (std::size_t i = 0; i < 4; ++i) {
      const auto& r = rs.real_roots[i];
      CHECK_FALSE(r.exact.has_value());
      CHECK(r.lower < r.upper);
      CHECK(eval(f, r.lower) * eval(f, r.upper) < 0);
      if (i > 0) CHECK(rs.real_roots[i - 1].upper < r.lower);
    }
    // 3 - sqrt2 = 1.5857... lies in the third interval.
    CHECK(rs.real_roots[2].lower < Q(15858, 10000));
    CHECK(rs.real_roots[2].upper > Q(15857, 10000));
  }
}

namespace {

/// The product of two quadratics (coefficients low to high) as a quartic.
Quartic<Rational> product(const std::array<Rational, 3>& p, const std::array<Rational, 3>& q) {
  Quartic<Rational> f{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) f[i + j] += p[i] * q[j];
  return f;
}

/// Every interval of rs brackets a sign change of f, the intervals are disjoint and increasing,
/// and a rational root is reported exactly.
void check_isolation(const Quartic<Rational>& f, const relpos::RootStructure& rs) {
  for (std::size_t i = 0; i < rs.real_roots.size(); ++i) {
    const auto& r = rs.real_roots[i];
    CAPTURE(i);
    if (r.exact) {
      CHECK(eval(f, *r.exact) == 0);
      CHECK(r.lower <= *r.exact);
      CHECK(*r.exact <= r.upper);
    } else {
      CHECK(eval(f, r.lower) * eval(f, r.upper) < 0);
    }
    CHECK(r.sign == CGAL::sign(r.lower));
    CHECK(r.sign == CGAL::sign(r.upper));
    if (i > 0) CHECK(rs.real_roots[i - 1].upper < r.lower);
  }
}

}  // namespace

TEST_CASE("simple_root_structure: close roots, and common roots with s divided out", "[roots]") {
  using relpos::simple_root_structure;
  SECTION("two irrational roots 2^-69 sqrt 2 apart (closer than doubles resolve)") {
    // 2^139 (l^2 + l + 1/4 - 2^-139) (l^2 + 3 l + 1): roots -1/2 -+ sqrt(2) 2^-70, (-3 -+ sqrt 5) / 2.
    const Rational t(CGAL::Gmpz(1) << 139);
    const Quartic<Rational> f = product({t / 4 - 1, t, t}, {Q(1), Q(3), Q(1)});
    const auto rs = simple_root_structure(to_integer(f), to_integer(Quadratic<Rational>{Q(6), Q(5), Q(1)}));
    REQUIRE(rs.has_value());
    REQUIRE(rs->real_roots.size() == 4);
    CHECK(rs->nonreal == 0);
    CHECK(rs->degree_ftilde == 4);
    CHECK(rs->sign_disc_f == 1);
    check_isolation(f, *rs);
    // The cluster straddles -1/2, the minimum of its quadratic factor.
    CHECK(rs->real_roots[1].upper < Q(-1, 2));
    CHECK(Q(-1, 2) < rs->real_roots[2].lower);
  }
  SECTION("gcd(f, s) quadratic with rational roots: both divided out, reported exactly") {
    // f = (l + 1)(l + 4)(l^2 + 3 l + 1), s = (l + 1)(l + 4).
    const Quartic<Rational> f = product({Q(4), Q(5), Q(1)}, {Q(1), Q(3), Q(1)});
    const auto rs = simple_root_structure(to_integer(f), to_integer(Quadratic<Rational>{Q(4), Q(5), Q(1)}));
    REQUIRE(rs.has_value());
    REQUIRE(rs->real_roots.size() == 4);
    CHECK(rs->degree_ftilde == 2);
    CHECK(rs->sign_disc_ftilde == 1);
    check_isolation(f, *rs);
    REQUIRE(rs->real_roots[0].exact.has_value());
    CHECK(*rs->real_roots[0].exact == -4);
    CHECK(rs->real_roots[0].multiplicity_s == 1);
    REQUIRE(rs->real_roots[2].exact.has_value());
    CHECK(*rs->real_roots[2].exact == -1);
    CHECK_FALSE(rs->real_roots[1].exact.has_value());
  }
  SECTION("gcd(f, s) linear, s a square there: multiplicity 2 in s, the cofactor a cubic") {
    // f = (l + 4)(l^3 - 2), s = (l + 4)^2: one more real root, 2^(1/3), and a non-real pair.
    const Quartic<Rational> f{Q(-8), Q(-2), Q(0), Q(4), Q(1)};
    const auto rs = simple_root_structure(to_integer(f), to_integer(Quadratic<Rational>{Q(16), Q(8), Q(1)}));
    REQUIRE(rs.has_value());
    REQUIRE(rs->real_roots.size() == 2);
    CHECK(rs->nonreal == 2);
    CHECK(rs->degree_ftilde == 3);
    CHECK(rs->sign_disc_ftilde == -1);
    check_isolation(f, *rs);
    REQUIRE(rs->real_roots[0].exact.has_value());
    CHECK(*rs->real_roots[0].exact == -4);
    CHECK(rs->real_roots[0].multiplicity_s == 2);
    CHECK(rs->real_roots[1].lower < Q(126, 100));
    CHECK(Q(125, 100) < rs->real_roots[1].upper);
  }
}

TEST_CASE("RealRoot::exact is set for every rational root, simple ones included", "[roots][bug]") {
  // roots.hpp documents RealRoot::exact as "the root itself when it is rational". A square-free
  // quartic that splits over Q has four rational simple roots.
  const auto f = to_integer(quartic_from_roots(Q(-2), {Q(-5), Q(-1), Q(3), Q(7)}));
  const auto s = to_integer(Quadratic<Rational>{Q(6), Q(5), Q(1)});
  auto rs = relpos::exact_root_structure(f, s);
  REQUIRE(rs.real_roots.size() == 4);
  const Rational want[4] = {Q(-5), Q(-1), Q(3), Q(7)};
  for (std::size_t i = 0; i < 4; ++i) {
    CAPTURE(i);
    REQUIRE(rs.real_roots[i].exact.has_value());
    CHECK(*rs.real_roots[i].exact == want[i]);
  }
}

TEST_CASE("Classification::roots gives the rational simple roots -a^2, -b^2 exactly", "[roots][bug]") {
  // Sphere centred (0, 0, 1), r = 1/4, paraboloid x^2 + y^2/4 = z: by eq. (4)
  // f = -(l + 1)(l + 4)(l^2 + 4 l + 1/4) / 16, so -1 and -4 are rational (simple) roots of f.
  const auto e = relpos::Ellipsoid::sphere({Q(0), Q(0), Q(1)}, Q(1, 4));
  const auto p = relpos::Paraboloid::standard({Q(0), Q(0), Q(0)}, Q(1), Q(2));
  const relpos::Classification c = relpos::classify(e, p);
  REQUIRE(c.verdict.position == relpos::Position::I);
  int found = 0;
  for (const auto& r : c.roots)
    for (const Rational& x : {Q(-1), Q(-4)})
      if (r.lower <= x && x <= r.upper) {
        CAPTURE(relpos::to_string(x));
        ++found;
        REQUIRE(r.exact.has_value());
        CHECK(*r.exact == x);
      }
  CHECK(found == 2);
}

TEST_CASE("exact_root_structure: a repeated factor of 30 000-bit coefficients", "[roots][bug]") {
  // f = (a l + b)^2 (l^2 + 1), a = 2^30000 + 12345, b = 7 - floor(3a / 2): one double root -b/a near
  // 3/2 and a non-real pair. The square-free factorisation's gcd has coefficients of 60 000 bits,
  // beyond what a gcd modulo CGAL's table of 2 000 primes of 26 bits can rebuild: with that gcd
  // (CGAL_USE_INTERNAL_MODULAR_GCD, CMakeLists.txt) this never ended. Its isolation needs a few
  // levels only, so the case is quick.
  Integer a(1);
  mpz_mul_2exp(a.mpz(), a.mpz(), 30000);
  a += 12345;
  Integer b = Integer(3) * a;
  mpz_fdiv_q_2exp(b.mpz(), b.mpz(), 1);
  b = Integer(7) - b;
  // (a l + b)^2 (l^2 + 1) = b^2 + 2ab l + (a^2 + b^2) l^2 + 2ab l^3 + a^2 l^4
  const Quartic<Integer> f{b * b, 2 * a * b, a * a + b * b, 2 * a * b, a * a};
  const Quadratic<Integer> s{Integer(5), Integer(0), Integer(1)};  // l^2 + 5: no common root
  const auto rs = relpos::exact_root_structure(f, s);
  REQUIRE(rs.real_roots.size() == 1);
  const auto& r = rs.real_roots[0];
  CHECK(r.multiplicity_f == 2);
  CHECK(r.multiplicity_s == 0);
  REQUIRE(r.exact);
  CHECK(*r.exact == Rational(-b, a));
  CHECK(rs.nonreal == 2);
  CHECK(rs.sign_disc_f == 0);
  const auto d = relpos::real_root_decimals(f, 12);
  REQUIRE(d.size() == 1);
  CHECK(rabs(relpos::parse_rational(d[0]) - Rational(-b, a)) < Rational(1, 1000000) * Rational(1, 100000));
}

TEST_CASE("root isolation on a thread with a small stack: roots 2^-3000 apart", "[roots][bug]") {
  // f = (a l - b)(a l - b - 1)(l^2 + 1), a = 2^3000 + 1, b = a + 3: two roots 1/a apart near 1. CGAL's
  // Descartes method recurses about once per bit of their separation, 3 000 levels of about 210
  // bytes: more than the 256 KiB stack of the thread below. The isolation asks for its own stack
  // (large_stack.hpp, isolate_on_fitting_stack); without it this test dies of a stack overflow.
  Integer a(1);
  mpz_mul_2exp(a.mpz(), a.mpz(), 3000);
  a += 1;
  const Integer b = a + 3, c = b + 1;
  // (a l - b)(a l - c) = a^2 l^2 - a (b + c) l + b c; times l^2 + 1.
  const Integer q2 = a * a, q1 = -a * (b + c), q0 = b * c;
  const Quartic<Integer> f{q0, q1, q0 + q2, q1, q2};
  std::vector<std::string> d;
  relpos::detail::run_on_large_stack(std::size_t(256) << 10, [&] { d = relpos::real_root_decimals(f, 12); });
  REQUIRE(d.size() == 2);
  CHECK(rabs(relpos::parse_rational(d[0]) - Rational(b, a)) < Rational(1, 1000000) * Rational(1, 100000));
  CHECK(rabs(relpos::parse_rational(d[1]) - Rational(c, a)) < Rational(1, 1000000) * Rational(1, 100000));
}

TEST_CASE("sign_of_discriminant for degrees 1 to 4", "[roots]") {
  using relpos::sign_of_discriminant;
  CHECK(sign_of_discriminant({Integer(3), Integer(2)}) == 1);
  CHECK(sign_of_discriminant({Integer(2), Integer(-3), Integer(1)}) == 1);                // (l-1)(l-2)
  CHECK(sign_of_discriminant({Integer(1), Integer(0), Integer(1)}) == -1);                // l^2 + 1
  CHECK(sign_of_discriminant({Integer(1), Integer(-2), Integer(1)}) == 0);                // (l-1)^2
  CHECK(sign_of_discriminant({Integer(-2), Integer(0), Integer(-1)}) == -1);              // -(l^2 + 2)
  CHECK(sign_of_discriminant({Integer(-6), Integer(11), Integer(-6), Integer(1)}) == 1);  // (l-1)(l-2)(l-3)
  CHECK(sign_of_discriminant({Integer(-1), Integer(1), Integer(-1), Integer(1)}) == -1);  // (l-1)(l^2+1)
  CHECK(sign_of_discriminant({Integer(0), Integer(0), Integer(1), Integer(1)}) == 0);     // l^2 (l+1)
  Rng g(2718);
  for (int i = 0; i < 100; ++i) {
    Quartic<Rational> f{Q(g.uniform(-20, 20)), Q(g.uniform(-20, 20)), Q(g.uniform(-20, 20)), Q(g.uniform(-20, 20)),
                        Q(g.uniform(1, 20) * (g.chance(50) ? 1 : -1))};
    CHECK(sign_of_discriminant({f[0].numerator(), f[1].numerator(), f[2].numerator(), f[3].numerator(),
                                f[4].numerator()}) == sgn(quartic_discriminant(f)));
  }
}

TEST_CASE("real_root_decimals: certified digits", "[roots]") {
  // (l^2 - 2)(l + 3)(l - 1/2) * 2: -3, -1.41421356..., 0.5, 1.41421356...
  Quartic<Rational> f{};
  const Rational p[3] = {Q(-2), Q(0), Q(1)}, q[3] = {Q(-3), Q(5), Q(2)};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) f[static_cast<std::size_t>(i + j)] += p[i] * q[j];
  auto d = relpos::real_root_decimals(to_integer(f), 8);
  REQUIRE(d.size() == 4);
  // Each decimal is within one unit of its 8th significant digit (10^-7 here) of the true root.
  const Rational unit(1, 10000000);
  CHECK(rabs(relpos::parse_rational(d[0]) + 3) <= unit * 10);
  CHECK(rabs(relpos::parse_rational(d[2]) - Q(1, 2)) <= unit);
  for (std::size_t i : {std::size_t(1), std::size_t(3)}) {
    const Rational x = rabs(relpos::parse_rational(d[i]));  // sqrt 2 = 1.41421356...
    CAPTURE(d[i]);
    CHECK((x - unit) * (x - unit) < 2);
    CHECK(2 < (x + unit) * (x + unit));
  }
  CHECK(relpos::parse_rational(d[1]) < 0);
  CHECK(relpos::parse_rational(d[3]) > 0);
}

TEST_CASE("sign_of_discriminant: Disc(pq) = Disc(p) Disc(q) Res(p, q)^2 on products of quadratics", "[roots][random]") {
  // The identity FLINT's t-discriminant checks, read on signs: sign Disc(pq) is the product of the
  // factors' signs when p and q are coprime (Res != 0), and 0 when they share a root. Res(p, q) of two
  // quadratics is computed here from its 4x4 Sylvester determinant's closed form.
  Rng g(141421);
  int shared = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const long a = g.uniform(1, 9) * (g.chance(50) ? 1 : -1);
    std::array<Integer, 3> p{Integer(g.uniform(-12, 12)), Integer(g.uniform(-12, 12)), Integer(a)};
    std::array<Integer, 3> q{Integer(g.uniform(-12, 12)), Integer(g.uniform(-12, 12)), Integer(g.uniform(1, 9))};
    if (trial % 4 == 0) {  // a common root r: p = p2 (x - r)(x - u), q = q2 (x - r)(x - v)
      const long r = g.uniform(-5, 5), u = g.uniform(-5, 5), v = g.uniform(-5, 5);
      p = {Integer(a * r * u), Integer(-a * (r + u)), Integer(a)};
      q = {Integer(r * v), Integer(-(r + v)), Integer(1)};
    }
    std::vector<Integer> pq(5, Integer(0));
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) pq[i + j] += p[i] * q[j];
    // Res(p, q) = (p2 q0 - p0 q2)^2 - (p2 q1 - p1 q2)(p1 q0 - p0 q1).
    const Integer u = p[2] * q[0] - p[0] * q[2], v = p[2] * q[1] - p[1] * q[2], w = p[1] * q[0] - p[0] * q[1];
    const Integer res = u * u - v * w;
    const int disc_p = relpos::sign_of_discriminant({p[0], p[1], p[2]});
    const int disc_q = relpos::sign_of_discriminant({q[0], q[1], q[2]});
    CAPTURE(trial);
    CHECK(disc_p == sgn(Rational(p[1] * p[1] - 4 * p[2] * p[0])));
    CHECK(relpos::sign_of_discriminant(pq) == (res == 0 ? 0 : disc_p * disc_q));
    shared += res == 0;
  }
  CHECK(shared >= 500);
}
