// pencil.hpp, sturm.hpp, smallness.hpp, roots.hpp: the polynomials and the exact tools that read them.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <relpos/classify.hpp>
#include <vector>

#include "algebra/between.hpp"
#include "algebra/exact_pencil.hpp"
#include "filters/fixed_pencil.hpp"
#include "algebra/forms.hpp"
#include "algebra/pencil.hpp"
#include "algebra/roots.hpp"
#include "algebra/smallness.hpp"
#include "algebra/sturm.hpp"
#include "filters/pooled_integer.hpp"
#include "support/construct.hpp"
#include "support/printers.hpp"

using namespace rt;
using relpos::characteristic_polynomial;
using relpos::exact_characteristic_polynomial;
using relpos::exact_special_polynomial;
using relpos::special_polynomial;

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

TEST_CASE("characteristic_polynomial is the paper's closed form (eq. 4) for spheres", "[pencil]") {
  const std::uint64_t seed = 0xF00D;
  Rng g(seed);
  CAPTURE(seed);
  for (int i = 0; i < 150; ++i) {
    const Rational a = g.positive_rational(9, 4), b = g.positive_rational(9, 4), r = g.positive_rational(9, 4);
    const Vector3 c{g.rational(-9, 9, 4), g.rational(-9, 9, 4), g.rational(-9, 9, 4)};
    CAPTURE(relpos::to_string(a), relpos::to_string(b), relpos::to_string(r));
    const Matrix4 e = sphere_matrix(c, r), p = paraboloid_matrix(a, b);
    const Quartic<Rational> f = characteristic_polynomial<Rational>(p, e);
    const Quartic<Rational> want = paper_f(a, b, c, r);
    for (std::size_t k = 0; k < 5; ++k) CHECK(f[k] == want[k]);
    CHECK(f[4] == det4(p));  // leading coefficient det P
    CHECK(f[0] == det4(e));  // constant term det E = -r^2
    CHECK(f[0] == -r * r);
    // At a few rational lambdas, f is det(lambda P + E) computed by elimination.
    for (long num : {-3L, -1L, 2L}) {
      const Rational l = Q(num, 2);
      Matrix4 pencil;
      for (std::size_t k = 0; k < 16; ++k) pencil.a[k] = l * p.a[k] + e.a[k];
      CHECK(eval(f, l) == det4(pencil));
    }
    const Quadratic<Rational> s = special_polynomial<Rational>(p, e);
    const Quadratic<Rational> ws = paper_s(a, b);
    for (std::size_t k = 0; k < 3; ++k) CHECK(s[k] == ws[k]);
    CHECK(eval(s, -a * a) == 0);
    CHECK(eval(s, -b * b) == 0);
  }
}

TEST_CASE("f and s are congruence invariants: f_H = det(H)^2 f, s_H = det(L)^2 s", "[pencil][random]") {
  const std::uint64_t seed = 0xBEEF01;
  Rng g(seed);
  CAPTURE(seed);
  for (int i = 0; i < 100; ++i) {
    CAPTURE(i);
    // Arbitrary symmetric matrices: the identity holds for any pencil.
    Matrix4 e, p;
    for (int r = 0; r < 4; ++r)
      for (int c = r; c < 4; ++c) {
        set_sym(e, r, c, g.rational(-6, 6, 3));
        set_sym(p, r, c, g.rational(-6, 6, 3));
      }
    Congruence h = random_congruence(g);
    const auto f = characteristic_polynomial<Rational>(p, e);
    const auto fh = characteristic_polynomial<Rational>(congruence(p, h.h), congruence(e, h.h));
    for (std::size_t k = 0; k < 5; ++k) CHECK(fh[k] == h.det * h.det * f[k]);
    // s drops the cubic term det A, so compare on matrices whose A has rank 2 (paraboloids).
    const Matrix4 par = paraboloid_matrix(g.positive_rational(5, 3), g.positive_rational(5, 3));
    const auto s = special_polynomial<Rational>(par, e);
    const auto sh = special_polynomial<Rational>(congruence(par, h.h), congruence(e, h.h));
    for (std::size_t k = 0; k < 3; ++k) CHECK(sh[k] == h.det * h.det * s[k]);
  }
}

TEST_CASE("the generic pencil code gives the same polynomial over Z, Q and doubles", "[pencil]") {
  // Integer matrices: the Integer and double instantiations must agree exactly (small values), and
  // PooledInteger (its fused add_product / sub_product) with Integer (the generic ones).
  Rng g(31337);
  for (int i = 0; i < 30; ++i) {
    std::array<Integer, 16> ei{}, pi{};
    std::array<double, 16> ed{}, pd{};
    Matrix4 eq, pq;
    for (int r = 0; r < 4; ++r)
      for (int c = r; c < 4; ++c) {
        long x = g.uniform(-9, 9), y = g.uniform(-9, 9);
        for (auto idx : {4 * r + c, 4 * c + r}) {
          const auto k = static_cast<std::size_t>(idx);
          ei[k] = Integer(x);
          pi[k] = Integer(y);
          ed[k] = static_cast<double>(x);
          pd[k] = static_cast<double>(y);
        }
        set_sym(eq, r, c, Q(x));
        set_sym(pq, r, c, Q(y));
      }
    struct MI {
      std::array<Integer, 16> a;
      const Integer& operator()(int r, int c) const { return a[static_cast<std::size_t>(4 * r + c)]; }
    };
    struct MD {
      std::array<double, 16> a;
      const double& operator()(int r, int c) const { return a[static_cast<std::size_t>(4 * r + c)]; }
    };
    struct MP {
      std::array<relpos::PooledInteger, 16> a;
      const relpos::PooledInteger& operator()(int r, int c) const { return a[static_cast<std::size_t>(4 * r + c)]; }
    };
    MP pp, ep;
    for (std::size_t k = 0; k < 16; ++k) pp.a[k] = relpos::PooledInteger(pi[k]), ep.a[k] = relpos::PooledInteger(ei[k]);
    const auto fz = characteristic_polynomial<Integer>(MI{pi}, MI{ei});
    const auto fd = characteristic_polynomial<double>(MD{pd}, MD{ed});
    const auto fq = characteristic_polynomial<Rational>(pq, eq);
    const auto fp = characteristic_polynomial<relpos::PooledInteger>(pp, ep);
    for (std::size_t k = 0; k < 5; ++k) {
      CHECK(Rational(fz[k]) == fq[k]);
      CHECK(Rational(fd[k]) == fq[k]);  // all values are small integers: exact in double
      CHECK(fp[k].to_integer() == fz[k]);
    }
    const auto sz = special_polynomial<Integer>(MI{pi}, MI{ei});
    const auto sp = special_polynomial<relpos::PooledInteger>(pp, ep);
    for (std::size_t k = 0; k < 3; ++k) CHECK(sp[k].to_integer() == sz[k]);
    // The exact-only forms (exact_pencil.hpp), fused and generic, and on entries of some 200 bits
    // (GMP's multi-limb addmul and submul, signs of every kind).
    const auto fe = exact_characteristic_polynomial<relpos::PooledInteger>(pp, ep);
    const auto se = exact_special_polynomial<relpos::PooledInteger>(pp, ep);
    const auto fei = exact_characteristic_polynomial<Integer>(MI{pi}, MI{ei});
    for (std::size_t k = 0; k < 5; ++k) CHECK(fe[k].to_integer() == fz[k]);
    for (std::size_t k = 0; k < 5; ++k) CHECK(fei[k] == fz[k]);
    for (std::size_t k = 0; k < 3; ++k) CHECK(se[k].to_integer() == sz[k]);
    Integer big(1);
    mpz_mul_2exp(big.mpz(), big.mpz(), 200);
    big = big + Integer(g.uniform(1, 1000000));
    MI pl{pi}, el{ei};
    for (std::size_t k = 0; k < 16; ++k) {
      pl.a[k] = pl.a[k] * big + Integer(g.uniform(-9, 9) * (k % 5 == 0));  // symmetric: k % 5 == 0 on the diagonal
      el.a[k] = el.a[k] * big * big;
    }
    MP ppl, epl;
    for (std::size_t k = 0; k < 16; ++k)
      ppl.a[k] = relpos::PooledInteger(pl.a[k]), epl.a[k] = relpos::PooledInteger(el.a[k]);
    const auto fl = characteristic_polynomial<Integer>(pl, el);
    const auto fel = exact_characteristic_polynomial<relpos::PooledInteger>(ppl, epl);
    for (std::size_t k = 0; k < 5; ++k) CHECK(fel[k].to_integer() == fl[k]);
    const auto sl = special_polynomial<Integer>(pl, el);
    const auto sel = exact_special_polynomial<relpos::PooledInteger>(ppl, epl);
    for (std::size_t k = 0; k < 3; ++k) CHECK(sel[k].to_integer() == sl[k]);
  }
}

TEST_CASE("the fixed-size pencil equals the GMP one on entries below 2^62 and declines larger ones", "[pencil]") {
  // Against the generic formulas on Integer (another order, other arithmetic): random entries of
  // every length up to 62 bits and every sign, zeros in a paraboloid's places, the largest entries
  // 2^62 - 1 in a Hadamard sign pattern (coefficients near the 2^257 of the overflow proof, and
  // every carry and borrow of the 320-bit sums); 2^62 and two-limb entries take the GMP path.
  using relpos::PooledInteger;
  using Forms = relpos::forms::MatrixOf<PooledInteger>;
  Rng g(6262);
  const long top = (1L << 62) - 1;
  auto check = [](const std::array<long, 16>& pv, const std::array<long, 16>& ev) {
    Forms pp, ep;
    std::array<Integer, 16> pi, ei;
    for (std::size_t k = 0; k < 16; ++k) {
      mpz_set_si(pp.a[k].mpz(), pv[k]);
      mpz_set_si(ep.a[k].mpz(), ev[k]);
      pi[k] = Integer(pv[k]);
      ei[k] = Integer(ev[k]);
    }
    relpos::Quartic<PooledInteger> f;
    relpos::Quadratic<PooledInteger> s;
    REQUIRE(relpos::small_pencil_polynomials(pp, ep, f, s));
    const auto fz =
        characteristic_polynomial<Integer>(relpos::forms::MatrixOf<Integer>{pi}, relpos::forms::MatrixOf<Integer>{ei});
    const auto sz = exact_special_polynomial<PooledInteger>(pp, ep);
    for (std::size_t k = 0; k < 5; ++k) CHECK(f[k].to_integer() == fz[k]);
    for (std::size_t k = 0; k < 3; ++k) CHECK(s[k].to_integer() == sz[k].to_integer());
  };
  static constexpr int hadamard[4][4] = {{1, 1, 1, 1}, {1, -1, 1, -1}, {1, 1, -1, -1}, {1, -1, -1, 1}};
  for (int flip = 0; flip < 16; ++flip) {  // +-(2^62 - 1) with det +-16 (2^62 - 1)^4 at mu = 0 and mu -> oo
    std::array<long, 16> pv{}, ev{};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) {
        const auto k = static_cast<std::size_t>(4 * r + c);
        ev[k] = hadamard[r][c] * top * ((flip >> r & 1) ? -1 : 1);
        pv[k] = hadamard[c][r] * top * ((flip >> c & 1) ? -1 : 1) * (r == 3 ? -1 : 1);
      }
    check(pv, ev);
    for (std::size_t k = 0; k < 16; ++k) pv[k] = (k % 5 == 0 || k == 11 || k == 14) ? pv[k] : 0;  // sparse P
    check(pv, ev);
  }
  for (int i = 0; i < 300; ++i) {
    std::array<long, 16> pv{}, ev{};
    for (std::size_t k = 0; k < 16; ++k) {
      const int bits = static_cast<int>(g.uniform(0, 62));
      const long mag = bits == 0 ? 0 : static_cast<long>(g.gen() >> (64 - bits));
      ev[k] = g.chance(50) ? -mag : mag;
      const long pmag = g.chance(20) ? top : static_cast<long>(g.gen() >> 2);
      pv[k] = (i % 2 == 0 && !(k % 5 == 0 || k == 11 || k == 14)) ? 0 : (g.chance(50) ? -pmag : pmag);
    }
    check(pv, ev);
  }
  // 2^62, -2^62 and a two-limb entry: declined, f and s untouched.
  for (int which = 0; which < 3; ++which) {
    Forms pp, ep;
    for (std::size_t k = 0; k < 16; ++k) {
      mpz_set_si(pp.a[k].mpz(), g.uniform(-1000, 1000));
      mpz_set_si(ep.a[k].mpz(), g.uniform(-1000, 1000));
    }
    mpz_set_ui(ep.a[5].mpz(), 1);
    mpz_mul_2exp(ep.a[5].mpz(), ep.a[5].mpz(), which == 2 ? 64 : 62);
    if (which == 1) mpz_neg(ep.a[5].mpz(), ep.a[5].mpz());
    relpos::Quartic<PooledInteger> f{PooledInteger(7), PooledInteger(7), PooledInteger(7), PooledInteger(7),
                                     PooledInteger(7)};
    relpos::Quadratic<PooledInteger> s{PooledInteger(7), PooledInteger(7), PooledInteger(7)};
    CHECK_FALSE(relpos::small_pencil_polynomials(pp, ep, f, s));
    CHECK_FALSE(relpos::small_pencil_polynomials(ep, pp, f, s));
    for (const auto& c : f) CHECK(c.to_integer() == Integer(7));
    for (const auto& c : s) CHECK(c.to_integer() == Integer(7));
    mpz_set_si(ep.a[5].mpz(), which == 1 ? -top : top);  // one less in magnitude: taken
    CHECK(relpos::small_pencil_polynomials(pp, ep, f, s));
  }
}

TEST_CASE("Sturm-Habicht root counts on quartics with known roots", "[sturm]") {
  struct Known {
    std::array<Rational, 4> roots;
    int real, negative, positive;
  };
  const std::vector<Known> known = {
      {{Q(-1), Q(-2), Q(-3), Q(-4)}, 4, 4, 0},
      {{Q(-1), Q(-2), Q(3), Q(5)}, 4, 2, 2},
      {{Q(1, 3), Q(2), Q(-7, 2), Q(9)}, 4, 1, 3},
      {{Q(1), Q(2), Q(3), Q(4)}, 4, 0, 4},
  };
  for (const auto& k : known)
    for (int lead : {1, -3}) {
      const Quartic<Rational> f = quartic_from_roots(Q(lead), k.roots);
      relpos::SturmHabicht<Rational> sh(f);
      auto c = relpos::count_roots(f, sh);
      REQUIRE(c.has_value());
      CHECK(c->real == k.real);
      CHECK(c->negative == k.negative);
      CHECK(c->positive == k.positive);
      CHECK(sh.discriminant() > 0);
    }
  // Non-real roots: (l^2 + 1)(l + 1)(l - 2): 2 real; (l^2 + 1)(l^2 + 4): none;
  // (l^2 - 2l + 5)(l + 3)(l + 5/2): 2 real negative.
  auto times = [](const std::array<Rational, 3>& p, const std::array<Rational, 3>& q) {
    Quartic<Rational> f{};
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) f[i + j] += p[i] * q[j];
    return f;
  };
  struct KnownPoly {
    Quartic<Rational> f;
    int real, negative, positive, disc_sign;
  };
  const std::vector<KnownPoly> polys = {
      {times({Q(1), Q(0), Q(1)}, {Q(-2), Q(-1), Q(1)}), 2, 1, 1, -1},
      {times({Q(1), Q(0), Q(1)}, {Q(4), Q(0), Q(1)}), 0, 0, 0, 1},
      {times({Q(5), Q(-2), Q(1)}, {Q(15, 2), Q(11, 2), Q(1)}), 2, 2, 0, -1},
  };
  for (const auto& k : polys) {
    relpos::SturmHabicht<Rational> sh(k.f);
    auto c = relpos::count_roots(k.f, sh);
    REQUIRE(c.has_value());
    CHECK(c->real == k.real);
    CHECK(c->negative == k.negative);
    CHECK(c->positive == k.positive);
    CHECK(sgn(sh.discriminant()) == k.disc_sign);
  }
  // A double root makes the sequence defective (Disc = 0): no answer, the caller goes exact.
  const Quartic<Rational> dbl = quartic_from_roots(Q(1), {Q(-1), Q(-1), Q(2), Q(3)});
  relpos::SturmHabicht<Rational> sh(dbl);
  CHECK(sh.discriminant() == 0);
  CHECK_FALSE(relpos::count_roots(dbl, sh).has_value());
}

TEST_CASE("the Sturm-Habicht g0 is the discriminant of f", "[sturm][random]") {
  Rng g(8080);
  for (int i = 0; i < 200; ++i) {
    Quartic<Rational> f{g.nonzero_rational(-9, 9, 3), g.rational(-9, 9, 3), g.rational(-9, 9, 3), g.rational(-9, 9, 3),
                        g.nonzero_rational(-9, 9, 3)};
    relpos::SturmHabicht<Rational> sh(f);
    CHECK(sh.discriminant() == quartic_discriminant(f));
  }
  // And the 16-term formula itself: Disc = a^6 prod (ri - rj)^2.
  const std::array<Rational, 4> r{Q(-1), Q(2), Q(1, 2), Q(5)};
  Rational prod(1);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j) prod *= (r[i] - r[j]) * (r[i] - r[j]);
  CHECK(quartic_discriminant(quartic_from_roots(Q(3), r)) == pow_q(Q(3), 6) * prod);
}

TEST_CASE("compare_rho_with_one: rho = 4 r^2 / min(a,b)^4 against 1", "[smallness]") {
  struct Case {
    Rational a, b, r;
    int want;
  };
  const std::vector<Case> cases = {
      {Q(1), Q(2), Q(1, 4), -1},
      {Q(1), Q(2), Q(1, 2), 0},
      {Q(1), Q(2), Q(3, 4), 1},
      {Q(2), Q(1), Q(1, 2), 0},
      {Q(2), Q(1), Q(1, 2) + Q(1, 1000000), 1},
      {Q(2), Q(1), Q(1, 2) - Q(1, 1000000), -1},
      {Q(1), Q(1), Q(1, 2), 0},
      {Q(1), Q(1), Q(2), 1},
      {Q(6, 5), Q(3, 2), Q(1, 4), -1},
      {Q(6, 5), Q(3, 2), Q(18, 25), 0},
      {Q(3, 2), Q(6, 5), Q(18, 25), 0},
  };
  Rng g(11);
  for (const auto& k : cases) {
    CAPTURE(relpos::to_string(k.a), relpos::to_string(k.b), relpos::to_string(k.r));
    for (int rep = 0; rep < 5; ++rep) {
      const Vector3 c{g.rational(-5, 5, 2), g.rational(-5, 5, 2), g.rational(-5, 5, 2)};
      const auto f = paper_f(k.a, k.b, c, k.r);
      const auto s = paper_s(k.a, k.b);
      auto cmp = relpos::compare_rho_with_one(f, s);
      REQUIRE(cmp.has_value());
      CHECK(*cmp == k.want);
      // Independent of positive rescalings of the pencil (lambda -> t lambda, f -> u f, s -> v s).
      const Rational t = g.positive_rational(9, 7), u = g.positive_rational(9, 7), v = g.positive_rational(9, 7);
      Quartic<Rational> f2;
      Quadratic<Rational> s2;
      for (int i = 0; i < 5; ++i) f2[static_cast<std::size_t>(i)] = u * pow_q(t, i) * f[static_cast<std::size_t>(i)];
      for (int i = 0; i < 3; ++i) s2[static_cast<std::size_t>(i)] = v * pow_q(t, i) * s[static_cast<std::size_t>(i)];
      auto cmp2 = relpos::compare_rho_with_one(f2, s2);
      REQUIRE(cmp2.has_value());
      CHECK(*cmp2 == k.want);
    }
  }
}

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

namespace {

/// The exact sign of h (integer coefficients h[0..n]) at a double x, in rationals.
int exact_sign_at(const std::vector<Integer>& h, double x) {
  Rational v(0);
  const Rational q(x);
  for (std::size_t i = h.size(); i-- > 0;) v = v * q + Rational(h[i]);
  return CGAL::sign(v);
}

/// The product of the integer polynomials a and b (coefficients from the constant term up).
std::vector<Integer> times(const std::vector<Integer>& a, const std::vector<Integer>& b) {
  std::vector<Integer> out(a.size() + b.size() - 1, Integer(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
  return out;
}

}  // namespace

TEST_CASE("DoubleSign: the floating-point stages answer only with the exact sign", "[roots]") {
  using relpos::detail::DoubleSign;
  std::mt19937_64 rng(20261126);
  auto big = [&](int bits) {  // a random odd integer of about `bits` bits, random sign
    Integer z(0);
    for (int b = 0; b < bits; b += 32) z = z * Integer(1L << 32) + Integer(static_cast<long>(rng() >> 32));
    z = 2 * z + 1;
    return (rng() & 1) ? z : Integer(-z);
  };
  int certified = 0, asked = 0;
  SECTION("dyadic roots, their neighbours a few ulps away, and a large common factor") {
    for (int trial = 0; trial < 300; ++trial) {
      // h = K (2^k1 x - m1) (2^k2 x - m2) (x^2 + c) or a cubic / quadratic: the roots m / 2^k are
      // doubles, where h is exactly 0 and no filter may answer.
      const int n = 2 + trial % 3;
      std::vector<double> roots;
      std::vector<Integer> h{big(1 + static_cast<int>(rng() % 150))};
      for (int j = 0; j < 2; ++j) {
        const int k = static_cast<int>(rng() % 60);
        const long m = static_cast<long>(rng() >> 12) | 1;
        roots.push_back(std::ldexp(static_cast<double>(m), -k));
        Integer pk(1);
        for (int b = 0; b < k; ++b) pk *= 2;
        h = times(h, {Integer(-m), pk});
      }
      if (n == 3) h = times(h, {big(40), Integer(1)});
      if (n == 4) h = times(h, {Integer(1) + big(20) * big(20), Integer(0), Integer(1)});
      DoubleSign sign(h.data(), n);
      for (const double r : roots) {
        CHECK(sign.filtered(r) == 0);  // h(r) = 0 exactly
        CHECK(sign(r) == 0);
        double below = r, above = r;
        for (int step = 0; step < 6; ++step) {
          below = std::nextafter(below, -HUGE_VAL);
          above = std::nextafter(above, HUGE_VAL);
          for (const double x : {below, above}) {
            const int exact = exact_sign_at(h, x), s = sign.filtered(x);
            ++asked;
            if (s != 0) ++certified;
            CHECK((s == 0 || s == exact));
            CHECK(sign(x) == exact);
          }
        }
      }
    }
    CHECK(certified > 0);  // one ulp from a simple root of a well-scaled h is usually within reach
  }
  SECTION("two roots 2^-20 apart: points 2^-44 away from them, out of the crude bound's reach") {
    // h = (2^20 x - 2^20)(2^20 x - 2^20 - 1) (x^2 + x + 1) K: near x = 1, h' x is 2^-20 of the magnitude
    // sum |h_i| |x|^i, so h(1 +- 2^-44) is below 2^-48 of it; the compensated bound is 2^-96 of it.
    for (int trial = 0; trial < 100; ++trial) {
      const Integer two20(1L << 20);
      std::vector<Integer> h = times({big(1 + trial)}, {-two20, two20});
      h = times(h, {-two20 - 1, two20});
      h = times(h, {Integer(1), Integer(1), Integer(1)});
      DoubleSign sign(h.data(), 4);
      for (const double r : {1.0, 1.0 + std::ldexp(1.0, -20)})
        for (const double x : {r * (1 - 0x1p-44), r * (1 + 0x1p-44)}) {
          const int exact = exact_sign_at(h, x);
          REQUIRE(exact != 0);
          CHECK(sign.filtered(x) == exact);  // certified by the compensated stage
          CHECK(sign(x) == exact);
        }
    }
  }
  SECTION("random quartics with large coefficients, at random doubles near and far from their roots") {
    for (int trial = 0; trial < 300; ++trial) {
      std::vector<Integer> h;
      for (int i = 0; i <= 4; ++i) h.push_back(big(1 + static_cast<int>(rng() % 200)));
      DoubleSign sign(h.data(), 4);
      for (int j = 0; j < 20; ++j) {
        const double x = std::ldexp(static_cast<double>(static_cast<long>(rng() >> 11)) - 0x1p52,
                                    static_cast<int>(rng() % 400) - 252);
        const int exact = exact_sign_at(h, x), s = sign.filtered(x);
        CHECK((s == 0 || s == exact));
        CHECK(sign(x) == exact);
      }
    }
  }
}
